//! The step loop: a motion source gives crank states (a prescribed one a block of
//! [`LANES`] at a time, straight into the block's columns), the mechanism fills its columns,
//! each load family its loads' columns, the finiteness of every step is checked, the stages
//! ([`Stage`]: the gear ratings, the loss budget, the machine) evaluate the block from its
//! columns into columns of their own, and the block is handed to the sinks (the summary reads
//! the columns; per-step files take the steps one at a time, gathered from the columns only
//! where they are wanted) and then forgotten. Nothing here grows with the number of steps.
//! [`crate::run_parallel`] shares one run among threads, each piece through this loop.

use crate::rooms::{RunRoom, RunRooms};
use crate::stage::{Block, LaneError, PassedOn, Stage, StageError};
use crate::step::{Sink, Step, StepBlock};
use cardan_loads::energy::torque_shares;
use cardan_loads::family::LoadFamily;
use cardan_mechanism::{
    vectorised, Column, Loads, LoadsBlock, Mechanism, MotionError, MotionSource, State, StateBlock,
    Topology, LANES, ZERO,
};

/// Why a run stopped.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum RunError {
    #[error("step {step}: {source}")]
    Motion { step: usize, source: MotionError },
    #[error("step {step} (crank angle {angle_deg:.4}°): {quantity} is not finite ({value})")]
    NonFinite {
        step: usize,
        angle_deg: f64,
        quantity: String,
        value: f64,
    },
    #[error("step {step}: {message}")]
    Sink { step: usize, message: String },
}

pub use crate::stage::GasAt;

/// Runs `mechanism` through every crank state of `motion`, with the loads of `families`, the
/// pistons pushed by `gas` if given, the `stages` evaluated in their order from the total
/// loads at every block, every step to every sink.
pub fn run(
    mechanism: &dyn Mechanism,
    motion: &mut dyn MotionSource,
    families: &[&dyn LoadFamily],
    gas: Option<GasAt>,
    stages: &mut [&mut dyn Stage],
    sinks: &mut [&mut dyn Sink],
) -> Result<(), RunError> {
    let room = &mut RunRoom::new(mechanism.topology(), families.len());
    run_in(room, mechanism, motion, families, gas, stages, sinks)
}

impl RunRooms {
    /// [`run`] in a kept room that fits, or a new one; the room is kept again if the run
    /// succeeds.
    pub fn run(
        &self,
        mechanism: &dyn Mechanism,
        motion: &mut dyn MotionSource,
        families: &[&dyn LoadFamily],
        gas: Option<GasAt>,
        stages: &mut [&mut dyn Stage],
        sinks: &mut [&mut dyn Sink],
    ) -> Result<(), RunError> {
        let (kind, mut room) = self.take(mechanism, families);
        run_in(&mut room, mechanism, motion, families, gas, stages, sinks)?;
        self.keep(kind, room);
        Ok(())
    }
}

