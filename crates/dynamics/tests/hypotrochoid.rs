//! The hypotrochoid mechanism (Vidinsky 2021) through the general planar solve: its topology is
//! statically determinate and consistent (residual ~0) away from the folds of its
//! parallelogram crank chain, the drive torque is the power balance, and a pair of opposite
//! forces on two adjacent piston links (the chamber between them) reaches the crank with the
//! paper's mechanical advantage (eq 21) and the validation model's torque (§6, L401).

use cardan_dynamics::{planar, torque_shares};
use cardan_mechanism::hypotrochoid::Hypotrochoid;
use cardan_mechanism::{
    entry, Bearings, CrankMotion, Loads, MachineGeometry, MassInputs, Mechanism, OptionValue,
    Options,
};

/// The validation model (§6): p = 75 mm, u = 100 mm, r = 1.7·m·u; masses made up (the paper
/// has none) so that every massive body has inertia.
fn model(m: usize) -> (Hypotrochoid, Box<dyn Mechanism>) {
    let g = MachineGeometry {
        crank_length: 0.075,
        rod_length: 0.2,
        bore: 0.1,
        pin_offset: 0.0,
    };
    let inputs = MassInputs {
        crankshaft_inertia: Some(0.02),
        wheel_inertia: Some(0.004),
        rod_mass: Some(1.3),
        rod_inertia: Some(0.015),
        rod_cg: Some(0.12),
        ..MassInputs::default()
    };
    let mut o = Options::new();
    o.insert("angular_modulus".into(), OptionValue::Number(m as f64));
    let h = Hypotrochoid::build(&g, &inputs, &o).unwrap();
    let boxed = (entry("hypotrochoid").unwrap().build)(&g, &inputs, &o).unwrap();
    (h, boxed)
}

/// Over two crank turns, speeding up, with inertia and a different force on every piston
/// link: the residual of the planar solve is round-off and the drive torque equals the power
/// balance Σ (m·a·v + J·α·ω) + Σ F·ẋ over ω to 1e-9, wherever |sin((m+1)θ)| > 0.02 (the
/// parallelogram is not folded).
#[test]
fn planar_solve_is_consistent_and_meets_the_power_balance() {
    for m in [2, 3, 4] {
        let (h, mech) = model(m);
        let topology = mech.topology();
        let motion = CrankMotion {
            start_angle: 0.1,
            initial_speed: 40.0,
            angular_acceleration: 250.0,
        };
        let mut checked = 0;
        for crank in motion
            .grid(0.1, 0.1 + 4.0 * std::f64::consts::PI, 997)
            .unwrap()
        {
            let theta = h.carrier_angle(crank.angle);
            if h.fold_sine(theta).abs() < 0.02 {
                continue;
            }
            let st = mech.state(&crank);
            let forces: Vec<f64> = (0..m)
                .map(|k| 500.0 * (k as f64 + 1.0) * (1.0 + 0.3 * (crank.angle + k as f64).sin()))
                .collect();
            let mut loads = Loads::for_topology(topology);
            let residual = planar::loads(topology, &st, true, &forces, &mut loads);
            let scale = loads
                .joints
                .iter()
                .map(|j| j.force.norm())
                .fold(1.0, f64::max);
            assert!(
                residual < 1e-9 * scale,
                "m = {m} φ = {}: residual {residual} of {scale}",
                crank.angle
            );
            let mut shares = vec![0.0; topology.bodies.len()];
            torque_shares(topology, &st, true, &forces, &mut shares);
            let balance: f64 = shares.iter().sum();
            let size = balance.abs().max(loads.crank_torque.abs()).max(1.0);
            assert!(
                (loads.crank_torque - balance).abs() <= 1e-9 * size,
                "m = {m} φ = {}: planar {} vs power balance {balance}",
                crank.angle,
                loads.crank_torque
            );
            // Every piston link carries its force: its share includes F·ẋ/ω.
            for (f, piston) in forces.iter().zip(&st.pistons) {
                assert!(f * piston.velocity != 0.0);
            }
            checked += 1;
        }
        assert!(
            checked > 900,
            "m = {m}: only {checked} states away from the folds"
        );
    }
}

