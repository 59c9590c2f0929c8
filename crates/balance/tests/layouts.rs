//! Multi-cylinder machines against the direct-and-reverse-crank closed forms and the classic
//! layout table (`docs/validation/balance.md`): each cylinder runs the registered slider-crank
//! (its reciprocating mass alone: a massless rod, as the textbook examples take it), summed by
//! [`Layout`].
//!
//! The closed form: cylinder i's order k is P_k·cos k(ψ_i − π/2) along its axis i·e^{iβ_i}
//! (ψ_i = θ + φ_i − β_i; P_k = m·r·ω²·q_k(λ), `common::q`), i.e. two half-size vectors turning
//! at ±k·ω; summed, |A_k| = (P_k/2)·|Σ_i w_i·e^{i(k·φ_i + (1−k)·β_i)}| and |B_k| =
//! (P_k/2)·|Σ_i w_i·e^{i(−k·φ_i + (1+k)·β_i)}|, with w_i = 1 for the force and w_i = z_i − z₀ for
//! the free moment.

mod common;
use cardan_balance::{
    lanchester_shafts, throws_from_firing_order, CardanCounterweights, CardanMasses, Cylinder,
    Layout, MachineOrders, Rotor,
};
use cardan_mechanism::{MassInputs, Mechanism, C};
use cardan_testing::near;
use common::*;
use std::f64::consts::PI;

/// 360 steps per revolution: the orders of λ ≤ 0.43 above 180 are below 1e-60 of the first.
const STEPS: usize = 360;

/// The closed-form |A_k|, |B_k| of the force (`moment` false) or the free moment of `layout`,
/// for the reciprocating harmonic amplitude `p` (N).
fn direct_and_reverse(layout: &Layout, k: usize, p: f64, moment: bool) -> (f64, f64) {
    let z0 = layout.reference();
    let k = k as f64;
    let (mut a, mut b) = (C::new(0.0, 0.0), C::new(0.0, 0.0));
    for c in &layout.cylinders {
        let w = if moment { c.axial_position - z0 } else { 1.0 };
        a += w * C::from_polar(1.0, k * c.throw + (1.0 - k) * c.axis_angle);
        b += w * C::from_polar(1.0, -k * c.throw + (1.0 + k) * c.axis_angle);
    }
    (p / 2.0 * a.norm(), p / 2.0 * b.norm())
}

/// The machine's orders 0..=6 and the checks of orders 1, 2, 4 against the closed form, to
/// 1e-10 of the single cylinder's first order (round-off of 360-term sums).
struct Machine {
    mech: Box<dyn Mechanism>,
    speed: f64,
    p1: f64,
    lambda: f64,
}

impl Machine {
    fn new(crank: f64, rod: f64, mass: f64, rpm: f64) -> Self {
        let speed = rpm * 2.0 * PI / 60.0;
        Self {
            mech: pistons_only("slider_crank", crank, rod, mass),
            speed,
            p1: mass * crank * speed * speed,
            lambda: crank / rod,
        }
    }

    fn orders(&self, layout: &Layout) -> MachineOrders {
        layout.orders(self.mech.as_ref(), &[], self.speed, STEPS, 6)
    }

    fn check(&self, name: &str, layout: &Layout) -> MachineOrders {
        let o = self.orders(layout);
        let tol = 1e-10 * self.p1 * layout.cylinders.len() as f64;
        let arm = layout
            .cylinders
            .iter()
            .map(|c| (c.axial_position - layout.reference()).abs());
        let mtol = tol * arm.fold(1.0, f64::max);
        for k in [1, 2, 4] {
            let p = self.p1 * q(k, self.lambda);
            let (a, b) = direct_and_reverse(layout, k, p, false);
            near(
                &format!("{name} force order {k} forward"),
                o.force[k].forward.norm(),
                a,
                tol,
            );
            near(
                &format!("{name} force order {k} backward"),
                o.force[k].backward.norm(),
                b,
                tol,
            );
            let (a, b) = direct_and_reverse(layout, k, p, true);
            near(
                &format!("{name} moment order {k} forward"),
                o.moment[k].forward.norm(),
                a,
                mtol,
            );
            near(
                &format!("{name} moment order {k} backward"),
                o.moment[k].backward.norm(),
                b,
                mtol,
            );
        }
        o
    }
}

