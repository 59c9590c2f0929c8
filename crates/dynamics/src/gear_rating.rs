//! Rating of every gear mesh of a mechanism at every step, from the mesh joint's total load:
//! Buckingham's dynamic tooth load (Karhula 2008 A8.1.1-14), AGMA 2001-D04 contact and bending
//! stresses with their safety factors, and the Anderson & Loewenthal mesh loss, through
//! [`cardan_gears::GearSet`]. The pair is built from the mesh joint's declared pitch radius,
//! ratio, pressure angle and internal ring, and the case's [`GearSpec`]; no mechanism code.
//!
//! The tooth load is the mesh force along the pitch-circle tangent (A8.1.10, A9.1.44), in either
//! mesh-force reading of the cardan gear. [`ToothLoad::Thesis`] is the reading that reproduces
//! Karhula's published dynamic tooth loads (App. 11.6.1); [`ToothLoad::RingForce`] rates the
//! magnitude of the mesh force. The mesh loss is always charged on the tangential load, whatever
//! load is rated, so that it equals the loss budget's mesh component.
//!
//! The rating reads a block of steps from its columns ([`GearRatings::evaluate_block`]: the
//! mesh joint's motion, its force in the total and the inertial family, the pinion's angular
//! velocity and the wheel's acceleration), as its mesh loss model does ([`Loss`]), so that a
//! run gathers no step for it; a single state is rated as a block of one lane
//! ([`GearRatings::evaluate`]).

use cardan_gears::agma::factors::{
    bending_allowable_through_hardened, carburized_allowables, contact_allowable_through_hardened,
    elastic_coefficient, DynamicFactor, Enclosure, Grade, LoadDistribution, Quality,
};
use cardan_gears::agma::{GearSetRating, MemberData, PreparedRating, SizeFactor};
use cardan_gears::buckingham::{BuckinghamPair, SaturatedLoad, FULL_DEPTH_20};
use cardan_gears::mesh_loss::{Lubricant, MeshGeometry, PreparedMeshLoss, Reading};
use cardan_gears::{
    pitting_geometry_factor, BendingJMemo, GearPair, GearSet, GeneratedMember, IForm, MeshStep,
    PairMember,
};
use cardan_mechanism::{
    Column, JointKind, JointMotion, Loads, LoadsBlock, Material, Mechanism, MeshForce, State,
    StateBlock, Topology, C, ZERO,
};

use crate::loss::{BindInput, LaneFailure, Loss, LossLanes, Oil};
use crate::loss_models::{find, Attachment};
use crate::losses::Friction;
use crate::mesh::{
    mesh_pair, mesh_speeds, tangential, GearMaterial, GearSpec, GearStandard, ToothLoad,
};
use crate::stage::{Block, SetupError};
use crate::{failed, GearInput, SetupInput};
use cardan_gears::iso6336::PreparedIso;

mod iso;
mod lanes;

use iso::iso_rating;
pub use iso::ISO_PINION_CYCLES;

/// The bending geometry factors `[pinion, gear]` of a mesh whose `[gear] j` is not given,
/// computed from the tooth form with the default generating rack (ISO 53, tip radius 0.25 m):
/// AGMA 908-B89 for an external member, ISO 6336-3 method B for an internal ring
/// ([`cardan_gears::agma908`]), through `memo` (the same pair's factors computed once).
fn computed_j(pair: &GearPair, memo: &BendingJMemo) -> Result<[f64; 2], SetupError> {
    let mut j = [0.0; 2];
    for (k, (which, name)) in [(PairMember::Pinion, "pinion"), (PairMember::Gear, "gear")]
        .into_iter()
        .enumerate()
    {
        j[k] = memo
            .get(pair, GeneratedMember::new(which))
            .map_err(|e| SetupError {
                field: SetupInput::Gear(GearInput::J),
                rule: format!(
                    "the {name}'s bending geometry factor J cannot be computed from the tooth form ({e}): give [gear] j"
                ),
            })?
            .j;
    }
    Ok(j)
}

