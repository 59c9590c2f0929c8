//! The step loop takes a prescribed motion's crank states a block at a time and a solved one's
//! one at a time; either way every step reaches the sinks in order, and a motion that cannot
//! go on fails at the step where it stops.

use cardan_balance::{Cylinder, Layout, MachineBalance};
use cardan_dynamics::{
    run, Inertial, LoadFamily, Machine, MachineKind, MachineStage, RunError, Sink, Solver, Stage,
    Steps, Summary, SummarySink,
};
use cardan_mechanism::{
    CrankMotion, Grid, MachineGeometry, MassInputs, Mechanism, MotionSource, Options, MECHANISMS,
};
use cardan_testing::OneByOne;
use std::sync::Arc;

fn steps(
    motion: &mut dyn MotionSource,
) -> (Vec<cardan_dynamics::StepRecord>, Result<(), RunError>) {
    let (kept, _, result) = run_slider_crank(motion, true);
    (kept, result)
}

/// The slider-crank run through `motion`: its steps if `keep`, its summary, how it ended.
fn run_slider_crank(
    motion: &mut dyn MotionSource,
    keep: bool,
) -> (
    Vec<cardan_dynamics::StepRecord>,
    Result<Summary, String>,
    Result<(), RunError>,
) {
    let g = MachineGeometry {
        crank_length: 0.06,
        rod_length: 0.14,
        bore: 0.12,
        pin_offset: 0.0,
    };
    let slider = MECHANISMS
        .iter()
        .find(|e| e.name == "slider_crank")
        .unwrap();
    let m = (slider.build)(&g, &MassInputs::default(), &Options::new()).unwrap();
    let inertial = Inertial::new(Solver::ClosedForm);
    let families: [&dyn LoadFamily; 1] = [&inertial];
    let mut kept = Steps::default();
    let mut summary = SummarySink::new(m.as_ref(), &["inertial"], motion.len());
    let result = {
        let mut sinks: Vec<&mut dyn Sink> = vec![&mut summary];
        if keep {
            sinks.push(&mut kept);
        }
        run(m.as_ref(), motion, &families, None, &mut [], &mut sinks)
    };
    (kept.0, summary.finish(m.as_ref()), result)
}

/// The summary takes a block's steps together (`Sink::push_block`), closing its integrals'
/// chunk inside a block: the summary of steps taken one at a time, bit for bit.
#[test]
fn a_summary_of_blocks_is_the_summary_of_single_steps() {
    let motion = CrankMotion {
        start_angle: 1.0,
        initial_speed: 100.0,
        angular_acceleration: 500.0,
    };
    // Chunks of 64 and 192 steps (`summary_chunk`), each closed at the first step of a block.
    for steps in [100, 67, 2 * 128 + 11] {
        let (_, blocks, a) = run_slider_crank(&mut Grid::new(motion, 1.0, 20.0, steps), false);
        let (_, single, b) =
            run_slider_crank(&mut OneByOne(Grid::new(motion, 1.0, 20.0, steps)), false);
        assert!(a.is_ok() && b.is_ok());
        assert_eq!(blocks.unwrap(), single.unwrap(), "{steps} steps");
    }
}

#[test]
fn blocks_and_single_steps_give_the_same_run() {
    let motion = CrankMotion {
        start_angle: 1.0,
        initial_speed: 100.0,
        angular_acceleration: 500.0,
    };
    // 101 states: a block of 64 and a part.
    let (blocks, a) = steps(&mut Grid::new(motion, 1.0, 8.0, 100));
    let (single, b) = steps(&mut OneByOne(Grid::new(motion, 1.0, 8.0, 100)));
    assert!(a.is_ok() && b.is_ok());
    assert_eq!(blocks.len(), 101);
    assert_eq!(blocks, single);
}

