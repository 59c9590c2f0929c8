//! A small SVG writer for the reports: line charts (every series on one axis, decimated to at
//! most [`MAX_POINTS`] points keeping each bucket's minimum and maximum) and heat maps (a
//! colour legend, optionally the contour of 0). No font files, no ids (many charts are
//! inlined into one HTML page), fixed float formatting so that the output is reproducible.
//!
//! Every chart carries its data in attributes that the tests read back: the plot area
//! (`data-area`: left, top, width, height in px) and the axis ranges (`data-x-min`, ...) on
//! `<g class="plot">`, and on each `<polyline class="series">` its label, its source
//! (`data-source`, `file:column`) and its number of points (`data-n`). Heat maps are in
//! `heatmap.rs`.

use crate::svg_text::fixed_decimals;
pub(crate) use crate::svg_text::{c, esc, points_text, push_esc, put};
use std::fmt::Write as _;

/// Most points a plotted series keeps (min/max per bucket beyond that).
pub const MAX_POINTS: usize = 1000;

/// Colour-blind-safe series colours (Okabe-Ito), by mechanism order.
pub(super) const PALETTE: [&str; 8] = [
    "#0072b2", "#d55e00", "#009e73", "#cc79a7", "#e69f00", "#56b4e9", "#000000", "#f0e442",
];
/// Dash patterns: every series of a chart its own (`dash`), so that a chart printed in black
/// and white still tells its lines apart (issue 38).
pub(super) const DASHES: [&str; 8] = [
    "",
    "6 3",
    "2 2",
    "8 3 2 3",
    "12 4",
    "4 2 1 2 1 2",
    "1 3",
    "10 2 2 2 2 2",
];

pub(super) const WIDTH: f64 = 760.0;
pub(super) const LEFT: f64 = 78.0;
pub(super) const RIGHT: f64 = 24.0;
pub(super) const TOP: f64 = 36.0;
pub(super) const PLOT_HEIGHT: f64 = 300.0;
pub(super) const FONT: &str = "font-family=\"sans-serif\"";

/// One plotted series.
#[derive(Debug, Clone)]
pub struct Series {
    /// Legend text.
    pub label: String,
    /// Where the data come from (`file:column`), for readers and tests.
    pub source: String,
    pub x: Vec<f64>,
    pub y: Vec<f64>,
    /// Colour index into the palette.
    pub colour: usize,
    /// Dash pattern index.
    pub dash: usize,
    /// Draws a marker at each point (few points: sweeps).
    pub markers: bool,
    /// The column x is made of (`data-x-column`) when it is not the crank angle or a sweep's
    /// field: the piston position of an indicator diagram's volume (`indicator.rs`).
    pub x_column: Option<String>,
}

/// A chart of series over one x axis.
#[derive(Debug, Clone, Default)]
pub struct LineChart {
    pub title: String,
    pub x_label: String,
    /// Quantity name; the unit (with its SI prefix) is appended.
    pub y_label: String,
    /// SI unit of y.
    pub y_unit: String,
    pub series: Vec<Series>,
    /// Draws a line at y = 0 when it is inside the range.
    pub zero_line: bool,
    /// Tick labels at x = 0, 1, 2, ... instead of numbers (categorical x).
    pub x_categories: Option<Vec<String>>,
    /// Fixed x ticks for crank angles: multiples of 90°.
    pub angle_axis: bool,
    /// The engineering units the series are in: each series' x and y are its SI data times
    /// these factors (bar: 1e-5 per Pa), written on the plot group (`data-x-factor`,
    /// `data-y-factor`) for readers going back to SI. `None`: SI.
    pub factors: Option<(f64, f64)>,
    /// Horizontal bands (y from, y to; colour; dash), in the series' units: a crank speed's
    /// fluctuation band.
    pub bands: Vec<Band>,
}

/// A horizontal band across a line chart (`<rect class="band">` with its edges as lines).
#[derive(Debug, Clone)]
pub struct Band {
    pub from: f64,
    pub to: f64,
    pub colour: usize,
    pub dash: usize,
    /// What the band is, for readers and tests (`data-label`).
    pub label: String,
}

/// Fixed formatting of a data value in an attribute (round-trip exact, reproducible).
pub fn attr_num(v: f64) -> String {
    if v.is_finite() {
        format!("{v:e}")
    } else {
        "NaN".into()
    }
}

