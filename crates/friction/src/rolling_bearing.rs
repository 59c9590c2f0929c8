//! Rolling-bearing friction: Karhula's (2008) reading of the Palmgren model as printed, the
//! Palmgren/Harris form M = M0 + M1, and the SKF rolling + sliding model.
//!
//! Why two Palmgren readings (`docs/validation/rolling-bearings.md`): Karhula's load term
//! T_L = 0.009 F^1.55 C0^−0.55 d_m (A9.1.26) is about 18× the Harris/Palmgren deep-groove value
//! f1 = 0.0005 (P0/C0)^0.55 for a 6208 at 2 kN (0.313 vs 0.0174 N·m), and his low-speed viscous
//! constant 24.1 f0 d_m³ (A9.1.30) is 55 % above his own high-speed form at νn = 2000
//! (9.79e-2 · 2000^(2/3) = 15.5), while Palmgren's 160e-7 (N·mm units, = 16 in SI) is continuous
//! to within 1 %. The 6208 example (`docs/validation/rolling-bearings.md`) totals 0.378 N·m in Karhula's reading against
//! 0.0836 N·m in the Harris reading: a factor 4.5. [`RollingReading::Karhula`] reproduces the
//! thesis; [`RollingReading::Palmgren`] is the physically correct reading.
//!
//! All readings use the bearing's equivalent (here: radial) load for both P0 and P1 and ignore
//! seals, drag and replenishment; speed is the relative angular speed of the two rings.

use crate::{positive, FrictionError};
use cardan_numeric::KeptPower;
use std::f64::consts::PI;

/// A rolling bearing as the friction models see it.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct RollingBearing {
    /// Pitch (mean) diameter d_m = (d + D)/2, m.
    pub pitch_diameter: f64,
    /// Basic static load rating C0, N.
    pub static_load_rating: f64,
}

impl RollingBearing {
    /// A bearing of pitch diameter `pitch_diameter` (m) and static load rating
    /// `static_load_rating` (N), both positive.
    pub fn new(pitch_diameter: f64, static_load_rating: f64) -> Result<Self, FrictionError> {
        Ok(Self {
            pitch_diameter: positive("pitch_diameter", pitch_diameter)?,
            static_load_rating: positive("static_load_rating", static_load_rating)?,
        })
    }
}

/// Default bearing sizes of Karhula (2008) App. 9.1 for a machine of piston diameter d_pis;
/// override with catalogue values where known.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct KarhulaBearingSizes {
    /// Piston-pin bearing: d_m = d_pis/4 (A9.1.10), C0 = (d_m in mm) × 10³ N (A9.1.12).
    pub piston_pin: RollingBearing,
    /// Crank-pin bearing: d_m = 1.5 d_m,pis (A9.1.11), C0 = 2 C0,pis (A9.1.13). The cardan wheel
    /// has two of these side by side, each carrying half the joint force (A9.1.23).
    pub crank_pin: RollingBearing,
    /// Main bearing: as the crank pin (A9.1.11, A9.1.13); two per machine, each carrying half
    /// the main-joint force (A9.1.24–25).
    pub main: RollingBearing,
}

impl KarhulaBearingSizes {
    /// Sizes from the piston diameter `piston_diameter` (m).
    pub fn from_piston_diameter(piston_diameter: f64) -> Result<Self, FrictionError> {
        positive("piston_diameter", piston_diameter)?;
        let dm_pis = piston_diameter / 4.0;
        let c0_pis = dm_pis * 1e3 * 1e3; // d_m in mm × 10³ N
        let big = RollingBearing {
            pitch_diameter: 1.5 * dm_pis,
            static_load_rating: 2.0 * c0_pis,
        };
        Ok(Self {
            piston_pin: RollingBearing {
                pitch_diameter: dm_pis,
                static_load_rating: c0_pis,
            },
            crank_pin: big,
            main: big,
        })
    }
}

