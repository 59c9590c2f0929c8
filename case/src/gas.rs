//! The `[gas]` table of a case: which gas model loads the pistons, with its inputs converted
//! to SI and validated once, here.
//!
//! `model` picks a [`GasEntry`] of [`MODELS`]; the rest of the table is that model's typed
//! table (a struct with `deny_unknown_fields`, one module per model), read by
//! [`crate::schema::read`], then built into the model by [`ModelTable::build`], which checks
//! the rules that join fields (through the gas crate's own checks, naming the field).

use crate::error::{CaseError, Machine};
use crate::schema::FieldError;
use cardan_gas::{Cylinder, GasError, GasModel};
use schemars::{json_schema, JsonSchema, Schema, SchemaGenerator};
use serde::de::DeserializeOwned;
use std::path::Path;
use std::sync::Arc;

mod closed_cycle;
mod compressor;
mod karhula;
mod pressure_trace;

pub use closed_cycle::ClosedCycleTable;
pub use compressor::CompressorTable;
pub use karhula::{KarhulaEngineTable, KarhulaPumpTable};
pub use pressure_trace::PressureTraceTable;

/// How the clearance volume is given.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Clearance {
    /// Compression ratio ε = (V_stroke + V_comp)/V_comp.
    CompressionRatio(f64),
    /// Clearance ratio c = V_comp/V_stroke, which may be zero.
    ClearanceRatio(f64),
}

/// The gas of a case.
#[derive(Clone)]
pub struct GasCase {
    /// The registry's name of the model (`gas.model`).
    name: &'static str,
    model: Arc<dyn GasModel + Send>,
    pub clearance: Clearance,
}

impl std::fmt::Debug for GasCase {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("GasCase")
            .field("model", &self.name)
            .field("clearance", &self.clearance)
            .finish()
    }
}

impl GasCase {
    /// The model's name as written in case files.
    pub fn name(&self) -> &'static str {
        self.name
    }

    pub fn model(&self) -> &dyn GasModel {
        self.model.as_ref()
    }

    /// The cylinder of `bore` (m) shared by `pistons` pistons of `stroke` (m) each, with this
    /// case's clearance.
    pub fn cylinder(&self, bore: f64, stroke: f64, pistons: u32) -> Result<Cylinder, GasError> {
        self.clearance.cylinder(bore, stroke, pistons)
    }
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
/// one line in [`MODELS`] (`entry::<Table>(name, machine)`).
pub struct GasEntry {
    /// `gas.model` in case files.
    pub name: &'static str,
    /// The machine it belongs to (`None`: either).
    pub machine: Option<Machine>,
    /// Reads the model's typed table (the `[gas]` table without `model`) and builds it.
    read: fn(toml::Value, &Context) -> Result<ReadModel, CaseError>,
    /// The JSON Schema of the model's table (inline, without `model`).
    pub schema: fn(&mut SchemaGenerator) -> Schema,
}

/// The registry line of a model whose table is `T`.
pub const fn entry<T: ModelTable>(name: &'static str, machine: Option<Machine>) -> GasEntry {
    GasEntry {
        name,
        machine,
        read: read_table::<T>,
        schema: T::json_schema,
    }
}

/// The registry of gas models.
pub const MODELS: &[GasEntry] = &[
    karhula::PUMP,
    karhula::ENGINE,
    closed_cycle::ENTRY,
    compressor::ENTRY,
    pressure_trace::ENTRY,
];

/// What a model's table is read in: the case file (relative paths are taken from it), the
/// case, its machine, and the table as written (for the values of messages).
pub struct Context<'a> {
    table: &'a toml::Table,
    /// The case file, which relative paths are taken from.
    pub file: &'a Path,
    case: &'a str,
    /// The case's machine.
    pub machine: Machine,
    /// `gas.model`.
    model: &'static str,
}

impl Context<'_> {
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

/// Validates a `[gas]` table of the case `case` of the file `file`, a case of `machine`.
pub fn parse(
    table: &toml::Table,
    file: &Path,
    case: &str,
    machine: Machine,
) -> Result<GasCase, CaseError> {
    let mut cx = Context {
        table,
        file,
        case,
        machine,
        model: "",
    };
    let names: Vec<&str> = MODELS.iter().map(|m| m.name).collect();
    let listed = || {
        let quoted: Vec<String> = names.iter().map(|n| format!("\"{n}\"")).collect();
        quoted.join(", ")
    };
    let name = match table.get("model") {
        Some(toml::Value::String(s)) => s.as_str(),
        Some(v) => return Err(cx.refuse("model", v, &format!("must be one of {}", listed()))),
        None => {
            return Err(cx.refuse(
                "model",
                &"(missing)",
                &format!("is required: one of {}", listed()),
            ))
        }
    };
    let Some(entry) = MODELS.iter().find(|m| m.name == name) else {
        let guess = crate::schema::nearest(name, &names)
            .map(|n| format!("did you mean \"{n}\"? "))
            .unwrap_or_default();
        return Err(cx.refuse(
            "model",
            &format!("\"{name}\""),
            &format!("unknown gas model: {guess}use one of {}", listed()),
        ));
    };
    if let Some(own) = entry.machine.filter(|&m| m != machine) {
        return Err(cx.refuse(
            "model",
            &format!("\"{name}\""),
            &format!(
                "is a model of a {}: set machine = \"{}\"",
                own.name(),
                own.name()
            ),
        ));
    }
    cx.model = entry.name;
    let mut rest = table.clone();
    rest.remove("model");
    let (model, clearance) = (entry.read)(toml::Value::Table(rest), &cx)?;
    // The cylinder rules (a compression ratio above 1) do not depend on its size.
    clearance.cylinder(1.0, 1.0, 1).map_err(|e| cx.broken(e))?;
    Ok(GasCase {
        name: entry.name,
        model,
        clearance,
    })
}

