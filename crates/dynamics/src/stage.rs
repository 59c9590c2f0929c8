//! Per-step stages: what a step computes from its total loads besides the loads themselves
//! (the loss budget, the gear ratings: their impls are in [`crate::stages`]), behind one trait,
//! so that the step loop ([`crate::run`]) and the summary ([`crate::SummarySink`]) take any
//! stage without naming it. A stage evaluates each step, one at a time, into values of its own
//! ([`crate::Step::stages`]); declares the per-step columns it fills and the summary metrics it
//! defines (its part of the registry, [`crate::metrics`]); and makes the accumulator that totals
//! its values into the summary ([`StageTotals`]).

use crate::metrics::{MetricDef, Summary};
use crate::step::StepBlock;
use cardan_mechanism::{Column, Loads, LoadsBlock, State, StateBlock};
use std::any::Any;
use std::ops::Range;

/// The gas at a crank angle: (absolute pressure in Pa, force on each piston in N); `Sync`, so
/// that the threads sharing a run ([`crate::run_parallel`]) can all ask it.
pub type GasAt<'a> = &'a (dyn Fn(f64) -> (f64, f64) + Sync);

/// What a stage evaluates at a step.
#[derive(Clone, Copy)]
pub struct StageInput<'a> {
    pub state: &'a State,
    /// The total loads of the step.
    pub total: &'a Loads,
    /// The inertial family's loads (`None` in a run without one).
    pub inertial: Option<&'a Loads>,
    /// Absolute cylinder pressure, Pa, if a gas model runs.
    pub pressure: Option<f64>,
    /// The gas force on each piston, N, if a gas model runs.
    pub force: Option<f64>,
    /// The gas at any crank angle (pressure, force on each piston), if a gas model runs: for a
    /// stage that evaluates the cylinder at other angles (a machine's other cylinders).
    pub gas: Option<GasAt<'a>>,
}

impl std::fmt::Debug for StageInput<'_> {
    fn fmt(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
        f.debug_struct("StageInput")
            .field("state", self.state)
            .field("total", self.total)
            .field("inertial", &self.inertial)
            .field("pressure", &self.pressure)
            .field("force", &self.force)
            .field("gas", &self.gas.map(|_| "a function of the crank angle"))
            .finish()
    }
}

/// What a step's stages hand on to the stages after them (emptied at every step).
#[derive(Debug, Clone, Default)]
pub struct Handed {
    /// The loss (W) of each gear-mesh joint a stage has rated at this step, by joint index: a
    /// later stage that charges the mesh loss takes it as it is, so that it is computed once.
    pub mesh_losses: Vec<(usize, f64)>,
    /// The run's train's power loss at this step, W, once its loss budget has taken it: the
    /// machine's stage charges it to cylinder 1 ([`crate::MachineStage`]).
    pub loss_power: Option<f64>,
}

/// What a stage evaluated a block at a time ([`Stage::evaluate_block`]) takes: the block's
/// states and total loads, and the gas where a gas model runs.
#[derive(Clone, Copy)]
pub struct BlockInput<'a> {
    pub states: &'a StateBlock,
    pub total: &'a LoadsBlock,
    /// Absolute cylinder pressure, Pa, and the gas force on each piston, N, at each lane.
    pub pressure: Option<&'a Column>,
    pub force: Option<&'a Column>,
    /// The gas at any crank angle.
    pub gas: Option<GasAt<'a>>,
}

/// Why a stage stops the run at a step.
#[derive(Debug, Clone, PartialEq)]
pub enum StageError {
    /// A model cannot be evaluated at the step: why.
    Failed(String),
    /// A value is not finite: its name and value.
    NonFinite { quantity: String, value: f64 },
}

/// A stage that cannot be set up for a mechanism (a loss model, a gear pair): the case field at
/// fault and why.
#[derive(Debug, Clone, PartialEq)]
pub struct SetupError {
    pub field: String,
    pub rule: String,
}

impl std::fmt::Display for SetupError {
    fn fmt(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
        write!(f, "{}: {}", self.field, self.rule)
    }
}

/// One per-step column a stage fills: its name (unit in the name) and which of the stage's
/// values it holds.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct StageColumn {
    pub name: String,
    pub value: usize,
}

/// A computation run at every step on the step's state and total loads. Stages are evaluated
/// in the run's order, one step at a time (a run with such stages gathers its steps from the
/// columns): a dynamic call per stage and step, beside models that cost far more. A stage that
/// needs only the block's states and total loads may evaluate a whole block from its columns
/// instead ([`Stage::by_block`]): a run whose stages all do so, and whose sinks want neither
/// steps nor details, gathers no step.
pub trait Stage: Send + Sync {
    /// The number of values it gives per step.
    fn width(&self) -> usize;

    /// Its values at the step `input` into `out` ([`Stage::width`] of them); `handed` holds what
    /// the stages before it handed on, and takes what it hands on.
    fn evaluate(
        &mut self,
        input: &StageInput,
        handed: &mut Handed,
        out: &mut [f64],
    ) -> Result<(), StageError>;

    /// The per-step columns it fills (the per-step files' names for its values).
    fn columns(&self) -> Vec<StageColumn>;

    /// The summary metrics its totals define: its part of the registry
    /// ([`crate::metrics::METRICS`]).
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

    /// Whether it evaluates whole blocks ([`Stage::evaluate_block`]) rather than one step at a
    /// time: a stage that needs only a step's state and total loads, takes nothing handed on
    /// and hands nothing on.
    fn by_block(&self) -> bool {
        false
    }

    /// For a stage [`by_block`](Stage::by_block): its values at every lane of the block
    /// `input` into `out` (a column per value,
    /// [`Stage::width`] of them), the very values [`Stage::evaluate`] gives at each step (the
    /// same bits). An error names the first lane it fails at and why (its values from there
    /// on are not used; every lane is evaluated, whatever its inputs, without panicking).
    fn evaluate_block(
        &mut self,
        _input: &BlockInput,
        _out: &mut [Column],
    ) -> Result<(), (usize, StageError)> {
        Err((
            0,
            StageError::Failed("the stage evaluates one step at a time".into()),
        ))
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
    /// Takes the stage's values (`block.steps[i].stages[stage]`, or `block.stage_columns[stage]`
    /// for a stage evaluated [by block](Stage::by_block)) at the lanes `lanes` of `block`
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
