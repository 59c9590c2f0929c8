//! Load families: each puts a force (and couple) on every joint and a torque on the drive at
//! every step, as if it acted alone. Generic code sums them into the totals (Karhula A7.1: the
//! summed lossless dynamics are the sum of the inertial and gas loads) where every joint's
//! reaction is linear in the loads; where one is not (an involute mesh's loaded flank,
//! [`cardan_mechanism::Topology::superposable`]) the totals are solved from the families'
//! loads together, and a family's force on such a joint is its own, alone, which does not add
//! up to the total. The drive torque is linear in every mechanism: its families always add up.
//! A loss model later reads each joint's total load and relative speed and needs no mechanism
//! code.

use crate::planar;
use cardan_mechanism::{
    Column, JointKind, Loads, LoadsBlock, Mechanism, State, StateBlock, Topology, C,
};

/// Which path computes the loads.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Solver {
    /// The mechanism's closed forms, falling back to the general solve where it has none.
    #[default]
    ClosedForm,
    /// The general planar Newton-Euler solve of [`planar`], for any mechanism.
    General,
}

impl Solver {
    /// The loads of the bodies' inertia (if `inertia`) and of the force `piston_force` on every
    /// piston (none without one) at the steps of `block`.
    pub fn loads(
        self,
        mechanism: &dyn Mechanism,
        block: &StateBlock,
        inertia: bool,
        piston_force: Option<&Column>,
        out: &mut LoadsBlock,
    ) {
        if self == Solver::ClosedForm
            && mechanism.closed_form_block(block, inertia, piston_force, out)
        {
            return;
        }
        // The general solve works a state at a time.
        let t = mechanism.topology();
        let (mut state, mut loads) = (State::for_topology(t), Loads::for_topology(t));
        let mut forces = vec![0.0; piston_force.map_or(0, |_| t.pistons.len())];
        for i in 0..block.len {
            block.gather(i, &mut state);
            if let Some(f) = piston_force {
                forces.fill(f[i]);
            }
            planar::loads(t, &state, inertia, &forces, &mut loads);
            out.scatter(i, &loads);
        }
    }
}

/// A family of loads.
pub trait LoadFamily: Sync {
    /// Its name in outputs (`inertial`, `gas`).
    fn name(&self) -> &'static str;

    /// Whether it carries the bodies' inertia (for the torque shares).
    fn inertia(&self) -> bool;

    /// Whether it carries the piston forces.
    fn piston_forces(&self) -> bool;

    /// The path its loads are computed by; a mechanism whose joints do not superpose
    /// ([`cardan_mechanism::Topology::superposable`]) has its total loads solved by the first
    /// family's, from the families' inertia and piston forces together.
    fn solver(&self) -> Solver;

    /// Its loads at the steps of `block`, written to `out`. `piston_force` is the gas force on
    /// every piston at each step (N, towards the crankshaft; none without gas); `before` the sum
    /// of the loads of the families before it in the run (what a tooth-load or friction family
    /// acts on; zero for the first family).
    fn loads(
        &self,
        mechanism: &dyn Mechanism,
        block: &StateBlock,
        piston_force: Option<&Column>,
        before: &LoadsBlock,
        out: &mut LoadsBlock,
    );

    /// Adds to `out` the loads this family puts on the joints from outside the mechanism's
    /// topology (the crankshaft's extra masses of [`Inertial`]), which superpose on any joint
    /// and so are added again to a total solved from the families together; its
    /// [`LoadFamily::loads`] includes them.
    fn add_carried(&self, _topology: &Topology, _block: &StateBlock, _out: &mut LoadsBlock) {}
}

/// The loads of the bodies' inertia (d'Alembert), with no force on the pistons (Karhula A5.2.1),
/// and of the masses the crankshaft carries outside the mechanism's bodies.
#[derive(Debug, Clone, Copy, Default)]
pub struct Inertial {
    pub solver: Solver,
    /// Σ m·ρ of the masses the crankshaft carries besides the mechanism's bodies (its own
    /// unbalance, its counterweight: `cardan_balance::PreparedBalance::crank_masses`), kg·m,
    /// complex: towards where they are at θ = 0; 0 for a balanced crankshaft, as Karhula's.
    pub crank_masses: C,
}

