//! The report of one case: metric tables by group with the difference to the reference, the
//! "which is better" summary, the loss budget; the charts over crank angle are drawn by
//! `case_plots.rs`.

use crate::case_plots::{charts, locus_charts, plot_specs};
use crate::chart_columns::wanted_columns;
use crate::data::{self, family_rank, CaseSummary, MechanismSummary};
use crate::doc::{write_report, Align, Block, Doc};
use crate::envelope::{ChartData, ChartRecorder};
use crate::numbers::{
    better, delta, engineering, fmt_delta, fmt_num, phrase, round_off_floor, signed, Better, Delta,
    ROUND_OFF_LEGEND, SIGN_LEGEND,
};
use crate::svg::{self, MAX_POINTS};
use cardan_metrics::Group as MetricGroup;
use rayon::prelude::*;
use std::collections::BTreeMap;
use std::path::Path;

/// Groups of the metric tables, in report order.
#[derive(Debug, Clone, PartialEq, Eq, PartialOrd, Ord)]
enum Group {
    /// The whole machine: every cylinder's torque, power, losses, journal and pin loads.
    Machine,
    Kinematics,
    /// Loads at one joint.
    Joint(String),
    Torque,
    Gas,
    /// The rating of the gear meshes.
    Gears,
    Losses,
    /// The machine's shaking forces and moments (the order table).
    Balance,
    Other,
}

impl Group {
    /// The section's title; `whose` names the one cylinder the per-cylinder sections are of,
    /// when the machine has more ([`CaseSummary::one_cylinder`]).
    fn title(&self, whose: Option<&str>) -> String {
        let title = self.subject();
        match (self, whose) {
            (Group::Machine | Group::Balance | Group::Other, _) | (_, None) => title,
            (Group::Kinematics, Some(w)) => {
                format!("{title}: the crank's motion; the piston and rod of {w}")
            }
            (_, Some(w)) => format!("{title}: {w}"),
        }
    }

    fn subject(&self) -> String {
        match self {
            Group::Machine => "The whole machine".into(),
            Group::Kinematics => "Kinematics".into(),
            Group::Joint(j) => format!("Joint loads: `{j}`"),
            Group::Torque => "Drive torque, power and work".into(),
            Group::Gas => "Cylinder and gas".into(),
            Group::Gears => "Gear rating".into(),
            Group::Losses => "Losses and efficiency".into(),
            Group::Balance => "Balance: shaking forces and moments".into(),
            Group::Other => "Other".into(),
        }
    }
}

/// The group of a metric and its sort key within the group.
fn classify(metric: &str, families: &[String]) -> (Group, (usize, (usize, String), String)) {
    let def = cardan_metrics::find(metric);
    let registry = def.map_or(usize::MAX, |d| {
        cardan_metrics::METRICS
            .iter()
            .position(|m| m.name == d.name)
            .unwrap_or(usize::MAX)
    });
    let family = families
        .iter()
        .find(|f| metric.starts_with(&format!("{f}_")))
        .cloned();
    let key = (
        registry,
        family_rank(family.as_deref().unwrap_or("")),
        metric.to_string(),
    );
    // The registry's group; a joint's loads get a section per joint (the name after the
    // family), and a joint metric whose family the case does not list stays with the torque.
    let group = match def.map(|d| d.group) {
        None => Group::Other,
        Some(MetricGroup::Kinematics) => Group::Kinematics,
        Some(MetricGroup::JointLoads) => match &family {
            Some(f) => {
                let rest = &metric[f.len() + 1..];
                let joint = ["_force_max", "_moment_max", "_tangential_max"]
                    .iter()
                    .find_map(|s| rest.strip_suffix(s))
                    .unwrap_or(rest);
                Group::Joint(joint.to_string())
            }
            None => Group::Torque,
        },
        Some(MetricGroup::DriveTorque) => Group::Torque,
        Some(MetricGroup::Gas) => Group::Gas,
        Some(MetricGroup::GearRating) => Group::Gears,
        Some(MetricGroup::Losses) => Group::Losses,
        Some(MetricGroup::Balance) => Group::Balance,
        Some(MetricGroup::Machine) => Group::Machine,
    };
    (group, key)
}

