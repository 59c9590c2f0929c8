//! The whole machine as a per-step stage ([`MachineStage`]): at every step every cylinder of
//! the [`Machine`] at its own crank angle, axis and gas phase, loaded by the run's own load
//! families (the closed forms, or the general solve where the mechanism has none), and from
//! them the machine's drive torque (every cylinder's gas and inertia, and with `[friction]`
//! every cylinder's losses), its main journals' and crank pins' loads, each cylinder's gas
//! force, and its shaking force and free moments (`cardan-balance`); its accumulator
//! ([`MachineTotals`]) makes the machine's metrics (`metrics::MACHINE`) and the balance's,
//! with the orders at constant speed over one revolution whatever the run's motion.
//!
//! The run's own train is the mechanism at the machine's crank angle in its own frame: where
//! that is cylinder 1 ([`Machine::train_is_first`]: every layout but a vee), cylinder 1's
//! state and loads are the step's own, and its works and losses the run's (so that a machine
//! of one cylinder has the train's figures bit for bit); every other cylinder is loaded here.
//! Without `[friction]` the stage evaluates a block at a time from the block's columns
//! ([`Stage::by_block`]); with it, a step at a time, after the train's loss budget, whose loss
//! it takes from [`Handed::loss_power`], each other cylinder's losses by a loss budget of its
//! own (the case's friction at that cylinder's state and loads; a rated mesh's loss computed
//! by the budget, the same figure as the rating's).

use crate::family::{Gas, Inertial, LoadFamily};
use crate::losses::LossBudget;
use crate::machine::Machine;
use crate::metrics::{self, MetricDef, Summary};
use crate::stage::{
    BlockInput, GasAt, Handed, RunTotals, Stage, StageColumn, StageError, StageInput, StageTotals,
};
use crate::step::StepBlock;
use crate::stepper::Loading;
use crate::summary::peaks::raise;
use crate::summary::Integral;
use cardan_balance::{shaking, shaking_lane, Shaking};
use cardan_mechanism::{
    Column, CrankState, Loads, LoadsBlock, Mechanism, State, StateBlock, C, LANES,
};
use std::any::Any;
use std::ops::Range;
use std::sync::Arc;

/// The stage's first per-step columns: the machine's shaking force (x, y) and free moment
/// (pitch, yaw), its drive torque; then each main journal's load (x, y in the machine frame),
/// each cylinder's crank-pin load (x, y in the machine frame) and gas force
/// ([`MachineStage::columns`]).
pub const COLUMNS: [&str; 5] = [
    "shaking_force_x_n",
    "shaking_force_y_n",
    "shaking_moment_pitch_nm",
    "shaking_moment_yaw_nm",
    "machine_torque_nm",
];

/// Where each of the stage's values sits in its row of values.
#[derive(Debug, Clone, Copy)]
struct Places {
    cylinders: usize,
    journals: usize,
    /// Whether the mechanism has a crank pin (its columns).
    pins: bool,
    /// Whether the case has a gas model (the gas forces' columns).
    gas: bool,
}

impl Places {
    const TORQUE: usize = 4;

    fn journal(&self, j: usize) -> usize {
        5 + 2 * j
    }

    fn pin(&self, k: usize) -> usize {
        self.journal(self.journals) + 2 * k
    }

    fn gas(&self, k: usize) -> usize {
        self.pin(if self.pins { self.cylinders } else { 0 }) + k
    }

    /// The values no column shows: the cylinders' apart from the train's drive torque (gas and
    /// inertia), gas torque and loss power.
    fn others(&self) -> usize {
        self.gas(if self.gas { self.cylinders } else { 0 })
    }

    fn width(&self) -> usize {
        self.others() + 3
    }
}

