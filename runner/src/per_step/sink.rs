//! The sink that writes a crank train's per-step rows to its files ([`PerStepSink`]), and
//! records the charts of the rows it writes if asked.

use super::charts::chart_recorder;
use super::row::{finite_row, Row, RunLayout};
use super::writer::{Writer, BLOCK_ROWS};
use cardan_case::case::OutputOptions;
use cardan_dynamics::{Sink, Step};
use cardan_mechanism::Mechanism;
use cardan_report::{row_count, ChartData, ChartRecorder};
use std::path::Path;

/// A sink writing the per-step rows of one crank train to its files, and thinning them for the
/// report's charts if asked.
pub struct PerStepSink<'a> {
    row: Row<'a>,
    decimation: usize,
    last_step: usize,
    files: Writer,
    charts: Option<ChartRecorder>,
}

impl<'a> PerStepSink<'a> {
    /// Creates `<label>.csv` and/or `<label>.npy` (with `<label>.columns.json`) in `dir`, as
    /// `options` asks, and records the report's charts if `charts`, for `mechanism` run with
    /// `run`'s families and stages over `last_step + 1` steps; `None` if `options` asks for no file
    /// ([`ChartSink`](super::ChartSink) records the charts alone). The charts take the rows the
    /// files take (every `options.decimation`-th step and the last), so that a chart draws the very
    /// rows of the file it names.
    pub fn create(
        dir: &Path,
        label: &str,
        mechanism: &'a dyn Mechanism,
        run: &RunLayout,
        options: OutputOptions,
        last_step: usize,
        charts: bool,
    ) -> anyhow::Result<Option<Self>> {
        if !(options.csv || options.npy) {
            return Ok(None);
        }
        let row = Row::new(mechanism, run);
        let rows = row_count(last_step, options.decimation);
        let charts = charts.then(|| {
            let file = if options.csv {
                format!("{label}.csv")
            } else {
                format!("{label}.npy")
            };
            chart_recorder(&row, mechanism, rows, file)
        });
        let files = Writer::start(dir, label, row.header(), rows, options)?;
        Ok(Some(Self {
            row,
            decimation: options.decimation,
            last_step,
            files,
            charts,
        }))
    }

    /// Writes out the last rows and waits until every file is complete; returns the charts'
    /// series if they were recorded.
    pub fn finish(self) -> anyhow::Result<Option<ChartData>> {
        self.files.finish()?;
        Ok(self.charts.map(ChartRecorder::finish))
    }
}

impl Sink for PerStepSink<'_> {
    /// The files hold the torque shares and the extras.
    fn wants_details(&self) -> bool {
        true
    }

    fn push(&mut self, s: &Step) -> Result<(), String> {
        if s.index % self.decimation != 0 && s.index != self.last_step {
            return Ok(());
        }
        let files = &mut self.files;
        let start = files.block.len();
        self.row.fill(s, &mut files.block);
        finite_row(
            self.row.header(),
            &files.block[start..],
            0..self.row.header().len(),
            s,
        )?;
        if let Some(c) = &mut self.charts {
            c.record(&files.block[start..]);
        }
        if files.block.len() >= BLOCK_ROWS * files.columns {
            files.send()?;
        }
        Ok(())
    }
}
