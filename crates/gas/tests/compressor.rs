//! The reciprocating compressor (`cardan_gas::compressor`) against its closed forms, a
//! textbook example and the dynamics crate.
//!
//! Tolerances: closed-form identities are exact up to round-off (1e-12); the numerical ∮ p dV
//! (midpoint rule, 36 000 steps per revolution) and the dynamics' torque integral (trapezoidal
//! rule, 36 000 steps) carry an O(h²) error at the four valve events where dp/dV jumps, about
//! 1e-8 relative, so they are checked at 1e-6; the steady state is converged to 1e-12 of the
//! inducted mass and checked at 1e-9. Every `close` is relative to the expected value, with no
//! floor (0.0).

use cardan_dynamics::{run_summary, Solver};
use cardan_gas::compressor::{Compressor, IndicatorDiagram, AIR_GAS_CONSTANT};
use cardan_gas::{Chamber, Cylinder, GasCycle, GasError, GasModel, Volume};
use cardan_mechanism::{CrankMotion, Grid, MachineGeometry, MassInputs, Mechanism, Options};
use cardan_testing::close;
use std::f64::consts::PI;

const SPEED: f64 = 100.0 * PI; // 3000 rpm

/// The slider-crank and the cardan gear, by registry name.
const MECHANISMS: [&str; 2] = ["slider_crank", "cardan_gear"];

/// Karhula's thesis machine (r = 0.06 m, l = 0.14 m, bore 0.12 m, rod centre of gravity at
/// 0.07 m) as `name`; the cardan gear of the same stroke (its crank is 0.03 m).
fn mechanism(name: &str) -> Box<dyn Mechanism> {
    let geometry = MachineGeometry {
        crank_length: 0.06,
        rod_length: 0.14,
        bore: 0.12,
        pin_offset: 0.0,
    };
    let masses = MassInputs {
        rod_cg: Some(0.07),
        ..MassInputs::default()
    };
    (cardan_mechanism::entry(name).unwrap().build)(&geometry, &masses, &Options::new()).unwrap()
}

/// A 120 mm bore on a mechanism's volume curve, clearance `clearance`·V_s.
fn with_chamber<R>(mech: &dyn Mechanism, clearance: f64, f: impl FnOnce(&Chamber) -> R) -> R {
    let swept = PI / 4.0 * 0.12 * 0.12 * mech.stroke();
    Cylinder::with_clearance(0.12, swept, clearance * swept)
        .unwrap()
        .with_chamber(mech, f)
}

/// A harmonic volume curve V = V_c + V_s·(1 − cos(θ − 90°))/2: the model needs no mechanism.
fn with_harmonic<R>(cylinder: Cylinder, f: impl FnOnce(&Chamber) -> R) -> R {
    let (vc, vs) = (cylinder.clearance_volume, cylinder.swept_volume);
    let volume = move |theta: f64| Volume {
        volume: vc + 0.5 * vs * (1.0 - (theta - PI / 2.0).cos()),
        rate: 0.5 * vs * (theta - PI / 2.0).sin(),
    };
    f(&Chamber {
        cylinder,
        tdc_angle: PI / 2.0,
        volume: &volume,
        piston: None,
    })
}

fn metric(gas: &GasCycle, name: &str) -> f64 {
    gas.metric(name)
        .unwrap_or_else(|| panic!("no metric {name}"))
}

fn air(delivery: f64, n: f64) -> Compressor {
    Compressor::air(1e5, 293.15, delivery, n).unwrap()
}

fn cylinder(clearance: f64) -> Cylinder {
    Cylinder::with_clearance(0.1, 1e-3, clearance * 1e-3).unwrap()
}

#[test]
fn zero_clearance_inducts_the_whole_swept_volume() {
    let c = air(8e5, 1.3);
    let cyl = cylinder(0.0);
    let (d, cycles) = c.steady_state(&cyl).unwrap();
    assert_eq!(cycles, 1, "nothing is left over to settle");
    assert!((d.volumetric_efficiency() - 1.0).abs() <= 1e-12);
    assert_eq!(d.points[3].volume, 0.0, "no re-expansion volume");
    assert_eq!(d.mass_balance(), 0.0);
    // Without a residual the charge is at the suction temperature (T_1 = T_s).
    close("T_1", d.points[0].temperature, 293.15, 1e-12, 0.0);
    let gas = with_harmonic(cyl, |ch| c.cycle(ch, SPEED, &[PI / 2.0 + 0.3]).unwrap());
    assert!((metric(&gas, "volumetric_efficiency") - 1.0).abs() <= 1e-12);
    // The suction stroke is at p_s: no piston force against the crankcase at p_s.
    assert_eq!(gas.pressure, [1e5]);
    assert_eq!(gas.piston_force, [0.0]);
}

