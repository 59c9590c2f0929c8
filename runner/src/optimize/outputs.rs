//! An optimisation's folder, written into a temporary folder that then replaces
//! `<out>/<name>/` whole: per mechanism `optimum.json` (the variables, objective, every
//! constraint with its margin, the evaluations, the stopping reason, what sits on a bound or a
//! constraint, the failures), `history.csv` (every evaluation) and `summary.json` (its run at
//! the optimum); `convergence.svg`; `at-optima/` (every mechanism at its own optimum in one
//! `summary.json`, with the case report's side-by-side comparison); `report.md`; and last the
//! folder's record, `run.json` (`crate::run::stamp`), as a case folder's.

use super::search::MechanismOptimum;
use crate::output::summary_json;
use crate::run::stamp;
use cardan_case::optimize::{Optimization, Relation, Sense};
use cardan_optimize::{Outcome, Record};
use cardan_report::files;
use serde_json::{json, Value};
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

/// A variable this close to an end of its range (fraction of the range) sits on that bound.
const ON_BOUND: f64 = 1e-9;

/// A constraint whose relative margin is at most this is active (the optimum sits on it): ten
/// times the default location tolerance, in the constraint's relative terms.
const ACTIVE: f64 = 1e-3;

/// The objective in SI from a record's outcome (the search minimises −objective to maximise).
fn objective(o: &Optimization, outcome: &Outcome) -> Option<f64> {
    outcome.objective().map(|v| match o.sense {
        Sense::Max => -v,
        Sense::Min => v,
    })
}

/// Constraint `c`'s metric value (SI) from its relative margin.
fn constraint_value(o: &Optimization, c: usize, margin: f64) -> f64 {
    let c = &o.constraints[c];
    let scale = if c.bound == 0.0 { 1.0 } else { c.bound.abs() };
    match c.relation {
        Relation::AtMost => c.bound - margin * scale,
        Relation::AtLeast => c.bound + margin * scale,
    }
}

/// Where a variable at `u` (fraction of its range) sits: "lower", "upper" or none.
fn bound_of(u: f64) -> Value {
    if u <= ON_BOUND {
        json!("lower")
    } else if u >= 1.0 - ON_BOUND {
        json!("upper")
    } else {
        Value::Null
    }
}

/// `optimum.json` of one mechanism (also what `cardan.optimize` returns per mechanism).
pub fn optimum_json(o: &Optimization, m: &MechanismOptimum) -> Value {
    let best = m.optimum.best.as_ref();
    let values = best.map(|b| m.values(o, &b.x)).unwrap_or_default();
    let variables: Vec<Value> = m
        .active
        .iter()
        .enumerate()
        .map(|(j, &k)| {
            let v = &o.variables[k];
            let u = best.map_or(f64::NAN, |b| b.x[j]);
            json!({
                "path": v.path, "value": values.get(k).copied().flatten(), "unit": v.unit,
                "lower": v.lower, "upper": v.upper, "on_bound": bound_of(u),
            })
        })
        .collect();
    let margins = match best.map(|b| &b.outcome) {
        Some(Outcome::Value { margins, .. }) => margins.clone(),
        _ => Vec::new(),
    };
    let constraints: Vec<Value> = m
        .constraints
        .iter()
        .zip(&margins)
        .map(|(&c, &r)| {
            let k = &o.constraints[c];
            let value = constraint_value(o, c, r);
            json!({
                "constraint": k.text, "metric": k.metric, "unit": k.unit, "value": value,
                "bound": k.bound, "margin": k.margin(value), "relative_margin": r,
                "satisfied": r >= 0.0, "active": r.abs() <= ACTIVE,
            })
        })
        .collect();
    let stop = m
        .optimum
        .starts
        .get(m.optimum.best_start)
        .map(|s| s.stop.describe(&m.settings));
    let failures: Vec<Value> = m
        .optimum
        .failures()
        .take(20)
        .map(|r| match &r.outcome {
            Outcome::Failed(why) => {
                json!({ "start": r.start, "evaluation": r.evaluation, "reason": why })
            }
            _ => Value::Null,
        })
        .collect();
    let left_out = |list: &[(String, String)]| -> Vec<Value> {
        list.iter()
            .map(|(what, why)| json!({ "name": what, "why": why }))
            .collect()
    };
    json!({
        "mechanism": m.mechanism,
        "objective": {
            "metric": o.objective, "unit": o.objective_unit,
            "sense": match o.sense { Sense::Max => "max", Sense::Min => "min" },
            "value": best.and_then(|b| objective(o, &b.outcome)),
        },
        "feasible": m.optimum.feasible(),
        "variables": variables,
        "variables_left_out": left_out(&m.left_out),
        "constraints": constraints,
        "constraints_left_out": left_out(&m.constraints_left_out),
        "evaluations": m.optimum.evaluations(),
        "probe_evaluations": m.probes,
        "failed_evaluations": m.optimum.failures().count(),
        "failures": failures,
        "stopping_reason": stop,
        "best_start": m.optimum.best_start,
        "starts": m.optimum.starts.iter().map(|s| json!({
            "evaluations": s.records.len(),
            "stopping_reason": s.stop.describe(&m.settings),
            "objective": s.best.as_ref().and_then(|b| objective(o, &b.outcome)),
            "feasible": s.best.as_ref().is_some_and(|b| b.outcome.feasible()),
        })).collect::<Vec<_>>(),
        "settings": {
            "method": "Nelder-Mead (Lagarias et al. 1998) with restarts, then compass search (Kolda, Lewis & Torczon 2003); constraints by Deb's (2000) feasibility rules; starts from a Latin hypercube",
            "starts": m.settings.starts, "seed": m.settings.seed,
            "max_evaluations_per_start": m.settings.max_evaluations,
            "tolerance": m.settings.tolerance,
        },
    })
}

