//! Random valid cases (issue 22): every mechanism, with and without gas and friction, over a
//! range of geometries, speeds and accelerations. Each run writes complete, finite results,
//! and they hold together: the stroke is the piston's travel in the CSV, each peak metric is
//! the largest value of its CSV column, and the energy balance is met.

use cardan_mechanism::MECHANISMS;
use cardan_runner::{run_paths, RunOptions};
use proptest::prelude::*;
use serde_json::Value;
use std::collections::HashMap;
use std::path::Path;

/// A case file of the machine drawn by the strategy below.
#[allow(clippy::too_many_arguments)]
fn case_text(
    mechanism: &str,
    crank_mm: f64,
    rod_ratio: f64,
    bore_ratio: f64,
    speed: f64,
    alpha: f64,
    steps: usize,
    gas: bool,
    friction: bool,
) -> String {
    let mut text = format!(
        "name = \"random\"\nmachine = \"pump\"\nmechanisms = [\"{mechanism}\"]\n\
         [geometry]\ncrank_length = \"{crank_mm} mm\"\nrod_length = \"{} mm\"\nbore = \"{} mm\"\n\
         [motion]\nstart_angle = 90.0\nend_angle = 810.0\ninitial_speed = \"{speed} rad/s\"\n\
         angular_acceleration = \"{alpha} rad/s^2\"\nsteps = {steps}\n",
        crank_mm * rod_ratio,
        2.0 * crank_mm * bore_ratio,
    );
    if gas {
        text.push_str(
            "[gas]\nmodel = \"karhula_pump\"\ncompression_ratio = 12\npolytropic_exponent = 1.4\n",
        );
    }
    if friction {
        text.push_str("[friction]\n");
    }
    text
}

/// The CSV's columns by name.
fn read_csv(path: &Path) -> HashMap<String, Vec<f64>> {
    let text = std::fs::read_to_string(path).unwrap();
    let mut lines = text.lines();
    let header: Vec<String> = lines.next().unwrap().split(',').map(String::from).collect();
    let mut columns: Vec<Vec<f64>> = vec![Vec::new(); header.len()];
    for line in lines {
        for (k, cell) in line.split(',').enumerate() {
            // An empty cell is a documented gap (a torque share at standstill).
            columns[k].push(if cell.is_empty() {
                f64::NAN
            } else {
                cell.parse().unwrap()
            });
        }
    }
    header.into_iter().zip(columns).collect()
}

fn largest(column: &[f64]) -> f64 {
    column
        .iter()
        .copied()
        .filter(|v| !v.is_nan())
        .fold(f64::MIN, f64::max)
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 40, ..ProptestConfig::default() })]

    #[test]
    fn random_valid_cases_write_complete_consistent_results(
        mechanism in 0..MECHANISMS.len(),
        crank_mm in 20.0..100.0f64,
        rod_ratio in 2.7..5.0f64,
        bore_ratio in 1.0..1.8f64,
        speed in 5.0..1200.0f64,
        alpha in 0.0..2000.0f64,
        steps in 721..2400usize,
        gas: bool,
        friction: bool,
    ) {
        let entry = &MECHANISMS[mechanism];
        // The hypotrochoid's pistons turn: no gas model takes its volume.
        let gas = gas && entry.name != "hypotrochoid";
        let text = case_text(
            entry.name, crank_mm, rod_ratio, bore_ratio, speed, alpha, steps, gas, friction,
        );
        let dir = tempfile::tempdir().unwrap();
        let file = dir.path().join("random.toml");
        std::fs::write(&file, &text).unwrap();
        // A grid on the hypotrochoid's fold is refused on reading, as it should be.
        if let Err(e) = cardan_case::case::load(&file) {
            prop_assume!(!e.to_string().contains("fold"));
            panic!("a valid case is refused: {e}\n{text}");
        }
        let report = run_paths(&[file], &dir.path().join("out"), RunOptions::default());
        prop_assert!(report.failures.is_empty(), "{:?}\n{text}", report.failures);
        let folder = dir.path().join("out/random");
        let summary: Value =
            serde_json::from_str(&std::fs::read_to_string(folder.join("summary.json")).unwrap())
                .unwrap();
        let metrics = summary["mechanisms"][entry.name]["metrics"].as_object().unwrap();
        for (name, v) in metrics {
            prop_assert!(v.as_f64().is_some_and(f64::is_finite), "{name} = {v}\n{text}");
        }
        let csv = read_csv(&folder.join(format!("{}.csv", entry.name)));
        for (name, column) in &csv {
            prop_assert!(column.iter().all(|v| !v.is_infinite()), "{name} infinite\n{text}");
        }
        // The stroke is the first piston's travel between its dead centres, which a grid of
        // at least 721 steps over two revolutions samples to a part in 1e-4 (the travel's
        // curvature at a dead centre times half a step squared).
        let stroke = metrics["piston_stroke"].as_f64().unwrap();
        // (An in-line piston's; the hypotrochoid's piston links turn.)
        if let Some(position) = csv.get("piston_position_m") {
            let travel = largest(position) + largest(&position.iter().map(|x| -x).collect::<Vec<_>>());
            prop_assert!((travel - stroke).abs() <= 1e-4 * stroke, "travel {travel}, stroke {stroke}\n{text}");
        }
        // Every peak of a joint force is the largest of its CSV column, to round-off: the CSV
        // holds the shortest text that reads back to the same number, but the summary keeps
        // squared peaks and takes one square root at the end where the CSV takes each step's
        // hypot, a few units in the last place apart.
        let mut peaks = 0;
        for (name, v) in metrics {
            let Some(stem) = name.strip_suffix("_force_max") else { continue };
            let column = format!("{stem}_force_magnitude_n");
            if let Some(c) = csv.get(&column) {
                let (csv_peak, peak) = (largest(c), v.as_f64().unwrap());
                prop_assert!((csv_peak - peak).abs() <= 1e-14 * peak, "{name}: CSV {csv_peak}, summary {peak}\n{text}");
                peaks += 1;
            }
        }
        prop_assert!(peaks >= 3, "only {peaks} peaks compared");
        let torque = metrics["inertial_torque_max"].as_f64().unwrap();
        let column = &csv["inertial_torque_nm"];
        let magnitude = largest(&column.iter().map(|t| t.abs()).collect::<Vec<_>>());
        prop_assert!((magnitude - torque).abs() <= 1e-14 * torque, "torque: CSV {magnitude}, summary {torque}\n{text}");
        prop_assert!(metrics["energy_balance_error"].as_f64().unwrap() <= 1e-3);
    }
}
