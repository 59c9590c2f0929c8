//! Case files: TOML in, a validated [`Case`] out. Every rule a value breaks is reported with
//! the file, the case, the field, the rule and the value. Mechanisms are named from the
//! registry of `cardan-mechanism`; each builds itself from the shared geometry, the mass fields
//! and its own table (`[cardan_gear]`, ...).

use crate::digest::InputDigest;
use crate::error::Invalid;
use crate::error::{CaseError, Machine};
use crate::gas::GasCase;
use crate::input_field::mechanism_field;
use crate::masses::MassTable;
use crate::quantity::{
    Angle, AngularAcceleration, AngularSpeed, Length, Positive, Quantity, Whole,
};
use crate::read_once::ReadOnce;
use crate::setup::Setup;
use crate::units::is_folder_name;
use cardan_dynamics::{Friction, GearSpec};
use cardan_mechanism::{CrankMotion, Input, MachineGeometry, Mechanism};
use rayon::prelude::*;
use schemars::JsonSchema;
use serde::Deserialize;
use std::path::{Path, PathBuf};
use std::sync::Arc;

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
    /// A sweep's points each in a folder of their own (`Some(true)`), or only as rows of the
    /// sweep table (`Some(false)`); `None`: the runner's default by the number of points.
    pub case_folders: Option<bool>,
}

