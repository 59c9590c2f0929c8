//! The size of a case's per-step files: estimated before the case runs, and a case larger
//! than the limit refused.

use super::options::RunOptions;
use crate::per_step::{Row, RunLayout};
use cardan_case::case::Case;
use cardan_dynamics::{Gas, Inertial, LoadFamily, Solver};

/// The largest size of a case's per-step files, in bytes, unless a run is allowed more
/// ([`RunOptions::max_bytes`], `--allow-large`): 10 GB.
pub const DEFAULT_MAX_BYTES: u64 = 10_000_000_000;

/// Bytes a CSV value takes, comma included, when written as the shortest text that reads
/// back (`-1.2345678901234567e-100`: at most 24).
const CSV_BYTES_SHORTEST: u64 = 24;

/// More per-step columns than any crank train has (a pump case with gas and friction has about
/// 100 per mechanism): a bound that spares counting them for a case far below the limit.
const PLENTY_OF_COLUMNS: u64 = 4096;

/// An estimate of the bytes of the per-step files `case` writes (as its `[output]` asks):
/// rows × columns × bytes per value (8 in NPY, the digits asked plus sign, point, exponent and
/// comma in CSV), over every crank train; and that as a sentence.
pub fn estimated_bytes(case: &Case) -> Result<(u64, String), String> {
    let o = case.output;
    if !(o.csv || o.npy) {
        return Ok((0, "no per-step file".into()));
    }
    let rows = cardan_report::row_count(case.steps, o.decimation) as u64;
    let mut names = vec![Inertial::new(Solver::ClosedForm).name()];
    if case.gas.is_some() {
        names.push(Gas(Solver::ClosedForm).name());
    }
    let csv_bytes = o
        .significant_digits
        .map_or(CSV_BYTES_SHORTEST, |d| d as u64 + 7);
    let per_value = u64::from(o.npy) * 8 + u64::from(o.csv) * csv_bytes;
    let trains = if case.crank_phase != 0.0 { 2 } else { 1 };
    let mut columns = 0u64;
    for (m, setup) in case.mechanisms.iter().zip(&case.setups) {
        let stages = setup.stages();
        let layout = RunLayout {
            families: &names,
            gas: case.gas.is_some(),
            stages: &stages.iter().map(|s| s.columns()).collect::<Vec<_>>(),
        };
        columns += trains * Row::new(m.as_ref(), &layout).header().len() as u64;
    }
    let bytes = rows.saturating_mul(columns).saturating_mul(per_value);
    let what = [(o.csv, "CSV"), (o.npy, "NPY")]
        .iter()
        .filter(|(on, _)| *on)
        .map(|(_, n)| *n)
        .collect::<Vec<_>>()
        .join(" + ");
    Ok((
        bytes,
        format!(
            "about {} ({rows} rows x {columns} columns in all x {per_value} bytes per value, {what})",
            human_bytes(bytes)
        ),
    ))
}

/// `bytes` as "12.3 GB" (powers of 1000).
pub fn human_bytes(bytes: u64) -> String {
    let b = bytes as f64;
    for (unit, scale) in [("TB", 1e12), ("GB", 1e9), ("MB", 1e6), ("kB", 1e3)] {
        if b >= scale {
            return format!("{:.1} {unit}", b / scale);
        }
    }
    format!("{bytes} B")
}

/// Refuses `case` if its per-step files would be larger than `options` allows (unless it
/// allows any size): the run's own refusal, which `cardan check` makes too.
pub fn check_size(case: &Case, options: &RunOptions) -> Result<(), String> {
    if options.allow_large {
        return Ok(());
    }
    let limit = options.max_bytes.unwrap_or(DEFAULT_MAX_BYTES);
    // Most cases are far below the limit whatever their columns: no need to count them.
    let rows = cardan_report::row_count(case.steps, case.output.decimation) as u64;
    let csv_bytes = case
        .output
        .significant_digits
        .map_or(CSV_BYTES_SHORTEST, |d| CSV_BYTES_SHORTEST.max(d as u64 + 7));
    let bound = rows
        .saturating_mul(case.mechanisms.len() as u64 * 2 * PLENTY_OF_COLUMNS)
        .saturating_mul(8 + csv_bytes);
    let (bytes, estimate) = if bound <= limit {
        (0, String::new())
    } else {
        estimated_bytes(case)
            .map_err(|e| format!("{}: case \"{}\": {e}", case.file.display(), case.name))?
    };
    if bytes > limit {
        return Err(format!(
            "{}: case \"{}\": output: would write {estimate} of per-step files, more than the limit of {}: refused (thin it with [output] decimation, write fewer files, or pass --allow-large)",
            case.file.display(),
            case.name,
            human_bytes(limit)
        ));
    }
    Ok(())
}
