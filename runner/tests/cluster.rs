//! Beyond one run (issue 26): the shipped configs run in three shards and merged equal one run
//! byte for byte; a run resumed after the states a kill leaves (case folders missing, a
//! sweep's temporary folder half written, a truncated file, leftovers) equals one run byte for
//! byte; shards that do not belong together are refused; the parts are balanced by cost.

use cardan_runner::run::{load_cases, merge, shard};
use cardan_runner::{run_paths, RunOptions};
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

fn configs() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../configs")
}

fn options() -> RunOptions {
    RunOptions {
        reports: true,
        ..RunOptions::default()
    }
}

/// Every file under `dir` (relative path with `/`) and its bytes.
fn tree(dir: &Path) -> BTreeMap<String, Vec<u8>> {
    fn walk(dir: &Path, prefix: &str, out: &mut BTreeMap<String, Vec<u8>>) {
        for entry in std::fs::read_dir(dir).unwrap() {
            let entry = entry.unwrap();
            let name = format!("{prefix}{}", entry.file_name().to_string_lossy());
            if entry.file_type().unwrap().is_dir() {
                walk(&entry.path(), &format!("{name}/"), out);
            } else {
                out.insert(name, std::fs::read(entry.path()).unwrap());
            }
        }
    }
    let mut out = BTreeMap::new();
    walk(dir, "", &mut out);
    out
}

/// Fails naming the first paths that differ (the `diff -r` of two folders).
fn assert_same_tree(expected: &Path, actual: &Path) {
    let (a, b) = (tree(expected), tree(actual));
    let only_a: Vec<&String> = a.keys().filter(|k| !b.contains_key(*k)).collect();
    let only_b: Vec<&String> = b.keys().filter(|k| !a.contains_key(*k)).collect();
    let differ: Vec<&String> = a
        .iter()
        .filter(|(k, v)| b.get(*k).is_some_and(|w| w != *v))
        .map(|(k, _)| k)
        .collect();
    assert!(
        only_a.is_empty() && only_b.is_empty() && differ.is_empty(),
        "only in {}: {only_a:?}\nonly in {}: {only_b:?}\ndiffer: {differ:?}",
        expected.display(),
        actual.display()
    );
    assert!(a.len() > 100, "{} files only", a.len());
}

/// The shipped configs in one run, and in three shards merged: the same files, byte for byte
/// (summaries, per-step CSVs, reports and charts, every sweep's `sweep.csv` and report, the
/// optimisation's folder, the index). Then the shards' records refuse what does not belong together.
#[test]
fn three_shards_merged_equal_one_run_and_strangers_are_refused() {
    let tmp = tempfile::tempdir().unwrap();
    let single = tmp.path().join("single");
    let report = run_paths(&[configs()], &single, options());
    assert!(report.failures.is_empty(), "{:#?}", report.failures);
    let shards: Vec<PathBuf> = (1..=3)
        .map(|k| tmp.path().join(format!("shard{k}")))
        .collect();
    let mut ran = 0;
    for (k, dir) in shards.iter().enumerate() {
        let o = RunOptions {
            shard: Some((k + 1, 3)),
            ..options()
        };
        let report = run_paths(&[configs()], dir, o);
        assert!(report.failures.is_empty(), "{:#?}", report.failures);
        assert!(!report.written.is_empty(), "shard {} ran nothing", k + 1);
        assert!(!dir.join("index.html").exists(), "a shard writes no index");
        ran += report.written.len();
    }
    assert_eq!(ran, report.written.len(), "every case in one shard");
    let merged = tmp.path().join("merged");
    // The shards in any order.
    let report = merge(
        &[shards[2].clone(), shards[0].clone(), shards[1].clone()],
        &merged,
    );
    assert!(report.failures.is_empty(), "{:#?}", report.failures);
    assert_same_tree(&single, &merged);
    // The shipped optimisation (issue 40) among them: run whole by one shard, copied with its
    // record, listed by the index.
    let optimum = "optimize-thesis-pump";
    let holding: Vec<&PathBuf> = shards.iter().filter(|s| s.join(optimum).exists()).collect();
    assert_eq!(
        holding.len(),
        1,
        "the optimisation in one shard: {holding:?}"
    );
    for f in [
        "run.json",
        "report.md",
        "cardan_gear/optimum.json",
        "slider_crank/history.csv",
    ] {
        assert!(
            merged.join(optimum).join(f).is_file(),
            "{optimum}/{f} missing"
        );
    }
    let index = std::fs::read_to_string(merged.join("index.html")).unwrap();
    assert!(
        index.contains(&format!("{optimum}/report.md")),
        "not in the index"
    );

    // Refused, with nothing written: a shard missing, a shard twice, a shard of another batch
    // (other cases), a shard of another program.
    let refused = |dirs: &[PathBuf], words: &[&str]| {
        let out = tmp.path().join("refused");
        let report = merge(dirs, &out);
        let said = report.failures.join("\n");
        assert!(said.contains("cannot merge"), "{said}");
        for w in words {
            assert!(said.contains(w), "{w:?} not in: {said}");
        }
        assert!(!out.exists(), "a refused merge wrote {}", out.display());
    };
    refused(&shards[..2], &["3/3", "missing"]);
    refused(
        &[shards[0].clone(), shards[0].clone(), shards[2].clone()],
        &["both are shard 1/3"],
    );
    let other = tmp.path().join("other");
    let one_file = configs().join("karhula-pump-r60-l140-a0-w3pi.toml");
    assert!(one_file.is_file());
    let o = RunOptions {
        shard: Some((2, 3)),
        ..options()
    };
    run_paths(&[one_file], &other, o);
    refused(
        &[shards[0].clone(), other, shards[2].clone()],
        &["different inputs"],
    );
    let manifest = shards[1].join(shard::MANIFEST);
    let text = std::fs::read_to_string(&manifest).unwrap();
    std::fs::write(
        &manifest,
        text.replace("\"cardan ", "\"cardan 0.0.0-other "),
    )
    .unwrap();
    refused(&shards, &["written by cardan 0.0.0-other"]);
}

