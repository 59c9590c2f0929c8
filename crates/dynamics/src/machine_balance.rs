//! The machine's balance as a per-step stage ([`MachineStage`]): at every step the shaking
//! force and free moments of all the machine's cylinders and rotors on the frame
//! (`cardan-balance`: [`PreparedBalance::at_state`]), and the machine's total drive torque, the
//! sum of every cylinder's; its accumulator ([`BalanceTotals`]) keeps their peaks and the
//! torque's mean, and takes the orders at constant speed over one revolution
//! ([`PreparedBalance::orders`]) whatever the run's motion (issue 24).
//!
//! For the torque, cylinder 1 is the run's own train: its state and total loads are the step's
//! (the machine's torque is then taken at a crank angle shifted by cylinder 1's β_1 − φ_1, a
//! constant). Every other cylinder i runs the same mechanism at its crank angle relative to
//! cylinder 1's, θ + (φ_i − β_i) − (φ_1 − β_1) (its throw and axis, as
//! [`cardan_balance::Layout::cylinder_crank`] places them: the same speed and acceleration, the
//! cylinders sharing the crankshaft, so this holds for any motion), with the gas of cylinder 1
//! `firing_delay[i]` later (the firing order), solved by the general planar solve (which the
//! closed forms equal to 1e-9, `tests/cross_checks.rs`). The drive torque of a machine is the
//! sum of its cylinders' (one crankshaft; Karhula 2008 A5.2.1.69 per cylinder); the rotors'
//! own inertia is not part of it.
//!
//! A machine of one cylinder is evaluated a block at a time from the block's columns
//! ([`Stage::by_block`], [`PreparedBalance::at_block`]; its torque is the step's own), the
//! same bits as step by step: a run without other stages or per-step files then gathers no
//! step. A machine of several cylinders solves each other cylinder's loads at every step
//! ([`planar::loads`] on one state), so it stays one step at a time.

use crate::metrics::{self, MetricDef, Summary};
use crate::planar;
use crate::stage::{Handed, RunTotals, Stage, StageColumn, StageError, StageInput, StageTotals};
use crate::step::StepBlock;
use crate::summary::peaks::raise;
use crate::summary::Integral;
use cardan_balance::{CylinderScratch, MachineBalance, Phase, PreparedBalance};
use cardan_mechanism::{Column, CrankState, Loads, LoadsBlock, Mechanism, State, StateBlock};
use std::any::Any;
use std::ops::Range;
use std::sync::Arc;

/// The per-step columns of the stage: the shaking force (x, y) and the free moment (pitch,
/// yaw) of the machine, then, for a machine of several cylinders, its total drive torque.
pub const COLUMNS: [&str; 5] = [
    "shaking_force_x_n",
    "shaking_force_y_n",
    "shaking_moment_pitch_nm",
    "shaking_moment_yaw_nm",
    "machine_torque_nm",
];

/// The machine's balance of one mechanism as a stage (module note).
#[derive(Debug, Clone)]
pub struct MachineStage {
    balance: Arc<PreparedBalance>,
    mechanism: Arc<dyn Mechanism>,
    /// Each cylinder's crank angle and gas phase relative to cylinder 1's.
    phases: Arc<[Phase]>,
    /// Speed of the revolution the orders are taken over, rad/s.
    order_speed: f64,
    /// Room for another cylinder's state, filled through a block of one lane (made at the
    /// first step that needs it: some 30 kB, and a sweep holds a stage per point) and loads.
    block: Option<Box<StateBlock>>,
    state: State,
    loads: Loads,
    /// Room for the states of the cylinders the balance evaluates apart from the step's.
    scratch: CylinderScratch,
}