/// At most `max` points of (x, y), NaNs dropped: all of them if few enough, else per bucket
/// the points of smallest and largest y in their order, so that every peak survives.
pub fn decimate(x: &[f64], y: &[f64], max: usize) -> (Vec<f64>, Vec<f64>) {
    let idx: Vec<usize> = (0..x.len().min(y.len()))
        .filter(|&k| x[k].is_finite() && y[k].is_finite())
        .collect();
    if idx.len() <= max {
        return (
            idx.iter().map(|&k| x[k]).collect(),
            idx.iter().map(|&k| y[k]).collect(),
        );
    }
    // The ends, and per bucket the smallest and largest y: at most 2 + 2 × buckets ≤ max.
    let buckets = (max.saturating_sub(2) / 2).max(1);
    let n = idx.len();
    let mut keep = Vec::with_capacity(max);
    keep.push(idx[0]);
    for b in 0..buckets {
        let part = &idx[b * n / buckets..(b + 1) * n / buckets];
        let (mut lo, mut hi) = (part[0], part[0]);
        for &k in part {
            if y[k] < y[lo] {
                lo = k;
            }
            if y[k] > y[hi] {
                hi = k;
            }
        }
        keep.push(lo.min(hi));
        keep.push(lo.max(hi));
    }
    keep.push(idx[n - 1]);
    keep.dedup();
    (
        keep.iter().map(|&k| x[k]).collect(),
        keep.iter().map(|&k| y[k]).collect(),
    )
}

/// Tick positions covering [min, max] with a 1-2-2.5-5 step, about `target` intervals: (low
/// end, high end, step).
pub fn nice_range(min: f64, max: f64, target: f64) -> (f64, f64, f64) {
    let (mut min, mut max) = (min, max);
    if !(min.is_finite() && max.is_finite()) {
        return (0.0, 1.0, 0.2);
    }
    if max - min <= f64::EPSILON * max.abs().max(min.abs()).max(1e-300) {
        let pad = if min == 0.0 { 1.0 } else { 0.1 * min.abs() };
        min -= pad;
        max += pad;
    }
    let raw = (max - min) / target;
    let mag = 10f64.powf(raw.log10().floor());
    let step = [1.0, 2.0, 2.5, 5.0, 10.0]
        .iter()
        .map(|f| f * mag)
        .find(|s| *s >= raw * (1.0 - 1e-12))
        .unwrap_or(10.0 * mag);
    let lo = (min / step + 1e-9).floor() * step;
    let hi = (max / step - 1e-9).ceil() * step;
    (lo, hi, step)
}

/// Units the charts print beside SI in the engineer's own (issue 38), never given an SI prefix.
pub(super) const ENGINEERING_UNITS: [&str; 6] = ["bar", "rpm", "cm^3", "kN", "kW", "L"];

/// The SI prefix that keeps tick labels short: (factor to divide by, prefix).
pub(super) fn prefix(max_abs: f64, unit: &str) -> (f64, &'static str) {
    if unit.is_empty()
        || unit == "1"
        || unit == "%"
        || unit == "deg"
        || ENGINEERING_UNITS.contains(&unit)
        || unit.starts_with("rpm")
    {
        return (1.0, "");
    }
    match max_abs {
        v if v >= 1e10 => (1e9, "G"),
        v if v >= 1e7 => (1e6, "M"),
        v if v >= 1e4 => (1e3, "k"),
        v if v > 0.0 && v < 1e-4 => (1e-6, "µ"),
        v if v > 0.0 && v < 1e-1 => (1e-3, "m"),
        _ => (1.0, ""),
    }
}

/// A tick label: as few decimals as the step needs.
pub(super) fn tick_label(v: f64, step: f64) -> String {
    let decimals = (-(step.log10().floor()) + if is_quarter(step) { 1.0 } else { 0.0 })
        .clamp(0.0, 8.0) as usize;
    let s = fixed_decimals(v, decimals);
    if s.starts_with('-') && s[1..].chars().all(|ch| ch == '0' || ch == '.') {
        s[1..].to_string()
    } else {
        s
    }
}

fn is_quarter(step: f64) -> bool {
    let m = step / 10f64.powf(step.log10().floor());
    (m - 2.5).abs() < 1e-9
}

/// Approximate width of `s` at font size `size` (sans-serif).
pub(super) fn text_width(s: &str, size: f64) -> f64 {
    s.chars().count() as f64 * size * 0.58
}

