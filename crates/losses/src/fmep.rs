//! The whole-engine fmep cross-check of an engine with friction, after its run: the Patton,
//! Nitschke & Heywood (1989) whole-engine friction mean effective pressure with the Sandoval &
//! Heywood (2003) update ([`pnh_fmep`]) on an engine of this bore and stroke whose bearings and
//! valves are scaled from the bore ([`pnh_engine`]); its constants are those of Sandoval (2002,
//! MIT BSc thesis, eqs 7.a-11 and Table 4.2) as transcribed in
//! `docs/validation/engine-friction.md`. [`engine_metrics`] compares it with the run's own fmep
//! (the loss budget's work, [`crate::engine_losses`] among its components).

use crate::engine_losses::{displacement, EngineLosses, FmepModel};
use crate::loss::Oil;
use crate::losses::Friction;
use cardan_friction::{pnh_fmep, FmepBreakdown, Follower, PnhEngine, PnhVariant, ShaftBearings};
use cardan_mechanism::{CrankMotion, Mechanism};
use cardan_metrics::Summary;
use std::f64::consts::PI;

/// Reference kinematic viscosity ν₀ of the Sandoval & Heywood (2003) viscosity scaling, m²/s:
/// 10.6 cSt, the 10W-30 oil of Patton et al. at 90 °C (Sandoval 2002 §3.2).
pub const PNH_REFERENCE_VISCOSITY: f64 = 10.6e-6;

/// The one-cylinder engine of bore B and stroke S the PNH cross-check runs on. Bearings and
/// valves scaled from the bore with the proportions of the round engine of `docs/validation/engine-friction.md`
/// (§7.2: B = S = 100 mm) \[M\]: two main bearings of diameter 0.5·B and length 0.2·B, one rod
/// bearing of 0.4·B by 0.2·B, two cam bearings, two valves of lift 0.1·B (the cam's lift if the
/// case gives a valve-train geometry); the follower of the case's valve train (flat without
/// one), the layout and compression ratio of `engine`.
pub fn pnh_engine(engine: &EngineLosses, bore: f64, stroke: f64) -> PnhEngine {
    let lift = engine
        .valve_train
        .and_then(|v| v.geometry)
        .map_or(0.1 * bore, |g| g.cam.lift);
    PnhEngine {
        bore,
        stroke,
        cylinders: 1,
        compression_ratio: engine.compression_ratio,
        main_bearings: ShaftBearings {
            count: 2,
            diameter: 0.5 * bore,
            length: 0.2 * bore,
        },
        rod_bearings: ShaftBearings {
            count: 1,
            diameter: 0.4 * bore,
            length: 0.2 * bore,
        },
        cam_bearings: 2,
        valves: 2,
        max_valve_lift: lift,
        valvetrain: engine.pnh_valvetrain,
        follower: engine
            .valve_train
            .map_or(Follower::Flat, |v| v.follower.pnh_follower()),
    }
}

/// The whole-engine fmep breakdown (Pa) of [`pnh_engine`] at crank speed ω (rad/s, > 0) with
/// `oil`: Patton, Nitschke & Heywood (1989) or Sandoval & Heywood (2003) with ν/ν₀ =
/// ν_oil/10.6 cSt ([`pnh_fmep`]; Sandoval 2002 eqs 7.a crankshaft, 8.a reciprocating, 9.a gas
/// loading, 10.a valve train, 11 auxiliaries, Table 4.2), at `engine`'s intake pressure.
/// Mechanical friction and auxiliaries only: PNH's pumping terms are not included.
pub fn fmep_breakdown(
    engine: &EngineLosses,
    oil: &Oil,
    bore: f64,
    stroke: f64,
    crank_speed: f64,
) -> FmepBreakdown {
    let variant = match engine.fmep_model {
        FmepModel::Pnh1989 => PnhVariant::Pnh1989,
        FmepModel::SandovalHeywood2003 => PnhVariant::SandovalHeywood2003 {
            viscosity_ratio: oil.kinematic_viscosity / PNH_REFERENCE_VISCOSITY,
        },
    };
    pnh_fmep(
        &pnh_engine(engine, bore, stroke),
        variant,
        crank_speed,
        engine.intake_pressure,
        engine.ambient_pressure,
    )
}

