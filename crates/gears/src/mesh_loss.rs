//! Gear mesh power loss after Anderson & Loewenthal (NASA TP-1622, 1980; ASME 1981/1982) as
//! transcribed by Karhula 2008, appendix 9.1, eqs. A9.1.40–A9.1.55: sliding loss with the
//! Benedict & Kelley friction coefficient, rolling (EHD pumping) loss with the EHD film
//! thickness, and windage.
//!
//! Two readings, chosen with [`Reading`]:
//!
//! * [`Reading::Karhula`] — the thesis as printed: path of contact and contact ratio from
//!   A9.1.40/A9.1.52 (full addenda, no shift, whatever the real pair is); mesh speed = the
//!   cardan wheel's **absolute** speed (A9.1.41); sliding factor `(1+i)/i` (A9.1.42) and
//!   rolling term `d1 sin α − (L/4)(i−1)/i` (A9.1.43) — the external-gear forms; equivalent
//!   radius A9.1.50 as printed; dynamic viscosity in **Pa·s** (A9.1.47) in the friction,
//!   film and windage correlations.
//! * [`Reading::Corrected`] — (1) viscosity in **centipoise** in A9.1.48, A9.1.51 and A9.1.54
//!   (`docs/validation/gears.md` §4.3: Benedict & Kelley's `3.17·10⁸` in lb/in, in/s, cP converts
//!   exactly to the printed 29.66 in N/m, m/s, cP, and the film formula with cP agrees with a
//!   Hamrock–Dowson check, ~0.13 µm, whereas Pa·s gives ~1 nm); (2) internal-mesh kinematics
//!   (`docs/validation/gears.md` §4.4): the mesh speed is the pinion speed **relative to the
//!   carrier** (crank), `2ω` for the 2:1 cardan gear where Karhula's absolute speed is `ω`; the
//!   sliding factor of an internal mesh is `(i−1)/i` and the rolling-sum term `(i+1)/i` (derived
//!   here: at a distance `s` from the pitch point the sliding speed is `(ω1 ∓ ω2) s` and the
//!   rolling-speed sum `ω1 d1 sin α + ω1 (1 ∓ 1/i) s`, upper sign external); the equivalent radius
//!   is `ρ1 ρ2/(ρ1 ± ρ2)` at the same contact point as A9.1.50 (`ρ1 = (d1 sin α + L/2)/2`), whose
//!   printed denominator `2(d2 sin α + L/2)` matches neither pair type; path of contact, contact
//!   ratio and pressure angle are the pair's actual (operating) values. The friction
//!   coefficient is clamped at 0 where the Benedict & Kelley logarithm turns negative
//!   (outside its range), flagged in [`MeshLoss::friction_clamped`]. Windage uses the pinion's
//!   absolute spin speed in both readings.
//!
//! For a fixed-axis external pair (`carrier = 0`) both readings use the same speeds and
//! external factors and differ only in the viscosity unit, path of contact and `R_eq`.
//!
//! Not verified against TP-1622 itself (its Table III could not be read): the windage
//! correlation is used as Karhula prints it (`1 + 2.3 b/d1`, `(d1/2)^4.6`, `d1/2` in m).

use cardan_numeric::{log10_lane, log10_lanes, powf_lane, powf_lanes, KeptPower};
use std::f64::consts::PI;

use crate::error::{non_negative, positive, require, GearError};
use crate::geometry::{karhula_contact_ratio, karhula_path_of_contact, GearPair};
use crate::units::CENTIPOISE;

/// Which transcription of the Anderson & Loewenthal model to use (see module docs).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Reading {
    /// Karhula 2008 A9.1.40–A9.1.55 as printed.
    Karhula,
    /// Viscosity in cP, carrier-relative internal-mesh kinematics, actual geometry.
    Corrected,
}

impl Reading {
    /// The individual switches this reading stands for.
    pub fn options(self) -> LossOptions {
        let c = self == Reading::Corrected;
        LossOptions {
            viscosity_in_centipoise: c,
            mesh_kinematics: c,
            actual_geometry: c,
            clamp_friction: c,
        }
    }
}

