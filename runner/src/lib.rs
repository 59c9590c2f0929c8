//! The batch runner: TOML case files → validated cases → mechanism runs in parallel, each step
//! streamed to the summary and the per-step files → `summary.json` and, per mechanism, a CSV
//! and/or an NPY file per case. Physics lives in the `cardan-*` crates; this crate only reads, validates, schedules and
//! writes.

pub mod case;
pub mod friction;
pub mod gas;
pub mod gear;
pub mod output;
pub mod per_step;
pub mod report;
pub mod run;
pub mod sweep;
pub mod units;

pub use case::{Case, CaseError};
pub use run::{run_case, run_paths, Report, RunOptions};
