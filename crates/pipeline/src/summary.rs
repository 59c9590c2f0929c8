//! The cycle summary, accumulated block by block in O(1) memory: [`SummarySink`] composes
//! accumulators, each with its push (the lanes of a block), its merge (with a later piece of a
//! run shared by threads, [`crate::Joinable`]) and its finish (its metrics into the
//! [`Summary`]): the motion's, joints' and gas's peaks (`summary/peaks.rs`), each family's
//! drive work (`summary/work.rs`), the lever (`summary/lever.rs`), the ends and the energy
//! check (`summary/energy.rs`), and the totals of each per-step stage ([`crate::StageTotals`]).
//! Their integrals are summed chunk by chunk (`summary/integral.rs`). Metric names and units
//! come from [`cardan_metrics`].

mod energy;
mod integral;
mod lever;
pub mod peaks;
mod work;

pub use integral::{add_trapezoids, Integral};

use crate::stage::{RunTotals, Stage, StageTotals};
use crate::step::{Sink, StepBlock};
use cardan_mechanism::vectorised;
use cardan_mechanism::{Mechanism, Topology};
use cardan_metrics::{self as metrics, MetricDef, Summary};
use energy::Ends;
use lever::Lever;
use peaks::{GasPeaks, JointKinds, JointPeaks, MotionPeaks};
use std::ops::Range;
use work::DriveWork;

/// The most steps in a chunk of [`summary_chunk`].
pub const MAX_CHUNK: usize = 4096;

/// Steps whose integral terms a summary adds up apart before adding their sum to the run's,
/// in a run of `points` states: the pieces a run is shared in among threads
/// ([`crate::run_parallel`]), each piece whole chunks, whose sums are added in the chunks'
/// order. Within a chunk the order of the terms is a function of their steps' indices alone
/// (four running sums by index mod 4), so a summary is the same bit for bit however the run
/// is shared (tested). A function of the run's length alone, not of the threads, so that a
/// run on one thread and a shared one agree: an even number of near-equal chunks, so that two
/// cores share a run evenly, of whole grid blocks ([`cardan_mechanism::REANCHOR`], where a
/// grid can be split), none longer than [`MAX_CHUNK`] (bounding what a piece holds).
pub fn summary_chunk(points: usize) -> usize {
    const BLOCK: usize = cardan_mechanism::REANCHOR;
    let blocks = points.saturating_sub(1).div_ceil(BLOCK).max(1);
    let chunks = blocks.div_ceil(MAX_CHUNK / BLOCK).next_multiple_of(2);
    blocks.div_ceil(chunks) * BLOCK
}

/// One load family's accumulators (the total's, after the families, with several).
#[derive(Debug, Clone)]
struct Family {
    name: &'static str,
    peaks: JointPeaks,
    drive: DriveWork,
}

/// A stage's accumulator, with the metrics its stage defines.
#[derive(Debug, Clone)]
struct StageSlot {
    /// The stage's index in the run (of its values in [`crate::Step::stages`]).
    index: usize,
    metrics: &'static [MetricDef],
    totals: Box<dyn StageTotals>,
}

/// A sink that accumulates the summary of one mechanism's run.
#[derive(Debug, Clone)]
pub struct SummarySink {
    topology: Topology,
    kinds: JointKinds,
    motion: MotionPeaks,
    /// Each family, then the total if there is more than one family.
    families: Vec<Family>,
    lever: Lever,
    ends: Ends,
    gas: GasPeaks,
    stages: Vec<StageSlot>,
    /// The previous step's angle, speed and time (`None` before the first).
    previous: Option<(f64, f64, f64)>,
    /// Steps of the chunks of its integrals ([`summary_chunk`]).
    chunk: usize,
    /// Whether [`SummarySink::finish`] enforces the energy balance (all but a run kept for its
    /// peaks alone).
    energy_check: bool,
}

