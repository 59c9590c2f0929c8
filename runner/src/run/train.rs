//! Running one case's crank trains (every mechanism in parallel, and the second train of a
//! phased opposed-piston case), each step streamed to the summary, the per-step files and the
//! charts: [`run_case`], and each train's [`MechanismResult`].

use super::sampling::{sampling_warning, shifted_peaks, SAMPLING_CHECK_STEPS_PER_REV};
use crate::output::MechanismResult;
use crate::per_step::{ChartSink, ColumnSink, PerStepSink, RunLayout, StepColumns};
use crate::progress::StepCounter;
use cardan_case::case::Case;
use cardan_case::machine_motion::Dynamics;
use cardan_case::setup::Setup;
use cardan_dynamics::machine_friction::MotionFriction;
use cardan_dynamics::machine_motion::{MachineTorques, SolvedMotion, SolvedRun};
use cardan_dynamics::stepper::GasAt;
use cardan_dynamics::{
    at_each_lane, run, CylinderGas, Gas, Inertial, LoadFamily, RunRooms, Sink, Stage, Summary,
    SummarySink,
};
use cardan_gas::{GasMetric, PreparedGas};
use cardan_mechanism::{Column, CrankMotion, Grid, Mechanism, StateBlock, LANES};
use cardan_report::ChartData;
use rayon::prelude::*;
use std::path::Path;
use std::sync::Arc;

/// The mean crank speed over the run, rad/s: the speed of a steady run, which the
/// speed-dependent gas models use.
fn mean_speed(case: &Case) -> f64 {
    cardan_case::case::mean_speed(&case.motion, case.end_angle)
}

/// Where a crank train's per-step rows go besides its summary.
#[derive(Debug, Clone, Copy)]
pub(crate) enum StepsTo<'p> {
    /// Nowhere: the summary alone (the run shared by the threads).
    Summary,
    /// The per-step files `case.output` asks for, in the folder `dir`; with `charts`, the
    /// report's charts too.
    Files { dir: &'p Path, charts: bool },
    /// Memory, as columns ([`ColumnSink`]: every `case.output.decimation`-th step and the last).
    Memory,
}

impl<'p> StepsTo<'p> {
    /// The folder of the per-step files, if any, and whether the charts are recorded.
    fn files(self) -> (Option<&'p Path>, bool) {
        match self {
            StepsTo::Files { dir, charts } => (Some(dir), charts),
            StepsTo::Summary | StepsTo::Memory => (None, false),
        }
    }
}

/// What one crank train's run gives besides its summary and warnings: the report's chart
/// series and its per-step columns, each if asked.
#[derive(Default)]
pub(crate) struct TrainRows {
    pub charts: Option<ChartData>,
    pub columns: Option<StepColumns>,
}

/// A crank train on the solved motion of `case.dynamics` (`[motion] mode = "dynamic"`): its cycles before
/// the reported one (and the flywheel, if sized) solved first (`dynamic.rs`), then the
/// reported cycle stepped one state at a time into `sinks`; the friction torque of the
/// `setup`'s loss budget (with `[friction]`) among the motion's torques; returns the motion's
/// metrics, its cycles' starts and its run-up ([`MechanismResult::cycle_starts`],
/// [`MechanismResult::runup`]).
#[allow(clippy::too_many_arguments)]
fn run_solved(
    case: &Case,
    (mechanism, setup): (&dyn Mechanism, &Setup),
    shift: f64,
    families: &[&dyn LoadFamily],
    gas: Option<GasAt>,
    stages: &mut [Box<dyn Stage>],
    mut sinks: Vec<&mut dyn Sink>,
) -> Result<(Metrics, RunUp), String> {
    // The solved motion: its states depend on the run's torques, so one thread takes them one
    // at a time.
    let d: &Dynamics = case.dynamics.as_ref().ok_or("not a solved motion")?;
    let torques = MachineTorques {
        mechanism,
        cylinders: setup.machine.phases(),
        gas,
        load: &d.load,
        flywheel: d.flywheel,
        friction: setup
            .losses
            .as_ref()
            .map(|budget| MotionFriction { budget, families }),
    };
    let run_spec = SolvedRun {
        start: case.motion.start_angle + shift,
        end: case.end_angle + shift,
        steps: case.steps,
        initial_speed: case.motion.initial_speed,
        cycles: d.cycles,
        steady_tolerance: d.steady_tolerance,
    };
    let solved = super::dynamic::solve(d, &torques, run_spec)?;
    let torques = MachineTorques {
        flywheel: solved.flywheel,
        ..torques
    };
    let mut motion = SolvedMotion::new(&torques, solved.run, &solved.cycles);
    let mut stages: Vec<&mut dyn Stage> = stages
        .iter_mut()
        .map(|s| &mut **s as &mut dyn Stage)
        .collect();
    run(
        mechanism,
        &mut motion,
        families,
        gas,
        &mut stages,
        &mut sinks,
    )
    .map_err(|e| e.to_string())?;
    let runup = RunUp {
        starts: solved.cycles.starts,
        series: solved.cycles.runup,
    };
    Ok((solved.metrics, runup))
}

