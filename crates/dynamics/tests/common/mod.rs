//! Shared set-up for the dynamics tests: the thesis machine of Karhula (2008), r = 0.06 m,
//! l = 0.14 m (ZBA = 2.33·ZAA0), bore 0.12 m, cycle 90° → 810°.
#![allow(dead_code)]

use cardan_dynamics::{run_cycle, MassProperties, Material, Step, Summary};
use cardan_mechanism::{CardanGear, CrankMotion, Mechanism, MechanismKind, SliderCrank};
use std::f64::consts::PI;

pub const CRANK: f64 = 0.06;
pub const ROD: f64 = 0.14;
pub const BORE: f64 = 0.12;

/// The masses the thesis's published inertial results imply (it does not print them): its
/// cardan crank-pin forces give a reciprocating mass (piston + pin + rod) of 1.282 kg with the
/// steel rod, of which the chapter-10 rod rule gives 1.256 kg, leaving 0.026 kg for the piston
/// and pin; its mean inertial torques give the slider-crank rod a moment of inertia of about
/// m·ℓ²/3 = 0.0167 kg·m² (ℓ = 0.2 m). The same values are in configs/karhula-*.toml.
pub fn thesis_masses(kind: MechanismKind, rod: Material) -> MassProperties {
    let mut m = MassProperties::estimate(kind, CRANK, ROD, BORE, rod);
    m.piston_mass = 0.026;
    if kind == MechanismKind::SliderCrank {
        m.rod_inertia = 0.0167;
    }
    m
}

pub fn mechanism(kind: MechanismKind, rod_point: f64) -> Box<dyn Mechanism> {
    match kind {
        MechanismKind::SliderCrank => {
            Box::new(SliderCrank::new(CRANK, ROD, 0.0, rod_point).unwrap())
        }
        MechanismKind::CardanGear => {
            Box::new(CardanGear::equivalent_to_slider_crank(CRANK, ROD, rod_point).unwrap())
        }
    }
}

/// The thesis cycle at initial speed `w0` and acceleration `alpha` (rad/s, rad/s²).
pub fn cycle(
    kind: MechanismKind,
    masses: &MassProperties,
    w0: f64,
    alpha: f64,
    steps: usize,
) -> (Vec<Step>, Summary) {
    let mech = mechanism(kind, masses.rod_cg);
    let motion = CrankMotion {
        start_angle: PI / 2.0,
        initial_speed: w0,
        angular_acceleration: alpha,
    };
    let grid = motion.grid(PI / 2.0, 4.5 * PI, steps).unwrap();
    let steps = run_cycle(mech.as_ref(), masses, &grid, None);
    let summary = Summary::of_cycle(mech.as_ref(), masses, &steps);
    (steps, summary)
}
