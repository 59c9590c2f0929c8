//! The report of a sweep: the key metrics over one swept field (line charts of every mechanism
//! and of the difference to the reference), or over a grid of two (heat maps of each mechanism
//! and of the difference, with the 0 % contour where the mechanisms swap places).

use crate::data::{self, parse_quantity, SweepTable};
use crate::doc::{self, write_report, Align, Block, Doc};
use crate::heatmap::{self, HeatMap};
use crate::numbers::{
    better, delta, fmt_num, fmt_pct, phrase, round_off_floor, signed, Better, Delta,
    ROUND_OFF_LEGEND, SIGN_LEGEND,
};
use crate::svg::{self, LineChart, Series};
use crate::sweep_axis::Axis;
use std::path::Path;

/// The metrics a sweep report charts, in this order: each entry is a list of alternatives of
/// which the first present in `sweep.csv` is taken (a metric already taken is not repeated).
/// Efficiency and losses come first (present once friction is modelled), then the power need
/// or output, the peak drive torque (total, then inertial), the peak crank-pin force and the
/// mean drive power.
pub const KEY_METRICS: &[&[&str]] = &[
    &["mechanical_efficiency"],
    &["power_loss_mean"],
    &["power_need_mean", "output_power_mean"],
    &["total_torque_max", "inertial_torque_max"],
    &["inertial_torque_max"],
    &["total_crank_pin_force_max", "inertial_crank_pin_force_max"],
    &["total_power_mean", "inertial_power_mean"],
];

/// The key metrics of a sweep of a machine of several cylinders (issue 35), in this order, as
/// [`KEY_METRICS`]: the whole machine's efficiency, losses, mean drive power (lower is better:
/// a pump's smaller need, an engine's larger output, which is negative), peak drive torque
/// ([`MACHINE_TORQUE_PEAK`]), peak main-journal and crank-pin loads; then one cylinder's peak
/// drive torque, labelled as that cylinder's.
pub const MACHINE_KEY_METRICS: &[&[&str]] = &[
    &["machine_mechanical_efficiency"],
    &["machine_loss_power_mean"],
    &["machine_power_mean"],
    &[MACHINE_TORQUE_PEAK],
    &["machine_main_bearing_force_max"],
    &["machine_crank_pin_force_max"],
    &["total_torque_max", "inertial_torque_max"],
];

/// The peak of the machine's drive torque, which a sweep report makes of each point's
/// `machine_torque_max` and `machine_torque_min` (signed): the larger of their magnitudes. Not
/// a column of `sweep.csv`.
pub const MACHINE_TORQUE_PEAK: &str = "machine_torque_peak";

/// Whether a sweep is of a machine of several cylinders: its first point's, or a sweep of the
/// layout itself (`layout.*` swept), whose points may differ.
fn multi_cylinder(t: &SweepTable) -> bool {
    t.cylinders > 1 || t.swept.iter().any(|f| f.starts_with("layout."))
}

/// Whose figures a sweep's metric is, for a machine of several cylinders: the machine's
/// (`machine_*`, the balance), else one cylinder's (cylinder 1; a vee's at the machine angle).
fn whose(t: &SweepTable, metric: &str) -> Option<&'static str> {
    let machine = metric.starts_with("machine_")
        || cardan_metrics::find(metric).is_some_and(|d| d.group == cardan_metrics::Group::Balance);
    (multi_cylinder(t) && !machine).then(|| {
        if t.layout_kind.as_deref() == Some("vee") {
            "one cylinder at the machine's crank angle"
        } else {
            "cylinder 1"
        }
    })
}

/// `metric` with whose figures it is ([`whose`]), for a report's text.
fn named(t: &SweepTable, metric: &str) -> String {
    match whose(t, metric) {
        Some(w) => format!("`{metric}` of {w}"),
        None => format!("`{metric}`"),
    }
}

/// Which way a sweep's metric is better: the registry's, but lower for the machine's mean
/// drive power (a pump's need; an engine's output, negative: lower is more) and its peak
/// torque ([`MACHINE_TORQUE_PEAK`]).
fn direction(metric: &str) -> Option<Better> {
    match metric {
        "machine_power_mean" | MACHINE_TORQUE_PEAK => Some(Better::Lower),
        _ => better(metric),
    }
}

