//! `[sweep]` tables: every point a case with a readable name, all in `out/<sweep>/`, gathered in
//! `sweep.csv`; grids and zips; bad sweeps named by their field.

use cardan_runner::{run_paths, RunOptions};
use std::path::Path;

const BASE: &str = r#"
name = "pump-sweep"
machine = "pump"
mechanisms = ["slider_crank", "cardan_gear"]
[geometry]
crank_length = 0.06
rod_length = 0.14
bore = 0.12
[motion]
start_angle = 90.0
end_angle = 810.0
initial_speed = 100.0
angular_acceleration = 0.0
steps = 720
[output]
csv = false
"#;

fn run(dir: &Path, sweep: &str) -> cardan_runner::Report {
    let file = dir.join("sweep.toml");
    std::fs::write(&file, format!("{BASE}{sweep}")).unwrap();
    run_paths(&[file], &dir.join("out"), RunOptions::default())
}

fn rows(dir: &Path) -> Vec<Vec<String>> {
    std::fs::read_to_string(dir.join("out/pump-sweep/sweep.csv"))
        .unwrap()
        .lines()
        .map(|l| l.split(',').map(String::from).collect())
        .collect()
}

#[test]
fn a_grid_sweep_writes_every_point_and_one_table() {
    let dir = tempfile::tempdir().unwrap();
    let report = run(
        dir.path(),
        r#"
[sweep]
"motion.initial_speed" = ["10 rad/s", "20 rad/s"]
"geometry.rod_length" = { from = "140 mm", to = "240 mm", points = 3 }
"#,
    );
    assert!(report.failures.is_empty(), "{:#?}", report.failures);
    assert_eq!(report.written.len(), 6);
    let folder = dir.path().join("out/pump-sweep");
    assert!(folder
        .join("pump-sweep-initial_speed-10rad_s-rod_length-190mm/summary.json")
        .is_file());
    let t = rows(dir.path());
    assert_eq!(t.len(), 1 + 6);
    assert_eq!(
        t[0][..3],
        ["case", "motion.initial_speed", "geometry.rod_length"]
    );
    let col = |name: &str| t[0].iter().position(|c| c == name).unwrap();
    let torque = col("cardan_gear.inertial_torque_max");
    // The cardan gear's inertial torque does not depend on the rod length... but its rod mass
    // does (the rod rule): the longer rod gives the larger torque at the same speed; and the
    // torque grows as ω² between the two speeds.
    let value = |r: usize, c: usize| t[r][c].parse::<f64>().unwrap();
    for r in 1..=6 {
        assert!(value(r, torque) > 0.0);
    }
    let at = |speed: &str, rod: &str| {
        (1..=6)
            .find(|&r| t[r][1] == speed && t[r][2] == rod)
            .unwrap()
    };
    let ratio = value(at("20 rad/s", "140 mm"), torque) / value(at("10 rad/s", "140 mm"), torque);
    assert!((ratio - 4.0).abs() < 1e-9, "{ratio}");
    assert!(value(at("10 rad/s", "240 mm"), torque) > value(at("10 rad/s", "140 mm"), torque));
    // Re-running a smaller sweep replaces the folder as a whole.
    let report = run(dir.path(), "\n[sweep]\n\"motion.initial_speed\" = [10.0]\n");
    assert!(report.failures.is_empty(), "{:#?}", report.failures);
    let entries = std::fs::read_dir(&folder).unwrap().count();
    assert_eq!(entries, 2, "one point and sweep.csv");
}

#[test]
fn a_zipped_log_sweep_pairs_its_values() {
    let dir = tempfile::tempdir().unwrap();
    let report = run(
        dir.path(),
        r#"
[sweep]
mode = "zip"
"motion.initial_speed" = { from = 10, to = 1000, points = 3, scale = "log" }
"masses.piston_mass" = ["0.1 kg", "0.2 kg", "0.4 kg"]
"#,
    );
    assert!(report.failures.is_empty(), "{:#?}", report.failures);
    let t = rows(dir.path());
    assert_eq!(t.len(), 4);
    let speeds: Vec<f64> = (1..4).map(|r| t[r][1].parse().unwrap()).collect();
    for (s, want) in speeds.iter().zip([10.0, 100.0, 1000.0]) {
        assert!((s / want - 1.0).abs() < 1e-12, "{s}");
    }
    assert_eq!(t[3][2], "0.4 kg");
}

/// 1000 points over two parameters from one file (issue 12), with the sweep's report: its heat
/// maps hold one cell per point.
#[test]
fn a_thousand_point_sweep_runs_from_one_file() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("sweep.toml");
    let sweep = r#"
[sweep]
"motion.initial_speed" = { from = 10, to = 700, points = 40 }
"geometry.rod_length" = { from = "100 mm", to = "300 mm", points = 25 }
"#;
    std::fs::write(&file, format!("{BASE}{sweep}")).unwrap();
    let options = RunOptions {
        reports: true,
        ..RunOptions::default()
    };
    let report = run_paths(&[file], &dir.path().join("out"), options);
    assert!(
        report.failures.is_empty(),
        "{:#?}",
        report.failures[..3.min(report.failures.len())].to_vec()
    );
    assert_eq!(report.written.len(), 1000);
    assert_eq!(rows(dir.path()).len(), 1001);
    let folder = dir.path().join("out/pump-sweep");
    let map = std::fs::read_to_string(
        folder.join("plots/inertial_torque_max_difference_cardan_gear.svg"),
    )
    .unwrap();
    assert_eq!(map.matches("class=\"cell\"").count(), 1000);
    assert!(std::fs::read_to_string(folder.join("report.md"))
        .unwrap()
        .contains("inertial_torque_max_difference_cardan_gear.svg"));
    assert!(dir.path().join("out/index.html").is_file());
}