/// A run, then what kills leave: a case folder gone (killed before it was written), a sweep
/// still in its temporary folder with a point missing and a point's own temporary inside it
/// (killed while the sweep ran), a truncated file (a folder not written by this program's
/// rename), leftovers of a killed process, the index gone. `--resume` then gives the single
/// run's folder byte for byte, and runs only what it must.
#[test]
fn a_resumed_run_equals_one_run() {
    let tmp = tempfile::tempdir().unwrap();
    let single = tmp.path().join("single");
    let report = run_paths(&[configs()], &single, options());
    assert!(report.failures.is_empty(), "{:#?}", report.failures);
    let total = report.written.len();
    let resumed = tmp.path().join("resumed");
    let copy = std::process::Command::new("cp")
        .arg("-r")
        .arg(&single)
        .arg(&resumed)
        .status()
        .unwrap();
    assert!(copy.success());
    // A process id no process has (above the kernel's largest, 2^22).
    let dead = 4_194_304 + 7;
    let sweep = "karhula-pump-speed-sweep";
    let sweep_tmp = resumed.join(format!(".{sweep}.tmp-{dead}"));
    std::fs::rename(resumed.join(sweep), &sweep_tmp).unwrap();
    let point = format!("{sweep}-initial_speed-3000rpm");
    std::fs::remove_dir_all(sweep_tmp.join(&point)).unwrap();
    std::fs::create_dir(sweep_tmp.join(format!(".{point}.tmp-{dead}"))).unwrap();
    std::fs::remove_file(sweep_tmp.join("sweep.csv")).unwrap();
    std::fs::remove_dir_all(resumed.join("example-compressor")).unwrap();
    let summary = resumed.join("karhula-r60-l140-a0-w3pi/summary.json");
    let text = std::fs::read(&summary).unwrap();
    std::fs::write(&summary, &text[..100]).unwrap();
    std::fs::create_dir(resumed.join(format!(".vidinsky-hm2-p75-r340.tmp-{dead}"))).unwrap();
    std::fs::remove_file(resumed.join("index.html")).unwrap();

    let o = RunOptions {
        resume: true,
        ..options()
    };
    let report = run_paths(&[configs()], &resumed, o.clone());
    assert!(report.failures.is_empty(), "{:#?}", report.failures);
    assert_eq!(report.written.len(), total);
    // The missing case, the missing point and the truncated case were run again.
    assert_eq!(report.reused, total - 3, "kept");
    assert_same_tree(&single, &resumed);
    // Resumed again, everything is kept and nothing changes.
    let report = run_paths(&[configs()], &resumed, o);
    assert_eq!(report.reused, total);
    assert_same_tree(&single, &resumed);
}

/// Another input is no earlier result: a case whose file changed is run again by `--resume`.
#[test]
fn resume_runs_again_a_case_whose_input_changed() {
    let tmp = tempfile::tempdir().unwrap();
    let file = tmp.path().join("case.toml");
    let text = std::fs::read_to_string(configs().join("karhula-pump-r60-l140-a0-w3pi.toml"))
        .unwrap()
        .replace("name = \"karhula-pump-r60-l140-a0-w3pi\"", "name = \"c\"");
    std::fs::write(&file, &text).unwrap();
    let out = tmp.path().join("out");
    let o = RunOptions {
        resume: true,
        csv: Some(false),
        ..RunOptions::default()
    };
    let run = |o: &RunOptions| run_paths(std::slice::from_ref(&file), &out, o.clone());
    assert_eq!(run(&o).reused, 0);
    assert_eq!(run(&o).reused, 1);
    // Another output option is another input.
    let with_csv = RunOptions {
        csv: Some(true),
        ..o.clone()
    };
    assert_eq!(run(&with_csv).reused, 0);
    assert!(out.join("c/slider_crank.csv").is_file());
    assert_eq!(run(&with_csv).reused, 1);
    let commented = text.replacen("[motion]", "[motion]\n# changed", 1);
    assert_ne!(commented, text);
    std::fs::write(&file, &commented).unwrap();
    // A comment is no change of the validated input.
    assert_eq!(run(&with_csv).reused, 1);
    let changed = text.replacen("steps = 7200", "steps = 720", 1);
    assert_ne!(changed, text);
    std::fs::write(&file, &changed).unwrap();
    assert_eq!(run(&with_csv).reused, 0);
    assert_eq!(run(&with_csv).reused, 1);
}