impl SummarySink {
    /// A summary of `mechanism` under the load families named `families` (in the run's order),
    /// over a run of `points` steps (numbered from 0: the motion's first index plus its
    /// length), which set its chunks ([`summary_chunk`]) as [`crate::run_parallel`] sets its
    /// pieces.
    pub fn new(mechanism: &dyn Mechanism, families: &[&'static str], points: usize) -> Self {
        let topology = mechanism.topology().clone();
        let joints = topology.joints.len();
        let total = (families.len() > 1).then_some("total");
        let families = families.iter().copied().chain(total);
        Self {
            kinds: JointKinds::new(&topology),
            motion: MotionPeaks::new(&topology),
            families: families
                .map(|name| Family {
                    name,
                    peaks: JointPeaks::new(joints),
                    drive: DriveWork::default(),
                })
                .collect(),
            lever: Lever::default(),
            ends: Ends::new(&topology, points),
            gas: GasPeaks::default(),
            stages: Vec::new(),
            previous: None,
            chunk: summary_chunk(points),
            energy_check: true,
            topology,
        }
    }

    /// The same summary, without enforcing the energy balance at its end: for a run kept for
    /// its peaks alone (the runner's sampling check, whose shifted grids do not span whole
    /// cycles and may be too coarse for the quadrature of the works).
    pub fn for_peaks(mut self) -> Self {
        self.energy_check = false;
        self
    }

    /// The same summary, with the totals of the run's `stages` (in the run's order), whose
    /// metrics it holds in the registry's order ([`metrics::METRICS`]).
    pub fn with_stages(mut self, stages: &[&dyn Stage]) -> Self {
        self.stages
            .extend(stages.iter().enumerate().map(|(index, s)| StageSlot {
                index,
                metrics: s.metrics(),
                totals: s.totals(),
            }));
        let registered = |s: &StageSlot| {
            let first = s.metrics.first().map(|d| d.name);
            metrics::METRICS.iter().position(|d| Some(d.name) == first)
        };
        self.stages
            .sort_by_key(|s| registered(s).unwrap_or(usize::MAX));
        self
    }

    /// Closes the chunk of every integral (at each step whose index is a multiple of
    /// its chunk, after its interval was added).
    fn close_chunk(&mut self) {
        for f in &mut self.families {
            f.drive.close_chunk();
        }
        self.lever.close_chunk();
        for s in &mut self.stages {
            s.totals.close_chunk();
        }
    }

    /// Continues this summary with `later`, the summary of the steps from the last one this
    /// summary took (a chunk boundary: its index a multiple of its chunk) on, made
    /// from a copy of the same fresh summary: the summary of all the steps, the same bit for
    /// bit as if one summary had taken them all (peaks are maxima; the integrals add the same
    /// chunk sums in the same order). A summary that took no step changes nothing.
    pub fn merge(&mut self, later: &SummarySink) {
        if !later.ends.started() {
            return;
        }
        self.motion.merge(&later.motion);
        for (a, b) in self.families.iter_mut().zip(&later.families) {
            a.peaks.merge(&b.peaks);
            a.drive.merge(&b.drive);
        }
        self.lever.merge(&later.lever);
        self.ends.merge(&later.ends);
        self.gas.merge(&later.gas);
        for (a, b) in self.stages.iter_mut().zip(&later.stages) {
            a.totals.merge(b.totals.as_ref());
        }
        self.previous = later.previous;
    }

    /// The summary, or why the run cannot be trusted (the energy check).
    pub fn finish(&self, mechanism: &dyn Mechanism) -> Result<Summary, String> {
        let mut m = Summary::default();
        let (span, time) = self.ends.span().ok_or("the run has no steps")?;
        let t = &self.topology;
        m.push("piston_stroke", mechanism.stroke());
        self.motion.finish(t, &mut m);
        for f in &self.families {
            f.peaks.finish(f.name, t, &self.kinds, &mut m);
            f.drive.finish(f.name, span, &mut m);
        }
        let radius = mechanism.crank_radius();
        self.lever.finish(radius, mechanism.stroke(), span, &mut m);
        let inertial = self.families.iter().find(|f| f.name == "inertial");
        let inertial = inertial.map(|f| (f.drive.work(), f.drive.abs_work()));
        self.ends.finish(inertial, self.energy_check, &mut m)?;
        m.push("cycle_time", time);
        let works: Vec<(&'static str, f64)> = self
            .families
            .iter()
            .map(|f| (f.name, f.drive.work()))
            .collect();
        let run = RunTotals {
            span,
            time,
            works: &works,
        };
        for s in &self.stages {
            let from = m.metrics.len();
            s.totals.finish(&run, &mut m);
            debug_assert!(
                m.metrics[from..]
                    .iter()
                    .all(|x| metrics::find_in(s.metrics, &x.name).is_some()),
                "a stage's metrics are its own part of the registry"
            );
        }
        self.gas.finish(&mut m);
        Ok(m)
    }
}

impl Sink for SummarySink {
    /// The lanes up to each one that closes a chunk (its step's index a multiple of its chunk)
    /// taken together, then the chunk closed.
    fn push_block(&mut self, block: &StepBlock) -> Result<(), (usize, String)> {
        let (n, mut lo) = (block.len(), 0);
        while lo < n {
            // The lane of the next step whose index is a multiple of the chunk.
            let closing = (block.first + lo).next_multiple_of(self.chunk) - block.first;
            let hi = (closing + 1).min(n);
            let time = self.previous.map(|(_, _, t)| t);
            for s in &mut self.stages {
                s.totals.push_lanes(block, lo..hi, s.index, time);
            }
            take_lanes(self, block, lo..hi);
            if closing < n {
                self.close_chunk();
            }
            lo = hi;
        }
        Ok(())
    }

    fn wants_steps(&self) -> bool {
        false
    }
}

vectorised! {
    /// Takes the lanes `lanes` of `block` (in order, none of them but the last closing a
    /// chunk): each peak raised over all of them before it is stored back, each integral's
    /// terms added in the steps' order.
    fn take_lanes(summary: &mut SummarySink, block: &StepBlock, lanes: Range<usize>) {
        let Some(last) = lanes.end.checked_sub(1) else {
            return;
        };
        summary.motion.push(block.state, lanes.clone());
        let previous = summary.previous.map(|(a, w, _)| (a, w));
        for (k, f) in summary.families.iter_mut().enumerate() {
            // The loads of family k (the total after the families).
            let loads = block.families.get(k).unwrap_or(block.total);
            f.peaks.push(block, loads, lanes.clone(), &summary.kinds);
            f.drive.push(block, loads, lanes.clone(), previous);
        }
        summary.lever.push(block, lanes.clone(), previous.map(|(a, _)| a));
        summary.ends.push(block, lanes.clone(), &summary.topology);
        summary.gas.push(block, lanes);
        let c = &block.state.crank;
        summary.previous = Some((c.angle[last], c.speed[last], c.time[last]));
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use cardan_mechanism::REANCHOR;

    /// Chunks are whole grid blocks, at most MAX_CHUNK steps, an even number of them for a
    /// run, differing by less than a block but the last (which takes what is left).
    #[test]
    fn a_run_is_chunked_evenly_in_whole_blocks() {
        for points in (2..40_000).step_by(37).chain([4097, 4098, 7201, 720_001]) {
            let chunk = summary_chunk(points);
            assert_eq!(chunk % REANCHOR, 0, "{points}");
            assert!((REANCHOR..=MAX_CHUNK).contains(&chunk), "{points}: {chunk}");
            let intervals = points - 1;
            let chunks = intervals.div_ceil(chunk);
            let wanted = intervals.div_ceil(REANCHOR).div_ceil(MAX_CHUNK / REANCHOR);
            assert!(
                chunks <= wanted.next_multiple_of(2),
                "{points}: {chunks} chunks"
            );
            if intervals > REANCHOR {
                assert_eq!(chunks % 2, 0, "{points}: {chunks} chunks");
            }
            // The last chunk is short by less than one block per chunk.
            let short = chunks * chunk - intervals;
            assert!(
                short < chunks * REANCHOR,
                "{points}: last chunk short by {short}"
            );
        }
        assert_eq!(summary_chunk(7201), 3648);
    }
}