#[test]
fn isothermal_limit_is_ps_vin_ln_r() {
    let cyl = cylinder(0.05);
    let (ps, pd) = (1e5, 8e5);
    let r: f64 = pd / ps;
    // Isothermal re-expansion: V_4 = V_c·r.
    let isothermal = ps * (cyl.max_volume() - cyl.clearance_volume * r) * r.ln();
    close(
        "n = 1",
        air(pd, 1.0).closed_form_work(&cyl).unwrap(),
        isothermal,
        1e-14,
        0.0,
    );
    // n − 1 = 1e-6 moves the work by about (n − 1)·ln r ≈ 2e-6 relative.
    let near = air(pd, 1.000_001).closed_form_work(&cyl).unwrap();
    close("n = 1.000001", near, isothermal, 1e-5, 0.0);
    assert!(near > isothermal, "polytropic work exceeds isothermal work");
    // The specific energy is R·T_s·ln r at n = 1 ([CB] ch. 7).
    let gas = with_harmonic(cyl, |ch| air(pd, 1.0).cycle(ch, SPEED, &[]).unwrap());
    close(
        "isothermal specific energy",
        metric(&gas, "specific_energy"),
        AIR_GAS_CONSTANT * 293.15 * r.ln(),
        1e-6,
        0.0,
    );
}

/// −∮ p dV of the pressure trace `cycle` returns, over one revolution from TDC, by the midpoint
/// rule on the volume with its own grid (50 000 steps).
fn trace_work(model: &Compressor, ch: &Chamber) -> f64 {
    let n = 50_000;
    let h = 2.0 * PI / n as f64;
    let mids: Vec<f64> = (0..n).map(|k| PI / 2.0 + h * (k as f64 + 0.5)).collect();
    let gas = model.cycle(ch, SPEED, &mids).unwrap();
    let v = |k: usize| (ch.volume)(PI / 2.0 + h * k as f64).volume;
    (0..n).map(|k| -gas.pressure[k] * (v(k + 1) - v(k))).sum()
}

#[test]
fn numeric_work_on_both_mechanisms_matches_the_closed_form() {
    for n in [1.0, 1.3] {
        for name in MECHANISMS {
            let c = air(8e5, n);
            let mech = mechanism(name);
            with_chamber(mech.as_ref(), 0.05, |ch| {
                let closed = c.closed_form_work(&ch.cylinder).unwrap();
                let label = format!("{name} n = {n}");
                close(&label, c.indicated_work(ch).unwrap(), closed, 1e-6, 0.0);
                close(&label, trace_work(&c, ch), closed, 1e-6, 0.0);
                let gas = c.cycle(ch, SPEED, &[]).unwrap();
                close(
                    &label,
                    metric(&gas, "indicated_power"),
                    closed * SPEED / (2.0 * PI),
                    1e-6,
                    0.0,
                );
            });
        }
    }
}

#[test]
fn dynamics_gas_work_is_the_pdv_work() {
    for name in MECHANISMS {
        let c = Compressor::new(1e5, 293.15, 8e5, 1.35, 1.25, AIR_GAS_CONSTANT).unwrap();
        let mech = mechanism(name);
        let motion = CrankMotion {
            start_angle: PI / 2.0,
            initial_speed: SPEED,
            angular_acceleration: 0.0,
        };
        let mut grid = Grid::new(motion, PI / 2.0, 2.5 * PI, 36_000);
        let (summary, work, power) = with_chamber(mech.as_ref(), 0.05, |ch| {
            let gas = c.prepare(*ch, SPEED).unwrap();
            let at = |theta: f64| gas.at(theta);
            let (_, summary) = run_summary(
                mech.as_ref(),
                &mut grid,
                Some(&at),
                Solver::ClosedForm,
                false,
            )
            .unwrap();
            let power = gas
                .metrics()
                .iter()
                .find(|m| m.name == "indicated_power")
                .expect("no metric indicated_power")
                .value;
            (summary, c.indicated_work(ch).unwrap(), power)
        });
        close(name, summary.get("gas_work").unwrap(), work, 1e-6, 0.0);
        close(
            name,
            summary.get("gas_power_mean").unwrap(),
            power,
            1e-6,
            0.0,
        );
    }
}

