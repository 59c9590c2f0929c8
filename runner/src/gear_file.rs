//! Gear files: one spur pair (external or internal, any ratio) in a TOML file → the ISO 21771
//! geometry, the interference checks with their margins and remedies and, when a `[rating]`
//! table is given, the AGMA 2001-D04 stresses and safety factors → `DIR/<name>/gear.json` and
//! `DIR/<name>/report.md`. The physics is `cardan-gears`'; this module reads, validates and
//! writes (see README.md, "Gear pair calculator").
//!
//! Values take units as case files do, from the one table of [`crate::units`]: a bare number
//! is in the field's SI unit (lengths m, angles deg, speeds rad/s, power W, torque N·m, stress
//! Pa), a string is "NUMBER UNIT" (inches, hp, lbf·in, psi for the US-unit textbook examples).
//!
//! Bad input is a [`GearFileError`] naming the file, the pair, the field, its value and the
//! rule, never a panic. A pair that cannot work (interference, contact ratio below 1, jammed
//! teeth, a safety factor below `required_safety_factor`, a figure that is not finite) is not
//! an input error: it is written, with the failures and their remedies, and
//! [`GearReport::failures`] lists it so the command can exit 1; [`GearReport::warnings`] lists
//! the rules of thumb it breaks.

use crate::output::{replace_dir, temporary_dir, write_file};
use crate::units::{is_folder_name, to_si, Dimension};
use cardan_gears::agma::factors::{
    bending_allowable_through_hardened, contact_allowable_through_hardened, Grade,
};
use cardan_gears::{
    bending_cycle_factor, cardan_module, dynamic_factor, elastic_coefficient,
    hardness_ratio_factor, pitting_cycle_factor, pitting_geometry_factor, reliability_factor_fit,
    reliability_factor_table, BendingHighCycle, BendingLowCycle, CheckKind, CheckReport, Enclosure,
    GearError, GearPair, GearSetRating, GearSpec, HardnessPairing, IForm, LoadDistribution,
    MemberData, PairSpec, Quality, SizeFactor, Tip,
};
use serde::Deserialize;
use serde_json::{json, Map, Value};
use std::f64::consts::PI;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

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

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawGearFile {
    name: String,
    module: Option<toml::Value>,
    cardan_crank_length: Option<toml::Value>,
    pressure_angle: toml::Value,
    teeth: toml::Value,
    profile_shift: Option<toml::Value>,
    center_distance: Option<toml::Value>,
    tip_diameter: Option<toml::Value>,
    addendum_coefficient: Option<toml::Value>,
    dedendum_coefficient: Option<toml::Value>,
    thickness_allowance: Option<toml::Value>,
    face_width: Option<toml::Value>,
    min_teeth_difference: Option<toml::Value>,
    rating: Option<RawRating>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawRating {
    power: Option<toml::Value>,
    torque: Option<toml::Value>,
    pinion_speed: toml::Value,
    quality: Option<toml::Value>,
    accuracy_level: Option<toml::Value>,
    dynamic_factor: Option<toml::Value>,
    overload_factor: Option<toml::Value>,
    reliability: Option<toml::Value>,
    reliability_factor: Option<toml::Value>,
    temperature_factor: Option<toml::Value>,
    surface_condition_factor: Option<toml::Value>,
    pinion_cycles: Option<toml::Value>,
    bending_cycle_low: Option<String>,
    bending_cycle_high: Option<String>,
    pitting_nitrided: Option<bool>,
    geometry_factor_i: Option<toml::Value>,
    elastic_coefficient: Option<toml::Value>,
    hardness_ratio_factor: Option<toml::Value>,
    enclosure: Option<String>,
    crowned: Option<bool>,
    offset_ratio: Option<toml::Value>,
    adjusted_at_assembly: Option<bool>,
    required_safety_factor: Option<toml::Value>,
    pinion: RawMember,
    gear: RawMember,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawMember {
    j: toml::Value,
    rim_factor: Option<toml::Value>,
    lewis_y: Option<toml::Value>,
    size_factor: Option<toml::Value>,
    hardness: Option<toml::Value>,
    grade: Option<toml::Value>,
    bending_allowable: Option<toml::Value>,
    contact_allowable: Option<toml::Value>,
    youngs_modulus: Option<toml::Value>,
    poisson_ratio: Option<toml::Value>,
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
    pub j: f64,
    pub rim_factor: f64,
    pub lewis_y: Option<f64>,
    pub size_factor: Option<f64>,
    pub hardness: Option<f64>,
    pub bending_allowable: f64,
    pub contact_allowable: f64,
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
    /// `required_safety_factor` (default 1): see [`GearReport::failures`].
    pub required_safety_factor: f64,
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
    pub rating: Option<RatingInputs>,
    /// The fields as written in the file (dotted name, TOML text), for the report.
    pub given: Vec<(String, String)>,
}

/// Reads and validates one gear file.
pub fn load(file: &Path) -> Result<GearFile, GearFileError> {
    let text = std::fs::read_to_string(file).map_err(|source| GearFileError::Io {
        file: file.into(),
        source,
    })?;
    parse(file, &text)
}

type Invalid<'a> = dyn Fn(&str, &dyn std::fmt::Display, &str) -> GearFileError + 'a;

/// Validates the text of a gear file; `file` is only for the messages.
pub fn parse(file: &Path, text: &str) -> Result<GearFile, GearFileError> {
    let raw: RawGearFile = toml::from_str(text).map_err(|e| GearFileError::Syntax {
        file: file.into(),
        message: e.to_string().trim_end().to_string(),
    })?;
    let name = raw.name.clone();
    let invalid = |field: &str, value: &dyn std::fmt::Display, rule: &str| GearFileError::Invalid {
        file: file.into(),
        name: name.clone(),
        field: field.to_string(),
        value: value.to_string(),
        rule: rule.to_string(),
    };
    if !is_folder_name(&raw.name) {
        return Err(invalid(
            "name",
            &format!("\"{}\"", raw.name),
            "must be a non-empty folder name of at most 200 letters, digits, '-', '_' and '.', not starting with '.'",
        ));
    }
    let given = given_fields(text);
    let length = |field: &str, v: &toml::Value| {
        to_si(v, Dimension::Length).map_err(|r| invalid(field, v, &r))
    };
    let positive_length = |field: &str, v: &toml::Value| {
        let x = length(field, v)?;
        if x > 0.0 {
            Ok(x)
        } else {
            Err(invalid(field, v, "must be positive"))
        }
    };
    let number = |field: &str, v: &toml::Value| {
        to_si(v, Dimension::Number).map_err(|r| invalid(field, v, &r))
    };

    // Teeth.
    let teeth = pair_of(&raw.teeth, "teeth", &invalid)?;
    let mut z = [0i32; 2];
    for k in 0..2 {
        z[k] = match teeth[k].as_integer() {
            Some(i) if (-100_000..=100_000).contains(&i) => i as i32,
            _ => {
                return Err(invalid(
                    "teeth",
                    &raw.teeth,
                    "must be two whole numbers [z1, z2] (z2 negative for an internal gear), |z| <= 100000",
                ))
            }
        };
    }

    // Module, or the cardan crank length it follows from.
    let (module, crank) = match (&raw.module, &raw.cardan_crank_length) {
        (Some(m), None) => {
            // A module is millimetres (ISO 54: 0.05…100 mm): a bare number above 0.1 m was
            // meant in mm, as a bare crank of 60 is refused in case files.
            let module = positive_length("module", m)?;
            if module > 0.1 && !m.is_str() {
                return Err(invalid(
                    "module",
                    m,
                    &format!("a bare number is in m: a module of {} m is implausible (ISO 54 modules run to 100 mm); write \"{} mm\" if you meant millimetres, or give the unit explicitly", crate::units::short(module), crate::units::short(module)),
                ));
            }
            (module, None)
        }
        (None, Some(e)) => {
            let e_si = positive_length("cardan_crank_length", e)?;
            let m = cardan_module(e_si, z[0].max(0) as u32).map_err(|err| {
                invalid(
                    "cardan_crank_length",
                    e,
                    &format!("gives no module m = 2e/z1: {err}"),
                )
            })?;
            (m, Some(e_si))
        }
        (Some(m), Some(_)) => {
            return Err(invalid(
                "module",
                m,
                "give module or cardan_crank_length (m = 2e/z1, Karhula A9.1.37), not both",
            ))
        }
        (None, None) => {
            return Err(invalid(
                "module",
                &"(missing)",
                "give module (a length, e.g. \"3 mm\") or cardan_crank_length",
            ))
        }
    };
    let pressure_angle = to_si(&raw.pressure_angle, Dimension::Angle)
        .map_err(|r| invalid("pressure_angle", &raw.pressure_angle, &r))?;

    let mut spec = PairSpec {
        module,
        pressure_angle,
        pinion: GearSpec::standard(z[0], 0.0),
        gear: GearSpec::standard(z[1], 0.0),
        centre_distance: None,
        min_teeth_difference: 10,
    };
    if let Some(v) = &raw.profile_shift {
        let x = pair_of(v, "profile_shift", &invalid)?;
        spec.pinion.shift = number("profile_shift", &x[0])?;
        spec.gear.shift = number("profile_shift", &x[1])?;
    }
    if let Some(v) = &raw.addendum_coefficient {
        let h = pair_of(v, "addendum_coefficient", &invalid)?;
        spec.pinion.tip = Tip::Coefficient(number("addendum_coefficient", &h[0])?);
        spec.gear.tip = Tip::Coefficient(number("addendum_coefficient", &h[1])?);
    }
    if let Some(v) = &raw.tip_diameter {
        if raw.addendum_coefficient.is_some() {
            return Err(invalid(
                "tip_diameter",
                v,
                "give tip_diameter or addendum_coefficient, not both",
            ));
        }
        let d = pair_of(v, "tip_diameter", &invalid)?;
        spec.pinion.tip = Tip::Diameter(positive_length("tip_diameter", &d[0])?);
        spec.gear.tip = Tip::Diameter(positive_length("tip_diameter", &d[1])?);
    }
    if let Some(v) = &raw.dedendum_coefficient {
        let h = pair_of(v, "dedendum_coefficient", &invalid)?;
        spec.pinion.dedendum_coefficient = number("dedendum_coefficient", &h[0])?;
        spec.gear.dedendum_coefficient = number("dedendum_coefficient", &h[1])?;
    }
    if let Some(v) = &raw.thickness_allowance {
        let t = pair_of(v, "thickness_allowance", &invalid)?;
        spec.pinion.thickness_allowance = length("thickness_allowance", &t[0])?;
        spec.gear.thickness_allowance = length("thickness_allowance", &t[1])?;
    }
    if let Some(v) = &raw.center_distance {
        spec.centre_distance = Some(positive_length("center_distance", v)?);
    }
    if let Some(v) = &raw.min_teeth_difference {
        spec.min_teeth_difference = match v.as_integer() {
            Some(i) if (0..=1000).contains(&i) => i as u32,
            _ => {
                return Err(invalid(
                    "min_teeth_difference",
                    v,
                    "must be a whole number from 0 to 1000",
                ))
            }
        };
    }
    // The geometry is validated here, so that a bad pair is an input error of this file.
    GearPair::new(spec).map_err(|e| geometry_error(e, &raw, &invalid))?;

    let face_width = raw
        .face_width
        .as_ref()
        .map(|v| positive_length("face_width", v))
        .transpose()?;
    let rating = match &raw.rating {
        None => None,
        Some(r) => {
            if face_width.is_none() {
                return Err(invalid(
                    "face_width",
                    &"(missing)",
                    "a pair with a [rating] table needs its face width",
                ));
            }
            Some(parse_rating(r, &invalid)?)
        }
    };
    Ok(GearFile {
        file: file.into(),
        name: raw.name,
        spec,
        cardan_crank_length: crank,
        face_width,
        rating,
        given,
    })
}

/// `[a, b]` of a two-entry array field.
fn pair_of(
    v: &toml::Value,
    field: &str,
    invalid: &Invalid,
) -> Result<[toml::Value; 2], GearFileError> {
    match v.as_array() {
        Some(a) if a.len() == 2 => Ok([a[0].clone(), a[1].clone()]),
        _ => Err(invalid(
            field,
            v,
            "must be a list of two values [pinion, gear]",
        )),
    }
}

/// Names the file's field behind an input error of the geometry.
fn geometry_error(e: GearError, raw: &RawGearFile, invalid: &Invalid) -> GearFileError {
    let GearError::InvalidInput { field, rule, value } = e else {
        return invalid("teeth", &raw.teeth, &e.to_string());
    };
    let tip_field = if raw.tip_diameter.is_some() {
        "tip_diameter"
    } else {
        "addendum_coefficient"
    };
    let name = match field {
        "module" if raw.module.is_none() => "cardan_crank_length",
        "module" => "module",
        "pressure_angle" => "pressure_angle",
        "pinion.teeth" | "gear.teeth" => "teeth",
        "pinion.shift" | "gear.shift" | "shift" => "profile_shift",
        "pinion.dedendum_coefficient" | "gear.dedendum_coefficient" => "dedendum_coefficient",
        "pinion.thickness_allowance" | "gear.thickness_allowance" => "thickness_allowance",
        "centre_distance" => "center_distance",
        "tip diameter" => "tip_diameter",
        _ => tip_field,
    };
    let given = match name {
        "cardan_crank_length" => raw.cardan_crank_length.clone(),
        "module" => raw.module.clone(),
        "pressure_angle" => Some(raw.pressure_angle.clone()),
        "teeth" => Some(raw.teeth.clone()),
        "profile_shift" => raw.profile_shift.clone(),
        "dedendum_coefficient" => raw.dedendum_coefficient.clone(),
        "thickness_allowance" => raw.thickness_allowance.clone(),
        "center_distance" => raw.center_distance.clone(),
        "tip_diameter" => raw.tip_diameter.clone(),
        _ => raw.addendum_coefficient.clone(),
    };
    let detail = format!("{rule} (as computed: {field} = {value})");
    match given {
        Some(v) => invalid(name, &v, &detail),
        None => invalid(name, &"(default)", &detail),
    }
}

fn parse_rating(r: &RawRating, invalid: &Invalid) -> Result<RatingInputs, GearFileError> {
    let quantity = |field: &str, v: &toml::Value, q: Dimension| {
        to_si(v, q).map_err(|rule| invalid(field, v, &rule))
    };
    let number = |field: &str, v: &toml::Value| {
        to_si(v, Dimension::Number).map_err(|rule| invalid(field, v, &rule))
    };
    let positive_number = |field: &str, v: &toml::Value| {
        let x = number(field, v)?;
        if x > 0.0 {
            Ok(x)
        } else {
            Err(invalid(field, v, "must be positive"))
        }
    };
    let factor = |field: &str, v: &Option<toml::Value>| match v {
        Some(v) => positive_number(field, v),
        None => Ok(1.0),
    };
    let gear_err =
        |field: &str, v: &dyn std::fmt::Display, e: GearError| invalid(field, v, &e.to_string());

    let load = match (&r.power, &r.torque) {
        (Some(p), None) => Load::Power(quantity("rating.power", p, Dimension::Power)?),
        (None, Some(t)) => Load::Torque(quantity("rating.torque", t, Dimension::Torque)?),
        (Some(p), Some(_)) => {
            return Err(invalid(
                "rating.power",
                p,
                "give power or the pinion torque, not both",
            ))
        }
        (None, None) => {
            return Err(invalid(
                "rating.power",
                &"(missing)",
                "give power (e.g. \"4 hp\", \"3 kW\") or the pinion torque (\"20 N*m\")",
            ))
        }
    };
    let (load_field, load_value) = match load {
        Load::Power(p) => ("rating.power", p),
        Load::Torque(t) => ("rating.torque", t),
    };
    if load_value <= 0.0 {
        let v = r
            .power
            .as_ref()
            .or(r.torque.as_ref())
            .unwrap_or(&r.pinion_speed);
        return Err(invalid(
            load_field,
            v,
            "must be positive (a pair without load has no rating: leave out [rating] for the geometry only)",
        ));
    }
    let pinion_speed = to_si(&r.pinion_speed, Dimension::AngularSpeed)
        .map_err(|rule| invalid("rating.pinion_speed", &r.pinion_speed, &rule))?;
    if pinion_speed <= 0.0 {
        return Err(invalid(
            "rating.pinion_speed",
            &r.pinion_speed,
            "must be positive",
        ));
    }

    let kv = match (&r.quality, &r.accuracy_level, &r.dynamic_factor) {
        (Some(q), None, None) => {
            let qv = number("rating.quality", q)?;
            dynamic_factor(Quality::Qv(qv), 0.0).map_err(|e| gear_err("rating.quality", q, e))?;
            KvInput::Quality(Quality::Qv(qv))
        }
        (None, Some(a), None) => {
            let av = number("rating.accuracy_level", a)?;
            dynamic_factor(Quality::Av(av), 0.0)
                .map_err(|e| gear_err("rating.accuracy_level", a, e))?;
            KvInput::Quality(Quality::Av(av))
        }
        (None, None, Some(k)) => {
            let kv = number("rating.dynamic_factor", k)?;
            if kv < 1.0 {
                return Err(invalid("rating.dynamic_factor", k, "must be >= 1"));
            }
            KvInput::Given(kv)
        }
        _ => {
            return Err(invalid(
                "rating.quality",
                &r.quality.clone().unwrap_or(toml::Value::String("(missing)".into())),
                "give exactly one of quality (AGMA 2001 Qv, 5-12), accuracy_level (AGMA 2101 Av, 6-12) or dynamic_factor (Kv)",
            ))
        }
    };

    let reliability_factor = match (&r.reliability, &r.reliability_factor) {
        (Some(v), None) => {
            let rel = number("rating.reliability", v)?;
            reliability_factor_table(rel)
                .or_else(|_| reliability_factor_fit(rel))
                .map_err(|e| gear_err("rating.reliability", v, e))?
        }
        (None, Some(v)) => positive_number("rating.reliability_factor", v)?,
        (Some(v), Some(_)) => {
            return Err(invalid(
                "rating.reliability",
                v,
                "give reliability or reliability_factor (KR), not both",
            ))
        }
        (None, None) => 1.0,
    };
    let pinion_cycles = match &r.pinion_cycles {
        Some(v) => {
            let n = number("rating.pinion_cycles", v)?;
            pitting_cycle_factor(n, false).map_err(|e| gear_err("rating.pinion_cycles", v, e))?;
            n
        }
        None => 1e7,
    };
    let bending_low =
        match r.bending_cycle_low.as_deref().unwrap_or("hb250") {
            "hb400" => BendingLowCycle::Hb400,
            "case-carburized" => BendingLowCycle::CaseCarburized,
            "hb250" => BendingLowCycle::Hb250,
            "nitrided" => BendingLowCycle::Nitrided,
            "hb160" => BendingLowCycle::Hb160,
            other => return Err(invalid(
                "rating.bending_cycle_low",
                &format!("\"{other}\""),
                "must be one of \"hb400\", \"case-carburized\", \"hb250\", \"nitrided\", \"hb160\"",
            )),
        };
    let bending_high = match r.bending_cycle_high.as_deref().unwrap_or("upper") {
        "upper" => BendingHighCycle::Upper,
        "lower" => BendingHighCycle::Lower,
        other => {
            return Err(invalid(
                "rating.bending_cycle_high",
                &format!("\"{other}\""),
                "must be \"upper\" (general) or \"lower\" (critical service)",
            ))
        }
    };
    let i = match &r.geometry_factor_i {
        None => IInput::Form(IForm::Lpstc),
        Some(toml::Value::String(s)) if s == "lpstc" => IInput::Form(IForm::Lpstc),
        Some(toml::Value::String(s)) if s == "pitch-point" => IInput::Form(IForm::PitchPoint),
        Some(v @ (toml::Value::Float(_) | toml::Value::Integer(_))) => {
            IInput::Given(positive_number("rating.geometry_factor_i", v)?)
        }
        Some(v) => {
            return Err(invalid(
                "rating.geometry_factor_i",
                v,
                "must be \"lpstc\" (AGMA 908), \"pitch-point\" (Shigley eq. 14-23) or a number",
            ))
        }
    };
    let enclosure = match r.enclosure.as_deref().unwrap_or("commercial") {
        "open" => Enclosure::Open,
        "commercial" => Enclosure::CommercialEnclosed,
        "precision" => Enclosure::PrecisionEnclosed,
        "extra-precision" => Enclosure::ExtraPrecisionEnclosed,
        other => {
            return Err(invalid(
                "rating.enclosure",
                &format!("\"{other}\""),
                "must be one of \"open\", \"commercial\", \"precision\", \"extra-precision\"",
            ))
        }
    };
    let offset_ratio = match &r.offset_ratio {
        Some(v) => {
            let x = number("rating.offset_ratio", v)?;
            if x < 0.0 {
                return Err(invalid("rating.offset_ratio", v, "must not be negative"));
            }
            x
        }
        None => 0.0,
    };

    let member = |which: &str, m: &RawMember| -> Result<MemberInputs, GearFileError> {
        let f = |k: &str| format!("rating.{which}.{k}");
        let j = positive_number(&f("j"), &m.j)?;
        let rim_factor = factor(&f("rim_factor"), &m.rim_factor)?;
        let lewis_y = m
            .lewis_y
            .as_ref()
            .map(|v| positive_number(&f("lewis_y"), v))
            .transpose()?;
        let size_factor = m
            .size_factor
            .as_ref()
            .map(|v| positive_number(&f("size_factor"), v))
            .transpose()?;
        if let (Some(v), Some(_)) = (&m.lewis_y, &m.size_factor) {
            return Err(invalid(
                &f("lewis_y"),
                v,
                "give lewis_y (Ks from Shigley eq. 14-10) or size_factor (Ks), not both",
            ));
        }
        let hardness = m
            .hardness
            .as_ref()
            .map(|v| positive_number(&f("hardness"), v))
            .transpose()?;
        let grade = match &m.grade {
            None => Grade::One,
            Some(v) => match v.as_integer() {
                Some(1) => Grade::One,
                Some(2) => Grade::Two,
                _ => return Err(invalid(&f("grade"), v, "must be 1 or 2 (AGMA 2001 grade)")),
            },
        };
        let allowable = |key: &str,
                         given: &Option<toml::Value>,
                         chart: fn(f64, Grade) -> Result<f64, GearError>|
         -> Result<f64, GearFileError> {
            match (given, hardness) {
                (Some(v), _) => {
                    let s = quantity(&f(key), v, Dimension::Pressure)?;
                    if s > 0.0 {
                        Ok(s)
                    } else {
                        Err(invalid(&f(key), v, "must be positive"))
                    }
                }
                (None, Some(hb)) => chart(hb, grade).map_err(|e| {
                    gear_err(&f("hardness"), m.hardness.as_ref().unwrap_or(&m.j), e)
                }),
                (None, None) => Err(invalid(
                    &f(key),
                    &"(missing)",
                    "give it (a stress, e.g. \"31350 psi\") or the Brinell hardness of a through-hardened steel (AGMA 2001 charts)",
                )),
            }
        };
        Ok(MemberInputs {
            j,
            rim_factor,
            lewis_y,
            size_factor,
            hardness,
            bending_allowable: allowable(
                "bending_allowable",
                &m.bending_allowable,
                bending_allowable_through_hardened,
            )?,
            contact_allowable: allowable(
                "contact_allowable",
                &m.contact_allowable,
                contact_allowable_through_hardened,
            )?,
        })
    };
    let members = [member("pinion", &r.pinion)?, member("gear", &r.gear)?];
    if members[0].lewis_y.is_some() != members[1].lewis_y.is_some() {
        return Err(invalid(
            "rating.gear.lewis_y",
            &r.gear
                .lewis_y
                .clone()
                .unwrap_or(toml::Value::String("(missing)".into())),
            "give lewis_y for both members or for neither",
        ));
    }

    let elastic = match &r.elastic_coefficient {
        Some(v) => {
            let cp = quantity("rating.elastic_coefficient", v, Dimension::RootStress)?;
            if cp <= 0.0 {
                return Err(invalid("rating.elastic_coefficient", v, "must be positive"));
            }
            cp
        }
        None => {
            let mut en = [(0.0, 0.0); 2];
            for (k, (which, m)) in [("pinion", &r.pinion), ("gear", &r.gear)]
                .iter()
                .enumerate()
            {
                let (Some(e), Some(nu)) = (&m.youngs_modulus, &m.poisson_ratio) else {
                    return Err(invalid(
                        "rating.elastic_coefficient",
                        &"(missing)",
                        &format!("give it (e.g. \"2300 sqrt(psi)\", \"190 sqrt(MPa)\") or youngs_modulus and poisson_ratio in [rating.{which}]"),
                    ));
                };
                en[k] = (
                    quantity(
                        &format!("rating.{which}.youngs_modulus"),
                        e,
                        Dimension::Pressure,
                    )?,
                    number(&format!("rating.{which}.poisson_ratio"), nu)?,
                );
            }
            elastic_coefficient(en[0].0, en[0].1, en[1].0, en[1].1).map_err(|e| {
                gear_err(
                    "rating.pinion.youngs_modulus",
                    r.pinion.youngs_modulus.as_ref().unwrap_or(&r.pinion.j),
                    e,
                )
            })?
        }
    };
    let required_safety_factor = match &r.required_safety_factor {
        None => 1.0,
        Some(v) => {
            let n = number("rating.required_safety_factor", v)?;
            if !n.is_finite() {
                return Err(invalid(
                    "rating.required_safety_factor",
                    v,
                    "must be a finite number",
                ));
            }
            if n < 1.0 {
                return Err(invalid(
                    "rating.required_safety_factor",
                    v,
                    "must be >= 1 (below 1 the pair is expected to break)",
                ));
            }
            n
        }
    };
    let hardness_ratio_factor = r
        .hardness_ratio_factor
        .as_ref()
        .map(|v| positive_number("rating.hardness_ratio_factor", v))
        .transpose()?;

    Ok(RatingInputs {
        load,
        pinion_speed,
        kv,
        overload: factor("rating.overload_factor", &r.overload_factor)?,
        reliability_factor,
        temperature_factor: factor("rating.temperature_factor", &r.temperature_factor)?,
        surface_condition: factor(
            "rating.surface_condition_factor",
            &r.surface_condition_factor,
        )?,
        pinion_cycles,
        bending_low,
        bending_high,
        nitrided: r.pitting_nitrided.unwrap_or(false),
        i,
        elastic_coefficient: elastic,
        hardness_ratio_factor,
        load_distribution: LoadDistribution {
            crowned: r.crowned.unwrap_or(false),
            offset_ratio,
            enclosure,
            adjusted_at_assembly: r.adjusted_at_assembly.unwrap_or(false),
        },
        members,
        required_safety_factor,
    })
}

/// The top-level and `[rating]` entries of the file as written, for the report.
fn given_fields(text: &str) -> Vec<(String, String)> {
    let Ok(table) = text.parse::<toml::Table>() else {
        return Vec::new();
    };
    let mut out = Vec::new();
    fn walk(prefix: &str, t: &toml::Table, out: &mut Vec<(String, String)>) {
        for (k, v) in t {
            let key = if prefix.is_empty() {
                k.clone()
            } else {
                format!("{prefix}.{k}")
            };
            match v {
                toml::Value::Table(sub) => walk(&key, sub, out),
                _ => out.push((key, v.to_string())),
            }
        }
    }
    walk("", &table, &mut out);
    out
}

/// Whether a failed check makes the pair unusable (`Error`) or only breaks a rule of thumb
/// (`Warning`: the AGMA 917 teeth difference, the rack-generation undercut limit).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Severity {
    Error,
    Warning,
}

/// The JSON name, severity and meaning of a check.
pub fn check_info(kind: CheckKind) -> (&'static str, Severity, &'static str) {
    match kind {
        CheckKind::InvoluteInterferencePinion => (
            "involute_interference_pinion",
            Severity::Error,
            "the mate's tip stays off the pinion flank below its base circle (KHK); margin in units of rb2·tan α_op",
        ),
        CheckKind::InvoluteInterferenceGear => (
            "involute_interference_gear",
            Severity::Error,
            "the pinion tip stays off the gear flank below its base circle; margin in units of rb1·tan α_op",
        ),
        CheckKind::TrochoidInterference => (
            "trochoid_interference",
            Severity::Error,
            "no tip/trochoid interference while the pinion leaves the ring (KHK θ1·z1/z2 >= θ2); margin z1/|z2| - θ2/θ1",
        ),
        CheckKind::RingTipInsideBaseCircle => (
            "ring_tip_inside_base_circle",
            Severity::Error,
            "the ring tip circle lies outside its base circle; margin (|da2| - |db2|)/(2 m) in modules",
        ),
        CheckKind::TeethDifference => (
            "teeth_difference",
            Severity::Warning,
            "|z2| - z1 >= min_teeth_difference (AGMA 917-B97 rule of thumb); margin in teeth",
        ),
        CheckKind::ContactRatio => (
            "contact_ratio",
            Severity::Error,
            "transverse contact ratio >= 1; margin εα - 1",
        ),
        CheckKind::PinionUndercut => (
            "pinion_undercut",
            Severity::Warning,
            "rack-generated pinion without undercut, x1 >= 1 - z1 sin²α/2 (rule of thumb); margin in shift",
        ),
        CheckKind::Backlash => (
            "backlash",
            Severity::Error,
            "backlash not negative (teeth do not jam); margin jt/m in modules",
        ),
    }
}

/// Stresses, factors and safety factors of a rated pair; arrays are `[pinion, gear]`, SI.
#[derive(Debug, Clone, PartialEq)]
pub struct RatingResult {
    pub power: f64,
    pub pinion_torque: f64,
    pub pitch_line_velocity: f64,
    pub tangential_load: f64,
    pub kv: f64,
    /// Pitch-line velocity limit of the Kv curve, m/s (`None` for a given Kv).
    pub kv_velocity_limit: Option<f64>,
    pub km: f64,
    pub i: f64,
    pub cycles: [f64; 2],
    pub ks: [f64; 2],
    pub yn: [f64; 2],
    pub zn: [f64; 2],
    pub ch: [f64; 2],
    pub bending_stress: [f64; 2],
    pub contact_stress: [f64; 2],
    pub bending_safety: [f64; 2],
    pub contact_safety: [f64; 2],
    /// The face width at which every safety factor reaches the required one, m, when one falls
    /// short and a face width up to 40 in is enough ([`GearSetRating::required_face_width`]).
    pub face_width_for_required: Option<f64>,
    pub warnings: Vec<String>,
}

/// Everything computed for one gear file.
#[derive(Debug, Clone)]
pub struct GearReport {
    pub input: GearFile,
    pub pair: GearPair,
    pub checks: Vec<CheckReport>,
    /// `None` without a `[rating]` table; `Some(Err)` when the pair cannot be rated.
    pub rating: Option<Result<RatingResult, String>>,
}

impl GearReport {
    /// Why the pair cannot work, each with its remedy; empty when the pair works. The verdict
    /// (README.md, "Gear pair calculator"):
    ///
    /// * every blocking check passes: involute and trochoid interference, ring tip outside its
    ///   base circle, contact ratio >= 1, backlash >= 0 ([`check_info`]; the rules of thumb,
    ///   teeth difference and undercut, are [`warnings`](Self::warnings));
    /// * every geometry figure written is a finite number;
    /// * with `[rating]`: the rating is computed with every figure finite, and each member's
    ///   bending safety factor `SF` and pitting safety factor `SH` is at least
    ///   `required_safety_factor` (default 1). Both are compared directly, as the design
    ///   factors of the allowable-stress equations `σ_all = St YN / (SF KT KR)` and
    ///   `σc_all = Sc ZN CH / (SH KT KR)` (Shigley, Budynas & Nisbett, eqs. 14-17 and 14-18;
    ///   AGMA 2001-D04 clause 4), with `SF`, `SH` from Shigley eqs. 14-41 and 14-42.
    pub fn failures(&self) -> Vec<String> {
        let mut out: Vec<String> = self
            .checks
            .iter()
            .filter(|c| !c.passed && check_info(c.kind).1 == Severity::Error)
            .map(|c| format!("{}: {}", check_info(c.kind).0, remedy_text(c)))
            .collect();
        for (quantity, value) in self.geometry_figures() {
            if !value.is_finite() {
                out.push(format!(
                    "geometry: {quantity} = {value} is not a finite number; check module, teeth, profile_shift and center_distance"
                ));
            }
        }
        match &self.rating {
            None => {}
            Some(Err(e)) => out.push(format!("rating: {e}")),
            Some(Ok(r)) => out.extend(self.safety_failures(r)),
        }
        out
    }

    /// The safety factors below `required_safety_factor`, each with the pair's remedy.
    fn safety_failures(&self, r: &RatingResult) -> Vec<String> {
        let Some(inputs) = &self.input.rating else {
            return Vec::new();
        };
        let n = inputs.required_safety_factor;
        let members = ["pinion", "gear"];
        let mut short = Vec::new();
        for (k, member) in members.iter().enumerate() {
            if r.bending_safety[k] < n {
                short.push(format!(
                    "bending safety factor SF of the {member} = {:.4} < required_safety_factor {n} (Shigley eq. 14-41)",
                    r.bending_safety[k]
                ));
            }
        }
        for (k, member) in members.iter().enumerate() {
            if r.contact_safety[k] < n {
                short.push(format!(
                    "pitting safety factor SH of the {member} = {:.4} < required_safety_factor {n} (Shigley eq. 14-42)",
                    r.contact_safety[k]
                ));
            }
        }
        if short.is_empty() {
            return short;
        }
        let remedy = self.safety_remedy(r, n);
        short
            .into_iter()
            .map(|s| format!("{s}; remedy: {remedy}"))
            .collect()
    }

    /// The remedy of a pair whose safety factors fall short of `n`: the largest load, from the
    /// stresses' dependence on the tangential load at a fixed speed (bending `σ ∝ Wt`, AGMA
    /// 2001-D04 eq. 15; contact `σc ∝ √Wt`, eq. 1; `Kv` depends on the speed, `Km`, `Ks` on the
    /// face width), so the load may be scaled by `min(SF/n, (SH/n)²)`; the face width at which
    /// every factor reaches `n`; a larger module, a stronger material.
    fn safety_remedy(&self, r: &RatingResult, n: f64) -> String {
        let f = (0..2)
            .map(|k| (r.bending_safety[k] / n).min((r.contact_safety[k] / n).powi(2)))
            .fold(f64::INFINITY, f64::min);
        let load = match self.input.rating.as_ref().map(|i| i.load) {
            Some(Load::Torque(t)) => format!("rating.torque at most {} N*m", sig4(t * f, false)),
            _ => format!("rating.power at most {} kW", sig4(r.power * f / 1e3, false)),
        };
        let width = match r.face_width_for_required {
            Some(b) => format!("face_width at least {} mm", sig4(b * 1e3, true)),
            None => "no face width up to 40 in is enough".to_string(),
        };
        format!(
            "{load}, or {width}, or a larger module, or a stronger material (larger allowable stresses St, Sc)"
        )
    }

    /// Rules of thumb the pair breaks (failed `Warning` checks: teeth difference, undercut),
    /// with their remedies, and the rating's warnings.
    pub fn warnings(&self) -> Vec<String> {
        let mut out: Vec<String> = self
            .checks
            .iter()
            .filter(|c| !c.passed && check_info(c.kind).1 == Severity::Warning)
            .map(|c| format!("{}: {}", check_info(c.kind).0, remedy_text(c)))
            .collect();
        if let Some(Ok(r)) = &self.rating {
            out.extend(r.warnings.iter().map(|w| format!("rating: {w}")));
        }
        out
    }

    /// Every geometry figure written to `gear.json` and `report.md`, with its name.
    fn geometry_figures(&self) -> Vec<(String, f64)> {
        let p = &self.pair;
        let s = &p.spec;
        let mut v: Vec<(String, f64)> = vec![
            ("module".into(), s.module),
            ("pressure angle".into(), s.pressure_angle),
            ("profile shift x1".into(), s.pinion.shift),
            ("profile shift x2".into(), s.gear.shift),
            ("ratio".into(), p.ratio),
            ("working pressure angle".into(), p.working_pressure_angle),
            (
                "operating pressure angle".into(),
                p.operating_pressure_angle,
            ),
            ("working centre distance".into(), p.working_centre_distance),
            ("centre distance".into(), p.centre_distance),
            ("base pitch".into(), p.base_pitch),
            ("path of contact".into(), p.path_of_contact),
            ("contact ratio".into(), p.contact_ratio),
            (
                "circumferential backlash".into(),
                p.backlash_circumferential,
            ),
            ("normal backlash".into(), p.backlash_normal),
            ("gear addendum".into(), p.gear_addendum()),
            (
                "largest gear addendum without interference".into(),
                p.max_gear_addendum_without_interference(),
            ),
        ];
        if p.internal {
            v.push(("trochoid ratio".into(), p.trochoid_ratio()));
        }
        for (member, d) in [("pinion", &p.pinion), ("gear", &p.gear)] {
            for (name, x) in [
                ("reference diameter", d.reference),
                ("base diameter", d.base),
                ("tip diameter", d.tip),
                ("root diameter", d.root),
                ("working diameter", d.working),
            ] {
                v.push((format!("{member} {name}"), x));
            }
        }
        for c in &self.checks {
            v.push((format!("margin of {}", check_info(c.kind).0), c.margin));
        }
        v
    }
}

/// `x` to 4 significant digits, rounded up (`up`) or down, so that a remedy's bound is safe.
fn sig4(x: f64, up: bool) -> String {
    if !(x.is_finite() && x > 0.0) {
        return format!("{x}");
    }
    let e = x.log10().floor() as i32;
    let scale = 10f64.powi(e - 3);
    let y = if up {
        (x / scale * (1.0 - 1e-12)).ceil() * scale
    } else {
        (x / scale * (1.0 + 1e-12)).floor() * scale
    };
    let decimals = (3 - e).max(0) as usize;
    format!("{y:.decimals$}")
}

fn remedy_text(c: &CheckReport) -> String {
    let mut s = format!("margin {:.5}", c.margin);
    if c.passed {
        s.push_str(", ok");
    } else {
        s.push_str(", FAILED");
        if !c.remedies.is_empty() {
            s.push_str("; remedy: ");
            s.push_str(
                &c.remedies
                    .iter()
                    .map(|r| r.to_string())
                    .collect::<Vec<_>>()
                    .join(", or "),
            );
        }
    }
    s
}

/// Computes the geometry, the checks and the rating of a validated gear file.
pub fn evaluate(input: &GearFile) -> Result<GearReport, GearFileError> {
    let pair = GearPair::new(input.spec).map_err(|e| GearFileError::Invalid {
        file: input.file.clone(),
        name: input.name.clone(),
        field: "teeth".into(),
        value: format!("{:?}", [input.spec.pinion.teeth, input.spec.gear.teeth]),
        rule: e.to_string(),
    })?;
    let checks = pair.checks();
    let rating = match (&input.rating, input.face_width) {
        (Some(r), Some(b)) => Some(rate(&pair, r, b)),
        _ => None,
    };
    Ok(GearReport {
        input: input.clone(),
        pair,
        checks,
        rating,
    })
}

/// Rates the pair; an error names the quantity that could not be computed or is not finite.
fn rate(pair: &GearPair, r: &RatingInputs, face_width: f64) -> Result<RatingResult, String> {
    let mut result = rate_figures(pair, r, face_width).map_err(|e| e.to_string())?;
    let figures = rating_figures(&result);
    if let Some((quantity, value, unit)) = figures.iter().find(|(_, v, _)| !v.is_finite()) {
        return Err(format!(
            "{quantity} = {value} {unit} is not a finite number (pinion torque {:e} N·m at pinion speed {:e} rad/s): check rating.power or rating.torque, rating.pinion_speed and the factors",
            result.pinion_torque, r.pinion_speed
        ));
    }
    let n = r.required_safety_factor;
    if result
        .bending_safety
        .iter()
        .chain(&result.contact_safety)
        .any(|&x| x < n)
    {
        result.face_width_for_required = rating_set(pair, r, &result)
            .required_face_width(result.tangential_load, result.kv, n, n, 1)
            .ok()
            .map(|w| w.governing);
    }
    Ok(result)
}

/// Every figure of a rating written to `gear.json` and `report.md`, in the order they are
/// computed: (quantity, value, unit).
fn rating_figures(r: &RatingResult) -> Vec<(String, f64, &'static str)> {
    let mut v: Vec<(String, f64, &'static str)> = vec![
        ("pitch-line velocity".into(), r.pitch_line_velocity, "m/s"),
        ("power".into(), r.power, "W"),
        ("pinion torque".into(), r.pinion_torque, "N·m"),
        ("tangential load Wt".into(), r.tangential_load, "N"),
        ("dynamic factor Kv".into(), r.kv, ""),
        ("load distribution factor Km".into(), r.km, ""),
        ("pitting geometry factor I".into(), r.i, ""),
    ];
    if let Some(x) = r.kv_velocity_limit {
        v.push(("velocity limit of Kv".into(), x, "m/s"));
    }
    let per_member: [(&str, &[f64; 2], &'static str); 9] = [
        ("load cycles", &r.cycles, ""),
        ("size factor Ks", &r.ks, ""),
        ("stress-cycle factor YN", &r.yn, ""),
        ("stress-cycle factor ZN", &r.zn, ""),
        ("hardness-ratio factor CH", &r.ch, ""),
        ("bending stress", &r.bending_stress, "Pa"),
        ("contact stress", &r.contact_stress, "Pa"),
        ("bending safety factor SF", &r.bending_safety, ""),
        ("pitting safety factor SH", &r.contact_safety, ""),
    ];
    for (name, a, unit) in per_member {
        for (k, member) in ["pinion", "gear"].iter().enumerate() {
            v.push((format!("{name} of the {member}"), a[k], unit));
        }
    }
    v
}

/// The AGMA 2001-D04 rating set of the pair (the inputs of [`GearSetRating::rate`]).
fn gear_set(
    pair: &GearPair,
    r: &RatingInputs,
    i: f64,
    yn: [f64; 2],
    zn: [f64; 2],
    ch: [f64; 2],
) -> GearSetRating {
    let d1 = pair.pinion.working;
    let m = pair.spec.module;
    let member = |k: usize| MemberData {
        j: r.members[k].j,
        rim: r.members[k].rim_factor,
        bending_allowable: r.members[k].bending_allowable,
        contact_allowable: r.members[k].contact_allowable,
        yn: yn[k],
        zn: zn[k],
        ch: ch[k],
    };
    let size = match (r.members[0].lewis_y, r.members[1].lewis_y) {
        (Some(y1), Some(y2)) => SizeFactor::Shigley { lewis_y: [y1, y2] },
        _ => SizeFactor::Given([
            r.members[0].size_factor.unwrap_or(1.0),
            r.members[1].size_factor.unwrap_or(1.0),
        ]),
    };
    GearSetRating {
        module: m,
        pinion_diameter: d1,
        overload: r.overload,
        load_distribution: r.load_distribution,
        size,
        surface_condition: r.surface_condition,
        geometry_i: i,
        elastic_coefficient: r.elastic_coefficient,
        temperature: r.temperature_factor,
        reliability: r.reliability_factor,
        pinion: member(0),
        gear: member(1),
    }
}

/// [`gear_set`] of a computed rating.
fn rating_set(pair: &GearPair, r: &RatingInputs, result: &RatingResult) -> GearSetRating {
    gear_set(pair, r, result.i, result.yn, result.zn, result.ch)
}

fn rate_figures(
    pair: &GearPair,
    r: &RatingInputs,
    face_width: f64,
) -> Result<RatingResult, GearError> {
    let mut warnings = Vec::new();
    let u = pair.ratio;
    if u < 1.0 {
        warnings.push(
            "gear 1 is the larger member; AGMA's pinion is the smaller one, so its diameter and CH apply to gear 2 (not applied here: gear 1 is rated as the pinion)".to_string(),
        );
    }
    let d1 = pair.pinion.working;
    let v = r.pinion_speed * d1 / 2.0;
    let (power, torque) = match r.load {
        Load::Power(p) => (p, p / r.pinion_speed),
        Load::Torque(t) => (t * r.pinion_speed, t),
    };
    let wt = torque / (d1 / 2.0);
    let (kv, kv_limit) = match r.kv {
        KvInput::Given(k) => (k, None),
        KvInput::Quality(q) => {
            let d = dynamic_factor(q, v)?;
            if !d.within_limit {
                warnings.push(format!(
                    "pitch-line velocity {:.3} m/s exceeds the Kv curve's limit {:.3} m/s: Kv is extrapolated",
                    v, d.v_max
                ));
            }
            (d.kv, Some(d.v_max))
        }
    };
    let i = match r.i {
        IInput::Given(i) => i,
        IInput::Form(f) => pitting_geometry_factor(pair, f)?,
    };
    let cycles = [r.pinion_cycles, r.pinion_cycles / u];
    let yn = [
        bending_cycle_factor(cycles[0], r.bending_low, r.bending_high)?,
        bending_cycle_factor(cycles[1], r.bending_low, r.bending_high)?,
    ];
    let zn = [
        pitting_cycle_factor(cycles[0], r.nitrided)?,
        pitting_cycle_factor(cycles[1], r.nitrided)?,
    ];
    let ch_gear = match (
        r.hardness_ratio_factor,
        r.members[0].hardness,
        r.members[1].hardness,
    ) {
        (Some(ch), _, _) => ch,
        (None, Some(hp), Some(hg)) if u >= 1.0 => hardness_ratio_factor(
            HardnessPairing::ThroughHardened {
                pinion_hb: hp,
                gear_hb: hg,
            },
            u,
        )?,
        _ => 1.0,
    };
    let ch = [1.0, ch_gear];
    let set = gear_set(pair, r, i, yn, zn, ch);
    let km = r.load_distribution.factor(face_width, d1)?;
    if !km.within_validity {
        warnings.push(format!(
            "face width / pinion diameter = {:.3} > 2: outside the empirical Km method",
            face_width / d1
        ));
    }
    let out = set.rate(wt, kv, face_width)?;
    Ok(RatingResult {
        power,
        pinion_torque: torque,
        pitch_line_velocity: v,
        tangential_load: wt,
        kv,
        kv_velocity_limit: kv_limit,
        km: out.km,
        i,
        cycles,
        ks: out.ks,
        yn,
        zn,
        ch,
        bending_stress: out.bending_stress,
        contact_stress: out.contact_stress,
        bending_safety: out.bending_safety,
        contact_safety: out.contact_safety,
        face_width_for_required: None,
        warnings,
    })
}

/// Text for a Markdown table cell: `|` escaped.
fn cell(s: &str) -> String {
    s.replace('|', "\\|")
}

fn diameters_json(d: &cardan_gears::Diameters) -> Value {
    json!({
        "reference_diameter": d.reference,
        "base_diameter": d.base,
        "tip_diameter": d.tip,
        "root_diameter": d.root,
        "working_diameter": d.working,
    })
}

impl GearReport {
    /// `gear.json` (see README.md, "Gear pair calculator"): SI numbers (m, N, Pa, W, rad/s),
    /// angles in degrees in fields named `*_deg`.
    pub fn to_json(&self) -> Value {
        let p = &self.pair;
        let s = &p.spec;
        let checks: Vec<Value> = self
            .checks
            .iter()
            .map(|c| {
                let (name, severity, meaning) = check_info(c.kind);
                json!({
                    "check": name,
                    "severity": match severity { Severity::Error => "error", Severity::Warning => "warning" },
                    "passed": c.passed,
                    "margin": c.margin,
                    "rule": meaning,
                    "remedies": c.remedies.iter().map(|r| r.to_string()).collect::<Vec<_>>(),
                })
            })
            .collect();
        let warnings = self.warnings();
        let rating = match &self.rating {
            None => Value::Null,
            Some(Err(e)) => json!({ "error": e }),
            Some(Ok(r)) => {
                let inputs = self.input.rating.as_ref().expect("rated pairs have inputs");
                let member = |k: usize| {
                    let mi = &inputs.members[k];
                    json!({
                        "cycles": r.cycles[k],
                        "j": mi.j,
                        "kb": mi.rim_factor,
                        "ks": r.ks[k],
                        "yn": r.yn[k],
                        "zn": r.zn[k],
                        "ch": r.ch[k],
                        "bending_allowable": mi.bending_allowable,
                        "contact_allowable": mi.contact_allowable,
                        "bending_stress": r.bending_stress[k],
                        "contact_stress": r.contact_stress[k],
                        "bending_safety_factor": r.bending_safety[k],
                        "contact_safety_factor": r.contact_safety[k],
                    })
                };
                json!({
                    "power": r.power,
                    "pinion_torque": r.pinion_torque,
                    "pinion_speed": inputs.pinion_speed,
                    "pitch_line_velocity": r.pitch_line_velocity,
                    "tangential_load": r.tangential_load,
                    "face_width": self.input.face_width,
                    "kv": r.kv,
                    "kv_velocity_limit": r.kv_velocity_limit,
                    "ko": inputs.overload,
                    "km": r.km,
                    "i": r.i,
                    "cp": inputs.elastic_coefficient,
                    "kt": inputs.temperature_factor,
                    "kr": inputs.reliability_factor,
                    "cf": inputs.surface_condition,
                    "required_safety_factor": inputs.required_safety_factor,
                    "pinion": member(0),
                    "gear": member(1),
                    "warnings": r.warnings,
                })
            }
        };
        let mut inputs = Map::new();
        for (k, v) in &self.input.given {
            inputs.insert(k.clone(), json!(v));
        }
        json!({
            "schema_version": SCHEMA_VERSION,
            "name": self.input.name,
            "file": self.input.file.display().to_string(),
            "pair": if p.internal { "internal" } else { "external" },
            "passed": self.failures().is_empty(),
            "failures": self.failures(),
            "warnings": warnings,
            "inputs": inputs,
            "module": s.module,
            "cardan_crank_length": self.input.cardan_crank_length,
            "pressure_angle_deg": s.pressure_angle.to_degrees(),
            "teeth": [s.pinion.teeth, s.gear.teeth],
            "profile_shift": [s.pinion.shift, s.gear.shift],
            "ratio": p.ratio,
            "working_pressure_angle_deg": p.working_pressure_angle.to_degrees(),
            "operating_pressure_angle_deg": p.operating_pressure_angle.to_degrees(),
            "working_center_distance": p.working_centre_distance,
            "center_distance": p.centre_distance,
            "base_pitch": p.base_pitch,
            "path_of_contact": p.path_of_contact,
            "contact_ratio": p.contact_ratio,
            "backlash_circumferential": p.backlash_circumferential,
            "backlash_normal": p.backlash_normal,
            "gear_addendum": p.gear_addendum(),
            "max_gear_addendum_without_interference": p.max_gear_addendum_without_interference(),
            "trochoid_ratio": if p.internal { json!(p.trochoid_ratio()) } else { Value::Null },
            "pinion": diameters_json(&p.pinion),
            "gear": diameters_json(&p.gear),
            "face_width": self.input.face_width,
            "checks": checks,
            "rating": rating,
        })
    }

    /// `report.md`: inputs with units, geometry, checks with margins and remedies, rating.
    pub fn to_markdown(&self) -> String {
        let p = &self.pair;
        let s = &p.spec;
        let mm = |x: f64| format!("{:.4}", x * 1e3);
        let mut o = String::new();
        let _ = writeln!(o, "# Gear pair `{}`\n", self.input.name);
        let _ = writeln!(
            o,
            "{} spur pair {}/{} from `{}`.\n",
            if p.internal { "Internal" } else { "External" },
            s.pinion.teeth,
            s.gear.teeth,
            self.input.file.display()
        );
        let failures = self.failures();
        if failures.is_empty() {
            let rated = match &self.input.rating {
                Some(r) => format!(
                    ", every safety factor at least required_safety_factor {}",
                    r.required_safety_factor
                ),
                None => ", geometry only".to_string(),
            };
            let _ = writeln!(
                o,
                "**Verdict: the pair works** (every blocking check passed{rated}).\n"
            );
        } else {
            let _ = writeln!(o, "**Verdict: the pair cannot work as given.**\n");
            for f in &failures {
                let _ = writeln!(o, "- {f}");
            }
            o.push('\n');
        }
        let warnings = self.warnings();
        if !warnings.is_empty() {
            let _ = writeln!(
                o,
                "Warnings (rules of thumb and the rating's caveats; they do not fail the pair):\n"
            );
            for w in &warnings {
                let _ = writeln!(o, "- {w}");
            }
            o.push('\n');
        }

        let _ = writeln!(o, "## Inputs\n\n| field | value as given |\n|---|---|");
        for (k, v) in &self.input.given {
            let _ = writeln!(o, "| `{k}` | `{}` |", cell(v));
        }
        let _ = writeln!(
            o,
            "\nBare numbers are SI (lengths m, speeds rad/s, power W, torque N·m, stress Pa), except angles (degrees).\n"
        );

        let _ = writeln!(o, "## Geometry (ISO 21771)\n");
        let _ = writeln!(o, "| quantity | value | unit |\n|---|---:|---|");
        let mut row = |q: &str, v: String, u: &str| {
            let _ = writeln!(o, "| {} | {v} | {u} |", cell(q));
        };
        row("module m", mm(s.module), "mm");
        if let Some(e) = self.input.cardan_crank_length {
            row("cardan crank length e (m = 2e/z1, A9.1.37)", mm(e), "mm");
        }
        row(
            "reference pressure angle α",
            format!("{:.4}", s.pressure_angle.to_degrees()),
            "deg",
        );
        row(
            "teeth z1 / z2",
            format!("{} / {}", s.pinion.teeth, s.gear.teeth),
            "-",
        );
        row(
            "profile shift x1 / x2 (ISO)",
            format!("{:.4} / {:.4}", s.pinion.shift, s.gear.shift),
            "-",
        );
        row("ratio u = |z2|/z1", format!("{:.4}", p.ratio), "-");
        row(
            "working pressure angle αw",
            format!("{:.4}", p.working_pressure_angle.to_degrees()),
            "deg",
        );
        row(
            "operating pressure angle",
            format!("{:.4}", p.operating_pressure_angle.to_degrees()),
            "deg",
        );
        row(
            "zero-backlash centre distance aw",
            mm(p.working_centre_distance),
            "mm",
        );
        row("centre distance a", mm(p.centre_distance), "mm");
        row("base pitch pb", mm(p.base_pitch), "mm");
        row("path of contact gα", mm(p.path_of_contact), "mm");
        row("contact ratio εα", format!("{:.4}", p.contact_ratio), "-");
        row(
            "backlash jt / jn",
            format!(
                "{} / {}",
                mm(p.backlash_circumferential),
                mm(p.backlash_normal)
            ),
            "mm",
        );
        row("gear addendum", mm(p.gear_addendum()), "mm");
        row(
            "largest gear addendum without involute interference",
            mm(p.max_gear_addendum_without_interference()),
            "mm",
        );
        if let Some(b) = self.input.face_width {
            row("face width b", mm(b), "mm");
        }
        let _ = writeln!(o, "\n| diameter [mm] | pinion | gear |\n|---|---:|---:|");
        for (name, f) in [
            (
                "reference d",
                (|d: &cardan_gears::Diameters| d.reference) as fn(&cardan_gears::Diameters) -> f64,
            ),
            ("base db", |d| d.base),
            ("tip da", |d| d.tip),
            ("root df", |d| d.root),
            ("working dw", |d| d.working),
        ] {
            let _ = writeln!(o, "| {name} | {} | {} |", mm(f(&p.pinion)), mm(f(&p.gear)));
        }

        let _ = writeln!(
            o,
            "\n## Checks\n\n| check | kind | margin | result | rule | remedy |\n|---|---|---:|---|---|---|"
        );
        for c in &self.checks {
            let (name, severity, meaning) = check_info(c.kind);
            let _ = writeln!(
                o,
                "| {name} | {} | {:.5} | {} | {} | {} |",
                match severity {
                    Severity::Error => "blocking",
                    Severity::Warning => "rule of thumb",
                },
                c.margin,
                if c.passed { "ok" } else { "**FAILED**" },
                cell(meaning),
                cell(
                    &c.remedies
                        .iter()
                        .map(|r| r.to_string())
                        .collect::<Vec<_>>()
                        .join("; or ")
                )
            );
        }

        match &self.rating {
            None => {
                let _ = writeln!(o, "\n## Rating\n\nNo `[rating]` table: geometry only.");
            }
            Some(Err(e)) => {
                let _ = writeln!(o, "\n## Rating\n\nThe pair could not be rated: {e}");
            }
            Some(Ok(r)) => {
                let inputs = self.input.rating.as_ref().expect("rated pairs have inputs");
                let _ = writeln!(o, "\n## Rating (AGMA 2001-D04)\n");
                let _ = writeln!(o, "| quantity | value | unit |\n|---|---:|---|");
                let mut row = |q: &str, v: String, u: &str| {
                    let _ = writeln!(o, "| {q} | {v} | {u} |");
                };
                row("power", format!("{:.1}", r.power), "W");
                row("pinion torque", format!("{:.3}", r.pinion_torque), "N·m");
                row(
                    "pinion speed",
                    format!("{:.2}", inputs.pinion_speed * 30.0 / PI),
                    "rpm",
                );
                row(
                    "pitch-line velocity",
                    format!("{:.4}", r.pitch_line_velocity),
                    "m/s",
                );
                row(
                    "tangential load Wt",
                    format!("{:.2}", r.tangential_load),
                    "N",
                );
                row("dynamic factor Kv", format!("{:.4}", r.kv), "-");
                row("overload factor Ko", format!("{:.4}", inputs.overload), "-");
                row("load distribution factor Km", format!("{:.4}", r.km), "-");
                row("pitting geometry factor I", format!("{:.4}", r.i), "-");
                row(
                    "elastic coefficient Cp",
                    format!("{:.2}", inputs.elastic_coefficient / 1e3),
                    "√MPa",
                );
                row(
                    "temperature factor KT",
                    format!("{:.4}", inputs.temperature_factor),
                    "-",
                );
                row(
                    "reliability factor KR",
                    format!("{:.4}", inputs.reliability_factor),
                    "-",
                );
                let _ = writeln!(
                    o,
                    "\n| per member | pinion | gear | unit |\n|---|---:|---:|---|"
                );
                let mi = &inputs.members;
                let mut pair_row = |q: &str, a: [f64; 2], fmt: &dyn Fn(f64) -> String, u: &str| {
                    let _ = writeln!(o, "| {q} | {} | {} | {u} |", fmt(a[0]), fmt(a[1]));
                };
                let f4 = |x: f64| format!("{x:.4}");
                let f3 = |x: f64| format!("{x:.3}");
                let mpa = |x: f64| format!("{:.2}", x / 1e6);
                let cyc = |x: f64| format!("{x:.4e}");
                pair_row("load cycles", r.cycles, &cyc, "-");
                pair_row("bending geometry factor J", [mi[0].j, mi[1].j], &f4, "-");
                pair_row(
                    "rim thickness factor KB",
                    [mi[0].rim_factor, mi[1].rim_factor],
                    &f4,
                    "-",
                );
                pair_row("size factor Ks", r.ks, &f4, "-");
                pair_row("stress-cycle factor YN", r.yn, &f4, "-");
                pair_row("stress-cycle factor ZN", r.zn, &f4, "-");
                pair_row("hardness-ratio factor CH", r.ch, &f4, "-");
                pair_row(
                    "allowable bending stress St",
                    [mi[0].bending_allowable, mi[1].bending_allowable],
                    &mpa,
                    "MPa",
                );
                pair_row(
                    "allowable contact stress Sc",
                    [mi[0].contact_allowable, mi[1].contact_allowable],
                    &mpa,
                    "MPa",
                );
                pair_row("bending stress σ", r.bending_stress, &mpa, "MPa");
                pair_row("contact stress σc", r.contact_stress, &mpa, "MPa");
                pair_row("bending safety factor SF", r.bending_safety, &f3, "-");
                pair_row(
                    "pitting safety factor SH (stress ratio; compare SH² with SF)",
                    r.contact_safety,
                    &f3,
                    "-",
                );
                let _ = writeln!(
                    o,
                    "\nRequired safety factor (`required_safety_factor`, both SF and SH): {}",
                    inputs.required_safety_factor
                );
            }
        }
        o
    }
}

/// What [`run`] wrote.
#[derive(Debug)]
pub struct GearRun {
    /// `DIR/<name>`.
    pub dir: PathBuf,
    pub report: GearReport,
}

/// Reads, validates and rates `file` and writes `out/<name>/gear.json` and `report.md`, the
/// folder replaced as a whole. A pair that cannot work is still written; see
/// [`GearReport::failures`].
pub fn run(file: &Path, out: &Path) -> Result<GearRun, GearFileError> {
    let input = load(file)?;
    let report = evaluate(&input)?;
    let dir = out.join(&input.name);
    let cannot_write = |e: anyhow::Error| GearFileError::Write {
        file: input.file.clone(),
        name: input.name.clone(),
        dir: dir.clone(),
        message: format!("{e:#}"),
    };
    let tmp = temporary_dir(&dir).map_err(cannot_write)?;
    let written = (|| -> anyhow::Result<()> {
        let mut json = serde_json::to_string_pretty(&report.to_json())?;
        json.push('\n');
        write_file(&tmp.join("gear.json"), json.as_bytes())?;
        write_file(&tmp.join("report.md"), report.to_markdown().as_bytes())?;
        replace_dir(&tmp, &dir)
    })();
    if let Err(e) = written {
        let _ = std::fs::remove_dir_all(&tmp);
        return Err(cannot_write(e));
    }
    Ok(GearRun { dir, report })
}