/// The JSON Schema of `[gas]`: one branch per registered model, its table with `model` as a
/// constant.
pub fn gas_schema(generator: &mut SchemaGenerator) -> Schema {
    let branches: Vec<serde_json::Value> = MODELS
        .iter()
        .map(|entry| {
            let mut branch = (entry.schema)(generator);
            let machine = match entry.machine {
                Some(m) => format!(" (a {} model)", m.name()),
                None => String::new(),
            };
            let model = json_schema!({
                "const": entry.name,
                "description": format!("The gas model{machine}."),
            });
            let object = branch.ensure_object();
            let properties = object
                .entry("properties")
                .or_insert_with(|| serde_json::json!({}));
            if let Some(p) = properties.as_object_mut() {
                p.insert("model".into(), model.to_value());
            }
            let required = object
                .entry("required")
                .or_insert_with(|| serde_json::json!([]));
            if let Some(r) = required.as_array_mut() {
                r.insert(0, "model".into());
            }
            branch.to_value()
        })
        .collect();
    json_schema!({
        "description": "The gas that loads the pistons: `model` names one of the registered models, whose fields follow.",
        "type": "object",
        "oneOf": branches,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every shipped case's `[gas]` reads (through the whole case, as the runner reads it).
    #[test]
    fn every_shipped_gas_table_reads() {
        let configs = Path::new(env!("CARGO_MANIFEST_DIR")).join("../configs");
        let mut read = 0;
        for entry in std::fs::read_dir(&configs).unwrap() {
            let file = entry.unwrap().path();
            if file.extension().is_none_or(|e| e != "toml") {
                continue;
            }
            let text = std::fs::read_to_string(&file).unwrap();
            let table: toml::Table = toml::from_str(&text).unwrap();
            let Some(toml::Value::Table(gas)) = table.get("gas") else {
                continue;
            };
            let machine = match table.get("machine").and_then(|m| m.as_str()) {
                Some("engine") => Machine::Engine,
                _ => Machine::Pump,
            };
            let case = parse(gas, &file, "shipped", machine)
                .unwrap_or_else(|e| panic!("{}: {e}", file.display()));
            assert_eq!(Some(case.name()), gas.get("model").and_then(|m| m.as_str()));
            read += 1;
        }
        assert!(read >= 5, "{read} shipped cases with [gas]");
    }

    fn error(machine: Machine, text: &str) -> String {
        let table: toml::Table = toml::from_str(text).unwrap();
        parse(&table, Path::new("c.toml"), "c", machine)
            .unwrap_err()
            .to_string()
    }

    /// A misspelled field of each model's table names its path, the nearest field and the
    /// model.
    #[test]
    fn a_misspelled_field_of_each_model_names_the_nearest_field() {
        for (machine, text, wrong, near) in [
            (
                Machine::Pump,
                "model = \"karhula_pump\"\ncompression_ratio = 12\npolytropic_exponnet = 1.4",
                "polytropic_exponnet",
                "polytropic_exponent",
            ),
            (
                Machine::Engine,
                "model = \"karhula_engine\"\ncompression_ratio = 12\npolytropic_exponent = 1.4\npeak_presure = \"12 MPa\"\ncombustion_delay = 9.5",
                "peak_presure",
                "peak_pressure",
            ),
            (
                Machine::Engine,
                "model = \"closed_cycle\"\ncompression_ratio = 10\nlamda = 1.0",
                "lamda",
                "lambda",
            ),
            (
                Machine::Pump,
                "model = \"compressor\"\nsuction_pressure = \"1 bar\"\nsuction_temperature = \"20 °C\"\ndelivery_pressure = \"8 bar\"\nclearance_ration = 0.05\ncompression_exponent = 1.3",
                "clearance_ration",
                "clearance_ratio",
            ),
            (
                Machine::Pump,
                "model = \"pressure_trace\"\nfiles = \"trace.csv\"",
                "files",
                "file",
            ),
        ] {
            let e = error(machine, text);
            let model = text.lines().next().unwrap().replace("model", "gas.model");
            for part in [
                format!("gas.{wrong}: unknown field \"{wrong}\""),
                format!("did you mean \"{near}\"?"),
                format!("not an input of {model}"),
            ] {
                assert!(e.contains(&part), "{e}\nlacks: {part}");
            }
        }
    }

    #[test]
    fn a_misspelled_model_names_the_nearest_model() {
        let e = error(Machine::Pump, "model = \"karhula_pmup\"");
        assert!(e.contains("did you mean \"karhula_pump\"?"), "{e}");
    }

    /// The schema has a branch per model, `model` a constant in each, and every field of the
    /// model's table.
    #[test]
    fn the_schema_lists_every_model() {
        let mut generator = SchemaGenerator::default();
        let schema = gas_schema(&mut generator).to_value();
        let branches = schema["oneOf"].as_array().unwrap();
        assert_eq!(branches.len(), MODELS.len());
        for (branch, entry) in branches.iter().zip(MODELS) {
            assert_eq!(branch["properties"]["model"]["const"], entry.name);
            assert_eq!(branch["required"][0], "model");
            assert_eq!(branch["additionalProperties"], false, "{}", entry.name);
        }
        let pump = &branches[0]["properties"];
        assert!(pump.get("polytropic_exponent").is_some(), "{pump}");
    }
}