/// The load families of a case: the prefixes `f` of the metrics `f_torque_max`.
fn families(s: &CaseSummary) -> Vec<String> {
    let mut f: Vec<String> = s
        .mechanisms
        .iter()
        .flat_map(|m| m.metrics.keys())
        .filter_map(|k| k.strip_suffix("_torque_max"))
        .filter(|f| !f.is_empty() && *f != "friction")
        .map(String::from)
        .collect();
    f.sort_by_key(|x| family_rank(x));
    f.dedup();
    f
}

/// How a headline figure is read from a mechanism's metrics.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Source {
    /// The metric as it is.
    Metric(&'static str),
    /// The metric with its sign turned: an engine's mean output from the machine's signed
    /// mean power (`machine_power_mean` is negative when the machine gives power out).
    Negated(&'static str),
    /// The larger magnitude of a signed maximum and minimum: the peak of a signed torque
    /// (`machine_torque_max`, `machine_torque_min`), whichever way it turns.
    Peak(&'static str, &'static str),
}

impl Source {
    /// The metric whose unit (and round-off floor) the figure has.
    fn metric(self) -> &'static str {
        match self {
            Source::Metric(m) | Source::Negated(m) | Source::Peak(m, _) => m,
        }
    }

    /// The figure of mechanism `m`, if it has the metrics.
    fn value(self, m: &MechanismSummary) -> Option<f64> {
        match self {
            Source::Metric(k) => m.get(k),
            Source::Negated(k) => m.get(k).map(|v| -v),
            Source::Peak(hi, lo) => Some(m.get(hi)?.abs().max(m.get(lo)?.abs())),
        }
    }

    /// The round-off floor of the figure (a signed mean's, [`round_off_floor`]).
    fn floor(self, m: &MechanismSummary) -> Option<f64> {
        match self {
            Source::Metric(k) | Source::Negated(k) => round_off_floor(k, |x| m.get(x)),
            Source::Peak(..) => None,
        }
    }

    /// How the figure is made, in a report's words.
    fn describe(self) -> String {
        match self {
            Source::Metric(k) => format!("`{k}`"),
            Source::Negated(k) => format!("−`{k}`"),
            Source::Peak(hi, lo) => format!("the larger of |`{hi}`| and |`{lo}`|"),
        }
    }
}

/// One headline comparison of the summary: what, the alternatives (the first that two
/// mechanisms have is compared) and which way is better (the registry's for a plain metric).
#[derive(Debug, Clone)]
struct Headline {
    what: String,
    alternatives: Vec<Source>,
    direction: Better,
}

/// The whole machine's headline comparisons (issue 35): its mean power need (a pump's or
/// compressor's; an engine's mean output power, −`machine_power_mean`), its peak drive
/// torque, the peak loads of its main journals and crank pins, its mechanical efficiency and
/// its friction losses. Every cylinder counts, each at its own crank angle.
fn machine_headlines(s: &CaseSummary) -> Vec<Headline> {
    let headline = |what: &str, source: Source, direction: Better| Headline {
        what: what.into(),
        alternatives: vec![source],
        direction,
    };
    let power = if s.is_engine() {
        headline(
            "Mean output power of the machine",
            Source::Negated("machine_power_mean"),
            Better::Higher,
        )
    } else {
        headline(
            "Mean power need of the machine",
            Source::Metric("machine_power_mean"),
            Better::Lower,
        )
    };
    vec![
        power,
        headline(
            "Peak drive torque of the machine",
            Source::Peak("machine_torque_max", "machine_torque_min"),
            Better::Lower,
        ),
        headline(
            "Peak main-journal load of the machine",
            Source::Metric("machine_main_bearing_force_max"),
            Better::Lower,
        ),
        headline(
            "Peak crank-pin load of the machine",
            Source::Metric("machine_crank_pin_force_max"),
            Better::Lower,
        ),
        headline(
            "Mechanical efficiency of the machine",
            Source::Metric("machine_mechanical_efficiency"),
            Better::Higher,
        ),
        headline(
            "Mean friction power loss of the machine",
            Source::Metric("machine_loss_power_mean"),
            Better::Lower,
        ),
    ]
}

