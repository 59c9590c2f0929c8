//! The summary's lever: the drive torque per unit force on the first piston, |dx/dθ|, its peak
//! and its mean over the crank angle (the mechanical advantage).

use super::integral::{add_trapezoids, Integral};
use super::peaks::{raise, raise_over_lanes};
use crate::step::StepBlock;
use cardan_metrics::Summary;
use std::ops::Range;

/// Largest |dx/dθ| of the first piston, m/rad, and ∫|dx/dθ| dθ, m.
#[derive(Debug, Clone, Default)]
pub(crate) struct Lever {
    peak: f64,
    integral: Integral,
    /// |dx/dθ| of the last step taken.
    previous: f64,
}

impl Lever {
    /// Takes the lanes `lanes` of `block` (`previous`: the angle of the step before them, `None`
    /// before the first; a mechanism without a piston has no lever).
    #[inline(always)]
    pub(crate) fn push(&mut self, block: &StepBlock, lanes: Range<usize>, previous: Option<f64>) {
        let (Some(p), Some(last)) = (block.state.pistons.first(), lanes.end.checked_sub(1)) else {
            return;
        };
        let (a, x) = (&block.state.crank.angle, &p.dx_dtheta);
        raise_over_lanes(&mut self.peak, lanes.clone(), |i| x[i].abs());
        let l0 = self.previous;
        add_trapezoids(
            &mut self.integral,
            block.first,
            lanes,
            || previous.map(|a0| 0.5 * (a[0] - a0) * (x[0].abs() + l0)),
            |i| 0.5 * (a[i] - a[i - 1]) * (x[i].abs() + x[i - 1].abs()),
        );
        self.previous = x[last].abs();
    }

    pub(crate) fn close_chunk(&mut self) {
        self.integral.close_chunk();
    }

    /// Continues with `later`, which took the steps from the last one this took on.
    pub(crate) fn merge(&mut self, later: &Self) {
        raise(&mut self.peak, later.peak);
        self.integral.merge(&later.integral);
        self.previous = later.previous;
    }

    /// The mechanical advantage of a mechanism of crank `radius` and `stroke` (m) over a run of
    /// crank-angle `span` (rad).
    pub(crate) fn finish(&self, radius: f64, stroke: f64, span: f64, m: &mut Summary) {
        // Power balance: the drive torque per unit force on the piston is dx/dθ. Vidinsky's
        // (2021) mechanical advantage refers it to the crank radius (F_out = T/p, eq 21 and
        // L225); per unit stroke it compares mechanisms of equal displacement fairly.
        m.push("mechanical_advantage_max", self.peak / radius);
        m.push(
            "mechanical_advantage_mean",
            self.integral.value() / span / radius,
        );
        m.push("torque_per_force_stroke_max", self.peak / stroke);
    }
}
