//! Anderson & Loewenthal mesh loss: Karhula's printed reading against the derived sample of
//! `docs/validation/gears.md` §4.2, the viscosity-unit and kinematics corrections (§4.3, §4.4).

use cardan_gears::*;

fn setup() -> (MeshGeometry, Lubricant) {
    // docs/validation/gears.md §4.2: m = 3 mm, 20/40 internal, α = 20°, b = 20 mm, ν = 5 mm²/s,
    // ρ = 900 kg/m³.
    let pair = GearPair::new(PairSpec::standard(
        3e-3,
        20,
        -40,
        20f64.to_radians(),
        0.0,
        0.0,
    ))
    .unwrap();
    (
        MeshGeometry::from_pair(&pair, 0.020).unwrap(),
        Lubricant {
            kinematic_viscosity: 5e-6,
            density: 900.0,
        },
    )
}

/// Cardan gear: crank (carrier) at ω, wheel absolute −ω (i = 2); Karhula's n = |ω|.
fn cardan_speeds(rpm: f64) -> MeshSpeeds {
    let w = rpm * std::f64::consts::PI / 30.0;
    MeshSpeeds {
        pinion_absolute: -w,
        carrier: w,
    }
}

/// Relative closeness to a value printed with `digits` significant figures: half a unit of
/// the last digit, relative.
fn sig(value: f64, printed: f64, digits: i32) -> bool {
    let unit = 10f64.powi(printed.abs().log10().floor() as i32 - digits + 1);
    (value - printed).abs() <= 0.5 * unit + 1e-12
}

#[test]
fn karhula_reading_reproduces_derived_sample() {
    // docs/validation/gears.md §4.2 (derived), Ft = 2000 N, viscosity in Pa·s as Karhula's A9.1.47.
    // Printed with 2–4 significant figures; tolerance half a unit of the last printed digit.
    let (g, lub) = setup();
    for (rpm, vs, vr, mu, ps, h_um, pr, pw) in [
        (3000.0, 2.245, 5.698, 0.0849, 405.5, 0.0013, 0.028, 0.12),
        (6000.0, 4.490, 11.396, 0.0734, 701.4, 0.0020, 0.089, 0.85),
    ] {
        let r = mesh_loss(&g, &lub, &cardan_speeds(rpm), 2000.0, Reading::Karhula).unwrap();
        assert!(
            sig(r.sliding_velocity, vs, 4),
            "{rpm}: vs {}",
            r.sliding_velocity
        );
        let vr_digits = if vr > 10.0 { 5 } else { 4 };
        assert!(
            sig(r.rolling_velocity, vr, vr_digits),
            "{rpm}: vr {}",
            r.rolling_velocity
        );
        assert!(
            sig(r.friction_coefficient, mu, 3),
            "{rpm}: mu {}",
            r.friction_coefficient
        );
        assert!(sig(r.sliding_power, ps, 4), "{rpm}: Ps {}", r.sliding_power);
        assert!(
            sig(r.film_thickness * 1e6, h_um, 2),
            "{rpm}: h {}",
            r.film_thickness
        );
        assert!(sig(r.rolling_power, pr, 2), "{rpm}: Pr {}", r.rolling_power);
        assert!(sig(r.windage_power, pw, 2), "{rpm}: Pw {}", r.windage_power);
        assert!((r.contact_ratio - 2.15).abs() < 5e-4);
        assert!(
            (r.total_power - (r.sliding_power + r.rolling_power + r.windage_power)).abs() < 1e-9
        );
    }
}

#[test]
fn centipoise_rows_of_the_derived_sample() {
    // gears.md §4.2 cP rows (Karhula kinematics, viscosity in cP, §4.3): μ 0.0468 / 0.0353,
    // Ps 223.4 / 337.3 W, h 0.129 / 0.206 µm (≈ 0.13 µm Hamrock–Dowson check), Pr 2.85 / 9.08 W,
    // Pw 0.18 / 1.27 W. Half a unit of the last printed digit, except Ps: the page's Ps uses
    // its rounded μ (0.0468 vs 0.04677, 0.07 %), so Ps gets 0.1 %.
    let (g, lub) = setup();
    let opt = LossOptions {
        viscosity_in_centipoise: true,
        mesh_kinematics: false,
        actual_geometry: false,
        clamp_friction: false,
    };
    for (rpm, mu, ps, h_um, pr, pw) in [
        (3000.0, 0.0468, 223.4, 0.129, 2.85, 0.18),
        (6000.0, 0.0353, 337.3, 0.206, 9.08, 1.27),
    ] {
        let r = mesh_loss_with(&g, &lub, &cardan_speeds(rpm), 2000.0, opt).unwrap();
        assert!(
            sig(r.friction_coefficient, mu, 3),
            "{rpm}: mu {}",
            r.friction_coefficient
        );
        assert!(
            (r.sliding_power / ps - 1.0).abs() < 1e-3,
            "{rpm}: Ps {}",
            r.sliding_power
        );
        assert!(
            sig(r.film_thickness * 1e6, h_um, 3),
            "{rpm}: h {}",
            r.film_thickness
        );
        assert!(sig(r.rolling_power, pr, 3), "{rpm}: Pr {}", r.rolling_power);
        assert!(sig(r.windage_power, pw, 2), "{rpm}: Pw {}", r.windage_power);
    }
}

