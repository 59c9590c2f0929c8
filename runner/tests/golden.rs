//! Reviewed snapshots of every shipped case's summary, kept in golden/.
//!
//! Floats are rounded to 6 significant digits, well above the round-off of the runs and below
//! any change a reviewer should see; magnitudes under 1e-6 (SI) are written as 0: they are
//! the quadrature round-off of quantities that vanish, such as the inertial work at constant
//! speed (about 1e-12 J), and would differ between machines.

use cardan_case::case;
use cardan_case::optimize::Optimization;
use cardan_runner::optimize::{optimize, optimum_json};
use cardan_runner::{output, run_case};
use serde_json::Value;
use std::path::{Path, PathBuf};

fn round(v: &mut Value) {
    match v {
        Value::Number(n) => {
            let x = n.as_f64().unwrap();
            let r = if x.abs() < 1e-6 {
                0.0
            } else {
                format!("{x:.5e}").parse::<f64>().unwrap()
            };
            *v = serde_json::json!(r);
        }
        Value::Array(a) => a.iter_mut().for_each(round),
        Value::Object(o) => o.values_mut().for_each(round),
        _ => {}
    }
}

/// A dynamic run's `runup` (up to `MAX_RUNUP_POINTS` points a mechanism, thinned by the run)
/// as its digest, so that a snapshot stays reviewable: its number of points, its first and last
/// (time s, speed rad/s) and its smallest and largest speed (the series itself is checked against
/// the cycle starts, the CSV and its chart in report_charts.rs, its thinning in
/// cardan-dynamics' runup.rs and machine_motion.rs).
fn digest_runup(summary: &mut Value) {
    let Some(mechanisms) = summary.get_mut("mechanisms").and_then(Value::as_object_mut) else {
        return;
    };
    for m in mechanisms.values_mut() {
        let Some(runup) = m.get("runup") else {
            continue;
        };
        let list = |k: &str| -> Vec<f64> {
            runup[k]
                .as_array()
                .unwrap()
                .iter()
                .map(|x| x.as_f64().unwrap())
                .collect()
        };
        let (t, w) = (list("time_s"), list("crank_speed_rad_s"));
        let n = t.len();
        m["runup"] = serde_json::json!({
            "points": n,
            "first": [t[0], w[0]],
            "last": [t[n - 1], w[n - 1]],
            "crank_speed_min_rad_s": w.iter().copied().fold(f64::MAX, f64::min),
            "crank_speed_max_rad_s": w.iter().copied().fold(f64::MIN, f64::max),
        });
    }
}

/// Runs the shipped case `configs/<stem>.toml` and compares its rounded summary with
/// `golden/<stem>.snap`.
fn check(stem: &str) {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    let file = root.join("configs").join(format!("{stem}.toml"));
    if let Some(o) = optimization(&file) {
        return snapshot(&root, stem, optimization_summary(&o));
    }
    let cases = case::load_file(&file).unwrap_or_else(|e| panic!("{e}"));
    assert!(
        cases[0].sweep.is_none(),
        "{stem} is a sweep: its points are checked by running it (runner/tests/sweep.rs)"
    );
    let case = &cases[0];
    let summary = output::summary_json(
        case,
        &run_case(case, None).unwrap_or_else(|e| panic!("{e}")),
    );
    snapshot(&root, stem, summary);
}

/// The optimisation of the case file `file`, if it has an `[optimize]` table.
fn optimization(file: &Path) -> Option<Optimization> {
    let text = std::fs::read_to_string(file).unwrap();
    let table = case::toml_table(file, &text).unwrap_or_else(|e| panic!("{e}"));
    Optimization::define(file, table).unwrap_or_else(|e| panic!("{e}"))
}

/// An optimisation's summary: each mechanism's `optimum.json` (its variables, objective,
/// constraints with their margins, evaluations and stopping reason) and the summary of every
/// mechanism at its own optimum (`at-optima/summary.json`), as `cardan run` writes them.
fn optimization_summary(o: &Optimization) -> Value {
    let results = optimize(o).unwrap_or_else(|e| panic!("{e}"));
    let optima: serde_json::Map<String, Value> = results
        .iter()
        .map(|m| (m.mechanism.clone(), optimum_json(o, m)))
        .collect();
    let bests: Vec<_> = results.iter().filter_map(|m| m.best.clone()).collect();
    let (case, _) = bests.first().expect("an optimum");
    let all: Vec<_> = bests.iter().map(|(_, r)| r.clone()).collect();
    serde_json::json!({
        "optimum": optima,
        "at_optima": output::summary_json(case, &all),
    })
}

