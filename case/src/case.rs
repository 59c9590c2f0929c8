//! Case files: TOML in, a validated [`Case`] out. Every rule a value breaks is reported with
//! the file, the case, the field, the rule and the value. Mechanisms are named from the
//! registry of `cardan-mechanism`; each builds itself from the shared geometry, the mass fields
//! and its own table (`[cardan_gear]`, ...).

use crate::gas::GasCase;
use crate::units::{is_folder_name, to_si, Dimension};
use cardan_dynamics::{Friction, GearRatings, GearSpec, LossBudget};
use cardan_mechanism::{
    CrankMotion, MachineGeometry, MassInputs, MassRules, Material, Mechanism, OptionKind,
    OptionValue, Options,
};
use rayon::prelude::*;
use serde::Deserialize;
use std::path::{Path, PathBuf};
use std::sync::Arc;

/// Why a case file could not become a case.
#[derive(Debug, thiserror::Error)]
pub enum CaseError {
    #[error("{file}: cannot read: {source}")]
    Io {
        file: PathBuf,
        source: std::io::Error,
    },
    /// TOML syntax, a missing field, an unknown key or a value of the wrong type; the message
    /// is the TOML reader's, with the line and column.
    #[error("{file}: {message}")]
    Syntax { file: PathBuf, message: String },
    /// A field of the typed schema that did not read: its path and what is wrong with it.
    #[error("{file}: case \"{case}\": {error}")]
    Field {
        file: PathBuf,
        case: String,
        error: crate::schema::FieldError,
    },
    #[error("{file}: case \"{case}\": {field} = {value}: {rule}")]
    Invalid {
        file: PathBuf,
        case: String,
        field: String,
        value: String,
        rule: String,
    },
}

/// Pump or engine: what the gas does (used by the gas models).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Machine {
    Pump,
    Engine,
}

impl Machine {
    pub fn name(self) -> &'static str {
        match self {
            Machine::Pump => "pump",
            Machine::Engine => "engine",
        }
    }
}

/// What a case writes besides `summary.json`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct OutputOptions {
    /// Write `<mechanism>.csv`, one row per step.
    pub csv: bool,
    /// Write `<mechanism>.npy` (binary, column after column) and `<mechanism>.columns.json`.
    pub npy: bool,
    /// Write every n-th step (and the last).
    pub decimation: usize,
    /// Significant digits of the CSV numbers; `None`: the shortest text that reads back to
    /// the same number.
    pub significant_digits: Option<usize>,
}

impl Default for OutputOptions {
    fn default() -> Self {
        Self {
            csv: true,
            npy: false,
            decimation: 1,
            significant_digits: None,
        }
    }
}

/// A validated case.
#[derive(Debug, Clone)]
pub struct Case {
    pub file: PathBuf,
    pub name: String,
    pub machine: Machine,
    pub geometry: MachineGeometry,
    /// Pistons sharing one cylinder: 1, or 2 for the opposed-piston layout (two identical
    /// crank trains, no cylinder head, Nunes 2017). Without a crank phase the trains mirror
    /// each other: the case runs one, the other carries the same loads.
    pub pistons: u32,
    /// Lead of the second crank train's crank over the first's, rad (opposed pistons only; 0:
    /// the two trains mirror each other and one is run). With a lead both trains run, on one
    /// chamber ([`cardan_gas::Cylinder::with_phased_chamber`]).
    pub crank_phase: f64,
    pub motion: CrankMotion,
    /// Crank angle at the end of the run, rad.
    pub end_angle: f64,
    /// Number of crank-angle intervals; the run has steps + 1 points.
    pub steps: usize,
    pub mechanisms: Vec<Arc<dyn Mechanism>>,
    /// The gas loading the pistons; without it the run has inertial loads only.
    pub gas: Option<GasCase>,
    /// The loss models; without them the run has no losses.
    pub friction: Option<Friction>,
    /// The gear pair and rating data of every gear mesh; without it no mesh is rated.
    pub gear: Option<GearSpec>,
    pub output: OutputOptions,
    /// The sweep this case is a point of (its results go to `out/<sweep>/<case>/`), and the
    /// value of each swept field (dotted path, value as written).
    pub sweep: Option<(String, Vec<(String, String)>)>,
}

