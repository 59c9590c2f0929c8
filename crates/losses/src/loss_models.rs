//! The registry of loss models: every model a case file can name, its word, where it attaches
//! and how it is bound ([`Bind`]: the function that makes its bound [`crate::Loss`] from the
//! parameters of `[friction]` and its site). The case schema takes the words from here
//! ([`LOSS_MODELS`], [`words`]); [`crate::LossBudget`] binds the models to a mechanism's
//! pistons and joints by kind.
//!
//! Adding a loss model: its physics in `cardan-friction`, its [`crate::Loss`] impl and the
//! function that binds it ([`crate::losses::models`]), one line in [`LOSS_MODELS`] with the
//! parameters it reads; a parameter of its own is a [`LossParameter`] with its default and a
//! field of the case's `[friction]` table.

pub use crate::attachment::Attachment;
use crate::engine_losses::FollowerContact;
use crate::loss::{BindInput, LossParameter, ParameterValues};
use crate::losses::models::{
    bind_coulomb, bind_journal, bind_mesh, bind_ring_films, bind_ring_pack, bind_rolling,
    bind_viscous_skirt, BoundLoss,
};
use cardan_friction::{PalmgrenCoefficients, RollingReading, SkfDeepGrooveBall};
use cardan_gears::mesh_loss::Reading;

/// The word that switches an attachment's loss off.
pub const NONE: &str = "none";

/// How a registry entry binds its model.
#[derive(Clone, Copy)]
pub enum Bind {
    /// At a piston's cylinder or a joint: the bound loss from its [`BindInput`] (rings, skirt,
    /// bearings, gear mesh).
    Loss(fn(&BindInput) -> BoundLoss),
    /// At a gear mesh: Anderson & Loewenthal's loss in a reading ([`bind_mesh`]), which a gear
    /// rating of the mesh also takes over a block's lanes (the same model, the same bits).
    Mesh(Reading),
    /// An engine's valve train: its cam/follower contact from the parameters, which the engine's
    /// valve train ([`crate::ValveTrain`], with its springs and geometry) binds to the crank
    /// and the fmep cross-check reads (its PNH follower).
    Follower(fn(&ParameterValues) -> FollowerContact),
}

/// A loss model as the registry knows it.
#[derive(Clone, Copy)]
pub struct LossModel {
    /// Its word in case files (`"karhula"`, `"film"`), unique within its attachment.
    pub name: &'static str,
    pub attachment: Attachment,
    /// What it computes, with its source, in one line (the documentation's).
    pub summary: &'static str,
    /// The parameters it reads (the only ones its bind may read: [`BindInput::parameter`]).
    pub parameters: &'static [LossParameter],
    /// How it is bound.
    pub bind: Bind,
}

impl LossModel {
    /// The model bound at `site`; `None` for a valve train, which the engine binds
    /// ([`Bind::Follower`]).
    pub fn bind_at(&self, site: &BindInput) -> Option<BoundLoss> {
        let site = BindInput {
            declared: self.parameters,
            ..*site
        };
        match self.bind {
            Bind::Loss(bind) => Some(bind(&site)),
            Bind::Mesh(reading) => Some(bind_mesh(&site, reading)),
            Bind::Follower(_) => None,
        }
    }

    /// The reading of Anderson & Loewenthal's mesh loss this model is (`None`: another model).
    pub fn mesh_reading(&self) -> Option<Reading> {
        match self.bind {
            Bind::Mesh(reading) => Some(reading),
            _ => None,
        }
    }
}

/// A model is its attachment and word (unique in the registry).
impl PartialEq for LossModel {
    fn eq(&self, other: &Self) -> bool {
        self.attachment == other.attachment && self.name == other.name
    }
}

impl std::fmt::Debug for LossModel {
    fn fmt(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
        write!(f, "{:?} = \"{}\"", self.attachment, self.name)
    }
}

use LossParameter::*;

