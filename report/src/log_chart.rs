//! A line chart on logarithmic axes (both): the indicator diagram's log-log form, where a
//! polytropic change p·Vⁿ = const is a straight line of slope −n (log p = log C − n·log V;
//! the indicator diagram of engine texts in its log form). Ticks at 1, 2 and 5 of every decade the axes span (only the decades past three
//! of them). The plot group carries the line chart's attributes (`svg.rs`), its ranges the
//! values at the axes' ends, and a `<desc class="log-axes">` saying both are logarithmic: a
//! value v is at left + (log₁₀ v − log₁₀ min)/(log₁₀ max − log₁₀ min)·width.

use crate::svg::{
    axis_titles, c, chart_heading, legend_layout, legend_lines, open_plot, open_svg, plot_factors,
    pretty_unit, series_lines, LineChart, LEFT, PLOT_HEIGHT, RIGHT, TOP, WIDTH,
};
use std::fmt::Write as _;

/// The ends of a log axis over the positive values `lo..hi`: the nearest 1-2-5 values
/// outside, as log₁₀ (`lo` = `hi`: a factor 2 either side).
fn log_range(lo: f64, hi: f64) -> (f64, f64) {
    let down = |v: f64| {
        let d = v.log10().floor();
        let m = v / 10f64.powf(d);
        let f = [5.0, 2.0, 1.0]
            .into_iter()
            .find(|f| *f <= m * (1.0 + 1e-12));
        d + f.unwrap_or(1.0).log10()
    };
    let up = |v: f64| {
        let d = v.log10().floor();
        let m = v / 10f64.powf(d);
        let f = [1.0, 2.0, 5.0, 10.0]
            .into_iter()
            .find(|f| *f >= m * (1.0 - 1e-12));
        d + f.unwrap_or(10.0).log10()
    };
    if !(lo > 0.0 && hi.is_finite()) {
        return (0.0, 1.0);
    }
    let (a, b) = (down(lo), up(hi));
    if b - a < 1e-9 {
        (a - 0.301, b + 0.301)
    } else {
        (a, b)
    }
}

/// The ticks of a log axis from `lo` to `hi` (log₁₀): 1, 2, 5 of each decade, or the decades
/// alone over more than three.
fn log_ticks(lo: f64, hi: f64) -> Vec<f64> {
    let factors: &[f64] = if hi - lo > 3.0 {
        &[1.0]
    } else {
        &[1.0, 2.0, 5.0]
    };
    let mut ticks = Vec::new();
    let mut d = lo.floor() as i32;
    while f64::from(d) <= hi + 1e-9 {
        for f in factors {
            let v = f.log10() + f64::from(d);
            if v >= lo - 1e-9 && v <= hi + 1e-9 {
                ticks.push(v);
            }
        }
        d += 1;
    }
    ticks
}

/// A tick's label: the value 10^`log` with as many decimals as it needs (0.02, 5, 200).
fn log_label(log: f64) -> String {
    let v = 10f64.powf(log);
    let decimals = (-(log + 1e-9).floor()).clamp(0.0, 12.0) as usize;
    format!("{v:.decimals$}")
}

