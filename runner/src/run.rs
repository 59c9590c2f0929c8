//! Running cases: every mechanism of every case in parallel, each step streamed to its sinks;
//! one failure (an error or a panic) never stops the rest.

use crate::case::{self, Case, CaseError};
use crate::output;
use crate::per_step::{ChartSink, PerStepSink, RunLayout};
use crate::report::ChartData;
use anyhow::Context;
use cardan_dynamics::stepper::GasAt;
use cardan_dynamics::{
    run, run_parallel, Gas, GearRatings, Inertial, LoadFamily, LossBudget, Solver, Stages, Summary,
    SummarySink,
};
use cardan_mechanism::{CrankMotion, Grid, Mechanism};
use rayon::prelude::*;
use std::collections::HashMap;
use std::path::{Path, PathBuf};
use std::sync::Arc;

/// The result of one crank train of a case: one per mechanism, two per mechanism in an
/// opposed-piston case with a crank phase offset.
#[derive(Debug, Clone)]
pub struct MechanismResult {
    pub mechanism: Arc<dyn Mechanism>,
    /// Its name in the outputs (the key in `summary.json`, the CSV's name): the mechanism's
    /// name, with `_crank2` for the second crank train of a phased opposed-piston case.
    pub label: String,
    pub summary: Summary,
    /// What the case should know about these results (a grid too coarse for its peaks), said
    /// on stderr and in summary.json and the report.
    pub warnings: Vec<String>,
}

/// Steps per crank revolution below which a run estimates its peaks' sampling error: on a
/// 0.25° grid the error of a peak of a smooth load, about (Δθ·k)²/8 for its k-th harmonic, is
/// far below [`SAMPLING_TOLERANCE`] for the orders a crank mechanism has.
const SAMPLING_CHECK_STEPS_PER_REV: f64 = 1440.0;

/// Largest relative sampling error of a peak metric that passes without a warning.
const SAMPLING_TOLERANCE: f64 = 1e-3;

/// The warning for the peak metrics (`*_max`) of `fine` (a run of `steps` intervals, `per_rev`
/// of them per revolution) that its samples may put more than [`SAMPLING_TOLERANCE`] below
/// the true peak, from `shifted`: the same run's peaks on the grids shifted by a third and two
/// thirds of a step. Together the three sample the run every third of a step, so their
/// largest value less the run's own is what the run's grid missed; it is a lower bound of the
/// true error (no sample exceeds the peak) and, for a smooth peak (a parabola near its
/// maximum), short of it by at most a ninth of the worst error a grid of this step can have.
fn sampling_warning(
    fine: &Summary,
    shifted: &[Summary],
    steps: usize,
    per_rev: f64,
) -> Option<String> {
    let mut worst: Option<(f64, &str)> = None;
    let mut count = 0;
    for m in fine.metrics.iter().filter(|m| m.name.ends_with("_max")) {
        if m.value.abs() <= f64::MIN_POSITIVE {
            continue;
        }
        let best = shifted
            .iter()
            .filter_map(|s| s.get(&m.name))
            .fold(m.value, f64::max);
        let error = (best - m.value) / best.abs();
        if error > SAMPLING_TOLERANCE {
            count += 1;
            if worst.is_none_or(|(w, _)| error > w) {
                worst = Some((error, &m.name));
            }
        }
    }
    let (error, name) = worst?;
    // The error goes as the step squared.
    let needed = (steps as f64 * (error / SAMPLING_TOLERANCE).sqrt()).ceil();
    Some(format!(
        "{count} peak metric(s) are low from sampling at {per_rev:.0} steps per revolution, by \
         at least {:.2} % ({name}: the grid shifted by a third of a step finds more); raise \
         motion.steps to at least {needed} for {} %",
        100.0 * error,
        100.0 * SAMPLING_TOLERANCE
    ))
}

/// The mean crank speed over the run, rad/s: the speed of a steady run, which the
/// speed-dependent gas models use.
fn mean_speed(case: &Case) -> f64 {
    match case.motion.at_angle(case.end_angle) {
        Ok(end) if end.time > 0.0 => (case.end_angle - case.motion.start_angle) / end.time,
        _ => case.motion.initial_speed,
    }
}

