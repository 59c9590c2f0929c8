//! Running cases: every mechanism of every case in parallel, each step streamed to its sinks;
//! one failure (an error or a panic) never stops the rest.
//!
//! A batch ([`run_paths`], `batch.rs`) reads its case files (`cases.rs`), runs each case into
//! its folder (`case_folder.rs`: refused first if its files would be too large, `size.rs`),
//! its crank trains in parallel (`train.rs`, with the sampling check of a coarse grid in
//! `sampling.rs`; a solved machine motion's cycles and flywheel in `dynamic.rs`), then writes the sweeps' folders (`sweeps.rs`), runs the optimisations (`optimizations.rs`: each
//! whole, into its folder, with its record) and writes the index. How a batch
//! runs is [`RunOptions`], what it did [`Report`] (`options.rs`). Each case folder records
//! what made it ([`stamp`], `run.json`: `--resume` keeps a folder whose record matches); a
//! shard (`--shard K/N`) runs its part of the cases ([`shard`]) and [`merge`] gathers the
//! shards into what one run writes (`merge.rs`).

mod batch;
mod case_folder;
mod cases;
mod dynamic;
mod merge;
mod optimizations;
mod options;
mod sampling;
pub mod shard;
mod size;
pub mod stamp;
mod sweeps;
mod table;
mod table_merge;
pub(crate) mod train;

pub use batch::{run_paths, worker_threads};
pub use cases::{case_files, load_batch, load_cases, matches_pattern, Batch, RESERVED};
pub use merge::merge;
pub use options::{Progress, Report, RunOptions};
pub use size::{check_size, estimated_bytes, human_bytes, DEFAULT_MAX_BYTES};
pub use table::{case_folders, TableSweep, CASE_FOLDERS_UP_TO};
pub use train::run_case;
#[cfg(feature = "test-hooks")]
pub use train::test_hooks;
