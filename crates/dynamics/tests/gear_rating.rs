//! Gear rating in runs: each mesh's rating is the gears crate's chain evaluated on the mesh
//! joint's own tooth load and pitch-line velocity (Buckingham A8.1.1-14 checked against the
//! chain evaluated by hand here), the twin set halves the load, and the ring-force reading takes
//! the force's magnitude.

mod common;

use cardan_dynamics::mesh::GearStandard;
use cardan_dynamics::{
    run, Block, Gas, GasAt, GearRatings, GearSpec, GearStage, Inertial, LaneError, LoadFamily,
    MeshRating, MetricDef, PassedOn, Solver, Stage, StageColumn, StageTotals, Steps, ToothLoad,
};
use cardan_mechanism::{
    Column, CrankMotion, CrankState, Grid, Loads, Material, Mechanism, MotionSource, C, ZERO,
};
use cardan_testing::OneByOne;
use common::{every_machine, pump_gas, thesis};
use std::f64::consts::PI;

/// Karhula's Buckingham chain in US units as printed (A8.1.3-14) for the cardan pair of crank
/// e = 0.03 m, 20/40 teeth, b = d1/3, E = 210 GPa (Karhula's "≈ 30e6 psi", taken exactly here
/// as the code's SI default), e = 0.005 in: tangential load `ft` (N) at crank speed `w` (rad/s),
/// N.
fn karhula_dynamic_load(ft: f64, w: f64) -> f64 {
    let (inch, lbf) = (0.0254, 4.448_221_615_260_5);
    let (r1, r2): (f64, f64) = (0.03 / inch, 0.06 / inch);
    let h = 0.00120 * (1.0 / r1 - 1.0 / r2);
    let d1 = 2.0 * r1;
    let m1 = PI * d1.powi(4) / 32.0 / (r1 * r1);
    let v = 2.0 * 0.03 * w / 0.00508; // ft/min (A8.1.7)
    let f1 = h * m1 * v * v;
    let ft = ft / lbf;
    let e_psi = 210e9 / 6_894.757_293_168;
    let def = 9.0 * ft / (d1 / 3.0) * (2.0 / e_psi);
    let f2 = ft * (0.005 / def + 1.0);
    let fa = f1 * f2 / (f1 + f2);
    (ft + (fa * (2.0 * f2 - fa)).sqrt()) * lbf
}

fn rate(spec: &GearSpec, w: f64, force: C) -> (MeshRating, C) {
    let m = thesis("cardan_gear", Material::Steel);
    let state = m.state(&CrankState::new(1.0, w, 0.0, 0.0));
    let mesh = m
        .topology()
        .joints
        .iter()
        .position(|j| j.name == "gear_mesh")
        .unwrap();
    let mut loads = Loads::for_topology(m.topology());
    let d = state.joints[mesh].direction;
    loads.joints[mesh].force = force.re * C::i() * d + force.im * d;
    let mut ratings = GearRatings::new(spec, m.as_ref(), None).unwrap();
    assert_eq!(ratings.names(), ["gear_mesh"]);
    let mut out = [MeshRating::default()];
    ratings
        .evaluate(m.topology(), &state, &loads, None, &mut out)
        .unwrap();
    (out[0], loads.joints[mesh].force)
}

#[test]
fn the_dynamic_tooth_load_is_buckingham_on_the_tangential_load() {
    // A mesh force of 8 kN tangential and 3 kN radial, at 30π and 200π rad/s. Tolerance 1e-6:
    // the chain in US units and the SI one differ only by the unit constants' roundings.
    for w in [30.0 * PI, 200.0 * PI] {
        let (r, _) = rate(&GearSpec::default(), w, C::new(8000.0, 3000.0));
        assert!((r.tooth_load - 8000.0).abs() < 1e-9, "{}", r.tooth_load);
        let want = karhula_dynamic_load(8000.0, w);
        assert!(
            (r.dynamic_load / want - 1.0).abs() < 1e-6,
            "{} vs {want}",
            r.dynamic_load
        );
        assert!(r.dynamic_load > r.tooth_load);
        assert!(r.contact_stress > 0.0 && r.contact_safety.is_finite());
        // Issue 39.1: J not given is computed from the tooth form (AGMA 908-B89 for the
        // pinion, ISO 6336-3 method B for the ring): the rating equals one with those J given.
        assert!(r.bending_stress > 0.0 && r.bending_safety.is_finite());
        let mut karhula =
            cardan_gears::PairSpec::standard(3e-3, 20, -40, 20f64.to_radians(), 0.0, 0.0);
        karhula.gear = karhula.gear.with_addendum(0.8);
        let pair = cardan_gears::GearPair::new(karhula).unwrap();
        let j = |which| {
            cardan_gears::bending_geometry_factor(&pair, cardan_gears::GeneratedMember::new(which))
                .unwrap()
                .j
        };
        let given = GearSpec {
            j: Some([
                j(cardan_gears::PairMember::Pinion),
                j(cardan_gears::PairMember::Gear),
            ]),
            ..GearSpec::default()
        };
        let (g, _) = rate(&given, w, C::new(8000.0, 3000.0));
        assert_eq!(g.bending_stress, r.bending_stress);
        assert_eq!(g.bending_safety, r.bending_safety);
    }
}

