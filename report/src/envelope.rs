//! A series thinned while it is being made: a case's charts come from its run, step by step,
//! in memory that does not grow with the number of steps.
//!
//! [`Envelope`] keeps what the SVG writer's [`decimate`](crate::svg::decimate) would keep of
//! the whole series, computed on the fly: all the points when the run has at most the budget,
//! else the first point, per bucket of consecutive rows the points of smallest and largest
//! value in their order, and the last point. The buckets are decimate's (`buckets = (budget −
//! 2) / 2`, bucket `b` the rows `b·n/buckets .. (b+1)·n/buckets` of the `n` announced), so a
//! series without gaps thins to the very points the writer would have drawn from the whole
//! CSV: the charts are byte-identical, and the writer keeps them as they are (the envelope
//! never holds more than the budget). A finer envelope (more bins than the writer draws)
//! would be thinned again by the writer, so it would buy nothing on the page.
//!
//! [`ChartRecorder`] applies one envelope per series the charts draw to a crank train's per-step
//! rows (the rows of the runner's `per_step` module, whose header names their columns). Of a run of
//! more than [`MAX_CHART_ROWS`](crate::rows::MAX_CHART_ROWS) rows it takes every k-th row (and the
//! last), the fewest k that keeps it within that many: at least 32 rows per bucket of the envelope
//! still, so a peak of a smooth curve is drawn within a small fraction of a pixel (the summary has
//! the exact peaks), and a summary-only run of millions of steps does not pay the charts' per-row
//! cost at every step. Reading the rows back from a CSV takes the same rows.

use crate::chart_columns::{loci, traces, Frame};
use crate::rows::{row_count, ChartRows};
pub use crate::thinning::Envelope;
use crate::thinning::Locus;
use std::collections::BTreeMap;

/// What a chart draws of one crank train: x (the crank angle) and y, thinned.
#[derive(Debug, Clone, Default)]
pub struct Trace {
    pub x: Vec<f64>,
    pub y: Vec<f64>,
}

/// The chart data of one crank train, from its run or its CSV.
#[derive(Debug, Clone, Default)]
pub struct ChartData {
    /// The crank train's per-step column names (the CSV header), which say which charts apply.
    pub header: Vec<String>,
    /// Where the rows are, for each series' `data-source` (`<label>.csv`, `<label>.npy`, or the
    /// label alone when the run wrote no per-step file).
    pub file: String,
    /// Per series: a column's name, or the names of the columns summed joined by `+`; a locus
    /// (`locus:x:y`, its trace's x and y the two columns at the same rows).
    pub traces: BTreeMap<String, Trace>,
}

/// Thins, row by row, the series the charts draw from a crank train's per-step rows.
#[derive(Debug, Clone)]
pub struct ChartRecorder {
    header: Vec<String>,
    file: String,
    /// The rows taken, and the next row's index.
    pick: ChartRows,
    next: usize,
    /// The crank angle's index in a row.
    x: Option<usize>,
    /// Per series: its key, the row indices it sums (one for a plain column), its envelope.
    series: Vec<(String, Vec<usize>, Envelope)>,
    /// Per locus (`locus.rs`): its key, the row indices of its x and y, its frame, its
    /// thinning.
    loci: Vec<(String, [usize; 2], Frame, Locus)>,
    /// The columns read, once [packed](ChartRecorder::pack): the indices above are then into
    /// rows of these columns alone.
    packed: Option<Vec<usize>>,
}

impl ChartRecorder {
    /// A recorder for rows named by `header` of a mechanism with the joints `joints`, `rows`
    /// rows in all, each series thinned to `budget` points; `file` names the rows' file.
    pub fn new(
        header: &[String],
        joints: &[String],
        rows: usize,
        budget: usize,
        file: String,
    ) -> Self {
        let index = |c: &str| header.iter().position(|h| h == c);
        let pick = ChartRows::new(rows);
        let taken = row_count(rows.saturating_sub(1), pick.stride);
        let series = traces(header, joints)
            .into_iter()
            .map(|(key, columns)| {
                let at = columns.iter().filter_map(|c| index(c)).collect();
                (key, at, Envelope::new(taken, budget))
            })
            .collect();
        let loci = loci(header)
            .into_iter()
            .filter_map(|(key, x, y, frame)| {
                Some((
                    key,
                    [index(&x)?, index(&y)?],
                    frame,
                    Locus::new(taken, budget),
                ))
            })
            .collect();
        Self {
            header: header.to_vec(),
            file,
            pick,
            next: 0,
            x: index("crank_angle_deg"),
            series,
            loci,
            packed: None,
        }
    }

