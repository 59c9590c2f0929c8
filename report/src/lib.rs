//! Comparison reports and charts made from a run's output folder, so that a reader sees at a
//! glance which mechanism is better where, and by how much, without a spreadsheet.
//!
//! - [`case_report`]: for one case folder (`summary.json`, and for the charts the series its
//!   run recorded ([`ChartRecorder`], given to [`case_report_from_run`]) or else the per-step
//!   CSVs), `report.md` and `report.html` with every metric of every mechanism side by side
//!   (units, and the percentage difference to a reference mechanism, as in Karhula's (2008)
//!   appendix tables),
//!   grouped into kinematics, joint loads (per joint), torque/power/work, cylinder and gas,
//!   and losses; a generated "which is better" summary; a loss budget when the summary holds
//!   friction losses; and charts in `plots/*.svg`: first those engineers read first (issue 38:
//!   the indicator diagram `pv_diagram.svg` (`indicator.rs`), a dynamic run's `crank_speed.svg`
//!   with its fluctuation band and a run-up's `crank_speed_time.svg` over time
//!   (`crank_speed.rs`), the bearings' polar load diagrams
//!   `main_bearing_polar.svg` and `crank_pin_polar.svg` (`bearing_polar.rs`)), then over crank
//!   angle (piston motion, cylinder pressure, drive torques, joint forces, friction).
//! - [`sweep_report`]: for a sweep folder (`sweep.csv`), the [`KEY_METRICS`] over one swept
//!   field (line charts of every mechanism and of the difference in %), or over two (heat maps
//!   of each mechanism and of the difference, with the 0 % contour: where the mechanisms swap
//!   places); a sweep of a machine of several cylinders charts the whole machine's
//!   [`MACHINE_KEY_METRICS`] instead, one cylinder's figures named as that cylinder's.
//!   A case report of a machine of several cylinders leads with the whole machine's figures
//!   (`machine_*`) and names the per-joint and per-crank-train figures as one cylinder's.
//! - [`index`]: `<out>/index.html`, linking every report with a few headline metrics per case:
//!   the whole machine's.
//! - [`files`]: an output folder's files, each written whole (used by the runner and the
//!   gear calculator too).
//!
//! The differences are `Δ = (mechanism − reference) / |reference| × 100 %`; lower is better for
//! loads, torques, power need and losses, higher for efficiency and output. The reference is
//! the one asked for, else the first registered mechanism of the results (the slider-crank when
//! present).
//!
//! Charts are SVG written here (see `svg.rs`): no font or system library, reproducible bytes,
//! series decimated to at most [`MAX_POINTS`] points keeping each bucket's extremes. A run
//! thins its series that way while it steps (`envelope.rs`), so its report neither reads back
//! the CSV it wrote nor holds more than [`MAX_POINTS`] points per series, and draws the same
//! bytes as a report made from the CSV. Reports hold no timestamps and list everything in a
//! fixed order, so that two runs give the same bytes.
//!
//! This crate knows a run's per-step rows by their column names only: the runner's one row
//! definition (`cardan_runner::per_step::Row`) fills them and hands them to a
//! [`ChartRecorder`], or writes them to the CSV this crate reads back; which rows are taken is
//! [`row_count`] and [`ChartRows`]. It does not depend on the runner.

mod bearing_polar;
mod case_plots;
mod cases;
mod chart_columns;
mod convergence;
mod crank_speed;
mod data;
mod doc;
mod envelope;
pub mod files;
mod heatmap;
mod index;
mod indicator;
mod locus;
mod log_chart;
mod numbers;
mod rows;
mod svg;
mod svg_text;
mod sweep_axis;
mod sweeps;
mod thinning;

pub use convergence::{convergence_chart, Convergence};
pub use envelope::{ChartData, ChartRecorder, Envelope, Trace};
pub use rows::{row_count, ChartRows, MAX_CHART_ROWS};
pub use svg::MAX_POINTS;
pub use sweeps::{KEY_METRICS, MACHINE_KEY_METRICS, MACHINE_TORQUE_PEAK};

