//! `model = "pressure_trace"`: a measured (or computed) indicator diagram, the cylinder's
//! absolute pressure over crank angle read from a CSV file, loads the pistons.
//!
//! The file (`file`, relative to the case file) has the header line
//! `crank_angle_deg,pressure_pa`, then one row per sample: the crank angle in the case's
//! convention (degrees from the +x axis, 90° top dead centre of an in-line machine, as the
//! per-step CSV's `crank_angle_deg`) and the absolute pressure in Pa. The angles must
//! increase and span one cycle of the machine (360° for a pump, 720° for an engine): the
//! first row is the cycle's start, the gap from the last row back to the first, a cycle on,
//! no wider than the widest gap between rows (so the trace covers the cycle as evenly as it
//! samples it). A last row at the first's angle plus the cycle (within 1e-9 of the cycle: the
//! closed form, as a run's own CSV over one cycle ends) repeats the first: its pressure must
//! be the first's within 1e-9 of the trace's largest pressure ([`CLOSURE`]), and it is
//! dropped. Between rows the pressure is interpolated linearly, across the wrap too, and
//! it repeats every cycle. The force on each piston is p·A_pis towards the crankshaft, as in
//! Karhula's models on their closed strokes (A6.2.1.1), but on every stroke: a trace of gauge
//! pressure gives the net force on a piston whose crankcase is at ambient. The Karhula models
//! put no force on their open strokes, where the pressure they report (a run's
//! `cylinder_pressure_pa`) is ambient: the trace that reproduces such a run's loads is its
//! `gas_force_n / A_pis` (docs/results.md; `runner/tests/pressure_trace.rs`).

use super::model::{entry, Clearance, Context, GasEntry, ModelTable, ReadModel};
use crate::error::{CaseError, Machine};
use crate::plausible::CompressionRatio;
use crate::quantity::Ranged;
use cardan_gas::{Chamber, GasError, GasMetric, GasModel, PreparedGas};
use schemars::JsonSchema;
use serde::Deserialize;
use std::f64::consts::PI;

/// The registry line.
pub const ENTRY: GasEntry = entry::<PressureTraceTable>("pressure_trace", None);

/// The compression ratio when not given: any, as the pressure does not depend on the volume
/// (10 keeps the cylinder's rules satisfied).
pub const DEFAULT_COMPRESSION_RATIO: f64 = 10.0;

/// `[gas]` of `model = "pressure_trace"`: a measured (or computed) indicator diagram.
#[derive(Debug, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct PressureTraceTable {
    /// The trace: a CSV file, relative to the case file, with the header line
    /// `crank_angle_deg,pressure_pa` then rows of crank angle (degrees, increasing, one cycle
    /// of the machine) and absolute pressure (Pa); required.
    pub file: String,
    /// Compression ratio of the cylinder, greater than 1; it does not enter the pressure.
    /// Default 10.
    pub compression_ratio: Option<Ranged<CompressionRatio>>,
}

/// The trace, in SI: crank angles (rad, increasing) and absolute pressures (Pa), and the
/// cycle it repeats over (rad).
#[derive(Debug, Clone, PartialEq)]
pub struct PressureTrace {
    angles: Vec<f64>,
    pressures: Vec<f64>,
    period: f64,
}

impl PressureTrace {
    /// The pressure at crank angle `theta` (rad): the trace's linear interpolation, periodic.
    pub fn pressure(&self, theta: f64) -> f64 {
        let (a, p) = (&self.angles, &self.pressures);
        let x = a[0] + (theta - a[0]).rem_euclid(self.period);
        // The row at or before x (x ≥ a[0]); past the last row, the wrap back to the first.
        let k = a.partition_point(|&t| t <= x) - 1;
        let (t0, p0) = (a[k], p[k]);
        let (t1, p1) = match a.get(k + 1) {
            Some(&t) => (t, p[k + 1]),
            None => (a[0] + self.period, p[0]),
        };
        p0 + (p1 - p0) * (x - t0) / (t1 - t0)
    }
}

impl ModelTable for PressureTraceTable {
    fn build(self, cx: &Context) -> Result<ReadModel, CaseError> {
        let period = match cx.machine {
            Machine::Engine => 4.0 * PI,
            _ => 2.0 * PI,
        };
        let kind = format!("pressure trace over {period} rad");
        let limit = (cardan_files::DATA_TABLE, kind.as_str());
        let trace = cx.read_file("file", &self.file, limit, |text| parse(text, period))?;
        // The cylinder's clearance does not enter the pressure.
        let ratio = self
            .compression_ratio
            .map_or(DEFAULT_COMPRESSION_RATIO, |r| r.si);
        Ok((trace, Clearance::CompressionRatio(ratio)))
    }
}

