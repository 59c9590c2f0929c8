//! The `[gas]` table of a case: which gas model loads the pistons, with its inputs converted
//! to SI and validated once, here.

use crate::case::{CaseError, Machine};
use crate::units::{to_si, Dimension};
use cardan_gas::closed_cycle::ClosedCycle;
use cardan_gas::compressor::{Compressor, AIR_GAS_CONSTANT};
use cardan_gas::{
    Cylinder, EngineReading, GasError, GasModel, KarhulaEngine, KarhulaPump, Polytropic,
};
use std::cell::RefCell;
use std::path::Path;
use std::sync::Arc;

mod pressure_trace;

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

/// A gas model a `[gas]` table may name: adding one is a module with its reader and one line
/// in [`MODELS`].
pub struct GasEntry {
    /// `gas.model` in case files.
    pub name: &'static str,
    /// The machine it belongs to (`None`: either).
    pub machine: Option<Machine>,
    /// Reads the model's fields of the table (each read field is then known to the table's
    /// check of unknown keys), validated and in SI.
    read: fn(&Fields) -> Result<ReadModel, CaseError>,
}

/// The registry of gas models.
pub const MODELS: &[GasEntry] = &[
    GasEntry {
        name: "karhula_pump",
        machine: Some(Machine::Pump),
        read: karhula_pump,
    },
    GasEntry {
        name: "karhula_engine",
        machine: Some(Machine::Engine),
        read: karhula_engine,
    },
    GasEntry {
        name: "closed_cycle",
        machine: Some(Machine::Engine),
        read: closed_cycle,
    },
    GasEntry {
        name: "compressor",
        machine: Some(Machine::Pump),
        read: compressor,
    },
    pressure_trace::ENTRY,
];

type Invalid<'a> = dyn Fn(&str, &dyn std::fmt::Display, &str) -> CaseError + 'a;

/// The keys of a `[gas]` table, read one by one; keys nobody read are reported.
pub struct Fields<'a> {
    table: &'a toml::Table,
    read: RefCell<Vec<&'static str>>,
    invalid: &'a Invalid<'a>,
    /// The case file, which relative paths are taken from.
    file: &'a Path,
    machine: Machine,
}

impl Fields<'_> {
    /// A string field, if given (an error if it is not a string).
    fn text(&self, key: &'static str) -> Result<Option<&str>, CaseError> {
        self.read.borrow_mut().push(key);
        match self.table.get(key) {
            None => Ok(None),
            Some(toml::Value::String(s)) => Ok(Some(s)),
            Some(v) => Err((self.invalid)(&format!("gas.{key}"), v, "must be a string")),
        }
    }

    /// A rule of the model's broken by the value of `key`.
    fn refuse(&self, key: &str, value: &dyn std::fmt::Display, rule: &str) -> CaseError {
        (self.invalid)(&format!("gas.{key}"), value, rule)
    }

    fn optional(&self, key: &'static str, dim: Dimension) -> Result<Option<f64>, CaseError> {
        self.read.borrow_mut().push(key);
        self.table
            .get(key)
            .map(|v| to_si(v, dim).map_err(|rule| (self.invalid)(&format!("gas.{key}"), v, &rule)))
            .transpose()
    }

    fn required(&self, key: &'static str, dim: Dimension) -> Result<f64, CaseError> {
        self.optional(key, dim)?.ok_or_else(|| {
            (self.invalid)(
                &format!("gas.{key}"),
                &"(missing)",
                &format!("is required by gas.model = \"{}\"", self.model()),
            )
        })
    }

    fn model(&self) -> String {
        self.table
            .get("model")
            .and_then(|v| v.as_str())
            .unwrap_or_default()
            .to_string()
    }

    /// A model's rule broken: the field as the case file names it, with the value given.
    fn broken(&self, e: GasError) -> CaseError {
        let field = format!("gas.{}", e.field);
        match self.table.get(e.field) {
            Some(v) => (self.invalid)(&field, v, e.rule),
            None => (self.invalid)(&field, &e.value, e.rule),
        }
    }

    fn no_other_keys(&self) -> Result<(), CaseError> {
        let read = self.read.borrow();
        match self
            .table
            .keys()
            .find(|k| *k != "model" && !read.contains(&k.as_str()))
        {
            None => Ok(()),
            Some(k) => Err((self.invalid)(
                &format!("gas.{k}"),
                &self.table[k],
                &format!(
                    "is not an input of gas.model = \"{}\"; it takes: {}",
                    self.model(),
                    read.join(", ")
                ),
            )),
        }
    }
}

