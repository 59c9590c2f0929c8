//! A sweep's folder: where its points are written ([`SweepTarget`]: a temporary folder that
//! replaces it whole, or the folder itself when `--only` re-runs some of its points), its
//! `sweep.csv` (made, or merged with the earlier one) and its report.

use super::options::Report;
use super::stamp::{Cell, STAMP};
use anyhow::Context;
use cardan_case::case::Case;
use cardan_report::files;
use std::collections::{BTreeMap, HashMap};
use std::io::Read;
use std::path::{Path, PathBuf};

/// A sweep point's row: its name, the value of each swept field (dotted path, value as
/// written) and its metrics ([`Cell`]s, each crank train's in order).
pub(crate) type Point<'a> = (&'a str, &'a [(String, String)], &'a [Cell]);

/// `sweep.csv`: one row per written point: its name, the value of each swept field, then every
/// summary metric of every mechanism (`<mechanism>.<metric>`, in SI, units in `summary.json`).
pub(crate) fn sweep_csv(points: &[Point]) -> String {
    // The columns in the order they first appear, each found by a hash of its name: a sweep of
    // 10 000 points has some 200 columns, which a search through the list per metric and point
    // took a noticeable part of the sweep's time to match.
    let mut columns: Vec<(String, String)> = Vec::new();
    let mut index: HashMap<(&str, &str), usize> = HashMap::new();
    for (_, _, cells) in points {
        for (label, name, _) in *cells {
            index
                .entry((label.as_str(), name.as_str()))
                .or_insert_with(|| {
                    columns.push((label.clone(), name.clone()));
                    columns.len() - 1
                });
        }
    }
    let swept: Vec<String> = points
        .first()
        .map(|(_, v, _)| v.iter().map(|(p, _)| p.clone()).collect())
        .unwrap_or_default();
    let mut w = csv::Writer::from_writer(Vec::new());
    let mut header = vec!["case".to_string()];
    header.extend(swept.iter().cloned());
    header.extend(columns.iter().map(|(m, k)| format!("{m}.{k}")));
    let _ = w.write_record(&header);
    for (name, swept, cells) in points {
        let mut row = vec![name.to_string()];
        row.extend(swept.iter().map(|(_, x)| x.clone()));
        let mut values: Vec<Option<&str>> = vec![None; columns.len()];
        for (label, name, text) in *cells {
            // The first of a name, as a search from the start would find.
            let slot = &mut values[index[&(label.as_str(), name.as_str())]];
            slot.get_or_insert(text.as_str());
        }
        row.extend(
            values
                .into_iter()
                .map(|v| v.unwrap_or_default().to_string()),
        );
        let _ = w.write_record(&row);
    }
    String::from_utf8(w.into_inner().unwrap_or_default()).unwrap_or_default()
}

/// Where a sweep's selected points are written.
pub(super) enum SweepTarget {
    /// Into this temporary folder, which then replaces `out/<sweep>` as a whole.
    Whole(PathBuf),
    /// Into the existing `out/<sweep>` itself, each point's folder replaced on its own, its
    /// `sweep.csv` (and report) then rewritten to hold every point the folder holds: an
    /// `--only` run of some points of a sweep written before.
    Update,
}

/// The swept fields' columns of an existing `sweep.csv` (after `case`), for `want` of them.
fn swept_columns(csv_path: &Path, want: usize) -> anyhow::Result<Vec<String>> {
    let file = files::open_regular(csv_path, files::RESULT_RECORD)
        .with_context(|| format!("read {}", csv_path.display()))?;
    let mut r = csv::Reader::from_reader(file.take(files::RESULT_RECORD.bytes));
    let header = r.headers()?.clone();
    Ok(header.iter().skip(1).take(want).map(String::from).collect())
}

