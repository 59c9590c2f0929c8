//! Energy of the moving bodies and the power balance that splits the drive torque among them.

use cardan_mechanism::{State, Topology};

/// Kinetic energy of all bodies, J: Σ ½·m·|v_g|² + ½·J·ω² (every body's translation of its
/// centre of gravity and rotation about it).
pub fn kinetic_energy(topology: &Topology, state: &State) -> f64 {
    topology
        .bodies
        .iter()
        .zip(&state.bodies)
        .map(|(b, m)| {
            0.5 * b.mass * m.cg.velocity.norm_sqr()
                + 0.5 * b.inertia * m.angular_velocity * m.angular_velocity
        })
        .sum()
}

/// Each body's share of the drive torque, N·m, by the power balance: the drive's power T·ω
/// pays for the rate of change of each body's kinetic energy, m·a_g·v_g + J·α·ω_b (if
/// `inertia`), and for the work done on the gas, F·v at each piston (F towards the crankshaft).
/// The shares add up to the drive torque of a frictionless mechanism (tested for every
/// mechanism); for the slider-crank they are Karhula's T_1i10, T_2i10, T_3i10 (A5.2.1.1,
/// A5.2.1.15, A5.2.1.23). NaN where the crank stands still.
pub fn torque_shares(
    topology: &Topology,
    state: &State,
    inertia: bool,
    piston_forces: &[f64],
    out: &mut [f64],
) {
    let w = state.crank.speed;
    for ((share, b), m) in out.iter_mut().zip(&topology.bodies).zip(&state.bodies) {
        *share = if inertia {
            let v = m.cg.velocity;
            let a = m.cg.acceleration;
            (b.mass * (a.re * v.re + a.im * v.im)
                + b.inertia * m.angular_acceleration * m.angular_velocity)
                / w
        } else {
            0.0
        };
    }
    for ((piston, motion), force) in topology
        .pistons
        .iter()
        .zip(&state.pistons)
        .zip(piston_forces)
    {
        out[piston.body] += force * motion.velocity / w;
    }
}
