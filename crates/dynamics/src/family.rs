//! Load families: each puts a force (and couple) on every joint and a torque on the drive at
//! every step. Generic code sums them into the totals (Karhula A7.1: the summed lossless
//! dynamics are the sum of the inertial and gas loads); a loss model later reads each joint's
//! total load and relative speed and needs no mechanism code.

use crate::planar;
use cardan_mechanism::{Loads, Mechanism, State};

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
    /// The loads of the bodies' inertia (if `inertia`) and of `piston_forces` at `state`.
    pub fn loads(
        self,
        mechanism: &dyn Mechanism,
        state: &State,
        inertia: bool,
        piston_forces: &[f64],
        out: &mut Loads,
    ) {
        if self == Solver::ClosedForm
            && mechanism.closed_form_loads(state, inertia, piston_forces, out)
        {
            return;
        }
        planar::loads(mechanism.topology(), state, inertia, piston_forces, out);
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

    /// Its loads at `state`, written to `out`. `piston_forces` is the gas force on each piston
    /// (N, towards the crankshaft); `before` the sum of the loads of the families before it in
    /// the run (what a tooth-load or friction family acts on; zero for the first family).
    fn loads(
        &self,
        mechanism: &dyn Mechanism,
        state: &State,
        piston_forces: &[f64],
        before: &Loads,
        out: &mut Loads,
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

    fn loads(
        &self,
        mechanism: &dyn Mechanism,
        state: &State,
        _: &[f64],
        _: &Loads,
        out: &mut Loads,
    ) {
        self.0.loads(mechanism, state, true, &[], out);
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

    fn loads(
        &self,
        mechanism: &dyn Mechanism,
        state: &State,
        forces: &[f64],
        _: &Loads,
        out: &mut Loads,
    ) {
        self.0.loads(mechanism, state, false, forces, out);
    }
}
