//! The solved machine motion's tables: `[motion] mode = "dynamic"` with its `cycles` and
//! `steady_tolerance`, `[load]` and `[flywheel]` (`cardan_dynamics::machine_motion`; method and
//! sources in docs/validation/machine-motion.md), read by typed structs and validated into a
//! [`Dynamics`].

use crate::error::{CaseError, Invalid};
use crate::plausible::{FluctuationCoefficient, TorquePerSpeed, TorquePerSpeedSquared};
use crate::quantity::{Angle, Inertia, NonNegative, Quantity, Ranged, Torque};
use cardan_dynamics::machine_motion::{LoadTorque, Table};
use schemars::JsonSchema;
use serde::Deserialize;

/// How the crank moves.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Deserialize, JsonSchema, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum MotionMode {
    /// The crank follows the law of `[motion]`: θ = θ0 + ω0·t + ½·α·t².
    #[default]
    Prescribed,
    /// The crank's speed is solved from its torques (gas, inertia, `[load]`, `[flywheel]`),
    /// from `initial_speed` at `start_angle`.
    Dynamic,
}

/// `[load]`: the torque a load or motor applies to the crankshaft, positive in the direction of
/// rotation (a brake, a pump or a driven machine negative; a motor positive); the terms add up.
#[derive(Debug, Deserialize, JsonSchema, serde::Serialize)]
#[serde(deny_unknown_fields)]
pub struct LoadTable {
    /// A constant torque, N·m ("-200 N*m", "kN*m", "lbf*ft").
    pub torque: Option<Quantity<Torque>>,
    /// A torque over one period of crank angle: [[angle, torque], ...], angles (degrees, or with
    /// a unit) strictly increasing, the last a period after the first with the first's torque
    /// (within 1e-9 of the table's largest |torque|, then taken as the first's); linear in
    /// between and repeated every period.
    pub torque_table: Option<Vec<(Quantity<Angle>, Quantity<Torque>)>>,
    /// k of a term k·ω, N·m·s/rad: a motor's falling characteristic (negative).
    pub torque_per_speed: Option<Ranged<TorquePerSpeed>>,
    /// k of a term k·ω², N·m·s²/rad²: the fan, pump and propeller law (negative for a load).
    pub torque_per_speed_squared: Option<Ranged<TorquePerSpeedSquared>>,
}

/// `[flywheel]`: a flywheel on the crankshaft, given or sized.
#[derive(Debug, Deserialize, JsonSchema, serde::Serialize)]
#[serde(deny_unknown_fields)]
pub struct FlywheelTable {
    /// Its moment of inertia, kg·m², at most 1e6 kg·m² (a bare number above 100 is taken for
    /// g·cm²: write "360 kg*m^2").
    pub inertia: Option<NonNegative<Inertia>>,
    /// The coefficient of fluctuation of speed (ω_max − ω_min)/ω_mean to meet, from 0 to 1
    /// (exclusive): the solver finds the flywheel inertia that meets it on the solved motion.
    pub fluctuation_coefficient: Option<Ranged<FluctuationCoefficient>>,
}

/// The largest flywheel a case may give, kg·m²: ten times the largest built (about 1e5 kg·m²,
/// marine diesels and flywheel energy stores). Far above it a crank's speed changes by less
/// than double precision resolves over a cycle (issue 36.3: 1e15 kg·m² reported ΔE = 0).
pub const MAX_FLYWHEEL: f64 = 1e6;

/// A validated solved motion.
#[derive(Debug, Clone, PartialEq)]
pub struct Dynamics {
    /// Cycles run from the initial state; the last is reported.
    pub cycles: usize,
    /// Stop early once a cycle ends within this fraction of its start speed.
    pub steady_tolerance: Option<f64>,
    pub load: LoadTorque,
    /// Flywheel inertia, kg·m².
    pub flywheel: f64,
    /// The coefficient of fluctuation the flywheel is sized for.
    pub fluctuation_target: Option<f64>,
}