    /// Whether a series reads the row's column `k` (the others may be left unfilled).
    pub fn reads(&self, k: usize) -> bool {
        if let Some(read) = &self.packed {
            return read.binary_search(&k).is_ok();
        }
        self.x == Some(k)
            || self.series.iter().any(|(_, at, _)| at.contains(&k))
            || self.loci.iter().any(|(_, at, _, _)| at.contains(&k))
    }

    /// The columns the series read ([`ChartRecorder::reads`]), in the header's order; from
    /// now on [`ChartRecorder::add`] takes rows of these columns alone, in this order (a sink
    /// that keeps only what the charts read copies no whole row for them).
    pub fn pack(&mut self) -> Vec<usize> {
        if let Some(read) = &self.packed {
            return read.clone();
        }
        let read: Vec<usize> = (0..self.header.len()).filter(|&k| self.reads(k)).collect();
        let at = |k: &mut usize| *k = read.binary_search(k).expect("a column a series reads");
        if let Some(x) = &mut self.x {
            at(x);
        }
        for (_, columns, _) in &mut self.series {
            columns.iter_mut().for_each(at);
        }
        for (_, columns, _, _) in &mut self.loci {
            columns.iter_mut().for_each(at);
        }
        self.packed = Some(read.clone());
        read
    }

    /// Whether the next row is one the series take (every `stride`-th and the last).
    fn takes_next(&self) -> bool {
        self.pick.takes(self.next)
    }

    /// The rows the series take.
    pub fn rows(&self) -> ChartRows {
        self.pick
    }

    /// Takes one row (in the header's order; not [packed](ChartRecorder::pack)), if it is one
    /// the series take.
    pub fn record(&mut self, row: &[f64]) {
        debug_assert!(self.packed.is_none(), "a packed recorder takes packed rows");
        let taken = self.takes_next();
        self.next += 1;
        if taken {
            self.add(row);
        }
    }

    /// Adds a row the series take ([`ChartRows::takes`]) to them, the rows in their order: a
    /// whole row (in the header's order), or of the columns [`ChartRecorder::pack`] said.
    pub fn add(&mut self, row: &[f64]) {
        let Some(x) = self.x.map(|k| row[k]) else {
            return;
        };
        for (_, at, envelope) in &mut self.series {
            let y = match at.as_slice() {
                [k] => row[*k],
                // A sum (the total power loss): of the finite parts, as the charts always did.
                parts => parts
                    .iter()
                    .map(|k| row[*k])
                    .filter(|v| v.is_finite())
                    .sum(),
            };
            envelope.push(x, y);
        }
        for (_, [a, b], frame, locus) in &mut self.loci {
            let (a, b) = (row[*a], row[*b]);
            match frame {
                Frame::Machine => locus.push(a, b),
                Frame::Crank => {
                    let (u, v) = crank_frame(x, a, b);
                    locus.push(u, v);
                }
            }
        }
    }

    /// The thinned series.
    pub fn finish(self) -> ChartData {
        let traces = self
            .series
            .into_iter()
            .map(|(key, _, envelope)| {
                let (x, y) = envelope.finish();
                (key, Trace { x, y })
            })
            .chain(self.loci.into_iter().map(|(key, _, _, locus)| {
                let (x, y) = locus.finish();
                (key, Trace { x, y })
            }))
            .collect();
        ChartData {
            header: self.header,
            file: self.file,
            traces,
        }
    }
}