impl Default for OutputOptions {
    fn default() -> Self {
        Self {
            csv: true,
            npy: false,
            decimation: 1,
            significant_digits: None,
            case_folders: None,
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
    /// Each mechanism's per-step stages as validation built them (one per mechanism, in
    /// order), which its runs take: after changing `friction`, `gear` or a mechanism, build
    /// them again ([`Case::build_setups`]).
    pub setups: Vec<Setup>,
    /// The solved machine motion (`[motion] mode = "dynamic"`, `[load]`, `[flywheel]`);
    /// `None`: the crank follows `motion`.
    pub dynamics: Option<crate::machine_motion::Dynamics>,
    pub output: OutputOptions,
    /// `[output] metrics`: the summary metrics a sweep's table holds, each mechanism's, in the
    /// summary's order (None: every metric); summary.json holds every metric whatever it says.
    pub table_metrics: Option<Arc<[String]>>,
    /// The machine's layout and balancing devices (`[layout]`, `[balance]`; default: one
    /// cylinder, none).
    pub balance: cardan_balance::MachineBalance,
    /// The sweep this case is a point of (its results go to `out/<sweep>/<case>/`), and the
    /// value of each swept field (dotted path, value as written).
    pub sweep: Option<(String, Vec<(String, String)>)>,
    /// The digest of the case's whole input as read ([`crate::digest`]): its typed document
    /// ([`CaseFile`], every field, a quantity in SI), its mechanisms' own tables, and the
    /// name and bytes of every file it read (a `[gas]` pressure trace); made at once, but by
    /// [`point_to_run`] when first read. The runner's input hash (`run.json`, `shard.json`)
    /// is made from it.
    pub input_digest: InputDigest,
    /// Notes on inputs taken as written that were likely meant otherwise (a bare whole
    /// `initial_speed` of rpm's size taken as rad/s): printed by `cardan check`, and meant for
    /// summary.json's `warnings`.
    pub notes: Vec<String>,
}

/// Whole bare crank speeds from this many rad/s (955 rpm) up to the plausible bare limit read
/// like rpm: issue 36.15's 980, taken as 980 rad/s (9358 rpm).
const RPM_LIKE_SPEED: f64 = 100.0;

/// The note on a bare `initial_speed` that reads like rpm, if it does.
fn speed_note(speed: &Quantity<AngularSpeed>) -> Option<String> {
    let x = speed.si;
    let bare = !speed.written.starts_with('"');
    (bare && x.fract() == 0.0 && x.abs() >= RPM_LIKE_SPEED).then(|| {
        let rpm = x * 60.0 / std::f64::consts::TAU;
        format!(
            "motion.initial_speed = {0} is taken as {0} rad/s ({rpm:.0} rpm); if {0} rpm was \
             meant, write \"{0} rpm\"; write \"{0} rad/s\" to keep it without this note",
            speed.written
        )
    })
}

/// A case file as written: the typed schema of its top level. The mechanisms' own tables
/// (`[cardan_gear]`, ...) and their mass tables (`[masses.cardan_gear]`) are named by the
/// registry of `cardan-mechanism` and read apart (`mechanism_tables`).
#[derive(Deserialize, JsonSchema, serde::Serialize)]
#[serde(deny_unknown_fields)]
pub struct CaseFile {
    /// The case's name, and its results folder: at most 200 letters, digits, '-', '_' and '.',
    /// not starting with '.'.
    pub name: FolderName,
    /// What the gas does: "pump" or "engine".
    pub machine: Machine,
    /// The mechanisms compared, by their registry names, e.g. ["slider_crank"].
    pub mechanisms: Vec<String>,
    pub geometry: GeometryTable,
    pub motion: MotionTable,
    /// The masses; fields left out are estimated by the mass rules.
    #[serde(default)]
    pub masses: MassTable,
    /// The gas loading the pistons (its model and their inputs); without it, inertial loads only.
    /// Read by the model `model` names ([`crate::gas::MODELS`]).
    #[serde(default)]
    #[schemars(schema_with = "crate::gas::gas_schema")]
    pub gas: Option<toml::Table>,
    /// The loss models; without it the run has no losses.
    pub friction: Option<crate::friction::FrictionTable>,
    /// The gear pair and its rating data; without it no gear mesh is rated.
    pub gear: Option<crate::gear::GearTable>,
    /// The torque a load or motor applies to the crankshaft (`[motion] mode = "dynamic"` only).
    pub load: Option<crate::machine_motion::LoadTable>,
    /// A flywheel on the crankshaft, given or sized (`[motion] mode = "dynamic"` only).
    pub flywheel: Option<crate::machine_motion::FlywheelTable>,
    #[serde(default)]
    pub output: OutputTable,
    /// The machine's cylinders: several on one crankshaft; without it, one cylinder.
    pub layout: Option<crate::balance::LayoutTable>,
    /// Counterweights and balance shafts; without it, none (a balanced crankshaft).
    pub balance: Option<crate::balance::BalanceTable>,
}

/// `[geometry]`: the machine's shared dimensions.
#[derive(Deserialize, JsonSchema, serde::Serialize)]
#[serde(deny_unknown_fields)]
pub struct GeometryTable {
    /// Crank radius r, m.
    pub crank_length: Positive<Length>,
    /// Connecting-rod centre distance l, m.
    pub rod_length: Positive<Length>,
    /// Cylinder bore, m.
    pub bore: Positive<Length>,
    /// Piston-pin offset from the cylinder axis, m; default 0.
    pub pin_offset: Option<Quantity<Length>>,
    /// Two pistons in one cylinder, no cylinder head (Nunes 2017); default false.
    #[serde(default)]
    pub opposed_pistons: bool,
    /// Lead of the second crank train's crank over the first's, from -90° to 90° (opposed
    /// pistons only); default 0.
    pub crank_phase: Option<Quantity<Angle>>,
}

/// `[motion]`: the crank's prescribed motion.
#[derive(Deserialize, JsonSchema, serde::Serialize)]
#[serde(deny_unknown_fields)]
pub struct MotionTable {
    /// Crank angle at the start of the run; a bare number is in degrees.
    pub start_angle: Quantity<Angle>,
    /// Crank angle at the end of the run, greater than the start.
    pub end_angle: Quantity<Angle>,
    /// Crank speed at the start angle, rad/s.
    pub initial_speed: Quantity<AngularSpeed>,
    /// Constant crank angular acceleration, rad/s².
    pub angular_acceleration: Quantity<AngularAcceleration>,
    /// The number of crank-angle intervals (the run has steps + 1 points); of one cycle in a
    /// dynamic run.
    pub steps: Whole<8, MAX_STEPS>,
    /// "prescribed" (default: the crank follows the law above) or "dynamic" (its speed solved
    /// from its torques from initial_speed at start_angle; angular_acceleration unused).
    #[serde(default)]
    pub mode: crate::machine_motion::MotionMode,
    /// Dynamic: cycles of start_angle..end_angle run from the initial state, the last reported;
    /// default 1; cycles × steps at most 20 million integration steps.
    pub cycles: Option<Whole<1, 100_000>>,
    /// Dynamic: stop before `cycles` once a cycle ends within this fraction of its start speed
    /// (periodic steady state), from 0 to 1 (exclusive); default: run every cycle.
    pub steady_tolerance: Option<crate::quantity::Ranged<crate::plausible::SteadyTolerance>>,
}

/// `[output]`: what a case writes besides `summary.json`.
#[derive(Deserialize, JsonSchema, serde::Serialize)]
#[serde(deny_unknown_fields)]
pub struct OutputTable {
    /// Write `<mechanism>.csv`, one row per step; default true.
    #[serde(default = "yes")]
    pub csv: bool,
    /// Write `<mechanism>.npy` and `<mechanism>.columns.json`; default false.
    #[serde(default)]
    pub npy: bool,
    /// Write every n-th step (and the last), from 1 to the largest number of steps; default
    /// 1, every step.
    pub decimation: Option<Whole<1, MAX_STEPS>>,
    /// Significant digits of the CSV numbers, from 1 to 17; default: the shortest text that
    /// reads back to the same number.
    pub significant_digits: Option<Whole<1, 17>>,
    /// A sweep's points each in a folder of their own (summary.json, per-step files, listed in
    /// sweep.csv); false: only as rows of the sweep table (columns/*.npy and sweep.json, no
    /// folders, no per-step files), for sweeps of many points. Default: true up to 10 000
    /// points, false above. Not read outside a sweep.
    pub case_folders: Option<bool>,
    /// The summary metrics written as the sweep table's columns, for each mechanism (a sweep
    /// written as a table: columns/*.npy; with case folders: sweep.csv), e.g.
    /// ["mechanical_efficiency", "power_loss_mean"]: names of the metric table of
    /// docs/results.md, `{joint}`, `{body}`, ... filled in ("total_crank_pin_force_max").
    /// Default: every metric. summary.json always holds every metric.
    pub metrics: Option<Vec<String>>,
}

fn yes() -> bool {
    true
}

impl Default for OutputTable {
    fn default() -> Self {
        Self {
            csv: true,
            npy: false,
            decimation: None,
            significant_digits: None,
            case_folders: None,
            metrics: None,
        }
    }
}

impl From<&OutputTable> for OutputOptions {
    fn from(o: &OutputTable) -> Self {
        Self {
            csv: o.csv,
            npy: o.npy,
            decimation: o.decimation.map_or(1, |d| d.0 as usize),
            significant_digits: o.significant_digits.map(|d| d.0 as usize),
            case_folders: o.case_folders,
        }
    }
}

/// A case's name: a folder name ([`is_folder_name`]).
#[derive(Debug, Clone, JsonSchema, serde::Serialize)]
#[schemars(transparent)]
pub struct FolderName(pub String);

impl<'de> Deserialize<'de> for FolderName {
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let name = String::deserialize(d)?;
        if is_folder_name(&name) {
            Ok(FolderName(name))
        } else {
            Err(serde::de::Error::custom(crate::quantity::broken(
                &format!("\"{name}\""),
                "must be a non-empty folder name of at most 200 letters, digits, '-', '_' and '.', not starting with '.'",
            )))
        }
    }
}

/// Largest accepted number of steps.
pub const MAX_STEPS: i64 = 100_000_000;

/// Largest accepted number of integration steps of a dynamic run's cycles (`cycles × steps`):
/// 20 million, a run-up of 27 000 cycles of 720 steps, some minutes a mechanism with every
/// loss model (issue 36.10: 100 000 cycles were accepted and took about 13 hours).
pub const MAX_SOLVED_STEPS: i64 = 20_000_000;

/// Reads and validates one case file.
pub fn load(file: &Path) -> Result<Case, CaseError> {
    let text = read_case_text(file)?;
    parse(file, &text)
}

/// The text of the case file `file`, read through the bounded reader (a regular file of at
/// most [`cardan_files::CASE_FILE`]'s 16 MiB).
pub fn read_case_text(file: &Path) -> Result<String, CaseError> {
    cardan_files::read_text(file, cardan_files::CASE_FILE).map_err(|source| CaseError::Io {
        file: file.into(),
        source,
    })
}

/// Reads one case file: one case, or every point of its `[sweep]` (see [`crate::sweep`]).
pub fn load_file(file: &Path) -> Result<Vec<Case>, CaseError> {
    let text = read_case_text(file)?;
    cases_of_table(file, toml_table(file, &text)?)
}

/// The cases of a case file's table read as TOML (or made otherwise, e.g. by the Python
/// package from a dict): one case, or every point of its `[sweep]`. `file` is only for the
/// messages. The same reader as [`load_file`]'s, so the same errors.
pub fn cases_of_table(file: &Path, table: toml::Table) -> Result<Vec<Case>, CaseError> {
    match crate::sweep::expand(file, table.clone())? {
        None => from_table(file, table, &ReadOnce::default()).map(|c| vec![digested(c)]),
        Some((sweep, points)) => {
            let read_once = ReadOnce::default();
            // Each point's table read as it is (written out as TOML text and parsed again, it
            // took most of the time of reading a sweep of 10 000 points), the points on every
            // thread, the first failure in the points' order reported.
            let cases: Vec<Result<Case, CaseError>> = points
                .into_par_iter()
                .map(|p| {
                    let mut case = digested(from_table(file, p.table, &read_once)?);
                    case.sweep = Some((sweep.clone(), p.values));
                    Ok(case)
                })
                .collect();
            cases.into_iter().collect()
        }
    }
}

/// Point `k` of `sweep` (from 0) validated: the case it runs as, with its sweep's name and its
/// swept values; the errors are those of a case file of that point's table.
pub fn point_case(sweep: &crate::sweep::Sweep, k: usize) -> Result<Case, CaseError> {
    point_to_run(sweep, k).map(digested)
}

/// [`point_case`], its input digest made only when read, for a point run and dropped (a sweep
/// written as a table never reads its points' digests: issue 37).
pub fn point_to_run(sweep: &crate::sweep::Sweep, k: usize) -> Result<Case, CaseError> {
    let point = sweep.point(k)?;
    let mut case = from_table(&sweep.file, point.table, sweep.read_once())?;
    case.sweep = Some((sweep.name.clone(), point.values));
    Ok(case)
}

/// Validates a case file's table that has no `[sweep]` (one made by
/// [`crate::sweep::Sweep::define`]'s caller, or read by [`toml_table`]); `file` is only for the
/// messages.
pub fn case_of_table(file: &Path, table: toml::Table) -> Result<Case, CaseError> {
    from_table(file, table, &ReadOnce::default()).map(digested)
}

/// Validates the text of a case file; `file` is only for the messages.
pub fn parse(file: &Path, text: &str) -> Result<Case, CaseError> {
    from_table(file, toml_table(file, text)?, &ReadOnce::default()).map(digested)
}

/// `case` with its input digest made: a case kept drops its typed document now (4 kB), not
/// when its digest is first read.
fn digested(case: Case) -> Case {
    case.input_digest.hex();
    case
}

/// The TOML of a case file; a syntax error as the TOML reader says it, with line and column.
pub fn toml_table(file: &Path, text: &str) -> Result<toml::Table, CaseError> {
    toml::from_str(text).map_err(|e: toml::de::Error| CaseError::Syntax {
        file: file.into(),
        message: e.to_string().trim_end().to_string(),
    })
}

/// Reads a case's table (a file's, or a sweep point's) into the schema, then validates it; the
/// files it reads are read once for every case sharing `read_once`.
fn from_table(
    file: &Path,
    mut table: toml::Table,
    read_once: &ReadOnce,
) -> Result<Case, CaseError> {
    let name = match table.get("name") {
        Some(toml::Value::String(name)) => name.clone(),
        _ => "(unnamed)".to_string(),
    };
    if table.contains_key("optimize") {
        // Read by `crate::optimize::Optimization::define`, which takes it out first.
        return Err(CaseError::Invalid {
            file: file.into(),
            case: name,
            field: "optimize".into(),
            value: "an [optimize] table".into(),
            rule: "an optimisation is run by `cardan run` (or `cardan.optimize` in Python), not as a single case: run the file with `cardan run`".into(),
        });
    }
    let own = crate::mechanism_table::mechanism_tables(&mut table);
    let raw: CaseFile = crate::schema::read(toml::Value::Table(table), "").map_err(|error| {
        // The mechanisms' tables are valid names at the top level and in [masses].
        let error = match error.field.rsplit_once('.') {
            None | Some(("masses", _)) => error.unknown_among(&mechanism_names()),
            _ => error,
        };
        CaseError::Field {
            file: file.into(),
            case: name.clone(),
            error,
        }
    })?;
    validate(file, raw, own, read_once)
}

fn mechanism_names() -> Vec<&'static str> {
    cardan_mechanism::MECHANISMS
        .iter()
        .map(|e| e.name)
        .collect()
}