/// Adds [`MACHINE_TORQUE_PEAK`] to the table of a multi-cylinder sweep, for each mechanism
/// with both signed extremes.
fn add_machine_torque_peak(t: &mut SweepTable) {
    if !multi_cylinder(t) {
        return;
    }
    for m in t.mechanisms.clone() {
        let (Some(hi), Some(lo)) = (
            t.column(&m, "machine_torque_max"),
            t.column(&m, "machine_torque_min"),
        ) else {
            continue;
        };
        let peak: Vec<f64> = hi
            .iter()
            .zip(lo)
            .map(|(h, l)| h.abs().max(l.abs()))
            .collect();
        t.metrics.insert(format!("{m}.{MACHINE_TORQUE_PEAK}"), peak);
        t.units.insert(MACHINE_TORQUE_PEAK.into(), "N*m".into());
    }
}

/// The key metrics present: the first alternative of each [`KEY_METRICS`] entry that some
/// mechanism has (with a finite value), without repeats.
pub(super) fn key_metrics(t: &SweepTable) -> Vec<String> {
    let mut chosen: Vec<String> = Vec::new();
    let lists = if multi_cylinder(t) {
        MACHINE_KEY_METRICS
    } else {
        KEY_METRICS
    };
    for alternatives in lists {
        let found = alternatives.iter().find(|m| {
            t.mechanisms.iter().any(|mech| {
                t.column(mech, m)
                    .is_some_and(|c| c.iter().any(|v| v.is_finite()))
            })
        });
        if let Some(m) = found {
            if !chosen.iter().any(|c| c == m) {
                chosen.push(m.to_string());
            }
        }
    }
    chosen
}

/// How the points lie: along one axis, or on a full grid of two.
enum Layout {
    Line(Axis),
    Grid(Axis, Axis),
}

fn layout(t: &SweepTable) -> Layout {
    let n = t.cases.len();
    if t.swept.len() == 2 {
        let (a, b) = (Axis::of(t, 0), Axis::of(t, 1));
        let (la, ia) = a.levels();
        let (lb, ib) = b.levels();
        let mut pairs: Vec<(usize, usize)> = ia.iter().copied().zip(ib.iter().copied()).collect();
        pairs.sort_unstable();
        pairs.dedup();
        if la.len() > 1 && lb.len() > 1 && la.len() * lb.len() == n && pairs.len() == n {
            return Layout::Grid(a, b);
        }
    }
    if t.swept.is_empty() {
        return Layout::Line(Axis {
            title: "point".into(),
            numbers: None,
            texts: t.cases.clone(),
        });
    }
    // Along the first field when its values are distinct numbers (one field, or a zip);
    // else the points in file order, named by all their values.
    let first = Axis::of(t, 0);
    if first.numbers.is_some() && first.levels().0.len() == n {
        return Layout::Line(first);
    }
    Layout::Line(Axis {
        title: t.swept.join(" / "),
        numbers: None,
        texts: t.params.iter().map(|p| p.join(" / ")).collect(),
    })
}

/// The difference of `mechanism` to the reference per point, in %: NaN where undefined or
/// where a value is within its round-off floor ([`round_off_floor`], from the same point's
/// metrics), so that neither a chart nor a range shows a % of round-off.
fn differences(t: &SweepTable, metric: &str, mechanism: &str, reference: &str) -> Vec<f64> {
    match (t.column(mechanism, metric), t.column(reference, metric)) {
        (Some(v), Some(r)) => v
            .iter()
            .zip(r)
            .enumerate()
            .map(|(k, (v, r))| {
                let floor = |m: &str| round_off_floor(metric, |x| Some(t.column(m, x)?[k]));
                match delta(*v, floor(mechanism), *r, floor(reference)) {
                    Delta::Percent(Some(d)) => d,
                    _ => f64::NAN,
                }
            })
            .collect(),
        _ => vec![f64::NAN; t.cases.len()],
    }
}