/// The solved motion of a case from its tables (`None` in a prescribed one; `[load]` or
/// `[flywheel]` there is an error).
pub(crate) fn build(
    mode: MotionMode,
    cycles: Option<i64>,
    steady_tolerance: Option<f64>,
    load: Option<&LoadTable>,
    flywheel: Option<&FlywheelTable>,
    invalid: &Invalid,
) -> Result<Option<Dynamics>, CaseError> {
    if mode == MotionMode::Prescribed {
        let needs =
            |field: &str| {
                invalid(
                field,
                &format!("[{}] in a prescribed motion", field.split('.').next().unwrap_or(field)),
                "a load, a flywheel, cycles and a steady tolerance need motion.mode = \"dynamic\"",
            )
            };
        return match (load, flywheel, cycles, steady_tolerance) {
            (Some(_), ..) => Err(needs("load")),
            (_, Some(_), ..) => Err(needs("flywheel")),
            (_, _, Some(_), _) => Err(needs("motion.cycles")),
            (.., Some(_)) => Err(needs("motion.steady_tolerance")),
            _ => Ok(None),
        };
    }
    let load = match load {
        None => LoadTorque::default(),
        Some(l) => LoadTorque {
            constant: l.torque.as_ref().map_or(0.0, |t| t.si),
            table: l
                .torque_table
                .as_ref()
                .map(|t| table(t, invalid))
                .transpose()?,
            per_speed: l.torque_per_speed.as_ref().map_or(0.0, |k| k.si),
            per_speed_squared: l.torque_per_speed_squared.as_ref().map_or(0.0, |k| k.si),
        },
    };
    let (flywheel, target) = match flywheel {
        None => (0.0, None),
        Some(f) => {
            let target = f.fluctuation_coefficient.as_ref().map(|c| c.si);
            if let Some(c) = target.filter(|c| *c >= 1.0) {
                return Err(invalid(
                    "flywheel.fluctuation_coefficient",
                    &c,
                    "must be below 1 (a speed ripple as large as the mean speed cannot be met)",
                ));
            }
            if f.inertia.is_some() && target.is_some() {
                return Err(invalid(
                    "flywheel.fluctuation_coefficient",
                    &"with flywheel.inertia",
                    "give the flywheel's inertia or the coefficient it is sized for, not both",
                ));
            }
            if let Some(j) = f.inertia.as_ref().filter(|j| j.si > MAX_FLYWHEEL) {
                return Err(invalid(
                    "flywheel.inertia",
                    &j.written,
                    "must be at most 1e6 kg*m^2: the largest flywheels built (marine diesels, \
                     flywheel energy stores) are about 1e5 kg*m^2, and the solved speed of a \
                     crank carrying more barely moves (a unit mistake? a bare number above 100 \
                     is g*cm^2)",
                ));
            }
            (f.inertia.as_ref().map_or(0.0, |j| j.si), target)
        }
    };
    if let Some(t) = steady_tolerance.filter(|t| t.is_nan() || *t <= 0.0 || *t >= 1.0) {
        return Err(invalid(
            "motion.steady_tolerance",
            &t,
            "must be between 0 and 1 (exclusive)",
        ));
    }
    Ok(Some(Dynamics {
        cycles: cycles.unwrap_or(1) as usize,
        steady_tolerance,
        load,
        flywheel,
        fluctuation_target: target,
    }))
}

/// The relative tolerance of a periodic torque table's closure: its last torque (a period after
/// the first) must equal the first's within this fraction of the table's largest |torque|, and
/// is then taken as the first's. A table computed from a periodic function leaves round-off
/// there (−1.7e-13 N·m where 0 was meant, against torques of kN·m); a real mismatch is far
/// larger.
pub const TABLE_CLOSURE: f64 = 1e-9;

/// A periodic torque table: at least two points, angles strictly increasing, the last's torque
/// the first's within [`TABLE_CLOSURE`].
fn table(
    points: &[(Quantity<Angle>, Quantity<Torque>)],
    invalid: &Invalid,
) -> Result<Table, CaseError> {
    let field = "load.torque_table";
    if points.len() < 2 {
        return Err(invalid(
            field,
            &format!("{} points", points.len()),
            "needs at least two points, a period apart",
        ));
    }
    for (k, w) in points.windows(2).enumerate() {
        if w[1].0.si <= w[0].0.si {
            return Err(invalid(
                &format!("{field}[{}]", k + 1),
                &w[1].0.written,
                &format!("angles must increase strictly (after {})", w[0].0.written),
            ));
        }
    }
    let (first, last) = (&points[0], &points[points.len() - 1]);
    let largest = points.iter().map(|p| p.1.si.abs()).fold(0.0, f64::max);
    if (last.1.si - first.1.si).abs() > TABLE_CLOSURE * largest {
        return Err(invalid(
            &format!("{field}[{}]", points.len() - 1),
            &last.1.written,
            &format!(
                "the table is periodic: its last point, a period after the first, must have the first's torque ({}) within {TABLE_CLOSURE:e} of the table's largest torque ({largest} N*m)",
                first.1.written
            ),
        ));
    }
    let start = first.0.si;
    let mut points: Vec<(f64, f64)> = points.iter().map(|(a, t)| (a.si - start, t.si)).collect();
    // Within the tolerance the last torque is the first's: the table exactly periodic.
    let n = points.len();
    points[n - 1].1 = points[0].1;
    Ok(Table { start, points })
}
