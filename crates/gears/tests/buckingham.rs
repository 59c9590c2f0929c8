//! Buckingham's dynamic tooth load: SI chain against the same chain in US units, and the
//! formula-level values of `docs/validation/gears.md` §3.

use cardan_gears::buckingham::{
    cardan_pitch_line_velocity, deformation_factor, dynamic_load_simplified, k3_exact,
};
use cardan_gears::units::{FT_PER_MIN, INCH, LBF, PSI};
use cardan_gears::{BuckinghamPair, FULL_DEPTH_20};

/// Karhula A8.1.1–A8.1.14 written out in US units exactly as printed (in, lb, ft/min, psi),
/// independently of the crate: returns (f1, f2, fa, Fdyn) in lb.
#[allow(clippy::too_many_arguments)]
fn karhula_us(r1: f64, r2: f64, b: f64, e: f64, e1: f64, e2: f64, ft: f64, v: f64) -> [f64; 4] {
    let h = 0.00120 * (1.0 / r1 - 1.0 / r2);
    let d1 = 2.0 * r1;
    let ip = std::f64::consts::PI * d1.powi(4) / 32.0;
    let m1 = ip / (r1 * r1);
    let f1 = h * m1 * v * v;
    let def = 9.00 * ft / b * (1.0 / e1 + 1.0 / e2);
    let f2 = ft * (e / def + 1.0);
    let fa = f1 * f2 / (f1 + f2);
    [f1, f2, fa, ft + (fa * (2.0 * f2 - fa)).sqrt()]
}

fn karhula_pair() -> BuckinghamPair {
    // m = 3 mm, 20/40: r1 = 30 mm, r2 = 60 mm, b = d1/3 = 20 mm, e = 0.005 in, E = 30 Mpsi.
    BuckinghamPair {
        pinion_radius: 0.030,
        gear_radius: 0.060,
        internal: true,
        face_width: 0.020,
        error: 0.005 * INCH,
        e1: 30e6 * PSI,
        e2: 30e6 * PSI,
        form: FULL_DEPTH_20,
    }
}

#[test]
fn si_chain_equals_us_chain() {
    // The only dimensional constant is converted exactly, so SI and US agree to rounding
    // (1e-12 relative) over loads and speeds.
    let p = karhula_pair();
    for ft_lb in [1.0, 500.0, 5000.0, 20000.0] {
        for rpm in [10.0, 3000.0, 6000.0, 20000.0] {
            let v = cardan_pitch_line_velocity(rpm * std::f64::consts::PI / 30.0, 0.030);
            let si = p.dynamic_load(ft_lb * LBF, v).unwrap();
            let us = karhula_us(
                0.030 / INCH,
                0.060 / INCH,
                0.020 / INCH,
                0.005,
                30e6,
                30e6,
                ft_lb,
                v / FT_PER_MIN,
            );
            let got = [si.f1, si.f2, si.fa, si.dynamic_load].map(|x| x / LBF);
            for k in 0..4 {
                assert!(
                    (got[k] / us[k] - 1.0).abs() < 1e-12,
                    "{ft_lb} lb {rpm} rpm #{k}"
                );
            }
        }
    }
}

#[test]
fn karhula_method_derived_sample() {
    // docs/validation/gears.md §3.3 (derived): Ft = 500 lb, crank 3000 rpm (v = 3710.5 ft/min):
    // def = 3.810e-4 in, f2 = 7061.7 lb, f1 = 15 326 lb, fa = 4834 lb, Fdyn = 7201 lb;
    // 6000 rpm: Fdyn = 7524 lb. Half-unit tolerances of the printed digits.
    let p = karhula_pair();
    let v = cardan_pitch_line_velocity(3000.0 * std::f64::consts::PI / 30.0, 0.030);
    assert!((v / FT_PER_MIN - 3710.5).abs() < 0.05);
    let r = p.dynamic_load(500.0 * LBF, v).unwrap();
    assert!((r.deformation / INCH - 3.810e-4).abs() < 5e-8);
    assert!((r.f2 / LBF - 7061.7).abs() < 0.05);
    assert!((r.f1 / LBF - 15326.0).abs() < 0.5);
    assert!((r.fa / LBF - 4834.0).abs() < 0.5);
    assert!((r.dynamic_load / LBF - 7201.0).abs() < 0.5);
    let v6 = cardan_pitch_line_velocity(6000.0 * std::f64::consts::PI / 30.0, 0.030);
    let r6 = p.dynamic_load(500.0 * LBF, v6).unwrap();
    assert!((r6.dynamic_load / LBF - 7524.0).abs() < 0.5);
}

