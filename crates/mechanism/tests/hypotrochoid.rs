//! The hypotrochoid mechanism against Vidinsky (2021) (values verified in
//! docs/validation/vidinsky-2021.md), its own kinematic identities, finite
//! differences of its state, and its option checks.

use cardan_mechanism::hypotrochoid::{slider_crank_mechanical_advantage, Hypotrochoid};
use cardan_mechanism::{
    Bearings, CrankMotion, CrankState, MachineGeometry, MassInputs, Mechanism, OptionValue,
    Options, State, C,
};
use std::f64::consts::{PI, TAU};

/// The paper's theory model (Figs 10-18): p = 3/4, r = 1.7·m, u = 1 (eq 5).
fn paper(m: usize) -> Hypotrochoid {
    Hypotrochoid::new(
        m,
        0.75,
        1.7 * m as f64,
        1.0,
        cardan_mechanism::hypotrochoid::massless(),
        [Bearings::single(0.01, 1e4); 3],
    )
    .unwrap()
}

fn deg(x: f64) -> f64 {
    x.to_radians()
}

/// Largest MA on a fine θ grid over the working range L..N, and where.
fn max_ma(h: &Hypotrochoid) -> (f64, f64) {
    let (l, _, n) = h.working_range();
    (0..=200_000)
        .map(|k| {
            let th = l + (n - l) * k as f64 / 200_000.0;
            (h.mechanical_advantage(th), th)
        })
        .fold((f64::MIN, 0.0), |a, b| if b.0 > a.0 { b } else { a })
}

/// Vidinsky L335, L345, L499: maximum mechanical advantage 3 (m = 2) at θ = 120° and
/// 2.31567 (m = 3) at 97.5°.
#[test]
fn maximum_mechanical_advantage() {
    let (ma, at) = max_ma(&paper(2));
    assert!((ma - 3.0).abs() < 1e-9, "m = 2: {ma}");
    assert!((at.to_degrees() - 120.0).abs() < 1e-3, "m = 2 at {at}");
    assert!((paper(2).mechanical_advantage(deg(120.0)) - 3.0).abs() < 1e-14);
    let (ma, at) = max_ma(&paper(3));
    assert!((ma - 2.315669).abs() < 5e-7, "m = 3: {ma}");
    assert!((at.to_degrees() - 97.5).abs() < 1e-3, "m = 3 at {at}");
    // The closed form of the extraction (§2.5): 2(m+1)·sin(π/m)/(m·√(1 − λ²cos²(π/m))).
    let lambda = 0.75 / 5.1;
    let closed =
        8.0 * (PI / 3.0).sin() / (3.0 * (1.0 - (lambda * (PI / 3.0).cos()).powi(2)).sqrt());
    assert!((paper(3).mechanical_advantage(deg(97.5)) - closed).abs() < 1e-13);
}

/// The working range (L229): L_2 = π/2, N_2 = 5π/6; L_3 = 5π/12, N_3 = 2π/3; MA = 0 there
/// and δ at its extremes (§4.1: 154.5128° → 205.4872° for m = 2, 105.3663° → 134.6337° for
/// m = 3).
#[test]
fn chamber_angle_at_l_and_n() {
    for (m, l, n, dl, dn) in [
        (2, PI / 2.0, 5.0 * PI / 6.0, 154.5128, 205.4872),
        (3, 5.0 * PI / 12.0, 2.0 * PI / 3.0, 105.3663, 134.6337),
    ] {
        let h = paper(m);
        let (hl, hm, hn) = h.working_range();
        assert!((hl - l).abs() < 1e-15 && (hn - n).abs() < 1e-15);
        assert!((hm - (l + n) / 2.0).abs() < 1e-15);
        assert!(h.mechanical_advantage(l).abs() < 1e-14);
        assert!(h.mechanical_advantage(n).abs() < 1e-14);
        assert!(
            (h.chamber_angle(l).0.to_degrees() - dl).abs() < 5e-5,
            "m = {m}"
        );
        assert!(
            (h.chamber_angle(n).0.to_degrees() - dn).abs() < 5e-5,
            "m = {m}"
        );
        // δ(M) = 2π/m, its mean.
        assert!((h.chamber_angle(hm).0 - TAU / m as f64).abs() < 1e-14);
        // δ between L and N never leaves [δ(L), δ(N)].
        for k in 0..=100 {
            let d = h
                .chamber_angle(l + (n - l) * k as f64 / 100.0)
                .0
                .to_degrees();
            assert!(d >= dl - 5e-5 && d <= dn + 5e-5);
        }
    }
}

