//! Closed-form kinetostatics of the slider-crank, Karhula (2008) eqs. (A5.2.1.1)-(A5.2.1.39),
//! extended with a force applied to the piston (the gas) and a piston-pin offset.
//!
//! As in the thesis the loads are superposed: the rod's inertia with a massless piston, then
//! the piston's inertia (and the applied force) with a massless rod. All joints are frictionless.
//! The rod's centre of gravity must be the rod point of the kinematic state.

use crate::kinetostatics::cross;
use crate::{Loads, MassProperties};
use cardan_mechanism::{KinematicState, C};

pub fn loads(state: &KinematicState, masses: &MassProperties, piston_force: f64) -> Loads {
    let a_pin = state.crank_pin.position;
    let e_rod = state.rod.direction;
    let sin_rod = e_rod.im;
    let rod_length = (state.piston_pin.position - a_pin).norm();

    // Rod with a massless piston. Its inertial force −m2·a_g2 (A5.2.1.4) and inertial couple
    // −J2·α_BA (5.1.2) have the moment M_i about the crank pin; that moment is what places the
    // resultant at the centre of percussion L_i2 (A5.2.1.6-8): M_i = L_i2·|F|·sin(β_g2 + π − θ_BA).
    // The massless piston can only pass on a force across the cylinder, so the piston pin force
    // on the rod is horizontal, and moments about the crank pin give it (A5.2.1.9-10).
    let f_ine2 = -masses.rod_mass * state.rod.point.acceleration;
    let couple = -masses.rod_inertia * state.rod.angular_acceleration;
    let moment_about_crank_pin = cross(masses.rod_cg * e_rod, f_ine2) + couple;
    let f_piston_on_rod = C::new(moment_about_crank_pin / (rod_length * sin_rod), 0.0);
    let f_crank_on_rod_2 = -f_ine2 - f_piston_on_rod; // (A5.2.1.11)
    let arm = cross(e_rod, f_ine2);
    let rod_percussion_centre = (arm.abs() > 1e-12 * f_ine2.norm().max(f64::MIN_POSITIVE))
        .then(|| moment_about_crank_pin / arm);

    // Piston with a massless rod: the rod is a two-force member along its line (A5.2.1.17-22).
    let load = -masses.piston_mass * state.piston_pin.acceleration - C::new(0.0, piston_force);
    let f_rod_on_piston_3 = -load.im / sin_rod * e_rod;
    let side_3 = -(load.re + f_rod_on_piston_3.re); // (A5.2.1.20)

    let f_crank_on_rod = f_crank_on_rod_2 + f_rod_on_piston_3; // (A5.2.1.27)
    let crank_pin = -f_crank_on_rod; // (A5.2.1.28)
    let crankshaft = masses.crankshaft_inertia * state.crank.acceleration; // −T_ine1 (A5.2.1.1)
    let rod = -cross(a_pin, -f_crank_on_rod_2); // −T_2i10 (A5.2.1.15)
    let piston = -cross(a_pin, -f_rod_on_piston_3); // −T_3i10 (A5.2.1.23)
    Loads {
        main_bearing: f_crank_on_rod, // (A5.2.1.25): the crankshaft's centre of gravity is on its axis
        crank_pin,
        piston_pin: f_rod_on_piston_3 - f_piston_on_rod,
        piston_side: f_piston_on_rod.re + side_3,
        gear_mesh: C::new(0.0, 0.0),
        crank_torque: crankshaft + rod + piston, // −T_Σi10 (A5.2.1.36)
        torque_by_link: [crankshaft, rod, piston],
        rod_percussion_centre,
    }
}