/// One mesh's rating at one step.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct MeshRating {
    /// The rated tooth load (tangential or ring force, per gear set), N.
    pub tooth_load: f64,
    /// Buckingham's dynamic tooth load, N (A8.1.14).
    pub dynamic_load: f64,
    /// AGMA contact stress, Pa.
    pub contact_stress: f64,
    /// AGMA pitting safety factor (the smaller member's; infinite at zero load).
    pub contact_safety: f64,
    /// AGMA bending stress, the larger member's, Pa (NaN without J).
    pub bending_stress: f64,
    /// AGMA bending safety factor, the smaller member's (NaN without J).
    pub bending_safety: f64,
    /// Anderson & Loewenthal mesh power loss, W (all gear sets).
    pub loss: f64,
    /// ISO 6336-2 contact stress σ_H, the larger member's, Pa (NaN without an ISO rating; 0
    /// at zero load).
    pub iso_contact_stress: f64,
    /// ISO 6336-2 pitting safety factor S_H, the smaller member's (infinite at zero load).
    pub iso_contact_safety: f64,
    /// ISO 6336-3 root stress σ_F, the larger member's, Pa.
    pub iso_bending_stress: f64,
    /// ISO 6336-3 root safety factor S_F, the smaller member's.
    pub iso_bending_safety: f64,
}

impl MeshRating {
    /// Values of a rating as a stage's values ([`crate::Step::stages`]): its fields in order.
    pub const WIDTH: usize = 11;
    /// The values of a rating without ISO 6336 (the first of [`MeshRating::values`]): a stage
    /// rating by AGMA alone keeps only these.
    pub const AGMA_WIDTH: usize = 7;

    /// The rating as [`MeshRating::WIDTH`] values.
    pub fn values(&self) -> [f64; Self::WIDTH] {
        [
            self.tooth_load,
            self.dynamic_load,
            self.contact_stress,
            self.contact_safety,
            self.bending_stress,
            self.bending_safety,
            self.loss,
            self.iso_contact_stress,
            self.iso_contact_safety,
            self.iso_bending_stress,
            self.iso_bending_safety,
        ]
    }

    /// The rating at lane `i` of `columns`, a column per [value](MeshRating::values): all
    /// [`MeshRating::WIDTH`] of them, or the first [`MeshRating::AGMA_WIDTH`] (the ISO
    /// values then NaN).
    pub fn at_lane(columns: &[Column], i: usize) -> Self {
        let iso = |k: usize| columns.get(k).map_or(f64::NAN, |c| c[i]);
        Self {
            tooth_load: columns[0][i],
            dynamic_load: columns[1][i],
            contact_stress: columns[2][i],
            contact_safety: columns[3][i],
            bending_stress: columns[4][i],
            bending_safety: columns[5][i],
            loss: columns[6][i],
            iso_contact_stress: iso(7),
            iso_contact_safety: iso(8),
            iso_bending_stress: iso(9),
            iso_bending_safety: iso(10),
        }
    }
}

/// The rated meshes of one mechanism.
#[derive(Debug, Clone)]
pub struct GearRatings {
    meshes: Vec<RatedMesh>,
    standard: GearStandard,
}

