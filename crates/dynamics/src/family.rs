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
use cardan_mechanism::{Column, Loads, LoadsBlock, Mechanism, State, StateBlock};

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
}

/// The loads of the bodies' inertia (d'Alembert), with no force on the pistons (Karhula A5.2.1).
#[derive(Debug, Clone, Copy, Default)]
pub struct Inertial(pub Solver);

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
        self.0
    }

    fn loads(
        &self,
        mechanism: &dyn Mechanism,
        block: &StateBlock,
        _: Option<&Column>,
        _: &LoadsBlock,
        out: &mut LoadsBlock,
    ) {
        self.0.loads(mechanism, block, true, None, out);
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
