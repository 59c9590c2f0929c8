//! ISO 6336-2:2019 method B surface durability (pitting) of spur and helical gears: the
//! nominal contact stress `σ_H0`, the contact stress `σ_H`, the permissible contact stress
//! `σ_HP` and the safety factor `S_H`, with their influence factors. SI arguments (N, m, Pa,
//! rad); `Z_E` in √Pa.

use std::f64::consts::PI;

use crate::error::{require, GearError};
use crate::materials::LifeCurve;

/// Elasticity factor `Z_E = √(1 / (π [(1 − ν1²)/E1 + (1 − ν2²)/E2]))` \[√Pa\]
/// (ISO 6336-2:2019 §7, eq. (16)). Steel on steel (206 GPa, 0.3) gives 189.8 √(N/mm²). The
/// same quantity as AGMA 2001's elastic coefficient `C_p`: one formula,
/// [`crate::agma::factors::elastic_coefficient`].
pub fn elasticity_factor(e1: f64, nu1: f64, e2: f64, nu2: f64) -> Result<f64, GearError> {
    crate::agma::factors::elastic_coefficient(e1, nu1, e2, nu2)
}

/// Zone factor `Z_H = √(2 cos β_b cos α_wt / (cos² α_t sin α_wt))` (ISO 6336-2:2019 §6.1,
/// eq. (9)). Angles \[rad\]: base helix angle, working and reference transverse pressure
/// angles.
pub fn zone_factor(beta_b: f64, alpha_wt: f64, alpha_t: f64) -> f64 {
    (2.0 * beta_b.cos() * alpha_wt.cos() / (alpha_t.cos().powi(2) * alpha_wt.sin())).sqrt()
}

/// Contact ratio factor `Z_ε` (ISO 6336-2:2019 §8, eqs. (19)-(21)): spur `√((4 − ε_α)/3)`;
/// helical `ε_β < 1`: `√((4 − ε_α)/3 (1 − ε_β) + ε_β/ε_α)`; `ε_β ≥ 1`: `√(1/ε_α)`.
pub fn contact_ratio_factor(eps_alpha: f64, eps_beta: f64) -> f64 {
    if eps_beta >= 1.0 {
        (1.0 / eps_alpha).sqrt()
    } else {
        ((4.0 - eps_alpha) / 3.0 * (1.0 - eps_beta) + eps_beta / eps_alpha).sqrt()
    }
}

/// Helix angle factor `Z_β = 1/√(cos β)` (ISO 6336-2:2019 §9, eq. (22); the 2006 edition's
/// `√(cos β)` was replaced). 1 for spur gears.
pub fn helix_angle_factor(beta: f64) -> f64 {
    1.0 / beta.cos().sqrt()
}

/// Single pair tooth contact factors `(Z_B, Z_D)` of the pinion and the wheel
/// (ISO 6336-2:2019 §6.2, eqs. (10)-(14)): `M1 = tan α_wt / √([√(d_a1²/d_b1² − 1) − 2π/z1]
/// [√(d_a2²/d_b2² − 1) − (ε_α − 1) 2π/z2])`, `M2` the same with the gears swapped; spur
/// `Z_B = max(1, M1)`, `Z_D = max(1, M2)`; `ε_β ≥ 1`: 1; between: `M − ε_β (M − 1)` (not
/// below 1). An internal wheel has `Z_D = 1` (§6.2), and its `z2` counts negative in `M1`
/// (ISO's sign convention for internal gears): the ring's flank at the pinion's inner point of
/// single contact lies `(ε_α − 1) p_b` beyond the ring's tip along the line of action, where an
/// external wheel's lies short of its tip, so its term is `√(d_a2²/d_b2² − 1) + (ε_α − 1) 2π/|z2|`.
/// Diameters \[m\] (magnitudes), `z2` \[-\] (magnitude), `alpha_wt` \[rad\].
#[allow(clippy::too_many_arguments)]
pub fn single_pair_factors(
    z1: f64,
    z2: f64,
    da: [f64; 2],
    db: [f64; 2],
    alpha_wt: f64,
    eps_alpha: f64,
    eps_beta: f64,
    internal: bool,
) -> (f64, f64) {
    let r1 = ((da[0] / db[0]).powi(2) - 1.0).max(0.0).sqrt();
    let r2 = ((da[1] / db[1]).powi(2) - 1.0).max(0.0).sqrt();
    let t = alpha_wt.tan();
    let sign = if internal { -1.0 } else { 1.0 };
    let m1 = t / ((r1 - 2.0 * PI / z1) * (r2 - (eps_alpha - 1.0) * 2.0 * PI / (sign * z2))).sqrt();
    let m2 = t / ((r2 - 2.0 * PI / z2) * (r1 - (eps_alpha - 1.0) * 2.0 * PI / z1)).sqrt();
    let pick = |m: f64| {
        if !m.is_finite() || eps_beta >= 1.0 {
            1.0
        } else {
            (m - eps_beta * (m - 1.0)).max(1.0)
        }
    };
    let zb = pick(m1);
    let zd = if internal { 1.0 } else { pick(m2) };
    (zb, zd)
}

