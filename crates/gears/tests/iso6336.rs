//! ISO 6336 method B rating, the materials table and the tooth thickness measurements:
//! published values where one was reachable, and cross-checks that need no paper.

use cardan_gears::iso6336::{rate, IsoDynamic, IsoInputs, IsoMember, STEEL_DENSITY};
use cardan_gears::iso6336_pitting::{contact_ratio_factor, elasticity_factor, zone_factor};
use cardan_gears::materials::{material, IsoQuality, LifeCurve};
use cardan_gears::tooth_measurement::{span_width, span_width_auto, MeasuredGear};
use cardan_gears::units::PSI;
use cardan_gears::{GearPair, PairSpec};

fn member(y_f: f64) -> IsoMember {
    IsoMember {
        sigma_hlim: 1500e6,
        sigma_flim: 425e6,
        life_curve: LifeCurve::CaseHardened,
        form_factor: y_f,
        stress_correction_factor: 1.9,
        rim_factor: 1.0,
        notch_sensitivity: 1.0,
        surface_factor: 1.0,
        cycles: 1e9,
    }
}

fn inputs(torque: f64, dynamic: IsoDynamic, transverse: Option<f64>) -> IsoInputs {
    IsoInputs {
        pinion_torque: torque,
        pinion_speed: 1500.0 * std::f64::consts::PI / 30.0,
        face_width: 30e-3,
        application_factor: 1.25,
        dynamic,
        accuracy_grade: Some(6.0),
        face_load_factor: 1.3,
        transverse_load_factor: transverse,
        elasticity_factor: elasticity_factor(206e9, 0.3, 206e9, 0.3).unwrap(),
        lubrication: None,
        members: [member(2.6), member(2.3)],
    }
}

fn pair(z2: i32) -> GearPair {
    GearPair::new(PairSpec::standard(
        3e-3,
        20,
        z2,
        20f64.to_radians(),
        0.0,
        0.0,
    ))
    .unwrap()
}

#[test]
fn steel_pair_from_the_table_gives_189_8() {
    // ISO 6336-2 §7: Z_E = 189.8 √(N/mm²) for steel on steel (printed to 4 digits).
    let s = material("steel-case-carburized").unwrap();
    let z = elasticity_factor(
        s.youngs_modulus,
        s.poisson_ratio,
        s.youngs_modulus,
        s.poisson_ratio,
    )
    .unwrap();
    assert!((z / 1e3 - 189.8).abs() < 0.05, "{}", z / 1e3);
}

#[test]
fn agma_through_hardened_allowables_match_shigley_example_14_4() {
    // Shigley Ex. 14-4: grade 1, 240 HB: St = 31 350 psi, Sc = 106 400 psi (printed to 4
    // and 4 significant digits: ±5 and ±50 psi).
    let m = material("steel-through-hardened").unwrap();
    let a = m.agma_allowables(Some(240.0), 1).unwrap();
    assert!(
        (a.bending / PSI - 31_350.0).abs() <= 5.0,
        "{}",
        a.bending / PSI
    );
    assert!(
        (a.contact / PSI - 106_400.0).abs() <= 50.0,
        "{}",
        a.contact / PSI
    );
    // The brief's SI form of grade 1: s_ac = 2.22 HB + 200 MPa (AGMA 2001-D04 Fig. 8 metric),
    // equal to the psi line to its 3-digit coefficients (0.3 %).
    assert!((a.contact / 1e6 - (2.22 * 240.0 + 200.0)).abs() / a.contact * 1e6 < 3e-3);
}

#[test]
fn iso_limits_lie_on_the_table_lines_and_bronze_has_none() {
    let m = material("steel-case-carburized").unwrap();
    let l = m.iso_limits(None, IsoQuality::Mq).unwrap();
    assert_eq!((l.contact, l.bending), (1500e6, 425e6));
    // ML < MQ < ME for every steel and hardness inside the ranges.
    for (name, hb) in [
        ("steel-through-hardened", Some(300.0)),
        ("steel-nitrided", Some(300.0)),
        ("nitriding-steel", Some(300.0)),
        ("steel-case-carburized", None),
    ] {
        let m = material(name).unwrap();
        let q = |q| m.iso_limits(hb, q).unwrap();
        let (ml, mq, me) = (q(IsoQuality::Ml), q(IsoQuality::Mq), q(IsoQuality::Me));
        assert!(ml.contact < mq.contact && mq.contact < me.contact, "{name}");
        assert!(ml.bending < mq.bending && mq.bending < me.bending, "{name}");
    }
    assert!(material("tin-bronze")
        .unwrap()
        .iso_limits(None, IsoQuality::Mq)
        .is_err());
    // Outside the table's hardness range is refused, not extrapolated.
    assert!(material("steel-through-hardened")
        .unwrap()
        .iso_limits(Some(150.0), IsoQuality::Mq)
        .is_err());
}

