//! The `nunes` reading: AGMA face-width sizing of the internal 26/52 cardan pair exactly as
//! Nunes 2017 §4.4 did it (eqs. 2.76–2.79, 4.19–4.30, Tables 4.8–4.12), kept to reproduce the
//! thesis. It is **not** AGMA-correct for an internal pair:
//!
//! | item | `nunes` reading | correct internal reading ([`super::GearSetRating`]) |
//! |---|---|---|
//! | `I`, `J` | external AGMA 908 tables, bilinear interpolation ([`super::geometry_factors::agma908_table`]) | `I` from the internal LPSTC formula; `J` see [`super::geometry_factors::internal_j_conservative`] |
//! | contact `d` | each member's own pitch diameter (26 / 52 mm) | pinion operating pitch diameter for both |
//! | `Km` | `Cpf`, `Cma` at the maximum allowed face width (52 mm), each member's own `d`, Nunes's `Cma` constant A = 0.0380 | actual face width, pinion `d`, AGMA table constants |
//! | `Kv` | metric `Av` form with each member's own `v = π d N / 60` | one pitch-line velocity for the mesh |
//!
//! Other factors as Nunes: `Ko = KB = Ks = Cf = YN = ZN = KT = KR = CH = 1`, `SF = SH = 1`.

use super::factors::{dynamic_factor, DynamicFactor, Quality};
use crate::error::{positive, GearError};

/// Nunes 2017 eqs. 4.19–4.24: `Km = 1 + Cmc (Cpf Cpm + Cma Ce)` with `Cmc = 1`,
/// `Cpf = FW/(10 d) − 0.025` (FW ≤ 25 mm) or `FW/(10 d) − 0.0375 + 0.000492 FW`
/// (25 < FW ≤ 432 mm), `Cma = 0.0380 + 0.402·10⁻³ FW − 1.27·10⁻⁷ FW²` (FW in mm).
/// `face_width` (Nunes: the maximum allowed 2·d_pinion) and `member_diameter` \[m\].
/// Nunes: pinion `Cpm = 1.1`, ring `Cpm = 1.0`, `Ce = 0.8` → 1.2537 / 1.1349 (Table 4.10).
pub fn load_distribution_factor(
    face_width: f64,
    member_diameter: f64,
    cpm: f64,
    ce: f64,
) -> Result<f64, GearError> {
    positive("face_width", face_width)?;
    positive("member_diameter", member_diameter)?;
    let fw = face_width * 1e3;
    let d = member_diameter * 1e3;
    let cpf = if fw <= 25.0 {
        fw / (10.0 * d) - 0.025
    } else {
        fw / (10.0 * d) - 0.0375 + 0.000492 * fw
    };
    let cma = 0.0380 + 0.402e-3 * fw - 1.27e-7 * fw * fw;
    Ok(1.0 + (cpf * cpm + cma * ce))
}

/// Nunes 2017 eqs. 4.25–4.29: metric `Kv` with accuracy level `Av` at the member's own pitch
/// line velocity `v = π d N / 60`, `d` \[m\], `N` crank speed \[rpm\].
pub fn dynamic_factor_member(
    av: f64,
    member_diameter: f64,
    crank_rpm: f64,
) -> Result<DynamicFactor, GearError> {
    positive("member_diameter", member_diameter)?;
    dynamic_factor(
        Quality::Av(av),
        std::f64::consts::PI * member_diameter * crank_rpm / 60.0,
    )
}

/// Nunes's bending face width (eq. 2.76 solved for FW with `σF = σFP`):
/// `FW = F_gt Kv Km / (m σFP J)` \[m\]. `f_gt` \[N\], `module` \[m\], `sigma_fp` \[Pa\].
pub fn bending_face_width(f_gt: f64, kv: f64, km: f64, module: f64, sigma_fp: f64, j: f64) -> f64 {
    f_gt * kv * km / (module * sigma_fp * j)
}

/// Nunes's contact face width (eq. 2.78 solved for FW with `σH = σHP`):
/// `FW = F_gt Kv Km Z_E² / (d I σHP²)` \[m\], `d` the member's **own** pitch diameter \[m\],
/// `ze` \[√Pa\], `sigma_hp` \[Pa\].
pub fn contact_face_width(
    f_gt: f64,
    kv: f64,
    km: f64,
    ze: f64,
    member_diameter: f64,
    i: f64,
    sigma_hp: f64,
) -> f64 {
    f_gt * kv * km * ze * ze / (member_diameter * i * sigma_hp * sigma_hp)
}

/// Nunes 2017 eq. 4.1: allowable bending stress of grade 2 Nitralloy,
/// `σFP = 0.7255 HB + 153.63` MPa (AGMA, US `105.2 HB + 22 280 psi` in metric) \[Pa\].
/// Nunes uses HB 415 (after nitriding) → 454.713 MPa.
pub fn nitralloy_grade2_bending_allowable(hb: f64) -> Result<f64, GearError> {
    positive("hb", hb)?;
    Ok((0.7255 * hb + 153.63) * 1e6)
}
