//! The polar load diagrams bearing designers read (issue 38): the tip of the load vector on a
//! bearing traced over the run, as engine-bearing practice draws them: the main bearing's
//! relative to the frame (`main_bearing_polar.svg`: the load on the shell, fixed in the block)
//! and relative to the crank (`main_bearing_polar_crank.svg`: where on the turning journal it
//! bears), the crank pin's relative to the crank (`crank_pin_polar.svg`: the pin turns with
//! it). Every mechanism on one chart, on the locus chart's equal axes through the origin
//! (`locus.rs`).
//!
//! The loads are the machine's (`summary.json` has no other): the load on the crankshaft at
//! main journal k from the frame (`main_bearing_<k>_force_x_n`, `_y_n`) and at cylinder k's
//! crank pin from its rod (`cylinder_<k>_crank_pin_force_x_n`, `_y_n`), in the machine's
//! frame (x across, y along the cylinder). Of a machine of several journals or pins each
//! mechanism's is drawn whose load peaks highest, named in the legend. The crank's frame turns
//! the vector by −(θ − 90°) at each row's crank angle θ (`envelope::crank_frame`): the crank
//! points along +y, as at top dead centre, where the two frames agree.

use crate::chart_columns::{bearing_loads, crank_key, locus_key};
use crate::data::CaseSummary;
use crate::envelope::{ChartData, Trace};
use crate::locus::{locus_chart, LocusChart};
use crate::svg::Series;

/// One polar diagram: its file, title, which bearings (`main_bearing_` or `cylinder_`), the
/// frame, and its caption.
struct Polar {
    file: &'static str,
    title: &'static str,
    prefix: &'static str,
    crank_frame: bool,
    caption: &'static str,
}

const POLARS: [Polar; 3] = [
    Polar {
        file: "main_bearing_polar.svg",
        title: "Main bearing load, relative to the frame (the bearing shell)",
        prefix: "main_bearing_",
        crank_frame: false,
        caption: "Polar load diagram of the main bearing relative to the frame (the load on \
                  the crankshaft from the frame, x across and y along the cylinder; the \
                  crank axis at the origin; a dot at the first step): every mechanism, its \
                  most loaded journal",
    },
    Polar {
        file: "main_bearing_polar_crank.svg",
        title: "Main journal load, relative to the crank (turning with the journal)",
        prefix: "main_bearing_",
        crank_frame: true,
        caption: "Polar load diagram of the main journal relative to the crank (the same load \
                  turned by −(θ − 90°): the crank along +y, as at top dead centre): every \
                  mechanism, its most loaded journal",
    },
    Polar {
        file: "crank_pin_polar.svg",
        title: "Crank pin load, relative to the crank (turning with the pin)",
        prefix: "cylinder_",
        crank_frame: true,
        caption: "Polar load diagram of the crank pin relative to the crank (the load on the \
                  pin from the rod or wheel, turned by −(θ − 90°): the crank along +y, as at \
                  top dead centre): every mechanism, its most loaded pin",
    },
];

/// The largest load of a locus (its thinned points keep each component's extremes).
fn peak(t: &Trace) -> f64 {
    t.x.iter()
        .zip(&t.y)
        .map(|(a, b)| a.hypot(*b))
        .filter(|v| v.is_finite())
        .fold(0.0, f64::max)
}

/// The polar load diagrams of the case whose rows hold the bearing loads.
pub(super) fn polar_charts(
    s: &CaseSummary,
    data: &[Option<ChartData>],
) -> Vec<(String, String, String)> {
    let mut out = Vec::new();
    for polar in &POLARS {
        let mut chart = LocusChart {
            title: polar.title.into(),
            x_label: "F_x".into(),
            y_label: "F_y".into(),
            unit: "N".into(),
            crank_frame: polar.crank_frame,
            ..LocusChart::default()
        };
        if polar.crank_frame {
            chart.x_label = "across the crank".into();
            chart.y_label = "along the crank".into();
        }
        for (k, m) in s.mechanisms.iter().enumerate() {
            let Some(d) = &data[k] else { continue };
            let loads: Vec<String> = bearing_loads(&d.header)
                .into_iter()
                .filter(|p| p.starts_with(polar.prefix))
                .collect();
            let key = |p: &str| {
                let (x, y) = (format!("{p}_force_x_n"), format!("{p}_force_y_n"));
                if polar.crank_frame {
                    crank_key(&x, &y)
                } else {
                    locus_key(&x, &y)
                }
            };
            // The most loaded bearing (the first of equal peaks).
            let Some((p, t)) = loads
                .iter()
                .filter_map(|p| Some((p, d.traces.get(&key(p))?)))
                .filter(|(_, t)| !t.x.is_empty())
                .fold(None::<(&String, &Trace)>, |best, (p, t)| match best {
                    Some((_, b)) if peak(b) >= peak(t) => best,
                    _ => Some((p, t)),
                })
            else {
                continue;
            };
            let label = if loads.len() > 1 {
                format!("{} ({})", m.name, p.replace('_', " "))
            } else {
                m.name.clone()
            };
            chart.series.push(Series {
                label,
                source: format!("{}:{p}_force_y_n", d.file),
                x: t.x.clone(),
                y: t.y.clone(),
                colour: k,
                dash: chart.series.len(),
                markers: false,
                x_column: None,
            });
            chart.x_columns.push(format!("{p}_force_x_n"));
        }
        if chart.series.is_empty() {
            continue;
        }
        out.push((polar.file.into(), locus_chart(&chart), polar.caption.into()));
    }
    out
}