/// Runs one crank train of `case`: `mechanism` with its crank `shift` (rad) ahead of the
/// case's (the second train of a phased opposed-piston case; 0 otherwise), writing its
/// per-step files (named `label`, as `case.output` asks) into `dir` if given. Both trains'
/// pistons see the one chamber's pressure. With `dir` and `charts`, it also records the
/// series of the report's charts (thinned as it steps, see `report/envelope.rs`) and returns
/// them, so that the report need not read the CSV back, nor the CSV exist.
fn run_mechanism(
    case: &Case,
    mechanism: &dyn Mechanism,
    shift: f64,
    label: &str,
    dir: Option<&Path>,
    charts: bool,
) -> Result<(Summary, Option<ChartData>, Vec<String>), String> {
    let inertial = Inertial(Solver::ClosedForm);
    let gas_family = Gas(Solver::ClosedForm);
    let mut families: Vec<&dyn LoadFamily> = vec![&inertial];
    if case.gas.is_some() {
        families.push(&gas_family);
    }
    let names: Vec<&'static str> = families.iter().map(|f| f.name()).collect();
    let mut losses = match &case.friction {
        Some(f) => Some(
            LossBudget::new(f, mechanism, case.geometry.bore)
                .map_err(|e| format!("{}: {}", e.field, e.rule))?,
        ),
        None => None,
    };
    let loss_names = losses.as_ref().map_or(Vec::new(), |l| l.names().to_vec());
    let gears = match &case.gear {
        Some(spec) => {
            let ratings = GearRatings::new(spec, mechanism, case.friction.as_ref())
                .map_err(|e| format!("{}: {}", e.field, e.rule))?;
            (!ratings.names().is_empty()).then_some(ratings)
        }
        None => None,
    };
    let mut summary = SummarySink::new(mechanism, &names, case.steps + 1);
    if let Some(l) = &losses {
        summary = summary.with_losses(l.names());
    }
    if let Some(g) = &gears {
        summary = summary.with_gears(g);
    }
    let layout = RunLayout {
        families: &names,
        gas: case.gas.is_some(),
        losses: &loss_names,
        gears: gears.as_ref(),
    };
    let mut per_step = match dir {
        Some(dir) => PerStepSink::create(
            dir,
            label,
            mechanism,
            &layout,
            case.output,
            case.steps,
            charts,
        )
        .map_err(|e| format!("{e:#}"))?,
        None => None,
    };
    // Without files, the charts take their rows on their own, so that the run can be shared.
    let mut sinks = (
        summary,
        (per_step.is_none() && dir.is_some() && charts).then(|| {
            ChartSink::new(
                mechanism,
                &layout,
                case.output.decimation,
                case.steps,
                label,
            )
        }),
    );
    // A coarse grid's peaks are checked by the same run on the grid shifted by a third and by
    // two thirds of a step (summaries only).
    let revolutions = (case.end_angle - case.motion.start_angle) / std::f64::consts::TAU;
    let per_rev = case.steps as f64 / revolutions;
    let check_sampling = per_rev < SAMPLING_CHECK_STEPS_PER_REV;
    let mut shifted = Vec::new();
    let mut steps = |gas: Option<GasAt>| {
        let motion = CrankMotion {
            start_angle: case.motion.start_angle + shift,
            ..case.motion
        };
        let mut grid = Grid::new(
            motion,
            motion.start_angle,
            case.end_angle + shift,
            case.steps,
        );
        let stages = Stages {
            losses: losses.as_mut(),
            gears: gears.as_ref(),
        };
        // Without files the run is shared by the threads (the same results bit for bit); the
        // files are written in the steps' order, by a thread of their own.
        match per_step.as_mut() {
            Some(p) => run(
                mechanism,
                &mut grid,
                &families,
                gas,
                stages,
                &mut [&mut sinks.0, p],
            ),
            None => run_parallel(mechanism, &mut grid, &families, gas, stages, &mut sinks),
        }
        .map_err(|e| e.to_string())?;
        if check_sampling {
            let h = (case.end_angle - case.motion.start_angle) / case.steps as f64;
            let n = case.steps - 1;
            for third in [1.0, 2.0] {
                let a = motion.start_angle + third * h / 3.0;
                let mut grid = Grid::new(motion, a, a + n as f64 * h, n);
                let mut sink = SummarySink::new(mechanism, &names, n + 1).for_peaks();
                let stages = Stages::default();
                run_parallel(mechanism, &mut grid, &families, gas, stages, &mut sink)
                    .map_err(|e| format!("the run on the shifted grid (sampling check): {e}"))?;
                shifted.push(sink.finish(mechanism)?);
            }
        }
        Ok::<(), String>(())
    };
    let gas_metrics = match &case.gas {
        None => {
            steps(None)?;
            Vec::new()
        }
        Some(gas) => {
            let failed = |e: cardan_gas::GasError| format!("gas.{e}");
            let cylinder = gas
                .cylinder(case.geometry.bore, mechanism.stroke(), case.pistons)
                .map_err(failed)?;
            cylinder.with_phased_chamber(mechanism, case.crank_phase, |chamber| {
                let prepared = gas
                    .model()
                    .prepare(*chamber, mean_speed(case))
                    .map_err(failed)?;
                // The chamber's pressure is a function of the first train's crank angle.
                let at = |theta: f64| prepared.at(theta - shift);
                steps(Some(&at))?;
                Ok::<_, String>(prepared.metrics())
            })?
        }
    };
    let (summary, chart_rows) = sinks;
    let mut summary = summary.finish(mechanism)?;
    for m in gas_metrics {
        if !m.value.is_finite() {
            return Err(format!(
                "gas model metric {} is not finite ({})",
                m.name, m.value
            ));
        }
        summary.push(m.name, m.value);
    }
    if let Some(f) = &case.friction {
        // An engine's fmep and the whole-engine correlation beside it.
        for (name, value) in cardan_dynamics::engine_metrics(
            f,
            mechanism,
            case.geometry.bore,
            &case.motion,
            case.end_angle,
            &summary,
        ) {
            summary.push(name, value);
        }
    }
    // Every metric written is finite: a peak or an integral of finite steps can still
    // overflow (a crank speed of 1e150 rad/s), and summary.json would hold a null.
    if let Some(m) = summary.metrics.iter().find(|m| !m.value.is_finite()) {
        return Err(format!(
            "the summary's {} is not finite ({}): the run's numbers overflow or are undefined",
            m.name, m.value
        ));
    }
    let charts = match per_step {
        Some(p) => p
            .finish()
            .map_err(|e| format!("cannot write the per-step files: {e:#}"))?,
        None => chart_rows.and_then(ChartSink::finish),
    };
    let warnings = sampling_warning(&summary, &shifted, case.steps, per_rev)
        .into_iter()
        .collect();
    Ok((summary, charts, warnings))
}