#[derive(Debug, Clone)]
struct RatedMesh {
    joint: usize,
    body: usize,
    name: &'static str,
    set: GearSet,
    pitch_radius: f64,
    /// Gear sets sharing the load.
    sets: f64,
    bending: bool,
    tooth_load: ToothLoad,
    /// The mesh's first gear as a solid steel disc of its pitch diameter and the rated face
    /// width, m = ρ·b·π·d²/4, kg (A8.1.5, A8.1.9; the wheel's mass of [`ToothLoad::Thesis`]).
    disc_mass: f64,
    /// Unit vector of the thesis's ring force: the tied mesh force's direction (the cylinder
    /// axis in the cardan gear; unused with involute teeth).
    axis: C,
    /// The mesh loss: the case's gear-mesh model bound to this mesh (the loss budget's own), so
    /// that the rating's loss and the budget's mesh component are one figure.
    loss: Box<dyn Loss>,
    /// The same model over a block's lanes where it is Anderson & Loewenthal's
    /// ([`PreparedMeshLoss::total_power_lanes`] on the pair and oil `loss` is bound to: the
    /// same bits); `None`: another model, or a pair it refuses (`loss` then says why).
    loss_lanes: Option<PreparedMeshLoss>,
    /// The dynamic factor at the last step's pitch-line velocity (its bits; `None` before the
    /// first), kept while the speed does not change.
    kv: Option<(u64, DynamicFactor)>,
    /// The set's rating at its face width, prepared once.
    rating: PreparedRating,
    /// The ISO 6336 rating of the pair, prepared once (`None`: AGMA alone).
    iso: Option<PreparedIso>,
    /// Buckingham's saturated load of the set ([`ToothLoad::Thesis`]), its checks made once
    /// (a failed one fails the first step rated, as the load's own checks would).
    saturated: Result<SaturatedLoad, cardan_gears::GearError>,
}

impl GearRatings {
    /// The ratings of every gear mesh of `mechanism` under `spec`, the mesh loss that of
    /// `friction` (its gear-mesh model, parameters and oil) on the pair of `spec`, or, without
    /// one or with its mesh loss off, Anderson & Loewenthal's in the corrected reading (with
    /// Karhula's oil, [`Friction::karhula`], without `friction`).
    pub fn new(
        spec: &GearSpec,
        mechanism: &dyn Mechanism,
        friction: Option<&Friction>,
    ) -> Result<Self, SetupError> {
        Self::with_memo(spec, mechanism, friction, &BendingJMemo::default())
    }

    /// [`GearRatings::new`], the bending geometry factors computed from the tooth form taken
    /// from `memo` where it holds them (the points of a sweep share one: issue 37).
    pub fn with_memo(
        spec: &GearSpec,
        mechanism: &dyn Mechanism,
        friction: Option<&Friction>,
        memo: &BendingJMemo,
    ) -> Result<Self, SetupError> {
        let oil = friction.map_or(Friction::karhula().oil, |f| f.oil);
        let topology = mechanism.topology();
        let mut meshes = Vec::new();
        for (k, j) in topology.joints.iter().enumerate() {
            let JointKind::GearMesh {
                ratio,
                pitch_radius,
                internal,
                pressure_angle,
                force,
            } = j.kind
            else {
                continue;
            };
            let axis = tooth_load_axis(spec.tooth_load, force, j.name)?;
            let (pair, face_width) =
                mesh_pair(spec, ratio, pitch_radius, internal, pressure_angle)?;
            let set = gear_set(spec, pair, (face_width, internal), oil, memo)?;
            let (loss, reading) = mesh_loss(spec, mechanism, friction, k)?;
            let loss_lanes = reading.and_then(|reading| {
                let geometry = MeshGeometry::from_pair(&set.pair, set.face_width).ok()?;
                Some(PreparedMeshLoss::new(
                    &geometry,
                    &set.lubricant,
                    reading.options(),
                ))
            });
            let prepared = PreparedRating::new(&set.rating, set.face_width);
            let iso = if spec.standard.iso() {
                Some(iso_rating(spec, &set)?)
            } else {
                None
            };
            meshes.push(RatedMesh {
                joint: k,
                body: j.body,
                name: j.name,
                pitch_radius,
                sets: if spec.twin { 2.0 } else { 1.0 },
                // J is given or computed for every mesh (a J that cannot be computed is a
                // setup error), so every mesh has a bending rating.
                bending: true,
                tooth_load: spec.tooth_load,
                disc_mass: Material::Steel.density()
                    * face_width
                    * std::f64::consts::PI
                    * pitch_radius
                    * pitch_radius,
                axis,
                loss,
                loss_lanes,
                kv: None,
                rating: prepared,
                iso,
                saturated: set.buckingham.saturated(),
                set,
            });
        }
        Ok(Self {
            meshes,
            standard: spec.standard,
        })
    }

