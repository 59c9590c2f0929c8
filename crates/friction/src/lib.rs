//! Friction and power-loss models for the joints, pistons and auxiliaries of reciprocating
//! machines (pumps, compressors, engines), mechanism-independent.
//!
//! Every model is a pure function of a joint's geometry, its load and its relative speed (or of
//! the piston's side force and sliding speed) and returns an instantaneous power loss in W and,
//! where meaningful, a friction force in N or a friction torque in N·m. Nothing here knows which
//! mechanism (slider crank, cardan gear, Scotch yoke) produced the loads: the caller passes, for
//! example, "a revolute joint of journal radius R carrying a force of magnitude F at a relative
//! angular speed ω".
//!
//! Units are SI throughout the public API (m, N, Pa, Pa·s, m²/s, rad/s, W, J). Where a
//! correlation is published in other units (mm, rev/min, kPa, cSt) the conversion happens inside
//! the function and the doc comment says so.
//!
//! Modules, named after the physics:
//!
//! * [`rings`]: piston rings. Karhula's (2008) constant-coefficient ring pack (A9.1.2–A9.1.4) and
//!   a hydrodynamic/mixed ring film (Reynolds equation with squeeze film and Reynolds
//!   cavitation, Greenwood–Tripp asperity contact; Furuhama 1959, Thai thesis §2.5.c).
//! * [`skirt`]: Coulomb skirt friction on the side force (Karhula A9.1.5), the viscous skirt of
//!   the Thai thesis (2.5.c.1–3) and a generic Coulomb sliding contact (e.g. a Scotch-yoke slot).
//! * [`rolling_bearing`]: rolling bearings in Karhula's reading (A9.1.10–A9.1.35), Palmgren's
//!   M = M0 + M1 and the SKF rolling + sliding model.
//! * [`journal_bearing`]: Petroff, the short (Ocvirk) bearing with the eccentricity solved from the
//!   instantaneous load and the Thai thesis's eccentric form (2.5.a.13).
//! * [`engine`]: valve train (cam with flat or roller follower), Bishop (1964) accessory and
//!   pumping correlations and the Patton–Nitschke–Heywood (1989) whole-engine fmep with the
//!   Sandoval–Heywood (2003) update.
//!
//! Karhula's totals and efficiencies (A9.1.56–75) are the cycle summary's
//! (`cardan_dynamics::summary`), which reads the losses these models give.
//!
//! Where a source's formula is doubtful (units, a constant) the source's reading is implemented
//! so that its numbers reproduce, with the physically correct reading beside it, selectable by
//! an enum (see [`rolling_bearing::RollingReading`]).

pub mod engine;
pub mod journal_bearing;
pub mod rings;
pub mod rolling_bearing;
pub mod skirt;

/// The memo of [`RollingModel::loss_kept`], from the crate the gear mesh loss shares it with.
pub use cardan_numeric::KeptPower;
pub use engine::{
    bishop_pumps_misc_mep, bishop_throttling_mep, cam_drive_torque, flat_follower_friction,
    follower_load, mep_power, pnh_fmep, roller_follower_friction, FmepBreakdown, Follower,
    PnhEngine, PnhVariant, ShaftBearings, Valvetrain,
};
pub use journal_bearing::{
    ocvirk_attitude_angle, ocvirk_eccentricity, ocvirk_sommerfeld, petroff, short_bearing,
    sommerfeld_number, thai_eccentric_loss, JournalBearing, ShortBearingState,
};
pub use rings::{
    thai_ring_friction_per_length, thai_ring_power, AsperityContact, KarhulaRingPack, RingFilm,
    RingFilmState, RingLoad, RingProfile, KARHULA_RING_MU,
};
pub use rolling_bearing::{
    rolling_bearing_loss, KarhulaBearingSizes, LoadPower, PalmgrenCoefficients, RollingBearing,
    RollingLoss, RollingModel, RollingReading, SkfDeepGrooveBall, KARHULA_LOAD_CONSTANT,
    KARHULA_LOAD_CONSTANT_PRINTED,
};
pub use skirt::{coulomb_sliding, karhula_skirt, viscous_skirt, ViscousSkirt, KARHULA_SKIRT_MU};

/// Errors of the constructors and solvers of this crate.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum FrictionError {
    /// A geometric or material input that must be positive and finite was not.
    #[error("{name} must be positive and finite, got {value}")]
    NotPositive {
        /// Name of the offending input.
        name: &'static str,
        /// Its value.
        value: f64,
    },
    /// An input outside the range where the model is defined.
    #[error("{name} = {value} is outside the valid range {range}")]
    OutOfRange {
        /// Name of the offending input.
        name: &'static str,
        /// Its value.
        value: f64,
        /// Description of the valid range.
        range: &'static str,
    },
}

/// Checks that `value` is positive and finite.
pub(crate) fn positive(name: &'static str, value: f64) -> Result<f64, FrictionError> {
    if value.is_finite() && value > 0.0 {
        Ok(value)
    } else {
        Err(FrictionError::NotPositive { name, value })
    }
}

/// Friction of a sliding (prismatic) contact at one instant.
#[derive(Debug, Clone, Copy, PartialEq, Default, serde::Serialize, serde::Deserialize)]
pub struct SlidingLoss {
    /// Magnitude of the friction force, N. It acts against the relative sliding velocity.
    pub friction_force: f64,
    /// Power dissipated, W (= friction force × |sliding speed|, never negative).
    pub power: f64,
}

/// Friction of a rotating (revolute) joint at one instant.
#[derive(Debug, Clone, Copy, PartialEq, Default, serde::Serialize, serde::Deserialize)]
pub struct RotaryLoss {
    /// Magnitude of the friction torque, N·m. It acts against the relative angular velocity.
    pub friction_torque: f64,
    /// Power dissipated, W (= friction torque × |relative angular speed|, never negative).
    pub power: f64,
}
