//! Case files: TOML in, a validated [`Case`] out. Every rule a value breaks is reported with
//! the file, the case, the field, the rule and the value.

use crate::gas::GasCase;
use crate::units::{to_si, Dimension};
use cardan_dynamics::{MassProperties, Material};
use cardan_mechanism::{
    CardanGear, CrankMotion, GeometryError, Mechanism, MechanismKind, SliderCrank,
};
use serde::Deserialize;
use std::path::{Path, PathBuf};

/// Why a case file could not become a case.
#[derive(Debug, thiserror::Error)]
pub enum CaseError {
    #[error("{file}: cannot read: {source}")]
    Io {
        file: PathBuf,
        source: std::io::Error,
    },
    /// TOML syntax, a missing field, an unknown key or a value of the wrong type; the message
    /// is the TOML reader's, with the line and column.
    #[error("{file}: {message}")]
    Syntax { file: PathBuf, message: String },
    #[error("{file}: case \"{case}\": {field} = {value}: {rule}")]
    Invalid {
        file: PathBuf,
        case: String,
        field: String,
        value: String,
        rule: String,
    },
}

/// Pump or engine: what the gas does (used by the gas models).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Machine {
    Pump,
    Engine,
}

impl Machine {
    pub fn name(self) -> &'static str {
        match self {
            Machine::Pump => "pump",
            Machine::Engine => "engine",
        }
    }
}

/// Geometry shared by the mechanisms of a case, SI.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Geometry {
    /// Slider-crank crank length, m; the cardan crank is half of it.
    pub crank_length: f64,
    /// Rod length, m.
    pub rod_length: f64,
    /// Bore, m.
    pub bore: f64,
    /// Slider-crank piston-pin offset, m.
    pub pin_offset: f64,
    /// Pistons sharing one cylinder: 1, or 2 for the opposed-piston layout (two identical
    /// mirrored crank trains, no cylinder head, Nunes 2017). The case runs one crank train;
    /// the other carries the same loads.
    pub pistons: u32,
}

/// One mechanism of a case, ready to run.
#[derive(Debug, Clone, PartialEq)]
pub struct MechanismCase {
    pub kind: MechanismKind,
    pub masses: MassProperties,
    pub rod_material: Material,
    pub slider_crank: Option<SliderCrank>,
    pub cardan_gear: Option<CardanGear>,
}

impl MechanismCase {
    pub fn mechanism(&self) -> &dyn Mechanism {
        match (&self.slider_crank, &self.cardan_gear) {
            (Some(m), _) => m,
            (_, Some(m)) => m,
            _ => unreachable!("a mechanism case holds its mechanism"),
        }
    }
}

