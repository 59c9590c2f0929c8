//! ISO 6336-1:2019 load factors of a spur pair: the dynamic factor `K_v` by method B
//! (§6.5), the transverse load factors `K_Hα`, `K_Fα` by method B (§8.3), the face load factor
//! for bending `K_Fβ` from `K_Hβ` (§7.6), and what they need: the single and mesh stiffness
//! `c'`, `c_γα` (§9.3, §9.4, with the ISO 6336-1 coefficients of `q'`), the running-in
//! allowances `y_α`, `y_f` and tip relief `C_ay` (§8.3.4, §6.5.9), and the pitch and profile
//! deviations from an ISO 1328-1:1995 accuracy grade.
//!
//! Units inside follow the standard's (mm, µm, N, kg, N/mm); arguments and results are SI
//! as named in each doc comment.

use std::f64::consts::PI;

use crate::error::{positive, require, GearError};

/// Range limits of the reference diameter \[mm\] of the ISO 1328-1:1995 tolerance tables
/// (clause 5, the ranges of its tables): 5-20, 20-50, 50-125, 125-280, 280-560, 560-1000, 1000-1600,
/// 1600-2500, 2500-4000, 4000-6000, 6000-8000, 8000-10 000.
const ISO1328_DIAMETERS: [f64; 13] = [
    5.0, 20.0, 50.0, 125.0, 280.0, 560.0, 1000.0, 1600.0, 2500.0, 4000.0, 6000.0, 8000.0, 10_000.0,
];

/// Range limits of the normal module \[mm\] of the same tables: 0.5-2, 2-3.5, 3.5-6, 6-10,
/// 10-16, 16-25, 25-40, 40-70.
const ISO1328_MODULES: [f64; 9] = [0.5, 2.0, 3.5, 6.0, 10.0, 16.0, 25.0, 40.0, 70.0];

/// The value the ISO 1328-1:1995 tables put in a formula for `x` (mm): the geometric mean
/// of the limits of the range holding it, lower limit excluded (ISO 1328-1:1995 clause 5: the
/// tolerances are computed with the geometric means of the ranges, not the gear's own `m`
/// and `d`); below
/// the first or above the last range, `x` itself (the formula beyond the tables).
fn iso1328_range_mean(limits: &[f64], x: f64) -> f64 {
    if x < limits[0] || x > limits[limits.len() - 1] {
        return x;
    }
    let k = limits.windows(2).position(|w| x <= w[1]).unwrap_or(0);
    (limits[k] * limits[k + 1]).sqrt()
}

/// ISO 1328-1:1995 clause 5 rounding of a tolerance value `t` \[µm\]: above 10 µm to the
/// whole µm, from 5 to 10 µm to 0.5 µm, below 5 µm to 0.1 µm.
fn iso1328_round(t: f64) -> f64 {
    if t > 10.0 {
        t.round()
    } else if t >= 5.0 {
        (2.0 * t).round() / 2.0
    } else {
        (10.0 * t).round() / 10.0
    }
}

/// Single pitch deviation `f_pt` and profile form deviation `f_fα` \[m\] of accuracy grade `q`,
/// as ISO 1328-1:1995 tabulates them (Tables 1 and 3): the grade 5 formulas
/// `f_pt = 0.3 (m + 0.4 √d) + 4` µm and `f_fα = 2.5 √m + 0.17 √d + 0.5` µm (clause 6), with
/// `m` and `d` the geometric means of the tables' module and diameter ranges
/// (`iso1328_range_mean`), times the step `√2^(q − 5)` of the unrounded grade 5 value,
/// then rounded (`iso1328_round`) (clause 5). Grade 7, 50 < d ≤ 125 mm,
/// 2 < m ≤ 3.5 mm: 12 µm and 12 µm, the tables' values. `module`, `diameter` \[m\] (the
/// diameter's magnitude for a ring), `q` in 1..=12.
pub fn iso1328_deviations(module: f64, diameter: f64, q: f64) -> Result<(f64, f64), GearError> {
    positive("module", module)?;
    positive("reference diameter", diameter)?;
    require(
        q.is_finite() && (1.0..=12.0).contains(&q),
        "accuracy_grade",
        "ISO 1328-1 accuracy grade must lie in [1, 12]",
        q,
    )?;
    let m = iso1328_range_mean(&ISO1328_MODULES, module * 1e3);
    let d = iso1328_range_mean(&ISO1328_DIAMETERS, diameter * 1e3);
    let step = 2f64.sqrt().powf(q - 5.0);
    let f_pt = iso1328_round((0.3 * (m + 0.4 * d.sqrt()) + 4.0) * step);
    let f_fa = iso1328_round((2.5 * m.sqrt() + 0.17 * d.sqrt() + 0.5) * step);
    Ok((f_pt * 1e-6, f_fa * 1e-6))
}

