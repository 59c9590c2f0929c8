//! One optimisation's searches: for each mechanism, the variables it has (a variable of
//! another mechanism's tables, or one that changes none of the objective's and constraints'
//! values at its two ends, is left out and said so), the constraints on metrics its summary
//! has (the others left out and said so), then `cardan-optimize`'s search over the unit cube of
//! its variables.

use crate::memory::run_in_memory;
use crate::output::MechanismResult;
use cardan_case::case::Case;
use cardan_case::optimize::{Optimization, Sense};
use cardan_case::CaseError;
use cardan_optimize::{minimise, Optimum, Outcome, Settings};

/// One mechanism's optimisation.
#[derive(Debug, Clone)]
pub struct MechanismOptimum {
    pub mechanism: String,
    /// The variables searched (indices into the optimisation's).
    pub active: Vec<usize>,
    /// The variables left out, each with why.
    pub left_out: Vec<(String, String)>,
    /// The constraints (indices) that hold for this mechanism's summary.
    pub constraints: Vec<usize>,
    /// The constraints left out, each with why.
    pub constraints_left_out: Vec<(String, String)>,
    /// Evaluations spent finding which variables and constraints apply.
    pub probes: usize,
    pub settings: Settings,
    pub optimum: Optimum,
    /// The best point's case and result (`None` if no evaluation ran).
    pub best: Option<(Case, MechanismResult)>,
}

impl MechanismOptimum {
    /// The value of every variable (in the unit written) at unit-cube point `u` of the active
    /// ones (`None`: not varied for this mechanism).
    pub fn values(&self, o: &Optimization, u: &[f64]) -> Vec<Option<f64>> {
        let mut values = vec![None; o.variables.len()];
        for (j, &k) in self.active.iter().enumerate() {
            values[k] = Some(o.variables[k].at(u[j]));
        }
        values
    }
}

/// The case of `mechanism` at `values`, run: its first crank train's result.
fn run_at(
    o: &Optimization,
    mechanism: &str,
    values: &[Option<f64>],
) -> Result<(Case, MechanismResult), String> {
    let case = o.case_at(mechanism, values).map_err(|e| e.to_string())?;
    let run = run_in_memory(&case, false)?;
    let result = run
        .results
        .into_iter()
        .next()
        .ok_or("the case ran no crank train")?;
    Ok((case, result))
}

/// The outcome of a result for the search: the objective (negated to maximise) and each
/// constraint's relative margin.
fn outcome(o: &Optimization, constraints: &[usize], result: &MechanismResult) -> Outcome {
    let Some(value) = result.summary.get(&o.objective) else {
        return Outcome::Failed(format!("the summary has no metric {}", o.objective));
    };
    let objective = match o.sense {
        Sense::Max => -value,
        Sense::Min => value,
    };
    let margins = constraints
        .iter()
        .map(|&c| {
            let c = &o.constraints[c];
            result
                .summary
                .get(&c.metric)
                .map_or(f64::NAN, |v| c.relative_margin(v))
        })
        .collect();
    Outcome::Value { objective, margins }
}

/// The values (objective, then each constraint's metric) a variable's end gives, to compare.
fn watched(o: &Optimization, constraints: &[usize], result: &MechanismResult) -> Vec<Option<u64>> {
    std::iter::once(&o.objective)
        .chain(constraints.iter().map(|&c| &o.constraints[c].metric))
        .map(|m| result.summary.get(m).map(f64::to_bits))
        .collect()
}

/// Every variable of `mechanism` at the middle of its range, the others as the file gives them:
/// where [`applicable`] and [`check_metrics`] look at what its summary reports.
fn middle(o: &Optimization, mechanism: &str) -> Vec<Option<f64>> {
    (0..o.variables.len())
        .map(|k| o.applies(mechanism, k).then(|| o.variables[k].at(0.5)))
        .collect()
}

