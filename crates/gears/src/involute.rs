//! The involute function and its inverse (ISO 21771:2007, clause 4.2: inv α = tan α − α).

use crate::error::{require, GearError};

/// Involute function inv α = tan α − α (ISO 21771, eq. for the involute polar angle) \[rad\].
pub fn inv(alpha: f64) -> f64 {
    alpha.tan() - alpha
}

/// Inverse of the involute function: the angle α in [0, π/2) with inv α = `y` \[rad\].
///
/// Safeguarded Newton iteration. Because inv is increasing and convex on (0, π/2) and
/// inv α ≥ α³/3, the start (3y)^(1/3) lies right of the root and Newton converges
/// monotonically; a bisection step keeps the iterate inside the bracket otherwise.
pub fn inv_inverse(y: f64) -> Result<f64, GearError> {
    // inv(80°) ≈ 4.3; far beyond any gear pressure angle.
    require(
        y.is_finite() && (0.0..=4.3).contains(&y),
        "involute function value",
        "must lie in [0, inv 80°]",
        y,
    )?;
    if y == 0.0 {
        return Ok(0.0);
    }
    let (mut lo, mut hi) = (0.0_f64, 80.0_f64.to_radians());
    let mut a = (3.0 * y).cbrt().min(hi);
    for _ in 0..100 {
        let f = inv(a) - y;
        if f > 0.0 {
            hi = a;
        } else {
            lo = a;
        }
        let t = a.tan();
        let mut next = a - f / (t * t);
        if !(next > lo && next < hi) {
            next = 0.5 * (lo + hi);
        }
        if (next - a).abs() <= 1e-15 * a.max(1e-3) {
            return Ok(next);
        }
        a = next;
    }
    Err(GearError::NoConvergence {
        what: "inverse involute function",
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn inverse_round_trips() {
        // Round trip to 1e-13 rad: only double rounding is involved.
        for deg in [0.5_f64, 10.0, 14.5, 20.0, 25.0, 31.3209, 45.0, 70.0] {
            let a = deg.to_radians();
            assert!((inv_inverse(inv(a)).unwrap() - a).abs() < 1e-13, "{deg}");
        }
    }

    #[test]
    fn rejects_negative() {
        assert!(inv_inverse(-0.1).is_err());
        assert!(inv_inverse(f64::NAN).is_err());
    }
}
