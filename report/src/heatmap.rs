//! Heat maps: a grid of values coloured by a scale (viridis, or blue-white-red symmetric about
//! 0 for differences), a colour legend, and optionally the contour of 0 (marching squares), so
//! that a reader sees where one mechanism overtakes the other over two swept fields. Cells are
//! `<rect class="cell">` with `data-i`, `data-j`, `data-value`; the legend is
//! `<g class="legend">` with `data-min`/`data-max`; the contour `<path class="contour">`.

use crate::svg::{
    attr_num, axis_titles, c, chart_heading, esc, nice_range, open_svg, text_width, tick_label,
    PLOT_HEIGHT, TOP, WIDTH,
};
use std::fmt::Write as _;

/// A grid of values coloured by a scale.
#[derive(Debug, Clone, Default)]
pub struct HeatMap {
    pub title: String,
    pub x_label: String,
    pub y_label: String,
    /// Column labels (x, left to right).
    pub x_labels: Vec<String>,
    /// Row labels (y, bottom to top).
    pub y_labels: Vec<String>,
    /// `values[j][i]`: row j (y), column i (x); NaN for a missing point.
    pub values: Vec<Vec<f64>>,
    /// Legend title (quantity and unit).
    pub value_label: String,
    /// Blue-white-red scale symmetric about 0 (differences), else viridis.
    pub diverging: bool,
    /// Draws the contour where the value is 0.
    pub zero_contour: bool,
}

/// Viridis at `t` in [0, 1] (9 control points, linear in between).
fn viridis(t: f64) -> [f64; 3] {
    const P: [[f64; 3]; 9] = [
        [68.0, 1.0, 84.0],
        [71.0, 44.0, 122.0],
        [59.0, 81.0, 139.0],
        [44.0, 113.0, 142.0],
        [33.0, 144.0, 141.0],
        [39.0, 173.0, 129.0],
        [92.0, 200.0, 99.0],
        [170.0, 220.0, 50.0],
        [253.0, 231.0, 37.0],
    ];
    interpolate(&P, t)
}

/// Blue (0) - white (0.5) - red (1).
fn diverging(t: f64) -> [f64; 3] {
    const P: [[f64; 3]; 5] = [
        [33.0, 102.0, 172.0],
        [146.0, 197.0, 222.0],
        [247.0, 247.0, 247.0],
        [244.0, 165.0, 130.0],
        [178.0, 24.0, 43.0],
    ];
    interpolate(&P, t)
}

fn interpolate(p: &[[f64; 3]], t: f64) -> [f64; 3] {
    let t = if t.is_finite() {
        t.clamp(0.0, 1.0)
    } else {
        0.0
    };
    let s = t * (p.len() - 1) as f64;
    let k = (s.floor() as usize).min(p.len() - 2);
    let f = s - k as f64;
    [0, 1, 2].map(|i| p[k][i] + f * (p[k + 1][i] - p[k][i]))
}

fn hex(rgb: [f64; 3]) -> String {
    format!(
        "#{:02x}{:02x}{:02x}",
        rgb[0].round() as u8,
        rgb[1].round() as u8,
        rgb[2].round() as u8
    )
}

/// The colour scale of a heat map: (low end, high end) of the legend.
pub fn colour_range(values: &[Vec<f64>], diverging: bool) -> (f64, f64) {
    let finite = values.iter().flatten().filter(|v| v.is_finite());
    let (lo, hi) = finite.fold((f64::MAX, f64::MIN), |(a, b), v| (a.min(*v), b.max(*v)));
    if lo > hi {
        return (0.0, 1.0);
    }
    if diverging {
        let m = lo.abs().max(hi.abs());
        let m = if m > 0.0 { m } else { 1.0 };
        (-m, m)
    } else if hi > lo {
        (lo, hi)
    } else {
        let pad = if lo == 0.0 { 1.0 } else { 0.05 * lo.abs() };
        (lo - pad, hi + pad)
    }
}

/// The colour of `v` on the scale `range`.
pub fn colour(v: f64, range: (f64, f64), diverging_scale: bool) -> String {
    if !v.is_finite() {
        return "#cccccc".into();
    }
    let t = (v - range.0) / (range.1 - range.0);
    hex(if diverging_scale {
        diverging(t)
    } else {
        viridis(t)
    })
}

