//! Spur gear pair geometry per ISO 21771:2007, external and internal, with the checks an
//! internal (cardan) pair needs.
//!
//! # Conventions
//!
//! * ISO 21771 signed convention: an internal gear has a **negative** tooth number `z2 < 0`,
//!   and with it negative reference, base, tip, root and working diameters and a negative
//!   centre distance. The same formulas then serve both pair types. The public outputs of
//!   [`GearPair`] are **magnitudes** (positive), documented field by field.
//! * Profile shift `x` follows ISO 21771: tip diameter `da = d + 2 m (ha* + x)` and
//!   `inv αw = inv α + 2 tan α (x1 + x2)/(z1 + z2)` for both pair types. On an internal gear a
//!   positive `x2` therefore *lengthens* its addendum (its tip circle moves towards the axis).
//!   KHK's "Gear Technical Reference" writes the internal gear the other way round
//!   (`da2 = d2 − 2 m (ha* − x2)`), so `x2(ISO) = −x2(KHK)`; Nunes 2017's "+0.5/−0.5"
//!   (long-addendum pinion, short-addendum ring) is ISO `x1 = +0.5, x2 = −0.5`.
//! * Angles in radians, lengths in metres.
//!
//! # Checks ([`GearPair::checks`])
//!
//! Every check returns a dimensionless margin (≥ 0 passes) and, on failure, the remedies:
//! involute interference (KHK criterion, both flanks of an external pair, the pinion flank of an
//! internal pair), tip/trochoid interference (KHK), ring tip circle inside its base circle,
//! minimum teeth difference (AGMA 917-B97 as quoted by Nunes 2017), transverse contact ratio
//! ≥ 1, pinion undercut (rack generation) and backlash sign.

use std::f64::consts::PI;

use crate::error::{finite, non_negative, positive, require, GearError};
use crate::involute::{inv, inv_inverse};

/// How the tip diameter of one gear is fixed.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Tip {
    /// From the addendum coefficient `ha*` (ISO 21771: `da = d + 2 m (ha* + x)`, signed `d`);
    /// `1.0` for the ISO 53 basic rack.
    Coefficient(f64),
    /// Given tip diameter magnitude \[m\] (for an internal gear: the inner, tip circle diameter).
    Diameter(f64),
}

/// One gear of the pair.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GearSpec {
    /// Number of teeth `z` \[-\]: positive for an external gear, negative for an internal gear
    /// (ISO 21771). The pinion must be external.
    pub teeth: i32,
    /// Profile shift coefficient `x` \[-\], ISO 21771 sign convention (see module docs).
    pub shift: f64,
    /// Tip diameter rule.
    pub tip: Tip,
    /// Dedendum coefficient `hf*` \[-\] (root diameter `df = d − 2 m (hf* − x)`, signed `d`);
    /// 1.25 for the ISO 53 basic rack.
    pub dedendum_coefficient: f64,
    /// Circumferential tooth thickness allowance at the reference circle \[m\], ≥ 0 (the amount
    /// the tooth is thinned to create backlash).
    pub thickness_allowance: f64,
}

impl GearSpec {
    /// A gear with the ISO 53 basic rack (`ha* = 1`, `hf* = 1.25`), shift `x`, no thinning.
    pub fn standard(teeth: i32, shift: f64) -> Self {
        Self {
            teeth,
            shift,
            tip: Tip::Coefficient(1.0),
            dedendum_coefficient: 1.25,
            thickness_allowance: 0.0,
        }
    }

    /// Same gear with the addendum coefficient `ha*` replaced.
    pub fn with_addendum(mut self, ha: f64) -> Self {
        self.tip = Tip::Coefficient(ha);
        self
    }
}

/// Input of a spur gear pair.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PairSpec {
    /// Module `m` \[m\].
    pub module: f64,
    /// Reference (generating) pressure angle `α` \[rad\].
    pub pressure_angle: f64,
    /// Pinion (gear 1, external, `z1 > 0`).
    pub pinion: GearSpec,
    /// Gear 2: external (`z2 > 0`) or internal ring (`z2 < 0`, `|z2| > z1`).
    pub gear: GearSpec,
    /// Operating centre distance magnitude \[m\]; `None` = the zero-backlash working centre
    /// distance from the profile shifts.
    pub centre_distance: Option<f64>,
    /// Minimum `|z2| − z1` of an internal pair \[-\]; 10 per AGMA 917-B97 as quoted by Nunes 2017
    /// (§2.8, L1666) against tip fouling.
    pub min_teeth_difference: u32,
}

