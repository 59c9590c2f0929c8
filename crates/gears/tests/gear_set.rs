//! Per-step evaluation of a cardan gear set (the API the mechanism/dynamics code will call).

use cardan_gears::agma::factors::{
    bending_allowable_through_hardened, contact_allowable_through_hardened, Grade,
};
use cardan_gears::units::INCH;
use cardan_gears::*;

fn cardan_set() -> GearSet {
    // Karhula's pair: e = 0.03 m, z1 = 20 -> m = 3 mm, 20/40 internal, 20°, ring addendum
    // shortened to 0.85 m (below the 0.8975 m interference limit), b = d1/3.
    let m = cardan_module(0.03, 20).unwrap();
    let mut spec = PairSpec::standard(m, 20, -40, 20f64.to_radians(), 0.0, 0.0);
    spec.gear = spec.gear.with_addendum(0.85);
    let pair = GearPair::new(spec).unwrap();
    assert!(pair.verify().is_ok(), "{:?}", pair.verify());
    let b = pair.pinion.reference / 3.0;
    let member = |hb: f64, j: f64| MemberData {
        j,
        rim: 1.0,
        bending_allowable: bending_allowable_through_hardened(hb, Grade::Two).unwrap(),
        contact_allowable: contact_allowable_through_hardened(hb, Grade::Two).unwrap(),
        yn: 1.0,
        zn: 1.0,
        ch: 1.0,
    };
    let rating = GearSetRating {
        module: m,
        pinion_diameter: pair.pinion.working,
        overload: 1.0,
        load_distribution: LoadDistribution {
            crowned: false,
            offset_ratio: 0.0,
            enclosure: Enclosure::PrecisionEnclosed,
            adjusted_at_assembly: false,
        },
        size: SizeFactor::Given([1.0, 1.0]),
        surface_condition: 1.0,
        geometry_i: pitting_geometry_factor(&pair, IForm::Lpstc).unwrap(),
        elastic_coefficient: elastic_coefficient(210e9, 0.3, 210e9, 0.3).unwrap(),
        temperature: 1.0,
        reliability: 1.0,
        pinion: member(300.0, 0.40),
        gear: member(300.0, 0.45),
    };
    GearSet {
        buckingham: BuckinghamPair {
            pinion_radius: pair.pinion.reference / 2.0,
            gear_radius: pair.gear.reference / 2.0,
            internal: true,
            face_width: b,
            error: 0.005 * INCH,
            e1: 210e9,
            e2: 210e9,
            form: FULL_DEPTH_20,
        },
        pair,
        face_width: b,
        quality: Quality::Qv(8.0),
        rating,
        lubricant: Lubricant {
            kinematic_viscosity: 5e-6,
            density: 900.0,
        },
        loss_reading: Some(Reading::Corrected),
    }
}

#[test]
fn step_with_load_and_without() {
    let set = cardan_set();
    let w = 200.0 * std::f64::consts::PI;
    let speeds = MeshSpeeds {
        pinion_absolute: -w,
        carrier: w,
    };
    let v = cardan_gears::buckingham::cardan_pitch_line_velocity(w, 0.03);
    let r = set
        .evaluate(&MeshStep {
            tangential_load: -20_000.0,
            pitch_line_velocity: v,
            speeds,
        })
        .unwrap();
    // Physical ordering, no paper needed: dynamic load above the static load, Kv > 1,
    // finite positive stresses and safety factors, positive loss.
    assert!(r.dynamic.dynamic_load > 20_000.0);
    assert!(r.kv.kv > 1.0);
    for k in 0..2 {
        assert!(r.rating.bending_stress[k] > 0.0 && r.rating.bending_safety[k].is_finite());
        assert!(r.rating.contact_safety[k] > 0.0);
    }
    let loss = r.loss.unwrap();
    assert!(loss.total_power > 0.0);
    // Zero load: zero stresses and dynamic load, only windage remains.
    let z = set
        .evaluate(&MeshStep {
            tangential_load: 0.0,
            pitch_line_velocity: v,
            speeds,
        })
        .unwrap();
    assert_eq!(z.dynamic.dynamic_load, 0.0);
    assert_eq!(z.rating.bending_stress, [0.0, 0.0]);
    assert!(z.rating.bending_safety[0].is_infinite());
    let zero = z.loss.unwrap();
    assert_eq!(zero.total_power, zero.windage_power);
    // Invalid step input is an error, not a panic.
    assert!(set
        .evaluate(&MeshStep {
            tangential_load: f64::NAN,
            pitch_line_velocity: v,
            speeds,
        })
        .is_err());
}
