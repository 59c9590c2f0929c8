//! A sweep without case folders (`[output] case_folders = false`, issue 26): its table read
//! back (one NPY file per column, described by `sweep.json`) holds, bit for bit, what the same
//! sweep with folders writes in `sweep.csv`; no point folder is written; sharded and merged
//! it is the single run's; the default follows the number of points.

use cardan_runner::run::{case_folders, load_cases, merge, shard, CASE_FOLDERS_UP_TO};
use cardan_runner::{run_paths, RunOptions};
use serde_json::Value;
use std::path::{Path, PathBuf};

/// The shipped speed-and-rod map (80 points) under the name `t`, with `[output] case_folders`.
fn sweep_file(dir: &Path, folders: bool) -> PathBuf {
    let text = std::fs::read_to_string(
        Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("../configs/sweeps/karhula-pump-map-speed-rod.toml"),
    )
    .unwrap();
    let name = text.lines().find(|l| l.starts_with("name = ")).unwrap();
    let text = text.replacen(name, "name = \"t\"", 1).replacen(
        "[output]",
        &format!("[output]\ncase_folders = {folders}"),
        1,
    );
    assert!(text.contains("case_folders"));
    let file = dir.join(format!("t-{folders}.toml"));
    std::fs::write(&file, text).unwrap();
    file
}

/// A one-dimensional NPY array's type and raw values.
fn read_npy(path: &Path) -> (String, Vec<u8>) {
    let bytes = std::fs::read(path).unwrap();
    assert_eq!(&bytes[..8], b"\x93NUMPY\x01\x00", "{}", path.display());
    let len = u16::from_le_bytes([bytes[8], bytes[9]]) as usize;
    let header = String::from_utf8(bytes[10..10 + len].to_vec()).unwrap();
    assert_eq!((10 + len) % 64, 0, "aligned");
    let descr = header.split('\'').nth(3).unwrap().to_string();
    (descr, bytes[10 + len..].to_vec())
}

#[test]
fn the_table_holds_the_sweep_csv_bit_for_bit() {
    let tmp = tempfile::tempdir().unwrap();
    let (with, without) = (tmp.path().join("with"), tmp.path().join("without"));
    let o = RunOptions::default();
    let r = run_paths(&[sweep_file(tmp.path(), true)], &with, o.clone());
    assert!(r.failures.is_empty(), "{:?}", r.failures);
    let r = run_paths(&[sweep_file(tmp.path(), false)], &without, o.clone());
    assert!(r.failures.is_empty(), "{:?}", r.failures);
    assert_eq!(r.sweeps.len(), 1);
    assert_eq!(r.sweeps[0].2, 80, "points");
    assert!(r.written.is_empty(), "no case folder: {:?}", r.written);
    let dir = without.join("t");
    let entries: Vec<String> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    assert_eq!(entries.len(), 2, "{entries:?}");
    let header: Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join("sweep.json")).unwrap()).unwrap();
    assert_eq!(header["rows"], 80);
    let mut csv = csv::Reader::from_path(with.join("t/sweep.csv")).unwrap();
    let names: Vec<String> = csv.headers().unwrap().iter().map(String::from).collect();
    let rows: Vec<csv::StringRecord> = csv.records().map(Result::unwrap).collect();
    assert_eq!(rows.len(), 80);
    let columns = header["columns"].as_array().unwrap();
    let listed: Vec<&str> = columns
        .iter()
        .map(|c| c["name"].as_str().unwrap())
        .collect();
    assert_eq!(listed, names, "the table's columns are sweep.csv's");
    for (k, c) in columns.iter().enumerate() {
        let (descr, data) = read_npy(&dir.join(c["file"].as_str().unwrap()));
        assert_eq!(descr, c["dtype"].as_str().unwrap());
        if let Some(width) = descr.strip_prefix("|S") {
            let width: usize = width.parse().unwrap();
            assert_eq!(data.len(), 80 * width);
            for (row, text) in rows.iter().zip(data.chunks(width)) {
                let text = String::from_utf8(text.to_vec()).unwrap();
                assert_eq!(text.trim_end_matches('\0'), &row[k], "{}", names[k]);
            }
        } else {
            assert_eq!(descr, "<f8");
            assert!(c["unit"].is_string(), "{c}");
            assert_eq!(data.len(), 80 * 8);
            for (row, v) in rows.iter().zip(data.chunks(8)) {
                let v = f64::from_le_bytes(v.try_into().unwrap());
                let expected: f64 = row[k].parse().unwrap();
                assert_eq!(v.to_bits(), expected.to_bits(), "{}", names[k]);
            }
        }
    }

    // In two shards (the table split between them), merged: the single run's folder.
    let shards: Vec<PathBuf> = (1..=2).map(|k| tmp.path().join(format!("s{k}"))).collect();
    let both = [sweep_file(tmp.path(), false), with.join("../t-true.toml")];
    let single = tmp.path().join("single");
    let renamed =
        std::fs::read_to_string(&both[1])
            .unwrap()
            .replacen("name = \"t\"", "name = \"u\"", 1);
    std::fs::write(&both[1], renamed).unwrap();
    assert!(run_paths(&both, &single, o.clone()).failures.is_empty());
    for (k, s) in shards.iter().enumerate() {
        let o = RunOptions {
            shard: Some((k + 1, 2)),
            ..o.clone()
        };
        assert!(run_paths(&both, s, o).failures.is_empty());
    }
    let merged = tmp.path().join("merged");
    assert!(merge(&shards, &merged).failures.is_empty());
    assert_same_tree(&single, &merged);
}