/// The best feasible objective after each evaluation of `records` (NaN until one is feasible).
fn best_so_far(o: &Optimization, records: &[&Record]) -> Vec<f64> {
    let mut best: Option<f64> = None;
    records
        .iter()
        .map(|r| {
            if r.outcome.feasible() {
                let v = objective(o, &r.outcome).unwrap_or(f64::NAN);
                best = Some(match (best, o.sense) {
                    (None, _) => v,
                    (Some(b), Sense::Max) => b.max(v),
                    (Some(b), Sense::Min) => b.min(v),
                });
            }
            best.unwrap_or(f64::NAN)
        })
        .collect()
}

/// `history.csv`: every evaluation, start after start.
fn history_csv(o: &Optimization, m: &MechanismOptimum) -> (String, Vec<f64>) {
    let records: Vec<&Record> = m.optimum.history().collect();
    let best = best_so_far(o, &records);
    let mut t = String::from("start,evaluation,phase");
    for &k in &m.active {
        let v = &o.variables[k];
        let _ = write!(
            t,
            ",{}{}",
            v.path,
            if v.unit.is_empty() {
                String::new()
            } else {
                format!(" [{}]", v.unit)
            }
        );
    }
    let _ = write!(t, ",{} [{}]", o.objective, o.objective_unit);
    for &c in &m.constraints {
        let _ = write!(
            t,
            ",{} [{}]",
            o.constraints[c].metric, o.constraints[c].unit
        );
    }
    t.push_str(",violation,feasible,best_so_far,failure\n");
    for (r, b) in records.iter().zip(&best) {
        let _ = write!(t, "{},{},{}", r.start, r.evaluation, r.phase);
        for (j, &k) in m.active.iter().enumerate() {
            let _ = write!(t, ",{}", o.variables[k].at(r.x[j]));
        }
        let cell = |x: Option<f64>| x.map_or(String::new(), |x| x.to_string());
        let _ = write!(t, ",{}", cell(objective(o, &r.outcome)));
        let margins = match &r.outcome {
            Outcome::Value { margins, .. } => margins.clone(),
            Outcome::Failed(_) => vec![f64::NAN; m.constraints.len()],
        };
        for (&c, &margin) in m.constraints.iter().zip(&margins) {
            let _ = write!(
                t,
                ",{}",
                cell(margin.is_finite().then(|| constraint_value(o, c, margin)))
            );
        }
        let failure = match &r.outcome {
            Outcome::Failed(why) => format!("\"{}\"", why.replace('"', "'")),
            _ => String::new(),
        };
        let _ = writeln!(
            t,
            ",{},{},{},{failure}",
            r.outcome.violation(),
            r.outcome.feasible(),
            cell(b.is_finite().then_some(*b))
        );
    }
    (t, best)
}

