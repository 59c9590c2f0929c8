//! The whole machine as a per-step stage ([`MachineStage`]): at every step every cylinder of
//! the [`Machine`] at its own crank angle, axis and gas phase, loaded by the run's own load
//! families (the closed forms, or the general solve where the mechanism has none), and from
//! them the machine's drive torque (every cylinder's gas and inertia, and with `[friction]`
//! every cylinder's losses), its main journals' and crank pins' loads, each cylinder's gas
//! force, and where the case asks for them (`[layout]` or `[balance]`:
//! [`Machine::shaking_per_step`]) its shaking force and free moments (`cardan-balance`),
//! which a case that does not ask need not pay for at every step; its accumulator
//! ([`MachineTotals`]) makes the machine's metrics (`metrics::MACHINE`) and the balance's,
//! with the orders at constant speed over one revolution whatever the run's motion.
//!
//! The run's own train is the mechanism at the machine's crank angle in its own frame: where
//! that is cylinder 1 ([`Machine::train_is_first`]: every layout but a vee), cylinder 1's
//! state and loads are the step's own, and its works and losses the run's (so that a machine
//! of one cylinder has the train's figures bit for bit); every other cylinder is loaded here,
//! a block at a time. With `[friction]` the stage comes after the train's loss budget, whose
//! loss it takes from [`PassedOn::loss_power`], and charges each other cylinder's losses by a
//! loss budget of its own (the case's friction at that cylinder's state and loads; a rated
//! mesh's loss computed by the budget, the same figure as the rating's).

use crate::family::{Gas, Inertial, LoadFamily};
use crate::losses::LossBudget;
use crate::machine::Machine;
use crate::machine_totals::{MachineTotals, Places};
use crate::metrics::{self, MetricDef};
use crate::stage::{
    Block, GasAt, LaneError, PassedOn, Stage, StageColumn, StageError, StageTotals,
};
use crate::stepper::Loading;
use crate::LossLanes;
use cardan_balance::{shaking_lane, Shaking};
use cardan_mechanism::vectorised;
use cardan_mechanism::{Column, CrankState, LoadsBlock, Mechanism, StateBlock, C, LANES, ZERO};
use std::sync::Arc;

/// The stage's first per-step columns where the case asks for the machine's shaking step by
/// step (`[layout]` or `[balance]`): its shaking force (x, y) and free moment (pitch, yaw);
/// then [`TORQUE_COLUMN`], each main journal's load (x, y in the machine frame), each
/// cylinder's crank-pin load (x, y in the machine frame) and gas force
/// ([`MachineStage::columns`]).
pub const SHAKING_COLUMNS: [&str; 4] = [
    "shaking_force_x_n",
    "shaking_force_y_n",
    "shaking_moment_pitch_nm",
    "shaking_moment_yaw_nm",
];

/// The machine's drive torque's column.
pub const TORQUE_COLUMN: &str = "machine_torque_nm";

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
    /// Gas force on each of its pistons, N.
    gas_force: f64,
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
    /// One cylinder's loss components at each lane, W.
    parts: Vec<Column>,
    /// Each cylinder at each lane of the block, cylinder by cylinder.
    at: Vec<CylinderAt>,
}

impl MachineStage {
    /// The stage of the machine `machine`, its orders taken at `order_speed` (rad/s); `gas`:
    /// whether the case has a gas model; `losses`: the case's loss budget of the mechanism
    /// (with `[friction]`), copied for each cylinder the stage loads itself. The machine's
    /// shaking step by step ([`SHAKING_COLUMNS`] and their peaks) where the case asks for it
    /// ([`Machine::shaking_per_step`]); the orders, taken over one revolution at the finish,
    /// are every run's.
    pub fn new(
        machine: Arc<Machine>,
        order_speed: f64,
        gas: bool,
        losses: Option<&LossBudget>,
    ) -> Self {
        let n = machine.cylinders();
        let own = n - usize::from(machine.train_is_first());
        let places = Places {
            shaking: machine.shaking_per_step,
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
    /// (cylinder by cylinder), but the train's where it is cylinder 1 (the caller's); an error
    /// names the lane of a loss budget that fails.
    fn load_cylinders(&mut self, gas: Option<GasAt>, lanes: usize) -> Result<(), LaneError> {
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
                    (pressure[k], room.force[k]) = g.at(c.angle - phase.firing_delay);
                }
            }
            let applied = gas.map(|_| &room.force);
            loading.loads(m, &room.block, applied, &mut room.loads, &mut room.total);
            let total = if total_is_first {
                &room.loads[0]
            } else {
                &room.total
            };
            let losses = match self.losses.get_mut(i - first) {
                Some(budget) => {
                    room.parts.resize(budget.names().len(), ZERO);
                    let at = LossLanes {
                        lanes: 0..lanes,
                        states: &room.block,
                        total,
                        pressure: gas.map(|_| &pressure),
                        rated_meshes: &[],
                    };
                    budget
                        .evaluate(&at, &mut room.parts)
                        .map_err(|f| StageError::Failed(f.why).at_lane(f.lane))?;
                    true
                }
                None => false,
            };
            for k in 0..lanes {
                let mut at = CylinderAt {
                    shaking: match self.places.shaking {
                        true => shaking_lane(t, &room.block, k),
                        false => Shaking::default(),
                    },
                    torque: total.crank_torque[k],
                    gas_torque: room.loads.get(1).map_or(0.0, |g| g.crank_torque[k]),
                    gas_force: gas.map_or(0.0, |_| room.force[k]),
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
                if losses {
                    at.loss = room.parts.iter().map(|c| c[k]).sum();
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
        if self.places.shaking {
            let s = self
                .machine
                .balance()
                .sum((0..n).map(|i| at(i).shaking), crank);
            out[0] = s.force.re;
            out[1] = s.force.im;
            out[2] = s.pitch();
            out[3] = s.yaw();
        }
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
        out[p.torque()] = torque;
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
                at: Vec::new(),
            })
        })
    }
}