/// Palmgren coefficients: M0 lubrication factor f0 and the load factor f1 = z (P0/C0)^y.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct PalmgrenCoefficients {
    /// Lubrication factor f0 (Karhula A9.1.31 takes 2; no published table of f0 by lubrication
    /// method could be read, `docs/validation/rolling-bearings.md`).
    pub f0: f64,
    /// Load-factor constant z of f1 = z (P0/C0)^y.
    pub z: f64,
    /// Load-factor exponent y of f1 = z (P0/C0)^y (0 for a constant f1).
    pub y: f64,
}

impl PalmgrenCoefficients {
    /// Deep-groove ball bearing: z = 0.0005, y = 0.55, f0 = 2 (f0 as Karhula A9.1.31). z and y
    /// are assumed, not published: no source that could be read gives them
    /// (`docs/validation/rolling-bearings.md`).
    pub const DEEP_GROOVE_BALL: Self = Self {
        f0: 2.0,
        z: 0.0005,
        y: 0.55,
    };
    /// Deep-groove ball bearing, a second load-factor form f1 = 0.0007 (P0/C0)^0.5, f0 = 2:
    /// assumed, not published (`docs/validation/rolling-bearings.md`).
    pub const DEEP_GROOVE_BALL_OLD_SKF: Self = Self {
        f0: 2.0,
        z: 0.0007,
        y: 0.5,
    };
    /// Cylindrical roller bearing with cage under radial load: a constant f1 = 0.0003 and
    /// f0 = 2.5, assumed, not published (`docs/validation/rolling-bearings.md`).
    pub const CYLINDRICAL_ROLLER: Self = Self {
        f0: 2.5,
        z: 0.0003,
        y: 0.0,
    };
}

/// SKF rolling + sliding model constants of a deep-groove ball bearing series (SKF catalogue
/// "Rolling bearings", friction chapter, table of geometry constants; values from the
/// `docs/validation/rolling-bearings.md`, low confidence: verify against the catalogue).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct SkfDeepGrooveBall {
    /// Rolling-frictional-moment constant R1.
    pub r1: f64,
    /// Sliding-frictional-moment constant S1.
    pub s1: f64,
    /// Sliding friction coefficient in full-film (EHL) conditions μ_EHL (0.05 mineral oil,
    /// 0.04 synthetic, 0.1 transmission fluid).
    pub mu_ehl: f64,
    /// Boundary sliding friction coefficient μ_bl (≈ 0.15).
    pub mu_bl: f64,
}

impl SkfDeepGrooveBall {
    /// Series 62, mineral oil.
    pub const SERIES_62: Self = Self {
        r1: 3.9e-7,
        s1: 3.23e-3,
        mu_ehl: 0.05,
        mu_bl: 0.15,
    };
    /// Series 60, mineral oil.
    pub const SERIES_60: Self = Self {
        r1: 4.1e-7,
        s1: 3.73e-3,
        mu_ehl: 0.05,
        mu_bl: 0.15,
    };
    /// Series 63, mineral oil.
    pub const SERIES_63: Self = Self {
        r1: 3.7e-7,
        s1: 2.84e-3,
        mu_ehl: 0.05,
        mu_bl: 0.15,
    };
}

/// The load-term constant of A9.1.26-27 as printed: 0.009.
pub const KARHULA_LOAD_CONSTANT_PRINTED: f64 = 0.009;

/// The load-term constant that reproduces the thesis's tables: 0.0009. With the printed 0.009
/// the slider-crank air pump of appendix 11.6.1 loses 38.9 kW at 200π rad/s against the
/// published 29.28 kW, and a least-squares fit of the published losses over 3π...200π against
/// this project's ring, skirt and bearing components scales the bearings by 0.089 while the
/// rings and skirt come out at 1.02 and 0.94; 0.0009 reproduces all six published
/// slider-crank losses within 6 %
/// (`runner/tests/friction.rs`).
pub const KARHULA_LOAD_CONSTANT: f64 = 0.0009;

