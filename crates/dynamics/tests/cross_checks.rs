//! Checks that need no paper, over every mechanism with closed forms and every reading (a
//! mechanism that has only the general solve is checked in its own test file, e.g.
//! `hypotrochoid.rs`: residual, power balance, energy): the closed forms against the
//! general faer solve built from the declared topology, the energy balance of the drive
//! torque, the power balance of the torque shares, and the two cardan mesh readings against
//! each other.

mod common;
use cardan_dynamics::{kinetic_energy, planar, run_summary, torque_shares, Solver};
use cardan_mechanism::{CrankMotion, Grid, Loads, Mechanism, C};
use common::*;
use std::f64::consts::PI;

/// An arbitrary applied piston force, to exercise the gas path of both solvers, N.
fn gas(theta: f64) -> f64 {
    20_000.0 * (0.5 * theta).sin().max(0.0) + 3_000.0 * (3.0 * theta).cos()
}

/// Every joint force and couple and the drive torque of both solvers over a cycle, with and
/// without inertia and gas.
fn both_solvers(
    mech: &dyn Mechanism,
    w0: f64,
    alpha: f64,
    inertia: bool,
    with_gas: bool,
) -> Vec<(Loads, Loads)> {
    let motion = CrankMotion {
        start_angle: 1.0,
        initial_speed: w0,
        angular_acceleration: alpha,
    };
    let topology = mech.topology();
    let mut pairs = Vec::new();
    for crank in motion.grid(1.0, 1.0 + 4.0 * PI, 1440).unwrap() {
        let st = mech.state(&crank);
        let f = [if with_gas { gas(crank.angle) } else { 0.0 }];
        let mut closed = Loads::for_topology(topology);
        let mut general = Loads::for_topology(topology);
        assert!(mech.closed_form_loads(&st, inertia, &f, &mut closed));
        let residual = planar::loads(topology, &st, inertia, &f, &mut general);
        let scale = closed
            .joints
            .iter()
            .map(|j| j.force.norm())
            .fold(1.0, f64::max);
        assert!(
            residual < 1e-9 * scale,
            "{}: residual {residual}: the model is statically inconsistent",
            mech.name()
        );
        pairs.push((closed, general));
    }
    pairs
}

/// Worst difference of `get` between the pairs, relative to its largest value over the cycle
/// (relative to the instantaneous value would be meaningless at its zeros), or to `floor` for
/// a load that vanishes (a slide's couple in a mechanism whose slide carries none).
fn worst(pairs: &[(Loads, Loads)], get: &dyn Fn(&Loads) -> C, floor: f64) -> (f64, f64) {
    let scale = pairs
        .iter()
        .map(|(c, _)| get(c).norm())
        .fold(floor, f64::max);
    let worst = pairs
        .iter()
        .map(|(c, g)| (get(c) - get(g)).norm())
        .fold(0.0, f64::max);
    (worst, scale)
}

/// Closed form and general solve agree to 1e-9 on every joint and the torque, for every
/// mechanism and reading.
#[test]
fn closed_form_equals_general_planar_solve() {
    let machines = closed_form_machines();
    let added = machines.iter().filter(|(n, _)| n.contains("added mass"));
    assert!(
        added.count() >= 4,
        "both cardan readings, with and without a wheel mass"
    );
    for (name, mech) in machines {
        for (w0, alpha, inertia, with_gas) in [
            (628.3, 0.0, true, false),
            (9.42, 314.16, true, false),
            (94.2, 628.0, true, true),
            (300.0, -50.0, false, true),
        ] {
            let pairs = both_solvers(mech.as_ref(), w0, alpha, inertia, with_gas);
            // The largest joint force, N, and its moment over the crank length, N·m: loads
            // below a millionth of these are round-off zeros.
            let force = pairs
                .iter()
                .flat_map(|(c, _)| c.joints.iter().map(|j| j.force.norm()))
                .fold(0.0, f64::max);
            let (f_floor, m_floor) = (1e-6 * force, 1e-6 * force * GEOMETRY.crank_length);
            for (k, joint) in mech.topology().joints.iter().enumerate() {
                let (w, s) = worst(&pairs, &|l| l.joints[k].force, f_floor);
                assert!(w <= 1e-9 * s, "{name} {} force: {w} of {s}", joint.name);
                let (w, s) = worst(&pairs, &|l| l.joints[k].moment.into(), m_floor);
                assert!(w <= 1e-9 * s, "{name} {} couple: {w} of {s}", joint.name);
            }
            let (w, s) = worst(&pairs, &|l| l.crank_torque.into(), m_floor);
            assert!(w <= 1e-9 * s, "{name} torque: {w} of {s}");
        }
    }
}

