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
//! mechanism the run-up through every cycle before the reported one (`summary.json`'s `runup`:
//! each cycle's start and its steps' extremes, thinned by the run), the speed at the start of
//! every cycle (markers; the same crank angle, `start_angle`), and every row of the reported
//! cycle over `time_s`; the same band marked. Both charts are made by one builder
//! ([`speed_chart`]), apart only in their x column.

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
    speed_chart(s, data, Over::Angle)
}

/// The crank speed over time of the case's run-up: none unless a dynamic run solved cycles
/// before the reported one. Per mechanism three series, each its own dash: the run-up
/// (`summary.json:runup`, where the summary has it), the speed at the start of every cycle
/// (markers; `summary.json:cycle_starts`), and the reported cycle's rows over `time_s`, which
/// start where the run-up ends, at the last cycle start.
pub(super) fn crank_speed_time_charts(
    s: &CaseSummary,
    data: &[Option<ChartData>],
) -> Vec<(String, String, String)> {
    speed_chart(s, data, Over::Time)
}

/// The x column of a crank-speed chart.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Over {
    /// The crank angle (`crank_speed.svg`): the reported cycle.
    Angle,
    /// `time_s` (`crank_speed_time.svg`): the run from its start.
    Time,
}

impl Over {
    /// The chart's trace of the crank speed over this x.
    fn trace(self) -> String {
        match self {
            Over::Angle => "crank_speed_rad_s".into(),
            Over::Time => locus_key("time_s", "crank_speed_rad_s"),
        }
    }

    /// `data-x-column` of its series (the crank angle is every chart's default).
    fn x_column(self) -> Option<String> {
        (self == Over::Time).then(|| "time_s".into())
    }
}

/// A series of mechanism `m` (colour `k`) from `summary.json`'s `field`, (time s, speed
/// rad/s) pairs drawn in rpm over time.
fn summary_series(
    m: &MechanismSummary,
    field: &str,
    label: &str,
    points: &[(f64, f64)],
    k: usize,
    dash: usize,
    markers: bool,
) -> Series {
    let (x, y): (Vec<f64>, Vec<f64>) = points.iter().copied().unzip();
    Series {
        label: format!("{}: {label}", m.name),
        source: format!("summary.json:{}:{field}", m.name),
        x,
        y: y.iter().map(|v| v * RPM_PER_RAD_S).collect(),
        colour: k,
        dash,
        markers,
        x_column: Over::Time.x_column(),
    }
}

/// The crank-speed chart over `over`: per dynamic mechanism the reported cycle's rows with its
/// fluctuation band, over time with the run before them (a run-up: more than one cycle start).
fn speed_chart(
    s: &CaseSummary,
    data: &[Option<ChartData>],
    over: Over,
) -> Vec<(String, String, String)> {
    let (series, bands) = speed_series(s, data, over);
    if series.is_empty() {
        return Vec::new();
    }
    let whole = s.one_cylinder().is_some();
    let (title, x_label, file, caption) = speed_chart_words(over);
    let chart = LineChart {
        title: if whole {
            format!("{title} (the whole machine)")
        } else {
            title.into()
        },
        x_label: x_label.into(),
        y_label: "crank speed".into(),
        y_unit: "rpm".into(),
        series,
        angle_axis: over == Over::Angle,
        factors: Some((1.0, RPM_PER_RAD_S)),
        bands,
        ..LineChart::default()
    };
    vec![(file.into(), svg::line_chart(&chart), caption.into())]
}

/// The series of the crank-speed chart over `over` and each dynamic mechanism's fluctuation
/// band: over time the run-up and the cycles' starts before the reported cycle's rows.
fn speed_series(
    s: &CaseSummary,
    data: &[Option<ChartData>],
    over: Over,
) -> (Vec<Series>, Vec<Band>) {
    let mut series = Vec::new();
    let mut bands = Vec::new();
    for (k, m) in s.mechanisms.iter().enumerate() {
        let Some(d) = &data[k] else { continue };
        let (Some(lo), Some(hi), Some(mean)) =
            (m.get("speed_min"), m.get("speed_max"), m.get("speed_mean"))
        else {
            continue;
        };
        let Some(t) = d.traces.get(&over.trace()) else {
            continue;
        };
        if !t.y.iter().any(|v| v.is_finite()) {
            continue;
        }
        let label = match over {
            Over::Angle => format!("{} ({})", m.name, mean_and_delta(m, mean)),
            Over::Time if m.cycle_starts.len() < 2 => continue,
            Over::Time => {
                if m.runup.len() > 1 {
                    let run = "run-up, each cycle's start and extremes";
                    series.push(summary_series(
                        m,
                        "runup",
                        run,
                        &m.runup,
                        k,
                        series.len(),
                        false,
                    ));
                }
                let starts = "speed at each cycle's start";
                let n = series.len();
                series.push(summary_series(
                    m,
                    "cycle_starts",
                    starts,
                    &m.cycle_starts,
                    k,
                    n,
                    true,
                ));
                format!("{}: reported cycle ({})", m.name, mean_and_delta(m, mean))
            }
        };
        let dash = series.len();
        series.push(Series {
            label,
            source: format!("{}:crank_speed_rad_s", d.file),
            x: t.x.clone(),
            y: t.y.iter().map(|v| v * RPM_PER_RAD_S).collect(),
            colour: k,
            dash,
            markers: false,
            x_column: over.x_column(),
        });
        bands.push(band(m, [lo, hi], k, dash));
    }
    (series, bands)
}

/// The crank-speed chart's title, x axis title, file and caption over `over`.
fn speed_chart_words(over: Over) -> (&'static str, &'static str, &'static str, &'static str) {
    match over {
        Over::Angle => (
            "Crank speed over the reported cycle",
            "crank angle θ, °",
            "crank_speed.svg",
            "Crank speed of the reported cycle over crank angle, every mechanism; the shaded \
             band of each runs from its speed_min to its speed_max (the cycle's extremes, \
             between the rows too), δ = (speed_max − speed_min)/speed_mean",
        ),
        Over::Time => (
            "Crank speed over time, from the run's start",
            "time t, s",
            "crank_speed_time.svg",
            "Crank speed over time from the run's start (its cycles before the reported one, a \
             run-up), every mechanism: the run-up (each cycle's start and the extremes of its \
             steps, thinned), the speed at the start of each cycle (markers, the same crank \
             angle), then every row of the reported cycle; the shaded band of each runs from \
             its speed_min to its speed_max over the reported cycle",
        ),
    }
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
