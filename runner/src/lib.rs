//! The batch runner: TOML case files → validated cases → mechanism runs in parallel, each step
//! streamed to the summary and the per-step files → `summary.json` and, per mechanism, a CSV
//! and/or an NPY file per case. Physics lives in the `cardan-*` crates; this crate only reads, validates, schedules and
//! writes.

pub mod output;
pub mod per_step;
pub mod run;

pub use cardan_case::{Case, CaseError};
pub use run::{run_case, run_paths, Report, RunOptions};