/// The individual differences between the two readings, for sensitivity studies
/// ([`mesh_loss_with`]); `Reading::Karhula.options()` is all `false`,
/// `Reading::Corrected.options()` all `true`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct LossOptions {
    /// Viscosity in cP (`docs/validation/gears.md` §4.3) instead of Pa·s in A9.1.48, A9.1.51,
    /// A9.1.54.
    pub viscosity_in_centipoise: bool,
    /// Carrier-relative mesh speed and internal-mesh sliding/rolling factors
    /// (`docs/validation/gears.md` §4.4).
    pub mesh_kinematics: bool,
    /// Actual path of contact, contact ratio, operating pressure angle and pitch diameters and
    /// the curvature-consistent `R_eq`, instead of A9.1.40, A9.1.52, A9.1.50.
    pub actual_geometry: bool,
    /// Clamp a negative Benedict & Kelley friction coefficient at 0.
    pub clamp_friction: bool,
}

/// Geometry of the mesh as the loss model needs it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MeshGeometry {
    /// Module `m` \[m\].
    pub module: f64,
    /// Reference pressure angle `α` \[rad\] (Karhula reading).
    pub pressure_angle: f64,
    /// Operating pressure angle \[rad\] (corrected reading).
    pub operating_pressure_angle: f64,
    /// Pinion reference pitch diameter `d1` \[m\] (Karhula reading).
    pub pinion_diameter: f64,
    /// Gear reference pitch diameter magnitude `d2` \[m\] (Karhula reading).
    pub gear_diameter: f64,
    /// Pinion operating pitch diameter \[m\] (corrected reading).
    pub pinion_working_diameter: f64,
    /// Gear operating pitch diameter magnitude \[m\] (corrected reading).
    pub gear_working_diameter: f64,
    /// Internal pair.
    pub internal: bool,
    /// Face width `b` \[m\].
    pub face_width: f64,
    /// Actual length of path of contact \[m\] (corrected reading).
    pub path_of_contact: f64,
    /// Actual transverse contact ratio \[-\] (corrected reading).
    pub contact_ratio: f64,
}

impl MeshGeometry {
    /// From a validated pair and a face width `b` \[m\].
    pub fn from_pair(pair: &GearPair, face_width: f64) -> Result<Self, GearError> {
        positive("face_width", face_width)?;
        Ok(Self {
            module: pair.spec.module,
            pressure_angle: pair.spec.pressure_angle,
            operating_pressure_angle: pair.operating_pressure_angle,
            pinion_diameter: pair.pinion.reference,
            gear_diameter: pair.gear.reference,
            pinion_working_diameter: pair.pinion.working,
            gear_working_diameter: pair.gear.working,
            internal: pair.internal,
            face_width,
            path_of_contact: pair.path_of_contact,
            contact_ratio: pair.contact_ratio,
        })
    }
}

/// Lubricant properties.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Lubricant {
    /// Kinematic viscosity `ν` \[m²/s\] (Karhula: ≲ 5 mm²/s).
    pub kinematic_viscosity: f64,
    /// Density `ρ` \[kg/m³\] (Karhula: ≈ 900).
    pub density: f64,
}

impl Lubricant {
    /// Dynamic viscosity `η = ν ρ` \[Pa·s\] (Karhula A9.1.47).
    pub fn dynamic_viscosity(&self) -> f64 {
        self.kinematic_viscosity * self.density
    }
}

/// Angular speeds of the mesh members.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MeshSpeeds {
    /// Absolute angular speed of the pinion (cardan wheel) \[rad/s\].
    pub pinion_absolute: f64,
    /// Angular speed of the carrier (crank) that holds the pinion axis \[rad/s\]; 0 for fixed
    /// axes.
    pub carrier: f64,
}

/// Loss breakdown \[SI\].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MeshLoss {
    /// Path of contact used `L` \[m\].
    pub path_of_contact: f64,
    /// Contact ratio used \[-\].
    pub contact_ratio: f64,
    /// Average sliding velocity `v_s` \[m/s\] (A9.1.42).
    pub sliding_velocity: f64,
    /// Average rolling velocity `v_r` \[m/s\] (A9.1.43).
    pub rolling_velocity: f64,
    /// Normal load per tooth pair `F_n = |Ft|/(2 cos α)` \[N\] (A9.1.45).
    pub normal_load: f64,
    /// Benedict & Kelley friction coefficient `μ` \[-\] (A9.1.48).
    pub friction_coefficient: f64,
    /// Equivalent contact radius `R_eq` \[m\] (A9.1.50).
    pub equivalent_radius: f64,
    /// Central EHD film thickness `h` \[m\] (A9.1.51).
    pub film_thickness: f64,
    /// Sliding power loss \[W\] (A9.1.49).
    pub sliding_power: f64,
    /// Rolling power loss \[W\] (A9.1.53).
    pub rolling_power: f64,
    /// Windage power loss \[W\] (A9.1.54).
    pub windage_power: f64,
    /// Total \[W\] (A9.1.55).
    pub total_power: f64,
    /// The friction coefficient was negative and set to 0 (when `clamp_friction`).
    pub friction_clamped: bool,
}

