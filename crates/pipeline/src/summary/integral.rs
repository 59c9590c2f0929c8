//! The summary's integrals: trapezoids summed chunk by chunk ([`crate::summary_chunk`]), each
//! chunk's terms in four running sums keyed by step index mod 4, so that a run gives the same
//! bits however it is cut into blocks and pieces.

use cardan_mechanism::LANES;
use std::ops::Range;

/// Running sums an integral's terms are shared among, by their step's index modulo `SLOTS`.
const SLOTS: usize = 4;

/// A trapezoidal integral summed chunk by chunk ([`crate::summary_chunk`]). Within a chunk, the term
/// of the interval ending at step k goes to running sum k mod `SLOTS` (4), each sum taking its
/// terms in the steps' order; a chunk's value is the sums added pairwise. The order is a
/// function of the steps' indices alone, so a run gives the same bits however it is cut into
/// blocks and pieces; the sums are independent, so four terms are added at once (one add's
/// latency per four steps, not per step; the error bound is that of sequential summation of
/// a quarter as many terms).
#[derive(Debug, Clone, Copy, Default)]
pub struct Integral {
    /// The sum of the chunks closed so far, and the running sums of the chunk under way.
    closed: f64,
    open: [f64; SLOTS],
}

impl Integral {
    /// Adds `term`, the trapezoid of the interval ending at step `step`.
    #[inline]
    pub fn add(&mut self, step: usize, term: f64) {
        self.open[step % SLOTS] += term;
    }

    /// The running sums added pairwise.
    #[inline]
    fn chunk(&self) -> f64 {
        let [a, b, c, d] = self.open;
        (a + b) + (c + d)
    }

    /// Closes the chunk under way (its sums added pairwise to the closed ones).
    #[inline]
    pub fn close_chunk(&mut self) {
        self.closed += self.chunk();
        self.open = [0.0; SLOTS];
    }

    /// The integral so far, J or whatever the terms' unit.
    #[inline]
    pub fn value(&self) -> f64 {
        self.closed + self.chunk()
    }

    /// Continues with the chunks of `later`, a summary of the steps after these (its first
    /// step closed this one's last chunk).
    #[inline]
    pub fn merge(&mut self, later: &Integral) {
        self.closed += later.closed;
        self.open = later.open;
    }
}

/// Adds to `integral` the trapezoids of the intervals ending at the lanes `lanes` of a block
/// whose lane 0 is step `first`:
/// `term(i)` that of lane i ≥ 1 (from lane i − 1), `first_term` that of lane 0 (from the step
/// before the block; `None` at the first step a summary takes, which ends no interval of its
/// own). Up to a step whose index is a multiple of `SLOTS` (4) a term at a time, then `SLOTS`
/// at once, each to its own sum, kept in one vector register; a whole block starting on such a
/// step (a run's blocks do) takes lane 0's term with lanes 1 to 3 (the term a summary's first
/// step lacks counted as +0, which leaves the fresh sums' bits as they are).
#[inline(always)]
pub fn add_trapezoids(
    integral: &mut Integral,
    first: usize,
    lanes: Range<usize>,
    first_term: impl FnOnce() -> Option<f64>,
    term: impl Fn(usize) -> f64,
) {
    let end = lanes.end.min(LANES);
    let mut open = integral.open;
    let mut i = lanes.start;
    if i == 0 && first % SLOTS == 0 && end >= SLOTS {
        let head = [first_term().unwrap_or(0.0), term(1), term(2), term(3)];
        for (o, t) in open.iter_mut().zip(head) {
            *o += t;
        }
        i = SLOTS;
    } else if i == 0 && i < end {
        if let Some(t) = first_term() {
            open[first % SLOTS] += t;
        }
        i = 1;
    }
    while i < end && (first + i) % SLOTS != 0 {
        open[(first + i) % SLOTS] += term(i);
        i += 1;
    }
    // The rest of a whole block (most blocks): a loop of a known count, which the compiler
    // unrolls; the same terms into the same sums in the same order.
    if i == SLOTS && end == LANES && (first + i) % SLOTS == 0 {
        for chunk in 1..LANES / SLOTS {
            for (k, o) in open.iter_mut().enumerate() {
                *o += term(SLOTS * chunk + k);
            }
        }
        integral.open = open;
        return;
    }
    while i + SLOTS <= end {
        for (k, o) in open.iter_mut().enumerate() {
            *o += term(i + k);
        }
        i += SLOTS;
    }
    for i in i..end {
        open[(first + i) % SLOTS] += term(i);
    }
    integral.open = open;
}

#[cfg(test)]
mod tests {
    use super::*;

    /// An integral's sums depend on the steps' indices alone: a block taken whole (the fast
    /// path), in the pieces a chunk's close cuts it into, or a lane at a time, and blocks that
    /// start off the slots, give the same bits; the value is the sum of the terms to within
    /// the round-off of summing 64 terms (64·ε of Σ|term|), and exact for terms summed
    /// exactly (small integers).
    #[test]
    fn an_integral_is_the_same_however_its_lanes_are_taken() {
        // Terms of varied sign and size, each from its lane and the one before.
        let column: Vec<f64> = (0..LANES + 1)
            .map(|k| ((k as f64) * 0.7).sin() * 10f64.powi(k as i32 % 5 - 2))
            .collect();
        let term = |i: usize| 0.5 * (column[i] + column[i - 1]);
        for first in [0, 64, 128 + 3, 7] {
            let lane0 = || Some(0.25 * column[LANES]);
            let whole = {
                let mut g = Integral::default();
                add_trapezoids(&mut g, first, 0..LANES, lane0, term);
                g
            };
            let cuts = [
                vec![0, 1, LANES],
                vec![0, 5, 6, 33, LANES],
                (0..=LANES).collect(),
            ];
            for cut in cuts {
                let mut g = Integral::default();
                for w in cut.windows(2) {
                    add_trapezoids(&mut g, first, w[0]..w[1], lane0, term);
                }
                assert_eq!(g.open.map(f64::to_bits), whole.open.map(f64::to_bits));
            }
            let terms: Vec<f64> = std::iter::once(0.25 * column[LANES])
                .chain((1..LANES).map(term))
                .collect();
            let exact: f64 = terms.iter().sum();
            let scale: f64 = terms.iter().map(|t| t.abs()).sum();
            assert!((whole.value() - exact).abs() <= 64.0 * f64::EPSILON * scale);
        }
        // A summary's first step ends no interval: counted as +0, the sums stay fresh.
        let mut g = Integral::default();
        add_trapezoids(&mut g, 0, 0..LANES, || None, |i| i as f64);
        assert_eq!(g.value(), (1..LANES).sum::<usize>() as f64);
        assert!(g.open.iter().all(|o| o.is_sign_positive()));
    }
}
