//! Buckingham's dynamic tooth load (Buckingham 1949, as applied by Karhula 2008, chapter 8 and
//! appendix 8.1, eqs. 8.1 and A8.1.1–A8.1.14), in SI.
//!
//! Karhula's chain (US units: in, lb, ft/min, psi):
//!
//! ```text
//! H     = 0.00120 (1/r1 − 1/r2)                 (A8.1.3, 20° full depth, internal pair)
//! Ip    = π d1⁴ / 32,  m1 = Ip / r1²            (A8.1.5, A8.1.6: "reduced mass", in²)
//! f1    = H m1 v²                               (A8.1.8, v pitch-line velocity = 2 v_AA0c, A8.1.7)
//! def   = 9.00 Ft / b · (1/E1 + 1/E2)           (A8.1.11)
//! f2    = Ft (e/def + 1)                        (A8.1.12, e ≈ 0.005 in)
//! fa    = f1 f2 / (f1 + f2)                     (A8.1.13)
//! Fdyn  = Ft + √(fa (2 f2 − fa))                (A8.1.14, eq. 8.1)
//! ```
//!
//! Unit conversion: `def`, `f2`, `fa`, `Fdyn` are homogeneous (any consistent units). Only `H`
//! carries units: `0.00120 lbf/(in·(ft/min)²)` is converted exactly with [`crate::units`] to
//! `0.00120 · LBF / (INCH · FT_PER_MIN²) ≈ 8143.3 kg/m²` ([`h_constant_si`]). Note
//! `f2 − Ft = e b / (9.00 (1/E1 + 1/E2)) = b C`, the "b C" of the simplified formula
//! ([`dynamic_load_simplified`]).

use crate::error::{non_negative, positive, GearError};
use crate::units::{FT_PER_MIN, INCH, LBF};
use std::f64::consts::PI;

/// Buckingham constants of a tooth form.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ToothForm {
    /// Constant of `H` in US units \[lbf/(in·(ft/min)²)\] (Karhula A8.1.3: 0.00120 for 20° FD).
    pub h_us: f64,
    /// Deformation constant `def = k_def Ft/b (1/E1 + 1/E2)` \[-\] (Karhula A8.1.11: 9.00 for
    /// 20° FD, i.e. Buckingham's `k = 1/9 = 0.111`).
    pub deformation: f64,
}

/// 20° full-depth involute teeth (the only form Karhula gives).
pub const FULL_DEPTH_20: ToothForm = ToothForm {
    h_us: 0.00120,
    deformation: 9.00,
};

/// `H` constant converted exactly to SI \[kg/m²\]: `h_us · LBF / (INCH · FT_PER_MIN²)`.
pub fn h_constant_si(form: &ToothForm) -> f64 {
    form.h_us * LBF / (INCH * FT_PER_MIN * FT_PER_MIN)
}

/// Gear pair and material data of the Buckingham calculation.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BuckinghamPair {
    /// Pinion (cardan wheel) pitch radius `r1` \[m\] (Karhula A8.1.1: the cardan crank length).
    pub pinion_radius: f64,
    /// Gear (ring) pitch radius magnitude `r2` \[m\] (Karhula A8.1.2).
    pub gear_radius: f64,
    /// Internal pair: `H ∝ (1/r1 − 1/r2)` and only the pinion's mass is accelerated (the ring
    /// is fixed), as Karhula. External pair: `H ∝ (1/r1 + 1/r2)` (curvature sum) and the
    /// series mass `m1 m2 / (m1 + m2)`, a Buckingham-style extension not in Karhula.
    pub internal: bool,
    /// Face width `b` \[m\] (Karhula A8.1.9: `≈ d1/3`).
    pub face_width: f64,
    /// Effective profile error `e` \[m\] (Karhula: 0.005 in = 0.127 mm).
    pub error: f64,
    /// Young's modulus of the pinion `E1` \[Pa\].
    pub e1: f64,
    /// Young's modulus of the gear `E2` \[Pa\].
    pub e2: f64,
    /// Tooth form constants.
    pub form: ToothForm,
}

/// Intermediate and final values of the chain \[N, m\].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DynamicLoad {
    /// Force to accelerate the effective mass `f1` \[N\] (A8.1.8).
    pub f1: f64,
    /// Tooth deformation under `Ft`, `def` \[m\] (A8.1.11).
    pub deformation: f64,
    /// Force to deform the teeth by the error `f2` \[N\] (A8.1.12).
    pub f2: f64,
    /// Acceleration load `fa` \[N\] (A8.1.13).
    pub fa: f64,
    /// Dynamic tooth load `Fdyn` \[N\] (A8.1.14).
    pub dynamic_load: f64,
}