/// The chart of `chart` on log-log axes, the series in their own units
/// (`factors`), each point with a non-positive coordinate left out.
pub(crate) fn log_chart(chart: &LineChart) -> String {
    let logs: Vec<(Vec<f64>, Vec<f64>)> = chart
        .series
        .iter()
        .map(|s| {
            s.x.iter()
                .zip(&s.y)
                .filter(|(a, b)| **a > 0.0 && **b > 0.0 && a.is_finite() && b.is_finite())
                .map(|(a, b)| (a.log10(), b.log10()))
                .unzip()
        })
        .collect();
    let ext = |on_x: bool| {
        logs.iter()
            .flat_map(|(x, y)| if on_x { x.iter() } else { y.iter() })
            .fold((f64::MAX, f64::MIN), |(a, b), v| (a.min(*v), b.max(*v)))
    };
    let ((x0, x1), (y0, y1)) = (ext(true), ext(false));
    let (x_lo, x_hi) = log_range(10f64.powf(x0), 10f64.powf(x1));
    let (y_lo, y_hi) = log_range(10f64.powf(y0), 10f64.powf(y1));
    let plot_w = WIDTH - LEFT - RIGHT;
    let px = |v: f64| LEFT + (v - x_lo) / (x_hi - x_lo) * plot_w;
    let py = |v: f64| TOP + (y_hi - v) / (y_hi - y_lo) * PLOT_HEIGHT;
    let labels: Vec<String> = chart.series.iter().map(|s| s.label.clone()).collect();
    let legend_top = TOP + PLOT_HEIGHT + 50.0;
    let (legend, legend_h) = legend_layout(&labels, legend_top);
    let mut o = String::with_capacity(16 * 1024);
    open_svg(&mut o, legend_top + legend_h + 6.0);
    chart_heading(&mut o, &chart.title, LEFT);
    open_plot(
        &mut o,
        [LEFT, TOP, plot_w, PLOT_HEIGHT],
        (10f64.powf(x_lo), 10f64.powf(x_hi)),
        (10f64.powf(y_lo), 10f64.powf(y_hi)),
    );
    plot_factors(&mut o, chart.factors);
    o.push_str("<desc class=\"log-axes\">both axes logarithmic</desc>\n");
    let _ = writeln!(
        o,
        "<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"none\" stroke=\"#444\"/>",
        c(LEFT),
        c(TOP),
        c(plot_w),
        c(PLOT_HEIGHT)
    );
    for v in log_ticks(y_lo, y_hi) {
        let _ = writeln!(
            o,
            "<line x1=\"{}\" y1=\"{y}\" x2=\"{}\" y2=\"{y}\" stroke=\"#ddd\"/><text x=\"{}\" y=\"{}\" text-anchor=\"end\">{}</text>",
            c(LEFT),
            c(LEFT + plot_w),
            c(LEFT - 6.0),
            c(py(v) + 4.0),
            log_label(v),
            y = c(py(v))
        );
    }
    for v in log_ticks(x_lo, x_hi) {
        let _ = writeln!(
            o,
            "<line x1=\"{x}\" y1=\"{}\" x2=\"{x}\" y2=\"{}\" stroke=\"#ddd\"/><text x=\"{x}\" y=\"{}\" text-anchor=\"middle\">{}</text>",
            c(TOP),
            c(TOP + PLOT_HEIGHT),
            c(TOP + PLOT_HEIGHT + 16.0),
            log_label(v),
            x = c(px(v))
        );
    }
    series_lines(&mut o, &chart.series, &logs, px, py);
    o.push_str("</g>\n");
    let unit = pretty_unit(&chart.y_unit);
    let y_title = if unit.is_empty() {
        chart.y_label.clone()
    } else {
        format!("{}, {unit} (log scale)", chart.y_label)
    };
    let x_title = format!("{} (log scale)", chart.x_label);
    let middle = (LEFT + plot_w / 2.0, TOP + PLOT_HEIGHT / 2.0);
    axis_titles(&mut o, middle, TOP + PLOT_HEIGHT, (&x_title, &y_title));
    legend_lines(&mut o, &chart.series, &legend);
    o.push_str("</g>\n</svg>\n");
    o
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn log_axes_end_on_1_2_5_values_around_the_data() {
        let (lo, hi) = log_range(29.4, 660.0);
        assert!((10f64.powf(lo) - 20.0).abs() < 1e-9 && (10f64.powf(hi) - 1000.0).abs() < 1e-6);
        let (lo, hi) = log_range(1.0, 8.0);
        assert!((10f64.powf(lo) - 1.0).abs() < 1e-12 && (10f64.powf(hi) - 10.0).abs() < 1e-9);
        let labels: Vec<String> = log_ticks(lo, hi).into_iter().map(log_label).collect();
        assert_eq!(labels, ["1", "2", "5", "10"]);
        let labels: Vec<String> = log_ticks(-2.0, 0.0).into_iter().map(log_label).collect();
        assert_eq!(labels, ["0.01", "0.02", "0.05", "0.1", "0.2", "0.5", "1"]);
    }
}
