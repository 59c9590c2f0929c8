//! The crank speed of a dynamic run (`crank_speed.svg`, issue 38): the crank speed of the
//! reported cycle over crank angle in rpm, every mechanism on one chart, with each one's
//! fluctuation band marked: from `speed_min` to `speed_max` of `summary.json` (the cycle's
//! extremes, between the rows too), its coefficient of speed fluctuation
//! δ = (ω_max − ω_min)/ω_mean (`speed_fluctuation_coefficient`) in the legend. A run of
//! prescribed motion (no `speed_mean` metric) has no such chart: its speed is given, not found.
//!
//! A dynamic run that solved cycles before the reported one (a run-up from rest or from any
//! start speed: `summary.json`'s `cycle_starts` lists more than one) also has its crank speed
//! over time (`crank_speed_time.svg`), from the run's start to the reported cycle's end: per
//! mechanism the speed at the start of every cycle (the same crank angle, `start_angle`: the
//! run-up without its fluctuation within the cycles, which the run does not keep), and every
//! row of the reported cycle over `time_s`; the same band marked.

use crate::chart_columns::locus_key;
use crate::data::{CaseSummary, MechanismSummary};
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
        let dash = series.len();
        series.push(Series {
            label: format!("{} ({})", m.name, mean_and_delta(m, mean)),
            source: format!("{}:crank_speed_rad_s", d.file),
            x: t.x.clone(),
            y: t.y.iter().map(|v| v * RPM_PER_RAD_S).collect(),
            colour: k,
            dash,
            markers: false,
            x_column: None,
        });
        bands.push(band(m, [lo, hi], k, dash));
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

/// "mean 900.0 rpm, δ = 2.345 %": the reported cycle's mean speed and its coefficient of
/// speed fluctuation, where the summary has it.
fn mean_and_delta(m: &MechanismSummary, mean: f64) -> String {
    let delta = m
        .get("speed_fluctuation_coefficient")
        .filter(|v| v.is_finite())
        .map_or(String::new(), |v| format!(", δ = {:.3} %", v * 100.0));
    format!("mean {:.1} rpm{delta}", mean * RPM_PER_RAD_S)
}

/// The fluctuation band of mechanism `m` (colour `k`, the dash of its reported cycle's line):
/// from its `speed_min` to its `speed_max`, in rpm.
fn band(m: &MechanismSummary, [lo, hi]: [f64; 2], k: usize, dash: usize) -> Band {
    Band {
        from: lo * RPM_PER_RAD_S,
        to: hi * RPM_PER_RAD_S,
        colour: k,
        dash,
        label: format!("{}: speed_min to speed_max", m.name),
    }
}

/// The crank speed over time of the case's run-up: none unless a dynamic run solved cycles
/// before the reported one. Per mechanism two series, each its own dash: the speed at the
/// start of every cycle (markers; `summary.json:cycle_starts`), and the reported cycle's rows
/// over `time_s`, which start where the last cycle start is.
pub(super) fn crank_speed_time_charts(
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
        let Some(t) = d.traces.get(&locus_key("time_s", "crank_speed_rad_s")) else {
            continue;
        };
        if m.cycle_starts.len() < 2 || !t.y.iter().any(|v| v.is_finite()) {
            continue;
        }
        let (x, y): (Vec<f64>, Vec<f64>) = m.cycle_starts.iter().copied().unzip();
        series.push(Series {
            label: format!("{}: speed at each cycle's start", m.name),
            source: format!("summary.json:{}:cycle_starts", m.name),
            x,
            y: y.iter().map(|v| v * RPM_PER_RAD_S).collect(),
            colour: k,
            dash: series.len(),
            markers: true,
            x_column: Some("time_s".into()),
        });
        let dash = series.len();
        series.push(Series {
            label: format!("{}: reported cycle ({})", m.name, mean_and_delta(m, mean)),
            source: format!("{}:crank_speed_rad_s", d.file),
            x: t.x.clone(),
            y: t.y.iter().map(|v| v * RPM_PER_RAD_S).collect(),
            colour: k,
            dash,
            markers: false,
            x_column: Some("time_s".into()),
        });
        bands.push(band(m, [lo, hi], k, dash));
    }
    if series.is_empty() {
        return Vec::new();
    }
    let title = match s.one_cylinder() {
        Some(_) => "Crank speed over time, from the run's start (the whole machine)",
        None => "Crank speed over time, from the run's start",
    };
    let chart = LineChart {
        title: title.into(),
        x_label: "time t, s".into(),
        y_label: "crank speed".into(),
        y_unit: "rpm".into(),
        series,
        factors: Some((1.0, RPM_PER_RAD_S)),
        bands,
        ..LineChart::default()
    };
    vec![(
        "crank_speed_time.svg".into(),
        svg::line_chart(&chart),
        "Crank speed over time from the run's start (its cycles before the reported one, a \
         run-up), every mechanism: the speed at the start of each cycle (the same crank angle), \
         then every row of the reported cycle; the shaded band of each runs from its speed_min \
         to its speed_max over the reported cycle"
            .into(),
    )]
}