/// What a solved motion's cycles give the outputs (empty for a prescribed motion).
#[derive(Default)]
struct RunUp {
    /// (time s, crank speed rad/s) at the start of every cycle it ran.
    starts: Vec<(f64, f64)>,
    /// (time s, crank speed rad/s) through the cycles before the reported one, thinned.
    series: Vec<(f64, f64)>,
}

/// A solved motion's metrics, by name (SI).
type Metrics = Vec<(&'static str, f64)>;

/// A train's load families: the bodies' inertia with the masses its crankshaft carries
/// (`PreparedBalance::crank_masses`), and the gas where the case has one.
struct TrainFamilies {
    inertial: Inertial,
    gas: Option<Gas>,
}

impl TrainFamilies {
    fn of(case: &Case, setup: &Setup) -> Self {
        let (inertial, gas) = setup.machine.load_families(case.gas.is_some());
        Self { inertial, gas }
    }

    fn list(&self) -> Vec<&dyn LoadFamily> {
        let mut families: Vec<&dyn LoadFamily> = vec![&self.inertial];
        families.extend(self.gas.as_ref().map(|g| g as &dyn LoadFamily));
        families
    }
}

/// The sinks every step of a train feeds: its summary, the charts' rows where they are taken
/// on their own (without files), and the steps counted for the progress display.
type SharedSinks<'a> = (SummarySink, (Option<ChartSink<'a>>, StepCounter));

/// The sinks a train's per-step rows are kept in, each if asked: the per-step files (which
/// record the charts' series too) or the columns in memory.
struct KeptSinks<'a> {
    per_step: Option<PerStepSink<'a>>,
    columns: Option<ColumnSink<'a>>,
}

impl KeptSinks<'_> {
    /// The one sink that keeps the rows, if any: the files before the columns.
    fn kept(&mut self) -> Option<&mut dyn Sink> {
        match (self.per_step.as_mut(), self.columns.as_mut()) {
            (Some(p), _) => Some(p),
            (None, Some(c)) => Some(c),
            (None, None) => None,
        }
    }
}

/// Runs one crank train of `case`: `mechanism` (its stages copied from its `setup`, which
/// validation built) with its crank `shift` (rad) ahead of the case's (the second train of a
/// phased opposed-piston case; 0 otherwise), its per-step rows (named `label`) where `to` says.
/// Both trains' pistons see the one chamber's pressure. With files and charts, it also records
/// the series of the report's charts (thinned as it steps, see `report/src/envelope.rs`) and
/// returns them, so that the report need not read the CSV back, nor the CSV exist.
fn run_mechanism(
    case: &Case,
    mechanism: &dyn Mechanism,
    setup: &Setup,
    shift: f64,
    label: &str,
    (to, rooms): (StepsTo, &RunRooms),
) -> Result<(Summary, Vec<String>, RunUp, TrainRows), String> {
    let own = TrainFamilies::of(case, setup);
    let families = own.list();
    let names: Vec<&'static str> = families.iter().map(|f| f.name()).collect();
    let mut stages = setup.stages();
    let listed: Vec<&dyn Stage> = stages.iter().map(|s| s.as_ref()).collect();
    let summary = SummarySink::new(mechanism, &names, case.steps + 1).with_stages(&listed);
    let columns: Vec<_> = stages.iter().map(|s| s.columns()).collect();
    let layout = RunLayout {
        families: &names,
        gas: case.gas.is_some(),
        stages: &columns,
    };
    let (mut sinks, mut kept) = open_sinks(case, mechanism, label, to, &layout, summary)?;
    // A coarse grid's peaks are checked by the same run on the grid shifted by a third and by
    // two thirds of a step (summaries only).
    let revolutions = (case.end_angle - case.motion.start_angle) / std::f64::consts::TAU;
    let per_rev = case.steps as f64 / revolutions;
    let check_sampling = per_rev < SAMPLING_CHECK_STEPS_PER_REV && case.dynamics.is_none();
    let mut shifted = Vec::new();
    let mut solved_metrics = Vec::new();
    let mut runup = RunUp::default();
    let mut steps = |gas: Option<GasAt>| {
        if case.dynamics.is_some() {
            let list = solved_sinks(&mut sinks, &mut kept);
            (solved_metrics, runup) = run_solved(
                case,
                (mechanism, setup),
                shift,
                &families,
                gas,
                &mut stages,
                list,
            )?;
            return Ok(());
        }
        let motion = run_kinematic(
            case,
            (mechanism, shift, rooms),
            &families,
            gas,
            &mut stages,
            &mut sinks,
            &mut kept,
        )?;
        if check_sampling {
            shifted.extend(shifted_peaks(
                case, mechanism, motion, &names, &families, gas,
            )?);
        }
        Ok::<(), String>(())
    };
    let gas_metrics = with_gas(case, mechanism, shift, &mut steps)?;
    let (summary, (chart_rows, _)) = sinks;
    let mut summary = finish_summary(case, mechanism, &summary, gas_metrics, &solved_metrics)?;
    push_solved(&mut summary, solved_metrics)?;
    let rows = finish_rows(kept, chart_rows)?;
    // What of the case this mechanism ignores, then the sampling check's.
    let warnings = setup
        .notes
        .iter()
        .cloned()
        .chain(sampling_warning(&summary, &shifted, case.steps, per_rev))
        .collect();
    Ok((summary, warnings, runup, rows))
}

