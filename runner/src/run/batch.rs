//! A batch: every case under the paths given run into its folder of the output folder, on the
//! worker threads, then the sweeps' `sweep.csv` and reports and the index ([`run_paths`]).

use super::case_folder::run_and_write;
use super::cases::{load_cases, matches_pattern};
use super::options::{Report, RunOptions};
use super::sweeps::{sweep_targets, write_sweeps, SweepTarget};
use crate::output::MechanismResult;
use cardan_case::case::Case;
use cardan_report::files;
use rayon::prelude::*;
use std::collections::HashMap;
use std::path::{Path, PathBuf};

/// The most worker threads a run starts per core: `--jobs` beyond it only costs memory and
/// start-up time (100 000 threads did not finish a 10 ms case in a minute).
pub const JOBS_PER_CORE: usize = 4;

/// Loads, validates, runs and writes every case under `paths` (or those `options.only`
/// selects) into `out/<case name>/`. A panic inside a case is caught and reported as that
/// case's failure. An `out` that is not a folder is refused before anything runs; leftovers
/// of killed runs in it are removed; `index.html` (and an `--only` run's sweep report) is
/// rewritten whenever the folder's contents change, so that it never describes old results.
pub fn run_paths(paths: &[PathBuf], out: &Path, options: RunOptions) -> Report {
    let mut report = Report::default();
    if let Ok(meta) = std::fs::metadata(out) {
        if !meta.is_dir() {
            let kind = if meta.is_file() {
                "a file"
            } else {
                "a device or other special file"
            };
            report.failures.push(format!(
                "--out {}: is {kind}, not a folder: nothing was run",
                out.display()
            ));
            return report;
        }
    }
    let (mut cases, failures) = load_cases(paths);
    report.failures = failures;
    // Every sweep's points in their order, before `--only` selects some.
    let mut all_points: HashMap<String, Vec<String>> = HashMap::new();
    for c in &cases {
        if let Some((sweep, _)) = &c.sweep {
            all_points
                .entry(sweep.clone())
                .or_default()
                .push(c.name.clone());
        }
    }
    if let Some(pattern) = &options.only {
        cases.retain(|c| matches_pattern(pattern, &c.name));
    }
    for case in &mut cases {
        case.output.csv = options.csv.unwrap_or(case.output.csv);
        case.output.npy = options.npy.unwrap_or(case.output.npy);
    }
    files::remove_stale_temporaries(out);
    let mut selected: HashMap<&str, usize> = HashMap::new();
    for c in &cases {
        if let Some((sweep, _)) = &c.sweep {
            *selected.entry(sweep.as_str()).or_default() += 1;
        }
    }
    // A sweep's points run into a temporary folder that replaces `out/<sweep>` as a whole, or,
    // when `--only` selects some of the points of a sweep written before, into its folder.
    let sweeps = sweep_targets(&cases, out, &selected, &all_points, &mut report.failures);
    cases.retain(|c| match &c.sweep {
        Some((sweep, _)) => sweeps.get(sweep).is_some_and(Option::is_some),
        None => true,
    });
    let base = |case: &Case| -> PathBuf {
        match &case.sweep {
            Some((sweep, _)) => match &sweeps[sweep] {
                Some(SweepTarget::Whole(tmp)) => tmp.clone(),
                Some(SweepTarget::Update) => out.join(sweep),
                None => unreachable!("kept only with a folder"),
            },
            None => out.to_path_buf(),
        }
    };
    let Some(outcomes) = run_all(&cases, &base, &options, &mut report.failures) else {
        return report;
    };
    let mut points: std::collections::BTreeMap<&str, Vec<(&Case, &[MechanismResult])>> =
        Default::default();
    let mut failed: HashMap<&str, usize> = HashMap::new();
    for (case, o) in cases.iter().zip(&outcomes) {
        match o {
            Ok((name, dir, results)) => {
                let dir = match &case.sweep {
                    Some((sweep, _)) => {
                        points.entry(sweep).or_default().push((case, results));
                        out.join(sweep).join(name)
                    }
                    None => dir.clone(),
                };
                tracing::info!(case = %name, folder = %dir.display(), "written");
                report.written.push((name.clone(), dir));
            }
            Err(e) => {
                if let Some((sweep, _)) = &case.sweep {
                    *failed.entry(sweep.as_str()).or_default() += 1;
                }
                report.failures.push(e.clone())
            }
        }
    }
    write_sweeps(
        &sweeps,
        out,
        &points,
        &failed,
        &all_points,
        options.reports,
        &mut report,
    );
    // The index describes what the folder holds: rewritten whenever that changes, also by a
    // run that writes no reports (else it links reports that are gone, with old numbers).
    let changed = !report.written.is_empty() || !report.sweeps.is_empty();
    let index = out.join("index.html");
    if changed && (options.reports || index.symlink_metadata().is_ok()) {
        if let Err(e) = cardan_report::index(out) {
            report
                .failures
                .push(format!("cannot write {}: {e:#}", index.display()));
        }
    }
    report
}

/// A case's outcome: its name, its folder and its results, or its failure.
type Outcome = Result<(String, PathBuf, Vec<MechanismResult>), String>;

/// Runs and writes every case of `cases` into its folder under `base(case)` on the worker
/// threads `options` asks for, telling `options.progress` of each; a panic is the case's
/// failure. None, with the failure in `failures`, if the threads cannot be started.
fn run_all(
    cases: &[Case],
    base: &(dyn Fn(&Case) -> PathBuf + Sync),
    options: &RunOptions,
    failures: &mut Vec<String>,
) -> Option<Vec<Outcome>> {
    let total = cases.len();
    let done = std::sync::atomic::AtomicUsize::new(0);
    let work = || -> Vec<Outcome> {
        cases
            .par_iter()
            .map(|case| {
                let _span = tracing::info_span!("case", name = %case.name).entered();
                let outcome = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
                    run_and_write(case, &base(case), options)
                }));
                if let Some(progress) = &options.progress {
                    progress(
                        done.fetch_add(1, std::sync::atomic::Ordering::Relaxed) + 1,
                        total,
                    );
                }
                match outcome {
                    Ok(r) => r.map(|(dir, results)| (case.name.clone(), dir, results)),
                    Err(panic) => Err(format!(
                        "{}: case \"{}\": internal error (a bug, please report it): {}",
                        case.file.display(),
                        case.name,
                        panic
                            .downcast_ref::<String>()
                            .map(String::as_str)
                            .or_else(|| panic.downcast_ref::<&str>().copied())
                            .unwrap_or("panic")
                    )),
                }
            })
            .collect()
    };
    let cap = std::thread::available_parallelism().map_or(1, |n| n.get()) * JOBS_PER_CORE;
    let jobs = options.jobs.map(|n| {
        if n > cap {
            tracing::warn!(
                "--jobs {n}: more worker threads than {JOBS_PER_CORE} per core only cost memory; running {cap}"
            );
            cap
        } else {
            n
        }
    });
    let outcomes = match jobs {
        Some(n) => match rayon::ThreadPoolBuilder::new().num_threads(n).build() {
            Ok(pool) => pool.install(work),
            Err(e) => {
                failures.push(format!("cannot start {n} worker threads: {e}"));
                return None;
            }
        },
        None => work(),
    };
    Some(outcomes)
}
