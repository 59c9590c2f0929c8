//! The loss budget: each component is its friction model at its joint with the joint's load,
//! bearing count and relative speed (hand-evaluated here from the thesis's formulas), and the
//! losses keep the energy books: the friction torque integrated over the crank angle is the lost
//! energy integrated over time.

mod common;

use cardan_dynamics::{
    run, Attachment, Friction, Gas, Inertial, LoadFamily, LossBudget, LossStage, Sink, Solver,
    Steps, SummarySink,
};
use cardan_gears::geometry::{GearPair, PairSpec};
use cardan_gears::mesh_loss::{mesh_loss, Lubricant, MeshGeometry, MeshSpeeds, Reading};
use cardan_mechanism::{CrankState, Grid, Loads, Material, Mechanism, C};
use common::{accelerating_pump, pump_gas, thesis};
use std::f64::consts::PI;

/// Karhula's ring pack contact force for the 120 mm piston: 2·0.19 MPa·π·d·2 mm +
/// 1 MPa·π·d·4 mm (A9.1.2-3) = 4760 N/m · π · 0.12 m.
const RING_FORCE: f64 = 4760.0 * PI * 0.12;

/// Karhula's bearing torque, N·m (A9.1.26-33) with the load constant 0.0009, f0 = 2 and
/// ν = 5 mm²/s, for one bearing of pitch diameter `dm` (m) and rating `c0` (N) carrying `f` (N)
/// at relative speed `w` (rad/s).
fn karhula_torque(f: f64, c0: f64, dm: f64, w: f64) -> f64 {
    let n = w.abs() * 60.0 / (2.0 * PI);
    let nun = 5.0 * n;
    let viscous = if nun > 2000.0 {
        9.79e-2 * 2.0 * nun.powf(2.0 / 3.0) * dm.powi(3)
    } else {
        24.1 * 2.0 * dm.powi(3)
    };
    0.0009 * f.powf(1.55) * c0.powf(-0.55) * dm + viscous
}

fn joint(m: &dyn Mechanism, name: &str) -> usize {
    m.topology()
        .joints
        .iter()
        .position(|j| j.name == name)
        .unwrap()
}

fn loss(budget: &LossBudget, out: &[f64], name: &str) -> f64 {
    out[budget.names().iter().position(|n| n == name).unwrap()]
}

