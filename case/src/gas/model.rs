//! What a gas model's module builds on, below the registry of [`super::MODELS`] that lists
//! the modules: the clearance a model takes, its typed table ([`ModelTable`]), its registry
//! line ([`GasEntry`], [`entry`]) and what its table is read in ([`Context`]).

use crate::error::{CaseError, Machine};
use crate::schema::FieldError;
use cardan_gas::{Cylinder, GasError, GasModel};
use schemars::{JsonSchema, Schema, SchemaGenerator};
use serde::de::DeserializeOwned;
use std::path::Path;
use std::sync::Arc;

/// How the clearance volume is given.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Clearance {
    /// Compression ratio ε = (V_stroke + V_comp)/V_comp.
    CompressionRatio(f64),
    /// Clearance ratio c = V_comp/V_stroke, which may be zero.
    ClearanceRatio(f64),
}

impl Clearance {
    /// The cylinder of `bore` (m) shared by `pistons` pistons of `stroke` (m) each, with this
    /// clearance.
    pub fn cylinder(self, bore: f64, stroke: f64, pistons: u32) -> Result<Cylinder, GasError> {
        let swept = f64::from(pistons) * std::f64::consts::PI / 4.0 * bore * bore * stroke;
        match self {
            Clearance::CompressionRatio(e) => Cylinder::with_compression_ratio(bore, swept, e),
            // The case file gives the ratio, not the volume.
            Clearance::ClearanceRatio(c) => Cylinder::with_clearance(bore, swept, c * swept)
                .map_err(|e| match e.field {
                    "clearance_volume" => GasError {
                        field: "clearance_ratio",
                        value: c,
                        ..e
                    },
                    _ => e,
                }),
        }?
        .with_pistons(pistons)
    }
}

/// A model read from its `[gas]` table, with the cylinder's clearance it takes.
pub type ReadModel = (Arc<dyn GasModel + Send>, Clearance);

/// A model's typed table (the `[gas]` table without `model`): its fields, their units and
/// defaults, and how they build the model.
pub trait ModelTable: DeserializeOwned + JsonSchema {
    /// The model and its clearance; a rule that joins fields, broken, names its field
    /// ([`Context::broken`]).
    fn build(self, cx: &Context) -> Result<ReadModel, CaseError>;
}

/// A gas model a `[gas]` table may name: adding one is a module with its [`ModelTable`] and
/// one line in [`super::MODELS`] (`entry::<Table>(name, machine)`).
pub struct GasEntry {
    /// `gas.model` in case files.
    pub name: &'static str,
    /// The machine it belongs to (`None`: either).
    pub machine: Option<Machine>,
    /// Reads the model's typed table (the `[gas]` table without `model`) and builds it.
    pub(super) read: fn(toml::Value, &Context) -> Result<ReadModel, CaseError>,
    /// The JSON Schema of the model's table (inline, without `model`).
    pub schema: fn(&mut SchemaGenerator) -> Schema,
    /// Its cycle takes two crank turns (a four-stroke engine's): a machine of it fires each
    /// cylinder once every 720°, and a `[layout] cycle = "two_stroke"` is refused.
    pub four_stroke: bool,
}

impl GasEntry {
    /// The same model, whose cycle takes two crank turns (the entry's `four_stroke`).
    pub const fn four_stroke(self) -> Self {
        Self {
            four_stroke: true,
            ..self
        }
    }
}

/// The registry line of a model whose table is `T`.
pub const fn entry<T: ModelTable>(name: &'static str, machine: Option<Machine>) -> GasEntry {
    GasEntry {
        name,
        machine,
        read: read_table::<T>,
        schema: T::json_schema,
        four_stroke: false,
    }
}

/// What a model's table is read in: the case file (relative paths are taken from it), the
/// case, its machine, and the table as written (for the values of messages).
pub struct Context<'a> {
    pub(super) table: &'a toml::Table,
    /// The case file, which relative paths are taken from.
    pub file: &'a Path,
    pub(super) case: &'a str,
    /// The case's machine.
    pub machine: Machine,
    /// `gas.model`.
    pub(super) model: &'static str,
    /// The files the model read: each as named in the table and the digest of its bytes
    /// ([`Context::read_file`]).
    pub(super) files: std::cell::RefCell<Vec<(String, String)>>,
    /// The files the case file's cases read so far, shared by a sweep's points.
    pub(super) read_once: &'a crate::read_once::ReadOnce,
}

impl Context<'_> {
    /// The file the field `key` names (`name`, relative to the case file), read through the
    /// bounded reader within `limit` and parsed by `parse` (a value or the rule the text
    /// breaks) once for every case of the case file (`kind` names what the parse depends on
    /// beyond the bytes). The digest of its bytes is recorded with its name: it enters the
    /// case's input digest ([`crate::case::Case::input_digest`]), so that a run resumed or
    /// merged after the file changed runs the case again. Every model that reads a file reads
    /// it so.
    pub fn read_file<T: std::any::Any + Send + Sync>(
        &self,
        key: &str,
        name: &str,
        (limit, kind): (cardan_files::Limit, &str),
        parse: impl FnOnce(&str) -> Result<T, String>,
    ) -> Result<Arc<T>, CaseError> {
        let path = self.file.parent().unwrap_or(Path::new(".")).join(name);
        let shown = format!("\"{name}\"");
        let (digest, value) = self.read_once.get(&path, kind, || {
            let text = cardan_files::read_text(&path, limit).map_err(|e| {
                self.refuse(key, &shown, &format!("cannot read {}: {e}", path.display()))
            })?;
            let value = parse(&text).map_err(|rule| self.refuse(key, &shown, &rule))?;
            Ok((crate::digest::of_bytes(text.as_bytes()), value))
        })?;
        self.files.borrow_mut().push((name.to_string(), digest));
        Ok(value)
    }

    /// A rule broken by `value` of the field `key` of `[gas]`.
    pub fn refuse(&self, key: &str, value: &dyn std::fmt::Display, rule: &str) -> CaseError {
        CaseError::Invalid {
            file: self.file.into(),
            case: self.case.to_string(),
            field: format!("gas.{key}"),
            value: crate::units::show(&value.to_string()),
            rule: rule.to_string(),
        }
    }

    /// A model's rule broken: the field as the case file names it, with the value given.
    pub fn broken(&self, e: GasError) -> CaseError {
        match self.table.get(e.field) {
            Some(v) => self.refuse(e.field, v, e.rule),
            None => self.refuse(e.field, &e.value, e.rule),
        }
    }

    /// A field of the table that did not read, said in the model's terms.
    fn field(&self, mut error: FieldError) -> CaseError {
        let model = format!("gas.model = \"{}\"", self.model);
        let m = &error.message;
        if let Some(rest) = m.strip_prefix("unknown field \"") {
            if let Some(end) = rest.find('"') {
                let name = &rest[..end];
                let tail = rest[end + 1..].replace("the fields here", "its fields");
                error.message = format!("unknown field \"{name}\", not an input of {model}{tail}");
            }
        } else if let Some(what) = m.strip_prefix("= (missing): required") {
            error.message = format!("= (missing): required by {model}{what}");
        }
        CaseError::Field {
            file: self.file.into(),
            case: self.case.to_string(),
            error,
        }
    }
}

fn read_table<T: ModelTable>(rest: toml::Value, cx: &Context) -> Result<ReadModel, CaseError> {
    crate::schema::read::<T>(rest, "gas")
        .map_err(|e| cx.field(e))?
        .build(cx)
}