/// A sentence per key metric and mechanism: at how many points it beats the reference, the
/// range of Δ, and along a numeric axis where Δ changes sign.
fn verdicts(t: &SweepTable, keys: &[String], reference: &str, line: Option<&Axis>) -> Vec<String> {
    let mut items = Vec::new();
    for metric in keys {
        for mech in t.mechanisms.iter().filter(|m| *m != reference) {
            let d = differences(t, metric, mech, reference);
            let finite: Vec<f64> = d.iter().copied().filter(|v| v.is_finite()).collect();
            if finite.is_empty() {
                continue;
            }
            let (lo, hi) = finite
                .iter()
                .fold((f64::MAX, f64::MIN), |(a, b), v| (a.min(*v), b.max(*v)));
            let mut text = match direction(metric) {
                Some(direction) => {
                    let wins = finite
                        .iter()
                        .filter(|v| match direction {
                            Better::Lower => **v < 0.0,
                            Better::Higher => **v > 0.0,
                            Better::Neither => false,
                        })
                        .count();
                    format!(
                        "{} ({}): `{mech}` is better than `{reference}` at {wins} of {} points; Δ from {} to {}",
                        named(t, metric),
                        phrase(direction),
                        finite.len(),
                        fmt_pct(Some(lo)),
                        fmt_pct(Some(hi))
                    )
                }
                None => format!(
                    "{}: Δ `{mech}` to `{reference}` from {} to {}",
                    named(t, metric),
                    fmt_pct(Some(lo)),
                    fmt_pct(Some(hi))
                ),
            };
            if let Some(Axis {
                numbers: Some(x),
                texts,
                ..
            }) = line
            {
                let mut order: Vec<usize> = (0..x.len()).filter(|&k| d[k].is_finite()).collect();
                order.sort_by(|a, b| x[*a].total_cmp(&x[*b]));
                let unit = parse_quantity(&texts[0]).map(|q| q.1).unwrap_or_default();
                for w in order.windows(2) {
                    let (a, b) = (w[0], w[1]);
                    if (d[a] < 0.0) != (d[b] < 0.0) && d[a] != 0.0 && d[b] != 0.0 {
                        let at = x[a] + (x[b] - x[a]) * d[a] / (d[a] - d[b]);
                        text.push_str(&format!(
                            "; Δ crosses 0 between {} and {} (≈ {} {unit} by linear interpolation)",
                            texts[a],
                            texts[b],
                            fmt_num(at)
                        ));
                    }
                }
            }
            text.push('.');
            items.push(text);
        }
    }
    items
}

/// The table of one metric: each point's swept values, every mechanism's value and Δ.
fn metric_table(t: &SweepTable, metric: &str, reference: &str) -> Block {
    let mut header: Vec<String> = t.swept.iter().map(|s| format!("`{s}`")).collect();
    let mut align = vec![Align::Left; header.len()];
    for m in &t.mechanisms {
        header.push(format!("`{m}`"));
        align.push(Align::Right);
    }
    let others: Vec<&String> = t.mechanisms.iter().filter(|m| *m != reference).collect();
    for m in &others {
        header.push(format!("Δ `{m}`"));
        align.push(Align::Right);
    }
    let diffs: Vec<Vec<f64>> = others
        .iter()
        .map(|m| differences(t, metric, m, reference))
        .collect();
    let rows = (0..t.cases.len())
        .map(|r| {
            let mut row = t.params[r].clone();
            for m in &t.mechanisms {
                row.push(fmt_num(t.column(m, metric).map_or(f64::NAN, |c| c[r])));
            }
            for d in &diffs {
                row.push(fmt_pct(d[r].is_finite().then_some(d[r])));
            }
            row
        })
        .collect();
    Block::Table {
        header,
        align,
        rows,
    }
}

/// Line charts over one axis: each key metric of every mechanism, and all differences.
fn line_charts(
    t: &SweepTable,
    keys: &[String],
    reference: &str,
    axis: &Axis,
) -> Vec<(String, String, String)> {
    let n = t.cases.len();
    let (x, categories): (Vec<f64>, Option<Vec<String>>) = match &axis.numbers {
        Some(v) => (v.clone(), None),
        None => ((0..n).map(|k| k as f64).collect(), Some(axis.texts.clone())),
    };
    let mut order: Vec<usize> = (0..n).collect();
    order.sort_by(|a, b| x[*a].total_cmp(&x[*b]));
    let pick = |v: &[f64]| -> Vec<f64> { order.iter().map(|&k| v[k]).collect() };
    let along = Along {
        axis,
        xs: pick(&x),
        categories,
        pick: &pick,
    };
    let mut out: Vec<(String, String, String)> = keys
        .iter()
        .map(|metric| metric_line_chart(t, metric, &along))
        .collect();
    out.extend(difference_line_chart(t, keys, reference, &along));
    out
}

