//! The skirt and sliding-contact models.

use cardan_friction::{coulomb_sliding, karhula_skirt, viscous_skirt, ViscousSkirt};
use std::f64::consts::PI;

#[test]
fn sliding_contacts() {
    // Karhula A9.1.5: μ_skirt = 0.09 on the side force; P = F|v| (A9.1.8). 1000 N side force
    // at −4 m/s: F = 90 N, P = 360 W (exact decimals). Zero speed: zero power.
    let s = karhula_skirt(-1000.0, -4.0);
    assert!((s.friction_force - 90.0).abs() < 1e-12);
    assert!((s.power - 360.0).abs() < 1e-12);
    assert_eq!(coulomb_sliding(0.15, 500.0, 0.0).power, 0.0);
}

#[test]
fn viscous_skirt_scales_as_couette_flow() {
    // Thai eqs 2.5.c.1–2 are a Couette film: the force is linear in μ and U and inverse in the
    // clearance, the power is F·U (so quadratic in U), and nothing moves at U = 0. The cycle
    // mean of the instantaneous power for a harmonic stroke U = (π/2) S̄p sin θ is π²/8 times
    // the power at the mean speed S̄p (the thesis's eq. 2.5.c.3 reading): ⟨sin²⟩ = ½, exact
    // for the 3600-point rectangle rule up to rounding (1e-9).
    let sk = ViscousSkirt::new(0.09, 0.05, 20e-6).unwrap();
    let (mu, u) = (0.01, 7.0);
    let v = viscous_skirt(&sk, mu, u);
    let r = |a: f64, b: f64| assert!((a / b - 1.0).abs() < 1e-12, "{a} vs {b}");
    r(
        viscous_skirt(&sk, 2.0 * mu, u).friction_force,
        2.0 * v.friction_force,
    );
    r(
        viscous_skirt(&sk, mu, 3.0 * u).friction_force,
        3.0 * v.friction_force,
    );
    r(viscous_skirt(&sk, mu, -3.0 * u).power, 9.0 * v.power);
    let wide = ViscousSkirt::new(0.09, 0.05, 40e-6).unwrap();
    r(
        viscous_skirt(&wide, mu, u).friction_force,
        0.5 * v.friction_force,
    );
    r(v.power, v.friction_force * u);
    let n = 3600;
    let mean: f64 = (0..n)
        .map(|i| {
            let th = 2.0 * PI * i as f64 / n as f64;
            viscous_skirt(&sk, mu, PI / 2.0 * u * th.sin()).power
        })
        .sum::<f64>()
        / n as f64;
    assert!((mean / v.power - PI * PI / 8.0).abs() < 1e-9);
    assert_eq!(viscous_skirt(&sk, mu, 0.0).power, 0.0);
}
