//! The stage contract: what a run computes from a block's states and total loads besides the
//! loads themselves (the gear ratings, the loss budget, the whole machine: their impls are in
//! `cardan-dynamics`, above this crate), behind one trait, so that the step loop
//! ([`crate::run`]) and the summary ([`crate::SummarySink`]) take any stage without naming it.
//! A stage evaluates a whole block at a time from the block's columns into columns of its own
//! ([`crate::StepBlock::stage_columns`]); declares the per-step columns it fills and the
//! summary metrics it defines (its part of the registry, [`cardan_metrics`]); and makes the
//! accumulator that totals its values into the summary ([`StageTotals`]). A model of one
//! step (a loss model, a gear rating) reads its lanes from the block's columns, and a single
//! step is a block of one lane; the step loop knows one path.

use crate::step::StepBlock;
use cardan_mechanism::{Column, LoadsBlock, StateBlock, LANES};
use cardan_metrics::{MetricDef, Summary};
use std::any::Any;
use std::ops::Range;

/// The gas at a crank angle: (absolute pressure in Pa, force on each piston in N); `Sync`, so
/// that the threads sharing a run ([`crate::run_parallel`]) can all ask it. Any
/// `Fn(f64) -> (f64, f64)` is one.
pub type GasAt<'a> = &'a dyn CylinderGas;

/// The gas in the cylinder a run's pistons share, at one crank angle and over a block's lanes.
pub trait CylinderGas: Sync {
    /// (absolute pressure, Pa; force on each piston, N) at crank angle `theta` (rad).
    fn at(&self, theta: f64) -> (f64, f64);

    /// The same at the first `states.len` lanes of `states` into `pressure` and `force`: by
    /// default [`CylinderGas::at`] at each lane's crank angle. A gas whose chamber volume is
    /// the block's piston positions' takes it from there, at once over the lanes
    /// (`cardan_gas::PreparedGas::lanes`).
    fn lanes(&self, states: &StateBlock, pressure: &mut Column, force: &mut Column) {
        at_each_lane(self, states, pressure, force);
    }
}

/// [`CylinderGas::at`] at each of the first `states.len` lanes' crank angles, into `pressure`
/// and `force`: the lanes of a gas that takes them one at a time.
pub fn at_each_lane<G: CylinderGas + ?Sized>(
    gas: &G,
    states: &StateBlock,
    pressure: &mut Column,
    force: &mut Column,
) {
    let n = states.len.min(LANES);
    for ((p, f), &theta) in pressure
        .iter_mut()
        .zip(force.iter_mut())
        .zip(&states.crank.angle[..n])
    {
        (*p, *f) = gas.at(theta);
    }
}

impl<F: Fn(f64) -> (f64, f64) + Sync> CylinderGas for F {
    fn at(&self, theta: f64) -> (f64, f64) {
        self(theta)
    }
}

/// A block of consecutive steps as the stages read it: lane `i` of every column is the
/// block's step `i`. Only the first [`Block::len`] lanes are evaluated: the steps before the
/// first whose loads are not finite (the run fails there), so that no stage sees a NaN load.
#[derive(Clone, Copy)]
pub struct Block<'a> {
    /// The lanes to evaluate (at most `states.len`).
    pub len: usize,
    pub states: &'a StateBlock,
    /// The total loads of each step.
    pub total: &'a LoadsBlock,
    /// The inertial family's loads (`None` in a run without one).
    pub inertial: Option<&'a LoadsBlock>,
    /// Absolute cylinder pressure, Pa, and the gas force on each piston, N, at each lane, if a
    /// gas model runs.
    pub pressure: Option<&'a Column>,
    pub force: Option<&'a Column>,
    /// The gas at any crank angle (pressure, force on each piston), if a gas model runs: for a
    /// stage that evaluates the cylinder at other angles (a machine's other cylinders).
    pub gas: Option<GasAt<'a>>,
}

impl std::fmt::Debug for Block<'_> {
    fn fmt(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
        f.debug_struct("Block")
            .field("len", &self.len)
            .field("states", self.states)
            .field("total", self.total)
            .field("inertial", &self.inertial)
            .field("pressure", &self.pressure)
            .field("force", &self.force)
            .field("gas", &self.gas.map(|_| "a function of the crank angle"))
            .finish()
    }
}

/// What a block's stages pass on to the stages after them in the run's order, a column per
/// quantity (emptied at every block).
#[derive(Debug, Clone, Default)]
pub struct PassedOn {
    /// The power loss (W) of each gear-mesh joint a stage has rated, at each lane, by joint
    /// index: a later stage that charges the mesh loss takes it as it is, so that it is
    /// computed once.
    pub mesh_losses: Vec<(usize, Column)>,
    /// The run's train's power loss at each lane, W, once its loss budget has taken it: the
    /// machine's stage charges it to cylinder 1 (`cardan_dynamics::MachineStage`).
    pub loss_power: Option<Column>,
}