#[test]
fn mass_balance_closes_at_the_steady_state_only() {
    for (nc, ne) in [(1.3, 1.3), (1.4, 1.2), (1.0, 1.0)] {
        let c = Compressor::new(1e5, 293.15, 8e5, nc, ne, AIR_GAS_CONSTANT).unwrap();
        let cyl = cylinder(0.06);
        let first: IndicatorDiagram = c.cycles(&cyl).unwrap().next().unwrap();
        let (d, cycles) = c.steady_state(&cyl).unwrap();
        let label = format!("n_c = {nc}, n_e = {ne}");
        assert!(
            nc == 1.0 || first.mass_balance().abs() > 1e-3 * first.inducted_mass,
            "{label}: the cold first cycle should not balance, {first:?}"
        );
        assert!(cycles > 1 || nc == 1.0, "{label}: {cycles} cycles");
        assert!(
            d.mass_balance().abs() <= 1e-9 * d.inducted_mass,
            "{label}: {d:?}"
        );
        // Steady-state residual m_res = m_in·V_c/(V_2 − V_c): the fixed point of
        // m_res' = (V_c/V_2)·(m_res + m_in).
        let v = d.points.map(|p| p.volume);
        close(
            &label,
            d.points[3].mass,
            d.inducted_mass * v[2] / (v[1] - v[2]),
            1e-9,
            0.0,
        );
        close(&label, d.points[2].mass, d.points[3].mass, 1e-9, 0.0);
        if nc == ne {
            // With equal exponents the steady charge starts compression at T_s ([EM] ch. 9).
            close(&label, d.points[0].temperature, 293.15, 1e-9, 0.0);
        }
        let gas = with_harmonic(cyl, |ch| c.cycle(ch, SPEED, &[]).unwrap());
        close(
            &label,
            metric(&gas, "delivered_mass_flow"),
            d.inducted_mass * SPEED / (2.0 * PI),
            1e-12,
            0.0,
        );
    }
}

#[test]
fn volumetric_efficiency_falls_with_clearance_and_pressure_ratio() {
    let eta = |clearance: f64, delivery: f64| {
        let (d, _) = air(delivery, 1.3)
            .steady_state(&cylinder(clearance))
            .unwrap();
        let want = 1.0 - clearance * ((delivery / 1e5).powf(1.0 / 1.3) - 1.0);
        close("η_v formula", d.volumetric_efficiency(), want, 1e-12, 0.0);
        d.volumetric_efficiency()
    };
    let by_clearance: Vec<f64> = [0.0, 0.02, 0.05, 0.1].map(|c| eta(c, 8e5)).into();
    let by_ratio: Vec<f64> = [2e5, 4e5, 8e5, 12e5].map(|p| eta(0.05, p)).into();
    for w in [by_clearance, by_ratio] {
        assert!(w.windows(2).all(|p| p[1] < p[0]), "{w:?}");
    }
}

