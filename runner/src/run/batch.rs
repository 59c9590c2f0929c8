//! A batch: every case under the paths given run into its folder of the output folder, on the
//! worker threads, then the sweeps' `sweep.csv` and reports and the index ([`run_paths`]).

use super::case_folder::{run_and_write, Written};
use super::cases::{load_batch, matches_pattern};
use super::optimizations::run_optimizations;
use super::options::{Report, RunOptions};
use super::shard;
use super::sweeps::{sweep_targets, write_sweeps, Point, SweepTarget};
use super::table::{run_table, TableSweep};
use cardan_case::case::Case;
use cardan_report::files;
use rayon::prelude::*;
use std::collections::{BTreeMap, HashMap};
use std::path::{Path, PathBuf};

/// The worker threads a run starts for `requested` (`--jobs`; None: one per core) on a machine of
/// `cores` cores, and the warning to log when `requested` is capped: the cases are CPU-bound, so
/// threads beyond the cores only cost memory and start-up time (100 000 threads did not finish a
/// 10 ms case in a minute; the per-step files' writer threads are apart from these).
pub fn worker_threads(requested: Option<usize>, cores: usize) -> (Option<usize>, Option<String>) {
    let cores = cores.max(1);
    match requested {
        Some(n) if n > cores => (
            Some(cores),
            Some(format!(
                "--jobs {n}: more worker threads than the machine's {cores} core(s) only cost memory; running {cores}"
            )),
        ),
        other => (other, None),
    }
}

/// Loads, validates, runs and writes every case under `paths` (or those `options.only`
/// selects) into `out/<case name>/`, then every optimisation (`[optimize]`) into its folder.
/// A panic inside a case is caught and reported as that case's failure. An `out` that is not
/// a folder is refused before anything runs; leftovers of killed runs in it are removed;
/// `index.html` (and an `--only` run's sweep report) is rewritten whenever the folder's
/// contents change, so that it never describes old results.
pub fn run_paths(paths: &[PathBuf], out: &Path, options: RunOptions) -> Report {
    let mut report = Report::default();
    if let Some(why) = not_a_folder(out) {
        report.failures.push(why);
        return report;
    }
    let (batch, failures) = load_batch(paths);
    report.failures = failures;
    let (mut cases, mut tables) = (batch.cases, batch.tables);
    let mut optimizations = batch.optimizations;
    override_outputs(&mut cases, &mut tables, &options);
    // A shard runs its part of the cases as if they were all: its sweeps' folders hold its
    // points only, and `cardan merge` gathers them.
    let manifest = options.shard.map(|shard| {
        shard::take(
            &mut cases,
            &mut tables,
            &mut optimizations,
            shard,
            options.reports,
            &report.failures,
        )
    });
    if let Some(Err(why)) = manifest.as_ref().map(|_| shard::remove_record(out)) {
        report.failures.push(why);
        return report;
    }
    // Every sweep's points in their order, before `--only` selects some.
    let all_points = sweep_points(&cases);
    if let Some(pattern) = &options.only {
        if let Err(partial) = select(pattern, &mut cases, &mut tables) {
            report.failures.extend(partial);
            return report;
        }
        optimizations.retain(|o| matches_pattern(pattern, &o.name));
    }
    let selected = selected_points(&cases);
    // A sweep's points run into a temporary folder that replaces `out/<sweep>` as a whole, or,
    // when `--only` selects some of the points of a sweep written before, into its folder.
    let sweeps = sweep_targets(
        &cases,
        out,
        &selected,
        &all_points,
        options.resume,
        &mut report.failures,
    );
    // After the sweeps' targets: `--resume` keeps the points in the leftovers of killed runs.
    files::remove_stale_temporaries(out);
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
    let Some((mut outcomes, tables)) =
        run_all(&cases, &tables, out, &base, &options, &mut report.failures)
    else {
        return report;
    };
    keep_summaries(&cases, &mut outcomes, &mut report);
    record_tables(tables, out, &mut report);
    let (points, failed) = record_outcomes(&cases, &outcomes, out, &mut report);
    write_sweeps(
        &sweeps,
        out,
        &points,
        &failed,
        &all_points,
        options.reports && manifest.is_none(),
        &mut report,
    );
    // After the cases: each whole, on the shard it is given to.
    let cores = std::thread::available_parallelism().map_or(1, |n| n.get());
    let threads = worker_threads(options.jobs, cores).0;
    run_optimizations(&optimizations, out, &options, threads, &mut report);
    if let Some(manifest) = manifest {
        // A shard's sweeps and index are the merge's to report.
        if let Err(e) = manifest.write(out, &report.failures) {
            report.failures.push(format!("{e:#}"));
        }
        return report;
    }
    report.write_index(out, options.reports);
    report
}

