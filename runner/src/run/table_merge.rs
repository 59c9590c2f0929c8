//! `cardan merge` of a sweep written as a table and split by the shards into ranges of its
//! points (`shard.rs`, `assign`): the parts checked to cover the sweep's points once each
//! ([`parts`], before anything is written), then each column's parts concatenated into one NPY
//! file with the total row count in its header, streamed (the merge's time is linear in the
//! table's size, its memory a copy buffer), and `sweep.json` as one run writes it
//! ([`merge_table`]).

use super::table::{column_json, header_json, npy_header, write_header};
use anyhow::{bail, Context};
use cardan_report::files;
use serde_json::Value;
use std::fs::File;
use std::io::{BufWriter, Read, Seek, SeekFrom, Write};
use std::path::{Path, PathBuf};

/// One shard's part of a table: its points `start..end`, its folder of the sweep, its
/// `sweep.json`.
pub(super) struct Part {
    pub start: usize,
    pub end: usize,
    pub dir: PathBuf,
    pub header: Value,
}

/// The parts of the table sweep `sweep` of `points` points, from the shards' folders
/// `shard_dirs` that its `ranges` (start, end, shard) name, in order; refused (missing, in
/// two shards, or not a part of this sweep) with the points concerned and the folders.
pub(super) fn parts(
    sweep: &str,
    points: usize,
    ranges: &[super::shard::Range],
    shard_dirs: &[&Path],
) -> Result<Vec<Part>, String> {
    let mut parts = Vec::new();
    for &(start, end, k) in ranges {
        let Some(shard) = k.checked_sub(1).and_then(|i| shard_dirs.get(i)) else {
            return Err(format!(
                "sweep \"{sweep}\": points {start}..{end} of shard {k}?"
            ));
        };
        let dir = shard.join(sweep);
        let file = dir.join("sweep.json");
        let header: Value = files::read_text(&file, files::RESULT_RECORD)
            .ok()
            .and_then(|t| serde_json::from_str(&t).ok())
            .ok_or_else(|| {
                format!(
                    "sweep \"{sweep}\": points {start}..{end} (shard {k}) missing: no readable {}: \
                     run the shard again (`--shard K/N --resume`), then merge",
                    file.display()
                )
            })?;
        let range = |i: usize| header["range"][i].as_u64().map(|v| v as usize);
        let (Some(s), Some(e)) = (range(0), range(1)) else {
            return Err(format!(
                "sweep \"{sweep}\": {}: not a shard's part of a table (no range)",
                file.display()
            ));
        };
        if header["points"].as_u64() != Some(points as u64) || header["sweep"] != sweep {
            return Err(format!(
                "sweep \"{sweep}\": {}: a part of another sweep (of {} points, \"{}\")",
                file.display(),
                header["points"],
                header["sweep"].as_str().unwrap_or("?")
            ));
        }
        parts.push(Part {
            start: s,
            end: e,
            dir,
            header,
        });
    }
    parts.sort_by_key(|p| (p.start, p.end));
    let mut covered = 0;
    for (i, p) in parts.iter().enumerate() {
        if p.start > covered {
            return Err(format!(
                "sweep \"{sweep}\": points {covered}..{} missing: no shard's part holds them",
                p.start
            ));
        }
        if p.start < covered {
            let other = &parts[i - 1];
            let what = if (other.start, other.end) == (p.start, p.end) {
                "doubled"
            } else {
                "overlapping"
            };
            return Err(format!(
                "sweep \"{sweep}\": points {}..{} in {} and {}: {what} ranges",
                p.start,
                covered.min(p.end),
                other.dir.display(),
                p.dir.display()
            ));
        }
        covered = p.end;
    }
    if covered < points {
        return Err(format!(
            "sweep \"{sweep}\": points {covered}..{points} missing: no shard's part holds them"
        ));
    }
    Ok(parts)
}

/// A part's rows and those of its points that ran.
fn rows(p: &Part) -> (usize, usize) {
    let rows = p.header["rows"].as_u64().unwrap_or(0) as usize;
    let failed = p.header["failed"].as_array().map_or(0, Vec::len);
    (rows, rows.saturating_sub(failed))
}