#[test]
fn cardan_gear_components_are_their_models_at_their_joints() {
    let m = thesis("cardan_gear", Material::Steel);
    let w = 200.0 * PI;
    let state = m.state(&CrankState::new(1.0, w, 0.0, 0.0));
    let mut loads = Loads::for_topology(m.topology());
    let (main, pin, mesh) = (
        joint(m.as_ref(), "main_bearing"),
        joint(m.as_ref(), "crank_pin"),
        joint(m.as_ref(), "gear_mesh"),
    );
    loads.joints[main].force = C::new(6000.0, -8000.0);
    loads.joints[pin].force = C::new(3000.0, 4000.0);
    // A mesh force of 2 kN along the pitch-circle tangent and 700 N radial.
    let d = state.joints[mesh].direction;
    loads.joints[mesh].force = C::i() * d * 2000.0 + d * 700.0;
    let mut budget = LossBudget::new(&Friction::karhula(), m.as_ref(), 0.12).unwrap();
    assert_eq!(
        budget.names(),
        [
            "rings",
            "main_bearing",
            "crank_pin",
            "piston_pin",
            "gear_mesh"
        ]
    );
    let mut out = vec![f64::NAN; budget.names().len()];
    budget
        .at_state(m.topology(), (&state, &loads), None, &mut out)
        .unwrap();
    let close = |what: &str, got: f64, want: f64| {
        assert!(
            (got - want).abs() <= 1e-12 * want.abs().max(1.0),
            "{what}: {got} vs {want}"
        );
    };
    // Rings: μ_ring·F_cont·|v| (A9.1.4, A9.1.8); the cardan piston moves at 2·r_c·ω·cos θ.
    close(
        "rings",
        loss(&budget, &out, "rings"),
        0.07 * RING_FORCE * (2.0 * 0.03 * w * 1f64.cos()).abs(),
    );
    // Main bearings: two, 5 kN each, at ω; d_m = 45 mm, C0 = 60 kN (A9.1.11, 13, 25).
    close(
        "main_bearing",
        loss(&budget, &out, "main_bearing"),
        2.0 * karhula_torque(5000.0, 60e3, 0.045, w) * w,
    );
    // Crank pin: two bearings in the wheel, 2.5 kN each (A9.1.23), at 2ω (A9.1.17).
    close(
        "crank_pin",
        loss(&budget, &out, "crank_pin"),
        2.0 * karhula_torque(2500.0, 60e3, 0.045, 2.0 * w) * 2.0 * w,
    );
    // Piston pin unloaded: the viscous term alone, d_m = 30 mm, at ω (A9.1.15).
    close(
        "piston_pin",
        loss(&budget, &out, "piston_pin"),
        karhula_torque(0.0, 30e3, 0.030, w) * w,
    );
    // Mesh: the 20/40 pair of module 3 mm (A9.1.37), b = d1/3, the wheel turning at −ω
    // absolute and −2ω relative to the crank that carries it.
    let mut spec = PairSpec::standard(0.003, 20, -40, 20f64.to_radians(), 0.0, 0.0);
    spec.gear = spec.gear.with_addendum(0.8);
    let pair = GearPair::new(spec).unwrap();
    let geometry = MeshGeometry::from_pair(&pair, 0.02).unwrap();
    let lubricant = Lubricant {
        kinematic_viscosity: 5e-6,
        density: 900.0,
    };
    for (word, reading) in [
        ("karhula", Reading::Karhula),
        ("corrected", Reading::Corrected),
    ] {
        let mut friction = Friction::karhula();
        friction.gear_mesh = cardan_dynamics::loss_models::find(Attachment::GearMesh, word);
        let mut budget = LossBudget::new(&friction, m.as_ref(), 0.12).unwrap();
        budget
            .at_state(m.topology(), (&state, &loads), None, &mut out)
            .unwrap();
        let speeds = MeshSpeeds {
            pinion_absolute: -w,
            carrier: w,
        };
        let want = mesh_loss(&geometry, &lubricant, &speeds, 2000.0, reading)
            .unwrap()
            .total_power;
        close("gear_mesh", loss(&budget, &out, "gear_mesh"), want);
    }
}

#[test]
fn the_skirt_carries_coulomb_friction_on_the_side_force() {
    // A9.1.5: F = μ_skirt·|F_Σ03|, P = F·|v_piston| with μ_skirt = 0.09.
    let m = thesis("slider_crank", Material::Steel);
    let w = 30.0 * PI;
    let state = m.state(&CrankState::new(2.0, w, 0.0, 0.0));
    let mut loads = Loads::for_topology(m.topology());
    loads.joints[joint(m.as_ref(), "piston_side")].force = C::new(-1500.0, 0.0);
    let mut budget = LossBudget::new(&Friction::karhula(), m.as_ref(), 0.12).unwrap();
    let mut out = vec![0.0; budget.names().len()];
    budget
        .at_state(m.topology(), (&state, &loads), None, &mut out)
        .unwrap();
    let v = state.pistons[0].velocity.abs();
    assert!(v > 1.0);
    let skirt = loss(&budget, &out, "skirt");
    assert!((skirt - 0.09 * 1500.0 * v).abs() < 1e-9 * skirt, "{skirt}");
    // The cardan gear has no piston slide, hence no skirt (A9.1.7).
    let c = thesis("cardan_gear", Material::Steel);
    let budget = LossBudget::new(&Friction::karhula(), c.as_ref(), 0.12).unwrap();
    assert!(!budget.names().iter().any(|n| n == "skirt"));
}

/// Records the crank angle and friction torque of every step (the loss budget's first value:
/// the run's only stage).
#[derive(Default)]
struct FrictionTorque(Vec<(f64, f64)>);

impl Sink for FrictionTorque {
    fn push(&mut self, s: &cardan_dynamics::Step) -> Result<(), String> {
        self.0.push((s.state.crank.angle, s.stages[0][0]));
        Ok(())
    }
}