#[test]
fn sweeps_of_many_points_default_to_the_table() {
    let tmp = tempfile::tempdir().unwrap();
    let file = sweep_file(tmp.path(), true);
    let text = std::fs::read_to_string(&file)
        .unwrap()
        .replace("case_folders = true\n", "");
    std::fs::write(&file, text).unwrap();
    let (cases, failures) = load_cases(&[file]);
    assert!(failures.is_empty(), "{failures:?}");
    assert!(case_folders(&cases[0], CASE_FOLDERS_UP_TO));
    assert!(!case_folders(&cases[0], CASE_FOLDERS_UP_TO + 1));
    let mut asked = cases[0].clone();
    asked.output.case_folders = Some(true);
    assert!(case_folders(&asked, 10 * CASE_FOLDERS_UP_TO));
}

/// A table sweep of 80 points split over 3 shards: each shard runs one contiguous range of its
/// points (recorded in `shard.json` and its part's `sweep.json`), and the merge joins the
/// parts into the single run's table byte for byte; a part missing, or two parts holding the
/// same points, are refused before anything is written, naming the points.
#[test]
fn a_table_split_over_three_shards_merges_into_the_single_run() {
    let tmp = tempfile::tempdir().unwrap();
    let file = sweep_file(tmp.path(), false);
    let o = RunOptions::default();
    let single = tmp.path().join("single");
    assert!(run_paths(std::slice::from_ref(&file), &single, o.clone())
        .failures
        .is_empty());
    let shards: Vec<PathBuf> = (1..=3).map(|k| tmp.path().join(format!("s{k}"))).collect();
    let mut ranges = Vec::new();
    for (k, s) in shards.iter().enumerate() {
        let o = RunOptions {
            shard: Some((k + 1, 3)),
            ..o.clone()
        };
        let r = run_paths(std::slice::from_ref(&file), s, o);
        assert!(r.failures.is_empty(), "{:?}", r.failures);
        let record = shard::Manifest::read(s).unwrap();
        assert_eq!(record.tables.len(), 1);
        let (name, points, all) = &record.tables[0];
        assert_eq!((name.as_str(), *points), ("t", 80));
        assert_eq!(all.len(), 3, "a range per shard: {all:?}");
        let part: Value =
            serde_json::from_str(&std::fs::read_to_string(s.join("t/sweep.json")).unwrap())
                .unwrap();
        let (start, end, _) = all[k];
        assert_eq!(part["range"], serde_json::json!([start, end]));
        assert_eq!(part["rows"], end - start);
        assert_eq!(r.sweeps[0].2, end - start, "points run by shard {}", k + 1);
        ranges.push((start, end));
    }
    // Contiguous, in shard order, every point once, near-equal (the points cost the same).
    assert_eq!(ranges.first().unwrap().0, 0);
    assert_eq!(ranges.last().unwrap().1, 80);
    for w in ranges.windows(2) {
        assert_eq!(w[0].1, w[1].0, "{ranges:?}");
    }
    assert!(
        ranges.iter().all(|(a, b)| (26..=27).contains(&(b - a))),
        "{ranges:?}"
    );
    let merged = tmp.path().join("merged");
    let r = merge(
        &[shards[1].clone(), shards[2].clone(), shards[0].clone()],
        &merged,
    );
    assert!(r.failures.is_empty(), "{:?}", r.failures);
    assert_eq!(r.sweeps[0].2, 80);
    assert_same_tree(&single, &merged);

    let refused = |words: &[&str]| {
        let out = tmp.path().join("refused");
        let said = merge(&shards, &out).failures.join("\n");
        assert!(said.contains("cannot merge"), "{said}");
        for w in words {
            assert!(said.contains(w), "{w:?} not in: {said}");
        }
        assert!(!out.exists(), "a refused merge wrote {}", out.display());
    };
    // Shard 3's part holding shard 2's points as well: overlapping.
    let part3 = shards[2].join("t/sweep.json");
    let text = std::fs::read_to_string(&part3).unwrap();
    let (s2, s3) = (ranges[1].0, ranges[2].0);
    let widened = text.replacen(&format!("\n    {s3},"), &format!("\n    {s2},"), 1);
    assert_ne!(widened, text);
    std::fs::write(&part3, widened).unwrap();
    refused(&[&format!("points {s2}..{s3} in"), "overlapping"]);
    std::fs::write(&part3, &text).unwrap();
    // Shard 2's part gone: its points are missing.
    std::fs::remove_file(shards[1].join("t/sweep.json")).unwrap();
    refused(&[&format!("points {s2}..{s3}"), "missing"]);
}