impl BuckinghamPair {
    /// Karhula's "reduced mass" of a solid disc of pitch diameter `d = 2 r`:
    /// `Ip / r² = (π d⁴ / 32) / r² = π d² / 8` \[m²\] (A8.1.5, A8.1.6; density sits in `H`).
    pub fn disc_mass(radius: f64) -> f64 {
        let d = 2.0 * radius;
        PI * d.powi(4) / 32.0 / (radius * radius)
    }

    /// Dynamic tooth load for tangential load `ft` \[N\] (≥ 0) at pitch-line velocity `v` \[m/s\]
    /// (for the cardan gear `v = 2 ω e`, see [`cardan_pitch_line_velocity`]). A zero load gives
    /// `Fdyn = 0` (the limit of A8.1.14 as `Ft → 0`).
    pub fn dynamic_load(&self, ft: f64, v: f64) -> Result<DynamicLoad, GearError> {
        positive("pinion_radius", self.pinion_radius)?;
        positive("gear_radius", self.gear_radius)?;
        positive("face_width", self.face_width)?;
        non_negative("error", self.error)?;
        positive("e1", self.e1)?;
        positive("e2", self.e2)?;
        positive("form.h_us", self.form.h_us)?;
        positive("form.deformation", self.form.deformation)?;
        non_negative("tangential load", ft)?;
        non_negative("pitch-line velocity", v.abs())?;
        let (r1, r2) = (self.pinion_radius, self.gear_radius);
        let (curv, mass) = if self.internal {
            (1.0 / r1 - 1.0 / r2, Self::disc_mass(r1))
        } else {
            let (m1, m2) = (Self::disc_mass(r1), Self::disc_mass(r2));
            (1.0 / r1 + 1.0 / r2, m1 * m2 / (m1 + m2))
        };
        let f1 = h_constant_si(&self.form) * curv * mass * v * v;
        let compliance = 1.0 / self.e1 + 1.0 / self.e2;
        let deformation = self.form.deformation * ft / self.face_width * compliance;
        // f2 = Ft (e/def + 1) = b e / (k (1/E1+1/E2)) + Ft, finite also at Ft = 0.
        let f2 = self.face_width * self.error / (self.form.deformation * compliance) + ft;
        let fa = if f1 + f2 > 0.0 {
            f1 * f2 / (f1 + f2)
        } else {
            0.0
        };
        let dynamic_load = if ft == 0.0 {
            0.0
        } else {
            ft + (fa * (2.0 * f2 - fa)).max(0.0).sqrt()
        };
        Ok(DynamicLoad {
            f1,
            deformation,
            f2,
            fa,
            dynamic_load,
        })
    }
}

impl BuckinghamPair {
    /// The limit of the chain for an effective mass without bound (f1 → ∞ in A8.1.13): the
    /// acceleration load reaches f2 and A8.1.14 becomes `Fdyn = Ft + f2 = 2·Ft + b·e/(k·(1/E1 +
    /// 1/E2))` at any speed. Karhula's published dynamic tooth loads (App. 11.6.1) follow this
    /// limit to within 1 % (their values at 3π rad/s for the pump and the engine fix the
    /// intercept b·e/(k·(1/E1+1/E2)) = 29.2 kN of his 20-tooth pair, e = 0.005 in, E = 30·10⁶
    /// psi), although his own f1 (A8.1.8) is 10⁴ times smaller than that would need; some unit
    /// slip in A8.1.5-8 must have made f1 huge, and the table cannot tell which. For
    /// [`crate::GearSet`] users who reproduce the thesis; [`Self::dynamic_load`] is the chain.
    pub fn saturated_dynamic_load(&self, ft: f64) -> Result<DynamicLoad, GearError> {
        self.saturated()?.at(ft)
    }

    /// [`Self::saturated_dynamic_load`] with the pair's checks made and its constants taken
    /// once, for a load rated step after step.
    pub fn saturated(&self) -> Result<SaturatedLoad, GearError> {
        positive("face_width", self.face_width)?;
        non_negative("error", self.error)?;
        positive("e1", self.e1)?;
        positive("e2", self.e2)?;
        positive("form.deformation", self.form.deformation)?;
        let compliance = 1.0 / self.e1 + 1.0 / self.e2;
        Ok(SaturatedLoad {
            face_width: self.face_width,
            deformation: self.form.deformation,
            compliance,
            f2_unloaded: self.face_width * self.error / (self.form.deformation * compliance),
        })
    }
}

