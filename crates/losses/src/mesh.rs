//! A gear mesh joint of a mechanism, as the loss budget and the gear rating both take it: the
//! components of its force (the tangential tooth load, Karhula 2008 A8.1.10), its speeds, and
//! the gear pair built from the joint's declared pitch radius, ratio, pressure angle and
//! internal ring with the case's [`GearSpec`] (ISO 21771 through [`cardan_gears::geometry`]).

use crate::{GearInput, SetupError, SetupInput};
use cardan_gears::geometry::{GearPair, PairSpec};
pub use cardan_gears::materials::IsoQuality;
use cardan_gears::mesh_loss::MeshSpeeds;
use cardan_mechanism::{JointMotion, C};

/// The component of a mesh force along the pitch-circle tangent t = i·d (d: from the pitch
/// point towards the centre of the mesh's first gear): the tooth load that transmits torque
/// (Karhula A8.1.10).
#[inline]
pub fn tangential(force: C, mesh: &JointMotion) -> f64 {
    let t = C::i() * mesh.direction;
    force.re * t.re + force.im * t.im
}

/// The component of a mesh force along d, towards the centre of the mesh's first gear.
#[inline]
pub fn radial(force: C, mesh: &JointMotion) -> f64 {
    force.re * mesh.direction.re + force.im * mesh.direction.im
}

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
    ///   ([`cardan_gears::buckingham::BuckinghamPair::saturated_dynamic_load`]).
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

/// Which standard rates the meshes' stresses and safety factors: the words of the gear file's
/// `[rating] basis` (`cardan gear`), and both side by side.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum GearStandard {
    /// AGMA 2001-D04 (the rating of every run before ISO 6336 came in).
    #[default]
    Agma2001,
    /// ISO 6336-2/-3:2019 method B, in place of AGMA's stresses and safety factors.
    Iso6336,
    /// Both, side by side.
    Both,
}

impl GearStandard {
    /// Whether AGMA 2001's stresses and safety factors are reported.
    pub fn agma(self) -> bool {
        self != Self::Iso6336
    }

    /// Whether ISO 6336's are computed and reported.
    pub fn iso(self) -> bool {
        self != Self::Agma2001
    }
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
    /// AGMA bending geometry factors [pinion, gear]; `None`: computed from the tooth form (AGMA
    /// 908-B89 for an external member, ISO 6336-3 method B for an internal ring,
    /// `cardan_gears::agma908`).
    pub j: Option<[f64; 2]>,
    /// Buckingham's effective profile error (backlash), m (Karhula: 0.005 in = 0.127 mm).
    pub error: f64,
    /// Young's modulus of both gears, Pa (Karhula: 210 GPa).
    pub youngs_modulus: f64,
    /// Two identical gear sets side by side share the load (Nunes 2017's twin set).
    pub twin: bool,
    pub tooth_load: ToothLoad,
    /// Which standard rates the stresses (default AGMA 2001 alone).
    pub standard: GearStandard,
    /// ISO 1328-1 accuracy grade of both gears (1-12), for ISO 6336-1 method B's `K_v` and
    /// `K_Hα`; required with an ISO rating (no default: nothing in the case implies it).
    pub accuracy_grade: Option<f64>,
    /// ISO 6336-1 application factor `K_A` (default 1: the run's tooth load is the computed
    /// load at every step, gas and inertia, as the AGMA rating's overload factor `K_o` = 1;
    /// ISO 6336-1:2019 Annex B, Table B.1: 1.00 for a uniform driver and driven machine).
    pub application_factor: f64,
    /// ISO 6336-5 material quality of both gears, for `σ_Hlim` and `σ_Flim` (default MQ,
    /// ISO 6336-5:2016 §5.2's usual industrial quality, the gear file's default).
    pub iso_quality: IsoQuality,
    /// Factors and limits of the ISO rating a user knows better than its defaults (the gear
    /// file's fields of the same names).
    pub iso_overrides: IsoOverrides,
}

/// What replaces an ISO 6336 rating's own factors and limits where given (`None`: computed, as
/// `cardan_dynamics::gear_rating` says): ISO 6336-1's method A, a measured or otherwise
/// established value, takes precedence over method B (ISO 6336-1:2019 §4.1.6).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct IsoOverrides {
    /// Dynamic factor `K_v` (ISO 6336-1 §6), ≥ 1; else method B from the accuracy grade.
    pub dynamic_factor: Option<f64>,
    /// Transverse load factor `K_Hα` (= `K_Fα`, ISO 6336-1 §8), ≥ 1; else method B.
    pub transverse_load_factor: Option<f64>,
    /// Face load factor `K_Hβ` (ISO 6336-1 §7), ≥ 1; else the AGMA rating's `K_m` for the face
    /// width; `K_Fβ` follows from it (ISO 6336-1 §7.6).
    pub face_load_factor: Option<f64>,
    /// Allowable contact stress numbers `σ_Hlim` [pinion, gear], Pa; else ISO 6336-5 for the
    /// material, hardness and quality.
    pub sigma_hlim: Option<[f64; 2]>,
    /// Nominal bending stress numbers `σ_Flim` [pinion, gear], Pa; else ISO 6336-5.
    pub sigma_flim: Option<[f64; 2]>,
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
            standard: GearStandard::Agma2001,
            accuracy_grade: None,
            application_factor: 1.0,
            iso_quality: IsoQuality::Mq,
            iso_overrides: IsoOverrides::default(),
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
) -> Result<(GearPair, f64), SetupError> {
    let failed = |field: GearInput, rule: String| SetupError {
        field: SetupInput::Gear(field),
        rule,
    };
    let z1 = spec.teeth as i32;
    let z2_real = ratio * f64::from(z1);
    let z2 = z2_real.round() as i32;
    if (f64::from(z2) - z2_real).abs() > 1e-9 {
        return Err(failed(
            GearInput::Teeth,
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
    let pair = GearPair::new(pair_spec).map_err(|e| failed(GearInput::Pair, e.to_string()))?;
    pair.verify().map_err(|e| {
        failed(
            GearInput::RingAddendum,
            format!(
                "{e} (ring addendum {} modules, {z1}/{z2} teeth): shorten the ring addendum, shift the profiles or raise the pressure angle",
                spec.ring_addendum
            ),
        )
    })?;
    let face_width = spec.face_width.unwrap_or(pair.pinion.reference / 3.0);
    Ok((pair, face_width))
}

/// The speeds of a mesh whose pinion turns at `pinion` (rad/s, absolute) with pitch radius
/// `pitch_radius` (m): the pinion's absolute angular speed, and the carrier's from the mesh
/// joint's `relative_speed` (m/s), which is the pitch-line speed relative to the carrier.
pub fn mesh_speeds(pinion: f64, relative_speed: f64, pitch_radius: f64) -> MeshSpeeds {
    MeshSpeeds {
        pinion_absolute: pinion,
        carrier: pinion - relative_speed / pitch_radius,
    }
}