/// Life factor for contact stress `Z_NT` at `n` load cycles (ISO 6336-2:2019 Table 2,
/// method B, log-log between the points): through-hardened and case-hardened steels (no
/// pitting permitted) 1.6 up to 1e5, 1.0 at 5e7, 0.85 at 1e10; nitrided steels and grey iron
/// 1.3 up to 1e5, 1.0 at 2e6, 0.85 at 1e10. The 0.85 at 1e10 is the standard's value for
/// ordinary conditions (1.0 only with optimum lubrication, material and manufacture).
pub fn life_factor_contact(curve: LifeCurve, n: f64) -> Result<f64, GearError> {
    require(
        n.is_finite() && n > 0.0,
        "load cycles",
        "must be positive",
        n,
    )?;
    let pts: &[(f64, f64)] = match curve {
        LifeCurve::ThroughHardened | LifeCurve::CaseHardened => {
            &[(1e5, 1.6), (5e7, 1.0), (1e10, 0.85)]
        }
        LifeCurve::Nitrided | LifeCurve::GreyIron => &[(1e5, 1.3), (2e6, 1.0), (1e10, 0.85)],
    };
    Ok(log_log(pts, n))
}

/// Piecewise log-log interpolation through `pts`, constant beyond the ends.
pub(crate) fn log_log(pts: &[(f64, f64)], n: f64) -> f64 {
    if n <= pts[0].0 {
        return pts[0].1;
    }
    for w in pts.windows(2) {
        let ((n0, y0), (n1, y1)) = (w[0], w[1]);
        if n <= n1 {
            let e = (y1 / y0).ln() / (n1 / n0).ln();
            return y0 * (n / n0).powf(e);
        }
    }
    pts[pts.len() - 1].1
}

/// Size factor `Z_X` (ISO 6336-2:2019 §13, Table 3, long life): through-hardened steel and
/// grey iron 1.0; case-hardened 1.0 up to `m_n` = 10 mm, `1.05 − 0.005 m_n` below 30 mm, 0.9
/// from 30 mm; nitrided 1.0 below `m_n` = 7.5 mm, `1.08 − 0.011 m_n` below 30 mm, 0.75 from
/// 30 mm (the table's breaks, not where the line meets 1: at 7.3 mm it is 1.0, not 0.9997);
/// `m_n` in mm. `module` \[m\].
pub fn size_factor_contact(curve: LifeCurve, module: f64) -> f64 {
    let m = module * 1e3;
    match curve {
        LifeCurve::ThroughHardened | LifeCurve::GreyIron => 1.0,
        LifeCurve::CaseHardened if m <= 10.0 => 1.0,
        LifeCurve::CaseHardened if m < 30.0 => 1.05 - 0.005 * m,
        LifeCurve::CaseHardened => 0.9,
        LifeCurve::Nitrided if m < 7.5 => 1.0,
        LifeCurve::Nitrided if m < 30.0 => 1.08 - 0.011 * m,
        LifeCurve::Nitrided => 0.75,
    }
}

/// Lubricant, velocity and roughness factors `(Z_L, Z_v, Z_R)` by ISO 6336-2:2019 method B
/// (§11, eqs. (24)-(31)): `C_ZL` = 0.83 below `σ_Hlim` = 850 N/mm², 0.91 above 1200,
/// `0.08 (σ_Hlim − 850)/350 + 0.83` between; `Z_L = C_ZL + 4 (1 − C_ZL)/(1.2 + 134/ν40)²`;
/// `C_Zv = C_ZL + 0.02`, `Z_v = C_Zv + 2 (1 − C_Zv)/√(0.8 + 32/v)`;
/// `Z_R = (3/R_z10)^C_ZR`, `R_z10 = R_z (10/ρ_red)^(1/3)` (mm, µm), `C_ZR` = 0.15 below
/// 850 N/mm², 0.08 above 1200, `0.32 − 0.0002 σ_Hlim` between. `sigma_hlim` \[Pa\] (the
/// smaller of the pair), `nu40` \[mm²/s\], `v` \[m/s\], `rz` mean flank roughness \[m\],
/// `rho_red` relative radius of curvature at the pitch point \[m\].
pub fn lubrication_factors(sigma_hlim: f64, nu40: f64, v: f64, rz: f64, rho_red: f64) -> [f64; 3] {
    let s = sigma_hlim / 1e6;
    let c_zl = if s < 850.0 {
        0.83
    } else if s > 1200.0 {
        0.91
    } else {
        0.08 * (s - 850.0) / 350.0 + 0.83
    };
    let z_l = c_zl + 4.0 * (1.0 - c_zl) / (1.2 + 134.0 / nu40).powi(2);
    let c_zv = c_zl + 0.02;
    let z_v = c_zv + 2.0 * (1.0 - c_zv) / (0.8 + 32.0 / v.max(1e-9)).sqrt();
    let c_zr = if s < 850.0 {
        0.15
    } else if s > 1200.0 {
        0.08
    } else {
        0.32 - 0.0002 * s
    };
    let rz10 = rz * 1e6 * (10.0 / (rho_red * 1e3)).cbrt();
    let z_r = (3.0 / rz10).powf(c_zr);
    [z_l, z_v, z_r]
}

