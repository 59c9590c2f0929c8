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

/// A validated gas model of a case.
#[derive(Debug, Clone, PartialEq)]
pub enum GasModelCase {
    KarhulaPump(KarhulaPump),
    KarhulaEngine(KarhulaEngine),
    ClosedCycle(ClosedCycle),
    Compressor(Compressor),
}

/// How the clearance volume is given.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Clearance {
    /// Compression ratio ε = (V_stroke + V_comp)/V_comp.
    CompressionRatio(f64),
    /// Clearance ratio c = V_comp/V_stroke, which may be zero.
    ClearanceRatio(f64),
}

/// The gas of a case.
#[derive(Debug, Clone, PartialEq)]
pub struct GasCase {
    pub model: GasModelCase,
    pub clearance: Clearance,
}

impl GasCase {
    /// The model's name as written in case files.
    pub fn name(&self) -> &'static str {
        match self.model {
            GasModelCase::KarhulaPump(_) => "karhula_pump",
            GasModelCase::KarhulaEngine(_) => "karhula_engine",
            GasModelCase::ClosedCycle(_) => "closed_cycle",
            GasModelCase::Compressor(_) => "compressor",
        }
    }

    pub fn model(&self) -> &dyn GasModel {
        match &self.model {
            GasModelCase::KarhulaPump(m) => m,
            GasModelCase::KarhulaEngine(m) => m,
            GasModelCase::ClosedCycle(m) => m,
            GasModelCase::Compressor(m) => m,
        }
    }

    /// The cylinder of `bore` (m) shared by `pistons` pistons of `stroke` (m) each, with this
    /// case's clearance.
    pub fn cylinder(&self, bore: f64, stroke: f64, pistons: u32) -> Result<Cylinder, GasError> {
        let swept = f64::from(pistons) * std::f64::consts::PI / 4.0 * bore * bore * stroke;
        match self.clearance {
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

/// The models a `[gas]` table may name, with the machine each belongs to.
const MODELS: [(&str, Machine); 4] = [
    ("karhula_pump", Machine::Pump),
    ("karhula_engine", Machine::Engine),
    ("closed_cycle", Machine::Engine),
    ("compressor", Machine::Pump),
];

type Invalid<'a> = dyn Fn(&str, &dyn std::fmt::Display, &str) -> CaseError + 'a;

/// The keys of a `[gas]` table, read one by one; keys nobody read are reported.
struct Fields<'a> {
    table: &'a toml::Table,
    read: RefCell<Vec<&'static str>>,
    invalid: &'a Invalid<'a>,
}

impl Fields<'_> {
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
fn closed_cycle(f: &Fields) -> Result<ClosedCycle, CaseError> {
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

/// Validates a `[gas]` table for a case of `machine`.
pub(crate) fn parse(
    table: &toml::Table,
    machine: Machine,
    invalid: &Invalid,
) -> Result<GasCase, CaseError> {
    let names = || {
        MODELS
            .iter()
            .map(|(n, _)| format!("\"{n}\""))
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
    let Some(&(name, model_machine)) = MODELS.iter().find(|(n, _)| *n == name) else {
        return Err(invalid(
            "gas.model",
            &format!("\"{name}\""),
            &format!("unknown gas model: use one of {}", names()),
        ));
    };
    if model_machine != machine {
        return Err(invalid(
            "gas.model",
            &format!("\"{name}\""),
            &format!(
                "is a model of a {}: set machine = \"{}\"",
                model_machine.name(),
                model_machine.name()
            ),
        ));
    }
    let f = Fields {
        table,
        read: RefCell::new(Vec::new()),
        invalid,
    };
    let polytropic = || -> Result<Polytropic, CaseError> {
        Polytropic::new(
            f.required("polytropic_exponent", Dimension::Number)?,
            f.optional("filling", Dimension::Number)?.unwrap_or(1.0),
            f.optional("ambient_pressure", Dimension::Pressure)?
                .unwrap_or(101_325.0),
        )
        .map_err(|e| f.broken(e))
    };
    let compression_ratio = || {
        Ok(Clearance::CompressionRatio(
            f.required("compression_ratio", Dimension::Number)?,
        ))
    };
    let (model, clearance) = match name {
        "karhula_pump" => (
            GasModelCase::KarhulaPump(KarhulaPump { gas: polytropic()? }),
            compression_ratio()?,
        ),
        "karhula_engine" => {
            let mut engine = KarhulaEngine::new(
                polytropic()?,
                f.required("peak_pressure", Dimension::Pressure)?,
                f.required("combustion_delay", Dimension::Angle)?,
            )
            .map_err(|e| f.broken(e))?;
            f.read.borrow_mut().push("reading");
            engine.reading = match table.get("reading") {
                None => EngineReading::Direct,
                Some(v) => match v.as_str() {
                    Some("direct") => EngineReading::Direct,
                    Some("thesis") => EngineReading::Thesis,
                    _ => {
                        return Err(invalid(
                            "gas.reading",
                            v,
                            "must be \"direct\" (polytropic compression stroke) or \"thesis\" (the combustion pressure on the compression stroke too, as Karhula's work columns imply)",
                        ))
                    }
                },
            };
            (GasModelCase::KarhulaEngine(engine), compression_ratio()?)
        }
        "closed_cycle" => (
            GasModelCase::ClosedCycle(closed_cycle(&f)?),
            compression_ratio()?,
        ),
        "compressor" => {
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
            (
                GasModelCase::Compressor(compressor),
                Clearance::ClearanceRatio(f.required("clearance_ratio", Dimension::Number)?),
            )
        }
        _ => unreachable!("MODELS lists the models matched here"),
    };
    f.no_other_keys()?;
    let gas = GasCase { model, clearance };
    // The cylinder rules (compression ratio above 1, a compressor that delivers) do not
    // depend on its size.
    let cylinder = gas.cylinder(1.0, 1.0, 1).map_err(|e| f.broken(e))?;
    if let GasModelCase::Compressor(c) = &gas.model {
        c.steady_state(&cylinder).map_err(|e| f.broken(e))?;
    }
    Ok(gas)
}