/// A chamber force F_in between piston links 1 and 2 (link 2 pushed ahead, link 1 back) on the
/// massless mechanism: the crank delivers F_out = F_in·MA(θ) at the crank pin (eq 21), i.e. a
/// drive torque −F_in·p·MA. The validation model (F_in = 10 N, p = 75 mm, 1 rad/s): sample 22
/// (m = 2, θ = 120.32°) prints 2249.68 N·mm, sample 24 (m = 3, θ = 97.48°) 1736.46 N·mm.
#[test]
fn chamber_force_reaches_the_crank_with_the_mechanical_advantage() {
    for (m, theta, torque, tol) in [
        (
            2,
            std::f64::consts::FRAC_PI_2 + 0.004211 + 21.0 * 0.025,
            2.24968,
            2e-5,
        ),
        (
            3,
            5.0 * std::f64::consts::PI / 12.0 + 0.009014 + 23.0 / 60.0,
            1.73646,
            3e-4,
        ),
    ] {
        let (h, _) = model(m);
        let massless = Hypotrochoid::new(
            m,
            h.crank,
            h.link,
            h.planet,
            cardan_mechanism::hypotrochoid::massless(),
            [Bearings::single(0.005, 1e4); 3],
        )
        .unwrap();
        let crank = CrankMotion {
            start_angle: 0.0,
            initial_speed: 1.0,
            angular_acceleration: 0.0,
        }
        .at_angle(massless.crank_angle(theta))
        .unwrap();
        let st = massless.state(&crank);
        let mut forces = vec![0.0; m];
        forces[0] = 10.0;
        forces[1] = -10.0;
        let mut loads = Loads::for_topology(massless.topology());
        let residual = planar::loads(massless.topology(), &st, false, &forces, &mut loads);
        assert!(residual < 1e-9);
        let ma = massless.mechanical_advantage(theta);
        assert!(
            (loads.crank_torque + 10.0 * h.crank * ma).abs() < 1e-12,
            "m = {m}: {} vs MA {ma}",
            loads.crank_torque
        );
        assert!(
            (-loads.crank_torque - torque).abs() < tol * torque,
            "m = {m}: {} N·m vs the paper's {torque}",
            -loads.crank_torque
        );
        assert!((st.extras[2] - ma).abs() < 1e-15);
    }
}

/// The energy balance of crates/dynamics/tests/cross_checks.rs, with the gas work summed over
/// every piston (the step loop applies the gas force to each of the m piston links; the
/// generic test counts the first piston only): drive work = ΔKE + Σ_k ∫ F·dx_k.
#[test]
fn drive_work_balances_kinetic_energy_and_the_work_on_every_piston() {
    use cardan_dynamics::{kinetic_energy, run_summary, Solver, StepRecord};
    let gas = |theta: f64| 20_000.0 * (0.5 * theta).sin().max(0.0) + 3_000.0 * (3.0 * theta).cos();
    // φ = 0 is a fold of the parallelogram for m = 3 (module note): that grid only for m = 2.
    for (m, start, end, w0, alpha) in [
        (2, 2.0, 9.0, 50.0, 150.0),
        (2, 0.0, 5.0, 300.0, -200.0),
        (3, 2.0, 9.0, 50.0, 150.0),
    ] {
        let (_, mech) = model(m);
        {
            let motion = CrankMotion {
                start_angle: start,
                initial_speed: w0,
                angular_acceleration: alpha,
            };
            let mut grid = cardan_mechanism::Grid::new(motion, start, end, 20_000);
            let at = |theta: f64| (0.0, gas(theta));
            let (steps, _) = run_summary(
                mech.as_ref(),
                &mut grid,
                Some(&at),
                Solver::ClosedForm,
                true,
            )
            .unwrap();
            let (mut work, mut gas_work, mut scale) = (0.0, 0.0, 0.0);
            for w in steps.windows(2) {
                let dth = w[1].state.crank.angle - w[0].state.crank.angle;
                let t = 0.5 * (w[0].total.crank_torque + w[1].total.crank_torque);
                work += t * dth;
                scale += t.abs() * dth;
                let f = |s: &StepRecord, k: usize| s.piston_forces[k];
                for k in 0..m {
                    let dx = w[1].state.pistons[k].position - w[0].state.pistons[k].position;
                    gas_work += 0.5 * (f(&w[0], k) + f(&w[1], k)) * dx;
                }
            }
            let t = mech.topology();
            let de = kinetic_energy(t, &steps[steps.len() - 1].state)
                - kinetic_energy(t, &steps[0].state);
            assert!(
                (work - de - gas_work).abs() <= 1e-7 * scale,
                "m = {m} {start}→{end}: drive work {work}, ΔKE {de}, gas work {gas_work}"
            );
        }
    }
}
