//! What a search is told ([`Settings`]), what it records of each evaluation ([`Record`]) and
//! why a start stops ([`Stop`]): below the search (`search.rs`) and the crate's root.

use crate::order::Outcome;

/// How the search runs.
#[derive(Debug, Clone, PartialEq)]
pub struct Settings {
    /// Starts of the Latin hypercube (at least 1).
    pub starts: usize,
    /// The seed of the starts' design.
    pub seed: u64,
    /// Evaluations a start may spend at most.
    pub max_evaluations: usize,
    /// The compass search's last step, as a fraction of each variable's range: the optimum is
    /// located to within it.
    pub tolerance: f64,
    /// The simplex's size (∞-norm, fraction of the ranges) at which the compass search takes
    /// over.
    pub simplex_tolerance: f64,
    /// The initial simplex's edge, fraction of the ranges.
    pub initial_step: f64,
    /// The compass search's first step, fraction of the ranges.
    pub compass_step: f64,
}

impl Default for Settings {
    fn default() -> Self {
        Self {
            starts: 4,
            seed: 1,
            max_evaluations: 200,
            tolerance: 1e-4,
            simplex_tolerance: 1e-3,
            initial_step: 0.1,
            compass_step: 0.02,
        }
    }
}

/// Why a start stopped.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Stop {
    /// The compass step fell below the tolerance: no step of that size along any variable
    /// improves on the point (`step` is the last step, fraction of the ranges).
    Converged { step: f64 },
    /// The start spent its evaluations.
    Budget,
}

impl Stop {
    pub fn describe(&self, settings: &Settings) -> String {
        match self {
            Stop::Converged { .. } => format!(
                "converged: no step of {:e} of any variable's range improves the point (compass search)",
                settings.tolerance
            ),
            Stop::Budget => format!(
                "evaluation budget spent ({} evaluations) before converging",
                settings.max_evaluations
            ),
        }
    }
}

/// One evaluation: its start, its number within the start (from 0), its point in the unit
/// cube, its outcome, and the phase that asked for it ("simplex" or "compass").
#[derive(Debug, Clone, PartialEq)]
pub struct Record {
    pub start: usize,
    pub evaluation: usize,
    pub x: Vec<f64>,
    pub outcome: Outcome,
    pub phase: &'static str,
}
