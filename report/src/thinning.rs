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

/// The extremes a bucket keeps: per slot, the coordinate (0: x, 1: y) and whether its largest
/// (`true`) or smallest value.
type Slots<const K: usize> = [(usize, bool); K];

/// The running thinning keeping `K` extremes per bucket (module note).
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
    slots: Slots<K>,
    /// The current bucket's extremes, one per slot: (row, x, y).
    extremes: [Option<(usize, f64, f64)>; K],
    /// The last finite point so far, and the row of the last point kept.
    last: Option<(usize, f64, f64)>,
    kept_row: Option<usize>,
    x: Vec<f64>,
    y: Vec<f64>,
}

/// A series against the crank angle: each bucket's smallest and largest y (`envelope.rs`).
pub type Envelope = Thinning<2>;

/// A locus: each bucket's smallest and largest x and y (`locus.rs`).
pub type Locus = Thinning<4>;

impl Envelope {
    /// An envelope of `rows` rows keeping at most `budget` points (at least 4: the two ends
    /// and one bucket's two extremes).
    pub fn new(rows: usize, budget: usize) -> Self {
        Thinning::with_slots(rows, budget, [(1, false), (1, true)])
    }
}

impl Locus {
    /// A locus of `rows` rows keeping at most `budget` points (at least 6: the two ends and
    /// one bucket's four extremes).
    pub fn new(rows: usize, budget: usize) -> Self {
        Thinning::with_slots(rows, budget, [(0, false), (0, true), (1, false), (1, true)])
    }
}

impl<const K: usize> Thinning<K> {
    fn with_slots(rows: usize, budget: usize, slots: Slots<K>) -> Self {
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
            slots,
            extremes: [None; K],
            last: None,
            kept_row: None,
            x: Vec::with_capacity(rows.min(budget)),
            y: Vec::with_capacity(rows.min(budget)),
        }
    }

    /// Keeps a point whose row is past the last kept one (the rows come in order).
    fn keep(&mut self, (row, x, y): (usize, f64, f64)) {
        if self.kept_row.is_none_or(|k| k < row) {
            self.kept_row = Some(row);
            self.x.push(x);
            self.y.push(y);
        }
    }

    /// Keeps the current bucket's extremes in row order (a stable sort: of two slots on one
    /// row, the first slot's).
    fn close_bucket(&mut self) {
        let mut points = std::mem::replace(&mut self.extremes, [None; K]);
        points.sort_by_key(|p| p.map_or(usize::MAX, |p| p.0));
        for p in points.into_iter().flatten() {
            self.keep(p);
        }
    }

    /// Takes the next row's point (x, y); a point with a NaN or infinite part is a gap, as in
    /// the charts (skipped).
    pub fn push(&mut self, x: f64, y: f64) {
        let row = self.row;
        self.row += 1;
        if !(x.is_finite() && y.is_finite()) {
            return;
        }
        let point = (row, x, y);
        if self.buckets == 0 {
            self.keep(point);
            return;
        }
        // Rows past the announced count stay in the last bucket.
        while row >= self.bucket_end && self.bucket + 1 < self.buckets {
            self.close_bucket();
            self.bucket += 1;
            self.bucket_end = (self.bucket + 1) * self.rows / self.buckets;
        }
        if self.last.is_none() {
            self.keep(point);
        }
        self.last = Some(point);
        // Strict comparisons: the first row of an extreme value, as decimate.
        let value = [x, y];
        for (slot, &(coordinate, largest)) in self.extremes.iter_mut().zip(&self.slots) {
            let v = value[coordinate];
            let better = |p: &(usize, f64, f64)| {
                let held = if coordinate == 0 { p.1 } else { p.2 };
                if largest {
                    v > held
                } else {
                    v < held
                }
            };
            if slot.as_ref().is_none_or(better) {
                *slot = Some(point);
            }
        }
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
        if let Some(last) = self.last {
            self.keep(last);
        }
        (self.x, self.y)
    }
}