#[test]
fn deformation_factor_values() {
    // docs/validation/gears.md §3.1: steel/steel E = 30 Mpsi, e = 0.001 in, k = 0.111
    // -> C = 1665 lb/in (exact arithmetic, printed to 4 figures); SI: E = 207 000 N/mm²,
    // Σe = 0.032 mm -> 367.6 N/mm.
    let c = deformation_factor(0.111, 0.001 * INCH, 30e6 * PSI, 30e6 * PSI).unwrap();
    assert!((c / (LBF / INCH) - 1665.0).abs() < 0.5);
    let c = deformation_factor(0.111, 0.032e-3, 207e9, 207e9).unwrap();
    assert!((c / 1e3 - 367.6).abs() < 0.05);
}

#[test]
fn simplified_form() {
    // docs/validation/gears.md §3.3: US simplified form Ft = 1000 lb, V = 2000 ft/min, b = 1 in,
    // C = 1665 lb/in -> Fd = 2757.6 lb; exact K3 makes the SI evaluation identical (±0.05 lb print).
    let fd = dynamic_load_simplified(1000.0 * LBF, 2000.0 * FT_PER_MIN, 1665.0 * LBF, k3_exact())
        .unwrap();
    assert!((fd / LBF - 2757.6).abs() < 0.05);
    // The exact constant sits between the textbook roundings 20.67 (PSG) and 21 (Bhandari).
    assert!((k3_exact() - 20.759).abs() < 5e-4);
    // docs/validation/gears.md §3.2, calculators with K3 = 21 (increments): v = 3.7,
    // C = 1100 N/mm², e = 0.05 mm, b = 34 mm, Pt = 952 N -> 1676.0832 N; v = 2.5, C = 10,
    // e = 0.05, b = 40, Pt = 2000 -> 1088.3128 N (printed to 1e-4 N).
    let inc = |v: f64, c: f64, e: f64, b: f64, pt: f64| {
        dynamic_load_simplified(pt, v, c * e * b, 21.0).unwrap() - pt
    };
    assert!((inc(3.7, 1100.0, 0.05, 34.0, 952.0) - 1676.0832).abs() < 5e-4);
    assert!((inc(2.5, 10.0, 0.05, 40.0, 2000.0) - 1088.3128).abs() < 5e-4);
}

#[test]
fn limits() {
    let p = karhula_pair();
    // No speed: f1 = 0, so fa = 0 and Fdyn = Ft exactly.
    let r = p.dynamic_load(1000.0, 0.0).unwrap();
    assert_eq!(r.dynamic_load, 1000.0);
    // No load: zero dynamic load, no NaN.
    assert_eq!(p.dynamic_load(0.0, 20.0).unwrap().dynamic_load, 0.0);
    // Very high speed: fa -> f2 and Fdyn -> Ft + f2 (the error-closing load).
    let r = p.dynamic_load(1000.0, 1e5).unwrap();
    assert!((r.dynamic_load - (1000.0 + r.f2)).abs() / r.f2 < 1e-6);
    // Bad input is an error.
    let mut q = p;
    q.face_width = -1.0;
    assert!(q.dynamic_load(1.0, 1.0).is_err());
}

#[test]
fn saturated_load_is_the_chain_without_bound_on_f1() {
    // Paper-free: the chain's f1 grows as H (A8.1.3); with H a million times Buckingham's the
    // chain must sit on the saturated limit Ft + f2 (fa → f2), and the limit must exceed the
    // chain at the real H (fa < f2 there).
    let p = karhula_pair();
    let mut huge = p;
    huge.form.h_us *= 1e12;
    for (ft, v) in [(1000.0, 1.0), (12_000.0, 5.0), (40_000.0, 37.7)] {
        let s = p.saturated_dynamic_load(ft).unwrap();
        let limit = huge.dynamic_load(ft, v).unwrap();
        assert!(
            (s.dynamic_load / limit.dynamic_load - 1.0).abs() < 1e-9,
            "{ft} N, {v} m/s: {} vs {}",
            s.dynamic_load,
            limit.dynamic_load
        );
        assert!(s.dynamic_load > p.dynamic_load(ft, v).unwrap().dynamic_load);
        // 2·Ft + b·e/(k·(1/E1+1/E2)), written out.
        let c = p.face_width * p.error / (p.form.deformation * (1.0 / p.e1 + 1.0 / p.e2));
        assert!((s.dynamic_load - (2.0 * ft + c)).abs() < 1e-9 * s.dynamic_load);
    }
    assert_eq!(p.saturated_dynamic_load(0.0).unwrap().dynamic_load, 0.0);
}