/// Legend entries flowed into rows under the plot: (x, y) of each and the height used.
pub(super) fn legend_layout(labels: &[String], top: f64) -> (Vec<(f64, f64)>, f64) {
    let mut pos = Vec::new();
    let (mut x, mut y) = (LEFT, top);
    for l in labels {
        let w = 34.0 + text_width(l, 12.0) + 18.0;
        if x + w > WIDTH - RIGHT && x > LEFT {
            x = LEFT;
            y += 18.0;
        }
        pos.push((x, y));
        x += w;
    }
    (
        pos,
        if labels.is_empty() {
            0.0
        } else {
            y - top + 18.0
        },
    )
}

/// The opening tag of a chart `height` px high.
pub(super) fn open_svg(o: &mut String, height: f64) {
    let _ = writeln!(
        o,
        "<svg xmlns=\"http://www.w3.org/2000/svg\" class=\"chart\" width=\"{w}\" height=\"{h}\" viewBox=\"0 0 {w} {h}\" {FONT} font-size=\"12\">",
        w = c(WIDTH),
        h = c(height)
    );
}

/// The line chart as an SVG document.
/// A chart's `<title>`, white background and bold heading at `left` (px).
pub(crate) fn chart_heading(o: &mut String, title: &str, left: f64) {
    let _ = writeln!(o, "<title>{}</title>", esc(title));
    let _ = writeln!(o, "<rect width=\"100%\" height=\"100%\" fill=\"#ffffff\"/>");
    let _ = writeln!(
        o,
        "<text x=\"{}\" y=\"22\" font-size=\"15\" font-weight=\"bold\">{}</text>",
        c(left),
        esc(title)
    );
}

/// Opens a chart's plot group: its area (left, top, width, height; px) and its axes' ranges,
/// which the tests read back (`cardan_testing::chart::Axes`).
pub(crate) fn open_plot(
    o: &mut String,
    area: [f64; 4],
    (x_lo, x_hi): (f64, f64),
    (y_lo, y_hi): (f64, f64),
) {
    let _ = writeln!(
        o,
        "<g class=\"plot\" data-area=\"{} {} {} {}\" data-x-min=\"{}\" data-x-max=\"{}\" data-y-min=\"{}\" data-y-max=\"{}\">",
        c(area[0]),
        c(area[1]),
        c(area[2]),
        c(area[3]),
        attr_num(x_lo),
        attr_num(x_hi),
        attr_num(y_lo),
        attr_num(y_hi)
    );
}

/// The line chart as an SVG document: the series thinned to [`MAX_POINTS`], its bands, the
/// grid, the axes' titles and the legend.
pub fn line_chart(chart: &LineChart) -> String {
    let decimated: Vec<(Vec<f64>, Vec<f64>)> = chart
        .series
        .iter()
        .map(|s| decimate(&s.x, &s.y, MAX_POINTS))
        .collect();
    let (x_min, x_max, mut y_min, mut y_max) = extent(&decimated);
    for b in &chart.bands {
        y_min = y_min.min(b.from.min(b.to));
        y_max = y_max.max(b.from.max(b.to));
    }
    let (x_lo, x_hi, x_step) = x_range(chart, x_min, x_max);
    let (y_lo, y_hi, y_step) = nice_range(y_min, y_max, 5.0);
    let (scale, pre) = prefix(y_lo.abs().max(y_hi.abs()), &chart.y_unit);
    let plot_w = WIDTH - LEFT - RIGHT;
    let px = |v: f64| LEFT + (v - x_lo) / (x_hi - x_lo) * plot_w;
    let py = |v: f64| TOP + (y_hi - v) / (y_hi - y_lo) * PLOT_HEIGHT;
    let labels: Vec<String> = chart.series.iter().map(|s| s.label.clone()).collect();
    let legend_top = TOP + PLOT_HEIGHT + 50.0;
    let (legend, legend_h) = legend_layout(&labels, legend_top);
    let height = legend_top + legend_h + 6.0;

    let mut o = String::with_capacity(16 * 1024);
    open_svg(&mut o, height);
    chart_heading(&mut o, &chart.title, LEFT);
    open_plot(
        &mut o,
        [LEFT, TOP, plot_w, PLOT_HEIGHT],
        (x_lo, x_hi),
        (y_lo, y_hi),
    );
    plot_factors(&mut o, chart.factors);
    let _ = writeln!(
        o,
        "<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"none\" stroke=\"#444\"/>",
        c(LEFT),
        c(TOP),
        c(plot_w),
        c(PLOT_HEIGHT)
    );
    // Grid and tick labels.
    y_grid(&mut o, (y_lo, y_hi, y_step), scale, plot_w, &py);
    x_grid(&mut o, &chart.x_categories, (x_lo, x_hi, x_step), &px);
    if chart.zero_line && y_lo < 0.0 && y_hi > 0.0 {
        let _ = writeln!(
            o,
            "<line class=\"zero\" x1=\"{}\" y1=\"{y}\" x2=\"{}\" y2=\"{y}\" stroke=\"#000\" stroke-width=\"1.2\"/>",
            c(LEFT),
            c(LEFT + plot_w),
            y = c(py(0.0))
        );
    }
    bands(&mut o, &chart.bands, (LEFT, plot_w), &py);
    series_lines(&mut o, &chart.series, &decimated, px, py);
    o.push_str("</g>\n");
    line_axis_titles(&mut o, chart, pre, plot_w);
    legend_lines(&mut o, &chart.series, &legend);
    o.push_str("</g>\n</svg>\n");
    o
}