/// [`run`] in the blocks of `room` (made for `mechanism` and `families`).
pub(crate) fn run_in(
    room: &mut RunRoom,
    mechanism: &dyn Mechanism,
    motion: &mut dyn MotionSource,
    families: &[&dyn LoadFamily],
    gas: Option<GasAt>,
    stages: &mut [&mut dyn Stage],
    sinks: &mut [&mut dyn Sink],
) -> Result<(), RunError> {
    let topology = mechanism.topology();
    // A prescribed motion's states come a block at a time, filled and loaded column by column
    // (`Mechanism::fill_block`, `LoadFamily::loads`) and taken so by the sinks
    // (`Sink::push_block`); a solved motion's one at a time, each after the torque of the one
    // before.
    let block = if motion.prescribed() { LANES } else { 1 };
    let RunRoom {
        states,
        loads,
        total,
    } = room;
    let (mut pressure, mut force) = ([0.0; LANES], [0.0; LANES]);
    let details = sinks.iter().any(|s| s.wants_details());
    let mut staged = StageValues::new(stages);
    // The steps one at a time, for the sinks that take them.
    let one_by_one = details || sinks.iter().any(|s| s.wants_steps());
    let pistons = if gas.is_some() {
        topology.pistons.len()
    } else {
        0
    };
    let fresh = StepOut::new(topology, families.len(), pistons, stages);
    let mut out = vec![fresh; if one_by_one { block } else { 0 }];
    // The allocation of the block's steps, kept from block to block.
    let mut spare: Vec<Step<'static>> = Vec::with_capacity(block);
    let mut previous_torque = None;
    // A part of a run numbers its steps as the whole run does.
    let mut index = motion.first_index();
    let mut loading = Loading::new(families, topology);
    loading.gas = gas;
    let mut ended = false;
    while !ended {
        let stopped;
        (stopped, ended) = next_states(states, mechanism, motion, block, index, previous_torque);
        let n = states.len;
        if let Some(g) = gas {
            g.lanes(states, &mut pressure, &mut force);
        }
        let applied = gas.map(|_| &force);
        let gas_pressure = gas.map(|_| &pressure);
        loading.loads(mechanism, states, applied, loads, total);
        let total: &LoadsBlock = if loading.several { total } else { &loads[0] };
        // The first step whose loads are not finite, if one is: the run fails there, unless
        // a stage fails before it.
        let unclean = match loading.all_finite(states, gas_pressure, loads, total) {
            true => None,
            false => {
                let gas = gas.map(|_| (&pressure, &force));
                loading.first_not_finite(index, states, gas, loads, total, mechanism)
            }
        };
        if let Some(t) = total.crank_torque[..n].last() {
            previous_torque = Some(*t);
        }
        let input = Block {
            len: unclean.as_ref().map_or(n, |(lane, _)| *lane),
            states,
            total,
            inertial: loading.inertial.map(|k| &loads[k]),
            pressure: gas_pressure,
            force: applied,
            gas,
        };
        if let Some(e) = staged.evaluate(stages, &input) {
            return Err(e.error.at(index + e.lane, states.crank.angle[e.lane]));
        }
        if let Some((_, e)) = unclean {
            return Err(e);
        }
        for (i, o) in out.iter_mut().take(n).enumerate() {
            let lane = Lane {
                states,
                i,
                force: force[i],
                loads,
                total,
            };
            o.take(&lane, &loading, mechanism, details, &staged.columns);
        }
        // The block's steps, in an allocation kept from block to block (emptied, it takes
        // steps borrowing this block's results).
        let mut steps: Vec<Step> = spare.into_iter().map(|_| unreachable!()).collect();
        steps.extend(out.iter().take(n).enumerate().map(|(j, o)| Step {
            index: index + j,
            state: &o.state,
            pressure: gas.map(|_| pressure[j]),
            piston_forces: &o.forces,
            families: &o.loads,
            total: if loading.several {
                &o.total
            } else {
                &o.loads[0]
            },
            stages: &o.stages,
            shares: &o.shares,
        }));
        let taken = StepBlock {
            first: index,
            state: states,
            pressure: gas_pressure,
            piston_force: applied,
            families: loads,
            total,
            steps: &steps,
            stage_columns: &staged.columns,
        };
        for sink in sinks.iter_mut() {
            sink.push_block(&taken)
                .map_err(|(step, message)| RunError::Sink { step, message })?;
        }
        steps.clear();
        spare = steps.into_iter().map(|_| unreachable!()).collect();
        index += n;
        if let Some(e) = stopped {
            return Err(e);
        }
    }
    Ok(())
}

/// Fills `states` with the next block of `motion`'s states (`block` of them, or one: a solved
/// motion's next state after the torque `previous_torque` of the one before), whose first is
/// step `index`: the error that stopped the motion, if it did, and whether it has ended.
fn next_states(
    states: &mut StateBlock,
    mechanism: &dyn Mechanism,
    motion: &mut dyn MotionSource,
    block: usize,
    index: usize,
    previous_torque: Option<f64>,
) -> (Option<RunError>, bool) {
    if block > 1 {
        let stopped = states
            .fill_next(mechanism, motion)
            .map(|source| RunError::Motion {
                step: index + states.len,
                source,
            });
        return (stopped, states.len < block);
    }
    let (crank, stopped) = match motion.next(previous_torque) {
        None => (None, None),
        Some(Ok(crank)) => (Some(crank), None),
        Some(Err(source)) => (
            None,
            Some(RunError::Motion {
                step: index,
                source,
            }),
        ),
    };
    states.fill(mechanism, crank.as_slice());
    (stopped, crank.is_none())
}

