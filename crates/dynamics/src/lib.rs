//! Kinetostatics of any mechanism of `cardan-mechanism`, a block of steps at a time: the step
//! loop ([`run`], [`run_parallel`]) that loads each block by the load families of
//! `cardan-loads` (inertia, gas; their totals), evaluates the per-step stages on its columns
//! ([`Stage`]: the gear ratings, the loss budget of `cardan-losses`, the whole machine), and
//! streams the block to sinks (the cycle summary, [`SummarySink`]) so that memory does not grow
//! with the number of steps; the whole machine ([`Machine`]) and its solved crank motion
//! ([`machine_motion`]). It re-exports the loads' and the losses' crates under their old paths.
//!
//! Two independent paths compute the same loads (`cardan-loads`):
//! - the closed forms each mechanism carries (Karhula 2008, appendix 5.2.1, for the slider-crank
//!   and the cardan gear), through [`cardan_mechanism::Mechanism::closed_form_loads`];
//! - a general planar solve ([`planar`]): the Newton-Euler equations of every body with every
//!   joint reaction unknown, built from the declared topology and solved with faer.
//!
//! Sign conventions: forces are complex vectors in the frame of the main bearing axis (cylinder
//! on the imaginary axis), each joint's force acting on its `body` from its `other`; the drive
//! torque is the torque the drive applies to the crankshaft, positive in the direction of
//! rotation, so that its work over a crank-angle interval equals the gain of kinetic energy of
//! the bodies plus the work done on the gas.

pub mod flywheel_sizing;
pub mod gear_rating;
pub mod machine;
pub mod machine_friction;
pub mod machine_motion;
pub mod machine_stage;
pub mod machine_totals;
pub mod runup;
/// The loads (families, the planar solve, energy, the reduced inertia), their own crate:
/// re-exported, so that their paths here stay as they were.
pub use cardan_loads::{energy, family, planar, reduced_inertia};
/// The losses, their own crate (the loss models, the budget, engine losses, fmep, the mesh
/// joint's components): re-exported, so that their paths here stay as they were.
pub use cardan_losses::{engine_losses, fmep, loss, loss_models, losses, mesh};
/// The metric registry, its own crate (the reports read it without the physics).
pub use cardan_metrics as metrics;
/// The step pipeline (the stage contract, the step loop, the sinks and the summary), its own
/// crate: re-exported, so that its paths here stay as they were.
pub use cardan_pipeline::{parallel, stage, step, stepper, summary};
pub mod stages;

pub use cardan_loads::{
    kinetic_energy, torque_shares, Gas, Inertial, LoadFamily, ReducedInertia, ReducedInertiaOf,
    Solver,
};
pub use cardan_losses::{
    engine_metrics, failed, fmep_breakdown, pnh_engine, radial, tangential, Attachment,
    BearingSize, Bind, BindInput, CircularArcCam, EngineInput, EngineLosses, FmepModel,
    FollowerContact, Friction, GearInput, GearMaterial, GearSpec, LaneFailure, Loss, LossBudget,
    LossLanes, LossModel, LossParameter, Oil, ParameterValues, SetupInput, ToothLoad, ValveTrain,
    ValveTrainGeometry, ValveTrainLoss, LOSS_MODELS,
};
pub use cardan_pipeline::{
    at_each_lane, run, run_parallel, run_summary, summary_chunk, Block, CylinderGas, GasAt,
    Joinable, LaneError, PassedOn, RunError, RunRooms, RunTotals, SetupError, Sink, Stage,
    StageColumn, StageError, StageTotals, Step, StepBlock, StepRecord, Steps, SummarySink,
    MAX_CHUNK,
};
pub use gear_rating::{GearRatings, MeshRating};
pub use machine::{Machine, MachineKind};
pub use machine_stage::MachineStage;
pub use metrics::{Aggregation, Metric, MetricDef, Summary, METRICS};
pub use stages::{GearStage, LossStage};