#[test]
fn spur_factors_in_closed_form() {
    // Unshifted spur pair: α_wt = α, so Z_H = 2/√(sin 2α) and Z_ε = √((4 − ε_α)/3).
    let p = pair(40);
    let r = rate(&p, &inputs(200.0, IsoDynamic::Given(1.1), Some(1.0))).unwrap();
    let a = 20f64.to_radians();
    assert!((r.z_h - zone_factor(0.0, a, a)).abs() < 1e-12);
    assert!((r.z_eps - contact_ratio_factor(p.contact_ratio, 0.0)).abs() < 1e-12);
    // σ_H0 by hand: F_t = 2T/d1, √(F_t/(d1 b) (u+1)/u).
    let d1 = 60e-3;
    let ft = 2.0 * 200.0 / d1;
    let hand = r.z_h * r.z_e * r.z_eps * (ft / (d1 * 30e-3) * 3.0_f64 / 2.0).sqrt();
    assert!((r.sigma_h0 - hand).abs() < 1e-9 * hand);
    // σ_F0 = F_t/(b m) Y_F Y_S for spur (Y_β = Y_B = Y_DT = 1).
    let sf0 = ft / (30e-3 * 3e-3) * 2.6 * 1.9;
    assert!((r.sigma_f0[0] - sf0).abs() < 1e-9 * sf0);
}

#[test]
fn safety_factors_scale_with_load() {
    // With the load-dependent factors held (K_v, K_Hα given), S_H ∝ 1/√F_t and S_F ∝ 1/F_t.
    let p = pair(40);
    let a = rate(&p, &inputs(100.0, IsoDynamic::Given(1.1), Some(1.05))).unwrap();
    let b = rate(&p, &inputs(400.0, IsoDynamic::Given(1.1), Some(1.05))).unwrap();
    for k in 0..2 {
        assert!((a.s_h[k] / b.s_h[k] - 2.0).abs() < 1e-12);
        assert!((a.s_f[k] / b.s_f[k] - 4.0).abs() < 1e-12);
    }
}

#[test]
fn internal_pair_contact_is_milder_and_has_no_z_d() {
    // (u+1)/u: external 20/40 → 1.5, internal 20/−40 → 0.5, so σ_H0 falls by √3 with the
    // same Z_H Z_E Z_ε (both unshifted: α_wt = α), and the ring's Z_D is 1 (ISO 6336-2 §6.2).
    let e = rate(&pair(40), &inputs(200.0, IsoDynamic::Given(1.1), Some(1.0))).unwrap();
    let i = rate(
        &pair(-40),
        &inputs(200.0, IsoDynamic::Given(1.1), Some(1.0)),
    )
    .unwrap();
    let ratio = (e.sigma_h0 / e.z_eps) / (i.sigma_h0 / i.z_eps);
    assert!((ratio - 3f64.sqrt()).abs() < 1e-9, "{ratio}");
    assert_eq!(i.z_bd[1], 1.0);
}

