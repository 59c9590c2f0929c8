//! What a loss model is, below every module that binds or registers one: the trait of a bound
//! model ([`Loss`]), what it reads at a step ([`LossInput`]), what it is bound with ([`BindInput`]:
//! where it attaches and what a registry entry's `bind` reads), the oil and the parameters of `[friction]` ([`Parameters`],
//! each default once, next to its source). The models are in [`crate::losses::models`], the
//! registry in [`crate::loss_models`], the budget that binds them in [`crate::losses`].

use crate::engine_losses::FollowerContact;
use crate::mesh::GearSpec;
use crate::SetupError;
use cardan_friction::{KARHULA_LOAD_CONSTANT, KARHULA_RING_MU, KARHULA_SKIRT_MU};
use cardan_mechanism::{Bearings, Loads, Mechanism, State};

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

/// What a loss model reads at a step.
#[derive(Debug, Clone, Copy)]
pub struct LossInput<'a> {
    /// The step's state (crank, pistons, joints).
    pub state: &'a State,
    /// The total (lossless) loads.
    pub total: &'a Loads,
    /// Absolute cylinder pressure, Pa, if a gas model runs.
    pub pressure: Option<f64>,
    /// The loss (W) of each gear-mesh joint a `GearRatings` (`cardan-dynamics`) has rated at this step.
    pub rated_meshes: &'a [(usize, f64)],
}

/// A loss model bound to its piston, joint or crank: its power loss step by step. A model is a
/// type of [`crate::losses::models`] (or of its own module) implementing this and deriving
/// `Clone`.
pub trait Loss: LossClone + std::fmt::Debug + Send + Sync {
    /// The power loss at the step, W; `Err`: why it cannot be computed.
    fn power(&mut self, at: &LossInput) -> Result<f64, String>;

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
