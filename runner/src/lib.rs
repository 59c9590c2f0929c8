//! The batch runner: validated cases (`cardan-case`) → mechanism runs in parallel, each step
//! streamed to the summary and the per-step files → `summary.json` and, per mechanism, a CSV
//! and/or an NPY file per case; the reports are `cardan-report`'s. Physics lives in the
//! `cardan-*` crates; this crate only schedules and writes. A case can also be run in memory
//! ([`memory`]: its summary and per-step columns, for the Python package).

pub mod memory;
pub mod optimize;
pub mod output;
pub mod per_step;
pub mod progress;
pub mod run;

pub use run::{run_case, run_paths, Report, RunOptions};