/// Segments of the contour `values = 0` by marching squares on the cell centres, in cell
/// coordinates (column i at x = i, row j at y = j).
pub fn zero_contour(values: &[Vec<f64>]) -> Vec<[(f64, f64); 2]> {
    let mut segments = Vec::new();
    let ny = values.len();
    for j in 0..ny.saturating_sub(1) {
        let nx = values[j].len().min(values[j + 1].len());
        for i in 0..nx.saturating_sub(1) {
            // Corners counter-clockwise: (i,j), (i+1,j), (i+1,j+1), (i,j+1).
            let corners = [
                (i as f64, j as f64, values[j][i]),
                (i as f64 + 1.0, j as f64, values[j][i + 1]),
                (i as f64 + 1.0, j as f64 + 1.0, values[j + 1][i + 1]),
                (i as f64, j as f64 + 1.0, values[j + 1][i]),
            ];
            if corners.iter().any(|p| !p.2.is_finite()) {
                continue;
            }
            let mut crossings = Vec::new();
            for e in 0..4 {
                let (a, b) = (corners[e], corners[(e + 1) % 4]);
                if (a.2 < 0.0) != (b.2 < 0.0) {
                    let f = a.2 / (a.2 - b.2);
                    crossings.push((a.0 + f * (b.0 - a.0), a.1 + f * (b.1 - a.1)));
                }
            }
            for pair in crossings.chunks_exact(2) {
                segments.push([pair[0], pair[1]]);
            }
        }
    }
    segments
}

/// The heat map as an SVG document.
pub fn heat_map(map: &HeatMap) -> String {
    let nx = map.x_labels.len().max(1);
    let ny = map.y_labels.len().max(1);
    let left = 110.0;
    let plot_w = WIDTH - left - 150.0;
    let plot_h = PLOT_HEIGHT;
    let (cw, ch) = (plot_w / nx as f64, plot_h / ny as f64);
    let grid = Grid {
        left,
        plot_w,
        plot_h,
        cw,
        ch,
    };
    let range = colour_range(&map.values, map.diverging);
    let height = TOP + plot_h + 56.0;
    let mut o = String::with_capacity(16 * 1024);
    open_svg(&mut o, height);
    chart_heading(&mut o, &map.title, left);
    let _ = writeln!(
        o,
        "<g class=\"heatmap\" data-area=\"{} {} {} {}\" data-nx=\"{nx}\" data-ny=\"{ny}\">",
        c(left),
        c(TOP),
        c(plot_w),
        c(plot_h)
    );
    cells(&mut o, map, &grid, range);
    if map.zero_contour {
        contour_path(&mut o, map, &grid);
    }
    frame_and_ticks(&mut o, map, &grid, ny);
    o.push_str("</g>\n");
    let middle = (left + plot_w / 2.0, TOP + plot_h / 2.0);
    axis_titles(&mut o, middle, TOP + plot_h, (&map.x_label, &map.y_label));
    colour_legend(&mut o, map, range, left + plot_w + 24.0, plot_h);
    o.push_str("</svg>\n");
    o
}

/// Where a heat map's plot and its cells are, px.
struct Grid {
    /// The plot's left edge.
    left: f64,
    /// The plot's width.
    plot_w: f64,
    /// The plot's height.
    plot_h: f64,
    /// A cell's width.
    cw: f64,
    /// A cell's height.
    ch: f64,
}

impl Grid {
    /// The horizontal centre of column `i`.
    fn cx(&self, i: f64) -> f64 {
        self.left + (i + 0.5) * self.cw
    }

    /// The vertical centre of row `j` (row 0 at the bottom).
    fn cy(&self, j: f64) -> f64 {
        TOP + self.plot_h - (j + 0.5) * self.ch
    }
}

/// A rectangle per cell, coloured by its value over `range`, with its indices and value.
fn cells(o: &mut String, map: &HeatMap, grid: &Grid, range: (f64, f64)) {
    for (j, row) in map.values.iter().enumerate() {
        for (i, v) in row.iter().enumerate() {
            let _ = writeln!(
                o,
                "<rect class=\"cell\" data-i=\"{i}\" data-j=\"{j}\" data-value=\"{}\" x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"{}\"/>",
                attr_num(*v),
                c(grid.left + i as f64 * grid.cw),
                c(TOP + grid.plot_h - (j + 1) as f64 * grid.ch),
                c(grid.cw + 0.4),
                c(grid.ch + 0.4),
                colour(*v, range, map.diverging)
            );
        }
    }
}

