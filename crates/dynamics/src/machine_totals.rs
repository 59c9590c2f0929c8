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

/// Where each of the stage's values sits in its row of values: the shaking force (x, y) and
/// free moment (pitch, yaw) where the case asks for them, the drive torque, each main
/// journal's load (x, y), each crank pin's (x, y), each cylinder's gas force, then the values
/// no column shows ([`Places::others`]).
#[derive(Debug, Clone, Copy)]
pub(crate) struct Places {
    /// Whether the case asks for the machine's shaking step by step (`[layout]` or
    /// `[balance]`): its columns, and the peaks `shaking_force_max` and `shaking_moment_max`.
    pub(crate) shaking: bool,
    pub(crate) cylinders: usize,
    pub(crate) journals: usize,
    /// Whether the mechanism has a crank pin (its columns).
    pub(crate) pins: bool,
    /// Whether the case has a gas model (the gas forces' columns).
    pub(crate) gas: bool,
}

impl Places {
    /// The drive torque's place.
    pub(crate) fn torque(&self) -> usize {
        4 * usize::from(self.shaking)
    }

    pub(crate) fn journal(&self, j: usize) -> usize {
        self.torque() + 1 + 2 * j
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

/// The largest |(x, y)| = `x.hypot(y)` of the pairs pushed, bit for bit the peak that raising
/// it to each pair's `hypot` gives, with `hypot` (a libm call, some 80 instructions) taken only
/// of the pairs that may be the largest: a pair is dropped where another one's norm is surely
/// not smaller. A pair whose computed x² + y² is below another's times (1 − 2⁻⁴⁰) has the
/// smaller `hypot`: the computed squares and sum are within (1 ± 2u) of the exact x² + y², with
/// u = 2⁻⁵³ (Higham, *Accuracy and Stability of Numerical Algorithms*, 2nd ed., §3.1, the
/// model of floating-point arithmetic), so its exact norm is below the other's by more than
/// 2⁻⁴², and `hypot` (within 1 ulp, glibc's documented bound) keeps that order. The latest
/// candidate stays pending (a peak that rises step after step takes no `hypot` until it is
/// read); one that cannot be told from the pending one, or whose sum of squares is below
/// [`SMALL`] or overflows, is resolved at once. The values are finite (the stage checked).
#[derive(Debug, Clone, Copy)]
struct NormPeak {
    /// The largest `hypot` resolved so far (0 at first).
    peak: f64,
    /// The pending candidate's (x, y) and x² + y² (an x² + y² of 0: none).
    pending: (f64, f64, f64),
    /// A computed x² + y² below this is surely not the largest: the larger of the pending
    /// one's and the peak's square, times (1 − 2⁻⁴⁰), where that is safe (else −∞).
    drop_below: f64,
}

impl Default for NormPeak {
    fn default() -> Self {
        Self {
            peak: 0.0,
            pending: (0.0, 0.0, 0.0),
            drop_below: f64::NEG_INFINITY,
        }
    }
}

impl NormPeak {
    const BELOW: f64 = 1.0 - 1.0 / (1u64 << 40) as f64;

    /// Below this a computed x² + y² is surely the smaller norm beside `than` (the type note), or
    /// −∞ where `than` is too small or not finite to tell.
    #[inline(always)]
    fn bound(than: f64) -> f64 {
        if than > SMALL && than.is_finite() {
            than * Self::BELOW
        } else {
            f64::NEG_INFINITY
        }
    }

    /// The pairs (`xs[i]`, `ys[i]`) of a block's lanes (at most [`LANES`]) in order, as
    /// [`NormPeak::push`] of each: the block's largest sum of squares first (eight running
    /// maxima, kept in vector registers), then only the pairs not surely below it, for a pair
    /// surely below another of the block has the smaller `hypot` (the type note), and that
    /// one is pushed.
    #[inline]
    fn push_block(&mut self, xs: &[f64], ys: &[f64]) {
        let n = xs.len().min(ys.len()).min(LANES);
        let (xs, ys) = (&xs[..n], &ys[..n]);
        let mut squares = [0.0; LANES];
        for ((s, &x), &y) in squares.iter_mut().zip(xs).zip(ys) {
            *s = x * x + y * y;
        }
        let larger = |a: f64, b: f64| if b > a { b } else { a };
        let mut top = [f64::NEG_INFINITY; 8];
        let chunks = squares[..n].chunks_exact(8);
        let rest = chunks.remainder();
        for c in chunks {
            for (m, &s) in top.iter_mut().zip(c) {
                *m = larger(*m, s);
            }
        }
        let top = rest
            .iter()
            .chain(&top)
            .fold(f64::NEG_INFINITY, |a, &b| larger(a, b));
        let below = Self::bound(top).max(self.drop_below);
        for ((&s, &x), &y) in squares.iter().zip(xs).zip(ys) {
            if s < below || (x == 0.0 && y == 0.0) {
                continue;
            }
            self.take(x, y, s);
        }
    }

    #[inline(always)]
    fn push(&mut self, x: f64, y: f64) {
        let s = x * x + y * y;
        // (0, 0): the free moments of a machine in one plane.
        if s < self.drop_below || (x == 0.0 && y == 0.0) {
            return;
        }
        self.take(x, y, s);
    }

    /// A pair that may be the largest.
    #[inline(never)]
    fn take(&mut self, x: f64, y: f64, s: f64) {
        let (px, py, ps) = self.pending;
        if ps >= Self::bound(s) {
            raise(&mut self.peak, px.hypot(py));
        }
        if s > SMALL && s.is_finite() {
            self.pending = (x, y, s);
        } else {
            raise(&mut self.peak, x.hypot(y));
            self.pending = (0.0, 0.0, 0.0);
        }
        self.drop_below = Self::bound(self.pending.2.max(self.peak * self.peak));
    }

    /// The peak.
    fn value(&self) -> f64 {
        let (x, y, _) = self.pending;
        let mut peak = self.peak;
        raise(&mut peak, x.hypot(y));
        peak
    }

    /// The peak over both runs of pairs.
    fn merge(&mut self, later: &Self) {
        self.peak = self.value();
        raise(&mut self.peak, later.value());
        self.pending = (0.0, 0.0, 0.0);
        self.drop_below = Self::bound(self.peak * self.peak);
    }
}

/// About 2⁻⁹⁰⁰: [`NormPeak`]'s smallest sum of squares that may stay pending or drop a pair
/// (far above the subnormals).
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
    force: NormPeak,
    moment: NormPeak,
    journal: NormPeak,
    pin: NormPeak,
    /// Whether each cylinder has a crank pin of its own, the pins in the cylinders' order (its
    /// pin's load is then its own).
    own_pins: bool,
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
        let own_pins = (0..machine.cylinders()).all(|k| machine.pin_of(k) == k);
        Self {
            pins: vec![C::new(0.0, 0.0); machine.pins()],
            machine,
            places,
            order_speed,
            friction,
            force: NormPeak::default(),
            moment: NormPeak::default(),
            journal: NormPeak::default(),
            pin: NormPeak::default(),
            own_pins,
            torque: None,
            work: Integral::default(),
            gas_work: Integral::default(),
            loss_work: Integral::default(),
            previous: None,
            others,
        }
    }