/// Material class of the running-in allowances (ISO 6336-1:2019 §8.3.4, Table 9).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum RunningIn {
    /// St, V, GGG (perl., bai.), GTS (perl.): `y_α = 160/σ_Hlim · f_pb`.
    ThroughHardened,
    /// GG, GGG (ferr.): `y_α = 0.275 f_pb`.
    GreyIron,
    /// Eh, IF, NT, NV: `y_α = 0.075 f_pb`, at most 3 µm.
    Hardened,
}

/// Running-in allowance `y` \[m\] for deviation `f` \[m\] (`f_pb` for `y_α` = `y_p`, `f_fα`
/// for `y_f`), ISO 6336-1:2019 §8.3.4 Table 9: through-hardened `160/σ_Hlim · f` with
/// `y ≤ 12 800/σ_Hlim` µm for 5 < v ≤ 10 m/s and `6 400/σ_Hlim` µm above 10 m/s; grey iron
/// `0.275 f`, ≤ 22 µm (5-10 m/s), ≤ 11 µm (> 10 m/s); hardened `0.075 f`, ≤ 3 µm.
/// `sigma_hlim` \[Pa\], `v` pitch-line velocity \[m/s\].
pub fn running_in_allowance(class: RunningIn, f: f64, sigma_hlim: f64, v: f64) -> f64 {
    let f_um = f * 1e6;
    let s = sigma_hlim / 1e6;
    let y = match class {
        RunningIn::ThroughHardened => {
            let y = 160.0 / s * f_um;
            if v > 10.0 {
                y.min(6400.0 / s)
            } else if v > 5.0 {
                y.min(12_800.0 / s)
            } else {
                y
            }
        }
        RunningIn::GreyIron => {
            let y = 0.275 * f_um;
            if v > 10.0 {
                y.min(11.0)
            } else if v > 5.0 {
                y.min(22.0)
            } else {
                y
            }
        }
        RunningIn::Hardened => (0.075 * f_um).min(3.0),
    };
    y * 1e-6
}

/// Amount of tip relief worn in by running-in, for gears without tip relief,
/// `C_ay = (1/18)(σ_Hlim/97 − 18.45)² + 1.5` µm (ISO 6336-1:2019 §6.5.9, `σ_Hlim` in N/mm²)
/// \[m\].
pub fn running_in_tip_relief(sigma_hlim: f64) -> f64 {
    let s = sigma_hlim / 1e6;
    ((s / 97.0 - 18.45).powi(2) / 18.0 + 1.5) * 1e-6
}

