//! The loss budget: friction models of `cardan-friction` and the gear-mesh loss of
//! `cardan-gears` attached to a mechanism's pistons and joints by kind, with no mechanism code.
//! At every step each component's power loss follows from the joint's total (lossless) load and
//! relative speed, or from the piston's speed, as Karhula (2008) App. 9.1 computes them: the
//! losses are charged to the drive afterwards (A9.1.56-75) and do not change the loads.
//!
//! The components, in this order:
//! - `rings`: the piston rings of every piston in a cylinder (A9.1.2-4, A9.1.8), or each ring
//!   on its oil film (Reynolds with squeeze film and asperity contact, [`cardan_friction::RingFilm`]);
//! - per prismatic joint: `skirt` for the slide of a piston on the frame (its side force,
//!   A9.1.5; the viscous skirt of the Thai thesis 2.5.c.1-3 in the other reading), the joint's
//!   own name for any other slide (a Scotch-yoke slot: Coulomb friction on its force);
//! - per revolute joint, by its name: its rolling bearings (A9.1.10-35; Palmgren; SKF) or a
//!   plain journal bearing (Petroff; short bearing with the eccentricity from the load);
//! - per gear mesh, by its name: Anderson & Loewenthal's sliding, rolling and windage loss
//!   (A9.1.36-55) in the thesis's or the corrected reading;
//! - of an engine ([`Friction::engine`]) with a cylinder, each if switched on: `valve_train`,
//!   `accessories`, `pumping` ([`crate::engine_losses`]), at the step's crank speed.

pub mod models;

use crate::engine_losses::{displacement, EngineLosses, ValveTrainLoss};
use crate::loss_models::Parameters;
use crate::mesh::{mesh_pair, GearSpec};
use crate::stage::SetupError;
use cardan_friction::{
    AsperityContact, JournalBearing, KarhulaRingPack, RingFilm, RingProfile, RollingBearing,
    RollingModel, RollingReading, ViscousSkirt, KARHULA_SKIRT_MU,
};
use cardan_gears::mesh_loss::{Lubricant, MeshGeometry, Reading};
use cardan_mechanism::{Bearings, JointKind, Loads, Mechanism, State};

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

/// How the piston rings are modelled.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Rings {
    /// Karhula's pack (2 compression rings of 2 mm at 0.19 MPa, 1 oil ring of 4 mm at 1 MPa)
    /// with a constant friction coefficient (A9.1.2-4, A9.1.8).
    Karhula {
        /// μ_ring (Karhula: 0.07, Andersson et al. 2002).
        friction_coefficient: f64,
    },
    /// Each ring of the same pack on an oil film: a barrel face of the ring's height and
    /// `crown_height`, loaded by its elastic pressure and, for the top ring, the cylinder
    /// pressure above atmospheric behind it (the lower rings see none: inter-ring pressures are
    /// not modelled); squeeze film stepped in time, Greenwood-Tripp asperity contact with
    /// [`AsperityContact::typical`] surfaces.
    Film {
        /// Crown height of the barrel faces, m.
        crown_height: f64,
    },
}

/// How the skirt of a piston sliding on the frame is modelled.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Skirt {
    /// Coulomb friction on the side force (A9.1.5; μ_skirt = 0.09 in the thesis).
    Coulomb { friction_coefficient: f64 },
    /// Couette shear of a concentric full film (Thai thesis 2.5.c.1-3): needs no side force.
    Viscous {
        /// Skirt length, m.
        length: f64,
        /// Radial skirt-to-liner clearance, m.
        clearance: f64,
    },
}

/// How the bearings of a revolute joint are modelled.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Bearing {
    /// The joint's rolling bearings ([`Bearings`]: pitch diameter, C0, how many share the load)
    /// in one of the readings of [`cardan_friction::rolling_bearing_loss`].
    Rolling(RollingReading),
    /// A plain journal bearing of the joint's journal radius.
    Journal {
        /// Short-bearing (Ocvirk) solution with the eccentricity from the instantaneous load;
        /// `false`: Petroff's concentric journal.
        short_bearing: bool,
        /// Bearing length over diameter L/D.
        length_ratio: f64,
        /// Radial clearance over journal radius c/R.
        clearance_ratio: f64,
    },
}

/// Catalogue values of a joint's bearings; `None` keeps the declared value.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct BearingSize {
    /// Pitch (mean) diameter d_m of one bearing, m (the journal diameter of a plain bearing).
    pub pitch_diameter: Option<f64>,
    /// Basic static load rating C0 of one bearing, N.
    pub static_load_rating: Option<f64>,
    /// Bearings side by side sharing the joint's load.
    pub count: Option<u32>,
}

