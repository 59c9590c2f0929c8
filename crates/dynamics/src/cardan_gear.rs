//! Closed-form kinetostatics of the cardan gear, Karhula (2008) eqs. (A5.2.1.40)-(A5.2.1.72),
//! extended with a force applied to the piston (the gas).
//!
//! The reciprocating assembly (piston, pin and rod, ch. 11.2) moves on the cylinder axis; its
//! inertial force plus the applied force, P, reaches the cardan wheel at T. The thesis takes
//! the ring gear's reaction on the wheel equal to P and parallel to the cylinder axis, so the
//! crank pin carries 2·P (A5.2.1.48-51); the wheel's moment balance about S then holds exactly,
//! because T + P_mesh − 2·S lies on the cylinder axis. There is no piston side force
//! (A5.2.1.50).
//!
//! Reading of (A5.2.1.43)-(A5.2.1.46): the thesis adds the wheel's inertial torque −J_2c·α_BAc
//! = +J_2c·α to the crankshaft with the opposite sign to the crankshaft's own −J_1c·α. The
//! wheel's kinetic energy ½·J_2c·ω² grows whenever the crankshaft speeds up, whichever way
//! the wheel spins, so that sign breaks the energy balance. We add the wheel's inertia to the
//! crankshaft's: the drive supplies (J_1c + J_2c)·α. For the thesis geometry the difference is
//! 2·J_2c·α = 0.13 N·m at α = 100π rad/s², 0.9 % of the mean inertial torque.

use crate::kinetostatics::cross;
use crate::{Loads, MassProperties};
use cardan_mechanism::{KinematicState, MechanismKind, C};

pub fn loads(state: &KinematicState, masses: &MassProperties, piston_force: f64) -> Loads {
    let m = masses.reciprocating_mass(MechanismKind::CardanGear);
    // P: what the reciprocating assembly pushes onto the wheel at T (A5.2.1.47-48).
    let p = -m * state.piston_pin.acceleration - C::new(0.0, piston_force);
    let crank_pin = 2.0 * p; // (A5.2.1.51)
    let alpha = state.crank.acceleration;
    let crankshaft = masses.crankshaft_inertia * alpha; // −T_1i10c (A5.2.1.40-41)
    let wheel = masses.wheel_inertia * alpha; // see the module note on (A5.2.1.43-46)
    let assembly = -cross(state.crank_pin.position, crank_pin); // −T_3i10c (A5.2.1.52)
    Loads {
        main_bearing: -crank_pin, // (A5.2.1.54)
        crank_pin,
        piston_pin: -p,   // (A5.2.1.49)
        piston_side: 0.0, // (A5.2.1.50)
        gear_mesh: p,
        crank_torque: crankshaft + wheel + assembly, // −T_Σi10c (A5.2.1.69)
        torque_by_link: [crankshaft, wheel, assembly],
        rod_percussion_centre: None,
    }
}
