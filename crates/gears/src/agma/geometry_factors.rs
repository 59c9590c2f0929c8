//! AGMA 908-B89 geometry factors: pitting resistance `I` (formula, external and internal) and
//! bending strength `J` (table store, external only).
//!
//! # I
//!
//! AGMA 908-B89 §4 (spur, `mN = 1`), load at the lowest point of single tooth contact (LPSTC):
//! `ρ1 = √(ra1² − rb1²) − pb`, `ρ2 = a sin φ ∓ ρ1`, `I = cos φ / ((1/ρ1 ± 1/ρ2) d)`,
//! upper sign external, lower sign internal, `d` the pinion operating pitch diameter, `φ` the
//! operating pressure angle. Shigley eq. 14-23 uses the pitch point instead:
//! `I = cos φ sin φ / 2 · mG/(mG ± 1)`. The LPSTC formula reproduces every external value of the
//! AGMA 908 tables reproduced in Nunes 2017 Annex A to ±0.0006 (`docs/validation/gears.md` §2.3);
//! for the internal 26/52 pair it gives 0.305 where Nunes interpolated the external table (0.1168).
//!
//! # J
//!
//! The full AGMA 908 J (Lewis parabola inscribed in the generated trochoid fillet, load at the
//! highest point of single tooth contact) is computed by [`crate::agma908`]. The tables here
//! are the AGMA 908-B89 tables as reproduced in Nunes 2017 Annex A.2–A.4 (φ = 25°, whole depth
//! 2.35, tool edge radius 0.27, tooth thinning 0.024, HPSTC, x = 0, ±0.25, ±0.5) with the
//! bilinear interpolation in tooth counts that Nunes used (which AGMA itself advises against):
//! the published values the computation is tested against, and Nunes's reading. AGMA 908 has
//! no J for internal gears; [`internal_j_conservative`] documents the proxy Nunes-style
//! readings use (a case file's default J is computed instead).

use crate::error::{require, GearError};
use crate::geometry::GearPair;

/// Contact point of the pitting geometry factor.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum IForm {
    /// AGMA 908-B89: lowest point of single tooth contact.
    Lpstc,
    /// Shigley eq. 14-23: pitch point.
    PitchPoint,
}

/// Pitting resistance geometry factor `I` \[-\] of a spur pair (external or internal), spur
/// `mN = 1`. See the module docs for the formulas.
pub fn pitting_geometry_factor(pair: &GearPair, form: IForm) -> Result<f64, GearError> {
    let phi = pair.operating_pressure_angle;
    let u = pair.ratio;
    let sign = if pair.internal { -1.0 } else { 1.0 };
    match form {
        IForm::PitchPoint => Ok(phi.cos() * phi.sin() / 2.0 * u / (u + sign)),
        IForm::Lpstc => {
            let rb1 = pair.pinion.base / 2.0;
            let ra1 = pair.pinion.tip / 2.0;
            let c6 = pair.centre_distance * phi.sin();
            let rho1 = (ra1 * ra1 - rb1 * rb1).sqrt() - pair.base_pitch;
            let rho2 = c6 - sign * rho1;
            require(
                rho1 > 0.0 && rho2 > 0.0,
                "pair",
                "LPSTC lies below a base circle (contact ratio too small or tips too short)",
                rho1,
            )?;
            Ok(phi.cos() / ((1.0 / rho1 + sign / rho2) * pair.pinion.working))
        }
    }
}

/// Shift case of the AGMA 908-B89 φ = 25° tables (long-addendum pinion `+x`, short-addendum
/// gear `−x`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ShiftCase {
    /// x = 0 (Nunes 2017 Annex A.2).
    Zero,
    /// x = ±0.25 (Annex A.3).
    Quarter,
    /// x = ±0.5 (Annex A.4, partly illegible; only the legible cells are stored).
    Half,
}

/// One table cell: `I`, `J` pinion, `J` gear (NaN = illegible in the source).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TableEntry {
    /// Pitting geometry factor `I` \[-\].
    pub i: f64,
    /// Bending geometry factor of the pinion `JP` \[-\].
    pub jp: f64,
    /// Bending geometry factor of the gear `JG` \[-\].
    pub jg: f64,
}

const N: f64 = f64::NAN;
const TEETH: [u32; 8] = [12, 14, 17, 21, 26, 35, 55, 135];

