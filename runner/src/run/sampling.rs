//! The sampling check of a coarse grid: the peaks of a run of fewer than 360 steps per
//! revolution again on its grid shifted by a third and two thirds of a step, and the warning
//! when they show the run's own peaks low by more than [`SAMPLING_TOLERANCE`].

use cardan_case::case::Case;
use cardan_dynamics::stepper::GasAt;
use cardan_dynamics::{run_parallel, LoadFamily, Summary, SummarySink};
use cardan_mechanism::{CrankMotion, Grid, Mechanism};

/// Steps per crank revolution below which a run estimates its peaks' sampling error: from a 1°
/// grid on, the error of a peak of a smooth load, about (Δθ·k)²/8 for its k-th harmonic, is
/// under [`SAMPLING_TOLERANCE`] for the orders a crank mechanism has (k ≤ 4: 6·10⁻⁴), and so it
/// is for the sharpest shipped load, the Karhula engine's combustion (measured at 1° against
/// 0.1°: 4.2·10⁻⁴ on the slider-crank's peak gas force). The check costs two summary runs.
pub(super) const SAMPLING_CHECK_STEPS_PER_REV: f64 = 360.0 - 1e-9;

/// Largest relative sampling error of a peak metric that passes without a warning.
const SAMPLING_TOLERANCE: f64 = 1e-3;

/// The warning for the peak metrics (`*_max`) of `fine` (a run of `steps` intervals, `per_rev`
/// of them per revolution) that its samples may put more than [`SAMPLING_TOLERANCE`] below
/// the true peak, from `shifted`: the same run's peaks on the grids shifted by a third and two
/// thirds of a step. Together the three sample the run every third of a step, so their
/// largest value less the run's own is what the run's grid missed; it is a lower bound of the
/// true error (no sample exceeds the peak) and, for a smooth peak (a parabola near its
/// maximum), short of it by at most a ninth of the worst error a grid of this step can have.
pub(super) fn sampling_warning(
    fine: &Summary,
    shifted: &[Summary],
    steps: usize,
    per_rev: f64,
) -> Option<String> {
    let mut worst: Option<(f64, &str)> = None;
    let mut count = 0;
    for m in fine.metrics.iter().filter(|m| m.name.ends_with("_max")) {
        if m.value.abs() <= f64::MIN_POSITIVE {
            continue;
        }
        let best = shifted
            .iter()
            .filter_map(|s| s.get(&m.name))
            .fold(m.value, f64::max);
        let error = (best - m.value) / best.abs();
        if error > SAMPLING_TOLERANCE {
            count += 1;
            if worst.is_none_or(|(w, _)| error > w) {
                worst = Some((error, &m.name));
            }
        }
    }
    let (error, name) = worst?;
    // The error goes as the step squared.
    let needed = (steps as f64 * (error / SAMPLING_TOLERANCE).sqrt()).ceil();
    Some(format!(
        "{count} peak metric(s) are low from sampling at {per_rev:.0} steps per revolution, by \
         at least {:.2} % ({name}: the grid shifted by a third of a step finds more); raise \
         motion.steps to at least {needed} for {} %",
        100.0 * error,
        100.0 * SAMPLING_TOLERANCE
    ))
}

/// The peaks of the run of `mechanism` in `case` (its crank `motion`, load `families` named
/// `names`, `gas`) on its grid shifted by a third and by two thirds of a step (summaries
/// only), for [`sampling_warning`].
pub(super) fn shifted_peaks(
    case: &Case,
    mechanism: &dyn Mechanism,
    motion: CrankMotion,
    names: &[&'static str],
    families: &[&dyn LoadFamily],
    gas: Option<GasAt>,
) -> Result<Vec<Summary>, String> {
    let mut shifted = Vec::new();
    let h = (case.end_angle - case.motion.start_angle) / case.steps as f64;
    let n = case.steps - 1;
    for third in [1.0, 2.0] {
        let a = motion.start_angle + third * h / 3.0;
        let mut grid = Grid::new(motion, a, a + n as f64 * h, n);
        let mut sink = SummarySink::new(mechanism, names, n + 1).for_peaks();
        run_parallel(mechanism, &mut grid, families, gas, &mut [], &mut sink)
            .map_err(|e| format!("the run on the shifted grid (sampling check): {e}"))?;
        shifted.push(sink.finish(mechanism)?);
    }
    Ok(shifted)
}