impl PassedOn {
    /// Empties it for the next block (keeping its allocation).
    pub fn clear(&mut self) {
        self.mesh_losses.clear();
        self.loss_power = None;
    }
}

/// Why a stage stops the run at a step.
#[derive(Debug, Clone, PartialEq)]
pub enum StageError {
    /// A model cannot be evaluated at the step: why.
    Failed(String),
    /// A value is not finite: its name and value.
    NonFinite { quantity: String, value: f64 },
}

/// A stage's error at a lane of its block: the first lane it fails at, and why.
#[derive(Debug, Clone, PartialEq)]
pub struct LaneError {
    pub lane: usize,
    pub error: StageError,
}

impl StageError {
    /// This error at lane `lane` of the block.
    pub fn at_lane(self, lane: usize) -> LaneError {
        LaneError { lane, error: self }
    }
}

pub use cardan_losses::SetupError;

/// One per-step column a stage fills: its name (unit in the name) and which of the stage's
/// values it holds.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct StageColumn {
    pub name: String,
    pub value: usize,
}

/// A computation run at every block of a run on the block's states and total loads, in the
/// run's order.
pub trait Stage: std::fmt::Debug + Send + Sync {
    /// The number of values it gives per step.
    fn width(&self) -> usize;

    /// Its values at the first [`Block::len`] lanes of `block` into `out` (a column per value,
    /// [`Stage::width`] of them); `passed` holds what the stages before it passed on, and
    /// takes what it passes on. An error names the first lane it fails at and why: the run
    /// fails there, and the values from there on are not used (a stage may leave them unset).
    fn evaluate(
        &mut self,
        block: &Block,
        passed: &mut PassedOn,
        out: &mut [Column],
    ) -> Result<(), LaneError>;

    /// The per-step columns it fills (the per-step files' names for its values).
    fn columns(&self) -> Vec<StageColumn>;

    /// The summary metrics its totals define: its part of the registry
    /// ([`cardan_metrics::METRICS`]).
    fn metrics(&self) -> &'static [MetricDef];

    /// A fresh accumulator of its values for a summary.
    fn totals(&self) -> Box<dyn StageTotals>;

    /// Whether a step's values depend on the steps before it: then the steps must be taken in
    /// order, by one thread ([`crate::run_parallel`]).
    fn carries_history(&self) -> bool {
        false
    }

    /// A copy for a piece of a run shared by threads, before it takes any step.
    fn fork(&self) -> Box<dyn Stage>;
}

impl Clone for Box<dyn Stage> {
    fn clone(&self) -> Self {
        self.fork()
    }
}

/// The run's totals a stage's accumulator may refer its metrics to.
#[derive(Debug, Clone, Copy)]
pub struct RunTotals<'a> {
    /// Crank-angle span of the run, rad.
    pub span: f64,
    /// Duration of the run, s.
    pub time: f64,
    /// Each family's drive work ∫ T dθ, J, by name (then `total`'s with several families).
    pub works: &'a [(&'static str, f64)],
}

impl RunTotals<'_> {
    /// The drive work of the family `name`, J.
    pub fn work(&self, name: &str) -> Option<f64> {
        self.works.iter().find(|(n, _)| *n == name).map(|(_, w)| *w)
    }
}

/// A stage's accumulator in a summary: it takes the stage's values step by step, its integrals
/// chunk by chunk ([`crate::summary_chunk`]), and is joined with the accumulators of the later
/// pieces of a shared run, bit for bit as if it had taken every step.
pub trait StageTotals: std::fmt::Debug + Send + Sync {
    /// Takes the stage's values (`block.stage_columns[stage]`) at the lanes `lanes` of `block`
    /// (none of them but the last closing a chunk); `previous` is the time of the step before
    /// them (`None` before the summary's first step).
    fn push_lanes(
        &mut self,
        block: &StepBlock,
        lanes: Range<usize>,
        stage: usize,
        previous: Option<f64>,
    );

    /// Closes the chunk of its integrals.
    fn close_chunk(&mut self);

    /// Continues with `later`, the accumulator of the same stage that took the steps from the
    /// last one this took on (the same kind: made by the same stage's [`Stage::totals`]).
    fn merge(&mut self, later: &dyn StageTotals);

    /// Its metrics into `summary`.
    fn finish(&self, run: &RunTotals, summary: &mut Summary);

    /// A copy (a summary is cloned for each piece of a shared run).
    fn fork(&self) -> Box<dyn StageTotals>;

    /// Itself, for [`StageTotals::merge`] to find its own kind.
    fn as_any(&self) -> &dyn Any;
}

impl Clone for Box<dyn StageTotals> {
    fn clone(&self) -> Self {
        self.fork()
    }
}
