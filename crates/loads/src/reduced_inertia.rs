//! The moment of inertia of a whole mechanism reduced to its crank, J*(θ), and its derivative
//! dJ*/dθ, from the state of any declared topology: no mechanism code.
//!
//! The kinetic energy of the bodies is T = Σ ½·m·|v_g|² + ½·J_g·ω_b² ([`crate::kinetic_energy`]).
//! Every velocity of a one-degree-of-freedom mechanism is its crank speed ω times a function of
//! the crank angle alone, v_g = u_g(θ)·ω and ω_b = k_b(θ)·ω, so that T = ½·J*(θ)·ω² with
//!
//! J*(θ) = Σ m·|u_g|² + J_g·k_b²,
//!
//! the reduced moment of inertia of Petrescu & Petrescu (2015) eq. (1) and section 7.3 of the
//! extraction (shared/notes/petrescu-2015-extraction.md; docs/validation/machine-motion.md).
//! The pistons' masses belong to the bodies that carry them, so they count once. At a state of
//! unit crank speed and no crank acceleration, u_g and k_b are the velocities themselves and
//! the accelerations are their derivatives du_g/dθ and dk_b/dθ (a = u'·ω² + u·α), whence
//!
//! dJ*/dθ = 2·Σ m·(u_g · u_g') + J_g·k_b·k_b'.
//!
//! The drive torque of the bodies' inertia is then J*·α + ½·dJ*/dθ·ω² (Petrescu eq. 5, the
//! Lagrange equation of a one-degree-of-freedom machine): tested against the inertial loads of
//! every registered mechanism (`crates/dynamics/tests/machine_motion.rs`).

use cardan_mechanism::{CrankState, Mechanism, State, StateBlock, Topology};

/// The reduced moment of inertia at one crank angle, and what the gas does per radian there.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct ReducedInertia {
    /// J*(θ), kg·m².
    pub inertia: f64,
    /// dJ*/dθ, kg·m²/rad.
    pub derivative: f64,
    /// Σ dx/dθ over the pistons, m/rad: a force F on every piston (towards the crankshaft)
    /// asks the drive for the torque F·Σ dx/dθ (the power balance F·v = T·ω).
    pub piston_lever: f64,
}

/// J*, dJ*/dθ and the pistons' lever of `topology` from `unit`, a state at crank speed 1 rad/s
/// and crank acceleration 0 (see the module's doc).
pub fn reduced_inertia(topology: &Topology, unit: &State) -> ReducedInertia {
    let mut r = ReducedInertia::default();
    for (b, m) in topology.bodies.iter().zip(&unit.bodies) {
        let (u, du) = (m.cg.velocity, m.cg.acceleration);
        r.inertia += b.mass * u.norm_sqr() + b.inertia * m.angular_velocity * m.angular_velocity;
        r.derivative += 2.0
            * (b.mass * (u.re * du.re + u.im * du.im)
                + b.inertia * m.angular_velocity * m.angular_acceleration);
    }
    r.piston_lever = unit.pistons.iter().map(|p| p.dx_dtheta).sum();
    r
}

/// The reduced inertia of one mechanism at any crank angle, with the scratch space that its
/// state takes kept from call to call (the solved motion asks four times a step).
#[derive(Debug, Clone)]
pub struct ReducedInertiaOf<'m> {
    mechanism: &'m dyn Mechanism,
    block: StateBlock,
    state: State,
}

impl<'m> ReducedInertiaOf<'m> {
    pub fn new(mechanism: &'m dyn Mechanism) -> Self {
        let t = mechanism.topology();
        Self {
            mechanism,
            block: StateBlock::for_topology(t),
            state: State::for_topology(t),
        }
    }

    /// J*, dJ*/dθ and the pistons' lever at crank angle `angle` (rad).
    pub fn at(&mut self, angle: f64) -> ReducedInertia {
        let crank = CrankState::new(angle, 1.0, 0.0, 0.0);
        self.block
            .fill(self.mechanism, std::slice::from_ref(&crank));
        self.block.gather(0, &mut self.state);
        reduced_inertia(self.mechanism.topology(), &self.state)
    }
}