/// The train as cylinder 1 at lane `i` of the block `input`, from its columns (its shaking
/// where `shaking`).
fn train_lane(machine: &Machine, input: &Block, i: usize, shaking: bool) -> CylinderAt {
    let total = input.total;
    let joint = |j: Option<usize>| {
        j.map_or(C::new(0.0, 0.0), |j| {
            let l = &total.joints[j];
            machine.axis(0) * C::new(l.fx[i], l.fy[i])
        })
    };
    CylinderAt {
        shaking: match shaking {
            true => shaking_lane(machine.mechanism().topology(), input.states, i),
            false => Shaking::default(),
        },
        torque: total.crank_torque[i],
        main: joint(machine.main_bearing()),
        pin: joint(machine.crank_pin()),
        gas_force: input.force.map_or(0.0, |f| f[i]),
        ..CylinderAt::default()
    }
}

impl Stage for MachineStage {
    fn width(&self) -> usize {
        self.places.width()
    }

    /// Every lane of the block (module note): the train's columns as cylinder 1 where it is.
    fn evaluate(
        &mut self,
        input: &Block,
        passed: &mut PassedOn,
        out: &mut [Column],
    ) -> Result<(), LaneError> {
        let n = input.len;
        let train_loss = passed.loss_power.as_ref();
        if self.machine.cylinders() == 1 && self.machine.train_is_first() {
            one_cylinder_block(self, input, train_loss, out);
            return self.check_block(n, out);
        }
        let room = self.room();
        room.cranks.clear();
        room.cranks.extend((0..n).map(|i| input.states.crank.at(i)));
        self.load_cylinders(input.gas, n)?;
        let mut row = std::mem::take(&mut self.row);
        row.resize(self.width(), 0.0);
        for i in 0..n {
            let mut loss = 0.0;
            if self.machine.train_is_first() {
                let train = train_lane(&self.machine, input, i, self.places.shaking);
                self.room.as_mut().expect("room made").at[i] = train;
                loss = train_loss.map_or(0.0, |l| l[i]);
            }
            let crank = input.states.crank.at(i);
            self.values(i, &crank, loss, &mut row);
            for (c, v) in out.iter_mut().zip(&row) {
                c[i] = *v;
            }
        }
        self.row = row;
        self.check_block(n, out)
    }

    fn columns(&self) -> Vec<StageColumn> {
        let p = self.places;
        let mut columns: Vec<(usize, String)> = match p.shaking {
            true => SHAKING_COLUMNS
                .iter()
                .enumerate()
                .map(|(v, c)| (v, c.to_string()))
                .collect(),
            false => Vec::new(),
        };
        columns.push((p.torque(), TORQUE_COLUMN.into()));
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
        let machine = Arc::clone(&self.machine);
        let totals = MachineTotals::new(machine, self.places, self.order_speed, self.friction);
        Box::new(totals)
    }

    fn carries_history(&self) -> bool {
        self.losses.iter().any(LossBudget::carries_history)
    }

    fn fork(&self) -> Box<dyn Stage> {
        Box::new(self.clone())
    }
}

/// The first `n` values of the neighbouring columns `k` and `k + 1` of `out` (a load's x and y).
#[inline(always)]
fn column_pair(out: &mut [Column], k: usize, n: usize) -> (&mut [f64], &mut [f64]) {
    let (x, rest) = out[k..].split_at_mut(1);
    (&mut x[0][..n], &mut rest[0][..n])
}