#[test]
fn corrected_kinematics_ratios() {
    // gears.md §4.4 (finding 5), paper-free: for the 2:1 cardan mesh the carrier-relative speed is
    // 2ω and the internal sliding factor (i−1)/i = 1/2, against Karhula's ω and (i+1)/i = 3/2: the
    // corrected sliding velocity is exactly 2/3 of Karhula's for the same path of contact
    // (full-addendum 20/40, where the actual path equals A9.1.40).
    let (g, lub) = setup();
    let only_kin = LossOptions {
        viscosity_in_centipoise: false,
        mesh_kinematics: true,
        actual_geometry: false,
        clamp_friction: false,
    };
    let s = cardan_speeds(3000.0);
    let k = mesh_loss(&g, &lub, &s, 2000.0, Reading::Karhula).unwrap();
    let c = mesh_loss_with(&g, &lub, &s, 2000.0, only_kin).unwrap();
    assert!((c.sliding_velocity / k.sliding_velocity - 2.0 / 3.0).abs() < 1e-12);
    // Pitch-point rolling-speed sum 12.89 m/s (kinematic) vs 6.45 m/s (A9.1.43 at the pitch
    // point), gears.md §4.4: ω_rel d1 sin α with ω_rel = 2ω.
    let w = 3000.0 * std::f64::consts::PI / 30.0;
    let pitch_sum = 2.0 * w * 0.06 * 20f64.to_radians().sin();
    assert!((pitch_sum - 12.89).abs() < 5e-3);
    // For a fixed-axis external pair both readings see the same speeds.
    let e = GearPair::new(PairSpec::standard(
        3e-3,
        20,
        40,
        20f64.to_radians(),
        0.0,
        0.0,
    ))
    .unwrap();
    let ge = MeshGeometry::from_pair(&e, 0.02).unwrap();
    let fixed = MeshSpeeds {
        pinion_absolute: w,
        carrier: 0.0,
    };
    let a = mesh_loss_with(&ge, &lub, &fixed, 2000.0, only_kin).unwrap();
    let b = mesh_loss(&ge, &lub, &fixed, 2000.0, Reading::Karhula).unwrap();
    assert!((a.sliding_velocity - b.sliding_velocity).abs() < 1e-12);
    assert!((a.rolling_velocity - b.rolling_velocity).abs() < 1e-12);
}

#[test]
fn corrected_reading_is_finite_and_limits_hold() {
    let (g, lub) = setup();
    let c = mesh_loss(&g, &lub, &cardan_speeds(6000.0), 2000.0, Reading::Corrected).unwrap();
    assert!(c.total_power.is_finite() && c.total_power > 0.0);
    assert!(c.friction_coefficient >= 0.0);
    // At standstill every loss vanishes (v log v -> 0, h·v -> 0, n^2.8 -> 0).
    for reading in [Reading::Karhula, Reading::Corrected] {
        let r = mesh_loss(&g, &lub, &cardan_speeds(0.0), 2000.0, reading).unwrap();
        assert_eq!(r.total_power, 0.0);
        // Zero load: no sliding or rolling loss, only windage.
        let r = mesh_loss(&g, &lub, &cardan_speeds(3000.0), 0.0, reading).unwrap();
        assert_eq!(r.sliding_power + r.rolling_power, 0.0);
        assert!(r.windage_power > 0.0);
        // The sign of Ft does not matter.
        let p = mesh_loss(&g, &lub, &cardan_speeds(3000.0), 1500.0, reading).unwrap();
        let n = mesh_loss(&g, &lub, &cardan_speeds(3000.0), -1500.0, reading).unwrap();
        assert_eq!(p, n);
    }
    let mut bad = lub;
    bad.density = 0.0;
    assert!(mesh_loss(&g, &bad, &cardan_speeds(1.0), 1.0, Reading::Karhula).is_err());
}

