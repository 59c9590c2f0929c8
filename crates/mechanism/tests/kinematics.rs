//! Kinematic checks over every registered mechanism, with no paper needed: velocities and
//! accelerations are the time derivatives of positions; the piston-only path (cylinder volumes)
//! is the full state's; dead centres.

use cardan_mechanism::{
    CrankMotion, CrankState, MachineGeometry, MassInputs, Mechanism, Options, State, StateBlock, C,
    LANES, MECHANISMS,
};

fn machines() -> Vec<Box<dyn Mechanism>> {
    let mut all = Vec::new();
    for (crank, rod, offset) in [(0.06, 0.14, 0.0), (0.06, 0.14, 0.015), (0.026, 0.09, -0.01)] {
        let g = MachineGeometry {
            crank_length: crank,
            rod_length: rod,
            bore: 0.1,
            pin_offset: offset,
        };
        for e in MECHANISMS {
            let inputs = MassInputs {
                rod_cg: Some(0.4 * rod),
                ..MassInputs::default()
            };
            all.push((e.build)(&g, &inputs, &Options::new()).unwrap());
        }
    }
    all
}

/// Central differences in time over ±1e-5 s agree with the velocities and accelerations the
/// mechanism fills, for every body's centre of gravity and orientation and every piston, under
/// a crank that speeds up (so α ≠ 0 is exercised).
#[test]
fn derivatives_match_finite_differences() {
    let motion = CrankMotion {
        start_angle: 0.3,
        initial_speed: 30.0,
        angular_acceleration: 400.0,
    };
    for m in machines() {
        for theta in [0.4, 1.2, 2.5, 4.0, 5.9] {
            let now = motion.at_angle(theta).unwrap();
            let at = |dt: f64| {
                m.state(&CrankState::new(
                    theta + now.speed * dt + 0.5 * now.acceleration * dt * dt,
                    now.speed + now.acceleration * dt,
                    now.acceleration,
                    now.time + dt,
                ))
            };
            let h = 1e-5;
            let (s, p, q) = (m.state(&now), at(-h), at(h));
            let d = |f: &dyn Fn(&State) -> C| (f(&q) - f(&p)) / (2.0 * h);
            let check = |what: &str, numeric: C, exact: C| {
                let scale = exact.norm().max(1.0);
                assert!(
                    (numeric - exact).norm() < 1e-5 * scale,
                    "{} θ = {theta}: {what}: numeric {numeric} vs {exact}",
                    m.name()
                );
            };
            for (k, b) in m.topology().bodies.iter().enumerate() {
                let cg = s.bodies[k].cg;
                check(b.name, d(&|x| x.bodies[k].cg.position), cg.velocity);
                check(b.name, d(&|x| x.bodies[k].cg.velocity), cg.acceleration);
                // d(e^{iφ})/dt = i·ω·e^{iφ}
                let e = s.bodies[k].orientation;
                check(
                    b.name,
                    d(&|x| x.bodies[k].orientation),
                    C::i() * s.bodies[k].angular_velocity * e,
                );
                check(
                    b.name,
                    d(&|x| x.bodies[k].angular_velocity.into()),
                    s.bodies[k].angular_acceleration.into(),
                );
            }
            let piston = s.pistons[0];
            check(
                "piston",
                d(&|x| x.pistons[0].position.into()),
                piston.velocity.into(),
            );
            check(
                "piston",
                d(&|x| x.pistons[0].velocity.into()),
                piston.acceleration.into(),
            );
            // dx/dθ is v/ω for any motion; d²x/dθ² is a/ω² at α = 0.
            let v = piston.dx_dtheta * now.speed;
            assert!((v - piston.velocity).abs() <= 1e-12 * (1.0 + v.abs()));
            let steady = m.state(&CrankState::new(theta, 7.0, 0.0, 0.0)).pistons[0];
            let a = steady.d2x_dtheta2 * 49.0;
            assert!((a - steady.acceleration).abs() <= 1e-12 * (1.0 + a.abs()));
        }
    }
}

/// The piston-only path (a separate code path, for speed) gives the full state's position bit
/// for bit (the state's crank direction e^{iθ}) and dx/dθ to round-off; its dx/dθ is the derivative of its own x (central differences, an
/// independent check); top dead centre is where the piston reaches its top, with dx/dθ = 0.
#[test]
fn piston_position_is_the_states_and_dead_centres() {
    for m in machines() {
        for k in 0..=1000 {
            let theta = -7.0 + 0.0173 * k as f64;
            let p = m.state(&CrankState::new(theta, 1.0, 0.0, 0.0)).pistons[0];
            let (x, dx) = m.piston_position(theta);
            assert!(
                (dx - p.dx_dtheta).abs() <= 1e-15,
                "{} θ = {theta}",
                m.name()
            );
            // Bit for bit where the crank direction is e^{iθ}: a gas model takes a block's
            // chamber volumes from its positions (`cardan_gas::PreparedGas::lanes`).
            assert_eq!(
                x.to_bits(),
                p.position.to_bits(),
                "{} θ = {theta}",
                m.name()
            );
            if m.has_cylinder() {
                assert!(p.position <= m.piston_top() * (1.0 + 1e-15));
                assert!(p.position >= m.piston_bottom() * (1.0 - 1e-15));
            }
        }
        // Dead centres belong to pistons in cylinders; turning piston links have none.
        if !m.has_cylinder() {
            continue;
        }
        let tdc = m.piston_position(m.top_dead_centre());
        assert!((tdc.0 - m.piston_top()).abs() < 1e-14, "{}", m.name());
        assert!(tdc.1.abs() < 1e-14, "{}", m.name());
    }
}

/// A block of crank states filled together is, lane by lane, what filling each alone (a block
/// of one, [`Mechanism::state`]) gives, for every mechanism, whatever the block's length (a
/// mechanism may work across the block); a lane scattered back is the lane.
#[test]
fn fill_block_is_fill_state_by_state() {
    let motion = CrankMotion {
        start_angle: 0.3,
        initial_speed: 200.0,
        angular_acceleration: 300.0,
    };
    let cranks = motion.grid(0.3, 7.0, LANES + 3).unwrap();
    for m in machines() {
        let t = m.topology();
        let mut block = StateBlock::for_topology(t);
        for len in [1, 7, 8, 9, 16, 38, LANES] {
            block.fill(m.as_ref(), &cranks[..len]);
            assert_eq!(block.len, len);
            for (i, c) in cranks[..len].iter().enumerate() {
                let mut got = State::for_topology(t);
                block.gather(i, &mut got);
                let alone = m.state(c);
                got.extras.clone_from(&alone.extras);
                assert_eq!(got, alone, "{} at {} rad, block {len}", m.name(), c.angle);
                let mut back = block.clone();
                back.scatter(i, &got);
                assert_eq!(back, block, "{} lane {i}", m.name());
            }
        }
    }
}