/// The 0 contour through the cells' centres as one path, none where the values never cross 0.
fn contour_path(o: &mut String, map: &HeatMap, grid: &Grid) {
    let segments = zero_contour(&map.values);
    if !segments.is_empty() {
        let mut d = String::new();
        for [a, b] in &segments {
            let _ = write!(
                d,
                "M{} {}L{} {}",
                c(grid.cx(a.0)),
                c(grid.cy(a.1)),
                c(grid.cx(b.0)),
                c(grid.cy(b.1))
            );
        }
        let _ = writeln!(
            o,
            "<path class=\"contour\" data-level=\"0\" data-segments=\"{}\" d=\"{d}\" fill=\"none\" stroke=\"#000\" stroke-width=\"2.2\"/>",
            segments.len()
        );
    }
}

/// The plot's frame and the levels' labels: on x as many as fit side by side, on y at most 12.
fn frame_and_ticks(o: &mut String, map: &HeatMap, grid: &Grid, ny: usize) {
    let _ = writeln!(
        o,
        "<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"none\" stroke=\"#444\"/>",
        c(grid.left),
        c(TOP),
        c(grid.plot_w),
        c(grid.plot_h)
    );
    let widest = map
        .x_labels
        .iter()
        .map(|l| text_width(l, 12.0))
        .fold(0.0, f64::max);
    let every_x = ((widest + 8.0) / grid.cw).ceil().max(1.0) as usize;
    for (i, l) in map.x_labels.iter().enumerate().step_by(every_x) {
        let _ = writeln!(
            o,
            "<text x=\"{}\" y=\"{}\" text-anchor=\"middle\">{}</text>",
            c(grid.cx(i as f64)),
            c(TOP + grid.plot_h + 16.0),
            esc(l)
        );
    }
    let every_y = ny.div_ceil(12).max(1);
    for (j, l) in map.y_labels.iter().enumerate().step_by(every_y) {
        let _ = writeln!(
            o,
            "<text x=\"{}\" y=\"{}\" text-anchor=\"end\">{}</text>",
            c(grid.left - 6.0),
            c(grid.cy(j as f64) + 4.0),
            esc(l)
        );
    }
}

/// Writes the colour legend of `map` (its colours over `range`) at x = `lx`, beside a plot
/// `plot_h` high: 64 bands from the low end (bottom) to the high end (top), ticks and the
/// value's label.
fn colour_legend(o: &mut String, map: &HeatMap, range: (f64, f64), lx: f64, plot_h: f64) {
    let bands = 64;
    let _ = writeln!(
        o,
        "<g class=\"legend\" data-min=\"{}\" data-max=\"{}\">",
        attr_num(range.0),
        attr_num(range.1)
    );
    for b in 0..bands {
        let v = range.0 + (b as f64 + 0.5) / bands as f64 * (range.1 - range.0);
        let _ = writeln!(
            o,
            "<rect class=\"band\" x=\"{}\" y=\"{}\" width=\"18\" height=\"{}\" fill=\"{}\"/>",
            c(lx),
            c(TOP + plot_h - (b + 1) as f64 * plot_h / bands as f64),
            c(plot_h / bands as f64 + 0.4),
            colour(v, range, map.diverging)
        );
    }
    let (lo, hi, step) = nice_range(range.0, range.1, 5.0);
    let ticks = ((hi - lo) / step).round() as usize;
    for k in 0..=ticks {
        let v = lo + k as f64 * step;
        if v < range.0 - 1e-9 * step || v > range.1 + 1e-9 * step {
            continue;
        }
        let y = TOP + plot_h - (v - range.0) / (range.1 - range.0) * plot_h;
        let _ = writeln!(
            o,
            "<line x1=\"{}\" y1=\"{y}\" x2=\"{}\" y2=\"{y}\" stroke=\"#000\"/><text x=\"{}\" y=\"{}\">{}</text>",
            c(lx + 18.0),
            c(lx + 23.0),
            c(lx + 26.0),
            c(y + 4.0),
            tick_label(v, step),
            y = c(y)
        );
    }
    let _ = writeln!(
        o,
        "<text x=\"{}\" y=\"{}\" font-size=\"11\">{}</text>",
        c(lx - 10.0),
        c(TOP - 8.0),
        esc(&map.value_label)
    );
    o.push_str("</g>\n");
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn contour_crosses_where_the_sign_changes() {
        let values = vec![vec![-1.0, 1.0], vec![-1.0, 1.0]];
        let s = zero_contour(&values);
        assert_eq!(s.len(), 1);
        for p in s[0] {
            assert!((p.0 - 0.5).abs() < 1e-12);
        }
    }
}
