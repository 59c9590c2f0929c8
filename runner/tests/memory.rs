//! A case run in memory (`cardan_runner::memory`, the Python package's entry) gives the batch's
//! numbers: its summary is the `summary.json` a batch writes, its per-step columns the CSV's
//! (bit for bit, with `[output] decimation`), a sweep's table the `sweep.csv` of the same sweep.

use cardan_case::case::{cases_of_table, parse};
use cardan_runner::memory::{run_in_memory, run_sweep, SweepTable};
use cardan_runner::{run_paths, RunOptions};
use std::path::Path;

/// The loaded thesis pump, every 7th step written.
fn case() -> String {
    cardan_testing::cases::loaded_thesis_pump("memory") + "[output]\ndecimation = 7\n"
}

/// The batch's output folder of `text` written as `name.toml`.
fn batch(text: &str, name: &str) -> tempfile::TempDir {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join(format!("{name}.toml"));
    std::fs::write(&file, text).unwrap();
    let out = dir.path().join("out");
    let report = run_paths(&[file], &out, RunOptions::default());
    assert!(report.failures.is_empty(), "{:?}", report.failures);
    dir
}

#[test]
fn a_case_in_memory_is_the_batchs_summary_and_csv() {
    let dir = batch(&case(), "memory");
    let folder = dir.path().join("out/memory");
    let written: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(folder.join("summary.json")).unwrap())
            .unwrap();
    let case = parse(Path::new("memory.toml"), &case()).unwrap();
    for steps in [true, false] {
        let run = run_in_memory(&case, steps).unwrap();
        assert_eq!(run.summary, written, "steps kept: {steps}");
        assert_eq!(run.steps.len(), if steps { 2 } else { 0 });
    }
    let run = run_in_memory(&case, true).unwrap();
    for (result, columns) in run.results.iter().zip(&run.steps) {
        let mut csv = csv::Reader::from_path(folder.join(format!("{}.csv", result.label))).unwrap();
        let header: Vec<String> = csv.headers().unwrap().iter().map(String::from).collect();
        assert_eq!(columns.names, header);
        let rows: Vec<csv::StringRecord> = csv.records().map(Result::unwrap).collect();
        // Every 7th of 1442 points and the last.
        assert_eq!(rows.len(), 207);
        assert_eq!(columns.rows(), rows.len());
        for (k, name) in header.iter().enumerate() {
            for (row, record) in rows.iter().enumerate() {
                let cell = &record[k];
                let want = if cell.is_empty() {
                    f64::NAN
                } else {
                    cell.parse::<f64>().unwrap()
                };
                let got = columns.values[k][row];
                assert!(
                    got.to_bits() == want.to_bits() || (got.is_nan() && want.is_nan()),
                    "{}: {name} row {row}: {got} against the CSV's {want}",
                    result.label
                );
            }
        }
    }
}

#[test]
fn a_sweep_in_memory_is_sweep_csv() {
    let text = case().replace("steps = 1441", "steps = 360")
        + "[sweep]\n\"motion.initial_speed\" = [\"30 rad/s\", 300.0]\n\"geometry.rod_length\" = { from = \"140 mm\", to = \"200 mm\", points = 3 }\n";
    let dir = batch(&text, "memory-sweep");
    let written = std::fs::read_to_string(dir.path().join("out/memory/sweep.csv")).unwrap();
    let table: toml::Table = toml::from_str(&text).unwrap();
    let cases = cases_of_table(Path::new("memory-sweep.toml"), table).unwrap();
    let results: Vec<_> = run_sweep(&cases).into_iter().map(Result::unwrap).collect();
    let points: Vec<_> = cases
        .iter()
        .zip(&results)
        .map(|(c, r)| (c, &r[..]))
        .collect();
    let t = SweepTable::new(&points);
    let mut csv = csv::Reader::from_reader(written.as_bytes());
    let header: Vec<String> = csv.headers().unwrap().iter().map(String::from).collect();
    let mut names = vec!["case".to_string()];
    names.extend(t.swept.iter().map(|(p, _)| p.clone()));
    names.extend(t.metrics.iter().map(|(m, _)| m.clone()));
    assert_eq!(names, header);
    let rows: Vec<csv::StringRecord> = csv.records().map(Result::unwrap).collect();
    assert_eq!(rows.len(), 6);
    for (i, record) in rows.iter().enumerate() {
        assert_eq!(record[0], t.case[i]);
        for (k, (path, values)) in t.swept.iter().enumerate() {
            assert_eq!(record[1 + k], values[i], "{path}");
        }
        for (k, (name, values)) in t.metrics.iter().enumerate() {
            let cell: f64 = record[1 + t.swept.len() + k].parse().unwrap();
            assert_eq!(cell.to_bits(), values[i].to_bits(), "point {i}: {name}");
        }
    }
}