/// Z_B = M1 is √ of the relative curvature at the pinion's inner point of single contact B over
/// that at the pitch point C (ISO 6336-2 §6.2's meaning of eq. (10)), computed here from the
/// flanks' radii of curvature along the line of action, with no ISO formula: ρ1 from the
/// pinion's tip less one base pitch, ρ2 = ρ1 ∓ the distance between the tangency points
/// (external: Σ ρ = a sin α_w; internal: ρ2 − ρ1 = a sin α_w), curvature 1/ρ1 ± 1/ρ2. An
/// internal 20/40 pair at 20° with a 0.8-module ring addendum: M1 ≈ 1.17 (before the ring's
/// sign was kept, the external formula gave 2.25 and σ_H 1.9 times too high).
#[test]
fn z_b_is_the_curvature_ratio_of_the_inner_single_contact_point() {
    use cardan_gears::iso6336_pitting::single_pair_factors;
    for (z2, ring_addendum) in [(40, 1.0), (-40, 0.8), (-60, 1.0)] {
        let mut spec = cardan_gears::PairSpec::standard(3e-3, 20, z2, 20f64.to_radians(), 0.0, 0.0);
        if z2 < 0 {
            spec.gear = spec.gear.with_addendum(ring_addendum);
        }
        let p = cardan_gears::GearPair::new(spec).unwrap();
        let internal = z2 < 0;
        let (rb1, rb2) = (p.pinion.base / 2.0, p.gear.base.abs() / 2.0);
        let ra1 = p.pinion.tip / 2.0;
        let aw = p.operating_pressure_angle;
        let tangency = (rb2 - if internal { rb1 } else { -rb1 }) * aw.tan();
        let pb = std::f64::consts::PI * 3e-3 * 20f64.to_radians().cos();
        let rho1 = |at_b: bool| {
            if at_b {
                (ra1 * ra1 - rb1 * rb1).sqrt() - pb
            } else {
                rb1 * aw.tan()
            }
        };
        let curvature = |r1: f64| {
            if internal {
                1.0 / r1 - 1.0 / (r1 + tangency)
            } else {
                1.0 / r1 + 1.0 / (tangency - r1)
            }
        };
        let m1 = (curvature(rho1(true)) / curvature(rho1(false))).sqrt();
        let (zb, _) = single_pair_factors(
            20.0,
            f64::from(z2.abs()),
            [p.pinion.tip, p.gear.tip.abs()],
            [p.pinion.base, p.gear.base.abs()],
            aw,
            p.contact_ratio,
            0.0,
            internal,
        );
        // The same geometry two ways: only rounding apart.
        assert!(
            (zb - m1.max(1.0)).abs() < 1e-9,
            "z2 = {z2}: Z_B {zb}, curvature ratio {m1}"
        );
    }
}

#[test]
fn method_b_dynamic_factor_is_plausible_and_grows_with_speed() {
    // Method B K_v: above 1, rising with speed below resonance, and the transverse factors
    // within ISO 6336-1 §8.3.4's limits.
    let p = pair(40);
    let mut lo = inputs(
        200.0,
        IsoDynamic::MethodB {
            density: STEEL_DENSITY,
        },
        None,
    );
    lo.pinion_speed = 500.0 * std::f64::consts::PI / 30.0;
    let mut hi = lo;
    hi.pinion_speed = 3000.0 * std::f64::consts::PI / 30.0;
    let (a, b) = (rate(&p, &lo).unwrap(), rate(&p, &hi).unwrap());
    assert!(a.resonance_ratio.unwrap() < b.resonance_ratio.unwrap());
    assert!(b.resonance_ratio.unwrap() < 0.85, "{:?}", b.resonance_ratio);
    assert!(1.0 < a.k_v && a.k_v < b.k_v, "{} {}", a.k_v, b.k_v);
    assert!(
        a.k_halpha >= 1.0 && a.k_halpha <= p.contact_ratio / (p.contact_ratio * a.z_eps.powi(2))
    );
    // Without the accuracy grade method B cannot run: a clear error.
    let mut none = lo;
    none.accuracy_grade = None;
    assert!(rate(&p, &none).is_err());
}

#[test]
fn span_width_matches_the_published_example() {
    // MachineCalcs span calculator worked example: m = 2 mm, z = 20, α = 20°, x = 0:
    // k = 3, W = 15.321 mm (printed to 0.001 mm: ±0.0005 mm).
    let g = MeasuredGear {
        module: 2e-3,
        pressure_angle: 20f64.to_radians(),
        teeth: 20,
        shift: 0.0,
        thinning: 0.0,
        internal: false,
    };
    let s = span_width_auto(&g).unwrap();
    assert_eq!(s.teeth, 3);
    assert!((s.width * 1e3 - 15.321).abs() < 5e-4, "{}", s.width * 1e3);
    // One more tooth adds one base pitch; thinning j takes j cos α off.
    let s4 = span_width(&g, 4).unwrap();
    assert!(
        (s4.width - s.width - std::f64::consts::PI * 2e-3 * 20f64.to_radians().cos()).abs() < 1e-15
    );
    let thin = MeasuredGear {
        thinning: 0.1e-3,
        ..g
    };
    let t = span_width(&thin, 3).unwrap();
    assert!((s.width - t.width - 0.1e-3 * 20f64.to_radians().cos()).abs() < 1e-15);
}
