//! Finding and reading a batch's case files: every `*.toml` under the paths given, each
//! validated, one output folder per case or sweep; and the `--only` pattern.

use super::table::{case_folders, TableSweep};
use cardan_case::case::{self, Case};
use cardan_case::optimize::Optimization;
use cardan_case::sweep::{Sweep, MAX_EXPANDED};
use cardan_case::CaseError;
use rayon::prelude::*;
use std::path::{Path, PathBuf};
use std::sync::Arc;

/// Every `*.toml` file under `paths` (files, or folders searched recursively), sorted, and a
/// message for each path that cannot be read.
///
/// A symbolic link to a folder found inside a folder is not followed (as `find` does not):
/// a folder linking to itself or to a parent would otherwise be searched without end, and a
/// link to a folder elsewhere would bring cases from outside the folder given. A link to a
/// file is read as the file; a path given on the command line is followed whatever it is.
pub fn case_files(paths: &[PathBuf]) -> (Vec<PathBuf>, Vec<String>) {
    fn walk(dir: &Path, out: &mut Vec<PathBuf>) -> std::io::Result<()> {
        for entry in std::fs::read_dir(dir)? {
            let entry = entry?;
            let path = entry.path();
            let kind = entry.file_type()?;
            if kind.is_dir() {
                walk(&path, out)?;
            } else if kind.is_symlink() && path.is_dir() {
                // Not followed (see above).
            } else if path.extension().is_some_and(|e| e == "toml") {
                out.push(path);
            }
        }
        Ok(())
    }
    let mut files = Vec::new();
    let mut failures = Vec::new();
    for p in paths {
        if p.is_dir() {
            let before = files.len();
            if let Err(e) = walk(p, &mut files) {
                failures.push(format!("{}: cannot list: {e}", p.display()));
            } else if files.len() == before {
                failures.push(format!(
                    "{}: no *.toml case files in this folder",
                    p.display()
                ));
            }
        } else if p.is_file() {
            files.push(p.clone());
        } else {
            match std::fs::metadata(p) {
                // A FIFO, a device (`/dev/zero`), a socket: there, but nothing to read.
                Ok(meta) => failures.push(format!(
                    "{}: cannot read: not a regular file ({})",
                    p.display(),
                    cardan_report::files::kind_of(&meta)
                )),
                Err(e) if e.kind() == std::io::ErrorKind::NotFound => {
                    failures.push(format!("{}: no such file or folder", p.display()))
                }
                Err(e) => failures.push(format!("{}: cannot read: {e}", p.display())),
            }
        }
    }
    files.sort();
    files.dedup();
    (files, failures)
}

/// Names an output folder uses itself, which no case or sweep may take.
pub const RESERVED: &[&str] = &["index.html", "shard.json"];

/// A batch's cases as read: the cases run into folders of their own (single cases, and the
/// points of sweeps written as case folders, all validated), and the sweeps written as tables
/// (their points made and validated when they run).
#[derive(Debug, Default)]
pub struct Batch {
    pub cases: Vec<Case>,
    pub tables: Vec<TableSweep>,
    /// The case files with an `[optimize]` table (`crate::optimize`), each into its folder.
    pub optimizations: Vec<Optimization>,
}

/// What one case file holds: its cases, or a sweep written as a table.
enum Entry {
    Cases(Vec<Case>),
    Table(Box<TableSweep>),
    Optimize(Box<Optimization>),
}

impl Entry {
    /// The output folder it takes (a case's name, or its sweep's) and its file.
    fn folder(&self) -> Option<(String, PathBuf)> {
        match self {
            Entry::Cases(cases) => cases.first().map(|c| {
                let folder = c.sweep.as_ref().map_or(c.name.clone(), |(s, _)| s.clone());
                (folder, c.file.clone())
            }),
            Entry::Table(t) => Some((t.sweep.name.clone(), t.sweep.file.clone())),
            Entry::Optimize(o) => Some((o.name.clone(), o.file.clone())),
        }
    }
}

/// Reads the case file `file`: a case; a sweep's points validated, if it writes a folder per
/// point ([`case_folders`]: at most [`MAX_EXPANDED`] of them); or a sweep written as a table,
/// its definition and its first point validated.
fn load_entry(file: &Path) -> Result<Entry, CaseError> {
    let text = case::read_case_text(file)?;
    let table = case::toml_table(file, &text)?;
    if let Some(o) = Optimization::define(file, table.clone())? {
        // What the run refuses, the check refuses: a metric no mechanism reports.
        crate::optimize::check_metrics(&o)?;
        return Ok(Entry::Optimize(Box::new(o)));
    }
    let Some(sweep) = Sweep::define(file, table.clone())? else {
        return Ok(Entry::Cases(vec![case::case_of_table(file, table)?]));
    };
    let first = case::point_case(&sweep, 0)?;
    let n = sweep.len();
    if !case_folders(&first, n) {
        return Ok(Entry::Table(Box::new(TableSweep {
            sweep: Arc::new(sweep),
            first,
            selected: None,
            range: None,
        })));
    }
    if n > MAX_EXPANDED {
        return Err(CaseError::Invalid {
            file: file.into(),
            case: sweep.name.clone(),
            field: "output.case_folders".into(),
            value: format!("true, for a sweep of {n} points"),
            rule: format!("a sweep writes a case folder per point up to {MAX_EXPANDED} points: write it as a table (case_folders = false)"),
        });
    }
    let points: Vec<Case> = (1..n)
        .into_par_iter()
        .map(|k| case::point_case(&sweep, k))
        .collect::<Result<_, _>>()?;
    Ok(Entry::Cases(std::iter::once(first).chain(points).collect()))
}