/// One cylinder at one step, in the machine frame.
#[derive(Debug, Clone, Copy, Default)]
struct CylinderAt {
    shaking: Shaking,
    /// Drive torque of its gas and inertia, and of its gas alone, N·m.
    torque: f64,
    gas_torque: f64,
    /// Its main bearing's and crank pin's loads (on the crankshaft), N.
    main: C,
    pin: C,
    /// Gas force on each of its pistons, N, and the absolute pressure, Pa.
    gas_force: f64,
    pressure: Option<f64>,
    /// Its power loss, W.
    loss: f64,
}

/// The whole machine as a stage (module note).
#[derive(Debug, Clone)]
pub struct MachineStage {
    machine: Arc<Machine>,
    places: Places,
    /// Speed of the revolution the orders are taken over, rad/s.
    order_speed: f64,
    inertial: Inertial,
    gas: Option<Gas>,
    /// Each cylinder's loss budget apart from the train's (with `[friction]`).
    losses: Vec<LossBudget>,
    friction: bool,
    /// Room for the cylinders' states and loads (made at the first block that needs it: some
    /// 30 kB a block, and a sweep holds a stage per point).
    room: Option<Box<Room>>,
    /// A row of the stage's values, kept from block to block.
    row: Vec<f64>,
}

/// The stage's working space.
#[derive(Debug, Clone)]
struct Room {
    block: StateBlock,
    loads: Vec<LoadsBlock>,
    total: LoadsBlock,
    force: Column,
    cranks: Vec<CrankState>,
    /// One cylinder's crank states at the machine's `cranks`.
    own: Vec<CrankState>,
    /// One cylinder's loss components at a step, W.
    parts: Vec<f64>,
    state: State,
    one: Loads,
    /// Each cylinder at each lane of the block, cylinder by cylinder.
    at: Vec<CylinderAt>,
}

impl MachineStage {
    /// The stage of the machine `machine`, its orders taken at `order_speed` (rad/s); `gas`:
    /// whether the case has a gas model; `losses`: the case's loss budget of the mechanism
    /// (with `[friction]`), copied for each cylinder the stage loads itself.
    pub fn new(
        machine: Arc<Machine>,
        order_speed: f64,
        gas: bool,
        losses: Option<&LossBudget>,
    ) -> Self {
        let n = machine.cylinders();
        let own = n - usize::from(machine.train_is_first());
        let places = Places {
            cylinders: n,
            journals: machine.journals(),
            pins: machine.crank_pin().is_some() && machine.main_bearing().is_some(),
            gas,
        };
        let (inertial, gas_family) = machine.load_families(gas);
        Self {
            inertial,
            gas: gas_family,
            losses: losses.map_or(vec![], |l| vec![l.clone(); own]),
            friction: losses.is_some(),
            places,
            order_speed,
            room: None,
            row: Vec::new(),
            machine,
        }
    }

    /// The machine.
    pub fn machine(&self) -> &Machine {
        &self.machine
    }

