//! What a loss model is, below every module that binds or registers one: the trait of a bound
//! model ([`Loss`]), what it reads over a block's lanes ([`LossLanes`]), what it is bound with ([`BindInput`]:
//! where it attaches and what a registry entry's `bind` reads), the oil and the parameters of `[friction]` ([`Parameters`],
//! each default once, next to its source). The models are in [`crate::losses::models`], the
//! registry in [`crate::loss_models`], the budget that binds them in [`crate::losses`].

use crate::engine_losses::FollowerContact;
use crate::mesh::GearSpec;
use crate::SetupError;
use cardan_friction::{KARHULA_LOAD_CONSTANT, KARHULA_RING_MU, KARHULA_SKIRT_MU};
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

/// The parameters of the loss models, SI: what `[friction]` may set besides the models' words
/// and the oil. [`Parameters::default`] holds every default, with its source.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Parameters {
    /// μ_ring of Karhula's ring pack (A9.1.4; Andersson et al. 2002: 0.07).
    pub ring_friction_coefficient: f64,
    /// Crown height of the film model's barrel ring faces, m (5 µm: this project's choice, the
    /// order of the h_s of the Thai thesis's ring example, `docs/validation/thai-thesis.md`).
    pub ring_crown_height: f64,
    /// μ_skirt of Karhula's Coulomb skirt (A9.1.5; Andersson et al. 2002: 0.09).
    pub skirt_friction_coefficient: f64,
    /// Skirt length of the viscous skirt, m; `None`: 0.6 × bore (the Thai thesis's example
    /// proportions).
    pub skirt_length: Option<f64>,
    /// Radial skirt-to-liner clearance of the viscous skirt, m (20 µm, the Thai thesis's
    /// example).
    pub skirt_clearance: f64,
    /// Lubrication factor f0 of the Karhula and Palmgren bearings (Karhula App. 9.1: 2).
    pub lubrication_factor: f64,
    /// Constant of Karhula's bearing load term ([`KARHULA_LOAD_CONSTANT`]: 0.0009, which
    /// reproduces the thesis's tables; the print's 0.009 is `KARHULA_LOAD_CONSTANT_PRINTED`).
    pub bearing_load_constant: f64,
    /// Length over diameter L/D of a plain journal bearing (0.5: this project's choice, a
    /// short bearing, one of the ratios tabulated in `docs/validation/journal-bearings.md`).
    pub journal_length_ratio: f64,
    /// Radial clearance over journal radius c/R of a plain journal bearing (0.001: this
    /// project's choice, the usual design ratio).
    pub journal_clearance_ratio: f64,
    /// μ at a flat follower's cam contact ([`FollowerContact::FLAT`]: 0.08).
    pub cam_friction_coefficient: f64,
}

impl Default for Parameters {
    fn default() -> Self {
        Self {
            ring_friction_coefficient: KARHULA_RING_MU,
            ring_crown_height: 5e-6,
            skirt_friction_coefficient: KARHULA_SKIRT_MU,
            skirt_length: None,
            skirt_clearance: 20e-6,
            lubrication_factor: 2.0,
            bearing_load_constant: KARHULA_LOAD_CONSTANT,
            journal_length_ratio: 0.5,
            journal_clearance_ratio: 1e-3,
            cam_friction_coefficient: match FollowerContact::FLAT {
                FollowerContact::Flat {
                    friction_coefficient,
                } => friction_coefficient,
                FollowerContact::Roller { .. } => unreachable!(),
            },
        }
    }
}

/// What a loss model is bound with: where it attaches (the joint, its bearings, the bore) and
/// what it reads there (parameters, oil, gear pair, mechanism), the input of a registry entry's
/// `bind` ([`crate::loss_models::Bind::Loss`]).
#[derive(Clone, Copy)]
pub struct BindInput<'a> {
    /// The models' parameters (`[friction]`'s, else their defaults).
    pub parameters: &'a Parameters,
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

/// A setup that failed: the case field at fault and why.
pub fn failed(field: &str, e: &dyn std::fmt::Display) -> SetupError {
    SetupError {
        field: field.to_string(),
        rule: e.to_string(),
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