/// The relative tolerance of a trace's closed form: a last row within this fraction of the
/// cycle of the first's angle plus the cycle is the first row repeated, and its pressure must
/// be the first's within this fraction of the trace's largest pressure (a trace written from a
/// periodic computation, as a run's own `cylinder_pressure_pa` column over one cycle, leaves
/// round-off there; a real mismatch is far larger).
pub const CLOSURE: f64 = 1e-9;

/// The trace of the CSV `text` over a cycle of `period` (rad), or the rule it breaks (with the
/// line).
fn parse(text: &str, period: f64) -> Result<PressureTrace, String> {
    let mut lines = text
        .lines()
        .enumerate()
        .filter(|(_, l)| !l.trim().is_empty());
    match lines.next() {
        Some((_, h)) if h.trim() == "crank_angle_deg,pressure_pa" => {}
        _ => return Err("must start with the header line crank_angle_deg,pressure_pa".into()),
    }
    let (mut angles, mut pressures) = (Vec::new(), Vec::new());
    // The line of the last row read, for the closing row's message.
    let mut last_line = 0;
    for (n, line) in lines {
        last_line = n + 1;
        let cells: Vec<&str> = line.split(',').map(str::trim).collect();
        let number = |s: &str| s.parse::<f64>().ok().filter(|x| x.is_finite());
        let (Some(a), Some(p), 2) = (
            cells.first().and_then(|c| number(c)),
            cells.get(1).and_then(|c| number(c)),
            cells.len(),
        ) else {
            return Err(format!(
                "line {}: \"{line}\" is not two finite numbers",
                n + 1
            ));
        };
        if p < 0.0 {
            return Err(format!(
                "line {}: an absolute pressure cannot be negative ({p} Pa)",
                n + 1
            ));
        }
        if angles.last().is_some_and(|&last| a.to_radians() <= last) {
            return Err(format!(
                "line {}: crank angle {a}° does not increase (the rows must be sorted by angle)",
                n + 1
            ));
        }
        angles.push(a.to_radians());
        pressures.push(p);
    }
    if angles.len() < 2 {
        return Err("needs at least two rows".into());
    }
    let cycle = period.to_degrees();
    let span = angles[angles.len() - 1] - angles[0];
    let closing = span - period;
    if closing.abs() <= CLOSURE * period {
        // The closed form: the last row is the first a cycle on, with its pressure.
        let (first, last) = (pressures[0], pressures[pressures.len() - 1]);
        let largest = pressures.iter().fold(0.0, |a: f64, &b| a.max(b));
        if (last - first).abs() > CLOSURE * largest {
            return Err(format!(
                "line {last_line}: the row at {:.6}°, the first's angle plus the machine's cycle of {cycle}°, closes the trace: its pressure ({last} Pa) must be the first row's ({first} Pa) within {CLOSURE:e} of the trace's largest ({largest} Pa)",
                angles[angles.len() - 1].to_degrees()
            ));
        }
        angles.pop();
        pressures.pop();
        if angles.len() < 2 {
            return Err("needs at least two rows besides the one closing the cycle".into());
        }
    } else if closing > 0.0 {
        return Err(format!(
            "line {last_line}: spans {:.6}°, {:.3e}° more than the machine's cycle of {cycle}°: give one cycle (a last row at the first's angle plus the cycle, within {CLOSURE:e} of it, closes the trace)",
            span.to_degrees(),
            closing.to_degrees()
        ));
    }
    let widest = angles.windows(2).map(|w| w[1] - w[0]).fold(0.0, f64::max);
    let wrap = angles[0] + period - angles[angles.len() - 1];
    if wrap > widest * (1.0 + 1e-9) {
        return Err(format!(
            "covers {:.6}° of the machine's cycle of {cycle}°: the gap of {:.6}° back to the first row is wider than any between rows ({:.6}°)",
            span.to_degrees(),
            wrap.to_degrees(),
            widest.to_degrees()
        ));
    }
    Ok(PressureTrace {
        angles,
        pressures,
        period,
    })
}

impl GasModel for PressureTrace {
    fn prepare<'a>(
        &'a self,
        chamber: Chamber<'a>,
        _speed: f64,
    ) -> Result<Box<dyn PreparedGas + 'a>, GasError> {
        Ok(Box::new(Prepared {
            trace: self,
            area: chamber.cylinder.area,
        }))
    }
}

struct Prepared<'a> {
    trace: &'a PressureTrace,
    area: f64,
}