/// A validated case.
#[derive(Debug, Clone, PartialEq)]
pub struct Case {
    pub file: PathBuf,
    pub name: String,
    pub machine: Machine,
    pub geometry: Geometry,
    pub motion: CrankMotion,
    /// Crank angle at the end of the run, rad.
    pub end_angle: f64,
    /// Number of crank-angle intervals; the run has steps + 1 points.
    pub steps: usize,
    pub mechanisms: Vec<MechanismCase>,
    /// The gas loading the pistons; without it the run has inertial loads only.
    pub gas: Option<GasCase>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawCase {
    name: String,
    machine: String,
    mechanisms: Vec<String>,
    geometry: RawGeometry,
    motion: RawMotion,
    masses: Option<RawMasses>,
    gas: Option<toml::Table>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawGeometry {
    crank_length: toml::Value,
    rod_length: toml::Value,
    bore: toml::Value,
    pin_offset: Option<toml::Value>,
    opposed_pistons: Option<bool>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawMotion {
    start_angle: toml::Value,
    end_angle: toml::Value,
    initial_speed: toml::Value,
    angular_acceleration: toml::Value,
    steps: i64,
}

/// `[masses]` applies to every mechanism; `[masses.slider_crank]` and `[masses.cardan_gear]`
/// override it for one.
#[derive(Deserialize, Default, Clone)]
#[serde(deny_unknown_fields)]
struct RawMasses {
    rod_material: Option<String>,
    crankshaft_inertia: Option<toml::Value>,
    wheel_inertia: Option<toml::Value>,
    rod_mass: Option<toml::Value>,
    rod_inertia: Option<toml::Value>,
    rod_cg: Option<toml::Value>,
    piston_mass: Option<toml::Value>,
    slider_crank: Option<Box<RawMasses>>,
    cardan_gear: Option<Box<RawMasses>>,
}

/// Reads one optional field of a `[masses]` table.
type Getter = fn(&RawMasses) -> Option<&toml::Value>;

/// Largest accepted number of steps: 10 million points of about 1 kB of state each.
pub const MAX_STEPS: i64 = 10_000_000;

/// Reads and validates one case file.
pub fn load(file: &Path) -> Result<Case, CaseError> {
    let text = std::fs::read_to_string(file).map_err(|source| CaseError::Io {
        file: file.into(),
        source,
    })?;
    parse(file, &text)
}

/// Validates the text of a case file; `file` is only for the messages.
pub fn parse(file: &Path, text: &str) -> Result<Case, CaseError> {
    let raw: RawCase = toml::from_str(text).map_err(|e| CaseError::Syntax {
        file: file.into(),
        message: e.to_string().trim_end().to_string(),
    })?;
    let case_name = raw.name.clone();
    let invalid = |field: &str, value: &dyn std::fmt::Display, rule: &str| CaseError::Invalid {
        file: file.into(),
        case: case_name.clone(),
        field: field.to_string(),
        value: value.to_string(),
        rule: rule.to_string(),
    };
    if raw.name.is_empty()
        || raw.name.starts_with('.')
        || !raw
            .name
            .chars()
            .all(|c| c.is_ascii_alphanumeric() || "-_.".contains(c))
    {
        return Err(invalid("name", &format!("\"{}\"", raw.name), "must be a non-empty folder name of letters, digits, '-', '_' and '.', not starting with '.'"));
    }
    let machine = match raw.machine.as_str() {
        "pump" => Machine::Pump,
        "engine" => Machine::Engine,
        other => {
            return Err(invalid(
                "machine",
                &format!("\"{other}\""),
                "must be \"pump\" or \"engine\"",
            ))
        }
    };
    let quantity = |field: &str, value: &toml::Value, dim: Dimension| {
        to_si(value, dim).map_err(|rule| invalid(field, value, &rule))
    };
    let positive = |field: &str, value: &toml::Value, dim: Dimension| {
        let x = quantity(field, value, dim)?;
        if x > 0.0 {
            Ok(x)
        } else {
            Err(invalid(field, value, "must be positive"))
        }
    };

    let g = &raw.geometry;
    let geometry = Geometry {
        crank_length: positive("geometry.crank_length", &g.crank_length, Dimension::Length)?,
        rod_length: positive("geometry.rod_length", &g.rod_length, Dimension::Length)?,
        bore: positive("geometry.bore", &g.bore, Dimension::Length)?,
        pin_offset: match &g.pin_offset {
            Some(v) => quantity("geometry.pin_offset", v, Dimension::Length)?,
            None => 0.0,
        },
        pistons: if g.opposed_pistons == Some(true) {
            2
        } else {
            1
        },
    };
    if geometry.rod_length <= geometry.crank_length {
        return Err(invalid(
            "geometry.rod_length",
            &g.rod_length,
            &format!("must be longer than geometry.crank_length ({} m): a rod no longer than its crank cannot turn it", geometry.crank_length),
        ));
    }

    let m = &raw.motion;
    let start_angle = quantity("motion.start_angle", &m.start_angle, Dimension::Angle)?;
    let end_angle = quantity("motion.end_angle", &m.end_angle, Dimension::Angle)?;
    if end_angle <= start_angle {
        return Err(invalid(
            "motion.end_angle",
            &m.end_angle,
            "must be greater than motion.start_angle",
        ));
    }
    let motion = CrankMotion {
        start_angle,
        initial_speed: quantity(
            "motion.initial_speed",
            &m.initial_speed,
            Dimension::AngularSpeed,
        )?,
        angular_acceleration: quantity(
            "motion.angular_acceleration",
            &m.angular_acceleration,
            Dimension::AngularAcceleration,
        )?,
    };
    if let Err(e) = motion.at_angle(end_angle) {
        return Err(invalid(
            "motion.initial_speed",
            &m.initial_speed,
            &e.to_string(),
        ));
    }
    if !(8..=MAX_STEPS).contains(&m.steps) {
        return Err(invalid(
            "motion.steps",
            &m.steps,
            &format!("must be an integer from 8 to {MAX_STEPS}"),
        ));
    }

    if raw.mechanisms.is_empty() {
        return Err(invalid(
            "mechanisms",
            &"[]",
            "must list at least one of \"slider_crank\", \"cardan_gear\"",
        ));
    }
    let raw_masses = raw.masses.clone().unwrap_or_default();
    if raw_masses
        .slider_crank
        .as_ref()
        .is_some_and(|s| s.slider_crank.is_some() || s.cardan_gear.is_some())
        || raw_masses
            .cardan_gear
            .as_ref()
            .is_some_and(|s| s.slider_crank.is_some() || s.cardan_gear.is_some())
    {
        return Err(invalid(
            "masses",
            &"nested tables",
            "mechanism tables cannot nest: use [masses.slider_crank] and [masses.cardan_gear]",
        ));
    }
    let mut mechanisms = Vec::new();
    for name in &raw.mechanisms {
        let Some(kind) = MechanismKind::from_name(name) else {
            return Err(invalid(
                "mechanisms",
                &format!("\"{name}\""),
                "unknown mechanism: use \"slider_crank\" or \"cardan_gear\"",
            ));
        };
        if mechanisms.iter().any(|c: &MechanismCase| c.kind == kind) {
            return Err(invalid(
                "mechanisms",
                &format!("\"{name}\""),
                "is listed twice",
            ));
        }
        let specific = match kind {
            MechanismKind::SliderCrank => raw_masses.slider_crank.as_deref(),
            MechanismKind::CardanGear => raw_masses.cardan_gear.as_deref(),
        };
        // The mechanism's own table wins over the common one.
        let pick = |get: fn(&RawMasses) -> Option<&toml::Value>,
                    field: &str|
         -> (Option<toml::Value>, String) {
            match specific.and_then(get) {
                Some(v) => (Some(v.clone()), format!("masses.{}.{field}", kind.name())),
                None => (get(&raw_masses).cloned(), format!("masses.{field}")),
            }
        };
        let (material_name, material_field) = match specific.and_then(|s| s.rod_material.clone()) {
            Some(v) => (Some(v), format!("masses.{}.rod_material", kind.name())),
            None => (
                raw_masses.rod_material.clone(),
                "masses.rod_material".to_string(),
            ),
        };
        let rod_material = match material_name {
            None => Material::Steel,
            Some(n) => match Material::from_name(&n) {
                Some(Material::Aluminium) | None => {
                    return Err(invalid(
                        &material_field,
                        &format!("\"{n}\""),
                        "must be \"steel\" or \"titanium\"",
                    ))
                }
                Some(mat) => mat,
            },
        };
        let mut masses = MassProperties::estimate(
            kind,
            geometry.crank_length,
            geometry.rod_length,
            geometry.bore,
            rod_material,
        );
        let overrides: [(Getter, &str, Dimension, &mut f64); 6] = [
            (
                |r| r.crankshaft_inertia.as_ref(),
                "crankshaft_inertia",
                Dimension::Inertia,
                &mut masses.crankshaft_inertia,
            ),
            (
                |r| r.wheel_inertia.as_ref(),
                "wheel_inertia",
                Dimension::Inertia,
                &mut masses.wheel_inertia,
            ),
            (
                |r| r.rod_mass.as_ref(),
                "rod_mass",
                Dimension::Mass,
                &mut masses.rod_mass,
            ),
            (
                |r| r.rod_inertia.as_ref(),
                "rod_inertia",
                Dimension::Inertia,
                &mut masses.rod_inertia,
            ),
            (
                |r| r.rod_cg.as_ref(),
                "rod_cg",
                Dimension::Length,
                &mut masses.rod_cg,
            ),
            (
                |r| r.piston_mass.as_ref(),
                "piston_mass",
                Dimension::Mass,
                &mut masses.piston_mass,
            ),
        ];
        for (get, field, dim, target) in overrides {
            if let (Some(v), path) = pick(get, field) {
                let x = quantity(&path, &v, dim)?;
                if x < 0.0 {
                    return Err(invalid(&path, &v, "must not be negative"));
                }
                *target = x;
            }
        }
        if kind == MechanismKind::SliderCrank && masses.wheel_inertia != 0.0 {
            return Err(invalid(
                "masses.wheel_inertia",
                &masses.wheel_inertia,
                "applies to the cardan gear only: set it in [masses.cardan_gear]",
            ));
        }
        let geometry_error = |e: GeometryError| {
            match e {
            GeometryError::PointOffRod { point, rod } => invalid(
                &pick(|r| r.rod_cg.as_ref(), "rod_cg").1,
                &point,
                &format!("the rod's centre of gravity must lie on the rod, between 0 and geometry.rod_length ({rod} m)"),
            ),
            GeometryError::RodTooShort { .. } => invalid("geometry.pin_offset", &geometry.pin_offset, &e.to_string()),
            other => invalid("geometry", &"", &other.to_string()),
        }
        };
        let (slider_crank, cardan_gear) = match kind {
            MechanismKind::SliderCrank => (
                Some(
                    SliderCrank::new(
                        geometry.crank_length,
                        geometry.rod_length,
                        geometry.pin_offset,
                        masses.rod_cg,
                    )
                    .map_err(geometry_error)?,
                ),
                None,
            ),
            MechanismKind::CardanGear => (
                None,
                Some(
                    CardanGear::equivalent_to_slider_crank(
                        geometry.crank_length,
                        geometry.rod_length,
                        masses.rod_cg,
                    )
                    .map_err(geometry_error)?,
                ),
            ),
        };
        mechanisms.push(MechanismCase {
            kind,
            masses,
            rod_material,
            slider_crank,
            cardan_gear,
        });
    }
    let gas = raw
        .gas
        .as_ref()
        .map(|table| crate::gas::parse(table, machine, &invalid))
        .transpose()?;
    Ok(Case {
        file: file.into(),
        name: raw.name,
        machine,
        geometry,
        motion,
        end_angle,
        steps: m.steps as usize,
        mechanisms,
        gas,
    })
}
