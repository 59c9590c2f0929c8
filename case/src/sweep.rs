//! Sweeps: a `[sweep]` table varies numeric fields of a case (each by its dotted path, with
//! units) over a list, a linear range or a logarithmic range, as a grid (every combination) or
//! zipped (the n-th value of every field together). Each point is an ordinary case with a
//! stable, readable name; the points run into `out/<sweep name>/<point>/` and their summaries are
//! gathered in `out/<sweep name>/sweep.csv`.
//!
//! ```toml
//! [sweep]
//! mode = "grid"                                   # or "zip"
//! "motion.initial_speed" = ["3 rad/s", "30 rad/s"]
//! "geometry.rod_length" = { from = "120 mm", to = "200 mm", points = 5 }
//! "motion.angular_acceleration" = { from = 10, to = 1000, points = 3, scale = "log" }
//! ```

use crate::error::CaseError;
use crate::quantity::Whole;
use crate::units::split_number;
use rayon::prelude::*;
use schemars::JsonSchema;
use serde::Deserialize;
use std::path::Path;

/// One point of a sweep: its name, the value of each swept field, and its case table.
#[derive(Debug, Clone)]
pub struct Point {
    pub name: String,
    /// (dotted path, value as written in the point's case).
    pub values: Vec<(String, String)>,
    pub table: toml::Table,
}

/// Largest number of points a sweep may have.
pub const MAX_POINTS: usize = 100_000;

fn invalid(
    file: &Path,
    case: &str,
    field: &str,
    value: &dyn std::fmt::Display,
    rule: &str,
) -> CaseError {
    CaseError::Invalid {
        file: file.into(),
        case: case.to_string(),
        field: field.to_string(),
        value: value.to_string(),
        rule: rule.to_string(),
    }
}

/// A number and the unit written after it ("120 mm" → (120, "mm"); 0.5 → (0.5, "")).
fn number_and_unit(v: &toml::Value) -> Option<(f64, String)> {
    match v {
        toml::Value::Float(x) => Some((*x, String::new())),
        toml::Value::Integer(i) => Some((*i as f64, String::new())),
        toml::Value::String(s) => split_number(s).ok().map(|(x, u)| (x, u.to_string())),
        _ => None,
    }
}

/// A range of values `{ from, to, points, scale }` of a swept field.
#[derive(Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
struct Range {
    /// The first value: a number, or a string with a unit ("120 mm").
    #[schemars(schema_with = "number_or_text")]
    from: toml::Value,
    /// The last value, in the unit of `from`.
    #[schemars(schema_with = "number_or_text")]
    to: toml::Value,
    /// How many values, the ends included.
    points: Whole<2, { MAX_POINTS as i64 }>,
    /// "linear" (the default) or "log" (evenly spaced logarithms; positive ends).
    #[serde(default)]
    scale: Scale,
}

fn number_or_text(_: &mut schemars::SchemaGenerator) -> schemars::Schema {
    schemars::json_schema!({ "type": ["number", "string"] })
}

#[derive(Default, Deserialize, JsonSchema, PartialEq)]
#[serde(rename_all = "snake_case")]
enum Scale {
    #[default]
    Linear,
    Log,
}

/// `[sweep]`'s JSON Schema: `mode`, then each swept field by its dotted path, a list or a
/// [`Range`].
pub(crate) fn json_schema(generator: &mut schemars::SchemaGenerator) -> serde_json::Value {
    let range = serde_json::to_value(generator.subschema_for::<Range>()).unwrap_or_default();
    let value = serde_json::json!({ "type": ["number", "string"] });
    serde_json::json!({
        "type": "object",
        "description": "Varies fields of the case: each by its dotted path, over a list or a range; the points run as cases of their own",
        "properties": {
            "mode": {
                "description": "\"grid\" (every combination, the default) or \"zip\" (the n-th values together)",
                "enum": ["grid", "zip"]
            }
        },
        "additionalProperties": {
            "anyOf": [{ "type": "array", "items": value, "minItems": 1 }, range]
        }
    })
}

