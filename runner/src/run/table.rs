//! A sweep without case folders (`[output] case_folders = false`, the default above
//! [`CASE_FOLDERS_UP_TO`] points): its points only as rows of the sweep table, one NPY file
//! per column (`columns/<column>.npy`: the case names and the swept values as text, each
//! metric as f64) described by `sweep.json`. The points run a chunk at a time on the worker
//! threads, and each chunk's rows are appended in the points' order as it finishes: memory
//! holds one chunk's results, whatever the number of points; the folder replaces the
//! sweep's folder whole when the table is complete.
//!
//! Read it with NumPy (`numpy.load`, one column per file), and so pandas and polars
//! (`pandas.DataFrame({c["name"]: numpy.load(...)})`, `polars.from_numpy`), or DuckDB through
//! them; docs/results.md shows how.

use super::options::RunOptions;
use super::train::{run_trains, StepsTo};
use crate::output::MechanismResult;
use anyhow::Context;
use cardan_case::case::{point_to_run, Case};
use cardan_case::sweep::Sweep;
use cardan_case::CaseError;
use cardan_dynamics::RunRooms;
use cardan_report::files;
use rayon::prelude::*;
use serde_json::json;
use std::fs::File;
use std::io::{BufWriter, Write};
use std::path::Path;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::Arc;

/// The most points a sweep writes as case folders by default; above it, only its table.
pub const CASE_FOLDERS_UP_TO: usize = 10_000;

/// Points run at once before their rows are written.
const CHUNK: usize = 1024;

/// Whether the sweep of which `case` is one of `points` points writes a folder per point.
pub fn case_folders(case: &Case, points: usize) -> bool {
    case.output
        .case_folders
        .unwrap_or(points <= CASE_FOLDERS_UP_TO)
}

/// A sweep written as a table: its definition, its first point validated (the options and
/// expected cost of every point), and the points a run of it writes.
#[derive(Debug, Clone)]
pub struct TableSweep {
    pub sweep: Arc<Sweep>,
    /// Point 0, validated (with the command line's overrides of its `[output]`).
    pub first: Case,
    /// The points run, by index in increasing order (`--only`); None: every point.
    pub selected: Option<Vec<usize>>,
    /// The points `start..end` a shard runs of it (`--shard K/N`, `shard.rs`), written as a
    /// part of the table that `cardan merge` joins with the others (`table_merge.rs`); None:
    /// the whole table.
    pub range: Option<std::ops::Range<usize>>,
}

impl TableSweep {
    /// How many points a run of it writes.
    pub fn points(&self) -> usize {
        match &self.range {
            Some(r) => r.len(),
            None => self.selected.as_ref().map_or(self.sweep.len(), Vec::len),
        }
    }

    /// The index in the sweep of the j-th point a run of it writes.
    pub fn index(&self, j: usize) -> usize {
        match &self.range {
            Some(r) => r.start + j,
            None => self.selected.as_ref().map_or(j, |s| s[j]),
        }
    }

    /// Validates every point of the sweep as a run would before stepping it, 4096 (`CHECK_CHUNK`)
    /// points at a time on the worker threads (none kept): the first point in order that fails,
    /// or how many points are valid.
    pub fn check(&self) -> Result<usize, CaseError> {
        let n = self.sweep.len();
        for start in (0..n).step_by(CHECK_CHUNK) {
            let end = (start + CHECK_CHUNK).min(n);
            let first_error = (start..end)
                .into_par_iter()
                .map(|k| point_to_run(&self.sweep, k).err())
                .find_first(Option::is_some)
                .flatten();
            if let Some(e) = first_error {
                return Err(e);
            }
        }
        Ok(n)
    }
}

/// Points validated at once by [`TableSweep::check`].
const CHECK_CHUNK: usize = 4096;

