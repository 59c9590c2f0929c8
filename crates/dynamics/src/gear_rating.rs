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

use cardan_gears::agma::factors::{
    bending_allowable_through_hardened, carburized_allowables, contact_allowable_through_hardened,
    elastic_coefficient, Enclosure, Grade, LoadDistribution, Quality,
};
use cardan_gears::agma::{GearSetRating, MemberData, SizeFactor};
use cardan_gears::buckingham::{BuckinghamPair, FULL_DEPTH_20};
use cardan_gears::geometry::{GearPair, PairSpec};
use cardan_gears::mesh_loss::{Lubricant, MeshSpeeds, Reading};
use cardan_gears::{pitting_geometry_factor, GearSet, IForm, MeshStep, ShiftCase};
use cardan_mechanism::{JointKind, Loads, Material, Mechanism, MeshForce, State, C};

use crate::losses::{Friction, LossError};
use crate::summary::tangential;

/// Which force the rating takes as the tooth load.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum ToothLoad {
    /// The component along the pitch-circle tangent (A8.1.10): the torque-transmitting load.
    #[default]
    Tangential,
    /// The magnitude of the mesh force (the thesis's ring force |F_Σ02c|).
    RingForce,
    /// Karhula's reading, which reproduces his published dynamic tooth loads of the cardan gear
    /// (App. 11.6.1: air pump within 1.2 %, engine within 0.4 %; docs/case-file.md "Gear rating in runs")
    /// with the `karhula` mesh-force reading:
    /// - the mesh force of A8.1.10 with the thesis's sign slip: A6.2.1.36 and A6.2.1.51 give
    ///   the ring force the gas force's sign (F_comp02c = +F_comp23c) where A5.2.1.49 gives
    ///   the inertial force the opposite one (F_3i02c = −F_3i23c), so A7.1.15 adds what
    ///   physically cancels: gas − inertial, i.e. total − 2·inertial;
    /// - plus the cardan wheel's own translational inertia force (inferred, not printed: the
    ///   thesis's model gives the wheel only a torque, A5.2.1.43-46, and this project, as the
    ///   thesis, carries the wheel's mass on the balanced crankshaft): the wheel is the steel
    ///   disc of A8.1.5 of its pitch diameter and face width (0.444 kg for Karhula's pair, not
    ///   fitted); without it the pump's loads at 100π-200π rad/s are 1.7-7.2 % low;
    /// - its part along the tied mesh force's direction (the cylinder axis; A5.2.1.48-51),
    ///   projected on the pitch-circle tangent (A8.1.10), as a magnitude;
    /// - Buckingham's load in its saturated limit
    ///   ([`BuckinghamPair::saturated_dynamic_load`]).
    Thesis,
}

/// The gears' steel, for the AGMA allowable stress numbers (grade 2).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum GearMaterial {
    /// Through-hardened, from the hardness (AGMA 2001-D04 Figs. 3 and 8).
    #[default]
    ThroughHardened,
    /// Carburized and hardened (AGMA 2001-D04 Tables 3 and 4): Karhula's chapter 8 names
    /// carburizing steel for the cardan pair.
    Carburized,
}

/// The gear pair of a mesh and its rating data, SI. Defaults: Karhula (2008) App. 8.1 and 9.1
/// where it gives a value, this project's stated choice elsewhere.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GearSpec {
    /// Teeth of the gear on the mesh's body (the cardan wheel; Karhula A9.1.36: 20).
    pub teeth: u32,
    /// Face width, m; `None`: a third of the pinion's pitch diameter (A8.1.9, A9.1.46).
    pub face_width: Option<f64>,
    /// Addendum of an internal (ring) gear in modules: 0.8 gives the contact ratio ≈ 1.8 of
    /// Karhula's text (a full 1.0 interferes on 20/40 at 20°, docs/validation/gears.md §1.3).
    pub ring_addendum: f64,
    /// Profile shift coefficients [pinion, gear] (ISO 21771 signs).
    pub profile_shift: [f64; 2],
    /// AGMA 2000 quality number Qv for the dynamic factor (this project's default 8).
    pub quality: f64,
    /// The gears' steel and its treatment, for the allowable stresses.
    pub material: GearMaterial,
    /// Brinell hardness of [pinion, gear] of through-hardened steel (this project's default
    /// 300 HB).
    pub hardness: [f64; 2],
    /// AGMA bending geometry factors [pinion, gear]; `None`: the AGMA 908 25° table proxy for an
    /// internal pair at 25°, no bending rating otherwise (AGMA 908 tabulates no 20° internal J).
    pub j: Option<[f64; 2]>,
    /// Buckingham's effective profile error (backlash), m (Karhula: 0.005 in = 0.127 mm).
    pub error: f64,
    /// Young's modulus of both gears, Pa (Karhula: 210 GPa).
    pub youngs_modulus: f64,
    /// Two identical gear sets side by side share the load (Nunes 2017's twin set).
    pub twin: bool,
    pub tooth_load: ToothLoad,
}