impl PairSpec {
    /// A pair of ISO 53 gears (`ha* = 1`, `hf* = 1.25`) with shifts `x1`, `x2`, at the
    /// zero-backlash working centre distance.
    pub fn standard(module: f64, z1: i32, z2: i32, pressure_angle: f64, x1: f64, x2: f64) -> Self {
        Self {
            module,
            pressure_angle,
            pinion: GearSpec::standard(z1, x1),
            gear: GearSpec::standard(z2, x2),
            centre_distance: None,
            min_teeth_difference: 10,
        }
    }
}

/// Diameters of one gear, all magnitudes \[m\] (ISO 21771 signed values are negative for an
/// internal gear).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Diameters {
    /// Reference diameter `|d| = m |z|` \[m\].
    pub reference: f64,
    /// Base diameter `|db| = |d| cos α` \[m\].
    pub base: f64,
    /// Tip diameter `|da|` \[m\] (inner circle of an internal gear).
    pub tip: f64,
    /// Root diameter `|df|` \[m\] (outer circle of an internal gear).
    pub root: f64,
    /// Operating pitch diameter `|dw| = |db| / cos α_op` \[m\].
    pub working: f64,
}

/// A validated spur gear pair with its derived ISO 21771 geometry.
#[derive(Debug, Clone, PartialEq)]
pub struct GearPair {
    /// The input.
    pub spec: PairSpec,
    /// `true` for an internal pair (`z2 < 0`).
    pub internal: bool,
    /// Gear ratio `u = |z2| / z1` \[-\].
    pub ratio: f64,
    /// Pinion diameters.
    pub pinion: Diameters,
    /// Gear (or ring) diameters.
    pub gear: Diameters,
    /// Working pressure angle for zero backlash, `inv αw = inv α + 2 tan α (x1+x2)/(z1+z2)`
    /// (ISO 21771 eq. for the working transverse pressure angle) \[rad\].
    pub working_pressure_angle: f64,
    /// Zero-backlash working centre distance magnitude
    /// `|aw| = |m (z1+z2)/2 · cos α / cos αw|` \[m\].
    pub working_centre_distance: f64,
    /// Operating centre distance magnitude \[m\] (= given, or `working_centre_distance`).
    pub centre_distance: f64,
    /// Operating pressure angle `cos α_op = |a0| cos α / |a|` \[rad\] (= `working_pressure_angle`
    /// when no centre distance is given).
    pub operating_pressure_angle: f64,
    /// Transverse base pitch `pb = π m cos α` \[m\].
    pub base_pitch: f64,
    /// Length of path of contact `gα = ½[√(da1²−db1²) ± √(da2²−db2²)] − |a| sin α_op`
    /// (ISO 21771, `+` external, `−` internal) \[m\]. A tip circle inside its base circle counts
    /// as ending on the base circle (see [`checks::CheckKind::RingTipInsideBaseCircle`]).
    pub path_of_contact: f64,
    /// Transverse contact ratio `εα = gα / pb` \[-\].
    pub contact_ratio: f64,
    /// Circumferential backlash on the operating pitch circle (ISO 21771 tooth thickness
    /// transferred to `dw`): `jt = π dw1/z1 − sw1 − sw2` \[m\]; negative = the teeth jam.
    pub backlash_circumferential: f64,
    /// Normal backlash `jn = jt cos α_op` \[m\].
    pub backlash_normal: f64,
}