#[derive(Deserialize)]
struct RawCase {
    name: String,
    machine: String,
    mechanisms: Vec<String>,
    geometry: RawGeometry,
    motion: RawMotion,
    masses: Option<toml::Table>,
    gas: Option<toml::Table>,
    friction: Option<toml::Table>,
    gear: Option<toml::Table>,
    output: Option<RawOutput>,
    /// The mechanisms' own tables, checked against the registry.
    #[serde(flatten)]
    rest: toml::Table,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawGeometry {
    crank_length: toml::Value,
    rod_length: toml::Value,
    bore: toml::Value,
    pin_offset: Option<toml::Value>,
    opposed_pistons: Option<bool>,
    crank_phase: Option<toml::Value>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawMotion {
    start_angle: toml::Value,
    end_angle: toml::Value,
    initial_speed: toml::Value,
    angular_acceleration: toml::Value,
    steps: i64,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawOutput {
    csv: Option<bool>,
    npy: Option<bool>,
    decimation: Option<i64>,
    significant_digits: Option<i64>,
}

/// Largest accepted number of steps.
pub const MAX_STEPS: i64 = 100_000_000;

/// The mass fields of `[masses]` and `[masses.<mechanism>]`, with their dimensions.
const MASS_FIELDS: [(&str, Dimension); 6] = [
    ("crankshaft_inertia", Dimension::Inertia),
    ("wheel_inertia", Dimension::Inertia),
    ("rod_mass", Dimension::Mass),
    ("rod_inertia", Dimension::Inertia),
    ("rod_cg", Dimension::Length),
    ("piston_mass", Dimension::Mass),
];

/// Reads and validates one case file.
pub fn load(file: &Path) -> Result<Case, CaseError> {
    let text = std::fs::read_to_string(file).map_err(|source| CaseError::Io {
        file: file.into(),
        source,
    })?;
    parse(file, &text)
}

/// Reads one case file: one case, or every point of its `[sweep]` (see [`crate::sweep`]).
pub fn load_file(file: &Path) -> Result<Vec<Case>, CaseError> {
    let text = std::fs::read_to_string(file).map_err(|source| CaseError::Io {
        file: file.into(),
        source,
    })?;
    let syntax = |e: &dyn std::fmt::Display| CaseError::Syntax {
        file: file.into(),
        message: e.to_string().trim_end().to_string(),
    };
    let table: toml::Table = toml::from_str(&text).map_err(|e| syntax(&e))?;
    match crate::sweep::expand(file, table)? {
        None => Ok(vec![parse(file, &text)?]),
        Some((sweep, points)) => {
            // Each point's table read as it is (written out as TOML text and parsed again, it
            // took most of the time of reading a sweep of 10 000 points), the points on every
            // thread, the first failure in the points' order reported.
            let cases: Vec<Result<Case, CaseError>> = points
                .into_par_iter()
                .map(|p| {
                    check_form(file, &p.table)?;
                    let raw: RawCase = toml::Value::Table(p.table)
                        .try_into()
                        .map_err(|e| syntax(&format!("sweep point \"{}\": {e}", p.name)))?;
                    let mut case = validate(file, raw)?;
                    case.sweep = Some((sweep.clone(), p.values));
                    Ok(case)
                })
                .collect();
            cases.into_iter().collect()
        }
    }
}

/// Reports a broken rule: the field, its value, the rule.
pub(crate) type Invalid<'a> = dyn Fn(&str, &dyn std::fmt::Display, &str) -> CaseError + 'a;

/// Validates the text of a case file; `file` is only for the messages.
pub fn parse(file: &Path, text: &str) -> Result<Case, CaseError> {
    let raw: RawCase = match toml::from_str(text) {
        Ok(raw) => raw,
        Err(e) => {
            // Say a mistake of form as a person would (the reader names its Rust types); any
            // other, and TOML syntax, as the reader does, with the line and column.
            if let Ok(table) = toml::from_str::<toml::Table>(text) {
                check_form(file, &table)?;
            }
            return Err(CaseError::Syntax {
                file: file.into(),
                message: e.to_string().trim_end().to_string(),
            });
        }
    };
    validate(file, raw)
}

/// What a field of a case must be, for [`check_form`].
#[derive(Clone, Copy)]
enum Form {
    /// A string in quotes; what it says.
    Text(&'static str),
    /// A list of strings in quotes; an example.
    Texts(&'static str),
    Table,
    /// A whole number; what it counts.
    Whole(&'static str),
    Flag,
    /// A number or a string with a unit (read by [`to_si`], which names a wrong type itself);
    /// the unit.
    Quantity(&'static str),
}

/// The fields of a case the TOML reader checks the form of: (dotted path, form, required).
const FORMS: &[(&str, Form, bool)] = &[
    ("name", Form::Text("the case's name"), true),
    ("machine", Form::Text("\"pump\" or \"engine\""), true),
    ("mechanisms", Form::Texts("[\"slider_crank\"]"), true),
    ("geometry", Form::Table, true),
    ("geometry.crank_length", Form::Quantity("m"), true),
    ("geometry.rod_length", Form::Quantity("m"), true),
    ("geometry.bore", Form::Quantity("m"), true),
    ("geometry.opposed_pistons", Form::Flag, false),
    ("motion", Form::Table, true),
    ("motion.start_angle", Form::Quantity("degrees"), true),
    ("motion.end_angle", Form::Quantity("degrees"), true),
    ("motion.initial_speed", Form::Quantity("rad/s"), true),
    (
        "motion.angular_acceleration",
        Form::Quantity("rad/s²"),
        true,
    ),
    (
        "motion.steps",
        Form::Whole("the number of crank-angle intervals, from 8 to 100000000"),
        true,
    ),
    ("masses", Form::Table, false),
    ("gas", Form::Table, false),
    ("friction", Form::Table, false),
    ("gear", Form::Table, false),
    ("output", Form::Table, false),
    ("output.csv", Form::Flag, false),
    ("output.npy", Form::Flag, false),
    (
        "output.decimation",
        Form::Whole("write every n-th step"),
        false,
    ),
    (
        "output.significant_digits",
        Form::Whole("significant digits of the CSV numbers"),
        false,
    ),
];

/// The first field of `table` (a case) of the wrong form or missing, as a [`CaseError::Invalid`]
/// that names it, says what it must be and shows what was written.
fn check_form(file: &Path, table: &toml::Table) -> Result<(), CaseError> {
    let case = match table.get("name") {
        Some(toml::Value::String(name)) => name.clone(),
        _ => "(unnamed)".to_string(),
    };
    let invalid = |field: &str, value: &dyn std::fmt::Display, rule: String| CaseError::Invalid {
        file: file.into(),
        case: case.clone(),
        field: field.to_string(),
        value: value.to_string(),
        rule,
    };
    for &(path, form, required) in FORMS {
        let (parent, key) = match path.split_once('.') {
            Some((t, k)) => match table.get(t) {
                Some(toml::Value::Table(t)) => (t, k),
                // Its table is missing or of the wrong form: reported as such.
                _ => continue,
            },
            None => (table, path),
        };
        let Some(value) = parent.get(key) else {
            if !required {
                continue;
            }
            let what = match form {
                Form::Text(what) => format!("a string: {what}"),
                Form::Texts(example) => format!("a list of mechanism names, e.g. {example}"),
                Form::Table => format!("a table [{path}]"),
                Form::Whole(what) => format!("a whole number: {what}"),
                Form::Flag => "true or false".to_string(),
                Form::Quantity(unit) => {
                    format!("a number in {unit} or a string with a unit")
                }
            };
            return Err(invalid(path, &"(missing)", format!("required: {what}")));
        };
        let rule = match (form, value) {
            (Form::Text(_), toml::Value::String(_)) => continue,
            (Form::Text(what), _) => format!("must be a string in quotes: {what}"),
            (Form::Texts(_), toml::Value::Array(a)) if a.iter().all(|v| v.is_str()) => continue,
            (Form::Texts(example), toml::Value::Array(_)) => {
                format!("must be a list of names in quotes, e.g. {example}")
            }
            (Form::Texts(example), _) => {
                format!("must be a list of names in brackets, e.g. {example}, even of one")
            }
            (Form::Table, toml::Value::Table(_)) => continue,
            (Form::Table, toml::Value::Array(a)) if a.iter().all(|v| v.is_table()) => format!(
                "must be a table ([{path}]), not an array of tables ([[{path}]]): write [{path}] once"
            ),
            (Form::Table, _) => format!("must be a table ([{path}])"),
            (Form::Whole(_), toml::Value::Integer(_)) => continue,
            (Form::Whole(what), toml::Value::Float(x)) if x.fract() == 0.0 && x.abs() < 1e15 => {
                format!("must be a whole number ({x:.0}, not {value}): {what}")
            }
            (Form::Whole(what), toml::Value::String(s)) if s.trim().parse::<i64>().is_ok() => {
                format!(
                    "must be a whole number, written without quotes ({}, not {value}): {what}",
                    s.trim()
                )
            }
            (Form::Whole(what), _) => format!("must be a whole number: {what}"),
            (Form::Flag, toml::Value::Boolean(_)) => continue,
            (Form::Flag, _) => "must be true or false (without quotes)".to_string(),
            // A wrong type is named by the reading of the quantity, with its unit.
            (Form::Quantity(_), _) => continue,
        };
        return Err(invalid(path, value, rule));
    }
    Ok(())
}

/// Validates a case read from `file` (only for the messages).
fn validate(file: &Path, raw: RawCase) -> Result<Case, CaseError> {
    let case_name = raw.name.clone();
    let invalid = |field: &str, value: &dyn std::fmt::Display, rule: &str| CaseError::Invalid {
        file: file.into(),
        case: case_name.clone(),
        field: field.to_string(),
        value: crate::units::show(&value.to_string()),
        rule: rule.to_string(),
    };
    if !is_folder_name(&raw.name) {
        return Err(invalid("name", &format!("\"{}\"", raw.name), "must be a non-empty folder name of at most 200 letters, digits, '-', '_' and '.', not starting with '.'"));
    }
    let machine = match raw.machine.as_str() {
        "pump" => Machine::Pump,
        "engine" => Machine::Engine,
        other => {
            return Err(invalid(
                "machine",
                &format!("\"{other}\""),
                "must be \"pump\" or \"engine\"",
            ))
        }
    };
    let quantity = |field: &str, value: &toml::Value, dim: Dimension| {
        to_si(value, dim).map_err(|rule| invalid(field, value, &rule))
    };
    let positive = |field: &str, value: &toml::Value, dim: Dimension| {
        let x = quantity(field, value, dim)?;
        if x > 0.0 {
            Ok(x)
        } else {
            Err(invalid(field, value, "must be positive"))
        }
    };

    let g = &raw.geometry;
    let geometry = MachineGeometry {
        crank_length: positive("geometry.crank_length", &g.crank_length, Dimension::Length)?,
        rod_length: positive("geometry.rod_length", &g.rod_length, Dimension::Length)?,
        bore: positive("geometry.bore", &g.bore, Dimension::Length)?,
        pin_offset: match &g.pin_offset {
            Some(v) => quantity("geometry.pin_offset", v, Dimension::Length)?,
            None => 0.0,
        },
    };
    let pistons = if g.opposed_pistons == Some(true) {
        2
    } else {
        1
    };
    let crank_phase = match &g.crank_phase {
        None => 0.0,
        Some(v) => {
            let phase = quantity("geometry.crank_phase", v, Dimension::Angle)?;
            if pistons != 2 {
                return Err(invalid(
                    "geometry.crank_phase",
                    v,
                    "a phase between two crank trains needs opposed_pistons = true",
                ));
            }
            if phase.abs() > std::f64::consts::FRAC_PI_2 {
                return Err(invalid(
                    "geometry.crank_phase",
                    v,
                    "must be from -90° to 90° (the second crank's lead over the first)",
                ));
            }
            phase
        }
    };

    let m = &raw.motion;
    let start_angle = quantity("motion.start_angle", &m.start_angle, Dimension::Angle)?;
    let end_angle = quantity("motion.end_angle", &m.end_angle, Dimension::Angle)?;
    if end_angle <= start_angle {
        return Err(invalid(
            "motion.end_angle",
            &m.end_angle,
            "must be greater than motion.start_angle",
        ));
    }
    let motion = CrankMotion {
        start_angle,
        initial_speed: quantity(
            "motion.initial_speed",
            &m.initial_speed,
            Dimension::AngularSpeed,
        )?,
        angular_acceleration: quantity(
            "motion.angular_acceleration",
            &m.angular_acceleration,
            Dimension::AngularAcceleration,
        )?,
    };
    if let Err(e) = motion.at_angle(end_angle) {
        return Err(invalid(
            "motion.initial_speed",
            &m.initial_speed,
            &e.to_string(),
        ));
    }
    if !(8..=MAX_STEPS).contains(&m.steps) {
        return Err(invalid(
            "motion.steps",
            &m.steps,
            &format!("must be an integer from 8 to {MAX_STEPS}"),
        ));
    }

    let output = output_options(raw.output.as_ref(), &invalid)?;
    let masses = raw.masses.clone().unwrap_or_default();
    for key in masses.keys() {
        let known = MASS_FIELDS.iter().any(|(f, _)| f == key)
            || key == "rod_material"
            || key == "rules"
            || cardan_mechanism::entry(key).is_some();
        if !known {
            return Err(invalid(
                &format!("masses.{key}"),
                &masses[key],
                &format!(
                    "unknown field: the mass fields are {}, rod_material, rules, and a table per mechanism",
                    MASS_FIELDS.map(|(f, _)| f).join(", ")
                ),
            ));
        }
    }
    for key in raw.rest.keys() {
        if cardan_mechanism::entry(key).is_none() {
            return Err(invalid(
                key,
                &raw.rest[key],
                &format!(
                    "unknown field or table: a case has name, machine, mechanisms, [geometry], [motion], [masses], [gas], [friction], [gear], [output], and a table per mechanism ({})",
                    cardan_mechanism::names()
                ),
            ));
        }
    }

    if raw.mechanisms.is_empty() {
        return Err(invalid(
            "mechanisms",
            &"[]",
            &format!("must list at least one of {}", cardan_mechanism::names()),
        ));
    }
    let mut mechanisms: Vec<Arc<dyn Mechanism>> = Vec::new();
    for name in &raw.mechanisms {
        let Some(entry) = cardan_mechanism::entry(name) else {
            return Err(invalid(
                "mechanisms",
                &format!("\"{name}\""),
                &format!(
                    "unknown mechanism: use one of {}",
                    cardan_mechanism::names()
                ),
            ));
        };
        if mechanisms.iter().any(|c| c.name() == entry.name) {
            return Err(invalid(
                "mechanisms",
                &format!("\"{name}\""),
                "is listed twice",
            ));
        }
        let own = match masses.get(entry.name) {
            Some(toml::Value::Table(t)) => Some(t),
            Some(other) => {
                return Err(invalid(
                    &format!("masses.{}", entry.name),
                    other,
                    "must be a table of mass fields",
                ))
            }
            None => None,
        };
        let inputs = mass_inputs(&masses, own, entry, &quantity, &invalid)?;
        let options = mechanism_options(raw.rest.get(entry.name), entry, &invalid)?;
        let mechanism = (entry.build)(&geometry, &inputs, &options).map_err(|e| {
            let field = match e.field.as_str() {
                // The rod's centre of gravity may come from either mass table.
                "masses.rod_cg" if own.is_some_and(|t| t.contains_key("rod_cg")) => {
                    format!("masses.{}.rod_cg", entry.name)
                }
                f => f.to_string(),
            };
            invalid(&field, &e.value, &e.rule)
        })?;
        let step = (end_angle - start_angle) / m.steps as f64;
        mechanism
            .check_angles(start_angle, step, m.steps as usize)
            .map_err(|e| invalid(&e.field, &e.value, &e.rule))?;
        mechanisms.push(Arc::from(mechanism));
    }
    let gas = raw
        .gas
        .as_ref()
        .map(|table| crate::gas::parse(table, file, &case_name, machine))
        .transpose()?;
    if gas.is_some() {
        if let Some(m) = mechanisms.iter().find(|m| !m.has_cylinder()) {
            return Err(invalid(
                "gas",
                &format!("a [gas] table with the {}", m.name()),
                &format!(
                    "the {}'s pistons do not move in a cylinder, and the gas models need a cylinder volume: run it without [gas]",
                    m.name()
                ),
            ));
        }
    }
    let gear = match &raw.gear {
        None => None,
        Some(table) => {
            let spec = crate::gear::parse(table, file, &case_name)?;
            let mut meshes = 0;
            for m in &mechanisms {
                let ratings = GearRatings::new(&spec, m.as_ref(), None)
                    .map_err(|e| invalid(&e.field, &format!("(for the {})", m.name()), &e.rule))?;
                meshes += ratings.names().len();
            }
            if meshes == 0 {
                return Err(invalid(
                    "gear",
                    &"a [gear] table",
                    "no mechanism of the case has a gear mesh to rate",
                ));
            }
            Some(spec)
        }
    };
    let friction = match &raw.friction {
        None => None,
        Some(table) => {
            let f = crate::friction::parse(
                table,
                gear.as_ref(),
                geometry.bore,
                machine,
                gas.as_ref(),
                &invalid,
            )?;
            let named = f.joint_bearings.iter().map(|(j, _)| j);
            for joint in named.chain(f.joint_sizes.iter().map(|(j, _)| j)) {
                let revolute = |m: &Arc<dyn Mechanism>| {
                    m.topology().joints.iter().any(|j| {
                        j.name == joint
                            && matches!(j.kind, cardan_mechanism::JointKind::Revolute(_))
                    })
                };
                if !mechanisms.iter().any(revolute) {
                    return Err(invalid(
                        &format!("friction.joints.{joint}"),
                        &table["joints"][joint],
                        "no mechanism of the case has a revolute joint of this name (see summary.json's joints)",
                    ));
                }
            }
            for m in &mechanisms {
                LossBudget::new(&f, m.as_ref(), geometry.bore)
                    .map_err(|e| invalid(&e.field, &format!("(for the {})", m.name()), &e.rule))?;
            }
            Some(f)
        }
    };
    Ok(Case {
        file: file.into(),
        name: raw.name,
        machine,
        geometry,
        pistons,
        crank_phase,
        motion,
        end_angle,
        steps: m.steps as usize,
        mechanisms,
        gas,
        friction,
        gear,
        output,
        sweep: None,
    })
}

fn output_options(raw: Option<&RawOutput>, invalid: &Invalid) -> Result<OutputOptions, CaseError> {
    let mut o = OutputOptions::default();
    let Some(raw) = raw else { return Ok(o) };
    o.csv = raw.csv.unwrap_or(true);
    o.npy = raw.npy.unwrap_or(false);
    if let Some(d) = raw.decimation {
        if d < 1 {
            return Err(invalid(
                "output.decimation",
                &d,
                "must be a whole number of at least 1 (1 writes every step)",
            ));
        }
        o.decimation = d as usize;
    }
    if let Some(d) = raw.significant_digits {
        if !(1..=17).contains(&d) {
            return Err(invalid(
                "output.significant_digits",
                &d,
                "must be from 1 to 17 (leave it out for the shortest exact text)",
            ));
        }
        o.significant_digits = Some(d as usize);
    }
    Ok(o)
}

/// The mass fields for one mechanism: its own table wins over the common one.
fn mass_inputs(
    common: &toml::Table,
    own: Option<&toml::Table>,
    entry: &cardan_mechanism::Entry,
    quantity: &dyn Fn(&str, &toml::Value, Dimension) -> Result<f64, CaseError>,
    invalid: &Invalid,
) -> Result<MassInputs, CaseError> {
    let pick = |field: &str| match own.and_then(|t| t.get(field)) {
        Some(v) => Some((v, format!("masses.{}.{field}", entry.name))),
        None => common.get(field).map(|v| (v, format!("masses.{field}"))),
    };
    if let Some(t) = own {
        for key in t.keys() {
            if key != "rod_material" && !MASS_FIELDS.iter().any(|(f, _)| f == key) {
                return Err(invalid(
                    &format!("masses.{}.{key}", entry.name),
                    &t[key],
                    &format!(
                        "unknown field: the mass fields are {}, rod_material (mechanism tables cannot nest)",
                        MASS_FIELDS.map(|(f, _)| f).join(", ")
                    ),
                ));
            }
        }
    }
    let mut inputs = MassInputs::default();
    for (field, dim) in MASS_FIELDS {
        let Some((v, path)) = pick(field) else {
            continue;
        };
        if entry.unused_masses.contains(&field) {
            return Err(invalid(
                &path,
                v,
                &format!(
                    "does not apply to the {}: set it in the table of the mechanism it applies to, e.g. [masses.cardan_gear]",
                    entry.name
                ),
            ));
        }
        let x = quantity(&path, v, dim)?;
        if x < 0.0 {
            return Err(invalid(&path, v, "must not be negative"));
        }
        let slot = match field {
            "crankshaft_inertia" => &mut inputs.crankshaft_inertia,
            "wheel_inertia" => &mut inputs.wheel_inertia,
            "rod_mass" => &mut inputs.rod_mass,
            "rod_inertia" => &mut inputs.rod_inertia,
            "rod_cg" => &mut inputs.rod_cg,
            _ => &mut inputs.piston_mass,
        };
        *slot = Some(x);
    }
    // The reading of the estimation rules is the machine's, in the common table only.
    if let Some(v) = common.get("rules") {
        inputs.rules = match v.as_str().and_then(MassRules::from_name) {
            Some(r) => Some(r),
            None => {
                return Err(invalid(
                    "masses.rules",
                    v,
                    "must be \"rod_length\" (the default) or \"overall_length\"",
                ))
            }
        };
    }
    if let Some((v, path)) = pick("rod_material") {
        inputs.rod_material = match v.as_str().and_then(Material::from_name) {
            Some(m @ (Material::Steel | Material::Titanium)) => Some(m),
            _ => return Err(invalid(&path, v, "must be \"steel\" or \"titanium\"")),
        };
    }
    Ok(inputs)
}

/// A mechanism's own table (`[cardan_gear]`), read against the options it declares.
fn mechanism_options(
    table: Option<&toml::Value>,
    entry: &cardan_mechanism::Entry,
    invalid: &Invalid,
) -> Result<Options, CaseError> {
    let mut options = Options::new();
    let Some(table) = table else {
        return Ok(options);
    };
    let Some(table) = table.as_table() else {
        return Err(invalid(
            entry.name,
            table,
            "must be a table of the mechanism's options",
        ));
    };
    let declared = || {
        if entry.options.is_empty() {
            "it has none".to_string()
        } else {
            entry
                .options
                .iter()
                .map(|o| o.name)
                .collect::<Vec<_>>()
                .join(", ")
        }
    };
    for (key, value) in table {
        let field = format!("{}.{key}", entry.name);
        let Some(spec) = entry.options.iter().find(|o| o.name == key) else {
            return Err(invalid(
                &field,
                value,
                &format!("unknown option of the {}: {}", entry.name, declared()),
            ));
        };
        let v = match spec.kind {
            OptionKind::Choice(words) => match value.as_str() {
                Some(w) if words.contains(&w) => OptionValue::Word(w.to_string()),
                _ => {
                    return Err(invalid(
                        &field,
                        value,
                        &format!(
                            "must be one of {}",
                            words
                                .iter()
                                .map(|w| format!("\"{w}\""))
                                .collect::<Vec<_>>()
                                .join(", ")
                        ),
                    ))
                }
            },
            OptionKind::Angle => OptionValue::Number(
                to_si(value, Dimension::Angle).map_err(|r| invalid(&field, value, &r))?,
            ),
            OptionKind::Length => OptionValue::Number(
                to_si(value, Dimension::Length).map_err(|r| invalid(&field, value, &r))?,
            ),
            OptionKind::Number => OptionValue::Number(
                to_si(value, Dimension::Number).map_err(|r| invalid(&field, value, &r))?,
            ),
        };
        options.insert(key.clone(), v);
    }
    Ok(options)
}