impl Default for GearSpec {
    fn default() -> Self {
        Self {
            teeth: 20,
            face_width: None,
            ring_addendum: 0.8,
            profile_shift: [0.0, 0.0],
            quality: 8.0,
            material: GearMaterial::ThroughHardened,
            hardness: [300.0, 300.0],
            j: None,
            error: 0.005 * 0.0254,
            youngs_modulus: 210e9,
            twin: false,
            tooth_load: ToothLoad::Tangential,
        }
    }
}

/// The validated pair of a mesh whose pinion has pitch radius `pitch_radius` (m): module
/// m = 2·r/z1 (Karhula A9.1.37 for the cardan wheel, r = Z_AA0c), z2 = ratio·z1 (negative for an
/// internal gear, ISO 21771); the pair must pass the interference and contact checks, each
/// failure naming the field to change.
pub fn mesh_pair(
    spec: &GearSpec,
    ratio: f64,
    pitch_radius: f64,
    internal: bool,
    pressure_angle: f64,
) -> Result<(GearPair, f64), LossError> {
    let failed = |field: &str, rule: String| LossError {
        field: field.into(),
        rule,
    };
    let z1 = spec.teeth as i32;
    let z2_real = ratio * f64::from(z1);
    let z2 = z2_real.round() as i32;
    if (f64::from(z2) - z2_real).abs() > 1e-9 {
        return Err(failed(
            "gear.teeth",
            format!("{z1} teeth on the pinion give {z2_real} on the gear of ratio {ratio}: choose a number of teeth that makes it whole"),
        ));
    }
    let module = 2.0 * pitch_radius / f64::from(z1);
    let [x1, x2] = spec.profile_shift;
    let mut pair_spec = PairSpec::standard(
        module,
        z1,
        if internal { -z2 } else { z2 },
        pressure_angle,
        x1,
        x2,
    );
    if internal {
        pair_spec.gear = pair_spec.gear.with_addendum(spec.ring_addendum);
    }
    let pair = GearPair::new(pair_spec).map_err(|e| failed("gear", e.to_string()))?;
    pair.verify().map_err(|e| {
        failed(
            "gear.ring_addendum",
            format!(
                "{e} (ring addendum {} modules, {z1}/{z2} teeth): shorten the ring addendum, shift the profiles or raise the pressure angle",
                spec.ring_addendum
            ),
        )
    })?;
    let face_width = spec.face_width.unwrap_or(pair.pinion.reference / 3.0);
    Ok((pair, face_width))
}

/// The speeds of a mesh joint `joint` whose pinion is on `body` with pitch radius
/// `pitch_radius` (m): the pinion's absolute angular speed, and the carrier's from the joint's
/// relative speed, which is the pitch-line speed relative to the carrier.
pub(crate) fn mesh_speeds(
    state: &State,
    joint: usize,
    body: usize,
    pitch_radius: f64,
) -> MeshSpeeds {
    let pinion = state.bodies[body].angular_velocity;
    MeshSpeeds {
        pinion_absolute: pinion,
        carrier: pinion - state.joints[joint].relative_speed / pitch_radius,
    }
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
}

/// The rated meshes of one mechanism.
#[derive(Debug, Clone)]
pub struct GearRatings {
    meshes: Vec<Rated>,
}

#[derive(Debug, Clone)]
struct Rated {
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
}

