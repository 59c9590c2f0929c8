//! Each gas model over one 720° cycle of 7200 crank angles on the slider-crank's volume curve
//! (the runner's unit of gas work per mechanism), Karhula's thesis cylinder.

use cardan_gas::{ClosedCycle, Compressor, Cylinder, GasModel, KarhulaEngine, Polytropic};
use cardan_mechanism::{MachineGeometry, MassInputs, Mechanism, Options, SliderCrank};
use criterion::{criterion_group, criterion_main, Criterion};
use std::f64::consts::PI;
use std::hint::black_box;

fn gas(c: &mut Criterion) {
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

criterion_group!(benches, gas);
criterion_main!(benches);
