//! The optimiser on problems whose optimum is known in closed form: interior, on a bound, on a
//! constraint; infeasible problems and failing evaluations reported; the same seed, the same
//! result.

use cardan_optimize::{minimise, Outcome, Settings, Stop};

fn value(objective: f64, margins: Vec<f64>) -> Outcome {
    Outcome::Value { objective, margins }
}

/// Tolerance on the location: the compass search stops at a step of 1e-4 of the range; on a
/// smooth bowl the optimum is within a few steps of it. 1e-3 leaves a factor 10.
const X_TOL: f64 = 1e-3;

#[test]
fn finds_an_interior_minimum() {
    // A rotated, badly scaled quadratic bowl with its minimum at (0.3, 0.7): f = 0 there.
    let f = |x: &[f64]| {
        let (u, v) = (x[0] - 0.3, x[1] - 0.7);
        value(100.0 * (u + v).powi(2) + (u - v).powi(2), vec![])
    };
    let r = minimise(2, &Settings::default(), &f);
    let best = r.best.unwrap();
    assert!(
        (best.x[0] - 0.3).abs() < X_TOL && (best.x[1] - 0.7).abs() < X_TOL,
        "{:?}",
        best.x
    );
    assert!(r
        .starts
        .iter()
        .all(|s| matches!(s.stop, Stop::Converged { .. })));
}

#[test]
fn finds_rosenbrocks_valley_floor() {
    // Rosenbrock's function on [-2, 2]² mapped to the unit cube: minimum 0 at (1, 1), i.e.
    // at (0.75, 0.75).
    let f = |x: &[f64]| {
        let (a, b) = (4.0 * x[0] - 2.0, 4.0 * x[1] - 2.0);
        value(100.0 * (b - a * a).powi(2) + (1.0 - a).powi(2), vec![])
    };
    let settings = Settings {
        max_evaluations: 1000,
        ..Settings::default()
    };
    let best = minimise(2, &settings, &f).best.unwrap();
    // The valley is flat along its floor: a step of 1e-4 of [-2, 2] changes f by ~1e-7.
    assert!(
        (best.x[0] - 0.75).abs() < 5e-3 && (best.x[1] - 0.75).abs() < 1e-2,
        "{:?}",
        best.x
    );
}

#[test]
fn finds_a_minimum_on_a_bound_and_on_a_constraint() {
    // min x0 + x1 subject to x0·x1 ≥ 0.09: on the constraint, at x0 = x1 = 0.3 (AM-GM).
    let f = |x: &[f64]| value(x[0] + x[1], vec![(x[0] * x[1] - 0.09) / 0.09]);
    let best = minimise(2, &Settings::default(), &f).best.unwrap();
    assert!(best.outcome.feasible());
    assert!(
        (best.outcome.objective().unwrap() - 0.6).abs() < 2e-3,
        "{best:?}"
    );
    // min -x0 + (x1 - 0.5)²: at x0 = 1 (the bound), x1 = 0.5.
    let f = |x: &[f64]| value(-x[0] + (x[1] - 0.5).powi(2), vec![]);
    let best = minimise(2, &Settings::default(), &f).best.unwrap();
    assert_eq!(best.x[0], 1.0);
    assert!((best.x[1] - 0.5).abs() < X_TOL);
}

#[test]
fn an_infeasible_problem_reports_its_least_violation() {
    // x0 ≥ 2 cannot hold on [0, 1]: the least violation is at x0 = 1.
    let f = |x: &[f64]| value(x[1], vec![x[0] - 2.0]);
    let r = minimise(2, &Settings::default(), &f);
    assert!(!r.feasible());
    let best = r.best.unwrap();
    assert_eq!(best.x[0], 1.0);
    assert!((best.outcome.violation() - 1.0).abs() < 1e-12);
}

#[test]
fn failing_evaluations_are_kept_and_avoided() {
    // The model refuses x0 > 0.5; the minimum of (x0 - 0.8)² where it runs is at the edge.
    let f = |x: &[f64]| {
        if x[0] > 0.5 {
            Outcome::Failed(format!("refused at {}", x[0]))
        } else {
            value((x[0] - 0.8).powi(2), vec![])
        }
    };
    let r = minimise(1, &Settings::default(), &f);
    assert!(r.failures().count() > 0);
    let best = r.best.unwrap();
    assert!(best.x[0] <= 0.5 && best.x[0] > 0.5 - X_TOL, "{:?}", best.x);
}

#[test]
fn the_same_seed_gives_the_same_result_whatever_the_threads() {
    let f = |x: &[f64]| value((x[0] - 0.2).powi(2) + (x[1] - 0.9).powi(4) + x[2], vec![]);
    let settings = Settings {
        starts: 5,
        seed: 7,
        ..Settings::default()
    };
    let a = minimise(3, &settings, &f);
    let one = rayon::ThreadPoolBuilder::new()
        .num_threads(1)
        .build()
        .unwrap();
    let b = one.install(|| minimise(3, &settings, &f));
    assert_eq!(a, b);
    let c = minimise(
        3,
        &Settings {
            seed: 8,
            ..settings
        },
        &f,
    );
    assert_ne!(a.starts[0].x0, c.starts[0].x0);
}

#[test]
fn the_budget_stops_a_start_and_says_so() {
    let f = |x: &[f64]| value((x[0] - 0.37).powi(2), vec![]);
    let settings = Settings {
        max_evaluations: 5,
        starts: 1,
        ..Settings::default()
    };
    let r = minimise(1, &settings, &f);
    assert_eq!(r.starts[0].stop, Stop::Budget);
    assert_eq!(r.evaluations(), 5);
    assert!(r.starts[0].stop.describe(&settings).contains("budget"));
}
