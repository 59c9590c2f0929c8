//! The step pipeline of any mechanism of `cardan-mechanism`, a block of steps at a time: the
//! step loop ([`run`], [`run_parallel`]) fills a block of states, loads it by the load
//! families of `cardan-loads` (inertia, gas; their total), evaluates the run's stages on its
//! columns through one contract ([`Stage`]: a block in, columns out; the stages themselves,
//! the gear ratings, the loss budget and the whole machine, are `cardan-dynamics`'s, above this
//! crate), and streams each block to sinks ([`Sink`]: the cycle summary, [`SummarySink`], and
//! the runner's per-step files) so that memory does not grow with the number of steps. The
//! accumulators a stage's totals are made of ([`summary::peaks::raise`], [`summary::Integral`])
//! are public for the stages above.

pub mod parallel;
pub mod rooms;
pub mod stage;
pub mod step;
pub mod stepper;
pub mod summary;

pub use parallel::{run_parallel, run_summary, Joinable};
pub use rooms::{RunRooms, KEPT_ROOMS};
pub use stage::{
    at_each_lane, Block, CylinderGas, LaneError, PassedOn, RunTotals, SetupError, Stage,
    StageColumn, StageError, StageTotals,
};
pub use step::{Sink, Step, StepBlock, StepRecord, Steps};
pub use stepper::{run, GasAt, Loading, RunError};
pub use summary::{summary_chunk, SummarySink, MAX_CHUNK};