/// The points of a line sweep in the order of their axis, as its charts draw them.
struct Along<'a> {
    /// The swept axis.
    axis: &'a Axis,
    /// The points' abscissae in increasing order (a text axis's points numbered).
    xs: Vec<f64>,
    /// A text axis's labels, `None` for a numeric one.
    categories: Option<Vec<String>>,
    /// A column of the table in the order of `xs`.
    pick: &'a dyn Fn(&[f64]) -> Vec<f64>,
}

/// The line chart of one key metric: a series per mechanism that has it.
fn metric_line_chart(t: &SweepTable, metric: &String, along: &Along) -> (String, String, String) {
    let axis = along.axis;
    let series: Vec<Series> = t
        .mechanisms
        .iter()
        .enumerate()
        .filter_map(|(k, m)| {
            t.column(m, metric).map(|c| Series {
                label: m.clone(),
                source: format!("sweep.csv:{m}.{metric}"),
                x: along.xs.clone(),
                y: (along.pick)(c),
                colour: k,
                // Told apart in black and white too (issue 38).
                dash: k,
                markers: true,
                x_column: None,
            })
        })
        .collect();
    let unit = t.units.get(metric).cloned().unwrap_or_default();
    let chart = LineChart {
        title: match whose(t, metric) {
            Some(w) => format!("{metric} ({w}) over {}", axis.title),
            None => format!("{metric} over {}", axis.title),
        },
        x_label: axis.title.clone(),
        y_label: metric.clone(),
        y_unit: unit,
        series,
        zero_line: true,
        x_categories: along.categories.clone(),
        angle_axis: false,
        ..LineChart::default()
    };
    (
        format!("{metric}.svg"),
        svg::line_chart(&chart),
        format!(
            "{} of every mechanism over `{}`",
            named(t, metric),
            axis.title
        ),
    )
}

/// The chart of every other mechanism's differences to the reference, none without any.
fn difference_line_chart(
    t: &SweepTable,
    keys: &[String],
    reference: &str,
    along: &Along,
) -> Option<(String, String, String)> {
    let axis = along.axis;
    let others: Vec<&String> = t.mechanisms.iter().filter(|m| *m != reference).collect();
    let mut series = Vec::new();
    for m in &others {
        for (b, metric) in keys.iter().enumerate() {
            let d = differences(t, metric, m, reference);
            if !d.iter().any(|v| v.is_finite()) {
                continue;
            }
            series.push(Series {
                label: if others.len() > 1 {
                    format!("{m}: {metric}")
                } else {
                    metric.clone()
                },
                source: format!("sweep.csv:{m}.{metric}-{reference}.{metric}"),
                x: along.xs.clone(),
                y: (along.pick)(&d),
                colour: b,
                // Every series its own dash (issue 38): told apart in black and white.
                dash: series.len(),
                markers: true,
                x_column: None,
            });
        }
    }
    if series.is_empty() {
        return None;
    }
    let names: Vec<&str> = others.iter().map(|s| s.as_str()).collect();
    let chart = LineChart {
        title: format!("Difference of {} to {reference}", names.join(", ")),
        x_label: axis.title.clone(),
        y_label: "Δ".into(),
        y_unit: "%".into(),
        series,
        zero_line: true,
        x_categories: along.categories.clone(),
        angle_axis: false,
        ..LineChart::default()
    };
    Some((
        "difference.svg".into(),
        svg::line_chart(&chart),
        format!(
            "Δ = (mechanism − `{reference}`) / |`{reference}`| in % over `{}`; below 0 the mechanism's value is smaller",
            axis.title
        ),
    ))
}