/// The inline six of the standard crank (throws 1/6, 2/5, 3/4 at 120°, from the four-stroke
/// firing order 1-5-3-6-2-4) has no first or second order force or moment, and its sixth
/// order force is six cylinders' (6·m·r·ω²·q₆).
#[test]
fn an_inline_six_is_free_of_first_and_second_orders() {
    let m = Machine::new(0.045, 0.15, 0.6, 6000.0);
    let throws = throws_from_firing_order(&[1, 5, 3, 6, 2, 4], 4.0 * PI / 6.0);
    for (i, t) in throws.iter().enumerate() {
        let pair = throws[5 - i];
        near("mirror throws", (t - pair).abs(), 0.0, 1e-12);
    }
    let layout = Layout::in_line(&throws, 0.1);
    let o = m.check("inline-6", &layout);
    let tol = 1e-10 * m.p1;
    for k in [1, 2, 3, 4, 5] {
        near(
            &format!("force order {k}"),
            o.force[k].amplitude(),
            0.0,
            tol * 6.0,
        );
        near(
            &format!("moment order {k}"),
            o.moment[k].amplitude(),
            0.0,
            tol * 6.0 * 0.25,
        );
    }
    let six = 6.0 * m.p1 * q(6, m.lambda);
    near("force order 6", o.force[6].amplitude(), six, tol * 6.0);
}

/// The inline four of the flat crank (0°, 180°, 180°, 0°): no first order force or moment, no
/// second order moment, a second order force of 4·m·r·ω²·q₂ (≈ 4·m·r·ω²·λ, within the λ³/4
/// the approximation leaves out) and a fourth of 4·m·r·ω²·q₄.
#[test]
fn a_flat_inline_four_shakes_at_the_second_order() {
    let m = Machine::new(0.04, 0.14, 0.5, 6000.0);
    let layout = Layout::in_line(&[0.0, PI, PI, 0.0], 0.09);
    let o = m.check("inline-4", &layout);
    let tol = 1e-10 * m.p1 * 4.0;
    near("force order 1", o.force[1].amplitude(), 0.0, tol);
    near("moment order 1", o.moment[1].amplitude(), 0.0, tol);
    near("moment order 2", o.moment[2].amplitude(), 0.0, tol);
    let second = 4.0 * m.p1 * q(2, m.lambda);
    near("force order 2", o.force[2].amplitude(), second, tol);
    let approx = 4.0 * m.p1 * m.lambda;
    near(
        "force order 2 ≈ 4·m·r·ω²·λ",
        o.force[2].amplitude(),
        approx,
        approx * m.lambda.powi(2) / 3.0,
    );
    near(
        "force order 4",
        o.force[4].amplitude(),
        4.0 * m.p1 * q(4, m.lambda),
        tol,
    );
    // The throws of the four-stroke firing order 1-3-4-2 are the flat crank.
    let throws = throws_from_firing_order(&[1, 3, 4, 2], PI);
    for (t, want) in throws.iter().zip([0.0, PI, PI, 0.0]) {
        near("flat crank", *t, want, 1e-12);
    }
}