use anyhow::Context;
use std::collections::BTreeMap;
use std::path::Path;

/// Writes the report of the case in `case_dir` (`summary.json`, and `<mechanism>.csv` where
/// present): `report.md`, `report.html` (self-contained) and `plots/*.svg`. Differences are
/// taken to `reference` (a mechanism of the case), by default the first registered mechanism
/// present (the slider-crank when the case has it).
pub fn case_report(case_dir: &Path, reference: Option<&str>) -> anyhow::Result<()> {
    cases::case_report(case_dir, None, reference, BTreeMap::new())
        .map(drop)
        .with_context(|| format!("report of {}", case_dir.display()))
}

/// A case's summary as its report read it, which [`index_with`] lists without reading its
/// `summary.json` again.
#[derive(Debug, Clone)]
pub struct CaseSummary {
    summary: data::CaseSummary,
    /// Whether its mechanisms are in the order of the default reference, the index's.
    default_order: bool,
}

/// [`case_report`] of a run: `summary` is what it wrote to `case_dir`'s `summary.json`
/// (not read back: serde_json's `float_roundtrip` reads its numbers back as they are, so the
/// report is the same), and the charts of the crank trains in `charts` (keyed by their names
/// in `summary.json`) are drawn from the series their run recorded ([`ChartRecorder`])
/// instead of their CSVs, which need not exist (`[output] csv = false`). A crank train not in
/// `charts` is drawn from its CSV, if any. Returns the summary as the report read it, for
/// [`index_with`].
pub fn case_report_from_run(
    case_dir: &Path,
    summary: &serde_json::Value,
    reference: Option<&str>,
    charts: BTreeMap<String, ChartData>,
) -> anyhow::Result<CaseSummary> {
    cases::case_report(case_dir, Some(summary), reference, charts)
        .map(|summary| CaseSummary {
            summary,
            default_order: reference.is_none(),
        })
        .with_context(|| format!("report of {}", case_dir.display()))
}

/// Writes the report of the sweep in `sweep_dir` (`sweep.csv` and the points' folders):
/// `report.md`, `report.html` and `plots/*.svg` with the [`KEY_METRICS`] present: over one
/// swept field, line charts of every mechanism and of the difference to `reference` in %;
/// over a grid of two, heat maps of each mechanism and of the difference, with its 0 %
/// contour. A point is linked to its `report.html` if that exists, else to its
/// `summary.json`: call this after [`case_report`] of the points. `name` is the sweep's (its
/// folder may be a temporary one).
pub fn sweep_report(sweep_dir: &Path, name: &str, reference: Option<&str>) -> anyhow::Result<()> {
    sweeps::sweep_report(sweep_dir, name, reference)
        .with_context(|| format!("report of {}", sweep_dir.display()))
}

/// Writes `<out_dir>/index.html`: a link to every case and sweep folder's report (or, without
/// one, its results), and a table of headline metrics per case and mechanism. Call it after
/// the reports.
pub fn index(out_dir: &Path) -> anyhow::Result<()> {
    index_with(out_dir, &BTreeMap::new())
}

/// [`index`], the case folders named in `known` (by folder name) listed with the summary
/// given there instead of their `summary.json` read again: a run's, which has just written
/// those folders and reported them ([`case_report_from_run`]; one reported to another
/// reference than the default is read again).
pub fn index_with(out_dir: &Path, known: &BTreeMap<String, CaseSummary>) -> anyhow::Result<()> {
    let known = known
        .iter()
        .filter(|(_, s)| s.default_order)
        .map(|(name, s)| (name.as_str(), &s.summary))
        .collect();
    index::index(out_dir, &known).with_context(|| format!("index of {}", out_dir.display()))
}