/// The reference kinematics of the extraction §4.1 (θ, ψ, χ, q, ψ'(θ), ψ'(θ+2π/m), δ, MA).
#[test]
fn reference_kinematics_table() {
    let rows: [(usize, [f64; 8]); 6] = [
        (
            2,
            [
                105.0, 113.9736, -8.9736, 2.828055, 0.526263, 1.473737, 162.0528, 2.147606,
            ],
        ),
        (2, [120.0, 120.0, 0.0, 2.65, 0.338235, 1.661765, 180.0, 3.0]),
        (
            2,
            [150.0, 137.2564, 12.7436, 3.316248, 1.0, 1.0, 205.4872, 0.0],
        ),
        (
            3,
            [
                75.0, 82.3169, -7.3169, 4.683471, 0.703468, 0.703468, 105.3663, 0.0,
            ],
        ),
        (
            3,
            [
                86.25, 88.4313, -2.1813, 4.371860, 0.431396, 1.153806, 109.6523, 1.637462,
            ],
        ),
        (
            3,
            [
                108.75, 100.5836, 8.1664, 4.854171, 0.846194, 1.568604, 130.3477, 1.637462,
            ],
        ),
    ];
    for (m, [th, psi, chi, q, d0, d1, delta, ma]) in rows {
        let h = paper(m);
        let t = deg(th);
        let near = |a: f64, b: f64, tol: f64, what: &str| {
            assert!((a - b).abs() <= tol, "m = {m} θ = {th}: {what} {a} vs {b}")
        };
        near(h.psi(t).0.to_degrees(), psi, 5e-5, "ψ");
        near(h.chi(t).0.to_degrees(), chi, 5e-5, "χ");
        near(h.rod(t).0, q, 5e-7, "q");
        near(h.psi(t).1, d0, 5e-7, "ψ'");
        near(h.psi(t + TAU / m as f64).1, d1, 5e-7, "ψ'(θ+2π/m)");
        near(h.chamber_angle(t).0.to_degrees(), delta, 5e-5, "δ");
        near(h.mechanical_advantage(t), ma, 5e-7, "MA");
    }
}

/// Appendix B replay (extraction §7.3): the validation model's printed peaks MA[[22]] =
/// 2.99959 (m = 2) and MA[[24]] = 2.31548 (m = 3), at θ_k = L + off + (k−1)·0.05/m.
#[test]
fn validation_model_samples() {
    let h = paper(2);
    let th = PI / 2.0 + 0.004211 + 21.0 * 0.05 / 2.0;
    assert!((h.mechanical_advantage(th) - 2.99959).abs() < 2e-5);
    let h = paper(3);
    let th = 5.0 * PI / 12.0 + 0.009014 + 23.0 * 0.05 / 3.0;
    assert!((h.mechanical_advantage(th) - 2.31548).abs() < 4e-4);
}