/// Checks a pair's input field by field, in the order [`GearPair::new`] reports the first
/// failure.
fn check_input(spec: &PairSpec) -> Result<(), GearError> {
    let m = spec.module;
    positive("module", m)?;
    let alpha = spec.pressure_angle;
    require(
        alpha.is_finite() && alpha > 0.0 && alpha < 45f64.to_radians(),
        "pressure_angle",
        "must lie in (0, 45°) [rad]",
        alpha,
    )?;
    let z1 = spec.pinion.teeth;
    let z2 = spec.gear.teeth;
    require(
        z1 >= 3,
        "pinion.teeth",
        "must be >= 3 (external pinion)",
        z1 as f64,
    )?;
    require(
        z2 != 0,
        "gear.teeth",
        "must be non-zero (negative = internal)",
        0.0,
    )?;
    let internal = z2 < 0;
    if internal {
        require(
            -z2 > z1,
            "gear.teeth",
            "an internal gear needs more teeth than the pinion (|z2| > z1)",
            z2 as f64,
        )?;
    } else {
        require(z2 >= 3, "gear.teeth", "must be >= 3", z2 as f64)?;
    }
    for (name_x, name_hf, name_j, g) in [
        (
            "pinion.shift",
            "pinion.dedendum_coefficient",
            "pinion.thickness_allowance",
            &spec.pinion,
        ),
        (
            "gear.shift",
            "gear.dedendum_coefficient",
            "gear.thickness_allowance",
            &spec.gear,
        ),
    ] {
        finite(name_x, g.shift)?;
        require(g.shift.abs() <= 3.0, name_x, "|x| must be <= 3", g.shift)?;
        non_negative(name_hf, g.dedendum_coefficient)?;
        non_negative(name_j, g.thickness_allowance)?;
        match g.tip {
            Tip::Coefficient(ha) => {
                require(
                    ha.is_finite() && (0.0..=3.0).contains(&ha),
                    "tip addendum coefficient",
                    "must lie in [0, 3]",
                    ha,
                )?;
            }
            Tip::Diameter(da) => positive("tip diameter", da)?,
        }
    }
    Ok(())
}

impl GearPair {
    /// Validates the input and computes the ISO 21771 geometry. Never panics; invalid input
    /// returns [`GearError::InvalidInput`] naming the field, the rule and the value.
    pub fn new(spec: PairSpec) -> Result<Self, GearError> {
        check_input(&spec)?;
        let m = spec.module;
        let alpha = spec.pressure_angle;
        let (z1, z2) = (spec.pinion.teeth, spec.gear.teeth);
        let internal = z2 < 0;
        let (zf1, zf2) = (z1 as f64, z2 as f64);
        let ca = alpha.cos();
        // Signed ISO 21771 diameters.
        let d1 = m * zf1;
        let d2 = m * zf2;
        let db1 = d1 * ca;
        let db2 = d2 * ca;
        let [da1, df1, da2, df2] = tips_and_roots(&spec, d1, d2)?;

        let (aw_angle, a_w, a_op, alpha_op) = operating_mesh(&spec)?;
        let dw1 = db1 / alpha_op.cos();
        let dw2 = db2 / alpha_op.cos();

        tip_to_root_clearance(&spec, internal, [da1, df1, da2, df2], a_op)?;

        // Path of contact (ISO 21771); a tip inside its base circle ends contact at the base.
        let half_root = |da: f64, db: f64| 0.5 * (da * da - db * db).max(0.0).sqrt();
        let g_alpha =
            half_root(da1, db1) + z2.signum() as f64 * half_root(da2, db2) - a_op * alpha_op.sin();
        let pb = PI * m * ca;
        let eps = g_alpha / pb;

        let jt = circumferential_backlash(&spec, [d1, d2], [dw1, dw2], alpha_op)?;

        let diam = |d: f64, db: f64, da: f64, df: f64, dw: f64| Diameters {
            reference: d.abs(),
            base: db.abs(),
            tip: da.abs(),
            root: df.abs(),
            working: dw.abs(),
        };
        Ok(Self {
            spec,
            internal,
            ratio: zf2.abs() / zf1,
            pinion: diam(d1, db1, da1, df1, dw1),
            gear: diam(d2, db2, da2, df2, dw2),
            working_pressure_angle: aw_angle,
            working_centre_distance: a_w.abs(),
            centre_distance: a_op.abs(),
            operating_pressure_angle: alpha_op,
            base_pitch: pb,
            path_of_contact: g_alpha,
            contact_ratio: eps,
            backlash_circumferential: jt,
            backlash_normal: jt * alpha_op.cos(),
        })
    }

    /// Pressure angle at the tip of the pinion, `cos αa1 = db1/da1` \[rad\].
    pub fn pinion_tip_pressure_angle(&self) -> f64 {
        tip_angle(self.pinion.base, self.pinion.tip)
    }

    /// Pressure angle at the tip of gear 2, `cos αa2 = |db2|/|da2|` \[rad\]; 0 when the tip
    /// circle lies inside the base circle.
    pub fn gear_tip_pressure_angle(&self) -> f64 {
        tip_angle(self.gear.base, self.gear.tip)
    }