/// The horizontal grid lines over `(y_lo, y_hi, y_step)` with their tick labels in the
/// axis's prefixed unit (`scale` SI units per displayed unit).
fn y_grid(
    o: &mut String,
    (y_lo, y_hi, y_step): (f64, f64, f64),
    scale: f64,
    plot_w: f64,
    py: &impl Fn(f64) -> f64,
) {
    let y_ticks = ((y_hi - y_lo) / y_step).round() as usize;
    for k in 0..=y_ticks {
        let v = y_lo + k as f64 * y_step;
        let y = py(v);
        put!(o; "<line x1=\"", c(LEFT), "\" y1=\"", c(y), "\" x2=\"", c(LEFT + plot_w),
            "\" y2=\"", c(y), "\" stroke=\"#ddd\"/><text x=\"", c(LEFT - 6.0), "\" y=\"",
            c(y + 4.0), "\" text-anchor=\"end\">", tick_label(v / scale, y_step / scale),
            "</text>\n");
    }
}

/// The vertical grid lines with their labels: of a text axis at most 12 of its categories,
/// else over `(x_lo, x_hi, x_step)`.
fn x_grid(
    o: &mut String,
    categories: &Option<Vec<String>>,
    (x_lo, x_hi, x_step): (f64, f64, f64),
    px: &impl Fn(f64) -> f64,
) {
    // A vertical grid line at x with its label under the plot.
    let x_tick = |o: &mut String, x: f64, label: &str| {
        put!(o; "<line x1=\"", c(x), "\" y1=\"", c(TOP), "\" x2=\"", c(x), "\" y2=\"",
            c(TOP + PLOT_HEIGHT), "\" stroke=\"#ddd\"/><text x=\"", c(x), "\" y=\"",
            c(TOP + PLOT_HEIGHT + 16.0), "\" text-anchor=\"middle\">", label, "</text>\n");
    };
    match categories {
        Some(cats) => {
            let every = cats.len().div_ceil(12).max(1);
            for (k, cat) in cats.iter().enumerate().step_by(every) {
                x_tick(o, px(k as f64), &esc(cat));
            }
        }
        None => {
            let x_ticks = ((x_hi - x_lo) / x_step).round() as usize;
            for k in 0..=x_ticks {
                let v = x_lo + k as f64 * x_step;
                x_tick(o, px(v), &tick_label(v, x_step));
            }
        }
    }
}

/// The line chart's axis titles: x as given, y with its unit and the unit's prefix.
fn line_axis_titles(o: &mut String, chart: &LineChart, pre: &str, plot_w: f64) {
    let unit = pretty_unit_prefixed(pre, &chart.y_unit);
    let y_title = if unit.is_empty() {
        chart.y_label.clone()
    } else {
        format!("{}, {unit}", chart.y_label)
    };
    let x_title = &chart.x_label;
    let middle = (LEFT + plot_w / 2.0, TOP + PLOT_HEIGHT / 2.0);
    axis_titles(o, middle, TOP + PLOT_HEIGHT, (x_title, &y_title));
}

/// A chart's axis titles: `titles.0` centred under the plot (its middle `middle.0`, its bottom
/// edge `bottom`), `titles.1` turned up the left edge beside its middle `middle.1`.
pub(crate) fn axis_titles(o: &mut String, middle: (f64, f64), bottom: f64, titles: (&str, &str)) {
    let _ = writeln!(
        o,
        "<text x=\"{}\" y=\"{}\" text-anchor=\"middle\">{}</text>",
        c(middle.0),
        c(bottom + 36.0),
        esc(titles.0)
    );
    let _ = writeln!(
        o,
        "<text transform=\"translate(16 {}) rotate(-90)\" text-anchor=\"middle\">{}</text>",
        c(middle.1),
        esc(titles.1)
    );
}

