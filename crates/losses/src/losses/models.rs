//! The loss models bound to a mechanism: one type per model, each its power loss over a block's
//! lanes ([`Loss`], read from the block's columns) from the joint's total load and relative speed, the pistons' speeds or the
//! crank's, and the functions that bind it from its [`BindInput`] (the registry's entries,
//! [`crate::loss_models::LOSS_MODELS`], call them); [`crate::LossBudget`] binds them by joint
//! kind.

use crate::attachment::Attachment;
use crate::engine_losses::{
    accessories_power, pumping_power, EngineLosses, ValveTrainLoss, AMBIENT_PRESSURE,
};
use crate::loss::{BindInput, LaneFailure, Loss, LossLanes, LossParameter};
use crate::mesh::{mesh_pair, mesh_speeds, tangential};
use crate::setup_error::{failed, GearInput, SetupError, SetupInput};
use cardan_friction::{
    coulomb_sliding, petroff, short_bearing, viscous_skirt, AsperityContact, JournalBearing,
    KarhulaRingPack, KeptPower, LoadPower, RingFilm, RingLoad, RingProfile, RollingBearing,
    RollingModel, RollingReading, ViscousSkirt,
};
use cardan_gears::mesh_loss::{Lubricant, MeshGeometry, PreparedMeshLoss, Reading};
use cardan_mechanism::{Bearings, Column, JointKind, ZERO};
use std::ops::Range;

/// What a bound model is: its [`Loss`], or why it cannot be set up.
pub type BoundLoss = Result<Box<dyn Loss>, SetupError>;

/// Karhula's ring pack (2 compression rings of 2 mm at 0.19 MPa, 1 oil ring of 4 mm at 1 MPa)
/// in a cylinder of the site's bore.
fn ring_pack(site: &BindInput) -> Result<KarhulaRingPack, SetupError> {
    KarhulaRingPack::karhula(site.bore).map_err(|e| failed(SetupInput::Bore, &e))
}

/// Karhula's ring pack with a constant friction coefficient μ (A9.1.2-4, A9.1.8).
pub fn bind_ring_pack(site: &BindInput, friction_coefficient: f64) -> BoundLoss {
    let pack = ring_pack(site)?;
    Ok(Box::new(RingPack {
        force: friction_coefficient * pack.contact_force(),
    }))
}