impl GearRatings {
    /// The ratings of every gear mesh of `mechanism` under `spec`, the mesh loss in the reading
    /// and oil of `friction` (its gear-mesh reading and its oil), or without one in the corrected
    /// reading with Karhula's oil ([`Friction::karhula`]).
    pub fn new(
        spec: &GearSpec,
        mechanism: &dyn Mechanism,
        friction: Option<&Friction>,
    ) -> Result<Self, LossError> {
        let (reading, oil) = match friction {
            Some(f) => (f.gear_mesh.map_or(Reading::Corrected, |g| g.reading), f.oil),
            None => (Reading::Corrected, Friction::karhula().oil),
        };
        let failed = |field: &str, e: &dyn std::fmt::Display| LossError {
            field: field.into(),
            rule: e.to_string(),
        };
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
            // The thesis's ring force acts along its tied direction (A5.2.1.48-51); involute
            // teeth have no such direction.
            let axis = match (spec.tooth_load, force) {
                (_, MeshForce::Tied { direction, .. }) => direction,
                (ToothLoad::Thesis, MeshForce::Involute) => {
                    return Err(LossError {
                        field: "gear.tooth_load".into(),
                        rule: format!(
                            "\"thesis\" is Karhula's reading of his own mesh force, which acts \
                             along a fixed direction; the mesh {} has involute teeth pushing \
                             along the line of action (the `involute` mesh-force reading): rate \
                             it with \"tangential\", or use the `karhula` mesh-force reading",
                            j.name
                        ),
                    });
                }
                (_, MeshForce::Involute) => C::i(),
            };
            let (pair, face_width) =
                mesh_pair(spec, ratio, pitch_radius, internal, pressure_angle)?;
            // The load distribution's empirical Cpf holds up to 40 in (AGMA 2001-D04 eq. 28-30):
            // a wider face is refused here, before any step, not at the first step's rating.
            cardan_gears::agma::factors::pinion_proportion_factor(face_width, pair.pinion.working)
                .map_err(|e| failed("gear.face_width", &e))?;
            let table_j = (internal && (pressure_angle.to_degrees() - 25.0).abs() < 1e-9)
                .then(|| {
                    cardan_gears::agma::geometry_factors::internal_j_conservative(
                        ShiftCase::Zero,
                        spec.teeth,
                    )
                    .ok()
                })
                .flatten();
            let j_factors = spec.j.or(table_j.map(|(a, b)| [a, b]));
            let member = |m: usize| -> Result<MemberData, LossError> {
                let (bending_allowable, contact_allowable) = match spec.material {
                    GearMaterial::ThroughHardened => (
                        bending_allowable_through_hardened(spec.hardness[m], Grade::Two)
                            .map_err(|e| failed("gear.hardness", &e))?,
                        contact_allowable_through_hardened(spec.hardness[m], Grade::Two)
                            .map_err(|e| failed("gear.hardness", &e))?,
                    ),
                    GearMaterial::Carburized => carburized_allowables(Grade::Two),
                };
                Ok(MemberData {
                    j: j_factors.map_or(1.0, |j| j[m]),
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
                    .map_err(|e| failed("gear", &e))?,
                elastic_coefficient: elastic_coefficient(
                    spec.youngs_modulus,
                    0.3,
                    spec.youngs_modulus,
                    0.3,
                )
                .map_err(|e| failed("gear.youngs_modulus", &e))?,
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
                loss_reading: reading,
            };
            meshes.push(Rated {
                joint: k,
                body: j.body,
                name: j.name,
                set,
                pitch_radius,
                sets: if spec.twin { 2.0 } else { 1.0 },
                bending: j_factors.is_some(),
                tooth_load: spec.tooth_load,
                disc_mass: Material::Steel.density()
                    * face_width
                    * std::f64::consts::PI
                    * pitch_radius
                    * pitch_radius,
                axis,
            });
        }
        Ok(Self { meshes })
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

    /// Whether each mesh gets a bending rating (its J is known).
    pub fn bending(&self) -> Vec<bool> {
        self.meshes.iter().map(|m| m.bending).collect()
    }

    /// Each mesh's rating at `state` under the `total` loads (and the `inertial` family's, which
    /// [`ToothLoad::Thesis`] needs; `None` without one), into `out`.
    pub fn evaluate(
        &self,
        state: &State,
        total: &Loads,
        inertial: Option<&Loads>,
        out: &mut [MeshRating],
    ) -> Result<(), String> {
        for (m, out) in self.meshes.iter().zip(out.iter_mut()) {
            let motion = &state.joints[m.joint];
            let force = total.joints[m.joint].force;
            let tangential_load = tangential(force, motion).abs() / m.sets;
            let step = MeshStep {
                tangential_load,
                pitch_line_velocity: motion.relative_speed,
                speeds: mesh_speeds(state, m.joint, m.body, m.pitch_radius),
            };
            let failed = |e: cardan_gears::GearError| format!("gear rating of {}: {e}", m.name);
            let mut r = m.set.evaluate(&step).map_err(failed)?;
            let load = match m.tooth_load {
                ToothLoad::Tangential => tangential_load,
                ToothLoad::RingForce => force.norm() / m.sets,
                ToothLoad::Thesis => {
                    let inertial = inertial.map_or(C::new(0.0, 0.0), |l| l.joints[m.joint].force);
                    let wheel = m.disc_mass * state.bodies[m.body].cg.acceleration;
                    let slipped = force - 2.0 * inertial + wheel;
                    let axial = m.axis * (slipped.re * m.axis.re + slipped.im * m.axis.im);
                    tangential(axial, motion).abs() / m.sets
                }
            };
            // Another rated load: the rating and Buckingham's load at it (the loss stays on the
            // tangential load).
            if m.tooth_load != ToothLoad::Tangential {
                r.dynamic = if m.tooth_load == ToothLoad::Thesis {
                    m.set.buckingham.saturated_dynamic_load(load)
                } else {
                    m.set
                        .buckingham
                        .dynamic_load(load, motion.relative_speed.abs())
                }
                .map_err(failed)?;
                r.rating = m
                    .set
                    .rating
                    .rate(load, r.kv.kv, m.set.face_width)
                    .map_err(failed)?;
            }
            let (bending_stress, bending_safety) = if m.bending {
                (
                    r.rating.bending_stress[0].max(r.rating.bending_stress[1]),
                    r.rating.bending_safety[0].min(r.rating.bending_safety[1]),
                )
            } else {
                (f64::NAN, f64::NAN)
            };
            *out = MeshRating {
                tooth_load: load,
                dynamic_load: r.dynamic.dynamic_load,
                contact_stress: r.rating.contact_stress[0].max(r.rating.contact_stress[1]),
                contact_safety: r.rating.contact_safety[0].min(r.rating.contact_safety[1]),
                bending_stress,
                bending_safety,
                loss: r.loss.total_power * m.sets,
            };
        }
        Ok(())
    }
}
