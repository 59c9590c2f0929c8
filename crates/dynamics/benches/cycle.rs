//! One mechanism over the thesis cycle at 7200 steps: kinematics, closed-form inertial loads
//! and the streamed summary (no per-step record), the unit of work of the runner, with the crank
//! grid made as it goes, the run shared by the rayon pool's threads as the runner shares it
//! (`*_7200_steps`) or on one thread (`*_7200_steps_one_thread`), or with the grid made
//! beforehand (`*_7200_steps_prebuilt_grid`, one thread: the work the benchmark of the earlier,
//! stored-steps design timed); and the same with every step kept in memory.

use cardan_dynamics::{run_summary, Solver};
use cardan_mechanism::{
    CrankMotion, CrankState, Grid, MachineGeometry, MassInputs, Mechanism, MotionError,
    MotionSource, Options, MECHANISMS,
};
use cardan_testing::OneThread;
use criterion::{criterion_group, criterion_main, Criterion};
use std::f64::consts::PI;
use std::hint::black_box;

/// Crank states made beforehand.
struct Prebuilt<'a>(std::slice::Iter<'a, CrankState>, usize);

impl MotionSource for Prebuilt<'_> {
    fn len(&self) -> usize {
        self.1
    }

    fn next(&mut self, _: Option<f64>) -> Option<Result<CrankState, MotionError>> {
        self.0.next().map(|c| Ok(*c))
    }

    fn prescribed(&self) -> bool {
        true
    }
}

/// Times `mech` through the motion `source` makes, the summary only or every step `kept`.
fn time<'a>(
    c: &mut Criterion,
    label: &str,
    mech: &dyn Mechanism,
    kept: bool,
    source: &dyn Fn() -> Box<dyn MotionSource + 'a>,
) {
    c.bench_function(label, |b| {
        b.iter(|| {
            let mut source = source();
            black_box(
                run_summary(
                    black_box(mech),
                    source.as_mut(),
                    None,
                    Solver::ClosedForm,
                    kept,
                )
                .unwrap(),
            )
        })
    });
}

fn cycle(c: &mut Criterion) {
    let motion = CrankMotion {
        start_angle: PI / 2.0,
        initial_speed: 200.0 * PI,
        angular_acceleration: 100.0 * PI,
    };
    let geometry = MachineGeometry {
        crank_length: 0.06,
        rod_length: 0.14,
        bore: 0.12,
        pin_offset: 0.0,
    };
    for entry in MECHANISMS {
        let name = entry.name;
        let mech = (entry.build)(&geometry, &MassInputs::default(), &Options::new()).unwrap();
        // The closed-form mechanisms: a mechanism that needs the general solve (one least-squares
        // system per step) is another order of time, and the hypotrochoid's single-planet model
        // is singular where its parallelogram folds, which this grid crosses.
        let probe = mech.state(&motion.at_angle(1.0).unwrap());
        let mut loads = cardan_mechanism::Loads::for_topology(mech.topology());
        if !mech.closed_form_loads(&probe, true, &[], &mut loads) {
            continue;
        }
        let grid = motion.grid(PI / 2.0, 4.5 * PI, 7200).unwrap();
        let whole = || Grid::new(motion, PI / 2.0, 4.5 * PI, 7200);
        let name = format!("{name}_7200_steps");
        let mech = mech.as_ref();
        time(c, &format!("{name}_prebuilt_grid"), mech, false, &|| {
            Box::new(Prebuilt(grid.iter(), grid.len()))
        });
        time(c, &format!("{name}_one_thread"), mech, false, &|| {
            Box::new(OneThread(whole()))
        });
        time(c, &name, mech, false, &|| Box::new(whole()));
        time(
            c,
            &format!("{name}_kept"),
            mech,
            true,
            &|| Box::new(whole()),
        );
    }
}

criterion_group!(benches, cycle);
criterion_main!(benches);