/// How a run loads its steps: its families, and how their total is made (also the solved
/// motion's friction torque, `machine_friction.rs`, which loads its states as a run does).
pub struct Loading<'f> {
    families: &'f [&'f dyn LoadFamily],
    /// Whether there are several families (one family is its own total).
    pub several: bool,
    /// Whether the total is the solve of the families' loads together, not their sum: a joint
    /// whose reaction is not linear in the loads (an involute mesh's loaded flank) makes it so.
    together: bool,
    together_inertia: bool,
    together_pushed: bool,
    /// The inertial family's index.
    inertial: Option<usize>,
    /// The families' names, then `total`.
    names: Vec<&'static str>,
    /// The gas, for a stage that evaluates the cylinder at other crank angles (the other
    /// cylinders of a machine, [`Block::gas`]).
    gas: Option<GasAt<'f>>,
}

impl<'f> Loading<'f> {
    /// The loading of `families` (in their order) on a mechanism of `topology`.
    pub fn new(families: &'f [&'f dyn LoadFamily], topology: &Topology) -> Self {
        let several = families.len() > 1;
        let mut names: Vec<&'static str> = families.iter().map(|f| f.name()).collect();
        names.push("total");
        Self {
            families,
            several,
            together: several && !topology.superposable(),
            together_inertia: families.iter().any(|f| f.inertia()),
            together_pushed: families.iter().any(|f| f.piston_forces()),
            inertial: families.iter().position(|f| f.inertia()),
            names,
            gas: None,
        }
    }

    /// Each family's loads at the block `states` into `loads` (the pistons pushed by `applied`
    /// where a family takes them), and with several families their total into `total`; each
    /// family sees the sum of those before it.
    pub fn loads(
        &self,
        mechanism: &dyn Mechanism,
        states: &StateBlock,
        applied: Option<&Column>,
        loads: &mut [LoadsBlock],
        total: &mut LoadsBlock,
    ) {
        let n = states.len;
        if self.several {
            total.clear(n);
        }
        for (family, out) in self.families.iter().zip(loads.iter_mut()) {
            let f = if family.piston_forces() {
                applied
            } else {
                None
            };
            family.loads(mechanism, states, f, total, out);
            if self.several {
                total.add(out, n);
            }
        }
        if self.together {
            let f = if self.together_pushed { applied } else { None };
            self.families[0]
                .solver()
                .loads(mechanism, states, self.together_inertia, f, total);
            for family in self.families {
                family.add_carried(mechanism.topology(), states, total);
            }
        }
    }

    /// Whether every step of the block is finite ([`all_finite`]): its families' loads, and
    /// the total where it is solved apart.
    fn all_finite(
        &self,
        states: &StateBlock,
        pressure: Option<&Column>,
        loads: &[LoadsBlock],
        total: &LoadsBlock,
    ) -> bool {
        all_finite(states, pressure, loads)
            && (!self.together || all_finite(states, None, std::slice::from_ref(total)))
    }

    /// The first lane of the block (whose first step is `first`) at which a quantity
    /// [`check_finite`] checks is not finite, and the run's error there: [`check_lane`] on the
    /// families' loads, and the total's where it is solved apart; `gas`: the pressure and
    /// piston force columns.
    fn first_not_finite(
        &self,
        first: usize,
        states: &StateBlock,
        gas: Option<(&Column, &Column)>,
        loads: &[LoadsBlock],
        total: &LoadsBlock,
        mechanism: &dyn Mechanism,
    ) -> Option<(usize, RunError)> {
        (0..states.len).find_map(|i| {
            let step = first + i;
            let gas = gas.map(|(p, f)| (p[i], f[i]));
            let families = check_lane(step, states, i, gas, &self.names, loads, mechanism);
            let together = || {
                let total = std::slice::from_ref(total);
                let names = &self.names[self.families.len()..];
                check_lane(step, states, i, None, names, total, mechanism)
            };
            match families {
                Err(e) => Some((i, e)),
                Ok(()) if self.together => together().err().map(|e| (i, e)),
                Ok(()) => None,
            }
        })
    }
}

/// Lane `i` of a block: its states, the gas force on each piston there (if a gas model
/// runs), the families' loads and their total.
struct Lane<'a> {
    states: &'a StateBlock,
    i: usize,
    force: f64,
    loads: &'a [LoadsBlock],
    total: &'a LoadsBlock,
}

/// A step's state and what it computes besides, one at a time, kept for each step of a block
/// until the sinks have taken the block.
#[derive(Clone)]
struct StepOut {
    state: State,
    forces: Vec<f64>,
    loads: Vec<Loads>,
    total: Loads,
    shares: Vec<Vec<f64>>,
    /// Each stage's values.
    stages: Vec<Vec<f64>>,
}