    /// The rated meshes' joints (indices in the topology), in rating order.
    pub fn joints(&self) -> impl Iterator<Item = usize> + '_ {
        self.meshes.iter().map(|m| m.joint)
    }

    /// The rated meshes' joint names.
    pub fn names(&self) -> Vec<&'static str> {
        self.meshes.iter().map(|m| m.name).collect()
    }

    /// Transverse contact ratio of each rated mesh.
    pub fn contact_ratios(&self) -> Vec<f64> {
        self.meshes
            .iter()
            .map(|m| m.set.pair.contact_ratio)
            .collect()
    }

    /// Which standard rates the stresses and safety factors.
    pub fn standard(&self) -> GearStandard {
        self.standard
    }

    /// Whether the meshes are rated by ISO 6336 too (each mesh's [`MeshRating`] then has all
    /// [`MeshRating::WIDTH`] values, else the first [`MeshRating::AGMA_WIDTH`]).
    pub fn iso(&self) -> bool {
        self.meshes.iter().any(|m| m.iso.is_some())
    }

    /// Whether each mesh gets a bending rating (its J is known).
    pub fn bending(&self) -> Vec<bool> {
        self.meshes.iter().map(|m| m.bending).collect()
    }

    /// Each mesh's rating at the first [`Block::len`] lanes of `block` (the inertial family's
    /// loads, which [`ToothLoad::Thesis`] reads, `None` without one): per mesh, in rating
    /// order, the first `per_mesh` of its [values](MeshRating::values) into a column each of
    /// `out`, and its loss, W, into its column of `losses` (a column per mesh, in rating
    /// order). The losses are taken over the block first
    /// ([`GearRatings::losses_over_lanes`]), then the ratings over the block's lanes, a mesh at
    /// a time ([`GearRatings::rate_lanes`]); where a lane fails a check there, the lanes one
    /// by one ([`GearRatings::evaluate_block_lane_by_lane`]), whose error this is.
    pub fn evaluate_block(
        &mut self,
        block: &Block,
        out: &mut [Column],
        per_mesh: usize,
        losses: &mut [(usize, Column)],
    ) -> Result<(), (usize, String)> {
        if self.losses_over_lanes(block, losses) && self.rate_lanes(block, out, per_mesh, losses) {
            return Ok(());
        }
        self.evaluate_block_lane_by_lane(block, out, per_mesh, losses)
    }

    /// Each mesh's loss (W) at the lanes of `block` into its column of `losses`, every lane at
    /// once where the mesh's model is Anderson & Loewenthal's (the bits of the bound model's
    /// lanes one by one): `false` where one fails a check (the lanes are then to be taken one
    /// by one, which say where and why).
    pub fn losses_over_lanes(&mut self, block: &Block, losses: &mut [(usize, Column)]) -> bool {
        let at = LossLanes {
            lanes: 0..block.len,
            ..LossLanes::one(block.states, block.total)
        };
        (self.meshes.iter_mut().zip(losses.iter_mut())).all(|(m, (_, loss))| {
            if m.loss_lanes.is_some() {
                m.loss_lanes(block, loss)
            } else {
                m.loss.power(&at, loss).is_ok()
            }
        })
    }

    /// The ratings of [`GearRatings::evaluate_block`] from the meshes' `losses` (at every
    /// lane), a mesh at a time over the block's lanes: `false` where a lane fails a check (the
    /// lanes are then to be rated one by one, which say where and why; `out` holds nothing to
    /// be taken).
    pub fn rate_lanes(
        &mut self,
        block: &Block,
        out: &mut [Column],
        per_mesh: usize,
        losses: &[(usize, Column)],
    ) -> bool {
        let meshes = self.meshes.iter_mut().zip(losses);
        meshes
            .zip(out.chunks_exact_mut(per_mesh))
            .all(|((m, (_, loss)), out)| m.rate_lanes(block, loss, out))
    }

    /// [`GearRatings::evaluate_block`] with the lanes rated one by one, every mesh at a lane
    /// before the next lane: the same values, bit for bit; `Err`: the first lane a mesh cannot
    /// be rated at (its loss included), and why; the lanes from there on are not rated.
    pub fn evaluate_block_lane_by_lane(
        &mut self,
        block: &Block,
        out: &mut [Column],
        per_mesh: usize,
        losses: &mut [(usize, Column)],
    ) -> Result<(), (usize, String)> {
        let failed = self.losses(block, losses);
        self.rate_lane_by_lane(block, out, per_mesh, losses, &failed)
    }

    /// Each mesh's loss at the lanes of `block` into its column of `losses` by its bound
    /// model, and where it fails, if it does.
    fn losses(
        &mut self,
        block: &Block,
        losses: &mut [(usize, Column)],
    ) -> Vec<Option<LaneFailure>> {
        let at = LossLanes {
            lanes: 0..block.len,
            ..LossLanes::one(block.states, block.total)
        };
        (self.meshes.iter_mut().zip(losses.iter_mut()))
            .map(|(m, (_, loss))| m.loss.power(&at, loss).err())
            .collect()
    }

    /// The ratings of [`GearRatings::evaluate_block_lane_by_lane`] from the meshes' `losses`,
    /// each failing where `failed` says.
    fn rate_lane_by_lane(
        &mut self,
        block: &Block,
        out: &mut [Column],
        per_mesh: usize,
        losses: &[(usize, Column)],
        failed: &[Option<LaneFailure>],
    ) -> Result<(), (usize, String)> {
        for i in 0..block.len {
            let meshes = self.meshes.iter_mut().zip(losses.iter()).zip(failed);
            for (((m, (_, loss)), failed), out) in meshes.zip(out.chunks_exact_mut(per_mesh)) {
                let loss = match failed {
                    Some(f) if f.lane == i => Err(f.why.clone()),
                    _ => Ok(loss[i]),
                };
                let r = m.rate(block, i, loss).map_err(|e| (i, e))?;
                for (c, v) in out.iter_mut().zip(r.values()) {
                    c[i] = v;
                }
            }
        }
        Ok(())
    }

    /// Each mesh's rating at `state` of a mechanism of `topology` under the `total` loads (and
    /// the `inertial` family's, which [`ToothLoad::Thesis`] needs; `None` without one), into
    /// `out`: [`GearRatings::evaluate_block`] on a block of one lane holding them.
    pub fn evaluate(
        &mut self,
        topology: &Topology,
        state: &State,
        total: &Loads,
        inertial: Option<&Loads>,
        out: &mut [MeshRating],
    ) -> Result<(), String> {
        let states = StateBlock::of_state(topology, state);
        let lane = |loads: &Loads| LoadsBlock::of_loads(topology, loads);
        let (total, inertial) = (lane(total), inertial.map(lane));
        let block = Block {
            len: 1,
            states: &states,
            total: &total,
            inertial: inertial.as_ref(),
            pressure: None,
            force: None,
            gas: None,
        };
        let width = MeshRating::WIDTH;
        let mut values = vec![ZERO; width * self.meshes.len()];
        let mut losses: Vec<_> = self.joints().map(|j| (j, ZERO)).collect();
        (self.evaluate_block(&block, &mut values, width, &mut losses)).map_err(|(_, e)| e)?;
        for (out, columns) in out.iter_mut().zip(values.chunks_exact(width)) {
            *out = MeshRating::at_lane(columns, 0);
        }
        Ok(())
    }
}