/// Single stiffness `c'` and mesh stiffness `c_γα` of a spur pair \[N/(mm·µm)\]
/// (ISO 6336-1:2019 §9.3, §9.4): `q' = C1 + C2/z1 + C3/z2 + C4 x1 + C5 x1/z1 + C6 x2 +
/// C7 x2/z2 + C8 x1² + C9 x2²` (Table 10: 0.047 23, 0.155 51, 0.257 91, −0.006 35, −0.116 54,
/// −0.001 93, −0.241 88, 0.005 29, 0.001 82; an internal gear counts as `z2 = ∞`),
/// `c'_th = 1/q'`, `c' = c'_th C_M C_R C_B` with `C_M` = 0.8, `C_R` = 1 (solid blanks),
/// `C_B = [1 + 0.5 (1.2 − h_fP/m)][1 − 0.02 (20° − α)]` averaged over both gears, times
/// `(K_A F_t/b / 100)^0.25` below 100 N/mm; `c_γα = c' (0.75 ε_α + 0.25)`.
/// `line_load` = `K_A F_t / b` \[N/m\], `dedendum` = `h_fP/m` of each gear, `alpha` \[rad\].
#[allow(clippy::too_many_arguments)]
pub fn mesh_stiffness(
    z1: f64,
    z2: f64,
    x1: f64,
    x2: f64,
    dedendum: [f64; 2],
    alpha: f64,
    contact_ratio: f64,
    line_load: f64,
) -> (f64, f64) {
    let inv_z2 = if z2 < 0.0 { 0.0 } else { 1.0 / z2 };
    let q = 0.04723 + 0.15551 / z1 + 0.25791 * inv_z2
        - 0.00635 * x1
        - 0.11654 * x1 / z1
        - 0.00193 * x2
        - 0.24188 * x2 * inv_z2
        + 0.00529 * x1 * x1
        + 0.00182 * x2 * x2;
    let c_th = 1.0 / q;
    let cb = |h: f64| (1.0 + 0.5 * (1.2 - h)) * (1.0 - 0.02 * (20.0 - alpha.to_degrees()));
    let c_b = 0.5 * (cb(dedendum[0]) + cb(dedendum[1]));
    let w = line_load / 1e3; // N/mm
    let load = if w < 100.0 {
        (w / 100.0).powf(0.25)
    } else {
        1.0
    };
    let c1 = c_th * 0.8 * c_b * load;
    (c1, c1 * (0.75 * contact_ratio + 0.25))
}

/// What `K_v` by method B needs.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DynamicInputs {
    /// Resonance ratio `N = n1/n_E1` \[-\].
    pub resonance_ratio: f64,
    /// Line load `K_A F_t / b` \[N/m\].
    pub line_load: f64,
    /// Single stiffness `c'` \[N/(mm·µm)\].
    pub single_stiffness: f64,
    /// Effective base pitch deviation `f_pb − y_p` \[m\].
    pub f_pb_eff: f64,
    /// Effective profile form deviation `f_fα − y_f` \[m\].
    pub f_fa_eff: f64,
    /// Tip relief `C_a` \[m\] (`C_ay` for gears without relief).
    pub tip_relief: f64,
    /// Total contact ratio `ε_γ` (= `ε_α` for spur gears) \[-\].
    pub total_contact_ratio: f64,
}

/// Resonance ratio `N = n1/n_E1`, `n_E1 = 30 000/(π z1) √(c_γα/m_red)` (ISO 6336-1:2019
/// §6.5.3, eqs. in mm, kg, µm), with `m_red = π/8 (d_m1/d_b1)² d_m1² / [1/ρ1 + 1/(ρ2 u²)]`
/// (both blanks of density `ρ`, so `m_red = m1*/(1 + 1/u²)`) for solid blanks of density `ρ` (§6.5.9; `d_m` the mean of tip and root diameters). For an
/// internal pair the ring's term is dropped (the ring taken as rigid against the pinion).
/// `omega1` \[rad/s\], the pinion's mean diameter `dm` and base diameter `db` \[m\], `density` \[kg/m³\], `c_ga` \[N/(mm·µm)\].
#[allow(clippy::too_many_arguments)]
pub fn resonance_ratio(
    omega1: f64,
    z1: f64,
    u: f64,
    internal: bool,
    dm: f64,
    db: f64,
    density: f64,
    c_ga: f64,
) -> f64 {
    let rho = density * 1e-9; // kg/mm³
    let (dm1, db1) = (dm * 1e3, db * 1e3);
    let m1 = PI / 8.0 * (dm1 / db1).powi(2) * dm1 * dm1 * rho;
    let m_red = if internal {
        m1
    } else {
        m1 / (1.0 + 1.0 / (u * u))
    };
    let n_e1 = 30_000.0 / (PI * z1) * (c_ga / m_red).sqrt();
    let n1 = omega1 * 30.0 / PI;
    n1 / n_e1
}