/// A three-cylinder radial engine, every rod on the one pin (the inputs of a textbook problem,
/// `docs/validation/balance.md`: stroke 120 mm, rod 240 mm, 1 kg per cylinder, 2400 rpm): the
/// primary force is a constant (3/2)·m·r·ω² = 5684.9 N turning with the crank, the secondary a
/// constant (3/2)·m·r·ω²·q₂ turning backwards (1444.1 N; 1421.2 N to first order in λ), the
/// fourth order forward.
#[test]
fn a_three_cylinder_radial_engine_has_rotating_primary_and_secondary_forces() {
    let m = Machine::new(0.06, 0.24, 1.0, 2400.0);
    let o = m.check("radial-3", &Layout::radial(3));
    let tol = 1e-10 * m.p1 * 3.0;
    near("primary", o.force[1].forward.norm(), 1.5 * m.p1, tol);
    near("primary backward", o.force[1].backward.norm(), 0.0, tol);
    near(
        "primary (derived value)",
        o.force[1].amplitude(),
        5684.89,
        0.01,
    );
    near(
        "secondary backward",
        o.force[2].backward.norm(),
        1.5 * m.p1 * q(2, m.lambda),
        tol,
    );
    near("secondary forward", o.force[2].forward.norm(), 0.0, tol);
    near(
        "secondary to first order in λ",
        o.force[2].amplitude(),
        1.5 * m.p1 * 0.25,
        1.5 * m.p1 * 0.25 * 0.02,
    );
    near("fourth backward", o.force[4].backward.norm(), 0.0, tol);
    // Its secondary turns backwards alone: of the two balance shafts sized from it, the
    // forward one has no mass, and the backward one cancels it (to 1e-12 of it).
    let shafts = lanchester_shafts(&o.force[2], m.speed, 0.0);
    near("forward shaft", shafts[0].mass_radius.norm(), 0.0, 1e-12);
    let balanced = Layout::radial(3).orders(m.mech.as_ref(), &shafts, m.speed, STEPS, 4);
    near(
        "secondary with a shaft",
        balanced.force[2].amplitude(),
        0.0,
        1e-12 * o.force[2].amplitude(),
    );
    near(
        "primary with a shaft",
        balanced.force[1].amplitude(),
        o.force[1].amplitude(),
        tol,
    );
    // One plane: no free moment.
    near(
        "moment",
        o.moment[1].amplitude() + o.moment[2].amplitude(),
        0.0,
        tol,
    );
}

/// An inline four with its throws at 90° in the order 1-4-2-3 (the inputs of a textbook
/// problem: crank 50 mm, rod 200 mm, 2 kg, 2000 rpm, cylinders 0.2 m apart): primary and
/// secondary forces cancel; the primary couple about the central plane is
/// m·r·ω²·|Σ zᵢ·e^{iφᵢ}| = m·r·ω²·0.2√2 = 1240.7 N·m, the secondary m·r·ω²·q₂·0.8 (877.3 N·m to
/// first order in λ).
#[test]
fn an_inline_four_with_cranks_at_ninety_degrees_has_primary_and_secondary_couples() {
    let m = Machine::new(0.05, 0.2, 2.0, 2000.0);
    // End view: 1 at 0°, 4 at 90°, 2 at 180°, 3 at 270°.
    let layout = Layout::in_line(&[0.0, PI, 1.5 * PI, 0.5 * PI], 0.2);
    let o = m.check("inline-4 90°", &layout);
    let tol = 1e-10 * m.p1 * 4.0;
    near("primary force", o.force[1].amplitude(), 0.0, tol);
    near("secondary force", o.force[2].amplitude(), 0.0, tol);
    near(
        "primary couple",
        o.moment[1].amplitude(),
        m.p1 * 0.2 * 2f64.sqrt(),
        tol,
    );
    near(
        "primary couple (derived value)",
        o.moment[1].amplitude(),
        1240.7,
        0.1,
    );
    near(
        "secondary couple",
        o.moment[2].amplitude(),
        m.p1 * q(2, m.lambda) * 0.8,
        tol,
    );
    let first_order = 877.3;
    near(
        "secondary couple ≈ first order in λ (derived value)",
        o.moment[2].amplitude(),
        first_order,
        first_order * m.lambda.powi(2) / 3.0,
    );
}