/// `[output] metrics`: a table sweep with 3 metrics writes exactly the case and swept columns
/// and those 3 of each mechanism, in the summary's order, with the full table's values bit for
/// bit; a folder sweep's `sweep.csv` holds the same columns; summary.json keeps every metric.
/// A misspelled metric is refused naming the field and the nearest name, before anything runs.
#[test]
fn the_metrics_chosen_are_the_tables_columns() {
    let tmp = tempfile::tempdir().unwrap();
    let full = tmp.path().join("full");
    let o = RunOptions::default();
    assert!(
        run_paths(&[sweep_file(tmp.path(), false)], &full, o.clone())
            .failures
            .is_empty()
    );
    let chosen = [
        "power_loss_mean",
        "mechanical_efficiency",
        "total_crank_pin_force_max",
    ];
    let with_metrics = |folders: bool, list: &str| {
        let file = sweep_file(tmp.path(), folders);
        let text = std::fs::read_to_string(&file).unwrap().replacen(
            "[output]",
            &format!("[output]\nmetrics = [{list}]"),
            1,
        );
        std::fs::write(&file, text).unwrap();
        file
    };
    let list = chosen.map(|m| format!("\"{m}\"")).join(", ");
    let few = tmp.path().join("few");
    let r = run_paths(&[with_metrics(false, &list)], &few, o.clone());
    assert!(r.failures.is_empty(), "{:?}", r.failures);
    let header = |dir: &Path| -> Value {
        serde_json::from_str(&std::fs::read_to_string(dir.join("t/sweep.json")).unwrap()).unwrap()
    };
    let (all, some) = (header(&full), header(&few));
    let names = |h: &Value| -> Vec<String> {
        h["columns"]
            .as_array()
            .unwrap()
            .iter()
            .map(|c| c["name"].as_str().unwrap().to_string())
            .collect()
    };
    // The summary's order: the full table's columns that are chosen.
    let expected: Vec<String> = all["columns"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|c| {
            let name = c["name"].as_str().unwrap();
            c["dtype"] != "<f8" || chosen.iter().any(|m| name.ends_with(&format!(".{m}")))
        })
        .map(|c| c["name"].as_str().unwrap().to_string())
        .collect();
    let mut wanted = vec!["case".to_string()];
    wanted.extend(["motion.initial_speed", "geometry.rod_length"].map(String::from));
    for mechanism in ["slider_crank", "cardan_gear"] {
        for m in chosen {
            assert!(
                expected.contains(&format!("{mechanism}.{m}")),
                "{expected:?}"
            );
        }
    }
    assert_eq!(
        expected.len(),
        wanted.len() + 2 * chosen.len(),
        "{expected:?}"
    );
    assert_eq!(names(&some), expected);
    for c in &expected {
        let file = format!("t/columns/{c}.npy");
        let (a, b) = (read_npy(&full.join(&file)), read_npy(&few.join(&file)));
        assert_eq!(a, b, "{c}");
    }
    assert_eq!(
        std::fs::read_dir(few.join("t/columns")).unwrap().count(),
        expected.len()
    );
    // With case folders: sweep.csv's columns are the same; each point's summary is whole.
    let folders = tmp.path().join("folders");
    let r = run_paths(&[with_metrics(true, &list)], &folders, o.clone());
    assert!(r.failures.is_empty(), "{:?}", r.failures);
    let mut csv = csv::Reader::from_path(folders.join("t/sweep.csv")).unwrap();
    let header: Vec<String> = csv.headers().unwrap().iter().map(String::from).collect();
    assert_eq!(header, expected);
    let point = &r.written[0].1;
    let summary = std::fs::read_to_string(point.join("summary.json")).unwrap();
    assert!(
        summary.contains("\"loss_work\""),
        "summary.json keeps every metric"
    );

    // Misspelled: refused, nothing run.
    let bad = tmp.path().join("bad");
    let r = run_paths(&[with_metrics(false, "\"mechanical_efficency\"")], &bad, o);
    let said = r.failures.join("\n");
    assert!(
        said.contains("output.metrics = \"mechanical_efficency\"")
            && said.contains("did you mean \"mechanical_efficiency\""),
        "{said}"
    );
    assert!(r.sweeps.is_empty() && !bad.join("t").exists());
}

