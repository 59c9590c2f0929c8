//! Karhula's totals and efficiency definitions (A9.1.56–75), the accumulator, and the skirt
//! and sliding-contact models.

use cardan_friction::{
    coulomb_sliding, engine_mechanical_efficiency, engine_output_power, karhula_skirt,
    power_to_torque, pump_mechanical_efficiency, pump_power_need, thai_skirt_mean_power,
    viscous_skirt, MachineLosses, ViscousSkirt, WorkAccumulator,
};
use std::f64::consts::PI;

#[test]
fn karhula_totals_and_efficiencies() {
    // Definitions A9.1.56–75 on round numbers (exact decimal arithmetic, 1e-12 relative):
    // losses 120 + 80 + 50 = 250 W; pump need 2000 + 250 = 2250 W; engine output
    // 5000 − 250 = 4750 W; torque 2250 W / 150 rad/s = 15 N·m;
    // η_pump = 900/(1000 + 125) = 0.8; η_eng = (2000 − 250)/2000 = 0.875.
    let l = MachineLosses {
        piston: 120.0,
        bearings: 80.0,
        gear_mesh: 50.0,
    };
    let r = |a: f64, b: f64| assert!((a / b - 1.0).abs() < 1e-12, "{a} vs {b}");
    r(l.total(), 250.0);
    r(pump_power_need(2000.0, l.total()), 2250.0);
    r(engine_output_power(5000.0, l.total()), 4750.0);
    r(power_to_torque(2250.0, 150.0), 15.0);
    r(pump_mechanical_efficiency(900.0, 1000.0, 125.0), 0.8);
    r(engine_mechanical_efficiency(2000.0, 250.0), 0.875);
}

#[test]
fn accumulator_integrates_a_cycle() {
    // ∫₀^{2π} P0 (1 + sin θ) dθ/ω = 2π P0/ω exactly; the left-point rule integrates a full
    // period of a sinusoid exactly (discrete orthogonality), so the error is rounding only:
    // 1e-12 relative. Mean torque = W/(2π) = P0/ω.
    let (p0, w, n) = (300.0, 100.0, 720);
    let mut acc = WorkAccumulator::new();
    let d = 2.0 * PI / n as f64;
    for i in 0..n {
        acc.add_angle_step(p0 * (1.0 + (i as f64 * d).sin()), d, w);
    }
    assert!((acc.work / (2.0 * PI * p0 / w) - 1.0).abs() < 1e-12);
    assert!((acc.mean_power() / p0 - 1.0).abs() < 1e-12);
    assert!((acc.mean_torque() / (p0 / w) - 1.0).abs() < 1e-12);
    assert!((acc.time - 2.0 * PI / w).abs() < 1e-15);
}

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
fn viscous_skirt_against_thai_eq() {
    // Thai eq. 2.5.c.3 evaluated at a constant speed U equals F·U of eqs 2.5.c.1–2 (the
    // instantaneous form) — two different expressions of the thesis; and the cycle mean of
    // the instantaneous form for U = (π/2) S̄p sin θ is (π²/8) × the thesis's mean-speed
    // power (exact for a harmonic stroke; 1e-9 from the 3600-point quadrature).
    let sk = ViscousSkirt::new(0.09, 0.05, 20e-6).unwrap();
    let (mu, u) = (0.01, 7.0);
    let v = viscous_skirt(&sk, mu, u);
    assert!((v.power / thai_skirt_mean_power(&sk, mu, u) - 1.0).abs() < 1e-12);
    assert!((v.power - v.friction_force * u).abs() < 1e-9);
    let n = 3600;
    let mean: f64 = (0..n)
        .map(|i| {
            let th = 2.0 * PI * i as f64 / n as f64;
            viscous_skirt(&sk, mu, PI / 2.0 * u * th.sin()).power
        })
        .sum::<f64>()
        / n as f64;
    assert!((mean / thai_skirt_mean_power(&sk, mu, u) - PI * PI / 8.0).abs() < 1e-9);
    assert_eq!(viscous_skirt(&sk, mu, 0.0).power, 0.0);
}