impl Inertial {
    /// The bodies' inertia through `solver`, on a balanced crankshaft.
    pub fn new(solver: Solver) -> Self {
        Self {
            solver,
            crank_masses: C::new(0.0, 0.0),
        }
    }

    /// The same with the crankshaft carrying `mass_radius` (kg·m) besides the mechanism's
    /// bodies ([`Inertial::crank_masses`]).
    pub fn carrying(self, mass_radius: C) -> Self {
        Self {
            crank_masses: mass_radius,
            ..self
        }
    }
}

/// The crankshaft's pin on the frame: the main bearing (which the crank's carried masses load
/// and the machine's journals take, `machine.rs`).
pub fn main_bearing(t: &Topology) -> Option<usize> {
    t.joints.iter().position(|j| {
        j.body == t.crankshaft && j.other.is_none() && matches!(j.kind, JointKind::Revolute(_))
    })
}

/// Adds to the main bearing's reaction (the crankshaft's pin on the frame) the m·a of masses
/// `u` (kg·m, complex, towards where they are at θ = 0) turning with the crank about the main
/// axis, at the steps of `block`. A mass m at ρ·e^{i(θ+γ)} has m·a = u·(iα − ω²)·e^{iθ} with
/// u = m·ρ·e^{iγ} (the rotor's shaking force −m·a, `cardan_balance::Rotor::force`, with the
/// sign turned): the frame's reaction supplies it, and no other joint sees it, because the
/// masses ride on the crankshaft alone, whose only other joints carry what the mechanism's
/// bodies do. Their torque m·ρ²·α needs their polar moment, which a mass·radius does not give:
/// it belongs to the crankshaft's inertia (`[masses] crank_inertia`), and the drive torque
/// is left as it is.
fn add_crank_masses(topology: &Topology, u: C, block: &StateBlock, out: &mut LoadsBlock) {
    if u == C::new(0.0, 0.0) {
        return;
    }
    let Some(main) = main_bearing(topology) else {
        return;
    };
    let c = &block.crank;
    let joint = &mut out.joints[main];
    for i in 0..block.len {
        let (w2, a) = (c.speed[i] * c.speed[i], c.acceleration[i]);
        let z = u * C::new(-w2, a) * C::new(c.cos[i], c.sin[i]);
        joint.fx[i] += z.re;
        joint.fy[i] += z.im;
    }
}

impl LoadFamily for Inertial {
    fn name(&self) -> &'static str {
        "inertial"
    }

    fn inertia(&self) -> bool {
        true
    }

    fn piston_forces(&self) -> bool {
        false
    }

    fn solver(&self) -> Solver {
        self.solver
    }

    fn loads(
        &self,
        mechanism: &dyn Mechanism,
        block: &StateBlock,
        _: Option<&Column>,
        _: &LoadsBlock,
        out: &mut LoadsBlock,
    ) {
        self.solver.loads(mechanism, block, true, None, out);
        self.add_carried(mechanism.topology(), block, out);
    }

    fn add_carried(&self, topology: &Topology, block: &StateBlock, out: &mut LoadsBlock) {
        add_crank_masses(topology, self.crank_masses, block, out);
    }
}

/// The loads of the gas force on the pistons in massless links (Karhula A6.2.1).
#[derive(Debug, Clone, Copy, Default)]
pub struct Gas(pub Solver);

impl LoadFamily for Gas {
    fn name(&self) -> &'static str {
        "gas"
    }

    fn inertia(&self) -> bool {
        false
    }

    fn piston_forces(&self) -> bool {
        true
    }

    fn solver(&self) -> Solver {
        self.0
    }

    fn loads(
        &self,
        mechanism: &dyn Mechanism,
        block: &StateBlock,
        force: Option<&Column>,
        _: &LoadsBlock,
        out: &mut LoadsBlock,
    ) {
        self.0.loads(mechanism, block, false, force, out);
    }
}
