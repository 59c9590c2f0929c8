//! AGMA 908-B89's bending strength geometry factor `J` of an external spur gear, computed from
//! the tooth form; for the internal ring of a cardan pair, `J` from ISO 6336-3 method B.
//!
//! # External gears: AGMA 908-B89 §5 (spur: `C_ψ = 1`, `m_N = 1`, `K_ψ = 1`, `C_h = 1`)
//!
//! * The fillet is the trochoid the generating rack's tip radius leaves
//!   ([`crate::tooth_root`], the same generation as ISO 6336-3 reads).
//! * The load acts at the highest point of single tooth contact (HPSTC), along the line of
//!   action; it cuts the tooth centre line at the radius `r_b / cos φ_L`, where the load angle
//!   `φ_L = φ_W − ψ_L` is the pressure angle at the load point less the half angular tooth
//!   thickness there, `ψ_L = (π/2 + 2 x_E tan φ)/z + inv φ − inv φ_W` (§5, the load angle).
//! * The critical section is where the Lewis parabola with its vertex at that point is tangent
//!   to the fillet: the fillet point with the largest `h_F / s_F²` (the parabola
//!   `(s/2)² ∝ h` inscribed in the fillet touches it where `s²/h` is smallest), `h_F` its
//!   height below the vertex, `s_F` the chord.
//! * Tooth form factor (§5, eq. for `Y`, lengths in modules):
//!   `Y = 1 / [ (cos φ_L / cos φ_r) (6 h_F / s_F² − tan φ_L / s_F) ]`, `φ_r` the operating
//!   pressure angle (the tangential load `W_t` is taken at the operating pitch circle).
//! * Stress correction factor (§5, Dolan & Broghamer):
//!   `K_f = H + (s_F/ρ_F)^L (s_F/h_F)^M`, `H = 0.331 − 0.436 φ`, `L = 0.324 − 0.492 φ`,
//!   `M = 0.261 + 0.545 φ` (`φ` the generating pressure angle in radians), `ρ_F` the
//!   smallest radius of curvature of the generated fillet, at the root circle (for a rack,
//!   `ρ_F = r_T + (b − r_T)² / (r + b − r_T)`, `b − r_T` the depth of the tool-tip centre below
//!   the rolling line; the classical form of AGMA 908's and Dolan & Broghamer's fillet radius,
//!   taken here from the generation itself and checked against that form in the tests). With
//!   the radius of curvature at the Lewis point instead, `J` comes out 0.01–0.03 above every
//!   AGMA 908 table value tried; with the root radius it meets them to ±0.01.
//! * `J = Y C_ψ / (K_f m_N) = Y / K_f`.
//!
//! # Internal gears: ISO 6336-3 method B
//!
//! AGMA 908-B89 has no method for internal teeth (its scope is external spur and helical
//! gears; its tables hold none). ISO 6336-3 method B treats them (the rack substitute of
//! [`crate::tooth_root`]). Its `Y_F`, `Y_S` become a `J` through the nominal root stress both
//! standards write: AGMA 2001-D04 eq. 15 `σ = W_t / (b m J)` (the K factors aside) and ISO
//! 6336-3:2006 eq. (3) `σ_F0 = F_t Y_F Y_S / (b m)` (`Y_β = Y_B = Y_DT = 1`, spur), with
//! `F_t = W_t d_w / d` (ISO's load at the reference circle, AGMA's at the operating pitch
//! circle): `J = d / (d_w Y_F Y_S)`. [`iso_j`] gives this for either member.

use std::f64::consts::PI;

use crate::error::{require, GearError};
use crate::geometry::GearPair;
use crate::tooth_root::{
    fillet_curvature_radius, fillet_point, fillet_range, generation, iso6336_method_b,
    GeneratedMember, PairMember, RootFactors,
};

/// How a `J` was obtained.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum JMethod {
    /// AGMA 908-B89 §5 (external gears).
    Agma908,
    /// ISO 6336-3 method B's `Y_F Y_S` turned into `J` (internal gears).
    Iso6336MethodB,
}

impl JMethod {
    /// The method's name for reports.
    pub fn name(self) -> &'static str {
        match self {
            JMethod::Agma908 => "AGMA 908-B89 (Lewis parabola in the generated fillet, load at HPSTC)",
            JMethod::Iso6336MethodB => {
                "ISO 6336-3 method B (Y_F, Y_S at the outer point of single contact; J = d/(d_w Y_F Y_S))"
            }
        }
    }
}

/// AGMA 908-B89 critical section and factors of one external member.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Agma908Section {
    /// Chord of the critical section `s_F` \[m\].
    pub chord: f64,
    /// Height of the Lewis parabola `h_F` (vertex to the critical section) \[m\].
    pub height: f64,
    /// Radius of curvature of the fillet at the critical point `ρ_F` \[m\].
    pub fillet_radius: f64,
    /// Load angle `φ_L` \[rad\].
    pub load_angle: f64,
    /// Radius of the load point (HPSTC) \[m\].
    pub load_radius: f64,
    /// Tooth form factor `Y` \[-\].
    pub form_factor: f64,
    /// Stress correction factor `K_f` \[-\].
    pub stress_correction: f64,
}