/// The headline comparisons of one cylinder's figures (the per-joint and per-crank-train
/// metrics: the mechanism at the machine's crank angle): (what, alternatives); which way is
/// better is the registry's.
const COMPARISONS: &[(&str, &[&str])] = &[
    (
        "Peak drive torque",
        &["total_torque_max", "inertial_torque_max"],
    ),
    (
        "Peak crank-pin force",
        &["total_crank_pin_force_max", "inertial_crank_pin_force_max"],
    ),
    (
        "Peak main-bearing force",
        &[
            "total_main_bearing_force_max",
            "inertial_main_bearing_force_max",
        ],
    ),
    ("Mean power loss", &["power_loss_mean"]),
    ("Mechanical efficiency", &["mechanical_efficiency"]),
    ("Mean power need", &["power_need_mean"]),
    ("Mean output power", &["output_power_mean"]),
    ("Peak friction torque", &["friction_torque_max"]),
];

/// The cylinder's headline comparisons, each labelled as one cylinder's when the machine has
/// more than one ([`CaseSummary::one_cylinder`]).
fn cylinder_headlines(s: &CaseSummary) -> Vec<Headline> {
    let whose = s.one_cylinder();
    COMPARISONS
        .iter()
        .filter_map(|(what, alternatives)| {
            let direction = better(alternatives[0])?;
            Some(Headline {
                what: match whose {
                    Some(w) => format!("{what} of {w}"),
                    None => what.to_string(),
                },
                alternatives: alternatives.iter().map(|m| Source::Metric(m)).collect(),
                direction,
            })
        })
        .collect()
}

/// The source of `h` that two mechanisms of `s` have, if any.
fn compared(h: &Headline, s: &CaseSummary) -> Option<Source> {
    h.alternatives.iter().copied().find(|src| {
        s.mechanisms
            .iter()
            .filter(|m| src.value(m).is_some())
            .count()
            >= 2
    })
}

/// Whether two sources give the same figure for every mechanism (within 1e-9, relative): a
/// one-cylinder machine's figure and its cylinder's, said once.
fn same_figures(a: Source, b: Source, s: &CaseSummary) -> bool {
    s.mechanisms.iter().all(|m| match (a.value(m), b.value(m)) {
        (Some(x), Some(y)) => (x - y).abs() <= 1e-9 * x.abs().max(y.abs()),
        (None, None) => true,
        _ => false,
    })
}

/// Whether every mechanism's figure is 0 up to round-off (within its floor): a mean drive
/// power of inertia alone over whole turns at constant speed, nothing to compare.
fn all_round_off(src: Source, s: &CaseSummary) -> bool {
    s.mechanisms.iter().all(|m| match src.value(m) {
        Some(v) => src.floor(m).is_some_and(|f| v.abs() < f),
        None => true,
    })
}

/// The headline comparisons of the summary, the machine's first, then the cylinder's; for a
/// machine of one cylinder, a cylinder figure that repeats a machine figure is said once. A
/// figure that is 0 up to round-off for every mechanism is left out.
fn headlines(s: &CaseSummary) -> Vec<(Headline, Source)> {
    let machine: Vec<(Headline, Source)> = machine_headlines(s)
        .into_iter()
        .filter_map(|h| compared(&h, s).map(|src| (h, src)))
        .filter(|(_, src)| !all_round_off(*src, s))
        .collect();
    let cylinder: Vec<(Headline, Source)> = cylinder_headlines(s)
        .into_iter()
        .filter_map(|h| compared(&h, s).map(|src| (h, src)))
        .filter(|(_, src)| !all_round_off(*src, s))
        .filter(|(_, src)| {
            s.one_cylinder().is_some() || !machine.iter().any(|(_, m)| same_figures(*m, *src, s))
        })
        .collect();
    machine.into_iter().chain(cylinder).collect()
}

