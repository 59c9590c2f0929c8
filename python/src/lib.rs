//! The native part of the Python package `cardan` (`cardan._cardan`; the package's Python
//! side, `python/cardan/__init__.py`, wraps it): a case (a path, TOML text or a dict in the
//! case-file schema) read by the case files' own reader (`cardan_case`) and run in memory by the
//! runner ([`cardan_runner::memory`]), the GIL released while it runs; the standalone gear-pair
//! rating of `cardan gear` (`cardan_gear_file`). Bad input raises `CaseError` with the
//! command line's message (the field's dotted path, the rule, the value); a run that fails
//! raises `RunError` naming the step and quantity; a panic is caught and raised as
//! `RunError`, never aborting the interpreter.

mod convert;
mod optimize;
mod sweep;
mod units;

use cardan_runner::memory::run_in_memory;
use numpy::PyArray1;
use pyo3::create_exception;
use pyo3::exceptions::PyException;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};
use std::path::{Path, PathBuf};

create_exception!(
    _cardan,
    CaseError,
    PyException,
    "A case or gear pair that does not read or validate; the message names the field."
);
create_exception!(
    _cardan,
    RunError,
    PyException,
    "A case that failed while running; the message names the step and the quantity."
);

/// A case as given: its label in messages and its TOML table.
struct Given {
    file: PathBuf,
    table: toml::Table,
}

/// Reads `case`: a dict in the case-file schema, an `os.PathLike` or `str` naming a file, or a
/// `str` of TOML text (one that holds a newline or an `=`).
fn given(case: &Bound<'_, PyAny>, what: &str) -> PyResult<Given> {
    if case.is_instance_of::<PyDict>() {
        return match convert::to_toml(case, "")? {
            toml::Value::Table(table) => Ok(Given {
                file: PathBuf::from("<dict>"),
                table,
            }),
            _ => unreachable!("a dict is a table"),
        };
    }
    let (file, text) = match case.extract::<String>() {
        Ok(text) if text.contains('\n') || text.contains('=') => {
            (PathBuf::from(format!("<{what} text>")), text)
        }
        _ => {
            let file: PathBuf = case.extract().map_err(|_| {
                CaseError::new_err(format!(
                    "a {what} is a path, TOML text or a dict, not a {}",
                    case.get_type()
                        .name()
                        .map(|n| n.to_string())
                        .unwrap_or_default()
                ))
            })?;
            // The command line's bounded reader: a regular file of at most 16 MiB.
            let text = cardan_case::case::read_case_text(&file).map_err(case_error)?;
            (file, text)
        }
    };
    let table = cardan_case::case::toml_table(&file, &text).map_err(case_error)?;
    Ok(Given { file, table })
}

fn case_error(e: impl std::fmt::Display) -> PyErr {
    CaseError::new_err(e.to_string())
}

/// The validated cases of a table (one, or a sweep's points), the GIL released.
fn cases(py: Python<'_>, g: Given) -> PyResult<Vec<cardan_case::Case>> {
    py.detach(|| {
        std::panic::catch_unwind(|| cardan_case::case::cases_of_table(&g.file, g.table))
            .map_err(|_| {
                RunError::new_err("internal error reading the case (a bug, please report it)")
            })?
            .map_err(case_error)
    })
}

/// Runs one case in memory: `(summary_json, [(label, {column: array})])`, the columns only if
/// `steps`. Each column is handed to numpy whole (no copy, no Python call per number).
#[pyfunction]
#[pyo3(signature = (case, steps = true))]
fn run<'py>(
    py: Python<'py>,
    case: &Bound<'py, PyAny>,
    steps: bool,
) -> PyResult<(Bound<'py, PyAny>, Bound<'py, PyList>)> {
    let g = given(case, "case")?;
    if g.table.contains_key("sweep") {
        return Err(CaseError::new_err(format!(
            "{}: the case has a [sweep]: run it with cardan.sweep",
            g.file.display()
        )));
    }
    let mut cases = cases(py, g)?;
    let case = cases.pop().expect("a case without [sweep] is one case");
    // The runner catches a panic of the run (`run_in_memory`); this catches anything else.
    let run = py
        .detach(|| {
            std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| run_in_memory(&case, steps)))
                .unwrap_or_else(|_| {
                    Err("internal error running the case (a bug, please report it)".into())
                })
        })
        .map_err(RunError::new_err)?;
    let summary = convert::to_python(py, &run.summary)?;
    let trains = PyList::empty(py);
    for (result, columns) in run.results.iter().zip(run.steps) {
        let dict = PyDict::new(py);
        for (name, values) in columns.names.into_iter().zip(columns.values) {
            dict.set_item(name, PyArray1::from_vec(py, values))?;
        }
        trains.append((result.label.as_str(), dict))?;
    }
    Ok((summary, trains))
}

/// Rates a gear pair given as `cardan gear`'s gear file (a path, TOML text or a dict): its
/// `gear.json` as a dict, with `failures` and `warnings` (the reasons the pair cannot work, the
/// rules of thumb it breaks; the command exits 1 on a failure, this returns them).
#[pyfunction]
fn gear<'py>(py: Python<'py>, pair: &Bound<'py, PyAny>) -> PyResult<Bound<'py, PyAny>> {
    let g = given(pair, "gear pair")?;
    let text = toml::to_string(&g.table).map_err(case_error)?;
    let file: &Path = &g.file;
    let report = py.detach(|| {
        std::panic::catch_unwind(|| {
            let input = cardan_gear_file::parse(file, &text).map_err(case_error)?;
            let report = cardan_gear_file::evaluate(&input).map_err(case_error)?;
            let mut json = report.to_json();
            json["failures"] = report.failures().into();
            json["warnings"] = report.warnings().into();
            Ok::<_, PyErr>(json)
        })
        .map_err(|_| {
            RunError::new_err("internal error rating the pair (a bug, please report it)")
        })?
    })?;
    convert::to_python(py, &report)
}

/// The per-step column templates and their meanings (`runner/src/per_step/row.rs`).
#[pyfunction]
fn columns() -> Vec<(&'static str, &'static str)> {
    cardan_runner::per_step::COLUMNS.to_vec()
}

#[pymodule]
fn _cardan(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add("CaseError", m.py().get_type::<CaseError>())?;
    m.add("RunError", m.py().get_type::<RunError>())?;
    m.add_function(wrap_pyfunction!(run, m)?)?;
    m.add_function(wrap_pyfunction!(sweep::sweep, m)?)?;
    m.add_function(wrap_pyfunction!(optimize::optimize, m)?)?;
    m.add_function(wrap_pyfunction!(units::quantity, m)?)?;
    m.add_function(wrap_pyfunction!(units::case_schema, m)?)?;
    // The package's version: the crate's (pyproject.toml takes it from Cargo.toml).
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    m.add_function(wrap_pyfunction!(gear, m)?)?;
    m.add_function(wrap_pyfunction!(columns, m)?)?;
    // Whether this build has the runner's test hook (feature `test-hooks`, .ci/run's wheel).
    m.add("TEST_HOOKS", cfg!(feature = "test-hooks"))?;
    #[cfg(feature = "test-hooks")]
    m.add(
        "TEST_PANIC_CASE",
        cardan_runner::run::test_hooks::TEST_PANIC_CASE,
    )?;
    Ok(())
}
