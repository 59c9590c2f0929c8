//! The invariants of ARCHITECTURE.md that a test can read from the sources.

use std::path::{Path, PathBuf};

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("..")
}

fn rust_files(dir: &Path, out: &mut Vec<PathBuf>) {
    for entry in std::fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        if path.is_dir() {
            rust_files(&path, out);
        } else if path.extension().is_some_and(|e| e == "rs") {
            out.push(path);
        }
    }
}

/// Physics crates never depend on the runner or the command line.
#[test]
fn physics_crates_do_not_depend_on_the_runner() {
    for krate in ["mechanism", "dynamics", "gas", "gears", "friction"] {
        let manifest =
            std::fs::read_to_string(root().join(format!("crates/{krate}/Cargo.toml"))).unwrap();
        for forbidden in ["cardan-runner", "cardan =", "\ncardan."] {
            assert!(
                !manifest.contains(forbidden),
                "crates/{krate} depends on {forbidden}"
            );
        }
    }
}

/// The case schema is read before anything runs: its crate never depends on the runner, the
/// reports or the command line.
#[test]
fn the_case_crate_does_not_depend_on_the_runner() {
    let manifest = std::fs::read_to_string(root().join("case/Cargo.toml")).unwrap();
    for forbidden in ["cardan-runner", "cardan-report", "cardan =", "\ncardan."] {
        assert!(!manifest.contains(forbidden), "case depends on {forbidden}");
    }
}

/// No code outside the mechanisms' own modules names a mechanism: the rest of the code reads
/// bodies, joints and pistons from the topology.
#[test]
fn no_code_outside_a_mechanism_module_names_a_mechanism() {
    let mut files = Vec::new();
    for dir in [
        "crates/dynamics/src",
        "crates/gas/src",
        "case/src",
        "runner/src",
        "cli/src",
    ] {
        rust_files(&root().join(dir), &mut files);
    }
    assert!(files.len() > 10);
    // Every registered mechanism, from the registry: its type (`slider_crank` → `SliderCrank`)
    // and its quoted name, and the old enum of mechanisms.
    let mut names = vec!["MechanismKind".to_string()];
    for entry in cardan_mechanism::MECHANISMS {
        let camel: String = entry
            .name
            .split('_')
            .map(|w| {
                let mut c = w.chars();
                c.next()
                    .unwrap()
                    .to_uppercase()
                    .chain(c)
                    .collect::<String>()
            })
            .collect();
        names.push(camel);
        names.push(format!("\"{}\"", entry.name));
    }
    assert!(names.iter().any(|n| n == "Hypotrochoid"), "{names:?}");
    for file in files {
        let text = std::fs::read_to_string(&file).unwrap();
        for name in &names {
            // Doc comments may mention mechanisms; code may not.
            let in_code = text
                .lines()
                .filter(|l| !l.trim_start().starts_with("//"))
                .any(|l| l.contains(name.as_str()));
            assert!(!in_code, "{} names {name}", file.display());
        }
    }
}
