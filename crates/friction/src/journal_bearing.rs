//! Hydrodynamic journal bearings: Petroff, the short (Ocvirk) bearing with the eccentricity
//! solved from the instantaneous load, and the Thai thesis's eccentric form. The formulas and
//! the worked cases the tests use are summarised in `docs/validation/journal-bearings.md`.
//!
//! All models are quasi-static: the film force balances the instantaneous load at the
//! instantaneous relative speed (no squeeze term, no whirl). For a dynamically loaded joint
//! (both members rotating, rotating load) the speed that builds the wedge is
//! ω_j + ω_b − 2ω_F (Booker's mobility argument), not the relative speed; a caller who knows the
//! load's rotation may pass that effective speed to [`short_bearing`] as `wedge_speed` and the
//! relative speed as `relative_speed`.

use crate::{positive, FrictionError, RotaryLoss};
use std::f64::consts::PI;

/// Geometry of a plain full (360°) journal bearing.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct JournalBearing {
    /// Journal radius R, m.
    pub radius: f64,
    /// Bearing (axial) length L, m.
    pub length: f64,
    /// Radial clearance c, m.
    pub radial_clearance: f64,
}

impl JournalBearing {
    /// A bearing of journal radius `radius` (m), axial length `length` (m) and radial clearance
    /// `radial_clearance` (m); all must be positive and the clearance smaller than the radius.
    pub fn new(radius: f64, length: f64, radial_clearance: f64) -> Result<Self, FrictionError> {
        positive("radius", radius)?;
        positive("length", length)?;
        positive("radial_clearance", radial_clearance)?;
        if radial_clearance >= radius {
            return Err(FrictionError::OutOfRange {
                name: "radial_clearance",
                value: radial_clearance,
                range: "smaller than the journal radius",
            });
        }
        Ok(Self {
            radius,
            length,
            radial_clearance,
        })
    }

    /// Journal diameter D = 2R, m.
    pub fn diameter(&self) -> f64 {
        2.0 * self.radius
    }

    /// Length-to-diameter ratio L/D.
    pub fn l_over_d(&self) -> f64 {
        self.length / self.diameter()
    }

    /// Load per unit projected area P = W/(2RL), Pa (Shigley, *Mechanical Engineering Design*,
    /// ch. 12, "unit load").
    pub fn unit_load(&self, load: f64) -> f64 {
        load.abs() / (2.0 * self.radius * self.length)
    }
}

/// Petroff's friction torque and power of a concentric journal, and the friction coefficient
/// against `load`.
///
/// T = 2π μ R³ L |ω| / c (Petroff 1883; Shigley, *Mechanical Engineering Design*, ch. 12,
/// Petroff's equation, in the form T = 4π² μ N R³ L / c with N = ω/2π rev/s), P = T |ω|.
/// `viscosity` is the dynamic viscosity μ in Pa·s, `relative_speed` the journal's angular speed
/// relative to the bearing in rad/s. Returns the loss and f = T/(W R) (not finite when `load` is 0).
pub fn petroff(
    bearing: &JournalBearing,
    viscosity: f64,
    relative_speed: f64,
    load: f64,
) -> (RotaryLoss, f64) {
    let w = relative_speed.abs();
    let torque = 2.0 * PI * viscosity * bearing.radius.powi(3) * bearing.length * w
        / bearing.radial_clearance;
    let f = torque / (load.abs() * bearing.radius);
    (
        RotaryLoss {
            friction_torque: torque,
            power: torque * w,
        },
        f,
    )
}

/// Sommerfeld number S = (R/c)² μ N / P with N = |ω|/2π in rev/s and P = W/(2RL)
/// (Shigley ch. 12, the bearing characteristic number). Infinite when the load is zero.
pub fn sommerfeld_number(
    bearing: &JournalBearing,
    viscosity: f64,
    relative_speed: f64,
    load: f64,
) -> f64 {
    let n = relative_speed.abs() / (2.0 * PI);
    (bearing.radius / bearing.radial_clearance).powi(2) * viscosity * n / bearing.unit_load(load)
}

/// Power loss of an eccentric journal with the pressure term dropped, as the Thai thesis uses
/// for the con-rod and main bearings: P = 2π μ R³ L Δω² / (c √(1 − ε²)) (Thai thesis eq.
/// 2.5.a.13; `docs/validation/thai-thesis.md`). The eccentricity ratio ε is an
/// input here (the thesis does not solve it from the load); ε = 0 gives Petroff.
pub fn thai_eccentric_loss(
    bearing: &JournalBearing,
    viscosity: f64,
    relative_speed: f64,
    eccentricity_ratio: f64,
) -> RotaryLoss {
    let w = relative_speed.abs();
    let e2 = eccentricity_ratio * eccentricity_ratio;
    let torque = 2.0 * PI * viscosity * bearing.radius.powi(3) * bearing.length * w
        / (bearing.radial_clearance * (1.0 - e2).sqrt());
    RotaryLoss {
        friction_torque: torque,
        power: torque * w,
    }
}

/// Sommerfeld number of the short (Ocvirk) bearing with a half (π) film:
/// S = (D/L)² (1 − ε²)² / (π ε √(π²(1 − ε²) + 16 ε²)).
///
/// Source: Ocvirk (1952), NACA TN 2808; the load function
/// W̄ = ε √(16ε² + π²(1 − ε²)) / (4(1 − ε²)²) in dimensionless form; written in Sommerfeld form in
/// `docs/validation/journal-bearings.md`.
pub fn ocvirk_sommerfeld(eccentricity_ratio: f64, l_over_d: f64) -> f64 {
    let e = eccentricity_ratio;
    let e2 = e * e;
    (1.0 / l_over_d).powi(2) * (1.0 - e2).powi(2)
        / (PI * e * (PI * PI * (1.0 - e2) + 16.0 * e2).sqrt())
}