    /// Takes the stage's values at `n` steps, `column(place)` the values at `place` of those
    /// steps; `steps`: each one's step number, crank angle in rad and time in s, in the steps'
    /// order (read only where the machine has cylinders apart from the train). The peaks a
    /// value at a time over the steps (each accumulator sees its values in the steps' order),
    /// the integrals step by step.
    #[inline]
    fn take<'v>(
        &mut self,
        n: usize,
        steps: &[(usize, f64, f64)],
        column: impl Fn(usize) -> &'v [f64],
    ) {
        let p = self.places;
        let norms = |peak: &mut NormPeak, x: usize| peak.push_block(column(x), column(x + 1));
        if p.shaking {
            norms(&mut self.force, 0);
            norms(&mut self.moment, 2);
        }
        for j in 0..p.journals {
            norms(&mut self.journal, p.journal(j));
        }
        let torques = column(p.torque());
        if let Some(&first) = torques.first() {
            let (mut lo, mut hi) = self.torque.unwrap_or((first, first));
            for &torque in torques {
                (lo, hi) = (lo.min(torque), hi.max(torque));
            }
            self.torque = Some((lo, hi));
        }
        if p.pins && self.own_pins {
            for k in 0..p.cylinders {
                norms(&mut self.pin, p.pin(k));
            }
        } else if p.pins {
            for i in 0..n {
                self.pins.fill(C::new(0.0, 0.0));
                for k in 0..p.cylinders {
                    let pin = C::new(column(p.pin(k))[i], column(p.pin(k) + 1)[i]);
                    self.pins[self.machine.pin_of(k)] += pin;
                }
                for f in &self.pins {
                    self.pin.push(f.re, f.im);
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
        let n = lanes.len();
        // The steps only for the integrals of the cylinders apart from the train.
        if self.others {
            for (i, j) in lanes.clone().enumerate() {
                steps[i] = (block.first + j, crank.angle[j], crank.time[j]);
            }
        }
        self.take(n, &steps[..n], |place| &c[place][lanes.clone()]);
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
        self.force.merge(&later.force);
        self.moment.merge(&later.moment);
        self.journal.merge(&later.journal);
        self.pin.merge(&later.pin);
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
        if self.places.shaking {
            m.push("shaking_force_max", self.force.value());
        }
        for k in [1, 2, 4] {
            let name = format!("shaking_force_order_{k}");
            m.push(name, orders.force[k].amplitude());
        }
        if self.places.shaking {
            m.push("shaking_moment_max", self.moment.value());
        }
        for k in [1, 2] {
            let name = format!("shaking_moment_order_{k}");
            m.push(name, orders.moment[k].amplitude());
        }
        if self.machine.main_bearing().is_some() {
            m.push("machine_main_bearing_force_max", self.journal.value());
        }
        if self.places.pins {
            m.push("machine_crank_pin_force_max", self.pin.value());
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

    /// A [`NormPeak`] is the peak that raising to each pair's `hypot` gives, bit for bit, after
    /// every pair and merged from two halves at any split, over runs of pairs that grow (at
    /// random and by single ulps), shrink, tie the peak and the floats about it, cross zero,
    /// and are tiny or huge (a generator of its own: no values copied from the program).
    #[test]
    fn a_norm_peak_is_the_peak_of_hypot() {
        let mut seed = 0x9e37_79b9_7f4a_7c15_u64;
        let mut next = || {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            (seed >> 11) as f64 / (1u64 << 53) as f64 - 0.5
        };
        let ulps = |x: f64, n: i64| f64::from_bits((x.to_bits() as i64 + n).max(0) as u64);
        for scale in [1e-160, 1e-140, 1e-130, 1e-3, 1.0, 1e3, 1e150, 1e160] {
            let mut pairs = Vec::new();
            let mut peak = 0.0_f64;
            for k in 0..20_000_u64 {
                let (x, y) = match k % 9 {
                    0 => (0.0, -0.0),
                    // Near the peak so far: a tie and the floats about it.
                    1 => (ulps(peak, (k % 3) as i64 - 1), 0.0),
                    // A rise of an ulp or two in both coordinates.
                    2 | 3 => pairs.last().map_or((scale, 0.0), |&(a, b): &(f64, f64)| {
                        (ulps(a.abs(), (k % 2 + 1) as i64), ulps(b.abs(), 1))
                    }),
                    // A ramp that grows in steps of about 1e-3.
                    4 => (scale * (0.5 + 1e-3 * (k % 500) as f64), -0.25 * scale),
                    _ => (scale * next(), scale * next()),
                };
                pairs.push((x, y));
                raise(&mut peak, x.hypot(y));
            }
            let mut expected = 0.0_f64;
            let mut norms = NormPeak::default();
            for (k, &(x, y)) in pairs.iter().enumerate() {
                raise(&mut expected, x.hypot(y));
                norms.push(x, y);
                let got = norms.value();
                assert_eq!(
                    expected.to_bits(),
                    got.to_bits(),
                    "{scale}: pair {k}, ({x}, {y})"
                );
            }
            // The same pairs a block at a time, blocks of every length up to LANES.
            let mut blocks = NormPeak::default();
            let (mut start, mut len) = (0, 1);
            while start < pairs.len() {
                let end = (start + len).min(pairs.len());
                let (xs, ys): (Vec<f64>, Vec<f64>) = pairs[start..end].iter().copied().unzip();
                blocks.push_block(&xs, &ys);
                let expected = pairs[..end].iter().fold(0.0, |mut p, &(x, y)| {
                    raise(&mut p, x.hypot(y));
                    p
                });
                assert_eq!(
                    blocks.value().to_bits(),
                    expected.to_bits(),
                    "{scale}: to {end}"
                );
                (start, len) = (end, len % LANES + 1);
            }
            for split in [0, 1, 7, 4_999, 10_000, 19_999] {
                let (mut a, mut b) = (NormPeak::default(), NormPeak::default());
                pairs[..split].iter().for_each(|&(x, y)| a.push(x, y));
                pairs[split..].iter().for_each(|&(x, y)| b.push(x, y));
                a.merge(&b);
                assert_eq!(
                    a.value().to_bits(),
                    peak.to_bits(),
                    "{scale}: split {split}"
                );
            }
        }
    }
}
