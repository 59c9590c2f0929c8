//! One mechanism over the thesis cycle at 7200 steps: kinematics + closed-form kinetostatics +
//! summary, the unit of work of the runner (target: under 200 µs on one core), and its two parts.

use cardan_dynamics::{run_cycle, MassProperties, Material, Summary};
use cardan_mechanism::{CardanGear, CrankMotion, Mechanism, MechanismKind, SliderCrank};
use criterion::{criterion_group, criterion_main, Criterion};
use std::f64::consts::PI;
use std::hint::black_box;

fn cycle(c: &mut Criterion) {
    let motion = CrankMotion {
        start_angle: PI / 2.0,
        initial_speed: 200.0 * PI,
        angular_acceleration: 100.0 * PI,
    };
    let grid = motion.grid(PI / 2.0, 4.5 * PI, 7200).unwrap();
    let slider = SliderCrank::new(0.06, 0.14, 0.0, 0.07).unwrap();
    let cardan = CardanGear::equivalent_to_slider_crank(0.06, 0.14, 0.07).unwrap();
    let machines: [(&str, &dyn Mechanism); 2] =
        [("slider_crank", &slider), ("cardan_gear", &cardan)];
    for (name, mech) in machines {
        let kind = MechanismKind::from_name(name).unwrap();
        let masses = MassProperties::estimate(kind, 0.06, 0.14, 0.12, Material::Steel);
        c.bench_function(&format!("{name}_7200_steps"), |b| {
            b.iter(|| {
                let steps = run_cycle(black_box(mech), &masses, black_box(&grid), None);
                black_box(Summary::of_cycle(mech, &masses, &steps))
            })
        });
        let steps = run_cycle(mech, &masses, &grid, None);
        c.bench_function(&format!("{name}_summary_only"), |b| {
            b.iter(|| black_box(Summary::of_cycle(mech, &masses, black_box(&steps))))
        });
        c.bench_function(&format!("{name}_steps_only"), |b| {
            b.iter(|| black_box(run_cycle(black_box(mech), &masses, black_box(&grid), None)))
        });
    }
}

criterion_group!(benches, cycle);
criterion_main!(benches);
