//! One cylinder against closed forms (`docs/validation/balance.md`): the slider-crank's exact
//! harmonic series, the cardan gear's pure first order, a partial counterweight, Lanchester
//! shafts and the cardan gear's counterweight pair. Every shaking force here is the general
//! computation (−Σ m·a over the topology's bodies) on the registered mechanism's states.

mod common;
use cardan_balance::{
    crank_counterweight, lanchester_shafts, orders, revolution, shaking, CardanCounterweights,
    CardanMasses, FirstOrderMasses, Layout, Order, Rotor,
};
use cardan_mechanism::{CrankMotion, MassInputs, Mechanism, C};
use cardan_testing::{close, near};
use common::*;

/// 3000 rpm, rad/s.
const SPEED: f64 = 100.0 * std::f64::consts::PI;
/// Steps per revolution: orders above 180 of the thesis slider-crank are below λ¹⁸⁰ ≈ 1e-66 of
/// the first, so the transform's orders are exact to round-off.
const STEPS: usize = 360;

/// The orders 0..=8 of one cylinder of `mech` with `rotors` at [`SPEED`].
fn single(mech: &dyn Mechanism, rotors: &[Rotor]) -> Vec<Order> {
    Layout::single().orders(mech, rotors, SPEED, STEPS, 8).force
}

/// The slider-crank's reciprocating mass m_B = piston + rod·g/l and rotating mass
/// m_A = rod·(1 − g/l), kg: the rod's centre of gravity g from the crank pin is the mass-weighted
/// mean of its two pins, so the two masses move its weight exactly.
fn two_masses(mech: &dyn Mechanism) -> (f64, f64) {
    let m = mech.masses();
    let share = m.rod_cg / THESIS.rod_length;
    (
        m.piston_mass + m.rod_mass * share,
        m.rod_mass * (1.0 - share),
    )
}

/// The thesis slider-crank's orders 1, 2, 4, 6 are the exact series m·r·ω²·q_k(λ) (λ = 3/7),
/// its orders 3, 5, 7 vanish; the first splits into forward (m_A + m_B/2)·r·ω² and backward
/// m_B·r·ω²/2. Tolerance 1e-10 of the first order: the transform sums 360 terms of round-off
/// 1e-16 each, the series is summed to 1e-20.
#[test]
fn slider_crank_orders_are_the_exact_harmonic_series() {
    let mech = machine("slider_crank", &THESIS, &MassInputs::default());
    let (m_b, m_a) = two_masses(mech.as_ref());
    let (r, lambda) = (THESIS.crank_length, THESIS.crank_length / THESIS.rod_length);
    let p = m_b * r * SPEED * SPEED;
    let o = single(mech.as_ref(), &[]);
    let tol = 1e-10 * o[1].amplitude();
    near(
        "order 1 forward",
        o[1].forward.norm(),
        (m_a + m_b / 2.0) * r * SPEED * SPEED,
        tol,
    );
    near("order 1 backward", o[1].backward.norm(), p / 2.0, tol);
    for k in [2, 4, 6] {
        near(
            &format!("order {k}"),
            o[k].amplitude(),
            p * q(k, lambda),
            tol,
        );
        // A reciprocating order: a line along the cylinder, |A| = |B|.
        near(
            &format!("order {k} |A| − |B|"),
            o[k].forward.norm() - o[k].backward.norm(),
            0.0,
            tol,
        );
    }
    for k in [3, 5, 7] {
        near(&format!("order {k}"), o[k].amplitude(), 0.0, tol);
    }
    // The textbook truncations, within their first neglected term (35λ⁷/512 for order 2,
    // 15λ⁷/128·… for order 4, bounded here by twice the next power's coefficient).
    let l = lambda;
    let two = l + l.powi(3) / 4.0 + 15.0 * l.powi(5) / 128.0;
    near(
        "order 2 to λ⁵",
        o[2].amplitude(),
        p * two,
        2.0 * 35.0 / 512.0 * l.powi(7) * p,
    );
    let four = l.powi(3) / 4.0 + 3.0 * l.powi(5) / 16.0;
    near(
        "order 4 to λ⁵",
        o[4].amplitude(),
        p * four,
        0.25 * l.powi(7) * p,
    );
}

/// The cardan gear's rod and piston move exactly as 2·r_c·sin θ: a first order alone, |A₁| =
/// |B₁| = m·r_c·ω² (r_c = r/2), and no second, fourth or any higher order (to round-off,
/// 1e-12 of the first).
#[test]
fn cardan_gear_has_no_order_above_the_first() {
    let mech = machine("cardan_gear", &THESIS, &MassInputs::default());
    let m = mech.topology().bodies.iter().map(|b| b.mass).sum::<f64>();
    let o = single(mech.as_ref(), &[]);
    let first = m * THESIS.crank_length / 2.0 * SPEED * SPEED;
    close("order 1 forward", o[1].forward.norm(), first, 1e-12, 0.0);
    close("order 1 backward", o[1].backward.norm(), first, 1e-12, 0.0);
    for (k, order) in o.iter().enumerate().skip(2) {
        near(&format!("order {k}"), order.amplitude(), 0.0, 1e-12 * first);
    }
}

