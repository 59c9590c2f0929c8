//! A case folder's record of what made it (`run.json`): the program and its version, a hash of
//! the case's validated input, the files the folder holds with their sizes, and, for a sweep's
//! point, its row of the sweep table. Written last into the temporary folder that then
//! replaces the case's folder whole, so a folder holding it is complete. `--resume` keeps a
//! folder whose record matches the case and the program ([`reusable`]); `cardan merge` reads
//! the sweep rows of the shards' points from it.

use crate::output::MechanismResult;
use cardan_case::case::Case;
use cardan_case::optimize::Optimization;
use cardan_report::files::{read_text, RESULT_RECORD};
use serde_json::{json, Value};
use std::path::{Path, PathBuf};

/// The record's file name in a case folder.
pub const STAMP: &str = "run.json";

/// The program and its version (Cargo's package version of the workspace), as recorded.
pub const PROGRAM: &str = concat!("cardan ", env!("CARGO_PKG_VERSION"));

/// One summary metric of a sweep point: (crank train label, metric name, the number as
/// `sweep.csv` writes it).
pub type Cell = (String, String, String);

pub use cardan_case::digest::Fnv;

/// The hash of `case`'s input as it runs (after the command line's overrides of its
/// `[output]`), and whether its folder holds a report: the program and its version, the
/// digest of the case's whole input ([`Case::input_digest`]: its typed document, serialized,
/// and the bytes of every file it reads), and its whole validated form, except the path of its
/// file (a case moved or run from another folder is the same case) and its setups (made from
/// the rest: their form holds scratch room for the run). The validated form is the program's
/// own (`Debug`); it holds the command line's overrides.
pub fn input_hash(case: &Case, report: bool) -> String {
    let case = Case {
        file: PathBuf::new(),
        setups: Vec::new(),
        ..case.clone()
    };
    Fnv::default()
        .update(PROGRAM.as_bytes())
        .update(case.input_digest.hex().as_bytes())
        .update(format!("{case:?}").as_bytes())
        .update(if report { b"report" } else { b"no report" })
        .hex()
}

/// A sweep point's row of the sweep table: every metric of every crank train, in order, or
/// those of `only` (`[output] metrics`).
pub fn cells(results: &[MechanismResult], only: Option<&[String]>) -> Vec<Cell> {
    let mut buffer = zmij::Buffer::new();
    results
        .iter()
        .flat_map(|r| {
            r.summary
                .metrics
                .iter()
                .filter(|m| only.is_none_or(|o| o.contains(&m.name)))
                .map(|m| (r.label.clone(), m.name.clone(), m.value))
                .collect::<Vec<_>>()
        })
        .map(|(label, name, v)| (label, name, buffer.format(v).to_string()))
        .collect()
}

/// Every file under `dir` (its path relative to `dir`, with `/`) and its size, sorted, except
/// the record itself.
fn listing(dir: &Path) -> std::io::Result<Vec<(String, u64)>> {
    fn walk(dir: &Path, prefix: &str, out: &mut Vec<(String, u64)>) -> std::io::Result<()> {
        for entry in std::fs::read_dir(dir)? {
            let entry = entry?;
            let name = format!("{prefix}{}", entry.file_name().to_string_lossy());
            let meta = entry.metadata()?;
            if meta.is_dir() {
                walk(&entry.path(), &format!("{name}/"), out)?;
            } else if name != STAMP {
                out.push((name, meta.len()));
            }
        }
        Ok(())
    }
    let mut out = Vec::new();
    walk(dir, "", &mut out)?;
    out.sort();
    Ok(out)
}

/// The hash of an optimisation's input (`[optimize]`, issue 40), and whether its folder holds
/// the reports: the program and its version, its whole validated definition except the path
/// of its file (the case table it varies, its objective, variables, constraints and search
/// settings), and the digest of each mechanism's case as the file gives it
/// ([`Case::input_digest`]: the bytes of every file it reads too). A case file that cannot be
/// validated any more hashes its error, so that its folder is never taken as current.
pub fn optimization_hash(o: &Optimization, report: bool) -> String {
    let mut hash = Fnv::default();
    hash.update(PROGRAM.as_bytes())
        .update(o.definition().as_bytes());
    for m in &o.mechanisms {
        match o.case_at(m, &vec![None; o.variables.len()]) {
            Ok(case) => hash.update(case.input_digest.hex().as_bytes()),
            Err(e) => hash.update(e.to_string().as_bytes()),
        };
    }
    hash.update(if report { b"report" } else { b"no report" })
        .hex()
}

/// Writes the record of `case` into its finished temporary folder `dir` (every other file
/// already written).
pub fn write(dir: &Path, case: &Case, report: bool, cells: &[Cell]) -> anyhow::Result<()> {
    let row = case
        .sweep
        .as_ref()
        .map(|(_, values)| (json!(values), json!(cells)));
    write_record(dir, input_hash(case, report), row)
}