/// The `sweep.csv` of the sweep folder `dir` after an `--only` run wrote `fresh` (the rows of
/// its points, as [`sweep_csv`] makes them): the earlier rows of the points not re-run, the
/// fresh rows of those re-run, each row only if its point's folder holds a `summary.json`, in
/// the sweep's point order (`order`), then any other point the folder holds.
fn merged_sweep_csv(dir: &Path, fresh: &str, order: &[String]) -> anyhow::Result<String> {
    let mut columns: Vec<String> = Vec::new();
    let mut rows: Vec<(String, HashMap<String, String>)> = Vec::new();
    let mut read = |r: &mut csv::Reader<&[u8]>| -> anyhow::Result<()> {
        let header: Vec<String> = r.headers()?.iter().map(String::from).collect();
        for h in &header {
            if !columns.contains(h) {
                columns.push(h.clone());
            }
        }
        for record in r.records() {
            let record = record?;
            let name = record.get(0).unwrap_or_default().to_string();
            let values = header
                .iter()
                .cloned()
                .zip(record.iter().map(String::from))
                .collect();
            match rows.iter_mut().find(|(n, _)| *n == name) {
                Some(row) => row.1 = values,
                None => rows.push((name, values)),
            }
        }
        Ok(())
    };
    let earlier = files::read_limited(&dir.join("sweep.csv"), files::RESULT_RECORD)
        .with_context(|| format!("read {}", dir.join("sweep.csv").display()))?;
    read(&mut csv::Reader::from_reader(&earlier[..]))?;
    read(&mut csv::Reader::from_reader(fresh.as_bytes()))?;
    rows.retain(|(name, _)| dir.join(name).join("summary.json").is_file());
    let position: HashMap<&str, usize> = order
        .iter()
        .enumerate()
        .map(|(k, n)| (n.as_str(), k))
        .collect();
    rows.sort_by_key(|(name, _)| position.get(name.as_str()).copied().unwrap_or(usize::MAX));
    let mut w = csv::Writer::from_writer(Vec::new());
    w.write_record(&columns)?;
    for (_, values) in &rows {
        w.write_record(
            columns
                .iter()
                .map(|c| values.get(c).map_or("", String::as_str)),
        )?;
    }
    Ok(String::from_utf8(w.into_inner()?)?)
}

/// Moves into `tmp`, the new temporary folder of the sweep `out/<sweep>`, the folders of its
/// `points` that an earlier run left complete (with their `run.json`): in the temporary
/// folders of killed runs of it, or in `out/<sweep>` itself (`--resume`). Whether each can be
/// kept is then [`super::stamp::reusable`]'s to tell.
fn salvage_points(out: &Path, sweep: &str, tmp: &Path, points: &[String]) {
    let prefix = format!(".{sweep}.tmp-");
    let mut sources: Vec<PathBuf> = files::stale_temporaries(out)
        .into_iter()
        .map(|(path, _)| path)
        .filter(|p| {
            p.is_dir()
                && p.file_name()
                    .is_some_and(|n| n.to_string_lossy().starts_with(&prefix))
        })
        .collect();
    sources.push(out.join(sweep));
    for source in sources {
        for point in points {
            let (from, to) = (source.join(point), tmp.join(point));
            if from.join(STAMP).is_file() && to.symlink_metadata().is_err() {
                if let Err(e) = std::fs::rename(&from, &to) {
                    tracing::warn!(from = %from.display(), "cannot keep the point of an earlier run: {e}");
                }
            }
        }
    }
}

