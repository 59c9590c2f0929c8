//! The losses of a mechanism's run, apart from the step loop that evaluates them: what a loss
//! model is ([`Loss`], the columns of a block it is evaluated on, [`LossLanes`]; what it is bound
//! with, [`BindInput`]), the registry of loss models ([`LOSS_MODELS`]) and their bound forms
//! ([`losses::models`], on the physics of `cardan-friction` and `cardan-gears`), the budget
//! that binds them to a mechanism's pistons and joints ([`LossBudget`], from the case's
//! [`Friction`]), the engine's own losses (valve train, accessories, pumping:
//! [`engine_losses`]) and the whole-engine fmep cross-check ([`fmep`]), a gear-mesh joint's
//! force components, speeds and pair ([`mesh`]), and the two definitions of the mechanical
//! efficiency ([`MachineKind`]). `cardan-dynamics` evaluates the budget at every step (its
//! loss stage) and re-exports this crate's items.

mod attachment;
pub mod engine_losses;
pub mod fmep;
pub mod loss;
pub mod loss_models;
mod loss_parameter;
pub mod losses;
mod machine_kind;
pub mod mesh;
mod setup_error;

pub use engine_losses::{
    CircularArcCam, EngineInput, EngineLosses, FmepModel, FollowerContact, ValveTrain,
    ValveTrainGeometry, ValveTrainLoss,
};
pub use fmep::{engine_metrics, fmep_breakdown, pnh_engine};
pub use loss::{BindInput, LaneFailure, Loss, LossLanes, LossParameter, Oil, ParameterValues};
pub use loss_models::{Attachment, Bind, LossModel, LOSS_MODELS};
pub use losses::{BearingSize, Friction, LossBudget};
pub use machine_kind::MachineKind;
pub use mesh::{radial, tangential, GearMaterial, GearSpec, IsoOverrides, ToothLoad};
pub use setup_error::{failed, GearInput, SetupError, SetupInput};
