//! `cardan merge`: the output folders of the N shards of one batch (`--shard K/N`) gathered
//! into what one run of the batch writes: each case's folder copied whole (its files
//! hard-linked where the file system allows), each sweep's folder
//! made of its points' folders with its `sweep.csv` (from the points' records, `run.json`)
//! and report, each sweep written as a table joined from its shards' ranges of points
//! (`table_merge.rs`), and the index. Shards of other inputs, another program or an incomplete set
//! are refused before anything is written.

use super::options::Report;
use super::shard::{Manifest, MANIFEST};
use super::stamp::{self, PROGRAM};
use super::sweeps::{sweep_csv, Point};
use super::table_merge;
use anyhow::Context;
use cardan_report::files;
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

/// Puts the folder `from` into the new folder `to`, file by file: each file hard-linked (the
/// same bytes, no copy: a merge's time and disk do not grow with the per-step files' size)
/// where `to` is on the same file system, else copied (another file system, or one without
/// hard links). Safe because nothing changes a written file in place: every case folder is
/// written anew and renamed onto the old one ([`files::replace_dir`]), so a later run or merge
/// into the shards or into `out` makes new files and leaves the linked ones as they were.
fn copy_dir(from: &Path, to: &Path) -> std::io::Result<()> {
    std::fs::create_dir_all(to)?;
    for entry in std::fs::read_dir(from)? {
        let entry = entry?;
        let target = to.join(entry.file_name());
        if entry.file_type()?.is_dir() {
            copy_dir(&entry.path(), &target)?;
        } else if std::fs::hard_link(entry.path(), &target).is_err() {
            std::fs::copy(entry.path(), &target)?;
        }
    }
    Ok(())
}

/// The shards' records, checked to be the N shards, each once, of one batch run by this
/// program; or why they cannot be merged.
fn manifests(dirs: &[PathBuf]) -> Result<Vec<Manifest>, String> {
    // A shard whose run was killed (time limit, node failure, cancelled) has no record yet:
    // its record is written last. Said as such, with what to do, rather than as a bad folder.
    let unfinished: Vec<String> = dirs
        .iter()
        .filter(|d| !d.join(MANIFEST).exists())
        .map(|d| d.display().to_string())
        .collect();
    if !unfinished.is_empty() {
        return Err(format!(
            "{}: no {MANIFEST}: the shard's run did not finish (killed, time limit, node failure, \
             cancelled), never started, or this is not a shard's output folder: run the shard \
             again (`cardan run ... --shard K/N --resume` keeps its finished cases; on Slurm \
             `sbatch --array=K run.sbatch`), then merge",
            unfinished.join(", ")
        ));
    }
    let mut all = Vec::new();
    for dir in dirs {
        all.push(Manifest::read(dir).map_err(|e| format!("{e:#}"))?);
    }
    let Some(first) = all.first() else {
        return Err("no shard folder given".into());
    };
    let n = first.shard.1;
    for (dir, m) in dirs.iter().zip(&all) {
        if m.program != PROGRAM {
            return Err(format!(
                "{}: written by {}, this is {PROGRAM}: run every shard with one program",
                dir.display(),
                m.program
            ));
        }
        if m.inputs_hash != first.inputs_hash
            || m.shard.1 != n
            || m.cases != first.cases
            || m.tables != first.tables
        {
            return Err(format!(
                "{} and {}: shards of different inputs (case files, options or shard count): they cannot be merged",
                dirs[0].display(),
                dir.display()
            ));
        }
    }
    let mut seen = vec![None; n];
    for (dir, m) in dirs.iter().zip(&all) {
        let k = m.shard.0;
        if k == 0 || k > n {
            return Err(format!("{}: shard {k} of {n}?", dir.display()));
        }
        if let Some(other) = seen[k - 1].replace(dir) {
            return Err(format!(
                "{} and {}: both are shard {k}/{n}",
                other.display(),
                dir.display()
            ));
        }
    }
    let missing: Vec<String> = (1..=n)
        .filter(|k| seen[k - 1].is_none())
        .map(|k| format!("{k}/{n}"))
        .collect();
    if !missing.is_empty() {
        return Err(format!("shard(s) {} missing", missing.join(", ")));
    }
    Ok(all)
}