/// The objective and the constraints checked against what the mechanisms' summaries report,
/// each mechanism's case run once at the middle of its ranges: the objective must be a metric
/// of every mechanism's summary (each is optimised on it), a constraint's metric of at least
/// one (a constraint binds the mechanisms that have its metric and is left out, said so, for
/// the others); a name the registry knows but no mechanism reports (another mechanism's joint
/// or body, a gear metric without a gear mesh) is refused naming the file, the field, the
/// metric and the nearest metric reported. `cardan check` and `cardan run` both refuse through
/// it (the batch's reading calls it), and so does [`optimize`].
pub fn check_metrics(o: &Optimization) -> Result<(), CaseError> {
    let invalid = |field: &str, value: String, rule: String| CaseError::Invalid {
        file: o.file.clone(),
        case: o.name.clone(),
        field: field.into(),
        value,
        rule,
    };
    let mut reported: Vec<(&str, Vec<String>)> = Vec::new();
    for m in &o.mechanisms {
        let (_, result) = run_at(o, m, &middle(o, m)).map_err(|e| {
            invalid(
                "optimize.variables",
                "every variable at the middle of its range".into(),
                format!("the {m}'s case there does not run, so its metrics are not known: narrow the ranges ({e})"),
            )
        })?;
        let names = result
            .summary
            .metrics
            .iter()
            .map(|x| x.name.clone())
            .collect();
        reported.push((m, names));
    }
    let nearest = |metric: &str, names: &[&String]| {
        let names: Vec<&str> = names.iter().map(|s| s.as_str()).collect();
        cardan_case::schema::nearest(metric, &names)
            .map_or(String::new(), |near| format!("did you mean \"{near}\"? "))
    };
    for (m, names) in &reported {
        if !names.contains(&o.objective) {
            let near = nearest(&o.objective, &names.iter().collect::<Vec<_>>());
            return Err(invalid(
                "optimize.objective",
                format!("\"{}\"", o.objective),
                format!("the {m}'s summary has no metric \"{}\" (the metrics of its summary.json; docs/results.md): {near}optimise a metric every mechanism of the case reports, or optimise the {m} in a case file of its own", o.objective),
            ));
        }
    }
    for c in &o.constraints {
        if reported.iter().any(|(_, names)| names.contains(&c.metric)) {
            continue;
        }
        let all: Vec<&String> = reported.iter().flat_map(|(_, n)| n).collect();
        let whose: Vec<String> = reported.iter().map(|(m, _)| format!("the {m}'s")).collect();
        return Err(invalid(
            "optimize.constraints",
            format!("\"{}\"", c.text),
            format!(
                "no mechanism of the case reports the metric \"{}\" ({} summary has no such metric; docs/results.md): {}constrain a metric one of them reports, or add the mechanism that has it to `mechanisms`",
                c.metric,
                whose.join(" and "),
                nearest(&c.metric, &all)
            ),
        ));
    }
    Ok(())
}

/// Which variables and constraints apply to `mechanism` (module docs), and the evaluations
/// that cost.
fn applicable(o: &Optimization, mechanism: &str) -> Result<MechanismOptimum, String> {
    let n = o.variables.len();
    let mut m = MechanismOptimum {
        mechanism: mechanism.to_string(),
        active: Vec::new(),
        left_out: Vec::new(),
        constraints: Vec::new(),
        constraints_left_out: Vec::new(),
        probes: 0,
        settings: settings(o),
        optimum: Optimum {
            best: None,
            best_start: 0,
            starts: Vec::new(),
        },
        best: None,
    };
    let mut candidates = Vec::new();
    for k in 0..n {
        if o.applies(mechanism, k) {
            candidates.push(k);
        } else {
            m.left_out.push((
                o.variables[k].path.clone(),
                format!("not a field of the {mechanism}"),
            ));
        }
    }
    let middle = middle(o, mechanism);
    m.probes += 1;
    let (_, centre) = run_at(o, mechanism, &middle)
        .map_err(|e| format!("the {mechanism} at the middle of the ranges: {e}"))?;
    if centre.summary.get(&o.objective).is_none() {
        return Err(format!("the {mechanism}'s summary has no metric {} (optimize.objective): optimise a metric it has, or list it apart", o.objective));
    }
    for (c, constraint) in o.constraints.iter().enumerate() {
        if centre.summary.get(&constraint.metric).is_some() {
            m.constraints.push(c);
        } else {
            m.constraints_left_out.push((
                constraint.text.clone(),
                format!(
                    "the {mechanism}'s summary has no metric {}",
                    constraint.metric
                ),
            ));
        }
    }
    for k in candidates {
        let ends: Vec<Result<Vec<Option<u64>>, String>> = [0.0, 1.0]
            .iter()
            .map(|&u| {
                let mut values = middle.clone();
                values[k] = Some(o.variables[k].at(u));
                run_at(o, mechanism, &values).map(|(_, r)| watched(o, &m.constraints, &r))
            })
            .collect();
        m.probes += 2;
        match (&ends[0], &ends[1]) {
            (Ok(a), Ok(b)) if a == b => m.left_out.push((
                o.variables[k].path.clone(),
                format!("changes neither the objective nor a constraint's metric of the {mechanism} from one end of its range to the other"),
            )),
            _ => m.active.push(k),
        }
    }
    Ok(m)
}

/// The search's settings from the optimisation's.
fn settings(o: &Optimization) -> Settings {
    Settings {
        starts: o.starts,
        seed: o.seed,
        max_evaluations: o.max_evaluations,
        tolerance: o.tolerance,
        ..Settings::default()
    }
}

/// Every mechanism of `o` optimised (module docs), in the case's order; a mechanism that
/// cannot be (its summary lacks the objective, its case fails at the middle of the ranges) is
/// the failure of the whole optimisation, said with the mechanism.
pub fn optimize(o: &Optimization) -> Result<Vec<MechanismOptimum>, String> {
    check_metrics(o).map_err(|e| e.to_string())?;
    let mut out = Vec::new();
    for mechanism in &o.mechanisms {
        let mut m = applicable(o, mechanism)
            .map_err(|e| format!("{}: case \"{}\": optimize: {e}", o.file.display(), o.name))?;
        let f = |u: &[f64]| -> Outcome {
            match run_at(o, mechanism, &m.values(o, u)) {
                Ok((_, result)) => outcome(o, &m.constraints, &result),
                Err(e) => Outcome::Failed(e),
            }
        };
        m.optimum = minimise(m.active.len(), &m.settings, &f);
        if let Some(best) = &m.optimum.best {
            m.best = run_at(o, mechanism, &m.values(o, &best.x)).ok();
        }
        out.push(m);
    }
    Ok(out)
}
