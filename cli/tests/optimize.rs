//! `cardan check` and `cardan run` on a case file with `[optimize]` (issue 40): check says it
//! is valid or refuses it naming the field, run writes the optimisation's folder beside the
//! batch's cases, `--shard` refuses it.

use std::process::Command;

const CASE: &str = r#"
name = "kinematic"
machine = "pump"
mechanisms = ["slider_crank"]
[geometry]
crank_length = "50 mm"
rod_length = "200 mm"
bore = "80 mm"
[motion]
start_angle = "0 deg"
end_angle = "360 deg"
initial_speed = "100 rad/s"
angular_acceleration = 0
steps = 360
[optimize]
objective = "piston_acceleration_max"
sense = "min"
variables = { "geometry.rod_length" = ["150 mm", "400 mm"] }
constraints = ["rod_angular_velocity_max >= 20 rad/s"]
"#;

fn cardan(args: &[&std::ffi::OsStr]) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_cardan"))
        .args(args)
        .output()
        .unwrap()
}

#[test]
fn check_and_run_an_optimisation() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("kinematic.toml");
    std::fs::write(&file, CASE).unwrap();
    let out = cardan(&["check".as_ref(), file.as_os_str()]);
    let said = String::from_utf8_lossy(&out.stdout);
    assert_eq!(out.status.code(), Some(0), "{said}");
    assert!(
        said.contains("valid   kinematic (an optimisation"),
        "{said}"
    );

    let bad = dir.path().join("bad.toml");
    std::fs::write(&bad, CASE.replace(">= 20 rad/s", ">= 20 N")).unwrap();
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
    let out = cardan(&[
        "run".as_ref(),
        file.as_os_str(),
        "--out".as_ref(),
        results.as_os_str(),
        "--quiet".as_ref(),
    ]);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
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

    let out = cardan(&[
        "run".as_ref(),
        file.as_os_str(),
        "--out".as_ref(),
        dir.path().join("shard").as_os_str(),
        "--shard".as_ref(),
        "1/2".as_ref(),
    ]);
    assert_eq!(out.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&out.stderr).contains("not split into shards"));
}
