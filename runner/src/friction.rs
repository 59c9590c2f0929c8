//! The `[friction]` and `[gear]` tables of a case: which loss model at which piston and joint,
//! converted to SI and validated once, here. Without `[friction]` a case has no losses; an
//! empty `[friction]` table is Karhula's (2008) App. 9.1 set ([`Friction::karhula`]).

use crate::case::{CaseError, Invalid};
use crate::units::{to_si, Dimension};
use cardan_dynamics::{Bearing, Friction, MeshLossModel, Rings, Skirt};
use cardan_friction::{
    PalmgrenCoefficients, RollingReading, SkfDeepGrooveBall, KARHULA_LOAD_CONSTANT,
};
use cardan_gears::mesh_loss::Reading;

/// The fields of `[friction]`, with their dimensions.
const FIELDS: [(&str, Dimension); 17] = [
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
];

/// The fields of `[gear]`.
const GEAR_FIELDS: [(&str, Dimension); 3] = [
    ("teeth", Dimension::Number),
    ("face_width", Dimension::Length),
    ("ring_addendum", Dimension::Number),
];

const BEARING_WORDS: &[&str] = &[
    "karhula",
    "palmgren",
    "skf",
    "petroff",
    "short_bearing",
    "none",
];

/// Reads `[friction]` (and `[gear]`, which only the mesh loss reads today) for a cylinder of
/// `bore` (m).
pub fn parse(
    table: &toml::Table,
    gear: Option<&toml::Table>,
    bore: f64,
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
                "must be a table of joint name = bearing model",
            ));
        };
        for (joint, v) in joints {
            match v.as_str() {
                Some(w) if BEARING_WORDS.contains(&w) => {
                    f.joint_bearings.push((joint.clone(), bearing(w)));
                }
                _ => {
                    return Err(invalid(
                        &format!("{path}.{joint}"),
                        v,
                        &one_of(BEARING_WORDS),
                    ))
                }
            }
        }
    }
    f.gear_mesh = match word("gear_mesh", &["karhula", "corrected", "none"], "karhula")?.as_str() {
        "none" => None,
        w => Some(gear_mesh(
            gear,
            if w == "karhula" {
                Reading::Karhula
            } else {
                Reading::Corrected
            },
            invalid,
        )?),
    };
    Ok(f)
}

/// The gear pair the mesh loss is computed on, from `[gear]`.
fn gear_mesh(
    gear: Option<&toml::Table>,
    reading: Reading,
    invalid: &Invalid,
) -> Result<MeshLossModel, CaseError> {
    let mut mesh = MeshLossModel {
        reading,
        ..Friction::karhula()
            .gear_mesh
            .expect("Karhula's set has a mesh loss")
    };
    let Some(gear) = gear else { return Ok(mesh) };
    for (key, value) in gear {
        let Some((_, dim)) = GEAR_FIELDS.iter().find(|(f, _)| f == key) else {
            return Err(invalid(
                &format!("gear.{key}"),
                value,
                &format!(
                    "unknown field: [gear] has {}",
                    GEAR_FIELDS.map(|(f, _)| f).join(", ")
                ),
            ));
        };
        let path = format!("gear.{key}");
        let x = to_si(value, *dim).map_err(|rule| invalid(&path, value, &rule))?;
        match key.as_str() {
            "teeth" => {
                if x.fract() != 0.0 || !(5.0..=1000.0).contains(&x) {
                    return Err(invalid(
                        &path,
                        value,
                        "must be a whole number from 5 to 1000",
                    ));
                }
                mesh.teeth = x as u32;
            }
            "face_width" => {
                if x <= 0.0 {
                    return Err(invalid(&path, value, "must be positive"));
                }
                mesh.face_width = Some(x);
            }
            _ => {
                if !(0.0..=1.5).contains(&x) {
                    return Err(invalid(
                        &path,
                        value,
                        "must be from 0 to 1.5 modules (1 is a full addendum)",
                    ));
                }
                mesh.ring_addendum = x;
            }
        }
    }
    Ok(mesh)
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