/// Which reading of the rolling-bearing friction to use.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
pub enum RollingReading {
    /// Karhula (2008) App. 9.1 as printed (A9.1.26–A9.1.33) with lubrication factor `f0`
    /// (Karhula: 2). Reproduces the thesis; see the module doc for why it is doubtful.
    Karhula {
        /// Lubrication factor f0.
        f0: f64,
        /// Constant of the load term: [`KARHULA_LOAD_CONSTANT`] (reproduces the thesis's
        /// tables) or [`KARHULA_LOAD_CONSTANT_PRINTED`].
        load_constant: f64,
    },
    /// Palmgren/Harris M = M0 + M1 (the physically correct reading of the same model).
    Palmgren(PalmgrenCoefficients),
    /// SKF rolling + sliding moments of a deep-groove ball bearing with the inlet-shear heating
    /// factor (seals, drag and replenishment omitted).
    Skf(SkfDeepGrooveBall),
}

/// Friction of a rolling bearing at one instant.
#[derive(Debug, Clone, Copy, PartialEq, Default, serde::Serialize, serde::Deserialize)]
pub struct RollingLoss {
    /// Load-dependent torque (Palmgren M1; SKF sliding moment M_sl), N·m.
    pub load_torque: f64,
    /// Speed/viscosity-dependent torque (Palmgren M0; SKF rolling moment M_rr), N·m.
    pub viscous_torque: f64,
    /// Total friction torque, N·m.
    pub friction_torque: f64,
    /// Power loss T·|ω| (Karhula A9.1.34–35), W.
    pub power: f64,
}

/// Friction torque and power of `bearing` carrying the equivalent load `load` (N) at the relative
/// angular speed `relative_speed` (rad/s) in oil of kinematic viscosity `kinematic_viscosity`
/// (m²/s; Karhula: ≲ 5 mm²/s = 5e-6 m²/s), in the chosen reading.
///
/// Internally ν is converted to mm²/s and n to rev/min, as in all three sources. The powers of
/// the load ([`LoadPower`]) are [`cardan_numeric::powf_lane`]'s, the function a block of steps
/// takes for all its lanes at once (within one ulp of `powf`, 0.2–0.3 % of arguments apart).
///
/// * Karhula: T_L = k F^1.55 C0^−0.55 d_m (A9.1.26–27 print k = 0.009; the tables need 0.0009,
///   see [`KARHULA_LOAD_CONSTANT`]; N·m with d_m in m, F and C0 in N);
///   T_V = 9.79e-2 f0 (νn)^(2/3) d_m³ for νn > 2000 (A9.1.28–29), T_V = 24.1 f0 d_m³ for
///   νn ≤ 2000 (A9.1.30–31, discontinuous at νn = 2000 by a factor 24.1/15.5); T = T_L + T_V
///   (A9.1.32–33).
/// * Palmgren (Harris, *Rolling Bearing Analysis*; SKF/INA catalogues): M0 = 1e-7 f0 (νn)^(2/3)
///   d_m³ N·mm for νn ≥ 2000, 160e-7 f0 d_m³ below (d_m in mm); M1 = f1 P d_m,
///   f1 = z (P/C0)^y.
/// * SKF: M_rr = φ_ish G_rr (νn)^0.6, G_rr = R1 d_m^1.96 F^0.54,
///   φ_ish = 1/(1 + 1.84e-9 (n d_m)^1.28 ν^0.64); M_sl = G_sl μ_sl, G_sl = S1 d_m^−0.26 F^(5/3),
///   μ_sl = φ_bl μ_bl + (1 − φ_bl) μ_EHL, φ_bl = exp(−2.6e-8 (nν)^1.4 d_m); N·mm with d_m in mm.
///
/// At zero speed the power is zero in every reading (the Karhula and Palmgren low-speed M0 is a
/// constant torque, which dissipates nothing at rest).
pub fn rolling_bearing_loss(
    bearing: &RollingBearing,
    reading: RollingReading,
    load: f64,
    relative_speed: f64,
    kinematic_viscosity: f64,
) -> RollingLoss {
    RollingModel::new(*bearing, reading).loss(load, relative_speed, kinematic_viscosity)
}

