//! Masses the crankshaft carries besides the mechanism's bodies (its own unbalance, its
//! counterweight: issue 24) load the main bearing, and nothing else. Cross-check without a
//! paper, the frame's equilibrium: the frame's reactions on the moving system (every joint whose
//! `other` is the frame) balance the machine's shaking force, the bodies' −Σ m·a
//! (`cardan_balance::shaking`) plus the carried masses' (`cardan_balance::Rotor::force`), at
//! every step of an accelerating run, for every registered mechanism and every reading of its
//! options (the involute cardan mesh's total is solved from the families together: the carried
//! masses must reach it too). Every other joint's load and the drive torque stay the balanced
//! crankshaft's, bit for bit.

use cardan_balance::{shaking, Rotor};
use cardan_dynamics::{run, Gas, Inertial, LoadFamily, Sink, Solver, StepRecord, Steps};
use cardan_mechanism::{
    CrankMotion, Grid, MachineGeometry, MassInputs, Mechanism, OptionKind, OptionValue, Options, C,
    MECHANISMS,
};
use cardan_testing::near;
use std::f64::consts::PI;

/// Karhula's machine (crank 60 mm, rod 140 mm, bore 120 mm).
const THESIS: MachineGeometry = MachineGeometry {
    crank_length: 0.06,
    rod_length: 0.14,
    bore: 0.12,
    pin_offset: 0.0,
};

/// Every registered mechanism in every reading of its options.
fn every_machine() -> Vec<(String, Box<dyn Mechanism>)> {
    let mut all = Vec::new();
    for entry in MECHANISMS {
        let build = |o: &Options| (entry.build)(&THESIS, &MassInputs::default(), o).unwrap();
        all.push((entry.name.to_string(), build(&Options::new())));
        for option in entry.options {
            if let OptionKind::Choice(words) = option.kind {
                for word in &words[1..] {
                    let mut o = Options::new();
                    o.insert(option.name.into(), OptionValue::Word(word.to_string()));
                    all.push((format!("{} {word}", entry.name), build(&o)));
                }
            }
        }
    }
    all
}

/// Every step of an accelerating run of `m` with the inertial family carrying `u` (kg·m) and a
/// gas family of no force (two families: a mechanism whose joints do not superpose solves its
/// total from them together).
fn steps(m: &dyn Mechanism, u: C) -> Vec<StepRecord> {
    let inertial = Inertial::new(Solver::ClosedForm).carrying(u);
    let gas = Gas(Solver::ClosedForm);
    let families: [&dyn LoadFamily; 2] = [&inertial, &gas];
    let no_force = |_: f64| (0.0, 0.0);
    let motion = CrankMotion {
        start_angle: 0.1,
        initial_speed: 60.0,
        angular_acceleration: 400.0,
    };
    // Clear of the hypotrochoid's folds, as `cardan-balance`'s frame test.
    let mut grid = Grid::new(motion, 0.1, 0.1 + 4.0 * PI, 997);
    let mut kept = Steps::default();
    let mut sinks: [&mut dyn Sink; 1] = [&mut kept];
    run(
        m,
        &mut grid,
        &families,
        Some(&no_force),
        &mut [],
        &mut sinks,
    )
    .unwrap();
    kept.0
}