/// Runs every mechanism of a case (in parallel), writing their per-step files into `dir` if
/// given (as the case's `[output]` asks).
/// A failure names the file, the case, the mechanism, and the step and quantity that went
/// wrong.
pub fn run_case(case: &Case, dir: Option<&Path>) -> Result<Vec<MechanismResult>, String> {
    let trains = run_trains(case, dir, false)?;
    Ok(trains.into_iter().map(|(r, _)| r).collect())
}

/// [`run_case`], with each crank train's chart series if `charts` (and `dir`) are given.
fn run_trains(
    case: &Case,
    dir: Option<&Path>,
    charts: bool,
) -> Result<Vec<(MechanismResult, Option<ChartData>)>, String> {
    // Each mechanism's crank train, and its second one in a phased opposed-piston case.
    let mut trains = Vec::new();
    for m in &case.mechanisms {
        trains.push((m, 0.0, m.name().to_string()));
        if case.crank_phase != 0.0 {
            trains.push((m, case.crank_phase, format!("{}_crank2", m.name())));
        }
    }
    let results: Vec<Result<(MechanismResult, Option<ChartData>), String>> = trains
        .par_iter()
        .map(|(m, shift, label)| {
            let (summary, series, warnings) =
                run_mechanism(case, m.as_ref(), *shift, label, dir, charts).map_err(|e| {
                    format!(
                        "{}: case \"{}\": {label}: {e}",
                        case.file.display(),
                        case.name
                    )
                })?;
            for w in &warnings {
                tracing::warn!(
                    "{}: case \"{}\": {label}: {w}",
                    case.file.display(),
                    case.name
                );
            }
            let result = MechanismResult {
                mechanism: Arc::clone(m),
                label: label.clone(),
                summary,
                warnings,
            };
            Ok((result, series))
        })
        .collect();
    // Every mechanism's failure, not only the first.
    let failures: Vec<String> = results
        .iter()
        .filter_map(|r| r.as_ref().err().cloned())
        .collect();
    if failures.is_empty() {
        Ok(results.into_iter().flatten().collect())
    } else {
        Err(failures.join("\n  "))
    }
}

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
    /// Writes the comparison reports ([`crate::report`]): one per case (not per sweep point),
    /// one per sweep, and `index.html` at the top of the output folder.
    pub reports: bool,
}