/// Writes the plot group's `factors` (`data-x-factor`, `data-y-factor`: display units per SI
/// unit) as a `<desc>` child's attributes, when the chart is not in SI.
pub(crate) fn plot_factors(o: &mut String, factors: Option<(f64, f64)>) {
    if let Some((fx, fy)) = factors {
        let _ = writeln!(
            o,
            "<desc class=\"factors\" data-x-factor=\"{}\" data-y-factor=\"{}\">display value = SI value × factor</desc>",
            attr_num(fx),
            attr_num(fy)
        );
    }
}

/// Writes each band as a light rectangle across the plot (`left`, `width`) between its y
/// values (pixels by `py`), its edges in its colour and dash.
fn bands(o: &mut String, bands: &[Band], (left, width): (f64, f64), py: &impl Fn(f64) -> f64) {
    for b in bands {
        let colour = PALETTE[b.colour % PALETTE.len()];
        let dash = DASHES[b.dash % DASHES.len()];
        let dash = if dash.is_empty() {
            String::new()
        } else {
            format!(" stroke-dasharray=\"{dash}\"")
        };
        let (top, bottom) = (py(b.from.max(b.to)), py(b.from.min(b.to)));
        let _ = writeln!(
            o,
            "<rect class=\"band\" data-label=\"{}\" data-from=\"{}\" data-to=\"{}\" x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"{colour}\" fill-opacity=\"0.12\"/>",
            esc(&b.label),
            attr_num(b.from),
            attr_num(b.to),
            c(left),
            c(top),
            c(width),
            c(bottom - top)
        );
        for y in [top, bottom] {
            let _ = writeln!(
                o,
                "<line class=\"band-edge\" x1=\"{}\" y1=\"{y}\" x2=\"{}\" y2=\"{y}\" stroke=\"{colour}\" stroke-width=\"0.8\"{dash}/>",
                c(left),
                c(left + width),
                y = c(y)
            );
        }
    }
}

/// The smallest and largest finite x and y of the series drawn, (x_min, x_max, y_min, y_max);
/// (0, 1, 0, 1) without any.
fn extent(decimated: &[(Vec<f64>, Vec<f64>)]) -> (f64, f64, f64, f64) {
    let finite = |v: &&f64| v.is_finite();
    let (mut x_min, mut x_max, mut y_min, mut y_max) = (f64::MAX, f64::MIN, f64::MAX, f64::MIN);
    for (x, y) in decimated {
        for v in x.iter().filter(finite) {
            x_min = x_min.min(*v);
            x_max = x_max.max(*v);
        }
        for v in y.iter().filter(finite) {
            y_min = y_min.min(*v);
            y_max = y_max.max(*v);
        }
    }
    if x_min > x_max {
        (x_min, x_max, y_min, y_max) = (0.0, 1.0, 0.0, 1.0);
    }
    (x_min, x_max, y_min, y_max)
}

/// The x axis of `chart` over the data's `x_min..x_max`: (low, high, tick step). Categories
/// one apart, half a step of margin; a crank angle of half a turn or more in steps of 90° (180°
/// over four turns); else a nice range.
fn x_range(chart: &LineChart, x_min: f64, x_max: f64) -> (f64, f64, f64) {
    if chart.x_categories.is_some() {
        (x_min - 0.5, x_max + 0.5, 1.0)
    } else if chart.angle_axis && x_max - x_min >= 180.0 {
        let step = if x_max - x_min > 1440.0 { 180.0 } else { 90.0 };
        (
            (x_min / step + 1e-9).floor() * step,
            (x_max / step - 1e-9).ceil() * step,
            step,
        )
    } else {
        nice_range(x_min, x_max, 8.0)
    }
}

