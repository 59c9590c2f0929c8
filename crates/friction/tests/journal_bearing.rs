//! Journal-bearing models against the published and derived cases of
//! `docs/validation/journal-bearings.md`. The Raimondi–Boyd table rows once quoted here from
//! memory (unverified against the book) are gone, and the tests that read them with them.

use cardan_friction::{
    ocvirk_attitude_angle, ocvirk_eccentricity, ocvirk_sommerfeld, petroff, short_bearing,
    sommerfeld_number, thai_eccentric_loss, JournalBearing,
};
use std::f64::consts::PI;

const INCH: f64 = 0.0254;
const LBF: f64 = 4.448_221_615_260_5;
const REYN: f64 = LBF / (INCH * INCH); // lbf·s/in² in Pa·s
const LBF_IN: f64 = LBF * INCH;

/// `|got − want| ≤ half a unit of the last printed decimal` (+ 1e-12 for representation).
fn printed(got: f64, want: f64, decimals: i32) {
    let tol = 0.5 * 10f64.powi(-decimals) + 1e-12;
    assert!(
        (got - want).abs() <= tol,
        "got {got}, published {want} (±{tol})"
    );
}

#[test]
fn sommerfeld_number_worked_by_hand_in_us_units() {
    // docs/validation/journal-bearings.md, the hand-worked US bearing (derived; no published
    // value): μ = 4 µreyn, N = 30 rev/s, W = 500 lbf, r = 0.75 in, c = 0.0015 in, l = 1.5 in;
    // S = (r/c)² μN/P = 500²·1.2e-4/222.2 = 0.1350 by hand in US units. Inputs converted to SI;
    // S is dimensionless. Tolerance: half a unit of the 4th decimal of the hand result.
    let b = JournalBearing::new(0.75 * INCH, 1.5 * INCH, 0.0015 * INCH).unwrap();
    let s = sommerfeld_number(&b, 4e-6 * REYN, 30.0 * 2.0 * PI, 500.0 * LBF);
    printed(s, 0.1350, 4);
    // P = W/(2rl) = 222.2 psi by hand, checked to the unit.
    printed(b.unit_load(500.0 * LBF) / (LBF / (INCH * INCH)), 222.0, 0);
}

#[test]
fn short_bearing_lies_on_or_above_petroffs_line() {
    // Shigley ch. 12: Petroff's concentric journal gives the friction variable (r/c) f = 2π² S;
    // an eccentric film carries more shear (1/√(1 − ε²)) and the load term, so the short
    // bearing's (r/c) f is above that line, and meets it as S → ∞ (ε → 0). On the hand-worked
    // US bearing (SI) over three decades of load: above, and within 1e-3 at S > 100.
    let b = JournalBearing::new(0.75 * INCH, 1.5 * INCH, 0.0015 * INCH).unwrap();
    let (mu, w) = (4e-6 * REYN, 30.0 * 2.0 * PI);
    for load in [0.5, 5.0, 50.0, 500.0 * LBF, 5000.0 * LBF] {
        let st = short_bearing(&b, mu, load, w, w);
        assert_eq!(st.sommerfeld, sommerfeld_number(&b, mu, w, load));
        let petroff_line = 2.0 * PI * PI * st.sommerfeld;
        let rfc = b.radius / b.radial_clearance * st.friction_coefficient;
        assert!(rfc >= petroff_line, "W {load}: {rfc} < {petroff_line}");
        if st.sommerfeld > 100.0 {
            assert!(
                rfc / petroff_line - 1.0 < 1e-3,
                "W {load}: {rfc} {petroff_line}"
            );
        }
    }
}

#[test]
fn faires_petroff_problem() {
    // Faires problem 551 (docs/validation/journal-bearings.md): 3 × 3 in, W = 900 lb, 400 rpm, c_r = 0.00075 in;
    // (a) μ = 7.25 µreyn: F = 17.173 lb, T = 25.76 lb·in, fhp = 0.1635 hp, f = 0.0191;
    // (b) μ = 2.2 µreyn: T = 7.817 lb·in, fhp = 0.0496 hp, f = 0.00579.
    // Tolerances: half a unit of the last printed digit.
    let b = JournalBearing::new(1.5 * INCH, 3.0 * INCH, 0.00075 * INCH).unwrap();
    let w = 400.0 * 2.0 * PI / 60.0;
    let hp = 745.699_871_582_270_1;
    let (la, fa) = petroff(&b, 7.25e-6 * REYN, w, 900.0 * LBF);
    printed(la.friction_torque / LBF_IN, 25.76, 2);
    printed(la.friction_torque / (1.5 * INCH) / LBF, 17.173, 3);
    printed(la.power / hp, 0.1635, 4);
    printed(fa, 0.0191, 4);
    let (lb, fb) = petroff(&b, 2.2e-6 * REYN, w, 900.0 * LBF);
    printed(lb.friction_torque / LBF_IN, 7.817, 3);
    printed(lb.power / hp, 0.0496, 4);
    printed(fb, 0.00579, 5);
}