/// Fails unless the folders `single` and `merged` hold the same files, byte for byte (`diff -r`).
fn assert_same_tree(single: &Path, merged: &Path) {
    let same = std::process::Command::new("diff")
        .arg("-r")
        .arg(single)
        .arg(merged)
        .status()
        .unwrap();
    assert!(same.success(), "merged differs from the single run");
}

/// `--only` selecting some points of a sweep written as a table is refused, naming the sweep,
/// the points selected and the fix, with nothing run: the table written before keeps all its
/// rows, byte for byte. A pattern selecting every point runs the whole table.
#[test]
fn only_some_points_of_a_table_are_refused() {
    let tmp = tempfile::tempdir().unwrap();
    let file = tmp.path().join("s.toml");
    std::fs::write(
        &file,
        r#"name = "s"
machine = "pump"
mechanisms = ["slider_crank"]
[geometry]
crank_length = 0.06
rod_length = 0.14
bore = 0.12
[motion]
start_angle = 0.0
end_angle = 360.0
initial_speed = 31.4
angular_acceleration = 0.0
steps = 36
[output]
case_folders = false
[sweep]
"motion.initial_speed" = [10.0, 20.0, 30.0, 40.0, 50.0, 60.0]
"#,
    )
    .unwrap();
    let out = tmp.path().join("out");
    let r = run_paths(std::slice::from_ref(&file), &out, RunOptions::default());
    assert!(r.failures.is_empty(), "{:?}", r.failures);
    let table = |out: &Path| -> Vec<(String, Vec<u8>)> {
        let mut files: Vec<(String, Vec<u8>)> = std::fs::read_dir(out.join("s/columns"))
            .unwrap()
            .map(|e| e.unwrap().path())
            .map(|p| (p.display().to_string(), std::fs::read(&p).unwrap()))
            .collect();
        files.push((
            "sweep.json".into(),
            std::fs::read(out.join("s/sweep.json")).unwrap(),
        ));
        files.sort();
        files
    };
    let before = table(&out);
    let text = std::fs::read_to_string(&file).unwrap();
    let sweep = cardan_case::sweep::Sweep::define(&file, toml::from_str(&text).unwrap())
        .unwrap()
        .unwrap();
    let second = sweep.point_name(1);
    let o = RunOptions {
        only: Some(second.clone()),
        ..RunOptions::default()
    };
    let r = run_paths(std::slice::from_ref(&file), &out, o);
    let said = r.failures.join("\n");
    for part in [
        "selects 1 of the 6 points of the sweep \"s\"",
        "written as a table",
        "case_folders = true",
    ] {
        assert!(said.contains(part), "{part:?} not in: {said}");
    }
    assert!(r.sweeps.is_empty() && r.written.is_empty(), "{r:?}");
    assert_eq!(before, table(&out), "the table changed");
    // Every point selected: the whole table, as without --only.
    let o = RunOptions {
        only: Some("s*".into()),
        ..RunOptions::default()
    };
    let r = run_paths(std::slice::from_ref(&file), &out, o);
    assert!(r.failures.is_empty(), "{:?}", r.failures);
    assert_eq!(r.sweeps[0].2, 6);
    assert_eq!(before, table(&out));
}
