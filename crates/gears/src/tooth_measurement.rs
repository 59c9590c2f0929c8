//! Tooth thickness measurements of a spur gear (ISO 21771:2007 §6.3 and §6.4, the same
//! relations as KHK's *Gear Technical Reference*, tooth thickness): the span width `W_k`
//! over `k` teeth of an external gear, and the dimension over two pins or balls `M_d` of an
//! external gear, or between them for an internal gear. For spur gears balls and pins give
//! the same dimension.
//!
//! The tooth thickness at the reference circle is ISO 21771's `s = m (π/2 + 2 x tan α)`
//! less the circumferential thinning `j` the file states (`thickness_allowance`); an
//! internal gear's space width is `e = π m − s`. Conventions of [`crate::geometry`]: `x`
//! with ISO signs, teeth counts as magnitudes here, lengths in metres, angles in radians.

use std::f64::consts::PI;

use crate::error::{positive, require, GearError};
use crate::involute::{inv, inv_inverse};

/// One gear for a measurement.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MeasuredGear {
    /// Module `m` \[m\].
    pub module: f64,
    /// Reference pressure angle `α` \[rad\].
    pub pressure_angle: f64,
    /// Number of teeth `|z|` \[-\].
    pub teeth: u32,
    /// Profile shift `x` (ISO 21771 sign) \[-\].
    pub shift: f64,
    /// Circumferential thinning of the teeth at the reference circle \[m\] (≥ 0).
    pub thinning: f64,
    /// `true` for an internal gear (ring).
    pub internal: bool,
}

impl MeasuredGear {
    fn check(&self) -> Result<(), GearError> {
        positive("module", self.module)?;
        require(
            self.pressure_angle.is_finite()
                && self.pressure_angle > 0.0
                && self.pressure_angle < PI / 4.0,
            "pressure_angle",
            "must lie in (0, 45°)",
            self.pressure_angle,
        )?;
        require(self.teeth >= 3, "teeth", "must be >= 3", self.teeth as f64)?;
        require(
            self.thinning.is_finite() && self.thinning >= 0.0,
            "thickness_allowance",
            "must be >= 0",
            self.thinning,
        )?;
        require(
            self.tooth_thickness() > 0.0 && self.tooth_thickness() < PI * self.module,
            "thickness_allowance",
            "leaves no tooth (or no space) at the reference circle",
            self.thinning,
        )
    }

    /// Reference diameter `d = m z` \[m\].
    pub fn reference_diameter(&self) -> f64 {
        self.module * self.teeth as f64
    }

    /// Base diameter `d_b = d cos α` \[m\].
    pub fn base_diameter(&self) -> f64 {
        self.reference_diameter() * self.pressure_angle.cos()
    }

    /// Tooth thickness at the reference circle `s = m (π/2 + 2 x tan α) − j` \[m\]
    /// (ISO 21771:2007 §5.4 for both external and internal gears).
    pub fn tooth_thickness(&self) -> f64 {
        self.module * (PI / 2.0 + 2.0 * self.shift * self.pressure_angle.tan()) - self.thinning
    }

    /// Half the angular width of the space the pin sits in, seen from the axis, at the
    /// reference circle, `e/d` \[rad\].
    fn space_half_angle(&self) -> f64 {
        (PI * self.module - self.tooth_thickness()) / self.reference_diameter()
    }
}

/// A span measurement over `k` teeth.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Span {
    /// Number of teeth spanned `k`.
    pub teeth: u32,
    /// Span width `W_k` \[m\].
    pub width: f64,
    /// Diameter at which the anvils touch the flanks, `√(d_b² + W_k²)` \[m\].
    pub contact_diameter: f64,
}

/// Span width over `k` teeth of an external gear, `W_k = (k − 1) p_b + s_b` with
/// `p_b = π m cos α` and `s_b = cos α (s + m z inv α)` (ISO 21771:2007 §6.3), i.e.
/// `W_k = m cos α [π (k − 0.5) + z inv α] + 2 x m sin α − j cos α`; the anvils touch the
/// flanks on the diameter `√(d_b² + W_k²)`.
pub fn span_width(g: &MeasuredGear, k: u32) -> Result<Span, GearError> {
    g.check()?;
    require(
        !g.internal,
        "teeth",
        "a span measurement needs an external gear (measure a ring over pins)",
        g.teeth as f64,
    )?;
    require(
        k >= 1 && k < g.teeth,
        "span teeth k",
        "must lie in [1, z − 1]",
        k as f64,
    )?;
    let (m, a) = (g.module, g.pressure_angle);
    let s_b = a.cos() * (g.tooth_thickness() + m * g.teeth as f64 * inv(a));
    let w = (k as f64 - 1.0) * PI * m * a.cos() + s_b;
    let db = g.base_diameter();
    Ok(Span {
        teeth: k,
        width: w,
        contact_diameter: (db * db + w * w).sqrt(),
    })
}

/// The span that touches the flanks nearest the diameter `d + 2 x m` (the middle of the
/// working profile, where ISO 21771 §6.3 and KHK place the measurement): `k` is the
/// whole number nearest `(√((d + 2xm)² − d_b²) − s_b)/p_b + 1`, within `[1, z − 1]`.
pub fn span_width_auto(g: &MeasuredGear) -> Result<Span, GearError> {
    g.check()?;
    let (m, a) = (g.module, g.pressure_angle);
    let db = g.base_diameter();
    let target = g.reference_diameter() + 2.0 * g.shift * m;
    let w_star = (target * target - db * db).max(0.0).sqrt();
    let s_b = a.cos() * (g.tooth_thickness() + m * g.teeth as f64 * inv(a));
    let k = ((w_star - s_b) / (PI * m * a.cos()) + 1.0).round();
    let k = k.clamp(1.0, (g.teeth - 1) as f64) as u32;
    span_width(g, k)
}

