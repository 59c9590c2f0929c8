//! Running an `[optimize]` (issue 40): each mechanism of the case searched on its own
//! (`search.rs`: the case of that mechanism alone at each point the optimiser asks for, run in
//! memory as the batch runs it, its summary read for the objective and the constraints), then
//! the outputs written into the optimisation's folder, replaced whole (`outputs.rs`:
//! `<mechanism>/optimum.json`, `<mechanism>/history.csv`, `<mechanism>/summary.json`,
//! `convergence.svg`, `report.md`, and `at-optima/`: every mechanism at its own optimum in one
//! summary, with the comparison report of a case).

mod outputs;
mod search;

pub use outputs::{optimum_json, report_md, write};
pub use search::{optimize, MechanismOptimum};

use crate::run::{worker_threads, Report};
use std::path::Path;

/// Runs and writes the optimisations `report` holds (those `cardan_runner::run_paths` read
/// and `--only` selected) into `out`, each after the other, its starts on `jobs` worker threads
/// (None: one per core); each written folder, or failure, into `report`.
pub fn run_optimizations(report: &mut Report, out: &Path, jobs: Option<usize>, reports: bool) {
    let optimizations = std::mem::take(&mut report.optimizations);
    if optimizations.is_empty() {
        return;
    }
    let work = || {
        optimizations
            .iter()
            .map(|o| {
                let _span = tracing::info_span!("optimize", name = %o.name).entered();
                optimize(o)
                    .and_then(|results| write(o, &results, out, reports))
                    .map(|dir| (o.name.clone(), dir))
            })
            .collect::<Vec<_>>()
    };
    let cores = std::thread::available_parallelism().map_or(1, |n| n.get());
    let outcomes = match worker_threads(jobs, cores).0 {
        Some(n) => match rayon::ThreadPoolBuilder::new().num_threads(n).build() {
            Ok(pool) => pool.install(work),
            Err(e) => {
                report
                    .failures
                    .push(format!("cannot start {n} worker threads: {e}"));
                return;
            }
        },
        None => work(),
    };
    for outcome in outcomes {
        match outcome {
            Ok(written) => report.written.push(written),
            Err(e) => report.failures.push(e),
        }
    }
}
