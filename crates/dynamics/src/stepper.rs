//! The step loop: a motion source gives crank states (a prescribed one a block of
//! [`LANES`] at a time, straight into the block's columns), the mechanism fills its columns,
//! each load family its loads' columns, the finiteness of every step is checked, and the block
//! is handed to the sinks (the summary reads the columns; per-step files and the stages, losses
//! and gear ratings, take the steps one at a time, gathered from the columns only where they
//! are wanted) and then forgotten. Nothing here grows with the number of steps.
//! [`crate::run_parallel`] shares one run among threads, each piece through this loop.

use crate::energy::torque_shares;
use crate::family::LoadFamily;
use crate::gear_rating::{GearRatings, MeshRating};
use crate::losses::LossBudget;
use cardan_mechanism::{
    vectorised, Column, Loads, LoadsBlock, Mechanism, MotionError, MotionSource, State, StateBlock,
    Topology, LANES,
};

/// One step, as the sinks that take steps one at a time see it.
#[derive(Debug, Clone, Copy)]
pub struct Step<'a> {
    /// Index of the step in the run, from 0.
    pub index: usize,
    pub state: &'a State,
    /// Absolute cylinder pressure, Pa, if a gas model loads the pistons.
    pub pressure: Option<f64>,
    /// Gas force on each piston along its axis, towards the crankshaft, N (empty without gas).
    pub piston_forces: &'a [f64],
    /// The loads of each family, in the order of the run's families.
    pub families: &'a [Loads],
    /// Their sum.
    pub total: &'a Loads,
    /// The power loss of each component of the run's [`LossBudget`], W (empty without one).
    pub losses: &'a [f64],
    /// The drive torque that covers the losses, Σ losses / ω, N·m (0 at rest, where the
    /// losses are 0 too).
    pub friction_torque: f64,
    /// The rating of each gear mesh of the run's [`GearRatings`] (empty without one).
    pub gears: &'a [MeshRating],
    /// Each family's torque shares by body ([`torque_shares`]), N·m; computed, with the
    /// state's extras, only when a sink [wants](Sink::wants_details) them (zeros otherwise).
    pub shares: &'a [Vec<f64>],
}

/// Consecutive steps (at most [`LANES`]), as columns, and one by one where wanted.
#[derive(Debug, Clone, Copy)]
pub struct StepBlock<'a> {
    /// Index of the block's first step in the run.
    pub first: usize,
    /// The mechanism's states: lane `i` is step `first + i`.
    pub state: &'a StateBlock,
    /// Absolute cylinder pressure at each step, Pa, if a gas model loads the pistons.
    pub pressure: Option<&'a Column>,
    /// Gas force on every piston at each step, along its axis towards the crankshaft, N, if a
    /// gas model loads the pistons.
    pub piston_force: Option<&'a Column>,
    /// The loads of each family, in the order of the run's families.
    pub families: &'a [LoadsBlock],
    /// Their sum.
    pub total: &'a LoadsBlock,
    /// The same steps one at a time, with the losses and gear ratings of the run's stages:
    /// made only when a sink [wants](Sink::wants_steps) them or the run has stages (empty
    /// otherwise).
    pub steps: &'a [Step<'a>],
}

impl StepBlock<'_> {
    /// Steps in the block.
    pub fn len(&self) -> usize {
        self.state.len
    }

    pub fn is_empty(&self) -> bool {
        self.state.len == 0
    }

    /// Lane `i` as a step: the run's own, if it made the steps one at a time, else gathered
    /// from the columns into `scratch` (a sink that takes few of a block's steps, without
    /// [wanting](Sink::wants_steps) them all; no losses, gear ratings or details then, as a
    /// run without stages or details has none).
    pub fn step<'s>(&'s self, i: usize, scratch: &'s mut StepScratch) -> Step<'s> {
        if let Some(s) = self.steps.get(i) {
            return *s;
        }
        let StepScratch {
            state,
            forces,
            families,
            total,
            shares,
        } = scratch;
        self.state.gather(i, state);
        forces.clear();
        if let Some(f) = self.piston_force {
            forces.resize(state.pistons.len(), f[i]);
        }
        families.resize(self.families.len(), total.clone());
        for (out, columns) in families.iter_mut().zip(self.families) {
            columns.gather(i, out);
        }
        self.total.gather(i, total);
        shares.resize(self.families.len(), vec![0.0; state.bodies.len()]);
        Step {
            index: self.first + i,
            state,
            pressure: self.pressure.map(|p| p[i]),
            piston_forces: forces,
            families,
            total,
            losses: &[],
            friction_torque: 0.0,
            gears: &[],
            shares,
        }
    }
}