    /// Every cylinder at the machine's crank angles `cranks` (a lane each) into `room.at`
    /// (cylinder by cylinder), but the train's where it is cylinder 1 (the caller's).
    fn load_cylinders(&mut self, gas: Option<GasAt>, lanes: usize) -> Result<(), StageError> {
        let m: &dyn Mechanism = self.machine.mechanism().as_ref();
        let t = m.topology();
        let n = self.machine.cylinders();
        let room = self.room.as_mut().expect("room made");
        room.at.resize(n * LANES, CylinderAt::default());
        let first = usize::from(self.machine.train_is_first());
        if first == n {
            return Ok(());
        }
        let families: Vec<&dyn LoadFamily> = match &self.gas {
            Some(g) => vec![&self.inertial, g],
            None => vec![&self.inertial],
        };
        let loading = Loading::new(&families, t);
        let total_is_first = families.len() == 1;
        for i in first..n {
            let phase = self.machine.phases()[i];
            let axis = self.machine.axis(i);
            room.own.clear();
            room.own.extend(
                room.cranks[..lanes].iter().map(|c| {
                    CrankState::new(c.angle + phase.lead, c.speed, c.acceleration, c.time)
                }),
            );
            room.block.fill(m, &room.own);
            let mut pressure = [0.0; LANES];
            if let Some(g) = gas {
                for (k, c) in room.cranks[..lanes].iter().enumerate() {
                    (pressure[k], room.force[k]) = g(c.angle - phase.firing_delay);
                }
            }
            let applied = gas.map(|_| &room.force);
            loading.loads(m, &room.block, applied, &mut room.loads, &mut room.total);
            let total = if total_is_first {
                &room.loads[0]
            } else {
                &room.total
            };
            for (k, &p) in pressure[..lanes].iter().enumerate() {
                let mut at = CylinderAt {
                    shaking: shaking_lane(t, &room.block, k),
                    torque: total.crank_torque[k],
                    gas_torque: room.loads.get(1).map_or(0.0, |g| g.crank_torque[k]),
                    gas_force: gas.map_or(0.0, |_| room.force[k]),
                    pressure: gas.map(|_| p),
                    ..CylinderAt::default()
                };
                if let Some(j) = self.machine.main_bearing() {
                    let l = &total.joints[j];
                    at.main = axis * C::new(l.fx[k], l.fy[k]);
                }
                if let Some(j) = self.machine.crank_pin() {
                    let l = &total.joints[j];
                    at.pin = axis * C::new(l.fx[k], l.fy[k]);
                }
                if let Some(budget) = self.losses.get_mut(i - first) {
                    room.block.gather(k, &mut room.state);
                    total.gather(k, &mut room.one);
                    room.parts.resize(budget.names().len(), 0.0);
                    budget
                        .evaluate(&room.state, &room.one, at.pressure, &[], &mut room.parts)
                        .map_err(StageError::Failed)?;
                    at.loss = room.parts.iter().sum();
                }
                room.at[i * LANES + k] = at;
            }
        }
        Ok(())
    }

    /// The stage's values at lane `k` of the block (the cylinders in `room.at`, the train's
    /// included), into `out`; `train_loss`: the train's power loss where it is cylinder 1.
    fn values(&self, k: usize, crank: &CrankState, train_loss: f64, out: &mut [f64]) {
        let room = self.room.as_ref().expect("room made");
        let n = self.machine.cylinders();
        let first = usize::from(self.machine.train_is_first());
        let at = |i: usize| &room.at[i * LANES + k];
        let s = self
            .machine
            .balance()
            .sum((0..n).map(|i| at(i).shaking), crank);
        out[0] = s.force.re;
        out[1] = s.force.im;
        out[2] = s.pitch();
        out[3] = s.yaw();
        let p = self.places;
        let (mut torque, mut gas_torque, mut loss) = (0.0, 0.0, 0.0);
        for i in first..n {
            torque += at(i).torque;
            gas_torque += at(i).gas_torque;
            loss += at(i).loss;
        }
        let others = p.others();
        out[others] = torque;
        out[others + 1] = gas_torque;
        out[others + 2] = loss;
        if first == 1 {
            torque += at(0).torque;
            loss += train_loss;
        }
        if self.friction && crank.speed != 0.0 {
            torque += loss / crank.speed.abs();
        }
        out[Places::TORQUE] = torque;
        for j in 0..p.journals {
            out[p.journal(j)] = 0.0;
            out[p.journal(j) + 1] = 0.0;
        }
        for i in 0..n {
            let c = at(i);
            for (j, share) in self.machine.journals_of(i) {
                out[p.journal(j)] += share * c.main.re;
                out[p.journal(j) + 1] += share * c.main.im;
            }
            if p.pins {
                out[p.pin(i)] = c.pin.re;
                out[p.pin(i) + 1] = c.pin.im;
            }
            if p.gas {
                out[p.gas(i)] = c.gas_force;
            }
        }
    }

