//! One run shared by the threads of the rayon pool, so that a single long case fills every
//! core: a prescribed motion is split into the chunks of its summary ([`summary_chunk`]: an
//! even number of near-equal pieces, none longer than [`MAX_CHUNK`] steps), each chunk is run
//! into sinks of its own, and the sinks are joined in the chunks' order. The summary adds its
//! integrals chunk by chunk in any run, so the result is the one [`run`] gives, bit for bit,
//! whatever the number of threads (tested in `tests/parallel.rs`).

use crate::family::LoadFamily;
use crate::losses::LossBudget;
use crate::stepper::{run, GasAt, RunError, Sink, Stages, StepBlock};
use crate::summary::{summary_chunk, SummarySink, MAX_CHUNK};
use cardan_mechanism::{Mechanism, MotionSource};
use rayon::prelude::*;

/// A sink whose steps several threads may take in pieces, each piece into a sink of its own,
/// the pieces' sinks then joined in the steps' order.
pub trait Joinable: Sink + Clone + Send + Sync {
    /// A sink for a piece of the run, made from this one before it takes any step.
    fn fork(&self) -> Self {
        self.clone()
    }

    /// Continues this sink with `later`, a [`Joinable::fork`] that took the steps from the
    /// last one this sink took (a chunk's start, taken by both) on.
    fn join(&mut self, later: Self);
}

impl Joinable for SummarySink {
    fn join(&mut self, later: Self) {
        self.merge(&later);
    }
}

impl<A: Sink, B: Sink> Sink for (A, B) {
    fn push_block(&mut self, block: &StepBlock) -> Result<(), (usize, String)> {
        self.0.push_block(block)?;
        self.1.push_block(block)
    }

    fn wants_steps(&self) -> bool {
        self.0.wants_steps() || self.1.wants_steps()
    }

    fn wants_details(&self) -> bool {
        self.0.wants_details() || self.1.wants_details()
    }
}

impl<S: Sink> Sink for Option<S> {
    fn push_block(&mut self, block: &StepBlock) -> Result<(), (usize, String)> {
        self.as_mut().map_or(Ok(()), |s| s.push_block(block))
    }

    fn wants_steps(&self) -> bool {
        self.as_ref().is_some_and(Sink::wants_steps)
    }

    fn wants_details(&self) -> bool {
        self.as_ref().is_some_and(Sink::wants_details)
    }
}

impl<S: Joinable> Joinable for Option<S> {
    fn fork(&self) -> Self {
        self.as_ref().map(Joinable::fork)
    }

    fn join(&mut self, later: Self) {
        if let (Some(a), Some(b)) = (self, later) {
            a.join(b);
        }
    }
}

impl<A: Joinable, B: Joinable> Joinable for (A, B) {
    fn fork(&self) -> Self {
        (self.0.fork(), self.1.fork())
    }

    fn join(&mut self, later: Self) {
        self.0.join(later.0);
        self.1.join(later.1);
    }
}

/// Pieces run at a time before their sinks are joined: bounds the memory held (a few kilobytes
/// a piece's summary, the charted columns of a piece's chart rows) whatever the run's length,
/// and gives each thread several pieces (measured: larger waves were no faster with two trains
/// of a case sharing the pool).
const WAVE: usize = 8;

/// Runs as [`run`] does with `sink` (no step taken yet) as the only sink, the steps shared by
/// the threads of the current rayon pool. A run of at most [`MAX_CHUNK`] steps (not worth the
/// threads' start: a sweep's short cases share the pool case by case), a motion that
/// cannot be split ([`MotionSource::part`]: a solved one) or a loss budget whose steps depend
/// on the ones before ([`LossBudget::carries_history`]) runs on the calling thread alone. A
/// failure is the one [`run`] reports: the first failing step's.
pub fn run_parallel(
    mechanism: &dyn Mechanism,
    motion: &mut dyn MotionSource,
    families: &[&dyn LoadFamily],
    gas: Option<GasAt>,
    stages: Stages,
    sink: &mut impl Joinable,
) -> Result<(), RunError> {
    let first = motion.first_index();
    let count = motion.len();
    let chunk = summary_chunk(first + count);
    let splittable = count > MAX_CHUNK + 1
        && first % chunk == 0
        && !stages
            .losses
            .as_deref()
            .is_some_and(LossBudget::carries_history)
        && motion.part(first, first).is_some();
    if !splittable {
        return run(mechanism, motion, families, gas, stages, &mut [sink]);
    }
    let Stages { losses, gears } = stages;
    let losses = losses.as_deref();
    let template = sink.fork();
    let last = first + count - 1;
    // Chunk k takes the steps from its start to the next chunk's start: the interval that
    // ends a chunk is the chunk's (its last step is taken twice; a peak does not mind).
    let starts: Vec<usize> = (first..last).step_by(chunk).collect();
    for wave in starts.chunks(WAVE) {
        let parts: Vec<_> = wave
            .iter()
            .map(|&s| {
                motion
                    .part(s, (s + chunk).min(last))
                    .expect("a splittable motion splits at every chunk start")
            })
            .collect();
        let pieces: Vec<Result<_, RunError>> = parts
            .into_par_iter()
            .map(|mut part| {
                let mut piece = template.clone();
                let mut budget = losses.cloned();
                let stages = Stages {
                    losses: budget.as_mut(),
                    gears,
                };
                run(
                    mechanism,
                    part.as_mut(),
                    families,
                    gas,
                    stages,
                    &mut [&mut piece],
                )?;
                Ok(piece)
            })
            .collect();
        for piece in pieces {
            sink.join(piece?);
        }
    }
    Ok(())
}
