//! `cardan check` and `cardan run` on a case file with `[optimize]` (issue 40): check says it
//! is valid or refuses it naming the field, run writes the optimisation's folder beside the
//! batch's cases and lists it in the index, two shards merged equal one run.

use cardan_testing::cases::kinematic_optimization;
use std::process::Command;

fn cardan(args: &[&std::ffi::OsStr]) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_cardan"))
        .args(args)
        .output()
        .unwrap()
}

/// `cardan args`, which must exit 0 (else its stderr is the failure's message).
fn cardan_ok(args: &[&std::ffi::OsStr]) {
    let out = cardan(args);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
}

#[test]
fn check_and_run_an_optimisation() {
    let dir = tempfile::tempdir().unwrap();
    // The batch: the optimisation and a case beside it (so that each of two shards has work).
    let batch = dir.path().join("batch");
    std::fs::create_dir(&batch).unwrap();
    std::fs::write(batch.join("good.toml"), cardan_testing::cases::THESIS_PUMP).unwrap();
    let file = batch.join("kinematic.toml");
    let case = kinematic_optimization("", "rod_angular_velocity_max >= 20 rad/s");
    std::fs::write(&file, &case).unwrap();
    let out = cardan(&["check".as_ref(), file.as_os_str()]);
    let said = String::from_utf8_lossy(&out.stdout);
    assert_eq!(out.status.code(), Some(0), "{said}");
    assert!(
        said.contains("valid   kinematic (an optimisation"),
        "{said}"
    );

    let bad = dir.path().join("bad.toml");
    std::fs::write(&bad, case.replace(">= 20 rad/s", ">= 20 N")).unwrap();
    let out = cardan(&["check".as_ref(), bad.as_os_str()]);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1));
    for w in [
        "bad.toml",
        "optimize.constraints",
        "\"rod_angular_velocity_max >= 20 N\"",
        "rad/s",
    ] {
        assert!(err.contains(w), "{w:?} not in {err}");
    }

    let results = dir.path().join("out");
    cardan_ok(&[
        "run".as_ref(),
        batch.as_os_str(),
        "--out".as_ref(),
        results.as_os_str(),
        "--quiet".as_ref(),
    ]);
    let folder = results.join("kinematic");
    for f in [
        "slider_crank/optimum.json",
        "slider_crank/history.csv",
        "slider_crank/summary.json",
        "convergence.svg",
        "report.md",
        "at-optima/summary.json",
        "at-optima/report.html",
    ] {
        assert!(folder.join(f).is_file(), "{f} missing");
    }

    // Two shards, one of which runs the optimisation whole, merged: one run's folder, byte
    // for byte, its index listing the optimisation.
    let mut shards = Vec::new();
    for k in ["1/2", "2/2"] {
        let shard = dir.path().join(format!("shard{}", &k[..1]));
        cardan_ok(&[
            "run".as_ref(),
            batch.as_os_str(),
            "--out".as_ref(),
            shard.as_os_str(),
            "--shard".as_ref(),
            k.as_ref(),
            "--quiet".as_ref(),
        ]);
        shards.push(shard);
    }
    let merged = dir.path().join("merged");
    let mut args: Vec<&std::ffi::OsStr> = vec!["merge".as_ref()];
    args.extend(shards.iter().map(|s| s.as_os_str()));
    args.extend(["--out".as_ref(), merged.as_os_str()]);
    cardan_ok(&args);
    let index = std::fs::read_to_string(merged.join("index.html")).unwrap();
    assert!(
        index.contains("Optimisations") && index.contains("kinematic/report.md"),
        "{index}"
    );
    for f in [
        "index.html",
        "good/summary.json",
        "kinematic/run.json",
        "kinematic/report.md",
        "kinematic/slider_crank/optimum.json",
        "kinematic/slider_crank/history.csv",
        "kinematic/at-optima/summary.json",
    ] {
        assert_eq!(
            std::fs::read(results.join(f)).unwrap(),
            std::fs::read(merged.join(f)).unwrap(),
            "{f}: the merged shards differ from one run"
        );
    }
}