/// The inline slider crank (eqs 22-29, L481): maxima 1.024092 at 78.10° (a = 0.75, h = 3.4)
/// and 1.010760 at 81.805° (h = 5.1), mean 1.0174 ("approximately 1.017"); eq 29 equals the
/// velocity ratio ṡ/(a·θ̇) of eqs 22-23 (eq 28) by central differences.
#[test]
fn slider_crank_mechanical_advantage_maxima() {
    let mut maxima = Vec::new();
    for (h, expected, at) in [(3.4, 1.024092, 78.098), (5.1, 1.010760, 81.805)] {
        let (ma, th) = (0..=1_000_000)
            .map(|k| {
                let th = PI * k as f64 / 1_000_000.0;
                (slider_crank_mechanical_advantage(0.75, h, th), th)
            })
            .fold((f64::MIN, 0.0), |a, b| if b.0 > a.0 { b } else { a });
        assert!((ma - expected).abs() < 5e-7, "h = {h}: {ma}");
        assert!((th.to_degrees() - at).abs() < 2e-3, "h = {h}: at {th}");
        maxima.push(ma);
        let s = |t: f64| {
            let beta = (0.75 * t.sin() / h).asin(); // eq 22
            0.75 * t.cos() + h * beta.cos() // eq 23
        };
        for k in 1..20 {
            let t = 0.157 * k as f64;
            let ds = (s(t + 1e-6) - s(t - 1e-6)) / 2e-6;
            assert!((-ds / 0.75 - slider_crank_mechanical_advantage(0.75, h, t)).abs() < 1e-8);
        }
    }
    assert!((0.5 * (maxima[0] + maxima[1]) - 1.017426).abs() < 1e-6);
    // Table of the extraction §4.1.
    for (h, th, ma) in [
        (3.4, 30.0, 0.596104),
        (3.4, 120.0, 0.768716),
        (5.1, 60.0, 0.930227),
    ] {
        assert!((slider_crank_mechanical_advantage(0.75, h, deg(th)) - ma).abs() < 5e-7);
    }
}

/// Gears and parallelogram: the planet rolls on the ring (its pitch point does not move), the
/// coupler C_u − A stays parallel and equal to the carrier O_u − O (the PCC), each block stays
/// on its rotor rod at distance r from O, and the rotor rods are spaced by 2π/m.
#[test]
fn rolling_parallelogram_and_rods() {
    for m in 2..=5 {
        let h = paper(m);
        for k in 0..40 {
            let phi = -2.0 + 0.37 * k as f64;
            let st = h.state(&CrankState::new(phi, 3.0, 2.0, 0.0));
            let planet = st.bodies[2];
            let mesh = st.joints[3].position;
            let v =
                planet.cg.velocity + C::i() * planet.angular_velocity * (mesh - planet.cg.position);
            assert!(v.norm() < 1e-12, "m = {m}: pitch point slips at {v}");
            assert!(
                (mesh.norm() - (m + 1) as f64).abs() < 1e-12,
                "ring radius (m+1)·u"
            );
            let (a, cu, ou) = (
                st.joints[4].position,
                st.joints[5].position,
                st.joints[2].position,
            );
            assert!((cu - a - ou).norm() < 1e-12);
            assert!((ou.norm() - m as f64).abs() < 1e-12, "carrier v = m·u");
            for j in 0..m {
                let b = st.joints[6 + 3 * j + 1].position;
                assert!((b.norm() - 1.7 * m as f64).abs() < 1e-12);
                let rod = st.joints[6 + 3 * j + 2].direction;
                assert!((b - a).im * rod.re - (b - a).re * rod.im < 1e-12);
                let expected =
                    st.bodies[3].orientation * C::from_polar(1.0, -TAU * j as f64 / m as f64);
                assert!((rod - expected).norm() < 1e-12);
            }
            // The crank turns m times as fast as the carrier, the other way (eq 4).
            assert!(
                (st.bodies[0].angular_velocity + m as f64 * st.bodies[1].angular_velocity).abs()
                    < 1e-12
            );
        }
    }
}

