//! The progress display's step count (`cardan_runner::progress`, issue 38.1): a case's run adds
//! its steps, whichever way the run goes (shared by the threads, with per-step files, a solved
//! motion's reported cycle). Alone in its test binary: no other run adds to the count.

use cardan_case::case;
use cardan_runner::progress::steps_run;
use std::path::Path;

/// The steps `file`'s case adds to the count when run (with per-step files where `files`).
fn counted(file: &str, files: bool) -> (u64, u64) {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../configs")
        .join(file);
    let text = std::fs::read_to_string(&path).unwrap();
    let case = case::parse(&path, &text).unwrap();
    let tmp = tempfile::tempdir().unwrap();
    let before = steps_run();
    cardan_runner::run_case(&case, files.then_some(tmp.path())).unwrap();
    let trains = case.mechanisms.len() as u64 * if case.crank_phase != 0.0 { 2 } else { 1 };
    (steps_run() - before, trains * (case.steps as u64 + 1))
}

#[test]
fn a_run_counts_its_steps() {
    // Summary only, the run shared by the threads in chunks (each chunk's first step is its
    // predecessor's last, taken by both: at most one step more per chunk of 4096 or so).
    let (n, steps) = counted("karhula-r60-l140-a0-w3pi.toml", false);
    assert!(
        n >= steps && n <= steps + steps / 100,
        "{n} counted, {steps} run"
    );
    // With per-step files: one thread, every step once.
    let (n, steps) = counted("karhula-r60-l140-a0-w3pi.toml", true);
    assert_eq!(n, steps);
    // A solved motion: its reported cycle's steps (the cycles before it are not counted).
    let (n, steps) = counted("karhula-pump-motor-dynamic.toml", false);
    assert!(
        n >= steps && n <= steps + steps / 100,
        "{n} counted, {steps} run"
    );
}