/// The classic table of free forces and moments by layout: which orders cancel and what is
/// left, from the direct-and-reverse-crank sums (`Machine::check`) and, for each entry the
/// table prints, its simple closed form (a: cylinder pitch; P₁ = m·r·ω², P₂ = P₁·q₂).
#[test]
fn the_layout_table_of_free_forces_and_moments() {
    let m = Machine::new(0.04, 0.16, 0.5, 5000.0);
    let a = 0.1;
    let (p1, p2) = (m.p1, m.p1 * q(2, m.lambda));
    let third = 2.0 * PI / 3.0;
    // (name, layout, [F1, F2, M1, M2] amplitudes)
    let vee = |bank: f64| Layout {
        cylinders: [-bank / 2.0, bank / 2.0]
            .iter()
            .map(|&b| Cylinder {
                throw: 0.0,
                axis_angle: b,
                axial_position: 0.0,
            })
            .collect(),
    };
    let boxer = Layout {
        cylinders: vec![
            Cylinder {
                throw: 0.0,
                axis_angle: 0.0,
                axial_position: 0.0,
            },
            Cylinder {
                throw: PI,
                axis_angle: PI,
                axial_position: a,
            },
        ],
    };
    let table: Vec<(&str, Layout, [f64; 4])> = vec![
        ("single", Layout::single(), [p1, p2, 0.0, 0.0]),
        (
            "inline-2 180°",
            Layout::in_line(&[0.0, PI], a),
            [0.0, 2.0 * p2, p1 * a, 0.0],
        ),
        (
            "inline-2 360°",
            Layout::in_line(&[0.0, 0.0], a),
            [2.0 * p1, 2.0 * p2, 0.0, 0.0],
        ),
        (
            "inline-3",
            Layout::in_line(&[0.0, 2.0 * third, third], a),
            [0.0, 0.0, 3f64.sqrt() * p1 * a, 3f64.sqrt() * p2 * a],
        ),
        (
            "inline-4 flat",
            Layout::in_line(&[0.0, PI, PI, 0.0], a),
            [0.0, 4.0 * p2, 0.0, 0.0],
        ),
        ("boxer-2", boxer, [0.0, 0.0, p1 * a, p2 * a]),
        ("vee-2 90°", vee(PI / 2.0), [p1, 2f64.sqrt() * p2, 0.0, 0.0]),
        (
            "vee-2 60°",
            vee(PI / 3.0),
            [1.5 * p1, 3f64.sqrt() / 2.0 * p2, 0.0, 0.0],
        ),
    ];
    for (name, layout, [f1, f2, m1, m2]) in table {
        let o = m.check(name, &layout);
        let tol = 1e-10 * p1 * 4.0;
        near(&format!("{name} F1"), o.force[1].amplitude(), f1, tol);
        near(&format!("{name} F2"), o.force[2].amplitude(), f2, tol);
        near(&format!("{name} M1"), o.moment[1].amplitude(), m1, tol);
        near(&format!("{name} M2"), o.moment[2].amplitude(), m2, tol);
    }
}

/// The thesis cardan gear in every cylinder (rod and piston m, crank r_c, with a 0.4 kg wheel
/// and a 0.01 kg·m crank unbalance per cylinder), its rotors given in the cylinder's frame and
/// placed by [`Layout::place`].
fn cardan() -> (Box<dyn Mechanism>, CardanMasses) {
    let mech = machine("cardan_gear", &THESIS, &MassInputs::default());
    let masses = CardanMasses {
        crank: THESIS.crank_length / 2.0,
        reciprocating: mech.topology().bodies.iter().map(|b| b.mass).sum(),
        wheel: 0.4,
        crank_unbalance: 0.01,
    };
    (mech, masses)
}

/// Each cylinder's rotors (in its own frame) placed in the machine frame.
fn placed(layout: &Layout, rotors: &[Rotor]) -> Vec<Rotor> {
    (0..layout.cylinders.len())
        .flat_map(|i| rotors.iter().map(move |r| layout.place(i, r)))
        .collect()
}

