//! The command a user runs: exit codes and the failure list.

use std::process::Command;

#[test]
fn failures_give_a_nonzero_exit_and_are_listed_after_the_good_cases_run() {
    let dir = tempfile::tempdir().unwrap();
    let good = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../configs/karhula-r60-l140-a0-w3pi.toml"
    ))
    .unwrap();
    std::fs::write(dir.path().join("good.toml"), &good).unwrap();
    std::fs::write(
        dir.path().join("bad.toml"),
        good.replace("name = \"karhula-r60-l140-a0-w3pi\"", "name = \"bad\"")
            .replace("steps = 7200", "steps = 3"),
    )
    .unwrap();
    let out = dir.path().join("results");
    let run = Command::new(env!("CARGO_BIN_EXE_xtask"))
        .arg("run")
        .arg(dir.path())
        .arg("--out")
        .arg(&out)
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&run.stderr);
    assert_eq!(run.status.code(), Some(1), "stderr: {stderr}");
    assert!(
        stderr.contains("bad.toml") && stderr.contains("motion.steps") && stderr.contains("from 8"),
        "stderr: {stderr}"
    );
    assert!(out.join("karhula-r60-l140-a0-w3pi/summary.json").is_file());
    assert!(out
        .join("karhula-r60-l140-a0-w3pi/cardan_gear.csv")
        .is_file());

    let usage = Command::new(env!("CARGO_BIN_EXE_xtask"))
        .arg("frobnicate")
        .output()
        .unwrap();
    assert_eq!(usage.status.code(), Some(2));
}