#[test]
fn the_crankshafts_carried_masses_load_the_main_bearing_alone() {
    let machines = every_machine();
    assert!(machines.len() > MECHANISMS.len(), "an option's reading too");
    // An unbalance off the crank's direction: both components of the force are exercised.
    let u = C::new(0.35, -0.12);
    let rotor = Rotor::on_crank(u, 0.0);
    for (name, m) in machines {
        let t = m.topology();
        let balanced = steps(m.as_ref(), C::new(0.0, 0.0));
        let carried = steps(m.as_ref(), u);
        let main = t
            .joints
            .iter()
            .position(|j| j.name == "main_bearing")
            .unwrap_or_else(|| panic!("{name}: a main bearing"));
        let peak = carried
            .iter()
            .map(|s| (shaking(t, &s.state).force + rotor.force(&s.state.crank)).norm())
            .fold(0.0, f64::max);
        assert!(peak > 1.0, "{name}: the machine shakes ({peak} N)");
        for (s, b) in carried.iter().zip(&balanced) {
            let angle = s.state.crank.angle;
            // Both the inertial family's loads and the total (the gas family adds nothing).
            for (label, loads) in [("inertial", &s.families[0]), ("total", &s.total)] {
                let reactions: C = t
                    .joints
                    .iter()
                    .zip(&loads.joints)
                    .filter(|(j, _)| j.other.is_none())
                    .map(|(_, l)| l.force)
                    .sum();
                let shaking = shaking(t, &s.state).force + rotor.force(&s.state.crank);
                // 1e-9 of the peak: the closed forms' own agreement with the frame's
                // equilibrium (`cardan-balance`'s frame_equilibrium.rs).
                near(
                    &format!("{name} {label} at {angle} rad: shaking + frame reactions"),
                    (shaking + reactions).norm(),
                    0.0,
                    1e-9 * peak,
                );
            }
            for (j, (with, without)) in s.total.joints.iter().zip(&b.total.joints).enumerate() {
                if j != main {
                    assert_eq!(with, without, "{name}: {} at {angle} rad", t.joints[j].name);
                }
            }
            assert_ne!(s.total.joints[main], b.total.joints[main], "{name}: loaded");
            assert_eq!(s.total.crank_torque, b.total.crank_torque, "{name}: torque");
        }
    }
}

/// The cardan counterweight pair in the joint loads: the mechanism equipped with the wheel's
/// counterweight (`MachineBalance::equip`), the crank's counterweight of the pair carried by the
/// crankshaft (`PreparedBalance::crank_masses`). The frame's reactions (main bearing and ring
/// gear) balance the machine's shaking force with every body and rotor, to 1e-9 of the peak
/// reaction, accelerating, in both mesh readings; and since the pair cancels the shaking force
/// at any crank acceleration (`cardan-balance`'s closed forms), the frame feels no net force:
/// the main bearing's reaction is minus the ring gear's at every step, neither of them zero.
#[test]
fn the_cardan_pair_loads_the_joints_and_leaves_the_frame_unshaken() {
    use cardan_balance::MachineBalance;
    use std::sync::Arc;
    let machine = MachineBalance {
        cardan_counterweights: true,
        ..MachineBalance::default()
    };
    let mut readings = 0;
    for (name, m) in every_machine() {
        // A mechanism without a cardan wheel ignores the pair (issue 35).
        if !machine.cardan_pair_applies(m.as_ref()) {
            continue;
        }
        let Ok(prepared) = machine.prepare(Arc::from(m)) else {
            continue;
        };
        readings += 1;
        let equipped = prepared.mechanism().as_ref();
        let t = equipped.topology();
        let carried = steps(equipped, prepared.crank_masses());
        let frame: Vec<usize> = (0..t.joints.len())
            .filter(|&j| t.joints[j].other.is_none())
            .collect();
        assert!(frame.len() >= 2, "{name}: main bearing and ring gear");
        let peak = carried
            .iter()
            .flat_map(|s| frame.iter().map(|&j| s.total.joints[j].force.norm()))
            .fold(0.0, f64::max);
        assert!(
            peak > 1.0,
            "{name}: the frame's joints are loaded ({peak} N)"
        );
        for s in &carried {
            let angle = s.state.crank.angle;
            let machine_shaking = prepared
                .at_state(&s.state, &mut cardan_balance::CylinderScratch::default())
                .force;
            near(
                &format!("{name} at {angle} rad: the pair's machine shaking"),
                machine_shaking.norm(),
                0.0,
                1e-9 * peak,
            );
            for (label, loads) in [("inertial", &s.families[0]), ("total", &s.total)] {
                let reactions: C = frame.iter().map(|&j| loads.joints[j].force).sum();
                near(
                    &format!("{name} {label} at {angle} rad: shaking + frame reactions"),
                    (machine_shaking + reactions).norm(),
                    0.0,
                    1e-9 * peak,
                );
            }
        }
    }
    assert_eq!(readings, 2, "the cardan gear in both mesh readings");
}
