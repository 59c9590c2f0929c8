//! Karhula (2008) thesis geometry ZBA = 2.33·ZAA0 against docs/validation/karhula-2008.md
//! (appendices 11.1.1, 11.2.1, 11.2.2 of the thesis).
//!
//! Tolerances:
//! - kinematics depend on geometry only: the thesis rounds its percentages to whole numbers,
//!   so we allow ±0.5 percentage point (±0.5 mm for the position difference);
//! - cardan-gear inertial loads depend on the reciprocating mass, whose thesis value is implied
//!   by the published steel crank-pin force (see `common::thesis_masses`): forces and peak
//!   torques to 1 % (the titanium rod, whose mass follows from the chapter-10 rule, also
//!   to 1 %); mean torques, works and powers, which also depend on the crankshaft estimate,
//!   to 1.5 %;
//! - slider-crank inertial loads depend on the rod's mass distribution, which the thesis does
//!   not give: its crank-pin forces within 5 %, its mean inertial torques, works and powers
//!   within 2.5 %, and its peak inertial torque within 25 % (we compute 448 N·m for the
//!   thesis's 556 N·m: no single rod inertia reproduces both this peak and the thesis's mean
//!   inertial torque, which we match to 1 %).

mod common;
use cardan_dynamics::Summary;
use cardan_mechanism::Material;
use cardan_testing::within;
use common::*;
use std::f64::consts::PI;

const S: &str = "slider_crank";
const C: &str = "cardan_gear";

fn run(name: &str, rod: Material, w0: f64, alpha: f64) -> Summary {
    cycle(thesis(name, rod).as_ref(), w0, alpha, 7200).1
}

#[test]
fn kinematics_match_appendix_11_1_1() {
    let (s_steps, s) = cycle(thesis(S, Material::Steel).as_ref(), 200.0 * PI, 0.0, 7200);
    let (c_steps, c) = cycle(thesis(C, Material::Steel).as_ref(), 200.0 * PI, 0.0, 7200);
    let (k, at) = s_steps
        .iter()
        .zip(&c_steps)
        .map(|(a, b)| {
            (
                b.state.pistons[0].position - a.state.pistons[0].position,
                a.state.pistons[0].position,
            )
        })
        .fold(
            (f64::MIN, 0.0),
            |best, x| if x.0 > best.0 { x } else { best },
        );
    assert!(
        (k - 0.014).abs() <= 0.0005,
        "max position difference {k} m, thesis +14 mm"
    );
    assert!(
        (k / at - 0.11).abs() <= 0.005,
        "max position difference {} of S, thesis +11 %",
        k / at
    );
    let change = |name: &str| c.get(name).unwrap() / s.get(name).unwrap() - 1.0;
    for (name, thesis) in [
        ("piston_velocity_max", -0.08),
        ("piston_acceleration_max", -0.30),
        ("rod_cg_velocity_max", -0.03),
        ("rod_cg_acceleration_max", -0.18),
    ] {
        assert!(
            (change(name) - thesis).abs() <= 0.005,
            "{name}: C vs S {:+.4}, thesis {thesis:+}",
            change(name)
        );
    }
}

