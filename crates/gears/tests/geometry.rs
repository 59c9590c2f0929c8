//! Internal/external pair geometry against `docs/validation/gears.md` §1 (KHK example, Karhula and
//! Nunes pairs) and paper-free cross-checks.

use cardan_gears::geometry::{karhula_contact_ratio, karhula_path_of_contact};
use cardan_gears::involute::inv;
use cardan_gears::{cardan_module, CheckKind, GearPair, PairSpec, Remedy};

fn deg(d: f64) -> f64 {
    d.to_radians()
}

fn check(p: &GearPair, kind: CheckKind) -> cardan_gears::CheckReport {
    p.checks().into_iter().find(|c| c.kind == kind).unwrap()
}

/// KHK limit `1 − tan αa2 / tan αw` (the right-hand side of the KHK criterion), recovered
/// from the margin `z1/z2 − limit`.
fn khk_limit(p: &GearPair) -> f64 {
    let z1 = p.spec.pinion.teeth as f64;
    let z2 = p.spec.gear.teeth.unsigned_abs() as f64;
    z1 / z2 - check(p, CheckKind::InvoluteInterferencePinion).margin
}

fn internal(m: f64, z1: i32, z2: i32, alpha_deg: f64, x1: f64, x2_iso: f64) -> GearPair {
    GearPair::new(PairSpec::standard(m, z1, -z2, deg(alpha_deg), x1, x2_iso)).unwrap()
}

fn internal_ring_ha(m: f64, z1: i32, z2: i32, alpha_deg: f64, ring_ha: f64) -> GearPair {
    let mut s = PairSpec::standard(m, z1, -z2, deg(alpha_deg), 0.0, 0.0);
    s.gear = s.gear.with_addendum(ring_ha);
    GearPair::new(s).unwrap()
}

#[test]
fn khk_internal_gear_example() {
    // docs/validation/gears.md §1.2: KHK Gear Technical Reference, m = 3, α = 20°, 16/24, x1 = 0,
    // x2(KHK) = 0.516 = −x2(ISO). Outputs (derived) printed to 4–6 significant figures: tolerances
    // are half a unit of the last printed digit.
    let p = internal(3e-3, 16, 24, 20.0, 0.0, -0.516);
    assert!((inv(p.working_pressure_angle) - 0.061857).abs() < 5e-7);
    assert!((p.working_pressure_angle.to_degrees() - 31.3209).abs() < 5e-5);
    assert!((p.working_centre_distance * 1e3 - 13.2000).abs() < 5e-5);
    assert!((p.pinion.reference * 1e3 - 48.0).abs() < 1e-9);
    assert!((p.gear.reference * 1e3 - 72.0).abs() < 1e-9);
    assert!((p.pinion.base * 1e3 - 45.1052).abs() < 5e-5);
    assert!((p.gear.base * 1e3 - 67.6579).abs() < 5e-5);
    assert!((p.pinion.working * 1e3 - 52.7998).abs() < 5e-5);
    assert!((p.gear.working * 1e3 - 79.1997).abs() < 5e-5);
    assert!((p.pinion.tip * 1e3 - 54.000).abs() < 5e-4);
    assert!((p.gear.tip * 1e3 - 69.096).abs() < 5e-4);
    assert!((p.contact_ratio - 1.6592).abs() < 5e-5);
    // Involute interference OK: z1/z2 = 0.6667 >= limit 0.6594.
    assert!((khk_limit(&p) - 0.6594).abs() < 5e-5);
    // Trochoid OK: 0.6667 >= θ2/θ1 = 0.6314.
    assert!((p.trochoid_ratio() - 0.6314).abs() < 5e-5);
    for kind in [
        CheckKind::InvoluteInterferencePinion,
        CheckKind::TrochoidInterference,
        CheckKind::RingTipInsideBaseCircle,
        CheckKind::ContactRatio,
        CheckKind::Backlash,
    ] {
        assert!(check(&p, kind).passed, "{kind:?}");
    }
    // KHK's example violates the conservative rules of thumb kept here: teeth difference
    // 8 < 10 (AGMA 917-B97 via Nunes) and a 16-tooth 20° pinion with x = 0 (x_min = 0.064).
    assert!(!check(&p, CheckKind::TeethDifference).passed);
    assert!(!check(&p, CheckKind::PinionUndercut).passed);

    // Same pair unshifted: ring tip 66 mm inside its base circle 67.658 mm.
    let q = internal(3e-3, 16, 24, 20.0, 0.0, 0.0);
    assert!((q.gear.tip * 1e3 - 66.0).abs() < 1e-9);
    let c = check(&q, CheckKind::RingTipInsideBaseCircle);
    assert!(!c.passed);
    assert!(c
        .remedies
        .iter()
        .any(|r| matches!(r, Remedy::ShortenRingAddendum { .. })));
    assert!(q.verify().is_err());
}