vectorised! {
    /// A block of a machine of one cylinder, the run's train (module note): its values from the
    /// train's columns a column at a time, with the operations of `MachineStage::values` in
    /// its order (the same bits) but without gathering each lane's cylinder and row;
    /// `train_loss`: the train's power loss at each lane (with `[friction]`), W.
    fn one_cylinder_block(
        stage: &MachineStage,
        input: &Block,
        train_loss: Option<&Column>,
        out: &mut [Column],
    ) {
        // A whole block (most blocks): loops of a known count, which the compiler unrolls.
        match input.len >= LANES {
            true => one_cylinder_lanes(stage, input, train_loss, out, LANES),
            false => one_cylinder_lanes(stage, input, train_loss, out, input.len),
        }
    }
}

/// [`one_cylinder_block`] over the first `n` lanes.
// A lane index runs over several columns of `out` and of the inputs at once.
#[allow(clippy::needless_range_loop)]
#[inline(always)]
fn one_cylinder_lanes(
    stage: &MachineStage,
    input: &Block,
    train_loss: Option<&Column>,
    out: &mut [Column],
    n: usize,
) {
    let n = n.min(LANES);
    let p = stage.places;
    let m = &*stage.machine;
    let t = m.mechanism().topology();
    let total = input.total;
    if p.shaking {
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
    }
    let others = p.others();
    for c in &mut out[others..others + 3] {
        c[..n].fill(0.0);
    }
    let torque = &mut out[p.torque()][..n];
    for (t, &c) in torque.iter_mut().zip(&total.crank_torque[..n]) {
        *t = 0.0 + c;
    }
    if stage.friction {
        let speed = &input.states.crank.speed[..n];
        for (i, (t, &w)) in torque.iter_mut().zip(speed).enumerate() {
            let loss = 0.0 + train_loss.map_or(0.0, |l| l[i]);
            if w != 0.0 {
                *t += loss / w.abs();
            }
        }
    }
    for j in 0..p.journals {
        out[p.journal(j)][..n].fill(0.0);
        out[p.journal(j) + 1][..n].fill(0.0);
    }
    let zero = [0.0; LANES];
    let load = |j: Option<usize>| match j {
        Some(j) => (&total.joints[j].fx[..n], &total.joints[j].fy[..n]),
        None => (&zero[..n], &zero[..n]),
    };
    let axis = m.axis(0);
    for (j, share) in m.journals_of(0) {
        let (x, y) = column_pair(out, p.journal(j), n);
        let (fx, fy) = load(m.main_bearing());
        for (((x, y), &fx), &fy) in x.iter_mut().zip(y).zip(fx).zip(fy) {
            let main = axis * C::new(fx, fy);
            *x += share * main.re;
            *y += share * main.im;
        }
    }
    if p.pins {
        let (x, y) = column_pair(out, p.pin(0), n);
        let (fx, fy) = load(m.crank_pin());
        for (((x, y), &fx), &fy) in x.iter_mut().zip(y).zip(fx).zip(fy) {
            let pin = axis * C::new(fx, fy);
            (*x, *y) = (pin.re, pin.im);
        }
    }
    if p.gas {
        let gas = &mut out[p.gas(0)][..n];
        match input.force {
            Some(f) => gas.copy_from_slice(&f[..n]),
            None => gas.fill(0.0),
        }
    }
}

impl MachineStage {
    /// Checks a block's `n` lanes of values `out`: the error of the first value not finite.
    fn check_block(&self, n: usize, out: &[Column]) -> Result<(), LaneError> {
        if sum_is_finite(out, n) {
            return Ok(());
        }
        for i in 0..n {
            if let Some(k) = out.iter().position(|c| !c[i].is_finite()) {
                return Err(self.not_finite(k, out[k][i]).at_lane(i));
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

vectorised! {
    /// Whether the sum of the first `n` values of every column of `out` is finite, in eight
    /// running sums: a NaN or an infinity makes it not (as the stepper's `all_finite`); only
    /// then, or when finite values overflow it, are the lanes checked one by one.
    fn sum_is_finite(out: &[Column], n: usize) -> bool {
        let n = n.min(LANES);
        let mut acc = [0.0; 8];
        for c in out {
            // A whole block (most blocks): a slice of a known length, whose loop the compiler
            // unrolls; the same additions in the same order.
            match n == LANES {
                true => add_by_eight(&mut acc, c),
                false => add_by_eight(&mut acc, &c[..n]),
            }
        }
        acc.iter().sum::<f64>().is_finite()
    }
}

/// Adds `values` to `acc`, value i to sum i mod 8.
#[inline(always)]
fn add_by_eight(acc: &mut [f64; 8], values: &[f64]) {
    let chunks = values.chunks_exact(8);
    let rest = chunks.remainder();
    for chunk in chunks {
        for (a, v) in acc.iter_mut().zip(chunk) {
            *a += v;
        }
    }
    for (a, v) in acc.iter_mut().zip(rest) {
        *a += v;
    }
}
