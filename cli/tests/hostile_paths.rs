//! Paths that are not what they seem (issue 36.8, 36.9): a device (`/dev/zero`), a FIFO or an
//! oversize file wherever the program reads a file, and case folders that link to themselves.
//! Each command runs as a child process killed after [`LIMIT`]: an endless read or a blocked
//! open fails the test instead of hanging it.

#![cfg(unix)]

use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

/// The longest a command here may take.
const LIMIT: Duration = Duration::from_secs(20);

/// Runs `cardan ARGS` in `cwd`, killed after [`LIMIT`]: exit code (None if killed) and stderr.
fn cardan_in(cwd: &Path, args: &[&dyn AsRef<std::ffi::OsStr>]) -> (Option<i32>, String, String) {
    let mut c = Command::new(env!("CARGO_BIN_EXE_cardan"));
    c.current_dir(cwd)
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped());
    for a in args {
        c.arg(a);
    }
    let mut child = c.spawn().unwrap();
    // Read the pipes on threads of their own, so that a full pipe cannot stall the child.
    let mut out = child.stdout.take().unwrap();
    let mut err = child.stderr.take().unwrap();
    let out = std::thread::spawn(move || {
        let mut s = String::new();
        std::io::Read::read_to_string(&mut out, &mut s).ok();
        s
    });
    let err = std::thread::spawn(move || {
        let mut s = String::new();
        std::io::Read::read_to_string(&mut err, &mut s).ok();
        s
    });
    let start = Instant::now();
    let code = loop {
        if let Some(status) = child.try_wait().unwrap() {
            break status.code();
        }
        if start.elapsed() > LIMIT {
            child.kill().unwrap();
            child.wait().unwrap();
            panic!(
                "cardan {:?} still running after {LIMIT:?}: killed",
                args.iter().map(|a| a.as_ref()).collect::<Vec<_>>()
            );
        }
        std::thread::sleep(Duration::from_millis(20));
    };
    (code, out.join().unwrap(), err.join().unwrap())
}

fn mkfifo(path: &Path) {
    let status = Command::new("mkfifo").arg(path).status().unwrap();
    assert!(status.success(), "mkfifo {}", path.display());
}

fn repo(path: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("..").join(path)
}

/// The shipped pressure-trace case, its `gas.file` replaced by `file`.
fn trace_case(file: &str) -> String {
    let text = std::fs::read_to_string(repo("configs/example-pressure-trace.toml")).unwrap();
    let line = text
        .lines()
        .find(|l| l.trim_start().starts_with("file ="))
        .unwrap();
    text.replace(line, &format!("file = \"{file}\""))
}

#[test]
fn check_of_a_device_says_what_it_is_not_that_it_is_missing() {
    let dir = tempfile::tempdir().unwrap();
    let (code, _, err) = cardan_in(dir.path(), &[&"check", &"/dev/zero"]);
    assert_eq!(code, Some(1), "stderr: {err}");
    assert!(
        err.contains("/dev/zero") && err.contains("not a regular file (a character device)"),
        "stderr: {err}"
    );
    assert!(!err.contains("no such file"), "stderr: {err}");
}

#[test]
fn a_case_file_that_is_a_fifo_is_refused_not_waited_on() {
    let dir = tempfile::tempdir().unwrap();
    mkfifo(&dir.path().join("pipe.toml"));
    for command in ["check", "run"] {
        // Given by name, and found in a folder.
        for path in [dir.path().join("pipe.toml"), dir.path().to_path_buf()] {
            let out = dir.path().join("out");
            let args: Vec<&dyn AsRef<std::ffi::OsStr>> = if command == "run" {
                vec![&command, &path, &"--out", &out]
            } else {
                vec![&command, &path]
            };
            let (code, _, err) = cardan_in(dir.path(), &args);
            assert_eq!(code, Some(1), "{command} {}: {err}", path.display());
            assert!(
                err.contains("pipe.toml") && err.contains("not a regular file (a FIFO)"),
                "{command}: {err}"
            );
        }
    }
}

#[test]
fn a_case_file_over_its_limit_is_refused_before_it_is_read() {
    let dir = tempfile::tempdir().unwrap();
    let big = dir.path().join("big.toml");
    // Sparse: 17 MiB of zeros that take no disk.
    std::fs::File::create(&big)
        .unwrap()
        .set_len(17 << 20)
        .unwrap();
    let (code, _, err) = cardan_in(dir.path(), &[&"check", &big]);
    assert_eq!(code, Some(1), "stderr: {err}");
    assert!(
        err.contains("big.toml") && err.contains("larger than the 16 MiB limit for a case file"),
        "stderr: {err}"
    );
}