/// One sentence per headline comparison present.
fn summary_items(s: &CaseSummary) -> Vec<String> {
    let reference = &s.mechanisms[0];
    let mut items = Vec::new();
    for (headline, source) in headlines(s) {
        let direction = headline.direction;
        let si = reference.unit(source.metric());
        let unit = svg::pretty_unit(si);
        // The SI figure, and the engineer's unit beside it where there is one (issue 38).
        let with_unit = |v: f64| {
            let text = if unit.is_empty() {
                fmt_num(v)
            } else {
                format!("{} {unit}", fmt_num(v))
            };
            match engineering(v, si) {
                Some(e) => format!("{text} ({e})"),
                None => text,
            }
        };
        let present: Vec<(&MechanismSummary, f64)> = s
            .mechanisms
            .iter()
            .filter_map(|m| source.value(m).filter(|v| v.is_finite()).map(|v| (m, v)))
            .collect();
        let best = present.iter().fold(None::<(&str, f64)>, |best, (m, v)| {
            let wins = best.is_none_or(|(_, b)| match direction {
                Better::Lower => *v < b,
                Better::Higher | Better::Neither => *v > b,
            });
            if wins {
                Some((m.name.as_str(), *v))
            } else {
                best
            }
        });
        let mut parts = Vec::new();
        if let Some(r) = source.value(reference).filter(|v| v.is_finite()) {
            for (m, v) in present.iter().filter(|(m, _)| m.name != reference.name) {
                let d = delta(*v, source.floor(m), r, source.floor(reference));
                let verdict = match d {
                    Delta::BothRoundOff => "equal: both 0 up to round-off".to_string(),
                    Delta::OneRoundOff => "not comparable: one is 0 up to round-off".to_string(),
                    Delta::Percent(Some(d)) if d.abs() < 0.05 => "equal".to_string(),
                    Delta::Percent(Some(d)) => {
                        let is_better = match direction {
                            Better::Lower => d < 0.0,
                            Better::Higher | Better::Neither => d > 0.0,
                        };
                        format!(
                            "{} by {:.1} %: {}",
                            if d < 0.0 { "lower" } else { "higher" },
                            d.abs(),
                            if is_better { "better" } else { "worse" }
                        )
                    }
                    Delta::Percent(None) => "not comparable".to_string(),
                };
                parts.push(format!(
                    "`{}` {} vs `{}` {} ({verdict})",
                    m.name,
                    with_unit(*v),
                    reference.name,
                    with_unit(r)
                ));
            }
        }
        if let Some((name, _)) = best {
            items.push(format!(
                "**{}** ({}, {}): best `{name}`; {}.",
                headline.what,
                source.describe(),
                phrase(direction),
                parts.join("; ")
            ));
        }
    }
    items
}

