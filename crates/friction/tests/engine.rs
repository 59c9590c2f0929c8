//! Engine-level correlations against `docs/validation/engine-friction.md` and the
//! Thai thesis (Bishop).

use cardan_friction::engine::BISHOP_EXHAUST_FULL_LOAD;
use cardan_friction::{
    bishop_pumps_misc_mep, bishop_throttling_mep, cam_drive_torque, flat_follower_friction,
    follower_load, mep_power, pnh_fmep, Follower, PnhEngine, PnhVariant, ShaftBearings, Valvetrain,
};
use std::f64::consts::PI;

fn round_engine() -> PnhEngine {
    // docs/validation/engine-friction.md, the round engine: B = S = 100 mm, 1 cylinder, r_c = 8, mains 2 × (50, 20 mm), rod 1 × (40,
    // 20 mm), 2 cam bearings, 2 valves, L_v = 10 mm, OHV flat follower.
    PnhEngine {
        bore: 0.1,
        stroke: 0.1,
        cylinders: 1,
        compression_ratio: 8.0,
        main_bearings: ShaftBearings {
            count: 2,
            diameter: 0.05,
            length: 0.02,
        },
        rod_bearings: ShaftBearings {
            count: 1,
            diameter: 0.04,
            length: 0.02,
        },
        cam_bearings: 2,
        valves: 2,
        max_valve_lift: 0.01,
        valvetrain: Valvetrain::Ohv,
        follower: Follower::Flat,
    }
}

const RPM1000: f64 = 1000.0 * 2.0 * PI / 60.0;

fn rel(got: f64, want: f64, tol: f64) {
    assert!(
        ((got - want) / want).abs() <= tol,
        "got {got}, want {want} (rel {tol})"
    );
}

#[test]
fn pnh_round_engine_breakdown() {
    // The round engine (derived); each term is an exact decimal of the hand formula (e.g. seals
    // 1.22e5·50/(100²·100) = 6.1 kPa), so 1e-9 relative (floating-point rounding of the unit
    // conversions only). Gas loading is printed 21.7454 (4 decimals): ±5e-5 kPa; the group sums
    // and the total are printed with 3 decimals: ±5e-4 kPa.
    let f = pnh_fmep(&round_engine(), PnhVariant::Pnh1989, RPM1000, 1e5, 1e5);
    let kpa = |x: f64| x / 1e3;
    rel(kpa(f.crank_seals), 6.1, 1e-9);
    rel(kpa(f.main_bearings), 1.515, 1e-9);
    rel(kpa(f.turbulent_dissipation), 0.675, 1e-9);
    rel(kpa(f.skirt), 9.8, 1e-9);
    rel(kpa(f.rings), 8.12, 1e-9);
    rel(kpa(f.rod_bearings), 0.38784, 1e-9);
    assert!((kpa(f.gas_loading) - 21.7454).abs() <= 5e-5);
    rel(kpa(f.cam_bearings), 4.608, 1e-9);
    rel(kpa(f.follower), 16.0, 1e-9);
    rel(kpa(f.oscillating_hydrodynamic), 0.1, 1e-9);
    rel(kpa(f.oscillating_mixed), 12.84, 1e-9);
    rel(kpa(f.auxiliaries), 11.271, 1e-9);
    assert!((kpa(f.crankshaft()) - 8.290).abs() <= 5e-4);
    assert!((kpa(f.reciprocating()) - 40.053).abs() <= 5e-4);
    assert!((kpa(f.valvetrain()) - 33.548).abs() <= 5e-4);
    assert!((kpa(f.total()) - 93.162).abs() <= 5e-4);
}

