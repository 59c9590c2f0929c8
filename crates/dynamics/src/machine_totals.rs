//! The whole machine's accumulator ([`MachineTotals`]): the peaks of its shaking force and
//! moments, its main journals' and crank pins' loads and its drive torque, and the works of the
//! cylinders the machine stage loads itself, over a run's steps; at the end the machine's
//! metrics (`metrics::MACHINE`) and its orders over one revolution. Below the stage
//! (`machine_stage.rs`), which writes the values it reads, where `Places` says.

use crate::machine::Machine;
use crate::metrics::Summary;
use crate::stage::{RunTotals, StageTotals};
use crate::step::StepBlock;
use crate::summary::peaks::raise;
use crate::summary::Integral;
use cardan_mechanism::{C, LANES};
use std::any::Any;
use std::ops::Range;
use std::sync::Arc;

/// Where each of the stage's values sits in its row of values.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Places {
    pub(crate) cylinders: usize,
    pub(crate) journals: usize,
    /// Whether the mechanism has a crank pin (its columns).
    pub(crate) pins: bool,
    /// Whether the case has a gas model (the gas forces' columns).
    pub(crate) gas: bool,
}

impl Places {
    pub(crate) const TORQUE: usize = 4;

    pub(crate) fn journal(&self, j: usize) -> usize {
        5 + 2 * j
    }

    pub(crate) fn pin(&self, k: usize) -> usize {
        self.journal(self.journals) + 2 * k
    }

    pub(crate) fn gas(&self, k: usize) -> usize {
        self.pin(if self.pins { self.cylinders } else { 0 }) + k
    }

    /// The values no column shows: the cylinders' apart from the train's drive torque (gas and
    /// inertia), gas torque and loss power.
    pub(crate) fn others(&self) -> usize {
        self.gas(if self.gas { self.cylinders } else { 0 })
    }

    pub(crate) fn width(&self) -> usize {
        self.others() + 3
    }
}

/// `raise(peak, x.hypot(y))`, the same result, with `hypot` (a libm call, 80 instructions)
/// skipped where it cannot raise the peak: (0, 0) (the free moments of one cylinder), and
/// x² + y² below peak²·(1 − 2⁻⁴⁰). There, with u = 2⁻⁵³, the computed squares and sum are
/// within (1 ± 2u) of the exact x² + y² (Higham, *Accuracy and Stability of Numerical
/// Algorithms*, 2nd ed., §3.1, the model of floating-point arithmetic) and peak² within
/// (1 ± u), so the exact norm is below peak·(1 − 2⁻⁴²), and `hypot` (within 1 ulp, glibc's
/// documented bound) rounds it to at most peak: no change. A peak² below [`SMALL`] or
/// infinite never skips.
#[inline]
fn raise_norm(peak: &mut f64, x: f64, y: f64) {
    const BELOW: f64 = 1.0 - 1.0 / (1u64 << 40) as f64;
    let p2 = *peak * *peak;
    let s = x * x + y * y;
    let zero = x == 0.0 && y == 0.0 && *peak >= 0.0;
    if zero || (p2 > SMALL && p2.is_finite() && s < p2 * BELOW) {
        return;
    }
    raise(peak, x.hypot(y));
}

/// About 2⁻⁹⁰⁰: [`raise_norm`]'s smallest peak² that may skip (far above the subnormals).
const SMALL: f64 = 1.2e-271;

/// The machine's accumulator: the peaks of the shaking force, free moment, journal and crank
/// pin loads, the machine torque's extremes, the integrals of the other cylinders' drive and
/// gas torques over the crank angle and of their losses over time, the orders at its finish.
#[derive(Debug, Clone)]
pub struct MachineTotals {
    machine: Arc<Machine>,
    places: Places,
    order_speed: f64,
    friction: bool,
    force: f64,
    moment: f64,
    journal: f64,
    pin: f64,
    /// Room for each crank pin's load at a step.
    pins: Vec<C>,
    /// The machine torque's smallest and largest value so far.
    torque: Option<(f64, f64)>,
    /// ∫ T dθ and ∫ T_gas dθ of the cylinders apart from the train, J.
    work: Integral,
    gas_work: Integral,
    /// ∫ P dt of their losses, J.
    loss_work: Integral,
    /// The angle, time and other cylinders' torque, gas torque and loss power at the last step
    /// taken.
    previous: Option<[f64; 5]>,
    /// Whether the machine has cylinders apart from the train (else their integrals stay 0).
    others: bool,
}