/// Dynamic factor `K_v` by ISO 6336-1:2019 method B (§6.5.4 to §6.5.8): with
/// `B_p = c' f_pb,eff/(K_A F_t/b)`, `B_f = c' f_fα,eff/(K_A F_t/b)`,
/// `B_k = |1 − c' C_a/(K_A F_t/b)|` (eqs. 15-17) and the coefficients `C_v1…C_v7` of
/// Table 8: subcritical `N ≤ N_S` `K_v = N (C_v1 B_p + C_v2 B_f + C_v3 B_k) + 1`; main
/// resonance `N_S < N ≤ 1.15` `K_v = C_v1 B_p + C_v2 B_f + C_v4 B_k + 1`; supercritical
/// `N ≥ 1.5` `K_v = C_v5 B_p + C_v6 B_f + C_v7`; linear between 1.15 and 1.5.
/// `N_S = 0.85`, or `0.5 + 0.35 √(K_A F_t/b / 100)` below 100 N/mm (eqs. 11, 12).
pub fn dynamic_factor_b(d: &DynamicInputs) -> Result<f64, GearError> {
    positive("line load K_A F_t/b", d.line_load)?;
    positive("single stiffness c'", d.single_stiffness)?;
    let eg = d.total_contact_ratio;
    require(eg > 1.0, "contact ratio", "must exceed 1", eg)?;
    let w = d.line_load / 1e3; // N/mm
    let cp = d.single_stiffness;
    let b_p = cp * d.f_pb_eff.max(0.0) * 1e6 / w;
    let b_f = cp * d.f_fa_eff.max(0.0) * 1e6 / w;
    let b_k = (1.0 - cp * d.tip_relief * 1e6 / w).abs();
    let (cv2, cv3, cv4, cv6) = if eg <= 2.0 {
        (0.34, 0.23, 0.90, 0.47)
    } else {
        (
            0.57 / (eg - 0.3),
            0.096 / (eg - 1.56),
            (0.57 - 0.05 * eg) / (eg - 1.44),
            0.12 / (eg - 1.74),
        )
    };
    let (cv1, cv5) = (0.32, 0.47);
    let cv7 = if eg <= 1.5 {
        0.75
    } else if eg <= 2.5 {
        0.125 * (PI * (eg - 2.0)).sin() + 0.875
    } else {
        1.0
    };
    let n_s = if w < 100.0 {
        0.5 + 0.35 * (w / 100.0).sqrt()
    } else {
        0.85
    };
    let n = d.resonance_ratio;
    let main = cv1 * b_p + cv2 * b_f + cv4 * b_k + 1.0;
    let superc = cv5 * b_p + cv6 * b_f + cv7;
    Ok(if n <= n_s {
        n * (cv1 * b_p + cv2 * b_f + cv3 * b_k) + 1.0
    } else if n <= 1.15 {
        main
    } else if n < 1.5 {
        superc + (main - superc) * (1.5 - n) / 0.35
    } else {
        superc
    })
}

/// Transverse load factors `(K_Hα, K_Fα)` by ISO 6336-1:2019 method B (§8.3.2, eqs. 73,
/// 74): `ε_γ ≤ 2`: `ε_γ/2 (0.9 + 0.4 c_γα (f_pb − y_α)/(F_tH/b))`; `ε_γ > 2`:
/// `0.9 + 0.4 √(2(ε_γ − 1)/ε_γ) c_γα (f_pb − y_α)/(F_tH/b)`; limited to
/// `1 ≤ K_Hα ≤ ε_γ/(ε_α Z_ε²)` and `1 ≤ K_Fα ≤ ε_γ/(0.25 ε_α + 0.75)` (§8.3.4, eqs. 75,
/// 76). `c_ga` \[N/(mm·µm)\], `f_pb_minus_y` \[m\], `f_th_per_b` = `F_t K_A K_v K_Hβ / b`
/// \[N/m\].
pub fn transverse_load_factors(
    contact_ratio: f64,
    z_eps: f64,
    c_ga: f64,
    f_pb_minus_y: f64,
    f_th_per_b: f64,
) -> (f64, f64) {
    let eg = contact_ratio;
    let term = c_ga * f_pb_minus_y.max(0.0) * 1e6 / (f_th_per_b / 1e3);
    let k = if eg <= 2.0 {
        eg / 2.0 * (0.9 + 0.4 * term)
    } else {
        0.9 + 0.4 * (2.0 * (eg - 1.0) / eg).sqrt() * term
    };
    let kh = k.min(eg / (contact_ratio * z_eps * z_eps)).max(1.0);
    let kf = k.min(eg / (0.25 * contact_ratio + 0.75)).max(1.0);
    (kh, kf)
}

