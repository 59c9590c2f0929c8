//! The locus of a planar vector over the run: one column against another at the same rows (the
//! shaking force's F_y against its F_x, issue 24's polar plot), thinned while it is made
//! ([`Locus`](crate::thinning::Locus)) and drawn on equal axes through the origin ([`locus_chart`]).
//!
//! A locus is a path, not a function of the crank angle: its points are kept in row order, so
//! that the polyline follows the vector's tip. Of a run of more rows than the budget it keeps
//! the first and the last row and, per bucket of consecutive rows, the rows of the smallest and
//! largest x and y (in their order): the extent of the path in both directions survives, as the
//! envelope keeps a series' peaks; the buckets are the envelope's (`thinning.rs`, shared by
//! both), a function of the rows announced, so a run and its CSV read back draw the same points.

use crate::svg::{
    axis_titles, c, chart_heading, esc, legend_layout, legend_lines, nice_range, open_plot,
    open_svg, points_text, pretty_unit_prefixed, put, tick_label, Series, DASHES, LEFT, PALETTE,
    PLOT_HEIGHT, TOP,
};
use std::fmt::Write as _;

/// A locus chart: every series' y against its x on equal axes.
#[derive(Debug, Clone, Default)]
pub struct LocusChart {
    pub title: String,
    /// The axes' titles (quantity names; the unit with its prefix is appended).
    pub x_label: String,
    pub y_label: String,
    /// SI unit of both axes.
    pub unit: String,
    /// Each series' `x` and `y` are the locus's (already thinned: [`Locus`](crate::thinning::Locus)); `source` names
    /// its y column (`file:column`).
    pub series: Vec<Series>,
    /// Per series, the column of its x (in the file of its `source`).
    pub x_columns: Vec<String>,
    /// The vector drawn in the crank's frame, turning with it (`data-frame="crank"` on each
    /// series): its x and y columns turned by −(θ − 90°), θ the row's crank angle, so that
    /// the crank points along +y as at top dead centre (`bearing_polar.rs`).
    pub crank_frame: bool,
}

/// The locus chart as an SVG document: a square plot, both axes over the same range
/// symmetric about 0 (lengths and angles true, the origin at the centre), the axes through the
/// origin, each series a polyline from its first row (marked with a dot) to its last. The plot
/// group and series carry the line chart's data attributes (`svg.rs`; `data-source` names the
/// y column), and each series its x column in `data-x-column`.
pub fn locus_chart(chart: &LocusChart) -> String {
    let reach = chart
        .series
        .iter()
        .flat_map(|s| s.x.iter().chain(&s.y))
        .filter(|v| v.is_finite())
        .fold(0.0_f64, |m, v| m.max(v.abs()));
    let (lo, hi, step) = nice_range(-reach, reach, 6.0);
    let square = Square {
        lo,
        hi,
        side: PLOT_HEIGHT,
    };
    let side = square.side;
    let (scale, pre) = crate::svg::prefix(lo.abs().max(hi.abs()), &chart.unit);
    let labels: Vec<String> = chart.series.iter().map(|s| s.label.clone()).collect();
    let legend_top = TOP + side + 50.0;
    let (legend, legend_h) = legend_layout(&labels, legend_top);
    let height = legend_top + legend_h + 6.0;
    let mut o = String::with_capacity(16 * 1024);
    open_svg(&mut o, height);
    chart_heading(&mut o, &chart.title, LEFT);
    open_plot(&mut o, [LEFT, TOP, side, side], (lo, hi), (lo, hi));
    square_grid(&mut o, &square, step, scale);
    for (k, s) in chart.series.iter().enumerate() {
        locus_series(&mut o, chart, k, s, &square);
    }
    o.push_str("</g>\n");
    locus_axis_titles(&mut o, chart, pre, side);
    legend_lines(&mut o, &chart.series, &legend);
    o.push_str("</g>\n</svg>\n");
    o
}

/// The square plot's range, the same on both axes, and its side in pixels.
struct Square {
    /// The axes' lower end, SI.
    lo: f64,
    /// The axes' upper end, SI.
    hi: f64,
    /// The side of the plot, px.
    side: f64,
}

impl Square {
    /// The horizontal pixel of `v` on the x axis.
    fn px(&self, v: f64) -> f64 {
        LEFT + (v - self.lo) / (self.hi - self.lo) * self.side
    }

    /// The vertical pixel of `v` on the y axis.
    fn py(&self, v: f64) -> f64 {
        TOP + (self.hi - v) / (self.hi - self.lo) * self.side
    }
}

/// The plot's frame, its grid lines with their tick labels on both axes, and the axes through
/// the origin.
fn square_grid(o: &mut String, square: &Square, step: f64, scale: f64) {
    let (lo, hi, side) = (square.lo, square.hi, square.side);
    let _ = writeln!(
        o,
        "<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"none\" stroke=\"#444\"/>",
        c(LEFT),
        c(TOP),
        c(side),
        c(side)
    );
    let ticks = ((hi - lo) / step).round() as usize;
    for k in 0..=ticks {
        let v = lo + k as f64 * step;
        let label = tick_label(v / scale, step / scale);
        let (x, y) = (square.px(v), square.py(v));
        put!(o; "<line x1=\"", c(LEFT), "\" y1=\"", c(y), "\" x2=\"", c(LEFT + side),
            "\" y2=\"", c(y), "\" stroke=\"#ddd\"/><text x=\"", c(LEFT - 6.0), "\" y=\"",
            c(y + 4.0), "\" text-anchor=\"end\">", label.as_str(), "</text>\n");
        put!(o; "<line x1=\"", c(x), "\" y1=\"", c(TOP), "\" x2=\"", c(x), "\" y2=\"",
            c(TOP + side), "\" stroke=\"#ddd\"/><text x=\"", c(x), "\" y=\"",
            c(TOP + side + 16.0), "\" text-anchor=\"middle\">", label, "</text>\n");
    }
    let _ = writeln!(
        o,
        "<line class=\"zero\" x1=\"{}\" y1=\"{y}\" x2=\"{}\" y2=\"{y}\" stroke=\"#000\" stroke-width=\"1.2\"/><line class=\"zero\" x1=\"{x}\" y1=\"{}\" x2=\"{x}\" y2=\"{}\" stroke=\"#000\" stroke-width=\"1.2\"/>",
        c(LEFT),
        c(LEFT + side),
        c(TOP),
        c(TOP + side),
        y = c(square.py(0.0)),
        x = c(square.px(0.0))
    );
}