// (pinion teeth, gear teeth, I, JP, JG) as transcribed in docs/validation/nunes-2017.md
// (Nunes 2017 Annex A.2–A.4, AGMA 908-B89 tables, φ 25°).
#[rustfmt::skip]
const X0: &[(u32, u32, f64, f64, f64)] = &[
    (14, 14, 0.086, 0.33, 0.33),
    (14, 17, 0.091, 0.33, 0.36), (17, 17, 0.090, 0.36, 0.36),
    (14, 21, 0.095, 0.33, 0.39), (17, 21, 0.096, 0.36, 0.39), (21, 21, 0.092, 0.39, 0.39),
    (14, 26, 0.100, 0.33, 0.41), (17, 26, 0.101, 0.37, 0.42), (21, 26, 0.099, 0.40, 0.42),
    (26, 26, 0.094, 0.43, 0.43),
    (14, 35, 0.106, 0.34, 0.44), (17, 35, 0.109, 0.37, 0.45), (21, 35, 0.108, 0.40, 0.45),
    (26, 35, 0.104, 0.43, 0.46), (35, 35, 0.095, 0.46, 0.46),
    (14, 55, 0.113, 0.34, 0.47), (17, 55, 0.119, 0.38, 0.48), (21, 55, 0.121, 0.41, 0.49),
    (26, 55, 0.119, 0.44, 0.49), (35, 55, 0.112, 0.47, 0.50), (55, 55, 0.095, 0.51, 0.51),
    (14, 135, 0.123, 0.35, 0.51), (17, 135, 0.132, 0.38, 0.52), (21, 135, 0.139, 0.42, 0.53),
    (26, 135, 0.142, 0.45, 0.53), (35, 135, 0.141, 0.48, 0.54), (55, 135, 0.131, 0.53, 0.56),
    (135, 135, 0.096, 0.57, 0.57),
];
#[rustfmt::skip]
const X25: &[(u32, u32, f64, f64, f64)] = &[
    (12, 12, 0.091, 0.38, 0.22),
    (12, 14, 0.095, 0.38, N), (14, 14, 0.093, 0.40, N),
    (12, 17, 0.100, 0.38, 0.29), (14, 17, 0.099, 0.40, 0.29), (17, 17, 0.094, 0.43, 0.29),
    (12, 21, 0.106, 0.38, 0.32), (14, 21, 0.106, 0.41, 0.32), (17, 21, 0.102, 0.43, 0.33),
    (21, 21, 0.095, 0.46, 0.33),
    (12, 26, 0.111, 0.39, 0.35), (14, 26, 0.112, 0.41, 0.35), (17, 26, 0.109, 0.44, 0.36),
    (21, 26, 0.103, 0.46, 0.36), (26, 26, 0.095, 0.48, 0.37),
    (12, 35, 0.118, 0.39, 0.38), (14, 35, 0.120, 0.41, 0.39), (17, 35, 0.119, 0.44, 0.39),
    (21, 35, 0.115, 0.47, 0.40), (26, 35, 0.108, 0.49, 0.41), (35, 35, 0.096, 0.51, 0.41),
    (12, 55, 0.127, 0.39, 0.42), (14, 55, 0.131, 0.42, 0.43), (17, 55, 0.133, 0.44, 0.44),
    (21, 55, 0.131, 0.47, 0.44), (26, 55, 0.126, 0.49, 0.45), (35, 55, 0.116, 0.52, 0.46),
    (55, 55, 0.096, 0.55, 0.47),
    (12, 135, 0.138, 0.40, 0.47), (14, 135, 0.145, 0.42, 0.48), (17, 135, 0.151, 0.45, 0.49),
    (21, 135, 0.153, 0.48, 0.49), (26, 135, 0.153, 0.50, 0.50), (35, 135, 0.148, 0.53, 0.51),
    (55, 135, 0.135, 0.56, 0.53), (135, 135, 0.096, 0.59, 0.55),
];
#[rustfmt::skip]
const X50: &[(u32, u32, f64, f64, f64)] = &[
    (21, 26, 0.106, 0.52, N), (26, 26, 0.096, 0.53, 0.31),
    (21, 35, 0.120, 0.52, N), (26, 35, 0.110, 0.53, 0.35), (35, 35, 0.096, N, N),
    (21, 55, 0.139, 0.52, 0.40), (26, 55, 0.131, 0.54, 0.41), (35, 55, 0.118, 0.56, 0.42),
    (55, 55, 0.096, 0.58, 0.43),
    (21, 135, 0.167, 0.53, 0.46), (26, 135, 0.163, 0.54, 0.47), (35, 135, 0.155, 0.56, 0.48),
    (55, 135, 0.138, 0.58, 0.50), (135, 135, 0.096, N, 0.53),
];