/// A counterweight of all the rotating mass and half the reciprocating mass, computed from the
/// masses the first order shows, leaves a first-order force of constant magnitude m_B·r·ω²/2:
/// the forward component is cancelled, the backward one is left (residual (1 − c)·m·r·ω²·cos φ
/// along the cylinder and c·m·r·ω²·sin φ across it, equal at c = ½). The identified masses are
/// the rod's two-mass split. With c = 1 the first order is moved across the cylinder.
#[test]
fn a_half_counterweight_leaves_a_first_order_of_constant_magnitude() {
    let mech = machine("slider_crank", &THESIS, &MassInputs::default());
    let (m_b, m_a) = two_masses(mech.as_ref());
    let r = THESIS.crank_length;
    let bare = single(mech.as_ref(), &[]);
    let masses = FirstOrderMasses::from_first_order(&bare[1], SPEED);
    close("rotating m·r", masses.rotating.re, m_a * r, 1e-12, 0.0);
    near(
        "rotating m·r across",
        masses.rotating.im,
        0.0,
        1e-12 * m_a * r,
    );
    close(
        "reciprocating m·r",
        masses.reciprocating,
        m_b * r,
        1e-12,
        0.0,
    );
    let p = m_b * r * SPEED * SPEED;
    let half = single(mech.as_ref(), &[crank_counterweight(&masses, 0.5, 0.0)]);
    near("forward", half[1].forward.norm(), 0.0, 1e-12 * p);
    close("backward", half[1].backward.norm(), p / 2.0, 1e-12, 0.0);
    close(
        "least over amplitude",
        half[1].least(),
        half[1].amplitude(),
        1e-12,
        0.0,
    );
    // The counterweight is first order alone: the second order is untouched.
    close(
        "order 2",
        half[2].amplitude(),
        bare[2].amplitude(),
        1e-12,
        0.0,
    );
    let full = single(mech.as_ref(), &[crank_counterweight(&masses, 1.0, 0.0)]);
    for theta in [0.0, 0.7, 2.0] {
        let f = full[1].at(theta);
        near("full: along the cylinder", f.im, 0.0, 1e-12 * p);
        close(
            "full: across",
            f.re.abs(),
            p * theta.cos().abs(),
            1e-12,
            1e-12 * p,
        );
    }
}

/// Two shafts at ±2ω sized from the second order cancel it (to 1e-12 of it) and leave the
/// fourth order as it was.
#[test]
fn lanchester_shafts_cancel_the_second_order() {
    let mech = machine("slider_crank", &THESIS, &MassInputs::default());
    let bare = single(mech.as_ref(), &[]);
    let shafts = lanchester_shafts(&bare[2], SPEED, 0.0);
    close(
        "shafts equal",
        shafts[0].mass_radius.norm(),
        shafts[1].mass_radius.norm(),
        1e-12,
        0.0,
    );
    let balanced = single(mech.as_ref(), &shafts);
    near(
        "order 2",
        balanced[2].amplitude(),
        0.0,
        1e-12 * bare[2].amplitude(),
    );
    close(
        "order 4",
        balanced[4].amplitude(),
        bare[4].amplitude(),
        1e-12,
        0.0,
    );
    close(
        "order 1",
        balanced[1].amplitude(),
        bare[1].amplitude(),
        1e-12,
        0.0,
    );
}

