//! Writing one case into its output folder: run into a temporary folder beside it
//! (`summary.json`, the per-step files, the report), which then replaces it as a whole.

use super::options::RunOptions;
use super::size::check_size;
use super::stamp::{self, Cell};
use super::train::{run_trains, StepsTo};
use crate::output::{self, MechanismResult};
use anyhow::Context;
use cardan_case::case::Case;
use cardan_dynamics::RunRooms;
use cardan_report::{files, CaseSummary, ChartData};
use std::path::{Path, PathBuf};

/// A case written: its folder, its sweep row ([`stamp::cells`]), whether `--resume` kept
/// the folder of an earlier run instead of running the case, and the summary its report
/// read (for the index: [`cardan_report::index_with`]), if it has one.
pub(super) struct Written {
    pub dir: PathBuf,
    pub cells: Vec<Cell>,
    pub reused: bool,
    pub summary: Option<CaseSummary>,
}

/// Runs one case into `out/<case name>/`, replacing that folder as a whole, its record
/// (`run.json`, [`stamp`]) written last; with `options.resume`, a complete folder recorded by
/// this program from this input is kept instead.
pub(super) fn run_and_write(
    case: &Case,
    out: &Path,
    options: &RunOptions,
) -> Result<Written, String> {
    let dir = out.join(&case.name);
    let cannot_write = |e: anyhow::Error| {
        format!(
            "{}: case \"{}\": cannot write results to {}: {e:#}",
            case.file.display(),
            case.name,
            dir.display()
        )
    };
    if let Ok(meta) = dir.symlink_metadata() {
        if !meta.is_dir() {
            return Err(format!(
                "{}: case \"{}\": {} is a file, not a case folder: it is not replaced; move it away or rename the case",
                case.file.display(),
                case.name,
                dir.display()
            ));
        }
    }
    // A sweep's points are reported by the sweep's report: no charts of their own.
    let report = options.reports && case.sweep.is_none();
    if options.resume {
        if let Some(cells) = stamp::reusable(&dir, case, report) {
            return Ok(Written {
                dir,
                cells,
                reused: true,
                summary: None,
            });
        }
    }
    check_size(case, options)?;
    let tmp = files::temporary_dir(&dir).map_err(cannot_write)?;
    let to = StepsTo::Files {
        dir: &tmp,
        charts: report,
    };
    let result = run_trains(case, to, &RunRooms::default()).and_then(|trains| {
        // The chart series go to the report, and are dropped with it: a batch keeps only
        // the summaries.
        let (results, series): (Vec<MechanismResult>, Vec<Option<ChartData>>) =
            trains.into_iter().map(|(r, rows)| (r, rows.charts)).unzip();
        super::train::log_warnings(case, &results);
        let charts: std::collections::BTreeMap<String, ChartData> = results
            .iter()
            .zip(series)
            .filter_map(|(r, s)| Some((r.label.clone(), s?)))
            .collect();
        let cells = if case.sweep.is_some() {
            stamp::cells(&results, case.table_metrics.as_deref())
        } else {
            Vec::new()
        };
        let json = output::summary_json(case, &results);
        let mut summary = serde_json::to_string_pretty(&json).map_err(|e| e.to_string())?;
        summary.push('\n');
        let reported = files::write_file(&tmp.join("summary.json"), summary.as_bytes())
            .and_then(|()| {
                // The summary as written, not read back (issue 37).
                let reported = report
                    .then(|| cardan_report::case_report_from_run(&tmp, &json, None, charts))
                    .transpose()
                    .context("the report")?;
                stamp::write(&tmp, case, report, &cells)?;
                files::replace_dir(&tmp, &dir)?;
                Ok(reported)
            })
            .map_err(cannot_write)?;
        Ok((cells, reported))
    });
    if result.is_err() {
        let _ = std::fs::remove_dir_all(&tmp);
    }
    result.map(|(cells, summary)| Written {
        dir,
        cells,
        reused: false,
        summary,
    })
}