/// Central differences in time of every body's centre of gravity and orientation, every
/// piston and every joint (position, and the relative speed of the slides and pins), for
/// m = 2, 3, 4 under a crank that speeds up; dx/dθ and d²x/dθ² of every piston.
#[test]
fn finite_differences() {
    let motion = CrankMotion {
        start_angle: 0.3,
        initial_speed: 30.0,
        angular_acceleration: 400.0,
    };
    for m in 2..=4 {
        let h = paper(m);
        for phi in [0.4, 1.2, 2.5, 4.0, 5.9, 9.7] {
            let now = motion.at_angle(phi).unwrap();
            let at = |dt: f64| {
                h.state(&CrankState::new(
                    phi + now.speed * dt + 0.5 * now.acceleration * dt * dt,
                    now.speed + now.acceleration * dt,
                    now.acceleration,
                    now.time + dt,
                ))
            };
            let dt = 1e-6;
            let (s, p, q) = (h.state(&now), at(-dt), at(dt));
            let d = |f: &dyn Fn(&State) -> C| (f(&q) - f(&p)) / (2.0 * dt);
            let check = |what: &str, numeric: C, exact: C| {
                let scale = exact.norm().max(1.0);
                assert!(
                    (numeric - exact).norm() < 1e-6 * scale,
                    "m = {m} φ = {phi}: {what}: numeric {numeric} vs {exact}"
                );
            };
            for (k, b) in h.topology().bodies.iter().enumerate() {
                let x = s.bodies[k];
                check(b.name, d(&|y| y.bodies[k].cg.position), x.cg.velocity);
                check(b.name, d(&|y| y.bodies[k].cg.velocity), x.cg.acceleration);
                check(
                    b.name,
                    d(&|y| y.bodies[k].orientation),
                    C::i() * x.angular_velocity * x.orientation,
                );
                check(
                    b.name,
                    d(&|y| y.bodies[k].angular_velocity.into()),
                    x.angular_acceleration.into(),
                );
            }
            for k in 0..m {
                let x = s.pistons[k];
                check(
                    "piston",
                    d(&|y| y.pistons[k].position.into()),
                    x.velocity.into(),
                );
                check(
                    "piston",
                    d(&|y| y.pistons[k].velocity.into()),
                    x.acceleration.into(),
                );
                assert!(
                    (x.dx_dtheta * now.speed - x.velocity).abs() < 1e-12 * (1.0 + x.velocity.abs())
                );
                let steady = h.state(&CrankState::new(phi, 7.0, 0.0, 0.0)).pistons[k];
                assert!(
                    (steady.d2x_dtheta2 * 49.0 - steady.acceleration).abs()
                        < 1e-12 * (1.0 + steady.acceleration.abs())
                );
            }
            let topology = h.topology();
            for (j, joint) in topology.joints.iter().enumerate() {
                // Pins and meshes: position of a point of `body` (the mesh: its pitch point
                // moves with the carrier). Relative speeds: body minus other.
                let w =
                    |y: &State, b: Option<usize>| b.map_or(0.0, |b| y.bodies[b].angular_velocity);
                let rel = s.bodies[joint.body].angular_velocity - w(&s, joint.other);
                match joint.kind {
                    cardan_mechanism::JointKind::Revolute(_) => {
                        assert!(
                            (s.joints[j].relative_speed - rel).abs() < 1e-12,
                            "{}",
                            joint.name
                        );
                    }
                    cardan_mechanism::JointKind::Prismatic => {
                        // The block's distance from A along the rod: q.
                        let a = |y: &State| y.joints[4].position;
                        let along = |y: &State| {
                            let b = y.joints[j].position - a(y);
                            let e = y.joints[j].direction;
                            C::new(b.re * e.re + b.im * e.im, 0.0)
                        };
                        check(joint.name, d(&along), s.joints[j].relative_speed.into());
                    }
                    cardan_mechanism::JointKind::GearMesh { ratio, .. } => {
                        assert_eq!(ratio, (m + 1) as f64);
                        let carrier = s.bodies[1].angular_velocity;
                        let planet = s.bodies[2].angular_velocity;
                        assert!(
                            (s.joints[j].relative_speed - h.planet * (planet - carrier)).abs()
                                < 1e-12
                        );
                    }
                }
            }
        }
    }
}