/// Mesh power loss for tangential tooth load `ft` \[N\] (its sign is ignored) in the given
/// reading.
pub fn mesh_loss(
    geometry: &MeshGeometry,
    lubricant: &Lubricant,
    speeds: &MeshSpeeds,
    ft: f64,
    reading: Reading,
) -> Result<MeshLoss, GearError> {
    mesh_loss_with(geometry, lubricant, speeds, ft, reading.options())
}

/// Mesh power loss with the reading's switches set one by one (see [`LossOptions`]).
pub fn mesh_loss_with(
    geometry: &MeshGeometry,
    lubricant: &Lubricant,
    speeds: &MeshSpeeds,
    ft: f64,
    options: LossOptions,
) -> Result<MeshLoss, GearError> {
    check_inputs(geometry, lubricant)?;
    check_step(speeds, ft)?;
    Ok(MeshConstants::new(geometry, lubricant, options)?.loss(
        speeds,
        ft,
        &mut KeptSpeedPowers::default(),
    ))
}

/// The checks of [`mesh_loss_with`] on the geometry and lubricant that come before the step's.
fn check_inputs(g: &MeshGeometry, lubricant: &Lubricant) -> Result<(), GearError> {
    positive("module", g.module)?;
    positive("face_width", g.face_width)?;
    positive("pinion_diameter", g.pinion_diameter)?;
    require(
        g.gear_diameter > g.pinion_diameter || !g.internal,
        "gear_diameter",
        "an internal gear must be larger than the pinion",
        g.gear_diameter,
    )?;
    positive("kinematic_viscosity", lubricant.kinematic_viscosity)?;
    positive("density", lubricant.density)?;
    Ok(())
}

/// The checks of [`mesh_loss_with`] on a step's load and speeds.
fn check_step(speeds: &MeshSpeeds, ft: f64) -> Result<(), GearError> {
    require(ft.is_finite(), "tangential load", "must be finite", ft)?;
    require(
        speeds.pinion_absolute.is_finite() && speeds.carrier.is_finite(),
        "speeds",
        "must be finite",
        speeds.pinion_absolute,
    )?;
    Ok(())
}

/// [`mesh_loss_with`] of one mesh, geometry, lubricant and reading, evaluated step by step:
/// what depends on neither the load nor the speeds (the path of contact, the pressure angle's
/// sine and cosine, `R_eq^0.464`, the windage's `(d1/2)^4.6` and viscosity term) taken once,
/// and the speed's powers kept from the step before while the speed does not change (a
/// constant crank speed). The same arithmetic, in the same order, as [`mesh_loss_with`]: the
/// same bits, and the same errors.
#[derive(Debug, Clone, PartialEq)]
pub struct PreparedMeshLoss {
    geometry: MeshGeometry,
    lubricant: Lubricant,
    options: LossOptions,
    /// `None` if the geometry or lubricant fails a check: every step then goes through
    /// [`mesh_loss_with`], which says which.
    constants: Option<MeshConstants>,
    kept: KeptSpeedPowers,
}

impl PreparedMeshLoss {
    /// The loss of the mesh `geometry` in `lubricant` under `options` (a reading's).
    pub fn new(geometry: &MeshGeometry, lubricant: &Lubricant, options: LossOptions) -> Self {
        let constants = check_inputs(geometry, lubricant)
            .and_then(|()| MeshConstants::new(geometry, lubricant, options))
            .ok();
        Self {
            geometry: *geometry,
            lubricant: *lubricant,
            options,
            constants,
            kept: KeptSpeedPowers::default(),
        }
    }

    /// [`mesh_loss_with`] at this step's `speeds` and tangential load `ft` \[N\].
    pub fn loss(&mut self, speeds: &MeshSpeeds, ft: f64) -> Result<MeshLoss, GearError> {
        match &self.constants {
            Some(c) => {
                check_step(speeds, ft)?;
                Ok(c.loss(speeds, ft, &mut self.kept))
            }
            None => mesh_loss_with(&self.geometry, &self.lubricant, speeds, ft, self.options),
        }
    }