#[test]
fn standard_two_to_one_pairs_interfere_with_full_ring_addendum() {
    // docs/validation/gears.md §1.3/§1.4 (finding 1), α = 20°, x = 0, ha = 1 m; module-independent.
    // KHK limits printed to 3 decimals (±0.0005); max addenda to 4 decimals (±0.00005 m).
    for (z1, z2, limit, interferes, max_ha) in [
        (19, 38, 0.648, true, 0.8526),
        (20, 40, 0.592, true, 0.8975),
        (25, 50, 0.426, false, 1.1218),
    ] {
        for m in [2e-3, 3e-3, 4e-3] {
            let p = internal(m, z1, z2, 20.0, 0.0, 0.0);
            assert!(
                (khk_limit(&p) - limit).abs() < 5e-4,
                "{z1}/{z2}: {}",
                khk_limit(&p)
            );
            let c = check(&p, CheckKind::InvoluteInterferencePinion);
            assert_eq!(!c.passed, interferes, "{z1}/{z2}");
            let ha = p.max_gear_addendum_without_interference() / m;
            assert!((ha - max_ha).abs() < 5e-5, "{z1}/{z2}: {ha}");
            if interferes {
                // The failure names the shorter ring addendum with the limit just found, plus
                // profile shift and a larger pressure angle.
                assert!(c.remedies.contains(&Remedy::ShortenRingAddendum {
                    max_addendum: p.max_gear_addendum_without_interference()
                }));
                assert!(c.remedies.contains(&Remedy::ProfileShift));
                assert!(c.remedies.contains(&Remedy::LargerPressureAngle));
                assert!(p.verify().is_err());
            }
            // A ring addendum just below the limit removes the interference.
            let q = internal_ring_ha(m, z1, z2, 20.0, max_ha - 1e-3);
            assert!(check(&q, CheckKind::InvoluteInterferencePinion).passed);
        }
    }
}

#[test]
fn contact_ratios_of_karhula_pairs() {
    // docs/validation/gears.md §1.4: εα with ring ha = 1.0 m and 0.8 m, printed to 4 decimals
    // (±5e-5); trochoid OK for all.
    for (z1, z2, eps_full, eps_08) in [
        (19, 38, 2.1985, 1.7770),
        (20, 40, 2.1500, 1.7649),
        (25, 50, 2.0389, 1.7343),
    ] {
        let p = internal(3e-3, z1, z2, 20.0, 0.0, 0.0);
        assert!(
            (p.contact_ratio - eps_full).abs() < 5e-5,
            "{z1}: {}",
            p.contact_ratio
        );
        assert!(check(&p, CheckKind::TrochoidInterference).passed);
        let q = internal_ring_ha(3e-3, z1, z2, 20.0, 0.8);
        assert!(
            (q.contact_ratio - eps_08).abs() < 5e-5,
            "{z1}: {}",
            q.contact_ratio
        );
    }
    // 20/40 trochoid ratio 0.484 (3 decimals) against z1/z2 = 0.5.
    let p = internal(3e-3, 20, 40, 20.0, 0.0, 0.0);
    assert!((p.trochoid_ratio() - 0.484).abs() < 5e-4);
}