/// `path` made absolute, its `.` and `..` taken lexically, and its longest existing part
/// resolved (symbolic links followed: [`std::fs::canonicalize`]), so that two names of one
/// folder compare equal, whether or not the rest of the path exists yet.
fn resolved(path: &Path) -> PathBuf {
    use std::path::Component;
    let absolute = std::env::current_dir()
        .map(|cwd| cwd.join(path))
        .unwrap_or_else(|_| path.to_path_buf());
    let mut lexical = PathBuf::new();
    for c in absolute.components() {
        match c {
            Component::CurDir => {}
            Component::ParentDir => {
                lexical.pop();
            }
            c => lexical.push(c),
        }
    }
    let mut existing = lexical.as_path();
    let mut rest = Vec::new();
    loop {
        if let Ok(real) = std::fs::canonicalize(existing) {
            return rest.iter().rev().fold(real, |p, c| p.join(c));
        }
        match (existing.parent(), existing.file_name()) {
            (Some(parent), Some(name)) => {
                rest.push(name.to_os_string());
                existing = parent;
            }
            _ => return lexical,
        }
    }
}

/// Refuses an output folder `out` that is one of the shards' folders `dirs`, inside one, or
/// holds one: the merge would write over the shards it reads.
fn apart(dirs: &[PathBuf], out: &Path) -> Result<(), String> {
    let o = resolved(out);
    for dir in dirs {
        let d = resolved(dir);
        let how = if o == d {
            "is"
        } else if o.starts_with(&d) {
            "is inside"
        } else if d.starts_with(&o) {
            "contains"
        } else {
            continue;
        };
        return Err(format!(
            "--out {} {how} the shard folder {}: the merge would write over the shards it \
             reads: choose an --out outside every shard folder",
            out.display(),
            dir.display()
        ));
    }
    Ok(())
}

/// Refuses shards that lost what they ran: every case (and sweep point) a shard's record
/// lists must have its complete folder in that shard ([`stamp::incomplete`]: present, its
/// record readable, its files those the record lists with their sizes), unless the shard
/// lists its failure (a case that failed has no folder). Checked before anything is written;
/// each loss named with its case, sweep and shard.
fn lost(all: &[Manifest], by_shard: &[&Path]) -> Result<(), String> {
    let first = &all[0];
    let mut losses = Vec::new();
    for (name, sweep, k) in &first.cases {
        let shard = by_shard[k - 1];
        let dir = match sweep {
            Some(s) => shard.join(s).join(name),
            None => shard.join(name),
        };
        let Some(why) = stamp::incomplete(&dir) else {
            continue;
        };
        let failed = format!("case \"{name}\":");
        let listed = all.iter().filter(|m| m.shard.0 == *k);
        if listed
            .flat_map(|m| &m.failures)
            .any(|f| f.contains(&failed))
        {
            continue;
        }
        let point = match sweep {
            Some(s) => format!(" (a point of sweep \"{s}\")"),
            None => String::new(),
        };
        losses.push(format!(
            "case \"{name}\"{point} of shard {k}/{} ({}): {}: {why}",
            first.shard.1,
            shard.display(),
            dir.display()
        ));
    }
    if losses.is_empty() {
        return Ok(());
    }
    Err(format!(
        "{}: the shard ran the case and lists no failure of it, but its folder is not the one \
         its run wrote (deleted, truncated or changed since): run the shard again (`cardan run \
         ... --shard K/N --resume` runs only what is missing), then merge",
        losses.join("; ")
    ))
}

/// Merges the output folders `dirs` of the shards of one batch into `out`, which then holds
/// byte for byte what one run of the batch writes. The failures of the shards are the
/// merge's; a refusal (shards that do not belong together) writes nothing.
pub fn merge(dirs: &[PathBuf], out: &Path) -> Report {
    let mut report = Report::default();
    if let Err(e) = apart(dirs, out) {
        report.failures.push(format!("cannot merge: {e}"));
        return report;
    }
    let all = match manifests(dirs) {
        Ok(all) => all,
        Err(e) => {
            report.failures.push(format!("cannot merge: {e}"));
            return report;
        }
    };
    // Each shard's folder by its K.
    let mut by_shard: Vec<&Path> = vec![Path::new(""); all.len()];
    for (dir, m) in dirs.iter().zip(&all) {
        by_shard[m.shard.0 - 1] = dir;
    }
    // The tables' parts, each range of points once: checked before anything is written.
    let mut tables = Vec::new();
    for (sweep, points, ranges) in &all[0].tables {
        match table_merge::parts(sweep, *points, ranges, &by_shard) {
            Ok(parts) => tables.push((sweep, parts)),
            Err(e) => {
                report.failures.push(format!("cannot merge: {e}"));
                return report;
            }
        }
    }
    if let Err(e) = lost(&all, &by_shard) {
        report.failures.push(format!("cannot merge: {e}"));
        return report;
    }
    for m in &all {
        for f in &m.failures {
            if !report.failures.contains(f) {
                report.failures.push(f.clone());
            }
        }
    }
    if let Err(e) = std::fs::create_dir_all(out) {
        report
            .failures
            .push(format!("--out {}: cannot create: {e}", out.display()));
        return report;
    }
    files::remove_stale_temporaries(out);
    let first = &all[0];
    let mut sweeps: BTreeMap<&str, Vec<(&str, &Path)>> = BTreeMap::new();
    for (name, sweep, k) in &first.cases {
        let shard = by_shard[k - 1];
        match sweep {
            Some(s) => sweeps.entry(s).or_default().push((name, shard)),
            None => copy_case(name, shard, out, &mut report),
        }
    }
    merge_tables(tables, out, &mut report);
    merge_sweeps(sweeps, out, first.reports, &mut report);
    report.write_index(out, first.reports);
    report
}

