//! The sink that thins a crank train's per-step rows for the report's charts when the run
//! writes no file ([`ChartSink`]; shared by the threads of a run), and the chart recorder of a
//! row both sinks use.

use super::lane::{BlockLane, Lane};
use super::row::{finite_row, Row, RunLayout};
use cardan_dynamics::{Sink, StepBlock, MAX_CHUNK};
use cardan_mechanism::Mechanism;
use cardan_report::{row_count, ChartData, ChartRecorder, ChartRows, MAX_POINTS};
use std::sync::Arc;

/// The recorder of the report's charts of `mechanism`'s rows `row`, `rows` of them, held in
/// the file `file` names (or none: the crank train's label).
pub(super) fn chart_recorder(
    row: &Row,
    mechanism: &dyn Mechanism,
    rows: usize,
    file: String,
) -> ChartRecorder {
    let joints: Vec<String> = mechanism
        .topology()
        .joints
        .iter()
        .map(|j| j.name.to_string())
        .collect();
    ChartRecorder::new(row.header(), &joints, rows, MAX_POINTS, file)
}

/// A sink thinning the per-step rows of a crank train that writes no file for the report's charts:
/// the rows [`PerStepSink`](super::PerStepSink) would write (every `decimation`-th step and the
/// last) that the charts take ([`ChartRows`]), the row's undrawn columns left unfilled. The pieces
/// of a shared run ([`cardan_dynamics::run_parallel`]) keep their rows until they are joined, in
/// the steps' order: the charts are the same as a run by one thread gives.
#[derive(Clone)]
pub struct ChartSink<'a> {
    decimation: usize,
    last_step: usize,
    pick: ChartRows,
    /// The next step the charts take (found at the first step this sink takes, then counted on:
    /// no division per step).
    next: Option<usize>,
    /// The steps between two rows taken (but the last), and (rows − 1)·`decimation`: a row
    /// taken at or past it is the last row (the last step's).
    step_stride: usize,
    last_row_step: usize,
    /// The rows taken.
    taken: Taken<'a>,
}

/// The rows a [`ChartSink`] took: recorded at once by the sink that has the recorder, kept by a
/// piece of a shared run until it is joined.
#[derive(Clone)]
struct Taken<'a> {
    row: Row<'a>,
    /// The recorder; `None` in a piece of a shared run.
    recorder: Option<ChartRecorder>,
    /// The columns the charts read (shared by the pieces): the recorder takes rows of these
    /// alone ([`ChartRecorder::pack`]).
    read: Arc<[usize]>,
    /// The row being filled (its unread columns left as they are).
    scratch: Vec<f64>,
    /// The rows taken and not yet recorded, one after the other, each of the `read` columns
    /// only, and the steps of the first and the last one taken.
    rows: Vec<f64>,
    first_taken: Option<usize>,
    last_taken: Option<usize>,
    /// The values a piece's rows hold at most: those of the rows a piece of at most
    /// [`MAX_CHUNK`] + 1 steps takes (reserved at its first row, not grown row by row).
    piece_room: usize,
}

impl<'a> ChartSink<'a> {
    /// The charts of `mechanism` run with `run`'s families and stages over `last_step + 1`
    /// steps, its rows every `decimation`-th step and the last; `label` names the series.
    pub fn new(
        mechanism: &'a dyn Mechanism,
        run: &RunLayout,
        decimation: usize,
        last_step: usize,
        label: &str,
    ) -> Self {
        let mut row = Row::new(mechanism, run);
        let rows = row_count(last_step, decimation);
        let mut recorder = chart_recorder(&row, mechanism, rows, label.to_string());
        row.skip_unread(|k| recorder.reads(k));
        let width = row.header().len();
        let pick = recorder.rows();
        let read: Arc<[usize]> = recorder.pack().into();
        // A piece's steps hold a taken step every `decimation · stride`, and maybe the last.
        let piece_rows = (MAX_CHUNK + 1) / (decimation * pick.stride()) + 2;
        Self {
            decimation,
            last_step,
            pick,
            next: None,
            step_stride: decimation * pick.stride(),
            last_row_step: (rows - 1) * decimation,
            taken: Taken {
                row,
                recorder: Some(recorder),
                scratch: vec![f64::NAN; width],
                rows: Vec::with_capacity(read.len()),
                piece_room: piece_rows * read.len(),
                read,
                first_taken: None,
                last_taken: None,
            },
        }
    }

    /// The first step from `step` on whose row the charts take (`usize::MAX` past the last).
    fn taken_from(&self, step: usize) -> usize {
        if step > self.last_step {
            return usize::MAX;
        }
        // The rows taken are every stride-th and the last (whose step is the last step).
        let last_row = row_count(self.last_step, self.decimation) - 1;
        let k = self.pick.next_taken(step.div_ceil(self.decimation));
        if k >= last_row {
            self.last_step
        } else {
            k * self.decimation
        }
    }