/// The values one swept field takes.
fn values_of(
    file: &Path,
    case: &str,
    path: &str,
    spec: &toml::Value,
) -> Result<Vec<toml::Value>, CaseError> {
    let field = format!("sweep.\"{path}\"");
    let fail = |rule: &str| Err(invalid(file, case, &field, spec, rule));
    let range: Range = match spec {
        toml::Value::Array(list) if !list.is_empty() => return Ok(list.clone()),
        toml::Value::Table(_) => {
            crate::schema::read(spec.clone(), &field).map_err(|error| CaseError::Field {
                file: file.into(),
                case: case.to_string(),
                error,
            })?
        }
        _ => {
            return fail(
                "must be a non-empty list of values, or a range { from, to, points, scale }",
            )
        }
    };
    let (Some((from, unit)), Some((to, unit_to))) =
        (number_and_unit(&range.from), number_and_unit(&range.to))
    else {
        return fail("a range needs `from` and `to` (numbers, or strings with the same unit)");
    };
    if unit != unit_to {
        return fail("`from` and `to` must have the same unit");
    }
    for (key, x, v) in [("from", from, &range.from), ("to", to, &range.to)] {
        if !x.is_finite() {
            let rule = format!("must be a finite number (it reads as {x})");
            return Err(invalid(file, case, &format!("{field}.{key}"), v, &rule));
        }
    }
    if from == to {
        return fail("`from` and `to` are equal: every point would be the same (and share one folder); give a single value as a list, e.g. [\"3000 rpm\"]");
    }
    let log = range.scale == Scale::Log;
    if log && !(from > 0.0 && to > 0.0) {
        return fail("a logarithmic range needs positive `from` and `to`");
    }
    let points = range.points.0 as usize;
    Ok((0..points)
        .map(|k| {
            let f = k as f64 / (points - 1) as f64;
            // Six significant digits: readable point names and axes (185.714 mm, not
            // 185.71428571428572 mm); the ends are exact.
            let x = if log {
                from * (to / from).powf(f)
            } else {
                from + (to - from) * f
            };
            let x = format!("{x:.5e}").parse::<f64>().unwrap_or(x);
            if unit.is_empty() {
                toml::Value::Float(x)
            } else {
                toml::Value::String(format!("{x} {unit}"))
            }
        })
        .collect())
}

/// Sets the value at the dotted `path` of `table`, making the tables on the way.
fn set(table: &mut toml::Table, path: &str, value: toml::Value) -> Result<(), String> {
    let mut parts: Vec<&str> = path.split('.').collect();
    let last = parts.pop().ok_or("an empty path")?;
    let mut t = table;
    for p in parts {
        t = t
            .entry(p)
            .or_insert_with(|| toml::Value::Table(toml::Table::new()))
            .as_table_mut()
            .ok_or_else(|| format!("{p} is not a table"))?;
    }
    t.insert(last.to_string(), value);
    Ok(())
}

/// A value as a piece of a folder name: "120 mm" → "120mm", "3 rad/s" → "3rad_s".
fn name_piece(v: &toml::Value) -> String {
    let text = match v {
        toml::Value::String(s) => s.clone(),
        other => other.to_string(),
    };
    text.chars()
        .filter(|c| !c.is_whitespace())
        .map(|c| {
            if c.is_ascii_alphanumeric() || "-_.".contains(c) {
                c
            } else {
                '_'
            }
        })
        .collect()
}

