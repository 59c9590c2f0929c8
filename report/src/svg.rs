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

/// Fixed formatting of a coordinate (one decimal: integer arithmetic, fast, and the same on
/// every machine; [`coord_digits`]).
pub(super) fn c(v: f64) -> Coord {
    Coord(v)
}

/// A coordinate written with one decimal ([`coord_digits`]) where it is formatted (`{}`): no
/// string of its own, no integer formatting (most of a report's formatting: issue 37).
#[derive(Debug, Clone, Copy)]
pub(super) struct Coord(f64);

impl std::fmt::Display for Coord {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let mut digits = [0; 24];
        let start = coord_digits(self.0, &mut digits);
        // Only ASCII digits, the point and the sign were written.
        f.pad(std::str::from_utf8(&digits[start..]).unwrap_or("0"))
    }
}

/// A polyline's `points`: each (x, y) of `xy` as `x,y` ([`c`]), separated by
/// spaces; `n` points expected. Written as bytes and made a string once (issue 37).
pub(super) fn points_text(xy: impl Iterator<Item = (f64, f64)>, n: usize) -> String {
    let mut text = Vec::with_capacity(n * 14);
    let mut digits = [0; 24];
    for (x, y) in xy {
        let start = coord_digits(x, &mut digits);
        text.extend_from_slice(&digits[start..]);
        text.push(b',');
        let start = coord_digits(y, &mut digits);
        text.extend_from_slice(&digits[start..]);
        text.push(b' ');
    }
    text.pop();
    // Only ASCII digits, points, signs, commas and spaces were written.
    String::from_utf8(text).unwrap_or_default()
}

/// `v` with one decimal, written at the end of `digits` from the returned index: the tenths
/// rounded to an integer and its digits with the point before the last; "0" beyond ±1e14 or
/// not finite. By hand rather than `{}` of the integers (the same digits: tested).
fn coord_digits(v: f64, digits: &mut [u8; 24]) -> usize {
    let t = (v * 10.0).round();
    let mut k = digits.len() - 1;
    if !t.is_finite() || t.abs() > 1e15 {
        digits[k] = b'0';
        return k;
    }
    // At most 1e15 tenths: a sign, 15 digits, the point and the tenth.
    let t = t as i64;
    let tenths = t.unsigned_abs();
    digits[k] = b'0' + (tenths % 10) as u8;
    k -= 1;
    digits[k] = b'.';
    let mut n = tenths / 10;
    loop {
        k -= 1;
        digits[k] = b'0' + (n % 10) as u8;
        n /= 10;
        if n == 0 {
            break;
        }
    }
    if t < 0 {
        k -= 1;
        digits[k] = b'-';
    }
    k
}

/// A piece of a chart's text that [`put!`] appends: text as it is, a coordinate ([`c`]).
pub(super) trait Piece {
    fn put(&self, o: &mut String);
}

impl Piece for &str {
    fn put(&self, o: &mut String) {
        o.push_str(self);
    }
}

impl Piece for String {
    fn put(&self, o: &mut String) {
        o.push_str(self);
    }
}

impl Piece for Coord {
    fn put(&self, o: &mut String) {
        let mut digits = [0; 24];
        let start = coord_digits(self.0, &mut digits);
        o.extend(digits[start..].iter().map(|&b| char::from(b)));
    }
}

/// Appends each piece ([`Piece`]) to the string, as `write!` of them one after another
/// would, without the formatting machinery: the lines a chart repeats, its grid and legend
/// (issue 37).
macro_rules! put {
    ($o:expr; $($piece:expr),+ $(,)?) => {{
        let o: &mut String = $o;
        $( $crate::svg::Piece::put(&$piece, o); )+
    }};
}
pub(crate) use put;

/// Fixed formatting of a data value in an attribute (round-trip exact, reproducible).
pub fn attr_num(v: f64) -> String {
    if v.is_finite() {
        format!("{v:e}")
    } else {
        "NaN".into()
    }
}

/// Escapes text for XML.
pub fn esc(s: &str) -> String {
    let mut o = String::with_capacity(s.len());
    push_esc(&mut o, s);
    o
}