fn cell(case: ShiftCase, zp: u32, zg: u32) -> Option<TableEntry> {
    let t = match case {
        ShiftCase::Zero => X0,
        ShiftCase::Quarter => X25,
        ShiftCase::Half => X50,
    };
    t.iter()
        .find(|r| r.0 == zp && r.1 == zg)
        .map(|r| TableEntry {
            i: r.2,
            jp: r.3,
            jg: r.4,
        })
}

fn bracket(z: u32) -> Option<(u32, u32, f64)> {
    if let Some(&k) = TEETH.iter().find(|&&k| k == z) {
        return Some((k, k, 0.0));
    }
    TEETH
        .windows(2)
        .find(|w| w[0] < z && z < w[1])
        .map(|w| (w[0], w[1], (z - w[0]) as f64 / (w[1] - w[0]) as f64))
}

/// External-gear `I`, `JP`, `JG` from the AGMA 908-B89 φ = 25° tables (as reproduced in Nunes
/// 2017 Annex A), bilinear in the tooth counts between table nodes as Nunes did (Nunes 2017
/// §4.4; verified against all 18 values of its Table 4.8). Errors when the pair lies outside
/// the table (`zp > zg`, counts outside 12…135) or a needed cell is illegible; an illegible
/// value inside a legible cell comes back as NaN.
pub fn agma908_table(case: ShiftCase, zp: u32, zg: u32) -> Result<TableEntry, GearError> {
    let out = || GearError::OutsideTable(format!("{case:?}: pinion {zp} / gear {zg}"));
    let (p0, p1, tp) = bracket(zp).ok_or_else(out)?;
    let (g0, g1, tg) = bracket(zg).ok_or_else(out)?;
    let c = |p, g| cell(case, p, g).ok_or_else(out);
    let (c00, c01, c10, c11) = (c(p0, g0)?, c(p0, g1)?, c(p1, g0)?, c(p1, g1)?);
    let lerp = |a: f64, b: f64, t: f64| if t == 0.0 { a } else { a + t * (b - a) };
    let bil = |f: fn(&TableEntry) -> f64| {
        let at_p0 = lerp(f(&c00), f(&c01), tg);
        let at_p1 = lerp(f(&c10), f(&c11), tg);
        lerp(at_p0, at_p1, tp)
    };
    Ok(TableEntry {
        i: bil(|e| e.i),
        jp: bil(|e| e.jp),
        jg: bil(|e| e.jg),
    })
}

/// Bending geometry factors `(JP, JG)` used here for an **internal** pair, for which AGMA 908
/// gives no J. Proxy: both are read from the external table with the ring replaced by the
/// largest tabulated mate (135 teeth): `JP = JP(zp, 135)`, `JG = JG(zp, 135)`.
///
/// Why this is on the safe side: J of an external member grows with the mate's tooth count
/// (the highest point of single tooth contact moves towards the pitch point as the contact
/// ratio grows); an internal mate gives a still longer path of contact, so the pinion's J is
/// at least the large-mate value. The ring tooth is thicker at its root than a rack (or a
/// 135-tooth external) tooth of the same module, so its true J is larger than the proxy.
/// The proxy is an engineering choice of this crate, not an AGMA value.
pub fn internal_j_conservative(case: ShiftCase, zp: u32) -> Result<(f64, f64), GearError> {
    let e = agma908_table(case, zp, 135)?;
    Ok((e.jp, e.jg))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn nodes_are_returned_exactly() {
        let e = agma908_table(ShiftCase::Zero, 26, 55).unwrap();
        assert_eq!((e.i, e.jp, e.jg), (0.119, 0.44, 0.49));
    }

    #[test]
    fn outside_table_is_an_error() {
        assert!(agma908_table(ShiftCase::Zero, 55, 26).is_err());
        assert!(agma908_table(ShiftCase::Zero, 26, 200).is_err());
        assert!(agma908_table(ShiftCase::Half, 14, 26).is_err());
    }
}