#[test]
fn karhula_path_of_contact_formula() {
    // Karhula A9.1.37: m = Z_AA0/z1 = 0.06/20 = 3 mm, i.e. 2 e / z1 with e = 0.03 m.
    let m = cardan_module(0.03, 20).unwrap();
    assert!((m - 3e-3).abs() < 1e-15);
    // A9.1.40 and A9.1.52 for 20/40: L = 19.0414 mm, CR = 2.1500 (gears.md §1.3, ±half unit),
    // although the thesis says εα ≈ 1.8 (finding 1).
    let l = karhula_path_of_contact(0.06, 0.12, m, deg(20.0));
    assert!((l * 1e3 - 19.0414).abs() < 5e-5);
    let cr = karhula_contact_ratio(l, m, deg(20.0));
    assert!((cr - 2.1500).abs() < 5e-5);
    // The printed formula is the ISO path of contact of the standard pair: equal to rounding.
    let p = internal(m, 20, 40, 20.0, 0.0, 0.0);
    assert!((p.path_of_contact - l).abs() < 1e-15);
    // CR uses 39.37 for 1/0.0254 (relative difference 2e-6).
    assert!((cr / p.contact_ratio - 1.0).abs() < 3e-6);
}

#[test]
fn nunes_pairs() {
    // docs/validation/gears.md §1.5: α = 25°, a = 13 mm; Nunes's "+0.5/−0.5" = ISO x1 = +0.5,
    // x2 = −0.5. Values printed to 4 decimals (εα) or 3 decimals (limits): half-unit tolerances.
    let p = internal(1e-3, 26, 52, 25.0, 0.0, 0.0);
    assert!((p.pinion.tip * 1e3 - 28.0).abs() < 1e-9 && (p.gear.tip * 1e3 - 50.0).abs() < 1e-9);
    assert!((p.contact_ratio - 1.6525).abs() < 5e-5);
    assert!(p.verify().is_ok(), "{:?}", p.verify());

    let f = internal(1e-3, 26, 52, 25.0, 0.5, -0.5);
    assert!((f.working_centre_distance * 1e3 - 13.0).abs() < 1e-12);
    assert!((f.pinion.tip * 1e3 - 29.0).abs() < 1e-9 && (f.gear.tip * 1e3 - 51.0).abs() < 1e-9);
    assert!((f.contact_ratio - 1.4750).abs() < 5e-5);
    assert!((khk_limit(&f) - 0.113).abs() < 5e-4);
    assert!((f.trochoid_ratio() - 0.477).abs() < 5e-4);
    assert!(f.verify().is_ok());

    let h = internal(0.5e-3, 52, 104, 25.0, 0.5, -0.5);
    assert!((h.pinion.tip * 1e3 - 27.5).abs() < 1e-9 && (h.gear.tip * 1e3 - 51.5).abs() < 1e-9);
    assert!((h.contact_ratio - 1.5452).abs() < 5e-5);
}

#[test]
fn contact_ratio_equals_direct_radius_formula() {
    // Paper-free: εα from gα/pb against the radius form of the same quantity
    // εα = [√(ra1²−rb1²) ∓ √(ra2²−rb2²) ± a sin αw] / (π m cos α), written out here
    // independently; 1e-12 relative is rounding.
    for (z1, z2, x1, x2) in [
        (17, 52, 0.3, -0.1),
        (20, -40, 0.2, -0.3),
        (26, -52, 0.5, -0.2),
    ] {
        let m = 2e-3;
        let a = deg(20.0);
        let p = GearPair::new(PairSpec::standard(m, z1, z2, a, x1, x2)).unwrap();
        let rb1 = m * z1 as f64 * a.cos() / 2.0;
        let rb2 = m * (z2 as f64).abs() * a.cos() / 2.0;
        let ra1 = m * z1 as f64 / 2.0 + m * (1.0 + x1);
        let (ra2, sign) = if z2 > 0 {
            (m * z2 as f64 / 2.0 + m * (1.0 + x2), 1.0)
        } else {
            (m * (-z2) as f64 / 2.0 - m * (1.0 + x2), -1.0)
        };
        let aw = p.working_centre_distance * p.working_pressure_angle.sin();
        let eps = ((ra1 * ra1 - rb1 * rb1).sqrt() + sign * (ra2 * ra2 - rb2 * rb2).sqrt()
            - sign * aw)
            / (std::f64::consts::PI * m * a.cos());
        assert!((p.contact_ratio / eps - 1.0).abs() < 1e-12, "{z1}/{z2}");
    }
}