impl BearingSize {
    /// `declared` with these values put in.
    pub fn apply(&self, declared: Bearings) -> Bearings {
        Bearings {
            radius: self.pitch_diameter.map_or(declared.radius, |d| d / 2.0),
            count: self.count.unwrap_or(declared.count),
            static_load_rating: self
                .static_load_rating
                .unwrap_or(declared.static_load_rating),
        }
    }
}

/// The gear mesh loss and the pair it is computed on.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MeshLossModel {
    pub reading: Reading,
    /// The pair (the case's `[gear]`; Karhula's 20-tooth wheel with a 0.8-module ring addendum
    /// and b = d1/3 by default, A9.1.36-46).
    pub pair: GearSpec,
}

/// Every loss model of a case, SI.
#[derive(Debug, Clone, PartialEq)]
pub struct Friction {
    pub oil: Oil,
    /// `None`: no ring loss.
    pub rings: Option<Rings>,
    /// `None`: no skirt loss.
    pub skirt: Option<Skirt>,
    /// Coulomb friction coefficient of the other slides (a Scotch-yoke slot).
    pub slide_friction_coefficient: f64,
    /// Model of every revolute joint; `None`: no bearing loss.
    pub bearings: Option<Bearing>,
    /// Models of named revolute joints (`None`: no loss), overriding [`Friction::bearings`].
    pub joint_bearings: Vec<(String, Option<Bearing>)>,
    /// Catalogue values of named revolute joints' bearings, overriding the sizing rules the
    /// mechanism declared (Karhula A9.1.10-13).
    pub joint_sizes: Vec<(String, BearingSize)>,
    /// `None`: no gear mesh loss.
    pub gear_mesh: Option<MeshLossModel>,
    /// The engine components (valve train, accessories, pumping) and the fmep cross-check of a
    /// four-stroke engine; `None` for a machine that is not an engine. The runner sets it for
    /// `machine = "engine"`, with every component off unless the case switches it on.
    pub engine: Option<EngineLosses>,
}

impl Friction {
    /// Karhula's (2008) App. 9.1 models and values ([`Parameters::default`]): ring pack with
    /// μ = 0.07, Coulomb skirt (and other slides) with μ = 0.09, rolling bearings in his reading
    /// with f0 = 2, mesh loss as printed with z1 = 20, oil of 5 mm²/s and 900 kg/m³; no engine
    /// components (the thesis has none).
    pub fn karhula() -> Self {
        let p = Parameters::default();
        Self {
            oil: Oil {
                kinematic_viscosity: 5e-6,
                density: 900.0,
            },
            rings: Some(Rings::Karhula {
                friction_coefficient: p.ring_friction_coefficient,
            }),
            skirt: Some(Skirt::Coulomb {
                friction_coefficient: p.skirt_friction_coefficient,
            }),
            slide_friction_coefficient: KARHULA_SKIRT_MU,
            bearings: Some(Bearing::Rolling(RollingReading::Karhula {
                f0: p.lubrication_factor,
                load_constant: p.bearing_load_constant,
            })),
            joint_bearings: Vec::new(),
            joint_sizes: Vec::new(),
            gear_mesh: Some(MeshLossModel {
                reading: Reading::Karhula,
                pair: GearSpec::default(),
            }),
            engine: None,
        }
    }
}

/// What a loss model reads at a step.
#[derive(Debug, Clone, Copy)]
pub struct At<'a> {
    /// The step's state (crank, pistons, joints).
    pub state: &'a State,
    /// The total (lossless) loads.
    pub total: &'a Loads,
    /// Absolute cylinder pressure, Pa, if a gas model runs.
    pub pressure: Option<f64>,
    /// The loss (W) of each gear-mesh joint a [`crate::GearRatings`] has rated at this step.
    pub rated_meshes: &'a [(usize, f64)],
}

