//! The `[gas]` table of a case: which gas model loads the pistons, with its inputs converted
//! to SI and validated once, here.
//!
//! `model` picks a [`GasEntry`] of [`MODELS`]; the rest of the table is that model's typed
//! table (a struct with `deny_unknown_fields`, one module per model), read by
//! [`crate::schema::read`], then built into the model by [`ModelTable::build`], which checks
//! the rules that join fields (through the gas crate's own checks, naming the field).

use crate::error::{CaseError, Machine};
use crate::read_once::ReadOnce;
use cardan_gas::{Cylinder, GasError, GasModel};
use schemars::{json_schema, Schema, SchemaGenerator};
use std::path::Path;
use std::sync::Arc;

mod closed_cycle;
mod compressor;
mod karhula;
mod model;
mod pressure_trace;

pub use closed_cycle::ClosedCycleTable;
pub use compressor::CompressorTable;
pub use karhula::{KarhulaEngineTable, KarhulaPumpTable};
pub use model::{entry, Clearance, Context, GasEntry, ModelTable, ReadModel};
pub use pressure_trace::PressureTraceTable;

/// The gas of a case.
#[derive(Clone)]
pub struct GasCase {
    /// The registry's name of the model (`gas.model`).
    name: &'static str,
    model: Arc<dyn GasModel + Send>,
    pub clearance: Clearance,
    /// The files the model read: each as named in `[gas]` and the digest of its bytes.
    pub files: Vec<(String, String)>,
}

impl std::fmt::Debug for GasCase {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("GasCase")
            .field("model", &self.name)
            .field("clearance", &self.clearance)
            .field("files", &self.files)
            .finish()
    }
}

impl GasCase {
    /// The model's name as written in case files.
    pub fn name(&self) -> &'static str {
        self.name
    }

    /// Whether its cycle takes two crank turns (the entry's `four_stroke`).
    pub fn four_stroke(&self) -> bool {
        MODELS.iter().any(|m| m.name == self.name && m.four_stroke)
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

/// The registry of gas models.
pub const MODELS: &[GasEntry] = &[
    karhula::PUMP,
    karhula::ENGINE,
    closed_cycle::ENTRY,
    compressor::ENTRY,
    pressure_trace::ENTRY,
];

/// Validates a `[gas]` table of the case `case` of the file `file`, a case of `machine`.
pub fn parse(
    table: &toml::Table,
    file: &Path,
    case: &str,
    (machine, read_once): (Machine, &ReadOnce),
) -> Result<GasCase, CaseError> {
    let mut cx = Context {
        table,
        file,
        case,
        machine,
        model: "",
        files: Default::default(),
        read_once,
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
        files: cx.files.into_inner(),
    })
}

/// Makes the gas ready for every crank train of a case as its run does (the cylinder of `bore`
/// shared by `pistons` pistons of each mechanism's stroke, its chamber with the trains' lead
/// `crank_phase`, the model prepared at the mean crank speed `speed`), so that a case `cardan
/// check` passes is not refused by its gas before stepping. A model's error names the `[gas]`
/// field as written (`table`); one about the cylinder's size (its bore, swept or chamber volume,
/// which the case does not give) is returned as `Err(Ok(error))` for the caller to say in the
/// geometry's fields.
#[allow(clippy::too_many_arguments)]
pub fn check_ready(
    gas: &GasCase,
    table: &toml::Table,
    (file, case, machine): (&Path, &str, Machine),
    mechanisms: &[Arc<dyn cardan_mechanism::Mechanism>],
    (bore, pistons, crank_phase): (f64, u32, f64),
    speed: f64,
) -> Result<(), Result<GasError, CaseError>> {
    let read_once = ReadOnce::default();
    let cx = Context {
        table,
        file,
        case,
        machine,
        model: gas.name,
        files: Default::default(),
        read_once: &read_once,
    };
    for mechanism in mechanisms {
        let ready = gas
            .cylinder(bore, mechanism.stroke(), pistons)
            .and_then(|cylinder| {
                cylinder.with_phased_chamber(mechanism.as_ref(), crank_phase, |chamber| {
                    gas.model().prepare(*chamber, speed).map(|_| ())
                })
            });
        match ready {
            Ok(()) => {}
            Err(e) if matches!(e.field, "bore" | "swept_volume" | "volume" | "speed") => {
                return Err(Ok(e))
            }
            // The compression ratio's rules, when the case gives the clearance ratio instead.
            Err(e) if e.field == "compression_ratio" && !table.contains_key(e.field) => {
                let field = if table.contains_key("clearance_ratio") {
                    "clearance_ratio"
                } else {
                    e.field
                };
                let value = table
                    .get(field)
                    .map_or(e.value.to_string(), |v| v.to_string());
                return Err(Err(cx.refuse(field, &value, e.rule)));
            }
            Err(e) => return Err(Err(cx.broken(e))),
        }
    }
    Ok(())
}