/// A measurement over (external) or between (internal) two pins or balls.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct OverPins {
    /// Pin or ball diameter `D_M` \[m\].
    pub pin_diameter: f64,
    /// Dimension over (external) or between (internal) the pins `M_d` \[m\].
    pub dimension: f64,
    /// Diameter of the circle through the pin centres \[m\].
    pub centre_diameter: f64,
    /// Pressure angle at the pin centre `α_M` \[rad\].
    pub centre_pressure_angle: f64,
}

/// Dimension over two pins or balls of diameter `pin` \[m\] (ISO 21771:2007 §6.4; KHK):
/// the pin centre lies at `d_M = d_b / cos α_M` with, for an external gear,
/// `inv α_M = inv α + D_M/d_b − e/d` and, for an internal gear,
/// `inv α_M = inv α + e/d − D_M/d_b` (`e = π m − s` the space width at the reference
/// circle); `M_d = d_M + D_M` (external) or `d_M − D_M` (internal) for an even number of
/// teeth, with `d_M cos(90°/z)` in place of `d_M` for an odd number.
pub fn over_pins(g: &MeasuredGear, pin: f64) -> Result<OverPins, GearError> {
    g.check()?;
    positive("pin diameter", pin)?;
    let a = g.pressure_angle;
    let db = g.base_diameter();
    let e_d = g.space_half_angle();
    let inv_m = if g.internal {
        inv(a) + e_d - pin / db
    } else {
        inv(a) + pin / db - e_d
    };
    require(
        inv_m > 0.0,
        "pin diameter",
        "is too small (external) or too large (internal): the pin does not reach the involute flanks",
        pin,
    )?;
    let a_m = inv_inverse(inv_m)?;
    let d_m = db / a_m.cos();
    let z = g.teeth;
    let reach = if z % 2 == 0 {
        d_m
    } else {
        d_m * (PI / (2.0 * z as f64)).cos()
    };
    let dimension = if g.internal { reach - pin } else { reach + pin };
    require(
        dimension > 0.0,
        "pin diameter",
        "is too large for this internal gear: the pins overlap",
        pin,
    )?;
    Ok(OverPins {
        pin_diameter: pin,
        dimension,
        centre_diameter: d_m,
        centre_pressure_angle: a_m,
    })
}

/// The pin diameter that touches the flanks on the diameter `d + 2 x m` \[m\]: with the
/// contact pressure angle `α_c` (`cos α_c = d_b/(d + 2xm)`), the pin centre angle is
/// `α_M = tan α_c − inv α + e/d` (external) or `tan α_c − inv α − e/d` (internal) and
/// `D_M = d_b |tan α_M − tan α_c|` (the pin's radius lies along the flank normal, tangent
/// to the base circle). For an unshifted external gear this is the familiar
/// `D_M ≈ 1.728 m` of z ≈ 20.
pub fn ideal_pin_diameter(g: &MeasuredGear) -> Result<f64, GearError> {
    g.check()?;
    let a = g.pressure_angle;
    let db = g.base_diameter();
    let dc = g.reference_diameter() + 2.0 * g.shift * g.module;
    require(
        dc > db,
        "profile_shift",
        "puts d + 2xm inside the base circle",
        g.shift,
    )?;
    let a_c = (db / dc).acos();
    let e_d = g.space_half_angle();
    let a_m = if g.internal {
        a_c.tan() - inv(a) - e_d
    } else {
        a_c.tan() - inv(a) + e_d
    };
    Ok(db * (a_m.tan() - a_c.tan()).abs())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn gear(z: u32, x: f64, internal: bool) -> MeasuredGear {
        MeasuredGear {
            module: 2e-3,
            pressure_angle: 20f64.to_radians(),
            teeth: z,
            shift: x,
            thinning: 0.0,
            internal,
        }
    }

    /// Smallest distance from `centre` (polar radius `rc` on the space centreline, angle 0)
    /// to the involute flank bounding the space, sampled finely along the flank.
    fn distance_to_flank(g: &MeasuredGear, rc: f64) -> f64 {
        let rb = g.base_diameter() / 2.0;
        let e_d = g.space_half_angle();
        let a = g.pressure_angle;
        let mut best = f64::INFINITY;
        for i in 0..200_000 {
            // Radii from the base circle to 1.6 × the reference radius.
            let r = rb * (1.0 + 0.7 * i as f64 / 200_000.0);
            let ar = (rb / r).acos();
            // Angle of the flank from the space centreline (ISO tooth/space geometry).
            let th = if g.internal {
                e_d + inv(a) - inv(ar)
            } else {
                e_d - inv(a) + inv(ar)
            };
            let (x, y) = (r * th.cos() - rc, r * th.sin());
            best = best.min((x * x + y * y).sqrt());
        }
        best
    }

    #[test]
    fn pins_touch_the_flanks() {
        // Paper-free check of the over-pin relations: the pin circle of radius D/2 about the
        // computed centre is tangent to the involute flank (sampled), for external and
        // internal gears, shifted and thinned. Sampling step ~3e-8 m: tolerance 1e-7 m.
        for (z, x, internal, j) in [
            (20, 0.0, false, 0.0),
            (17, 0.3, false, 0.05e-3),
            (40, 0.0, true, 0.0),
            (41, -0.2, true, 0.04e-3),
        ] {
            let mut g = gear(z, x, internal);
            g.thinning = j;
            let pin = ideal_pin_diameter(&g).unwrap();
            let p = over_pins(&g, pin).unwrap();
            let d = distance_to_flank(&g, p.centre_diameter / 2.0);
            assert!((d - pin / 2.0).abs() < 1e-7, "z {z}: {d} vs {}", pin / 2.0);
        }
    }
}
