//! The command a user runs: exit codes, the failure list, `check`, `--help`.

use std::path::Path;
use std::process::{Command, Output};

fn cardan(args: &[&dyn AsRef<std::ffi::OsStr>]) -> Output {
    let mut c = Command::new(env!("CARGO_BIN_EXE_cardan"));
    for a in args {
        c.arg(a);
    }
    c.output().unwrap()
}

fn shipped() -> String {
    std::fs::read_to_string(
        Path::new(env!("CARGO_MANIFEST_DIR")).join("../configs/karhula-r60-l140-a0-w3pi.toml"),
    )
    .unwrap()
}

#[test]
fn failures_give_exit_1_and_are_listed_after_the_good_cases_run() {
    let dir = tempfile::tempdir().unwrap();
    let good = shipped();
    std::fs::write(dir.path().join("good.toml"), &good).unwrap();
    std::fs::write(
        dir.path().join("bad.toml"),
        good.replace("name = \"karhula-r60-l140-a0-w3pi\"", "name = \"bad\"")
            .replace("steps = 7200", "steps = 3"),
    )
    .unwrap();
    let out = dir.path().join("results");
    let missing = dir.path().join("missing.toml");
    let run = cardan(&[
        &"run",
        &dir.path(),
        &missing,
        &"--out",
        &out,
        &"--jobs",
        &"2",
    ]);
    let stderr = String::from_utf8_lossy(&run.stderr);
    assert_eq!(run.status.code(), Some(1), "stderr: {stderr}");
    assert!(
        stderr.contains("bad.toml") && stderr.contains("motion.steps") && stderr.contains("from 8"),
        "stderr: {stderr}"
    );
    assert!(stderr.contains("missing.toml") && stderr.contains("no such file"));
    let case = out.join("karhula-r60-l140-a0-w3pi");
    assert!(case.join("summary.json").is_file());
    assert!(case.join("cardan_gear.csv").is_file());

    // --no-csv: the summary only.
    let only = cardan(&[
        &"run",
        &dir.path().join("good.toml"),
        &"--out",
        &out,
        &"--no-csv",
    ]);
    assert_eq!(only.status.code(), Some(0));
    assert!(!case.join("cardan_gear.csv").exists());

    // --only selects cases by name.
    let only = dir.path().join("only");
    let some = cardan(&[
        &"run",
        &dir.path().join("good.toml"),
        &"--out",
        &only,
        &"--only",
        &"nothing-like-it",
    ]);
    assert_eq!(some.status.code(), Some(1), "no case selected is a failure");
    let some = cardan(&[
        &"run",
        &dir.path().join("good.toml"),
        &"--out",
        &only,
        &"--only",
        &"karhula-*-w3pi",
        &"--quiet",
    ]);
    assert_eq!(some.status.code(), Some(0));
    assert!(only.join("karhula-r60-l140-a0-w3pi/summary.json").is_file());

    // check validates without running.
    let check = cardan(&[&"check", &dir.path()]);
    assert_eq!(check.status.code(), Some(1));
    let stdout = String::from_utf8_lossy(&check.stdout);
    assert!(
        stdout.contains("valid   karhula-r60-l140-a0-w3pi"),
        "{stdout}"
    );
    let check = cardan(&[&"check", &dir.path().join("good.toml")]);
    assert_eq!(check.status.code(), Some(0));
}

#[test]
fn usage_errors_exit_2_and_every_command_has_help() {
    assert_eq!(cardan(&[&"frobnicate"]).status.code(), Some(2));
    assert_eq!(cardan(&[&"run"]).status.code(), Some(2));
    assert_eq!(
        cardan(&[&"run", &"x", &"--jobs", &"0"]).status.code(),
        Some(2)
    );
    for args in [
        vec!["--help"],
        vec!["run", "--help"],
        vec!["check", "--help"],
    ] {
        let a: Vec<&dyn AsRef<std::ffi::OsStr>> = args.iter().map(|s| s as _).collect();
        let help = cardan(&a);
        assert_eq!(help.status.code(), Some(0));
        assert!(String::from_utf8_lossy(&help.stdout).contains("Usage"));
    }
}

/// Outputs are the same bytes whatever the number of worker threads, and whichever build of the
/// block kernels runs (AVX2, where the processor has it, or the baseline one that
/// `CARDAN_SIMD=baseline` forces): pump cases with gas (slider-crank, cardan gear) and the Scotch
/// yoke's compressor, every file.
#[test]
fn outputs_do_not_depend_on_the_thread_count_nor_the_kernels() {
    let dir = tempfile::tempdir().unwrap();
    let configs = Path::new(env!("CARGO_MANIFEST_DIR")).join("../configs");
    let runs = [
        ("one", "1", false),
        ("two", "2", false),
        ("baseline", "2", true),
    ];
    for (out, jobs, baseline) in runs {
        for only in ["karhula-pump", "example-scotch-yoke-compressor"] {
            let mut c = Command::new(env!("CARGO_BIN_EXE_cardan"));
            c.arg("run")
                .arg(&configs)
                .arg("--out")
                .arg(dir.path().join(out))
                .args(["--jobs", jobs, "--only", only, "--quiet"]);
            if baseline {
                c.env("CARDAN_SIMD", "baseline");
            }
            assert_eq!(c.output().unwrap().status.code(), Some(0), "{out} {only}");
        }
    }
    fn files(dir: &Path, out: &mut Vec<std::path::PathBuf>) {
        for e in std::fs::read_dir(dir).unwrap() {
            let p = e.unwrap().path();
            if p.is_dir() {
                files(&p, out);
            } else {
                out.push(p);
            }
        }
    }
    let one = dir.path().join("one");
    let mut all = Vec::new();
    files(&one, &mut all);
    let mut compared = 0;
    for file in all {
        for (other, _, _) in &runs[1..] {
            let other = dir
                .path()
                .join(other)
                .join(file.strip_prefix(&one).unwrap());
            assert!(
                std::fs::read(&file).unwrap() == std::fs::read(&other).unwrap(),
                "{} differs from {}",
                file.display(),
                other.display()
            );
        }
        compared += 1;
    }
    assert!(compared >= 9, "{compared} files compared");
}
