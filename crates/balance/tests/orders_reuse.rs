//! The orders a prepared machine reports (`PreparedBalance::orders`, taken in a room it keeps
//! from one call to the next) are, bit for bit, the plain computation's: every step's machine
//! shaking from freshly made states (`Layout::shaking`) and the transform's sums written out
//! as `harmonics` once wrote them, one vector at a time. Called again at another speed and back
//! (a room left by another call), and from a freshly prepared machine, for every registered
//! mechanism, one cylinder in its own frame or turned, with and without devices, and
//! machines of several cylinders. A cross-check of two paths of the same arithmetic: no
//! published value.

mod common;

use cardan_balance::{
    revolution, Cylinder, Layout, MachineBalance, MachineOrders, Order, PreparedBalance, Rotor,
    MAX_ORDER, ORDER_STEPS,
};
use cardan_mechanism::{Mechanism, C, MECHANISMS};
use common::*;
use std::f64::consts::{PI, TAU};
use std::sync::Arc;

/// The orders of `samples` (taken at 2πj/N) as the plain sums over the samples, order by order:
/// A_k = (1/N)·Σ v·e^{−ikθ_j}, B_k = (1/N)·Σ v·e^{ikθ_j}, e^{ikθ_j} = e^{i·m·2π/N} with
/// m = k·j mod N.
fn plain_orders(samples: &[C], max_order: usize) -> Vec<Order> {
    let n = samples.len();
    let step = TAU / n as f64;
    (0..=max_order)
        .map(|k| {
            let (mut forward, mut backward) = (C::new(0.0, 0.0), C::new(0.0, 0.0));
            for (j, v) in samples.iter().enumerate() {
                let e = C::from_polar(1.0, ((k * j) % n) as f64 * step);
                forward += v * e.conj();
                backward += v * e;
            }
            let backward = if k == 0 {
                C::new(0.0, 0.0)
            } else {
                backward / n as f64
            };
            Order {
                order: k,
                forward: forward / n as f64,
                backward,
            }
        })
        .collect()
}

/// The machine's orders at `speed` the plain way: the machine's shaking at each step of the
/// revolution from states made for it ([`Layout::shaking`]), then [`plain_orders`].
fn plain(layout: &Layout, m: &dyn Mechanism, rotors: &[Rotor], speed: f64) -> MachineOrders {
    let (forces, moments): (Vec<C>, Vec<C>) = revolution(0.0, speed, ORDER_STEPS)
        .iter()
        .map(|crank| {
            let s = layout.shaking(m, rotors, crank);
            (s.force, s.moment)
        })
        .unzip();
    MachineOrders {
        force: plain_orders(&forces, MAX_ORDER),
        moment: plain_orders(&moments, MAX_ORDER),
    }
}

/// Every component of `a` and `b` has the same bits.
fn assert_same_bits(a: &MachineOrders, b: &MachineOrders, what: &str) {
    let bits = |o: &[Order]| -> Vec<(usize, [u64; 4])> {
        o.iter()
            .map(|o| {
                let (f, b) = (o.forward, o.backward);
                let parts = [f.re, f.im, b.re, b.im].map(f64::to_bits);
                (o.order, parts)
            })
            .collect()
    };
    assert_eq!(bits(&a.force), bits(&b.force), "{what}: force");
    assert_eq!(bits(&a.moment), bits(&b.moment), "{what}: moment");
}

/// The machines: one cylinder in its own frame, turned, with a counterweight and Lanchester
/// shafts, with the cardan pair; an in-line three and four with counterweights; a radial
/// three.
fn machines() -> Vec<MachineBalance> {
    let turned = Layout {
        cylinders: vec![Cylinder {
            throw: 0.4,
            axis_angle: 0.3,
            axial_position: 0.05,
        }],
    };
    let several = [
        Layout::in_line(&[0.0, 2.0 * PI / 3.0, 4.0 * PI / 3.0], 0.09),
        Layout::in_line(&[0.0, PI, PI, 0.0], 0.1),
        Layout::radial(3),
    ];
    let mut all = vec![
        MachineBalance::default(),
        MachineBalance {
            counterweight: Some(0.5),
            lanchester: true,
            ..MachineBalance::default()
        },
        MachineBalance {
            cardan_counterweights: true,
            ..MachineBalance::default()
        },
        MachineBalance {
            layout: turned,
            ..MachineBalance::default()
        },
    ];
    for layout in several {
        let n = layout.cylinders.len();
        all.push(MachineBalance {
            layout,
            firing_delay: vec![0.0; n],
            counterweight: Some(0.5),
            ..MachineBalance::default()
        });
    }
    all
}

#[test]
fn the_orders_from_a_kept_room_are_the_plain_orders_bit_for_bit() {
    // 300 rpm, 3000 rpm, and back: each call's values differ from the last one's.
    let speeds = [10.0 * PI, 100.0 * PI, 10.0 * PI];
    let mut compared = 0;
    for entry in MECHANISMS {
        let m: Arc<dyn Mechanism> = machine(entry.name, &THESIS, &Default::default()).into();
        for machine in machines() {
            // Devices a mechanism cannot carry are refused: nothing to compare.
            let Ok(kept) = machine.prepare(Arc::clone(&m)) else {
                continue;
            };
            for (call, &speed) in speeds.iter().enumerate() {
                let what = format!("{}, {machine:?}, call {call} at {speed} rad/s", entry.name);
                let reused = kept.orders(speed);
                let fresh: PreparedBalance = machine.prepare(Arc::clone(&m)).unwrap();
                assert_same_bits(&reused, &fresh.orders(speed), &what);
                let equipped = kept.mechanism().as_ref();
                let reference = plain(&machine.layout, equipped, kept.rotors(), speed);
                assert_same_bits(&reused, &reference, &what);
                // A clone starts with a room of its own and gives the same bits.
                assert_same_bits(&reused, &kept.clone().orders(speed), &what);
                compared += 1;
            }
        }
    }
    assert!(
        compared >= 3 * 7 * MECHANISMS.len().min(2),
        "{compared} compared"
    );
}
