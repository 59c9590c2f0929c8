//! The sink that keeps a crank train's per-step rows in memory, column by column
//! ([`ColumnSink`]), for callers that want the numbers rather than files (the Python package).
//! Its rows are the files' rows ([`Row`]: the same names, the same numbers, every
//! `decimation`-th step and the last); its memory grows with the rows, which is what it is asked
//! for.

use super::row::{finite_row, Row, RunLayout};
use cardan_dynamics::{Sink, Step};
use cardan_mechanism::Mechanism;
use cardan_report::row_count;

/// A crank train's per-step columns: `names[k]` is the name of `values[k]` (the per-step files'
/// header, [`crate::per_step::COLUMNS`]), each column one number per row written.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct StepColumns {
    pub names: Vec<String>,
    pub values: Vec<Vec<f64>>,
}

impl StepColumns {
    /// The column named `name`.
    pub fn get(&self, name: &str) -> Option<&[f64]> {
        let k = self.names.iter().position(|n| n == name)?;
        Some(&self.values[k])
    }

    /// Rows held.
    pub fn rows(&self) -> usize {
        self.values.first().map_or(0, Vec::len)
    }
}

/// A sink keeping the per-step rows of one crank train as columns: each row filled by [`Row`]
/// (checked finite as the files' rows are), then its numbers appended to their columns.
pub struct ColumnSink<'a> {
    row: Row<'a>,
    decimation: usize,
    last_step: usize,
    scratch: Vec<f64>,
    columns: Vec<Vec<f64>>,
}

impl<'a> ColumnSink<'a> {
    /// The columns of `mechanism` run with `run`'s families and stages over `last_step + 1`
    /// steps, a row every `decimation`-th step and the last.
    pub fn new(
        mechanism: &'a dyn Mechanism,
        run: &RunLayout,
        decimation: usize,
        last_step: usize,
    ) -> Self {
        let row = Row::new(mechanism, run);
        let rows = row_count(last_step, decimation);
        let columns = vec![Vec::with_capacity(rows); row.header().len()];
        Self {
            scratch: Vec::with_capacity(columns.len()),
            row,
            decimation,
            last_step,
            columns,
        }
    }

    /// The columns, with their names.
    pub fn finish(self) -> StepColumns {
        StepColumns {
            names: self.row.header().to_vec(),
            values: self.columns,
        }
    }
}

impl Sink for ColumnSink<'_> {
    /// The rows hold the torque shares and the extras.
    fn wants_details(&self) -> bool {
        true
    }

    fn push(&mut self, s: &Step) -> Result<(), String> {
        if s.index % self.decimation != 0 && s.index != self.last_step {
            return Ok(());
        }
        self.scratch.clear();
        self.row.fill(s, &mut self.scratch);
        finite_row(self.row.header(), &self.scratch, 0..self.scratch.len(), s)?;
        for (column, &v) in self.columns.iter_mut().zip(&self.scratch) {
            column.push(v);
        }
        Ok(())
    }
}
