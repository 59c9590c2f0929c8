//! Running validated cases in memory, for callers that want numbers rather than folders (the
//! Python package, `python/`): a case's `summary.json` as the command line writes it and each
//! crank train's per-step columns ([`run_in_memory`]), and the points of a sweep in parallel
//! with the table of `sweep.csv` ([`run_sweep`], [`SweepTable`]). Nothing is written; the runs
//! are the batch's ([`crate::run_case`]), so the numbers are the files' bit for bit.

use crate::output::{summary_json, MechanismResult};
use crate::per_step::StepColumns;
use crate::run::train::{run_trains, StepsTo};
use cardan_case::case::Case;
use cardan_dynamics::RunRooms;
use rayon::prelude::*;
use std::collections::HashMap;

/// A case run in memory.
#[derive(Debug, Clone)]
pub struct CaseRun {
    /// The case's `summary.json`, as [`summary_json`] makes it for the command line.
    pub summary: serde_json::Value,
    /// Each crank train's result (its label, summary and warnings), in `summary.json`'s order.
    pub results: Vec<MechanismResult>,
    /// Each crank train's per-step columns, in the same order (empty unless asked).
    pub steps: Vec<StepColumns>,
}

/// The message of a panic caught while running `case`, as the batch says it.
fn panicked(case: &Case, panic: &(dyn std::any::Any + Send)) -> String {
    let message = panic
        .downcast_ref::<String>()
        .map(String::as_str)
        .or_else(|| panic.downcast_ref::<&str>().copied())
        .unwrap_or("panic");
    format!(
        "{}: case \"{}\": internal error (a bug, please report it): {message}",
        case.file.display(),
        case.name
    )
}

/// Runs every crank train of `case` (in parallel) without writing anything; with `steps`, keeps
/// each train's per-step rows as columns (every `case.output.decimation`-th step and the last,
/// the rows the per-step files would hold; memory grows with them), else shares each run among
/// the threads. A failure (a panic included) is the message the batch would give.
pub fn run_in_memory(case: &Case, steps: bool) -> Result<CaseRun, String> {
    run_in_rooms(case, steps, &RunRooms::default())
}

/// [`run_in_memory`] in blocks of `rooms`.
fn run_in_rooms(case: &Case, steps: bool, rooms: &RunRooms) -> Result<CaseRun, String> {
    let to = if steps {
        StepsTo::Memory
    } else {
        StepsTo::Summary
    };
    let trains =
        std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| run_trains(case, to, rooms)))
            .map_err(|panic| panicked(case, panic.as_ref()))??;
    let (results, rows): (Vec<MechanismResult>, Vec<_>) = trains.into_iter().unzip();
    crate::run::train::log_warnings(case, &results);
    Ok(CaseRun {
        summary: summary_json(case, &results),
        steps: rows.into_iter().filter_map(|r| r.columns).collect(),
        results,
    })
}

/// Runs the summaries of every case of `cases` (a sweep's points) in parallel, each case's
/// failure (a panic included) its own: one failing point never stops the others.
pub fn run_sweep(cases: &[Case]) -> Vec<Result<Vec<MechanismResult>, String>> {
    // The points' runs take one another's blocks instead of each making its own.
    let rooms = RunRooms::default();
    cases
        .par_iter()
        .map(|case| run_in_rooms(case, false, &rooms).map(|run| run.results))
        .collect()
}

/// The table of a sweep's points, column by column: the columns of `sweep.csv` (the point's
/// name, the value of each swept field as written, then every summary metric of every crank
/// train, `<label>.<metric>`, in SI, in the order they first appear; those of `[output]
/// metrics` if given), a metric a point lacks NaN.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct SweepTable {
    /// Each point's case name.
    pub case: Vec<String>,
    /// Each swept field's dotted path and its value at each point, as written.
    pub swept: Vec<(String, Vec<String>)>,
    /// Each metric's column name and its value at each point.
    pub metrics: Vec<(String, Vec<f64>)>,
}

impl SweepTable {
    /// The table of `points`: each point's case and results.
    pub fn new(points: &[(&Case, &[MechanismResult])]) -> Self {
        let mut table = SweepTable::default();
        if let Some((case, _)) = points.first() {
            for (path, _) in case.sweep.iter().flat_map(|(_, v)| v) {
                table.swept.push((path.clone(), Vec::new()));
            }
        }
        let mut index: HashMap<(&str, &str), usize> = HashMap::new();
        for (row, (case, results)) in points.iter().enumerate() {
            table.case.push(case.name.clone());
            let values = case.sweep.iter().flat_map(|(_, v)| v);
            for ((_, column), (_, value)) in table.swept.iter_mut().zip(values) {
                column.push(value.clone());
            }
            let only = case.table_metrics.as_deref();
            for r in *results {
                let wanted = r.summary.metrics.iter();
                for m in wanted.filter(|m| only.is_none_or(|o| o.contains(&m.name))) {
                    let k = *index
                        .entry((r.label.as_str(), m.name.as_str()))
                        .or_insert_with(|| {
                            let name = format!("{}.{}", r.label, m.name);
                            table.metrics.push((name, vec![f64::NAN; row]));
                            table.metrics.len() - 1
                        });
                    // The first of a name, as sweep.csv takes it.
                    let column = &mut table.metrics[k].1;
                    if column.len() == row {
                        column.push(m.value);
                    }
                }
            }
            for (_, column) in &mut table.metrics {
                column.resize(row + 1, f64::NAN);
            }
        }
        table
    }
}
