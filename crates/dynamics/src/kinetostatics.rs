//! The loads of one step, whichever mechanism produced them.

use crate::{cardan_gear, slider_crank, MassProperties};
use cardan_mechanism::{KinematicState, MechanismKind, C};

/// Joint forces and crank torque at one crank state. Forces are complex vectors (N) in the
/// frame of the main bearing axis.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Loads {
    /// Force on the crankshaft from the frame at the main bearings, N.
    pub main_bearing: C,
    /// Force on the crankshaft's crank pin from the rod (slider-crank) or from the cardan
    /// wheel (cardan gear), N.
    pub crank_pin: C,
    /// Slider-crank: force on the piston from the rod at the piston pin. Cardan gear: force on
    /// the rod from the cardan wheel at the wheel pin T (the rod's big-end bearing). N.
    pub piston_pin: C,
    /// Force on the piston from the cylinder wall, across the cylinder axis (+x), N. Zero in
    /// the cardan gear, whose rod moves on a straight line.
    pub piston_side: f64,
    /// Cardan gear: force on the cardan wheel from the ring gear at the pitch point, N; zero
    /// for the slider-crank.
    pub gear_mesh: C,
    /// Torque the drive applies to the crankshaft, positive in the direction of rotation, N·m.
    pub crank_torque: f64,
    /// Contributions to `crank_torque` of the crankshaft, of the rod (slider-crank) or cardan
    /// wheel (cardan gear), and of the piston (slider-crank) or piston-and-rod assembly
    /// (cardan gear, with the applied piston force), N·m (Karhula T_1i10, T_2i10, T_3i10).
    pub torque_by_link: [f64; 3],
    /// Slider-crank: distance from the crank pin along the rod of the rod's centre of
    /// percussion, where its inertial force acts with no couple, m (A5.2.1.6-7). `None` where
    /// the inertial force is parallel to the rod and the centre is undefined, and for the
    /// cardan gear, whose rod does not rotate.
    pub rod_percussion_centre: Option<f64>,
}

/// The loads of one step by the closed forms of Karhula (2008) appendix 5.2.1.
///
/// `piston_force` is the force of the gas on the piston along the cylinder axis, N, positive
/// when it pushes the piston towards the crankshaft; 0 gives the thesis's inertial loads.
pub fn loads(
    kind: MechanismKind,
    state: &KinematicState,
    masses: &MassProperties,
    piston_force: f64,
) -> Loads {
    match kind {
        MechanismKind::SliderCrank => slider_crank::loads(state, masses, piston_force),
        MechanismKind::CardanGear => cardan_gear::loads(state, masses, piston_force),
    }
}

/// Kinetic energy of all moving links, J: the quantity whose change the inertial crank torque
/// pays for. The crankshaft assembly turns at ω; the slider-crank rod translates with its
/// centre of gravity and turns at ω_BA; the cardan wheel turns at −ω about the crank pin (its
/// mass belongs to the crankshaft assembly); the reciprocating assembly translates.
pub fn kinetic_energy(kind: MechanismKind, state: &KinematicState, masses: &MassProperties) -> f64 {
    let w = state.crank.speed;
    let crankshaft = 0.5 * masses.crankshaft_inertia * w * w;
    let v = state.piston.velocity;
    let reciprocating = 0.5 * masses.reciprocating_mass(kind) * v * v;
    match kind {
        MechanismKind::SliderCrank => {
            let vg = state.rod.point.velocity.norm_sqr();
            let wr = state.rod.angular_velocity;
            crankshaft
                + reciprocating
                + 0.5 * masses.rod_mass * vg
                + 0.5 * masses.rod_inertia * wr * wr
        }
        MechanismKind::CardanGear => {
            crankshaft + 0.5 * masses.wheel_inertia * w * w + reciprocating
        }
    }
}

/// z × f, the moment about the origin of force f applied at z (scalar, counter-clockwise +).
pub(crate) fn cross(z: C, f: C) -> f64 {
    z.re * f.im - z.im * f.re
}

/// Superposition of loads (Karhula A7.1: the summed lossless dynamics are the sum of the
/// inertial and the gas loads). The centre of percussion, an inertial property, is kept from
/// the left operand.
impl std::ops::Add for Loads {
    type Output = Loads;

    fn add(self, o: Loads) -> Loads {
        Loads {
            main_bearing: self.main_bearing + o.main_bearing,
            crank_pin: self.crank_pin + o.crank_pin,
            piston_pin: self.piston_pin + o.piston_pin,
            piston_side: self.piston_side + o.piston_side,
            gear_mesh: self.gear_mesh + o.gear_mesh,
            crank_torque: self.crank_torque + o.crank_torque,
            torque_by_link: [0, 1, 2].map(|k| self.torque_by_link[k] + o.torque_by_link[k]),
            rod_percussion_centre: self.rod_percussion_centre,
        }
    }
}
