//! A model that cannot be set up for a mechanism: the input at fault and why. The input is the
//! physics', typed ([`SetupInput`]); the case maps it to its field.

use crate::attachment::Attachment;
use crate::engine_losses::EngineInput;
use crate::loss_parameter::LossParameter;

/// A stage that cannot be set up for a mechanism (a loss model, a gear pair): the input at
/// fault and why.
#[derive(Debug, Clone, PartialEq)]
pub struct SetupError {
    /// The input at fault.
    pub field: SetupInput,
    pub rule: String,
}

impl std::fmt::Display for SetupError {
    fn fmt(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
        write!(f, "{:?}: {}", self.field, self.rule)
    }
}

/// A setup that failed: the input at fault and why.
pub fn failed(field: SetupInput, e: &dyn std::fmt::Display) -> SetupError {
    SetupError {
        field,
        rule: e.to_string(),
    }
}

/// An input a stage is set up from.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SetupInput {
    /// The cylinder's bore.
    Bore,
    /// A loss model's parameter.
    Parameter(LossParameter),
    /// The loss model chosen for an attachment.
    Model(Attachment),
    /// An input of the gear pairs ([`crate::GearSpec`]).
    Gear(GearInput),
    /// An input of the engine's losses ([`crate::EngineLosses`]).
    Engine(EngineInput),
}

impl SetupInput {
    /// Every input, each parameter and attachment once.
    pub fn all() -> Vec<SetupInput> {
        let engine = EngineInput::ALL.into_iter().map(SetupInput::Engine);
        let parameters = LossParameter::ALL.into_iter().map(SetupInput::Parameter);
        let models = Attachment::ALL.into_iter().map(SetupInput::Model);
        let gear = GearInput::ALL.into_iter().map(SetupInput::Gear);
        let inputs = std::iter::once(SetupInput::Bore)
            .chain(engine)
            .chain(parameters);
        inputs.chain(models).chain(gear).collect()
    }
}

/// An input of the gear pairs, [`crate::GearSpec`]'s.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum GearInput {
    /// The pair as a whole (its tooth form from all of its inputs).
    Pair,
    /// [`crate::GearSpec::teeth`].
    Teeth,
    /// [`crate::GearSpec::ring_addendum`].
    RingAddendum,
    /// [`crate::GearSpec::face_width`].
    FaceWidth,
    /// [`crate::GearSpec::hardness`].
    Hardness,
    /// [`crate::GearSpec::youngs_modulus`].
    YoungsModulus,
    /// [`crate::GearSpec::tooth_load`].
    ToothLoad,
    /// [`crate::GearSpec::j`].
    J,
    /// [`crate::GearSpec::accuracy_grade`].
    AccuracyGrade,
}

impl GearInput {
    /// Every gear input.
    pub const ALL: [GearInput; 9] = [
        GearInput::Pair,
        GearInput::Teeth,
        GearInput::RingAddendum,
        GearInput::FaceWidth,
        GearInput::Hardness,
        GearInput::YoungsModulus,
        GearInput::ToothLoad,
        GearInput::J,
        GearInput::AccuracyGrade,
    ];
}