/// The AGMA 2001 gear set of one mesh of `spec`: the pair `pair`, its face width and whether
/// the gear is internal (`mesh`), the oil `oil` (its viscosity and density for the mesh loss
/// and the film), with the case's materials, J factors (given, or computed through `memo`) and
/// the factors a case run takes as 1; the face width refused where AGMA's load distribution
/// does not hold.
fn gear_set(
    spec: &GearSpec,
    pair: GearPair,
    (face_width, internal): (f64, bool),
    oil: Oil,
    memo: &BendingJMemo,
) -> Result<GearSet, SetupError> {
    // The load distribution's empirical Cpf holds up to 40 in (AGMA 2001-D04 eq. 28-30):
    // a wider face is refused here, before any step, not at the first step's rating.
    cardan_gears::agma::factors::pinion_proportion_factor(face_width, pair.pinion.working)
        .map_err(|e| failed(SetupInput::Gear(GearInput::FaceWidth), &e))?;
    let j_factors = match spec.j {
        Some(j) => j,
        None => computed_j(&pair, memo)?,
    };
    let member = |m: usize| -> Result<MemberData, SetupError> {
        let (bending_allowable, contact_allowable) = match spec.material {
            GearMaterial::ThroughHardened => (
                bending_allowable_through_hardened(spec.hardness[m], Grade::Two)
                    .map_err(|e| failed(SetupInput::Gear(GearInput::Hardness), &e))?,
                contact_allowable_through_hardened(spec.hardness[m], Grade::Two)
                    .map_err(|e| failed(SetupInput::Gear(GearInput::Hardness), &e))?,
            ),
            GearMaterial::Carburized => carburized_allowables(Grade::Two),
        };
        Ok(MemberData {
            j: j_factors[m],
            rim: 1.0,
            bending_allowable,
            contact_allowable,
            yn: 1.0,
            zn: 1.0,
            ch: 1.0,
        })
    };
    let rating = GearSetRating {
        module: pair.spec.module,
        pinion_diameter: pair.pinion.working,
        overload: 1.0,
        load_distribution: LoadDistribution {
            crowned: false,
            offset_ratio: 0.0,
            enclosure: Enclosure::PrecisionEnclosed,
            adjusted_at_assembly: false,
        },
        size: SizeFactor::Given([1.0, 1.0]),
        surface_condition: 1.0,
        geometry_i: pitting_geometry_factor(&pair, IForm::Lpstc)
            .map_err(|e| failed(SetupInput::Gear(GearInput::Pair), &e))?,
        elastic_coefficient: elastic_coefficient(
            spec.youngs_modulus,
            0.3,
            spec.youngs_modulus,
            0.3,
        )
        .map_err(|e| failed(SetupInput::Gear(GearInput::YoungsModulus), &e))?,
        temperature: 1.0,
        reliability: 1.0,
        pinion: member(0)?,
        gear: member(1)?,
    };
    let set = GearSet {
        buckingham: BuckinghamPair {
            pinion_radius: pair.pinion.reference / 2.0,
            gear_radius: pair.gear.reference.abs() / 2.0,
            internal,
            face_width,
            error: spec.error,
            e1: spec.youngs_modulus,
            e2: spec.youngs_modulus,
            form: FULL_DEPTH_20,
        },
        pair,
        face_width,
        quality: Quality::Qv(spec.quality),
        rating,
        lubricant: Lubricant {
            kinematic_viscosity: oil.kinematic_viscosity,
            density: oil.density,
        },
        loss_reading: None,
    };
    Ok(set)
}