/// The crank's motion of a case (`[motion]`, `[load]`, `[flywheel]`): the prescribed law, the
/// end angle (rad) and the solved motion's tables, with their rules.
fn motion_of(
    raw: &CaseFile,
    invalid: &Invalid,
) -> Result<(CrankMotion, f64, Option<crate::machine_motion::Dynamics>), CaseError> {
    let m = &raw.motion;
    let (start_angle, end_angle) = (m.start_angle.si, m.end_angle.si);
    if end_angle <= start_angle {
        return Err(invalid(
            "motion.end_angle",
            &m.end_angle.written,
            "must be greater than motion.start_angle",
        ));
    }
    let motion = CrankMotion {
        start_angle,
        initial_speed: m.initial_speed.si,
        angular_acceleration: m.angular_acceleration.si,
    };
    let dynamics = crate::machine_motion::build(
        m.mode,
        m.cycles.map(|c| c.0),
        m.steady_tolerance.as_ref().map(|t| t.si),
        raw.load.as_ref(),
        raw.flywheel.as_ref(),
        &invalid,
    )?;
    let (tolerance, cycles) = (
        m.steady_tolerance.as_ref().map(|t| t.si),
        m.cycles.as_ref().map(|c| c.0),
    );
    let dynamic = (
        dynamics.is_some(),
        &m.angular_acceleration,
        &m.initial_speed,
    );
    crate::unread::dynamic_inputs(dynamic, tolerance, cycles, &invalid)?;
    if let Some(cycles) = cycles.filter(|&c| c.saturating_mul(m.steps.0) > MAX_SOLVED_STEPS) {
        return Err(invalid(
            "motion.cycles",
            &cycles,
            &format!(
                "with motion.steps = {} is {} integration steps, more than {MAX_SOLVED_STEPS} \
                 (hours of solving, more with a sized flywheel): set motion.steady_tolerance to \
                 stop at the periodic steady state, or take fewer steps per cycle",
                m.steps.0,
                cycles * m.steps.0
            ),
        ));
    }
    if let (None, Err(e)) = (&dynamics, motion.at_angle(end_angle)) {
        return Err(invalid(
            "motion.initial_speed",
            &m.initial_speed.written,
            &e.to_string(),
        ));
    }
    Ok((motion, end_angle, dynamics))
}

