//! A run shared by threads ([`run_parallel`]) gives the summary of the same run taken step by
//! step by one thread ([`run`]), bit for bit, whatever the number of threads: with gas, losses
//! and gear ratings, on every closed-form mechanism, from rest, and when a step fails.

mod common;

use cardan_dynamics::{
    run, run_parallel, Friction, Gas, GearRatings, GearSpec, GearStage, Inertial, LoadFamily,
    LossBudget, LossStage, RunError, RunRooms, Solver, Stage, Summary, SummarySink, MAX_CHUNK,
};
use cardan_mechanism::{CrankMotion, Grid, Material, Mechanism};
use common::{accelerating_pump, every_machine, pump_gas, thesis};
use std::f64::consts::PI;

/// How a test's run is run.
#[derive(Clone, Copy)]
enum By<'r> {
    /// `run` on the calling thread.
    Run,
    /// `run_parallel` in a pool of this many threads.
    Threads(usize),
    /// `RunRooms::run_parallel` in these rooms, by this solver.
    Rooms(&'r RunRooms, Solver),
}

/// The summary of `m` over `steps` steps of `motion` from 90°, with a gas force and the
/// thesis's loss budget (and the gear rating where the mechanism has a mesh), run by
/// `run_parallel` in a pool of `threads` threads, or by `run` if `threads` is 0.
fn summary(
    m: &dyn Mechanism,
    motion: CrankMotion,
    steps: usize,
    threads: usize,
) -> Result<Summary, String> {
    let by = match threads {
        0 => By::Run,
        n => By::Threads(n),
    };
    summary_by(m, motion, steps, by)
}

/// [`summary`] run `by` (the closed forms' solver but by rooms).
fn summary_by(
    m: &dyn Mechanism,
    motion: CrankMotion,
    steps: usize,
    by: By,
) -> Result<Summary, String> {
    let solver = match by {
        By::Rooms(_, solver) => solver,
        _ => Solver::ClosedForm,
    };
    let inertial = Inertial::new(solver);
    let gas_family = Gas(solver);
    let families: [&dyn LoadFamily; 2] = [&inertial, &gas_family];
    let budget = LossBudget::new(&Friction::karhula(), m, 0.12).unwrap();
    assert!(!budget.carries_history());
    let mut budget = LossStage::new(budget);
    let mut gears = GearRatings::new(&GearSpec::default(), m, None)
        .ok()
        .filter(|g| !g.names().is_empty())
        .map(GearStage::new);
    // The ratings first: the budget takes their mesh losses.
    let mut stages: Vec<&mut dyn Stage> = Vec::new();
    if let Some(g) = &mut gears {
        stages.push(g);
    }
    stages.push(&mut budget);
    let listed: Vec<&dyn Stage> = stages.iter().map(|s| &**s).collect();
    let mut sink = SummarySink::new(m, &["inertial", "gas"], steps + 1).with_stages(&listed);
    let mut grid = Grid::new(
        motion,
        motion.start_angle,
        motion.start_angle + 4.0 * PI,
        steps,
    );
    let ran = match by {
        By::Run => run(
            m,
            &mut grid,
            &families,
            Some(&pump_gas),
            &mut stages,
            &mut [&mut sink],
        ),
        By::Rooms(rooms, _) => rooms.run_parallel(
            m,
            &mut grid,
            &families,
            Some(&pump_gas),
            &mut stages,
            &mut sink,
        ),
        By::Threads(threads) => rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap()
            .install(|| {
                run_parallel(
                    m,
                    &mut grid,
                    &families,
                    Some(&pump_gas),
                    &mut stages,
                    &mut sink,
                )
            }),
    };
    ran.map_err(|e: RunError| e.to_string())?;
    sink.finish(m)
}