/// (ε, S L/D=¼, its decimals, φ°, S L/D=½, its decimals, S L/D=1, its decimals)
type Row = (f64, f64, i32, f64, f64, i32, f64, i32);

#[test]
fn ocvirk_table() {
    // docs/validation/journal-bearings.md: closed-form values computed independently (a python
    // script, not this code), printed to 3–4 significant digits: tolerance half a unit of the
    // last printed decimal.
    // (ε, S L/D=¼, φ°, S L/D=½, S L/D=1)
    let rows: [Row; 6] = [
        (0.1, 15.840, 3, 82.71, 3.960, 3, 0.990, 3),
        (0.2, 7.379, 3, 75.43, 1.845, 3, 0.461, 3),
        (0.4, 2.727, 3, 60.94, 0.682, 3, 0.170, 3),
        (0.6, 1.000, 3, 46.32, 0.250, 3, 0.0625, 4),
        (0.8, 0.2222, 4, 30.50, 0.0555, 4, 0.0139, 4),
        (0.9, 0.0530, 4, 20.83, 0.0133, 4, 0.0033, 4),
    ];
    for (e, s4, d4, phi, s2, d2, s1, d1) in rows {
        printed(ocvirk_sommerfeld(e, 0.25), s4, d4);
        printed(ocvirk_attitude_angle(e).to_degrees(), phi, 2);
        printed(ocvirk_sommerfeld(e, 0.5), s2, d2);
        printed(ocvirk_sommerfeld(e, 1.0), s1, d1);
        // Inverse problem (given S and L/D → ε within 1e-9 of the table row), using
        // the exact S of the row's ε.
        let s_exact = ocvirk_sommerfeld(e, 0.25);
        assert!((ocvirk_eccentricity(s_exact, 0.25) - e).abs() < 1e-9);
    }
}

#[test]
fn short_bearing_tends_to_petroff_at_light_load() {
    // No paper: as W → 0, ε → 0 and the torque → Petroff. At W = 0.01 N (S ≈ 3e4, ε ≈ 5e-5) the
    // relative difference is O(ε) (load term) + O(ε²) (Couette); bound 1e-3.
    let b = JournalBearing::new(0.025, 0.0125, 25e-6).unwrap();
    let (mu, w) = (0.01, 300.0);
    let (pet, _) = petroff(&b, mu, w, 0.01);
    let st = short_bearing(&b, mu, 0.01, w, w);
    assert!(st.eccentricity_ratio < 1e-3, "{}", st.eccentricity_ratio);
    assert!((st.loss.friction_torque / pet.friction_torque - 1.0).abs() < 1e-3);
    // Thai eq. 2.5.a.13 at ε = 0 is Petroff exactly (same expression up to rounding).
    let thai = thai_eccentric_loss(&b, mu, w, 0.0);
    assert!((thai.power / pet.power - 1.0).abs() < 1e-14);
}

#[test]
fn short_bearing_loss_follows_load_and_is_consistent() {
    // No paper: loss ≥ 0, grows with load at fixed speed (ε grows), P = T ω exactly
    // (same floating product), zero speed gives zero loss.
    let b = JournalBearing::new(0.025, 0.02, 25e-6).unwrap();
    let mut last = 0.0;
    for k in 1..40 {
        let load = 500.0 * k as f64;
        let st = short_bearing(&b, 0.008, load, 400.0, 400.0);
        assert!(st.loss.power >= last);
        assert!(st.loss.power > 0.0);
        assert!((st.loss.power - st.loss.friction_torque * 400.0).abs() <= 1e-12 * st.loss.power);
        last = st.loss.power;
    }
    let st0 = short_bearing(&b, 0.008, 5000.0, 0.0, 0.0);
    assert_eq!(st0.loss.power, 0.0);
    assert_eq!(st0.loss.friction_torque, 0.0);
}
