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
use crate::read_once::ReadOnce;
use crate::units::split_number;
use rayon::prelude::*;
use schemars::JsonSchema;
use serde::Deserialize;
use std::path::{Path, PathBuf};

/// One point of a sweep: its name, the value of each swept field, and its case table.
#[derive(Debug, Clone)]
pub struct Point {
    pub name: String,
    /// (dotted path, value as written in the point's case).
    pub values: Vec<(String, String)>,
    pub table: toml::Table,
}

/// Largest number of points a sweep may have (written as a table: `[output] case_folders =
/// false`, each point made and validated when it runs).
pub const MAX_POINTS: usize = 10_000_000;

/// Largest number of points of a sweep made all at once ([`expand`]): a sweep written as case
/// folders, a sweep run in memory (the Python package). Each point made is a case table, and
/// each validated point a [`crate::Case`] (a few kilobytes each).
pub const MAX_EXPANDED: usize = 100_000;

/// A field of `case` in `file` refused: its value and the rule it breaks.
pub(crate) fn invalid(
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
    points: Whole<2, { MAX_EXPANDED as i64 }>,
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
    // An end that is not finite first: its unit is no matter then.
    for (key, x, v) in [("from", from, &range.from), ("to", to, &range.to)] {
        if !x.is_finite() {
            let rule = format!("must be a finite number (it reads as {x})");
            return Err(invalid(file, case, &format!("{field}.{key}"), v, &rule));
        }
    }
    if unit != unit_to {
        return fail("`from` and `to` must have the same unit");
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
pub(crate) fn set(table: &mut toml::Table, path: &str, value: toml::Value) -> Result<(), String> {
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

/// One swept field: its dotted path, the last part of it (for point names), and its values,
/// each with its piece of a point's name and its text as written in the point's case.
#[derive(Debug, Clone)]
struct Field {
    path: String,
    short: String,
    values: Vec<toml::Value>,
    pieces: Vec<String>,
    texts: Vec<String>,
}

/// Whether the sweep `[sweep]` (of the case `name` in `file`) zips its fields (`mode = "zip"`)
/// instead of taking every combination of their values (`"grid"`, the default).
fn sweep_mode(file: &Path, name: &str, sweep: &toml::Table) -> Result<bool, CaseError> {
    match sweep.get("mode").and_then(|m| m.as_str()) {
        None | Some("grid") => Ok(false),
        Some("zip") => Ok(true),
        Some(other) => Err(invalid(
            file,
            name,
            "sweep.mode",
            &other,
            "must be \"grid\" or \"zip\"",
        )),
    }
}

/// The fields `[sweep]` varies (of the case `name` in `file`), each by its dotted path, with
/// its values read and checked; at least one.
fn sweep_fields(file: &Path, name: &str, sweep: &toml::Table) -> Result<Vec<Field>, CaseError> {
    let mut fields: Vec<Field> = Vec::new();
    for (path, spec) in sweep {
        if path == "mode" {
            continue;
        }
        if path == "name" || path.starts_with("sweep") || !path.contains('.') {
            return Err(invalid(file, name, &format!("sweep.\"{path}\""), spec, "sweep a field by its dotted path, e.g. \"motion.initial_speed\" (not name or sweep)"));
        }
        if path.contains(['[', ']']) {
            return Err(invalid(file, name, &format!("sweep.\"{path}\""), spec, "an item of a list cannot be swept on its own: sweep the whole field by its dotted path with a list of its values, e.g. \"layout.crank_angles\" = [[0, 180], [0, 90]]"));
        }
        let values = values_of(file, name, path, spec)?;
        fields.push(Field {
            path: path.clone(),
            short: path.rsplit('.').next().unwrap_or(path).to_string(),
            pieces: values.iter().map(name_piece).collect(),
            texts: values
                .iter()
                .map(|v| match v {
                    toml::Value::String(s) => s.clone(),
                    o => o.to_string(),
                })
                .collect(),
            values,
        });
    }
    if fields.is_empty() {
        return Err(invalid(
            file,
            name,
            "sweep",
            &"{}",
            "names no field to vary",
        ));
    }
    Ok(fields)
}

/// How many points the sweep of `fields` has (`zip`: their values taken together, else every
/// combination), at most [`MAX_POINTS`].
fn point_count(file: &Path, name: &str, fields: &[Field], zip: bool) -> Result<usize, CaseError> {
    let count = if zip {
        let n = fields[0].values.len();
        if let Some(f) = fields.iter().find(|f| f.values.len() != n) {
            return Err(invalid(
                file,
                name,
                &format!("sweep.\"{}\"", f.path),
                &f.values.len(),
                &format!("a zipped sweep needs as many values in every field ({n})"),
            ));
        }
        n
    } else {
        fields
            .iter()
            .try_fold(1usize, |n, f| n.checked_mul(f.values.len()))
            .unwrap_or(usize::MAX)
    };
    if count > MAX_POINTS {
        return Err(invalid(
            file,
            name,
            "sweep",
            &count,
            &format!("at most {MAX_POINTS} points (a sweep of more: split it into several case files, e.g. by one field's range)"),
        ));
    }
    Ok(count)
}

/// A sweep's definition, its points made on demand ([`Sweep::point`]): point `k` of a grid takes
/// the value `k mod n₁` of the first field, `(k / n₁) mod n₂` of the second, ... (a mixed-radix
/// index, the first field fastest); of a zipped sweep, the k-th value of every field. Holding
/// a sweep costs its fields' values, not its points: a million points are a few kilobytes.
#[derive(Debug, Clone)]
pub struct Sweep {
    /// The case file (for messages).
    pub file: PathBuf,
    /// The sweep's name (the case file's `name`): its output folder.
    pub name: String,
    /// The case table without `[sweep]`.
    base: toml::Table,
    fields: Vec<Field>,
    zip: bool,
    count: usize,
    /// The files its points read, read once for all of them (clones of the sweep share it).
    read_once: ReadOnce,
}

impl Sweep {
    /// The files its points read, read once for all of them.
    pub(crate) fn read_once(&self) -> &ReadOnce {
        &self.read_once
    }

    /// The sweep of `table` (a case file with a `[sweep]` table), or `None` if it has none: its
    /// fields and values read and checked (at most [`MAX_POINTS`] points, each of a name of its
    /// own), none of its points made or validated.
    pub fn define(file: &Path, mut table: toml::Table) -> Result<Option<Self>, CaseError> {
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
        let zip = sweep_mode(file, &name, &sweep)?;
        let fields = sweep_fields(file, &name, &sweep)?;
        let count = point_count(file, &name, &fields, zip)?;
        let sweep = Self {
            file: file.into(),
            name,
            base: table,
            fields,
            zip,
            count,
            read_once: ReadOnce::default(),
        };
        // Where a swept path cannot be set (a part of it is not a table), it cannot at any
        // point: the first point tells.
        sweep.point(0)?;
        sweep.check_names()?;
        Ok(Some(sweep))
    }

    /// How many points the sweep has.
    pub fn len(&self) -> usize {
        self.count
    }

    /// Whether the sweep has no point (never: a sweep names at least one field and value).
    pub fn is_empty(&self) -> bool {
        self.count == 0
    }

    /// The index into each field's values of point `k`.
    fn indices(&self, k: usize) -> impl Iterator<Item = (&Field, usize)> + '_ {
        let mut rest = k;
        self.fields.iter().map(move |f| {
            if self.zip {
                (f, k)
            } else {
                let i = rest % f.values.len();
                rest /= f.values.len();
                (f, i)
            }
        })
    }

    /// The name of point `k`: the sweep's name, then `-<field>-<value>` of each swept field.
    pub fn point_name(&self, k: usize) -> String {
        let mut name = self.name.clone();
        for (f, i) in self.indices(k) {
            name.push('-');
            name.push_str(&f.short);
            name.push('-');
            name.push_str(&f.pieces[i]);
        }
        name
    }

    /// The value of each swept field at point `k`: (dotted path, value as written).
    pub fn values(&self, k: usize) -> Vec<(String, String)> {
        self.indices(k)
            .map(|(f, i)| (f.path.clone(), f.texts[i].clone()))
            .collect()
    }

    /// The sweep's definition as text: its case table (without `[sweep]`), each swept field
    /// with its values, its mode. Two sweeps of one definition have the same points: a hash of
    /// it stands for theirs.
    pub fn definition(&self) -> String {
        let fields: Vec<(&String, &Vec<toml::Value>)> =
            self.fields.iter().map(|f| (&f.path, &f.values)).collect();
        format!("{:?} {fields:?} zip {}", self.base, self.zip)
    }

    /// The swept fields' dotted paths, in order.
    pub fn paths(&self) -> Vec<&str> {
        self.fields.iter().map(|f| f.path.as_str()).collect()
    }

    /// The longest point name and the longest value text of each swept field, over the points
    /// `points` (indices).
    pub fn text_widths(&self, points: impl Iterator<Item = usize>) -> (usize, Vec<usize>) {
        let mut name = 0;
        let mut values = vec![0; self.fields.len()];
        for k in points {
            let mut len = self.name.len();
            for (j, (f, i)) in self.indices(k).enumerate() {
                len += 2 + f.short.len() + f.pieces[i].len();
                values[j] = values[j].max(f.texts[i].len());
            }
            name = name.max(len);
        }
        (name, values)
    }

    /// Point `k` (from 0; `k < len()`): its name, values and case table.
    pub fn point(&self, k: usize) -> Result<Point, CaseError> {
        let mut table = self.base.clone();
        for (f, i) in self.indices(k) {
            let v = f.values[i].clone();
            set(&mut table, &f.path, v.clone()).map_err(|rule| {
                invalid(
                    &self.file,
                    &self.name,
                    &format!("sweep.\"{}\"", f.path),
                    &v,
                    &rule,
                )
            })?;
        }
        let name = self.point_name(k);
        table.insert("name".into(), toml::Value::String(name.clone()));
        Ok(Point {
            name,
            values: self.values(k),
            table,
        })
    }

    /// Refuses two points of one name (they would share one folder and delete each other's
    /// files, or one row name), naming the first point in order whose name an earlier point
    /// has, and that earlier point. The names are hashed (16 bytes a point while checking), the
    /// hashes sorted, and only equal hashes compared by name.
    fn check_names(&self) -> Result<(), CaseError> {
        use std::hash::{Hash, Hasher};
        let hash = |k: usize| {
            let mut h = std::hash::DefaultHasher::new();
            self.point_name(k).hash(&mut h);
            h.finish()
        };
        let mut hashes: Vec<(u64, usize)> = (0..self.count)
            .into_par_iter()
            .map(|k| (hash(k), k))
            .collect();
        hashes.par_sort_unstable();
        // (the later point, the first point of its name), the earliest later point kept.
        let mut clash: Option<(usize, usize)> = None;
        for group in hashes.chunk_by(|a, b| a.0 == b.0).filter(|g| g.len() > 1) {
            let names: Vec<(String, usize)> = group
                .iter()
                .map(|&(_, k)| (self.point_name(k), k))
                .collect();
            for (j, (name, k)) in names.iter().enumerate() {
                if let Some((_, first)) = names[..j].iter().find(|(n, _)| n == name) {
                    if clash.is_none_or(|(later, _)| *k < later) {
                        clash = Some((*k, *first));
                    }
                }
            }
        }
        let Some((later, first)) = clash else {
            return Ok(());
        };
        let (first, p) = (self.values(first), self.values(later));
        let show = |q: &[(String, String)], k: usize| format!("{:?}", q[k].1);
        let (field, value) = if p.len() == 1 {
            (
                format!("sweep.\"{}\"", p[0].0),
                format!("{} and {}", show(&first, 0), show(&p, 0)),
            )
        } else {
            let each = |q: &[(String, String)]| {
                (0..q.len())
                    .map(|k| format!("{} = {}", q[k].0, show(q, k)))
                    .collect::<Vec<_>>()
                    .join(", ")
            };
            (
                "sweep".to_string(),
                format!("({}) and ({})", each(&first), each(&p)),
            )
        };
        Err(invalid(
            &self.file,
            &self.name,
            &field,
            &value,
            &format!(
                "two points would have the one name (and folder) \"{}\": every swept value must be distinct",
                self.point_name(later)
            ),
        ))
    }
}

/// The points of the sweep in `table` (a case file with a `[sweep]` table), all made at once
/// (at most [`MAX_EXPANDED`] of them), or `None` if it has none. A sweep of more points is
/// made a point at a time from its [`Sweep`].
pub fn expand(file: &Path, table: toml::Table) -> Result<Option<(String, Vec<Point>)>, CaseError> {
    let Some(sweep) = Sweep::define(file, table)? else {
        return Ok(None);
    };
    if sweep.len() > MAX_EXPANDED {
        return Err(invalid(
            file,
            &sweep.name,
            "sweep",
            &sweep.len(),
            &format!("at most {MAX_EXPANDED} points made at once (in memory, or each in a case folder); run a larger sweep with `cardan run` as a table (`[output] case_folders = false`)"),
        ));
    }
    let points = (0..sweep.len())
        .into_par_iter()
        .map(|k| sweep.point(k))
        .collect::<Result<Vec<Point>, CaseError>>()?;
    Ok(Some((sweep.name, points)))
}