/// Joins the `parts` of the table sweep `sweep` into its folder `dir`, replaced whole: what one
/// run writes. The metric columns are those of the table's first point that ran (its part's
/// first `first_columns`), NaN in a part without one; a table none of whose points ran is not
/// written (as by a run). Returns how many points ran.
pub(super) fn merge_table(sweep: &str, parts: &[Part], dir: &Path) -> anyhow::Result<usize> {
    let ran: usize = parts.iter().map(|p| rows(p).1).sum();
    let total: usize = parts.iter().map(|p| rows(p).0).sum();
    if ran == 0 {
        return Ok(0);
    }
    let columns = |p: &Part| p.header["columns"].as_array().cloned().unwrap_or_default();
    let is_text = |c: &Value| c["dtype"].as_str().is_some_and(|d| d.starts_with("|S"));
    let mut chosen: Vec<Value> = columns(&parts[0]).into_iter().filter(is_text).collect();
    let first = parts.iter().find(|p| rows(p).1 > 0).expect("a part ran");
    let first_columns = first.header["first_columns"].as_u64().unwrap_or(0) as usize;
    chosen.extend(
        columns(first)
            .into_iter()
            .filter(|c| !is_text(c))
            .take(first_columns),
    );
    let tmp = files::temporary_dir(dir)?;
    let result = (|| {
        std::fs::create_dir(tmp.join("columns"))?;
        let mut entries = Vec::new();
        for c in &chosen {
            let name = c["name"].as_str().context("a column without a name")?;
            let dtype = c["dtype"].as_str().context("a column without a type")?;
            let width = dtype.strip_prefix("|S").map(str::parse).transpose()?;
            join_column(name, dtype, total, parts, &tmp)?;
            entries.push(column_json(name, width, c["unit"].as_str().unwrap_or("")));
        }
        let failed: Vec<Value> = parts
            .iter()
            .flat_map(|p| p.header["failed"].as_array().cloned().unwrap_or_default())
            .collect();
        write_header(&tmp, &header_json(sweep, total, entries, failed))?;
        files::replace_dir(&tmp, dir)
    })();
    if result.is_err() {
        let _ = std::fs::remove_dir_all(&tmp);
    }
    result.map(|()| ran)
}

/// Writes `tmp/columns/<name>.npy` of `total` rows of type `dtype`: each part's rows of the
/// column in order (its file's data after its header), NaN rows for a part without it (a
/// metric none of its points had).
fn join_column(
    name: &str,
    dtype: &str,
    total: usize,
    parts: &[Part],
    tmp: &Path,
) -> anyhow::Result<()> {
    let item = match dtype.strip_prefix("|S") {
        Some(w) => w.parse::<u64>()?,
        None => 8,
    };
    let path = tmp.join("columns").join(format!("{name}.npy"));
    let mut out = BufWriter::with_capacity(
        1 << 16,
        File::create(&path).with_context(|| format!("create {}", path.display()))?,
    );
    out.write_all(&npy_header(dtype, total))?;
    for p in parts {
        let rows = rows(p).0 as u64;
        let from = p.dir.join("columns").join(format!("{name}.npy"));
        let mut file = match files::open_regular(&from, files::PER_STEP_FILE) {
            Ok(file) => file,
            // A column this part has not (a metric its points lack) reads as NaN; anything
            // else unreadable (not a regular file, say) is refused below.
            Err(e) if dtype == "<f8" && e.kind() == std::io::ErrorKind::NotFound => {
                for _ in 0..rows {
                    out.write_all(&f64::NAN.to_le_bytes())?;
                }
                continue;
            }
            Err(e) => bail!("{}: {e}: the shard's part is incomplete", from.display()),
        };
        let mut preamble = [0u8; 10];
        file.read_exact(&mut preamble)?;
        let len = u16::from_le_bytes([preamble[8], preamble[9]]) as u64;
        let mut dict = vec![0u8; len as usize];
        file.read_exact(&mut dict)?;
        let data = file.metadata()?.len() - 10 - len;
        let descr = format!("'descr': '{dtype}'");
        if &preamble[..8] != b"\x93NUMPY\x01\x00"
            || !String::from_utf8_lossy(&dict).contains(&descr)
            || data != rows * item
        {
            bail!(
                "{}: not {rows} rows of {dtype}: the shard's part is damaged or of another run",
                from.display()
            );
        }
        file.seek(SeekFrom::Start(10 + len))?;
        std::io::copy(&mut file.take(data), &mut out)?;
    }
    out.flush()?;
    Ok(())
}