/// The points of the sweep in `table` (a case file with a `[sweep]` table), or `None` if it
/// has none.
pub fn expand(
    file: &Path,
    mut table: toml::Table,
) -> Result<Option<(String, Vec<Point>)>, CaseError> {
    let Some(sweep) = table.remove("sweep") else {
        return Ok(None);
    };
    let name = table
        .get("name")
        .and_then(|n| n.as_str())
        .unwrap_or("")
        .to_string();
    let Some(sweep) = sweep.as_table().cloned() else {
        return Err(invalid(file, &name, "sweep", &sweep, "must be a table"));
    };
    let zip = match sweep.get("mode").and_then(|m| m.as_str()) {
        None | Some("grid") => false,
        Some("zip") => true,
        Some(other) => {
            return Err(invalid(
                file,
                &name,
                "sweep.mode",
                &other,
                "must be \"grid\" or \"zip\"",
            ))
        }
    };
    let mut fields: Vec<(String, Vec<toml::Value>)> = Vec::new();
    for (path, spec) in &sweep {
        if path == "mode" {
            continue;
        }
        if path == "name" || path.starts_with("sweep") || !path.contains('.') {
            return Err(invalid(file, &name, &format!("sweep.\"{path}\""), spec, "sweep a field by its dotted path, e.g. \"motion.initial_speed\" (not name or sweep)"));
        }
        fields.push((path.clone(), values_of(file, &name, path, spec)?));
    }
    if fields.is_empty() {
        return Err(invalid(
            file,
            &name,
            "sweep",
            &"{}",
            "names no field to vary",
        ));
    }
    let count = if zip {
        let n = fields[0].1.len();
        if let Some((path, v)) = fields.iter().find(|(_, v)| v.len() != n) {
            return Err(invalid(
                file,
                &name,
                &format!("sweep.\"{path}\""),
                &v.len(),
                &format!("a zipped sweep needs as many values in every field ({n})"),
            ));
        }
        n
    } else {
        fields.iter().map(|(_, v)| v.len()).product()
    };
    if count > MAX_POINTS {
        return Err(invalid(
            file,
            &name,
            "sweep",
            &count,
            &format!("at most {MAX_POINTS} points"),
        ));
    }
    // The points made on every thread (each a copy of the whole table), the first failure in
    // the points' order reported.
    let points: Vec<Result<Point, CaseError>> = (0..count)
        .into_par_iter()
        .map(|k| {
            let mut t = table.clone();
            let mut values = Vec::new();
            let mut point_name = name.clone();
            let mut rest = k;
            for (path, list) in &fields {
                let v = if zip {
                    list[k].clone()
                } else {
                    let v = list[rest % list.len()].clone();
                    rest /= list.len();
                    v
                };
                let short = path.rsplit('.').next().unwrap_or(path);
                point_name.push_str(&format!("-{short}-{}", name_piece(&v)));
                set(&mut t, path, v.clone()).map_err(|rule| {
                    invalid(file, &name, &format!("sweep.\"{path}\""), &v, &rule)
                })?;
                values.push((
                    path.clone(),
                    match &v {
                        toml::Value::String(s) => s.clone(),
                        o => o.to_string(),
                    },
                ));
            }
            t.insert("name".into(), toml::Value::String(point_name.clone()));
            Ok(Point {
                name: point_name,
                values,
                table: t,
            })
        })
        .collect();
    let points = points
        .into_iter()
        .collect::<Result<Vec<Point>, CaseError>>()?;
    // Two points of one name would share one folder (and delete each other's files).
    let mut seen: std::collections::HashMap<&str, &Point> = std::collections::HashMap::new();
    for p in &points {
        if let Some(first) = seen.insert(&p.name, p) {
            let show = |q: &Point, k: usize| format!("{:?}", q.values[k].1);
            let (field, value) = if p.values.len() == 1 {
                (
                    format!("sweep.\"{}\"", p.values[0].0),
                    format!("{} and {}", show(first, 0), show(p, 0)),
                )
            } else {
                let each = |q: &Point| {
                    (0..q.values.len())
                        .map(|k| format!("{} = {}", q.values[k].0, show(q, k)))
                        .collect::<Vec<_>>()
                        .join(", ")
                };
                (
                    "sweep".to_string(),
                    format!("({}) and ({})", each(first), each(p)),
                )
            };
            return Err(invalid(
                file,
                &name,
                &field,
                &value,
                &format!(
                    "two points would have the one name (and folder) \"{}\": every swept value must be distinct",
                    p.name
                ),
            ));
        }
    }
    Ok(Some((name, points)))
}