/// Writes the record of the optimisation `o` into its finished temporary folder `dir` (every
/// other file already written): what `--resume` and `cardan merge` read of its folder, as of a
/// case's.
pub fn write_optimization(dir: &Path, o: &Optimization, report: bool) -> anyhow::Result<()> {
    write_record(dir, optimization_hash(o, report), None)
}

/// Writes the record of `dir`: the program, `hash`, the files of `dir`, and a sweep point's
/// values and row.
fn write_record(dir: &Path, hash: String, row: Option<(Value, Value)>) -> anyhow::Result<()> {
    let files: serde_json::Map<String, Value> = listing(dir)?
        .into_iter()
        .map(|(name, size)| (name, json!(size)))
        .collect();
    let mut record = json!({
        "program": PROGRAM,
        "input_hash": hash,
        "files": files,
    });
    if let Some((values, cells)) = row {
        record["sweep_values"] = values;
        record["metrics"] = cells;
    }
    let mut text = serde_json::to_string(&record)?;
    text.push('\n');
    cardan_report::files::write_file(&dir.join(STAMP), text.as_bytes())
}

/// A case folder's record as read back.
#[derive(Debug, Clone, PartialEq)]
pub struct Record {
    pub program: String,
    pub input_hash: String,
    /// The value of each swept field (a sweep's point).
    pub sweep_values: Vec<(String, String)>,
    /// Its row of the sweep table (a sweep's point).
    pub metrics: Vec<Cell>,
    /// Whether the files the record lists are the folder's, with their sizes.
    pub complete: bool,
}

/// Reads the record of the case folder `dir`; None if it has none or it cannot be read.
pub fn read(dir: &Path) -> Option<Record> {
    let text = read_text(&dir.join(STAMP), RESULT_RECORD).ok()?;
    let v: Value = serde_json::from_str(&text).ok()?;
    let strings = |v: &Value| -> Option<Vec<String>> {
        v.as_array()?
            .iter()
            .map(|s| s.as_str().map(String::from))
            .collect()
    };
    // Sorted by name, as the listing is (a JSON object's keys are read back sorted).
    let listed: Option<Vec<(String, u64)>> = v["files"]
        .as_object()?
        .iter()
        .map(|(name, size)| Some((name.clone(), size.as_u64()?)))
        .collect();
    let complete = listing(dir).ok() == Some(listed?);
    let sweep_values = match v.get("sweep_values") {
        None => Vec::new(),
        Some(values) => values
            .as_array()?
            .iter()
            .map(|p| Some((p[0].as_str()?.to_string(), p[1].as_str()?.to_string())))
            .collect::<Option<_>>()?,
    };
    let metrics = match v.get("metrics") {
        None => Vec::new(),
        Some(values) => values
            .as_array()?
            .iter()
            .map(|c| {
                let c = strings(c)?;
                let [a, b, t] = <[String; 3]>::try_from(c).ok()?;
                Some((a, b, t))
            })
            .collect::<Option<_>>()?,
    };
    Some(Record {
        program: v["program"].as_str()?.to_string(),
        input_hash: v["input_hash"].as_str()?.to_string(),
        sweep_values,
        metrics,
        complete,
    })
}

/// Why the case folder `dir` is not complete as its record says (`None`: it is): the folder or
/// its record missing or unreadable, or the first file that is missing, of another size
/// (truncated) or not listed.
pub fn incomplete(dir: &Path) -> Option<String> {
    if !dir.is_dir() {
        return Some("missing".into());
    }
    let Some(record) = read(dir) else {
        return Some(format!("no readable {STAMP}"));
    };
    if record.complete {
        return None;
    }
    let text = read_text(&dir.join(STAMP), RESULT_RECORD).ok()?;
    let v: Value = serde_json::from_str(&text).ok()?;
    let listed = v["files"].as_object()?;
    let present = listing(dir).unwrap_or_default();
    for (name, size) in listed {
        match present.iter().find(|(n, _)| n == name) {
            None => return Some(format!("{name} missing")),
            Some((_, s)) if Some(*s) != size.as_u64() => {
                return Some(format!("{name} of {s} bytes, {} when written", size))
            }
            _ => {}
        }
    }
    let extra = present.iter().find(|(n, _)| !listed.contains_key(n));
    Some(
        extra.map_or("its files differ from its record".into(), |(n, _)| {
            format!("{n} not written by its run")
        }),
    )
}

/// The sweep row of the folder `dir` of `case`, if the folder is complete and was written by
/// this program from this very input: `--resume` keeps it instead of running the case again.
pub fn reusable(dir: &Path, case: &Case, report: bool) -> Option<Vec<Cell>> {
    let record = read(dir)?;
    (record.complete && record.program == PROGRAM && record.input_hash == input_hash(case, report))
        .then_some(record.metrics)
}

/// Whether the folder `dir` of the optimisation `o` is complete and was written by this program
/// from this very definition: `--resume` keeps it instead of running the search again.
pub fn reusable_optimization(dir: &Path, o: &Optimization, report: bool) -> bool {
    read(dir).is_some_and(|record| {
        record.complete
            && record.program == PROGRAM
            && record.input_hash == optimization_hash(o, report)
    })
}