/// Validates a case read from `file` (only for the messages): the rules between fields, and
/// the mechanisms built from the registry.
fn validate(
    file: &Path,
    raw: CaseFile,
    own: crate::mechanism_table::MechanismTables,
    read_once: &ReadOnce,
) -> Result<Case, CaseError> {
    let case_name = raw.name.0.clone();
    let invalid = |field: &str, value: &dyn std::fmt::Display, rule: &str| CaseError::Invalid {
        file: file.into(),
        case: case_name.clone(),
        field: field.to_string(),
        value: crate::units::show(&value.to_string()),
        rule: rule.to_string(),
    };
    let field_error = |error| CaseError::Field {
        file: file.into(),
        case: case_name.clone(),
        error,
    };
    let machine = raw.machine;
    let g = &raw.geometry;
    let geometry = machine_geometry(g);
    crate::unread::geometry_size([&g.crank_length, &g.rod_length, &g.bore], &invalid)?;
    let pistons = if g.opposed_pistons { 2 } else { 1 };
    let crank_phase = crank_phase(g, pistons, &invalid)?;

    let m = &raw.motion;
    let (motion, end_angle, dynamics) = motion_of(&raw, &invalid)?;
    let start_angle = motion.start_angle;
    let steps = m.steps.0 as usize;

    let step = (end_angle - start_angle) / steps as f64;
    let angles = (start_angle, step, steps);
    let mechanisms = build_mechanisms(&raw, &own, &geometry, angles, &invalid, &field_error)?;
    let gas = raw
        .gas
        .as_ref()
        .map(|table| crate::gas::parse(table, file, &case_name, (machine, read_once)))
        .transpose()?;
    if let Some(gas) = &gas {
        let cylinder = (geometry.bore, pistons, crank_phase);
        let ready = (&mechanisms[..], cylinder, mean_speed(&motion, end_angle));
        check_gas(file, &raw, gas, ready, &invalid)?;
    }
    let gear = raw.gear.as_ref().map(|t| t.build(&invalid)).transpose()?;
    if gear.is_some() {
        let written = [&*m.angular_acceleration.written, &*m.initial_speed.written];
        let run = (&motion, end_angle, dynamics.is_some());
        crate::gear_speed::check_run(&mechanisms, run, written, &invalid)?;
    }
    let with = (gear.as_ref(), machine, gas.as_ref());
    let friction = (raw.friction.as_ref())
        .map(|t| crate::friction::build_checked(t, with, &mechanisms, &invalid))
        .transpose()?;
    let balance = crate::balance::build(raw.layout.as_ref(), raw.balance.as_ref(), &invalid)?;
    let machines = crate::setup::check_machine(&balance, mechanisms, (pistons, machine), &invalid)?;
    let mechanisms = machines.iter().map(|m| Arc::clone(m.mechanism())).collect();
    let setups = crate::setup::setups(
        &machines,
        geometry.bore,
        (friction.as_ref(), gear.as_ref(), gas.is_some()),
        (motion.initial_speed, read_once.bending_j()),
        &invalid,
    )?;
    if dynamics.is_some() {
        solved_friction(&setups, &invalid)?;
    }
    let computed = crate::output_metrics::Computed::of(
        &gas,
        &friction,
        &gear,
        &dynamics,
        balance.shaking_per_step,
    );
    let listed = raw.output.metrics.as_deref();
    let table_metrics = crate::output_metrics::build(listed, &computed, &invalid)?;
    let (output, notes) = ((&raw.output).into(), speed_note(&m.initial_speed));
    let files = gas.iter().flat_map(|g| g.files.clone()).collect();
    Ok(Case {
        file: file.into(),
        name: raw.name.0.clone(),
        machine,
        geometry,
        pistons,
        crank_phase,
        motion,
        end_angle,
        steps,
        mechanisms,
        gas,
        friction,
        gear,
        setups,
        dynamics,
        output,
        table_metrics,
        balance,
        sweep: None,
        input_digest: InputDigest::new((raw, own.options, own.masses), files),
        notes: notes.into_iter().collect(),
    })
}

