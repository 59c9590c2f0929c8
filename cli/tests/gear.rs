//! `cardan gear`: the shipped examples, an impossible pair (exit 1, reasons on stderr, geometry
//! written), a bad file (exit 1, nothing written), usage errors.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn cardan(args: &[&dyn AsRef<std::ffi::OsStr>]) -> Output {
    let mut c = Command::new(env!("CARGO_BIN_EXE_cardan"));
    for a in args {
        c.arg(a);
    }
    c.output().unwrap()
}

fn shipped(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../configs-gears")
        .join(name)
}

#[test]
fn shipped_examples_pass_and_write_json_and_report() {
    let dir = tempfile::tempdir().unwrap();
    for (file, name) in [
        ("shigley-14-4.toml", "shigley-14-4"),
        ("karhula-cardan-20-40.toml", "karhula-cardan-20-40"),
    ] {
        let out = cardan(&[&"gear", &shipped(file), &"--out", &dir.path()]);
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(0), "{file}: {stderr}");
        assert!(String::from_utf8_lossy(&out.stdout).contains(name));
        let json = std::fs::read_to_string(dir.path().join(name).join("gear.json")).unwrap();
        for field in [
            "\"working_pressure_angle_deg\"",
            "\"center_distance\"",
            "\"path_of_contact\"",
            "\"contact_ratio\"",
            "\"checks\"",
            "\"margin\"",
        ] {
            assert!(json.contains(field), "{file}: {field}");
        }
        assert!(dir.path().join(name).join("report.md").is_file());
    }
    let json = std::fs::read_to_string(dir.path().join("shigley-14-4").join("gear.json")).unwrap();
    assert!(json.contains("\"bending_safety_factor\"") && json.contains("\"contact_stress\""));
}

#[test]
fn interfering_internal_pair_exits_1_naming_the_remedy() {
    // 20/40 internal, 20°, full ring addendum: KHK involute interference
    // (docs/validation/gears.md §1.3).
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("full-ring.toml");
    std::fs::write(
        &file,
        "name = \"full-ring\"\nmodule = \"3 mm\"\npressure_angle = \"20 deg\"\nteeth = [20, -40]\n",
    )
    .unwrap();
    let out = cardan(&[&"gear", &file, &"--out", &dir.path().join("out")]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1), "stderr: {stderr}");
    assert!(
        stderr.contains("full-ring.toml")
            && stderr.contains("involute_interference_pinion")
            && stderr.contains("shorter ring addendum (at most 2.692"),
        "stderr: {stderr}"
    );
    let written = dir.path().join("out/full-ring");
    let json = std::fs::read_to_string(written.join("gear.json")).unwrap();
    assert!(json.contains("\"passed\": false"));
    assert!(written.join("report.md").is_file());
}

#[test]
fn bad_file_exits_1_naming_the_field_and_writes_nothing() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("bad.toml");
    std::fs::write(
        &file,
        "name = \"bad\"\nmodule = \"3 mm\"\npressure_angle = \"20 deg\"\nteeth = [20, -12]\n",
    )
    .unwrap();
    let out = cardan(&[&"gear", &file, &"--out", &dir.path().join("out")]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1));
    assert!(
        stderr.contains("bad.toml") && stderr.contains("teeth") && stderr.contains("[20, -12]"),
        "stderr: {stderr}"
    );
    assert!(!dir.path().join("out/bad").exists());
    let missing = cardan(&[&"gear", &dir.path().join("missing.toml")]);
    assert_eq!(missing.status.code(), Some(1));
}

#[test]
fn gear_usage() {
    assert_eq!(cardan(&[&"gear"]).status.code(), Some(2));
    let help = cardan(&[&"gear", &"--help"]);
    assert_eq!(help.status.code(), Some(0));
    assert!(String::from_utf8_lossy(&help.stdout).contains("--out"));
}

const OVERLOADED: &str = include_str!("reproducers/r07-gear-overloaded.toml");

/// Issue 22, reproducer r07: 200 kW through a 3 mm, 20/40, 30 mm pair (SF ≈ 0.1 by hand, in the
/// file) exits 1 with the failed safety factors and the remedy.
#[test]
fn overloaded_pair_exits_1_naming_the_safety_factors() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("overloaded.toml");
    std::fs::write(&file, OVERLOADED).unwrap();
    let out = cardan(&[&"gear", &file, &"--out", &dir.path().join("out")]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1), "stderr: {stderr}");
    for part in [
        "overloaded.toml",
        "cannot work",
        "bending safety factor SF of the pinion",
        "required_safety_factor 1",
        "remedy",
    ] {
        assert!(stderr.contains(part), "{part}: {stderr}");
    }
    assert!(dir.path().join("out/overloaded/report.md").is_file());
}

/// Issue 22, reproducer r12: a pinion speed of 1e-300 rad/s gives infinite stresses: exit 1
/// naming the quantity.
#[test]
fn tiny_pinion_speed_exits_1_naming_the_quantity() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("tiny.toml");
    std::fs::write(
        &file,
        OVERLOADED
            .replace("\"200 kW\"", "\"4 hp\"")
            .replace("\"1800 rpm\"", "1e-300"),
    )
    .unwrap();
    let out = cardan(&[&"gear", &file, &"--out", &dir.path().join("out")]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1), "stderr: {stderr}");
    assert!(
        stderr.contains("pinion torque") && stderr.contains("not a finite number"),
        "stderr: {stderr}"
    );
}

/// Warnings (Shigley's pinion just below the undercut limit) go to stderr; the pair still works.
#[test]
fn warnings_print_on_stderr() {
    let dir = tempfile::tempdir().unwrap();
    let out = cardan(&[
        &"gear",
        &shipped("shigley-14-4.toml"),
        &"--out",
        &dir.path(),
    ]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(0), "stderr: {stderr}");
    assert!(
        stderr.contains("warning") && stderr.contains("pinion_undercut"),
        "stderr: {stderr}"
    );
}