#[test]
fn losses_keep_the_energy_books() {
    // An accelerating pump (ω from 30π to about 78π rad/s over the cycle) with a gas force: the
    // drive's extra work ∫ T_f dθ (friction torque over the crank angle) must equal the energy
    // lost ∫ P dt (power over time), and the summary's need and efficiency must follow from
    // the works (A9.1.60-73). The two integrals are different quadratures of the same energy:
    // they agree to the rule's error, O(h²).
    let m = thesis("slider_crank", Material::Steel);
    let motion = accelerating_pump();
    let inertial = Inertial::new(Solver::ClosedForm);
    let gas_family = Gas(Solver::ClosedForm);
    let families: [&dyn LoadFamily; 2] = [&inertial, &gas_family];
    let budget = LossBudget::new(&Friction::karhula(), m.as_ref(), 0.12).unwrap();
    let mut budget = LossStage::new(budget);
    let mut summary =
        SummarySink::new(m.as_ref(), &["inertial", "gas"], 7201).with_stages(&[&budget]);
    let mut torque = FrictionTorque::default();
    let mut steps = Steps::default();
    let mut grid = Grid::new(motion, PI / 2.0, 4.5 * PI, 7200);
    run(
        m.as_ref(),
        &mut grid,
        &families,
        Some(&pump_gas),
        &mut [&mut budget],
        &mut [&mut summary, &mut torque, &mut steps],
    )
    .unwrap();
    let s = summary.finish(m.as_ref()).unwrap();
    let lost = s.get("loss_work").unwrap();
    let by_angle: f64 = torque
        .0
        .windows(2)
        .map(|p| 0.5 * (p[1].0 - p[0].0) * (p[1].1 + p[0].1))
        .sum();
    assert!(lost > 100.0, "{lost}");
    assert!(
        (by_angle / lost - 1.0).abs() < 1e-5,
        "∫T_f dθ = {by_angle} J against ∫P dt = {lost} J"
    );
    let time = s.get("cycle_time").unwrap();
    let components: f64 = s
        .metrics
        .iter()
        .filter(|m| m.name.starts_with("power_loss_mean_"))
        .map(|m| m.value)
        .sum();
    assert!((components - s.get("power_loss_mean").unwrap()).abs() < 1e-9 * components);
    assert!((s.get("power_loss_mean").unwrap() * time - lost).abs() < 1e-9 * lost);
    let total = s.get("total_work").unwrap();
    let gas_work = s.get("gas_work").unwrap();
    assert!(total > 0.0, "a pump takes work");
    let need = s.get("torque_need_mean").unwrap() * 4.0 * PI;
    assert!((need - (total + lost)).abs() < 1e-9 * need);
    let efficiency = s.get("mechanical_efficiency").unwrap();
    assert!((efficiency - gas_work / (total + lost)).abs() < 1e-12);
    // Every step's losses are non-negative and sum to the friction torque times the speed.
    for r in &steps.0 {
        let (friction_torque, losses) = r.stages[0].split_first().unwrap();
        assert!(losses.iter().all(|p| *p >= 0.0));
        let sum: f64 = losses.iter().sum();
        assert!((sum - friction_torque * r.state.crank.speed).abs() <= 1e-9 * sum.max(1.0));
    }
}

#[test]
fn catalogue_values_override_the_declared_bearings() {
    // The cardan crank pin on one catalogue bearing of d_m = 50 mm and C0 = 80 kN instead of
    // the two rule-sized ones: the whole 5 kN on it, at 2ω.
    let m = thesis("cardan_gear", Material::Steel);
    let w = 100.0 * PI;
    let state = m.state(&CrankState::new(0.5, w, 0.0, 0.0));
    let mut loads = Loads::for_topology(m.topology());
    loads.joints[joint(m.as_ref(), "crank_pin")].force = C::new(0.0, 5000.0);
    let mut friction = Friction::karhula();
    friction.joint_sizes.push((
        "crank_pin".into(),
        cardan_dynamics::BearingSize {
            pitch_diameter: Some(0.05),
            static_load_rating: Some(80e3),
            count: Some(1),
        },
    ));
    let mut budget = LossBudget::new(&friction, m.as_ref(), 0.12).unwrap();
    let mut out = vec![0.0; budget.names().len()];
    budget
        .at_state(m.topology(), (&state, &loads), None, &mut out)
        .unwrap();
    let want = karhula_torque(5000.0, 80e3, 0.05, 2.0 * w) * 2.0 * w;
    let got = loss(&budget, &out, "crank_pin");
    assert!((got - want).abs() <= 1e-12 * want, "{got} vs {want}");
    // The main bearings keep their declared sizes.
    let main = loss(&budget, &out, "main_bearing");
    assert!((main - 2.0 * karhula_torque(0.0, 60e3, 0.045, w) * w).abs() <= 1e-12 * main);
}