/// The direction the rated tooth load is taken along (`tooth_load`) for a mesh whose force
/// reading is `force`: the thesis's ring force acts along its tied direction (A5.2.1.48-51);
/// involute teeth have no such direction, so the thesis's reading is refused on them (naming
/// the mesh `name`), and the tangential one takes the pitch-circle tangent.
fn tooth_load_axis(tooth_load: ToothLoad, force: MeshForce, name: &str) -> Result<C, SetupError> {
    match (tooth_load, force) {
        (_, MeshForce::Tied { direction, .. }) => Ok(direction),
        (ToothLoad::Thesis, MeshForce::Involute) => Err(SetupError {
            field: SetupInput::Gear(GearInput::ToothLoad),
            rule: format!(
                "\"thesis\" is Karhula's reading of his own mesh force, which acts \
                 along a fixed direction; the mesh {name} has involute teeth pushing \
                 along the line of action (the `involute` mesh-force reading): rate \
                 it with \"tangential\", or use the `karhula` mesh-force reading"
            ),
        }),
        (_, MeshForce::Involute) => Ok(C::i()),
    }
}

/// The mesh loss of gear-mesh joint `joint` of `mechanism` on the pair of `spec`: the model of
/// `friction` (its parameters and oil), or, without one or with its mesh loss off, Anderson &
/// Loewenthal's in the corrected reading (with Karhula's oil without `friction`); and its
/// reading of Anderson & Loewenthal's, if it is one.
fn mesh_loss(
    spec: &GearSpec,
    mechanism: &dyn Mechanism,
    friction: Option<&Friction>,
    joint: usize,
) -> Result<(Box<dyn Loss>, Option<Reading>), SetupError> {
    let karhula = Friction::karhula();
    let f = friction.unwrap_or(&karhula);
    let model = friction
        .and_then(|f| f.gear_mesh)
        .or_else(|| find(Attachment::GearMesh, "corrected"))
        .expect("the registry has the corrected mesh loss");
    let site = BindInput {
        parameters: &f.parameters,
        declared: &[],
        oil: &f.oil,
        pair: spec,
        mechanism,
        bore: 0.0,
        joint,
        bearings: None,
    };
    let loss = model.bind_at(&site).unwrap_or_else(|| {
        Err(failed(
            SetupInput::Model(Attachment::GearMesh),
            &"is not a gear-mesh loss",
        ))
    })?;
    Ok((loss, model.mesh_reading()))
}