/// Reads and validates every case under `paths`, the sweeps written as tables apart (see
/// [`Batch`]); failures are listed, not fatal. Two cases or sweeps with one name would write
/// one folder: the second is a failure.
pub fn load_batch(paths: &[PathBuf]) -> (Batch, Vec<String>) {
    let (files, mut failures) = case_files(paths);
    let loaded: Vec<Result<Entry, CaseError>> = files.par_iter().map(|f| load_entry(f)).collect();
    let mut batch = Batch::default();
    // Output folders taken: a case's name, or a sweep's (its points go inside it).
    let mut folders: std::collections::HashMap<String, PathBuf> = std::collections::HashMap::new();
    for result in loaded {
        let entry = match result {
            Ok(entry) => entry,
            Err(e) => {
                failures.push(e.to_string());
                continue;
            }
        };
        let Some((folder, file)) = entry.folder() else {
            continue;
        };
        if RESERVED.contains(&folder.as_str()) {
            failures.push(format!(
                "{}: case \"{}\": name = \"{folder}\": is reserved: the output folder's own file of that name ({}); give the case another name",
                file.display(),
                folder,
                RESERVED.join(", ")
            ));
            continue;
        }
        if let Some(other) = folders.get(&folder) {
            failures.push(format!(
                "{}: case \"{}\": name = \"{folder}\": is already the name of the case in {}; each case needs its own output folder",
                file.display(),
                folder,
                other.display()
            ));
            continue;
        }
        folders.insert(folder, file);
        match entry {
            Entry::Cases(cases) => batch.cases.extend(cases),
            Entry::Table(t) => batch.tables.push(*t),
            Entry::Optimize(o) => batch.optimizations.push(*o),
        }
    }
    (batch, failures)
}

/// Reads and validates every case under `paths`, every sweep's points made and validated
/// (those of sweeps written as tables too, at most [`MAX_EXPANDED`] a sweep: for tests and
/// small batches; a run reads them with [`load_batch`]); failures are listed, not fatal.
pub fn load_cases(paths: &[PathBuf]) -> (Vec<Case>, Vec<String>) {
    let (batch, mut failures) = load_batch(paths);
    let mut cases = batch.cases;
    for t in batch.tables {
        if t.sweep.len() > MAX_EXPANDED {
            failures.push(format!(
                "{}: sweep \"{}\": {} points: at most {MAX_EXPANDED} made at once",
                t.sweep.file.display(),
                t.sweep.name,
                t.sweep.len()
            ));
            continue;
        }
        let points: Result<Vec<Case>, CaseError> = (0..t.sweep.len())
            .into_par_iter()
            .map(|k| case::point_case(&t.sweep, k))
            .collect();
        match points {
            Ok(points) => cases.extend(points),
            Err(e) => failures.push(e.to_string()),
        }
    }
    (cases, failures)
}

/// Whether `name` matches `pattern`: `*` matches any run of characters; a pattern without `*`
/// matches any name that contains it.
pub fn matches_pattern(pattern: &str, name: &str) -> bool {
    if !pattern.contains('*') {
        return name.contains(pattern);
    }
    let parts: Vec<&str> = pattern.split('*').collect();
    let (first, last) = (parts[0], parts[parts.len() - 1]);
    if !name.starts_with(first) || !name[first.len()..].ends_with(last) {
        return false;
    }
    let mut rest = &name[first.len()..name.len() - last.len()];
    for middle in &parts[1..parts.len() - 1] {
        match rest.find(middle) {
            Some(k) => rest = &rest[k + middle.len()..],
            None => return false,
        }
    }
    true
}

#[cfg(test)]
mod tests {
    use super::matches_pattern;

    #[test]
    fn patterns_select_case_names() {
        assert!(matches_pattern("w30pi", "karhula-pump-r60-l140-a0-w30pi"));
        assert!(!matches_pattern("w3pi", "karhula-pump-r60-l140-a0-w30pi"));
        assert!(matches_pattern(
            "karhula-*-w3pi",
            "karhula-pump-r60-l140-a0-w3pi"
        ));
        assert!(matches_pattern("*", "anything"));
        assert!(matches_pattern("k*a*i", "karhula-pi"));
        assert!(!matches_pattern("karhula-*-w3pi", "karhula-pump-w30pi"));
        assert!(!matches_pattern("nunes*", "karhula"));
    }
}