impl std::fmt::Debug for RunOptions {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("RunOptions")
            .field("jobs", &self.jobs)
            .field("csv", &self.csv)
            .field("npy", &self.npy)
            .field("only", &self.only)
            .field("reports", &self.reports)
            .finish_non_exhaustive()
    }
}

/// Whether `name` matches `pattern`: `*` matches any run of characters; a pattern without `*`
/// matches any name that contains it.
pub fn matches_pattern(pattern: &str, name: &str) -> bool {
    if !pattern.contains('*') {
        return name.contains(pattern);
    }
    let parts: Vec<&str> = pattern.split('*').collect();
    let (first, last) = (parts[0], parts[parts.len() - 1]);
    if !name.starts_with(first) || !name[first.len()..].ends_with(last) {
        return false;
    }
    let mut rest = &name[first.len()..name.len() - last.len()];
    for middle in &parts[1..parts.len() - 1] {
        match rest.find(middle) {
            Some(k) => rest = &rest[k + middle.len()..],
            None => return false,
        }
    }
    true
}

/// What a batch did.
#[derive(Debug, Default)]
pub struct Report {
    /// Cases run and written: (case name, output folder).
    pub written: Vec<(String, PathBuf)>,
    /// Each failure: a path that does not exist, a case file that could not be read or
    /// validated, a case that failed to run or could not be written.
    pub failures: Vec<String>,
}

/// Every `*.toml` file under `paths` (files, or folders searched recursively), sorted, and a
/// message for each path that cannot be read.
pub fn case_files(paths: &[PathBuf]) -> (Vec<PathBuf>, Vec<String>) {
    fn walk(dir: &Path, out: &mut Vec<PathBuf>) -> std::io::Result<()> {
        for entry in std::fs::read_dir(dir)? {
            let path = entry?.path();
            if path.is_dir() {
                walk(&path, out)?;
            } else if path.extension().is_some_and(|e| e == "toml") {
                out.push(path);
            }
        }
        Ok(())
    }
    let mut files = Vec::new();
    let mut failures = Vec::new();
    for p in paths {
        if p.is_dir() {
            let before = files.len();
            if let Err(e) = walk(p, &mut files) {
                failures.push(format!("{}: cannot list: {e}", p.display()));
            } else if files.len() == before {
                failures.push(format!(
                    "{}: no *.toml case files in this folder",
                    p.display()
                ));
            }
        } else if p.is_file() {
            files.push(p.clone());
        } else {
            failures.push(format!("{}: no such file or folder", p.display()));
        }
    }
    files.sort();
    files.dedup();
    (files, failures)
}

/// Reads and validates every case under `paths`; failures are listed, not fatal. Two cases
/// with one name would write one folder: the second is a failure.
pub fn load_cases(paths: &[PathBuf]) -> (Vec<Case>, Vec<String>) {
    let (files, mut failures) = case_files(paths);
    let loaded: Vec<Result<Vec<Case>, CaseError>> =
        files.par_iter().map(|f| case::load_file(f)).collect();
    let mut cases: Vec<Case> = Vec::new();
    // Output folders taken: a case's name, or a sweep's (its points go inside it).
    let mut folders: std::collections::HashMap<String, PathBuf> = std::collections::HashMap::new();
    for result in loaded {
        let batch = match result {
            Ok(batch) => batch,
            Err(e) => {
                failures.push(e.to_string());
                continue;
            }
        };
        let Some(first) = batch.first() else { continue };
        let folder = first
            .sweep
            .as_ref()
            .map_or(first.name.clone(), |(s, _)| s.clone());
        if let Some(other) = folders.get(&folder) {
            failures.push(format!(
                "{}: case \"{}\": name = \"{folder}\": is already the name of the case in {}; each case needs its own output folder",
                first.file.display(),
                folder,
                other.display()
            ));
            continue;
        }
        folders.insert(folder, first.file.clone());
        cases.extend(batch);
    }
    (cases, failures)
}