/// Attitude angle of the short bearing, rad: tan φ = π √(1 − ε²) / (4ε) (Ocvirk 1952;
/// `docs/validation/journal-bearings.md`).
pub fn ocvirk_attitude_angle(eccentricity_ratio: f64) -> f64 {
    let e = eccentricity_ratio;
    (PI * (1.0 - e * e).sqrt()).atan2(4.0 * e)
}

/// Eccentricity ratio ε of the short bearing that carries Sommerfeld number `sommerfeld` at
/// length-to-diameter ratio `l_over_d` (inverse of [`ocvirk_sommerfeld`], which decreases
/// monotonically from ∞ at ε = 0 to 0 at ε = 1). Solved by bisection to |Δε| < 1e-14.
/// S = ∞ (no load) gives 0, S = 0 (no speed) gives 1.
pub fn ocvirk_eccentricity(sommerfeld: f64, l_over_d: f64) -> f64 {
    if sommerfeld.is_infinite() || sommerfeld.is_nan() {
        return 0.0;
    }
    if sommerfeld <= 0.0 {
        return 1.0;
    }
    let (mut lo, mut hi) = (0.0_f64, 1.0_f64);
    // ocvirk_sommerfeld(lo) > S > ocvirk_sommerfeld(hi) throughout.
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if ocvirk_sommerfeld(mid, l_over_d) > sommerfeld {
            lo = mid;
        } else {
            hi = mid;
        }
        if hi - lo < 1e-14 {
            break;
        }
    }
    0.5 * (lo + hi)
}

/// State of a short bearing under an instantaneous load.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct ShortBearingState {
    /// Sommerfeld number S (with the wedge speed).
    pub sommerfeld: f64,
    /// Eccentricity ratio ε = e/c.
    pub eccentricity_ratio: f64,
    /// Attitude angle φ between the load line and the line of centres, rad.
    pub attitude_angle: f64,
    /// Minimum film thickness h0 = c(1 − ε), m.
    pub min_film_thickness: f64,
    /// Friction torque on the journal and the power it dissipates.
    pub loss: RotaryLoss,
    /// Friction coefficient f = T/(W R) (not finite at zero load).
    pub friction_coefficient: f64,
}

/// Short (Ocvirk) bearing with the eccentricity solved from the instantaneous load, so that the
/// loss follows the load.
///
/// ε from [`ocvirk_eccentricity`] with S computed from `wedge_speed` (rad/s; pass the relative
/// speed for a fixed load on a stationary bushing). The friction torque on the journal is the
/// full-film (2π) Couette term plus the load term,
/// T = 2π μ R³ L |ω| / (c √(1 − ε²)) + c ε W sin φ / 2
/// (Hamrock, *Fundamentals of Fluid Film Lubrication*, journal-bearing friction; the same split
/// as the Thai thesis eq. 2.5.a.11 with F⊥ = W sin φ, which the thesis drops), and the power is
/// P = T |ω| with ω = `relative_speed`.
///
/// Limits: W → 0 gives ε → 0 and Petroff; ω → 0 gives ε → 1 and P → 0 (the torque also tends
/// to 0 because (1 − ε²) ~ √S). The short-bearing theory is accurate for L/D ≲ ½ and
/// under-predicts ε (over-predicts S) for longer bearings, whose end leakage it overstates.
pub fn short_bearing(
    bearing: &JournalBearing,
    viscosity: f64,
    load: f64,
    relative_speed: f64,
    wedge_speed: f64,
) -> ShortBearingState {
    let w_load = load.abs();
    let s = sommerfeld_number(bearing, viscosity, wedge_speed, w_load);
    let eps = ocvirk_eccentricity(s, bearing.l_over_d());
    let phi = ocvirk_attitude_angle(eps);
    let w = relative_speed.abs();
    let c = bearing.radial_clearance;
    let one_minus = 1.0 - eps * eps;
    let couette = if w == 0.0 {
        0.0
    } else {
        2.0 * PI * viscosity * bearing.radius.powi(3) * bearing.length * w
            / (c * one_minus.max(f64::MIN_POSITIVE).sqrt())
    };
    let load_term = if w == 0.0 {
        0.0
    } else {
        0.5 * c * eps * w_load * phi.sin()
    };
    let torque = couette + load_term;
    ShortBearingState {
        sommerfeld: s,
        eccentricity_ratio: eps,
        attitude_angle: phi,
        min_film_thickness: c * (1.0 - eps),
        loss: RotaryLoss {
            friction_torque: torque,
            power: torque * w,
        },
        friction_coefficient: torque / (w_load * bearing.radius),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sommerfeld_inverse_round_trip() {
        // The bisection stops at 1e-14 in ε; the ε tolerance 1e-12 leaves room for the
        // flat S(ε) near ε → 1.
        for &ld in &[0.25, 0.5, 1.0] {
            for i in 1..20 {
                let e = i as f64 / 20.0;
                let s = ocvirk_sommerfeld(e, ld);
                assert!((ocvirk_eccentricity(s, ld) - e).abs() < 1e-12);
            }
        }
    }

    #[test]
    fn zero_speed_zero_loss() {
        let b = JournalBearing::new(0.025, 0.02, 25e-6).unwrap();
        let st = short_bearing(&b, 0.01, 5000.0, 0.0, 0.0);
        assert_eq!(st.loss.power, 0.0);
        assert_eq!(st.eccentricity_ratio, 1.0);
    }
}