#[test]
fn sandoval_heywood_update() {
    // Derived by hand from docs/validation/engine-friction.md: with ν = ν0 only the boundary factor changes,
    // 1 + 1000/N = 2 → 1 + 500/N = 1.5 at 1000 rpm: rings 4.06e4·1.5/100² = 6.09 kPa,
    // follower 400·1.5·2/100 = 12 kPa, oscillating mixed 32.1·1.5·10·2/100 = 9.63 kPa.
    // With ν/ν0 = 4 the hydrodynamic terms double: mains 3.03, skirt 19.6, rod 0.77568,
    // cam bearings 0.976 + 4.12 = 5.096, osc. hydro 0.2 kPa, gas term
    // 6.89·(0.088·8·2 + 0.182·8^1.25067) = 26.5960 (4 decimals, ±5e-5). Exact decimals: 1e-9.
    let e = round_engine();
    let f = pnh_fmep(
        &e,
        PnhVariant::SandovalHeywood2003 {
            viscosity_ratio: 1.0,
        },
        RPM1000,
        1e5,
        1e5,
    );
    rel(f.rings / 1e3, 6.09, 1e-9);
    rel(f.follower / 1e3, 12.0, 1e-9);
    rel(f.oscillating_mixed / 1e3, 9.63, 1e-9);
    rel(f.main_bearings / 1e3, 1.515, 1e-9);
    let g = pnh_fmep(
        &e,
        PnhVariant::SandovalHeywood2003 {
            viscosity_ratio: 4.0,
        },
        RPM1000,
        1e5,
        1e5,
    );
    rel(g.main_bearings / 1e3, 3.03, 1e-9);
    rel(g.skirt / 1e3, 19.6, 1e-9);
    rel(g.rod_bearings / 1e3, 0.77568, 1e-9);
    rel(g.cam_bearings / 1e3, 5.096, 1e-9);
    rel(g.oscillating_hydrodynamic / 1e3, 0.2, 1e-9);
    rel(g.crank_seals / 1e3, 6.1, 1e-9);
    rel(g.turbulent_dissipation / 1e3, 0.675, 1e-9);
    assert!(
        (g.gas_loading / 1e3 - 26.5960).abs() <= 5e-5,
        "{}",
        g.gas_loading
    );
}

#[test]
fn mep_power_of_four_stroke() {
    // Thai eq. 2.5.e.3.2: P = mep·V_d·N/(60·2). 100 kPa, 1 L, 3000 rpm → 100e3·1e-3·25 =
    // 2500 W exactly (1e-12 relative: rounding of 2π/60 conversions).
    let p = mep_power(100e3, 1e-3, 3000.0 * 2.0 * PI / 60.0, 2.0);
    rel(p, 2500.0, 1e-12);
}

#[test]
fn bishop_correlations() {
    // Thai eq. 2.5.e.3.1: 2.69 kPa·(N/1000)^1.5; at 4000 rpm 2.69·8 = 21.52 kPa; equals
    // Bishop's 0.39 psi·8 = 3.12 psi = 21.51 kPa (the 2.69 is 0.390 psi rounded; ±0.01 kPa).
    let w4000 = 4000.0 * 2.0 * PI / 60.0;
    rel(bishop_pumps_misc_mep(w4000), 21.52e3, 1e-12);
    assert!((bishop_pumps_misc_mep(w4000) - 3.12 * 6.894_757e3).abs() < 10.0);
    // Throttling: at wide open throttle p_i = p_a the manifold term vanishes, imep_s =
    // 12.87·0.9·p_a; with p_a = 101.325 kPa and 4000 rpm: imep_s = 1173.65 kPa and the exhaust
    // term 33.86·(1173.65/3904·4)² = 48.96 kPa (hand, ±0.01 kPa).
    let t = bishop_throttling_mep(101_325.0, 101_325.0, BISHOP_EXHAUST_FULL_LOAD, w4000);
    assert!((t / 1e3 - 48.96).abs() < 0.01, "{t}");
    // Part load: the manifold vacuum adds p_a − p_i directly.
    let t2 = bishop_throttling_mep(101_325.0, 50_000.0, 0.0, w4000);
    rel(t2, 51_325.0, 1e-12);
}

#[test]
fn flat_follower_energy_and_torque() {
    // No paper: the friction torque μW(R + S) times ω equals μW × the sliding speed ω(R + S);
    // the drive torque is friction + geometric part (Thai 2.5.d.20).
    let w = follower_load(200.0, 30e3, 0.004, 0.1, -500.0); // 200 + 120 − 50 = 270 N
    rel(w, 270.0, 1e-12);
    let l = flat_follower_friction(0.08, w, 0.015, 0.004, 150.0);
    rel(l.power, 0.08 * w * 150.0 * 0.019, 1e-12);
    let t = cam_drive_torque(0.08, w, 0.015, 0.004, 0.01);
    rel(t, l.friction_torque + w * 0.01, 1e-12);
}
