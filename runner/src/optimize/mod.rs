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

use crate::run::{matches_pattern, worker_threads, Report, RunOptions};
use cardan_case::optimize::Optimization;
use std::path::Path;

/// Runs and writes every optimisation of a batch (those `--only` selects) into `out`, on the
/// worker threads `options` asks for; each written folder, or failure, into `report`. A
/// shard runs none (an optimisation is one search, not split): said as a failure.
pub fn run_optimizations(
    optimizations: &[Optimization],
    out: &Path,
    options: &RunOptions,
    report: &mut Report,
) {
    let selected: Vec<&Optimization> = optimizations
        .iter()
        .filter(|o| {
            options
                .only
                .as_deref()
                .is_none_or(|p| matches_pattern(p, &o.name))
        })
        .collect();
    if selected.is_empty() {
        return;
    }
    if options.shard.is_some() {
        for o in selected {
            report.failures.push(format!("{}: case \"{}\": an optimisation is one search and is not split into shards: run it without --shard", o.file.display(), o.name));
        }
        return;
    }
    let work = || {
        selected
            .iter()
            .map(|o| {
                let _span = tracing::info_span!("optimize", name = %o.name).entered();
                optimize(o)
                    .and_then(|results| write(o, &results, out, options.reports))
                    .map(|dir| (o.name.clone(), dir))
            })
            .collect::<Vec<_>>()
    };
    let cores = std::thread::available_parallelism().map_or(1, |n| n.get());
    let outcomes = match worker_threads(options.jobs, cores).0 {
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