    /// The room, made at its first use.
    fn room(&mut self) -> &mut Room {
        let t = self.machine.mechanism().topology();
        let families = 1 + usize::from(self.gas.is_some());
        self.room.get_or_insert_with(|| {
            Box::new(Room {
                block: StateBlock::for_topology(t),
                loads: vec![LoadsBlock::for_topology(t); families],
                total: LoadsBlock::for_topology(t),
                force: [0.0; LANES],
                cranks: Vec::with_capacity(LANES),
                own: Vec::with_capacity(LANES),
                parts: Vec::new(),
                state: State::for_topology(t),
                one: Loads::for_topology(t),
                at: Vec::new(),
            })
        })
    }
}

/// The train as cylinder 1 at one step, in the machine frame (its axis is the machine's).
fn train_at(machine: &Machine, input: &StageInput) -> CylinderAt {
    let total = input.total;
    let joint = |j: Option<usize>| {
        j.map_or(C::new(0.0, 0.0), |j| {
            let l = &total.joints[j];
            machine.axis(0) * l.force
        })
    };
    CylinderAt {
        shaking: shaking(machine.mechanism().topology(), input.state),
        torque: total.crank_torque,
        main: joint(machine.main_bearing()),
        pin: joint(machine.crank_pin()),
        gas_force: input.force.unwrap_or(0.0),
        pressure: input.pressure,
        ..CylinderAt::default()
    }
}

/// The train as cylinder 1 at lane `i` of the block `input`, from its columns.
fn train_lane(machine: &Machine, input: &BlockInput, i: usize) -> CylinderAt {
    let total = input.total;
    let joint = |j: Option<usize>| {
        j.map_or(C::new(0.0, 0.0), |j| {
            let l = &total.joints[j];
            machine.axis(0) * C::new(l.fx[i], l.fy[i])
        })
    };
    CylinderAt {
        shaking: shaking_lane(machine.mechanism().topology(), input.states, i),
        torque: total.crank_torque[i],
        main: joint(machine.main_bearing()),
        pin: joint(machine.crank_pin()),
        gas_force: input.force.map_or(0.0, |f| f[i]),
        pressure: input.pressure.map(|p| p[i]),
        ..CylinderAt::default()
    }
}

impl Stage for MachineStage {
    fn width(&self) -> usize {
        self.places.width()
    }

    fn evaluate(
        &mut self,
        input: &StageInput,
        handed: &mut Handed,
        out: &mut [f64],
    ) -> Result<(), StageError> {
        let crank = input.state.crank;
        let room = self.room();
        room.cranks.clear();
        room.cranks.push(crank);
        self.load_cylinders(input.gas, 1)?;
        let mut train_loss = 0.0;
        if self.machine.train_is_first() {
            let train = train_at(&self.machine, input);
            self.room.as_mut().expect("room made").at[0] = train;
            train_loss = handed.loss_power.unwrap_or(0.0);
        }
        self.values(0, &crank, train_loss, out);
        match out.iter().position(|v| !v.is_finite()) {
            Some(k) => Err(self.not_finite(k, out[k])),
            None => Ok(()),
        }
    }

    fn by_block(&self) -> bool {
        !self.friction
    }

    /// Every lane of the block (module note): the train's columns as cylinder 1 where it is.
    fn evaluate_block(
        &mut self,
        input: &BlockInput,
        out: &mut [Column],
    ) -> Result<(), (usize, StageError)> {
        let n = input.states.len;
        if self.machine.cylinders() == 1 && self.machine.train_is_first() {
            self.one_cylinder_block(input, out);
            return self.check_block(n, out);
        }
        let room = self.room();
        room.cranks.clear();
        room.cranks.extend((0..n).map(|i| input.states.crank.at(i)));
        self.load_cylinders(input.gas, n).map_err(|e| (0, e))?;
        let mut row = std::mem::take(&mut self.row);
        row.resize(self.width(), 0.0);
        for i in 0..n {
            if self.machine.train_is_first() {
                let train = train_lane(&self.machine, input, i);
                self.room.as_mut().expect("room made").at[i] = train;
            }
            let crank = input.states.crank.at(i);
            self.values(i, &crank, 0.0, &mut row);
            for (c, v) in out.iter_mut().zip(&row) {
                c[i] = *v;
            }
        }
        self.row = row;
        self.check_block(n, out)
    }