impl StepOut {
    fn new(
        topology: &Topology,
        families: usize,
        pistons: usize,
        stages: &[&mut dyn Stage],
    ) -> Self {
        Self {
            state: State::for_topology(topology),
            forces: vec![0.0; pistons],
            loads: vec![Loads::for_topology(topology); families],
            total: Loads::for_topology(topology),
            shares: vec![vec![0.0; topology.bodies.len()]; families],
            stages: stages.iter().map(|s| vec![0.0; s.width()]).collect(),
        }
    }

    /// Takes `lane` one at a time: gathers its state and loads (with the state's extras and
    /// the torque shares if `details`), and the stages' values from their columns.
    fn take(
        &mut self,
        lane: &Lane,
        loading: &Loading,
        mechanism: &dyn Mechanism,
        details: bool,
        stage_columns: &[Vec<Column>],
    ) {
        let topology = mechanism.topology();
        let i = lane.i;
        lane.states.gather(i, &mut self.state);
        if details {
            mechanism.fill_extras(&mut self.state);
        }
        let state: &State = &self.state;
        self.forces.fill(lane.force);
        for (((family, out), columns), share) in loading
            .families
            .iter()
            .zip(self.loads.iter_mut())
            .zip(lane.loads)
            .zip(&mut self.shares)
        {
            columns.gather(i, out);
            if details {
                let applied: &[f64] = if family.piston_forces() {
                    &self.forces
                } else {
                    &[]
                };
                torque_shares(topology, state, family.inertia(), applied, share);
            }
        }
        if loading.several {
            lane.total.gather(i, &mut self.total);
        }
        for (values, columns) in self.stages.iter_mut().zip(stage_columns) {
            for (v, c) in values.iter_mut().zip(columns) {
                *v = c[i];
            }
        }
    }
}

/// The values of the run's stages at a block, a column per value, and what they pass on.
struct StageValues {
    columns: Vec<Vec<Column>>,
    passed: PassedOn,
}

impl StageValues {
    fn new(stages: &[&mut dyn Stage]) -> Self {
        Self {
            columns: stages.iter().map(|s| vec![ZERO; s.width()]).collect(),
            passed: PassedOn::default(),
        }
    }

    /// Evaluates `stages` in the run's order at `block`: the error of the first lane a stage
    /// fails at, of the first stage in the run's order that fails there (a stage after one
    /// that failed is evaluated only on the lanes before the failure).
    fn evaluate(&mut self, stages: &mut [&mut dyn Stage], block: &Block) -> Option<LaneError> {
        self.passed.clear();
        let mut first: Option<LaneError> = None;
        for (stage, out) in stages.iter_mut().zip(&mut self.columns) {
            let len = first.as_ref().map_or(block.len, |e| e.lane);
            if len == 0 {
                break;
            }
            let lanes = Block { len, ..*block };
            if let Err(e) = stage.evaluate(&lanes, &mut self.passed, out) {
                first = Some(e);
            }
        }
        first
    }
}

impl StageError {
    /// The run's error for this stage's error at step `step` (crank angle `angle`, rad).
    fn at(self, step: usize, angle: f64) -> RunError {
        match self {
            StageError::Failed(message) => RunError::Sink { step, message },
            StageError::NonFinite { quantity, value } => RunError::NonFinite {
                step,
                angle_deg: angle.to_degrees(),
                quantity,
                value,
            },
        }
    }
}

vectorised! {
    /// Whether the quantities [`check_finite`] checks are finite at every step of `block`,
    /// from their sum over the block in eight running sums (one load and one addition per
    /// number, nothing stored): a NaN or an infinity makes a sum NaN or infinite, and so can
    /// finite numbers whose sum overflows, a block whose steps [`check_lane`] then passes one
    /// by one.
    fn all_finite(block: &StateBlock, pressure: Option<&Column>, loads: &[LoadsBlock]) -> bool {
        let n = block.len.min(LANES);
        let mut acc = [0.0; 8];
        let mut add = |column: &Column| add_lanes(&mut acc, column, n);
        let c = &block.crank;
        add(&c.speed);
        add(&c.time);
        if let Some(p) = pressure {
            add(p);
        }
        for p in &block.pistons {
            add(&p.position);
            add(&p.velocity);
            add(&p.acceleration);
        }
        for l in loads {
            add(&l.crank_torque);
            for j in &l.joints {
                add(&j.fx);
                add(&j.fy);
                add(&j.moment);
            }
        }
        acc.iter().all(|a| a.is_finite())
    }
}