impl MachineStage {
    /// The stage of `mechanism` in the machine `machine`, its orders taken at `order_speed`
    /// (rad/s); refused where a device of `machine` cannot be formed with the mechanism.
    pub fn new(
        machine: &MachineBalance,
        mechanism: Arc<dyn Mechanism>,
        order_speed: f64,
    ) -> Result<Self, String> {
        let balance = machine.prepare(Arc::clone(&mechanism))?;
        let t = mechanism.topology();
        Ok(Self {
            balance: Arc::new(balance),
            phases: machine.phases().into(),
            order_speed,
            block: None,
            state: State::for_topology(t),
            loads: Loads::for_topology(t),
            scratch: CylinderScratch::default(),
            mechanism,
        })
    }

    /// The machine's balance, prepared for this stage's mechanism (its crank masses load the
    /// main bearing: [`crate::Inertial::carrying`]).
    pub fn balance(&self) -> &PreparedBalance {
        &self.balance
    }

    fn cylinders(&self) -> usize {
        self.phases.len()
    }

    /// The machine's drive torque at the step `input`: cylinder 1's total, and every other
    /// cylinder's at its own angle and gas phase (module note).
    fn machine_torque(&mut self, input: &StageInput) -> f64 {
        let m = self.mechanism.as_ref();
        let t = m.topology();
        let crank = &input.state.crank;
        let mut torque = input.total.crank_torque;
        for i in 1..self.cylinders() {
            // Cylinder i relative to cylinder 1, which the run's train is (module note).
            let phase = self.phases[i];
            let at = CrankState::new(
                crank.angle + phase.lead,
                crank.speed,
                crank.acceleration,
                crank.time,
            );
            let block = self
                .block
                .get_or_insert_with(|| Box::new(StateBlock::for_topology(t)));
            block.fill(m, &[at]);
            block.gather(0, &mut self.state);
            let force = input.gas.map(|g| g(crank.angle - phase.firing_delay).1);
            let forces = force.map_or(vec![], |f| vec![f; t.pistons.len()]);
            planar::loads(
                t,
                &self.state,
                input.inertial.is_some(),
                &forces,
                &mut self.loads,
            );
            torque += self.loads.crank_torque;
        }
        torque
    }
}

impl Stage for MachineStage {
    fn width(&self) -> usize {
        COLUMNS.len()
    }

    fn evaluate(
        &mut self,
        input: &StageInput,
        _handed: &mut Handed,
        out: &mut [f64],
    ) -> Result<(), StageError> {
        let s = self.balance.at_state(input.state, &mut self.scratch);
        let torque = self.machine_torque(input);
        let values = [s.force.re, s.force.im, s.pitch(), s.yaw(), torque];
        if let Some(k) = values.iter().position(|v| !v.is_finite()) {
            return Err(not_finite(k, values[k]));
        }
        out.copy_from_slice(&values);
        Ok(())
    }

    fn by_block(&self) -> bool {
        self.cylinders() == 1 && self.balance.by_block()
    }

    /// One cylinder's balance over the block (module note): its torque is the step's total.
    fn evaluate_block(
        &mut self,
        states: &StateBlock,
        total: &LoadsBlock,
        out: &mut [Column],
    ) -> Result<(), (usize, StageError)> {
        let n = states.len;
        self.balance.at_block(states, &mut self.scratch, out);
        out[4][..n].copy_from_slice(&total.crank_torque[..n]);
        // One sum of every value first: a NaN or an infinity makes it so (as the stepper's
        // `all_finite`); only then, or when finite values overflow it, the lanes one by one.
        let sum: f64 = out.iter().map(|c| c[..n].iter().sum::<f64>()).sum();
        if sum.is_finite() {
            return Ok(());
        }
        for i in 0..n {
            if let Some(k) = out.iter().position(|c| !c[i].is_finite()) {
                return Err((i, not_finite(k, out[k][i])));
            }
        }
        Ok(())
    }

    fn columns(&self) -> Vec<StageColumn> {
        let shown = if self.cylinders() > 1 { 5 } else { 4 };
        (0..shown)
            .map(|value| StageColumn {
                name: COLUMNS[value].to_string(),
                value,
            })
            .collect()
    }

