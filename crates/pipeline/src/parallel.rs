//! One run shared by the threads of the rayon pool, so that a single long case fills every
//! core: a prescribed motion is split into the chunks of its summary ([`summary_chunk`]: an
//! even number of near-equal pieces, none longer than [`MAX_CHUNK`] steps), each chunk is run
//! into sinks of its own, and the sinks are joined in the chunks' order. The summary adds its
//! integrals chunk by chunk in any run, so the result is the one [`run`] gives, bit for bit,
//! whatever the number of threads (tested in `tests/parallel.rs`). [`run_summary`] is the whole
//! pipeline in one call.

use crate::rooms::RunRooms;
use crate::stage::Stage;
use crate::step::{Sink, StepBlock, StepRecord, Steps};
use crate::stepper::{run, GasAt, RunError};
use crate::summary::{summary_chunk, SummarySink, MAX_CHUNK};
use cardan_loads::family::{Gas, Inertial, LoadFamily, Solver};
use cardan_mechanism::{Mechanism, MotionSource};
use cardan_metrics::Summary;
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
/// cannot be split ([`MotionSource::part`]: a solved one) or a stage whose steps depend on the
/// ones before ([`Stage::carries_history`]) runs on the calling thread alone. Each piece
/// evaluates [forks](Stage::fork) of the `stages`. A failure is the one [`run`] reports: the
/// first failing step's.
pub fn run_parallel(
    mechanism: &dyn Mechanism,
    motion: &mut dyn MotionSource,
    families: &[&dyn LoadFamily],
    gas: Option<GasAt>,
    stages: &mut [&mut dyn Stage],
    sink: &mut impl Joinable,
) -> Result<(), RunError> {
    RunRooms::default().run_parallel(mechanism, motion, families, gas, stages, sink)
}

impl RunRooms {
    /// [`run_parallel`], a run on the calling thread alone and each piece of a shared one in
    /// a room of these ([`RunRooms::run`]).
    pub fn run_parallel(
        &self,
        mechanism: &dyn Mechanism,
        motion: &mut dyn MotionSource,
        families: &[&dyn LoadFamily],
        gas: Option<GasAt>,
        stages: &mut [&mut dyn Stage],
        sink: &mut impl Joinable,
    ) -> Result<(), RunError> {
        let first = motion.first_index();
        let count = motion.len();
        let chunk = summary_chunk(first + count);
        let splittable = count > MAX_CHUNK + 1
            && first % chunk == 0
            && !stages.iter().any(|s| s.carries_history())
            && motion.part(first, first).is_some();
        if !splittable {
            return self.run(mechanism, motion, families, gas, stages, &mut [sink]);
        }
        let stages: &[&mut dyn Stage] = stages;
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
            // The pieces take rooms one after another (`RunRooms`).
            let pieces: Vec<Result<_, RunError>> = parts
                .into_par_iter()
                .map(|mut part| {
                    let mut piece = template.clone();
                    let mut forks: Vec<Box<dyn Stage>> = stages.iter().map(|s| s.fork()).collect();
                    let mut forked: Vec<&mut dyn Stage> = forks
                        .iter_mut()
                        .map(|s| &mut **s as &mut dyn Stage)
                        .collect();
                    self.run(
                        mechanism,
                        part.as_mut(),
                        families,
                        gas,
                        &mut forked,
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
}

/// Runs `mechanism` through `motion` with the inertial loads (and the gas loads, if `gas` is
/// given), both by `solver`, and returns every step (if `keep_steps`) with the summary: the
/// whole pipeline in one call, for tests and small studies. Without the steps, the run is
/// shared by the threads of the rayon pool ([`run_parallel`]).
pub fn run_summary(
    mechanism: &dyn Mechanism,
    motion: &mut dyn MotionSource,
    gas: Option<GasAt>,
    solver: Solver,
    keep_steps: bool,
) -> Result<(Vec<StepRecord>, Summary), String> {
    let inertial = Inertial::new(solver);
    let gas_family = Gas(solver);
    let mut families: Vec<&dyn LoadFamily> = vec![&inertial];
    if gas.is_some() {
        families.push(&gas_family);
    }
    let names: Vec<&'static str> = families.iter().map(|f| f.name()).collect();
    let points = motion.first_index() + motion.len();
    let mut summary = SummarySink::new(mechanism, &names, points);
    let mut steps = Steps::default();
    if keep_steps {
        run(
            mechanism,
            motion,
            &families,
            gas,
            &mut [],
            &mut [&mut summary, &mut steps],
        )
    } else {
        run_parallel(mechanism, motion, &families, gas, &mut [], &mut summary)
    }
    .map_err(|e| e.to_string())?;
    Ok((steps.0, summary.finish(mechanism)?))
}