/// Heat maps over a grid: each key metric of every mechanism, and each difference.
fn heat_maps(
    t: &SweepTable,
    keys: &[String],
    reference: &str,
    a: &Axis,
    b: &Axis,
) -> Vec<(String, String, String)> {
    let (_, xi) = a.levels();
    let (_, yi) = b.levels();
    let (xl, yl) = (a.tick_labels(), b.tick_labels());
    let grid = |v: &[f64]| -> Vec<Vec<f64>> {
        let mut g = vec![vec![f64::NAN; xl.len()]; yl.len()];
        for r in 0..v.len() {
            g[yi[r]][xi[r]] = v[r];
        }
        g
    };
    let mut out = Vec::new();
    for metric in keys {
        let unit = svg::pretty_unit(t.units.get(metric).map_or("", String::as_str));
        for m in &t.mechanisms {
            let Some(c) = t.column(m, metric) else {
                continue;
            };
            let map = HeatMap {
                title: match whose(t, metric) {
                    Some(w) => format!("{metric} ({w}): {m}"),
                    None => format!("{metric}: {m}"),
                },
                x_label: a.title.clone(),
                y_label: b.title.clone(),
                x_labels: xl.clone(),
                y_labels: yl.clone(),
                values: grid(c),
                value_label: if unit.is_empty() {
                    metric.clone()
                } else {
                    unit.clone()
                },
                diverging: false,
                zero_contour: false,
            };
            out.push((
                format!("{metric}_{m}.svg"),
                heatmap::heat_map(&map),
                format!("{} of `{m}` over the grid", named(t, metric)),
            ));
        }
        for m in t.mechanisms.iter().filter(|m| *m != reference) {
            let d = differences(t, metric, m, reference);
            if !d.iter().any(|v| v.is_finite()) {
                continue;
            }
            let map = HeatMap {
                title: format!("{metric}: Δ {m} to {reference}"),
                x_label: a.title.clone(),
                y_label: b.title.clone(),
                x_labels: xl.clone(),
                y_labels: yl.clone(),
                values: grid(&d),
                value_label: "Δ, %".into(),
                diverging: true,
                zero_contour: true,
            };
            let sense = match direction(metric) {
                Some(Better::Lower) => format!("; blue (Δ < 0) is where `{m}` is better"),
                Some(Better::Higher) => format!("; red (Δ > 0) is where `{m}` is better"),
                Some(Better::Neither) | None => String::new(),
            };
            out.push((
                format!("{metric}_difference_{m}.svg"),
                heatmap::heat_map(&map),
                format!("Δ `{metric}` of `{m}` to `{reference}` in %, black line at Δ = 0{sense}"),
            ));
        }
    }
    out
}

/// Writes a sweep's report: what was swept, the verdicts, a table per key metric, the charts
/// and the links to its points.
pub(super) fn sweep_report(
    sweep_dir: &Path,
    name: &str,
    reference: Option<&str>,
) -> anyhow::Result<()> {
    let (mut t, reference) = data::read_sweep(sweep_dir, reference)?;
    add_machine_torque_peak(&mut t);
    let keys = key_metrics(&t);
    let layout = layout(&t);
    let mut doc = Doc {
        title: format!("Sweep report: {name}"),
        blocks: Vec::new(),
    };
    doc.push(Block::Paragraph(overview(&t, &layout, &reference)));
    doc.push(Block::Paragraph(key_metrics_legend(&t, &keys, &reference)));
    if t.mechanisms.len() > 1 {
        push_verdicts(&mut doc, &t, &keys, &reference, &layout);
    }
    doc.push(Block::Heading(2, "Key metrics".into()));
    for metric in &keys {
        push_metric_table(&mut doc, &t, metric, &reference);
    }
    let plots = match &layout {
        Layout::Line(axis) => line_charts(&t, &keys, &reference, axis),
        Layout::Grid(a, b) => heat_maps(&t, &keys, &reference, a, b),
    };
    doc.push(Block::Heading(2, "Charts".into()));
    for (file, svg_text, caption) in &plots {
        doc.push(Block::Figure {
            file: format!("plots/{file}"),
            svg: svg_text.clone(),
            caption: caption.clone(),
        });
    }
    let points = point_links(sweep_dir, &t.cases);
    if !points.is_empty() {
        doc.push(Block::Heading(2, "Points".into()));
        doc.push(Block::Links(points));
    }
    let files: Vec<(String, String)> = plots.into_iter().map(|(f, s, _)| (f, s)).collect();
    write_report(sweep_dir, &doc, &files)
}

