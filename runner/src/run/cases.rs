//! Finding and reading a batch's case files: every `*.toml` under the paths given, each
//! validated, one output folder per case or sweep; and the `--only` pattern.

use cardan_case::case::{self, Case};
use cardan_case::CaseError;
use rayon::prelude::*;
use std::path::{Path, PathBuf};

/// Every `*.toml` file under `paths` (files, or folders searched recursively), sorted, and a
/// message for each path that cannot be read.
pub fn case_files(paths: &[PathBuf]) -> (Vec<PathBuf>, Vec<String>) {
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
            failures.push(format!("{}: no such file or folder", p.display()));
        }
    }
    files.sort();
    files.dedup();
    (files, failures)
}

/// Names an output folder uses itself, which no case or sweep may take.
pub const RESERVED: &[&str] = &["index.html", "shard.json"];

/// Reads and validates every case under `paths`; failures are listed, not fatal. Two cases
/// with one name would write one folder: the second is a failure.
pub fn load_cases(paths: &[PathBuf]) -> (Vec<Case>, Vec<String>) {
    let (files, mut failures) = case_files(paths);
    let loaded: Vec<Result<Vec<Case>, CaseError>> =
        files.par_iter().map(|f| case::load_file(f)).collect();
    let mut cases: Vec<Case> = Vec::new();
    // Output folders taken: a case's name, or a sweep's (its points go inside it).
    let mut folders: std::collections::HashMap<String, PathBuf> = std::collections::HashMap::new();
    for result in loaded {
        let batch = match result {
            Ok(batch) => batch,
            Err(e) => {
                failures.push(e.to_string());
                continue;
            }
        };
        let Some(first) = batch.first() else { continue };
        let folder = first
            .sweep
            .as_ref()
            .map_or(first.name.clone(), |(s, _)| s.clone());
        if RESERVED.contains(&folder.as_str()) {
            failures.push(format!(
                "{}: case \"{}\": name = \"{folder}\": is reserved: the output folder's own file of that name ({}); give the case another name",
                first.file.display(),
                folder,
                RESERVED.join(", ")
            ));
            continue;
        }
        if let Some(other) = folders.get(&folder) {
            failures.push(format!(
                "{}: case \"{}\": name = \"{folder}\": is already the name of the case in {}; each case needs its own output folder",
                first.file.display(),
                folder,
                other.display()
            ));
            continue;
        }
        folders.insert(folder, first.file.clone());
        cases.extend(batch);
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
