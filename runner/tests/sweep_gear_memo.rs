//! The points of a sweep share what is computed once for all of them (issue 37: the bending
//! geometry factors J a gear pair's tooth-root search gives, `cardan_gears::BendingJMemo`):
//! every point of a sweep over the gear's own fields, the crank and the speed, made on the
//! worker threads from one sweep, is the case its table makes on its own (validated form,
//! setups with their J, and every summary metric to the bit), and the points with another pair
//! have other factors (the memo tells the pairs apart).

use cardan_case::case::{case_of_table, point_to_run};
use cardan_case::sweep::Sweep;
use cardan_runner::run_case;
use rayon::prelude::*;
use std::path::Path;

/// The cardan pump with its gear pair rated, 16 steps; swept over the wheel's teeth, the
/// ring's addendum, the crank (the pitch radius, so the module) and the speed: 3 × 2 × 2 × 2
/// points, the first field fastest.
const CASE: &str = r#"
name = "memo"
machine = "pump"
mechanisms = ["cardan_gear", "slider_crank"]
[geometry]
crank_length = "60 mm"
rod_length = "140 mm"
bore = "120 mm"
[motion]
start_angle = "90 deg"
end_angle = "450 deg"
initial_speed = "300 rpm"
angular_acceleration = 0.0
steps = 16
[output]
case_folders = false
[gear]
tooth_load = "thesis"
[sweep]
"gear.teeth" = [20, 24, 30]
"gear.ring_addendum" = [0.8, 0.6]
"geometry.crank_length" = ["50 mm", "60 mm"]
"motion.initial_speed" = ["300 rpm", "3000 rpm"]
"#;

/// Each summary metric of `case`'s run, by crank train and name, as its bits.
fn metrics(case: &cardan_case::Case) -> Vec<(String, String, u64)> {
    let results = run_case(case, None).unwrap();
    results
        .iter()
        .flat_map(|r| {
            r.summary
                .metrics
                .iter()
                .map(|m| (r.label.clone(), m.name.clone(), m.value.to_bits()))
        })
        .collect()
}

#[test]
fn every_point_of_a_sweep_over_the_gear_is_its_case_made_alone() {
    let file = Path::new("memo.toml");
    let table: toml::Table = toml::from_str(CASE).unwrap();
    let sweep = Sweep::define(file, table).unwrap().unwrap();
    assert_eq!(sweep.len(), 24);
    // The points made as a table sweep makes them: on the worker threads, one sweep's memo.
    let shared: Vec<cardan_case::Case> = (0..sweep.len())
        .into_par_iter()
        .map(|k| point_to_run(&sweep, k).unwrap())
        .collect();
    let mut ratings = Vec::new();
    for (k, point) in shared.iter().enumerate() {
        let alone = case_of_table(file, sweep.point(k).unwrap().table).unwrap();
        // The point's own case knows its sweep; the same case made alone does not.
        let unswept = cardan_case::Case {
            sweep: None,
            ..point.clone()
        };
        let same = format!("{unswept:?}") == format!("{alone:?}");
        assert!(
            same,
            "point {k}: its validated form is not its case's alone"
        );
        let setups = |c: &cardan_case::Case| format!("{:?}", c.setups);
        assert!(setups(point) == setups(&alone), "point {k}: setups");
        assert_eq!(metrics(point), metrics(&alone), "point {k}: summary");
        ratings.push(setups(point));
    }
    // The setups hold the J factors: points of another pair (teeth, addendum, crank) differ, the
    // points of one pair at two speeds have the same factors. Points k and k + 12 differ in the
    // speed only; k and k + 1 in the teeth.
    let j_of = |s: &str| -> Vec<String> {
        s.match_indices("j: ")
            .map(|(i, _)| s[i..].chars().take_while(|c| *c != ',').collect())
            .collect()
    };
    assert!(!j_of(&ratings[0]).is_empty(), "the setups show no J");
    for k in 0..12 {
        assert_eq!(j_of(&ratings[k]), j_of(&ratings[k + 12]), "point {k}");
    }
    for k in [0, 1, 3, 6] {
        assert_ne!(
            j_of(&ratings[k]),
            j_of(&ratings[k + 1]),
            "points {k} and {}",
            k + 1
        );
    }
}
