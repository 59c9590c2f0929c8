//! Running cases: every mechanism of every case in parallel, each step streamed to its sinks;
//! one failure (an error or a panic) never stops the rest.

use crate::output;
use crate::per_step::{ChartSink, PerStepSink, RunLayout};
use crate::report::ChartData;
use anyhow::Context;
use cardan_case::case::{self, Case, CaseError};
use cardan_dynamics::stepper::GasAt;
use cardan_dynamics::{
    run, run_parallel, Gas, GearRatings, Inertial, LoadFamily, LossBudget, Solver, Stage, Summary,
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

/// Steps per crank revolution below which a run estimates its peaks' sampling error: from a 1°
/// grid on, the error of a peak of a smooth load, about (Δθ·k)²/8 for its k-th harmonic, is
/// under [`SAMPLING_TOLERANCE`] for the orders a crank mechanism has (k ≤ 4: 6·10⁻⁴), and so it
/// is for the sharpest shipped load, the Karhula engine's combustion (measured at 1° against
/// 0.1°: 4.2·10⁻⁴ on the slider-crank's peak gas force). The check costs two summary runs.
const SAMPLING_CHECK_STEPS_PER_REV: f64 = 360.0 - 1e-9;

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

/// The stages of `mechanism` in `case`, as its run takes them: the gear ratings, then the loss
/// budget (which takes their mesh losses).
fn stages_of(case: &Case, mechanism: &dyn Mechanism) -> Result<Vec<Box<dyn Stage>>, String> {
    let losses = match &case.friction {
        Some(f) => Some(
            LossBudget::new(f, mechanism, case.geometry.bore)
                .map_err(|e| format!("{}: {}", e.field, e.rule))?,
        ),
        None => None,
    };
    let gears = match &case.gear {
        Some(spec) => {
            let ratings = GearRatings::new(spec, mechanism, case.friction.as_ref())
                .map_err(|e| format!("{}: {}", e.field, e.rule))?;
            (!ratings.names().is_empty()).then_some(ratings)
        }
        None => None,
    };
    let gears = gears.map(|g| Box::new(g) as Box<dyn Stage>);
    Ok(gears
        .into_iter()
        .chain(losses.map(|l| Box::new(l) as _))
        .collect())
}

/// The largest size of a case's per-step files, in bytes, unless a run is allowed more
/// ([`RunOptions::max_bytes`], `--allow-large`): 10 GB.
pub const DEFAULT_MAX_BYTES: u64 = 10_000_000_000;

/// Bytes a CSV value takes, comma included, when written as the shortest text that reads
/// back (`-1.2345678901234567e-100`: at most 24).
const CSV_BYTES_SHORTEST: u64 = 24;

/// More per-step columns than any crank train has (a pump case with gas and friction has about
/// 100 per mechanism): a bound that spares counting them for a case far below the limit.
const PLENTY_OF_COLUMNS: u64 = 4096;

/// An estimate of the bytes of the per-step files `case` writes (as its `[output]` asks):
/// rows × columns × bytes per value (8 in NPY, the digits asked plus sign, point, exponent and
/// comma in CSV), over every crank train; and that as a sentence.
pub fn estimated_bytes(case: &Case) -> Result<(u64, String), String> {
    let o = case.output;
    if !(o.csv || o.npy) {
        return Ok((0, "no per-step file".into()));
    }
    let rows = crate::per_step::row_count(case.steps, o.decimation) as u64;
    let mut names = vec![Inertial(Solver::ClosedForm).name()];
    if case.gas.is_some() {
        names.push(Gas(Solver::ClosedForm).name());
    }
    let csv_bytes = o
        .significant_digits
        .map_or(CSV_BYTES_SHORTEST, |d| d as u64 + 7);
    let per_value = u64::from(o.npy) * 8 + u64::from(o.csv) * csv_bytes;
    let trains = if case.crank_phase != 0.0 { 2 } else { 1 };
    let mut columns = 0u64;
    for m in &case.mechanisms {
        let stages = stages_of(case, m.as_ref())?;
        let layout = RunLayout {
            families: &names,
            gas: case.gas.is_some(),
            stages: &stages.iter().map(|s| s.columns()).collect::<Vec<_>>(),
        };
        columns += trains
            * crate::per_step::Row::new(m.as_ref(), &layout)
                .header()
                .len() as u64;
    }
    let bytes = rows.saturating_mul(columns).saturating_mul(per_value);
    let what = [(o.csv, "CSV"), (o.npy, "NPY")]
        .iter()
        .filter(|(on, _)| *on)
        .map(|(_, n)| *n)
        .collect::<Vec<_>>()
        .join(" + ");
    Ok((
        bytes,
        format!(
            "about {} ({rows} rows x {columns} columns in all x {per_value} bytes per value, {what})",
            human_bytes(bytes)
        ),
    ))
}

/// `bytes` as "12.3 GB" (powers of 1000).
pub fn human_bytes(bytes: u64) -> String {
    let b = bytes as f64;
    for (unit, scale) in [("TB", 1e12), ("GB", 1e9), ("MB", 1e6), ("kB", 1e3)] {
        if b >= scale {
            return format!("{:.1} {unit}", b / scale);
        }
    }
    format!("{bytes} B")
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
    let mut stages = stages_of(case, mechanism)?;
    let listed: Vec<&dyn Stage> = stages.iter().map(|s| s.as_ref()).collect();
    let summary = SummarySink::new(mechanism, &names, case.steps + 1).with_stages(&listed);
    let columns: Vec<_> = stages.iter().map(|s| s.columns()).collect();
    let layout = RunLayout {
        families: &names,
        gas: case.gas.is_some(),
        stages: &columns,
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
        let mut stages: Vec<&mut dyn Stage> = stages
            .iter_mut()
            .map(|s| &mut **s as &mut dyn Stage)
            .collect();
        // Without files the run is shared by the threads (the same results bit for bit); the
        // files are written in the steps' order, by a thread of their own.
        match per_step.as_mut() {
            Some(p) => run(
                mechanism,
                &mut grid,
                &families,
                gas,
                &mut stages,
                &mut [&mut sinks.0, p],
            ),
            None => run_parallel(
                mechanism,
                &mut grid,
                &families,
                gas,
                &mut stages,
                &mut sinks,
            ),
        }
        .map_err(|e| e.to_string())?;
        if check_sampling {
            let h = (case.end_angle - case.motion.start_angle) / case.steps as f64;
            let n = case.steps - 1;
            for third in [1.0, 2.0] {
                let a = motion.start_angle + third * h / 3.0;
                let mut grid = Grid::new(motion, a, a + n as f64 * h, n);
                let mut sink = SummarySink::new(mechanism, &names, n + 1).for_peaks();
                run_parallel(mechanism, &mut grid, &families, gas, &mut [], &mut sink)
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
    /// The largest estimated size of a case's per-step files, in bytes (None:
    /// [`DEFAULT_MAX_BYTES`]); a larger case is refused.
    pub max_bytes: Option<u64>,
    /// Runs cases of any size (`--allow-large`).
    pub allow_large: bool,
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
            .field("max_bytes", &self.max_bytes)
            .field("allow_large", &self.allow_large)
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
    /// Each sweep written: its name, its folder and how many of its points this run wrote
    /// (each point is also in `written`).
    pub sweeps: Vec<(String, PathBuf, usize)>,
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

/// Names an output folder uses itself, which no case or sweep may take.
pub const RESERVED: &[&str] = &["index.html"];

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
        if RESERVED.contains(&folder.as_str()) {
            failures.push(format!(
                "{}: case \"{}\": name = \"{folder}\": is reserved: the output folder's own file of that name ({}); give the case another name",
                first.file.display(),
                folder,
                RESERVED.join(", ")
            ));
            continue;
        }
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
    if let Ok(meta) = dir.symlink_metadata() {
        if !meta.is_dir() {
            return Err(format!(
                "{}: case \"{}\": {} is a file, not a case folder: it is not replaced; move it away or rename the case",
                case.file.display(),
                case.name,
                dir.display()
            ));
        }
    }
    if !options.allow_large {
        let limit = options.max_bytes.unwrap_or(DEFAULT_MAX_BYTES);
        // Most cases are far below the limit whatever their columns: no need to count them.
        let rows = crate::per_step::row_count(case.steps, case.output.decimation) as u64;
        let csv_bytes = case
            .output
            .significant_digits
            .map_or(CSV_BYTES_SHORTEST, |d| CSV_BYTES_SHORTEST.max(d as u64 + 7));
        let bound = rows
            .saturating_mul(case.mechanisms.len() as u64 * 2 * PLENTY_OF_COLUMNS)
            .saturating_mul(8 + csv_bytes);
        let (bytes, estimate) = if bound <= limit {
            (0, String::new())
        } else {
            estimated_bytes(case)
                .map_err(|e| format!("{}: case \"{}\": {e}", case.file.display(), case.name))?
        };
        if bytes > limit {
            return Err(format!(
                "{}: case \"{}\": output: would write {estimate} of per-step files, more than the limit of {}: refused (thin it with [output] decimation, write fewer files, or pass --allow-large)",
                case.file.display(),
                case.name,
                human_bytes(limit)
            ));
        }
    }
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

/// Where a sweep's selected points are written.
enum SweepTarget {
    /// Into this temporary folder, which then replaces `out/<sweep>` as a whole.
    Whole(PathBuf),
    /// Into the existing `out/<sweep>` itself, each point's folder replaced on its own, its
    /// `sweep.csv` (and report) then rewritten to hold every point the folder holds: an
    /// `--only` run of some points of a sweep written before.
    Update,
}

/// The swept fields' columns of an existing `sweep.csv` (after `case`), for `want` of them.
fn swept_columns(csv_path: &Path, want: usize) -> anyhow::Result<Vec<String>> {
    let mut r =
        csv::Reader::from_path(csv_path).with_context(|| format!("read {}", csv_path.display()))?;
    let header = r.headers()?.clone();
    Ok(header.iter().skip(1).take(want).map(String::from).collect())
}

/// The `sweep.csv` of the sweep folder `dir` after an `--only` run wrote `fresh` (the rows of
/// its points, as [`sweep_csv`] makes them): the earlier rows of the points not re-run, the
/// fresh rows of those re-run, each row only if its point's folder holds a `summary.json`, in
/// the sweep's point order (`order`), then any other point the folder holds.
fn merged_sweep_csv(dir: &Path, fresh: &str, order: &[String]) -> anyhow::Result<String> {
    let mut columns: Vec<String> = Vec::new();
    let mut rows: Vec<(String, HashMap<String, String>)> = Vec::new();
    let mut read = |r: &mut csv::Reader<&[u8]>| -> anyhow::Result<()> {
        let header: Vec<String> = r.headers()?.iter().map(String::from).collect();
        for h in &header {
            if !columns.contains(h) {
                columns.push(h.clone());
            }
        }
        for record in r.records() {
            let record = record?;
            let name = record.get(0).unwrap_or_default().to_string();
            let values = header
                .iter()
                .cloned()
                .zip(record.iter().map(String::from))
                .collect();
            match rows.iter_mut().find(|(n, _)| *n == name) {
                Some(row) => row.1 = values,
                None => rows.push((name, values)),
            }
        }
        Ok(())
    };
    let earlier = std::fs::read(dir.join("sweep.csv"))
        .with_context(|| format!("read {}", dir.join("sweep.csv").display()))?;
    read(&mut csv::Reader::from_reader(&earlier[..]))?;
    read(&mut csv::Reader::from_reader(fresh.as_bytes()))?;
    rows.retain(|(name, _)| dir.join(name).join("summary.json").is_file());
    let position: HashMap<&str, usize> = order
        .iter()
        .enumerate()
        .map(|(k, n)| (n.as_str(), k))
        .collect();
    rows.sort_by_key(|(name, _)| position.get(name.as_str()).copied().unwrap_or(usize::MAX));
    let mut w = csv::Writer::from_writer(Vec::new());
    w.write_record(&columns)?;
    for (_, values) in &rows {
        w.write_record(
            columns
                .iter()
                .map(|c| values.get(c).map_or("", String::as_str)),
        )?;
    }
    Ok(String::from_utf8(w.into_inner()?)?)
}

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
    output::remove_stale_temporaries(out);
    let mut selected: HashMap<&str, usize> = HashMap::new();
    for c in &cases {
        if let Some((sweep, _)) = &c.sweep {
            *selected.entry(sweep.as_str()).or_default() += 1;
        }
    }
    let done = std::sync::atomic::AtomicUsize::new(0);
    // A sweep's points run into a temporary folder that replaces `out/<sweep>` as a whole, or,
    // when `--only` selects some of the points of a sweep written before, into its folder.
    let mut sweeps: std::collections::BTreeMap<String, Option<SweepTarget>> = Default::default();
    for case in &cases {
        let Some((sweep, values)) = &case.sweep else {
            continue;
        };
        if sweeps.contains_key(sweep) {
            continue;
        }
        let dir = out.join(sweep);
        let some = selected[sweep.as_str()] < all_points[sweep].len();
        let target = if some && dir.join("sweep.csv").is_file() {
            output::remove_stale_temporaries(&dir);
            let swept: Vec<String> = values.iter().map(|(p, _)| p.clone()).collect();
            match swept_columns(&dir.join("sweep.csv"), swept.len()) {
                Ok(columns) if columns == swept => Ok(SweepTarget::Update),
                Ok(columns) => Err(anyhow::anyhow!(
                    "its folder holds a sweep over {columns:?}, this one is over {swept:?}: --only cannot update some of its points; run the whole sweep"
                )),
                Err(e) => Err(e),
            }
        } else {
            output::temporary_dir(&dir).map(SweepTarget::Whole)
        };
        if let Err(e) = &target {
            report.failures.push(format!(
                "{}: sweep \"{sweep}\": cannot write results to {}: {e:#}",
                case.file.display(),
                dir.display()
            ));
        }
        sweeps.insert(sweep.clone(), target.ok());
    }
    cases.retain(|c| match &c.sweep {
        Some((sweep, _)) => sweeps.get(sweep).is_some_and(Option::is_some),
        None => true,
    });
    let total = cases.len();
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
    for (sweep, target) in &sweeps {
        let Some(target) = target else { continue };
        let dir = out.join(sweep);
        let rows = points.get(sweep.as_str()).map_or(&[][..], Vec::as_slice);
        let written = match target {
            // Every point failed: the earlier sweep folder, if any, stays.
            SweepTarget::Whole(tmp) if rows.is_empty() && failed.contains_key(sweep.as_str()) => {
                let _ = std::fs::remove_dir_all(tmp);
                continue;
            }
            SweepTarget::Whole(tmp) => {
                output::write_file(&tmp.join("sweep.csv"), sweep_csv(rows).as_bytes())
                    .and_then(|()| {
                        if options.reports && !rows.is_empty() {
                            crate::report::sweep_report(tmp, sweep, None)
                                .context("the sweep report")?;
                        }
                        output::replace_dir(tmp, &dir)
                    })
                    .inspect_err(|_| {
                        let _ = std::fs::remove_dir_all(tmp);
                    })
            }
            SweepTarget::Update if rows.is_empty() => continue,
            SweepTarget::Update => {
                merged_sweep_csv(&dir, &sweep_csv(rows), &all_points[sweep])
                    .and_then(|csv| {
                        output::write_file_replacing(&dir.join("sweep.csv"), csv.as_bytes())
                    })
                    .and_then(|()| {
                        // The sweep's report, if asked or already there: never one of old points.
                        if options.reports || dir.join("report.html").is_file() {
                            crate::report::sweep_report(&dir, sweep, None)
                                .context("the sweep report")?;
                        }
                        Ok(())
                    })
            }
        };
        match written {
            Ok(()) => report.sweeps.push((sweep.clone(), dir, rows.len())),
            Err(e) => report.failures.push(format!(
                "sweep \"{sweep}\": cannot write results to {}: {e:#}",
                dir.display()
            )),
        }
    }
    // The index describes what the folder holds: rewritten whenever that changes, also by a
    // run that writes no reports (else it links reports that are gone, with old numbers).
    let changed = !report.written.is_empty() || !report.sweeps.is_empty();
    let index = out.join("index.html");
    if changed && (options.reports || index.symlink_metadata().is_ok()) {
        if let Err(e) = crate::report::index(out) {
            report
                .failures
                .push(format!("cannot write {}: {e:#}", index.display()));
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