/// Appends `s` escaped for XML: `&`, `<`, `>` and `"` as entities, the runs between them
/// whole (they are ASCII, so every other byte, of any character, is copied as it is).
pub fn push_esc(o: &mut String, s: &str) {
    let mut start = 0;
    for (k, b) in s.bytes().enumerate() {
        let entity = match b {
            b'&' => "&amp;",
            b'<' => "&lt;",
            b'>' => "&gt;",
            b'"' => "&quot;",
            _ => continue,
        };
        o.push_str(&s[start..k]);
        o.push_str(entity);
        start = k + 1;
    }
    o.push_str(&s[start..]);
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

/// `format!("{v:.decimals$}")` (decimals ≤ 8), by integer arithmetic where `v` is a whole
/// number of the last decimal's units, as a chart's ticks mostly are (issue 37): where
/// `v·10^decimals` rounds to an integer below 2^50 in floating point, the exact product is
/// within 1/8 of it, so the exact decimal rounding that `{:.N}` does gives that integer.
fn fixed_decimals(v: f64, decimals: usize) -> String {
    const POWERS: [f64; 9] = [1.0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8];
    let scaled = POWERS.get(decimals).map_or(f64::NAN, |p| v * p);
    if !(scaled.abs() < (1u64 << 50) as f64 && scaled == scaled.trunc()) {
        return format!("{v:.decimals$}");
    }
    let mut digits = scaled.abs() as u64;
    // The digits from the last, at least one before the point.
    let mut text = Vec::with_capacity(24);
    for k in 0.. {
        if k == decimals && decimals > 0 {
            text.push(b'.');
        }
        text.push(b'0' + (digits % 10) as u8);
        digits /= 10;
        if digits == 0 && k >= decimals {
            break;
        }
    }
    if v.is_sign_negative() {
        text.push(b'-');
    }
    text.reverse();
    // Only ASCII digits, the point and the sign were written.
    String::from_utf8(text).unwrap_or_else(|_| format!("{v:.decimals$}"))
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
    fn coordinates_are_written_as_the_formatting_machinery_wrote_them() {
        // The format coordinates had, `{}.{}` of the tenths' quotient and remainder.
        let by_format = |v: f64| {
            let t = (v * 10.0).round();
            if !t.is_finite() || t.abs() > 1e15 {
                return "0".to_string();
            }
            let t = t as i64;
            let sign = if t < 0 { "-" } else { "" };
            format!("{sign}{}.{}", t.abs() / 10, t.abs() % 10)
        };
        let mut values = vec![
            0.0,
            -0.0,
            0.04,
            -0.04,
            0.05,
            -0.05,
            0.95,
            -0.95,
            9.95,
            99.95,
            1e14,
            -1e14,
            99_999_999_999_999.9,
            1e15,
            f64::NAN,
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::MAX,
            f64::MIN_POSITIVE,
            u64::MAX as f64,
        ];
        // A SplitMix64 stream over many magnitudes, signs and fractions.
        let mut state = 0x9e37_79b9_7f4a_7c15_u64;
        for _ in 0..200_000 {
            state = state.wrapping_add(0x9e37_79b9_7f4a_7c15);
            let mut z = state;
            z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
            z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
            z ^= z >> 31;
            let unit = (z >> 11) as f64 / (1u64 << 53) as f64;
            let scale = 10f64.powi((z % 18) as i32 - 2);
            let sign = if z & (1 << 7) == 0 { 1.0 } else { -1.0 };
            values.push(sign * unit * scale);
        }
        for k in 0..=20_000 {
            values.push(k as f64 * 0.05 - 500.0);
        }
        for v in values {
            assert_eq!(c(v).to_string(), by_format(v), "{v:e}");
            assert_eq!(format!("[{:>12}]", c(v)), format!("[{:>12}]", by_format(v)));
        }
    }

    #[test]
    fn fixed_decimals_are_the_formatting_machinery_s() {
        let mut values = vec![
            0.0,
            -0.0,
            0.5,
            -0.5,
            1.5,
            2.5,
            -2.5,
            0.125,
            1e-9,
            -1e-9,
            0.1,
            0.3,
            1e15,
            -1e15,
            (1u64 << 50) as f64,
            (1u64 << 50) as f64 - 1.0,
            1e300,
            f64::NAN,
            f64::INFINITY,
            f64::NEG_INFINITY,
        ];
        // Ticks as the charts make them, lo + k·step over nice ranges of many magnitudes.
        let mut state = 0x2545_f491_4f6c_dd1d_u64;
        let mut next = || {
            state = state.wrapping_add(0x9e37_79b9_7f4a_7c15);
            let mut z = state;
            z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
            z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
            z ^ (z >> 31)
        };
        for _ in 0..20_000 {
            let z = next();
            let scale = 10f64.powi((z % 24) as i32 - 12);
            let a = ((z >> 11) as f64 / (1u64 << 53) as f64 - 0.5) * scale;
            let b = a + ((next() >> 11) as f64 / (1u64 << 53) as f64) * scale;
            let (lo, hi, step) = nice_range(a, b, 5.0);
            let ticks = ((hi - lo) / step).round() as usize;
            for k in 0..=ticks {
                values.push(lo + k as f64 * step);
                values.push((lo + k as f64 * step) / 1e3);
            }
            values.push(a);
        }
        // Both ways are taken: by integers, and by `format!`.
        let whole = |v: f64, d: i32| (v * 10f64.powi(d)).fract() == 0.0;
        let by_integers = values.iter().filter(|v| whole(**v, 2)).count();
        assert!(by_integers > 10_000 && by_integers + 10_000 < values.len());
        for v in values {
            for decimals in 0..=8 {
                assert_eq!(
                    fixed_decimals(v, decimals),
                    format!("{v:.decimals$}"),
                    "{v:e} to {decimals} decimals"
                );
            }
        }
    }

    #[test]
    fn escaping_is_by_character() {
        // The escape as it was, a character at a time.
        let by_chars = |s: &str| {
            let mut o = String::new();
            for ch in s.chars() {
                match ch {
                    '&' => o.push_str("&amp;"),
                    '<' => o.push_str("&lt;"),
                    '>' => o.push_str("&gt;"),
                    '"' => o.push_str("&quot;"),
                    _ => o.push(ch),
                }
            }
            o
        };
        for s in [
            "",
            "plain",
            "&",
            "<>\"&",
            "a < b & c > \"d\"",
            "Δ `x` → 10⁵ Pa & ° <µ>",
            "&&&",
            "é&é",
            "end&",
        ] {
            assert_eq!(esc(s), by_chars(s), "{s}");
        }
    }

    #[test]
    fn points_are_coordinates_pairs_by_spaces() {
        let xy = [(1.0, -2.25), (0.04, 1e20), (f64::NAN, -0.04), (123.45, 6.0)];
        let mut by_push = String::new();
        for (x, y) in xy {
            by_push.push_str(&format!("{},{} ", c(x), c(y)));
        }
        by_push.pop();
        assert_eq!(points_text(xy.into_iter(), 4), by_push);
        assert_eq!(by_push, "1.0,-2.3 0.0,0 0,0.0 123.5,6.0");
        assert_eq!(points_text(std::iter::empty(), 0), "");
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