#[test]
fn shared_runs_are_the_single_threads_bit_for_bit() {
    // MAX_CHUNK + 1 steps: the shortest run that is shared (two pieces of 2112 and 1985
    // steps); 7200 steps: two pieces (3648 and 3552); 3·MAX_CHUNK + 7 steps: four (3136 steps
    // each, the last 2887).
    for name in ["slider_crank", "cardan_gear", "scotch_yoke"] {
        let m = thesis(name, Material::Steel);
        for steps in [MAX_CHUNK + 1, 7200, 3 * MAX_CHUNK + 7] {
            let one = summary(m.as_ref(), accelerating_pump(), steps, 0).unwrap();
            assert!(one.get("loss_work").unwrap() > 0.0);
            assert_eq!(
                one.get("gear_mesh_power_loss_mean").is_some(),
                name == "cardan_gear"
            );
            for threads in [1, 2, 3] {
                let shared = summary(m.as_ref(), accelerating_pump(), steps, threads).unwrap();
                assert_eq!(shared, one, "{name}, {steps} steps, {threads} threads");
            }
        }
    }
}

/// A run in a room kept from a run of another machine of its kind (another geometry, reading,
/// added mass: `every_machine`) gives the summary of a run in fresh blocks, bit for bit, by
/// either solver; a failed run's room is not kept, and a room of one solver's families is not
/// taken by the other's.
#[test]
fn a_kept_room_gives_a_fresh_rooms_summary() {
    let rooms = RunRooms::default();
    let machines = every_machine();
    let mut ran = 0;
    for solver in [Solver::ClosedForm, Solver::General] {
        for (name, m) in machines.iter().chain(machines.iter().rev()) {
            let kept = summary_by(
                m.as_ref(),
                accelerating_pump(),
                200,
                By::Rooms(&rooms, solver),
            );
            let fresh = summary_by(
                m.as_ref(),
                accelerating_pump(),
                200,
                By::Rooms(&RunRooms::default(), solver),
            );
            assert_eq!(kept, fresh, "{name}, {solver:?}");
            ran += usize::from(kept.is_ok());
        }
    }
    // Every machine but those whose grid meets a fold of their chain (the hypotrochoid's).
    assert!(
        ran + 8 >= 4 * machines.len(),
        "{ran} of {}",
        4 * machines.len()
    );
}

#[test]
fn a_shared_run_fails_at_the_single_threads_step() {
    // ω² = (2π)² − 6·Δθ: the crank stops 6.58 rad after the start, between steps 10471 and
    // 10472 of h = π/5000, in the fourth of six pieces (of 3392 steps).
    let m = thesis("slider_crank", Material::Steel);
    let stopping = CrankMotion {
        start_angle: PI / 2.0,
        initial_speed: 2.0 * PI,
        angular_acceleration: -3.0,
    };
    let one = summary(m.as_ref(), stopping, 20_000, 0).unwrap_err();
    assert!(one.starts_with("step 10472:"), "{one}");
    for threads in [1, 2] {
        assert_eq!(
            summary(m.as_ref(), stopping, 20_000, threads).unwrap_err(),
            one
        );
    }
}

/// Counts the steps it takes and the pieces joined into it.
#[derive(Clone, Default)]
struct Pieces {
    steps: usize,
    pieces: usize,
}

impl cardan_dynamics::Sink for Pieces {
    fn push(&mut self, _: &cardan_dynamics::Step) -> Result<(), String> {
        self.steps += 1;
        Ok(())
    }
}

impl cardan_dynamics::Joinable for Pieces {
    fn join(&mut self, later: Self) {
        self.steps += later.steps;
        self.pieces += 1;
    }
}

#[test]
fn a_long_prescribed_run_is_split_at_chunk_starts() {
    // Each piece takes the step that starts the next one too.
    let m = thesis("cardan_gear", Material::Steel);
    let inertial = Inertial::new(Solver::ClosedForm);
    for (steps, pieces) in [
        (MAX_CHUNK, 0),
        (MAX_CHUNK + 1, 2),
        (7200, 2),
        (3 * MAX_CHUNK + 7, 4),
    ] {
        let mut grid = Grid::new(accelerating_pump(), PI / 2.0, 4.5 * PI, steps);
        let mut sink = Pieces::default();
        run_parallel(
            m.as_ref(),
            &mut grid,
            &[&inertial],
            None,
            &mut [],
            &mut sink,
        )
        .unwrap();
        assert_eq!(sink.pieces, pieces, "{steps} steps");
        assert_eq!(
            sink.steps,
            steps + 1 + pieces.saturating_sub(1),
            "{steps} steps"
        );
    }
}