/// Writes the optimisation's folder `<out>/<name>/` (module docs), with the reports unless
/// `reports` is false; returns the folder.
pub fn write(
    o: &Optimization,
    results: &[MechanismOptimum],
    out: &Path,
    reports: bool,
) -> Result<PathBuf, String> {
    let dir = out.join(&o.name);
    let fail = |e: anyhow::Error| {
        format!(
            "{}: case \"{}\": cannot write {}: {e:#}",
            o.file.display(),
            o.name,
            dir.display()
        )
    };
    let tmp = files::temporary_dir(&dir).map_err(fail)?;
    let mut searches = Vec::new();
    for m in results {
        let folder = tmp.join(&m.mechanism);
        std::fs::create_dir_all(&folder).map_err(|e| fail(e.into()))?;
        let text = serde_json::to_string_pretty(&optimum_json(o, m)).unwrap_or_default();
        files::write_file(&folder.join("optimum.json"), text.as_bytes()).map_err(fail)?;
        let (csv, best) = history_csv(o, m);
        files::write_file(&folder.join("history.csv"), csv.as_bytes()).map_err(fail)?;
        if let Some((case, result)) = &m.best {
            let summary =
                serde_json::to_string_pretty(&summary_json(case, std::slice::from_ref(result)))
                    .unwrap_or_default();
            files::write_file(&folder.join("summary.json"), summary.as_bytes()).map_err(fail)?;
        }
        searches.push(cardan_report::Convergence {
            label: m.mechanism.clone(),
            best_so_far: best,
        });
    }
    let chart = cardan_report::convergence_chart(&o.objective, o.objective_unit, &searches);
    files::write_file(&tmp.join("convergence.svg"), chart.as_bytes()).map_err(fail)?;
    let bests: Vec<_> = results.iter().filter_map(|m| m.best.clone()).collect();
    if let Some((case, _)) = bests.first() {
        let at = tmp.join("at-optima");
        std::fs::create_dir_all(&at).map_err(|e| fail(e.into()))?;
        let all: Vec<_> = bests.iter().map(|(_, r)| r.clone()).collect();
        let summary = serde_json::to_string_pretty(&summary_json(case, &all)).unwrap_or_default();
        files::write_file(&at.join("summary.json"), summary.as_bytes()).map_err(fail)?;
        if reports {
            cardan_report::case_report(&at, None).map_err(fail)?;
        }
    }
    files::write_file(&tmp.join("report.md"), report_md(o, results).as_bytes()).map_err(fail)?;
    // Last: the record that vouches for the folder (`--resume`, `cardan merge`).
    stamp::write_optimization(&tmp, o, reports).map_err(fail)?;
    files::replace_dir(&tmp, &dir).map_err(fail)?;
    Ok(dir)
}