/// Opens the sinks of one train's steps: `summary`, the per-step files or columns where `to`
/// says, and the charts' own rows when they are asked without files.
fn open_sinks<'a>(
    case: &Case,
    mechanism: &'a dyn Mechanism,
    label: &str,
    to: StepsTo,
    layout: &RunLayout,
    summary: SummarySink,
) -> Result<(SharedSinks<'a>, KeptSinks<'a>), String> {
    let (dir, charts) = to.files();
    let per_step = match dir {
        Some(dir) => PerStepSink::create(
            dir,
            label,
            mechanism,
            layout,
            case.output,
            case.steps,
            charts,
        )
        .map_err(|e| format!("{e:#}"))?,
        None => None,
    };
    let columns = matches!(to, StepsTo::Memory)
        .then(|| ColumnSink::new(mechanism, layout, case.output.decimation, case.steps));
    // Without files, the charts take their rows on their own, so that the run can be shared;
    // the steps are counted for the progress display.
    let chart_sink = (per_step.is_none() && charts)
        .then(|| ChartSink::new(mechanism, layout, case.output.decimation, case.steps, label));
    let sinks = (summary, (chart_sink, StepCounter));
    Ok((sinks, KeptSinks { per_step, columns }))
}

/// Every sink of a solved motion's steps, in the order they take each step: the summary,
/// the progress count, the per-step files, the charts' own rows, the columns.
fn solved_sinks<'s>(
    sinks: &'s mut SharedSinks<'_>,
    kept: &'s mut KeptSinks<'_>,
) -> Vec<&'s mut dyn Sink> {
    let mut list: Vec<&mut dyn Sink> = vec![&mut sinks.0, &mut sinks.1 .1];
    if let Some(p) = kept.per_step.as_mut() {
        list.push(p);
    }
    if let Some(c) = sinks.1 .0.as_mut() {
        list.push(c);
    }
    if let Some(c) = kept.columns.as_mut() {
        list.push(c);
    }
    list
}

/// Steps a train whose crank motion is given (`shift`, rad, ahead of the case's) into its
/// sinks, in blocks of `rooms` where the run is not shared, and returns that motion (the
/// sampling check steps it again on shifted grids).
fn run_kinematic(
    case: &Case,
    (mechanism, shift, rooms): (&dyn Mechanism, f64, &RunRooms),
    families: &[&dyn LoadFamily],
    gas: Option<GasAt>,
    stages: &mut [Box<dyn Stage>],
    sinks: &mut SharedSinks,
    kept: &mut KeptSinks,
) -> Result<CrankMotion, String> {
    let motion = CrankMotion {
        start_angle: case.motion.start_angle + shift,
        ..case.motion
    };
    let mut grid = Grid::new(
        motion,
        motion.start_angle,
        case.end_angle + shift,
        case.steps,
    );
    let mut stages: Vec<&mut dyn Stage> = stages
        .iter_mut()
        .map(|s| &mut **s as &mut dyn Stage)
        .collect();
    // Without rows kept the run is shared by the threads (the same results bit for bit);
    // the files are written in the steps' order, by a thread of their own.
    match kept.kept() {
        Some(p) => run(
            mechanism,
            &mut grid,
            families,
            gas,
            &mut stages,
            &mut [&mut sinks.0, &mut sinks.1 .1, p],
        ),
        None => rooms.run_parallel(mechanism, &mut grid, families, gas, &mut stages, sinks),
    }
    .map_err(|e| e.to_string())?;
    Ok(motion)
}