    /// The total loss [`PreparedMeshLoss::loss`] gives (W) at each lane `i` of a block, the
    /// pinion's absolute speed `pinion[i]` and the carrier's `carrier[i]` (rad/s) under the
    /// tangential load `ft[i]` (N), into `out[i]`, for the lanes of `out` (the others at least
    /// as long): the logarithms and powers of every lane at once
    /// ([`cardan_numeric::log10_lanes`], [`cardan_numeric::powf_lanes`]), the same bits as
    /// the lanes one by one. `false` where a lane or the mesh fails a check of
    /// [`PreparedMeshLoss::loss`] (which then says which: `out` holds nothing to be taken).
    /// Inlined, so that a block kernel (`cardan_mechanism::vectorised!`) compiles it for its
    /// instruction set.
    #[inline(always)]
    pub fn total_power_lanes(
        &mut self,
        pinion: &[f64],
        carrier: &[f64],
        ft: &[f64],
        out: &mut [f64],
    ) -> bool {
        let Some(c) = &self.constants else {
            return false;
        };
        let kept = &mut self.kept;
        for (k, out) in out.chunks_mut(CHUNK).enumerate() {
            let n = out.len();
            let lanes = k * CHUNK..k * CHUNK + n;
            let (pinion, carrier, ft) =
                (&pinion[lanes.clone()], &carrier[lanes.clone()], &ft[lanes]);
            let mut t = [SpeedTerms::default(); CHUNK];
            let (mut n_abs, mut f_n) = ([0.0; CHUNK], [0.0; CHUNK]);
            let mut checked = true;
            for i in 0..n {
                // check_step's conditions, without its error.
                checked &= ft[i].is_finite() && pinion[i].is_finite() && carrier[i].is_finite();
                (n_abs[i], t[i].v_s, t[i].v_r) = c.velocities(pinion[i], carrier[i]);
                f_n[i] = c.normal_load(ft[i]);
            }
            if !checked {
                return false;
            }
            // The speeds' powers lane by lane, kept while their arguments' bits stay.
            for (t, &n_abs) in t[..n].iter_mut().zip(&n_abs) {
                t.film = c.film_power(t.v_r, kept);
                t.windage = kept.windage.pow(n_abs, 2.8);
            }
            let (mut argument, mut base) = ([0.0; CHUNK], [0.0; CHUNK]);
            for i in 0..n {
                argument[i] = c.friction_argument(&t[i], f_n[i]);
                base[i] = load_base(f_n[i]);
            }
            let (mut log, mut power) = ([0.0; CHUNK], [0.0; CHUNK]);
            log10_lanes(&argument[..n], &mut log[..n]);
            powf_lanes(&base[..n], -0.067, &mut power[..n]);
            for (i, o) in out.iter_mut().enumerate() {
                *o = c.finish(&t[i], f_n[i], log[i], power[i]).total_power;
            }
        }
        true
    }
}

/// The lanes [`PreparedMeshLoss::total_power_lanes`] takes at once (a block's, or fewer).
const CHUNK: usize = 64;

/// The powers of the speed-dependent terms at the last step's arguments: `n_abs^2.8` and
/// `(v_r η)^0.67`, taken again only when their argument's bits change.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
struct KeptSpeedPowers {
    /// `n_abs^2.8` (A9.1.54).
    windage: KeptPower,
    /// `(v_r η)^0.67` (A9.1.51).
    film: KeptPower,
}

/// What [`mesh_loss_with`] computes from the geometry, lubricant and reading alone.
#[derive(Debug, Clone, Copy, PartialEq)]
struct MeshConstants {
    /// Pinion pitch diameter, path of contact and contact ratio of the reading.
    d1: f64,
    l: f64,
    cr: f64,
    /// [`LossOptions::mesh_kinematics`], [`LossOptions::clamp_friction`].
    mesh_kinematics: bool,
    clamp_friction: bool,
    /// Sliding and rolling factors of A9.1.42-43 (or their internal-mesh forms).
    slide_k: f64,
    roll_k: f64,
    /// Viscosity in the reading's unit.
    eta: f64,
    s: f64,
    c: f64,
    b: f64,
    r_eq: f64,
    /// `R_eq^0.464` (A9.1.51).
    r_eq_power: f64,
    /// `2.82e-7 (1 + 2.3 b/d1)`, `(d1/2)^4.6`, `(0.028 η + 0.019)^0.2` (A9.1.54).
    windage: [f64; 3],
}