/// The NPY 1.0 preamble of a one-dimensional array of `rows` values of type `descr` (NumPy's
/// `numpy.lib.format`: magic, version, header length, the header dictionary padded with
/// spaces to a multiple of 64 bytes and ended by a newline).
pub(super) fn npy_header(descr: &str, rows: usize) -> Vec<u8> {
    let dict = format!("{{'descr': '{descr}', 'fortran_order': False, 'shape': ({rows},), }}");
    let len = (10 + dict.len() + 1).div_ceil(64) * 64;
    let mut h = b"\x93NUMPY\x01\x00".to_vec();
    h.extend_from_slice(&((len - 10) as u16).to_le_bytes());
    h.extend_from_slice(dict.as_bytes());
    h.resize(len - 1, b' ');
    h.push(b'\n');
    h
}

/// One column file being written.
struct Column {
    name: String,
    /// Its text's width (`|S<width>`), or None for f64.
    width: Option<usize>,
    unit: &'static str,
    file: BufWriter<File>,
}

impl Column {
    fn create(dir: &Path, name: &str, width: Option<usize>, rows: usize) -> anyhow::Result<Self> {
        let path = dir.join("columns").join(format!("{name}.npy"));
        let file = File::create(&path).with_context(|| format!("create {}", path.display()))?;
        let mut file = BufWriter::with_capacity(1 << 16, file);
        let descr = width.map_or("<f8".to_string(), |w| format!("|S{w}"));
        file.write_all(&npy_header(&descr, rows))?;
        Ok(Self {
            name: name.to_string(),
            width,
            unit: "",
            file,
        })
    }

    fn text(&mut self, text: &str) -> std::io::Result<()> {
        let width = self.width.unwrap_or(0);
        let bytes = &text.as_bytes()[..text.len().min(width)];
        self.file.write_all(bytes)?;
        self.file.write_all(&vec![0; width - bytes.len()])
    }
}

/// The table's files as the rows come: the text columns from the start, the metric columns
/// from the first point that ran (every point of a sweep has its metrics; a metric another
/// point lacks is NaN there, one it adds is left out and said in the log). A shard's part
/// (`part`) adds a column for every metric some point of it has, NaN in the rows before: the
/// merge takes the columns of the table's first point that ran, which may be in another part.
struct Table<'a> {
    dir: &'a Path,
    rows: usize,
    text: Vec<Column>,
    metrics: Vec<Column>,
    /// The number of the table's first row (a part's first point).
    first_row: usize,
    /// The next row's number.
    next: usize,
    /// How many metric columns the first point that ran gave.
    first_columns: Option<usize>,
    /// A shard's part of the table: every metric a column.
    part: bool,
    /// The metrics written (`[output] metrics`); None: every metric.
    only: Option<Arc<[String]>>,
    failed: Vec<serde_json::Value>,
    warned: bool,
    /// How many points gave warnings, and the first one's (its name, train and warning):
    /// logged once for the sweep (a million points would log a million lines).
    warned_points: usize,
    first_warning: Option<String>,
}

