//! Kinematics of reciprocating mechanisms on the complex plane.
//!
//! Conventions of Karhula (2008), chapter 4: the main bearing axis is the origin, the cylinder
//! lies on the imaginary (iy) axis, the crank angle θ is measured from the real axis and grows in
//! the direction of rotation, so θ = 90° is top dead centre. Every quantity is SI: m, m/s, m/s²,
//! rad, rad/s, rad/s², s.
//!
//! Each mechanism maps a [`CrankState`] to a [`KinematicState`]: the same plain struct for every
//! mechanism, so that loads, gas models and friction models downstream never need to know which
//! mechanism produced it.

pub mod cardan_gear;
pub mod motion;
pub mod polar;
pub mod slider_crank;
mod state;

pub use cardan_gear::CardanGear;
pub use motion::{CrankMotion, CrankState};
pub use num_complex::Complex64 as C;
pub use polar::PolarComponents;
pub use slider_crank::SliderCrank;
pub use state::{JointSpeeds, KinematicState, PistonMotion, PointMotion, RodMotion, WheelMotion};

/// A physically impossible or ill-posed machine.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum GeometryError {
    #[error("{field} must be a finite positive length in metres, got {value}")]
    NotPositive { field: &'static str, value: f64 },
    #[error(
        "rod_length {rod} m must be longer than crank_length {crank} m plus |pin_offset| {offset} m, \
         or the rod cannot reach the cylinder axis at every crank angle"
    )]
    RodTooShort { rod: f64, crank: f64, offset: f64 },
    #[error("{field} must be finite, got {value}")]
    NotFinite { field: &'static str, value: f64 },
    #[error("rod_point {point} m must lie on the rod, between 0 and rod_length {rod} m")]
    PointOffRod { point: f64, rod: f64 },
}

/// The mechanisms the toolkit knows. Names are the ones used in case files and outputs.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum MechanismKind {
    SliderCrank,
    CardanGear,
}

impl MechanismKind {
    pub const ALL: [MechanismKind; 2] = [MechanismKind::SliderCrank, MechanismKind::CardanGear];

    pub fn name(self) -> &'static str {
        match self {
            MechanismKind::SliderCrank => "slider_crank",
            MechanismKind::CardanGear => "cardan_gear",
        }
    }

    pub fn from_name(name: &str) -> Option<Self> {
        Self::ALL.into_iter().find(|k| k.name() == name)
    }
}

/// Any mechanism: a pure function of the crank state.
pub trait Mechanism: Sync {
    fn kind(&self) -> MechanismKind;

    /// Positions, velocities and accelerations of every link at one crank state.
    fn state(&self, crank: CrankState) -> KinematicState;

    /// Piston-pin position x (m) and dx/dθ (m/rad) at crank angle `angle` (rad): what the
    /// cylinder volume V(θ) and dV/dθ need, without the rest of the state.
    fn piston_position(&self, angle: f64) -> (f64, f64) {
        let p = self.state(CrankState::new(angle, 1.0, 0.0, 0.0)).piston;
        (p.position, p.dx_dtheta)
    }

    /// Piston pin position along the cylinder axis at top dead centre, m.
    fn piston_top(&self) -> f64;

    /// Piston pin position along the cylinder axis at bottom dead centre, m.
    fn piston_bottom(&self) -> f64;

    /// Crank angle of top dead centre, where the piston pin reaches [`Mechanism::piston_top`],
    /// rad. In-line mechanisms have it at π/2 (the cylinder lies along +y).
    fn top_dead_centre(&self) -> f64 {
        std::f64::consts::FRAC_PI_2
    }

    /// Stroke, m.
    fn stroke(&self) -> f64 {
        self.piston_top() - self.piston_bottom()
    }
}

pub(crate) fn check_length(field: &'static str, value: f64) -> Result<f64, GeometryError> {
    if value.is_finite() && value > 0.0 {
        Ok(value)
    } else {
        Err(GeometryError::NotPositive { field, value })
    }
}