/// The gas checked against the crank trains it drives (`ready`: the mechanisms; the
/// cylinder's bore m, pistons and crank phase rad; the mean crank speed rad/s): each train has
/// a cylinder for it, and the gas is made ready for each as the run makes it.
fn check_gas(
    file: &Path,
    raw: &CaseFile,
    gas: &GasCase,
    ready: crate::unread::Trains,
    invalid: &Invalid,
) -> Result<(), CaseError> {
    crate::unread::gas_cylinders(ready.0, invalid)?;
    let Some(table) = &raw.gas else {
        return Ok(());
    };
    let (g, m) = (&raw.geometry, &raw.motion);
    let written = [
        &*g.bore.written,
        &g.crank_length.written,
        &m.initial_speed.written,
    ];
    let at = (file, raw.name.0.as_str(), raw.machine);
    let layout = (raw.layout.as_ref(), written);
    crate::unread::gas_ready(gas, table, at, ready, layout, invalid)
}

/// The mean crank speed of a prescribed `motion` from its start to `end_angle` (rad/s), at which
/// the gas models are prepared (their speed-dependent timing and heat transfer); the initial
/// speed if the crank does not get there in a positive time.
pub fn mean_speed(motion: &CrankMotion, end_angle: f64) -> f64 {
    match motion.at_angle(end_angle) {
        Ok(end) if end.time > 0.0 => (end_angle - motion.start_angle) / end.time,
        _ => motion.initial_speed,
    }
}