impl Table<'_> {
    fn row(
        &mut self,
        name: &str,
        values: &[(String, String)],
        result: Result<Vec<MechanismResult>, String>,
    ) -> anyhow::Result<()> {
        let row = self.next;
        let written = row - self.first_row;
        self.next += 1;
        self.text[0].text(name)?;
        for (column, (_, value)) in self.text[1..].iter_mut().zip(values) {
            column.text(value)?;
        }
        let results = match result {
            Ok(results) => results,
            Err(e) => {
                self.failed
                    .push(json!({"case": name, "error": e, "row": row}));
                return self.nan_row();
            }
        };
        if let Some(r) = results.iter().find(|r| !r.warnings.is_empty()) {
            self.warned_points += 1;
            self.first_warning
                .get_or_insert_with(|| format!("case \"{name}\": {}: {}", r.label, r.warnings[0]));
        }
        let only = self.only.clone();
        let wanted =
            |m: &&cardan_dynamics::Metric| only.as_ref().is_none_or(|o| o.contains(&m.name));
        let metrics = || {
            results.iter().flat_map(|r| {
                r.summary
                    .metrics
                    .iter()
                    .filter(wanted)
                    .map(|m| (r.label.as_str(), m.name.as_str(), m))
            })
        };
        if self.metrics.is_empty() || self.part {
            for (k, (label, metric, m)) in metrics().enumerate() {
                if column_of(&self.metrics, k, label, metric).is_none() {
                    let name = format!("{label}.{metric}");
                    let mut c = Column::create(self.dir, &name, None, self.rows)?;
                    c.unit = m.unit;
                    // The rows before: every point failed, or (a part) lacked the metric.
                    for _ in 0..written {
                        c.file.write_all(&f64::NAN.to_le_bytes())?;
                    }
                    self.metrics.push(c);
                }
            }
            self.first_columns.get_or_insert(self.metrics.len());
        }
        let mut values = vec![f64::NAN; self.metrics.len()];
        let left_out = place(
            &self.metrics,
            metrics().map(|(label, metric, m)| (label, metric, m.value)),
            &mut values,
        );
        if let Some((label, metric)) = left_out.filter(|_| !self.warned) {
            let name = format!("{label}.{metric}");
            tracing::warn!(case = %name, "metric {name} is not a column of the sweep table (the first point's): left out");
            self.warned = true;
        }
        for (c, v) in self.metrics.iter_mut().zip(values) {
            c.file.write_all(&v.to_le_bytes())?;
        }
        Ok(())
    }

    fn nan_row(&mut self) -> anyhow::Result<()> {
        for c in &mut self.metrics {
            c.file.write_all(&f64::NAN.to_le_bytes())?;
        }
        Ok(())
    }

    /// Flushes the columns and writes `sweep.json`; a shard's part (`part`: its range of the
    /// sweep's `points`) also records its range and how many metric columns its first point
    /// that ran gave.
    fn finish(
        self,
        sweep: &str,
        part: Option<(&std::ops::Range<usize>, usize)>,
    ) -> anyhow::Result<()> {
        let mut columns = Vec::new();
        for mut c in self.text.into_iter().chain(self.metrics) {
            c.file.flush()?;
            columns.push(column_json(&c.name, c.width, c.unit));
        }
        let mut header = header_json(sweep, self.rows, columns, self.failed);
        if let Some((range, points)) = part {
            header["range"] = json!([range.start, range.end]);
            header["points"] = json!(points);
            header["first_columns"] = json!(self.first_columns.unwrap_or(0));
        }
        write_header(self.dir, &header)
    }
}

impl AsRef<str> for Column {
    fn as_ref(&self) -> &str {
        &self.name
    }
}

/// Whether `name` is `{label}.{metric}`, told without formatting it.
fn is_named(name: &str, label: &str, metric: &str) -> bool {
    name.len() == label.len() + 1 + metric.len()
        && name.starts_with(label)
        && name.as_bytes()[label.len()] == b'.'
        && name.ends_with(metric)
}

/// The column of `columns` (their names unique) named `{label}.{metric}`, looked for first at
/// `guess`: the k-th metric of a point is in practice the k-th column, every point of a sweep
/// giving the same metrics in the same order; any other column is found by search.
fn column_of<N: AsRef<str>>(
    columns: &[N],
    guess: usize,
    label: &str,
    metric: &str,
) -> Option<usize> {
    if columns
        .get(guess)
        .is_some_and(|c| is_named(c.as_ref(), label, metric))
    {
        return Some(guess);
    }
    columns
        .iter()
        .position(|c| is_named(c.as_ref(), label, metric))
}

/// Puts each of a point's `metrics` (label, metric name, value; in their order) in `values`,
/// at its column's place among `columns` (`values` is NaN where no metric is): the first
/// metric of a name fills its column, as in sweep.csv. Returns the first metric (label,
/// metric name) that no column has.
fn place<'m, N: AsRef<str>>(
    columns: &[N],
    metrics: impl Iterator<Item = (&'m str, &'m str, f64)>,
    values: &mut [f64],
) -> Option<(&'m str, &'m str)> {
    let mut filled = vec![false; columns.len()];
    let mut left_out = None;
    for (k, (label, metric, value)) in metrics.enumerate() {
        match column_of(columns, k, label, metric) {
            Some(c) if !filled[c] => {
                values[c] = value;
                filled[c] = true;
            }
            Some(_) => {}
            None => {
                left_out.get_or_insert((label, metric));
            }
        }
    }
    left_out
}