/// The `k`th series: its polyline over the finite points with its data attributes, and a dot
/// at its first finite point.
fn locus_series(o: &mut String, chart: &LocusChart, k: usize, s: &Series, square: &Square) {
    let colour = PALETTE[s.colour % PALETTE.len()];
    let finite = || {
        (s.x.iter().zip(&s.y))
            .filter(|(a, b)| a.is_finite() && b.is_finite())
            .map(|(a, b)| (*a, *b))
    };
    let n = finite().count();
    let points = points_text(finite().map(|(a, b)| (square.px(a), square.py(b))), n);
    let x_column = chart.x_columns.get(k).map_or("", String::as_str);
    let dash = DASHES[s.dash % DASHES.len()];
    let dash = if dash.is_empty() {
        String::new()
    } else {
        format!(" stroke-dasharray=\"{dash}\"")
    };
    let frame = if chart.crank_frame {
        " data-frame=\"crank\""
    } else {
        ""
    };
    let _ = writeln!(
        o,
        "<polyline class=\"series\" data-label=\"{}\" data-source=\"{}\" data-x-column=\"{}\"{frame} data-n=\"{n}\" fill=\"none\" stroke=\"{colour}\" stroke-width=\"1.6\"{dash} points=\"{points}\"/>",
        esc(&s.label),
        esc(&s.source),
        esc(x_column),
    );
    if let Some((a, b)) =
        s.x.iter()
            .zip(&s.y)
            .find(|(a, b)| a.is_finite() && b.is_finite())
    {
        let _ = writeln!(
            o,
            "<circle class=\"start\" cx=\"{}\" cy=\"{}\" r=\"3\" fill=\"{colour}\"/>",
            c(square.px(*a)),
            c(square.py(*b))
        );
    }
}

/// Both axes' titles, each with the unit and its prefix.
fn locus_axis_titles(o: &mut String, chart: &LocusChart, pre: &str, side: f64) {
    let unit = pretty_unit_prefixed(pre, &chart.unit);
    let title = |label: &str| {
        if unit.is_empty() {
            label.to_string()
        } else {
            format!("{label}, {unit}")
        }
    };
    let middle = (LEFT + side / 2.0, TOP + side / 2.0);
    let titles = (title(&chart.x_label), title(&chart.y_label));
    axis_titles(o, middle, TOP + side, (&titles.0, &titles.1));
}

#[cfg(test)]
mod tests {
    use crate::thinning::Locus;

    fn thin(x: &[f64], y: &[f64], budget: usize) -> (Vec<f64>, Vec<f64>) {
        let mut l = Locus::new(x.len(), budget);
        for (a, b) in x.iter().zip(y) {
            l.push(*a, *b);
            assert!(l.len() <= budget);
        }
        l.finish()
    }

    /// A locus keeps every point under its budget; over it, at most the budget, the ends, and
    /// the extremes of both coordinates, each a point of the path at its own row (x and y
    /// from the same row), in row order.
    #[test]
    fn a_locus_keeps_the_ends_and_the_extremes_of_both_coordinates() {
        for n in [3usize, 1000, 1001, 7201, 100_003] {
            let t: Vec<f64> = (0..n).map(|k| k as f64 * 1e-3).collect();
            let x: Vec<f64> = t.iter().map(|t| (t * 3.1).cos() * (1.0 + t)).collect();
            let y: Vec<f64> = t
                .iter()
                .map(|t| (t * 3.1).sin() + 0.3 * (t * 11.0).sin())
                .collect();
            let (tx, ty) = thin(&x, &y, 1000);
            assert!(tx.len() <= 1000);
            if n <= 1000 {
                assert_eq!((tx.clone(), ty.clone()), (x.clone(), y.clone()));
            } else {
                assert!(tx.len() >= 500, "{n}: {}", tx.len());
            }
            assert_eq!((tx[0], ty[0]), (x[0], y[0]));
            assert_eq!((tx[tx.len() - 1], ty[ty.len() - 1]), (x[n - 1], y[n - 1]));
            let max = |v: &[f64]| v.iter().cloned().fold(f64::MIN, f64::max);
            let min = |v: &[f64]| v.iter().cloned().fold(f64::MAX, f64::min);
            assert_eq!((max(&tx), min(&tx)), (max(&x), min(&x)), "{n}: x extremes");
            assert_eq!((max(&ty), min(&ty)), (max(&y), min(&y)), "{n}: y extremes");
            // Each kept point is a row of the path, and the rows are in order.
            let mut from = 0;
            for (a, b) in tx.iter().zip(&ty) {
                let k = (from..n)
                    .find(|&k| x[k] == *a && y[k] == *b)
                    .expect("a row");
                from = k + 1;
            }
        }
    }
}
