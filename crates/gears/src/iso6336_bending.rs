//! ISO 6336-3:2019 method B tooth bending strength: the nominal root stress `σ_F0`, the root
//! stress `σ_F`, the bending stress limit `σ_FG` and the safety factor `S_F`, with the
//! influence factors that do not need the tooth form. The tooth form factor `Y_F` and the
//! stress correction factor `Y_S` (ISO 6336-3 §6, §7) are arguments: they come from the
//! tooth-form module or are given.

use crate::iso6336_pitting::log_log;
use crate::materials::LifeCurve;

/// Standard test gear stress correction factor `Y_ST` = 2.0 (ISO 6336-3:2019 §5.3; ISO
/// 6336-5: `σ_FE = σ_Flim Y_ST`).
pub const Y_ST: f64 = 2.0;

/// Nominal root stress `σ_F0 = F_t/(b m_n) Y_F Y_S Y_β Y_B Y_DT` \[Pa\] (ISO 6336-3:2019
/// §5.2, eq. (2), method B). `ft` \[N\], `b`, `module` \[m\].
#[allow(clippy::too_many_arguments)]
pub fn nominal_root_stress(
    ft: f64,
    b: f64,
    module: f64,
    y_f: f64,
    y_s: f64,
    y_beta: f64,
    y_b: f64,
    y_dt: f64,
) -> f64 {
    ft / (b * module) * y_f * y_s * y_beta * y_b * y_dt
}

/// Root stress `σ_F = σ_F0 K_A K_v K_Fβ K_Fα` \[Pa\] (ISO 6336-3:2019 §5.2, eq. (1);
/// `K_γ` = 1 for a single mesh).
pub fn root_stress(sigma_f0: f64, k_a: f64, k_v: f64, k_fb: f64, k_fa: f64) -> f64 {
    sigma_f0 * k_a * k_v * k_fb * k_fa
}

/// Tooth root stress limit `σ_FG = σ_Flim Y_ST Y_NT Y_δrelT Y_RrelT Y_X` \[Pa\]
/// (ISO 6336-3:2019 §5.3, eq. (4) with `S_Fmin` = 1); `σ_FP = σ_FG/S_Fmin` (eq. (3)) and
/// `S_F = σ_FG/σ_F` (§5.4, eq. (5)).
pub fn root_stress_limit(sigma_flim: f64, y_nt: f64, y_delta: f64, y_r: f64, y_x: f64) -> f64 {
    sigma_flim * Y_ST * y_nt * y_delta * y_r * y_x
}

/// Helix angle factor `Y_β = 1 − ε_β β/120°` with `ε_β` ≤ 1 and `β` ≤ 30° in the formula
/// (ISO 6336-3:2006 §9, eq. (41); 1 for spur gears). `beta` \[rad\].
pub fn helix_angle_factor(eps_beta: f64, beta: f64) -> f64 {
    1.0 - eps_beta.min(1.0) * beta.to_degrees().min(30.0) / 120.0
}

/// Contact ratio factor for bending `Y_ε = 0.25 + 0.75/ε_αn` (ISO 6336-3:2006 §8, eq. (38)):
/// applies only when `Y_F`, `Y_S` are those of load at the tooth tip (method C); method B's
/// `Y_F` at the outer point of single tooth contact already accounts for load sharing, so
/// the rating here does not use it.
pub fn contact_ratio_factor(eps_alpha_n: f64) -> f64 {
    0.25 + 0.75 / eps_alpha_n
}

/// Deep tooth factor `Y_DT` (ISO 6336-3:2019 §10, eqs. (51)-(53)): 1 for `ε_αn ≤ 2.05` or
/// an accuracy grade worse than 4; for grade ≤ 4, `−0.666 ε_αn + 2.366` up to 2.5 and 0.7
/// above.
pub fn deep_tooth_factor(eps_alpha_n: f64, accuracy_grade: Option<f64>) -> f64 {
    match accuracy_grade {
        Some(q) if q <= 4.0 && eps_alpha_n > 2.05 => {
            if eps_alpha_n > 2.5 {
                0.7
            } else {
                -0.666 * eps_alpha_n + 2.366
            }
        }
        _ => 1.0,
    }
}