/// A loss model bound to its piston, joint or crank: its power loss step by step. A model is a
/// type of [`models`] (or of its own module) implementing this and deriving `Clone`.
pub trait Loss: LossClone + std::fmt::Debug + Send + Sync {
    /// The power loss at the step, W; `Err`: why it cannot be computed.
    fn power(&mut self, at: &At) -> Result<f64, String>;

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

/// The loss models of one mechanism, ready to evaluate step by step.
#[derive(Debug, Clone)]
pub struct LossBudget {
    names: Vec<String>,
    parts: Vec<Box<dyn Loss>>,
}

impl LossBudget {
    /// The budget of `mechanism` in a cylinder of `bore` (m) under `friction`.
    pub fn new(
        friction: &Friction,
        mechanism: &dyn Mechanism,
        bore: f64,
    ) -> Result<Self, SetupError> {
        let t = mechanism.topology();
        let viscosity = friction.oil.dynamic_viscosity();
        let mut names = Vec::new();
        let mut parts = Vec::new();
        if mechanism.has_cylinder() {
            if let Some(rings) = friction.rings {
                names.push("rings".to_string());
                parts.push(rings.bind(bore, t.pistons.len(), viscosity)?);
            }
        }
        for (k, j) in t.joints.iter().enumerate() {
            match j.kind {
                JointKind::Prismatic => {
                    let skirt = j.other.is_none() && t.pistons.iter().any(|p| p.body == j.body);
                    let part = match (skirt, friction.skirt) {
                        (true, None) => continue,
                        (true, Some(model)) => model.bind(k, bore, viscosity)?,
                        (false, _) => models::coulomb(k, friction.slide_friction_coefficient),
                    };
                    names.push(if skirt { "skirt" } else { j.name }.to_string());
                    parts.push(part);
                }
                JointKind::Revolute(b) => {
                    let model = friction
                        .joint_bearings
                        .iter()
                        .find(|(name, _)| name == j.name)
                        .map_or(friction.bearings, |(_, m)| *m);
                    let Some(model) = model else { continue };
                    let b = friction
                        .joint_sizes
                        .iter()
                        .find(|(name, _)| name == j.name)
                        .map_or(b, |(_, size)| size.apply(b));
                    parts.push(model.bind(k, b, &friction.oil)?);
                    names.push(j.name.to_string());
                }
                JointKind::GearMesh {
                    ratio,
                    pitch_radius,
                    internal,
                    pressure_angle,
                    ..
                } => {
                    let Some(mesh) = friction.gear_mesh else {
                        continue;
                    };
                    let geometry =
                        mesh_geometry(&mesh, ratio, pitch_radius, internal, pressure_angle)?;
                    names.push(j.name.to_string());
                    parts.push(Box::new(models::Mesh {
                        joint: k,
                        body: j.body,
                        geometry,
                        lubricant: Lubricant {
                            kinematic_viscosity: friction.oil.kinematic_viscosity,
                            density: friction.oil.density,
                        },
                        reading: mesh.reading,
                        pitch_radius,
                        sets: if mesh.pair.twin { 2.0 } else { 1.0 },
                    }));
                }
            }
        }
        if let (Some(engine), true) = (&friction.engine, mechanism.has_cylinder()) {
            engine
                .check()
                .map_err(|(field, rule)| failed(field, &rule))?;
            let volume = displacement(bore, mechanism.stroke());
            if let Some(train) = &engine.valve_train {
                let part = ValveTrainLoss::new(train, bore, mechanism.top_dead_centre())
                    .map_err(|e| failed("friction.valve_train", &e))?;
                names.push("valve_train".to_string());
                parts.push(Box::new(part));
            }
            if engine.accessories {
                names.push("accessories".to_string());
                parts.push(Box::new(models::Accessories {
                    displacement: volume,
                }));
            }
            if engine.pumping {
                names.push("pumping".to_string());
                parts.push(Box::new(models::Pumping {
                    displacement: volume,
                    engine: *engine,
                }));
            }
        }
        Ok(Self { names, parts })
    }

    /// The components' names, in the order of [`LossBudget::evaluate`]'s output.
    pub fn names(&self) -> &[String] {
        &self.names
    }

    /// Whether a step's losses depend on the steps before it (the ring films' squeeze term
    /// carries each film's thickness from step to step): then the steps must be taken in
    /// order, by one thread.
    pub fn carries_history(&self) -> bool {
        self.parts.iter().any(|p| p.carries_history())
    }

