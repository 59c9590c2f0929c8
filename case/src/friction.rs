//! The `[friction]` table of a case: which loss model at which piston and joint,
//! converted to SI and validated once, here. Without `[friction]` a case has no losses; an
//! empty `[friction]` table is Karhula's (2008) App. 9.1 set ([`Friction::karhula`]). An
//! engine's `[friction]` also reads the engine components (valve train, accessories, pumping;
//! all off by default) and the settings of the fmep cross-check
//! ([`cardan_dynamics::EngineLosses`]).

use crate::case::{CaseError, Invalid, Machine};
use crate::gas::{Clearance, GasCase};
use crate::units::{to_si, Dimension};
use cardan_dynamics::engine_losses::AMBIENT_PRESSURE;
use cardan_dynamics::{
    Bearing, BearingSize, EngineLosses, FmepModel, FollowerContact, Friction, GearSpec,
    MeshLossModel, Rings, Skirt, ValveTrain,
};
use cardan_friction::{
    PalmgrenCoefficients, RollingReading, SkfDeepGrooveBall, KARHULA_LOAD_CONSTANT,
};
use cardan_gears::mesh_loss::Reading;

/// The fields of `[friction]`, with their dimensions.
const FIELDS: [(&str, Dimension); 24] = [
    ("rings", Dimension::Number),
    ("ring_friction_coefficient", Dimension::Number),
    ("ring_crown_height", Dimension::Length),
    ("skirt", Dimension::Number),
    ("skirt_friction_coefficient", Dimension::Number),
    ("skirt_length", Dimension::Length),
    ("skirt_clearance", Dimension::Length),
    ("slide_friction_coefficient", Dimension::Number),
    ("bearings", Dimension::Number),
    ("lubrication_factor", Dimension::Number),
    ("bearing_load_constant", Dimension::Number),
    ("journal_length_ratio", Dimension::Number),
    ("journal_clearance_ratio", Dimension::Number),
    ("gear_mesh", Dimension::Number),
    ("oil_viscosity", Dimension::KinematicViscosity),
    ("oil_density", Dimension::Density),
    ("joints", Dimension::Number),
    ("valve_train", Dimension::Number),
    ("cam_friction_coefficient", Dimension::Number),
    ("valve_spring_speed", Dimension::AngularSpeed),
    ("accessories", Dimension::Number),
    ("pumping", Dimension::Number),
    ("intake_pressure", Dimension::Pressure),
    ("fmep_model", Dimension::Number),
];

/// The fields only an engine reads.
const ENGINE_FIELDS: [&str; 7] = [
    "valve_train",
    "cam_friction_coefficient",
    "valve_spring_speed",
    "accessories",
    "pumping",
    "intake_pressure",
    "fmep_model",
];

/// Compression ratio of the PNH gas-loading term when the case has no gas model that gives one.
const DEFAULT_COMPRESSION_RATIO: f64 = 10.0;

const BEARING_WORDS: &[&str] = &[
    "karhula",
    "palmgren",
    "skf",
    "petroff",
    "short_bearing",
    "none",
];