#[test]
fn twin_sets_share_and_the_ring_force_reading_takes_the_magnitude() {
    let w = 100.0 * PI;
    let force = C::new(6000.0, 8000.0);
    let single = rate(&GearSpec::default(), w, force).0;
    let twin = rate(
        &GearSpec {
            twin: true,
            j: Some([0.3, 0.4]),
            ..GearSpec::default()
        },
        w,
        force,
    )
    .0;
    assert!((twin.tooth_load - 3000.0).abs() < 1e-9);
    assert!((twin.dynamic_load - karhula_dynamic_load(3000.0, w)).abs() < 1e-6 * twin.dynamic_load);
    assert!(twin.contact_stress < single.contact_stress);
    assert!(twin.bending_stress > 0.0 && twin.bending_safety.is_finite());
    let (ring, applied) = rate(
        &GearSpec {
            tooth_load: ToothLoad::RingForce,
            ..GearSpec::default()
        },
        w,
        force,
    );
    assert!((ring.tooth_load - applied.norm()).abs() < 1e-9);
    assert!((ring.tooth_load - 10_000.0).abs() < 1e-9);
}

#[test]
fn an_interfering_pair_is_refused_with_its_remedy() {
    // 20/40 at 20° with a full ring addendum interferes (docs/validation/gears.md §1.3): the error
    // names the field and the remedies.
    let m = thesis("cardan_gear", Material::Steel);
    let spec = GearSpec {
        ring_addendum: 1.0,
        ..GearSpec::default()
    };
    let e = GearRatings::new(&spec, m.as_ref(), None).unwrap_err();
    assert_eq!(
        e.field,
        cardan_dynamics::SetupInput::Gear(cardan_dynamics::GearInput::RingAddendum)
    );
    assert!(e.rule.contains("shorten the ring addendum"), "{}", e.rule);
    // 25 teeth on the wheel do not (the module follows: 2·30 mm / 25).
    let spec = GearSpec {
        teeth: 25,
        ring_addendum: 1.0,
        ..GearSpec::default()
    };
    assert!(GearRatings::new(&spec, m.as_ref(), None).is_ok());
    // Karhula's pair with the 0.8-module ring addendum: εα = 1.765 (configs-gears).
    let r = GearRatings::new(&GearSpec::default(), m.as_ref(), None).unwrap();
    assert!(
        (r.contact_ratios()[0] - 1.765).abs() < 5e-4,
        "{:?}",
        r.contact_ratios()
    );
}

/// The ISO 6336 rating beside AGMA's (`standard = Both`) leaves AGMA's figures as they were,
/// bit for bit; the ISO stresses grow with the load (σ_H about as its square root, σ_F about in
/// proportion, K_v and K_Hα aside), are 0 without a load, the safety factors then infinite as
/// AGMA's; `Iso6336` gives the same ISO figures as `Both`.
#[test]
fn the_iso_rating_stands_beside_agma_s_without_changing_it() {
    use cardan_dynamics::mesh::GearStandard;
    let iso = |standard| GearSpec {
        standard,
        accuracy_grade: Some(7.0),
        ..GearSpec::default()
    };
    let w = 30.0 * PI;
    let force = C::new(8000.0, 3000.0);
    let (agma, _) = rate(&GearSpec::default(), w, force);
    let (both, _) = rate(&iso(GearStandard::Both), w, force);
    let (alone, _) = rate(&iso(GearStandard::Iso6336), w, force);
    assert_eq!(
        agma.values()[..MeshRating::AGMA_WIDTH],
        both.values()[..MeshRating::AGMA_WIDTH]
    );
    assert!(agma.iso_contact_stress.is_nan());
    assert_eq!(both.values(), alone.values());
    assert!(both.iso_contact_stress > 0.0 && both.iso_bending_stress > 0.0);
    assert!(both.iso_contact_safety.is_finite() && both.iso_bending_safety.is_finite());
    let (double, _) = rate(&iso(GearStandard::Both), w, force * 2.0);
    let contact = double.iso_contact_stress / both.iso_contact_stress;
    let root = double.iso_bending_stress / both.iso_bending_stress;
    // K_v and K_Hα of method B fall as the line load rises: the ratios lie below √2 and 2.
    assert!(
        contact > 1.0 && contact <= 2f64.sqrt() * (1.0 + 1e-12),
        "{contact}"
    );
    assert!(root > 1.0 && root <= 2.0 * (1.0 + 1e-12), "{root}");
    // At no load at all the ISO stresses are 0 and the safety factors infinite, as AGMA's
    // (method B's K_v grows as 1/F_t, its dynamic increment staying as the load vanishes: a
    // load of round-off size is rated at that increment's finite stress).
    let (none, _) = rate(&iso(GearStandard::Both), w, C::new(0.0, 0.0));
    assert_eq!(none.iso_contact_stress, 0.0);
    assert_eq!(none.iso_contact_safety, f64::INFINITY);
    assert_eq!(none.iso_bending_safety, f64::INFINITY);
}

