//! The shaking force of one mechanism at one step: what its moving masses exert on the frame.
//!
//! d'Alembert: the moving system's bodies obey Σ F_ext = Σ m_i·a_i (a_i the acceleration of
//! body i's centre of gravity) and, about the crank axis O, Σ M_ext,O = Σ (z_i × m_i·a_i +
//! J_i·α_i) (Beer & Johnston, the Newton-Euler equations Karhula 2008 ch. 5 cites; written out
//! in `docs/validation/balance.md`). Without gas (the gas pushes the piston and the cylinder
//! head alike, a force inside the frame) and without gravity, the only external loads are the
//! frame's joint reactions and the drive torque, so the frame receives
//!
//! - the **shaking force** F_s = −Σ m_i·a_i, the inertia forces passed on to it (the
//!   theory-of-machines texts' "unbalanced force or shaking force", the resultant on the engine
//!   body of the inertia forces alone; `docs/validation/balance.md`), and
//! - about the crank axis the **roll moment** M_s = −Σ (z_i × m_i·a_i + J_i·α_i), the frame's
//!   share of the inertia couples including the drive's reaction (a motor on the frame).
//!
//! Every body of the [`Topology`] counts with its mass, centre of gravity and acceleration: a
//! [`cardan_mechanism::Piston`] carries no mass of its own (its mass is its body's, e.g. the rod
//! that carries the piston), so pistons add nothing here. Bodies whose mass the mechanism folds
//! elsewhere (mass 0, such as a balanced crankshaft) add nothing either; their real unbalance is
//! given explicitly as rotors ([`crate::Rotor`]).

use cardan_mechanism::{cross, Body, State, StateBlock, Topology, C};

/// The inertia loads one mechanism's moving masses put on the frame at one step, in the
/// mechanism's own plane frame (origin on the crank axis, the cylinder along +y).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Shaking {
    /// Shaking force F_s = −Σ m_i·a_i on the frame, N (x, y as re, im).
    pub force: C,
    /// Moment on the frame about the crank axis, −Σ (z_i × m_i·a_i + J_i·α_i), N·m,
    /// counter-clockwise positive (the roll reaction; not part of the free moments of a
    /// machine, [`crate::MachineShaking`]).
    pub roll: f64,
}

impl std::ops::Add for Shaking {
    type Output = Shaking;
    fn add(self, other: Shaking) -> Shaking {
        Shaking {
            force: self.force + other.force,
            roll: self.roll + other.roll,
        }
    }
}

/// The shaking force and roll moment of the bodies of `topology` in `state` (module note).
pub fn shaking(topology: &Topology, state: &State) -> Shaking {
    let mut out = Shaking::default();
    for (body, motion) in topology.bodies.iter().zip(&state.bodies) {
        let cg = &motion.cg;
        add_body(
            &mut out,
            body,
            cg.position,
            cg.acceleration,
            motion.angular_acceleration,
        );
    }
    out
}

/// [`shaking`] at lane `i` of `block`, read from its columns: the same operations in the same
/// order (the same bits), without gathering the lane's whole state.
#[inline]
pub fn shaking_lane(topology: &Topology, block: &StateBlock, i: usize) -> Shaking {
    let mut out = Shaking::default();
    for (body, c) in topology.bodies.iter().zip(&block.bodies) {
        let cg = &c.cg;
        add_body(
            &mut out,
            body,
            C::new(cg.x[i], cg.y[i]),
            C::new(cg.ax[i], cg.ay[i]),
            c.angular_acceleration[i],
        );
    }
    out
}

/// Adds one body's inertia force −m·a and its moment about the crank axis, z × (−m·a) − J·α,
/// to `out` (module note).
#[inline(always)]
fn add_body(
    out: &mut Shaking,
    body: &Body,
    position: C,
    acceleration: C,
    angular_acceleration: f64,
) {
    let inertia_force = -body.mass * acceleration;
    out.force += inertia_force;
    out.roll += cross(position, inertia_force) - body.inertia * angular_acceleration;
}
