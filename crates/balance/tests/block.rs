//! The machine's balance over a block of states (`PreparedBalance::at_block`, read from the
//! block's columns) gives the very bits of its step-by-step form (`PreparedBalance::at_state`
//! on each gathered state), and the step-by-step form with its kept block gives the bits of
//! the layout's own sum over freshly made states (`Layout::shaking`): for every registered
//! mechanism, with and without balancing devices, at an accelerating crank, one cylinder in its
//! own frame or turned, several cylinders. A cross-check of two paths of the same arithmetic:
//! no published value.

mod common;

use cardan_balance::{Cylinder, CylinderScratch, Layout, MachineBalance};
use cardan_mechanism::{CrankState, Mechanism, State, StateBlock, MECHANISMS, ZERO};
use common::*;
use std::f64::consts::PI;
use std::sync::Arc;

/// 50 crank states of a crank speeding up from 40 rad/s at 900 rad/s² (every lane's speed and
/// acceleration non-zero, so the rotors' tangential terms count).
fn cranks() -> Vec<CrankState> {
    (0..50)
        .map(|i| {
            let t = i as f64 * 1e-3;
            CrankState::new(0.3 + 40.0 * t + 450.0 * t * t, 40.0 + 900.0 * t, 900.0, t)
        })
        .collect()
}

/// The machines of one cylinder: none, a half counterweight with Lanchester shafts, the
/// cardan pair (where the mechanism has a wheel), each in its own frame and turned.
fn single_cylinder_machines() -> Vec<MachineBalance> {
    let turned = Layout {
        cylinders: vec![Cylinder {
            throw: 0.4,
            axis_angle: 0.3,
            axial_position: 0.05,
        }],
    };
    let mut all = Vec::new();
    for layout in [Layout::single(), turned] {
        let plain = MachineBalance {
            layout,
            ..MachineBalance::default()
        };
        all.push(MachineBalance {
            counterweight: Some(0.5),
            lanchester: true,
            ..plain.clone()
        });
        all.push(MachineBalance {
            cardan_counterweights: true,
            ..plain.clone()
        });
        all.push(plain);
    }
    all
}

#[test]
fn the_balance_of_a_block_is_the_balance_of_each_step_bit_for_bit() {
    let cranks = cranks();
    for entry in MECHANISMS {
        let m: Arc<dyn Mechanism> = machine(entry.name, &THESIS, &Default::default()).into();
        let t = m.topology();
        let mut block = StateBlock::for_topology(t);
        block.fill(m.as_ref(), &cranks);
        for machine in single_cylinder_machines() {
            // The cardan pair needs a wheel: refused otherwise, nothing to compare.
            let Ok(balance) = machine.prepare(Arc::clone(&m)) else {
                continue;
            };
            let mut out = [ZERO; 5];
            balance.at_block(&block, &mut CylinderScratch::default(), &mut out);
            let mut state = State::for_topology(t);
            let mut scratch = CylinderScratch::default();
            for i in 0..cranks.len() {
                block.gather(i, &mut state);
                let s = balance.at_state(&state, &mut scratch);
                let each = [s.force.re, s.force.im, s.pitch(), s.yaw()];
                for (k, (column, v)) in out.iter().zip(&each).enumerate() {
                    assert_eq!(
                        column[i].to_bits(),
                        v.to_bits(),
                        "{}, {machine:?}: lane {i}, value {k}",
                        entry.name
                    );
                }
            }
        }
    }
}

#[test]
fn the_balance_of_a_step_with_a_kept_block_is_the_layout_sum_bit_for_bit() {
    let cranks = cranks();
    let in_line = Layout::in_line(&[0.0, PI, PI, 0.0], 0.1);
    for entry in MECHANISMS {
        let m: Arc<dyn Mechanism> = machine(entry.name, &THESIS, &Default::default()).into();
        for layout in [in_line.clone(), Layout::radial(3)] {
            let n = layout.cylinders.len();
            let machine = MachineBalance {
                layout: layout.clone(),
                firing_delay: vec![0.0; n],
                counterweight: Some(0.5),
                ..MachineBalance::default()
            };
            let balance = machine.prepare(Arc::clone(&m)).unwrap();
            assert!(!balance.by_block());
            let mut scratch = CylinderScratch::default();
            for crank in &cranks {
                let own = m.state(crank);
                let kept = balance.at_state(&own, &mut scratch);
                let fresh = layout.shaking(m.as_ref(), balance.rotors(), crank);
                for (a, b) in [(kept.force, fresh.force), (kept.moment, fresh.moment)] {
                    assert_eq!(
                        (a.re.to_bits(), a.im.to_bits()),
                        (b.re.to_bits(), b.im.to_bits()),
                        "{}, {layout:?} at {crank:?}",
                        entry.name
                    );
                }
            }
        }
    }
}

/// A device that cannot be formed names the device (the case maps it to its field): the crank
/// counterweight beside the cardan pair, with every mechanism (the pair, where a mechanism
/// could not carry it, refused first).
#[test]
fn a_device_that_cannot_be_formed_names_the_device() {
    use cardan_balance::Device;
    let both = MachineBalance {
        counterweight: Some(0.5),
        cardan_counterweights: true,
        ..MachineBalance::default()
    };
    let pair = MachineBalance {
        cardan_counterweights: true,
        ..MachineBalance::default()
    };
    for entry in MECHANISMS {
        let m: Arc<dyn Mechanism> = machine(entry.name, &THESIS, &Default::default()).into();
        let e = both.prepare(Arc::clone(&m)).err();
        // The pair is equipped first: a mechanism that cannot carry it is refused for it.
        let device = e.map(|e| e.device);
        assert!(device.is_some(), "{}", entry.name);
        if let Err(e) = pair.prepare(Arc::clone(&m)) {
            assert_eq!(e.device, Device::CardanCounterweights, "{}", entry.name);
            assert_eq!(device, Some(Device::CardanCounterweights), "{}", entry.name);
        } else {
            assert_eq!(device, Some(Device::Counterweight), "{}", entry.name);
        }
    }
}
