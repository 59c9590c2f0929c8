//! The crank's state at one instant: the bottom of the crate, which every module reads.

pub use num_complex::Complex64 as C;

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
