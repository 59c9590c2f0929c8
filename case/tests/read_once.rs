//! Issue 36.10: a file a case file's cases read (a pressure trace) is read and parsed once
//! for all the points of a sweep, which then share the one parsed trace.

use cardan_case::case::{cases_of_table, point_case, toml_table};
use cardan_case::sweep::Sweep;
use std::path::Path;

/// The shipped trace case with a sweep over the speed added.
fn trace_sweep() -> (std::path::PathBuf, toml::Table) {
    let file = Path::new(env!("CARGO_MANIFEST_DIR")).join("../configs/example-pressure-trace.toml");
    let text = std::fs::read_to_string(&file).unwrap();
    let text = format!(
        "{text}\n[sweep]\n\"motion.initial_speed\" = [\"3000 rpm\", \"4000 rpm\", \"5000 rpm\"]\n"
    );
    let table = toml_table(&file, &text).unwrap();
    (file, table)
}

/// The address of a case's gas model: the parsed trace.
fn model_address(case: &cardan_case::case::Case) -> *const () {
    let gas = case.gas.as_ref().expect("the case has gas");
    gas.model() as *const dyn cardan_gas::GasModel as *const ()
}

#[test]
fn the_points_of_a_sweep_share_one_parsed_trace() {
    let (file, table) = trace_sweep();
    let cases = cases_of_table(&file, table.clone()).unwrap();
    assert_eq!(cases.len(), 3);
    for case in &cases[1..] {
        assert_eq!(model_address(case), model_address(&cases[0]));
        // The input digest still holds the trace's bytes.
        assert_eq!(
            case.gas.as_ref().unwrap().files,
            cases[0].gas.as_ref().unwrap().files
        );
    }
    // A sweep made point by point (a table sweep) shares it too.
    let sweep = Sweep::define(&file, table).unwrap().unwrap();
    let a = point_case(&sweep, 0).unwrap();
    let b = point_case(&sweep, 2).unwrap();
    assert_eq!(model_address(&a), model_address(&b));
}

#[test]
fn separate_readings_of_a_case_file_read_its_trace_again() {
    // The memo lives with one reading of a case file, not the process: a file edited between
    // two readings (`cardan check`, then `run`) is read as it is then.
    let (file, table) = trace_sweep();
    let a = cases_of_table(&file, table.clone()).unwrap();
    let b = cases_of_table(&file, table).unwrap();
    assert_ne!(model_address(&a[0]), model_address(&b[0]));
}