    fn columns(&self) -> Vec<StageColumn> {
        let p = self.places;
        let mut columns: Vec<(usize, String)> = (0..5).map(|v| (v, COLUMNS[v].into())).collect();
        for j in 0..p.journals {
            for (d, axis) in [(0, "x"), (1, "y")] {
                let name = format!("main_bearing_{}_force_{axis}_n", j + 1);
                columns.push((p.journal(j) + d, name));
            }
        }
        for i in 0..p.cylinders {
            if p.pins {
                for (d, axis) in [(0, "x"), (1, "y")] {
                    let name = format!("cylinder_{}_crank_pin_force_{axis}_n", i + 1);
                    columns.push((p.pin(i) + d, name));
                }
            }
        }
        if p.gas {
            for i in 0..p.cylinders {
                columns.push((p.gas(i), format!("cylinder_{}_gas_force_n", i + 1)));
            }
        }
        columns
            .into_iter()
            .map(|(value, name)| StageColumn { name, value })
            .collect()
    }

    fn metrics(&self) -> &'static [MetricDef] {
        metrics::MACHINE
    }

    fn totals(&self) -> Box<dyn StageTotals> {
        let p = self.places;
        Box::new(MachineTotals {
            machine: Arc::clone(&self.machine),
            places: p,
            order_speed: self.order_speed,
            friction: self.friction,
            force: 0.0,
            moment: 0.0,
            journal: 0.0,
            pin: 0.0,
            pins: vec![C::new(0.0, 0.0); self.machine.pins()],
            torque: None,
            work: Integral::default(),
            gas_work: Integral::default(),
            loss_work: Integral::default(),
            previous: None,
            others: self.machine.cylinders() > usize::from(self.machine.train_is_first()),
        })
    }

    fn carries_history(&self) -> bool {
        self.losses.iter().any(LossBudget::carries_history)
    }

    fn fork(&self) -> Box<dyn Stage> {
        Box::new(self.clone())
    }
}

impl MachineStage {
    /// A block of a machine of one cylinder, the run's train (module note): its values from the
    /// train's columns a column at a time, with the operations of [`MachineStage::values`] in
    /// its order (the same bits) but without gathering each lane's cylinder and row.
    fn one_cylinder_block(&self, input: &BlockInput, out: &mut [Column]) {
        let n = input.states.len;
        let p = self.places;
        let m = &*self.machine;
        let t = m.mechanism().topology();
        let total = input.total;
        let joint =
            |j: usize, i: usize| m.axis(0) * C::new(total.joints[j].fx[i], total.joints[j].fy[i]);
        for i in 0..n {
            let crank = input.states.crank.at(i);
            let s = m
                .balance()
                .sum(std::iter::once(shaking_lane(t, input.states, i)), &crank);
            out[0][i] = s.force.re;
            out[1][i] = s.force.im;
            out[2][i] = s.pitch();
            out[3][i] = s.yaw();
        }
        let others = p.others();
        for c in &mut out[others..others + 3] {
            c[..n].fill(0.0);
        }
        for i in 0..n {
            out[Places::TORQUE][i] = 0.0 + total.crank_torque[i];
        }
        for j in 0..p.journals {
            out[p.journal(j)][..n].fill(0.0);
            out[p.journal(j) + 1][..n].fill(0.0);
        }
        if let Some(b) = m.main_bearing() {
            for (j, share) in m.journals_of(0) {
                for i in 0..n {
                    let main = joint(b, i);
                    out[p.journal(j)][i] += share * main.re;
                    out[p.journal(j) + 1][i] += share * main.im;
                }
            }
        } else {
            for (j, share) in m.journals_of(0) {
                for i in 0..n {
                    out[p.journal(j)][i] += share * 0.0;
                    out[p.journal(j) + 1][i] += share * 0.0;
                }
            }
        }
        if p.pins {
            for i in 0..n {
                let pin = m.crank_pin().map_or(C::new(0.0, 0.0), |j| joint(j, i));
                out[p.pin(0)][i] = pin.re;
                out[p.pin(0) + 1][i] = pin.im;
            }
        }
        if p.gas {
            for i in 0..n {
                out[p.gas(0)][i] = input.force.map_or(0.0, |f| f[i]);
            }
        }
    }

