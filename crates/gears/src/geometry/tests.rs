use super::checks::*;
use super::*;

fn pair(z1: i32, z2: i32) -> GearPair {
    GearPair::new(PairSpec::standard(
        1e-3,
        z1,
        z2,
        20f64.to_radians(),
        0.0,
        0.0,
    ))
    .unwrap()
}

#[test]
fn invalid_inputs_are_errors_not_panics() {
    let base = PairSpec::standard(3e-3, 20, -40, 20f64.to_radians(), 0.0, 0.0);
    let mut s = base;
    s.module = -1.0;
    assert!(matches!(
        GearPair::new(s),
        Err(GearError::InvalidInput {
            field: "module",
            ..
        })
    ));
    let mut s = base;
    s.gear.teeth = -15;
    assert!(matches!(
        GearPair::new(s),
        Err(GearError::InvalidInput {
            field: "gear.teeth",
            ..
        })
    ));
    let mut s = base;
    s.pressure_angle = f64::NAN;
    assert!(GearPair::new(s).is_err());
    let mut s = base;
    s.centre_distance = Some(1e-3);
    assert!(GearPair::new(s).is_err());
    let mut s = base;
    s.gear.tip = Tip::Diameter(1.0);
    assert!(GearPair::new(s).is_err());
}

#[test]
fn zero_backlash_at_working_centre_distance() {
    // By construction of the involute inversion; 1e-15 m is rounding.
    for (z2, x2) in [(40, 0.3), (-40, -0.4), (-24, -0.516)] {
        let p = GearPair::new(PairSpec::standard(
            3e-3,
            16,
            z2,
            20f64.to_radians(),
            0.2,
            x2,
        ))
        .unwrap();
        assert!(p.backlash_circumferential.abs() < 1e-15, "{z2}");
    }
}

#[test]
fn checks_list_matches_pair_type() {
    assert_eq!(pair(20, 40).checks().len(), 5);
    assert_eq!(pair(25, -50).checks().len(), 7);
}

/// Issue 39.5: a margin that rounds to zero prints as `0.00000`, never `-0.00000` (a
/// zero-backlash pair computes jt ≈ −1e-17 m), in the one text both the case files and the
/// gear file use.
#[test]
fn a_margin_rounding_to_zero_has_no_sign() {
    assert_eq!(fixed(-1e-17, 5), "0.00000");
    assert_eq!(fixed(-0.000004, 5), "0.00000");
    assert_eq!(fixed(-0.00001, 5), "-0.00001");
    assert_eq!(fixed(0.0, 5), "0.00000");
    let pair = GearPair::new(PairSpec::standard(
        1e-3,
        20,
        50,
        20f64.to_radians(),
        0.0,
        0.0,
    ))
    .unwrap();
    let backlash = pair
        .checks()
        .into_iter()
        .find(|c| c.kind == CheckKind::Backlash)
        .unwrap();
    let text = backlash.to_string();
    assert!(!text.contains("-0.0000"), "{text}");
    assert!(text.ends_with("margin 0.00000, ok"), "{text}");
}
