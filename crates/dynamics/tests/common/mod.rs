//! Shared set-up for the dynamics tests: the thesis machine of Karhula (2008), r = 0.06 m,
//! l = 0.14 m (ZBA = 2.33·ZAA0), bore 0.12 m, cycle 90° → 810°.
#![allow(dead_code)]

use cardan_dynamics::{run_summary, Solver, StepRecord, Summary};
use cardan_mechanism::{
    entry, CrankMotion, Grid, MachineGeometry, MassInputs, Material, Mechanism, OptionValue,
    Options, C, MECHANISMS,
};
use std::f64::consts::PI;

pub const GEOMETRY: MachineGeometry = MachineGeometry {
    crank_length: 0.06,
    rod_length: 0.14,
    bore: 0.12,
    pin_offset: 0.0,
};

/// The masses of the shipped `configs/karhula-*.toml` cases: the default rules
/// (docs/mass-rules.md; they give the piston with pin the thesis's published cardan crank-pin
/// forces imply) but for the slider-crank rod's moment of inertia, 0.0167 kg·m² (about
/// m·ℓ²/3, ℓ = 0.2 m), which puts its crank-pin force and peak torque nearer the thesis's
/// than the rule's mean-torque value.
pub fn thesis_masses(mechanism: &str, rod: Material) -> MassInputs {
    MassInputs {
        rod_inertia: (mechanism == "slider_crank").then_some(0.0167),
        rod_material: Some(rod),
        ..MassInputs::default()
    }
}

/// The thesis machine as `mechanism` (a registry name), with `options`.
pub fn machine_with(
    mechanism: &str,
    geometry: &MachineGeometry,
    rod: Material,
    options: &[(&str, &str)],
) -> Box<dyn Mechanism> {
    let mut o = Options::new();
    for (k, v) in options {
        o.insert(k.to_string(), OptionValue::Word(v.to_string()));
    }
    (entry(mechanism).unwrap().build)(geometry, &thesis_masses(mechanism, rod), &o).unwrap()
}

pub fn thesis(mechanism: &str, rod: Material) -> Box<dyn Mechanism> {
    machine_with(mechanism, &GEOMETRY, rod, &[])
}

/// Every registered mechanism on the thesis geometry, plus the readings that are not their
/// defaults (an offset slider-crank, the involute cardan mesh): what the generic cross-checks
/// run over, so that a new mechanism is checked without touching them.
pub fn every_machine() -> Vec<(String, Box<dyn Mechanism>)> {
    let mut all: Vec<(String, Box<dyn Mechanism>)> = MECHANISMS
        .iter()
        .map(|e| (e.name.to_string(), thesis(e.name, Material::Steel)))
        .collect();
    let offset = MachineGeometry {
        pin_offset: 0.012,
        ..GEOMETRY
    };
    all.push((
        "slider_crank offset".into(),
        machine_with("slider_crank", &offset, Material::Steel, &[]),
    ));
    all.push((
        "cardan_gear involute".into(),
        machine_with(
            "cardan_gear",
            &GEOMETRY,
            Material::Steel,
            &[("gear_mesh_model", "involute")],
        ),
    ));
    // A wheel that carries its own mass (issue 24), in every reading of every mechanism that
    // has one (the registry's `unused_masses` says which).
    for e in MECHANISMS
        .iter()
        .filter(|e| !e.unused_masses.contains(&"wheel_mass"))
    {
        let masses = MassInputs {
            wheel_mass: Some(0.7),
            ..thesis_masses(e.name, Material::Steel)
        };
        let mut readings = vec![Options::new()];
        for option in e.options {
            if let cardan_mechanism::OptionKind::Choice(words) = option.kind {
                for word in &words[1..] {
                    let mut o = Options::new();
                    o.insert(option.name.into(), OptionValue::Word(word.to_string()));
                    readings.push(o);
                }
            }
        }
        for (k, o) in readings.iter().enumerate() {
            let m = (e.build)(&GEOMETRY, &masses, o).unwrap();
            all.push((format!("{} wheel mass {k}", e.name), m));
        }
    }
    // A rigid mass added to a body turning against the crank (the cardan pair's wheel
    // counterweight, `cardan_balance::MachineBalance::equip`), in every reading that takes
    // one: off the body's axis both ways, with a polar moment of its own, so that its force,
    // its moment about the body's joint and its inertia are all exercised.
    let equipped: Vec<_> = all
        .iter()
        .filter_map(|(name, m)| {
            let body = backward_body(m.as_ref())?;
            let added = m.with_added_mass(body, 0.9, C::new(-0.031, 0.0042), 2.0e-4)?;
            Some((format!("{name} with an added mass"), added))
        })
        .collect();
    all.extend(equipped);
    all
}

/// The first body of `m` turning at minus the crank speed.
pub fn backward_body(m: &dyn Mechanism) -> Option<usize> {
    let st = m.state(&cardan_mechanism::CrankState::new(0.4, 1.0, 0.0, 0.0));
    st.bodies
        .iter()
        .position(|b| (b.angular_velocity + 1.0).abs() < 1e-12)
}

/// The thesis cycle at initial speed `w0` and acceleration `alpha` (rad/s, rad/s²).
pub fn cycle(
    mech: &dyn Mechanism,
    w0: f64,
    alpha: f64,
    steps: usize,
) -> (Vec<StepRecord>, Summary) {
    let motion = CrankMotion {
        start_angle: PI / 2.0,
        initial_speed: w0,
        angular_acceleration: alpha,
    };
    let mut grid = Grid::new(motion, PI / 2.0, 4.5 * PI, steps);
    run_summary(mech, &mut grid, None, Solver::ClosedForm, true).unwrap()
}

/// An accelerating pump cycle from 90°: ω from 30π rad/s at α = 400π rad/s² (about 78π rad/s
/// after 720°).
pub fn accelerating_pump() -> CrankMotion {
    CrankMotion {
        start_angle: PI / 2.0,
        initial_speed: 30.0 * PI,
        angular_acceleration: 400.0 * PI,
    }
}

/// A made-up gas load for the 0.12 m bore: a piston force of 2·10⁴·(1 + sin θ) N and its
/// cylinder pressure, (Pa, N) at crank angle `theta`.
pub fn pump_gas(theta: f64) -> (f64, f64) {
    let f = 2e4 * (1.0 + theta.sin());
    (f / (PI / 4.0 * 0.12 * 0.12), f)
}

/// [`every_machine`] less the mechanisms without closed forms (their loads come from the
/// general solve alone, so comparing the two paths means nothing for them).
pub fn closed_form_machines() -> Vec<(String, Box<dyn Mechanism>)> {
    every_machine()
        .into_iter()
        .filter(|(_, m)| {
            let st = m.state(&cardan_mechanism::CrankState::new(1.0, 1.0, 0.0, 0.0));
            let mut loads = cardan_mechanism::Loads::for_topology(m.topology());
            m.closed_form_loads(&st, true, &[], &mut loads)
        })
        .collect()
}