impl MachineTotals {
    /// The empty accumulator of `machine`'s stage, its values where `places` says, the orders
    /// taken at `order_speed` (rad/s); `friction`: whether the case has loss models.
    pub(crate) fn new(
        machine: Arc<Machine>,
        places: Places,
        order_speed: f64,
        friction: bool,
    ) -> Self {
        let others = machine.cylinders() > usize::from(machine.train_is_first());
        Self {
            pins: vec![C::new(0.0, 0.0); machine.pins()],
            machine,
            places,
            order_speed,
            friction,
            force: 0.0,
            moment: 0.0,
            journal: 0.0,
            pin: 0.0,
            torque: None,
            work: Integral::default(),
            gas_work: Integral::default(),
            loss_work: Integral::default(),
            previous: None,
            others,
        }
    }

    /// Takes the stage's values at the steps `steps` (step number, crank angle in rad, time in
    /// s, in the steps' order), `column(place)` the values at `place` of those steps. The peaks
    /// a value at a time over the steps (each accumulator sees its values in the steps' order),
    /// the integrals step by step.
    #[inline]
    fn take<'v>(&mut self, steps: &[(usize, f64, f64)], column: impl Fn(usize) -> &'v [f64]) {
        let p = self.places;
        let norms = |peak: &mut f64, x: usize| {
            for (&a, &b) in column(x).iter().zip(column(x + 1)) {
                raise_norm(peak, a, b);
            }
        };
        norms(&mut self.force, 0);
        norms(&mut self.moment, 2);
        for j in 0..p.journals {
            norms(&mut self.journal, p.journal(j));
        }
        for &torque in column(Places::TORQUE) {
            self.torque = Some(match self.torque {
                None => (torque, torque),
                Some((lo, hi)) => (lo.min(torque), hi.max(torque)),
            });
        }
        if p.pins {
            for i in 0..steps.len() {
                self.pins.fill(C::new(0.0, 0.0));
                for k in 0..p.cylinders {
                    let pin = C::new(column(p.pin(k))[i], column(p.pin(k) + 1)[i]);
                    self.pins[self.machine.pin_of(k)] += pin;
                }
                for f in &self.pins {
                    raise_norm(&mut self.pin, f.re, f.im);
                }
            }
        }
        if !self.others {
            return;
        }
        let o = p.others();
        let (w, g, l) = (column(o), column(o + 1), column(o + 2));
        for (i, &(k, angle, time)) in steps.iter().enumerate() {
            let now = [angle, time, w[i], g[i], l[i]];
            if let Some([a0, t0, w0, g0, l0]) = self.previous {
                self.work.add(k, 0.5 * (angle - a0) * (now[2] + w0));
                self.gas_work.add(k, 0.5 * (angle - a0) * (now[3] + g0));
                self.loss_work.add(k, 0.5 * (time - t0) * (now[4] + l0));
            }
            self.previous = Some(now);
        }
    }
}

impl StageTotals for MachineTotals {
    fn push_lanes(
        &mut self,
        block: &StepBlock,
        lanes: Range<usize>,
        stage: usize,
        _previous: Option<f64>,
    ) {
        let c = &block.stage_columns[stage];
        let crank = &block.state.crank;
        let mut steps = [(0, 0.0, 0.0); LANES];
        for (i, j) in lanes.clone().enumerate() {
            steps[i] = (block.first + j, crank.angle[j], crank.time[j]);
        }
        self.take(&steps[..lanes.len()], |place| &c[place][lanes.clone()]);
    }

    fn close_chunk(&mut self) {
        self.work.close_chunk();
        self.gas_work.close_chunk();
        self.loss_work.close_chunk();
    }

    fn merge(&mut self, later: &dyn StageTotals) {
        let later = later
            .as_any()
            .downcast_ref::<Self>()
            .expect("machine totals");
        raise(&mut self.force, later.force);
        raise(&mut self.moment, later.moment);
        raise(&mut self.journal, later.journal);
        raise(&mut self.pin, later.pin);
        self.torque = match (self.torque, later.torque) {
            (Some((a, b)), Some((c, d))) => Some((a.min(c), b.max(d))),
            (x, y) => x.or(y),
        };
        self.work.merge(&later.work);
        self.gas_work.merge(&later.gas_work);
        self.loss_work.merge(&later.loss_work);
        self.previous = later.previous;
    }