    fn metrics(&self) -> &'static [MetricDef] {
        metrics::BALANCE
    }

    fn totals(&self) -> Box<dyn StageTotals> {
        Box::new(BalanceTotals {
            balance: Arc::clone(&self.balance),
            order_speed: self.order_speed,
            force: 0.0,
            moment: 0.0,
            torque: None,
            work: Integral::default(),
            previous: None,
        })
    }

    fn fork(&self) -> Box<dyn Stage> {
        Box::new(self.clone())
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

/// The error of the stage's value `k` not finite, `value`.
fn not_finite(k: usize, value: f64) -> StageError {
    StageError::NonFinite {
        quantity: COLUMNS[k].to_string(),
        value,
    }
}

/// The balance's accumulator: the peaks of |F| and |M|, the machine torque's extremes and its
/// integral over the crank angle (its mean), the orders at its finish.
#[derive(Debug, Clone)]
pub struct BalanceTotals {
    balance: Arc<PreparedBalance>,
    order_speed: f64,
    force: f64,
    moment: f64,
    /// The machine torque's smallest and largest value so far.
    torque: Option<(f64, f64)>,
    /// ∫ T dθ, J.
    work: Integral,
    /// The angle and machine torque of the last step taken.
    previous: Option<(f64, f64)>,
}

impl BalanceTotals {
    /// Takes the stage's values `v` at step `k`, crank angle `angle` (rad).
    #[inline]
    fn take(&mut self, k: usize, angle: f64, v: &[f64]) {
        raise_norm(&mut self.force, v[0], v[1]);
        raise_norm(&mut self.moment, v[2], v[3]);
        let torque = v[4];
        self.torque = Some(match self.torque {
            None => (torque, torque),
            Some((lo, hi)) => (lo.min(torque), hi.max(torque)),
        });
        if let Some((a0, t0)) = self.previous {
            self.work.add(k, 0.5 * (angle - a0) * (torque + t0));
        }
        self.previous = Some((angle, torque));
    }
}

impl StageTotals for BalanceTotals {
    fn push_lanes(
        &mut self,
        block: &StepBlock,
        lanes: Range<usize>,
        stage: usize,
        _previous: Option<f64>,
    ) {
        let columns = block.stage_columns.get(stage).filter(|c| !c.is_empty());
        if let Some(c) = columns {
            for (k, j) in (block.first + lanes.start..).zip(lanes) {
                let v = [c[0][j], c[1][j], c[2][j], c[3][j], c[4][j]];
                self.take(k, block.state.crank.angle[j], &v);
            }
            return;
        }
        let steps = block.steps.get(lanes.clone()).unwrap_or_default();
        for (k, s) in (block.first + lanes.start..).zip(steps) {
            self.take(k, s.state.crank.angle, &s.stages[stage]);
        }
    }

    fn close_chunk(&mut self) {
        self.work.close_chunk();
    }

    fn merge(&mut self, later: &dyn StageTotals) {
        let later = later
            .as_any()
            .downcast_ref::<Self>()
            .expect("balance totals");
        raise(&mut self.force, later.force);
        raise(&mut self.moment, later.moment);
        self.torque = match (self.torque, later.torque) {
            (Some((a, b)), Some((c, d))) => Some((a.min(c), b.max(d))),
            (x, y) => x.or(y),
        };
        self.work.merge(&later.work);
        self.previous = later.previous;
    }

    fn finish(&self, run: &RunTotals, m: &mut Summary) {
        let orders = self.balance.orders(self.order_speed);
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
        let (Some((lo, hi)), true) = (self.torque, run.span > 0.0) else {
            return;
        };
        let mean = self.work.value() / run.span;
        // A mean that is round-off of a torque that swings both ways (an inertial run at
        // constant speed) is zero: no uniformity then.
        if mean.abs() > 1e-9 * (hi - lo) {
            m.push("torque_nonuniformity", (hi - lo) / mean.abs());
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