/// Each ring of Karhula's pack on an oil film: a barrel face of the ring's height and
/// `crown_height` (m), loaded by its elastic pressure and, for the top ring, the cylinder
/// pressure above atmospheric behind it (the lower rings see none: inter-ring pressures are
/// not modelled); squeeze film stepped in time, Greenwood-Tripp asperity contact with
/// [`AsperityContact::typical`] surfaces; on every piston of the cylinder.
pub fn bind_ring_films(site: &BindInput, crown_height: f64) -> BoundLoss {
    let pack = ring_pack(site)?;
    let bore = site.bore;
    let ring = |height: f64, pressure: f64, top: bool| {
        let profile = RingProfile::Barrel {
            width: height,
            crown_height,
        };
        RingFilm::new(profile, bore, AsperityContact::typical())
            .map(|f| (f, pressure, top))
            .map_err(|e| failed(SetupInput::Parameter(LossParameter::RingCrownHeight), &e))
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
    let pistons = site.mechanism.topology().pistons.len();
    Ok(Box::new(RingFilms {
        films: vec![None; rings.len() * pistons],
        rings,
        time: None,
        viscosity: site.oil.dynamic_viscosity(),
    }))
}

/// Coulomb friction of `friction_coefficient` on the site's slide (Karhula A9.1.5).
pub fn bind_coulomb(site: &BindInput, friction_coefficient: f64) -> BoundLoss {
    Ok(coulomb(site.joint, friction_coefficient))
}

/// The viscous skirt (Thai thesis 2.5.c.1-3) of `length` and `clearance` (m) on the site's
/// slide, in a cylinder of its bore.
pub fn bind_viscous_skirt(site: &BindInput, length: f64, clearance: f64) -> BoundLoss {
    Ok(Box::new(ViscousSkirtLoss {
        joint: site.joint,
        skirt: ViscousSkirt::new(site.bore, length, clearance)
            .map_err(|e| failed(SetupInput::Parameter(LossParameter::SkirtLength), &e))?,
        viscosity: site.oil.dynamic_viscosity(),
    }))
}

/// The site's revolute-joint bearings.
fn bearings(site: &BindInput) -> Result<Bearings, SetupError> {
    site.bearings.ok_or_else(|| {
        failed(
            SetupInput::Model(Attachment::Bearing),
            &"attaches to a revolute joint only",
        )
    })
}

/// The site's rolling bearings in `reading` of [`cardan_friction::rolling_bearing_loss`].
pub fn bind_rolling(site: &BindInput, reading: RollingReading) -> BoundLoss {
    let b = bearings(site)?;
    Ok(Box::new(Rolling {
        joint: site.joint,
        model: RollingModel::new(
            RollingBearing::new(2.0 * b.radius, b.static_load_rating)
                .map_err(|e| failed(SetupInput::Model(Attachment::Bearing), &e))?,
            reading,
        ),
        count: f64::from(b.count.max(1)),
        viscosity: site.oil.kinematic_viscosity,
        kept: KeptPower::default(),
    }))
}

/// The site's plain journal bearings of its journal radius, L/D and c/R of the parameters:
/// Ocvirk's short bearing (`short`), else Petroff's concentric journal.
pub fn bind_journal(site: &BindInput, short: bool) -> BoundLoss {
    let b = bearings(site)?;
    let (length_ratio, clearance_ratio) = (
        site.value(LossParameter::JournalLengthRatio),
        site.value(LossParameter::JournalClearanceRatio),
    );
    Ok(Box::new(Journal {
        joint: site.joint,
        bearing: JournalBearing::new(
            b.radius,
            2.0 * b.radius * length_ratio,
            b.radius * clearance_ratio,
        )
        .map_err(|e| failed(SetupInput::Parameter(LossParameter::JournalLengthRatio), &e))?,
        count: f64::from(b.count.max(1)),
        short,
        viscosity: site.oil.dynamic_viscosity(),
    }))
}

/// Anderson & Loewenthal's mesh loss in `reading` on the site's gear-mesh joint, the pair
/// [`mesh_pair`] builds from the joint and the site's pair.
pub fn bind_mesh(site: &BindInput, reading: Reading) -> BoundLoss {
    let j = &site.mechanism.topology().joints[site.joint];
    let JointKind::GearMesh {
        ratio,
        pitch_radius,
        internal,
        pressure_angle,
        ..
    } = j.kind
    else {
        return Err(failed(
            SetupInput::Model(Attachment::GearMesh),
            &"attaches to a gear mesh only",
        ));
    };
    let (pair, face_width) = mesh_pair(site.pair, ratio, pitch_radius, internal, pressure_angle)?;
    let geometry = MeshGeometry::from_pair(&pair, face_width)
        .map_err(|e| failed(SetupInput::Gear(GearInput::FaceWidth), &e))?;
    let lubricant = Lubricant {
        kinematic_viscosity: site.oil.kinematic_viscosity,
        density: site.oil.density,
    };
    Ok(Box::new(Mesh {
        joint: site.joint,
        body: j.body,
        loss: PreparedMeshLoss::new(&geometry, &lubricant, reading.options()),
        pitch_radius,
        sets: if site.pair.twin { 2.0 } else { 1.0 },
    }))
}

/// Karhula's ring pack on every piston: a constant force μ·F_cont (A9.1.2-4) at the piston's
/// speed, P = F·|v| (A9.1.8).
#[derive(Debug, Clone)]
pub struct RingPack {
    /// μ_ring·F_cont, N.
    pub force: f64,
}

impl Loss for RingPack {
    fn power(&mut self, at: &LossLanes, out: &mut Column) -> Result<(), LaneFailure> {
        let (force, pistons) = (self.force, &at.states.pistons);
        for i in at.lanes.clone() {
            out[i] = pistons.iter().map(|p| force * p.velocity[i].abs()).sum();
        }
        Ok(())
    }
}

/// Every ring of every piston on its oil film ([`RingFilm`]): the minimum film of each ring of
/// each piston (`None` before the first step) carried from step to step by the squeeze term.
#[derive(Debug, Clone)]
pub struct RingFilms {
    /// Each ring of a piston: its film model, elastic pressure (Pa), whether it is the top ring
    /// (which the cylinder pressure above atmospheric loads).
    pub rings: Vec<(RingFilm, f64, bool)>,
    /// The minimum film of each ring of each piston, m.
    pub films: Vec<Option<f64>>,
    /// The time of the previous step, s.
    pub time: Option<f64>,
    /// Dynamic viscosity, Pa·s.
    pub viscosity: f64,
}

impl Loss for RingFilms {
    fn power(&mut self, at: &LossLanes, out: &mut Column) -> Result<(), LaneFailure> {
        for i in at.lanes.clone() {
            let now = at.states.crank.time[i];
            let dt = self.time.map(|t0| now - t0).filter(|dt| *dt > 0.0);
            self.time = Some(now);
            let gauge = at
                .pressure
                .map_or(0.0, |p| (p[i] - AMBIENT_PRESSURE).max(0.0));
            let mut power = 0.0;
            let per_piston = self.rings.len();
            for (k, p) in at.states.pistons.iter().enumerate() {
                let velocity = p.velocity[i];
                for (r, (film, elastic, top)) in self.rings.iter().enumerate() {
                    let load = RingLoad {
                        elastic_pressure: *elastic,
                        gas_pressure_behind: if *top { gauge } else { 0.0 },
                    };
                    let h = &mut self.films[k * per_piston + r];
                    let s = match (*h, dt) {
                        (Some(h0), Some(dt)) => film.step(h0, dt, self.viscosity, velocity, load),
                        _ => film.quasi_steady(self.viscosity, velocity, load),
                    };
                    *h = Some(s.min_film_thickness);
                    power += s.loss.power;
                }
            }
            out[i] = power;
        }
        Ok(())
    }

    fn carries_history(&self) -> bool {
        true
    }
}

/// Coulomb friction on a slide's normal force (Karhula A9.1.5 for a skirt; any other slide).
#[derive(Debug, Clone)]
pub struct Coulomb {
    pub joint: usize,
    pub friction_coefficient: f64,
}

/// [`Coulomb`] friction of `friction_coefficient` on prismatic joint `joint`.
pub fn coulomb(joint: usize, friction_coefficient: f64) -> Box<dyn Loss> {
    Box::new(Coulomb {
        joint,
        friction_coefficient,
    })
}

impl Loss for Coulomb {
    fn power(&mut self, at: &LossLanes, out: &mut Column) -> Result<(), LaneFailure> {
        let (load, motion) = (&at.total.joints[self.joint], &at.states.joints[self.joint]);
        let mut force = ZERO;
        magnitudes(&load.fx, &load.fy, at.lanes.clone(), &mut force);
        for i in at.lanes.clone() {
            let speed = motion.relative_speed[i];
            out[i] = coulomb_sliding(self.friction_coefficient, force[i], speed).power;
        }
        Ok(())
    }
}

/// The viscous skirt (Thai thesis 2.5.c.1-3) on a piston's slide.
#[derive(Debug, Clone)]
pub struct ViscousSkirtLoss {
    pub joint: usize,
    pub skirt: ViscousSkirt,
    /// Dynamic viscosity, Pa·s.
    pub viscosity: f64,
}

impl Loss for ViscousSkirtLoss {
    fn power(&mut self, at: &LossLanes, out: &mut Column) -> Result<(), LaneFailure> {
        let speed = &at.states.joints[self.joint].relative_speed;
        for i in at.lanes.clone() {
            out[i] = viscous_skirt(&self.skirt, self.viscosity, speed[i]).power;
        }
        Ok(())
    }
}

/// A revolute joint's rolling bearings in a reading of
/// [`cardan_friction::rolling_bearing_loss`]; each of `count` carries an equal share
/// (A9.1.23-25).
#[derive(Debug, Clone)]
pub struct Rolling {
    pub joint: usize,
    /// The bearing in its reading.
    pub model: RollingModel,
    pub count: f64,
    /// Kinematic viscosity, m²/s (the rolling readings' input).
    pub viscosity: f64,
    /// The viscous term's power of the speed at the step before.
    pub kept: KeptPower,
}

impl Loss for Rolling {
    fn power(&mut self, at: &LossLanes, out: &mut Column) -> Result<(), LaneFailure> {
        let (load, motion) = (&at.total.joints[self.joint], &at.states.joints[self.joint]);
        let (mut share, mut powers) = (ZERO, [ZERO; 2]);
        let wanted = self.model.load_powers();
        let lanes = at.lanes.clone();
        shares_and_powers(
            &load.fx,
            &load.fy,
            self.count,
            wanted,
            lanes,
            &mut share,
            &mut powers,
        );
        let mut speed_powers = ZERO;
        let l = at.lanes.clone();
        speed_powers_of(
            &self.model,
            &motion.relative_speed[l.clone()],
            self.viscosity,
            &mut self.kept,
            &mut speed_powers[l],
        );
        for i in at.lanes.clone() {
            let loss = self.model.loss_with_powers(
                share[i],
                motion.relative_speed[i],
                self.viscosity,
                [powers[0][i], powers[1][i]],
                speed_powers[i],
            );
            out[i] = self.count * loss.power;
        }
        Ok(())
    }
}

cardan_mechanism::vectorised! {
    /// |(fx, fy)| of the lanes `lanes` into `out`, `f64::hypot`'s bits all at once
    /// ([`cardan_numeric::hypot_lanes`]).
    fn magnitudes(fx: &Column, fy: &Column, lanes: Range<usize>, out: &mut Column) {
        let l = lanes;
        cardan_numeric::hypot_lanes(&fx[l.clone()], &fy[l.clone()], &mut out[l]);
    }
}

cardan_mechanism::vectorised! {
    /// [`RollingModel::speed_powers`] compiled for the block kernels' instruction set (its
    /// powers all at once vectorise there).
    fn speed_powers_of(
        model: &RollingModel,
        relative_speed: &[f64],
        kinematic_viscosity: f64,
        kept: &mut KeptPower,
        out: &mut [f64],
    ) {
        model.speed_powers(relative_speed, kinematic_viscosity, kept, out);
    }
}

cardan_mechanism::vectorised! {
    /// Each lane's share of the joint load carried by one of `count` bearings (A9.1.23-25),
    /// |(fx, fy)| / count ([`cardan_numeric::hypot_lanes`]: `f64::hypot`'s bits), and the
    /// `wanted` powers of it, every lane at once ([`cardan_numeric::powf_lanes`], the bits of
    /// [`cardan_friction::LoadPower::of`]).
    fn shares_and_powers(
        fx: &Column,
        fy: &Column,
        count: f64,
        wanted: &[LoadPower],
        lanes: Range<usize>,
        share: &mut Column,
        powers: &mut [Column; 2],
    ) {
        let l = lanes.clone();
        cardan_numeric::hypot_lanes(&fx[l.clone()], &fy[l.clone()], &mut share[l]);
        for s in &mut share[lanes.clone()] {
            *s /= count;
        }
        for (p, out) in wanted.iter().zip(powers.iter_mut()) {
            let mut base = ZERO;
            for i in lanes.clone() {
                base[i] = share[i] / p.divisor;
            }
            cardan_numeric::powf_lanes(&base[lanes.clone()], p.exponent, &mut out[lanes.clone()]);
        }
    }
}

/// A revolute joint's plain journal bearings: Petroff's concentric journal, or Ocvirk's short
/// bearing with the eccentricity from the instantaneous load.
#[derive(Debug, Clone)]
pub struct Journal {
    pub joint: usize,
    pub bearing: JournalBearing,
    pub count: f64,
    /// Ocvirk's short bearing; `false`: Petroff.
    pub short: bool,
    /// Dynamic viscosity, Pa·s.
    pub viscosity: f64,
}

impl Loss for Journal {
    fn power(&mut self, at: &LossLanes, out: &mut Column) -> Result<(), LaneFailure> {
        let (load, motion) = (&at.total.joints[self.joint], &at.states.joints[self.joint]);
        for i in at.lanes.clone() {
            let share = load.fx[i].hypot(load.fy[i]) / self.count;
            let w = motion.relative_speed[i];
            let one = if self.short {
                short_bearing(&self.bearing, self.viscosity, share, w, w)
                    .loss
                    .power
            } else {
                petroff(&self.bearing, self.viscosity, w, share).0.power
            };
            out[i] = self.count * one;
        }
        Ok(())
    }
}

/// Anderson & Loewenthal's mesh loss (Karhula A9.1.36-55) on a gear-mesh joint, charged on the
/// tangential load shared by the gear sets; a mesh a gear rating has rated takes the rating's
/// loss (the same model on the same pair), computed once.
#[derive(Debug, Clone)]
pub struct Mesh {
    pub joint: usize,
    /// The body carrying the pinion.
    pub body: usize,
    /// The model on the mesh's geometry and oil in its reading, prepared once.
    pub loss: PreparedMeshLoss,
    pub pitch_radius: f64,
    /// Gear sets sharing the load (2 for a twin set): each carries its share and loses its
    /// own, as in the gear rating.
    pub sets: f64,
}

impl Loss for Mesh {
    fn power(&mut self, at: &LossLanes, out: &mut Column) -> Result<(), LaneFailure> {
        if let Some((_, rated)) = at.rated_meshes.iter().find(|(j, _)| *j == self.joint) {
            out[at.lanes.clone()].copy_from_slice(&rated[at.lanes.clone()]);
            return Ok(());
        }
        let (joint, sets) = (self.joint, self.sets);
        let (load, motion) = (&at.total.joints[joint], &at.states.joints[joint]);
        for i in at.lanes.clone() {
            let ft = tangential(load.at(i).force, &motion.at(i));
            let pinion = at.states.bodies[self.body].angular_velocity[i];
            let speeds = mesh_speeds(pinion, motion.relative_speed[i], self.pitch_radius);
            let loss = self
                .loss
                .loss(&speeds, ft / sets)
                .map_err(|e| LaneFailure {
                    lane: i,
                    why: format!("gear mesh loss: {e}"),
                })?;
            out[i] = sets * loss.total_power;
        }
        Ok(())
    }
}

/// The cylinder's valve train at the step's crank angle, speed and acceleration.
impl Loss for ValveTrainLoss {
    fn power(&mut self, at: &LossLanes, out: &mut Column) -> Result<(), LaneFailure> {
        let c = &at.states.crank;
        for i in at.lanes.clone() {
            out[i] = ValveTrainLoss::power(self, c.angle[i], c.speed[i], c.acceleration[i]);
        }
        Ok(())
    }
}

/// Bishop's accessories on the swept volume.
#[derive(Debug, Clone)]
pub struct Accessories {
    /// Swept volume, m³.
    pub displacement: f64,
}

impl Loss for Accessories {
    fn power(&mut self, at: &LossLanes, out: &mut Column) -> Result<(), LaneFailure> {
        for i in at.lanes.clone() {
            out[i] = accessories_power(self.displacement, at.states.crank.speed[i]);
        }
        Ok(())
    }
}

/// Bishop's throttling loss on the swept volume.
#[derive(Debug, Clone)]
pub struct Pumping {
    /// Swept volume, m³.
    pub displacement: f64,
    pub engine: EngineLosses,
}

impl Loss for Pumping {
    fn power(&mut self, at: &LossLanes, out: &mut Column) -> Result<(), LaneFailure> {
        for i in at.lanes.clone() {
            out[i] = pumping_power(&self.engine, self.displacement, at.states.crank.speed[i]);
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use cardan_friction::{PalmgrenCoefficients, SkfDeepGrooveBall, KARHULA_LOAD_CONSTANT};
    use cardan_mechanism::{Joint, LoadsBlock, StateBlock, Topology, LANES};

    /// A block through `Rolling::power` (the shares and their powers of all lanes at once)
    /// gives each lane the bits of the single-step model (`RollingModel::loss` of the lane's
    /// share, times the bearing count), in every reading, over lanes of zero, tiny, ordinary
    /// and huge loads and a block that is not full.
    #[test]
    fn rolling_over_a_block_has_the_bits_of_single_steps() {
        let bearings = Bearings {
            radius: 0.0225,
            count: 2,
            static_load_rating: 60_000.0,
        };
        let t = Topology {
            bodies: Vec::new(),
            joints: vec![Joint::pin("main_bearing", bearings, 0, None)],
            pistons: Vec::new(),
            crankshaft: 0,
            extras: Vec::new(),
        };
        let (mut states, mut total) = (StateBlock::for_topology(&t), LoadsBlock::for_topology(&t));
        for i in 0..LANES {
            let f = if i == 0 {
                0.0
            } else {
                1e-3 * 1.35f64.powi(i as i32)
            };
            let a = 0.1 * i as f64;
            (total.joints[0].fx[i], total.joints[0].fy[i]) = (f * a.cos(), -f * a.sin());
        }
        for reading in [
            RollingReading::Karhula {
                f0: 2.0,
                load_constant: KARHULA_LOAD_CONSTANT,
            },
            RollingReading::Palmgren(PalmgrenCoefficients::DEEP_GROOVE_BALL),
            RollingReading::Palmgren(PalmgrenCoefficients::CYLINDRICAL_ROLLER),
            RollingReading::Skf(SkfDeepGrooveBall::SERIES_62),
        ] {
            let model = RollingModel::new(RollingBearing::new(0.045, 60_000.0).unwrap(), reading);
            let mut rolling = Rolling {
                joint: 0,
                model,
                count: 2.0,
                viscosity: 5e-6,
                kept: KeptPower::default(),
            };
            // Speeds that vary over the block (powers all at once), then a constant one (the
            // kept power).
            for (n, constant) in [(LANES, false), (37, false), (LANES, true), (37, true)] {
                for i in 0..LANES {
                    states.joints[0].relative_speed[i] = if constant {
                        250.0
                    } else {
                        300.0 - 10.0 * i as f64
                    };
                }
                let at = LossLanes {
                    lanes: 0..n,
                    ..LossLanes::one(&states, &total)
                };
                let mut out = [f64::NAN; LANES];
                rolling.power(&at, &mut out).unwrap();
                for (i, &got) in out[..n].iter().enumerate() {
                    let (load, j) = (&total.joints[0], &states.joints[0]);
                    let share = load.fx[i].hypot(load.fy[i]) / 2.0;
                    let one = model.loss(share, j.relative_speed[i], 5e-6).power;
                    assert_eq!(got.to_bits(), (2.0 * one).to_bits(), "{reading:?} lane {i}");
                }
                assert!(out[n..].iter().all(|v| v.is_nan()), "lanes past the block");
            }
        }
    }
}
