//! What a loss model is, below every module that binds or registers one: the trait of a bound
//! model ([`Loss`]), what it reads over a block's lanes ([`LossLanes`]), what it is bound with ([`BindInput`]:
//! where it attaches and what a registry entry's `bind` reads), the oil and the models'
//! parameters ([`LossParameter`], each default once, next to its source; the values a case
//! sets, [`ParameterValues`]). The models are in [`crate::losses::models`], the
//! registry in [`crate::loss_models`], the budget that binds them in [`crate::losses`].

pub use crate::loss_parameter::LossParameter;
use crate::mesh::GearSpec;
use cardan_mechanism::{Bearings, Column, LoadsBlock, Mechanism, StateBlock};
use std::ops::Range;

/// The lubricant of every lubricated contact.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Oil {
    /// Kinematic viscosity ν at the running temperature, m²/s (Karhula: ≲ 5 mm²/s).
    pub kinematic_viscosity: f64,
    /// Density ρ, kg/m³ (Karhula: ≈ 900).
    pub density: f64,
}

impl Oil {
    /// Dynamic viscosity η = ν·ρ, Pa·s (Karhula A9.1.47).
    pub fn dynamic_viscosity(&self) -> f64 {
        self.kinematic_viscosity * self.density
    }
}

/// The loss-model parameters a case sets, SI (the others take their defaults).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct ParameterValues(Vec<(LossParameter, f64)>);

impl ParameterValues {
    /// Sets `parameter` to `value`.
    pub fn set(&mut self, parameter: LossParameter, value: f64) {
        self.0.retain(|(p, _)| *p != parameter);
        self.0.push((parameter, value));
    }

    /// The value of `parameter`: the one set, else its default.
    pub fn get(&self, parameter: LossParameter) -> Option<f64> {
        self.0
            .iter()
            .find(|(p, _)| *p == parameter)
            .map(|(_, v)| *v)
            .or_else(|| parameter.default())
    }

    /// The value of `parameter`, which has a default ([`LossParameter::default`]).
    pub fn value(&self, parameter: LossParameter) -> f64 {
        self.get(parameter)
            .unwrap_or_else(|| unreachable!("{parameter:?} has a default"))
    }
}

/// What a loss model is bound with: where it attaches (the joint, its bearings, the bore) and
/// what it reads there (parameters, oil, gear pair, mechanism), the input of a registry entry's
/// `bind` ([`crate::loss_models::Bind::Loss`]).
#[derive(Clone, Copy)]
pub struct BindInput<'a> {
    /// The parameters the case sets.
    pub parameters: &'a ParameterValues,
    /// Those the model being bound declares ([`crate::LossModel::parameters`]): the only ones
    /// it may read (set by [`crate::LossModel::bind_at`]; a caller gives none).
    pub declared: &'static [LossParameter],
    /// The oil.
    pub oil: &'a Oil,
    /// The gear pair a mesh's loss is computed on (the case's `[gear]`).
    pub pair: &'a GearSpec,
    /// The mechanism.
    pub mechanism: &'a dyn Mechanism,
    /// Cylinder bore, m.
    pub bore: f64,
    /// The joint the model attaches to (an index of the topology's joints; the rings, which
    /// attach to every piston, read none).
    pub joint: usize,
    /// A revolute joint's bearings, the case's catalogue values put in (`None` at any other
    /// site).
    pub bearings: Option<Bearings>,
}

impl BindInput<'_> {
    /// The value of `parameter`, which the model being bound declares: the case's, else its
    /// default (`None`: the model's own rule).
    pub fn parameter(&self, parameter: LossParameter) -> Option<f64> {
        self.declares(parameter);
        self.parameters.get(parameter)
    }

    /// The value of `parameter`, which the model being bound declares and which has a default
    /// ([`ParameterValues::value`]).
    pub fn value(&self, parameter: LossParameter) -> f64 {
        self.declares(parameter);
        self.parameters.value(parameter)
    }

    /// Refuses (in a debug build) a parameter the model being bound does not declare.
    fn declares(&self, parameter: LossParameter) {
        debug_assert!(
            self.declared.contains(&parameter),
            "{parameter:?} is read by a model that does not declare it"
        );
    }
}

/// What a loss model reads over the lanes of a block of steps: the block's columns (a single
/// step is a block of one lane, [`LossLanes::lanes`] `0..1`).
#[derive(Debug, Clone)]
pub struct LossLanes<'a> {
    /// The lanes to evaluate, in order (the block's first lanes).
    pub lanes: Range<usize>,
    /// The steps' states (crank, bodies, joints, pistons).
    pub states: &'a StateBlock,
    /// The total (lossless) loads.
    pub total: &'a LoadsBlock,
    /// Absolute cylinder pressure at each lane, Pa, if a gas model runs.
    pub pressure: Option<&'a Column>,
    /// The loss (W) at each lane of each gear-mesh joint a `GearRatings` (`cardan-dynamics`)
    /// has rated, by joint index: taken as it is instead of being computed again.
    pub rated_meshes: &'a [(usize, Column)],
}

impl<'a> LossLanes<'a> {
    /// Lane 0 of `states` and `total` alone: a single step, without gas or rated meshes.
    pub fn one(states: &'a StateBlock, total: &'a LoadsBlock) -> Self {
        Self {
            lanes: 0..1,
            states,
            total,
            pressure: None,
            rated_meshes: &[],
        }
    }
}

/// A loss model that cannot be evaluated at a lane: the lane and why.
#[derive(Debug, Clone, PartialEq)]
pub struct LaneFailure {
    pub lane: usize,
    pub why: String,
}

/// A loss model bound to its piston, joint or crank: its power loss over the lanes of a block.
/// A model is a type of [`crate::losses::models`] (or of its own module) implementing this and
/// deriving `Clone`.
pub trait Loss: LossClone + std::fmt::Debug + Send + Sync {
    /// The power loss at each lane of `at.lanes`, W, into the same lanes of `out`; `Err`: the
    /// first lane it cannot be computed at, and why (the lanes from there on are left unset).
    fn power(&mut self, at: &LossLanes, out: &mut Column) -> Result<(), LaneFailure>;

    /// Whether a step's loss depends on the steps before it (then the steps are taken in
    /// order, by one thread).
    fn carries_history(&self) -> bool {
        false
    }
}

/// A boxed [`Loss`] cloned (every `Clone` model has it).
pub trait LossClone {
    fn clone_box(&self) -> Box<dyn Loss>;
}

impl<T: Loss + Clone + 'static> LossClone for T {
    fn clone_box(&self) -> Box<dyn Loss> {
        Box::new(self.clone())
    }
}

impl Clone for Box<dyn Loss> {
    fn clone(&self) -> Self {
        self.clone_box()
    }
}