/// Adds the first `n` numbers of `column` to `sums`, number i to sum i mod 8. Inlined into
/// the kernel (a closure would not take its target features).
#[inline(always)]
fn add_lanes(sums: &mut [f64; 8], column: &Column, n: usize) {
    // A whole block (most blocks): a loop of a known count, which the compiler unrolls; the
    // same additions in the same order.
    if n == LANES {
        for chunk in column.chunks_exact(8) {
            for (s, x) in sums.iter_mut().zip(chunk) {
                *s += x;
            }
        }
        return;
    }
    let mut i = 0;
    while i + 8 <= n {
        for (s, x) in sums.iter_mut().zip(&column[i..i + 8]) {
            *s += x;
        }
        i += 8;
    }
    for x in &column[i..n] {
        sums[0] += x;
    }
}

/// [`check_finite`] at lane `i` of a block (whose sum was not finite), with the gas's
/// (pressure, piston force) there.
fn check_lane(
    step: usize,
    block: &StateBlock,
    i: usize,
    gas: Option<(f64, f64)>,
    names: &[&str],
    loads: &[LoadsBlock],
    mechanism: &dyn Mechanism,
) -> Result<(), RunError> {
    let t = mechanism.topology();
    let mut state = State::for_topology(t);
    block.gather(i, &mut state);
    let lane: Vec<Loads> = loads
        .iter()
        .map(|l| {
            let mut out = Loads::for_topology(t);
            l.gather(i, &mut out);
            out
        })
        .collect();
    let forces = gas.map_or(vec![], |(_, f)| vec![f; t.pistons.len()]);
    check_finite(
        step,
        &state,
        gas.map(|(p, _)| p),
        &forces,
        names,
        &lane,
        mechanism,
    )
}

