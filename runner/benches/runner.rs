//! The runner in-process: one shipped case with gas, summaries only and with its per-step
//! files (CSV, NPY: written by their own thread, into a temporary folder), and read from its
//! text and run in memory as the Python package does (with and without its per-step columns);
//! and a sweep of 10 000
//! two-mechanism pump cases of 720 steps with gas, summaries only, on every core, without and
//! with the thesis's loss models (the issue-8
//! target through `cardan run` is 20 s; this is the computation without the files).

use cardan_case::case;
use cardan_runner::run_case;
use criterion::{criterion_group, criterion_main, Criterion};
use rayon::prelude::*;
use std::hint::black_box;
use std::path::Path;

fn shipped(name: &str) -> String {
    std::fs::read_to_string(
        Path::new(env!("CARGO_MANIFEST_DIR")).join(format!("../configs/{name}.toml")),
    )
    .unwrap()
}

fn runner(c: &mut Criterion) {
    let pump = shipped("karhula-pump-r60-l140-a0-w30pi");
    let one = case::parse(Path::new("pump.toml"), &pump).unwrap();
    c.bench_function("full_case_pump_7200_steps_two_mechanisms", |b| {
        b.iter(|| black_box(run_case(black_box(&one), None).unwrap()))
    });
    // The work of the Python package's `cardan.run(text)` (python/benches/run.py times it):
    // the case read and validated, run in memory, its summary.json value, with and without the
    // per-step columns.
    for (label, steps) in [("in_memory_steps", true), ("in_memory_summary", false)] {
        c.bench_function(
            &format!("case_text_pump_7200_steps_two_mechanisms_{label}"),
            |b| {
                b.iter(|| {
                    let case = case::parse(Path::new("pump.toml"), black_box(&pump)).unwrap();
                    black_box(cardan_runner::memory::run_in_memory(&case, steps).unwrap())
                })
            },
        );
    }
    // Into a fresh folder each time, as a run writes new files (rewriting the same files would
    // time the file system's truncation instead).
    let dir = tempfile::tempdir().unwrap();
    for (label, csv, npy) in [("csv", true, false), ("npy", false, true)] {
        let mut with_files = one.clone();
        with_files.output.csv = csv;
        with_files.output.npy = npy;
        c.bench_function(
            &format!("full_case_pump_7200_steps_two_mechanisms_{label}"),
            |b| {
                b.iter_batched(
                    // Removed when dropped, after the timing.
                    || tempfile::tempdir_in(dir.path()).unwrap(),
                    |folder| {
                        black_box(run_case(black_box(&with_files), Some(folder.path())).unwrap());
                        folder
                    },
                    criterion::BatchSize::PerIteration,
                )
            },
        );
    }
    let sweep: Vec<case::Case> = (0..10_000)
        .map(|k| {
            let text: String = pump
                .lines()
                .map(|l| match l.split_whitespace().next() {
                    Some("initial_speed") => format!("initial_speed = {}\n", 3.0 + 0.02 * k as f64),
                    Some("steps") => "steps = 720\n".to_string(),
                    _ => format!("{l}\n"),
                })
                .collect();
            case::parse(Path::new("sweep.toml"), &text).unwrap()
        })
        .collect();
    let mut group = c.benchmark_group("sweep");
    group.sample_size(10);
    let all = |cases: &[case::Case]| {
        cases
            .par_iter()
            .map(|c| run_case(c, None).unwrap().len())
            .sum::<usize>()
    };
    group.bench_function("10000_pump_cases_720_steps", |b| b.iter(|| all(&sweep)));
    // The same with the thesis's loss models (rings, skirt, bearings, gear mesh).
    let with_friction: Vec<case::Case> = sweep
        .iter()
        .map(|c| {
            let mut c = c.clone();
            c.friction = Some(cardan_dynamics::Friction::karhula());
            c.build_setups().unwrap();
            c
        })
        .collect();
    group.bench_function("10000_pump_cases_720_steps_friction", |b| {
        b.iter(|| all(&with_friction))
    });
    group.finish();
}

criterion_group!(benches, runner);
criterion_main!(benches);
