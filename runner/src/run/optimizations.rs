//! A batch's optimisations (`[optimize]`, issue 40), run after its cases: each whole (its
//! search is one, never split between shards), its starts on the batch's worker threads, into
//! its folder with its record (`run.json`), which `--resume` keeps when it matches and
//! `cardan merge` copies from the shard that ran it.

use super::options::{Report, RunOptions};
use super::stamp;
use crate::optimize::{optimize, write};
use cardan_case::optimize::Optimization;
use std::path::Path;

/// Runs and writes `optimizations` into `out`, each after the other, on `threads` worker
/// threads (None: one per core); each folder written or kept (`--resume`), or failure, into
/// `report`.
pub(super) fn run_optimizations(
    optimizations: &[Optimization],
    out: &Path,
    options: &RunOptions,
    threads: Option<usize>,
    report: &mut Report,
) {
    if optimizations.is_empty() {
        return;
    }
    let work = || {
        optimizations
            .iter()
            .map(|o| {
                let dir = out.join(&o.name);
                if options.resume && stamp::reusable_optimization(&dir, o, options.reports) {
                    tracing::info!(case = %o.name, folder = %dir.display(), "kept (--resume)");
                    return Ok((o.name.clone(), dir, true));
                }
                if dir.symlink_metadata().is_ok_and(|m| !m.is_dir()) {
                    return Err(format!(
                        "{}: case \"{}\": {} is a file, not an optimisation's folder: it is not replaced; move it away or rename the case",
                        o.file.display(),
                        o.name,
                        dir.display()
                    ));
                }
                let _span = tracing::info_span!("optimize", name = %o.name).entered();
                optimize(o)
                    .and_then(|results| write(o, &results, out, options.reports))
                    .map(|dir| (o.name.clone(), dir, false))
            })
            .collect::<Vec<_>>()
    };
    let outcomes = match threads {
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
            Ok((name, dir, reused)) => {
                report.reused += usize::from(reused);
                report.written.push((name, dir));
            }
            Err(e) => report.failures.push(e),
        }
    }
}