    /// Checks a block's `n` lanes of values `out`: the error of the first value not finite.
    fn check_block(&self, n: usize, out: &[Column]) -> Result<(), (usize, StageError)> {
        // One sum of every value first: a NaN or an infinity makes it so (as the stepper's
        // `all_finite`); only then, or when finite values overflow it, the lanes one by one.
        let sum: f64 = out.iter().map(|c| c[..n].iter().sum::<f64>()).sum();
        if sum.is_finite() {
            return Ok(());
        }
        for i in 0..n {
            if let Some(k) = out.iter().position(|c| !c[i].is_finite()) {
                return Err((i, self.not_finite(k, out[k][i])));
            }
        }
        Ok(())
    }

    /// The error of the stage's value `k` not finite, `value`.
    fn not_finite(&self, k: usize, value: f64) -> StageError {
        let quantity = match self.columns().into_iter().find(|c| c.value == k) {
            Some(c) => c.name,
            None => [
                "the other cylinders' drive torque",
                "the other cylinders' gas torque",
                "the other cylinders' power loss",
            ][k - self.places.others()]
            .to_string(),
        };
        StageError::NonFinite { quantity, value }
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
    /// Takes the stage's values at the steps `steps` (step number, crank angle in rad, time in
    /// s, in the steps' order), `value(i, place)` the value at `place` of the `i`-th of them.
    /// The peaks a value at a time over the steps (a peak is the same whatever the order), the
    /// integrals step by step in order.
    #[inline]
    fn take(&mut self, steps: &[(usize, f64, f64)], value: impl Fn(usize, usize) -> f64) {
        let p = self.places;
        let lanes = 0..steps.len();
        for i in lanes.clone() {
            raise_norm(&mut self.force, value(i, 0), value(i, 1));
        }
        for i in lanes.clone() {
            raise_norm(&mut self.moment, value(i, 2), value(i, 3));
        }
        for i in lanes.clone() {
            let torque = value(i, Places::TORQUE);
            self.torque = Some(match self.torque {
                None => (torque, torque),
                Some((lo, hi)) => (lo.min(torque), hi.max(torque)),
            });
        }
        for j in 0..p.journals {
            for i in lanes.clone() {
                raise_norm(
                    &mut self.journal,
                    value(i, p.journal(j)),
                    value(i, p.journal(j) + 1),
                );
            }
        }
        if p.pins {
            for i in lanes.clone() {
                self.pins.fill(C::new(0.0, 0.0));
                for k in 0..p.cylinders {
                    let pin = C::new(value(i, p.pin(k)), value(i, p.pin(k) + 1));
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
        for (i, &(k, angle, time)) in steps.iter().enumerate() {
            let now = [angle, time, value(i, o), value(i, o + 1), value(i, o + 2)];
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
        let columns = block.stage_columns.get(stage).filter(|c| !c.is_empty());
        if let Some(c) = columns {
            let crank = &block.state.crank;
            let mut steps = [(0, 0.0, 0.0); LANES];
            for (i, j) in lanes.clone().enumerate() {
                steps[i] = (block.first + j, crank.angle[j], crank.time[j]);
            }
            let start = lanes.start;
            self.take(&steps[..lanes.len()], |i, place| c[place][start + i]);
            return;
        }
        let steps = block.steps.get(lanes.clone()).unwrap_or_default();
        for (k, s) in (block.first + lanes.start..).zip(steps) {
            let crank = &s.state.crank;
            let v = &s.stages[stage];
            self.take(&[(k, crank.angle, crank.time)], |_, place| v[place]);
        }
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