/// A power (F / divisor)^exponent of the bearing load F (N) that a reading takes: Karhula's
/// F^1.55 (A9.1.26), Palmgren's (P/C0)^y (f1 = z (P/C0)^y), SKF's F^0.54 and F^(5/3) (G_rr,
/// G_sl). A block of steps takes them for all its lanes at once
/// ([`cardan_numeric::powf_lanes`]) and hands them to [`RollingModel::loss_with_powers`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LoadPower {
    /// Divides the load before the power (C0 for Palmgren, N; else 1).
    pub divisor: f64,
    /// The exponent.
    pub exponent: f64,
}

impl LoadPower {
    /// This power of the load `load` (N, ≥ 0): [`cardan_numeric::powf_lane`], the bits of a
    /// lane of [`cardan_numeric::powf_lanes`] (within one ulp of `powf`).
    #[inline]
    pub fn of(&self, load: f64) -> f64 {
        cardan_numeric::powf_lane(load / self.divisor, self.exponent)
    }
}

/// [`rolling_bearing_loss`] of one bearing in one reading, with the powers of the bearing's
/// own size (C0^−0.55, d_m³, d_m^1.96, d_m^−0.26) taken once instead of at every call: a run
/// evaluates its bearings at every step, and `powf` is most of their cost. The powers of the
/// load ([`LoadPower`]) are the caller's to take, a block's lanes at once
/// ([`RollingModel::load_powers`], [`RollingModel::loss_with_powers`]), or the model's for a
/// single step ([`RollingModel::loss`]): the same bits either way. The same arithmetic, in the
/// same order, as the formulas of [`rolling_bearing_loss`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RollingModel {
    bearing: RollingBearing,
    reading: RollingReading,
    /// The reading's powers of the size: Karhula (C0^−0.55, d_m³ in m³); Palmgren (d_m³ in
    /// mm³, unused); SKF (d_m^1.96, d_m^−0.26, d_m in mm).
    powers: [f64; 2],
    /// The reading's powers of the load (the first `load_power_count`).
    load_powers: [LoadPower; 2],
    load_power_count: usize,
}

/// νn of the viscous terms (Karhula A9.1.28-31, Palmgren's M0): the kinematic viscosity in
/// mm²/s times the speed in rpm, of a relative speed `relative_speed` (rad/s) and a kinematic
/// viscosity `kinematic_viscosity` (m²/s).
#[inline]
pub fn viscous_speed(relative_speed: f64, kinematic_viscosity: f64) -> f64 {
    let n_rpm = relative_speed.abs() * 60.0 / (2.0 * PI);
    let nu = kinematic_viscosity * 1e6; // mm²/s
    nu * n_rpm
}

impl RollingModel {
    pub fn new(bearing: RollingBearing, reading: RollingReading) -> Self {
        let dm = bearing.pitch_diameter;
        let powers = match reading {
            RollingReading::Karhula { .. } => [bearing.static_load_rating.powf(-0.55), dm.powi(3)],
            RollingReading::Palmgren(_) => [(dm * 1e3).powi(3), 0.0],
            RollingReading::Skf(_) => [(dm * 1e3).powf(1.96), (dm * 1e3).powf(-0.26)],
        };
        let of_load = |exponent| LoadPower {
            divisor: 1.0,
            exponent,
        };
        let (load_powers, load_power_count) = match reading {
            RollingReading::Karhula { .. } => ([of_load(1.55), of_load(1.0)], 1),
            RollingReading::Palmgren(c) => {
                let p = LoadPower {
                    divisor: bearing.static_load_rating,
                    exponent: c.y,
                };
                ([p, of_load(1.0)], 1)
            }
            RollingReading::Skf(_) => ([of_load(0.54), of_load(5.0 / 3.0)], 2),
        };
        Self {
            bearing,
            reading,
            powers,
            load_powers,
            load_power_count,
        }
    }

    /// The powers of the load this reading takes, in the order
    /// [`RollingModel::loss_with_powers`] wants them.
    pub fn load_powers(&self) -> &[LoadPower] {
        &self.load_powers[..self.load_power_count]
    }

