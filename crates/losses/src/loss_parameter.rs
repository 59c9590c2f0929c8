//! The parameters of the loss models, each with its default next to its source: below what a
//! loss model is ([`crate::loss`]) and the setup errors that name a parameter.

use crate::engine_losses::FollowerContact;
use cardan_friction::{KARHULA_LOAD_CONSTANT, KARHULA_RING_MU, KARHULA_SKIRT_MU};

/// A parameter of a loss model, by what it is. Each model declares those it reads
/// ([`crate::LossModel::parameters`]; several models may read one, as both rolling readings of
/// f0) and is bound with their values ([`crate::BindInput::parameter`]): a value the case sets, else
/// the parameter's default ([`LossParameter::default`], with its source).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum LossParameter {
    /// μ_ring of Karhula's ring pack.
    RingFrictionCoefficient,
    /// Crown height of the film model's barrel ring faces, m.
    RingCrownHeight,
    /// μ_skirt of Karhula's Coulomb skirt.
    SkirtFrictionCoefficient,
    /// Skirt length of the viscous skirt, m.
    SkirtLength,
    /// Radial skirt-to-liner clearance of the viscous skirt, m.
    SkirtClearance,
    /// Lubrication factor f0 of the Karhula and Palmgren bearings.
    LubricationFactor,
    /// Constant of Karhula's bearing load term.
    BearingLoadConstant,
    /// Length over diameter L/D of a plain journal bearing.
    JournalLengthRatio,
    /// Radial clearance over journal radius c/R of a plain journal bearing.
    JournalClearanceRatio,
    /// μ at a flat follower's cam contact.
    CamFrictionCoefficient,
}

impl LossParameter {
    /// Every parameter.
    pub const ALL: [LossParameter; 10] = [
        LossParameter::RingFrictionCoefficient,
        LossParameter::RingCrownHeight,
        LossParameter::SkirtFrictionCoefficient,
        LossParameter::SkirtLength,
        LossParameter::SkirtClearance,
        LossParameter::LubricationFactor,
        LossParameter::BearingLoadConstant,
        LossParameter::JournalLengthRatio,
        LossParameter::JournalClearanceRatio,
        LossParameter::CamFrictionCoefficient,
    ];

    /// Its value where a case does not set it, SI; `None`: the model's own rule (the viscous
    /// skirt's length, 0.6 × bore).
    pub fn default(self) -> Option<f64> {
        Some(match self {
            // Karhula A9.1.4 after Andersson et al. 2002.
            LossParameter::RingFrictionCoefficient => KARHULA_RING_MU,
            // This project's choice, the order of the h_s of the Thai thesis's ring example
            // (`docs/validation/thai-thesis.md`).
            LossParameter::RingCrownHeight => 5e-6,
            // Karhula A9.1.5 after Andersson et al. 2002.
            LossParameter::SkirtFrictionCoefficient => KARHULA_SKIRT_MU,
            // The Thai thesis's example proportions, 0.6 × bore (the viscous skirt's bind).
            LossParameter::SkirtLength => return None,
            // The Thai thesis's example.
            LossParameter::SkirtClearance => 20e-6,
            // Karhula App. 9.1.
            LossParameter::LubricationFactor => 2.0,
            // 0.0009, which reproduces the thesis's tables (the print's 0.009 is
            // `KARHULA_LOAD_CONSTANT_PRINTED`).
            LossParameter::BearingLoadConstant => KARHULA_LOAD_CONSTANT,
            // This project's choice: a short bearing, one of the ratios tabulated in
            // `docs/validation/journal-bearings.md`.
            LossParameter::JournalLengthRatio => 0.5,
            // This project's choice, the usual design ratio.
            LossParameter::JournalClearanceRatio => 1e-3,
            // [`FollowerContact::FLAT`].
            LossParameter::CamFrictionCoefficient => match FollowerContact::FLAT {
                FollowerContact::Flat {
                    friction_coefficient,
                } => friction_coefficient,
                FollowerContact::Roller { .. } => unreachable!(),
            },
        })
    }
}