/// Closes a train's row sinks: the per-step files written out (their charts' series
/// returned), or the charts' own rows; the columns, if kept.
fn finish_rows(kept: KeptSinks, chart_rows: Option<ChartSink>) -> Result<TrainRows, String> {
    let charts = match kept.per_step {
        Some(p) => p
            .finish()
            .map_err(|e| format!("cannot write the per-step files: {e:#}"))?,
        None => chart_rows.and_then(ChartSink::finish),
    };
    Ok(TrainRows {
        charts,
        columns: kept.columns.map(ColumnSink::finish),
    })
}

/// Runs `steps` with the case's gas, if any, as the chamber's pressure at the first train's
/// crank angle (`shift`: this train's lead), and returns the gas model's metrics.
fn with_gas(
    case: &Case,
    mechanism: &dyn Mechanism,
    shift: f64,
    steps: &mut dyn FnMut(Option<GasAt>) -> Result<(), String>,
) -> Result<Vec<GasMetric>, String> {
    let Some(gas) = &case.gas else {
        steps(None)?;
        return Ok(Vec::new());
    };
    let failed = |e: cardan_gas::GasError| format!("gas.{e}");
    let cylinder = gas
        .cylinder(case.geometry.bore, mechanism.stroke(), case.pistons)
        .map_err(failed)?;
    cylinder.with_phased_chamber(mechanism, case.crank_phase, |chamber| {
        let prepared = gas
            .model()
            .prepare(*chamber, mean_speed(case))
            .map_err(failed)?;
        let at = ChamberGas {
            prepared: prepared.as_ref(),
            shift,
        };
        steps(Some(&at))?;
        Ok::<_, String>(prepared.metrics())
    })
}

/// A prepared gas model as a train's cylinder gas: the chamber's pressure is a function of
/// the first train's crank angle, `shift` (rad) behind this train's.
struct ChamberGas<'a> {
    prepared: &'a dyn PreparedGas,
    shift: f64,
}

impl CylinderGas for ChamberGas<'_> {
    fn at(&self, theta: f64) -> (f64, f64) {
        self.prepared.at(theta - self.shift)
    }

    /// The first train's block (no shift) gives the model its piston positions, where the
    /// model takes them ([`PreparedGas::lanes`]); otherwise [`CylinderGas::at`] at each lane.
    fn lanes(&self, states: &StateBlock, pressure: &mut Column, force: &mut Column) {
        let n = states.len.min(LANES);
        let taken = self.shift == 0.0
            && states.pistons.first().is_some_and(|piston| {
                let (p, f) = (&mut pressure[..n], &mut force[..n]);
                (self.prepared).lanes(&states.crank.angle[..n], &piston.position[..n], p, f)
            });
        if !taken {
            at_each_lane(self, states, pressure, force);
        }
    }
}