#[test]
fn a_pressure_trace_that_is_a_device_a_fifo_or_too_large_is_refused() {
    let dir = tempfile::tempdir().unwrap();
    mkfifo(&dir.path().join("pipe.csv"));
    std::fs::File::create(dir.path().join("big.csv"))
        .unwrap()
        .set_len(257 << 20)
        .unwrap();
    for (file, why) in [
        ("/dev/zero", "not a regular file (a character device)"),
        ("/dev/urandom", "not a regular file (a character device)"),
        ("pipe.csv", "not a regular file (a FIFO)"),
        ("big.csv", "larger than the 256 MiB limit for a data table"),
    ] {
        std::fs::write(dir.path().join("case.toml"), trace_case(file)).unwrap();
        for command in ["check", "run"] {
            let out = dir.path().join("out");
            let args: Vec<&dyn AsRef<std::ffi::OsStr>> = if command == "run" {
                vec![&command, &"case.toml", &"--out", &out]
            } else {
                vec![&command, &"case.toml"]
            };
            let (code, _, err) = cardan_in(dir.path(), &args);
            assert_eq!(code, Some(1), "{command} with {file}: {err}");
            assert!(
                err.contains("gas.file") && err.contains(file) && err.contains(why),
                "{command} with {file}: {err}"
            );
        }
    }
}

#[test]
fn a_gear_file_that_is_a_device_or_a_fifo_is_refused() {
    let dir = tempfile::tempdir().unwrap();
    mkfifo(&dir.path().join("pipe.toml"));
    for (file, why) in [
        ("/dev/zero", "not a regular file (a character device)"),
        ("pipe.toml", "not a regular file (a FIFO)"),
    ] {
        let (code, _, err) = cardan_in(dir.path(), &[&"gear", &file, &"--out", &"out"]);
        assert_eq!(code, Some(1), "gear {file}: {err}");
        assert!(
            err.contains(file) && err.contains(why),
            "gear {file}: {err}"
        );
    }
}

#[test]
fn a_result_record_that_is_a_fifo_is_refused_by_merge() {
    // A shard's `shard.json` replaced by a FIFO: merge refuses it instead of waiting.
    let dir = tempfile::tempdir().unwrap();
    let shard = dir.path().join("shard");
    std::fs::create_dir(&shard).unwrap();
    mkfifo(&shard.join("shard.json"));
    let (code, _, err) = cardan_in(dir.path(), &[&"merge", &shard, &"--out", &"merged"]);
    assert_ne!(code, Some(0), "stderr: {err}");
    assert!(
        err.contains("shard.json") && err.contains("not a regular file (a FIFO)"),
        "stderr: {err}"
    );
}

#[test]
fn a_run_record_that_is_a_fifo_is_run_again_by_resume_not_waited_on() {
    // A case folder whose `run.json` is a FIFO: `--resume` cannot trust the folder, so it
    // runs the case again (the folder is replaced) instead of blocking on the read.
    let dir = tempfile::tempdir().unwrap();
    let case = repo("configs/karhula-pump-r60-l140-a0-w3pi.toml");
    let (code, _, err) = cardan_in(
        dir.path(),
        &[&"run", &case, &"--out", &"out", &"--no-report"],
    );
    assert_eq!(code, Some(0), "stderr: {err}");
    let record = dir
        .path()
        .join("out/karhula-pump-r60-l140-a0-w3pi/run.json");
    std::fs::remove_file(&record).unwrap();
    mkfifo(&record);
    let (code, _, err) = cardan_in(
        dir.path(),
        &[&"run", &case, &"--out", &"out", &"--no-report", &"--resume"],
    );
    assert_eq!(code, Some(0), "stderr: {err}");
    let meta = std::fs::symlink_metadata(&record).unwrap();
    assert!(meta.is_file(), "run.json is a regular file again");
}

#[test]
fn a_case_folder_linking_to_itself_and_its_parent_is_read_once() {
    let dir = tempfile::tempdir().unwrap();
    let cases = dir.path().join("cases");
    let inner = cases.join("inner");
    std::fs::create_dir_all(&inner).unwrap();
    std::fs::copy(
        repo("configs/karhula-r60-l140-a0-w3pi.toml"),
        inner.join("case.toml"),
    )
    .unwrap();
    // Two links to itself (2^40 paths if followed), one to its parent, one to the top.
    std::os::unix::fs::symlink(".", inner.join("self")).unwrap();
    std::os::unix::fs::symlink(".", inner.join("again")).unwrap();
    std::os::unix::fs::symlink("..", inner.join("up")).unwrap();
    std::os::unix::fs::symlink(&cases, inner.join("top")).unwrap();
    let (code, out, err) = cardan_in(dir.path(), &[&"check", &cases]);
    assert_eq!(code, Some(0), "stdout: {out}\nstderr: {err}");
    assert!(
        out.contains("1 case(s) valid"),
        "stdout: {out}\nstderr: {err}"
    );
    let (code, out, err) = cardan_in(
        dir.path(),
        &[
            &"run",
            &cases,
            &"--out",
            &"out",
            &"--no-csv",
            &"--no-report",
            &"--quiet",
        ],
    );
    assert_eq!(code, Some(0), "stdout: {out}\nstderr: {err}");
    let folders: Vec<_> = std::fs::read_dir(dir.path().join("out"))
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|n| !n.starts_with('.') && n != "index.html")
        .collect();
    assert_eq!(folders, ["karhula-r60-l140-a0-w3pi"], "stderr: {err}");
}