    /// The balance's metrics and the machine's (`docs/results.md`): the works of the train
    /// where it is cylinder 1 (the run's `total` and `gas` works and `loss_work`) and of every
    /// other cylinder; the need or output and the efficiency by the machine's kind (Karhula
    /// A9.1.60-75 for the whole machine).
    fn finish(&self, run: &RunTotals, m: &mut Summary) {
        let orders = self.machine.balance().orders(self.order_speed);
        m.push("shaking_force_max", self.force);
        for k in [1, 2, 4] {
            let name = format!("shaking_force_order_{k}");
            m.push(name, orders.force[k].amplitude());
        }
        m.push("shaking_moment_max", self.moment);
        for k in [1, 2] {
            let name = format!("shaking_moment_order_{k}");
            m.push(name, orders.moment[k].amplitude());
        }
        if self.machine.main_bearing().is_some() {
            m.push("machine_main_bearing_force_max", self.journal);
        }
        if self.places.pins {
            m.push("machine_crank_pin_force_max", self.pin);
        }
        let (span, time) = (run.span, run.time);
        let first = self.machine.train_is_first();
        let train = |name: &str| if first { run.work(name) } else { Some(0.0) };
        let (Some((lo, hi)), Some(total)) = (self.torque, train("total").or(train("inertial")))
        else {
            return;
        };
        let work = total + self.work.value();
        let lost = match self.friction {
            true => Some(
                if first {
                    m.get("loss_work").unwrap_or(0.0)
                } else {
                    0.0
                } + self.loss_work.value(),
            ),
            false => None,
        };
        let need = work + lost.unwrap_or(0.0);
        m.push("machine_torque_max", hi);
        m.push("machine_torque_min", lo);
        if span > 0.0 {
            m.push("machine_torque_mean", need / span);
            // A mean that is round-off of a torque that swings both ways (an inertial run at
            // constant speed) is zero: no uniformity then.
            let mean = need / span;
            if mean.abs() > 1e-9 * (hi - lo) {
                m.push("torque_nonuniformity", (hi - lo) / mean.abs());
            }
        }
        if time > 0.0 {
            m.push("machine_power_mean", need / time);
        }
        let Some(lost) = lost else { return };
        if time > 0.0 {
            m.push("machine_loss_power_mean", lost / time);
        }
        let Some(gas) = train("gas").map(|g| g + self.gas_work.value()) else {
            return;
        };
        if !self.places.gas {
            return;
        }
        let efficiency = self.machine.kind.efficiency(gas, work, lost);
        if let Some(e) = efficiency {
            m.push("machine_mechanical_efficiency", e);
        }
    }

    fn fork(&self) -> Box<dyn StageTotals> {
        Box::new(self.clone())
    }

    fn as_any(&self) -> &dyn Any {
        self
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `raise_norm` raises a peak exactly as raising it to `hypot` does, over a run of values
    /// that grow, shrink, tie and cross zero, their squares near the skip's edge, tiny and
    /// huge ones (a generator of its own: no values copied from the program).
    #[test]
    fn raise_norm_is_raise_of_hypot() {
        let mut seed = 0x9e37_79b9_7f4a_7c15_u64;
        let mut next = || {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            (seed >> 11) as f64 / (1u64 << 53) as f64 - 0.5
        };
        for scale in [1e-160, 1e-140, 1e-130, 1e-3, 1.0, 1e3, 1e150, 1e160] {
            let (mut a, mut b) = (0.0_f64, 0.0_f64);
            for k in 0..20_000 {
                let (x, y) = match k % 7 {
                    0 => (0.0, -0.0),
                    // Near the last peak: a tie and the next floats about it.
                    1 => {
                        let t = f64::from_bits((b.to_bits() + k % 3).saturating_sub(1));
                        (t, 0.0)
                    }
                    _ => (scale * next(), scale * next()),
                };
                raise(&mut a, x.hypot(y));
                raise_norm(&mut b, x, y);
                assert_eq!(a.to_bits(), b.to_bits(), "{scale}: step {k}, ({x}, {y})");
            }
        }
    }
}