impl PreparedGas for Prepared<'_> {
    fn at(&self, theta: f64) -> (f64, f64) {
        let p = self.trace.pressure(theta);
        (p, p * self.area)
    }

    fn metrics(&self) -> Vec<GasMetric> {
        Vec::new()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const TRACE: &str = "crank_angle_deg,pressure_pa\n0,1e5\n90,5e5\n180,1e5\n270,2e5\n";

    /// Linear between rows, across the wrap (270° → 360°), and periodic.
    #[test]
    fn the_trace_is_interpolated_linearly_and_repeats() {
        let t = parse(TRACE, 2.0 * PI).unwrap();
        let at = |deg: f64| t.pressure(deg.to_radians());
        for (deg, p) in [
            (0.0, 1e5),
            (45.0, 3e5),
            (90.0, 5e5),
            (135.0, 3e5),
            (315.0, 1.5e5),
            (360.0, 1e5),
            (405.0, 3e5),
            (-45.0, 1.5e5),
        ] {
            assert!(
                (at(deg) - p).abs() < 1e-6,
                "{deg}°: {} Pa, not {p}",
                at(deg)
            );
        }
    }

    /// A case names its trace file: one that cannot be read, or none, is refused naming
    /// `gas.file`.
    #[test]
    fn a_missing_trace_file_names_the_field() {
        let configs = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../configs");
        let file = configs.join("example-pressure-trace.toml");
        let text = std::fs::read_to_string(&file).unwrap();
        for (from, to, rule) in [
            ("traces/karhula", "traces/nothing-", "cannot read"),
            (
                "file = ",
                "# file = ",
                "required by gas.model = \"pressure_trace\"",
            ),
        ] {
            let e = crate::case::parse(&file, &text.replace(from, to)).unwrap_err();
            let e = e.to_string();
            assert!(e.contains("gas.file") && e.contains(rule), "{e}");
        }
    }

    /// The closed form (issue 35 §4): a last row at the first's angle plus the cycle with the
    /// first's pressure (to round-off: 1e-10 of it) is the open trace, the same pressure at
    /// every angle; with another pressure it is refused naming the line, both pressures and
    /// the tolerance; a row past the cycle says by how much, never "spans 360°, more than the
    /// machine's cycle of 360°".
    #[test]
    fn a_trace_closed_by_its_first_row_a_cycle_on() {
        let open = parse(TRACE, 2.0 * PI).unwrap();
        let closed = parse(
            &format!(
                "{TRACE}360,100000.00001
"
            ),
            2.0 * PI,
        )
        .unwrap();
        for deg in [0.0, 45.0, 300.0, 315.0, 359.0, 360.0, -10.0] {
            let theta = f64::to_radians(deg);
            assert_eq!(open.pressure(theta), closed.pressure(theta), "{deg}°");
        }
        let e = parse(
            &format!(
                "{TRACE}360,1.5e5
"
            ),
            2.0 * PI,
        )
        .unwrap_err();
        for part in [
            "line 6",
            "150000 Pa",
            "100000 Pa",
            "1e-9",
            "closes the trace",
        ] {
            assert!(e.contains(part), "{part}: {e}");
        }
        let e = parse(
            &format!(
                "{TRACE}360.001,1e5
"
            ),
            2.0 * PI,
        )
        .unwrap_err();
        assert!(e.contains("1.000e-3° more than"), "{e}");
        assert!(
            !e.contains("spans 360°") && !e.contains("spans 360.000000°"),
            "{e}"
        );
    }

    /// Refused: no header, unsorted, negative, more or less than a cycle, a bad number.
    #[test]
    fn bad_traces_are_refused_with_the_rule() {
        for (text, rule) in [
            ("0,1e5\n90,2e5\n", "header"),
            (
                "crank_angle_deg,pressure_pa\n0,1e5\n90,2e5\n45,1e5\n",
                "does not increase",
            ),
            ("crank_angle_deg,pressure_pa\n0,1e5\n90,-2\n", "negative"),
            ("crank_angle_deg,pressure_pa\n0,1e5\n90,2e5\n", "gap"),
            (
                "crank_angle_deg,pressure_pa\n0,1e5\n200,2e5\n400,1e5\n",
                "more than",
            ),
            ("crank_angle_deg,pressure_pa\n0,1e5\n90,x\n", "line 3"),
            ("crank_angle_deg,pressure_pa\n0,1e5\n", "two rows"),
        ] {
            let e = parse(text, 2.0 * PI).unwrap_err();
            assert!(e.contains(rule), "{text:?}: {e}");
        }
    }
}
