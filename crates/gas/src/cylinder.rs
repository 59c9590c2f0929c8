//! The cylinder and the chamber a gas model works in (Karhula 2008, A6.1.1.1-A6.1.1.10).

use crate::{require, GasError};
use cardan_mechanism::Mechanism;
use std::f64::consts::PI;

/// A cylinder with flat piston crowns and a flat head (or a second piston in its place).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Cylinder {
    /// Bore, m.
    pub bore: f64,
    /// Area of one piston crown A_pis = π·B²/4, m².
    pub area: f64,
    /// Swept volume of the chamber V_stroke (A6.1.1.2), m³: A_pis·stroke for one piston,
    /// the sum over the pistons for an opposed-piston chamber.
    pub swept_volume: f64,
    /// Clearance volume V_comp at the top dead centre (A6.1.1.3), m³.
    pub clearance_volume: f64,
    /// Pistons sharing the chamber: 1, or 2 for the opposed-piston layout of Nunes (2017,
    /// note section 1: identical mirrored crank trains, no head).
    pub pistons: u32,
}

impl Cylinder {
    /// A cylinder of `bore` (m) and `swept_volume` (m³) with compression ratio
    /// ε = (V_stroke + V_comp)/V_comp, so V_comp = V_stroke/(ε − 1) (A6.1.1.3).
    pub fn with_compression_ratio(
        bore: f64,
        swept_volume: f64,
        compression_ratio: f64,
    ) -> Result<Self, GasError> {
        require(
            "compression_ratio",
            compression_ratio,
            compression_ratio > 1.0,
            "must be greater than 1",
        )?;
        Self::with_clearance(bore, swept_volume, swept_volume / (compression_ratio - 1.0))
    }

    /// A cylinder of `bore` (m) and `swept_volume` (m³) with a clearance volume (m³) that may
    /// be zero (an ideal compressor).
    pub fn with_clearance(
        bore: f64,
        swept_volume: f64,
        clearance_volume: f64,
    ) -> Result<Self, GasError> {
        require("bore", bore, bore > 0.0, "must be positive")?;
        require(
            "swept_volume",
            swept_volume,
            swept_volume > 0.0,
            "must be positive",
        )?;
        require(
            "clearance_volume",
            clearance_volume,
            clearance_volume >= 0.0,
            "must not be negative",
        )?;
        Ok(Self {
            bore,
            area: PI / 4.0 * bore * bore,
            swept_volume,
            clearance_volume,
            pistons: 1,
        })
    }

    /// The same chamber shared by `pistons` pistons (the swept volume stays the chamber's).
    pub fn with_pistons(self, pistons: u32) -> Result<Self, GasError> {
        require(
            "pistons",
            f64::from(pistons),
            pistons >= 1,
            "must be at least 1",
        )?;
        Ok(Self { pistons, ..self })
    }

    /// Stroke of each piston, V_stroke/(pistons·A_pis), m.
    pub fn stroke(&self) -> f64 {
        self.swept_volume / (f64::from(self.pistons) * self.area)
    }

    /// Largest volume V_unc = V_stroke + V_comp (A6.1.1.5), m³.
    pub fn max_volume(&self) -> f64 {
        self.swept_volume + self.clearance_volume
    }

    /// Compression ratio ε = V_unc/V_comp (infinite without clearance).
    pub fn compression_ratio(&self) -> f64 {
        self.max_volume() / self.clearance_volume
    }