/// The JSON Schema of `[gas]`: `model` one of the registered models' names (an `enum`, so that
/// an editor names them at a misspelled model, issue 38.5), and for each model an `if`/`then`
/// whose `then` is the model's table with `model` as a constant (its fields, and no other).
pub fn gas_schema(generator: &mut SchemaGenerator) -> Schema {
    let names: Vec<&str> = MODELS.iter().map(|entry| entry.name).collect();
    let branches: Vec<serde_json::Value> = MODELS
        .iter()
        .map(|entry| {
            let mut branch = (entry.schema)(generator);
            let machine = match entry.machine {
                Some(Machine::Engine) => " (an engine model)".to_string(),
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
            serde_json::json!({
                "if": {
                    "properties": { "model": { "const": entry.name } },
                    "required": ["model"],
                },
                "then": branch.to_value(),
            })
        })
        .collect();
    json_schema!({
        "description": "The gas that loads the pistons: `model` names one of the registered models, whose fields follow.",
        "type": "object",
        "properties": {
            "model": {
                "description": format!("The gas model: {}.", names.join(", ")),
                "enum": names,
            }
        },
        "required": ["model"],
        "allOf": branches,
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
            let case = parse(gas, &file, "shipped", (machine, &ReadOnce::default()))
                .unwrap_or_else(|e| panic!("{}: {e}", file.display()));
            assert_eq!(Some(case.name()), gas.get("model").and_then(|m| m.as_str()));
            read += 1;
        }
        assert!(read >= 5, "{read} shipped cases with [gas]");
    }

    fn error(machine: Machine, text: &str) -> String {
        let table: toml::Table = toml::from_str(text).unwrap();
        parse(
            &table,
            Path::new("c.toml"),
            "c",
            (machine, &ReadOnce::default()),
        )
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

    /// The schema names every model in `model`'s `enum`, and has an `if`/`then` per model:
    /// `model` a constant in each, and every field of the model's table.
    #[test]
    fn the_schema_lists_every_model() {
        let mut generator = SchemaGenerator::default();
        let schema = gas_schema(&mut generator).to_value();
        let names: Vec<&str> = MODELS.iter().map(|m| m.name).collect();
        assert_eq!(
            schema["properties"]["model"]["enum"],
            serde_json::json!(names)
        );
        let branches = schema["allOf"].as_array().unwrap();
        assert_eq!(branches.len(), MODELS.len());
        for (branch, entry) in branches.iter().zip(MODELS) {
            assert_eq!(branch["if"]["properties"]["model"]["const"], entry.name);
            let then = &branch["then"];
            assert_eq!(then["properties"]["model"]["const"], entry.name);
            assert_eq!(then["required"][0], "model");
            assert_eq!(then["additionalProperties"], false, "{}", entry.name);
        }
        let pump = &branches[0]["then"]["properties"];
        assert!(pump.get("polytropic_exponent").is_some(), "{pump}");
    }
}