/// The report's opening: the points, each swept field's range, the layout, the mechanisms.
fn overview(t: &SweepTable, layout: &Layout, reference: &str) -> String {
    let fields: Vec<String> = (0..t.swept.len())
        .map(|k| {
            let axis = Axis::of(t, k);
            let (levels, _) = axis.levels();
            format!(
                "`{}` ({} values: {} … {})",
                t.swept[k],
                levels.len(),
                levels.first().map_or("", String::as_str),
                levels.last().map_or("", String::as_str)
            )
        })
        .collect();
    format!(
        "{} points; swept: {}; {}. Mechanisms: {}; reference `{reference}`.",
        t.cases.len(),
        if fields.is_empty() {
            "nothing".into()
        } else {
            fields.join(", ")
        },
        match layout {
            Layout::Grid(..) => "a full grid of two fields: heat maps",
            Layout::Line(_) => "charts along the points",
        },
        t.mechanisms
            .iter()
            .map(|m| format!("`{m}`"))
            .collect::<Vec<_>>()
            .join(", ")
    )
}

/// What Δ means, which way is better, and the list the key metrics were taken from.
fn key_metrics_legend(t: &SweepTable, keys: &[String], reference: &str) -> String {
    let list = if multi_cylinder(t) {
        format!(
            "of a machine of several cylinders: the whole machine's machine_mechanical_efficiency; \
             machine_loss_power_mean; machine_power_mean (lower is better: a pump's smaller \
             need, an engine's larger output, which is negative); {MACHINE_TORQUE_PEAK}, the \
             larger of |machine_torque_max| and |machine_torque_min| of each point (made by \
             this report); machine_main_bearing_force_max; machine_crank_pin_force_max; then \
             {}'s total_torque_max or inertial_torque_max",
            whose(t, "total_torque_max").unwrap_or("one cylinder")
        )
    } else {
        "mechanical_efficiency; power_loss_mean; power_need_mean or output_power_mean; \
         total_torque_max or inertial_torque_max; inertial_torque_max; \
         total_crank_pin_force_max or inertial_crank_pin_force_max; total_power_mean or \
         inertial_power_mean"
            .to_string()
    };
    format!(
        "Δ = (mechanism − reference) / |reference| × 100 %, to `{reference}`. Lower is better for \
         loads, torques, power need and losses; higher is better for efficiency and output. Key \
         metrics (the first present of each entry of the list {list}): {}. \
         {ROUND_OFF_LEGEND}",
        keys.iter()
            .map(|k| format!("`{k}`"))
            .collect::<Vec<_>>()
            .join(", ")
    )
}

/// The section of where each mechanism is better (a line sweep's verdicts name its ranges).
fn push_verdicts(doc: &mut Doc, t: &SweepTable, keys: &[String], reference: &str, layout: &Layout) {
    doc.push(Block::Heading(2, "Where each mechanism is better".into()));
    let line = match layout {
        Layout::Line(a) => Some(a),
        Layout::Grid(..) => None,
    };
    let items = verdicts(t, keys, reference, line);
    if items.is_empty() {
        doc.push(Block::Paragraph("No key metric to compare.".into()));
    } else {
        doc.push(Block::List(items));
    }
}

/// One key metric's heading with its unit, its table, and the sign legend where it is signed.
fn push_metric_table(doc: &mut Doc, t: &SweepTable, metric: &String, reference: &str) {
    let unit = svg::pretty_unit(t.units.get(metric).map_or("", String::as_str));
    doc.push(Block::Heading(
        3,
        if unit.is_empty() {
            named(t, metric)
        } else {
            format!("{}, {unit}", named(t, metric))
        },
    ));
    doc.push(metric_table(t, metric, reference));
    if signed(metric) {
        doc.push(Block::Paragraph(SIGN_LEGEND.into()));
    }
}

/// The links to the sweep's points: each to its report, else to its summary, else none.
fn point_links(sweep_dir: &Path, cases: &[String]) -> Vec<(String, String, String)> {
    let mut points = Vec::new();
    for c in cases {
        let dir = sweep_dir.join(c);
        if dir.join("report.html").is_file() {
            points.push((
                c.clone(),
                doc::href(&format!("{c}/report.html")),
                String::new(),
            ));
        } else if dir.join("summary.json").is_file() {
            points.push((
                c.clone(),
                doc::href(&format!("{c}/summary.json")),
                String::new(),
            ));
        }
    }
    points
}
