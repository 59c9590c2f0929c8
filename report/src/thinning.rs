//! The running thinning of a path of points (row, x, y) that the charts draw, as it is made:
//! of a run of at most the budget's rows every point; else the first row, per bucket of
//! consecutive rows the rows holding the bucket's extremes (in row order, none twice), and the
//! last row. The buckets are the SVG writer's ([`decimate`](crate::svg::decimate)): bucket `b`
//! holds the rows `b·n/buckets .. (b+1)·n/buckets` of the `n` announced, so a run and its CSV
//! read back keep the same points.
//!
//! Which extremes a bucket keeps is the thinning's kind: a series against the crank angle keeps
//! its smallest and largest y ([`Envelope`], `envelope.rs`: the very points the writer would
//! keep of the whole series); a locus, a path in the plane, its smallest and largest x and y
//! ([`Locus`], `locus.rs`: the path's extent in both directions).

/// A point of the path: its row and (x, y).
type Point = (usize, f64, f64);

/// The running thinning keeping `K` extremes per bucket (module note). Slot `j` of a bucket
/// holds the smallest (`j` even) or largest (`j` odd) value of one coordinate: y for `K = 2`,
/// x for slots 0 and 1 and y for slots 2 and 3 for `K = 4`. Fixed by `K`, so a push compares
/// without looking the slots up.
#[derive(Debug, Clone)]
pub struct Thinning<const K: usize> {
    /// Rows announced (the buckets' bounds follow from it).
    rows: usize,
    /// Buckets; 0 when every point is kept (`rows` ≤ budget).
    buckets: usize,
    /// The current bucket and the row where the next one begins.
    bucket: usize,
    bucket_end: usize,
    /// The next row's index.
    row: usize,
    /// The row from which a finite point takes [`Thinning::turn`]: 0 until the first (and
    /// every row when every point is kept), then the current bucket's end (none in the last
    /// bucket), so that a push between compares the extremes alone.
    watch: usize,
    /// The current bucket's extremes, one per slot (row `usize::MAX`: none yet), and the
    /// value each slot compares (±∞ while it holds none: every finite value beats it).
    extremes: [Point; K],
    held: [f64; K],
    /// The last finite point so far (row `usize::MAX`: none), and the row of the last point
    /// kept.
    last: Point,
    kept_row: Option<usize>,
    x: Vec<f64>,
    y: Vec<f64>,
}

/// A series against the crank angle: each bucket's smallest and largest y (`envelope.rs`).
pub type Envelope = Thinning<2>;

/// A locus: each bucket's smallest and largest x and y (`locus.rs`).
pub type Locus = Thinning<4>;

/// No point.
const NONE: Point = (usize::MAX, f64::NAN, f64::NAN);

impl<const K: usize> Thinning<K> {
    /// A thinning of `rows` rows keeping at most `budget` points (at least 2 + `K`: the two
    /// ends and one bucket's extremes).
    pub fn new(rows: usize, budget: usize) -> Self {
        const { assert!(K == 2 || K == 4) };
        let budget = budget.max(2 + K);
        // decimate's for K = 2: the ends and K points per bucket, 2 + K·buckets ≤ budget.
        let buckets = if rows <= budget { 0 } else { (budget - 2) / K };
        Self {
            rows,
            buckets,
            bucket: 0,
            // No buckets (every point kept): no bucket ever ends.
            bucket_end: rows.checked_div(buckets).unwrap_or(usize::MAX),
            row: 0,
            watch: 0,
            extremes: [NONE; K],
            held: Self::EMPTY,
            last: NONE,
            kept_row: None,
            x: Vec::with_capacity(rows.min(budget)),
            y: Vec::with_capacity(rows.min(budget)),
        }
    }

    /// The values an empty bucket's slots compare: +∞ for a smallest, −∞ for a largest.
    const EMPTY: [f64; K] = {
        let mut held = [f64::INFINITY; K];
        let mut j = 1;
        while j < K {
            held[j] = f64::NEG_INFINITY;
            j += 2;
        }
        held
    };

    /// Keeps a point whose row is past the last kept one (the rows come in order).
    fn keep(&mut self, (row, x, y): Point) {
        if self.kept_row.is_none_or(|k| k < row) {
            self.kept_row = Some(row);
            self.x.push(x);
            self.y.push(y);
        }
    }

    /// Keeps the current bucket's extremes in row order (a stable sort: of two slots on one
    /// row, the first slot's), and empties it.
    fn close_bucket(&mut self) {
        let mut points = std::mem::replace(&mut self.extremes, [NONE; K]);
        self.held = Self::EMPTY;
        points.sort_by_key(|p| p.0);
        for p in points.into_iter().take_while(|p| p.0 != usize::MAX) {
            self.keep(p);
        }
    }

    /// Closes the buckets that end at or before `row` (rows past the announced count stay
    /// in the last bucket).
    fn reach(&mut self, row: usize) {
        while row >= self.bucket_end && self.bucket + 1 < self.buckets {
            self.close_bucket();
            self.bucket += 1;
            self.bucket_end = (self.bucket + 1) * self.rows / self.buckets;
        }
    }