/// A column's entry in `sweep.json`: text of `width` bytes, or f64 of `unit`.
pub(super) fn column_json(name: &str, width: Option<usize>, unit: &str) -> serde_json::Value {
    let mut column = json!({
        "name": name,
        "file": format!("columns/{name}.npy"),
        "dtype": width.map_or("<f8".to_string(), |w| format!("|S{w}")),
    });
    if width.is_none() {
        column["unit"] = json!(unit);
    }
    column
}

/// `sweep.json` of a table of `rows` rows: its columns' entries ([`column_json`]) and its
/// failed points (`{"case", "error", "row"}`).
pub(super) fn header_json(
    sweep: &str,
    rows: usize,
    columns: Vec<serde_json::Value>,
    failed: Vec<serde_json::Value>,
) -> serde_json::Value {
    json!({
        "format": "cardan sweep table",
        "version": 1,
        "program": super::stamp::PROGRAM,
        "sweep": sweep,
        "rows": rows,
        "columns": columns,
        "failed": failed,
    })
}

/// Writes `header` as `dir/sweep.json`.
pub(super) fn write_header(dir: &Path, header: &serde_json::Value) -> anyhow::Result<()> {
    let mut text = serde_json::to_string_pretty(header)?;
    text.push('\n');
    files::write_file(&dir.join("sweep.json"), text.as_bytes())
}

/// Point `k` of `table` validated and run to its summaries in rooms of `rooms` (a panic is its
/// failure).
fn run_point(
    table: &TableSweep,
    k: usize,
    rooms: &RunRooms,
) -> Result<Vec<MechanismResult>, String> {
    std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
        let case = point_to_run(&table.sweep, k).map_err(|e| e.to_string())?;
        run_trains(&case, StepsTo::Summary, rooms)
    }))
    .unwrap_or_else(|_| {
        Err(format!(
            "{}: case \"{}\": internal error (a bug, please report it)",
            table.sweep.file.display(),
            table.sweep.point_name(k)
        ))
    })
    .map(|trains| trains.into_iter().map(|(r, _)| r).collect())
}

/// Runs the points of the sweep `table` (in their order) into its table in `out/<sweep>/`,
/// replaced whole; `done` counts the points for `options.progress` out of `total`. Returns
/// how many points ran, and each point's failure (a failed point's row is NaN).
pub(super) fn run_table(
    table: &TableSweep,
    out: &Path,
    options: &RunOptions,
    done: &AtomicUsize,
    total: usize,
) -> (usize, Vec<String>) {
    let sweep = table.sweep.name.as_str();
    let dir = out.join(sweep);
    let mut failures = Vec::new();
    let tmp = match files::temporary_dir(&dir) {
        Ok(tmp) => tmp,
        Err(e) => {
            failures.push(format!(
                "sweep \"{sweep}\": cannot write its table to {}: {e:#}",
                dir.display()
            ));
            return (0, failures);
        }
    };
    let written = write_table(table, (&tmp, &dir), options, (done, total), &mut failures);
    let kept = table.range.is_some() || matches!(written, Ok(n) if n > 0);
    if !(kept && written.is_ok()) {
        let _ = std::fs::remove_dir_all(&tmp);
    }
    match written {
        Ok(n) => (n, failures),
        Err(e) => {
            failures.push(format!(
                "sweep \"{sweep}\": cannot write its table to {}: {e:#}",
                dir.display()
            ));
            (0, failures)
        }
    }
}

