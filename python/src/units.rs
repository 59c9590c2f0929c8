//! The case files' quantities for Python: a swept field's values as numbers in SI, by the
//! same conversion a case file's value takes (`cardan_case::units::to_si`), and the case files'
//! JSON Schema, which names each field's unit (`x-unit`, the unit of a bare number).

use crate::convert;
use cardan_case::units::{to_si, Dimension};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;

/// Every dimension of the case files' quantities (`cardan_case::units::Dimension`).
const DIMENSIONS: [Dimension; 19] = [
    Dimension::Length,
    Dimension::Angle,
    Dimension::AngularSpeed,
    Dimension::AngularAcceleration,
    Dimension::Mass,
    Dimension::Inertia,
    Dimension::MassRadius,
    Dimension::Pressure,
    Dimension::Temperature,
    Dimension::SpecificEnergy,
    Dimension::GasConstant,
    Dimension::AnglePerSpeed,
    Dimension::KinematicViscosity,
    Dimension::Density,
    Dimension::Force,
    Dimension::Power,
    Dimension::Torque,
    Dimension::RootStress,
    Dimension::Number,
];

/// `value` (a number, or a str "NUMBER UNIT") of a field whose bare number is in `unit` (its
/// schema's `x-unit`) in SI, and the SI unit: `("6 bar", "Pa")` is `(600000.0, "Pa")`,
/// `(30, "deg")` is `(0.5236, "rad")`. A value the field would refuse raises `ValueError`
/// with the case file's rule.
#[pyfunction]
pub fn quantity(value: &Bound<'_, PyAny>, unit: &str) -> PyResult<(f64, String)> {
    let dim = DIMENSIONS
        .into_iter()
        .find(|d| !unit.is_empty() && d.default_unit() == unit)
        .ok_or_else(|| PyValueError::new_err(format!("no quantity has the unit {unit:?}")))?;
    let value =
        convert::to_toml(value, "value").map_err(|e| PyValueError::new_err(e.to_string()))?;
    let si = to_si(&value, dim).map_err(PyValueError::new_err)?;
    Ok((si, si_unit(dim)))
}

/// The dimension's SI unit: the one of its units in which 1 is 1 in SI.
fn si_unit(dim: Dimension) -> String {
    dim.unit_names()
        .find(|u| to_si(&toml::Value::String(format!("1 {u}")), dim) == Ok(1.0))
        .unwrap_or(dim.default_unit())
        .to_string()
}

/// The case files' JSON Schema (`schema/case.schema.json`) as a dict.
#[pyfunction]
pub fn case_schema(py: Python<'_>) -> PyResult<Bound<'_, PyAny>> {
    convert::to_python(py, &cardan_case::json_schema::case_schema())
}
