//! Karhula (2008) gas loads for the thesis geometry ZBA = 2.33·ZAA0 against
//! docs/validation/karhula-2008.md (appendices 11.3.1, 11.3.2).
//!
//! Tolerances (the issue allows at most 2 %): pressures depend on geometry only and the thesis
//! gives 4 digits: 0.1 %; pressure differences and peak torques: 1 % for the pump, 2 % for the
//! engine, whose combustion delay the thesis gives only as "8...10°" (we use 9.5°); works and
//! mean powers: 2 % (our direct integral is 1.5 % above the thesis's compression work, which
//! its coarser Mathcad quadrature plausibly explains).

use cardan_dynamics::{run_summary, Solver, Summary};
use cardan_gas::{Chamber, Cylinder, GasModel, KarhulaEngine, KarhulaPump, Polytropic};
use cardan_mechanism::{CrankMotion, Grid, MachineGeometry, MassInputs, Mechanism, Options};
use cardan_testing::within;
use std::f64::consts::PI;

const DELAY_DEG: f64 = 9.5;

/// The two mechanisms of the thesis, by registry name: slider-crank ("S") and cardan gear ("C").
const MECHANISMS: [&str; 2] = ["slider_crank", "cardan_gear"];

fn polytropic() -> Polytropic {
    Polytropic::new(1.4, 1.07, 101_325.0).unwrap()
}

/// The thesis machine (r = 0.06 m, l = 0.14 m, bore 0.12 m, rod centre of gravity at
/// 0.07 m); the cardan gear of the same stroke (its crank is 0.03 m).
fn mechanism(name: &str) -> Box<dyn Mechanism> {
    let geometry = MachineGeometry {
        crank_length: 0.06,
        rod_length: 0.14,
        bore: 0.12,
        pin_offset: 0.0,
    };
    let masses = MassInputs {
        rod_cg: Some(0.07),
        ..MassInputs::default()
    };
    (cardan_mechanism::entry(name).unwrap().build)(&geometry, &masses, &Options::new()).unwrap()
}

/// The thesis cylinder (bore 120 mm, ε = 12) on a mechanism's volume curve.
fn with_chamber<R>(mech: &dyn Mechanism, f: impl FnOnce(&Chamber) -> R) -> R {
    Cylinder::with_compression_ratio(0.12, PI / 4.0 * 0.12 * 0.12 * mech.stroke(), 12.0)
        .unwrap()
        .with_chamber(mech, f)
}

struct Run {
    pressures: Vec<f64>,
    summary: Summary,
}

fn peak(r: &Run) -> f64 {
    r.pressures.iter().copied().fold(0.0, f64::max)
}

/// Largest cardan-gear minus slider-crank pressure at the same crank angle.
fn max_difference(s: &Run, c: &Run) -> f64 {
    s.pressures
        .iter()
        .zip(&c.pressures)
        .map(|(a, b)| b - a)
        .fold(f64::MIN, f64::max)
}

/// The thesis cycle at constant ω = 200π; the gas family's loads are on massless links.
fn run(name: &str, model: &dyn GasModel) -> Run {
    let mech = mechanism(name);
    let motion = CrankMotion {
        start_angle: PI / 2.0,
        initial_speed: 200.0 * PI,
        angular_acceleration: 0.0,
    };
    let mut grid = Grid::new(motion, PI / 2.0, 4.5 * PI, 14_400);
    with_chamber(mech.as_ref(), |ch| {
        let gas = model.prepare(*ch, 200.0 * PI).unwrap();
        let at = |theta: f64| gas.at(theta);
        let (steps, summary) = run_summary(
            mech.as_ref(),
            &mut grid,
            Some(&at),
            Solver::ClosedForm,
            true,
        )
        .unwrap();
        Run {
            pressures: steps.iter().map(|s| s.pressure.unwrap()).collect(),
            summary,
        }
    })
}

/// ∫ p dV over the compression and power strokes (270°-630°) by the midpoint rule on volume.
fn pdv_work(mech: &dyn Mechanism, pressure: impl Fn(&Chamber, f64) -> f64) -> f64 {
    with_chamber(mech, |ch| {
        let n = 200_000;
        let h = PI / n as f64;
        (0..2 * n)
            .map(|k| {
                let (a, b) = (1.5 * PI + h * k as f64, 1.5 * PI + h * (k + 1) as f64);
                pressure(ch, 0.5 * (a + b)) * ((ch.volume)(b).volume - (ch.volume)(a).volume)
            })
            .sum()
    })
}

fn engine() -> KarhulaEngine {
    KarhulaEngine::new(polytropic(), 12e6, DELAY_DEG.to_radians()).unwrap()
}

