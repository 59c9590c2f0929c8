//! `cardan.optimize`'s native part: a case with an `[optimize]` table (its own, or one made of
//! the arguments), read by the case files' reader (`cardan_case::optimize`), each mechanism
//! searched by the runner (`cardan_runner::optimize`) with the GIL released; returned as each
//! mechanism's `optimum.json` and the optimisation's `report.md`.

use crate::{case_error, convert, given, CaseError, RunError};
use cardan_case::optimize::Optimization;
use pyo3::prelude::*;
use pyo3::types::PyDict;

/// Optimises `case` (a path, TOML text or a dict): `spec` (a dict in `[optimize]`'s schema,
/// docs/optimisation.md) replaces the case's own `[optimize]` entry by entry. Returns
/// `({mechanism: optimum.json as a dict}, report.md)`.
#[pyfunction]
#[pyo3(signature = (case, spec = None))]
pub fn optimize<'py>(
    py: Python<'py>,
    case: &Bound<'py, PyAny>,
    spec: Option<&Bound<'py, PyDict>>,
) -> PyResult<(Bound<'py, PyAny>, String)> {
    let mut g = given(case, "case")?;
    if let Some(spec) = spec {
        let mut table = match g.table.remove("optimize") {
            Some(toml::Value::Table(t)) => t,
            _ => toml::Table::new(),
        };
        for (k, v) in spec.iter() {
            let key: String = k
                .extract()
                .map_err(|_| CaseError::new_err("an [optimize] entry is named by a str"))?;
            let value = convert::to_toml(&v, &format!("optimize.{key}"))?;
            table.insert(key, value);
        }
        g.table.insert("optimize".into(), toml::Value::Table(table));
    }
    let (optima, report) = py.detach(|| {
        std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
            let o = Optimization::define(&g.file, g.table)
                .map_err(case_error)?
                .ok_or_else(|| {
                    CaseError::new_err(format!(
                        "{}: no [optimize] in the case and none given",
                        g.file.display()
                    ))
                })?;
            let results = cardan_runner::optimize::optimize(&o).map_err(RunError::new_err)?;
            let optima: serde_json::Map<String, serde_json::Value> = results
                .iter()
                .map(|m| {
                    (
                        m.mechanism.clone(),
                        cardan_runner::optimize::optimum_json(&o, m),
                    )
                })
                .collect();
            let report = cardan_runner::optimize::report_md(&o, &results);
            Ok::<_, PyErr>((serde_json::Value::Object(optima), report))
        }))
        .unwrap_or_else(|_| {
            Err(RunError::new_err(
                "internal error running the optimisation (a bug, please report it)",
            ))
        })
    })?;
    Ok((convert::to_python(py, &optima)?, report))
}