/// The crank train's dimensions (m) as the mechanisms take them: no pin offset given is none.
fn machine_geometry(g: &GeometryTable) -> MachineGeometry {
    MachineGeometry {
        crank_length: g.crank_length.si,
        rod_length: g.rod_length.si,
        bore: g.bore.si,
        pin_offset: g.pin_offset.as_ref().map_or(0.0, |p| p.si),
    }
}

/// The second crank train's lead (rad): only with opposed pistons, from -90° to 90°; 0 without.
fn crank_phase(g: &GeometryTable, pistons: u32, invalid: &Invalid) -> Result<f64, CaseError> {
    Ok(match &g.crank_phase {
        None => 0.0,
        Some(phase) if pistons != 2 => {
            return Err(invalid(
                "geometry.crank_phase",
                &phase.written,
                "a phase between two crank trains needs opposed_pistons = true",
            ))
        }
        Some(phase) if phase.si.abs() > std::f64::consts::FRAC_PI_2 => {
            return Err(invalid(
                "geometry.crank_phase",
                &phase.written,
                "must be from -90° to 90° (the second crank's lead over the first)",
            ))
        }
        Some(phase) => phase.si,
    })
}

/// Refuses the loss models a solved motion cannot take among its torques: those whose loss at
/// a step depends on the steps before (the ring films' squeeze term carries each film from the
/// previous step's time), which have no value at the Runge-Kutta stages' states
/// (`cardan_dynamics::machine_friction`).
fn solved_friction(setups: &[Setup], invalid: &Invalid) -> Result<(), CaseError> {
    let history = |s: &Setup| s.losses.as_ref().is_some_and(|l| l.carries_history());
    if setups.iter().any(history) {
        return Err(invalid(
            "friction.rings",
            &"\"film\" with motion.mode = \"dynamic\"",
            "the ring films carry their thickness from step to step, which a solved motion's Runge-Kutta stages do not have: use rings = \"karhula\" in a dynamic motion",
        ));
    }
    Ok(())
}