/// Buckingham's load at the limit f1 → ∞ ([`BuckinghamPair::saturated_dynamic_load`]) of a
/// checked pair: its constants, the same arithmetic as the pair's (the same bits).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SaturatedLoad {
    /// Face width `b` \[m\].
    face_width: f64,
    /// The tooth form's deformation factor `k` \[-\].
    deformation: f64,
    /// `1/E1 + 1/E2` \[1/Pa\].
    compliance: f64,
    /// `b·e/(k·(1/E1 + 1/E2))`, f2 at no load \[N\] (A8.1.13).
    f2_unloaded: f64,
}

impl SaturatedLoad {
    /// The load at the tangential load `ft` \[N\] (A8.1.13-14 with f1 → ∞).
    pub fn at(&self, ft: f64) -> Result<DynamicLoad, GearError> {
        non_negative("tangential load", ft)?;
        let f2 = self.f2_unloaded + ft;
        Ok(DynamicLoad {
            f1: f64::INFINITY,
            deformation: self.deformation * ft / self.face_width * self.compliance,
            f2,
            fa: f2,
            dynamic_load: self.dynamic_load(ft),
        })
    }

    /// Whether [`SaturatedLoad::at`] takes the tangential load `ft` \[N\] (finite, ≥ 0).
    #[inline(always)]
    pub fn takes(ft: f64) -> bool {
        ft.is_finite() && ft >= 0.0
    }

    /// The dynamic load of [`SaturatedLoad::at`] at a load it takes ([`SaturatedLoad::takes`]),
    /// `Ft + f2` (A8.1.14 with f1 → ∞), 0 at no load \[N\]: the same bits. Inlined, for a
    /// block kernel's loop over its lanes.
    #[inline(always)]
    pub fn dynamic_load(&self, ft: f64) -> f64 {
        let f2 = self.f2_unloaded + ft;
        if ft == 0.0 {
            0.0
        } else {
            ft + f2
        }
    }
}

/// Pitch-line velocity of the cardan gear mesh `v = 2 v_AA0c = 2 |ω| e` \[m/s\] (Karhula A8.1.7),
/// `crank_speed` ω \[rad/s\], `cardan_crank_length` e \[m\].
pub fn cardan_pitch_line_velocity(crank_speed: f64, cardan_crank_length: f64) -> f64 {
    2.0 * crank_speed.abs() * cardan_crank_length
}

/// Buckingham's deformation factor `C = k e / (1/E1 + 1/E2)`, a load per unit face width
/// \[N/m\] (`docs/validation/gears.md` §3.1; lb/in in US units). `k` \[-\] (0.111 for 20° FD), `e`
/// \[m\], `E` \[Pa\]. Homogeneous: the same `k` serves US and SI units.
pub fn deformation_factor(k: f64, error: f64, e1: f64, e2: f64) -> Result<f64, GearError> {
    positive("k", k)?;
    non_negative("error", error)?;
    positive("e1", e1)?;
    positive("e2", e2)?;
    Ok(k * error / (1.0 / e1 + 1.0 / e2))
}

/// Constant `K3` of the simplified SI form: the US `0.05 V` (V in ft/min, loads in lbf)
/// converted exactly, `K3 = 0.05 √LBF / FT_PER_MIN ≈ 20.76` \[√N·s/m\]. Bhandari-type texts
/// round it to 21, PSG data book scripts to 20.67.
pub fn k3_exact() -> f64 {
    0.05 * LBF.sqrt() / FT_PER_MIN
}

/// Buckingham's simplified dynamic load (`docs/validation/gears.md` §3.2/§3.3):
/// `Fd = Ft + K3 v (b C + Ft) / (K3 v + √(b C + Ft))` \[N\], `v` \[m/s\], `b C` \[N\] (face width
/// times deformation factor), `k3` \[√N·s/m\] ([`k3_exact`] or a textbook rounding).
/// Returns the **total** load `Fd`; the increment is `Fd − Ft`.
pub fn dynamic_load_simplified(ft: f64, v: f64, bc: f64, k3: f64) -> Result<f64, GearError> {
    non_negative("tangential load", ft)?;
    non_negative("pitch-line velocity", v)?;
    non_negative("b C", bc)?;
    positive("k3", k3)?;
    let x = bc + ft;
    if x == 0.0 {
        return Ok(0.0);
    }
    Ok(ft + k3 * v * x / (k3 * v + x.sqrt()))
}
