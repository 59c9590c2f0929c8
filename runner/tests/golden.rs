//! Reviewed snapshots of every shipped case's summary, kept in golden/.
//!
//! Floats are rounded to 6 significant digits, well above the round-off of the runs and below
//! any change a reviewer should see; magnitudes under 1e-6 (SI) are written as 0: they are
//! the quadrature round-off of quantities that vanish, such as the inertial work at constant
//! speed (about 1e-12 J), and would differ between machines.

use cardan_runner::{case, output, run_case};
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

#[test]
fn shipped_cases_match_golden_summaries() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    let (files, failures) = cardan_runner::run::case_files(&[root.join("configs")]);
    assert!(failures.is_empty(), "{failures:?}");
    assert!(files.len() >= 8, "the shipped cases are missing: {files:?}");
    for file in files {
        // A sweep's points are checked by running it (runner/tests/sweep.rs, and CI's main job).
        let cases = case::load_file(&file).unwrap_or_else(|e| panic!("{e}"));
        if cases[0].sweep.is_some() {
            continue;
        }
        let case = &cases[0];
        let mut summary = output::summary_json(
            case,
            &run_case(case, None).unwrap_or_else(|e| panic!("{e}")),
        );
        round(&mut summary);
        let name = PathBuf::from(&file)
            .file_stem()
            .unwrap()
            .to_string_lossy()
            .to_string();
        insta::with_settings!({ snapshot_path => root.join("golden"), prepend_module_to_snapshot => false, omit_expression => true }, {
            insta::assert_json_snapshot!(name, summary);
        });
    }
}