/// The vector (`x`, `y`) of the machine's frame in the crank's at the crank angle `theta_deg`
/// (degrees from +x): turned by −(θ − 90°), the plane rotation that takes the crank's direction
/// (cos θ, sin θ) to +y, so that the crank points up as at top dead centre and the frames
/// agree there. Its second component is then the load along the crank (positive outwards), its
/// first the load across it (positive on the side the crank has left, −x being the direction
/// of rotation for a crank turning counter-clockwise, the +θ direction).
pub(crate) fn crank_frame(theta_deg: f64, x: f64, y: f64) -> (f64, f64) {
    let (s, c) = (theta_deg - 90.0).to_radians().sin_cos();
    (x * c + y * s, -x * s + y * c)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::rows::MAX_CHART_ROWS;
    use crate::svg::decimate;

    fn thin(x: &[f64], y: &[f64], budget: usize) -> (Vec<f64>, Vec<f64>) {
        let mut e = Envelope::new(x.len(), budget);
        for (a, b) in x.iter().zip(y) {
            e.push(*a, *b);
            assert!(e.len() <= budget);
        }
        e.finish()
    }

    /// The crank's frame: a load along the crank points along +y at every crank angle, one in
    /// the direction of rotation (+θ) along −x, and the frames agree at top dead centre.
    #[test]
    fn the_crank_frame_turns_the_crank_onto_plus_y() {
        for theta in [0.0_f64, 37.0, 90.0, 180.0, 271.5, 450.0, 719.0] {
            let (s, c) = theta.to_radians().sin_cos();
            let along = crank_frame(theta, 3.0 * c, 3.0 * s);
            assert!(
                (along.0).abs() < 1e-12 && (along.1 - 3.0).abs() < 1e-12,
                "{theta}"
            );
            let ahead = crank_frame(theta, -2.0 * s, 2.0 * c);
            assert!(
                (ahead.0 + 2.0).abs() < 1e-12 && ahead.1.abs() < 1e-12,
                "{theta}"
            );
        }
        assert_eq!(crank_frame(90.0, 1.5, -4.0), (1.5, -4.0));
    }

    #[test]
    fn the_envelope_keeps_the_extremes_and_the_ends() {
        for n in [2usize, 999, 1000, 1001, 7201, 100_003] {
            let x: Vec<f64> = (0..n).map(|k| k as f64 * 0.05).collect();
            let mut y: Vec<f64> = x
                .iter()
                .map(|t| (t * 0.37).sin() + 0.1 * (t * 7.1).cos())
                .collect();
            y[n / 3] = 5.0;
            y[n / 2] = -7.0;
            let (tx, ty) = thin(&x, &y, 1000);
            assert!(tx.len() <= 1000);
            assert_eq!((tx[0], ty[0]), (x[0], y[0]), "{n}: first");
            assert_eq!(
                (*tx.last().unwrap(), *ty.last().unwrap()),
                (x[n - 1], y[n - 1]),
                "{n}: last"
            );
            assert!(ty.contains(&5.0) && ty.contains(&-7.0), "{n}: the extremes");
            assert!(tx.windows(2).all(|w| w[0] < w[1]), "{n}: in order");
            if n <= 1000 {
                assert_eq!((tx, ty), (x, y), "every step under the budget");
            }
        }
    }

    /// The envelope is what the SVG writer keeps of the whole series: the charts made from the
    /// run are those made from the CSV, point for point.
    #[test]
    fn the_envelope_is_the_writers_decimation() {
        for (n, budget) in [
            (7201, 1000),
            (3601, 1000),
            (1001, 1000),
            (50_000, 64),
            (10, 4),
        ] {
            let x: Vec<f64> = (0..n).map(|k| k as f64).collect();
            let y: Vec<f64> = x
                .iter()
                .map(|t| ((t * 0.013).sin() * 1e3).round() + (t * 0.7).cos())
                .collect();
            assert_eq!(
                thin(&x, &y, budget),
                decimate(&x, &y, budget),
                "{n} {budget}"
            );
            // Flat stretches (ties: the first of equal values, as decimate).
            let flat: Vec<f64> = x.iter().map(|t| (t / 500.0).floor()).collect();
            assert_eq!(thin(&x, &flat, budget), decimate(&x, &flat, budget));
        }
    }

    /// Memory: a long run holds at most the budget, whatever its length.
    #[test]
    fn a_long_run_keeps_at_most_the_budget() {
        let n = 3_000_000;
        let mut e = Envelope::new(n, 1000);
        let mut most = 0;
        for k in 0..n {
            let t = k as f64 * 1e-4;
            e.push(t, t.sin() * (1.0 + (t * 13.0).cos()));
            most = most.max(e.len());
        }
        assert!(most <= 1000, "{most}");
        let (x, _) = e.finish();
        assert!((900..=1000).contains(&x.len()), "{}", x.len());
        // Gaps are skipped; more rows than announced stay in the last bucket.
        let mut e = Envelope::new(10_000, 100);
        for k in 0..20_000 {
            e.push(
                k as f64,
                if k % 7 == 3 {
                    f64::NAN
                } else {
                    (k % 100) as f64
                },
            );
        }
        let (x, y) = e.finish();
        assert!(x.len() <= 100 && y.iter().all(|v| v.is_finite()));
        assert_eq!(*x.last().unwrap(), 19_999.0);
    }

    /// A packed recorder fed only the columns it reads draws what one fed whole rows draws,
    /// point for point: plain columns, a sum with gaps, loci in the machine's and the crank's
    /// frame, among columns no chart reads.
    #[test]
    fn a_packed_recorder_draws_what_whole_rows_draw() {
        let header: Vec<String> = [
            "crank_angle_deg",
            "time_s",
            "crank_speed_rad_s",
            "rod_angle_deg",
            "piston_position_m",
            "inertial_torque_nm",
            "power_loss_rings_w",
            "rod_cg_x_m",
            "power_loss_skirt_w",
            "main_bearing_1_force_x_n",
            "main_bearing_1_force_y_n",
        ]
        .map(String::from)
        .to_vec();
        let rows = 20_000;
        let mut whole = ChartRecorder::new(&header, &[], rows, 100, "c".into());
        let mut packed = whole.clone();
        let read = packed.pack();
        assert!(
            !read.contains(&3) && !read.contains(&7),
            "unread columns: {read:?}"
        );
        assert!(read.iter().all(|&k| whole.reads(k) && packed.reads(k)));
        for r in 0..rows {
            let t = r as f64 * 1e-3;
            let row: Vec<f64> = (0..header.len())
                .map(|k| match (k, r % 97) {
                    (0, _) => 90.0 + r as f64 * 0.036,
                    (6, 5) => f64::NAN,
                    _ => (t * (k as f64 + 0.5)).sin() * (k as f64 + 1.0),
                })
                .collect();
            whole.record(&row);
            if packed.rows().takes(r) {
                let kept: Vec<f64> = read.iter().map(|&k| row[k]).collect();
                packed.add(&kept);
            }
        }
        let (whole, packed) = (whole.finish(), packed.finish());
        assert!(whole.traces.keys().any(|k| k.starts_with("sum:")));
        assert!(whole.traces.keys().any(|k| k.starts_with("crank:")));
        assert_eq!(whole.traces.len(), packed.traces.len());
        for (key, w) in &whole.traces {
            let p = &packed.traces[key];
            assert!(!w.x.is_empty(), "{key}");
            assert_eq!((&w.x, &w.y), (&p.x, &p.y), "{key}");
        }
    }

    #[test]
    fn a_recorder_takes_every_row_up_to_its_limit_then_every_kth_and_the_last() {
        let header: Vec<String> = ["crank_angle_deg", "total_torque_nm"]
            .map(String::from)
            .to_vec();
        for (rows, stride) in [
            (7201, 1),
            (MAX_CHART_ROWS, 1),
            (MAX_CHART_ROWS + 1, 2),
            (720_001, 46),
        ] {
            let mut r = ChartRecorder::new(&header, &[], rows, 1000, "c.csv".into());
            let mut taken = Vec::new();
            for k in 0..rows {
                if r.takes_next() {
                    taken.push(k);
                }
                r.record(&[k as f64, (k as f64 * 1e-3).sin()]);
            }
            assert_eq!(r.pick.stride, stride, "{rows} rows");
            assert!(
                taken.len() <= MAX_CHART_ROWS + 1,
                "{rows} rows: {}",
                taken.len()
            );
            assert_eq!(taken.len(), row_count(rows - 1, stride));
            assert_eq!(taken.last(), Some(&(rows - 1)), "the last row is taken");
            assert!(taken.iter().all(|k| k % stride == 0 || *k == rows - 1));
            let data = r.finish();
            let t = &data.traces["total_torque_nm"];
            assert_eq!(*t.x.first().unwrap(), 0.0);
            assert_eq!(*t.x.last().unwrap(), (rows - 1) as f64);
        }
    }
}
