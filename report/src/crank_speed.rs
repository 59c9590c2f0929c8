//! The crank speed of a dynamic run (`crank_speed.svg`, issue 38): the crank speed of the
//! reported cycle over crank angle in rpm, every mechanism on one chart, with each one's
//! fluctuation band marked: from `speed_min` to `speed_max` of `summary.json` (the cycle's
//! extremes, between the rows too), its coefficient of speed fluctuation
//! δ = (ω_max − ω_min)/ω_mean (`speed_fluctuation_coefficient`) in the legend. A run of
//! prescribed motion (no `speed_mean` metric) has no such chart: its speed is given, not found.

use crate::data::CaseSummary;
use crate::envelope::ChartData;
use crate::svg::{self, Band, LineChart, Series};
use std::f64::consts::PI;

/// rad/s to rpm: 60/(2π).
pub(crate) const RPM_PER_RAD_S: f64 = 60.0 / (2.0 * PI);

/// The crank-speed chart of the case: none without a dynamic run's speed metrics.
pub(super) fn crank_speed_charts(
    s: &CaseSummary,
    data: &[Option<ChartData>],
) -> Vec<(String, String, String)> {
    let mut series = Vec::new();
    let mut bands = Vec::new();
    for (k, m) in s.mechanisms.iter().enumerate() {
        let Some(d) = &data[k] else { continue };
        let (Some(lo), Some(hi), Some(mean)) =
            (m.get("speed_min"), m.get("speed_max"), m.get("speed_mean"))
        else {
            continue;
        };
        let Some(t) = d.traces.get("crank_speed_rad_s") else {
            continue;
        };
        if !t.y.iter().any(|v| v.is_finite()) {
            continue;
        }
        let delta = m
            .get("speed_fluctuation_coefficient")
            .filter(|v| v.is_finite())
            .map_or(String::new(), |v| format!(", δ = {:.3} %", v * 100.0));
        let dash = series.len();
        series.push(Series {
            label: format!("{} (mean {:.1} rpm{delta})", m.name, mean * RPM_PER_RAD_S),
            source: format!("{}:crank_speed_rad_s", d.file),
            x: t.x.clone(),
            y: t.y.iter().map(|v| v * RPM_PER_RAD_S).collect(),
            colour: k,
            dash,
            markers: false,
            x_column: None,
        });
        bands.push(Band {
            from: lo * RPM_PER_RAD_S,
            to: hi * RPM_PER_RAD_S,
            colour: k,
            dash,
            label: format!("{}: speed_min to speed_max", m.name),
        });
    }
    if series.is_empty() {
        return Vec::new();
    }
    let title = match s.one_cylinder() {
        Some(_) => "Crank speed over the reported cycle (the whole machine)",
        None => "Crank speed over the reported cycle",
    };
    let chart = LineChart {
        title: title.into(),
        x_label: "crank angle θ, °".into(),
        y_label: "crank speed".into(),
        y_unit: "rpm".into(),
        series,
        angle_axis: true,
        factors: Some((1.0, RPM_PER_RAD_S)),
        bands,
        ..LineChart::default()
    };
    vec![(
        "crank_speed.svg".into(),
        svg::line_chart(&chart),
        "Crank speed of the reported cycle over crank angle, every mechanism; the shaded band \
         of each runs from its speed_min to its speed_max (the cycle's extremes, between the \
         rows too), δ = (speed_max − speed_min)/speed_mean"
            .into(),
    )]
}