/// The gear specifications the block tests rate: AGMA's defaults; both standards with the
/// ring-force reading on a twin set; ISO with the thesis's reading; AGMA with it.
fn block_specs() -> [GearSpec; 4] {
    [
        GearSpec::default(),
        GearSpec {
            standard: GearStandard::Both,
            accuracy_grade: Some(7.0),
            tooth_load: ToothLoad::RingForce,
            twin: true,
            ..GearSpec::default()
        },
        GearSpec {
            standard: GearStandard::Iso6336,
            accuracy_grade: Some(6.0),
            tooth_load: ToothLoad::Thesis,
            ..GearSpec::default()
        },
        GearSpec {
            tooth_load: ToothLoad::Thesis,
            ..GearSpec::default()
        },
    ]
}

/// `f` for every mechanism with a mesh and every spec of [`block_specs`] it takes (the
/// thesis's reading is refused on an involute mesh): its name, the mechanism, its load
/// families and gas (the gas only where there is a cylinder: the hypotrochoid's pistons are
/// in none), the spec and its ratings.
fn each_rated(
    mut f: impl FnMut(&str, &dyn Mechanism, &[&dyn LoadFamily], Option<GasAt>, &GearSpec, GearRatings),
) {
    let inertial = Inertial::new(Solver::ClosedForm);
    let gas = Gas(Solver::ClosedForm);
    for (name, m) in every_machine() {
        let cylinder = m.has_cylinder();
        let families: Vec<&dyn LoadFamily> = if cylinder {
            vec![&inertial, &gas]
        } else {
            vec![&inertial]
        };
        let gas_at: Option<GasAt> = cylinder.then_some(&pump_gas);
        for spec in &block_specs() {
            let Ok(ratings) = GearRatings::new(spec, m.as_ref(), None) else {
                continue;
            };
            if !ratings.names().is_empty() {
                f(&name, m.as_ref(), &families, gas_at, spec, ratings);
            }
        }
    }
}

/// The gear stage rates a block from its columns (`GearRatings::evaluate_block`): each lane's
/// values are those of its step rated in a block of its own (the steps handed out one at a
/// time, as a solved motion's), bit for bit, on every mechanism with a mesh, in every
/// tooth-load reading (the thesis's reads the inertial family's mesh force and the wheel's
/// acceleration) and standard, at an accelerating crank (every lane a different state).
#[test]
fn a_block_is_rated_lane_by_lane_as_each_step_alone() {
    let motion = CrankMotion {
        start_angle: 1.0,
        initial_speed: 100.0,
        angular_acceleration: 500.0,
    };
    let mut rated = Vec::new();
    each_rated(|name, m, families, gas_at, spec, ratings| {
        let stage = GearStage::new(ratings);
        let mut runs = Vec::new();
        for blocks in [true, false] {
            let grid = Grid::new(motion, 1.0, 20.0, 2 * 64 + 11);
            let mut one_by_one = OneByOne(grid.clone());
            let mut grid = grid;
            let source: &mut dyn MotionSource = match blocks {
                true => &mut grid,
                false => &mut one_by_one,
            };
            let mut s = stage.clone();
            let mut kept = Steps::default();
            run(m, source, families, gas_at, &mut [&mut s], &mut [&mut kept]).unwrap();
            let values: Vec<Vec<u64>> = (kept.0.iter())
                .map(|r| r.stages[0].iter().map(|v| v.to_bits()).collect())
                .collect();
            runs.push(values);
        }
        assert_eq!(runs[0].len(), 2 * 64 + 12, "{name}");
        assert!(runs[0].iter().all(|v| !v.is_empty()), "{name}");
        // The lanes differ (a block is not one state repeated).
        assert_ne!(runs[0][0], runs[0][70], "{name}");
        assert_eq!(runs[0], runs[1], "{name} {:?}", spec.tooth_load);
        rated.push((name.to_string(), spec.tooth_load));
    });
    // The cardan gear in both mesh-force readings and the hypotrochoid, in each tooth-load
    // reading they take.
    let has = |name: &str, load| rated.iter().any(|r| r.0 == name && r.1 == load);
    assert!(has("cardan_gear", ToothLoad::Thesis), "{rated:?}");
    assert!(
        has("cardan_gear involute", ToothLoad::RingForce),
        "{rated:?}"
    );
    assert!(has("hypotrochoid", ToothLoad::Tangential), "{rated:?}");
}

