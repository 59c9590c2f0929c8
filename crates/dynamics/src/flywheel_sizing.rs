//! The flywheel that brings the machine's speed fluctuation down to a target: a root of the
//! coefficient of fluctuation as a function of the flywheel's inertia, each evaluation a solve
//! of the machine's cycles (`machine_motion::solve_cycles`).
//!
//! Why not plain bisection: each evaluation runs every cycle of the solve, with friction a
//! fixed point per step; bisection to 1e-6 of the inertia took about 28 of them, which made a
//! run with friction and a sized flywheel 15-23 times slower than either alone (issue 36.10).
//! The coefficient is nearly inversely proportional to the inertia the crank carries
//! (δ ≈ ΔE/(J ω²), Petrescu 2015 §3, Shigley 16-62), so its reciprocal is nearly linear in the
//! flywheel: the textbook estimate brackets the root in one or two evaluations and the
//! Illinois variant of regula falsi on 1/δ closes the bracket from both sides in a few more
//! (Dowell & Jarratt 1971), as fast as the secant method on a smooth function and as safe as
//! bisection (a bisection step where the false position would not shrink the bracket).

/// The most evaluations of the coefficient a sizing may take: far above the 6-10 a machine
/// takes; the bisection fallback alone closes a bracket of 2⁶⁰ to 1e-6 in fewer.
pub const MAX_EVALUATIONS: usize = 120;

/// The relative width of the bracket at which the sizing stops: the flywheel is stated to 1e-6
/// of itself.
pub const INERTIA_TOLERANCE: f64 = 1e-6;

/// Why no flywheel meets the target coefficient of fluctuation.
#[derive(Debug, Clone, PartialEq)]
pub enum SizingError {
    /// The target was not met in [`MAX_EVALUATIONS`] evaluations.
    NotFound { target: f64 },
    /// The target is missed still with a flywheel of `largest` kg·m² (2⁶⁰ times the scale).
    Unreachable { target: f64, largest: f64 },
    /// An evaluation failed: why.
    Solve(String),
}

/// What the target fails by (a [`SizingError::Solve`]: the solve's own words).
impl std::fmt::Display for SizingError {
    fn fmt(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
        match self {
            SizingError::NotFound { target } => write!(
                f,
                "the flywheel for {target} not found in {MAX_EVALUATIONS} solves"
            ),
            SizingError::Unreachable { target, largest } => write!(
                f,
                "{target} cannot be reached (still missed with a flywheel of {largest} kg·m²)"
            ),
            SizingError::Solve(why) => f.write_str(why),
        }
    }
}

/// The smallest flywheel (kg·m²) at or above `start` whose coefficient of fluctuation
/// `fluctuation(J)` is at most `target`, to [`INERTIA_TOLERANCE`], and that coefficient: `start`
/// itself if it meets the target. `fluctuation` gives the coefficient (infinite where the
/// machine stops) and the largest reduced inertia of the mechanism over the cycle (kg·m²),
/// the scale of a first step; `scale` is used where that is zero (a mechanism of no inertia
/// without a flywheel). An unreachable target (still missed at 2⁶⁰ times the scale) is a
/// [`SizingError`], as is a failed evaluation.
pub fn inertia_for(
    mut fluctuation: impl FnMut(f64) -> Result<(f64, f64), String>,
    start: f64,
    target: f64,
    scale: f64,
) -> Result<(f64, f64), SizingError> {
    let mut evaluations = 0;
    let mut at = |j: f64| {
        evaluations += 1;
        if evaluations > MAX_EVALUATIONS {
            return Err(SizingError::NotFound { target });
        }
        fluctuation(j).map_err(SizingError::Solve)
    };
    let (bare, carried) = at(start)?;
    if bare <= target {
        return Ok((start, bare));
    }
    let carried = if carried > 0.0 { carried } else { scale };
    // g(J) = 1/δ(J) − 1/target: negative below the root, positive above, nearly linear.
    let g = |delta: f64| 1.0 / delta - 1.0 / target;
    let (mut lo, mut g_lo) = (start, g(bare));
    let (mut hi, mut at_hi) = (f64::NAN, f64::NAN);
    // Bracketing: δ ∝ 1/(J + J*) from the last point that missed (the textbook estimate),
    // never less than doubling; a machine that stops at `lo` doubles.
    let mut next = estimate(lo, bare, target, carried).max(2.0 * lo.max(carried));
    for _ in 0..=60 {
        let (delta, _) = at(next)?;
        if delta <= target {
            (hi, at_hi) = (next, delta);
            break;
        }
        (lo, g_lo) = (next, g(delta));
        next = estimate(lo, delta, target, carried).max(2.0 * lo);
    }
    if hi.is_nan() {
        return Err(SizingError::Unreachable {
            target,
            largest: lo,
        });
    }
    let mut g_hi = g(at_hi);
    // Illinois: the end kept twice in a row has its value halved, so the false position moves
    // past the root and the bracket closes from both sides.
    let mut kept = 0i8;
    while hi - lo > INERTIA_TOLERANCE * hi {
        let false_position = if g_lo.is_finite() && g_hi > g_lo {
            hi - g_hi * (hi - lo) / (g_hi - g_lo)
        } else {
            f64::NAN
        };
        // At least half the tolerance inside the bracket: a false position on the root (at an
        // end, or beside the end just moved) then closes the bracket with the next evaluation.
        let least = 0.5 * INERTIA_TOLERANCE * hi;
        let mid = if false_position.is_finite() {
            false_position.clamp(lo + least, hi - least)
        } else if lo > 0.0 {
            (lo * hi).sqrt()
        } else {
            0.5 * hi
        };
        let (delta, _) = at(mid)?;
        if delta > target {
            (lo, g_lo) = (mid, g(delta));
            if kept == 1 {
                g_hi *= 0.5;
            }
            kept = 1;
        } else {
            (hi, at_hi, g_hi) = (mid, delta, g(delta));
            if kept == -1 {
                g_lo *= 0.5;
            }
            kept = -1;
        }
    }
    Ok((hi, at_hi))
}