/// The mesh loss prepared once per mesh, its speed's powers kept while the speed's bits do not
/// change, gives `mesh_loss_with`'s bits at every step of a sequence whose speed stays, changes
/// and comes back, in both readings; and its errors.
#[test]
fn a_prepared_mesh_loss_is_the_mesh_loss_bit_for_bit() {
    let (g, lub) = setup();
    for reading in [Reading::Karhula, Reading::Corrected] {
        let mut prepared = PreparedMeshLoss::new(&g, &lub, reading.options());
        for (rpm, ft) in [
            (3000.0, 2000.0),
            (3000.0, 1500.0),
            (3000.0, 0.0),
            (6000.0, -800.0),
            (0.0, 800.0),
            (3000.0, 2000.0),
            (3000.0, 2000.0),
        ] {
            let s = cardan_speeds(rpm);
            assert_eq!(
                prepared.loss(&s, ft).unwrap(),
                mesh_loss(&g, &lub, &s, ft, reading).unwrap(),
                "{reading:?} at {rpm} rpm, {ft} N"
            );
        }
        let s = cardan_speeds(3000.0);
        assert_eq!(
            prepared.loss(&s, f64::NAN).unwrap_err().to_string(),
            mesh_loss(&g, &lub, &s, f64::NAN, reading)
                .unwrap_err()
                .to_string()
        );
        let bad = Lubricant {
            density: -1.0,
            ..lub
        };
        assert_eq!(
            PreparedMeshLoss::new(&g, &bad, reading.options())
                .loss(&s, 100.0)
                .unwrap_err()
                .to_string(),
            mesh_loss(&g, &bad, &s, 100.0, reading)
                .unwrap_err()
                .to_string()
        );
    }
}

/// A block's lanes (`PreparedMeshLoss::total_power_lanes`: the logarithms and powers of every
/// lane at once) have the single step's bits (`PreparedMeshLoss::loss`), in both readings,
/// over 2 000 blocks of 64 lanes and a short one: loads log-uniform over [10⁻², 10⁵] N of
/// either sign with some zero, at a speed per block (kept powers) or per lane, up to
/// 10 000 rpm with some at rest. A lane that fails a check (a load not finite) fails the
/// block.
#[test]
fn a_block_of_lanes_has_the_bits_of_its_steps() {
    let (g, lub) = setup();
    let mut state = 0x6EA2_u64;
    let mut unit = move || {
        // SplitMix64 (Steele, Lea & Flood 2014).
        state = state.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = state;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        ((z ^ (z >> 31)) >> 11) as f64 / (1u64 << 53) as f64
    };
    let mut compared = 0;
    for reading in [Reading::Karhula, Reading::Corrected] {
        let mut lanes = PreparedMeshLoss::new(&g, &lub, reading.options());
        let mut steps = PreparedMeshLoss::new(&g, &lub, reading.options());
        for block in 0..1_001 {
            let n = if block == 1_000 { 37 } else { 64 };
            let block_rpm = 10_000.0 * unit();
            let (mut pinion, mut carrier, mut ft) = (vec![0.0; n], vec![0.0; n], vec![0.0; n]);
            for i in 0..n {
                let rpm = match block % 3 {
                    0 => block_rpm,
                    1 => 10_000.0 * unit(),
                    _ => 0.0,
                };
                let s = cardan_speeds(rpm);
                (pinion[i], carrier[i]) = (s.pinion_absolute, s.carrier);
                let sign = if unit() < 0.5 { -1.0 } else { 1.0 };
                ft[i] = match unit() < 0.02 {
                    true => 0.0,
                    false => sign * (1e-2f64.ln() + (1e5f64.ln() - 1e-2f64.ln()) * unit()).exp(),
                };
            }
            let mut out = vec![0.0; n];
            assert!(lanes.total_power_lanes(&pinion, &carrier, &ft, &mut out));
            for i in 0..n {
                let speeds = MeshSpeeds {
                    pinion_absolute: pinion[i],
                    carrier: carrier[i],
                };
                let one = steps.loss(&speeds, ft[i]).unwrap().total_power;
                assert_eq!(
                    out[i].to_bits(),
                    one.to_bits(),
                    "{reading:?} block {block} lane {i}: {} against {one}",
                    out[i]
                );
                compared += 1;
            }
            if block == 7 {
                ft[3] = f64::INFINITY;
                assert!(!lanes.total_power_lanes(&pinion, &carrier, &ft, &mut out));
            }
        }
    }
    assert_eq!(compared, 2 * (1_000 * 64 + 37));
}