    /// The volume curve of this cylinder when each of its pistons is moved by `mechanism`:
    /// V(θ) = V_comp + pistons·A_pis·(x_TDC − x(θ)) and dV/dθ = −pistons·A_pis·dx/dθ
    /// (A6.1.1.7-A6.1.1.10 with h_deck eliminated). The swept volume must be
    /// pistons·A_pis·stroke for the curve to span it.
    pub fn volume_curve<'a>(
        &self,
        mechanism: &'a dyn Mechanism,
    ) -> impl Fn(f64) -> Volume + Sync + 'a {
        let piston = self.piston_volume(mechanism);
        move |theta| {
            let (x, dx) = mechanism.piston_position(theta);
            Volume {
                volume: piston.volume(x),
                rate: -piston.area * dx,
            }
        }
    }

    /// The volume of this cylinder as a function of the position of its pistons, each moved
    /// by `mechanism` in phase (A6.1.1.7-A6.1.1.10 with h_deck eliminated).
    pub fn piston_volume(&self, mechanism: &dyn Mechanism) -> PistonVolume {
        PistonVolume {
            clearance: self.clearance_volume,
            area: f64::from(self.pistons) * self.area,
            top: mechanism.piston_top(),
        }
    }

    /// Runs `f` on the chamber of this cylinder whose pistons `mechanism` moves, with the cycle
    /// opening at the mechanism's top dead centre.
    pub fn with_chamber<R>(self, mechanism: &dyn Mechanism, f: impl FnOnce(&Chamber) -> R) -> R {
        let volume = self.volume_curve(mechanism);
        f(&Chamber {
            cylinder: self,
            tdc_angle: mechanism.top_dead_centre(),
            volume: &volume,
            piston: Some(self.piston_volume(mechanism)),
        })
    }

    /// Runs `f` on the chamber of an opposed-piston cylinder (two pistons) whose second piston's
    /// crank leads the first's by `phase` (rad): V(θ) = V_comp + A_pis·[(x_TDC − x(θ)) +
    /// (x_TDC − x(θ + φ))] (Nunes 2017's chamber, each piston on its own crank train, with a
    /// phase offset between the cranks). The smallest volume, which opens the cycle, is at
    /// θ_TDC − φ/2 for a motion symmetric about its top dead centre (every in-line mechanism);
    /// with φ ≠ 0 it exceeds V_comp, so the compression ratio given for the cylinder is the
    /// zero-offset one. With `phase` = 0 this is [`Cylinder::with_chamber`].
    pub fn with_phased_chamber<R>(
        self,
        mechanism: &dyn Mechanism,
        phase: f64,
        f: impl FnOnce(&Chamber) -> R,
    ) -> R {
        if phase == 0.0 || self.pistons != 2 {
            return self.with_chamber(mechanism, f);
        }
        let (clearance, area) = (self.clearance_volume, self.area);
        let top = mechanism.piston_top();
        let volume = move |theta: f64| {
            let (x1, dx1) = mechanism.piston_position(theta);
            let (x2, dx2) = mechanism.piston_position(theta + phase);
            Volume {
                volume: clearance + area * (2.0 * top - x1 - x2),
                rate: -area * (dx1 + dx2),
            }
        };
        f(&Chamber {
            cylinder: self,
            tdc_angle: mechanism.top_dead_centre() - phase / 2.0,
            volume: &volume,
            piston: None,
        })
    }

    /// Gas-side wall area at volume `v`, m²: two flat ends (crown and head, or two crowns)
    /// and the liner between them, 2·A_pis + π·B·V/A_pis (Nunes 2017, L700-703).
    pub fn wall_area(&self, v: f64) -> f64 {
        2.0 * self.area + PI * self.bore * v / self.area
    }
}

/// Chamber volume and its rate at one crank angle.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Volume {
    /// V, m³.
    pub volume: f64,
    /// dV/dθ, m³/rad.
    pub rate: f64,
}

/// The chamber volume as a function of the position x of the first piston (all its pistons
/// moving in phase): V = V_comp + pistons·A_pis·(x_TDC − x) (A6.1.1.7-A6.1.1.10 with h_deck
/// eliminated). [`Cylinder::volume_curve`] is this at the mechanism's
/// [`Mechanism::piston_position`]; a block's steps, whose piston positions the mechanism has
/// filled, take it from there (the same arithmetic: the same bits for the same x).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PistonVolume {
    /// V_comp, m³.
    pub clearance: f64,
    /// pistons·A_pis, m².
    pub area: f64,
    /// The first piston's position at top dead centre x_TDC, m.
    pub top: f64,
}