/// Why `out` cannot take the run (it exists and is not a folder), if so.
fn not_a_folder(out: &Path) -> Option<String> {
    let meta = std::fs::metadata(out).ok()?;
    if meta.is_dir() {
        return None;
    }
    let kind = if meta.is_file() {
        "a file"
    } else {
        "a device or other special file"
    };
    Some(format!(
        "--out {}: is {kind}, not a folder: nothing was run",
        out.display()
    ))
}

/// The `--csv`/`--npy` options given, over every case's and sweep table's own.
fn override_outputs(cases: &mut [Case], tables: &mut [TableSweep], options: &RunOptions) {
    let overrides = |case: &mut Case| {
        case.output.csv = options.csv.unwrap_or(case.output.csv);
        case.output.npy = options.npy.unwrap_or(case.output.npy);
    };
    cases.iter_mut().for_each(overrides);
    tables.iter_mut().for_each(|t| overrides(&mut t.first));
}

/// Every sweep's points (case names), in their order, by sweep.
fn sweep_points(cases: &[Case]) -> HashMap<String, Vec<String>> {
    let mut all_points: HashMap<String, Vec<String>> = HashMap::new();
    for c in cases {
        if let Some((sweep, _)) = &c.sweep {
            all_points
                .entry(sweep.clone())
                .or_default()
                .push(c.name.clone());
        }
    }
    all_points
}

/// How many points of each sweep are among `cases` (the ones selected to run).
fn selected_points(cases: &[Case]) -> HashMap<&str, usize> {
    let mut selected: HashMap<&str, usize> = HashMap::new();
    for c in cases {
        if let Some((sweep, _)) = &c.sweep {
            *selected.entry(sweep.as_str()).or_default() += 1;
        }
    }
    selected
}

/// Each sweep written as a table into `report`: its folder if any of its points ran, and its
/// failures.
fn record_tables(tables: Vec<TableOutcome>, out: &Path, report: &mut Report) {
    for (sweep, written, failures) in tables {
        if written > 0 {
            report
                .sweeps
                .push((sweep.clone(), out.join(&sweep), written));
        }
        report.failures.extend(failures);
    }
}

/// A case's outcome: its folder and sweep row, or its failure.
type Outcome = Result<Written, String>;

/// A sweep written as a table: its name, how many of its points ran, its failures.
type TableOutcome = (String, usize, Vec<String>);

/// The summaries the reports of the cases (not sweep points) read, moved into `report` by
/// case name: the index lists those folders without reading them again (issue 37).
fn keep_summaries(cases: &[Case], outcomes: &mut [Outcome], report: &mut Report) {
    for (case, outcome) in cases.iter().zip(outcomes) {
        if let (None, Ok(written)) = (&case.sweep, outcome) {
            if let Some(summary) = written.summary.take() {
                report.summaries.insert(case.name.clone(), summary);
            }
        }
    }
}