/// The parts: every case in exactly one; the most expensive part exceeds the cheapest by at
/// most one case's cost (the longest-processing-time rule's bound); the same on every call.
#[test]
fn shards_partition_the_cases_balanced_by_cost() {
    let (cases, failures) = load_cases(&[configs()]);
    assert!(failures.is_empty(), "{failures:?}");
    for n in [1, 2, 3, 7] {
        let a = shard::assignment(&cases, n);
        assert_eq!(a, shard::assignment(&cases, n));
        let mut load = vec![0u128; n];
        for (case, k) in cases.iter().zip(&a) {
            assert!((1..=n).contains(k));
            load[k - 1] += shard::cost(case);
        }
        let largest = cases.iter().map(shard::cost).max().unwrap();
        let (lo, hi) = (load.iter().min().unwrap(), load.iter().max().unwrap());
        assert!(hi - lo <= largest, "{n} shards: loads {load:?}");
        for k in 1..=n {
            let part = shard::part(&cases, k, n);
            assert_eq!(
                part.iter().filter(|x| **x).count(),
                a.iter().filter(|s| **s == k).count()
            );
        }
    }
}

/// A small batch: a case and a sweep of three points with folders, tiny runs.
fn small_batch(dir: &Path) -> PathBuf {
    let cases = dir.join("cases");
    std::fs::create_dir_all(&cases).unwrap();
    let case = |name: &str, sweep: &str| {
        format!(
            r#"name = "{name}"
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
{sweep}"#
        )
    };
    std::fs::write(cases.join("one.toml"), case("one", "")).unwrap();
    let sweep = "[sweep]\n\"motion.initial_speed\" = [10.0, 20.0, 30.0]\n";
    std::fs::write(cases.join("speeds.toml"), case("speeds", sweep)).unwrap();
    cases
}

/// The batch's two shards, run into `dir`; the folder of each holding `what` (a relative
/// path), found.
fn two_shards(cases: &Path, dir: &Path) -> Vec<PathBuf> {
    (1..=2)
        .map(|k| {
            let out = dir.join(format!("shard{k}"));
            let o = RunOptions {
                shard: Some((k, 2)),
                ..options()
            };
            let report = run_paths(&[cases.to_path_buf()], &out, o);
            assert!(report.failures.is_empty(), "{:#?}", report.failures);
            out
        })
        .collect()
}

/// What a shard lost after its run (a case folder, a sweep point's folder, a truncated
/// `summary.json`) is refused by the merge, naming the case and the shard, with nothing
/// written; the shards as they were merge.
#[test]
fn a_merge_refuses_what_a_shard_lost() {
    let tmp = tempfile::tempdir().unwrap();
    let cases = small_batch(tmp.path());
    let shards = two_shards(&cases, &tmp.path().join("whole"));
    let report = merge(&shards, &tmp.path().join("merged"));
    assert!(report.failures.is_empty(), "{:#?}", report.failures);
    assert_eq!(report.written.len(), 4, "{:#?}", report.written);
    for (k, (point, damage)) in [
        (false, "remove"),
        (true, "remove"),
        (false, "truncate"),
        (true, "truncate"),
    ]
    .into_iter()
    .enumerate()
    {
        let shards = two_shards(&cases, &tmp.path().join(format!("damaged{k}")));
        // The case "one", or the first point folder of the sweep, in the shard that ran it.
        let (n, shard, case, folder) = shards
            .iter()
            .enumerate()
            .find_map(|(n, s)| {
                if !point {
                    return s
                        .join("one")
                        .is_dir()
                        .then(|| (n, s, "one".to_string(), s.join("one")));
                }
                let points = std::fs::read_dir(s.join("speeds")).ok()?;
                let p = points.map(|e| e.unwrap().path()).find(|p| p.is_dir())?;
                let name = p.file_name().unwrap().to_string_lossy().to_string();
                Some((n, s, name, p))
            })
            .unwrap();
        match damage {
            "remove" => std::fs::remove_dir_all(&folder).unwrap(),
            _ => {
                let path = folder.join("summary.json");
                let bytes = std::fs::read(&path).unwrap();
                std::fs::write(&path, &bytes[..bytes.len() / 2]).unwrap();
            }
        }
        let out = tmp.path().join(format!("out{k}"));
        let report = merge(&shards, &out);
        let said = report.failures.join("\n");
        let what = format!("{} ({damage})", folder.display());
        for part in [
            "cannot merge".to_string(),
            format!("case \"{case}\""),
            format!("shard {}/2", n + 1),
            shard.display().to_string(),
        ] {
            assert!(said.contains(&part), "{what}: {part:?} not in: {said}");
        }
        if damage == "truncate" {
            assert!(said.contains("summary.json of"), "{said}");
        }
        assert!(!out.exists(), "a refused merge wrote {}", out.display());
    }
}
