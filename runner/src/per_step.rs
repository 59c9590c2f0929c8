//! Per-step rows: one row per step (every `decimation`-th step and the last), defined once
//! ([`Row`]: the header and how a step fills it), written as CSV text (`<label>.csv`) and/or
//! as a binary columnar array (`<label>.npy`, NPY format 1.0, `<f8`, Fortran order: each
//! column contiguous, with its names in `<label>.columns.json`), and/or thinned for the
//! report's charts ([`ChartRecorder`](cardan_report::ChartRecorder): a few hundred points per
//! charted column, whatever the number of steps). The one sink fills each row once for all of
//! them.
//!
//! The run's thread only copies each row's numbers into a block; a thread of the sink's own
//! formats and writes the blocks, so a large case keeps two cores busy (float formatting is
//! most of a case's time when it writes text). Memory is a few blocks, whatever the number of
//! steps: the NPY file's size is known in advance (rows × columns), so every block's column
//! pieces are written in place.
//!
//! A caller that wants the rows in memory (the Python package) takes them as columns
//! ([`ColumnSink`], `columns.rs`), filled by the same row.
//!
//! The row's definition is `row.rs`; the sink that writes the files (and records the charts of the
//! rows it writes) `sink.rs`, the one for the charts alone (and the chart recorder both use)
//! `charts.rs`, which fills its rows from the run's blocks of columns (`lane.rs`: a step's
//! values as the row reads them); the writing thread `writer.rs`, the file formats `csv.rs`
//! and `npy.rs`.

mod charts;
mod columns;
mod csv;
mod lane;
mod npy;
mod row;
mod sink;
mod writer;

pub use charts::ChartSink;
pub use columns::{ColumnSink, StepColumns};
pub use npy::npy_header;
pub use row::{Row, RunLayout, COLUMNS};
pub use sink::PerStepSink;
