//! Running cases: every mechanism of every case in parallel; one failure never stops the rest.

use crate::case::{self, Case, CaseError, MechanismCase};
use crate::output;
use cardan_dynamics::{run_cycle, Step, Summary};
use cardan_gas::GasCycle;
use cardan_mechanism::CrankState;
use rayon::prelude::*;
use std::path::{Path, PathBuf};

/// The run of one mechanism of a case.
#[derive(Debug, Clone)]
pub struct MechanismRun {
    pub case: MechanismCase,
    pub steps: Vec<Step>,
    /// The gas on the same crank-angle grid, if the case has a `[gas]` table.
    pub gas: Option<GasCycle>,
    pub summary: Summary,
}

/// The gas of `case` on the volume curve of mechanism `m`, at the crank angles of `grid`.
fn gas_cycle(
    case: &Case,
    m: &MechanismCase,
    grid: &[CrankState],
) -> Result<Option<GasCycle>, String> {
    let Some(gas) = &case.gas else {
        return Ok(None);
    };
    let mech = m.mechanism();
    let failed = |e: cardan_gas::GasError| {
        format!(
            "{}: case \"{}\": {}: gas.{e}",
            case.file.display(),
            case.name,
            m.kind.name()
        )
    };
    let cylinder = gas
        .cylinder(case.geometry.bore, mech.stroke(), case.geometry.pistons)
        .map_err(failed)?;
    let angles: Vec<f64> = grid.iter().map(|g| g.angle).collect();
    // The mean crank speed over the run: the speed of a steady run.
    let (first, last) = (&grid[0], &grid[grid.len() - 1]);
    let speed = if last.time > first.time {
        (last.angle - first.angle) / (last.time - first.time)
    } else {
        first.speed
    };
    cylinder
        .with_chamber(mech, |chamber| gas.model().cycle(chamber, speed, &angles))
        .map(Some)
        .map_err(failed)
}

/// Runs every mechanism of a case (in parallel). A gas model that cannot run on a mechanism
/// fails the case with a message naming the file, the case and the mechanism.
pub fn run_case(case: &Case) -> Result<Vec<MechanismRun>, String> {
    let grid = case
        .motion
        .grid(case.motion.start_angle, case.end_angle, case.steps)
        .expect("validation checked that the crank reaches end_angle");
    case.mechanisms
        .par_iter()
        .map(|m| {
            let gas = gas_cycle(case, m, &grid)?;
            let forces = gas.as_ref().map(|g| g.piston_force.as_slice());
            let steps = run_cycle(m.mechanism(), &m.masses, &grid, forces);
            let mut summary = Summary::of_cycle(m.mechanism(), &m.masses, &steps);
            if let Some(g) = &gas {
                let p_max = g.pressure.iter().copied().fold(f64::NEG_INFINITY, f64::max);
                summary.push("cylinder_pressure_max", "Pa", p_max);
                for metric in &g.metrics {
                    summary.push(metric.name, metric.unit, metric.value);
                }
            }
            Ok(MechanismRun {
                case: m.clone(),
                steps,
                gas,
                summary,
            })
        })
        .collect()
}

/// What a batch did.
#[derive(Debug, Default)]
pub struct Report {
    /// Cases run and written: (case name, output folder).
    pub written: Vec<(String, PathBuf)>,
    /// Each failure: a case file that could not be read or validated, or a case whose
    /// outputs could not be written.
    pub failures: Vec<String>,
}

/// Every `*.toml` file under `paths` (files, or folders searched recursively), sorted.
pub fn case_files(paths: &[PathBuf]) -> Result<Vec<PathBuf>, String> {
    fn walk(dir: &Path, out: &mut Vec<PathBuf>) -> std::io::Result<()> {
        for entry in std::fs::read_dir(dir)? {
            let path = entry?.path();
            if path.is_dir() {
                walk(&path, out)?;
            } else if path.extension().is_some_and(|e| e == "toml") {
                out.push(path);
            }
        }
        Ok(())
    }
    let mut files = Vec::new();
    for p in paths {
        if p.is_dir() {
            walk(p, &mut files).map_err(|e| format!("{}: cannot list: {e}", p.display()))?;
        } else if p.is_file() {
            files.push(p.clone());
        } else {
            return Err(format!("{}: no such file or folder", p.display()));
        }
    }
    files.sort();
    files.dedup();
    Ok(files)
}

/// Loads, validates, runs and writes every case under `paths` into `out/<case name>/`.
pub fn run_paths(paths: &[PathBuf], out: &Path) -> Result<Report, String> {
    let files = case_files(paths)?;
    if files.is_empty() {
        return Err(format!(
            "no *.toml case files under {}",
            paths
                .iter()
                .map(|p| p.display().to_string())
                .collect::<Vec<_>>()
                .join(", ")
        ));
    }
    let loaded: Vec<Result<Case, CaseError>> = files.par_iter().map(|f| case::load(f)).collect();
    let mut report = Report::default();
    let mut cases: Vec<Case> = Vec::new();
    for result in loaded {
        match result {
            Ok(case) => match cases.iter().find(|c| c.name == case.name) {
                Some(first) => report.failures.push(format!(
                    "{}: case \"{}\": name = \"{}\": is already the name of the case in {}; each case needs its own output folder",
                    case.file.display(),
                    case.name,
                    case.name,
                    first.file.display()
                )),
                None => cases.push(case),
            },
            Err(e) => report.failures.push(e.to_string()),
        }
    }
    let outcomes: Vec<Result<(String, PathBuf), String>> = cases
        .par_iter()
        .map(|case| {
            let _span = tracing::info_span!("case", name = %case.name).entered();
            let runs = run_case(case)?;
            let dir = out.join(&case.name);
            output::write_case(&dir, case, &runs)
                .map(|()| (case.name.clone(), dir.clone()))
                .map_err(|e| {
                    format!(
                        "{}: case \"{}\": cannot write results to {}: {e:#}",
                        case.file.display(),
                        case.name,
                        dir.display()
                    )
                })
        })
        .collect();
    for o in outcomes {
        match o {
            Ok(w) => {
                tracing::info!(case = %w.0, folder = %w.1.display(), "written");
                report.written.push(w);
            }
            Err(e) => report.failures.push(e),
        }
    }
    Ok(report)
}
