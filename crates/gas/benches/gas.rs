//! Each gas model over one 720° cycle of 7200 crank angles on the slider-crank's volume curve
//! (the runner's unit of gas work per mechanism), Karhula's thesis cylinder; and one
//! mechanism's whole run with the pump's gas (`*_7200_steps_with_pump_gas`: kinematics,
//! inertial and gas loads, the summary; one thread), the work of issue 8's per-mechanism target
//! with the gas the `cardan-dynamics` cycle bench leaves out.

use cardan_dynamics::{run_summary, Solver};
use cardan_gas::{
    ClosedCycle, Compressor, Cylinder, GasModel, KarhulaEngine, KarhulaPump, Polytropic,
};
use cardan_mechanism::{
    CardanGear, CrankMotion, Grid, MachineGeometry, MassInputs, Mechanism, Options, SliderCrank,
};
use cardan_testing::OneThread;
use criterion::{criterion_group, criterion_main, Criterion};
use std::f64::consts::PI;
use std::hint::black_box;

/// Karhula's thesis machine: crank 60 mm, rod 140 mm, bore 120 mm.
fn thesis_geometry() -> MachineGeometry {
    MachineGeometry {
        crank_length: 0.06,
        rod_length: 0.14,
        bore: 0.12,
        pin_offset: 0.0,
    }
}

fn gas(c: &mut Criterion) {
    let geometry = thesis_geometry();
    let masses = MassInputs {
        rod_cg: Some(0.07),
        ..MassInputs::default()
    };
    let mech = SliderCrank::build(&geometry, &masses, &Options::new()).unwrap();
    let swept = PI / 4.0 * 0.12 * 0.12 * mech.stroke();
    let angles: Vec<f64> = (0..=7200)
        .map(|k| PI / 2.0 + 4.0 * PI * k as f64 / 7200.0)
        .collect();
    let speed = 200.0 * PI;
    let engine = KarhulaEngine::new(
        Polytropic::new(1.4, 1.07, 101_325.0).unwrap(),
        12e6,
        9.5_f64.to_radians(),
    )
    .unwrap();
    let compressor = Compressor::air(101_325.0, 293.15, 8e5, 1.3).unwrap();
    let models: [(&str, &dyn GasModel, Cylinder); 3] = [
        (
            "karhula_engine",
            &engine,
            Cylinder::with_compression_ratio(0.12, swept, 12.0).unwrap(),
        ),
        (
            "closed_cycle",
            &ClosedCycle::nunes_2017(),
            Cylinder::with_compression_ratio(0.12, swept, 10.0).unwrap(),
        ),
        (
            "compressor",
            &compressor,
            Cylinder::with_clearance(0.12, swept, 0.05 * swept).unwrap(),
        ),
    ];
    for (name, model, cylinder) in models {
        c.bench_function(&format!("{name}_7200_angles"), |b| {
            b.iter(|| {
                cylinder.with_chamber(&mech, |ch| {
                    black_box(model.cycle(ch, speed, black_box(&angles)).unwrap())
                })
            })
        });
    }
}

/// One mechanism over the Karhula cycle (7200 steps from 90°, ω0 = 200π rad/s, α = 100π
/// rad/s²) with the pump's gas (valves closed on the compression strokes), on one thread: the
/// grid is run as one piece, as a run with the ring-film losses is.
fn with_gas(c: &mut Criterion) {
    let geometry = thesis_geometry();
    let motion = CrankMotion {
        start_angle: PI / 2.0,
        initial_speed: 200.0 * PI,
        angular_acceleration: 100.0 * PI,
    };
    let pump = KarhulaPump {
        gas: Polytropic::new(1.4, 1.07, 101_325.0).unwrap(),
    };
    let slider = SliderCrank::build(&geometry, &MassInputs::default(), &Options::new()).unwrap();
    let gear = CardanGear::build(&geometry, &MassInputs::default(), &Options::new()).unwrap();
    let mechanisms: [(&str, &dyn Mechanism); 2] =
        [("slider_crank", &slider), ("cardan_gear", &gear)];
    for (name, mech) in mechanisms {
        let swept = PI / 4.0 * 0.12 * 0.12 * mech.stroke();
        let cylinder = Cylinder::with_compression_ratio(0.12, swept, 12.0).unwrap();
        cylinder.with_chamber(mech, |chamber| {
            let prepared = pump.prepare(*chamber, motion.initial_speed).unwrap();
            let gas = |theta: f64| prepared.at(theta);
            c.bench_function(&format!("{name}_7200_steps_with_pump_gas"), |b| {
                b.iter(|| {
                    let mut grid = OneThread(Grid::new(motion, PI / 2.0, 4.5 * PI, 7200));
                    let run = run_summary(mech, &mut grid, Some(&gas), Solver::ClosedForm, false);
                    black_box(run.unwrap())
                })
            });
        });
    }
}

criterion_group!(benches, gas, with_gas);
criterion_main!(benches);