/// Reads `[friction]`, its mesh loss on the pair of `[gear]` (`gear`), for a cylinder of
/// `bore` (m) of a `machine`; an engine's compression ratio (for the fmep cross-check) comes
/// from its `gas` model.
pub fn parse(
    table: &toml::Table,
    gear: Option<&GearSpec>,
    bore: f64,
    machine: Machine,
    gas: Option<&GasCase>,
    invalid: &Invalid,
) -> Result<Friction, CaseError> {
    for (key, value) in table {
        if !FIELDS.iter().any(|(f, _)| f == key) {
            return Err(invalid(
                &format!("friction.{key}"),
                value,
                &format!(
                    "unknown field: [friction] has {}",
                    FIELDS.map(|(f, _)| f).join(", ")
                ),
            ));
        }
    }
    let field = |name: &str| table.get(name).map(|v| (format!("friction.{name}"), v));
    let number = |name: &str, default: f64, positive: bool| -> Result<f64, CaseError> {
        let dim = FIELDS
            .iter()
            .find(|(f, _)| *f == name)
            .map_or(Dimension::Number, |(_, d)| *d);
        match field(name) {
            None => Ok(default),
            Some((path, v)) => {
                let x = to_si(v, dim).map_err(|rule| invalid(&path, v, &rule))?;
                if positive && x <= 0.0 {
                    Err(invalid(&path, v, "must be positive"))
                } else if x < 0.0 {
                    Err(invalid(&path, v, "must not be negative"))
                } else {
                    Ok(x)
                }
            }
        }
    };
    let word = |name: &str, words: &[&str], default: &'static str| -> Result<String, CaseError> {
        match field(name) {
            None => Ok(default.to_string()),
            Some((path, v)) => match v.as_str() {
                Some(w) if words.contains(&w) => Ok(w.to_string()),
                _ => Err(invalid(&path, v, &one_of(words))),
            },
        }
    };

    let mut f = Friction::karhula();
    f.oil.kinematic_viscosity = number("oil_viscosity", f.oil.kinematic_viscosity, true)?;
    f.oil.density = number("oil_density", f.oil.density, true)?;
    f.rings = match word("rings", &["karhula", "film", "none"], "karhula")?.as_str() {
        "karhula" => Some(Rings::Karhula {
            friction_coefficient: number("ring_friction_coefficient", 0.07, false)?,
        }),
        "film" => Some(Rings::Film {
            crown_height: number("ring_crown_height", 5e-6, true)?,
        }),
        _ => None,
    };
    f.skirt = match word("skirt", &["karhula", "viscous", "none"], "karhula")?.as_str() {
        "karhula" => Some(Skirt::Coulomb {
            friction_coefficient: number("skirt_friction_coefficient", 0.09, false)?,
        }),
        // Thai thesis example proportions: a skirt of 0.6 bore and 20 µm clearance.
        "viscous" => Some(Skirt::Viscous {
            length: number("skirt_length", 0.6 * bore, true)?,
            clearance: number("skirt_clearance", 20e-6, true)?,
        }),
        _ => None,
    };
    f.slide_friction_coefficient = number(
        "slide_friction_coefficient",
        f.slide_friction_coefficient,
        false,
    )?;
    let f0 = number("lubrication_factor", 2.0, true)?;
    let load_constant = number("bearing_load_constant", KARHULA_LOAD_CONSTANT, true)?;
    let length_ratio = number("journal_length_ratio", 0.5, true)?;
    let clearance_ratio = number("journal_clearance_ratio", 1e-3, true)?;
    let bearing = |w: &str| match w {
        "karhula" => Some(Bearing::Rolling(RollingReading::Karhula {
            f0,
            load_constant,
        })),
        "palmgren" => Some(Bearing::Rolling(RollingReading::Palmgren(
            PalmgrenCoefficients {
                f0,
                ..PalmgrenCoefficients::DEEP_GROOVE_BALL
            },
        ))),
        "skf" => Some(Bearing::Rolling(RollingReading::Skf(
            SkfDeepGrooveBall::SERIES_62,
        ))),
        "petroff" | "short_bearing" => Some(Bearing::Journal {
            short_bearing: w == "short_bearing",
            length_ratio,
            clearance_ratio,
        }),
        _ => None,
    };
    f.bearings = bearing(&word("bearings", BEARING_WORDS, "karhula")?);
    if let Some((path, v)) = field("joints") {
        let Some(joints) = v.as_table() else {
            return Err(invalid(
                &path,
                v,
                "must be a table of joint name = bearing model, or joint name = { model, pitch_diameter, static_load_rating, count }",
            ));
        };
        for (joint, v) in joints {
            let at = format!("{path}.{joint}");
            let model = |v: &toml::Value, at: &str| match v.as_str() {
                Some(w) if BEARING_WORDS.contains(&w) => Ok(bearing(w)),
                _ => Err(invalid(at, v, &one_of(BEARING_WORDS))),
            };
            // A model name, or a table of a model and catalogue values.
            let Some(t) = v.as_table() else {
                f.joint_bearings.push((joint.clone(), model(v, &at)?));
                continue;
            };
            let mut size = BearingSize::default();
            for (key, value) in t {
                let field = format!("{at}.{key}");
                let positive = |dim: Dimension| {
                    let x = to_si(value, dim).map_err(|rule| invalid(&field, value, &rule))?;
                    if x > 0.0 {
                        Ok(x)
                    } else {
                        Err(invalid(&field, value, "must be positive"))
                    }
                };
                match key.as_str() {
                    "model" => f.joint_bearings.push((joint.clone(), model(value, &field)?)),
                    "pitch_diameter" => size.pitch_diameter = Some(positive(Dimension::Length)?),
                    "static_load_rating" => {
                        size.static_load_rating = Some(positive(Dimension::Force)?)
                    }
                    "count" => {
                        let x = positive(Dimension::Number)?;
                        if x.fract() != 0.0 || x > 16.0 {
                            return Err(invalid(&field, value, "must be a whole number from 1 to 16"));
                        }
                        size.count = Some(x as u32);
                    }
                    _ => {
                        return Err(invalid(
                            &field,
                            value,
                            "unknown field: a joint's table has model, pitch_diameter, static_load_rating, count",
                        ))
                    }
                }
            }
            f.joint_sizes.push((joint.clone(), size));
        }
    }
    f.engine = match machine {
        Machine::Engine => Some(engine(table, gas, &number, &word, invalid)?),
        Machine::Pump => {
            if let Some(key) = ENGINE_FIELDS.iter().find(|k| table.contains_key(**k)) {
                return Err(invalid(
                    &format!("friction.{key}"),
                    &table[*key],
                    "only an engine has a valve train, accessories and pumping losses (and an fmep): this case has machine = \"pump\"",
                ));
            }
            None
        }
    };
    f.gear_mesh = match word("gear_mesh", &["karhula", "corrected", "none"], "karhula")?.as_str() {
        "none" => None,
        w => Some(MeshLossModel {
            reading: if w == "karhula" {
                Reading::Karhula
            } else {
                Reading::Corrected
            },
            pair: gear.copied().unwrap_or_default(),
        }),
    };
    Ok(f)
}

