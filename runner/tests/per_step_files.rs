//! The per-step files: the NPY array holds exactly the numbers of the CSV (NaN where a CSV
//! cell is empty), column after column, with the CSV header as its column names; both follow
//! `[output] decimation`; both are byte-identical between runs and thread counts.

use cardan_runner::{run_paths, RunOptions};
use std::path::Path;

/// The loaded thesis pump.
fn case() -> String {
    cardan_testing::cases::loaded_thesis_pump("npy")
}

/// An NPY 1.0 file of f64 in Fortran order, as (rows, columns, values column after column).
fn read_npy(path: &Path) -> (usize, usize, Vec<f64>) {
    let bytes = std::fs::read(path).unwrap();
    assert_eq!(&bytes[..8], b"\x93NUMPY\x01\x00", "NPY 1.0 magic");
    let len = u16::from_le_bytes([bytes[8], bytes[9]]) as usize;
    let header = std::str::from_utf8(&bytes[10..10 + len]).unwrap();
    assert_eq!((10 + len) % 64, 0, "data aligned to 64 bytes");
    assert!(header.contains("'descr': '<f8'") && header.contains("'fortran_order': True"));
    let shape = header.split("'shape': (").nth(1).unwrap();
    let shape: Vec<usize> = shape[..shape.find(')').unwrap()]
        .split(',')
        .map(|s| s.trim().parse().unwrap())
        .collect();
    let data: Vec<f64> = bytes[10 + len..]
        .chunks_exact(8)
        .map(|b| f64::from_le_bytes(b.try_into().unwrap()))
        .collect();
    assert_eq!(
        data.len(),
        shape[0] * shape[1],
        "the data fill the shape exactly"
    );
    (shape[0], shape[1], data)
}

fn run(dir: &Path, text: &str, jobs: Option<usize>) {
    let file = dir.join("case.toml");
    std::fs::write(&file, text).unwrap();
    let options = RunOptions {
        jobs,
        npy: Some(true),
        ..RunOptions::default()
    };
    let report = run_paths(&[file], &dir.join("out"), options);
    assert!(report.failures.is_empty(), "{:?}", report.failures);
}

fn check_npy_equals_csv(case_dir: &Path, mechanism: &str, rows_expected: usize) {
    let (rows, columns, data) = read_npy(&case_dir.join(format!("{mechanism}.npy")));
    let names: Vec<String> = serde_json::from_str(
        &std::fs::read_to_string(case_dir.join(format!("{mechanism}.columns.json"))).unwrap(),
    )
    .unwrap();
    let csv = std::fs::read_to_string(case_dir.join(format!("{mechanism}.csv"))).unwrap();
    let mut lines = csv.lines();
    assert_eq!(lines.next().unwrap().split(',').collect::<Vec<_>>(), names);
    assert_eq!((rows, columns), (rows_expected, names.len()));
    let mut seen = 0;
    for (r, line) in lines.enumerate() {
        for (c, cell) in line.split(',').enumerate() {
            let v = data[c * rows + r];
            if cell.is_empty() {
                assert!(
                    v.is_nan(),
                    "{mechanism} row {r} {}: {v} for an empty cell",
                    names[c]
                );
            } else {
                // Shortest round-trip text: the same bits.
                let x: f64 = cell.parse().unwrap();
                assert_eq!(x.to_bits(), v.to_bits(), "{mechanism} row {r} {}", names[c]);
            }
        }
        seen += 1;
    }
    assert_eq!(seen, rows);
}

#[test]
fn npy_holds_the_csv_numbers_column_after_column() {
    let dir = tempfile::tempdir().unwrap();
    run(dir.path(), &case(), None);
    for m in ["slider_crank", "cardan_gear"] {
        // More rows than one block of the writer, and not a multiple of it.
        check_npy_equals_csv(&dir.path().join("out/npy"), m, 1442);
    }
}

#[test]
fn npy_of_many_blocks_holds_the_csv_numbers() {
    // 9001 rows: 17 full blocks of the writer (512 rows) and a part, each written in place.
    let dir = tempfile::tempdir().unwrap();
    run(
        dir.path(),
        &case().replace("steps = 1441", "steps = 9000"),
        None,
    );
    check_npy_equals_csv(&dir.path().join("out/npy"), "cardan_gear", 9001);
}

#[test]
fn npy_follows_decimation() {
    let dir = tempfile::tempdir().unwrap();
    run(
        dir.path(),
        &format!("{}[output]\ndecimation = 100\n", case()),
        None,
    );
    // Steps 0, 100, ..., 1400 and the last, 1441.
    check_npy_equals_csv(&dir.path().join("out/npy"), "cardan_gear", 16);
}

#[test]
fn npy_alone_without_csv() {
    let dir = tempfile::tempdir().unwrap();
    run(
        dir.path(),
        &format!("{}[output]\ncsv = false\nnpy = true\n", case()),
        None,
    );
    let case = dir.path().join("out/npy");
    assert!(!case.join("cardan_gear.csv").exists());
    let (rows, columns, data) = read_npy(&case.join("cardan_gear.npy"));
    assert_eq!(rows, 1442);
    // The first column is the crank angle, 90° to 810° in equal steps.
    assert_eq!(data[0], 90.0);
    assert!((data[rows - 1] - 810.0).abs() < 1e-9);
    assert!(columns > 50);
}

#[test]
fn per_step_files_are_byte_identical_between_thread_counts() {
    let one = tempfile::tempdir().unwrap();
    let two = tempfile::tempdir().unwrap();
    run(one.path(), &case(), Some(1));
    run(two.path(), &case(), Some(2));
    for file in [
        "cardan_gear.csv",
        "cardan_gear.npy",
        "slider_crank.csv",
        "slider_crank.npy",
        "summary.json",
    ] {
        let a = std::fs::read(one.path().join("out/npy").join(file)).unwrap();
        let b = std::fs::read(two.path().join("out/npy").join(file)).unwrap();
        assert!(a == b, "{file} differs between 1 and 2 threads");
    }
}

/// A case without per-step files is shared by the threads (four pieces of 2304 steps), one with
/// them is not: the same summary.json, byte for byte, with 1 and 2 threads, with and without
/// files, with the report (its charts taken by the pieces) and without.
#[test]
fn a_shared_run_writes_the_summary_of_a_run_on_one_thread() {
    let case = case().replace("steps = 1441", "steps = 9000");
    let mut summaries = Vec::new();
    for (jobs, files, reports) in [
        (1, true, false),
        (1, false, false),
        (2, false, false),
        (2, false, true),
    ] {
        let dir = tempfile::tempdir().unwrap();
        let file = dir.path().join("case.toml");
        std::fs::write(&file, &case).unwrap();
        let options = RunOptions {
            jobs: Some(jobs),
            csv: Some(files),
            npy: Some(false),
            reports,
            ..RunOptions::default()
        };
        let report = run_paths(&[file], &dir.path().join("out"), options);
        assert!(report.failures.is_empty(), "{:?}", report.failures);
        let out = dir.path().join("out/npy");
        assert_eq!(out.join("slider_crank.csv").exists(), files);
        assert_eq!(out.join("plots").exists(), reports);
        summaries.push(std::fs::read(out.join("summary.json")).unwrap());
    }
    for (k, s) in summaries.iter().enumerate() {
        assert!(
            *s == summaries[0],
            "run {k} differs from the run with files"
        );
    }
}