    /// Largest addendum of gear 2 (from its reference circle) for which its tip contact
    /// point does not pass the pinion interference point T1 \[m\]: the tip radius is then
    /// `√(rb2² + (a sin α_op)²)` (internal) or `√(rb2² + (a sin α_op)²)` measured outward
    /// (external). Derived from the KHK criterion by setting its margin to zero.
    pub fn max_gear_addendum_without_interference(&self) -> f64 {
        let rb2 = self.gear.base / 2.0;
        let l = self.centre_distance * self.operating_pressure_angle.sin();
        let r_lim = (rb2 * rb2 + l * l).sqrt();
        let r2 = self.gear.reference / 2.0;
        if self.internal {
            r2 - r_lim
        } else {
            r_lim - r2
        }
    }

    /// Addendum of gear 2 from its reference circle, `| |d2| − |da2| | / 2` \[m\].
    pub fn gear_addendum(&self) -> f64 {
        (self.gear.reference - self.gear.tip).abs() / 2.0
    }

    /// KHK trochoid-interference ratio `θ2/θ1` of an internal pair (to be ≤ z1/|z2|):
    /// `θ1 = acos((ra2² − ra1² − a²)/(2 a ra1)) + inv αa1 − inv α_op`,
    /// `θ2 = acos((ra2² − ra1² + a²)/(2 a ra2)) + inv αa2 − inv α_op`
    /// (KHK Gear Technical Reference, internal gear interference, eq. for θ1, θ2).
    /// Returns 0 when the tip circles do not intersect (no tip crossing is possible) and
    /// `NaN` for an external pair.
    pub fn trochoid_ratio(&self) -> f64 {
        if !self.internal {
            return f64::NAN;
        }
        let ra1 = self.pinion.tip / 2.0;
        let ra2 = self.gear.tip / 2.0;
        let a = self.centre_distance;
        if ra2 >= ra1 + a {
            return 0.0;
        }
        let inv_w = inv(self.operating_pressure_angle);
        let c1 = ((ra2 * ra2 - ra1 * ra1 - a * a) / (2.0 * a * ra1)).clamp(-1.0, 1.0);
        let c2 = ((ra2 * ra2 - ra1 * ra1 + a * a) / (2.0 * a * ra2)).clamp(-1.0, 1.0);
        let th1 = c1.acos() + inv(self.pinion_tip_pressure_angle()) - inv_w;
        let th2 = c2.acos() + inv(self.gear_tip_pressure_angle()) - inv_w;
        th2 / th1
    }
}

/// The rounding allowance of a check's margin and of the tip-to-root clearance (in modules):
/// a zero-backlash pair computes jt ≈ ±1e-17 m.
const ROUNDING: f64 = 1e-12;

fn tip_angle(base: f64, tip: f64) -> f64 {
    if tip <= base {
        0.0
    } else {
        (base / tip).acos()
    }
}

/// The fastest pitch-line velocity a steel gear can run at, 500 m/s \[m/s\]: a thin ring
/// spinning at rim speed v carries the hoop stress σ = ρ v² (the rotating ring, e.g.
/// Timoshenko, Strength of Materials I, the stress of a rotating ring), so a steel rim
/// (ρ = 7850 kg/m³) at 500 m/s carries 1.96 GPa, the ultimate strength of the strongest
/// carburized gear steels: beyond it the rim bursts whatever the teeth carry. (The fastest
/// turbine gear units run below 200 m/s.)
pub const MAX_PITCH_LINE_VELOCITY: f64 = 500.0;

/// Refuses a pitch-line velocity `v` (m/s) that no gear pair can run at: not finite, negative,
/// or above [`MAX_PITCH_LINE_VELOCITY`]. The one check of a pair's speed, for the gear file
/// of `cardan gear` and any rating.
pub fn check_pitch_line_velocity(v: f64) -> Result<(), GearError> {
    require(
        v.is_finite() && (0.0..=MAX_PITCH_LINE_VELOCITY).contains(&v),
        "pitch-line velocity",
        "must be at most 500 m/s: a steel rim bursts beyond it (hoop stress ρ v² of a rotating ring, 1.96 GPa at 500 m/s)",
        v,
    )
}

/// Module of the cardan gear from the cardan crank length `e` (= the pinion's pitch radius,
/// so `d1 = 2 e`) and the pinion teeth: `m = 2 e / z1` \[m\]. Karhula 2008, A9.1.37, writes it
/// `m_c = Z_AA0 / z1` with `Z_AA0 = 2 Z_AA0c` the equal-stroke slider-crank crank length
/// (A8.1.1–A8.1.4: `r1c = Z_AA0c`, `d1c = Z_AA0`).
pub fn cardan_module(cardan_crank_length: f64, z1: u32) -> Result<f64, GearError> {
    positive("cardan_crank_length", cardan_crank_length)?;
    require(z1 >= 3, "z1", "must be >= 3", z1 as f64)?;
    Ok(2.0 * cardan_crank_length / z1 as f64)
}