/// Runs one case into `out/<case name>/`, replacing that folder as a whole.
fn run_and_write(
    case: &Case,
    out: &Path,
    options: &RunOptions,
) -> Result<(PathBuf, Vec<MechanismResult>), String> {
    let dir = out.join(&case.name);
    let cannot_write = |e: anyhow::Error| {
        format!(
            "{}: case \"{}\": cannot write results to {}: {e:#}",
            case.file.display(),
            case.name,
            dir.display()
        )
    };
    let tmp = output::temporary_dir(&dir).map_err(cannot_write)?;
    // A sweep's points are reported by the sweep's report: no charts of their own.
    let report = options.reports && case.sweep.is_none();
    let result = run_trains(case, Some(&tmp), report).and_then(|trains| {
        // The chart series go to the report, and are dropped with it: a batch keeps only
        // the summaries.
        let (results, series): (Vec<MechanismResult>, Vec<Option<ChartData>>) =
            trains.into_iter().unzip();
        let charts: std::collections::BTreeMap<String, ChartData> = results
            .iter()
            .zip(series)
            .filter_map(|(r, s)| Some((r.label.clone(), s?)))
            .collect();
        let mut summary = serde_json::to_string_pretty(&output::summary_json(case, &results))
            .map_err(|e| e.to_string())?;
        summary.push('\n');
        output::write_file(&tmp.join("summary.json"), summary.as_bytes())
            .and_then(|()| {
                if report {
                    crate::report::case_report_from_run(&tmp, None, charts)
                        .context("the report")?;
                }
                output::replace_dir(&tmp, &dir)
            })
            .map_err(cannot_write)?;
        Ok(results)
    });
    if result.is_err() {
        let _ = std::fs::remove_dir_all(&tmp);
    }
    result.map(|results| (dir, results))
}

/// `sweep.csv`: one row per written point: its name, the value of each swept field, then every
/// summary metric of every mechanism (`<mechanism>.<metric>`, in SI, units in `summary.json`).
fn sweep_csv(points: &[(&Case, &[MechanismResult])]) -> String {
    // The columns in the order they first appear, each found by a hash of its name: a sweep of
    // 10 000 points has some 200 columns, which a search through the list per metric and point
    // took a noticeable part of the sweep's time to match.
    let mut columns: Vec<(String, String)> = Vec::new();
    let mut index: HashMap<(&str, &str), usize> = HashMap::new();
    for (_, results) in points {
        for r in *results {
            for m in &r.summary.metrics {
                index
                    .entry((r.label.as_str(), m.name.as_str()))
                    .or_insert_with(|| {
                        columns.push((r.label.clone(), m.name.clone()));
                        columns.len() - 1
                    });
            }
        }
    }
    let swept: Vec<String> = points
        .first()
        .and_then(|(c, _)| c.sweep.as_ref())
        .map(|(_, v)| v.iter().map(|(p, _)| p.clone()).collect())
        .unwrap_or_default();
    let mut w = csv::Writer::from_writer(Vec::new());
    let mut header = vec!["case".to_string()];
    header.extend(swept.iter().cloned());
    header.extend(columns.iter().map(|(m, k)| format!("{m}.{k}")));
    let _ = w.write_record(&header);
    let mut buffer = zmij::Buffer::new();
    for (case, results) in points {
        let mut row = vec![case.name.clone()];
        row.extend(
            case.sweep
                .iter()
                .flat_map(|(_, v)| v.iter().map(|(_, x)| x.clone())),
        );
        let mut values = vec![None; columns.len()];
        for r in *results {
            for m in &r.summary.metrics {
                // The first of a name, as a search from the start would find.
                let slot = &mut values[index[&(r.label.as_str(), m.name.as_str())]];
                slot.get_or_insert(m.value);
            }
        }
        row.extend(
            values
                .into_iter()
                .map(|v| v.map_or(String::new(), |v| buffer.format(v).to_string())),
        );
        let _ = w.write_record(&row);
    }
    String::from_utf8(w.into_inner().unwrap_or_default()).unwrap_or_default()
}

