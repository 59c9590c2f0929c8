//! Shared set-up for the balance tests: machines from the registry, and the closed forms they
//! are checked against (`docs/validation/balance.md`).
#![allow(dead_code)]

use cardan_mechanism::{entry, MachineGeometry, MassInputs, Mechanism, Options};

/// The thesis machine of Karhula (2008): crank 0.06 m, rod 0.14 m, bore 0.12 m.
pub const THESIS: MachineGeometry = MachineGeometry {
    crank_length: 0.06,
    rod_length: 0.14,
    bore: 0.12,
    pin_offset: 0.0,
};

/// The registered mechanism `name` on `geometry` with `masses`.
pub fn machine(name: &str, geometry: &MachineGeometry, masses: &MassInputs) -> Box<dyn Mechanism> {
    (entry(name).unwrap().build)(geometry, masses, &Options::new()).unwrap()
}

/// A machine of crank `crank` and rod `rod` (m) whose only moving mass is `piston` (kg): the
/// textbooks' reciprocating mass at the piston pin, no rod mass.
pub fn pistons_only(name: &str, crank: f64, rod: f64, piston: f64) -> Box<dyn Mechanism> {
    let geometry = MachineGeometry {
        crank_length: crank,
        rod_length: rod,
        bore: 0.1,
        pin_offset: 0.0,
    };
    let masses = MassInputs {
        rod_mass: Some(0.0),
        rod_inertia: Some(0.0),
        piston_mass: Some(piston),
        crankshaft_inertia: Some(0.0),
        ..MassInputs::default()
    };
    machine(name, &geometry, &masses)
}

/// binom(1/2, n)·(−1)ⁿ: the coefficients of √(1 − u) = Σ cₙ·uⁿ.
fn sqrt_coefficient(n: usize) -> f64 {
    (0..n).fold(1.0, |c, i| c * (0.5 - i as f64) / (i + 1) as f64)
        * if n % 2 == 0 { 1.0 } else { -1.0 }
}

/// binom(n, k) as a float.
fn binomial(n: usize, k: usize) -> f64 {
    (0..k).fold(1.0, |b, i| b * (n - i) as f64 / (i + 1) as f64)
}

/// q_k(λ): the in-line slider-crank piston's acceleration harmonic of order k over r·ω² at
/// constant speed, exact (the series summed until its terms vanish), λ = r/l.
///
/// With φ the crank angle from top dead centre, x = r·cos φ + l·√(1 − λ²·sin²φ). By the binomial
/// series of the root and sin²ⁿφ = 4⁻ⁿ·[C(2n,n) + 2·Σ_j (−1)ʲ·C(2n, n−j)·cos 2jφ], the root's
/// cos 2jφ coefficient is s_j = Σ_{n≥j} cₙ·λ²ⁿ·2·4⁻ⁿ·(−1)ʲ·C(2n, n−j); twice differentiated, the
/// order 2j of the acceleration is (2j)²·l·|s_j|·ω² = r·ω²·(2j)²·|s_j|/λ. Odd orders above the
/// first vanish; the first is exactly r·ω². Order 2: λ + λ³/4 + 15λ⁵/128 + …; order 4:
/// λ³/4 + 3λ⁵/16 + …; order 6: 9λ⁵/128 + … (`docs/validation/balance.md`).
pub fn q(k: usize, lambda: f64) -> f64 {
    if k == 1 {
        return 1.0;
    }
    if k % 2 == 1 || k == 0 {
        return 0.0;
    }
    let j = k / 2;
    let mut s = 0.0;
    for n in j..200 {
        let term = sqrt_coefficient(n) * lambda.powi(2 * n as i32) * 2.0 / 4f64.powi(n as i32)
            * binomial(2 * n, n - j);
        s += term;
        if term.abs() < 1e-20 {
            break;
        }
    }
    (k * k) as f64 * s.abs() / lambda
}