/// Karhula's length of path of contact of the internal cardan pair, as printed
/// (Karhula 2008, A9.1.40; full addenda `1·m`, no shift):
/// `L = ½√((d1+2m)² − (d1 cos α)²) − ½√((d2−2m)² − (d2 cos α)²) + (d2 − d1)/2 · sin α` \[m\].
/// `d1`, `d2` pitch diameters (magnitudes) \[m\], `m` module \[m\], `alpha` \[rad\].
pub fn karhula_path_of_contact(d1: f64, d2: f64, m: f64, alpha: f64) -> f64 {
    let (c, s) = (alpha.cos(), alpha.sin());
    0.5 * ((d1 + 2.0 * m).powi(2) - (d1 * c).powi(2)).sqrt()
        - 0.5 * ((d2 - 2.0 * m).powi(2) - (d2 * c).powi(2)).sqrt()
        + 0.5 * (d2 - d1) * s
}

/// Karhula's contact ratio, as printed (Karhula 2008, A9.1.52):
/// `CR = 39.37 · L · (25.4 / m[mm]) / (π cos α)`, `L` and `m` in metres here.
/// (39.37 ≈ 1/0.0254 so this is `L/(π m cos α)` to 6 digits.)
pub fn karhula_contact_ratio(path_of_contact: f64, m: f64, alpha: f64) -> f64 {
    39.37 * path_of_contact * (25.4 / (m * 1e3)) / (PI * alpha.cos())
}

/// The tip and root diameters [da1, df1, da2, df2] of the pair's members at their signed
/// reference diameters `d1`, `d2` (ISO 21771: `da = d + 2 m (ha* + x)` or the given tip,
/// `df = d − 2 m (hf* − x)`), checked: each tip beyond its root, a ring's tip circle inside its
/// root circle and around the pinion's tip circle.
fn tips_and_roots(spec: &PairSpec, d1: f64, d2: f64) -> Result<[f64; 4], GearError> {
    let m = spec.module;
    let (x1, x2) = (spec.pinion.shift, spec.gear.shift);
    let internal = spec.gear.teeth < 0;
    let tip = |g: &GearSpec, d: f64| match g.tip {
        Tip::Coefficient(ha) => d + 2.0 * m * (ha + g.shift),
        Tip::Diameter(da) => da * d.signum(),
    };
    let da1 = tip(&spec.pinion, d1);
    let da2 = tip(&spec.gear, d2);
    let df1 = d1 - 2.0 * m * (spec.pinion.dedendum_coefficient - x1);
    let df2 = d2 - 2.0 * m * (spec.gear.dedendum_coefficient - x2);
    require(
        da1 > df1 && da1 > 0.0,
        "pinion tip",
        "pinion tip diameter must exceed its root diameter",
        da1,
    )?;
    if internal {
        // Signed: the ring tip circle (magnitude) must be smaller than its root circle.
        require(
            da2 < 0.0 && da2 > df2,
            "gear tip",
            "ring tip circle must lie inside its root circle",
            da2.abs(),
        )?;
        require(
            da2.abs() > da1,
            "gear tip",
            "ring tip circle must be larger than the pinion tip circle",
            da2.abs(),
        )?;
    } else {
        require(
            da2 > df2,
            "gear tip",
            "tip diameter must exceed root diameter",
            da2,
        )?;
    }
    Ok([da1, df1, da2, df2])
}

/// The working pressure angle and centre distance (ISO 21771: `inv αw = inv α + 2 tan α
/// (x1 + x2)/(z1 + z2)`, `aw = a0 cos α / cos αw`) and the operating ones, at the given centre
/// distance if any: (αw rad, aw m signed, a_op m signed, α_op rad).
fn operating_mesh(spec: &PairSpec) -> Result<(f64, f64, f64, f64), GearError> {
    let (m, alpha) = (spec.module, spec.pressure_angle);
    let (zf1, zf2) = (spec.pinion.teeth as f64, spec.gear.teeth as f64);
    let (x1, x2) = (spec.pinion.shift, spec.gear.shift);
    let (ca, ta) = (alpha.cos(), alpha.tan());
    let inv_aw = inv(alpha) + 2.0 * ta * (x1 + x2) / (zf1 + zf2);
    let aw_angle = inv_inverse(inv_aw).map_err(|_| GearError::InvalidInput {
        field: "shift",
        rule: "the sum of shifts gives no working pressure angle in (0, 80°)",
        value: x1 + x2,
    })?;
    let a0 = m * (zf1 + zf2) / 2.0;
    let a_w = a0 * ca / aw_angle.cos();
    let (a_op, alpha_op) = match spec.centre_distance {
        None => (a_w, aw_angle),
        Some(a) => {
            positive("centre_distance", a)?;
            let c = a0.abs() * ca / a;
            require(
                c < 1.0,
                "centre_distance",
                "must exceed |a0| cos α (else no operating pressure angle)",
                a,
            )?;
            (a * a0.signum(), c.acos())
        }
    };
    Ok((aw_angle, a_w, a_op, alpha_op))
}