/// A bending geometry factor and how it was obtained.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BendingJ {
    /// `J` \[-\].
    pub j: f64,
    /// The method.
    pub method: JMethod,
    /// AGMA 908's section (external members).
    pub agma: Option<Agma908Section>,
    /// ISO 6336-3's factors (internal members).
    pub iso: Option<RootFactors>,
}

/// AGMA 908-B89 stress correction factor `K_f = H + (s_F/ρ_F)^L (s_F/h_F)^M` (module docs).
pub fn stress_correction_factor(
    pressure_angle: f64,
    chord: f64,
    height: f64,
    fillet_radius: f64,
) -> f64 {
    let p = pressure_angle;
    let (h, l, m) = (0.331 - 0.436 * p, 0.324 - 0.492 * p, 0.261 + 0.545 * p);
    h + (chord / fillet_radius).powf(l) * (chord / height).powf(m)
}

/// AGMA 908-B89 `J` of an external member (module docs). Errors for an internal gear (no
/// AGMA 908 method; see [`bending_geometry_factor`]).
pub fn agma908_section(
    pair: &GearPair,
    member: GeneratedMember,
) -> Result<Agma908Section, GearError> {
    require(
        !(pair.internal && member.which == PairMember::Gear),
        "gear.teeth",
        "AGMA 908-B89 has no J for internal teeth (use ISO 6336-3 method B)",
        pair.spec.gear.teeth as f64,
    )?;
    let g = generation(pair, member)?;
    let (lo, hi) = fillet_range(&g).ok_or(GearError::InvalidInput {
        field: "shift",
        rule: "the generating rack's tip centre lies outside the rolling line: the profile shift is too large for a rack-generated fillet",
        value: g.x_e,
    })?;
    // Load angle at the HPSTC.
    let a = g.alpha;
    let phi_w = (g.rb / g.r_load).acos();
    let psi = (PI / 2.0 + 2.0 * g.x_e * a.tan()) / g.z + crate::involute::inv(a)
        - crate::involute::inv(phi_w);
    let phi_l = phi_w - psi;
    let vertex = g.rb / phi_l.cos();
    // Lewis parabola: the fillet point of largest h/s² (s = 2x); a scan then golden section.
    let ratio = |phi: f64| {
        let (x, y) = fillet_point(&g, phi);
        (vertex - y) / (4.0 * x * x)
    };
    let n = 400;
    let step = (hi - lo) / n as f64;
    let best = (0..=n)
        .map(|k| lo + step * k as f64)
        .max_by(|p, q| ratio(*p).total_cmp(&ratio(*q)))
        .unwrap_or(lo);
    let (mut a0, mut b0) = ((best - step).max(lo), (best + step).min(hi));
    let gr = (5f64.sqrt() - 1.0) / 2.0;
    for _ in 0..80 {
        let c = b0 - gr * (b0 - a0);
        let d = a0 + gr * (b0 - a0);
        if ratio(c) > ratio(d) {
            b0 = d;
        } else {
            a0 = c;
        }
    }
    let phi = 0.5 * (a0 + b0);
    let (x, y) = fillet_point(&g, phi);
    let (chord, height) = (2.0 * x, vertex - y);
    // ρ_F: the fillet's smallest radius of curvature, at the root circle (module docs).
    let fillet_radius = fillet_curvature_radius(&g, lo, (hi - lo) * 1e-4);
    for (field, v) in [("s_F", chord), ("h_F", height), ("rho_F", fillet_radius)] {
        require(
            v.is_finite() && v > 0.0,
            field,
            "the AGMA 908 critical section is degenerate",
            v,
        )?;
    }
    let m = g.m;
    let (s, h) = (chord / m, height / m);
    let y_form = 1.0
        / ((phi_l.cos() / pair.operating_pressure_angle.cos())
            * (6.0 * h / (s * s) - phi_l.tan() / s));
    let kf = stress_correction_factor(a, chord, height, fillet_radius);
    Ok(Agma908Section {
        chord,
        height,
        fillet_radius,
        load_angle: phi_l,
        load_radius: g.r_load,
        form_factor: y_form,
        stress_correction: kf,
    })
}

/// `J = d / (d_w Y_F Y_S)` from ISO 6336-3 method B (module docs), either member.
pub fn iso_j(pair: &GearPair, member: GeneratedMember) -> Result<(f64, RootFactors), GearError> {
    let f = iso6336_method_b(pair, member)?;
    let d = match member.which {
        PairMember::Pinion => &pair.pinion,
        PairMember::Gear => &pair.gear,
    };
    Ok((
        d.reference / (d.working * f.form_factor * f.stress_correction),
        f,
    ))
}

/// The bending geometry factor `J` of one member: AGMA 908-B89 for an external member, ISO
/// 6336-3 method B for an internal ring (module docs).
pub fn bending_geometry_factor(
    pair: &GearPair,
    member: GeneratedMember,
) -> Result<BendingJ, GearError> {
    if pair.internal && member.which == PairMember::Gear {
        let (j, f) = iso_j(pair, member)?;
        Ok(BendingJ {
            j,
            method: JMethod::Iso6336MethodB,
            agma: None,
            iso: Some(f),
        })
    } else {
        let s = agma908_section(pair, member)?;
        Ok(BendingJ {
            j: s.form_factor / s.stress_correction,
            method: JMethod::Agma908,
            agma: Some(s),
            iso: None,
        })
    }
}
