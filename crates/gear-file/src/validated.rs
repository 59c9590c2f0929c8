//! The validated gear file: what [`super::input`] makes of a gear file's text and what
//! [`super::rating`] and [`super::report`] read, below all three (no part imports the module
//! that holds it).

use cardan_gears::iso6336::{IsoDynamic, Lubrication};
use cardan_gears::materials::{LifeCurve, Material};
use cardan_gears::{BendingHighCycle, BendingLowCycle, IForm, LoadDistribution, PairSpec, Quality};
use std::path::PathBuf;

/// Version of the layout of `gear.json`; raised when a name or the shape changes.
pub const SCHEMA_VERSION: u32 = 1;

/// Why a gear file could not be rated or written.
#[derive(Debug, thiserror::Error)]
pub enum GearFileError {
    #[error("{file}: cannot read: {source}")]
    Io {
        file: PathBuf,
        source: std::io::Error,
    },
    /// TOML syntax, a missing field, an unknown key or a value of the wrong type; the message
    /// is the TOML reader's, with the line and column.
    #[error("{file}: {message}")]
    Syntax { file: PathBuf, message: String },
    /// A field of the typed schema that did not read (a misspelled field or word, a value of
    /// the wrong form): its path and what is wrong with it.
    #[error("{file}: gear pair \"{name}\": {error}")]
    Field {
        file: PathBuf,
        name: String,
        error: cardan_case::schema::FieldError,
    },
    #[error("{file}: gear pair \"{name}\": {field} = {value}: {rule}")]
    Invalid {
        file: PathBuf,
        name: String,
        field: String,
        value: String,
        rule: String,
    },
    #[error("{file}: gear pair \"{name}\": cannot write results to {dir}: {message}")]
    Write {
        file: PathBuf,
        name: String,
        dir: PathBuf,
        message: String,
    },
}

/// How the load is given.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Load {
    /// Transmitted power, W.
    Power(f64),
    /// Pinion torque, N·m.
    Torque(f64),
}

/// How `Kv` is obtained.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum KvInput {
    /// From an AGMA accuracy grade and the pitch-line velocity.
    Quality(Quality),
    /// Given.
    Given(f64),
}

/// How the pitting geometry factor `I` is obtained.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum IInput {
    /// AGMA 908 formula at the given contact point.
    Form(IForm),
    /// Given.
    Given(f64),
}

/// Validated rating inputs of one member; stresses in Pa.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MemberInputs {
    /// J as given (`None`: computed from the tooth form).
    pub j: Option<f64>,
    pub rim_factor: f64,
    pub lewis_y: Option<f64>,
    pub size_factor: Option<f64>,
    pub hardness: Option<f64>,
    pub bending_allowable: f64,
    pub contact_allowable: f64,
    /// The named material, if any.
    pub material: Option<&'static Material>,
    /// The member's ISO 6336 inputs, when the ISO rating is computed.
    pub iso: Option<IsoMemberInputs>,
}

/// One member's ISO 6336 inputs; stresses in Pa.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct IsoMemberInputs {
    /// Y_F and Y_S as given; `None`: computed from the tooth form by ISO 6336-3 method B
    /// (`cardan_gears::iso6336_method_b`) at rating.
    pub form_factor: Option<f64>,
    pub stress_correction_factor: Option<f64>,
    pub sigma_hlim: f64,
    pub sigma_flim: f64,
    pub life_curve: LifeCurve,
}

/// Which standard's safety factors decide the verdict.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Basis {
    Agma2001,
    Iso6336,
}

impl Basis {
    /// The word of the gear file and `gear.json`.
    pub fn word(self) -> &'static str {
        match self {
            Basis::Agma2001 => "agma2001",
            Basis::Iso6336 => "iso6336",
        }
    }
}

/// The pair's ISO 6336 inputs beside the AGMA ones.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct IsoRatingInputs {
    pub application_factor: f64,
    pub accuracy_grade: Option<f64>,
    pub dynamic: IsoDynamic,
    /// `None`: AGMA's empirical Km for the face width.
    pub face_load_factor: Option<f64>,
    /// `None`: ISO 6336-1 method B.
    pub transverse_load_factor: Option<f64>,
    pub lubrication: Option<Lubrication>,
}

/// `[measurement]`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MeasurementInputs {
    pub span_teeth: Option<[u32; 2]>,
    /// m.
    pub pin_diameter: Option<[f64; 2]>,
}

/// Validated `[rating]` table, SI.
#[derive(Debug, Clone, PartialEq)]
pub struct RatingInputs {
    pub load: Load,
    /// Pinion speed relative to the gear's frame (the carrier of a cardan gear), rad/s.
    pub pinion_speed: f64,
    pub kv: KvInput,
    pub overload: f64,
    pub reliability_factor: f64,
    pub temperature_factor: f64,
    pub surface_condition: f64,
    pub pinion_cycles: f64,
    pub bending_low: BendingLowCycle,
    pub bending_high: BendingHighCycle,
    pub nitrided: bool,
    pub i: IInput,
    /// √Pa.
    pub elastic_coefficient: f64,
    pub hardness_ratio_factor: Option<f64>,
    pub load_distribution: LoadDistribution,
    pub members: [MemberInputs; 2],
    /// The smallest bending (SF) and pitting (SH) safety factor the pair must reach,
    /// `required_safety_factor` (default 1): see [`GearReport::failures`](super::GearReport::failures).
    pub required_safety_factor: f64,
    /// The verdict's basis.
    pub basis: Basis,
    /// ISO 6336 inputs, when a member gives `form_factor` or the basis is ISO.
    pub iso: Option<IsoRatingInputs>,
}

/// A validated gear file.
#[derive(Debug, Clone, PartialEq)]
pub struct GearFile {
    pub file: PathBuf,
    pub name: String,
    pub spec: PairSpec,
    /// The cardan crank length the module was derived from (A9.1.37), m.
    pub cardan_crank_length: Option<f64>,
    /// Face width, m.
    pub face_width: Option<f64>,
    /// Tip radius of the generating rack (cutter) [pinion, gear], m (`None`: the default
    /// 0.25 m of `cardan_gears::tooth_root::DEFAULT_RACK_TIP_RADIUS`).
    pub rack_tip_radius: [Option<f64>; 2],
    pub rating: Option<RatingInputs>,
    pub measurement: Option<MeasurementInputs>,
    /// The fields as written in the file (dotted name, TOML text), for the report.
    pub given: Vec<(String, String)>,
}