/// Writes each series as a polyline of its `decimated` points (pixels by `px`, `py`), with
/// its markers if it has them.
pub(crate) fn series_lines(
    o: &mut String,
    series: &[Series],
    decimated: &[(Vec<f64>, Vec<f64>)],
    px: impl Fn(f64) -> f64,
    py: impl Fn(f64) -> f64,
) {
    for (s, (x, y)) in series.iter().zip(decimated) {
        let colour = PALETTE[s.colour % PALETTE.len()];
        let dash = DASHES[s.dash % DASHES.len()];
        let points = points_text(x.iter().zip(y).map(|(a, b)| (px(*a), py(*b))), x.len());
        let x_column = s
            .x_column
            .as_ref()
            .map_or(String::new(), |c| format!(" data-x-column=\"{}\"", esc(c)));
        let _ = writeln!(
            o,
            "<polyline class=\"series\" data-label=\"{}\" data-source=\"{}\"{x_column} data-n=\"{}\" fill=\"none\" stroke=\"{colour}\" stroke-width=\"1.6\"{} points=\"{points}\"/>",
            esc(&s.label),
            esc(&s.source),
            x.len(),
            if dash.is_empty() {
                String::new()
            } else {
                format!(" stroke-dasharray=\"{dash}\"")
            }
        );
        if s.markers {
            for (a, b) in x.iter().zip(y) {
                let _ = writeln!(
                    o,
                    "<circle class=\"marker\" cx=\"{}\" cy=\"{}\" r=\"3\" fill=\"{colour}\"/>",
                    c(px(*a)),
                    c(py(*b))
                );
            }
        }
    }
}

/// Writes the legend's line and label of each series, at the places `legend` laid out.
pub(super) fn legend_lines(o: &mut String, series: &[Series], legend: &[(f64, f64)]) {
    o.push_str("<g class=\"legend-lines\">\n");
    for (s, (x, y)) in series.iter().zip(legend) {
        let colour = PALETTE[s.colour % PALETTE.len()];
        let dash = DASHES[s.dash % DASHES.len()];
        put!(o; "<line x1=\"", c(*x), "\" y1=\"", c(y - 4.0), "\" x2=\"", c(x + 28.0),
            "\" y2=\"", c(y - 4.0), "\" stroke=\"", colour, "\" stroke-width=\"2.5\"");
        if !dash.is_empty() {
            put!(o; " stroke-dasharray=\"", dash, "\"");
        }
        put!(o; "/><text x=\"", c(x + 34.0), "\" y=\"", c(*y), "\">");
        push_esc(o, &s.label);
        o.push_str("</text>\n");
    }
}

/// A unit as printed: `N*m` → `N·m`, `m/s^2` → `m/s²`, `1` → nothing.
pub fn pretty_unit(unit: &str) -> String {
    match unit {
        "1" => String::new(),
        // Nothing to replace: most units (issue 37).
        u if !u.bytes().any(|b| b == b'*' || b == b'^') => u.to_string(),
        u => u.replace('*', "·").replace("^2", "²").replace("^3", "³"),
    }
}

pub(super) fn pretty_unit_prefixed(prefix: &str, unit: &str) -> String {
    let u = pretty_unit(unit);
    if prefix.is_empty() || u.is_empty() {
        u
    } else {
        format!("{prefix}{u}")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn decimation_keeps_the_peaks_and_the_budget() {
        let n = 7201;
        let x: Vec<f64> = (0..n).map(|k| k as f64 * 0.1).collect();
        let mut y: Vec<f64> = x.iter().map(|t| (t * 0.37).sin()).collect();
        y[1234] = 5.0;
        y[4321] = -7.0;
        let (dx, dy) = decimate(&x, &y, 1000);
        assert!(dx.len() <= 1000 && dx.len() >= 900, "{}", dx.len());
        assert!(dy.contains(&5.0) && dy.contains(&-7.0));
        assert!(dx.windows(2).all(|w| w[0] < w[1]));
        let (sx, _) = decimate(&x[..500], &y[..500], 1000);
        assert_eq!(sx.len(), 500);
    }

    #[test]
    fn units_are_printed_with_their_signs() {
        for (unit, printed) in [
            ("1", ""),
            ("N*m", "N·m"),
            ("m/s^2", "m/s²"),
            ("m^3", "m³"),
            ("kg*m^2", "kg·m²"),
            ("Pa", "Pa"),
            ("", ""),
            ("rad/s", "rad/s"),
        ] {
            assert_eq!(pretty_unit(unit), printed, "{unit}");
        }
    }

    #[test]
    fn nice_ranges_cover_the_data() {
        for (a, b) in [
            (0.0, 1.0),
            (-3.2, 7.9),
            (40830.0, 81690.0),
            (5.0, 5.0),
            (-1e-9, 2e-9),
        ] {
            let (lo, hi, step) = nice_range(a, b, 5.0);
            assert!(lo <= a && hi >= b, "{a} {b}: {lo} {hi}");
            assert!((hi - lo) / step <= 12.0);
        }
    }
}