/// The circumferential backlash on the operating pitch circle, m: the ISO 21771 tooth
/// thickness at the reference circle, less its allowance, transferred to the working
/// diameters `dw` (`d`: the signed reference diameters).
fn circumferential_backlash(
    spec: &PairSpec,
    [d1, d2]: [f64; 2],
    [dw1, dw2]: [f64; 2],
    alpha_op: f64,
) -> Result<f64, GearError> {
    let (m, alpha) = (spec.module, spec.pressure_angle);
    let ta = alpha.tan();
    let zf1 = spec.pinion.teeth as f64;
    // Backlash: ISO tooth thickness transferred to the operating pitch circle.
    let s = |g: &GearSpec| m * (PI / 2.0 + 2.0 * g.shift * ta) - g.thickness_allowance;
    // A tooth thinned by more than its thickness at the reference circle,
    // s = m (π/2 + 2 x tan α) (ISO 21771), is no tooth: its "backlash" would exceed the pitch.
    for (field, g) in [
        ("pinion.thickness_allowance", &spec.pinion),
        ("gear.thickness_allowance", &spec.gear),
    ] {
        require(
            s(g) > 0.0,
            field,
            "must be less than the tooth's thickness at the reference circle, m (π/2 + 2 x tan α): the tooth would be thinned away",
            g.thickness_allowance,
        )?;
    }
    let sw1 = dw1 * (s(&spec.pinion) / d1 + inv(alpha) - inv(alpha_op));
    let sw2 = dw2 * (s(&spec.gear) / d2 + inv(alpha) - inv(alpha_op));
    let jt = PI * dw1 / zf1 - sw1 - sw2;
    Ok(jt)
}

/// Tip-to-root clearance at the operating centre distance: each member's tip circle
/// must stay outside the mate's root circle, c ≥ 0 (ISO 21771's bottom clearance,
/// c = a − ra1 − rf2 for an external pair; for an internal one, in magnitudes, the
/// pinion tip reaches a + ra1 from the ring's axis, inside its root rf2, and the ring
/// tip ra2 must stay beyond a + rf1). A negative c is a tooth that hits the mate's
/// root: no pair, whatever the other checks say.
/// (`diameters`: the pinion's tip and root, the gear's tip and root, signed as ISO 21771's;
/// `a_op`: the operating centre distance, signed.)
fn tip_to_root_clearance(
    spec: &PairSpec,
    internal: bool,
    [da1, df1, da2, df2]: [f64; 4],
    a_op: f64,
) -> Result<(), GearError> {
    let m = spec.module;
    let (ra1, rf1, ra2, rf2, a) = (
        da1 / 2.0,
        df1 / 2.0,
        da2.abs() / 2.0,
        df2.abs() / 2.0,
        a_op.abs(),
    );
    let (c_pinion_tip, c_gear_tip) = if internal {
        (rf2 - a - ra1, ra2 - a - rf1)
    } else {
        (a - ra1 - rf2, a - ra2 - rf1)
    };
    require(
        c_pinion_tip >= -ROUNDING * m,
        "gear.dedendum_coefficient",
        "the pinion's tip circle reaches into the gear's root circle (tip-to-root clearance below 0): deepen the gear's dedendum or shorten the pinion's addendum",
        spec.gear.dedendum_coefficient,
    )?;
    require(
        c_gear_tip >= -ROUNDING * m,
        "pinion.dedendum_coefficient",
        "the gear's tip circle reaches into the pinion's root circle (tip-to-root clearance below 0): deepen the pinion's dedendum or shorten the gear's addendum",
        spec.pinion.dedendum_coefficient,
    )?;
    Ok(())
}

pub mod checks;

#[cfg(test)]
mod tests;