#[test]
fn internal_and_external_pairs_meet_at_the_rack_limit() {
    // As |z2| → ∞ both pair types tend to the pinion-rack mesh; for |z2| = 1e5 the contact
    // ratios differ by O(z1/z2) ~ 1e-4.
    let a = deg(20.0);
    let e = GearPair::new(PairSpec::standard(1e-3, 20, 100_000, a, 0.0, 0.0)).unwrap();
    let i = GearPair::new(PairSpec::standard(1e-3, 20, -100_000, a, 0.0, 0.0)).unwrap();
    assert!((e.contact_ratio - i.contact_ratio).abs() < 1e-3);
    // Pinion-rack contact ratio (ISO 21771 rack form): [√(ra1²−rb1²) − r1 sin α + ha m / sin α]
    // / (π m cos α), written out independently.
    let (r1, rb1, ra1) = (0.01, 0.01 * a.cos(), 0.011);
    let eps_rack = ((ra1 * ra1 - rb1 * rb1).sqrt() - r1 * a.sin() + 1e-3 / a.sin())
        / (std::f64::consts::PI * 1e-3 * a.cos());
    assert!((e.contact_ratio - eps_rack).abs() < 1e-3);
    assert!((i.contact_ratio - eps_rack).abs() < 1e-3);
}

#[test]
fn backlash_follows_centre_distance_change() {
    // Paper-free: moving the centres apart by Δa changes the normal backlash by 2 Δa sin α to
    // first order — positive for an external pair, negative for an internal pair (the pinion
    // moves deeper into the ring). Δa = 1 µm: second-order error ~1e-4 relative.
    let a = deg(20.0);
    let da = 1e-6;
    for (z2, sign) in [(40, 1.0), (-40, -1.0)] {
        let base = GearPair::new(PairSpec::standard(3e-3, 20, z2, a, 0.0, 0.0)).unwrap();
        let mut s = base.spec;
        s.centre_distance = Some(base.working_centre_distance + da);
        let moved = GearPair::new(s).unwrap();
        let expected = sign * 2.0 * da * a.sin();
        assert!(
            (moved.backlash_normal / expected - 1.0).abs() < 1e-3,
            "{z2}: {} vs {expected}",
            moved.backlash_normal
        );
        let c = check(&moved, CheckKind::Backlash);
        assert_eq!(c.passed, sign > 0.0);
        if !c.passed {
            assert_eq!(c.remedies, vec![Remedy::IncreaseCentreDistanceOrThinTeeth]);
        }
    }
}

#[test]
fn thinning_creates_backlash() {
    // Paper-free: thinning each tooth by t at the reference circle gives jt = (t1 + t2)·cos α/cos αw
    // on the working circle (thickness scales with dw/d); here x = 0 so αw = α and jt = t1 + t2.
    let mut s = PairSpec::standard(3e-3, 20, -40, deg(20.0), 0.0, 0.0);
    s.pinion.thickness_allowance = 40e-6;
    s.gear.thickness_allowance = 60e-6;
    let p = GearPair::new(s).unwrap();
    assert!((p.backlash_circumferential - 100e-6).abs() < 1e-15);
}

#[test]
fn teeth_difference_and_undercut_checks() {
    // 30/38: difference 8 < 10 (AGMA 917-B97 via Nunes) -> failure naming the minimum.
    let p = internal(1e-3, 30, 38, 20.0, 0.0, 0.0);
    let c = check(&p, CheckKind::TeethDifference);
    assert!(!c.passed && c.remedies == vec![Remedy::MoreTeethDifference { minimum: 10 }]);
    // Rack-generated 14-tooth 20° pinion: x_min = 1 − 14 sin²20°/2 = 0.18117 (closed form).
    let e = GearPair::new(PairSpec::standard(1e-3, 14, 40, deg(20.0), 0.0, 0.0)).unwrap();
    let u = check(&e, CheckKind::PinionUndercut);
    assert!(!u.passed);
    let x_min = 1.0 - 14.0 * deg(20.0).sin().powi(2) / 2.0;
    assert!(u
        .remedies
        .contains(&Remedy::PinionShiftAtLeast { min_shift: x_min }));
}

#[test]
fn unshifted_pair_has_reference_values() {
    // Limits: with x1 + x2 = 0 the working pressure angle is α and a = m (z2 − z1)/2 exactly.
    let p = internal(3e-3, 20, 40, 20.0, 0.3, -0.3);
    assert!((p.working_pressure_angle - deg(20.0)).abs() < 1e-15);
    assert!((p.working_centre_distance - 0.03).abs() < 1e-15);
}
