//! Gear files: one spur pair (external or internal, any ratio) in a TOML file → the ISO 21771
//! geometry, the interference checks with their margins and remedies and, when a `[rating]`
//! table is given, the AGMA 2001-D04 stresses and safety factors → `DIR/<name>/gear.json` and
//! `DIR/<name>/report.md`. The physics is `cardan-gears`'; this module reads, validates and
//! writes (see docs/gear-calculator.md).
//!
//! Values take units as case files do, from the one table of [`cardan_case::units`]: a bare number
//! is in the field's SI unit (lengths m, angles deg, speeds rad/s, power W, torque N·m, stress
//! Pa), a string is "NUMBER UNIT" (inches, hp, lbf·in, psi for the US-unit textbook examples).
//!
//! Bad input is a [`GearFileError`] naming the file, the pair, the field, its value and the
//! rule, never a panic. A pair that cannot work (interference, contact ratio below 1, jammed
//! teeth, a safety factor below `required_safety_factor`, a figure that is not finite) is not
//! an input error: it is written, with the failures and their remedies, and
//! [`GearReport::failures`] lists it so the command can exit 1; [`GearReport::warnings`] lists
//! the rules of thumb it breaks.

use cardan_gears::{BendingHighCycle, BendingLowCycle, IForm, LoadDistribution, PairSpec, Quality};
use cardan_report::files::{replace_dir, temporary_dir, write_file};
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

/// Version of the layout of `gear.json`; raised when a name or the shape changes.
mod input;
mod rating;
mod report;
mod table;
pub use input::parse;
pub use rating::{check_info, evaluate, GearReport, RatingResult, Severity};
pub use table::gear_file_schema;

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
