//! The run-up of a solved motion (`machine_motion::solve_cycles`) kept as it is integrated, in
//! bounded memory: the crank speed over time through every cycle before the reported one, for
//! `summary.json`'s `runup` and the report's `crank_speed_time.svg` (issue 38).
//!
//! Each cycle keeps its start (the grid's first row) and, per bucket of its steps
//! ([`BUCKETS_PER_CYCLE`] buckets: step k of a cycle of n steps in bucket ⌊k·B/n⌋), the rows of
//! the bucket's smallest and largest speed, in time order: at most 2·B + 1 points a cycle, the
//! speed's extremes within the cycle kept (the fluctuation a run-up chart shows). When the points
//! kept reach [`MAX_RUNUP_POINTS`], the buckets are merged pairwise (a merged bucket keeps the
//! extremes of its two halves: the same points as if it had been one bucket from the start),
//! down to one bucket a cycle; then the cycles themselves pairwise (a group of 2ʲ cycles keeps
//! the start of its first cycle and the extremes of all its rows). So the series never holds
//! more than [`MAX_RUNUP_POINTS`], whatever the steps and cycles, and every cycle's start is in
//! it while the run-up has at most about `MAX_RUNUP_POINTS`/3 cycles.

/// Buckets of a cycle's steps before any merging: at most 2·32 + 1 = 65 points a cycle.
pub const BUCKETS_PER_CYCLE: usize = 32;

/// The most points a run-up keeps (the report draws at most 1000 of them a series).
pub const MAX_RUNUP_POINTS: usize = 2048;

/// `sub` of a cycle's start.
const START: usize = usize::MAX;

/// A point kept: (time s, speed rad/s), its cycle and its bucket among the
/// [`BUCKETS_PER_CYCLE`] ([`START`] for the cycle's start).
#[derive(Debug, Clone, Copy)]
struct Kept {
    time: f64,
    speed: f64,
    cycle: usize,
    sub: usize,
}

/// The running thinning of a run-up (module note).
#[derive(Debug, Clone)]
pub struct RunUp {
    /// Steps a cycle.
    steps: usize,
    /// Buckets merged: 2^shift fine buckets in one.
    shift: u32,
    /// Cycles a group (a power of two; 1 until the buckets are one a cycle).
    group: usize,
    /// The cycles committed, thinned at the current merging.
    kept: Vec<Kept>,
    /// The index in `kept` of the last point that no merging can drop (a group's start).
    tail: usize,
    /// The current cycle's start and its fine buckets' (smallest, largest) speed rows.
    start: Option<Kept>,
    buckets: [[Option<Kept>; 2]; BUCKETS_PER_CYCLE],
}

impl RunUp {
    /// The run-up of cycles of `steps` steps each.
    pub fn new(steps: usize) -> Self {
        Self {
            steps: steps.max(1),
            shift: 0,
            group: 1,
            kept: Vec::new(),
            tail: 0,
            start: None,
            buckets: [[None; 2]; BUCKETS_PER_CYCLE],
        }
    }

    /// A cycle starts at `time` (s) with `speed` (rad/s): the cycle before it is kept.
    pub fn start(&mut self, time: f64, speed: f64) {
        let cycle = self.start.map_or(0, |s| s.cycle + 1);
        self.commit();
        self.start = Some(Kept {
            time,
            speed,
            cycle,
            sub: START,
        });
    }

    /// Row `k` (1 ≤ k < steps) of the current cycle, at `time` (s) with `speed` (rad/s).
    pub fn row(&mut self, k: usize, time: f64, speed: f64) {
        let Some(start) = self.start else { return };
        let sub = (k * BUCKETS_PER_CYCLE / self.steps).min(BUCKETS_PER_CYCLE - 1);
        let p = Kept {
            time,
            speed,
            cycle: start.cycle,
            sub,
        };
        let [lo, hi] = &mut self.buckets[sub];
        if lo.is_none_or(|q| speed < q.speed) {
            *lo = Some(p);
        }
        if hi.is_none_or(|q| speed > q.speed) {
            *hi = Some(p);
        }
    }

    /// The run-up: every cycle before the current one (the reported cycle, whose rows the run
    /// steps again), then the current cycle's start; (time s, speed rad/s) in time order.
    pub fn finish(mut self) -> Vec<(f64, f64)> {
        let last = self.start.take();
        let mut points: Vec<(f64, f64)> = self.kept.iter().map(|p| (p.time, p.speed)).collect();
        points.extend(last.map(|p| (p.time, p.speed)));
        points
    }

    /// Moves the current cycle (its start and its buckets' extremes) into `kept`, thinned.
    fn commit(&mut self) {
        let Some(start) = self.start else { return };
        self.kept.push(start);
        for [lo, hi] in std::mem::replace(&mut self.buckets, [[None; 2]; BUCKETS_PER_CYCLE]) {
            let (Some(lo), Some(hi)) = (lo, hi) else {
                continue;
            };
            let (a, b) = if lo.time <= hi.time {
                (lo, hi)
            } else {
                (hi, lo)
            };
            self.kept.push(a);
            if b.time != a.time {
                self.kept.push(b);
            }
        }
        self.thin(self.tail);
        // One place left for the reported cycle's start.
        while self.kept.len() >= MAX_RUNUP_POINTS {
            if (1usize << self.shift) < BUCKETS_PER_CYCLE {
                self.shift += 1;
            } else {
                self.group *= 2;
            }
            self.thin(0);
        }
    }

