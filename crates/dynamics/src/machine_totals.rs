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
use cardan_mechanism::{vectorised, C, LANES};
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

/// The largest |(x, y)| of the pairs pushed, taken as the summary takes each joint's peak
/// (`summary::peaks::JointPeaks`): the square root of the largest computed x² + y², so that
/// a machine of one cylinder on its axis reports its main journal's and crank pin's peaks
/// with the bits of the train's `total_{joint}_force_max`. The values are finite (the stage
/// checked).
#[derive(Debug, Clone, Copy, Default)]
struct NormPeak {
    /// The largest x² + y² so far (0 at first).
    square: f64,
}

impl NormPeak {
    /// The pairs (`xs[i]`, `ys[i]`) of a block's lanes (at most [`LANES`]).
    #[inline(always)]
    fn push_block(&mut self, xs: &[f64], ys: &[f64]) {
        let n = xs.len().min(ys.len()).min(LANES);
        // A whole block (most blocks): slices of a known length, whose loop the compiler
        // unrolls.
        match n == LANES {
            true => self.push_chunks(&xs[..LANES], &ys[..LANES]),
            false => self.push_chunks(&xs[..n], &ys[..n]),
        }
    }

    /// [`NormPeak::push_block`] of slices of one length.
    #[inline(always)]
    fn push_chunks(&mut self, xs: &[f64], ys: &[f64]) {
        // Eight running maxima side by side (kept in vector registers; a maximum does not
        // depend on the order), over chunks whose bounds the compiler sees.
        let mut m = [self.square; 8];
        let (xc, yc) = (xs.chunks_exact(8), ys.chunks_exact(8));
        let (xr, yr) = (xc.remainder(), yc.remainder());
        for (x, y) in xc.zip(yc) {
            for k in 0..8 {
                raise(&mut m[k], x[k] * x[k] + y[k] * y[k]);
            }
        }
        for (k, (x, y)) in xr.iter().zip(yr).enumerate() {
            raise(&mut m[k], x * x + y * y);
        }
        for v in m {
            raise(&mut self.square, v);
        }
    }

    #[inline(always)]
    fn push(&mut self, x: f64, y: f64) {
        raise(&mut self.square, x * x + y * y);
    }

    /// The peak.
    fn value(&self) -> f64 {
        self.square.sqrt()
    }

    /// The peak over both runs of pairs.
    fn merge(&mut self, later: &Self) {
        raise(&mut self.square, later.square);
    }
}

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
    #[inline(always)]
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
            // Eight running extremes side by side (vector registers), by comparisons (as
            // `raise`): the order does not matter, and they are `f64::min`'s and `max`'s, for
            // the values are finite and never −0 (each is a sum begun at +0).
            let (lo, hi) = self.torque.unwrap_or((first, first));
            let (mut lows, mut highs) = ([lo; 8], [hi; 8]);
            let lower = |l: &mut f64, t: f64| *l = if t < *l { t } else { *l };
            let chunks = torques.chunks_exact(8);
            let rest = chunks.remainder();
            for chunk in chunks {
                for k in 0..8 {
                    lower(&mut lows[k], chunk[k]);
                    raise(&mut highs[k], chunk[k]);
                }
            }
            for (k, &t) in rest.iter().enumerate() {
                lower(&mut lows[k], t);
                raise(&mut highs[k], t);
            }
            let (mut lo, mut hi) = (lo, hi);
            for k in 0..8 {
                lower(&mut lo, lows[k]);
                raise(&mut hi, highs[k]);
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
        push_lanes(self, block, lanes, stage);
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

vectorised! {
    /// [`StageTotals::push_lanes`] of the machine's totals: the stage's values at the lanes
    /// `lanes` of `block` (the stage's columns `block.stage_columns[stage]`).
    fn push_lanes(
        totals: &mut MachineTotals,
        block: &StepBlock,
        lanes: Range<usize>,
        stage: usize,
    ) {
        let c = &block.stage_columns[stage];
        let crank = &block.state.crank;
        let n = lanes.len();
        let column = |place: usize| &c[place][lanes.clone()];
        // The steps only for the integrals of the cylinders apart from the train.
        if !totals.others {
            // A whole block (most blocks): columns of a known length, whose loops the compiler
            // unrolls.
            return match lanes.start == 0 && n == LANES {
                true => totals.take(LANES, &[], |place: usize| &c[place][..]),
                false => totals.take(n, &[], column),
            };
        }
        let mut steps = [(0, 0.0, 0.0); LANES];
        for (i, j) in lanes.clone().enumerate() {
            steps[i] = (block.first + j, crank.angle[j], crank.time[j]);
        }
        totals.take(n, &steps[..n], column);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A [`NormPeak`] is the square root of the largest x² + y² of its pairs, pushed one by
    /// one, a block at a time (every block length) or merged from two halves at any split, as
    /// the summary's joint peaks take it (a generator of its own: no values copied from the
    /// program).
    #[test]
    fn a_norm_peak_is_the_root_of_the_largest_square() {
        let mut seed = 0x9e37_79b9_7f4a_7c15_u64;
        let mut next = || {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            (seed >> 11) as f64 / (1u64 << 53) as f64 - 0.5
        };
        for scale in [1e-100, 1e-3, 1.0, 1e3, 1e100] {
            let pairs: Vec<(f64, f64)> = (0..5_000)
                .map(|k| match k % 5 {
                    0 => (0.0, -0.0),
                    1 => (-scale * next(), 0.0),
                    _ => (scale * next(), scale * next()),
                })
                .collect();
            let square = |&(x, y): &(f64, f64)| x * x + y * y;
            let peak = pairs.iter().map(square).fold(0.0, f64::max).sqrt();
            let mut one = NormPeak::default();
            pairs.iter().for_each(|&(x, y)| one.push(x, y));
            assert_eq!(one.value().to_bits(), peak.to_bits(), "{scale}");
            let mut blocks = NormPeak::default();
            let (mut start, mut len) = (0, 1);
            while start < pairs.len() {
                let end = (start + len).min(pairs.len());
                let (xs, ys): (Vec<f64>, Vec<f64>) = pairs[start..end].iter().copied().unzip();
                blocks.push_block(&xs, &ys);
                let expected = pairs[..end].iter().map(square).fold(0.0, f64::max).sqrt();
                assert_eq!(
                    blocks.value().to_bits(),
                    expected.to_bits(),
                    "{scale}: to {end}"
                );
                (start, len) = (end, len % LANES + 1);
            }
            for split in [0, 1, 7, 2_499, 4_999] {
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