/// The closed-cycle model: every input optional, defaulting to Nunes (2017)'s (Table 3.2).
fn closed_cycle_inputs(f: &Fields) -> Result<ClosedCycle, CaseError> {
    use Dimension::*;
    let mut c = ClosedCycle::nunes_2017();
    let inputs: [(&'static str, Dimension, &mut f64); 21] = [
        ("ambient_pressure", Pressure, &mut c.ambient_pressure),
        (
            "ambient_temperature",
            Temperature,
            &mut c.ambient_temperature,
        ),
        ("wall_temperature", Temperature, &mut c.wall_temperature),
        ("gas_constant", GasConstant, &mut c.gas_constant),
        ("gamma", Number, &mut c.gamma),
        ("lambda", Number, &mut c.lambda),
        (
            "stoichiometric_air_fuel_ratio",
            Number,
            &mut c.stoichiometric_air_fuel_ratio,
        ),
        (
            "fuel_heating_value",
            SpecificEnergy,
            &mut c.fuel_heating_value,
        ),
        (
            "vaporisation_heat",
            SpecificEnergy,
            &mut c.vaporisation_heat,
        ),
        (
            "max_combustion_efficiency",
            Number,
            &mut c.max_combustion_efficiency,
        ),
        ("combustion_start", Angle, &mut c.combustion_start),
        (
            "combustion_start_per_speed",
            AnglePerSpeed,
            &mut c.combustion_start_per_speed,
        ),
        ("combustion_duration", Angle, &mut c.combustion_duration),
        (
            "combustion_duration_per_speed",
            AnglePerSpeed,
            &mut c.combustion_duration_per_speed,
        ),
        ("wiebe_a", Number, &mut c.wiebe_a),
        ("wiebe_m", Number, &mut c.wiebe_m),
        ("annand_a", Number, &mut c.annand_a),
        (
            "radiation_coefficient",
            Number,
            &mut c.radiation_coefficient,
        ),
        ("intake_closing", Angle, &mut c.intake_closing),
        ("exhaust_opening", Angle, &mut c.exhaust_opening),
        ("step", Angle, &mut c.step),
    ];
    for (key, dim, target) in inputs {
        if let Some(x) = f.optional(key, dim)? {
            *target = x;
        }
    }
    c.validate().map_err(|e| f.broken(e))?;
    Ok(c)
}

fn polytropic(f: &Fields) -> Result<Polytropic, CaseError> {
    Polytropic::new(
        f.required("polytropic_exponent", Dimension::Number)?,
        f.optional("filling", Dimension::Number)?.unwrap_or(1.0),
        f.optional("ambient_pressure", Dimension::Pressure)?
            .unwrap_or(101_325.0),
    )
    .map_err(|e| f.broken(e))
}

fn compression_ratio(f: &Fields) -> Result<Clearance, CaseError> {
    Ok(Clearance::CompressionRatio(
        f.required("compression_ratio", Dimension::Number)?,
    ))
}

/// Karhula's air pump (ch. 6.2).
fn karhula_pump(f: &Fields) -> Result<ReadModel, CaseError> {
    let gas = polytropic(f)?;
    Ok((Arc::new(KarhulaPump { gas }), compression_ratio(f)?))
}

/// Karhula's four-stroke engine (ch. 6.3), in its reading.
fn karhula_engine(f: &Fields) -> Result<ReadModel, CaseError> {
    let mut engine = KarhulaEngine::new(
        polytropic(f)?,
        f.required("peak_pressure", Dimension::Pressure)?,
        f.required("combustion_delay", Dimension::Angle)?,
    )
    .map_err(|e| f.broken(e))?;
    engine.reading = match f.text("reading")? {
        None | Some("direct") => EngineReading::Direct,
        Some("thesis") => EngineReading::Thesis,
        Some(other) => {
            return Err(f.refuse(
                "reading",
                &format!("\"{other}\""),
                "must be \"direct\" (polytropic compression stroke) or \"thesis\" (the combustion pressure on the compression stroke too, as Karhula's work columns imply)",
            ))
        }
    };
    Ok((Arc::new(engine), compression_ratio(f)?))
}

/// The closed cycle of Nunes (2017).
fn closed_cycle(f: &Fields) -> Result<ReadModel, CaseError> {
    let c = closed_cycle_inputs(f)?;
    Ok((Arc::new(c), compression_ratio(f)?))
}

/// A reciprocating compressor with its valves, in its periodic steady state.
fn compressor(f: &Fields) -> Result<ReadModel, CaseError> {
    let n_c = f.required("compression_exponent", Dimension::Number)?;
    let compressor = Compressor::new(
        f.required("suction_pressure", Dimension::Pressure)?,
        f.required("suction_temperature", Dimension::Temperature)?,
        f.required("delivery_pressure", Dimension::Pressure)?,
        n_c,
        f.optional("expansion_exponent", Dimension::Number)?
            .unwrap_or(n_c),
        f.optional("gas_constant", Dimension::GasConstant)?
            .unwrap_or(AIR_GAS_CONSTANT),
    )
    .map_err(|e| f.broken(e))?;
    let clearance = Clearance::ClearanceRatio(f.required("clearance_ratio", Dimension::Number)?);
    // A compressor must deliver, whatever its size.
    let cylinder = clearance.cylinder(1.0, 1.0, 1).map_err(|e| f.broken(e))?;
    compressor
        .steady_state(&cylinder)
        .map_err(|e| f.broken(e))?;
    Ok((Arc::new(compressor), clearance))
}

/// Validates a `[gas]` table of the case file `file`, a case of `machine`.
pub(crate) fn parse(
    table: &toml::Table,
    file: &Path,
    machine: Machine,
    invalid: &Invalid,
) -> Result<GasCase, CaseError> {
    let names = || {
        MODELS
            .iter()
            .map(|m| format!("\"{}\"", m.name))
            .collect::<Vec<_>>()
            .join(", ")
    };
    let name = match table.get("model") {
        Some(toml::Value::String(s)) => s.as_str(),
        Some(v) => {
            return Err(invalid(
                "gas.model",
                v,
                &format!("must be one of {}", names()),
            ))
        }
        None => {
            return Err(invalid(
                "gas.model",
                &"(missing)",
                &format!("is required: one of {}", names()),
            ))
        }
    };
    let Some(entry) = MODELS.iter().find(|m| m.name == name) else {
        return Err(invalid(
            "gas.model",
            &format!("\"{name}\""),
            &format!("unknown gas model: use one of {}", names()),
        ));
    };
    if let Some(own) = entry.machine.filter(|&m| m != machine) {
        return Err(invalid(
            "gas.model",
            &format!("\"{name}\""),
            &format!(
                "is a model of a {}: set machine = \"{}\"",
                own.name(),
                own.name()
            ),
        ));
    }
    let f = Fields {
        table,
        read: RefCell::new(Vec::new()),
        invalid,
        file,
        machine,
    };
    let (model, clearance) = (entry.read)(&f)?;
    f.no_other_keys()?;
    // The cylinder rules (a compression ratio above 1) do not depend on its size.
    clearance.cylinder(1.0, 1.0, 1).map_err(|e| f.broken(e))?;
    Ok(GasCase {
        name: entry.name,
        model,
        clearance,
    })
}