/// Face load factor for the root stress `K_Fβ = K_Hβ^N_F`,
/// `N_F = (b/h)² / (1 + b/h + (b/h)²)` with `b/h` the smaller of the two gears' face width
/// to tooth depth ratios, not below 3 (ISO 6336-1:2019 §7.6, eqs. 70, 71).
pub fn face_load_factor_root(k_hbeta: f64, b_over_h: f64) -> f64 {
    let r = b_over_h.max(3.0);
    let n_f = r * r / (1.0 + r + r * r);
    k_hbeta.powf(n_f)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn deviations_are_the_iso_1328_table_values() {
        // ISO 1328-1:1995 Table 1, ±f_pt for 50 < d ≤ 125 mm, 2 < m ≤ 3.5 mm, grades 5 to
        // 12: 6.0, 8.5, 12, 17, 23, 33, 47, 66 µm; Table 3, f_fα, grades 5 to 8: 6.0, 8.5, 12,
        // 17 µm. Printed values, so exact to their rounding (1e-9 µm here). Any m and d in
        // the ranges give them: the tables use the ranges' geometric means, so the gear's own
        // d = 120 mm, m = 2.5 mm (the formula with them: 12.13 µm at grade 7) must not show.
        let f_pt = [6.0, 8.5, 12.0, 17.0, 23.0, 33.0, 47.0, 66.0];
        let f_fa = [6.0, 8.5, 12.0, 17.0];
        for (k, want) in f_pt.iter().enumerate() {
            let q = 5.0 + k as f64;
            for (m, d) in [(2.5e-3, 120e-3), (3.5e-3, 51e-3), (2.01e-3, 80e-3)] {
                let (pt, fa) = iso1328_deviations(m, d, q).unwrap();
                assert!(
                    (pt * 1e6 - want).abs() < 1e-9,
                    "grade {q}: f_pt {}",
                    pt * 1e6
                );
                if k < f_fa.len() {
                    assert!(
                        (fa * 1e6 - f_fa[k]).abs() < 1e-9,
                        "grade {q}: f_fα {}",
                        fa * 1e6
                    );
                }
            }
        }
    }

    #[test]
    fn subcritical_kv_is_one_at_standstill_and_grows_with_n() {
        let mut d = DynamicInputs {
            resonance_ratio: 0.0,
            line_load: 300e3,
            single_stiffness: 14.0,
            f_pb_eff: 10e-6,
            f_fa_eff: 8e-6,
            tip_relief: 0.0,
            total_contact_ratio: 1.6,
        };
        assert_eq!(dynamic_factor_b(&d).unwrap(), 1.0);
        d.resonance_ratio = 0.5;
        let a = dynamic_factor_b(&d).unwrap();
        d.resonance_ratio = 0.8;
        assert!(dynamic_factor_b(&d).unwrap() > a && a > 1.0);
    }

    #[test]
    fn kv_is_continuous_across_the_intermediate_range() {
        // Eq. (22) interpolates linearly, so K_v meets the main-resonance value at 1.15 and
        // the supercritical one at 1.5 (to rounding).
        let mut d = DynamicInputs {
            resonance_ratio: 1.15,
            line_load: 300e3,
            single_stiffness: 14.0,
            f_pb_eff: 10e-6,
            f_fa_eff: 8e-6,
            tip_relief: 0.0,
            total_contact_ratio: 1.6,
        };
        let at = |d: &mut DynamicInputs, n: f64| {
            d.resonance_ratio = n;
            dynamic_factor_b(d).unwrap()
        };
        assert!((at(&mut d, 1.15) - at(&mut d, 1.15 + 1e-9)).abs() < 1e-6);
        assert!((at(&mut d, 1.5) - at(&mut d, 1.5 - 1e-9)).abs() < 1e-6);
    }
}
