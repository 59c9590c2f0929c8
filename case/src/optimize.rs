//! `[optimize]`: each mechanism of a case at its best. The table names a summary metric to
//! maximise or minimise, the numeric fields varied (each by its dotted path, as in `[sweep]`,
//! over a range with units) and constraints on summary metrics (bounds with units). This
//! module reads and checks the table and makes the case of one mechanism at a point; the
//! search (`cardan-optimize`) and the runs are the runner's (`runner/src/optimize/`).
//!
//! ```toml
//! [optimize]
//! objective = "machine_mechanical_efficiency"
//! sense = "max"
//! variables = { "geometry.rod_length" = ["100 mm", "300 mm"], "balance.counterweight" = [0.0, 1.0] }
//! constraints = ["bending_safety_factor >= 1.2", "total_piston_side_force_max <= 5 kN"]
//! ```

use crate::case::{case_of_table, Case};
use crate::error::CaseError;
use crate::output_metrics::{needs, Computed};
use crate::quantity::Whole;
use crate::sweep::invalid;
use crate::units::{split_number, to_si, Dimension};
use cardan_dynamics::metrics;
use schemars::JsonSchema;
use serde::Deserialize;
use std::path::{Path, PathBuf};

/// `[optimize]`: each mechanism at its best, a design optimisation of the case's fields under
/// constraints on its summary metrics (docs/optimisation.md).
#[derive(Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct OptimizeTable {
    /// The summary metric optimised (docs/results.md), e.g. "machine_mechanical_efficiency".
    pub objective: String,
    /// "max" or "min".
    pub sense: Sense,
    /// The fields varied, each by its dotted path (as in `[sweep]`) with its range `[lower, upper]`:
    /// numbers, or strings with one unit ("100 mm").
    #[schemars(schema_with = "variables_schema")]
    pub variables: toml::Table,
    /// Constraints on summary metrics, each `"<metric> <= <bound>"` or `"<metric> >= <bound>"`,
    /// the bound a number in the metric's SI unit or a string with a unit ("5 kN").
    #[serde(default)]
    pub constraints: Vec<String>,
    /// Starts of the search, from a Latin hypercube; default 4.
    pub starts: Option<Whole<1, 64>>,
    /// The seed of the starts' design; default 1. The same seed gives the same result.
    pub seed: Option<Whole<0, 4_294_967_295>>,
    /// Evaluations (runs) a start may spend at most; default 200.
    pub max_evaluations: Option<Whole<10, 100_000>>,
    /// The search's last step, as a fraction of each variable's range, from 1e-6 to 0.01;
    /// default 1e-4: the optimum is located to within it.
    pub tolerance: Option<crate::quantity::Ranged<crate::plausible::OptimizeTolerance>>,
}

fn variables_schema(_: &mut schemars::SchemaGenerator) -> schemars::Schema {
    schemars::json_schema!({
        "type": "object",
        "description": "Each varied field's dotted path and its range [lower, upper]",
        "additionalProperties": {
            "type": "array",
            "items": { "type": ["number", "string"] },
            "minItems": 2,
            "maxItems": 2
        }
    })
}

/// Which way the objective is better.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize, JsonSchema)]
#[serde(rename_all = "snake_case")]
pub enum Sense {
    Max,
    Min,
}

/// One varied field: its dotted path and range, in the unit written (`unit` "" for a bare
/// number).
#[derive(Debug, Clone, PartialEq)]
pub struct Variable {
    pub path: String,
    pub lower: f64,
    pub upper: f64,
    pub unit: String,
}

impl Variable {
    /// The value at `u` of the range (0: lower, 1: upper), in the unit written.
    pub fn at(&self, u: f64) -> f64 {
        self.lower + u * (self.upper - self.lower)
    }

    /// The value `x` (in the unit written) as a case file would write it.
    pub fn text(&self, x: f64) -> toml::Value {
        if self.unit.is_empty() {
            toml::Value::Float(x)
        } else {
            toml::Value::String(format!("{x} {}", self.unit))
        }
    }