/// The solved motion's metrics into `summary`; refused if one is not finite.
fn push_solved(summary: &mut Summary, metrics: Vec<(&'static str, f64)>) -> Result<(), String> {
    for (name, value) in metrics {
        if !value.is_finite() {
            return Err(format!(
                "the solved motion's {name} is not finite ({value})"
            ));
        }
        summary.push(name, value);
    }
    Ok(())
}

/// The summary of `mechanism`'s run in `case` from its sink, with the gas model's metrics and,
/// with `[friction]`, the engine's (its correlation at the case's prescribed motion, or at the
/// `speed_mean` of a solved one's metrics `solved`); refused if a metric is not finite.
fn finish_summary(
    case: &Case,
    mechanism: &dyn Mechanism,
    sink: &SummarySink,
    gas_metrics: Vec<GasMetric>,
    solved: &[(&'static str, f64)],
) -> Result<Summary, String> {
    let solved_speed = solved.iter().find(|m| m.0 == "speed_mean").map(|m| m.1);
    let mut summary = sink.finish(mechanism)?;
    for m in gas_metrics {
        if !m.value.is_finite() {
            return Err(format!(
                "gas model metric {} is not finite ({})",
                m.name, m.value
            ));
        }
        summary.push(m.name, m.value);
    }
    if let Some(f) = &case.friction {
        // An engine's fmep and the whole-engine correlation beside it; PNH's correlation of a
        // solved motion at its mean speed (a steady run's speed).
        let motion = match solved_speed {
            Some(speed) => CrankMotion {
                initial_speed: speed,
                angular_acceleration: 0.0,
                ..case.motion
            },
            None => case.motion,
        };
        for (name, value) in cardan_dynamics::engine_metrics(
            f,
            mechanism,
            case.geometry.bore,
            &motion,
            case.end_angle,
            &summary,
        ) {
            summary.push(name, value);
        }
    }
    // Every metric written is finite: a peak or an integral of finite steps can still
    // overflow (a crank speed of 1e150 rad/s), and summary.json would hold a null.
    if let Some(m) = summary.metrics.iter().find(|m| !m.value.is_finite()) {
        return Err(format!(
            "the summary's {} is not finite ({}): the run's numbers overflow or are undefined",
            m.name, m.value
        ));
    }
    Ok(summary)
}

/// Runs every mechanism of a case (in parallel), writing their per-step files into `dir` if
/// given (as the case's `[output]` asks).
/// A failure names the file, the case, the mechanism, and the step and quantity that went
/// wrong.
pub fn run_case(case: &Case, dir: Option<&Path>) -> Result<Vec<MechanismResult>, String> {
    let to = match dir {
        Some(dir) => StepsTo::Files { dir, charts: false },
        None => StepsTo::Summary,
    };
    let trains = run_trains(case, to, &RunRooms::default())?;
    let results: Vec<MechanismResult> = trains.into_iter().map(|(r, _)| r).collect();
    log_warnings(case, &results);
    Ok(results)
}

/// A deliberate panic, for tests of what catches one (built with the feature `test-hooks`
/// only, which no user build enables: python/Cargo.toml's `test-hooks`, .ci/run's wheel).
#[cfg(feature = "test-hooks")]
pub mod test_hooks {
    use cardan_case::case::Case;

    /// The case name that makes a run panic inside a crank train (a rayon worker).
    pub const TEST_PANIC_CASE: &str = "cardan-test-hook-panic";

    /// Panics if `case` is named [`TEST_PANIC_CASE`].
    pub(crate) fn panic_if_asked(case: &Case) {
        if case.name == TEST_PANIC_CASE {
            panic!("a deliberate panic of the test hook (feature test-hooks)");
        }
    }
}

/// Logs each warning of `results`, the trains of `case` (a case run on its own; a table
/// sweep's points are summed up once for the sweep, `table.rs`).
pub(crate) fn log_warnings(case: &Case, results: &[MechanismResult]) {
    for r in results {
        for w in &r.warnings {
            tracing::warn!(
                "{}: case \"{}\": {}: {w}",
                case.file.display(),
                case.name,
                r.label
            );
        }
    }
}

/// [`run_case`], each crank train's per-step rows where `to` says, with its [`TrainRows`]; the
/// warnings are in each [`MechanismResult`], not logged ([`log_warnings`]).
pub(crate) fn run_trains(
    case: &Case,
    to: StepsTo,
    rooms: &RunRooms,
) -> Result<Vec<(MechanismResult, TrainRows)>, String> {
    // Each mechanism's crank train, and its second one in a phased opposed-piston case.
    let mut trains = Vec::new();
    for (m, setup) in case.mechanisms.iter().zip(&case.setups) {
        trains.push((m, setup, 0.0, m.name().to_string()));
        if case.crank_phase != 0.0 {
            trains.push((m, setup, case.crank_phase, format!("{}_crank2", m.name())));
        }
    }
    let results: Vec<Result<(MechanismResult, TrainRows), String>> = trains
        .par_iter()
        .map(|(m, setup, shift, label)| {
            #[cfg(feature = "test-hooks")]
            test_hooks::panic_if_asked(case);
            let (summary, warnings, runup, rows) =
                run_mechanism(case, m.as_ref(), setup, *shift, label, (to, rooms)).map_err(
                    |e| {
                        format!(
                            "{}: case \"{}\": {label}: {e}",
                            case.file.display(),
                            case.name
                        )
                    },
                )?;
            let result = MechanismResult {
                mechanism: Arc::clone(m),
                label: label.clone(),
                summary,
                warnings,
                cycle_starts: runup.starts,
                runup: runup.series,
            };
            Ok((result, rows))
        })
        .collect();
    // Every mechanism's failure, not only the first.
    let failures: Vec<String> = results
        .iter()
        .filter_map(|r| r.as_ref().err().cloned())
        .collect();
    if failures.is_empty() {
        Ok(results.into_iter().flatten().collect())
    } else {
        Err(failures.join("\n  "))
    }
}
