//! Running cases: every mechanism of every case in parallel; one failure never stops the rest.

use crate::case::{self, Case, CaseError, MechanismCase};
use crate::output;
use cardan_dynamics::{run_cycle, Step, Summary};
use rayon::prelude::*;
use std::path::{Path, PathBuf};

/// The run of one mechanism of a case.
#[derive(Debug, Clone)]
pub struct MechanismRun {
    pub case: MechanismCase,
    pub steps: Vec<Step>,
    pub summary: Summary,
}

/// Runs every mechanism of a case (in parallel).
pub fn run_case(case: &Case) -> Vec<MechanismRun> {
    let grid = case
        .motion
        .grid(case.motion.start_angle, case.end_angle, case.steps)
        .expect("validation checked that the crank reaches end_angle");
    case.mechanisms
        .par_iter()
        .map(|m| {
            let steps = run_cycle(m.mechanism(), &m.masses, &grid, |_| 0.0);
            let summary = Summary::of_cycle(m.mechanism(), &m.masses, &steps);
            MechanismRun {
                case: m.clone(),
                steps,
                summary,
            }
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
            let runs = run_case(case);
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