impl PistonVolume {
    /// V at the first piston's position `x` (m), m³.
    #[inline(always)]
    pub fn volume(&self, x: f64) -> f64 {
        self.clearance + self.area * (self.top - x)
    }
}

/// The working chamber a gas model sees: the cylinder, the volume curve of the mechanism that
/// moves its piston(s), and where the cycle starts.
#[derive(Clone, Copy)]
pub struct Chamber<'a> {
    pub cylinder: Cylinder,
    /// Crank angle of the top dead centre that opens the cycle (the start of the intake or
    /// suction stroke), rad.
    pub tdc_angle: f64,
    /// V(θ) and dV/dθ for any crank angle θ (rad).
    pub volume: &'a (dyn Fn(f64) -> Volume + Sync),
    /// V as a function of the first piston's position alone, where the chamber has it (its
    /// pistons move in phase: [`Cylinder::with_chamber`]; `None` for a phased opposed-piston
    /// chamber, whose second piston is elsewhere): `volume` is then this at the mechanism's
    /// [`Mechanism::piston_position`], bit for bit.
    pub piston: Option<PistonVolume>,
}

impl Chamber<'_> {
    /// Crank angle from the opening top dead centre, in [0, 4π) (a four-stroke cycle), rad.
    #[inline(always)]
    pub fn cycle_angle(&self, theta: f64) -> f64 {
        const CYCLE: f64 = 4.0 * PI;
        let x = theta - self.tdc_angle;
        // `rem_euclid`'s own result without its `fmod` call over the first cycles: the
        // remainder is x itself on [0, 4π), x − 4π on [4π, 8π) (exact, Sterbenz), and
        // `rem_euclid` adds 4π on (−4π, 0).
        if (0.0..CYCLE).contains(&x) {
            x
        } else if (CYCLE..2.0 * CYCLE).contains(&x) {
            x - CYCLE
        } else if x > -CYCLE && x < 0.0 {
            x + CYCLE
        } else {
            x.rem_euclid(CYCLE)
        }
    }
}

impl std::fmt::Debug for Chamber<'_> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Chamber")
            .field("cylinder", &self.cylinder)
            .field("tdc_angle", &self.tdc_angle)
            .finish_non_exhaustive()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The cycle angle is `rem_euclid`'s, bit for bit, on its fast paths' ranges, at their
    /// edges and beyond them.
    #[test]
    fn the_cycle_angle_is_rem_euclids() {
        let volume = |_: f64| Volume {
            volume: 1.0,
            rate: 0.0,
        };
        let cycle = 4.0 * PI;
        let mut xs = vec![0.0, -0.0, cycle, 2.0 * cycle, -cycle, 3.0 * cycle, f64::NAN];
        for edge in [0.0, cycle, 2.0 * cycle, -cycle] {
            for k in 1..=4_u64 {
                xs.push(f64::from_bits(f64::to_bits(edge.abs().max(1e-300)) + k) * edge.signum());
                xs.push(f64::from_bits(f64::to_bits(edge.abs().max(1e-300)) - k) * edge.signum());
            }
        }
        xs.extend((0..20_000).map(|k| -60.0 + 0.006_1 * f64::from(k)));
        xs.extend([1e6, -1e6, 1e300, f64::INFINITY]);
        for tdc in [0.0, std::f64::consts::FRAC_PI_2, 1.234] {
            let chamber = Chamber {
                cylinder: Cylinder::with_compression_ratio(0.1, 1e-3, 10.0).unwrap(),
                tdc_angle: tdc,
                volume: &volume,
                piston: None,
            };
            for &x in &xs {
                let theta = x + tdc;
                let want = (theta - tdc).rem_euclid(cycle);
                let got = chamber.cycle_angle(theta);
                assert!(
                    got.to_bits() == want.to_bits() || (got.is_nan() && want.is_nan()),
                    "θ = {theta}: {got} vs {want}"
                );
            }
        }
    }
}
