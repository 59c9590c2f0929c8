//! Crank motion law and the crank-angle grid.

use crate::C;

/// Steps between exact evaluations of e^{iθ} on a grid.
pub const REANCHOR: usize = 32;

/// Crank motion with constant angular acceleration, Karhula (2008) eq. (A4.2.2.1):
/// θ(t) = θ0 + ω0·t + ½·α·t².
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CrankMotion {
    /// Crank angle at t = 0, rad.
    pub start_angle: f64,
    /// Crank angular velocity at t = 0, rad/s.
    pub initial_speed: f64,
    /// Constant crank angular acceleration, rad/s².
    pub angular_acceleration: f64,
}

/// The crank at one instant.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct CrankState {
    /// Crank angle θ, rad.
    pub angle: f64,
    /// e^{iθ} = cos θ + i·sin θ, carried so that a grid can supply it without a sine per step.
    pub direction: C,
    /// Crank angular velocity ω, rad/s.
    pub speed: f64,
    /// Crank angular acceleration α, rad/s².
    pub acceleration: f64,
    /// Time since the start of the motion, s.
    pub time: f64,
}

impl CrankState {
    pub fn new(angle: f64, speed: f64, acceleration: f64, time: f64) -> Self {
        Self {
            angle,
            direction: C::from_polar(1.0, angle),
            speed,
            acceleration,
            time,
        }
    }
}

/// Why a motion cannot reach a crank angle.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum MotionError {
    #[error("the crank must turn forwards: initial_speed {0} rad/s is negative")]
    Backwards(f64),
    #[error("the crank never turns: initial_speed and angular_acceleration are both 0")]
    Still,
    #[error(
        "the crank stops before {angle_deg:.3}°: ω² = ω0² + 2·α·Δθ becomes negative \
         (initial_speed {speed} rad/s, angular_acceleration {acceleration} rad/s²)"
    )]
    Stops {
        angle_deg: f64,
        speed: f64,
        acceleration: f64,
    },
}

impl CrankMotion {
    /// The crank state at angle `theta`, with the time obtained by inverting (A4.2.2.1) and
    /// ω = sqrt(ω0² + 2·α·(θ − θ0)) (constant acceleration, so ω = ω0 + α·t as in A4.2.2.64).
    pub fn at_angle(&self, theta: f64) -> Result<CrankState, MotionError> {
        let (w, time) = self.speed_and_time(theta)?;
        Ok(CrankState::new(theta, w, self.angular_acceleration, time))
    }

    /// ω and t at angle `theta`.
    fn speed_and_time(&self, theta: f64) -> Result<(f64, f64), MotionError> {
        let (w0, a) = (self.initial_speed, self.angular_acceleration);
        if w0 < 0.0 {
            return Err(MotionError::Backwards(w0));
        }
        if w0 == 0.0 && a == 0.0 {
            return Err(MotionError::Still);
        }
        let dtheta = theta - self.start_angle;
        let w2 = w0 * w0 + 2.0 * a * dtheta;
        if w2 < 0.0 || (w2 == 0.0 && dtheta > 0.0) {
            return Err(MotionError::Stops {
                angle_deg: theta.to_degrees(),
                speed: w0,
                acceleration: a,
            });
        }
        let w = w2.sqrt();
        // t = 2Δθ/(ω0 + ω) is the root of ½αt² + ω0t − Δθ = 0 without the cancellation of
        // (−ω0 + ω)/α, and it also holds for α = 0.
        let time = if dtheta == 0.0 {
            0.0
        } else {
            2.0 * dtheta / (w0 + w)
        };
        Ok((w, time))
    }

    /// `steps + 1` crank states, uniformly spaced in crank angle from `start` to `end` (rad).
    pub fn grid(&self, start: f64, end: f64, steps: usize) -> Result<Vec<CrankState>, MotionError> {
        let h = (end - start) / steps as f64;
        (0..=steps)
            .map(|k| self.at_angle(start + h * k as f64))
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    #[test]
    fn time_inverts_the_motion_law() {
        let m = CrankMotion {
            start_angle: 0.5,
            initial_speed: 3.0,
            angular_acceleration: 100.0,
        };
        for theta in [0.5, 1.0, 7.0, 14.1] {
            let s = m.at_angle(theta).unwrap();
            let t = s.time;
            assert_relative_eq!(0.5 + 3.0 * t + 50.0 * t * t, theta, max_relative = 1e-14);
            assert_relative_eq!(s.speed, 3.0 + 100.0 * t, max_relative = 1e-13);
        }
    }

    #[test]
    fn grid_directions_are_exact_to_round_off() {
        let m = CrankMotion {
            start_angle: 1.5,
            initial_speed: 3.0,
            angular_acceleration: 10.0,
        };
        for s in m.grid(1.5, 14.1, 7200).unwrap() {
            assert!((s.direction - C::from_polar(1.0, s.angle)).norm() < 1e-14);
        }
    }

    #[test]
    fn start_from_rest_and_stopping_crank() {
        let m = CrankMotion {
            start_angle: 0.0,
            initial_speed: 0.0,
            angular_acceleration: 2.0,
        };
        assert_relative_eq!(m.at_angle(1.0).unwrap().time, 1.0, max_relative = 1e-15);
        let m = CrankMotion {
            start_angle: 0.0,
            initial_speed: 1.0,
            angular_acceleration: -1.0,
        };
        assert!(matches!(m.at_angle(0.6), Err(MotionError::Stops { .. })));
        let m = CrankMotion {
            start_angle: 0.0,
            initial_speed: 0.0,
            angular_acceleration: 0.0,
        };
        assert_eq!(m.at_angle(1.0), Err(MotionError::Still));
    }
}
