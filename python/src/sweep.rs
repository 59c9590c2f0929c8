//! `cardan.sweep`'s native part: a sweep's points made and validated one by one (a point that
//! fails validation is that point's failure, as a run's failure is, when the caller keeps
//! going), run in parallel with the GIL released, and gathered into the columns of `sweep.csv`.

use crate::{case_error, convert, given, CaseError, RunError};
use cardan_case::case::point_case;
use cardan_case::sweep::{Sweep, MAX_EXPANDED};
use cardan_case::Case;
use cardan_runner::memory::{run_in_memory, SweepTable};
use cardan_runner::output::MechanismResult;
use numpy::PyArray1;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};
use rayon::prelude::*;
use std::collections::HashMap;
use std::path::Path;

/// A sweep's points run: every point's name and swept values, the metrics of the points that
/// ran (NaN elsewhere), each metric's unit, each point's failure.
struct Points {
    names: Vec<String>,
    swept: Vec<(String, Vec<String>)>,
    metrics: Vec<(String, Vec<f64>)>,
    units: Vec<(String, &'static str)>,
    errors: Vec<Option<String>>,
}

/// Runs a sweep: `case` with `fields` (`{dotted path: list or {from, to, points, scale}}`, as a
/// case file's `[sweep]`; none: the case's own `[sweep]`) in `mode` ("grid" or "zip"), the
/// points in parallel, the GIL released. A point that does not validate raises `CaseError`
/// (the first in the points' order) before any runs, unless `keep_going`: then it is that
/// point's failure. Returns `(case names, [(swept path, [value as written])],
/// {"<label>.<metric>": array}, {"<label>.<metric>": unit}, [error or None per point])`.
#[pyfunction]
#[pyo3(signature = (case, fields = None, mode = "grid", keep_going = false))]
#[allow(clippy::type_complexity)]
pub fn sweep<'py>(
    py: Python<'py>,
    case: &Bound<'py, PyAny>,
    fields: Option<&Bound<'py, PyDict>>,
    mode: &str,
    keep_going: bool,
) -> PyResult<(
    Vec<String>,
    Bound<'py, PyList>,
    Bound<'py, PyDict>,
    Bound<'py, PyDict>,
    Vec<Option<String>>,
)> {
    let mut g = given(case, "case")?;
    if let Some(fields) = fields {
        let mut table = toml::Table::new();
        table.insert("mode".into(), toml::Value::String(mode.into()));
        for (k, v) in fields.iter() {
            let path: String = k.extract().map_err(|_| {
                CaseError::new_err("a swept field is named by its dotted path, a str")
            })?;
            let values = convert::to_toml(&v, &format!("sweep.\"{path}\""))?;
            table.insert(path, values);
        }
        g.table.insert("sweep".into(), toml::Value::Table(table));
    } else if !g.table.contains_key("sweep") {
        return Err(CaseError::new_err(format!(
            "{}: no fields to sweep and no [sweep] in the case",
            g.file.display()
        )));
    }
    let points = py.detach(|| {
        std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
            run_points(&g.file, g.table, keep_going)
        }))
        .unwrap_or_else(|_| {
            Err(RunError::new_err(
                "internal error running the sweep (a bug, please report it)",
            ))
        })
    })?;
    let swept = PyList::empty(py);
    for (path, values) in points.swept {
        swept.append((path, values))?;
    }
    let metrics = PyDict::new(py);
    for (name, values) in points.metrics {
        metrics.set_item(name, PyArray1::from_vec(py, values))?;
    }
    let units = PyDict::new(py);
    for (name, unit) in points.units {
        units.set_item(name, unit)?;
    }
    Ok((points.names, swept, metrics, units, points.errors))
}

/// Makes, validates and runs every point of the sweep in `table` (which has a `[sweep]`).
fn run_points(file: &Path, table: toml::Table, keep_going: bool) -> PyResult<Points> {
    let sweep = Sweep::define(file, table)
        .map_err(case_error)?
        .ok_or_else(|| CaseError::new_err("no [sweep] in the case"))?;
    let n = sweep.len();
    if n > MAX_EXPANDED {
        return Err(CaseError::new_err(format!(
            "{}: sweep \"{}\": {n} points: at most {MAX_EXPANDED} run in memory; run a larger \
             sweep with `cardan run` as a table (`[output] case_folders = false`)",
            file.display(),
            sweep.name
        )));
    }
    let cases: Vec<Result<Case, String>> = (0..n)
        .into_par_iter()
        .map(|k| point_case(&sweep, k).map_err(|e| e.to_string()))
        .collect();
    if !keep_going {
        if let Some(Err(e)) = cases.iter().find(|c| c.is_err()) {
            return Err(CaseError::new_err(e.clone()));
        }
    }
    let outcomes: Vec<Result<(Case, Vec<MechanismResult>), String>> = cases
        .into_par_iter()
        .map(|case| {
            let case = case?;
            let results = run_in_memory(&case, false)?.results;
            Ok((case, results))
        })
        .collect();
    let mut rows = Vec::new();
    let mut ran = Vec::new();
    let mut errors = Vec::with_capacity(n);
    for (k, outcome) in outcomes.iter().enumerate() {
        match outcome {
            Ok((case, results)) => {
                rows.push(k);
                ran.push((case, results.as_slice()));
                errors.push(None);
            }
            Err(e) => errors.push(Some(e.clone())),
        }
    }
    // The table of the points that ran (a point that failed adds no metric), spread over every
    // point's row.
    let table = SweepTable::new(&ran);
    let metrics: Vec<(String, Vec<f64>)> = table
        .metrics
        .into_iter()
        .map(|(name, values)| {
            let mut column = vec![f64::NAN; n];
            for (&row, value) in rows.iter().zip(values) {
                column[row] = value;
            }
            (name, column)
        })
        .collect();
    let units = units_of(&metrics, &ran);
    let paths = sweep.paths();
    let mut swept: Vec<(String, Vec<String>)> = paths
        .iter()
        .map(|p| (p.to_string(), Vec::with_capacity(n)))
        .collect();
    let mut names = Vec::with_capacity(n);
    for k in 0..n {
        names.push(sweep.point_name(k));
        for ((_, column), (_, value)) in swept.iter_mut().zip(sweep.values(k)) {
            column.push(value);
        }
    }
    Ok(Points {
        names,
        swept,
        metrics,
        units,
        errors,
    })
}

/// The unit of each metric column, from the first point that has it.
fn units_of(
    metrics: &[(String, Vec<f64>)],
    ran: &[(&Case, &[MechanismResult])],
) -> Vec<(String, &'static str)> {
    let mut wanted: HashMap<&str, Option<&'static str>> = metrics
        .iter()
        .map(|(name, _)| (name.as_str(), None))
        .collect();
    let mut missing = wanted.len();
    'points: for (_, results) in ran {
        for r in *results {
            for m in &r.summary.metrics {
                let name = format!("{}.{}", r.label, m.name);
                if let Some(unit @ None) = wanted.get_mut(name.as_str()) {
                    *unit = Some(m.unit);
                    missing -= 1;
                    if missing == 0 {
                        break 'points;
                    }
                }
            }
        }
    }
    metrics
        .iter()
        .filter_map(|(name, _)| wanted[name.as_str()].map(|u| (name.clone(), u)))
        .collect()
}
