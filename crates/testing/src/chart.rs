//! An SVG chart of the reports read back (with roxmltree): its plot area and axis ranges, a
//! series' points, and the check that a series draws its data.

use std::path::Path;

/// A number attribute of an SVG element.
#[track_caller]
pub fn attr_f64(node: roxmltree::Node, name: &str) -> f64 {
    node.attribute(name)
        .unwrap_or_else(|| panic!("no {name}"))
        .parse()
        .unwrap()
}

/// The plot area and axis ranges of a line chart.
pub struct Axes {
    pub left: f64,
    pub top: f64,
    pub width: f64,
    pub height: f64,
    /// The x and y ranges drawn: (min, max).
    pub x: (f64, f64),
    pub y: (f64, f64),
}

/// A plot group's drawing area, `data-area="left top width height"` (SVG units).
#[track_caller]
pub fn data_area(g: roxmltree::Node) -> Vec<f64> {
    g.attribute("data-area")
        .unwrap()
        .split(' ')
        .map(|s| s.parse().unwrap())
        .collect()
}

impl Axes {
    /// The axes of the chart's plot group (`class="plot"`).
    #[track_caller]
    pub fn of(doc: &roxmltree::Document) -> Axes {
        let g = doc
            .descendants()
            .find(|n| n.attribute("class") == Some("plot"))
            .expect("a plot group");
        let area = data_area(g);
        Axes {
            left: area[0],
            top: area[1],
            width: area[2],
            height: area[3],
            x: (attr_f64(g, "data-x-min"), attr_f64(g, "data-x-max")),
            y: (attr_f64(g, "data-y-min"), attr_f64(g, "data-y-max")),
        }
    }

    /// The pixel column of `x`.
    pub fn px(&self, x: f64) -> f64 {
        self.left + (x - self.x.0) / (self.x.1 - self.x.0) * self.width
    }

    /// The pixel row of `y`.
    pub fn py(&self, y: f64) -> f64 {
        self.top + (self.y.1 - y) / (self.y.1 - self.y.0) * self.height
    }
}

/// The points of a series (`points="x,y x,y …"`), in pixels.
#[track_caller]
pub fn points(node: roxmltree::Node) -> Vec<(f64, f64)> {
    node.attribute("points")
        .unwrap()
        .split(' ')
        .map(|p| {
            let (a, b) = p.split_once(',').unwrap();
            (a.parse().unwrap(), b.parse().unwrap())
        })
        .collect()
}

/// The smallest and largest finite value.
pub fn min_max(v: &[f64]) -> (f64, f64) {
    v.iter()
        .filter(|x| x.is_finite())
        .fold((f64::MAX, f64::MIN), |(a, b), x| (a.min(*x), b.max(*x)))
}

/// Checks one series against its data: the point count, the axis covering the data without
/// being much wider, and the extremes drawn where they belong (peaks survive decimation). A
/// series of more than `max_points` finite points is drawn in between half and all of them.
#[track_caller]
pub fn check_series(
    file: &Path,
    axes: &Axes,
    node: roxmltree::Node,
    x: &[f64],
    y: &[f64],
    max_points: usize,
) {
    let label = format!("{}: {:?}", file.display(), node.attribute("data-source"));
    let pts = points(node);
    let n: usize = node.attribute("data-n").unwrap().parse().unwrap();
    assert_eq!(pts.len(), n, "{label}");
    let finite: Vec<(f64, f64)> = x
        .iter()
        .zip(y)
        .filter(|(a, b)| a.is_finite() && b.is_finite())
        .map(|(a, b)| (*a, *b))
        .collect();
    if finite.len() <= max_points {
        assert_eq!(n, finite.len(), "{label}");
    } else {
        assert!((max_points / 2..=max_points).contains(&n), "{label}: {n}");
    }
    let ys: Vec<f64> = finite.iter().map(|p| p.1).collect();
    let xs: Vec<f64> = finite.iter().map(|p| p.0).collect();
    let (lo, hi) = min_max(&ys);
    let (x_lo, x_hi) = min_max(&xs);
    let tol = 1e-9 * lo.abs().max(hi.abs()).max(1e-300);
    assert!(
        axes.y.0 <= lo + tol && axes.y.1 >= hi - tol,
        "{label}: {:?} vs {lo}..{hi}",
        axes.y
    );
    assert!(axes.x.0 <= x_lo && axes.x.1 >= x_hi, "{label}");
    // Every pixel inside the plot area; the extremes at their pixels (0.1 px rounding).
    for (a, b) in &pts {
        assert!(
            *a >= axes.left - 0.06 && *a <= axes.left + axes.width + 0.06,
            "{label}"
        );
        assert!(
            *b >= axes.top - 0.06 && *b <= axes.top + axes.height + 0.06,
            "{label}"
        );
    }
    let top = pts.iter().map(|p| p.1).fold(f64::MAX, f64::min);
    let bottom = pts.iter().map(|p| p.1).fold(f64::MIN, f64::max);
    assert!(
        (top - axes.py(hi)).abs() <= 0.06,
        "{label}: max at {top}, expected {}",
        axes.py(hi)
    );
    assert!((bottom - axes.py(lo)).abs() <= 0.06, "{label}: min");
    assert!(
        (pts[0].0 - axes.px(finite[0].0)).abs() <= 0.06,
        "{label}: first x"
    );
    let _ = (x_lo, x_hi);
}

/// The y range of a chart against the union of its series' data: covering and not more than
/// twice as wide (when the data span is not tiny).
#[track_caller]
pub fn check_axis_span(file: &Path, axes: &Axes, all: &[f64]) {
    let (lo, hi) = min_max(all);
    let span = hi - lo;
    if span > 1e-9 * lo.abs().max(hi.abs()) {
        assert!(
            axes.y.1 - axes.y.0 <= 2.0 * span + 1e-12,
            "{}: axis {:?} for data {lo}..{hi}",
            file.display(),
            axes.y
        );
    }
}
