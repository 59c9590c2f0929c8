//! The tangential tooth load of the cardan mesh, by hand: at constant speed the rod force is
//! P_y = m·2r_c·ω²·sin θ (the reciprocating mass's inertia) and its tangential component at the
//! pitch point is P_y·cos θ, largest at 45°: m·r_c·ω². Both mesh readings give it (α = 0, so
//! the wheel's own inertia adds nothing); the ring force of the thesis reading is P itself,
//! twice as large at its peak.

mod common;
use cardan_mechanism::Material;
use cardan_testing::within;
use common::*;
use std::f64::consts::PI;

#[test]
fn tangential_tooth_load_by_hand() {
    let w = 200.0 * PI;
    let r_c = GEOMETRY.crank_length / 2.0;
    // The reciprocating mass: the rod of the default rule and the piston with pin (common.rs).
    let reciprocating =
        |mech: &dyn cardan_mechanism::Mechanism| mech.masses().rod_mass + mech.masses().piston_mass;
    for options in [&[][..], &[("gear_mesh_model", "involute")][..]] {
        let mech = machine_with("cardan_gear", &GEOMETRY, Material::Steel, options);
        let m = reciprocating(mech.as_ref());
        let (_, s) = cycle(mech.as_ref(), w, 0.0, 7200);
        // The 0.1° grid includes 45° + k·90°: the peak is sampled exactly.
        within(
            "tangential",
            s.get("inertial_gear_mesh_tangential_max").unwrap(),
            m * r_c * w * w,
            1e-9,
        );
    }
    let mech = thesis("cardan_gear", Material::Steel);
    let m = reciprocating(mech.as_ref());
    let (_, s) = cycle(mech.as_ref(), w, 0.0, 7200);
    within(
        "ring force",
        s.get("inertial_gear_mesh_force_max").unwrap(),
        2.0 * m * r_c * w * w,
        1e-9,
    );
}