/// Copies a case run outside any sweep from its `shard`'s folder into `out`, replaced whole,
/// into `report`; a case the shard could not run is skipped (its failure is listed).
fn copy_case(name: &str, shard: &Path, out: &Path, report: &mut Report) {
    let from = shard.join(name);
    // A case the shard could not run has no complete folder: its failure is listed.
    if !stamp::read(&from).is_some_and(|r| r.complete) {
        return;
    }
    let dir = out.join(name);
    let copied = files::temporary_dir(&dir).and_then(|tmp| {
        copy_dir(&from, &tmp)
            .with_context(|| format!("copy {}", from.display()))
            .and_then(|()| files::replace_dir(&tmp, &dir))
            .inspect_err(|_| {
                let _ = std::fs::remove_dir_all(&tmp);
            })
    });
    match copied {
        Ok(()) => report.written.push((name.to_string(), dir)),
        Err(e) => report.failures.push(format!(
            "case \"{name}\": cannot write {}: {e:#}",
            dir.display()
        )),
    }
}

/// Writes each sweep run as a table into `out` from its shards' `parts`, into `report`.
fn merge_tables(tables: Vec<(&String, Vec<table_merge::Part>)>, out: &Path, report: &mut Report) {
    for (sweep, parts) in tables {
        // A sweep written as a table: its shards' ranges of points joined.
        let dir = out.join(sweep);
        match table_merge::merge_table(sweep, &parts, &dir) {
            Ok(0) => {}
            Ok(ran) => report.sweeps.push((sweep.clone(), dir, ran)),
            Err(e) => report.failures.push(format!(
                "sweep \"{sweep}\": cannot write its table to {}: {e:#}",
                dir.display()
            )),
        }
    }
}

/// Gathers each sweep's points (each with its shard's folder) into `out`, with its report if
/// `reports`, into `report`.
fn merge_sweeps(
    sweeps: BTreeMap<&str, Vec<(&str, &Path)>>,
    out: &Path,
    reports: bool,
    report: &mut Report,
) {
    for (sweep, points) in sweeps {
        let dir = out.join(sweep);
        match merge_sweep(sweep, &points, &dir, reports) {
            Ok(written) if written.is_empty() => {}
            Ok(written) => {
                report
                    .sweeps
                    .push((sweep.to_string(), dir.clone(), written.len()));
                for p in written {
                    report.written.push((p.to_string(), dir.join(p)));
                }
            }
            Err(e) => report.failures.push(format!(
                "sweep \"{sweep}\": cannot write results to {}: {e:#}",
                dir.display()
            )),
        }
    }
}

/// Gathers the sweep's `points` (each in its shard's folder of the sweep) into `dir`, replaced
/// whole, with `sweep.csv` and, if `reports`, the sweep's report; the points gathered. A sweep
/// none of whose points was written is not written (an earlier folder stays, as in a run).
fn merge_sweep<'a>(
    sweep: &str,
    points: &[(&'a str, &Path)],
    dir: &Path,
    reports: bool,
) -> anyhow::Result<Vec<&'a str>> {
    let tmp = files::temporary_dir(dir)?;
    let result = (|| {
        let mut rows = Vec::new();
        for (name, shard) in points {
            let from = shard.join(sweep).join(name);
            let Some(record) = stamp::read(&from).filter(|r| r.complete) else {
                continue;
            };
            copy_dir(&from, &tmp.join(name)).with_context(|| format!("copy {}", from.display()))?;
            rows.push((*name, record));
        }
        if rows.is_empty() {
            return Ok(Vec::new());
        }
        let table: Vec<Point> = rows
            .iter()
            .map(|(name, r)| (*name, &r.sweep_values[..], &r.metrics[..]))
            .collect();
        files::write_file(&tmp.join("sweep.csv"), sweep_csv(&table).as_bytes())?;
        if reports {
            cardan_report::sweep_report(&tmp, sweep, None).context("the sweep report")?;
        }
        files::replace_dir(&tmp, dir)?;
        Ok(rows.into_iter().map(|(name, _)| name).collect())
    })();
    if !matches!(&result, Ok(w) if !w.is_empty()) {
        let _ = std::fs::remove_dir_all(&tmp);
    }
    result
}