/// Nominal contact stress at the pitch point `σ_H0 = Z_H Z_E Z_ε Z_β √(F_t/(d1 b) (u+1)/u)`
/// \[Pa\] (ISO 6336-2:2019 §5.2, eq. (3)); `u = z2/z1` signed (negative for an internal pair,
/// so `(u+1)/u = (|u| − 1)/|u|`). `ft` \[N\] at the reference circle, `d1` reference
/// diameter \[m\], `b` \[m\], `z_e` \[√Pa\].
#[allow(clippy::too_many_arguments)]
pub fn nominal_contact_stress(
    ft: f64,
    d1: f64,
    b: f64,
    u: f64,
    z_h: f64,
    z_e: f64,
    z_eps: f64,
    z_beta: f64,
) -> f64 {
    z_h * z_e * z_eps * z_beta * (ft / (d1 * b) * (u + 1.0) / u).sqrt()
}

/// Contact stress `σ_H = Z_B,D σ_H0 √(K_A K_v K_Hβ K_Hα)` \[Pa\] (ISO 6336-2:2019 §5.2,
/// eqs. (1), (2); `K_γ` = 1 for a single mesh).
pub fn contact_stress(z_bd: f64, sigma_h0: f64, k_a: f64, k_v: f64, k_hb: f64, k_ha: f64) -> f64 {
    z_bd * sigma_h0 * (k_a * k_v * k_hb * k_ha).sqrt()
}

/// Pitting stress limit `σ_HG = σ_Hlim Z_NT Z_L Z_v Z_R Z_W Z_X` \[Pa\] (ISO 6336-2:2019 §5.3,
/// eq. (5) with `S_Hmin` = 1); `σ_HP = σ_HG / S_Hmin` (eq. (4)) and `S_H = σ_HG/σ_H`
/// (§5.4, eq. (6)).
pub fn pitting_stress_limit(sigma_hlim: f64, factors: [f64; 6]) -> f64 {
    sigma_hlim * factors.iter().product::<f64>()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn steel_on_steel_elasticity_factor() {
        // ISO 6336-2 §7: 189.8 √(N/mm²) for E = 206 000 N/mm², ν = 0.3 (4 digits printed).
        let z = elasticity_factor(206e9, 0.3, 206e9, 0.3).unwrap() / 1e3;
        assert!((z - 189.8).abs() < 0.05, "{z}");
    }

    #[test]
    fn zone_factor_of_unshifted_spur_is_2_495() {
        // Z_H = 2/√(sin 2α) for β = 0, α_wt = α_t = 20°: 2.4946 (the classic 2.49/2.5).
        let a = 20f64.to_radians();
        let z = zone_factor(0.0, a, a);
        assert!((z - 2.0 / (2.0 * a).sin().sqrt()).abs() < 1e-12);
        assert!((z - 2.4946).abs() < 1e-4);
    }

    #[test]
    fn size_factor_follows_the_table_breaks() {
        // ISO 6336-2 Table 3: nitrided steel keeps Z_X = 1 below m_n = 7.5 mm (the line
        // 1.08 − 0.011 m_n gives 0.9997 at 7.3 mm); 0.9975 at 7.5, 0.75 from 30 mm.
        let z = |m: f64| size_factor_contact(LifeCurve::Nitrided, m * 1e-3);
        assert_eq!(z(7.3), 1.0);
        assert!((z(7.5) - 0.9975).abs() < 1e-12 && z(30.0) == 0.75);
        let c = |m: f64| size_factor_contact(LifeCurve::CaseHardened, m * 1e-3);
        assert_eq!(c(10.0), 1.0);
        assert!((c(20.0) - 0.95).abs() < 1e-12 && c(30.0) == 0.9);
    }

    #[test]
    fn life_factor_nodes() {
        let z = |n| life_factor_contact(LifeCurve::ThroughHardened, n).unwrap();
        assert_eq!(z(1e4), 1.6);
        assert!((z(5e7) - 1.0).abs() < 1e-12 && (z(1e10) - 0.85).abs() < 1e-12);
        // ISO 6336-2 Table 2 writes the long-life branch as (5e7/N)^0.0306.
        assert!((z(1e9) - (5e7f64 / 1e9).powf(0.0306)).abs() < 1e-3);
        assert!((z(1e5) - 1.6).abs() < 1e-12);
        // Between 1e5 and 5e7 the table's exponent is 0.0756.
        assert!((z(1e6) - (5e7f64 / 1e6).powf(0.0756)).abs() < 1e-3);
    }
}