/// Where [`StepBlock::step`] gathers a step.
#[derive(Debug, Clone, Default)]
pub struct StepScratch {
    state: State,
    forces: Vec<f64>,
    families: Vec<Loads>,
    total: Loads,
    shares: Vec<Vec<f64>>,
}

impl StepScratch {
    /// Room for a step of a mechanism of `topology` (its extras left at 0: no details).
    pub fn for_topology(topology: &Topology) -> Self {
        Self {
            state: State::for_topology(topology),
            forces: Vec::new(),
            families: Vec::new(),
            total: Loads::for_topology(topology),
            shares: Vec::new(),
        }
    }
}

/// Where steps go.
pub trait Sink {
    /// Takes one step (a sink that [wants](Sink::wants_steps) steps); an error stops the run (a
    /// file that cannot be written).
    fn push(&mut self, _step: &Step) -> Result<(), String> {
        Ok(())
    }

    /// Takes a block of consecutive steps, in order; an error names the index of the step it
    /// stopped at. By default each of [`StepBlock::steps`] in turn.
    fn push_block(&mut self, block: &StepBlock) -> Result<(), (usize, String)> {
        for s in block.steps {
            self.push(s).map_err(|message| (s.index, message))?;
        }
        Ok(())
    }

    /// Whether it reads the steps one at a time ([`StepBlock::steps`]); a sink that reads only
    /// the columns spares the run a copy of every step.
    fn wants_steps(&self) -> bool {
        true
    }

    /// Whether it reads [`Step::shares`] and the state's extras (they cost divisions and square
    /// roots per step that a summary does not need).
    fn wants_details(&self) -> bool {
        false
    }
}

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

/// The gas at a crank angle: (absolute pressure in Pa, force on each piston in N); `Sync`, so
/// that the threads sharing a run ([`crate::run_parallel`]) can all ask it.
pub type GasAt<'a> = &'a (dyn Fn(f64) -> (f64, f64) + Sync);

/// What each step computes from its total loads besides the loads themselves.
#[derive(Default)]
pub struct Stages<'a> {
    /// The power loss of each component and the friction torque.
    pub losses: Option<&'a mut LossBudget>,
    /// The rating of each gear mesh.
    pub gears: Option<&'a GearRatings>,
}