/// Life factor for tooth root stress `Y_NT` at `n` cycles (ISO 6336-3:2019 Table 3, method
/// B, log-log between the points): through-hardened steels 2.5 up to 1e4, 1.0 at 3e6, 0.85
/// at 1e10; case-hardened 2.5 up to 1e3, 1.0 at 3e6, 0.85 at 1e10; nitrided steels and grey
/// iron 1.6 up to 1e3, 1.0 at 3e6, 0.85 at 1e10 (0.85, the standard's value for ordinary
/// conditions).
pub fn life_factor_root(curve: LifeCurve, n: f64) -> f64 {
    let pts: &[(f64, f64)] = match curve {
        LifeCurve::ThroughHardened => &[(1e4, 2.5), (3e6, 1.0), (1e10, 0.85)],
        LifeCurve::CaseHardened => &[(1e3, 2.5), (3e6, 1.0), (1e10, 0.85)],
        LifeCurve::Nitrided | LifeCurve::GreyIron => &[(1e3, 1.6), (3e6, 1.0), (1e10, 0.85)],
    };
    log_log(pts, n)
}

/// Size factor for root stress `Y_X` (ISO 6336-3:2019 §13, Table 5, long life): through-
/// hardened steel 1.0 up to m_n = 5 mm, `1.03 − 0.006 m_n` to 30 mm, 0.85 beyond;
/// case-hardened and nitrided `1.05 − 0.01 m_n` (≥ 0.8); grey iron `1.075 − 0.015 m_n`
/// (≥ 0.7); `m_n` in mm. `module` \[m\].
pub fn size_factor_root(curve: LifeCurve, module: f64) -> f64 {
    let m = module * 1e3;
    if m <= 5.0 {
        return 1.0;
    }
    match curve {
        LifeCurve::ThroughHardened => (1.03 - 0.006 * m).max(0.85),
        LifeCurve::CaseHardened | LifeCurve::Nitrided => (1.05 - 0.01 * m).max(0.8),
        LifeCurve::GreyIron => (1.075 - 0.015 * m).max(0.7),
    }
}

/// Relative surface factor `Y_RrelT` from the root roughness `R_z` (ISO 6336-3:2019 §12,
/// method B, eqs. (61)-(66), 1 µm ≤ R_z ≤ 40 µm): through-hardened and case-hardened steels
/// `1.674 − 0.529 (R_z + 1)^0.1`; nitrided steels and grey iron
/// `4.299 − 3.259 (R_z + 1)^0.0058`. `rz` \[m\].
pub fn relative_surface_factor(curve: LifeCurve, rz: f64) -> f64 {
    let r = (rz * 1e6).clamp(1.0, 40.0);
    match curve {
        LifeCurve::ThroughHardened | LifeCurve::CaseHardened => 1.674 - 0.529 * (r + 1.0).powf(0.1),
        LifeCurve::Nitrided | LifeCurve::GreyIron => 4.299 - 3.259 * (r + 1.0).powf(0.0058),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn life_factor_nodes() {
        let y = |n| life_factor_root(LifeCurve::ThroughHardened, n);
        assert_eq!(y(1e3), 2.5);
        assert!((y(3e6) - 1.0).abs() < 1e-12 && (y(1e10) - 0.85).abs() < 1e-12);
        // ISO 6336-3 Table 3 writes the 1e4..3e6 branch as (3e6/N)^0.16, its exponent
        // rounded from ln 2.5/ln 300 = 0.1606: the two agree to 0.005 at 1e5.
        assert!((y(1e5) - (3e6f64 / 1e5).powf(0.16)).abs() < 5e-3);
    }

    #[test]
    fn surface_factor_is_about_one_at_the_test_gear_roughness() {
        // The standard test gear has R_z ≈ 10 µm: Y_RrelT ≈ 1 (to the fit's 0.002).
        assert!((relative_surface_factor(LifeCurve::ThroughHardened, 10e-6) - 1.0).abs() < 0.002);
    }
}
