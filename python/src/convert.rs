//! Values between Python and the case files' TOML: a dict in the case-file schema becomes a TOML
//! table (read then by the same typed reader as a file), and a JSON value (`summary.json`,
//! `gear.json`) becomes Python objects.

use crate::CaseError;
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyDict, PyFloat, PyInt, PyList, PyString, PyTuple};

/// The dotted path of `key` in the table at `path`.
fn join(path: &str, key: &str) -> String {
    if path.is_empty() {
        key.to_string()
    } else {
        format!("{path}.{key}")
    }
}

/// A case-file error about the value at `path` of a dict given as a case.
fn bad(path: &str, value: &str, rule: &str) -> PyErr {
    CaseError::new_err(format!("<dict>: {path} = {value}: {rule}"))
}

/// `value` (the value at the dotted `path` of a dict) as TOML: dicts are tables, lists and
/// tuples (and numpy arrays, by their `tolist`) arrays, `bool`, `int`, `float` and `str` as
/// themselves. A number that is not finite, an integer beyond 64 bits, a key that is not a
/// string or a value of another type is a [`CaseError`] naming `path`.
pub fn to_toml(value: &Bound<'_, PyAny>, path: &str) -> PyResult<toml::Value> {
    if let Ok(dict) = value.cast::<PyDict>() {
        let mut table = toml::Table::new();
        for (k, v) in dict.iter() {
            let Ok(key) = k.extract::<String>() else {
                return Err(bad(
                    &join(path, &k.repr()?.to_string()),
                    "(a key)",
                    "a key must be a string",
                ));
            };
            let item = to_toml(&v, &join(path, &key))?;
            table.insert(key, item);
        }
        return Ok(toml::Value::Table(table));
    }
    if value.is_instance_of::<PyBool>() {
        return Ok(toml::Value::Boolean(value.extract()?));
    }
    if value.is_instance_of::<PyString>() {
        return Ok(toml::Value::String(value.extract()?));
    }
    if value.is_instance_of::<PyInt>() {
        return match value.extract::<i64>() {
            Ok(i) => Ok(toml::Value::Integer(i)),
            Err(_) => Err(bad(
                path,
                &value.str()?.to_string(),
                "an integer must fit in 64 bits",
            )),
        };
    }
    if value.is_instance_of::<PyFloat>() {
        return finite(value.extract()?, path);
    }
    if value.is_instance_of::<PyList>() || value.is_instance_of::<PyTuple>() {
        let mut items = Vec::new();
        for (k, item) in value.try_iter()?.enumerate() {
            items.push(to_toml(&item?, &format!("{path}[{k}]"))?);
        }
        return Ok(toml::Value::Array(items));
    }
    // numpy's arrays and scalars (np.float64 is a float already; np.int64 is not an int).
    if value.hasattr("tolist")? {
        return to_toml(&value.call_method0("tolist")?, path);
    }
    let kind = value.get_type().name()?.to_string();
    Err(bad(
        path,
        &value.repr()?.to_string(),
        &format!(
            "a {kind} cannot be a case file's value (dicts, lists, str, int, float and bool can)"
        ),
    ))
}

/// A float of a dict as TOML, refused if it is not finite.
fn finite(x: f64, path: &str) -> PyResult<toml::Value> {
    if x.is_finite() {
        Ok(toml::Value::Float(x))
    } else {
        Err(bad(path, &x.to_string(), "must be a finite number"))
    }
}

/// A JSON value as Python objects: objects are dicts (in their order), arrays lists, numbers
/// `int` or `float` as JSON writes them (a float's bits kept), `null` `None`.
pub fn to_python<'py>(py: Python<'py>, value: &serde_json::Value) -> PyResult<Bound<'py, PyAny>> {
    use serde_json::Value;
    Ok(match value {
        Value::Null => py.None().into_bound(py),
        Value::Bool(b) => PyBool::new(py, *b).to_owned().into_any(),
        Value::Number(n) => {
            if let Some(i) = n.as_i64() {
                i.into_pyobject(py)?.into_any()
            } else if let Some(u) = n.as_u64() {
                u.into_pyobject(py)?.into_any()
            } else {
                PyFloat::new(py, n.as_f64().unwrap_or(f64::NAN)).into_any()
            }
        }
        Value::String(s) => PyString::new(py, s).into_any(),
        Value::Array(items) => {
            let list = PyList::empty(py);
            for item in items {
                list.append(to_python(py, item)?)?;
            }
            list.into_any()
        }
        Value::Object(map) => {
            let dict = PyDict::new(py);
            for (k, v) in map {
                dict.set_item(k, to_python(py, v)?)?;
            }
            dict.into_any()
        }
    })
}