/// Where each sweep of `cases` is written ([`SweepTarget`]; None, with a failure in
/// `failures`, where it cannot be): `selected` of each sweep's `all_points` are run. With
/// `resume`, the complete points of earlier runs are gathered into a new sweep folder first.
pub(super) fn sweep_targets(
    cases: &[Case],
    out: &Path,
    selected: &HashMap<&str, usize>,
    all_points: &HashMap<String, Vec<String>>,
    resume: bool,
    failures: &mut Vec<String>,
) -> BTreeMap<String, Option<SweepTarget>> {
    let mut sweeps: BTreeMap<String, Option<SweepTarget>> = BTreeMap::new();
    for case in cases {
        let Some((sweep, values)) = &case.sweep else {
            continue;
        };
        if sweeps.contains_key(sweep) {
            continue;
        }
        let dir = out.join(sweep);
        let some = selected[sweep.as_str()] < all_points[sweep].len();
        let target = if some && dir.join("sweep.csv").is_file() {
            files::remove_stale_temporaries(&dir);
            let swept: Vec<String> = values.iter().map(|(p, _)| p.clone()).collect();
            match swept_columns(&dir.join("sweep.csv"), swept.len()) {
                Ok(columns) if columns == swept => Ok(SweepTarget::Update),
                Ok(columns) => Err(anyhow::anyhow!(
                    "its folder holds a sweep over {columns:?}, this one is over {swept:?}: --only cannot update some of its points; run the whole sweep"
                )),
                Err(e) => Err(e),
            }
        } else {
            files::temporary_dir(&dir).map(|tmp| {
                if resume {
                    salvage_points(out, sweep, &tmp, &all_points[sweep]);
                }
                SweepTarget::Whole(tmp)
            })
        };
        if let Err(e) = &target {
            failures.push(format!(
                "{}: sweep \"{sweep}\": cannot write results to {}: {e:#}",
                case.file.display(),
                dir.display()
            ));
        }
        sweeps.insert(sweep.clone(), target.ok());
    }
    sweeps
}

/// Writes each sweep's `sweep.csv` (and report, if `reports`) of the `points` written, into its
/// target folder ([`sweep_targets`]); a sweep all of whose points `failed` keeps its earlier
/// folder. Each sweep written, or its failure, goes into `report`.
pub(super) fn write_sweeps(
    sweeps: &BTreeMap<String, Option<SweepTarget>>,
    out: &Path,
    points: &BTreeMap<&str, Vec<Point>>,
    failed: &HashMap<&str, usize>,
    all_points: &HashMap<String, Vec<String>>,
    reports: bool,
    report: &mut Report,
) {
    for (sweep, target) in sweeps {
        let Some(target) = target else { continue };
        let dir = out.join(sweep);
        let rows = points.get(sweep.as_str()).map_or(&[][..], Vec::as_slice);
        let written = match target {
            // Every point failed: the earlier sweep folder, if any, stays.
            SweepTarget::Whole(tmp) if rows.is_empty() && failed.contains_key(sweep.as_str()) => {
                let _ = std::fs::remove_dir_all(tmp);
                continue;
            }
            SweepTarget::Whole(tmp) => {
                files::write_file(&tmp.join("sweep.csv"), sweep_csv(rows).as_bytes())
                    .and_then(|()| {
                        if reports && !rows.is_empty() {
                            cardan_report::sweep_report(tmp, sweep, None)
                                .context("the sweep report")?;
                        }
                        files::replace_dir(tmp, &dir)
                    })
                    .inspect_err(|_| {
                        let _ = std::fs::remove_dir_all(tmp);
                    })
            }
            SweepTarget::Update if rows.is_empty() => continue,
            SweepTarget::Update => {
                merged_sweep_csv(&dir, &sweep_csv(rows), &all_points[sweep])
                    .and_then(|csv| {
                        files::write_file_replacing(&dir.join("sweep.csv"), csv.as_bytes())
                    })
                    .and_then(|()| {
                        // The sweep's report, if asked or already there: never one of old points.
                        if reports || dir.join("report.html").is_file() {
                            cardan_report::sweep_report(&dir, sweep, None)
                                .context("the sweep report")?;
                        }
                        Ok(())
                    })
            }
        };
        match written {
            Ok(()) => report.sweeps.push((sweep.clone(), dir, rows.len())),
            Err(e) => report.failures.push(format!(
                "sweep \"{sweep}\": cannot write results to {}: {e:#}",
                dir.display()
            )),
        }
    }
}