    /// Whether the variable is a field of `mechanism`'s own tables (`[<other>]`,
    /// `[masses.<other>]`) of another mechanism: left out for `mechanism`.
    pub fn belongs_to_other(&self, mechanism: &str) -> bool {
        let mut parts = self.path.split('.');
        let first = parts.next().unwrap_or("");
        let owner = if first == "masses" {
            parts.next().unwrap_or("")
        } else {
            first
        };
        cardan_mechanism::entry(owner).is_some() && owner != mechanism
    }
}

/// `<=` or `>=`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Relation {
    AtMost,
    AtLeast,
}

/// One constraint on a summary metric, its bound in SI.
#[derive(Debug, Clone, PartialEq)]
pub struct Constraint {
    /// As written.
    pub text: String,
    pub metric: String,
    /// The metric's SI unit.
    pub unit: &'static str,
    pub relation: Relation,
    pub bound: f64,
}

impl Constraint {
    /// The margin at `value` (SI): ≥ 0 where the constraint holds, in the metric's unit.
    pub fn margin(&self, value: f64) -> f64 {
        match self.relation {
            Relation::AtMost => self.bound - value,
            Relation::AtLeast => value - self.bound,
        }
    }

    /// The margin relative to the bound's size (|bound|, or 1 in the metric's unit for a bound
    /// of 0): commensurate margins for the search's total violation.
    pub fn relative_margin(&self, value: f64) -> f64 {
        let scale = if self.bound == 0.0 {
            1.0
        } else {
            self.bound.abs()
        };
        self.margin(value) / scale
    }
}

/// A validated `[optimize]`: the case it varies, its objective, variables, constraints and the
/// search's settings.
#[derive(Debug, Clone)]
pub struct Optimization {
    pub file: PathBuf,
    /// The case's name: the optimisation's output folder.
    pub name: String,
    /// The case table without `[optimize]`.
    base: toml::Table,
    /// The case's mechanisms, each optimised on its own.
    pub mechanisms: Vec<String>,
    pub objective: String,
    /// The objective's SI unit.
    pub objective_unit: &'static str,
    pub sense: Sense,
    pub variables: Vec<Variable>,
    pub constraints: Vec<Constraint>,
    pub starts: usize,
    pub seed: u64,
    pub max_evaluations: usize,
    pub tolerance: f64,
}

/// The dimension whose SI unit is a metric's unit ("1": a pure number), if a case file has one.
fn dimension_of(unit: &str) -> Option<Dimension> {
    use Dimension::*;
    if unit == "1" {
        return Some(Number);
    }
    [
        Length,
        AngularSpeed,
        AngularAcceleration,
        Mass,
        Inertia,
        MassRadius,
        Pressure,
        Force,
        Power,
        Torque,
        Density,
        KinematicViscosity,
        SpecificEnergy,
    ]
    .into_iter()
    .find(|d| d.default_unit() == unit)
}

/// The bound `text` of a metric in `unit`, in SI: a bare number in the metric's unit, or a
/// number with a unit of its dimension.
fn bound_si(text: &str, unit: &'static str) -> Result<f64, String> {
    let (x, written) = split_number(text)?;
    if !x.is_finite() {
        return Err(format!("the bound must be a finite number, got {text}"));
    }
    if written.is_empty() || written == unit {
        return Ok(x);
    }
    let Some(dimension) = dimension_of(unit) else {
        return Err(format!(
            "the metric is in {unit}: give the bound as a bare number in {unit} or as \"{x} {unit}\""
        ));
    };
    let units: Vec<&str> = dimension.unit_names().filter(|u| !u.is_empty()).collect();
    to_si(&toml::Value::String(text.to_string()), dimension).map_err(|_| {
        if units.is_empty() {
            format!("the metric is a pure number: give the bound without a unit, e.g. {x}")
        } else {
            format!(
                "\"{written}\" is not a unit of the metric's dimension (it is in {unit}; units: {})",
                units.join(", ")
            )
        }
    })
}