/// The gear stage, each block rated both ways: over its lanes, a mesh at a time
/// (`GearRatings::losses_over_lanes` and `rate_lanes`, which `evaluate_block` takes: the mesh
/// loss's logarithm and power every lane at once) and lane by lane
/// (`GearRatings::evaluate_block_lane_by_lane`, the steps' own arithmetic with its checks); the
/// two must give the same bits, and the lanes' way must take every block (none out of range).
#[derive(Debug, Clone)]
struct BothWays {
    stage: GearStage,
    lanes: GearRatings,
    one_by_one: GearRatings,
    per_mesh: usize,
}

impl Stage for BothWays {
    fn width(&self) -> usize {
        self.stage.width()
    }

    fn evaluate(
        &mut self,
        block: &Block,
        passed: &mut PassedOn,
        out: &mut [Column],
    ) -> Result<(), LaneError> {
        let per_mesh = self.per_mesh;
        let mut losses: Vec<_> = self.lanes.joints().map(|j| (j, ZERO)).collect();
        (self.one_by_one)
            .evaluate_block_lane_by_lane(block, out, per_mesh, &mut losses)
            .unwrap();
        let mut lane_losses: Vec<_> = self.lanes.joints().map(|j| (j, ZERO)).collect();
        assert!(self.lanes.losses_over_lanes(block, &mut lane_losses));
        let mut lanes = vec![ZERO; out.len()];
        assert!(self
            .lanes
            .rate_lanes(block, &mut lanes, per_mesh, &lane_losses));
        let same = |a: &[Column], b: &[Column], what: &str| {
            for (k, (a, b)) in a.iter().zip(b).enumerate() {
                for i in 0..block.len {
                    assert_eq!(a[i].to_bits(), b[i].to_bits(), "{what} {k} lane {i}");
                }
            }
        };
        let columns = |l: &[(usize, Column)]| l.iter().map(|c| c.1).collect::<Vec<_>>();
        same(&columns(&losses), &columns(&lane_losses), "loss");
        same(out, &lanes, "value");
        passed.mesh_losses.extend(losses);
        Ok(())
    }

    fn columns(&self) -> Vec<StageColumn> {
        self.stage.columns()
    }

    fn metrics(&self) -> &'static [MetricDef] {
        self.stage.metrics()
    }

    fn totals(&self) -> Box<dyn StageTotals> {
        self.stage.totals()
    }

    fn fork(&self) -> Box<dyn Stage> {
        Box::new(self.clone())
    }
}

/// A block rated over its lanes has, bit for bit, the values of its lanes rated one by one
/// ([`BothWays`]), on every mechanism with a mesh, in every tooth-load reading and standard,
/// at an accelerating crank (every lane a different state, a speed each) and a constant one
/// (the kept dynamic factor), full blocks and a short one.
#[test]
fn a_block_rated_over_its_lanes_has_the_bits_of_its_lanes_one_by_one() {
    let mut rated = 0;
    each_rated(|name, m, families, gas_at, _, ratings| {
        let per_mesh = if ratings.iso() {
            MeshRating::WIDTH
        } else {
            MeshRating::AGMA_WIDTH
        };
        for acceleration in [500.0, 0.0] {
            let motion = CrankMotion {
                start_angle: 1.0,
                initial_speed: 100.0,
                angular_acceleration: acceleration,
            };
            let mut stage = BothWays {
                stage: GearStage::new(ratings.clone()),
                lanes: ratings.clone(),
                one_by_one: ratings.clone(),
                per_mesh,
            };
            let mut grid = Grid::new(motion, 1.0, 20.0, 2 * 64 + 11);
            let mut kept = Steps::default();
            run(
                m,
                &mut grid,
                families,
                gas_at,
                &mut [&mut stage],
                &mut [&mut kept],
            )
            .unwrap();
            assert_eq!(kept.0.len(), 2 * 64 + 12, "{name}");
            rated += 1;
        }
    });
    assert!(rated >= 8, "{rated} runs rated");
}
