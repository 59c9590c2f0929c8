//! Piston-skirt friction and generic sliding contacts.
//!
//! * [`coulomb_sliding`]: Coulomb friction on a normal force; serves a piston skirt on its side
//!   force, a crosshead, or a Scotch-yoke slot on the slot's normal force.
//! * [`karhula_skirt`]: Karhula (2008) A9.1.5 with μ_skirt = 0.09.
//! * [`viscous_skirt`]: the Thai thesis's Couette (Petroff-type) skirt, eqs 2.5.c.1–2, which
//!   does not depend on the side force.

use crate::{positive, FrictionError, SlidingLoss};
use std::f64::consts::PI;

/// Coulomb friction of a sliding contact: F = μ |N|, P = F |v|.
///
/// `friction_coefficient` μ, `normal_force` N (its sign is ignored), `sliding_speed` v in m/s
/// (its sign gives the direction; the force opposes it). Source: Coulomb's law as used by
/// Karhula (2008) A9.1.4–A9.1.5 and A9.1.8. At v = 0 the returned force is the kinetic value
/// μ|N| (the direction is undefined) and the power is 0.
pub fn coulomb_sliding(
    friction_coefficient: f64,
    normal_force: f64,
    sliding_speed: f64,
) -> SlidingLoss {
    let force = friction_coefficient * normal_force.abs();
    SlidingLoss {
        friction_force: force,
        power: force * sliding_speed.abs(),
    }
}

/// Skirt friction coefficient of Karhula (2008) App. 9.1 (from Andersson et al. 2002).
pub const KARHULA_SKIRT_MU: f64 = 0.09;

/// Karhula's skirt friction (A9.1.5): F = μ_skirt |F_Σ03| with μ_skirt = 0.09, against the
/// piston velocity; P = F |v_piston| (A9.1.8). `side_force` is the cylinder wall's normal force
/// on the piston, N; `piston_speed` in m/s. (A machine without side force, such as the cardan
/// gear, gets zero: Karhula A9.1.7.)
pub fn karhula_skirt(side_force: f64, piston_speed: f64) -> SlidingLoss {
    coulomb_sliding(KARHULA_SKIRT_MU, side_force, piston_speed)
}

/// Geometry of a hydrodynamically lubricated piston skirt (concentric, full film).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct ViscousSkirt {
    /// Piston (bore) diameter B, m.
    pub diameter: f64,
    /// Skirt length L, m.
    pub length: f64,
    /// Radial skirt-to-liner clearance C_p, m.
    pub clearance: f64,
}

impl ViscousSkirt {
    /// A skirt of diameter `diameter`, length `length` and radial clearance `clearance` (all m,
    /// positive).
    pub fn new(diameter: f64, length: f64, clearance: f64) -> Result<Self, FrictionError> {
        Ok(Self {
            diameter: positive("diameter", diameter)?,
            length: positive("length", length)?,
            clearance: positive("clearance", clearance)?,
        })
    }
}

/// Viscous (Couette) skirt friction at the instantaneous piston speed:
/// F = 2π μ R L |U| / C_p with R = B/2 (Thai thesis eqs 2.5.c.1–2), P = F |U|.
///
/// `viscosity` μ in Pa·s, `piston_speed` U in m/s. The thesis evaluates it at the mean piston
/// speed S̄p instead (eq. 2.5.c.3, P = π μ B L S̄p² / C_p: this function at U = S̄p); the cycle
/// mean of this instantaneous form is larger by ⟨U²⟩/S̄p², which is π²/8 = 1.234 for a harmonic
/// stroke (cardan gear) and about the same for a slider crank.
pub fn viscous_skirt(skirt: &ViscousSkirt, viscosity: f64, piston_speed: f64) -> SlidingLoss {
    let u = piston_speed.abs();
    let force = 2.0 * PI * viscosity * 0.5 * skirt.diameter * skirt.length * u / skirt.clearance;
    SlidingLoss {
        friction_force: force,
        power: force * u,
    }
}
