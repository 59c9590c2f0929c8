//! The total loads of a run with several load families (inertia and gas). Where every joint's
//! reaction is linear in the loads the total is the families' sum; where one is not (the
//! involute mesh's loaded flank) it is the solve of the summed loads. Both are checked against
//! the general planar solve of the total, and the involute cardan gear against a superposition
//! of the total built by hand from the families acting alone.

mod common;
use cardan_dynamics::{planar, run_summary, GasAt, Solver, StepRecord};
use cardan_mechanism::{CrankMotion, Grid, Loads, Mechanism, C};
use common::*;
use std::f64::consts::PI;

/// A gas force whose sign changes at other angles than the inertial loads' (a pump's
/// compression and a suction pull, N, on the 0.12 m bore): with the piston's inertia it puts
/// the mesh's inertial and gas tangential forces at opposite signs over part of the cycle.
fn gas(theta: f64) -> (f64, f64) {
    let f = 30_000.0 * (0.5 * theta + 0.3).sin() - 4_000.0;
    (f / (PI / 4.0 * 0.12 * 0.12), f)
}

/// Every step of two crank revolutions at `w0` (rad/s) with the inertial and gas families, by
/// `solver`. The grid (from 0.1 rad, 997 steps) keeps clear of the hypotrochoid's folds,
/// where its planar solve is singular (`hypotrochoid.rs`).
fn run(mech: &dyn Mechanism, w0: f64, solver: Solver) -> Vec<StepRecord> {
    let motion = CrankMotion {
        start_angle: 0.1,
        initial_speed: w0,
        angular_acceleration: 150.0,
    };
    let mut grid = Grid::new(motion, 0.1, 0.1 + 4.0 * PI, 997);
    let at: GasAt = &gas;
    run_summary(mech, &mut grid, Some(at), solver, true)
        .unwrap()
        .0
}

/// The largest joint force of the total over the run, N: the scale of the tolerances.
fn peak_force(steps: &[StepRecord]) -> f64 {
    steps
        .iter()
        .flat_map(|s| s.total.joints.iter().map(|j| j.force.norm()))
        .fold(0.0, f64::max)
}

/// With gas, every mechanism's total loads, by its closed forms and by the general solve of
/// each family, equal the general planar solve of the total (inertia and gas together) to
/// 1e-9 of the largest joint force (the closed forms and the general solve agree to that,
/// `cross_checks.rs`; the total adds one rounding per quantity).
#[test]
fn the_total_equals_the_general_solve_of_the_summed_loads() {
    for (name, mech) in every_machine() {
        let t = mech.topology();
        for w0 in [30.0 * PI, 200.0 * PI] {
            for solver in [Solver::ClosedForm, Solver::General] {
                let steps = run(mech.as_ref(), w0, solver);
                let scale = peak_force(&steps);
                let mut solved = Loads::for_topology(t);
                for s in &steps {
                    planar::loads(t, &s.state, true, &s.piston_forces, &mut solved);
                    for (k, joint) in t.joints.iter().enumerate() {
                        let d = (s.total.joints[k].force - solved.joints[k].force).norm();
                        assert!(
                            d <= 1e-9 * scale,
                            "{name} {solver:?} ω0 {w0}: {} off by {d} N at {}",
                            joint.name,
                            s.state.crank.angle
                        );
                        let d = (s.total.joints[k].moment - solved.joints[k].moment).abs();
                        assert!(d <= 1e-9 * scale * GEOMETRY.crank_length);
                    }
                    let d = (s.total.crank_torque - solved.crank_torque).abs();
                    assert!(d <= 1e-9 * scale * GEOMETRY.crank_length, "{name} torque");
                }
            }
        }
    }
}

/// The involute cardan gear against its total built by hand. The piston pin's force and the
/// mesh's tangential force are linear in the loads, so the families' add up; the teeth then
/// push on the flank the summed tangential force F_t loads: mesh = F_t·t − |F_t|·tan α·e
/// (t the pitch-line tangent i·e^{iθ}, e = e^{iθ} from the ring's centre to the pitch point),
/// crank pin = rod force + mesh force (the wheel's force balance, A5.2.1.47-51), main bearing
/// its opposite, torque the families' sum. Over the run the families' tangential forces have
/// opposite signs at some steps, where the families' sum is checked to be wrong, so that the
/// test fails on a run that adds the families' forces.
#[test]
fn the_involute_mesh_is_loaded_by_the_summed_tangential_force() {
    let mech = machine_with(
        "cardan_gear",
        &GEOMETRY,
        cardan_mechanism::Material::Steel,
        &[("gear_mesh_model", "involute")],
    );
    let tan = 20f64.to_radians().tan();
    let index = |n: &str| {
        mech.topology()
            .joints
            .iter()
            .position(|j| j.name == n)
            .unwrap()
    };
    let (main, crank_pin, piston_pin, mesh) = (
        index("main_bearing"),
        index("crank_pin"),
        index("piston_pin"),
        index("gear_mesh"),
    );
    let mut opposed = 0;
    for w0 in [30.0 * PI, 100.0 * PI, 200.0 * PI] {
        let steps = run(mech.as_ref(), w0, Solver::ClosedForm);
        let scale = peak_force(&steps);
        for s in &steps {
            let e = s.state.crank.direction;
            let t = C::i() * e;
            let tangential = |l: &Loads| {
                let f = l.joints[mesh].force;
                f.re * t.re + f.im * t.im
            };
            let [inertial, gas] = [&s.families[0], &s.families[1]];
            let f_t = tangential(inertial) + tangential(gas);
            let mesh_force = f_t * t - f_t.abs() * tan * e;
            // The wheel takes −(force on the rod from the wheel) at its pin.
            let rod = -(inertial.joints[piston_pin].force + gas.joints[piston_pin].force);
            let expected = [
                (main, -(rod + mesh_force)),
                (crank_pin, rod + mesh_force),
                (piston_pin, -rod),
                (mesh, mesh_force),
            ];
            for (k, f) in expected {
                let d = (s.total.joints[k].force - f).norm();
                assert!(
                    d <= 1e-9 * scale,
                    "ω0 {w0}, θ {}: joint {k} off by {d} N",
                    s.state.crank.angle
                );
            }
            let torque = inertial.crank_torque + gas.crank_torque;
            assert!((s.total.crank_torque - torque).abs() <= 1e-9 * scale * GEOMETRY.crank_length);
            if tangential(inertial) * tangential(gas) < 0.0
                && tangential(inertial).abs().min(tangential(gas).abs()) > 0.05 * scale
            {
                opposed += 1;
                let summed = inertial.joints[mesh].force + gas.joints[mesh].force;
                assert!((summed - mesh_force).norm() > 0.01 * scale);
            }
        }
    }
    assert!(opposed > 100, "the families oppose at {opposed} steps only");
}