    /// The powers of the load `load` (N) this reading takes ([`LoadPower::of`] of |load|; 0
    /// past the reading's count).
    fn load_powers_of(&self, load: f64) -> [f64; 2] {
        let mut p = [0.0; 2];
        for (p, power) in p.iter_mut().zip(self.load_powers()) {
            *p = power.of(load.abs());
        }
        p
    }

    /// [`rolling_bearing_loss`] of this bearing.
    pub fn loss(&self, load: f64, relative_speed: f64, kinematic_viscosity: f64) -> RollingLoss {
        self.loss_kept(
            load,
            relative_speed,
            kinematic_viscosity,
            &mut KeptPower::default(),
        )
    }

    /// [`RollingModel::loss`], the viscous term's power of the speed, (νn)^(2/3), taken from
    /// `kept` if νn has the bits of the step before (a constant joint speed), else computed
    /// and kept there: the same bits as [`RollingModel::loss`].
    pub fn loss_kept(
        &self,
        load: f64,
        relative_speed: f64,
        kinematic_viscosity: f64,
        kept: &mut KeptPower,
    ) -> RollingLoss {
        let powers = self.load_powers_of(load);
        let speed_power = if self.takes_speed_power() {
            kept.pow_lane(
                viscous_speed(relative_speed, kinematic_viscosity),
                2.0 / 3.0,
            )
        } else {
            0.0
        };
        self.loss_with_powers(
            load,
            relative_speed,
            kinematic_viscosity,
            powers,
            speed_power,
        )
    }

    /// Whether the reading's viscous term takes the power (νn)^(2/3) of the speed (Karhula's
    /// and Palmgren's, above νn = 2000).
    fn takes_speed_power(&self) -> bool {
        !matches!(self.reading, RollingReading::Skf(_))
    }

    /// The speed powers (νn)^(2/3) that [`RollingModel::loss_with_powers`] takes, of the
    /// lanes' relative speeds `relative_speed` (rad/s) at the kinematic viscosity
    /// `kinematic_viscosity` (m²/s), into `out` (the shorter's length; left alone by a reading
    /// that takes none, and where every lane is below νn = 2000, where the readings take
    /// none): [`KeptPower::pow_lane`]'s bits lane by lane, the lanes of a constant
    /// νn (a constant joint speed) from `kept`, the others all at once
    /// ([`cardan_numeric::powf_lanes`]). Inlined into a block kernel, which vectorises it.
    #[inline(always)]
    pub fn speed_powers(
        &self,
        relative_speed: &[f64],
        kinematic_viscosity: f64,
        kept: &mut KeptPower,
        out: &mut [f64],
    ) {
        if !self.takes_speed_power() {
            return;
        }
        const CHUNK: usize = 64;
        for (speeds, out) in relative_speed.chunks(CHUNK).zip(out.chunks_mut(CHUNK)) {
            let mut nun = [0.0; CHUNK];
            for (n, &w) in nun.iter_mut().zip(speeds) {
                *n = viscous_speed(w, kinematic_viscosity);
            }
            let nun = &nun[..speeds.len().min(out.len())];
            let first = nun.first().map_or(0, |n| n.to_bits());
            if nun.iter().all(|&n| n < 2000.0) {
                // Below νn = 2000 the readings take no power of the speed (A9.1.30-31).
                continue;
            } else if nun.iter().all(|n| n.to_bits() == first) {
                let p = kept.pow_lane(f64::from_bits(first), 2.0 / 3.0);
                out[..nun.len()].fill(p);
            } else {
                cardan_numeric::powf_lanes(nun, 2.0 / 3.0, out);
            }
        }
    }