/// Runs `mechanism` through every crank state of `motion`, with the loads of `families`, the
/// pistons pushed by `gas` if given, the `stages` computed from the total loads, every step to
/// every sink.
pub fn run(
    mechanism: &dyn Mechanism,
    motion: &mut dyn MotionSource,
    families: &[&dyn LoadFamily],
    gas: Option<GasAt>,
    stages: Stages,
    sinks: &mut [&mut dyn Sink],
) -> Result<(), RunError> {
    let Stages { mut losses, gears } = stages;
    let topology = mechanism.topology();
    // A prescribed motion's states come a block at a time, filled and loaded column by column
    // (`Mechanism::fill_block`, `LoadFamily::loads`) and taken so by the sinks
    // (`Sink::push_block`); a solved motion's one at a time, each after the torque of the one
    // before.
    let block = if motion.prescribed() { LANES } else { 1 };
    let mut states = StateBlock::for_topology(topology);
    let (mut pressure, mut force) = ([0.0; LANES], [0.0; LANES]);
    let mut loads = vec![LoadsBlock::for_topology(topology); families.len()];
    let mut total = LoadsBlock::for_topology(topology);
    let details = sinks.iter().any(|s| s.wants_details());
    // The steps one at a time, for the sinks that take them and for the stages.
    let one_by_one =
        details || losses.is_some() || gears.is_some() || sinks.iter().any(|s| s.wants_steps());
    let pistons = if gas.is_some() {
        topology.pistons.len()
    } else {
        0
    };
    let mut out = vec![
        StepOut {
            state: State::for_topology(topology),
            forces: vec![0.0; pistons],
            loads: vec![Loads::for_topology(topology); families.len()],
            total: Loads::for_topology(topology),
            shares: vec![vec![0.0; topology.bodies.len()]; families.len()],
            losses: vec![0.0; losses.as_ref().map_or(0, |l| l.names().len())],
            friction_torque: 0.0,
            ratings: vec![MeshRating::default(); gears.map_or(0, |g| g.names().len())],
        };
        if one_by_one { block } else { 0 }
    ];
    // The rated meshes' losses by joint, which the loss budget takes instead of computing them
    // again.
    let mut mesh_losses: Vec<(usize, f64)> =
        Vec::with_capacity(out.first().map_or(0, |o| o.ratings.len()));
    // The allocation of the block's steps, kept from block to block.
    let mut spare: Vec<Step<'static>> = Vec::with_capacity(block);
    let mut previous_torque = None;
    // A part of a run numbers its steps as the whole run does.
    let mut index = motion.first_index();
    let inertial = families.iter().position(|f| f.inertia());
    // Each family sees the sum of those before it; one family is its own total.
    let several = families.len() > 1;
    // A joint whose reaction is not linear in the loads (an involute mesh's loaded flank) makes
    // the total the solve of the families' loads together, not the sum of their solves.
    let together = several && !topology.superposable();
    let together_inertia = families.iter().any(|f| f.inertia());
    let together_pushed = families.iter().any(|f| f.piston_forces());
    let mut names: Vec<&str> = families.iter().map(|f| f.name()).collect();
    names.push("total");
    let mut ended = false;
    while !ended {
        let mut stopped = None;
        if block > 1 {
            if let Some(source) = states.fill_next(mechanism, motion) {
                stopped = Some(RunError::Motion {
                    step: index + states.len,
                    source,
                });
            }
            ended = states.len < block;
        } else {
            let crank = match motion.next(previous_torque) {
                None => None,
                Some(Ok(crank)) => Some(crank),
                Some(Err(source)) => {
                    stopped = Some(RunError::Motion {
                        step: index,
                        source,
                    });
                    None
                }
            };
            ended = crank.is_none();
            states.fill(mechanism, crank.as_slice());
        }
        let n = states.len;
        if let Some(g) = gas {
            for i in 0..n {
                (pressure[i], force[i]) = g(states.crank.angle[i]);
            }
        }
        let applied = gas.map(|_| &force);
        if several {
            total.clear(n);
        }
        for (family, out) in families.iter().zip(loads.iter_mut()) {
            let f = if family.piston_forces() {
                applied
            } else {
                None
            };
            family.loads(mechanism, &states, f, &total, out);
            if several {
                total.add(out, n);
            }
        }
        if together {
            let f = if together_pushed { applied } else { None };
            families[0]
                .solver()
                .loads(mechanism, &states, together_inertia, f, &mut total);
        }
        let total: &LoadsBlock = if several { &total } else { &loads[0] };
        let gas_pressure = gas.map(|_| &pressure);
        let clean = all_finite(&states, gas_pressure, &loads)
            && (!together || all_finite(&states, None, std::slice::from_ref(total)));
        if let Some(t) = total.crank_torque[..n].last() {
            previous_torque = Some(*t);
        }
        for i in 0..n {
            let step = index + i;
            if !clean {
                let gas = gas.map(|_| (pressure[i], force[i]));
                check_lane(step, &states, i, gas, &names, &loads, mechanism)?;
                if together {
                    let total = std::slice::from_ref(total);
                    check_lane(
                        step,
                        &states,
                        i,
                        None,
                        &names[families.len()..],
                        total,
                        mechanism,
                    )?;
                }
            }
            let Some(o) = out.get_mut(i) else {
                if clean {
                    break;
                }
                continue;
            };
            let StepOut {
                state,
                forces,
                loads: step_loads,
                total: step_total,
                shares,
                losses: power_losses,
                friction_torque,
                ratings,
            } = o;
            states.gather(i, state);
            if details {
                mechanism.fill_extras(state);
            }
            let state: &State = state;
            forces.fill(force[i]);
            for (((family, out), columns), share) in families
                .iter()
                .zip(step_loads.iter_mut())
                .zip(&loads)
                .zip(shares)
            {
                columns.gather(i, out);
                if details {
                    let applied: &[f64] = if family.piston_forces() { forces } else { &[] };
                    torque_shares(topology, state, family.inertia(), applied, share);
                }
            }
            if several {
                total.gather(i, step_total);
            }
            let total: &Loads = if several { step_total } else { &step_loads[0] };
            if let Some(g) = gears {
                g.evaluate(state, total, inertial.map(|k| &step_loads[k]), ratings)
                    .map_err(|message| RunError::Sink { step, message })?;
                mesh_losses.clear();
                mesh_losses.extend(g.joints().zip(ratings.iter().map(|r| r.loss)));
            }
            *friction_torque = 0.0;
            if let Some(budget) = losses.as_deref_mut() {
                budget
                    .evaluate(
                        state,
                        total,
                        gas.map(|_| pressure[i]),
                        &mesh_losses,
                        power_losses,
                    )
                    .map_err(|message| RunError::Sink { step, message })?;
                let sum: f64 = power_losses.iter().sum();
                if !sum.is_finite() {
                    let k = power_losses
                        .iter()
                        .position(|p| !p.is_finite())
                        .unwrap_or(0);
                    return Err(RunError::NonFinite {
                        step,
                        angle_deg: state.crank.angle.to_degrees(),
                        quantity: format!("power_loss_{}", budget.names()[k]),
                        value: power_losses[k],
                    });
                }
                if state.crank.speed != 0.0 {
                    *friction_torque = sum / state.crank.speed.abs();
                }
            }
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
            total: if several { &o.total } else { &o.loads[0] },
            losses: &o.losses,
            friction_torque: o.friction_torque,
            gears: &o.ratings,
            shares: &o.shares,
        }));
        let taken = StepBlock {
            first: index,
            state: &states,
            pressure: gas_pressure,
            piston_force: applied,
            families: &loads,
            total,
            steps: &steps,
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

/// A step's state and what it computes besides, one at a time, kept for each step of a block
/// until the sinks have taken the block.
#[derive(Clone)]
struct StepOut {
    state: State,
    forces: Vec<f64>,
    loads: Vec<Loads>,
    total: Loads,
    shares: Vec<Vec<f64>>,
    losses: Vec<f64>,
    friction_torque: f64,
    ratings: Vec<MeshRating>,
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

/// One step kept whole, for tests and callers that want every step in memory.
#[derive(Debug, Clone, PartialEq)]
pub struct StepRecord {
    pub state: State,
    pub pressure: Option<f64>,
    pub piston_forces: Vec<f64>,
    pub families: Vec<Loads>,
    pub total: Loads,
    pub losses: Vec<f64>,
    pub friction_torque: f64,
    pub shares: Vec<Vec<f64>>,
}

/// A sink that keeps every step (memory grows with the steps: for tests and small runs).
#[derive(Debug, Clone, Default)]
pub struct Steps(pub Vec<StepRecord>);

impl Sink for Steps {
    fn wants_details(&self) -> bool {
        true
    }

    fn push(&mut self, s: &Step) -> Result<(), String> {
        self.0.push(StepRecord {
            state: s.state.clone(),
            pressure: s.pressure,
            piston_forces: s.piston_forces.to_vec(),
            families: s.families.to_vec(),
            total: s.total.clone(),
            losses: s.losses.to_vec(),
            friction_torque: s.friction_torque,
            shares: s.shares.to_vec(),
        });
        Ok(())
    }
}

/// Runs `mechanism` through `motion` with the inertial loads (and the gas loads, if `gas` is
/// given), both by `solver`, and returns every step (if `keep_steps`) with the summary: the
/// whole pipeline in one call, for tests and small studies. Without the steps, the run is
/// shared by the threads of the rayon pool ([`crate::run_parallel`]).
pub fn run_summary(
    mechanism: &dyn Mechanism,
    motion: &mut dyn MotionSource,
    gas: Option<GasAt>,
    solver: crate::Solver,
    keep_steps: bool,
) -> Result<(Vec<StepRecord>, crate::Summary), String> {
    let inertial = crate::Inertial(solver);
    let gas_family = crate::Gas(solver);
    let mut families: Vec<&dyn LoadFamily> = vec![&inertial];
    if gas.is_some() {
        families.push(&gas_family);
    }
    let names: Vec<&'static str> = families.iter().map(|f| f.name()).collect();
    let points = motion.first_index() + motion.len();
    let mut summary = crate::SummarySink::new(mechanism, &names, points);
    let mut steps = Steps::default();
    if keep_steps {
        run(
            mechanism,
            motion,
            &families,
            gas,
            Stages::default(),
            &mut [&mut summary, &mut steps],
        )
    } else {
        crate::run_parallel(
            mechanism,
            motion,
            &families,
            gas,
            Stages::default(),
            &mut summary,
        )
    }
    .map_err(|e| e.to_string())?;
    Ok((steps.0, summary.finish(mechanism)?))
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