/// Extras: θ, δ and MA at the crank angle of each state; φ = π/2 is L_m.
#[test]
fn extras() {
    let h = paper(3);
    let (l, m_state, _) = h.working_range();
    let st = h.state(&CrankState::new(std::f64::consts::FRAC_PI_2, 1.0, 0.0, 0.0));
    assert!((st.extras[0] - 75.0).abs() < 1e-12);
    assert!((st.extras[1] - 105.3663).abs() < 5e-5);
    assert!(st.extras[2].abs() < 1e-14);
    let st = h.state(&CrankState::new(h.crank_angle(m_state), 1.0, 0.0, 0.0));
    assert!((st.extras[0] - 97.5).abs() < 1e-12);
    assert!((st.extras[2] - 2.315669).abs() < 5e-7);
    assert!((h.carrier_angle(h.crank_angle(1.234)) - 1.234).abs() < 1e-15);
    assert!((h.carrier_angle(std::f64::consts::FRAC_PI_2) - l).abs() < 1e-15);
    // The stroke is the first chamber's arc swing r·(δ(N) − δ(L)).
    assert!((h.stroke() - 5.1 * deg(134.6337 - 105.3663)).abs() < 1e-5);
}

fn geometry() -> MachineGeometry {
    MachineGeometry {
        crank_length: 0.075,
        rod_length: 0.2,
        bore: 0.1,
        pin_offset: 0.0,
    }
}

fn build(options: &[(&str, f64)]) -> Result<Hypotrochoid, cardan_mechanism::MechanismError> {
    let mut o = Options::new();
    for (k, v) in options {
        o.insert(k.to_string(), OptionValue::Number(*v));
    }
    Hypotrochoid::build(&geometry(), &MassInputs::default(), &o)
}

/// Defaults: the paper's validation model (§6, L365): p = 75 mm, u = 100 mm, r = 340 mm.
#[test]
fn defaults_are_the_validation_model() {
    let h = build(&[]).unwrap();
    assert_eq!(h.modulus, 2);
    assert!((h.planet - 0.1).abs() < 1e-15);
    assert!((h.link - 0.34).abs() < 1e-15);
    let h = build(&[("angular_modulus", 3.0)]).unwrap();
    assert!((h.link - 0.51).abs() < 1e-15);
    assert_eq!(h.topology().pistons.len(), 3);
    assert_eq!(h.topology().bodies.len(), 4 + 2 * 3);
    assert_eq!(h.topology().joints.len(), 6 + 3 * 3);
    assert_eq!(h.masses().piston_mass, 0.0);
}

#[test]
fn bad_options_name_their_field() {
    for (options, field) in [
        (vec![("angular_modulus", 1.0)], "angular_modulus"),
        (vec![("angular_modulus", 2.5)], "angular_modulus"),
        (vec![("angular_modulus", 9.0)], "angular_modulus"),
        (vec![("piston_link_length", 0.07)], "piston_link_length"),
        (vec![("piston_link_length", -1.0)], "piston_link_length"),
        (vec![("planet_radius", 0.0)], "planet_radius"),
    ] {
        let e = build(&options).unwrap_err();
        let field = cardan_mechanism::Input::Option {
            mechanism: "hypotrochoid",
            name: field,
        };
        assert_eq!(e.field, field, "{options:?}: {e}");
    }
    let inputs = MassInputs {
        rod_cg: Some(0.5),
        ..MassInputs::default()
    };
    let e = Hypotrochoid::build(&geometry(), &inputs, &Options::new()).unwrap_err();
    assert_eq!(e.field, cardan_mechanism::Input::RodCg);
}