    /// The power loss of each component at `state` under the `total` loads, W, into `out`
    /// (one per name). `pressure` is the absolute cylinder pressure, Pa, if a gas model runs;
    /// `rated_meshes` the loss (W) of each gear-mesh joint a [`crate::GearRatings`] has rated
    /// at this step, taken as it is instead of being computed again.
    pub fn evaluate(
        &mut self,
        state: &State,
        total: &Loads,
        pressure: Option<f64>,
        rated_meshes: &[(usize, f64)],
        out: &mut [f64],
    ) -> Result<(), String> {
        let at = At {
            state,
            total,
            pressure,
            rated_meshes,
        };
        for (part, out) in self.parts.iter_mut().zip(out.iter_mut()) {
            *out = part.power(&at)?;
        }
        Ok(())
    }
}

impl Rings {
    /// The rings of `pistons` pistons in a cylinder of `bore` (m), oil of dynamic viscosity
    /// `viscosity` (Pa·s).
    fn bind(self, bore: f64, pistons: usize, viscosity: f64) -> Result<Box<dyn Loss>, SetupError> {
        let pack = KarhulaRingPack::karhula(bore).map_err(|e| failed("geometry.bore", &e))?;
        Ok(match self {
            Rings::Karhula {
                friction_coefficient,
            } => Box::new(models::RingPack {
                force: friction_coefficient * pack.contact_force(),
            }),
            Rings::Film { crown_height } => {
                let ring = |height: f64, pressure: f64, top: bool| {
                    let profile = RingProfile::Barrel {
                        width: height,
                        crown_height,
                    };
                    RingFilm::new(profile, bore, AsperityContact::typical())
                        .map(|f| (f, pressure, top))
                        .map_err(|e| failed("friction.ring_crown_height", &e))
                };
                let mut rings = Vec::new();
                for k in 0..pack.compression_rings {
                    rings.push(ring(
                        pack.compression_ring_height,
                        pack.compression_ring_pressure,
                        k == 0,
                    )?);
                }
                for _ in 0..pack.oil_rings {
                    rings.push(ring(pack.oil_ring_height, pack.oil_ring_pressure, false)?);
                }
                Box::new(models::RingFilms {
                    films: vec![None; rings.len() * pistons],
                    rings,
                    time: None,
                    viscosity,
                })
            }
        })
    }
}

impl Skirt {
    /// The skirt of the piston sliding on prismatic joint `joint`, in a cylinder of `bore` (m).
    fn bind(self, joint: usize, bore: f64, viscosity: f64) -> Result<Box<dyn Loss>, SetupError> {
        Ok(match self {
            Skirt::Viscous { length, clearance } => Box::new(models::ViscousSkirtLoss {
                joint,
                skirt: ViscousSkirt::new(bore, length, clearance)
                    .map_err(|e| failed("friction.skirt_length", &e))?,
                viscosity,
            }),
            Skirt::Coulomb {
                friction_coefficient,
            } => models::coulomb(joint, friction_coefficient),
        })
    }
}

impl Bearing {
    /// The bearings `b` of revolute joint `joint`.
    fn bind(self, joint: usize, b: Bearings, oil: &Oil) -> Result<Box<dyn Loss>, SetupError> {
        let count = f64::from(b.count.max(1));
        Ok(match self {
            Bearing::Rolling(reading) => Box::new(models::Rolling {
                joint,
                model: RollingModel::new(
                    RollingBearing::new(2.0 * b.radius, b.static_load_rating)
                        .map_err(|e| failed("friction.bearings", &e))?,
                    reading,
                ),
                count,
                viscosity: oil.kinematic_viscosity,
            }),
            Bearing::Journal {
                short_bearing,
                length_ratio,
                clearance_ratio,
            } => Box::new(models::Journal {
                joint,
                bearing: JournalBearing::new(
                    b.radius,
                    2.0 * b.radius * length_ratio,
                    b.radius * clearance_ratio,
                )
                .map_err(|e| failed("friction.journal_length_ratio", &e))?,
                count,
                short: short_bearing,
                viscosity: oil.dynamic_viscosity(),
            }),
        })
    }
}

/// A setup that failed: the case field at fault and why.
fn failed(field: &str, e: &dyn std::fmt::Display) -> SetupError {
    SetupError {
        field: field.to_string(),
        rule: e.to_string(),
    }
}

/// The mesh geometry of the pair [`mesh_pair`] builds for a mesh joint.
fn mesh_geometry(
    mesh: &MeshLossModel,
    ratio: f64,
    pitch_radius: f64,
    internal: bool,
    pressure_angle: f64,
) -> Result<MeshGeometry, SetupError> {
    let (pair, face_width) = mesh_pair(&mesh.pair, ratio, pitch_radius, internal, pressure_angle)?;
    MeshGeometry::from_pair(&pair, face_width).map_err(|e| SetupError {
        field: "gear.face_width".into(),
        rule: e.to_string(),
    })
}