    /// The step after `step`, a step the charts take, that the charts take: `taken_from(step +
    /// 1)`, counted on. A step taken but the last is the row k·`decimation`, k a multiple of the
    /// stride, so the next is the row k + stride, or the last step past the last row.
    fn taken_after(&self, step: usize) -> usize {
        if step >= self.last_step {
            return usize::MAX;
        }
        let next = step + self.step_stride;
        if next >= self.last_row_step {
            self.last_step
        } else {
            next
        }
    }

    /// The thinned series.
    pub fn finish(self) -> Option<ChartData> {
        self.taken.recorder.map(ChartRecorder::finish)
    }
}

impl Taken<'_> {
    /// Takes the row of `s`, a step the charts take: recorded at once, unless this is a piece
    /// of a shared run.
    fn take(&mut self, s: &impl Lane) -> Result<(), String> {
        self.row.fill_slice(s, &mut self.scratch);
        if self.recorder.is_none() && self.rows.capacity() == 0 {
            self.rows.reserve_exact(self.piece_room);
        }
        let start = self.rows.len();
        let (whole, read) = (&self.scratch[..], &self.read[..]);
        self.rows.extend(read.iter().map(|&k| whole[k]));
        // One test for the row, not a branch a column.
        if (self.rows[start..].iter()).fold(false, |any, v| any | v.is_infinite()) {
            self.rows.truncate(start);
            let read = self.read.iter().copied();
            return finite_row(self.row.header(), &self.scratch, read, s);
        }
        self.first_taken.get_or_insert(s.index());
        self.last_taken = Some(s.index());
        if let Some(r) = &mut self.recorder {
            r.add(&self.rows);
            self.rows.clear();
        }
        Ok(())
    }
}

impl Sink for ChartSink<'_> {
    /// Only the steps the charts take, each read from the block's columns (a long run's charts
    /// take one step in many), or the run's own step if it made them.
    fn push_block(&mut self, block: &StepBlock) -> Result<(), (usize, String)> {
        let end = block.first + block.len();
        let mut next = match self.next {
            Some(n) => n,
            None => self.taken_from(block.first),
        };
        while next < end {
            let i = next - block.first;
            let taken = match block.steps.get(i) {
                Some(s) => self.taken.take(s),
                None => self.taken.take(&BlockLane { block, i }),
            };
            taken.map_err(|message| (next, message))?;
            next = self.taken_after(next);
        }
        self.next = Some(next);
        Ok(())
    }

    fn wants_steps(&self) -> bool {
        false
    }
}

impl cardan_dynamics::Joinable for ChartSink<'_> {
    fn fork(&self) -> Self {
        let mut piece = self.clone();
        piece.taken.recorder = None;
        piece
    }

    fn join(&mut self, later: Self) {
        // The step both pieces took is recorded once.
        let (taken, later) = (&mut self.taken, later.taken);
        let width = taken.read.len();
        let skip =
            usize::from(later.first_taken.is_some() && later.first_taken <= taken.last_taken);
        let rows = &later.rows[(skip * width).min(later.rows.len())..];
        match &mut taken.recorder {
            Some(r) => rows.chunks_exact(width).for_each(|row| r.add(row)),
            None => taken.rows.extend_from_slice(rows),
        }
        if later.last_taken.is_some() {
            taken.last_taken = later.last_taken;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The chart sink finds the next step the charts take by arithmetic: the steps the files
    /// would write (every `decimation`-th and the last) whose rows the charts take.
    #[test]
    fn chart_sink_takes_the_rows_the_recorder_takes() {
        // Any mechanism: the rows' layout does not matter here.
        let m = (cardan_mechanism::MECHANISMS[0].build)(
            &cardan_mechanism::MachineGeometry {
                crank_length: 0.06,
                rod_length: 0.14,
                bore: 0.12,
                pin_offset: 0.0,
            },
            &cardan_mechanism::MassInputs::default(),
            &cardan_mechanism::Options::new(),
        )
        .unwrap();
        let layout = RunLayout {
            families: &["inertial"],
            gas: false,
            stages: &[],
        };
        for (last_step, decimation) in [(10, 1), (100_000, 1), (100_000, 3), (700_001, 7)] {
            let sink = ChartSink::new(m.as_ref(), &layout, decimation, last_step, "c");
            let rows = row_count(last_step, decimation);
            let taken = |i: usize| {
                let row = if i % decimation == 0 {
                    i / decimation
                } else if i == last_step {
                    rows - 1
                } else {
                    return false;
                };
                sink.pick.takes(row)
            };
            let mut next = usize::MAX;
            for i in (0..=last_step).rev() {
                if taken(i) {
                    assert_eq!(sink.taken_after(i), next, "after {i} of {last_step}");
                    next = i;
                }
                assert_eq!(
                    sink.taken_from(i),
                    next,
                    "step {i} of {last_step}, every {decimation}"
                );
            }
            assert_eq!(sink.taken_from(last_step + 1), usize::MAX);
        }
    }
}