#[test]
fn bad_sweeps_name_their_field() {
    for (sweep, parts) in [
        ("[sweep]\nmode = \"spiral\"\n\"motion.steps\" = [8]\n", &["sweep.mode", "spiral"][..]),
        ("[sweep]\n\"motion.initial_speed\" = []\n", &["sweep.\"motion.initial_speed\"", "non-empty"][..]),
        ("[sweep]\n\"motion.initial_speed\" = { from = 1, to = \"2 rpm\", points = 3 }\n", &["same unit"][..]),
        ("[sweep]\n\"motion.initial_speed\" = { from = 0, to = 2, points = 3, scale = \"log\" }\n", &["positive"][..]),
        // Issue 36.15: an infinite end is said to be one, not a unit's mismatch.
        ("[sweep]\n\"motion.initial_speed\" = { from = \"1 rpm\", to = inf, points = 3 }\n", &["sweep.\"motion.initial_speed\".to", "finite"][..]),
        // Issue 36.15: an item of a list is not a bad case name but cannot be swept alone.
        ("[sweep]\n\"layout.crank_angles[1]\" = [0, 90]\n", &["sweep.\"layout.crank_angles[1]\"", "item of a list cannot be swept", "\"layout.crank_angles\" = [["][..]),
        ("[sweep]\nname = [\"a\"]\n", &["dotted path"][..]),
        ("[sweep]\nmode = \"zip\"\n\"motion.initial_speed\" = [1, 2]\n\"geometry.bore\" = [0.1]\n", &["as many values"][..]),
        // A swept value is checked like any case value, naming the point.
        ("[sweep]\n\"geometry.rod_length\" = [0.14, 0.01]\n", &["geometry.rod_length", "pump-sweep-rod_length-0.01"][..]),
        // A misspelled key of a range: its path and the nearest valid key.
        ("[sweep]\n\"motion.initial_speed\" = { from = 1, to = 2, pionts = 3 }\n", &["sweep.\"motion.initial_speed\".pionts", "did you mean \"points\"?"][..]),
        // A swept value of the wrong type: the point, the field's path and the value.
        ("[sweep]\n\"motion.steps\" = [\"many\"]\n", &["\"pump-sweep-steps-many\"", "motion.steps", "\"many\"", "whole number"][..]),
    ] {
        let dir = tempfile::tempdir().unwrap();
        let report = run(dir.path(), &format!("\n{sweep}"));
        let all = report.failures.join("\n");
        for p in parts {
            assert!(all.contains(p), "{sweep:?}: {all:?} lacks {p:?}");
        }
    }
}

/// Issue 22 (r04, r05): two points of one name shared one temporary folder and deleted each
/// other's files, and a broken sweep folder was published. Now they are refused before
/// anything runs, naming the values; nothing is written.
#[test]
fn duplicate_point_names_are_refused_before_anything_runs() {
    for (sweep, parts) in [
        (
            "[sweep]\n\"motion.initial_speed\" = [\"900 rpm\", \"900 rpm\", \"3000 rpm\"]\n",
            &["\"900 rpm\"", "pump-sweep-initial_speed-900rpm", "distinct"][..],
        ),
        (
            "[sweep]\n\"motion.initial_speed\" = { from = \"3000 rpm\", to = \"3000 rpm\", points = 4 }\n",
            &["sweep.\"motion.initial_speed\"", "3000 rpm", "equal"][..],
        ),
    ] {
        let dir = tempfile::tempdir().unwrap();
        let report = run(dir.path(), &format!("\n{sweep}"));
        let all = report.failures.join("\n");
        assert!(report.written.is_empty(), "{sweep:?}: {:?}", report.written);
        assert_eq!(report.failures.len(), 1, "{all}");
        for p in parts {
            assert!(all.contains(p), "{sweep:?}: {all:?} lacks {p:?}");
        }
        assert!(
            !dir.path().join("out/pump-sweep").exists(),
            "no sweep folder is published"
        );
    }
}

/// Issue 22: `points = 0` read `points = Some(Integer(0))`; an infinite end read as nan.
#[test]
fn bad_ranges_read_like_a_person_wrote_them() {
    for (sweep, parts, not) in [
        (
            "[sweep]\n\"motion.initial_speed\" = { from = 1, to = 2, points = 0 }\n",
            &[
                "sweep.\"motion.initial_speed\".points",
                "= 0",
                "whole number from 2",
            ][..],
            "Some(",
        ),
        (
            "[sweep]\n\"motion.initial_speed\" = { from = 1, to = 2 }\n",
            &["points", "missing"][..],
            "None",
        ),
        (
            "[sweep]\n\"motion.initial_speed\" = { from = 1, to = inf, points = 3 }\n",
            &["sweep.\"motion.initial_speed\".to", "inf", "finite"][..],
            "nan",
        ),
    ] {
        let dir = tempfile::tempdir().unwrap();
        let report = run(dir.path(), &format!("\n{sweep}"));
        let all = report.failures.join("\n");
        for p in parts {
            assert!(all.contains(p), "{sweep:?}: {all:?} lacks {p:?}");
        }
        assert!(
            !all.to_lowercase().contains(&not.to_lowercase()),
            "{sweep:?}: {all:?}"
        );
    }
}