/// A summary metric of the registry that the case computes, or why not.
fn metric(name: &str, computed: &Computed) -> Result<&'static metrics::MetricDef, String> {
    let names: Vec<&str> = metrics::METRICS.iter().map(|d| d.name).collect();
    let Some(def) = metrics::find(name) else {
        return Err(match crate::schema::nearest(name, &names) {
            Some(near) => format!("unknown metric \"{name}\": did you mean \"{near}\"? (the metrics: docs/results.md)"),
            None => format!("unknown metric \"{name}\" (the metrics: docs/results.md)"),
        });
    };
    match needs(def, computed) {
        Some(why) => Err(format!(
            "\"{name}\" is {why}: this case does not compute it"
        )),
        None => Ok(def),
    }
}

/// "metric <= bound" or "metric >= bound".
fn constraint(text: &str, computed: &Computed) -> Result<Constraint, String> {
    let (split, relation) = match (text.find("<="), text.find(">=")) {
        (Some(k), None) => (k, Relation::AtMost),
        (None, Some(k)) => (k, Relation::AtLeast),
        _ => return Err("must read \"<metric> <= <bound>\" or \"<metric> >= <bound>\", e.g. \"bending_safety_factor >= 1.2\" (one relation, <= or >=)".into()),
    };
    let (name, bound) = (text[..split].trim(), text[split + 2..].trim());
    let def = metric(name, computed)?;
    let bound = bound_si(bound, def.unit)?;
    Ok(Constraint {
        text: text.to_string(),
        metric: name.to_string(),
        unit: def.unit,
        relation,
        bound,
    })
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

/// One variable's range, or the rule it breaks.
fn variable(path: &str, range: &toml::Value, swept: &[String]) -> Result<Variable, String> {
    if path == "name"
        || path.starts_with("optimize")
        || path.starts_with("sweep")
        || !path.contains('.')
    {
        return Err("vary a field by its dotted path, e.g. \"geometry.rod_length\" (not name, sweep or optimize)".into());
    }
    if path.starts_with("mechanisms") || path.contains(['[', ']']) {
        return Err(
            "a list or an item of one cannot be varied: vary a numeric field by its dotted path"
                .into(),
        );
    }
    if swept.iter().any(|s| s == path) {
        return Err(
            "is also swept in [sweep]: a field is either swept or optimised; remove it from one"
                .into(),
        );
    }
    let ends = match range {
        toml::Value::Array(ends) if ends.len() == 2 => ends,
        _ => return Err("must be a range [lower, upper]: two numbers, or two strings with one unit (\"100 mm\")".into()),
    };
    let (Some((lower, unit)), Some((upper, unit_upper))) =
        (number_and_unit(&ends[0]), number_and_unit(&ends[1]))
    else {
        return Err("the range's ends must be numbers, or strings with a unit (\"100 mm\")".into());
    };
    if !(lower.is_finite() && upper.is_finite()) {
        return Err("the range's ends must be finite numbers".into());
    }
    if unit != unit_upper {
        return Err(format!(
            "the range's ends must have the same unit (\"{unit}\" and \"{unit_upper}\")"
        ));
    }
    if lower >= upper {
        return Err(format!("the range is empty: its lower end must be below its upper end (write [{upper}, {lower}] if they were swapped)"));
    }
    Ok(Variable {
        path: path.to_string(),
        lower,
        upper,
        unit,
    })
}

/// The fields a mechanism does not have, left out of its case: another mechanism's own tables
/// and mass tables, and a pin offset where its registry entry has no piston pin to offset.
fn leave_out(table: &mut toml::Table, mechanism: &str) {
    let other = |k: &str| cardan_mechanism::entry(k).is_some() && k != mechanism;
    table.retain(|k, _| !other(k));
    if let Some(toml::Value::Table(masses)) = table.get_mut("masses") {
        masses.retain(|k, _| !other(k));
    }
    let pin = cardan_mechanism::entry(mechanism).is_some_and(|e| e.pin_offset);
    if !pin {
        if let Some(toml::Value::Table(geometry)) = table.get_mut("geometry") {
            geometry.remove("pin_offset");
        }
    }
}

/// Removes the field at the dotted `path` of `table`; whether it was there.
fn remove_path(table: &mut toml::Table, path: &str) -> bool {
    match path.split_once('.') {
        None => table.remove(path).is_some(),
        Some((head, rest)) => match table.get_mut(head) {
            Some(toml::Value::Table(inner)) => remove_path(inner, rest),
            _ => false,
        },
    }
}

impl Optimization {
    /// The optimisation of `table` (a case file with an `[optimize]` table), or `None` if it
    /// has none: its table read and checked, and every mechanism's case validated at each end
    /// of each variable's range and at the two corners of the ranges (what `cardan check`
    /// refuses, the run refuses).
    pub fn define(file: &Path, mut table: toml::Table) -> Result<Option<Self>, CaseError> {
        let Some(spec) = table.remove("optimize") else {
            return Ok(None);
        };
        let name = table
            .get("name")
            .and_then(|n| n.as_str())
            .unwrap_or("(unnamed)")
            .to_string();
        let fail = |field: &str, value: &dyn std::fmt::Display, rule: &str| {
            invalid(file, &name, field, value, rule)
        };
        let raw: OptimizeTable =
            crate::schema::read(spec, "optimize").map_err(|error| CaseError::Field {
                file: file.into(),
                case: name.clone(),
                error,
            })?;
        let swept: Vec<String> = match table.get("sweep") {
            Some(toml::Value::Table(s)) => s.keys().filter(|k| *k != "mode").cloned().collect(),
            _ => Vec::new(),
        };
        if raw.variables.is_empty() {
            return Err(fail("optimize.variables", &"{}", "names no field to vary: give at least one, e.g. { \"geometry.rod_length\" = [\"100 mm\", \"300 mm\"] }"));
        }
        let mut variables = Vec::new();
        for (path, range) in &raw.variables {
            let v = variable(path, range, &swept)
                .map_err(|rule| fail(&format!("optimize.variables.\"{path}\""), range, &rule))?;
            variables.push(v);
        }
        if table.contains_key("sweep") {
            return Err(fail("sweep", &"a [sweep] table", "a case file with [optimize] cannot also sweep: the optimisation varies its own fields; sweep from a case file of its own"));
        }
        let base_case = case_of_table(file, table.clone())?;
        let computed = Computed::of(
            &base_case.gas,
            &base_case.friction,
            &base_case.gear,
            &base_case.dynamics,
            base_case.balance.shaking_per_step,
        );
        let objective = metric(&raw.objective, &computed).map_err(|rule| {
            fail(
                "optimize.objective",
                &format!("\"{}\"", raw.objective),
                &rule,
            )
        })?;
        let mut constraints = Vec::new();
        for text in &raw.constraints {
            let c = constraint(text, &computed)
                .map_err(|rule| fail("optimize.constraints", &format!("\"{text}\""), &rule))?;
            if constraints.iter().any(|o: &Constraint| o.text == c.text) {
                return Err(fail(
                    "optimize.constraints",
                    &format!("\"{text}\""),
                    "is listed twice",
                ));
            }
            constraints.push(c);
        }
        let tolerance = raw.tolerance.as_ref().map_or(1e-4, |t| t.si);
        let optimization = Self {
            file: file.into(),
            name: name.clone(),
            mechanisms: base_case
                .mechanisms
                .iter()
                .map(|m| m.name().to_string())
                .collect(),
            base: table,
            objective: raw.objective.clone(),
            objective_unit: objective.unit,
            sense: raw.sense,
            variables,
            constraints,
            starts: raw.starts.map_or(4, |w| w.0 as usize),
            seed: raw.seed.map_or(1, |w| w.0 as u64),
            max_evaluations: raw.max_evaluations.map_or(200, |w| w.0 as usize),
            tolerance,
        };
        optimization.check_ranges()?;
        Ok(Some(optimization))
    }

    /// The whole validated definition in the program's own form (`Debug`), except the path of
    /// its file (a case file moved or run from another folder is the same optimisation): the
    /// case table it varies, the objective, variables, constraints and the search's settings;
    /// the runner's input hash of an optimisation's folder is made from it.
    pub fn definition(&self) -> String {
        let definition = Self {
            file: PathBuf::new(),
            ..self.clone()
        };
        format!("{definition:?}")
    }

    /// Whether variable `k` is a field of `mechanism` (a field of another mechanism's own tables, or a pin offset where it has no piston pin, is not).
    pub fn applies(&self, mechanism: &str, k: usize) -> bool {
        let v = &self.variables[k];
        let pin = cardan_mechanism::entry(mechanism).is_some_and(|e| e.pin_offset);
        !v.belongs_to_other(mechanism) && (pin || v.path != "geometry.pin_offset")
    }

    /// The case of `mechanism` alone with variable k at `values[k]` (in the unit written; `None`:
    /// as the case file gives it), the fields it does not have left out.
    pub fn case_at(&self, mechanism: &str, values: &[Option<f64>]) -> Result<Case, CaseError> {
        let mut table = self.base.clone();
        table.insert(
            "mechanisms".into(),
            toml::Value::Array(vec![toml::Value::String(mechanism.into())]),
        );
        leave_out(&mut table, mechanism);
        for (v, x) in self.variables.iter().zip(values) {
            if let Some(x) = x {
                crate::sweep::set(&mut table, &v.path, v.text(*x)).map_err(|rule| {
                    invalid(
                        &self.file,
                        &self.name,
                        &format!("optimize.variables.\"{}\"", v.path),
                        &v.text(*x),
                        &rule,
                    )
                })?;
            }
        }
        // A field of the case that this mechanism alone does not read ([gear] without a mesh,
        // a pin offset without a pin) is refused by the case's own rule: left out for it.
        for _ in 0..8 {
            match case_of_table(&self.file, table.clone()) {
                Err(CaseError::Invalid { field, rule, .. })
                    if (rule.contains("no mechanism of the case")
                        || rule.contains("not among the case's mechanisms"))
                        && !self.variables.iter().any(|v| v.path == field)
                        && remove_path(&mut table, &field) => {}
                other => return other,
            }
        }
        case_of_table(&self.file, table)
    }

    /// Every mechanism's case validated at each end of each variable's range (the others as
    /// the case file gives them) and at the ranges' two corners; a failure names the variable
    /// and the end, with the case's own message.
    fn check_ranges(&self) -> Result<(), CaseError> {
        for m in &self.mechanisms {
            let active: Vec<usize> = (0..self.variables.len())
                .filter(|&k| self.applies(m, k))
                .collect();
            self.case_at(m, &vec![None; self.variables.len()])?;
            for &k in &active {
                for (end, u) in [("lower", 0.0), ("upper", 1.0)] {
                    let mut values = vec![None; self.variables.len()];
                    let v = &self.variables[k];
                    values[k] = Some(v.at(u));
                    self.case_at(m, &values).map_err(|e| {
                        invalid(&self.file, &self.name, &format!("optimize.variables.\"{}\"", v.path), &v.text(v.at(u)), &format!("the {m}'s case at the range's {end} end does not validate: narrow the range ({e})"))
                    })?;
                }
            }
            for (end, u) in [("lower", 0.0), ("upper", 1.0)] {
                let values: Vec<Option<f64>> = (0..self.variables.len())
                    .map(|k| active.contains(&k).then(|| self.variables[k].at(u)))
                    .collect();
                self.case_at(m, &values).map_err(|e| {
                    invalid(
                        &self.file,
                        &self.name,
                        "optimize.variables",
                        &format!("every variable at its {end} end"),
                        &format!("the {m}'s case there does not validate: narrow the ranges ({e})"),
                    )
                })?;
            }
        }
        Ok(())
    }
}
