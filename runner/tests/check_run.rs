//! check ≡ run (issue 36.11): for random single-field mutations of valid cases (shipped
//! configs of every gas model, prescribed and dynamic, one and several cylinders, and the thesis
//! pump of `cardan_testing::cases`), what `cardan check` passes (the case validated as the run
//! validates it, and its per-step files within the size limit: `load_file` and `check_size`)
//! the run does not refuse for a reason known before stepping, and what it refuses the run
//! refuses. A run's failure that names a case field (`gas.swept_volume`, `output: ...`) and no
//! step is such a reason, and fails the property; a failure at a step (the machine stalls, a
//! load is not finite) is known only by stepping. The runs are shortened (240 steps, two cycles)
//! and bounded in number so that the test runs in CI in seconds.

use cardan_runner::run::check_size;
use cardan_runner::{run_paths, RunOptions};
use proptest::prelude::*;
use std::path::{Path, PathBuf};
use toml::Value as Toml;

/// Shipped cases the mutations start from.
const SHIPPED: &[&str] = &[
    "karhula-r60-l140-a0-w200pi",
    "example-compressor",
    "example-offset-engine",
    "example-pressure-trace",
    "example-scotch-yoke-compressor",
    "nunes-op-r26-l90-2000rpm-lead10",
    "karhula-engine-dynamic-flywheel",
    "karhula-engine-dynamic-cs001",
    "balance-inline3",
    "balance-w3-cardan",
    "karhula-pump-r60-l140-a0-w30pi",
    "karhula-pump-motor-dynamic",
];

/// What a numeric field is multiplied by: zero, a sign change, small and large scales, the
/// edges of double precision.
const FACTORS: &[f64] = &[
    0.0, -1.0, 1e-300, 1e-9, 1e-3, 0.1, 0.5, 0.99, 1.01, 2.0, 10.0, 1e3, 1e6, 1e300,
];

fn configs() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../configs")
}

/// The valid cases, shortened: 240 steps, at most two cycles, a pressure trace's file by its
/// absolute path (the mutated case is written elsewhere).
fn bases() -> Vec<toml::Table> {
    let mut texts: Vec<String> = SHIPPED
        .iter()
        .map(|n| std::fs::read_to_string(configs().join(format!("{n}.toml"))).unwrap())
        .collect();
    texts.push(cardan_testing::cases::THESIS_PUMP.to_string());
    texts
        .iter()
        .map(|t| {
            let mut doc: toml::Table = t.parse().unwrap();
            let motion = doc["motion"].as_table_mut().unwrap();
            motion.insert("steps".into(), Toml::Integer(240));
            if motion.contains_key("cycles") {
                motion.insert("cycles".into(), Toml::Integer(2));
            }
            if let Some(Toml::Table(gas)) = doc.get_mut("gas") {
                if let Some(Toml::String(f)) = gas.get("file") {
                    let path = configs().join(f).to_string_lossy().into_owned();
                    gas.insert("file".into(), Toml::String(path));
                }
            }
            doc
        })
        .collect()
}

/// The paths of a document's numeric leaves (a number, "NUMBER UNIT", an array's number):
/// each a list of keys and array indices.
#[derive(Debug, Clone)]
enum Key {
    Name(String),
    Index(usize),
}

fn leaves(v: &Toml, at: &mut Vec<Key>, out: &mut Vec<Vec<Key>>) {
    match v {
        Toml::Table(t) => {
            for (k, v) in t {
                at.push(Key::Name(k.clone()));
                leaves(v, at, out);
                at.pop();
            }
        }
        Toml::Array(a) => {
            for (i, v) in a.iter().enumerate() {
                at.push(Key::Index(i));
                leaves(v, at, out);
                at.pop();
            }
        }
        Toml::Integer(_) | Toml::Float(_) => out.push(at.clone()),
        Toml::String(s) if cardan_case::units::split_number(s).is_ok() => out.push(at.clone()),
        _ => {}
    }
}