/// Writes the points of `table` into its table in the temporary folder `tmp`, which then
/// replaces `dir`; `done` counts the points out of `total`. Returns how many points ran (0 with
/// `dir` left as it was when every point of a whole table failed); each point's failure goes
/// to `failures`.
fn write_table(
    table: &TableSweep,
    (tmp, dir): (&Path, &Path),
    options: &RunOptions,
    progress: (&AtomicUsize, usize),
    failures: &mut Vec<String>,
) -> anyhow::Result<usize> {
    let sweep = table.sweep.name.as_str();
    let rows = table.points();
    let mut out = open_table(table, tmp, rows)?;
    let ran = run_rows(table, &mut out, options, progress, failures)?;
    if let Some(first) = &out.first_warning {
        tracing::warn!(
            "{}: sweep \"{sweep}\": {} of {} point(s) gave warnings; the first, {first}",
            table.sweep.file.display(),
            out.warned_points,
            rows
        );
    }
    let part = table.range.as_ref().map(|r| (r, table.sweep.len()));
    if ran == 0 && part.is_none() {
        // Every point failed: the earlier folder, if any, stays (a shard's part is
        // written: the merge needs its rows).
        return Ok(0);
    }
    out.finish(sweep, part)?;
    files::replace_dir(tmp, dir)?;
    Ok(ran)
}

/// A table of `rows` rows begun in `tmp`: its text columns (the case's name, each swept
/// field's value) created at their widths, no metric column yet.
fn open_table<'a>(table: &TableSweep, tmp: &'a Path, rows: usize) -> anyhow::Result<Table<'a>> {
    std::fs::create_dir(tmp.join("columns"))?;
    // Each text column's width: the longest name, the longest value of each swept field
    // (of the whole sweep for a shard's part: the merged table's).
    let (name_width, value_widths) = match &table.range {
        Some(_) => table.sweep.text_widths(0..table.sweep.len()),
        None => table.sweep.text_widths((0..rows).map(|j| table.index(j))),
    };
    let mut text = vec![Column::create(tmp, "case", Some(name_width.max(1)), rows)?];
    for (path, w) in table.sweep.paths().into_iter().zip(value_widths) {
        text.push(Column::create(tmp, path, Some(w.max(1)), rows)?);
    }
    let first_row = table.range.as_ref().map_or(0, |r| r.start);
    Ok(Table {
        dir: tmp,
        rows,
        text,
        metrics: Vec::new(),
        first_row,
        next: first_row,
        first_columns: None,
        part: table.range.is_some(),
        only: table.first.table_metrics.clone(),
        failed: Vec::new(),
        warned: false,
        warned_points: 0,
        first_warning: None,
    })
}

/// Runs the points of `table`, `CHUNK` at a time on the worker threads, into `out`'s rows in
/// their order; `done` counts the points for `options.progress` out of `total`. Returns how
/// many ran; each failure goes to `failures`.
fn run_rows(
    table: &TableSweep,
    out: &mut Table,
    options: &RunOptions,
    (done, total): (&AtomicUsize, usize),
    failures: &mut Vec<String>,
) -> anyhow::Result<usize> {
    let rows = table.points();
    let mut ran = 0;
    // The points' runs take one another's blocks instead of each making its own.
    let rooms = RunRooms::default();
    for start in (0..rows).step_by(CHUNK) {
        let results: Vec<Result<Vec<MechanismResult>, String>> = (start..(start + CHUNK).min(rows))
            .into_par_iter()
            .map(|j| {
                let r = run_point(table, table.index(j), &rooms);
                if let Some(progress) = &options.progress {
                    progress(done.fetch_add(1, Ordering::Relaxed) + 1, total);
                }
                r
            })
            .collect();
        for (j, result) in (start..).zip(results) {
            if let Err(e) = &result {
                failures.push(e.clone());
            } else {
                ran += 1;
            }
            let k = table.index(j);
            out.row(&table.sweep.point_name(k), &table.sweep.values(k), result)?;
        }
    }
    Ok(ran)
}

#[cfg(test)]
mod tests;