#[test]
fn pump_matches_appendix_11_3_1() {
    let pump = KarhulaPump { gas: polytropic() };
    let mech = mechanism("slider_crank");
    let cylinder = with_chamber(mech.as_ref(), |ch| ch.cylinder);
    within(
        "max polytropic pressure",
        pump.gas.max_pressure(&cylinder),
        3.612e6,
        0.001,
    );
    within(
        "max isothermal pressure",
        pump.gas.isothermal_max_pressure(&cylinder),
        1.216e6,
        0.001,
    );
    within("displacement", cylinder.swept_volume, 1357e-6, 0.001);

    let s = run("slider_crank", &pump);
    let c = run("cardan_gear", &pump);
    within("S max pressure", peak(&s), 3.612e6, 0.001);
    within("C max pressure", peak(&c), 3.612e6, 0.001);
    let dp = max_difference(&s, &c);
    within("max pressure difference C−S", dp, 0.3384e6, 0.01);
    within(
        "S max torque",
        s.summary.get("gas_torque_max").unwrap(),
        684.0,
        0.01,
    );
    within(
        "C max torque",
        c.summary.get("gas_torque_max").unwrap(),
        576.0,
        0.01,
    );
    within("S work", s.summary.get("gas_work").unwrap(), 1382.0, 0.02);
    within("C work", c.summary.get("gas_work").unwrap(), 1383.0, 0.02);
    within(
        "S mean power",
        s.summary.get("gas_power_mean").unwrap(),
        69.11e3,
        0.02,
    );
    within(
        "C mean power",
        c.summary.get("gas_power_mean").unwrap(),
        69.17e3,
        0.02,
    );
    // Two closed polytropic compressions from p1·V1 to p2·V2: W = 2·(p2·V2 − p1·V1)/(n − 1),
    // whatever the mechanism: the torque integral is the p·dV work.
    let g = pump.gas;
    let w = 2.0
        * (g.max_pressure(&cylinder) * cylinder.clearance_volume
            - g.pressure(&cylinder, cylinder.max_volume()) * cylinder.max_volume())
        / (g.exponent - 1.0);
    within(
        "S work = closed-form polytropic work",
        s.summary.get("gas_work").unwrap(),
        w,
        1e-6,
    );
    within(
        "C work = closed-form polytropic work",
        c.summary.get("gas_work").unwrap(),
        w,
        1e-6,
    );
}

#[test]
fn engine_peaks_match_appendix_11_3_2() {
    let s = run("slider_crank", &engine());
    let c = run("cardan_gear", &engine());
    within("S max combustion pressure", peak(&s), 12e6, 1e-4);
    within("C max combustion pressure", peak(&c), 12e6, 1e-4);
    let dp = max_difference(&s, &c);
    within("max combustion pressure difference C−S", dp, 1.142e6, 0.02);
    within(
        "S max combustion torque",
        s.summary.get("gas_torque_max").unwrap(),
        3453.0,
        0.02,
    );
    within(
        "C max combustion torque",
        c.summary.get("gas_torque_max").unwrap(),
        2701.0,
        0.02,
    );
}

/// Our reading integrates the pressure model directly: compression then combustion. Its
/// work is the p·dV work of the pressure trace on either mechanism, and about 2.5 kJ for the
/// slider-crank, as the reference file notes. The reference gives no direct-integral value for
/// the cardan gear: its published C figures (1267 J, −13 % against S) are the thesis's own
/// reading, checked in the next test. What the thesis concludes for both readings and every
/// geometry (ch. 12) is that the cardan gear engine does less combustion work than the
/// slider-crank engine of the same stroke, because of its half-size crank: that direction is
/// the cardan gear's check here. (Its 8-15 % margin belongs to the thesis's reading, not to
/// the direct integral, so it is not applied.)
#[test]
fn engine_work_is_the_direct_integral_of_the_pressure_model() {
    let mut works = Vec::new();
    for name in MECHANISMS {
        let e = engine();
        let r = run(name, &e);
        let work = -r.summary.get("gas_work").unwrap(); // the gas drives: negative drive work
        let pdv = pdv_work(mechanism(name).as_ref(), |ch, theta| {
            e.cycle(ch, 0.0, &[theta]).unwrap().pressure[0]
        });
        within(&format!("{name} engine work = ∮ p dV"), work, pdv, 1e-4);
        works.push(work);
    }
    let (s, c) = (works[0], works[1]);
    assert!(
        (2300.0..2700.0).contains(&s),
        "slider_crank: {s} J, reference about 2.5 kJ"
    );
    assert!(
        c < s,
        "cardan_gear: {c} J, not below the slider-crank's {s} J"
    );
}

/// The thesis's combustion work and power columns follow if the scaled, shifted pressure
/// p_comb(θ) acts on both the compression and the power strokes: we reproduce them that way,
/// which explains the discrepancy (see the `karhula` module documentation).
#[test]
fn the_thesis_combustion_work_is_the_scaled_pressure_on_both_strokes() {
    let e = engine();
    let mut works = Vec::new();
    for name in MECHANISMS {
        let w = pdv_work(mechanism(name).as_ref(), |ch, theta| {
            e.combustion_pressure(ch, theta)
        });
        works.push(w);
    }
    within("C combustion work (thesis reading)", works[1], 1267.0, 0.02);
    assert!(
        (works[1] / works[0] - 1.0 + 0.13).abs() < 0.01,
        "C vs S {}",
        works[1] / works[0] - 1.0
    );
    within(
        "C mean combustion power (thesis reading)",
        works[1] / (4.0 * PI) * 200.0 * PI,
        62.57e3,
        0.02,
    );
}