#[test]
fn inertial_forces_and_torques_match_appendix_11_2_1() {
    // (α, ω0, S crank-pin force, C crank-pin force, S torque, C torque)
    let table = [
        (0.0, 200.0, 38510.0, 60740.0, 556.0, 911.0),
        (100.0, 200.0, 39280.0, 61960.0, 575.0, 938.0),
        (200.0, 200.0, 40050.0, 63170.0, 596.0, 967.0),
        (100.0, 3.0, 780.0, 1228.0, 25.0, 29.0),
    ];
    for (alpha, w0, fs, fc, ts, tc) in table {
        let s = run(S, Material::Steel, w0 * PI, alpha * PI);
        let c = run(C, Material::Steel, w0 * PI, alpha * PI);
        within(
            "S crank pin",
            s.get("inertial_crank_pin_force_max").unwrap(),
            fs,
            0.05,
        );
        within(
            "C crank pin",
            c.get("inertial_crank_pin_force_max").unwrap(),
            fc,
            0.01,
        );
        within("S torque", s.get("inertial_torque_max").unwrap(), ts, 0.25);
        // The thesis prints 29 N·m to two digits: ±0.5 N·m.
        within(
            "C torque",
            c.get("inertial_torque_max").unwrap(),
            tc,
            if tc < 100.0 { 0.5 / tc } else { 0.01 },
        );
    }
    let c = run(C, Material::Titanium, 200.0 * PI, 0.0);
    within(
        "C titanium crank pin",
        c.get("inertial_crank_pin_force_max").unwrap(),
        37960.0,
        0.01,
    );
    within(
        "C titanium torque",
        c.get("inertial_torque_max").unwrap(),
        569.0,
        0.01,
    );
}

#[test]
fn inertial_work_torque_and_power_match_appendix_11_2_2() {
    for (alpha, ws, wc, ts, tc) in [
        (100.0, 189.0, 170.0, 15.03, 13.51),
        (200.0, 378.0, 340.0, 30.05, 27.03),
    ] {
        for w0 in [3.0, 200.0] {
            let s = run(S, Material::Steel, w0 * PI, alpha * PI);
            let c = run(C, Material::Steel, w0 * PI, alpha * PI);
            within("S work", s.get("inertial_work").unwrap(), ws, 0.025);
            within("C work", c.get("inertial_work").unwrap(), wc, 0.015);
            within(
                "S mean torque",
                s.get("inertial_torque_mean").unwrap(),
                ts,
                0.025,
            );
            within(
                "C mean torque",
                c.get("inertial_torque_mean").unwrap(),
                tc,
                0.015,
            );
        }
    }
    for (w0, ps, pc) in [
        (3.0, 908.0, 790.0),
        (30.0, 1705.0, 1484.0),
        (200.0, 9547.0, 8309.0),
    ] {
        let s = run(S, Material::Steel, w0 * PI, 100.0 * PI);
        let c = run(C, Material::Steel, w0 * PI, 100.0 * PI);
        within(
            "S mean power",
            s.get("inertial_power_mean").unwrap(),
            ps,
            0.025,
        );
        within(
            "C mean power",
            c.get("inertial_power_mean").unwrap(),
            pc,
            0.015,
        );
    }
}

/// The thesis's trends, which must hold whatever the mass estimates.
#[test]
fn trends_of_chapter_11_2() {
    let s = run(S, Material::Steel, 200.0 * PI, 100.0 * PI);
    let c = run(C, Material::Steel, 200.0 * PI, 100.0 * PI);
    let ct = run(C, Material::Titanium, 200.0 * PI, 100.0 * PI);
    let f = |x: &Summary| x.get("inertial_crank_pin_force_max").unwrap();
    // "crank pin inertial joint force maximums are over 50 % bigger in the cardan gear"
    assert!(f(&c) / f(&s) > 1.5);
    // "If the light titanium rod is used ... approximately equal" (thesis −1.4 %)
    assert!((f(&ct) / f(&s) - 1.0).abs() < 0.05);
    // "The mean inertial torque is 10...30 % smaller in the cardan gear machine"
    let t = |x: &Summary| x.get("inertial_torque_mean").unwrap();
    assert!((0.05..0.30).contains(&(1.0 - t(&c) / t(&s))));
    // Inertial work is independent of the initial speed and proportional to α.
    let w = |w0: f64, a: f64| {
        run(S, Material::Steel, w0 * PI, a * PI)
            .get("inertial_work")
            .unwrap()
    };
    within("work vs ω0", w(3.0, 100.0), w(200.0, 100.0), 1e-9);
    within("work vs α", w(30.0, 200.0), 2.0 * w(30.0, 100.0), 1e-9);
}