    /// [`RollingModel::loss_kept`] with the powers of the load already taken: `load_powers[j]`
    /// is [`RollingModel::load_powers`]`()[j]` of |`load`| (the rest unused), and
    /// `speed_power` the viscous term's (νn)^(2/3) of the speed ([`viscous_speed`];
    /// [`RollingModel::speed_powers`], unused by a reading that takes none). Every reading
    /// takes its powers from there.
    /// Inlined into a block's loop over its lanes (the reading's `match` then leaves the loop).
    #[inline]
    pub fn loss_with_powers(
        &self,
        load: f64,
        relative_speed: f64,
        kinematic_viscosity: f64,
        load_powers: [f64; 2],
        speed_power: f64,
    ) -> RollingLoss {
        let bearing = &self.bearing;
        let [p0, p1] = self.powers;
        let f = load.abs();
        let w = relative_speed.abs();
        let n_rpm = w * 60.0 / (2.0 * PI);
        let nu = kinematic_viscosity * 1e6; // mm²/s
        let nun = viscous_speed(relative_speed, kinematic_viscosity);
        let (load_torque, viscous_torque) = match self.reading {
            RollingReading::Karhula { f0, load_constant } => {
                let (dm, c0_power, dm3) = (bearing.pitch_diameter, p0, p1);
                let f_155 = load_powers[0];
                let tl = load_constant * f_155 * c0_power * dm;
                let tv = if nun > 2000.0 {
                    9.79e-2 * f0 * speed_power * dm3
                } else {
                    24.1 * f0 * dm3
                };
                (tl, tv)
            }
            RollingReading::Palmgren(c) => {
                let dm = bearing.pitch_diameter * 1e3; // mm
                let dm3 = p0;
                let m0 = if nun >= 2000.0 {
                    1e-7 * c.f0 * speed_power * dm3
                } else {
                    160e-7 * c.f0 * dm3
                };
                let f1 = c.z * load_powers[0]; // z (P/C0)^y
                let m1 = f1 * f * dm;
                (m1 * 1e-3, m0 * 1e-3)
            }
            RollingReading::Skf(c) => {
                let dm = bearing.pitch_diameter * 1e3; // mm
                let (dm_196, dm_026) = (p0, p1);
                let [f_054, f_53] = load_powers;
                let g_rr = c.r1 * dm_196 * f_054;
                let phi_ish = 1.0 / (1.0 + 1.84e-9 * (n_rpm * dm).powf(1.28) * nu.powf(0.64));
                let m_rr = phi_ish * g_rr * nun.powf(0.6);
                let g_sl = c.s1 * dm_026 * f_53;
                let phi_bl = (-2.6e-8 * nun.powf(1.4) * dm).exp();
                let mu_sl = phi_bl * c.mu_bl + (1.0 - phi_bl) * c.mu_ehl;
                (g_sl * mu_sl * 1e-3, m_rr * 1e-3)
            }
        };
        let total = load_torque + viscous_torque;
        RollingLoss {
            load_torque,
            viscous_torque,
            friction_torque: total,
            power: total * w,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn karhula_sizes_follow_the_rules() {
        // Exact arithmetic of A9.1.10–13 for d_pis = 120 mm; tolerance is rounding only.
        let s = KarhulaBearingSizes::from_piston_diameter(0.12).unwrap();
        assert!((s.piston_pin.pitch_diameter - 0.030).abs() < 1e-15);
        assert!((s.piston_pin.static_load_rating - 30_000.0).abs() < 1e-9);
        assert!((s.crank_pin.pitch_diameter - 0.045).abs() < 1e-15);
        assert!((s.main.static_load_rating - 60_000.0).abs() < 1e-9);
    }

    /// The viscous term's power kept from step to step gives `loss`'s bits whether the speed
    /// stays, changes or comes back, in every reading.
    #[test]
    fn a_kept_power_gives_the_same_bits() {
        let bearing = RollingBearing::new(0.045, 45_000.0).unwrap();
        for reading in [
            RollingReading::Karhula {
                f0: 2.0,
                load_constant: KARHULA_LOAD_CONSTANT,
            },
            RollingReading::Palmgren(PalmgrenCoefficients::DEEP_GROOVE_BALL),
        ] {
            let model = RollingModel::new(bearing, reading);
            let mut kept = KeptPower::default();
            for (load, speed) in [
                (1000.0, 300.0),
                (2000.0, 300.0),
                (2000.0, -300.0),
                (10.0, 1.0),
                (0.0, 0.0),
                (1000.0, 300.0),
            ] {
                assert_eq!(
                    model.loss_kept(load, speed, 5e-6, &mut kept),
                    model.loss(load, speed, 5e-6)
                );
            }
        }
    }

    fn readings() -> [RollingReading; 5] {
        [
            RollingReading::Karhula {
                f0: 2.0,
                load_constant: KARHULA_LOAD_CONSTANT,
            },
            RollingReading::Palmgren(PalmgrenCoefficients::DEEP_GROOVE_BALL),
            RollingReading::Palmgren(PalmgrenCoefficients::CYLINDRICAL_ROLLER),
            RollingReading::Skf(SkfDeepGrooveBall::SERIES_62),
            RollingReading::Skf(SkfDeepGrooveBall::SERIES_63),
        ]
    }

    /// The powers of a block's loads taken all at once (`powf_lanes`) and handed to
    /// `loss_with_powers` give the single-step `loss`'s bits, in every reading, at zero load
    /// and at loads from 1 mN to 1 MN.
    #[test]
    fn lane_wise_powers_give_the_bits_of_a_single_step() {
        let bearing = RollingBearing::new(0.045, 45_000.0).unwrap();
        let loads: Vec<f64> = (0..64)
            .map(|i| if i == 0 { 0.0 } else { 1e-3 * 1.4f64.powi(i) })
            .collect();
        for reading in readings() {
            let model = RollingModel::new(bearing, reading);
            let mut powers = [[0.0; 64]; 2];
            for (p, out) in model.load_powers().iter().zip(&mut powers) {
                let base: Vec<f64> = loads.iter().map(|f| f / p.divisor).collect();
                cardan_numeric::powf_lanes(&base, p.exponent, out);
            }
            // Speeds that vary over the lanes (all at once) and a constant one (kept).
            let varying: Vec<f64> = (0..64).map(|i| 20.0 + i as f64).collect();
            let mut speed_powers = [[0.0; 64]; 2];
            let mut kept = KeptPower::default();
            model.speed_powers(&varying, 5e-6, &mut kept, &mut speed_powers[0]);
            model.speed_powers(&[300.0; 64], 5e-6, &mut kept, &mut speed_powers[1]);
            for (i, &load) in loads.iter().enumerate() {
                for (speed, speed_power) in [
                    (varying[i], speed_powers[0][i]),
                    (300.0, speed_powers[1][i]),
                ] {
                    let lanes = model.loss_with_powers(
                        load,
                        speed,
                        5e-6,
                        [powers[0][i], powers[1][i]],
                        speed_power,
                    );
                    assert_eq!(
                        lanes,
                        model.loss(load, speed, 5e-6),
                        "{reading:?} at {load} N, {speed} rad/s"
                    );
                }
            }
        }
    }

    /// The model with the lane-wise powers (of the load and of the speed) is the formulas of
    /// `rolling_bearing_loss` with `powf`'s powers to within rounding: the powers are within
    /// one ulp of `powf`'s, and the
    /// torque is a short product and sum of them, so 8 ulp (1.8e-15 relative) bounds it.
    #[test]
    fn lane_wise_powers_are_powf_to_rounding() {
        let bearing = RollingBearing::new(0.045, 45_000.0).unwrap();
        for reading in readings() {
            let model = RollingModel::new(bearing, reading);
            for load in [0.5, 37.0, 2000.0, 18_500.0, 3.0e5] {
                let exact: Vec<f64> = model
                    .load_powers()
                    .iter()
                    .map(|p| (load / p.divisor).powf(p.exponent))
                    .chain([0.0])
                    .collect();
                let with_powf = model.loss_with_powers(
                    load,
                    300.0,
                    5e-6,
                    [exact[0], exact[1]],
                    viscous_speed(300.0, 5e-6).powf(2.0 / 3.0),
                );
                let lanes = model.loss(load, 300.0, 5e-6);
                let relative = (lanes.power - with_powf.power).abs() / with_powf.power;
                assert!(
                    relative <= 8.0 * f64::EPSILON,
                    "{reading:?} at {load} N: {relative}"
                );
            }
        }
    }
}
