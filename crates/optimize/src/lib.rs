//! A bounded derivative-free optimiser for objectives that are costly, noisy in their last
//! digits and may fail at some points (a whole machine run per evaluation): it knows nothing
//! of cases, mechanisms or units. The variables live in the unit cube [0, 1]ⁿ (the caller maps
//! them to its ranges); the objective is minimised (negate it to maximise); each constraint is
//! a margin, ≥ 0 where it holds, scaled by the caller.
//!
//! The method ([`minimise`]):
//! - starts: [`Settings::starts`] points of a Latin hypercube (`design.rs`) from
//!   [`Settings::seed`], run in parallel (rayon), each start's search sequential, so the result
//!   is the same whatever the threads;
//! - each start: Nelder-Mead (Lagarias et al. 1998) with trial points projected onto the bounds,
//!   down to a simplex of [`Settings::simplex_tolerance`], then a compass search (Kolda, Lewis &
//!   Torczon 2003, §3.1) from its best point down to a step of [`Settings::tolerance`]
//!   (`search.rs`);
//! - constraints and failures: Deb's (2000) feasibility rules (`order.rs`): feasible beats
//!   infeasible, feasible points by objective, infeasible ones by total violation, a failed
//!   evaluation below all. No penalty weight to tune;
//! - stopping: a start stops when its compass step falls below the tolerance (converged) or
//!   after [`Settings::max_evaluations`] evaluations (budget); the result is the best of the
//!   starts' best points by Deb's rules, the earlier start on a tie.
//!
//! Why not a crate: argmin's Nelder-Mead has no bounds and no constraints, and adds a
//! framework (its executor, observers, serde) for a hundred lines; the textbook methods are
//! short, cited, and tested here on problems with known optima.

mod design;
mod order;
mod search;
mod settings;

pub use design::{latin_hypercube, SplitMix64};
pub use order::Outcome;
use rayon::prelude::*;
pub use settings::{Record, Settings, Stop};

/// One start's search: where it started, its best record, its evaluations and why it stopped.
#[derive(Debug, Clone, PartialEq)]
pub struct StartResult {
    pub x0: Vec<f64>,
    pub best: Option<Record>,
    pub records: Vec<Record>,
    pub stop: Stop,
}

/// What [`minimise`] found.
#[derive(Debug, Clone, PartialEq)]
pub struct Optimum {
    /// The best record of all starts (Deb's rules), `None` only if nothing was evaluated.
    pub best: Option<Record>,
    /// The start it came from.
    pub best_start: usize,
    pub starts: Vec<StartResult>,
}

impl Optimum {
    /// Every evaluation, start after start, each start's in order.
    pub fn history(&self) -> impl Iterator<Item = &Record> {
        self.starts.iter().flat_map(|s| s.records.iter())
    }

    /// Evaluations in all.
    pub fn evaluations(&self) -> usize {
        self.starts.iter().map(|s| s.records.len()).sum()
    }

    /// Whether the best point satisfies every constraint.
    pub fn feasible(&self) -> bool {
        self.best.as_ref().is_some_and(|b| b.outcome.feasible())
    }

    /// The failed evaluations.
    pub fn failures(&self) -> impl Iterator<Item = &Record> {
        self.history()
            .filter(|r| matches!(r.outcome, Outcome::Failed(_)))
    }
}

fn best_of<'a>(records: impl Iterator<Item = &'a Record>) -> Option<&'a Record> {
    records.fold(None, |best: Option<&Record>, r| match best {
        Some(b) if !r.outcome.better_than(&b.outcome) => Some(b),
        _ => Some(r),
    })
}

/// Minimises `f` over [0, 1]^`dimension` (module docs). `f` is called from several threads at
/// once (one per start running).
pub fn minimise(
    dimension: usize,
    settings: &Settings,
    f: &(dyn Fn(&[f64]) -> Outcome + Sync),
) -> Optimum {
    let starts = latin_hypercube(settings.starts.max(1), dimension, settings.seed);
    let results: Vec<StartResult> = starts
        .into_par_iter()
        .enumerate()
        .map(|(k, x0)| {
            let mut tracker = search::Tracker::new(f, k, settings.max_evaluations);
            let stop = search::run_start(&mut tracker, &x0, settings);
            let records = tracker.records;
            StartResult {
                best: best_of(records.iter()).cloned(),
                x0,
                records,
                stop,
            }
        })
        .collect();
    let best_start = results
        .iter()
        .enumerate()
        .filter_map(|(k, s)| s.best.as_ref().map(|b| (k, b)))
        .fold(None, |best: Option<(usize, &Record)>, (k, r)| match best {
            Some(b) if !r.outcome.better_than(&b.1.outcome) => Some(b),
            _ => Some((k, r)),
        });
    Optimum {
        best: best_start.map(|(_, r)| r.clone()),
        best_start: best_start.map_or(0, |(k, _)| k),
        starts: results,
    }
}