/// The cardan gear with its wheel (0.4 kg at the crank pin) and the crank's own unbalance
/// (0.01 kg·m): without the pair, a first order forward ((m + m_w)·r_c + m·e)·ω², backward
/// m·r_c·ω²; with the counterweight pair sized from those masses, a shaking force of zero at
/// every step, at constant speed and accelerating (1e-12 of the unbalanced force: round-off).
#[test]
fn the_cardan_counterweight_pair_cancels_the_shaking_force_at_every_step() {
    let mech = machine("cardan_gear", &THESIS, &MassInputs::default());
    let m = mech.topology().bodies.iter().map(|b| b.mass).sum::<f64>();
    let masses = CardanMasses {
        crank: THESIS.crank_length / 2.0,
        reciprocating: m,
        wheel: 0.4,
        crank_unbalance: 0.01,
    };
    let extra = masses.rotors();
    let bare = single(mech.as_ref(), &extra);
    let w2 = SPEED * SPEED;
    close(
        "forward",
        bare[1].forward.norm(),
        ((m + 0.4) * masses.crank + 0.01) * w2,
        1e-12,
        0.0,
    );
    close(
        "backward",
        bare[1].backward.norm(),
        m * masses.crank * w2,
        1e-12,
        0.0,
    );
    // The first order read as the texts' masses: the wheel and crank turn, the rod and piston
    // reciprocate over the cardan gear's crank radius 2·r_c (half the stroke).
    let first = FirstOrderMasses::from_first_order(&bare[1], SPEED);
    close(
        "rotating",
        first.rotating.re,
        0.4 * masses.crank + 0.01,
        1e-12,
        0.0,
    );
    close(
        "reciprocating",
        first.reciprocating,
        m * 2.0 * masses.crank,
        1e-12,
        0.0,
    );
    let pair = CardanCounterweights::for_masses(&masses, 0.02);
    close(
        "wheel counterweight",
        pair.wheel_mass * 0.02,
        m * masses.crank,
        1e-12,
        0.0,
    );
    let rotors: Vec<Rotor> = extra.into_iter().chain(pair.rotors(&masses)).collect();
    let scale = bare[1].amplitude();
    for (w0, alpha) in [(SPEED, 0.0), (10.0, 2000.0), (300.0, -400.0)] {
        let motion = CrankMotion {
            start_angle: 0.3,
            initial_speed: w0,
            angular_acceleration: alpha,
        };
        for crank in motion
            .grid(0.3, 0.3 + 4.0 * std::f64::consts::PI, 1000)
            .unwrap()
        {
            let own = shaking(mech.topology(), &mech.state(&crank)).force;
            let f: C = own + rotors.iter().map(|r| r.force(&crank)).sum::<C>();
            let peak = scale * (crank.speed.powi(2) + crank.acceleration.abs()) / w2;
            near(
                "shaking force",
                f.norm(),
                0.0,
                1e-12 * peak.max(1e-3 * scale),
            );
        }
    }
    // At constant speed through the orders too.
    let all = single(mech.as_ref(), &rotors);
    assert!(all.iter().all(|o| o.amplitude() <= 1e-12 * scale));
}

/// `orders` reads a sampled revolution the same whichever angle it starts at.
#[test]
fn the_orders_do_not_depend_on_the_start_angle() {
    let mech = machine("slider_crank", &THESIS, &MassInputs::default());
    let at = |start: f64| {
        let f: Vec<C> = revolution(start, SPEED, STEPS)
            .iter()
            .map(|c| shaking(mech.topology(), &mech.state(c)).force)
            .collect();
        orders(&f, start, 4)
    };
    let (a, b) = (at(0.0), at(1.234));
    for k in 0..=4 {
        near(
            "forward",
            (a[k].forward - b[k].forward).norm(),
            0.0,
            1e-10 * a[1].amplitude(),
        );
        near(
            "backward",
            (a[k].backward - b[k].backward).norm(),
            0.0,
            1e-10 * a[1].amplitude(),
        );
    }
}

/// The summary's revolution of `ORDER_STEPS` samples gives the orders it reports (0..=6, and so
/// `MAX_ORDER`'s) as a revolution of eight times as many does, to 1e-12 of the first order, for
/// every registered mechanism on a short rod (λ = 0.6, the slider-crank's harmonics the slowest
/// to vanish) with the piston pin offset by 10 mm: what aliasing the coarser revolution folds
/// onto an order is below round-off. (With 16 samples the same test fails: the slider-crank's
/// order 16 then folds onto its order 0, 5e-7 of the first.)
#[test]
fn the_summary_revolution_gives_every_mechanisms_orders_to_round_off() {
    use cardan_balance::ORDER_STEPS;
    let short = cardan_mechanism::MachineGeometry {
        rod_length: 0.1,
        pin_offset: 0.01,
        ..THESIS
    };
    for e in cardan_mechanism::MECHANISMS {
        let mech = machine(e.name, &short, &MassInputs::default());
        let at = |steps| {
            Layout::single()
                .orders(mech.as_ref(), &[], SPEED, steps, 6)
                .force
        };
        let (coarse, fine) = (at(ORDER_STEPS), at(8 * ORDER_STEPS));
        let scale = fine[1].amplitude();
        for k in 0..=6 {
            let forward = (coarse[k].forward - fine[k].forward).norm();
            let backward = (coarse[k].backward - fine[k].backward).norm();
            assert!(
                forward <= 1e-12 * scale && backward <= 1e-12 * scale,
                "{}: order {k} differs by {forward:e}, {backward:e} of {scale:e}",
                e.name
            );
        }
    }
}