/// Crank-angle intervals of the PNH mean over an accelerating run.
const PNH_INTERVALS: usize = 720;

/// The fmep metrics of one mechanism's run of an engine with `friction` (empty for a machine
/// that is not an engine, a mechanism without a cylinder, or a run without losses), from its
/// `summary`, the run's `motion` and `end_angle`, and the cylinder's `bore` (m):
///
/// - `fmep`: the run's friction mean effective pressure, loss_work·4π/(span·V_d): the work
///   lost per displaced volume per four-stroke cycle (4π of crank angle), the run's span being
///   `end_angle − motion.start_angle` (a run of one cycle: loss_work/V_d);
/// - `fmep_mechanical`: the same without the `pumping` component, PNH's scope;
/// - `fmep_pnh` and its groups `fmep_pnh_crankshaft`, `_reciprocating`, `_valve_train`,
///   `_auxiliaries`: [`fmep_breakdown`] averaged over the run's crank angle (trapezoidal rule,
///   720 intervals, the speed ω(θ) of `motion`), which is its value at the speed of a steady
///   run; left out where the crank stops or turns backwards (PNH's boundary terms diverge at
///   rest) or the correlation has no value (an OHV roller follower).
pub fn engine_metrics(
    friction: &Friction,
    mechanism: &dyn Mechanism,
    bore: f64,
    motion: &CrankMotion,
    end_angle: f64,
    summary: &Summary,
) -> Vec<(&'static str, f64)> {
    let Some(engine) = &friction.engine else {
        return Vec::new();
    };
    let Some(lost) = summary.get("loss_work") else {
        return Vec::new();
    };
    let span = end_angle - motion.start_angle;
    let stroke = mechanism.stroke();
    let volume = displacement(bore, stroke);
    if !mechanism.has_cylinder() || span.is_nan() || span <= 0.0 || volume.is_nan() || volume <= 0.0
    {
        return Vec::new();
    }
    let per_cycle = 4.0 * PI / (span * volume);
    let pumping = match (
        summary.get("power_loss_mean_pumping"),
        summary.get("cycle_time"),
    ) {
        (Some(p), Some(t)) => p * t,
        _ => 0.0,
    };
    let mut out = vec![
        ("fmep", lost * per_cycle),
        ("fmep_mechanical", (lost - pumping) * per_cycle),
    ];
    let h = span / PNH_INTERVALS as f64;
    let mut sum = [0.0; 5];
    for k in 0..=PNH_INTERVALS {
        let Ok(crank) = motion.at_angle(motion.start_angle + h * k as f64) else {
            return out;
        };
        if crank.speed.is_nan() || crank.speed <= 0.0 {
            return out;
        }
        let f = fmep_breakdown(engine, &friction.oil, bore, stroke, crank.speed);
        let weight = if k == 0 || k == PNH_INTERVALS {
            0.5
        } else {
            1.0
        };
        let terms = [
            f.total(),
            f.crankshaft(),
            f.reciprocating(),
            f.valvetrain(),
            f.auxiliaries,
        ];
        for (s, t) in sum.iter_mut().zip(terms) {
            *s += weight * t;
        }
    }
    let mean = sum.map(|s| s / PNH_INTERVALS as f64);
    if mean.iter().all(|m| m.is_finite()) {
        out.extend([
            ("fmep_pnh", mean[0]),
            ("fmep_pnh_crankshaft", mean[1]),
            ("fmep_pnh_reciprocating", mean[2]),
            ("fmep_pnh_valve_train", mean[3]),
            ("fmep_pnh_auxiliaries", mean[4]),
        ]);
    }
    out
}