/// Loads, validates, runs and writes every case under `paths` (or those `options.only`
/// selects) into `out/<case name>/`. A panic inside a case is caught and reported as that
/// case's failure.
pub fn run_paths(paths: &[PathBuf], out: &Path, options: RunOptions) -> Report {
    let (mut cases, failures) = load_cases(paths);
    if let Some(pattern) = &options.only {
        cases.retain(|c| matches_pattern(pattern, &c.name));
    }
    for case in &mut cases {
        case.output.csv = options.csv.unwrap_or(case.output.csv);
        case.output.npy = options.npy.unwrap_or(case.output.npy);
    }
    let done = std::sync::atomic::AtomicUsize::new(0);
    let mut report = Report {
        failures,
        ..Report::default()
    };
    // A sweep's points run into a temporary folder that replaces `out/<sweep>` as a whole.
    let mut sweeps: std::collections::BTreeMap<String, Option<PathBuf>> = Default::default();
    for case in &cases {
        if let Some((sweep, _)) = &case.sweep {
            if !sweeps.contains_key(sweep) {
                let tmp = output::temporary_dir(&out.join(sweep));
                if let Err(e) = &tmp {
                    report.failures.push(format!(
                        "{}: sweep \"{sweep}\": cannot write results to {}: {e:#}",
                        case.file.display(),
                        out.join(sweep).display()
                    ));
                }
                sweeps.insert(sweep.clone(), tmp.ok());
            }
        }
    }
    cases.retain(|c| match &c.sweep {
        Some((sweep, _)) => sweeps.get(sweep).is_some_and(Option::is_some),
        None => true,
    });
    let total = cases.len();
    let base = |case: &Case| -> PathBuf {
        match &case.sweep {
            Some((sweep, _)) => sweeps[sweep].clone().expect("kept only with a folder"),
            None => out.to_path_buf(),
        }
    };
    type Outcome = Result<(String, PathBuf, Vec<MechanismResult>), String>;
    let work = || -> Vec<Outcome> {
        cases
            .par_iter()
            .map(|case| {
                let _span = tracing::info_span!("case", name = %case.name).entered();
                let outcome = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
                    run_and_write(case, &base(case), &options)
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
    let outcomes = match options.jobs {
        Some(n) => match rayon::ThreadPoolBuilder::new().num_threads(n).build() {
            Ok(pool) => pool.install(work),
            Err(e) => {
                report
                    .failures
                    .push(format!("cannot start {n} worker threads: {e}"));
                return report;
            }
        },
        None => work(),
    };
    let mut points: std::collections::BTreeMap<&str, Vec<(&Case, &[MechanismResult])>> =
        Default::default();
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
            Err(e) => report.failures.push(e.clone()),
        }
    }
    for (sweep, tmp) in &sweeps {
        let Some(tmp) = tmp else { continue };
        let rows = points.get(sweep.as_str()).map_or(&[][..], Vec::as_slice);
        let written = output::write_file(&tmp.join("sweep.csv"), sweep_csv(rows).as_bytes())
            .and_then(|()| {
                if options.reports && !rows.is_empty() {
                    crate::report::sweep_report(tmp, sweep, None).context("the sweep report")?;
                }
                output::replace_dir(tmp, &out.join(sweep))
            });
        if let Err(e) = written {
            let _ = std::fs::remove_dir_all(tmp);
            report.failures.push(format!(
                "sweep \"{sweep}\": cannot write results to {}: {e:#}",
                out.join(sweep).display()
            ));
        }
    }
    if options.reports && !report.written.is_empty() {
        if let Err(e) = crate::report::index(out) {
            report.failures.push(format!(
                "cannot write {}: {e:#}",
                out.join("index.html").display()
            ));
        }
    }
    report
}

#[cfg(test)]
mod tests {
    use super::matches_pattern;

    #[test]
    fn patterns_select_case_names() {
        assert!(matches_pattern("w30pi", "karhula-pump-r60-l140-a0-w30pi"));
        assert!(!matches_pattern("w3pi", "karhula-pump-r60-l140-a0-w30pi"));
        assert!(matches_pattern(
            "karhula-*-w3pi",
            "karhula-pump-r60-l140-a0-w3pi"
        ));
        assert!(matches_pattern("*", "anything"));
        assert!(matches_pattern("k*a*i", "karhula-pi"));
        assert!(!matches_pattern("karhula-*-w3pi", "karhula-pump-w30pi"));
        assert!(!matches_pattern("nunes*", "karhula"));
    }
}