impl MeshConstants {
    fn new(
        g: &MeshGeometry,
        lubricant: &Lubricant,
        options: LossOptions,
    ) -> Result<Self, GearError> {
        let eta_pa_s = lubricant.dynamic_viscosity();
        let (alpha, d1, d2, l, cr) = if options.actual_geometry {
            let (d1, d2) = (g.pinion_working_diameter, g.gear_working_diameter);
            positive("pinion_working_diameter", d1)?;
            positive("gear_working_diameter", d2)?;
            positive("path_of_contact", g.path_of_contact)?;
            non_negative("contact_ratio", g.contact_ratio)?;
            (
                g.operating_pressure_angle,
                d1,
                d2,
                g.path_of_contact,
                g.contact_ratio,
            )
        } else {
            // A9.1.40, A9.1.52
            let (d1, d2, a) = (g.pinion_diameter, g.gear_diameter, g.pressure_angle);
            let l = karhula_path_of_contact(d1, d2, g.module, a);
            (a, d1, d2, l, karhula_contact_ratio(l, g.module, a))
        };
        let i = d2 / d1;
        let (slide_k, roll_k) = if options.mesh_kinematics {
            if g.internal {
                ((i - 1.0) / i, (i + 1.0) / i)
            } else {
                ((i + 1.0) / i, (i - 1.0) / i)
            }
        } else {
            // A9.1.42–A9.1.43: external factors.
            ((1.0 + i) / i, (i - 1.0) / i)
        };
        let eta = if options.viscosity_in_centipoise {
            eta_pa_s / CENTIPOISE
        } else {
            eta_pa_s
        };
        let (s, c) = (alpha.sin(), alpha.cos());
        let b = g.face_width;
        // A9.1.50
        let a1 = d1 * s + l / 2.0;
        let r_eq = if !options.actual_geometry {
            a1 * (d2 * s - l / 2.0) / (2.0 * (d2 * s + l / 2.0))
        } else if g.internal {
            let b2 = d2 * s + l / 2.0;
            a1 * b2 / (2.0 * (b2 - a1))
        } else {
            let b2 = d2 * s - l / 2.0;
            a1 * b2 / (2.0 * (a1 + b2))
        };
        Ok(Self {
            d1,
            l,
            cr,
            mesh_kinematics: options.mesh_kinematics,
            clamp_friction: options.clamp_friction,
            slide_k,
            roll_k,
            eta,
            s,
            c,
            b,
            r_eq,
            r_eq_power: r_eq.powf(0.464),
            windage: [
                2.82e-7 * (1.0 + 2.3 * b / d1),
                (d1 / 2.0).powf(4.6),
                (0.028 * eta + 0.019).powf(0.2),
            ],
        })
    }

    /// The loss at `speeds` under `ft` (checked finite), A9.1.41-55: the terms of the speeds,
    /// the load's logarithm and power by the lanes' functions (within one ulp of libm's
    /// `log10` and `powf`, `cardan_numeric`), the rest ([`MeshConstants::finish`]), as a block's
    /// lanes take them ([`PreparedMeshLoss::total_power_lanes`]): the same bits.
    fn loss(&self, speeds: &MeshSpeeds, ft: f64, kept: &mut KeptSpeedPowers) -> MeshLoss {
        let t = self.speed_terms(speeds, kept);
        let f_n = self.normal_load(ft);
        let log = log10_lane(self.friction_argument(&t, f_n));
        let power = powf_lane(load_base(f_n), -0.067);
        self.finish(&t, f_n, log, power)
    }

    /// The terms of the speeds alone (A9.1.41-43; the powers of A9.1.51 and A9.1.54 from
    /// `kept`).
    #[inline(always)]
    fn speed_terms(&self, speeds: &MeshSpeeds, kept: &mut KeptSpeedPowers) -> SpeedTerms {
        let (n_abs, v_s, v_r) = self.velocities(speeds.pinion_absolute, speeds.carrier);
        SpeedTerms {
            v_s,
            v_r,
            film: self.film_power(v_r, kept),
            windage: kept.windage.pow(n_abs, 2.8),
        }
    }

