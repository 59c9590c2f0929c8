//! How a batch runs ([`RunOptions`]) and what it did ([`Report`]).

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

/// Called after each case with (cases finished, cases in the batch).
pub type Progress = std::sync::Arc<dyn Fn(usize, usize) + Send + Sync>;

/// How a batch runs.
#[derive(Clone, Default)]
pub struct RunOptions {
    /// Worker threads (None: one per core).
    pub jobs: Option<usize>,
    /// Overrides every case's `[output] csv`.
    pub csv: Option<bool>,
    /// Overrides every case's `[output] npy`.
    pub npy: Option<bool>,
    /// Runs only the cases whose name matches this pattern (`*` matches any run of
    /// characters; without a `*`, any name containing it).
    pub only: Option<String>,
    /// Told of every finished case.
    pub progress: Option<Progress>,
    /// The largest estimated size of a case's per-step files, in bytes (None:
    /// [`DEFAULT_MAX_BYTES`](super::DEFAULT_MAX_BYTES)); a larger case is refused.
    pub max_bytes: Option<u64>,
    /// Runs cases of any size (`--allow-large`).
    pub allow_large: bool,
    /// Writes the comparison reports ([`cardan_report`]): one per case (not per sweep point),
    /// one per sweep, and `index.html` at the top of the output folder.
    pub reports: bool,
    /// Keeps every case folder of an earlier run that is complete and was written by this
    /// program from the same input (`--resume`; its `run.json`), and runs the rest.
    pub resume: bool,
    /// Runs only the K-th (from 1) of N parts of the cases (`--shard K/N`): (K, N).
    pub shard: Option<(usize, usize)>,
}

impl std::fmt::Debug for RunOptions {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("RunOptions")
            .field("jobs", &self.jobs)
            .field("csv", &self.csv)
            .field("npy", &self.npy)
            .field("only", &self.only)
            .field("reports", &self.reports)
            .field("max_bytes", &self.max_bytes)
            .field("allow_large", &self.allow_large)
            .field("resume", &self.resume)
            .field("shard", &self.shard)
            .finish_non_exhaustive()
    }
}

/// What a batch did.
#[derive(Debug, Default)]
pub struct Report {
    /// Cases run and written: (case name, output folder).
    pub written: Vec<(String, PathBuf)>,
    /// The summaries of the case folders written with their report, as it read them, by
    /// folder name: the index lists them without reading them again (issue 37).
    pub summaries: BTreeMap<String, cardan_report::CaseSummary>,
    /// Each failure: a path that does not exist, a case file that could not be read or
    /// validated, a case that failed to run or could not be written.
    pub failures: Vec<String>,
    /// Each sweep written: its name, its folder and how many of its points this run wrote
    /// (each point is also in `written`).
    pub sweeps: Vec<(String, PathBuf, usize)>,
    /// Cases whose folder of an earlier run was kept (`--resume`; each is also in `written`).
    pub reused: usize,
}

impl Report {
    /// Rewrites `out/index.html` when the run (or merge) changed the folder's contents, also
    /// where it writes no reports (`reports` false) but an index is there: the index describes
    /// what the folder holds, and would otherwise link reports that are gone, with old numbers.
    /// A failure to write it is one of the batch's failures.
    pub(crate) fn write_index(&mut self, out: &Path, reports: bool) {
        let changed = !self.written.is_empty() || !self.sweeps.is_empty();
        let index = out.join("index.html");
        if changed && (reports || index.symlink_metadata().is_ok()) {
            if let Err(e) = cardan_report::index_with(out, &self.summaries) {
                (self.failures).push(format!("cannot write {}: {e:#}", index.display()));
            }
        }
    }
}