/// `report.md`: each mechanism at its own optimum, side by side.
pub fn report_md(o: &Optimization, results: &[MechanismOptimum]) -> String {
    let jsons: Vec<Value> = results.iter().map(|m| optimum_json(o, m)).collect();
    let mut t = report_heading(o, results);
    let row = |t: &mut String, label: &str, cell: &dyn Fn(&Value) -> String| {
        let cells: Vec<String> = jsons.iter().map(cell).collect();
        let _ = writeln!(t, "| {label} | {} |", cells.join(" | "));
    };
    row(
        &mut t,
        &format!("{} [{}]", o.objective, o.objective_unit),
        &|j| number(&j["objective"]["value"]),
    );
    row(&mut t, "feasible", &|j| {
        if j["feasible"] == true {
            "yes".into()
        } else {
            "**no**: least violation shown".into()
        }
    });
    for v in &o.variables {
        row(&mut t, &format!("{} [{}]", v.path, v.unit), &|j| {
            variable_cell(j, &v.path)
        });
    }
    for c in &o.constraints {
        row(&mut t, &format!("{} [{}]", c.text, c.unit), &|j| {
            constraint_cell(j, &c.text)
        });
    }
    row(&mut t, "evaluations (probes)", &|j| {
        format!("{} ({})", j["evaluations"], j["probe_evaluations"])
    });
    row(&mut t, "failed evaluations", &|j| {
        j["failed_evaluations"].to_string()
    });
    row(&mut t, "stopping reason", &|j| {
        j["stopping_reason"].as_str().unwrap_or("—").to_string()
    });
    left_out(&mut t, &jsons);
    t.push_str("\n![convergence](convergence.svg)\n\nEvery metric of every mechanism at its own optimum, side by side: [at-optima/report.md](at-optima/report.md). Each mechanism's search: `<mechanism>/optimum.json`, `<mechanism>/history.csv`.\n");
    t
}

/// `report.md`'s title, the objective and constraints in words, and its table's header (a
/// column per mechanism).
fn report_heading(o: &Optimization, results: &[MechanismOptimum]) -> String {
    let sense = match o.sense {
        Sense::Max => "maximised",
        Sense::Min => "minimised",
    };
    let mut t = format!(
        "# Optimisation: {}\n\nEach mechanism at its own best: `{}` {sense}",
        o.name, o.objective
    );
    if !o.constraints.is_empty() {
        let list: Vec<String> = o
            .constraints
            .iter()
            .map(|c| format!("`{}`", c.text))
            .collect();
        let _ = write!(t, " subject to {}", list.join(", "));
    }
    t.push_str(".\n\n| | ");
    t.push_str(
        &results
            .iter()
            .map(|m| m.mechanism.as_str())
            .collect::<Vec<_>>()
            .join(" | "),
    );
    t.push_str(" |\n|---|");
    t.push_str(&"---|".repeat(results.len()));
    t.push('\n');
    t
}

/// A number of `optimum.json` in `report.md`'s table (6 decimals), "—" if none.
fn number(v: &Value) -> String {
    v.as_f64().map_or("—".to_string(), |x| format!("{x:.6}"))
}

/// A mechanism's (`optimum.json` `j`) value of the variable `path` in `report.md`'s table, with
/// the bound it ends on; "left out" if the mechanism has no such field.
fn variable_cell(j: &Value, path: &str) -> String {
    let found = j["variables"]
        .as_array()
        .and_then(|a| a.iter().find(|x| x["path"] == path));
    match found {
        Some(x) => match x["on_bound"].as_str() {
            Some(b) => format!("{} (on its {b} bound)", number(&x["value"])),
            None => number(&x["value"]),
        },
        None => "left out".into(),
    }
}

/// A mechanism's (`optimum.json` `j`) value of the constraint `text` in `report.md`'s table, with
/// its margin and whether it is active or violated; "left out" if the mechanism has no such
/// metric.
fn constraint_cell(j: &Value, text: &str) -> String {
    let found = j["constraints"]
        .as_array()
        .and_then(|a| a.iter().find(|x| x["constraint"] == text));
    match found {
        Some(x) => format!(
            "{} (margin {}{})",
            number(&x["value"]),
            number(&x["margin"]),
            if x["active"] == true {
                ", active"
            } else if x["satisfied"] == false {
                ", **violated**"
            } else {
                ""
            }
        ),
        None => "left out".into(),
    }
}

/// `report.md`'s list of the variables and constraints each mechanism left out, and why.
fn left_out(t: &mut String, jsons: &[Value]) {
    t.push_str("\nLeft out (a field or metric a mechanism does not have):\n\n");
    for j in jsons {
        for what in ["variables_left_out", "constraints_left_out"] {
            for x in j[what].as_array().into_iter().flatten() {
                let _ = writeln!(
                    t,
                    "- {}: `{}`: {}",
                    j["mechanism"].as_str().unwrap_or(""),
                    x["name"].as_str().unwrap_or(""),
                    x["why"].as_str().unwrap_or("")
                );
            }
        }
    }
}