impl RatedMesh {
    /// AGMA's dynamic factor at `step` where the rated load is not the tangential one (whose
    /// rating gives it): kept with the pitch-line speed's bits it was taken at, the step's
    /// checks made again when kept (the same factor at the same speed).
    fn kept_dynamic_factor(
        &mut self,
        step: &MeshStep,
    ) -> Result<cardan_gears::DynamicFactor, cardan_gears::GearError> {
        let bits = step.pitch_line_velocity.abs().to_bits();
        match self.kv {
            Some((kept, kv)) if kept == bits => {
                self.set.check_step(step)?;
                Ok(kv)
            }
            _ => {
                let kv = self.set.dynamic_factor(step)?;
                self.kv = Some((bits, kv));
                Ok(kv)
            }
        }
    }

    /// The thesis's tooth load (Karhula A5.2.1.48-51, [`ToothLoad::Thesis`]) at lane `i` of
    /// `block`: the mesh force `force` less twice the inertial family's (none: zero) plus the
    /// wheel disc's inertia, its part along the mesh's tied axis, tangential to the pitch
    /// circle (the mesh joint's `motion`), per set of teeth.
    fn thesis_load(&self, block: &Block, i: usize, force: C, motion: &JointMotion) -> f64 {
        let inertial =
            (block.inertial).map_or(C::new(0.0, 0.0), |l| l.joints[self.joint].at(i).force);
        let cg = &block.states.bodies[self.body].cg;
        let wheel = self.disc_mass * C::new(cg.ax[i], cg.ay[i]);
        let slipped = force - 2.0 * inertial + wheel;
        let axial = self.axis * (slipped.re * self.axis.re + slipped.im * self.axis.im);
        tangential(axial, motion).abs() / self.sets
    }