    /// The pinion's absolute speed in rpm, and the sliding and rolling velocities `v_s`, `v_r`
    /// \[m/s\] (A9.1.41-43) at the pinion's and the carrier's speeds \[rad/s\].
    #[inline(always)]
    fn velocities(&self, pinion: f64, carrier: f64) -> (f64, f64, f64) {
        let to_rpm = 60.0 / (2.0 * PI);
        let n_abs = pinion.abs() * to_rpm;
        let n_mesh = if self.mesh_kinematics {
            (pinion - carrier).abs() * to_rpm
        } else {
            // A9.1.41: absolute wheel speed.
            n_abs
        };
        // A9.1.42, A9.1.43 (0.0262 ≈ 2π/60/4, 0.1047 ≈ 2π/60 as printed).
        let v_s = 0.0262 * n_mesh * self.slide_k * self.l;
        let v_r = (0.1047 * n_mesh * (self.d1 * self.s - self.l / 4.0 * self.roll_k)).max(0.0);
        (n_abs, v_s, v_r)
    }

    /// A9.1.51's `(v_r η)^0.67`, kept in `kept`.
    #[inline(always)]
    fn film_power(&self, v_r: f64, kept: &mut KeptSpeedPowers) -> f64 {
        kept.film.pow(v_r * self.eta, 0.67)
    }

    /// The normal load per tooth pair `F_n = |Ft|/(2 cos α)` \[N\] (A9.1.45).
    #[inline(always)]
    fn normal_load(&self, ft: f64) -> f64 {
        ft.abs() / (2.0 * self.c)
    }

    /// The argument of Benedict & Kelley's logarithm (A9.1.48) where the friction coefficient
    /// is taken from it (a load, sliding and rolling), 1 elsewhere (its logarithm unused).
    #[inline(always)]
    fn friction_argument(&self, t: &SpeedTerms, f_n: f64) -> f64 {
        if f_n > 0.0 && t.v_s > 0.0 && t.v_r > 0.0 {
            29.66 * f_n / (self.b * self.eta * t.v_s * t.v_r * t.v_r)
        } else {
            1.0
        }
    }

    /// The loss from the speeds' terms `t`, the normal load `f_n`, the logarithm `log` of its
    /// [friction argument](MeshConstants::friction_argument) and `power` = f_n^−0.067 (of
    /// [`load_base`]), A9.1.48-55.
    #[inline(always)]
    fn finish(&self, t: &SpeedTerms, f_n: f64, log: f64, power: f64) -> MeshLoss {
        let SpeedTerms { v_s, v_r, .. } = *t;
        let (b, r_eq) = (self.b, self.r_eq);
        // A9.1.48
        let taken = f_n > 0.0 && v_s > 0.0 && v_r > 0.0;
        let m = 0.0127 * log;
        let clamped = taken && self.clamp_friction && m < 0.0;
        let mu = if taken && !clamped { m } else { 0.0 };
        // A9.1.49 [kW] -> W
        let p_s = 2e-3 * v_s * mu * f_n * 1e3;
        // A9.1.51: undefined at zero load; reported as zero film and zero rolling loss.
        let h = if f_n > 0.0 && v_r > 0.0 && r_eq > 0.0 {
            2.051e-7 * t.film * power * self.r_eq_power
        } else {
            0.0
        };
        // A9.1.53 [kW] -> W
        let p_r = 9e4 * v_r * h * b * self.cr * 1e3;
        // A9.1.54 [kW] -> W; pinion absolute spin speed in both readings.
        let [w0, w1, w2] = self.windage;
        let p_w = w0 * t.windage * w1 * w2 * 1e3;
        MeshLoss {
            path_of_contact: self.l,
            contact_ratio: self.cr,
            sliding_velocity: v_s,
            rolling_velocity: v_r,
            normal_load: f_n,
            friction_coefficient: mu,
            equivalent_radius: r_eq,
            film_thickness: h,
            sliding_power: p_s,
            rolling_power: p_r,
            windage_power: p_w,
            total_power: p_s + p_r + p_w,
            friction_clamped: clamped,
        }
    }
}

/// The base of the load's power f_n^−0.067 (A9.1.51): the normal load where positive, else 1
/// (the film is then zero, its power unused).
#[inline(always)]
fn load_base(f_n: f64) -> f64 {
    if f_n > 0.0 {
        f_n
    } else {
        1.0
    }
}

/// A step's terms of the speeds alone ([`MeshConstants::speed_terms`]).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
struct SpeedTerms {
    /// Sliding and rolling velocities `v_s`, `v_r` \[m/s\] (A9.1.42-43).
    v_s: f64,
    v_r: f64,
    /// `(v_r η)^0.67` (A9.1.51), `n_abs^2.8` (A9.1.54).
    film: f64,
    windage: f64,
}