/// Compares `summary`, rounded, with `golden/<stem>.snap`.
fn snapshot(root: &Path, stem: &str, mut summary: Value) {
    digest_runup(&mut summary);
    round(&mut summary);
    insta::with_settings!({ snapshot_path => root.join("golden"), prepend_module_to_snapshot => false, omit_expression => true }, {
        insta::assert_json_snapshot!(stem, summary);
    });
}

/// One test per shipped case, so that every mismatch is reported, not only the first; the
/// list is checked against `configs/` by `every_shipped_case_has_its_golden_test`.
macro_rules! golden {
    ($($test:ident => $stem:literal,)*) => {
        $(
            #[test]
            fn $test() {
                check($stem);
            }
        )*
        const STEMS: &[&str] = &[$($stem),*];
    };
}

golden! {
    balance_boxer4 => "balance-boxer4",
    balance_inline3 => "balance-inline3",
    balance_inline4 => "balance-inline4",
    balance_inline6 => "balance-inline6",
    balance_radial5_cardan => "balance-radial5-cardan",
    balance_thesis_single_cw0 => "balance-thesis-single-cw0",
    balance_thesis_single_cw100 => "balance-thesis-single-cw100",
    balance_thesis_single_cw50 => "balance-thesis-single-cw50",
    balance_vee_twin_90 => "balance-vee-twin-90",
    balance_w3_cardan => "balance-w3-cardan",
    example_compressor => "example-compressor",
    example_offset_engine => "example-offset-engine",
    example_pressure_trace => "example-pressure-trace",
    example_scotch_yoke_compressor => "example-scotch-yoke-compressor",
    karhula_engine_r60_l140_a0_w200pi_titanium => "karhula-engine-r60-l140-a0-w200pi-titanium",
    karhula_pump_r60_l140_a0_w30pi => "karhula-pump-r60-l140-a0-w30pi",
    karhula_engine_dynamic_mean_load => "karhula-engine-dynamic-mean-load",
    karhula_engine_dynamic_flywheel => "karhula-engine-dynamic-flywheel",
    karhula_engine_dynamic_cs001 => "karhula-engine-dynamic-cs001",
    karhula_pump_motor_dynamic => "karhula-pump-motor-dynamic",
    karhula_pump_inline3_motor_dynamic => "karhula-pump-inline3-motor-dynamic",
    karhula_pump_motor_runup => "karhula-pump-motor-runup",
    karhula_pump_r60_l140_a0_w3pi => "karhula-pump-r60-l140-a0-w3pi",
    karhula_r60_l140_a0_w200pi_titanium => "karhula-r60-l140-a0-w200pi-titanium",
    karhula_r60_l140_a0_w200pi => "karhula-r60-l140-a0-w200pi",
    karhula_r60_l140_a0_w3pi => "karhula-r60-l140-a0-w3pi",
    karhula_r60_l140_a100pi_w200pi => "karhula-r60-l140-a100pi-w200pi",
    karhula_r60_l140_a100pi_w30pi => "karhula-r60-l140-a100pi-w30pi",
    karhula_r60_l140_a100pi_w3pi => "karhula-r60-l140-a100pi-w3pi",
    karhula_r60_l140_a200pi_w200pi => "karhula-r60-l140-a200pi-w200pi",
    nunes_op_r26_l90_2000rpm_lead10 => "nunes-op-r26-l90-2000rpm-lead10",
    nunes_op_r26_l90_2000rpm => "nunes-op-r26-l90-2000rpm",
    optimize_thesis_pump => "optimize-thesis-pump",
    vidinsky_hm2_p75_r340 => "vidinsky-hm2-p75-r340",
    vidinsky_hm3_p75_r510 => "vidinsky-hm3-p75-r510",
}

#[test]
fn every_shipped_case_has_its_golden_test() {
    // Every non-sweep case under configs/ is in the list above, and every listed case and
    // snapshot exists: a case added without its test, or a test left after its case, fails.
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    let (files, failures) = cardan_runner::run::case_files(&[root.join("configs")]);
    assert!(failures.is_empty(), "{failures:?}");
    let mut shipped: Vec<String> = files
        .iter()
        .filter(|file| {
            optimization(file).is_some() || {
                let cases = case::load_file(file).unwrap_or_else(|e| panic!("{e}"));
                cases[0].sweep.is_none()
            }
        })
        .map(|file| {
            PathBuf::from(file)
                .file_stem()
                .unwrap()
                .to_string_lossy()
                .to_string()
        })
        .collect();
    shipped.sort();
    let mut listed: Vec<String> = STEMS.iter().map(|s| s.to_string()).collect();
    listed.sort();
    assert_eq!(listed, shipped, "golden! {{ ... }} against configs/");
    for stem in STEMS {
        let snap = root.join("golden").join(format!("{stem}.snap"));
        assert!(snap.is_file(), "{} is missing", snap.display());
    }
}
