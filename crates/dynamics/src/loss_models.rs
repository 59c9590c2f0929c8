//! The registry of loss models: every model a case file can name, its word, where it attaches
//! and how its setting follows from the parameters of `[friction]` ([`Parameters`], each
//! default once, next to its source). The case schema takes the words from here
//! ([`LOSS_MODELS`], [`words`]); [`crate::LossBudget`] binds the settings to a mechanism's
//! pistons and joints by kind.
//!
//! Adding a loss model: its physics in `cardan-friction`, its setting (a variant of the
//! attachment's enum in [`crate::losses`] and its step in `LossBudget`), one line in
//! [`LOSS_MODELS`]; a parameter of its own is a field of [`Parameters`] and of the case's
//! `[friction]` table.

use crate::engine_losses::FollowerContact;
use crate::losses::{Bearing, Rings, Skirt};
use cardan_friction::{
    PalmgrenCoefficients, RollingReading, SkfDeepGrooveBall, KARHULA_LOAD_CONSTANT,
    KARHULA_RING_MU, KARHULA_SKIRT_MU,
};
use cardan_gears::mesh_loss::Reading;

/// Where a loss model attaches.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Attachment {
    /// The rings of every piston in a cylinder (`rings`).
    Rings,
    /// A piston's slide on the frame (`skirt`).
    Skirt,
    /// The bearings of a revolute joint (`bearings`, `joints.<name>`).
    Bearing,
    /// A gear mesh (`gear_mesh`).
    GearMesh,
    /// An engine's valve train (`valve_train`).
    ValveTrain,
}

impl Attachment {
    /// The field of `[friction]` that chooses this attachment's model.
    pub fn field(self) -> &'static str {
        match self {
            Attachment::Rings => "rings",
            Attachment::Skirt => "skirt",
            Attachment::Bearing => "bearings",
            Attachment::GearMesh => "gear_mesh",
            Attachment::ValveTrain => "valve_train",
        }
    }
}

/// The word that switches an attachment's loss off.
pub const NONE: &str = "none";

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

/// A model's setting, for its attachment.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Setting {
    Rings(Rings),
    Skirt(Skirt),
    Bearing(Bearing),
    GearMesh(Reading),
    ValveTrain(FollowerContact),
}

/// A loss model as the registry knows it.
#[derive(Debug, Clone, Copy)]
pub struct LossModel {
    /// Its word in case files (`"karhula"`, `"film"`), unique within its attachment.
    pub name: &'static str,
    pub attachment: Attachment,
    /// What it computes, with its source, in one line (the documentation's).
    pub summary: &'static str,
    /// Its setting from the parameters, for a cylinder of a bore (m).
    pub setting: fn(&Parameters, f64) -> Setting,
}