/// The loss budget: per component `power_loss_mean_<component>` the mean power loss of each
/// mechanism in W and in % of its total (`power_loss_mean`, else the components' sum).
fn loss_budget(s: &CaseSummary) -> Option<Block> {
    let mut components: Vec<String> = s
        .mechanisms
        .iter()
        .flat_map(|m| m.metrics.keys())
        .filter_map(|k| k.strip_prefix("power_loss_mean_"))
        .map(String::from)
        .collect();
    components.sort();
    components.dedup();
    if components.is_empty() {
        return None;
    }
    let totals: Vec<f64> = s
        .mechanisms
        .iter()
        .map(|m| {
            m.get("power_loss_mean").unwrap_or_else(|| {
                components
                    .iter()
                    .filter_map(|c| m.get(&format!("power_loss_mean_{c}")))
                    .filter(|v| v.is_finite())
                    .sum()
            })
        })
        .collect();
    let mut header = vec!["component".to_string()];
    let mut align = vec![Align::Left];
    for m in &s.mechanisms {
        header.push(format!("`{}`, W", m.name));
        header.push(format!("`{}`, % of total", m.name));
        align.extend([Align::Right, Align::Right]);
    }
    let share = |v: f64, total: f64| {
        if total > 0.0 && v.is_finite() {
            format!("{:.1} %", v / total * 100.0)
        } else {
            "—".into()
        }
    };
    let mut rows: Vec<Vec<String>> = components
        .iter()
        .map(|c| {
            let mut row = vec![format!("`{c}`")];
            for (m, total) in s.mechanisms.iter().zip(&totals) {
                let v = m.get(&format!("power_loss_mean_{c}")).unwrap_or(f64::NAN);
                row.push(fmt_num(v));
                row.push(share(v, *total));
            }
            row
        })
        .collect();
    let mut total_row = vec!["**total**".to_string()];
    for total in &totals {
        total_row.push(fmt_num(*total));
        total_row.push(share(*total, *total));
    }
    rows.push(total_row);
    Some(Block::Table {
        header,
        align,
        rows,
    })
}

/// The metric tables, one per group.
fn metric_tables(s: &CaseSummary) -> Vec<Block> {
    let families = families(s);
    let mut names: Vec<String> = s
        .mechanisms
        .iter()
        .flat_map(|m| m.metrics.keys().cloned())
        .collect();
    names.sort();
    names.dedup();
    let mut grouped: BTreeMap<Group, Vec<(_, String)>> = BTreeMap::new();
    for n in names {
        let (g, key) = classify(&n, &families);
        grouped.entry(g).or_default().push((key, n));
    }
    let reference = &s.mechanisms[0];
    let mut header = vec!["metric".to_string(), "unit".to_string()];
    let mut align = vec![Align::Left, Align::Left];
    for (k, m) in s.mechanisms.iter().enumerate() {
        header.push(if k == 0 {
            format!("`{}` (reference)", m.name)
        } else {
            format!("`{}`", m.name)
        });
        align.push(Align::Right);
    }
    for m in &s.mechanisms[1..] {
        header.push(format!("Δ `{}`", m.name));
        align.push(Align::Right);
    }
    let mut blocks = Vec::new();
    for (group, mut metrics) in grouped {
        metrics.sort();
        blocks.push(Block::Heading(3, group.title(s.one_cylinder())));
        let rows = metrics
            .iter()
            .map(|(_, n)| {
                let unit = s
                    .mechanisms
                    .iter()
                    .map(|m| m.unit(n))
                    .find(|u| !u.is_empty())
                    .unwrap_or("");
                let mut row = vec![format!("`{n}`"), svg::pretty_unit(unit)];
                // The SI value, and beside it the engineer's unit where there is one.
                row.extend(s.mechanisms.iter().map(|m| {
                    let v = m.get(n).unwrap_or(f64::NAN);
                    match engineering(v, unit) {
                        Some(e) => format!("{} ({e})", fmt_num(v)),
                        None => fmt_num(v),
                    }
                }));
                let r = reference.get(n);
                let r_floor = round_off_floor(n, |k| reference.get(k));
                for m in &s.mechanisms[1..] {
                    let d = match (m.get(n), r) {
                        (Some(v), Some(r)) => {
                            delta(v, round_off_floor(n, |k| m.get(k)), r, r_floor)
                        }
                        _ => Delta::Percent(None),
                    };
                    row.push(fmt_delta(d));
                }
                row
            })
            .collect();
        blocks.push(Block::Table {
            header: header.clone(),
            align: align.clone(),
            rows,
        });
        if metrics.iter().any(|(_, n)| signed(n)) {
            blocks.push(Block::Paragraph(SIGN_LEGEND.into()));
        }
    }
    blocks
}

