//! The summary's drive work of each load family: the peak drive torque and the trapezoidal
//! integrals of the torque over the crank angle (Karhula 2008 A5.2.1.37-39).

use super::integral::{add_trapezoids, Integral};
use super::peaks::{raise, raise_over_lanes};
use crate::step::StepBlock;
use cardan_mechanism::{LoadsBlock, LANES};
use cardan_metrics::Summary;
use std::ops::Range;

/// One family's peak |drive torque| and its integrals over the crank angle: the work ∫ T dθ,
/// ∫ |T| dθ (the energy the drive moves, the energy check's scale) and ∫ T·ω dθ.
#[derive(Debug, Clone, Default)]
pub(crate) struct DriveWork {
    torque: f64,
    work: Integral,
    abs_work: Integral,
    energy_flow: Integral,
    /// The torque of the last step taken.
    previous_torque: f64,
}

impl DriveWork {
    /// Takes the lanes `lanes` of `block` (`loads`: this family's loads there; `previous` the
    /// angle and speed of the step before them, `None` before the first).
    #[inline(always)]
    pub(crate) fn push(
        &mut self,
        block: &StepBlock,
        loads: &LoadsBlock,
        lanes: Range<usize>,
        previous: Option<(f64, f64)>,
    ) {
        let t = &loads.crank_torque;
        raise_over_lanes(&mut self.torque, lanes.clone(), |i| t[i].abs());
        // (A5.2.1.37) W = ∫ T dθ and the crank-angle integral of the power T·ω, by the
        // trapezoidal rule on the crank-angle grid.
        let (c, t0) = (&block.state.crank, self.previous_torque);
        let (a, w) = (&c.angle, &c.speed);
        let before = |f: fn(f64, f64, f64, f64) -> f64| {
            move || previous.map(|(a0, w0)| 0.5 * (a[0] - a0) * f(t[0], t0, w[0], w0))
        };
        add_trapezoids(
            &mut self.work,
            block.first,
            lanes.clone(),
            before(|t, t0, _, _| t + t0),
            |i| 0.5 * (a[i] - a[i - 1]) * (t[i] + t[i - 1]),
        );
        add_trapezoids(
            &mut self.abs_work,
            block.first,
            lanes.clone(),
            before(|t, t0, _, _| t.abs() + t0.abs()),
            |i| 0.5 * (a[i] - a[i - 1]) * (t[i].abs() + t[i - 1].abs()),
        );
        add_trapezoids(
            &mut self.energy_flow,
            block.first,
            lanes.clone(),
            before(|t, t0, w, w0| t * w + t0 * w0),
            |i| 0.5 * (a[i] - a[i - 1]) * (t[i] * w[i] + t[i - 1] * w[i - 1]),
        );
        if let Some(last) = lanes.end.checked_sub(1) {
            self.previous_torque = t[last.min(LANES - 1)];
        }
    }

    pub(crate) fn close_chunk(&mut self) {
        self.work.close_chunk();
        self.abs_work.close_chunk();
        self.energy_flow.close_chunk();
    }

    /// Continues with `later`, which took the steps from the last one this took on.
    pub(crate) fn merge(&mut self, later: &Self) {
        raise(&mut self.torque, later.torque);
        self.work.merge(&later.work);
        self.abs_work.merge(&later.abs_work);
        self.energy_flow.merge(&later.energy_flow);
        self.previous_torque = later.previous_torque;
    }

    /// ∫ T dθ, J.
    pub(crate) fn work(&self) -> f64 {
        self.work.value()
    }

    /// ∫ |T| dθ, J.
    pub(crate) fn abs_work(&self) -> f64 {
        self.abs_work.value()
    }

    /// The metrics of the family `family` over a run of crank-angle `span` (rad) (names joined
    /// by `concat`, not `format!`: see `MotionPeaks::finish`).
    pub(crate) fn finish(&self, family: &str, span: f64, m: &mut Summary) {
        m.push_as(
            "{family}_torque_max",
            [family, "_torque_max"].concat(),
            self.torque,
        );
        let work = self.work.value();
        m.push_as("{family}_work", [family, "_work"].concat(), work);
        // (A5.2.1.38)
        m.push_as(
            "{family}_torque_mean",
            [family, "_torque_mean"].concat(),
            work / span,
        );
        // (A5.2.1.39) averaged over the crank angle, as the thesis's tables are; at constant
        // speed this is the time average.
        m.push_as(
            "{family}_power_mean",
            [family, "_power_mean"].concat(),
            self.energy_flow.value() / span,
        );
    }
}