    /// Takes the next row's point (x, y); a point with a NaN or infinite part is a gap, as in
    /// the charts (skipped).
    #[inline]
    pub fn push(&mut self, x: f64, y: f64) {
        let row = self.row;
        self.row += 1;
        if !(x.is_finite() && y.is_finite()) {
            return;
        }
        let point = (row, x, y);
        if row >= self.watch && self.turn(point) {
            return;
        }
        self.last = point;
        // Strict comparisons: the first row of an extreme value, as decimate.
        for j in 0..K {
            let v = if K == 4 && j < 2 { x } else { y };
            let better = if j % 2 == 1 {
                v > self.held[j]
            } else {
                v < self.held[j]
            };
            if better {
                self.held[j] = v;
                self.extremes[j] = point;
            }
        }
    }

    /// A finite point at or past the row watched: kept, if every point is (then `true`: nothing
    /// more to do); else the buckets that end at or before its row closed, the point kept if
    /// it is the first finite one, and the current bucket's end watched.
    #[cold]
    fn turn(&mut self, point: Point) -> bool {
        if self.buckets == 0 {
            self.keep(point);
            return true;
        }
        self.reach(point.0);
        if self.last.0 == usize::MAX {
            self.keep(point);
        }
        self.watch = if self.bucket + 1 < self.buckets {
            self.bucket_end
        } else {
            usize::MAX
        };
        false
    }

    /// Points held so far (never more than the budget).
    pub fn len(&self) -> usize {
        self.x.len()
    }

    /// Whether no point is held yet.
    pub fn is_empty(&self) -> bool {
        self.x.is_empty()
    }

    /// The kept points in row order: (x, y).
    pub fn finish(mut self) -> (Vec<f64>, Vec<f64>) {
        self.close_bucket();
        if self.last.0 != usize::MAX {
            self.keep(self.last);
        }
        (self.x, self.y)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The thinning of a whole path at once, as the module note says: every finite point
    /// under the budget; else the first finite point, per bucket the rows of its slots'
    /// extremes (the first row of an extreme value; in row order, none twice), the last
    /// finite point.
    fn reference<const K: usize>(
        x: &[f64],
        y: &[f64],
        rows: usize,
        budget: usize,
    ) -> (Vec<f64>, Vec<f64>) {
        let budget = budget.max(2 + K);
        let finite: Vec<usize> = (0..x.len())
            .filter(|&k| x[k].is_finite() && y[k].is_finite())
            .collect();
        let mut kept: Vec<usize> = Vec::new();
        if rows <= budget {
            kept = finite;
        } else if let (Some(&first), Some(&last)) = (finite.first(), finite.last()) {
            let buckets = (budget - 2) / K;
            // Bucket b ends before row (b + 1)·rows / buckets; rows past them stay in the last.
            let ends: Vec<usize> = (0..buckets).map(|b| (b + 1) * rows / buckets).collect();
            let mut members = vec![Vec::new(); buckets];
            for &k in &finite {
                members[ends.partition_point(|&e| e <= k).min(buckets - 1)].push(k);
            }
            kept.push(first);
            for members in &members {
                let mut picks: Vec<usize> = (0..K)
                    .filter_map(|j| {
                        let v = |k: usize| if K == 4 && j < 2 { x[k] } else { y[k] };
                        members.iter().copied().reduce(|best, k| {
                            let better = if j % 2 == 1 {
                                v(k) > v(best)
                            } else {
                                v(k) < v(best)
                            };
                            if better {
                                k
                            } else {
                                best
                            }
                        })
                    })
                    .collect();
                picks.sort();
                kept.extend(picks);
            }
            kept.push(last);
            kept.dedup();
        }
        (
            kept.iter().map(|&k| x[k]).collect(),
            kept.iter().map(|&k| y[k]).collect(),
        )
    }

    fn thin<const K: usize>(
        x: &[f64],
        y: &[f64],
        rows: usize,
        budget: usize,
    ) -> (Vec<f64>, Vec<f64>) {
        let mut t = Thinning::<K>::new(rows, budget);
        for (a, b) in x.iter().zip(y) {
            t.push(*a, *b);
            // Within the budget while the rows are within the count announced.
            assert!(t.row > rows || t.len() <= budget.max(2 + K));
        }
        t.finish()
    }

    /// The running thinning keeps the points the whole path's thinning keeps, for both kinds,
    /// over paths with gaps (NaN, infinite), ties, leading gaps and more rows than announced.
    #[test]
    fn the_running_thinning_is_the_whole_paths() {
        let mut seed = 0x2545_f491_4f6c_dd1d_u64;
        let mut next = move || {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            seed
        };
        for case in 0..300 {
            let n = 1 + (next() % 3000) as usize;
            let rows = match case % 3 {
                0 => n,
                1 => n / 2 + 1,
                _ => n + 5,
            };
            let budget = 2 + (next() % 200) as usize;
            let lead = (next() % 4) as usize;
            let mut value = |k: usize| -> f64 {
                match next() % 40 {
                    0 => f64::NAN,
                    1 => f64::INFINITY,
                    2..=9 => (k % 7) as f64,
                    _ => (next() % 1000) as f64 * 0.25 - 100.0,
                }
            };
            let x: Vec<f64> = (0..n)
                .map(|k| if k < lead { f64::NAN } else { value(k) })
                .collect();
            let y: Vec<f64> = (0..n).map(&mut value).collect();
            assert_eq!(
                thin::<2>(&x, &y, rows, budget),
                reference::<2>(&x, &y, rows, budget),
                "envelope: case {case}, {n} points, {rows} rows, budget {budget}"
            );
            assert_eq!(
                thin::<4>(&x, &y, rows, budget),
                reference::<4>(&x, &y, rows, budget),
                "locus: case {case}, {n} points, {rows} rows, budget {budget}"
            );
        }
    }
}