/// The chart data of a mechanism from its CSV at `path` (the charts' columns only), thinned
/// as the run would have (a report made from a folder alone).
fn chart_data_from_csv(path: &Path, joints: &[String], file: String) -> anyhow::Result<ChartData> {
    let cols = data::read_columns(path, |h| wanted_columns(h, joints))?;
    let rows = cols.get("crank_angle_deg").map_or(0, <[f64]>::len);
    let mut recorder = ChartRecorder::new(&cols.header, joints, rows, MAX_POINTS, file);
    let read: Vec<(usize, &[f64])> = cols
        .header
        .iter()
        .enumerate()
        .filter_map(|(k, h)| cols.get(h).map(|v| (k, v)))
        .collect();
    let mut row = vec![f64::NAN; cols.header.len()];
    for r in 0..rows {
        for (k, v) in &read {
            row[*k] = v[r];
        }
        recorder.record(&row);
    }
    Ok(recorder.finish())
}

/// The report of the case in `case_dir`: of its `summary.json`, whose contents are `summary`
/// when given (a run's, which need not read back what it wrote), else as read; a
/// mechanism's charts from `from_run` (keyed by its name in `summary.json`) when it is
/// there, else from its CSV if the folder has one. Returns the summary as it was read.
pub(super) fn case_report(
    case_dir: &Path,
    summary: Option<&serde_json::Value>,
    reference: Option<&str>,
    from_run: BTreeMap<String, ChartData>,
) -> anyhow::Result<CaseSummary> {
    let path = case_dir.join("summary.json");
    let (s, reference) = match summary {
        Some(json) => data::summary_of(json, &path, reference)?,
        None => data::read_summary(&path, reference)?,
    };
    let data = chart_data(case_dir, &s, from_run)?;
    let plots = case_charts(&s, &data);

    let mut doc = Doc {
        title: format!("Case report: {}", s.case),
        blocks: Vec::new(),
    };
    push_overview(&mut doc, &s, &reference);
    // The method after the results (issue 38): what Δ is and which way is better.
    doc.push(Block::Paragraph(format!(
        "Δ = (mechanism − reference) / |reference| × 100 %, to `{reference}`. Lower is better \
         for loads, torques, power need and losses; higher is better for efficiency and output. \
         Values in SI units as in `summary.json` (rpm, bar, kN and kW beside them in brackets); \
         — where a mechanism has no such metric. \
         {ROUND_OFF_LEGEND}"
    )));
    push_loss_budget(&mut doc, &s);
    push_metrics(&mut doc, &s);
    push_charts(&mut doc, &plots);
    let files: Vec<(String, String)> = plots.into_iter().map(|(f, s, _)| (f, s)).collect();
    write_report(case_dir, &doc, &files)?;
    Ok(s)
}

/// Each mechanism's chart data, in the summary's order: the run's where it gave them, else
/// read from the mechanism's CSV where the folder has one, else none.
fn chart_data(
    case_dir: &Path,
    s: &CaseSummary,
    mut from_run: BTreeMap<String, ChartData>,
) -> anyhow::Result<Vec<Option<ChartData>>> {
    let given: Vec<Option<ChartData>> = s
        .mechanisms
        .iter()
        .map(|m| from_run.remove(&m.name))
        .collect();
    // Only the mechanisms the run did not chart read their CSV (in parallel).
    s.mechanisms
        .par_iter()
        .zip(given)
        .map(|(m, given)| {
            if given.is_some() {
                return Ok(given);
            }
            let file = format!("{}.csv", m.name);
            let path = case_dir.join(&file);
            if !path.is_file() {
                return Ok(None);
            }
            chart_data_from_csv(&path, &m.joints, file).map(Some)
        })
        .collect::<anyhow::Result<_>>()
}

