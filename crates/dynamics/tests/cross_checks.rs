//! Checks that need no paper: the closed forms against the general faer solve, and the energy
//! balance of the crank torque.

mod common;
use cardan_dynamics::{kinetic_energy, loads, planar, run_cycle, Material};
use cardan_mechanism::{CrankMotion, MechanismKind};
use common::*;

/// An arbitrary applied piston force, to exercise the gas path of both solvers, N.
fn gas(theta: f64) -> f64 {
    20_000.0 * (0.5 * theta).sin().max(0.0) + 3_000.0 * (3.0 * theta).cos()
}

/// Closed form and general solve agree to 1e-9 relative to the largest value of each load over
/// the cycle (relative to the instantaneous value would be meaningless at its zeros).
#[test]
fn closed_form_equals_general_planar_solve() {
    for kind in MechanismKind::ALL {
        for (w0, alpha, with_gas) in [
            (628.3, 0.0, false),
            (9.42, 314.16, false),
            (94.2, 628.0, true),
            (300.0, -50.0, true),
        ] {
            let masses = thesis_masses(kind, Material::Steel);
            let mech = mechanism(kind, masses.rod_cg);
            let motion = CrankMotion {
                start_angle: 1.0,
                initial_speed: w0,
                angular_acceleration: alpha,
            };
            let grid = motion
                .grid(1.0, 1.0 + 4.0 * std::f64::consts::PI, 1440)
                .unwrap();
            let mut pairs = Vec::new();
            for crank in grid {
                let st = mech.state(crank);
                let f = if with_gas { gas(crank.angle) } else { 0.0 };
                let closed = loads(kind, &st, &masses, f);
                let (general, residual) = planar::loads(kind, &st, &masses, f);
                let scale = closed.crank_pin.norm().max(1.0);
                assert!(
                    residual < 1e-9 * scale,
                    "{kind:?}: residual {residual}: the model is statically inconsistent"
                );
                pairs.push((closed, general));
            }
            let check =
                |name: &str, get: &dyn Fn(&cardan_dynamics::Loads) -> cardan_mechanism::C| {
                    let scale = pairs
                        .iter()
                        .map(|(c, _)| get(c).norm())
                        .fold(0.0, f64::max)
                        .max(1e-300);
                    let worst = pairs
                        .iter()
                        .map(|(c, g)| (get(c) - get(g)).norm())
                        .fold(0.0, f64::max);
                    assert!(
                        worst <= 1e-9 * scale,
                        "{kind:?} {name}: worst difference {worst}, scale {scale}"
                    );
                };
            check("main bearing", &|l| l.main_bearing);
            check("crank pin", &|l| l.crank_pin);
            check("piston pin", &|l| l.piston_pin);
            check("piston side", &|l| l.piston_side.into());
            check("gear mesh", &|l| l.gear_mesh);
            check("crank torque", &|l| l.crank_torque.into());
        }
    }
}

/// Work of the drive torque = change of kinetic energy + work done on the gas, over intervals
/// that do not return to the same configuration, with speed changing. The trapezoidal rule on
/// 20000 steps leaves a relative error of order 1e-8.
#[test]
fn crank_torque_work_balances_kinetic_energy_and_gas_work() {
    for kind in MechanismKind::ALL {
        for rod in [Material::Steel, Material::Titanium] {
            let masses = thesis_masses(kind, rod);
            let mech = mechanism(kind, masses.rod_cg);
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
                let grid = motion.grid(start, end, 20_000).unwrap();
                let forces: Vec<f64> = grid
                    .iter()
                    .map(|g| if with_gas { gas(g.angle) } else { 0.0 })
                    .collect();
                let force = |k: usize| forces[k];
                let steps = run_cycle(mech.as_ref(), &masses, &grid, Some(&forces));
                let (mut work, mut gas_work, mut scale) = (0.0, 0.0, 0.0);
                for (k, w) in steps.windows(2).enumerate() {
                    let dth = w[1].kinematics.crank.angle - w[0].kinematics.crank.angle;
                    let t = 0.5 * (w[0].total().crank_torque + w[1].total().crank_torque);
                    work += t * dth;
                    scale += t.abs() * dth;
                    // The drive pushes the piston against the gas: ∫ F·dx with F towards the crank.
                    let dx = w[1].kinematics.piston.position - w[0].kinematics.piston.position;
                    gas_work += 0.5 * (force(k) + force(k + 1)) * dx;
                }
                let de = kinetic_energy(kind, &steps[steps.len() - 1].kinematics, &masses)
                    - kinetic_energy(kind, &steps[0].kinematics, &masses);
                assert!(
                    (work - de - gas_work).abs() <= 1e-7 * scale,
                    "{kind:?} {rod:?} {start}→{end}: drive work {work}, ΔKE {de}, gas work {gas_work}"
                );
            }
        }
    }
}