/// A single-stage double-acting air compressor of the textbook kind, worked by hand (no
/// published answer is used: the textbook example these inputs were once remembered from could
/// not be read, `docs/validation.md`): 14 m³/min free air delivery at 1.013 bar, 15 °C; delivery
/// 7 bar; 300 rev/min; clearance 5 % of the swept volume; n = 1.3.
///
/// By hand (T_s = 288 K for 15 °C; R = 287.05): r = 7/1.013 = 6.910 168;
/// r^(1/1.3) = 4.423 443; η_v = 1 + 0.05 − 0.05·4.423 443 = 0.828 828; two strokes per
/// revolution give 600 suctions/min, so V_s = (14/600)/0.828 828 = 0.028 152 21 m³;
/// r^(0.3/1.3) = 1.562 169, T_d = 288·1.562 169 = 449.904 8 K; W = (1.3/0.3)·1.013e5·(14/600)·
/// 0.562 169 = 5 758.052 J per stroke, P = 10·W = 57 580.52 W; m = p_s·(14/600)/(R·T_s) =
/// 0.028 591 45 kg per stroke. A double-acting cylinder (piston rod neglected) is one chamber at
/// 600 cycles/min.
#[test]
fn double_acting_compressor_worked_by_hand() {
    let c = Compressor::air(1.013e5, 288.0, 7e5, 1.3).unwrap();
    let probe = Cylinder::with_clearance(0.3, 1.0, 0.05).unwrap();
    let eta = c.steady_state(&probe).unwrap().0.volumetric_efficiency();
    close("η_v (hand)", eta, 0.828_827_838_8, 1e-9, 0.0);
    let swept = 14.0 / 600.0 / eta;
    close("V_s (hand)", swept, 0.028_152_207_54, 1e-9, 0.0);

    let cyl = Cylinder::with_clearance(0.3, swept, 0.05 * swept).unwrap();
    let speed = 600.0 * 2.0 * PI / 60.0;
    let gas = with_harmonic(cyl, |ch| c.cycle(ch, speed, &[]).unwrap());
    let t_d = metric(&gas, "discharge_temperature");
    let power = metric(&gas, "indicated_power");
    close("T_d (hand)", t_d, 449.904_798_3, 1e-9, 0.0);
    close("power (hand)", power, 57_580.517_05, 1e-6, 0.0);
    close(
        "mass flow (hand)",
        metric(&gas, "delivered_mass_flow"),
        0.285_914_507_1,
        1e-9,
        0.0,
    );
    close(
        "specific energy (hand)",
        metric(&gas, "specific_energy"),
        57_580.517_05 / 0.285_914_507_1,
        1e-6,
        0.0,
    );
}

fn field(e: Result<impl std::fmt::Debug, GasError>) -> &'static str {
    e.expect_err("should be refused").field
}

#[test]
fn bad_inputs_name_their_field() {
    let r = AIR_GAS_CONSTANT;
    let new = |ps, ts, pd, nc, ne, r| Compressor::new(ps, ts, pd, nc, ne, r);
    assert_eq!(
        field(new(8e5, 293.0, 1e5, 1.3, 1.3, r)),
        "delivery_pressure"
    );
    assert_eq!(
        field(new(1e5, 293.0, 1e5, 1.3, 1.3, r)),
        "delivery_pressure"
    );
    assert_eq!(
        field(new(1e5, 293.0, 8e5, 0.99, 1.3, r)),
        "compression_exponent"
    );
    assert_eq!(
        field(new(1e5, 293.0, 8e5, 1.3, 0.5, r)),
        "expansion_exponent"
    );
    assert_eq!(
        field(new(-1e5, 293.0, 8e5, 1.3, 1.3, r)),
        "suction_pressure"
    );
    assert_eq!(
        field(new(1e5, -1.0, 8e5, 1.3, 1.3, r)),
        "suction_temperature"
    );
    assert_eq!(
        field(new(1e5, f64::NAN, 8e5, 1.3, 1.3, r)),
        "suction_temperature"
    );
    assert_eq!(
        field(new(1e5, 293.0, f64::INFINITY, 1.3, 1.3, r)),
        "delivery_pressure"
    );
    assert_eq!(
        field(new(1e5, 293.0, 8e5, f64::NAN, 1.3, r)),
        "compression_exponent"
    );
    assert_eq!(field(new(1e5, 293.0, 8e5, 1.3, 1.3, 0.0)), "gas_constant");
    assert!(
        new(1e5, 293.0, 8e5, 1.0, 1.0, r).is_ok(),
        "n = 1 is isothermal"
    );

    // Public fields set past `new` are checked again, without panicking.
    let mut c = air(8e5, 1.3);
    c.delivery_pressure = 0.5e5;
    let cyl = cylinder(0.05);
    let out = with_harmonic(cyl, |ch| c.cycle(ch, SPEED, &[0.0, 1.0]));
    assert_eq!(field(out), "delivery_pressure");

    // 5 % clearance re-expands to V_1 at r = 21^1.3 ≈ 52.4: beyond it nothing is delivered.
    let too_high = air(60e5, 1.3);
    assert_eq!(field(too_high.steady_state(&cyl)), "delivery_pressure");
    assert_eq!(field(too_high.closed_form_work(&cyl)), "delivery_pressure");
    assert!(air(50e5, 1.3).steady_state(&cyl).is_ok());
}