fn leaf<'a>(v: &'a mut Toml, path: &[Key]) -> &'a mut Toml {
    path.iter().fold(v, |v, k| match k {
        Key::Name(n) => &mut v.as_table_mut().unwrap()[n.as_str()],
        Key::Index(i) => &mut v.as_array_mut().unwrap()[*i],
    })
}

/// `v` multiplied by `factor`, of the same form (a whole number stays whole where it can).
fn scaled(v: &Toml, factor: f64) -> Toml {
    match v {
        Toml::Integer(i) => {
            let x = *i as f64 * factor;
            if x.fract() == 0.0 && x.abs() < 9e18 {
                Toml::Integer(x as i64)
            } else {
                Toml::Float(x)
            }
        }
        Toml::Float(x) => Toml::Float(x * factor),
        Toml::String(s) => {
            let (x, unit) = cardan_case::units::split_number(s).unwrap();
            Toml::String(format!("{:e} {unit}", x * factor).trim().to_string())
        }
        other => other.clone(),
    }
}

/// A failure the run made before stepping: it names a case field, and neither a step nor a
/// check of the steps' results (the energy balance, a metric not finite, a flywheel sized by
/// solving the motion that cannot reach its target).
fn known_before_stepping(failure: &str) -> bool {
    let after = [
        "the energy check fails",
        "is not finite",
        "cannot be reached",
        "cannot be resolved",
    ];
    if after.iter().any(|a| failure.contains(a)) {
        return false;
    }
    let tables = [
        "geometry.",
        "motion.",
        "gas.",
        "masses.",
        "friction.",
        "gear.",
        "load.",
        "flywheel.",
        "output",
        "layout.",
        "balance.",
        "mechanisms",
        "cardan_gear.",
        "hypotrochoid.",
    ];
    let at_step = failure
        .match_indices("step ")
        .any(|(i, _)| failure[i + 5..].starts_with(|c: char| c.is_ascii_digit()));
    tables.iter().any(|t| failure.contains(t)) && !at_step
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 96, ..ProptestConfig::default() })]

    #[test]
    fn check_passes_exactly_what_the_run_completes(
        base in 0..SHIPPED.len() + 1,
        which in any::<prop::sample::Index>(),
        factor in prop::sample::select(FACTORS),
    ) {
        let mut doc = Toml::Table(bases().swap_remove(base));
        let mut paths = Vec::new();
        leaves(&doc, &mut Vec::new(), &mut paths);
        let path = which.get(&paths).clone();
        let mutated = scaled(leaf(&mut doc, &path), factor);
        *leaf(&mut doc, &path) = mutated;
        let text = toml::to_string(&doc).unwrap();
        let tmp = tempfile::tempdir().unwrap();
        let file = tmp.path().join("mutated.toml");
        std::fs::write(&file, &text).unwrap();

        // `cardan check`: validation, then the size of the per-step files.
        let options = RunOptions::default();
        let checked = cardan_case::case::load_file(&file).map_err(|e| e.to_string()).and_then(|cases| {
            cases.iter().try_for_each(|c| check_size(c, &options)).map(|()| cases)
        });
        let cases = match checked {
            Err(refused) => {
                // The run refuses it too, writing nothing.
                let report = run_paths(std::slice::from_ref(&file), &tmp.path().join("out"), options);
                prop_assert!(!report.failures.is_empty() && report.written.is_empty(),
                    "check refused ({refused}) but the run wrote {:?}\n{text}", report.written);
                return Ok(());
            }
            Ok(cases) => cases,
        };
        // Cases too long to run in a test (a mutated step count or cycle count) are checked only.
        let cycles = doc["motion"].get("cycles").and_then(Toml::as_integer).unwrap_or(1);
        if cases.iter().any(|c| c.steps > 2000) || !(1..=4).contains(&cycles) {
            return Ok(());
        }
        let options = RunOptions { reports: false, ..RunOptions::default() };
        let report = run_paths(&[file], &tmp.path().join("out"), options);
        for f in &report.failures {
            prop_assert!(!known_before_stepping(f),
                "check passed, the run refused before stepping: {f}\n{path:?} x {factor}\n{text}");
            prop_assert!(!f.contains("internal error"), "a panic: {f}\n{text}");
        }
    }
}
