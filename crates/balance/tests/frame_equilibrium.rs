//! Cross-check without a paper: the shaking force is what the frame's equilibrium says it
//! receives. The general planar solve (`cardan_dynamics::planar`, Newton-Euler of every body
//! with every joint reaction unknown) gives the loads on each body from the frame through the
//! joints whose `other` is the frame, and the drive torque; the moving system's momentum
//! balance makes their sum Σ m·a, so the frame gets −Σ (its reactions): the shaking force. About
//! the crank axis, −Σ (z_j × F_j + M_j) − T_drive is the roll moment. Every registered
//! mechanism, inertia alone (gas acts on piston and head alike), accelerating, on a grid clear of
//! the hypotrochoid's folds (from 0.1 rad, 997 steps, as `cardan-dynamics`' own tests).

mod common;
use cardan_balance::shaking;
use cardan_dynamics::planar;
use cardan_mechanism::{
    cross, CrankMotion, Grid, Loads, MachineGeometry, MassInputs, Mechanism, MotionSource,
    OptionKind, OptionValue, Options, C, MECHANISMS,
};
use cardan_testing::near;
use common::*;
use std::f64::consts::PI;

/// Every registered mechanism on the thesis geometry, and the readings that are not defaults
/// (an offset piston pin, the involute cardan mesh), as `cardan-dynamics`' generic tests take
/// them.
fn every_machine() -> Vec<(String, Box<dyn Mechanism>)> {
    let mut all: Vec<(String, Box<dyn Mechanism>)> = MECHANISMS
        .iter()
        .map(|e| {
            (
                e.name.to_string(),
                machine(e.name, &THESIS, &MassInputs::default()),
            )
        })
        .collect();
    for entry in MECHANISMS {
        let offset = MachineGeometry {
            pin_offset: 0.012,
            ..THESIS
        };
        if let Ok(m) = (entry.build)(&offset, &MassInputs::default(), &Options::new()) {
            if m.topology().pistons
                != machine(entry.name, &THESIS, &MassInputs::default())
                    .topology()
                    .pistons
            {
                all.push((format!("{} offset", entry.name), m));
            }
        }
        // A wheel that carries its own mass, where the mechanism has a wheel (issue 24).
        let wheel = MassInputs {
            wheel_mass: Some(0.7),
            ..MassInputs::default()
        };
        let with_wheel = !entry.unused_masses.contains(&"wheel_mass");
        if with_wheel {
            let m = (entry.build)(&THESIS, &wheel, &Options::new()).unwrap();
            all.push((format!("{} wheel mass", entry.name), m));
        }
        for option in entry.options {
            if let OptionKind::Choice(words) = option.kind {
                for word in &words[1..] {
                    let mut o = Options::new();
                    o.insert(option.name.into(), OptionValue::Word(word.to_string()));
                    let m = (entry.build)(&THESIS, &MassInputs::default(), &o).unwrap();
                    all.push((format!("{} {word}", entry.name), m));
                    if with_wheel {
                        let m = (entry.build)(&THESIS, &wheel, &o).unwrap();
                        all.push((format!("{} {word} wheel mass", entry.name), m));
                    }
                }
            }
        }
    }
    all
}

#[test]
fn the_shaking_force_is_minus_the_frame_reactions_for_every_mechanism() {
    let machines = every_machine();
    // The registry, and at least the offset piston pin and the involute mesh besides.
    assert!(
        machines.len() >= MECHANISMS.len() + 2,
        "{} machines",
        machines.len()
    );
    for (name, mech) in machines {
        let topology = mech.topology();
        let motion = CrankMotion {
            start_angle: 0.1,
            initial_speed: 60.0,
            angular_acceleration: 400.0,
        };
        let mut grid = Grid::new(motion, 0.1, 0.1 + 4.0 * PI, 997);
        let mut rows = Vec::new();
        while let Some(crank) = grid.next(None) {
            let state = mech.state(&crank.unwrap());
            let mut loads = Loads::for_topology(topology);
            let residual = planar::loads(topology, &state, true, &[], &mut loads);
            let (mut force, mut moment) = (C::new(0.0, 0.0), loads.crank_torque);
            for (joint, (load, at)) in topology
                .joints
                .iter()
                .zip(loads.joints.iter().zip(&state.joints))
            {
                if joint.other.is_none() {
                    force += load.force;
                    moment += cross(at.position, load.force) + load.moment;
                }
            }
            rows.push((shaking(topology, &state), force, moment, residual));
        }
        // 1e-9 of the peak: the planar solve's own agreement with the closed forms
        // (`cardan-dynamics` cross_checks.rs); its residual is checked below it.
        let peak = rows.iter().map(|r| r.0.force.norm()).fold(0.0, f64::max);
        let peak_roll = rows
            .iter()
            .map(|r| r.0.roll.abs())
            .fold(peak * THESIS.crank_length, f64::max);
        assert!(peak > 1.0, "{}: the machine shakes ({peak} N)", name);
        for (s, reactions, moment, residual) in rows {
            assert!(residual < 1e-9 * peak, "{}: residual {residual}", name);
            near(
                &format!("{} shaking force + frame reactions", name),
                (s.force + reactions).norm(),
                0.0,
                1e-9 * peak,
            );
            near(
                &format!("{} roll + frame moments", name),
                s.roll + moment,
                0.0,
                1e-9 * peak_roll,
            );
        }
    }
}