/// Fails the step if any computed quantity is not finite, naming the first such quantity. The
/// check per step is one sum of the quantities: an infinity or a NaN among them makes the sum
/// an infinity or a NaN (one addition per quantity: `is_finite` on each, compared and flagged,
/// was a sixth of a summary-only run). Only then is the culprit looked for, value by value;
/// finite values whose sum overflows (beyond 1e308 together) find none and pass.
fn check_finite(
    step: usize,
    state: &State,
    pressure: Option<f64>,
    forces: &[f64],
    names: &[&str],
    loads: &[Loads],
    mechanism: &dyn Mechanism,
) -> Result<(), RunError> {
    // The loads carry every body's acceleration (times a mass that may be 0, which keeps a NaN
    // or an infinity non-finite) and the gas force; the pistons and the crank the rest.
    let mut sum = state.crank.speed + state.crank.time + pressure.unwrap_or(0.0);
    for p in &state.pistons {
        sum += p.position + p.velocity + p.acceleration;
    }
    for l in loads {
        let mut s = l.crank_torque;
        for j in &l.joints {
            s += (j.force.re + j.force.im) + j.moment;
        }
        sum += s;
    }
    if sum.is_finite() {
        return Ok(());
    }
    let t = mechanism.topology();
    let mut named: Vec<(String, f64)> = vec![
        ("crank_speed".into(), state.crank.speed),
        ("time".into(), state.crank.time),
        ("cylinder_pressure".into(), pressure.unwrap_or(0.0)),
    ];
    named.extend(forces.iter().map(|&f| ("gas_force".to_string(), f)));
    for (p, m) in t.pistons.iter().zip(&state.pistons) {
        named.push((format!("{}_position", p.name), m.position));
        named.push((format!("{}_velocity", p.name), m.velocity));
        named.push((format!("{}_acceleration", p.name), m.acceleration));
    }
    for (b, m) in t.bodies.iter().zip(&state.bodies) {
        named.push((
            format!("{}_cg_acceleration", b.name),
            m.cg.acceleration.norm(),
        ));
        named.push((
            format!("{}_angular_acceleration", b.name),
            m.angular_acceleration,
        ));
    }
    for (family, l) in names.iter().zip(loads) {
        named.push((format!("{family}_torque"), l.crank_torque));
        for (j, load) in t.joints.iter().zip(&l.joints) {
            let force = format!("{family}_{}_force", j.name);
            named.push((force.clone(), load.force.re));
            named.push((force, load.force.im));
            named.push((format!("{family}_{}_moment", j.name), load.moment));
        }
    }
    match named.into_iter().find(|(_, v)| !v.is_finite()) {
        Some((quantity, value)) => Err(RunError::NonFinite {
            step,
            angle_deg: state.crank.angle.to_degrees(),
            quantity,
            value,
        }),
        None => Ok(()),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use cardan_mechanism::{CrankState, MachineGeometry, MassInputs, Options, C, MECHANISMS};

    /// A non-finite value fails its step and is named, whichever quantity of the sum it is;
    /// finite values too large to be summed (the sum overflows) pass.
    #[test]
    fn the_finiteness_check_names_the_culprit_and_ignores_an_overflowing_sum() {
        let g = MachineGeometry {
            crank_length: 0.06,
            rod_length: 0.14,
            bore: 0.12,
            pin_offset: 0.0,
        };
        let families = ["inertial"];
        for entry in MECHANISMS {
            let m = (entry.build)(&g, &MassInputs::default(), &Options::new()).unwrap();
            let state = m.state(&CrankState::new(1.0, 100.0, 0.0, 0.0));
            let mut loads = Loads::for_topology(m.topology());
            let check = |state: &State, loads: &Loads| {
                check_finite(
                    7,
                    state,
                    Some(1e5),
                    &[],
                    &families,
                    std::slice::from_ref(loads),
                    m.as_ref(),
                )
            };
            assert_eq!(check(&state, &loads), Ok(()));
            loads.joints[0].force = C::new(f64::MAX, f64::MAX);
            loads.crank_torque = f64::MAX;
            assert_eq!(check(&state, &loads), Ok(()), "{}", entry.name);
            let last = m.topology().joints.len() - 1;
            let joint = m.topology().joints[last].name;
            for (value, culprit) in [
                (f64::NAN, "moment"),
                (f64::INFINITY, "force"),
                (f64::NEG_INFINITY, "force"),
            ] {
                let mut bad = loads.clone();
                match culprit {
                    "moment" => bad.joints[last].moment = value,
                    _ => bad.joints[last].force.im = value,
                }
                let Err(RunError::NonFinite { step, quantity, .. }) = check(&state, &bad) else {
                    panic!("{}: {value} in the {culprit} passed", entry.name)
                };
                assert_eq!((step, quantity), (7, format!("inertial_{joint}_{culprit}")));
            }
            let mut bad = state.clone();
            bad.pistons[0].velocity = f64::NAN;
            let Err(RunError::NonFinite { quantity, .. }) = check(&bad, &loads) else {
                panic!("{}: a NaN piston velocity passed", entry.name)
            };
            assert_eq!(
                quantity,
                format!("{}_velocity", m.topology().pistons[0].name)
            );
            // The same over a block's columns: a block with a NaN at lane 5 and finite loads
            // that overflow a sum at lane 2 fails the block's check; lane by lane, 5's NaN is
            // named and 2 passes. A block of finite values passes at once.
            let t = m.topology();
            let mut states = StateBlock::for_topology(t);
            let mut columns = LoadsBlock::for_topology(t);
            let fine = Loads::for_topology(t);
            let mut nan = fine.clone();
            nan.joints[last].force.im = f64::NAN;
            states.len = 9;
            for i in 0..9 {
                states.scatter(i, &state);
                let lane_loads = match i {
                    2 => &loads,
                    5 => &nan,
                    _ => &fine,
                };
                columns.scatter(i, lane_loads);
            }
            assert!(
                !all_finite(&states, None, std::slice::from_ref(&columns)),
                "{}",
                entry.name
            );
            let columns = std::slice::from_ref(&columns);
            let lane = |i| check_lane(7, &states, i, None, &families, columns, m.as_ref());
            assert_eq!(lane(2), Ok(()), "{}", entry.name);
            let Err(RunError::NonFinite { quantity, .. }) = lane(5) else {
                panic!("{}: lane 5's NaN passed", entry.name)
            };
            assert_eq!(quantity, format!("inertial_{joint}_force"));
            // Lane 2's overflow alone: the block is looked into, and every lane passes.
            let mut columns = LoadsBlock::for_topology(t);
            columns.scatter(2, &loads);
            let one = std::slice::from_ref(&columns);
            assert!(!all_finite(&states, None, one), "{}", entry.name);
            for i in 0..9 {
                assert_eq!(
                    check_lane(7, &states, i, None, &families, one, m.as_ref()),
                    Ok(())
                );
            }
            let mut columns = LoadsBlock::for_topology(t);
            columns.scatter(4, &fine);
            assert!(
                all_finite(&states, None, std::slice::from_ref(&columns)),
                "{}",
                entry.name
            );
        }
    }
}