/// Work of the drive torque = change of kinetic energy + work done on the gas, over intervals
/// that do not return to the same configuration, with speed changing. The trapezoidal rule on
/// 20000 steps leaves a relative error of order 1e-8.
#[test]
fn crank_torque_work_balances_kinetic_energy_and_gas_work() {
    for (name, mech) in closed_form_machines() {
        for (start, end, w0, alpha, with_gas) in [
            (1.4, 3.0, 200.0, 0.0, false),
            (0.2, 7.3, 10.0, 300.0, false),
            (2.0, 9.0, 50.0, 150.0, true),
            (0.0, 5.0, 300.0, -200.0, true),
        ] {
            let motion = CrankMotion {
                start_angle: start,
                initial_speed: w0,
                angular_acceleration: alpha,
            };
            let mut grid = Grid::new(motion, start, end, 20_000);
            let at = |theta: f64| (0.0, gas(theta));
            let gas_at: Option<cardan_dynamics::GasAt> = if with_gas { Some(&at) } else { None };
            let (steps, _) =
                run_summary(mech.as_ref(), &mut grid, gas_at, Solver::ClosedForm, true).unwrap();
            let (mut work, mut gas_work, mut scale) = (0.0, 0.0, 0.0);
            for w in steps.windows(2) {
                let dth = w[1].state.crank.angle - w[0].state.crank.angle;
                let t = 0.5 * (w[0].total.crank_torque + w[1].total.crank_torque);
                work += t * dth;
                scale += t.abs() * dth;
                // The drive pushes every piston against the gas: Σ ∫ F·dx, F towards the crank.
                for (p, (f0, f1)) in w[0]
                    .piston_forces
                    .iter()
                    .zip(&w[1].piston_forces)
                    .enumerate()
                {
                    let dx = w[1].state.pistons[p].position - w[0].state.pistons[p].position;
                    gas_work += 0.5 * (f0 + f1) * dx;
                }
            }
            let t = mech.topology();
            let de = kinetic_energy(t, &steps[steps.len() - 1].state)
                - kinetic_energy(t, &steps[0].state);
            assert!(
                (work - de - gas_work).abs() <= 1e-7 * scale,
                "{name} {start}→{end}: drive work {work}, ΔKE {de}, gas work {gas_work}"
            );
        }
    }
}

/// The bodies' torque shares by the power balance add up to the drive torque of either solver.
#[test]
fn torque_shares_add_up_to_the_drive_torque() {
    for (name, mech) in closed_form_machines() {
        let pairs = both_solvers(mech.as_ref(), 94.2, 628.0, true, true);
        let motion = CrankMotion {
            start_angle: 1.0,
            initial_speed: 94.2,
            angular_acceleration: 628.0,
        };
        let scale = pairs
            .iter()
            .map(|(c, _)| c.crank_torque.abs())
            .fold(0.0, f64::max);
        let mut shares = vec![0.0; mech.topology().bodies.len()];
        for (crank, (closed, _)) in motion
            .grid(1.0, 1.0 + 4.0 * PI, 1440)
            .unwrap()
            .iter()
            .zip(&pairs)
        {
            let st = mech.state(crank);
            torque_shares(mech.topology(), &st, true, &[gas(crank.angle)], &mut shares);
            let sum: f64 = shares.iter().sum();
            assert!(
                (sum - closed.crank_torque).abs() <= 1e-9 * scale,
                "{name} at {}: shares {sum}, torque {}",
                crank.angle,
                closed.crank_torque
            );
        }
    }
}

/// The involute reading of the cardan mesh gives the thesis reading's drive torque and rod
/// force, and a tangential mesh force lower by J_w·α/r_c: the wheel's own inertia torque,
/// which the thesis lumps into the crankshaft.
#[test]
fn cardan_mesh_readings_differ_only_by_the_wheel_inertia_and_the_radial_force() {
    let machines = closed_form_machines();
    let get = |n: &str| {
        machines
            .iter()
            .find(|(name, _)| name == n)
            .unwrap()
            .1
            .as_ref()
    };
    let (karhula, involute) = (get("cardan_gear"), get("cardan_gear involute"));
    let r_c = GEOMETRY.crank_length / 2.0;
    let j_w = cardan_mechanism::mass::cardan_wheel_inertia(GEOMETRY.crank_length);
    for (w0, alpha) in [(628.3, 0.0), (94.2, 628.0), (300.0, -500.0)] {
        let a = both_solvers(karhula, w0, alpha, true, true);
        let b = both_solvers(involute, w0, alpha, true, true);
        let motion = CrankMotion {
            start_angle: 1.0,
            initial_speed: w0,
            angular_acceleration: alpha,
        };
        let grid = motion.grid(1.0, 1.0 + 4.0 * PI, 1440).unwrap();
        let scale = a
            .iter()
            .map(|(c, _)| c.joints[2].force.norm())
            .fold(0.0, f64::max);
        for ((crank, (k, _)), (i, _)) in grid.iter().zip(&a).zip(&b) {
            assert!((k.crank_torque - i.crank_torque).abs() <= 1e-9 * scale * r_c * 4.0);
            assert!((k.joints[2].force - i.joints[2].force).norm() <= 1e-9 * scale);
            // Tangent at the pitch point, t = i·e^{iθ}.
            let t = C::i() * crank.direction;
            let tangential = |l: &Loads| l.joints[3].force.re * t.re + l.joints[3].force.im * t.im;
            let expected = tangential(k) - j_w * alpha / r_c;
            assert!(
                (tangential(i) - expected).abs() <= 1e-9 * scale,
                "θ {}: F_t {} vs {expected}",
                crank.angle,
                tangential(i)
            );
            // Involute teeth push along the line of action: radial part |F_t|·tan 20° inward.
            let radial = -(i.joints[3].force.re * crank.direction.re
                + i.joints[3].force.im * crank.direction.im);
            assert!(
                (radial - tangential(i).abs() * 20f64.to_radians().tan()).abs() <= 1e-9 * scale
            );
        }
    }
}