/// Every loss model a case file can name, one line each.
pub const LOSS_MODELS: &[LossModel] = &[
    LossModel {
        name: "karhula",
        attachment: Attachment::Rings,
        summary: "2 compression rings (2 mm, 0.19 MPa) and an oil ring (4 mm, 1 MPa), μ = ring_friction_coefficient (Karhula A9.1.2-4, A9.1.8)",
        setting: |p, _| Setting::Rings(Rings::Karhula {
            friction_coefficient: p.ring_friction_coefficient,
        }),
    },
    LossModel {
        name: "film",
        attachment: Attachment::Rings,
        summary: "each ring of the pack on its oil film (Reynolds with squeeze film, Greenwood-Tripp asperities), faces crowned by ring_crown_height",
        setting: |p, _| Setting::Rings(Rings::Film {
            crown_height: p.ring_crown_height,
        }),
    },
    LossModel {
        name: "karhula",
        attachment: Attachment::Skirt,
        summary: "Coulomb friction on the side force, μ = skirt_friction_coefficient (Karhula A9.1.5)",
        setting: |p, _| Setting::Skirt(Skirt::Coulomb {
            friction_coefficient: p.skirt_friction_coefficient,
        }),
    },
    LossModel {
        name: "viscous",
        attachment: Attachment::Skirt,
        summary: "Couette shear of a skirt of skirt_length and skirt_clearance (Thai thesis 2.5.c.1-3)",
        setting: |p, bore| Setting::Skirt(Skirt::Viscous {
            length: p.skirt_length.unwrap_or(0.6 * bore),
            clearance: p.skirt_clearance,
        }),
    },
    LossModel {
        name: "karhula",
        attachment: Attachment::Bearing,
        summary: "rolling bearings as printed (Karhula A9.1.26-33), f0 = lubrication_factor, bearing_load_constant",
        setting: |p, _| Setting::Bearing(Bearing::Rolling(RollingReading::Karhula {
            f0: p.lubrication_factor,
            load_constant: p.bearing_load_constant,
        })),
    },
    LossModel {
        name: "palmgren",
        attachment: Attachment::Bearing,
        summary: "Palmgren's M0 + M1 of a deep-groove ball bearing, f0 = lubrication_factor",
        setting: |p, _| Setting::Bearing(Bearing::Rolling(RollingReading::Palmgren(
            PalmgrenCoefficients {
                f0: p.lubrication_factor,
                ..PalmgrenCoefficients::DEEP_GROOVE_BALL
            },
        ))),
    },
    LossModel {
        name: "skf",
        attachment: Attachment::Bearing,
        summary: "SKF's rolling and sliding moments of a series-62 deep-groove ball bearing",
        setting: |_, _| Setting::Bearing(Bearing::Rolling(RollingReading::Skf(
            SkfDeepGrooveBall::SERIES_62,
        ))),
    },
    LossModel {
        name: "petroff",
        attachment: Attachment::Bearing,
        summary: "Petroff's concentric plain journal of journal_length_ratio and journal_clearance_ratio",
        setting: |p, _| Setting::Bearing(Bearing::Journal {
            short_bearing: false,
            length_ratio: p.journal_length_ratio,
            clearance_ratio: p.journal_clearance_ratio,
        }),
    },
    LossModel {
        name: "short_bearing",
        attachment: Attachment::Bearing,
        summary: "Ocvirk's short plain journal, the eccentricity from the instantaneous load",
        setting: |p, _| Setting::Bearing(Bearing::Journal {
            short_bearing: true,
            length_ratio: p.journal_length_ratio,
            clearance_ratio: p.journal_clearance_ratio,
        }),
    },
    LossModel {
        name: "karhula",
        attachment: Attachment::GearMesh,
        summary: "Anderson & Loewenthal's sliding, rolling and windage loss as printed (Karhula A9.1.36-55)",
        setting: |_, _| Setting::GearMesh(Reading::Karhula),
    },
    LossModel {
        name: "corrected",
        attachment: Attachment::GearMesh,
        summary: "the same in centipoise, with carrier-relative internal-mesh kinematics and the pair's real geometry",
        setting: |_, _| Setting::GearMesh(Reading::Corrected),
    },
    LossModel {
        name: "flat",
        attachment: Attachment::ValveTrain,
        summary: "two valves on circular-arc cams, flat followers, μ = cam_friction_coefficient (Thai thesis 2.5.d.15, 2.5.d.18)",
        setting: |p, _| Setting::ValveTrain(FollowerContact::Flat {
            friction_coefficient: p.cam_friction_coefficient,
        }),
    },
    LossModel {
        name: "roller",
        attachment: Attachment::ValveTrain,
        summary: "the same with roller followers: rolling resistance and the roller's pin bearing",
        setting: |_, _| Setting::ValveTrain(FollowerContact::ROLLER),
    },
];

/// The words of an attachment's models, then [`NONE`].
pub fn words(attachment: Attachment) -> Vec<&'static str> {
    LOSS_MODELS
        .iter()
        .filter(|m| m.attachment == attachment)
        .map(|m| m.name)
        .chain([NONE])
        .collect()
}

/// The model of an attachment when `[friction]` names none: Karhula's (2008) App. 9.1 set
/// ([`crate::Friction::karhula`]); no valve train (the thesis has none).
pub fn default_model(attachment: Attachment) -> Option<&'static LossModel> {
    match attachment {
        Attachment::ValveTrain => None,
        a => find(a, "karhula"),
    }
}

/// The model of `attachment` written `name`; `None` if there is none of that name.
pub fn find(attachment: Attachment, name: &str) -> Option<&'static LossModel> {
    LOSS_MODELS
        .iter()
        .find(|m| m.attachment == attachment && m.name == name)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_model_has_its_attachments_setting_and_a_unique_word() {
        let p = Parameters::default();
        for m in LOSS_MODELS {
            let same = LOSS_MODELS
                .iter()
                .filter(|n| n.attachment == m.attachment && n.name == m.name);
            assert_eq!(same.count(), 1, "{} twice", m.name);
            assert_ne!(m.name, NONE);
            let attachment = match (m.setting)(&p, 0.1) {
                Setting::Rings(_) => Attachment::Rings,
                Setting::Skirt(_) => Attachment::Skirt,
                Setting::Bearing(_) => Attachment::Bearing,
                Setting::GearMesh(_) => Attachment::GearMesh,
                Setting::ValveTrain(_) => Attachment::ValveTrain,
            };
            assert_eq!(attachment, m.attachment, "{}", m.name);
        }
    }
}