/// The flywheel at which δ ∝ 1/(J + J*) (the coefficient's law for a machine whose inertia
/// J + J* carries the energy fluctuation ΔE: δ = ΔE/((J + J*) ω²)) meets `target`, from the
/// flywheel `j` giving `delta` and the mechanism's inertia `carried`; a little past it, so that
/// the estimate lands above the root and brackets it (a 5 % margin, wider than the law's error
/// for a flywheel that dominates the inertia).
fn estimate(j: f64, delta: f64, target: f64, carried: f64) -> f64 {
    if !delta.is_finite() {
        return f64::NAN;
    }
    1.05 * (j + carried) * delta / target - carried
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The law δ = ΔE/((J + J*) ω²) (ω = 1) and its exact root.
    fn law(de: f64, carried: f64) -> impl Fn(f64) -> Result<(f64, f64), String> {
        move |j| Ok((de / (j + carried), carried))
    }

    #[test]
    fn the_root_of_the_textbook_law_in_a_few_solves() {
        for (de, carried, target) in [
            (100.0, 0.05, 0.01),
            (12_200.0, 2.0, 0.0005),
            (1.0, 1e-3, 0.2),
        ] {
            let root = de / target - carried;
            let mut solves = 0;
            let counted = |j: f64| {
                solves += 1;
                law(de, carried)(j)
            };
            let (j, delta) = inertia_for(counted, 0.0, target, 1e-6).unwrap();
            assert!(delta <= target, "δ {delta} above {target}");
            assert!(
                (j - root).abs() <= 2.0 * INERTIA_TOLERANCE * root,
                "{j} against {root}"
            );
            assert!(solves <= 8, "{solves} solves");
        }
    }

    #[test]
    fn a_coefficient_far_from_the_law_is_still_bracketed_and_closed() {
        // δ ∝ 1/√J: the law's estimate falls short every time; doubling and bisection finish.
        let f = |j: f64| {
            Ok((
                if j > 0.0 {
                    0.3 / j.sqrt()
                } else {
                    f64::INFINITY
                },
                0.0,
            ))
        };
        let (j, delta) = inertia_for(f, 0.0, 0.003, 1e-3).unwrap();
        let root: f64 = (0.3f64 / 0.003).powi(2);
        assert!(delta <= 0.003);
        assert!(
            (j - root).abs() <= 2.0 * INERTIA_TOLERANCE * root,
            "{j} against {root}"
        );
    }

    #[test]
    fn a_machine_that_stops_below_a_flywheel_and_an_unreachable_target() {
        // Stops (δ infinite) below 10 kg·m², the law above.
        let f = |j: f64| Ok((if j < 10.0 { f64::INFINITY } else { 50.0 / j }, 0.0));
        let (j, delta) = inertia_for(f, 0.0, 0.5, 1e-2).unwrap();
        assert!(delta <= 0.5 && (j - 100.0).abs() <= 2e-4, "{j}");
        // A coefficient that never falls below 0.1.
        let floor = |j: f64| Ok((0.1 + 1.0 / (1.0 + j), 1.0));
        let e = inertia_for(floor, 0.0, 0.05, 1.0).unwrap_err();
        assert!(
            matches!(e, SizingError::Unreachable { target: 0.05, .. }),
            "{e}"
        );
        // A flywheel that meets the target already is kept.
        assert_eq!(
            inertia_for(law(1.0, 1.0), 5.0, 0.5, 1.0).unwrap(),
            (5.0, 1.0 / 6.0)
        );
    }
}