    /// ISO 6336 at the rated load `load` (at the reference circle, the joint's pitch circle:
    /// module = 2·r/z1) and the pinion's speed relative to the carrier, |v|/r from the
    /// pitch-line velocity `velocity`: the larger member's contact stress, the smaller contact
    /// safety factor, the larger root stress, the smaller bending safety factor (NaN without
    /// an ISO rating).
    fn iso_at(&self, load: f64, velocity: f64) -> Result<[f64; 4], String> {
        Ok(match &self.iso {
            None => [f64::NAN; 4],
            // No load, no stress: the safety factors are infinite, as AGMA's.
            Some(_) if load == 0.0 => [0.0, f64::INFINITY, 0.0, f64::INFINITY],
            Some(iso) => {
                let speed = velocity.abs() / self.pitch_radius;
                let r = iso
                    .rate(load, speed)
                    .map_err(|e| format!("gear rating of {}: ISO 6336: {e}", self.name))?;
                [
                    r.sigma_h[0].max(r.sigma_h[1]),
                    r.s_h[0].min(r.s_h[1]),
                    r.sigma_f[0].max(r.sigma_f[1]),
                    r.s_f[0].min(r.s_f[1]),
                ]
            }
        })
    }

    /// The mesh's rating at lane `i` of `block`, its mesh loss `loss` (W) at the lane.
    fn rate(
        &mut self,
        block: &Block,
        i: usize,
        loss: Result<f64, String>,
    ) -> Result<MeshRating, String> {
        let m = self;
        let motion = &block.states.joints[m.joint].at(i);
        let force = block.total.joints[m.joint].at(i).force;
        let tangential_load = tangential(force, motion).abs() / m.sets;
        let step = MeshStep {
            tangential_load,
            pitch_line_velocity: motion.relative_speed,
            speeds: mesh_speeds(
                block.states.bodies[m.body].angular_velocity[i],
                motion.relative_speed,
                m.pitch_radius,
            ),
        };
        let name = m.name;
        let failed = |e: cardan_gears::GearError| format!("gear rating of {name}: {e}");
        // Rating another load than the tangential one, the set's rating and Buckingham load
        // at the tangential load would be replaced below: only its dynamic factor is taken.
        let tangential_rating = match m.tooth_load {
            ToothLoad::Tangential => Some(m.set.evaluate(&step).map_err(failed)?),
            _ => None,
        };
        let kv = match &tangential_rating {
            Some(r) => r.kv,
            None => m.kept_dynamic_factor(&step).map_err(failed)?,
        };
        let loss = loss.map_err(|e| format!("gear rating of {name}: {e}"))?;
        let load = match m.tooth_load {
            ToothLoad::Tangential => tangential_load,
            ToothLoad::RingForce => force.norm() / m.sets,
            ToothLoad::Thesis => m.thesis_load(block, i, force, motion),
        };
        // Another rated load: the rating and Buckingham's load at it (the loss stays on the
        // tangential load).
        let (dynamic, rating) = match tangential_rating {
            Some(r) => (r.dynamic, r.rating),
            None => (
                if m.tooth_load == ToothLoad::Thesis {
                    m.saturated
                        .as_ref()
                        .map_err(Clone::clone)
                        .and_then(|s| s.at(load))
                } else {
                    m.set
                        .buckingham
                        .dynamic_load(load, motion.relative_speed.abs())
                }
                .map_err(failed)?,
                m.rating.rate(load, kv.kv).map_err(failed)?,
            ),
        };
        let (bending_stress, bending_safety) = if m.bending {
            (
                rating.bending_stress[0].max(rating.bending_stress[1]),
                rating.bending_safety[0].min(rating.bending_safety[1]),
            )
        } else {
            (f64::NAN, f64::NAN)
        };
        let [iso_contact_stress, iso_contact_safety, iso_bending_stress, iso_bending_safety] =
            m.iso_at(load, motion.relative_speed)?;
        Ok(MeshRating {
            tooth_load: load,
            dynamic_load: dynamic.dynamic_load,
            contact_stress: rating.contact_stress[0].max(rating.contact_stress[1]),
            contact_safety: rating.contact_safety[0].min(rating.contact_safety[1]),
            bending_stress,
            bending_safety,
            loss,
            iso_contact_stress,
            iso_contact_safety,
            iso_bending_stress,
            iso_bending_safety,
        })
    }
}