#[test]
fn a_crank_that_stops_mid_block_fails_at_its_step() {
    // ω² = 1 − 2·Δθ: the crank stops between grid points 101 and 102 (h = 0.00495 rad).
    let motion = CrankMotion {
        start_angle: 0.0,
        initial_speed: 1.0,
        angular_acceleration: -1.0,
    };
    for source in [
        &mut Grid::new(motion, 0.0, 0.99, 200) as &mut dyn MotionSource,
        &mut OneByOne(Grid::new(motion, 0.0, 0.99, 200)),
    ] {
        let (kept, result) = steps(source);
        assert_eq!(
            kept.len(),
            102,
            "every step before the stop reached the sinks"
        );
        match result {
            Err(RunError::Motion { step, .. }) => assert_eq!(step, 102),
            other => panic!("{other:?}"),
        }
    }
}

/// A stage evaluates whole blocks of a prescribed motion and blocks of one step of a solved
/// one: the machine's stage (a machine of one cylinder, from the train's columns; of two, each
/// loaded by the stage) gives the same summary and step values, bit for bit, whether the steps
/// come 64 or one at a time and whether a sink keeps them, for every mechanism, with rotors (a
/// counterweight, Lanchester shafts) at an accelerating crank; in its own frame and turned.
#[test]
fn a_stage_gives_the_same_bits_in_blocks_and_one_step_at_a_time() {
    let g = MachineGeometry {
        crank_length: 0.06,
        rod_length: 0.14,
        bore: 0.12,
        pin_offset: 0.0,
    };
    let motion = CrankMotion {
        start_angle: 1.0,
        initial_speed: 100.0,
        angular_acceleration: 500.0,
    };
    let turned = Layout {
        cylinders: vec![Cylinder {
            throw: 0.4,
            axis_angle: 0.3,
            axial_position: 0.0,
        }],
    };
    let twin = Layout {
        cylinders: vec![
            turned.cylinders[0],
            Cylinder {
                throw: 2.0,
                axis_angle: 0.3,
                axial_position: 0.1,
            },
        ],
    };
    for entry in MECHANISMS {
        let m: Arc<dyn Mechanism> = (entry.build)(&g, &MassInputs::default(), &Options::new())
            .unwrap()
            .into();
        for layout in [Layout::single(), turned.clone(), twin.clone()] {
            let machine = MachineBalance {
                firing_delay: vec![0.0; layout.cylinders.len()],
                layout,
                counterweight: Some(0.5),
                lanchester: true,
                shaking_per_step: true,
                ..MachineBalance::default()
            };
            let Ok(built) = Machine::build(&machine, Arc::clone(&m), MachineKind::Pump) else {
                // A mechanism without a cylinder forms no machine of several.
                assert!(!m.has_cylinder(), "{}", entry.name);
                continue;
            };
            let stage = MachineStage::new(Arc::new(built), 100.0, false, None);
            let inertial = Inertial::new(Solver::ClosedForm);
            let families: [&dyn LoadFamily; 1] = [&inertial];
            // (in blocks, keep the steps)
            let mut runs = Vec::new();
            for (blocks, keep) in [(true, false), (true, true), (false, true)] {
                let mut s = stage.clone();
                let grid = Grid::new(motion, 1.0, 20.0, 2 * 128 + 11);
                let mut one_by_one = OneByOne(grid.clone());
                let mut grid = grid;
                let motion: &mut dyn MotionSource = match blocks {
                    true => &mut grid,
                    false => &mut one_by_one,
                };
                let mut summary =
                    SummarySink::new(m.as_ref(), &["inertial"], motion.len()).with_stages(&[&s]);
                let mut kept = Steps::default();
                let mut sinks: Vec<&mut dyn Sink> = vec![&mut summary];
                if keep {
                    sinks.push(&mut kept);
                }
                let stages: &mut [&mut dyn Stage] = &mut [&mut s];
                run(m.as_ref(), motion, &families, None, stages, &mut sinks).unwrap();
                let values: Vec<Vec<u64>> = (kept.0.iter())
                    .map(|r| r.stages[0].iter().map(|v| v.to_bits()).collect())
                    .collect();
                runs.push((summary.finish(m.as_ref()).unwrap(), values));
            }
            assert_eq!(runs[0].0, runs[2].0, "{}", entry.name);
            assert_eq!(runs[1], runs[2], "{}", entry.name);
            assert!(runs[2].0.get("shaking_force_max").unwrap() > 0.0);
        }
    }
}