/// Cardan machines whose every cylinder carries its counterweight pair (sized from its masses
/// in its own frame, placed by the layout) have no shaking force and no free moment at any
/// step, accelerating, whatever the throws, axis angles and axial positions (to 1e-12 of the
/// bare machine's first order: round-off).
#[test]
fn cardan_machines_with_their_counterweight_pairs_do_not_shake() {
    let (mech, masses) = cardan();
    let pair = CardanCounterweights::for_masses(&masses, 0.025);
    let own: Vec<Rotor> = masses
        .rotors()
        .into_iter()
        .chain(pair.rotors(&masses))
        .collect();
    let w = Layout {
        cylinders: [-60.0f64, 0.0, 60.0]
            .iter()
            .map(|b| Cylinder {
                throw: 0.0,
                axis_angle: b.to_radians(),
                axial_position: 0.0,
            })
            .collect(),
    };
    let odd = Layout {
        cylinders: vec![
            Cylinder {
                throw: 0.0,
                axis_angle: 0.0,
                axial_position: 0.0,
            },
            Cylinder {
                throw: 1.1,
                axis_angle: 0.7,
                axial_position: 0.05,
            },
            Cylinder {
                throw: 4.0,
                axis_angle: -2.0,
                axial_position: 0.13,
            },
        ],
    };
    let speed = 300.0;
    for (name, layout) in [
        ("radial-5", Layout::radial(5)),
        (
            "inline-3",
            Layout::in_line(&[0.0, 4.0 * PI / 3.0, 2.0 * PI / 3.0], 0.1),
        ),
        ("half-radial", w),
        ("custom", odd),
    ] {
        let rotors = placed(&layout, &own);
        let bare = layout.orders(
            mech.as_ref(),
            &placed(&layout, &masses.rotors()),
            speed,
            64,
            2,
        );
        let scale =
            bare.force[1].forward.norm() + masses.reciprocating * masses.crank * speed * speed;
        let motion = cardan_mechanism::CrankMotion {
            start_angle: 0.2,
            initial_speed: speed,
            angular_acceleration: -3000.0,
        };
        for crank in motion.grid(0.2, 6.0, 300).unwrap() {
            let s = layout.shaking(mech.as_ref(), &rotors, &crank);
            near(
                &format!("{name} force at {}", crank.angle),
                s.force.norm(),
                0.0,
                1e-12 * scale * 5.0,
            );
            near(
                &format!("{name} moment at {}", crank.angle),
                s.moment.norm(),
                0.0,
                1e-12 * scale * 0.5,
            );
        }
    }
}

/// A radial cardan engine (3 or more cylinders on one pin) has a first order that turns with
/// the crank alone, n·m·r_c·ω² forward plus the wheels' and cranks' unbalance, and no other
/// order: one counterweight on the crank, sized from those masses, balances it completely.
#[test]
fn a_radial_cardan_engine_is_balanced_by_one_crank_counterweight() {
    let (mech, masses) = cardan();
    let speed = 400.0;
    for n in [3, 5, 6] {
        let layout = Layout::radial(n);
        let unbalance: Vec<Rotor> = placed(&layout, &masses.rotors());
        let o = layout.orders(mech.as_ref(), &unbalance, speed, 64, 6);
        let forward = n as f64
            * ((masses.reciprocating + masses.wheel) * masses.crank + masses.crank_unbalance)
            * speed
            * speed;
        let tol = 1e-12 * forward;
        near(
            &format!("radial-{n} forward"),
            o.force[1].forward.norm(),
            forward,
            tol,
        );
        near(
            &format!("radial-{n} backward"),
            o.force[1].backward.norm(),
            0.0,
            tol,
        );
        for k in 2..=6 {
            near(
                &format!("radial-{n} order {k}"),
                o.force[k].amplitude(),
                0.0,
                tol,
            );
        }
        let weight = Rotor::on_crank(-o.force[1].forward / (speed * speed), 0.0);
        let all: Vec<Rotor> = unbalance.into_iter().chain([weight]).collect();
        let balanced = layout.orders(mech.as_ref(), &all, speed, 64, 6);
        assert!(
            balanced.force.iter().all(|o| o.amplitude() <= tol),
            "radial-{n}: {balanced:?}"
        );
    }
}