/// The case's charts as (file, SVG, caption), in the report's order.
fn case_charts(s: &CaseSummary, data: &[Option<ChartData>]) -> Vec<(String, String, String)> {
    let headers: Vec<Option<Vec<String>>> = data
        .iter()
        .map(|c| c.as_ref().map(|c| c.header.clone()))
        .collect();
    let specs = plot_specs(s, &headers);
    // The charts engineers read first (issue 38), then the rest.
    let mut plots = crate::indicator::indicator_charts(s, data);
    plots.extend(crate::crank_speed::crank_speed_charts(s, data));
    plots.extend(crate::crank_speed::crank_speed_time_charts(s, data));
    plots.extend(crate::bearing_polar::polar_charts(s, data));
    plots.extend(charts(s, &specs, data));
    plots.extend(locus_charts(s, data));
    plots
}

/// The report's opening: the machine, its layout, gas model and mechanisms, the run's
/// warnings, and, of several mechanisms, which is better.
fn push_overview(doc: &mut Doc, s: &CaseSummary, reference: &str) {
    let names: Vec<String> = s
        .mechanisms
        .iter()
        .map(|m| format!("`{}`", m.name))
        .collect();
    let layout = s
        .layout
        .as_ref()
        .map_or(String::new(), |l| format!("; layout: **{l}**"));
    doc.push(Block::Paragraph(format!(
        "Machine: **{}**{layout}; gas model: **{}**; mechanisms: {}. Reference: `{reference}`.",
        s.machine,
        s.gas_model.as_deref().unwrap_or("none"),
        names.join(", ")
    )));
    for w in &s.warnings {
        doc.push(Block::Paragraph(format!("**Warning:** {w}.")));
    }
    if s.mechanisms.len() > 1 {
        doc.push(Block::Heading(2, "Which is better".into()));
        let items = summary_items(s);
        if items.is_empty() {
            doc.push(Block::Paragraph(
                "No headline metric is shared by two mechanisms.".into(),
            ));
        } else {
            doc.push(Block::List(items));
        }
    }
}

/// The loss budget's section, where the summary has one.
fn push_loss_budget(doc: &mut Doc, s: &CaseSummary) {
    if let Some(budget) = loss_budget(s) {
        let (title, whose) = match s.one_cylinder() {
            Some(w) => (format!("Loss budget of {w}"), format!("the total of {w}")),
            None => (
                "Loss budget".to_string(),
                "the mechanism's total".to_string(),
            ),
        };
        doc.push(Block::Heading(2, title));
        doc.push(Block::Paragraph(format!(
            "Mean friction power loss by component (`power_loss_mean_<component>`), and its \
             share of {whose} (`power_loss_mean`)."
        )));
        doc.push(budget);
    }
}

/// The metrics' section: whose the tables are for a machine of several cylinders, then the
/// tables.
fn push_metrics(doc: &mut Doc, s: &CaseSummary) {
    doc.push(Block::Heading(2, "Metrics".into()));
    if let Some(w) = s.one_cylinder() {
        doc.push(Block::Paragraph(format!(
            "The machine has {} cylinders: \"The whole machine\" and the balance tables are \
             the machine's (every cylinder at its own crank angle); the other tables are those \
             of {w} only.",
            s.cylinders
        )));
    }
    doc.blocks.extend(metric_tables(s));
}

/// The charts' section: each chart as a figure, or why a report has none.
fn push_charts(doc: &mut Doc, plots: &[(String, String, String)]) {
    doc.push(Block::Heading(2, "Charts".into()));
    if plots.is_empty() {
        doc.push(Block::Paragraph(
            "No charts: this report was made from the folder alone, which holds no per-step \
             CSV (`[output] csv = false`); a run with its report (`cardan run` without \
             `--no-report`) charts its steps whatever its files."
                .into(),
        ));
    }
    for (file, svg_text, caption) in plots {
        doc.push(Block::Figure {
            file: format!("plots/{file}"),
            svg: svg_text.clone(),
            caption: caption.clone(),
        });
    }
}