    /// The merged bucket of `p`, `None` where `p` is a group's start (always kept).
    fn key(&self, p: &Kept) -> Option<(usize, usize)> {
        if p.sub == START && p.cycle % self.group == 0 {
            None
        } else if self.group > 1 {
            Some((p.cycle / self.group, 0))
        } else {
            Some((p.cycle, p.sub >> self.shift))
        }
    }

    /// Keeps of `kept[from..]` the groups' starts and, per merged bucket (a run of points of
    /// one key), its smallest and largest speed's points in time order (the first of equals).
    fn thin(&mut self, from: usize) {
        let (mut out, mut i) = (from, from);
        let n = self.kept.len();
        while i < n {
            let Some(key) = self.key(&self.kept[i]) else {
                self.kept[out] = self.kept[i];
                self.tail = out;
                (out, i) = (out + 1, i + 1);
                continue;
            };
            let (mut lo, mut hi, mut j) = (i, i, i);
            while j < n && self.key(&self.kept[j]) == Some(key) {
                if self.kept[j].speed < self.kept[lo].speed {
                    lo = j;
                }
                if self.kept[j].speed > self.kept[hi].speed {
                    hi = j;
                }
                j += 1;
            }
            self.kept[out] = self.kept[lo.min(hi)];
            out += 1;
            if lo != hi {
                self.kept[out] = self.kept[lo.max(hi)];
                out += 1;
            }
            i = j;
        }
        self.kept.truncate(out);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// (time, speed) points.
    type Points = Vec<(f64, f64)>;

    /// A run-up of `cycles` cycles of `steps` steps: time t = cycle + k/steps, speed rising
    /// with a ripple of two periods a cycle (its extremes at 1/8 + j/4 of a cycle). Returns the
    /// run-up, the cycles' starts and the largest speed of the rows before the last cycle.
    fn run(cycles: usize, steps: usize) -> (Points, Points, f64) {
        let speed = |t: f64| t + 0.3 * (4.0 * std::f64::consts::PI * t).sin();
        let mut r = RunUp::new(steps);
        let (mut starts, mut top) = (Vec::new(), f64::MIN);
        for c in 0..cycles {
            let t = c as f64;
            r.start(t, speed(t));
            starts.push((t, speed(t)));
            for k in 0..steps {
                let t = c as f64 + k as f64 / steps as f64;
                if c + 1 < cycles {
                    top = top.max(speed(t));
                }
                if k > 0 {
                    r.row(k, t, speed(t));
                }
            }
        }
        (r.finish(), starts, top)
    }

    #[test]
    fn a_short_run_up_keeps_every_row() {
        let (points, starts, _) = run(3, 20);
        assert_eq!(
            points.len(),
            2 * 20 + 1,
            "two cycles' rows and the last start"
        );
        assert_eq!(points.last(), starts.last());
    }

    #[test]
    fn a_cycle_keeps_its_start_and_each_buckets_extremes() {
        let (points, starts, _) = run(4, 720);
        // Three cycles of at most 65 points, and the reported cycle's start.
        assert!(points.len() <= 3 * 65 + 1, "{}", points.len());
        assert!(points.len() > 3 * 32, "{}", points.len());
        for s in &starts {
            assert!(points.contains(s), "{s:?}");
        }
        // Every local extreme of the ripple among the rows of the cycles before the last
        // (one a bucket at most: two a cycle each way, buckets of 1/32 of it).
        let speed = |t: f64| t + 0.3 * (4.0 * std::f64::consts::PI * t).sin();
        let mut extremes = 0;
        let time = |r: usize| (r / 720) as f64 + (r % 720) as f64 / 720.0;
        for r in 1..3 * 720 {
            let [a, b, c] = [r - 1, r, r + 1].map(|r| speed(time(r)));
            if (b > a && b > c) || (b < a && b < c) {
                extremes += 1;
                let row = (time(r), b);
                assert!(points.contains(&row), "the extreme {row:?}");
            }
        }
        assert_eq!(extremes, 3 * 4);
    }

    /// Bounded whatever the steps and cycles, in time order, from the first start to the last,
    /// the largest speed of the rows kept; every start while they fit, else the starts of every
    /// g-th cycle, g a power of two no larger than the cap's merging needs (3 points a group).
    #[test]
    fn a_long_run_up_is_bounded_and_in_time_order() {
        for (cycles, steps) in [(400, 720), (100, 100_000), (20_000, 8)] {
            let (points, starts, top) = run(cycles, steps);
            let n = points.len();
            assert!(
                n <= MAX_RUNUP_POINTS && n > MAX_RUNUP_POINTS / 4,
                "{cycles}: {n}"
            );
            assert!(points.windows(2).all(|w| w[0].0 < w[1].0), "{cycles}");
            assert_eq!(points[0], starts[0]);
            assert_eq!(points.last(), starts.last());
            // The groups the cap needs (at most three points each: start, min, max).
            let g = (3 * cycles)
                .div_ceil(MAX_RUNUP_POINTS - 1)
                .next_power_of_two();
            assert_eq!(g == 1, 3 * cycles < MAX_RUNUP_POINTS, "{cycles}");
            for c in (0..cycles).filter(|c| c % g == 0) {
                assert!(points.contains(&starts[c]), "{cycles}: the start of {c}");
            }
            let kept_top = points[..n - 1].iter().map(|p| p.1).fold(f64::MIN, f64::max);
            assert_eq!(kept_top, top, "{cycles}");
        }
    }
}