/// Every loss model a case file can name, one line each.
pub const LOSS_MODELS: &[LossModel] = &[
    LossModel {
        name: "karhula",
        attachment: Attachment::Rings,
        summary: "2 compression rings (2 mm, 0.19 MPa) and an oil ring (4 mm, 1 MPa), μ = ring_friction_coefficient (Karhula A9.1.2-4, A9.1.8)",
        parameters: &[RingFrictionCoefficient],
        bind: Bind::Loss(|s| bind_ring_pack(s, s.value(RingFrictionCoefficient))),
    },
    LossModel {
        name: "film",
        attachment: Attachment::Rings,
        summary: "each ring of the pack on its oil film (Reynolds with squeeze film, Greenwood-Tripp asperities), faces crowned by ring_crown_height",
        parameters: &[RingCrownHeight],
        bind: Bind::Loss(|s| bind_ring_films(s, s.value(RingCrownHeight))),
    },
    LossModel {
        name: "karhula",
        attachment: Attachment::Skirt,
        summary: "Coulomb friction on the side force, μ = skirt_friction_coefficient (Karhula A9.1.5)",
        parameters: &[SkirtFrictionCoefficient],
        bind: Bind::Loss(|s| bind_coulomb(s, s.value(SkirtFrictionCoefficient))),
    },
    LossModel {
        name: "viscous",
        attachment: Attachment::Skirt,
        summary: "Couette shear of a skirt of skirt_length and skirt_clearance (Thai thesis 2.5.c.1-3)",
        parameters: &[SkirtLength, SkirtClearance],
        bind: Bind::Loss(|s| {
            let length = s.parameter(SkirtLength).unwrap_or(0.6 * s.bore);
            bind_viscous_skirt(s, length, s.value(SkirtClearance))
        }),
    },
    LossModel {
        name: "karhula",
        attachment: Attachment::Bearing,
        summary: "rolling bearings as printed (Karhula A9.1.26-33), f0 = lubrication_factor, bearing_load_constant",
        parameters: &[LubricationFactor, BearingLoadConstant],
        bind: Bind::Loss(|s| bind_rolling(s, RollingReading::Karhula {
            f0: s.value(LubricationFactor),
            load_constant: s.value(BearingLoadConstant),
        })),
    },
    LossModel {
        name: "palmgren",
        attachment: Attachment::Bearing,
        summary: "Palmgren's M0 + M1 of a deep-groove ball bearing, f0 = lubrication_factor",
        parameters: &[LubricationFactor],
        bind: Bind::Loss(|s| bind_rolling(s, RollingReading::Palmgren(PalmgrenCoefficients {
            f0: s.value(LubricationFactor),
            ..PalmgrenCoefficients::DEEP_GROOVE_BALL
        }))),
    },
    LossModel {
        name: "skf",
        attachment: Attachment::Bearing,
        summary: "SKF's rolling and sliding moments of a series-62 deep-groove ball bearing",
        parameters: &[],
        bind: Bind::Loss(|s| bind_rolling(s, RollingReading::Skf(SkfDeepGrooveBall::SERIES_62))),
    },
    LossModel {
        name: "petroff",
        attachment: Attachment::Bearing,
        summary: "Petroff's concentric plain journal of journal_length_ratio and journal_clearance_ratio",
        parameters: &[JournalLengthRatio, JournalClearanceRatio],
        bind: Bind::Loss(|s| bind_journal(s, false)),
    },
    LossModel {
        name: "short_bearing",
        attachment: Attachment::Bearing,
        summary: "Ocvirk's short plain journal, the eccentricity from the instantaneous load",
        parameters: &[JournalLengthRatio, JournalClearanceRatio],
        bind: Bind::Loss(|s| bind_journal(s, true)),
    },
    LossModel {
        name: "karhula",
        attachment: Attachment::GearMesh,
        summary: "Anderson & Loewenthal's sliding, rolling and windage loss as printed (Karhula A9.1.36-55)",
        parameters: &[],
        bind: Bind::Mesh(Reading::Karhula),
    },
    LossModel {
        name: "corrected",
        attachment: Attachment::GearMesh,
        summary: "the same in centipoise, with carrier-relative internal-mesh kinematics and the pair's real geometry",
        parameters: &[],
        bind: Bind::Mesh(Reading::Corrected),
    },
    LossModel {
        name: "flat",
        attachment: Attachment::ValveTrain,
        summary: "two valves on circular-arc cams, flat followers, μ = cam_friction_coefficient (Thai thesis 2.5.d.15, 2.5.d.18)",
        parameters: &[CamFrictionCoefficient],
        bind: Bind::Follower(|p| FollowerContact::Flat {
            friction_coefficient: p.value(CamFrictionCoefficient),
        }),
    },
    LossModel {
        name: "roller",
        attachment: Attachment::ValveTrain,
        summary: "the same with roller followers: rolling resistance and the roller's pin bearing",
        parameters: &[],
        bind: Bind::Follower(|_| FollowerContact::ROLLER),
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
    use crate::loss::Oil;
    use crate::mesh::GearSpec;
    use cardan_mechanism::{JointKind, MachineGeometry, MassInputs, Options, MECHANISMS};

    #[test]
    fn every_model_has_a_unique_word_and_binds_at_its_attachment() {
        let g = MachineGeometry {
            crank_length: 0.06,
            rod_length: 0.14,
            bore: 0.12,
            pin_offset: 0.0,
        };
        let (p, pair) = (ParameterValues::default(), GearSpec::default());
        let oil = Oil {
            kinematic_viscosity: 5e-6,
            density: 900.0,
        };
        for m in LOSS_MODELS {
            let same = LOSS_MODELS
                .iter()
                .filter(|n| n.attachment == m.attachment && n.name == m.name);
            assert_eq!(same.count(), 1, "{} twice", m.name);
            assert_ne!(m.name, NONE);
            let ps = m.parameters;
            let once = (0..ps.len()).all(|i| !ps[..i].contains(&ps[i]));
            assert!(once, "{m:?} declares a parameter twice");
            // Only a valve train is bound by the engine; every other model binds at a site of
            // its attachment on every registered mechanism that has one.
            assert_eq!(
                matches!(m.bind, Bind::Follower(_)),
                m.attachment == Attachment::ValveTrain,
                "{m:?}"
            );
            for entry in MECHANISMS {
                let mechanism = (entry.build)(&g, &MassInputs::default(), &Options::new()).unwrap();
                let t = mechanism.topology();
                // `bind_at` declares the model's parameters: reading any other one panics.
                let site = |joint, bearings| BindInput {
                    parameters: &p,
                    declared: &[],
                    oil: &oil,
                    pair: &pair,
                    mechanism: mechanism.as_ref(),
                    bore: 0.12,
                    joint,
                    bearings,
                };
                let sites: Vec<BindInput> = match m.attachment {
                    Attachment::Rings => vec![site(0, None)],
                    Attachment::ValveTrain => vec![],
                    a => (t.joints.iter().enumerate())
                        .filter_map(|(k, j)| match (a, j.kind) {
                            (Attachment::Skirt, JointKind::Prismatic) => Some(site(k, None)),
                            (Attachment::Bearing, JointKind::Revolute(b)) => Some(site(k, Some(b))),
                            (Attachment::GearMesh, JointKind::GearMesh { .. }) => {
                                Some(site(k, None))
                            }
                            _ => None,
                        })
                        .collect(),
                };
                for s in &sites {
                    let bound = m.bind_at(s).expect("bound at its site");
                    assert!(bound.is_ok(), "{m:?} on {}: {bound:?}", entry.name);
                }
            }
        }
    }
}