/// The case's mechanisms from the registry, each with its masses and options, checked over the
/// run's angles (`start`, `step`, `steps`).
fn build_mechanisms(
    raw: &CaseFile,
    own: &crate::mechanism_table::MechanismTables,
    geometry: &MachineGeometry,
    (start, step, steps): (f64, f64, usize),
    invalid: &Invalid,
    field_error: &dyn Fn(crate::schema::FieldError) -> CaseError,
) -> Result<Vec<Arc<dyn Mechanism>>, CaseError> {
    if raw.mechanisms.is_empty() {
        return Err(invalid(
            "mechanisms",
            &"[]",
            &format!("must list at least one of {}", cardan_mechanism::names()),
        ));
    }
    crate::unread::tables(&raw.mechanisms, [&own.options, &own.masses], invalid)?;
    let mut mechanisms: Vec<Arc<dyn Mechanism>> = Vec::new();
    for name in &raw.mechanisms {
        let Some(entry) = cardan_mechanism::entry(name) else {
            let rule = crate::schema::suggest("mechanism", name, &mechanism_names());
            return Err(invalid("mechanisms", &format!("\"{name}\""), &rule));
        };
        if mechanisms.iter().any(|c| c.name() == entry.name) {
            return Err(invalid(
                "mechanisms",
                &format!("\"{name}\""),
                "is listed twice",
            ));
        }
        let own_masses = match own.masses.get(entry.name) {
            Some(v) => Some(crate::masses::own_table(v.clone(), entry.name).map_err(field_error)?),
            None => None,
        };
        let inputs = crate::masses::inputs(&raw.masses, own_masses.as_ref(), entry, invalid)?;
        let options = crate::mechanism_table::options(own.options.get(entry.name), entry)
            .map_err(field_error)?;
        let mechanism = (entry.build)(geometry, &inputs, &options).map_err(|e| {
            let field = match e.field {
                // The rod's centre of gravity may come from either mass table.
                Input::RodCg if own_masses.as_ref().is_some_and(|t| t.rod_cg.is_some()) => {
                    format!("masses.{}.rod_cg", entry.name)
                }
                f => mechanism_field(f),
            };
            invalid(&field, &e.value, &e.rule)
        })?;
        mechanism
            .check_angles(start, step, steps)
            .map_err(|e| invalid(&mechanism_field(e.field), &e.value, &e.rule))?;
        mechanisms.push(Arc::from(mechanism));
    }
    let offset = raw.geometry.pin_offset.as_ref();
    crate::unread::pin_offset(
        offset.map(|p| (p.si, p.written.as_str())),
        &mechanisms,
        invalid,
    )?;
    Ok(mechanisms)
}

impl Case {
    /// Builds its setups again from its mechanisms, `friction` and `gear` (after a change to
    /// them); the errors are validation's.
    pub fn build_setups(&mut self) -> Result<(), CaseError> {
        let invalid = |field: &str, value: &dyn std::fmt::Display, rule: &str| CaseError::Invalid {
            file: self.file.clone(),
            case: self.name.clone(),
            field: field.to_string(),
            value: crate::units::show(&value.to_string()),
            rule: rule.to_string(),
        };
        let machines = crate::setup::check_machine(
            &self.balance,
            self.mechanisms.clone(),
            (self.pistons, self.machine),
            &invalid,
        )?;
        self.mechanisms = machines.iter().map(|m| Arc::clone(m.mechanism())).collect();
        let tables = (
            self.friction.as_ref(),
            self.gear.as_ref(),
            self.gas.is_some(),
        );
        let setups = crate::setup::setups(
            &machines,
            self.geometry.bore,
            tables,
            (self.motion.initial_speed, &Default::default()),
            &invalid,
        )?;
        self.setups = setups;
        Ok(())
    }
}