/// Reads a number field of `[friction]`: (name, default, must be positive).
type NumberField<'a> = dyn Fn(&str, f64, bool) -> Result<f64, CaseError> + 'a;

/// Reads a word field of `[friction]`: (name, the words it may be, default).
type WordField<'a> = dyn Fn(&str, &[&str], &'static str) -> Result<String, CaseError> + 'a;

/// The engine components of `[friction]` (every one off by default) and the settings of the
/// fmep cross-check.
fn engine(
    table: &toml::Table,
    gas: Option<&GasCase>,
    number: &NumberField,
    word: &WordField,
    invalid: &Invalid,
) -> Result<EngineLosses, CaseError> {
    let flag = |name: &str| -> Result<bool, CaseError> {
        match table.get(name) {
            None => Ok(false),
            Some(v) => v
                .as_bool()
                .ok_or_else(|| invalid(&format!("friction.{name}"), v, "must be true or false")),
        }
    };
    let mut e = EngineLosses::off();
    if let Some(Clearance::CompressionRatio(r)) = gas.map(|g| g.clearance) {
        e.compression_ratio = r;
    } else {
        e.compression_ratio = DEFAULT_COMPRESSION_RATIO;
    }
    let train = word("valve_train", &["none", "flat", "roller"], "none")?;
    // A field that only one valve train reads is an error with any other.
    let only = |name: &str, rule: &str| -> Result<(), CaseError> {
        match table.get(name) {
            Some(v) => Err(invalid(&format!("friction.{name}"), v, rule)),
            None => Ok(()),
        }
    };
    e.valve_train = match train.as_str() {
        "none" => {
            for name in ["cam_friction_coefficient", "valve_spring_speed"] {
                only(
                    name,
                    "is read only with valve_train = \"flat\" or \"roller\" (the valve train is off)",
                )?;
            }
            None
        }
        w => {
            let follower = if w == "flat" {
                FollowerContact::Flat {
                    friction_coefficient: number("cam_friction_coefficient", 0.08, false)?,
                }
            } else {
                only(
                    "cam_friction_coefficient",
                    "is read only with valve_train = \"flat\" (a roller follower rolls: its loss is rolling resistance and the roller's pin bearing)",
                )?;
                FollowerContact::ROLLER
            };
            let mut v = ValveTrain::new(follower);
            v.spring_speed = number("valve_spring_speed", v.spring_speed, true)?;
            Some(v)
        }
    };
    e.accessories = flag("accessories")?;
    e.pumping = flag("pumping")?;
    e.intake_pressure = number("intake_pressure", AMBIENT_PRESSURE, true)?;
    if let Some(v) = table.get("intake_pressure") {
        let pa = e.ambient_pressure;
        if !(e.intake_pressure > 0.1 * pa && e.intake_pressure <= pa) {
            return Err(invalid(
                "friction.intake_pressure",
                v,
                &format!(
                    "must be above 0.1 × ambient ({} Pa, where Bishop's standard imep is zero) and at most ambient ({pa} Pa: wide-open throttle; Bishop's engines are not boosted)",
                    0.1 * pa
                ),
            ));
        }
    }
    e.fmep_model = match word(
        "fmep_model",
        &["sandoval_heywood", "pnh"],
        "sandoval_heywood",
    )?
    .as_str()
    {
        "pnh" => FmepModel::Pnh1989,
        _ => FmepModel::SandovalHeywood2003,
    };
    Ok(e)
}

fn one_of(words: &[&str]) -> String {
    format!(
        "must be one of {}",
        words
            .iter()
            .map(|w| format!("\"{w}\""))
            .collect::<Vec<_>>()
            .join(", ")
    )
}