/// Each case's outcome into `report` (its folder written or kept, or its failure), and the
/// points of each sweep that ran and the count of those that failed, for the sweep tables.
fn record_outcomes<'a>(
    cases: &'a [Case],
    outcomes: &'a [Outcome],
    out: &Path,
    report: &mut Report,
) -> (BTreeMap<&'a str, Vec<Point<'a>>>, HashMap<&'a str, usize>) {
    let mut points: BTreeMap<&str, Vec<Point>> = Default::default();
    let mut failed: HashMap<&str, usize> = HashMap::new();
    for (case, o) in cases.iter().zip(outcomes) {
        match o {
            Ok(written) => {
                let name = &case.name;
                let dir = match &case.sweep {
                    Some((sweep, values)) => {
                        points
                            .entry(sweep)
                            .or_default()
                            .push((name, values, &written.cells));
                        out.join(sweep).join(name)
                    }
                    None => written.dir.clone(),
                };
                if written.reused {
                    tracing::info!(case = %name, folder = %dir.display(), "kept (--resume)");
                    report.reused += 1;
                } else {
                    tracing::info!(case = %name, folder = %dir.display(), "written");
                }
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
    (points, failed)
}

/// Runs and writes every case of `cases` into its folder under `base(case)`, then each sweep
/// of `tables` into its table (`table.rs`), on the worker threads `options` asks for, telling
/// `options.progress` of each case and point; a panic is the case's failure. None, with the
/// failure in `failures`, if the threads cannot be started.
fn run_all(
    cases: &[Case],
    tables: &[TableSweep],
    out: &Path,
    base: &(dyn Fn(&Case) -> PathBuf + Sync),
    options: &RunOptions,
    failures: &mut Vec<String>,
) -> Option<(Vec<Outcome>, Vec<TableOutcome>)> {
    let total = cases.len() + tables.iter().map(TableSweep::points).sum::<usize>();
    let done = std::sync::atomic::AtomicUsize::new(0);
    let work = || {
        let outcomes = cases
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
                    Ok(r) => r,
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
            .collect::<Vec<Outcome>>();
        let tables: Vec<TableOutcome> = tables
            .iter()
            .map(|table| {
                let (n, failures) = run_table(table, out, options, &done, total);
                (table.sweep.name.clone(), n, failures)
            })
            .collect();
        (outcomes, tables)
    };
    let cores = std::thread::available_parallelism().map_or(1, |n| n.get());
    let (jobs, warning) = worker_threads(options.jobs, cores);
    if let Some(warning) = warning {
        tracing::warn!("{warning}");
    }
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

/// Keeps the cases and the points of each table sweep whose name matches `pattern`
/// (`--only`); refused (nothing run) where it selects some of a table sweep's points but not
/// all: a table is written whole, so some of its points alone would replace it with their rows.
fn select(
    pattern: &str,
    cases: &mut Vec<Case>,
    tables: &mut Vec<TableSweep>,
) -> Result<(), Vec<String>> {
    cases.retain(|c| matches_pattern(pattern, &c.name));
    for t in tables.iter_mut() {
        let sweep = &t.sweep;
        t.selected = Some(
            (0..sweep.len())
                .filter(|&k| matches_pattern(pattern, &sweep.point_name(k)))
                .collect(),
        );
    }
    tables.retain(|t| t.points() > 0);
    let partial: Vec<String> = tables
        .iter()
        .filter(|t| t.points() < t.sweep.len())
        .map(|t| {
            format!(
                "--only {pattern}: selects {} of the {} points of the sweep \"{}\", written as a table ([output] case_folders = false), which is written whole: nothing was run; run the whole sweep (a pattern matching all its points, or none of them), or write its points as folders ([output] case_folders = true), whose points --only updates in place",
                t.points(),
                t.sweep.len(),
                t.sweep.name
            )
        })
        .collect();
    if partial.is_empty() {
        Ok(())
    } else {
        Err(partial)
    }
}

#[cfg(test)]
mod tests {
    use super::worker_threads;

    #[test]
    fn jobs_above_the_cores_are_capped_with_one_warning() {
        assert_eq!(worker_threads(None, 2), (None, None));
        assert_eq!(worker_threads(Some(1), 2), (Some(1), None));
        assert_eq!(worker_threads(Some(2), 2), (Some(2), None));
        let (n, warning) = worker_threads(Some(100_000), 2);
        assert_eq!(n, Some(2));
        let warning = warning.expect("a warning");
        assert!(
            warning.contains("--jobs 100000") && warning.contains("running 2"),
            "{warning}"
        );
        // No core count known: one thread.
        assert_eq!(worker_threads(Some(3), 0).0, Some(1));
    }
}
