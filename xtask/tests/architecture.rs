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
    for krate in [
        "mechanism",
        "dynamics",
        "gas",
        "gears",
        "friction",
        "balance",
    ] {
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

/// The reports are made from an output folder: their crate never depends on the runner (which
/// depends on it) or the command line.
#[test]
fn the_report_crate_does_not_depend_on_the_runner() {
    let manifest = std::fs::read_to_string(root().join("report/Cargo.toml")).unwrap();
    for forbidden in ["cardan-runner", "cardan =", "\ncardan."] {
        assert!(
            !manifest.contains(forbidden),
            "report depends on {forbidden}"
        );
    }
}

/// The lengths of the functions of a Rust file formatted by rustfmt: (name, first line,
/// lines from `fn` to its closing brace, both counted). A function ends at the first later
/// line that is its indentation and `}`; a declaration without a body is skipped.
fn function_lengths(text: &str) -> Vec<(String, usize, usize)> {
    let lines: Vec<&str> = text.lines().collect();
    let mut out = Vec::new();
    for (k, line) in lines.iter().enumerate() {
        let body = line.trim_start();
        let indent = &line[..line.len() - body.len()];
        let mut rest = body;
        for prefix in ["pub(crate) ", "pub(super) ", "pub ", "const ", "unsafe "] {
            rest = rest.strip_prefix(prefix).unwrap_or(rest);
        }
        let Some(name) = rest.strip_prefix("fn ") else {
            continue;
        };
        let name: String = name
            .chars()
            .take_while(|c| c.is_alphanumeric() || *c == '_')
            .collect();
        // The signature runs to the line with the body's `{` (or a `;`: no body).
        let Some(open) = (k..lines.len())
            .find(|&j| lines[j].contains('{') || lines[j].trim_end().ends_with(';'))
        else {
            continue;
        };
        if !lines[open].contains('{') {
            continue;
        }
        let closing = format!("{indent}}}");
        let end = if lines[open].trim_end().ends_with('}') {
            Some(open)
        } else {
            (open + 1..lines.len()).find(|&j| lines[j].trim_end() == closing)
        };
        if let Some(end) = end {
            out.push((name, k + 1, end - k + 1));
        }
    }
    out
}

/// The code stays readable: no source file over 800 lines, no function over 150 (issue 23), in
/// every crate of the workspace.
#[test]
fn files_and_functions_are_short() {
    let mut files = Vec::new();
    for dir in [
        "case/src",
        "runner/src",
        "report/src",
        "cli/src",
        "xtask/src",
        // The Python package's native part: a workspace of its own, held to the same rule.
        "python/src",
    ] {
        rust_files(&root().join(dir), &mut files);
    }
    for entry in std::fs::read_dir(root().join("crates")).unwrap() {
        rust_files(&entry.unwrap().path().join("src"), &mut files);
    }
    assert!(files.len() > 80, "{} files", files.len());
    for file in files {
        let text = std::fs::read_to_string(&file).unwrap();
        let lines = text.lines().count();
        assert!(lines <= 800, "{}: {lines} lines", file.display());
        for (name, line, length) in function_lengths(&text) {
            assert!(
                length <= 150,
                "{}:{line}: fn {name} is {length} lines",
                file.display()
            );
        }
    }
    // The measure itself: a function of three lines, and a declaration without a body.
    let sample = "fn a() {\n    1\n}\ntrait T {\n    fn b();\n}\n";
    assert_eq!(function_lengths(sample), vec![("a".to_string(), 1, 3)]);
}

/// No code outside the mechanisms' own modules names a mechanism: the rest of the code reads
/// bodies, joints and pistons from the topology.
#[test]
fn no_code_outside_a_mechanism_module_names_a_mechanism() {
    let mut files = Vec::new();
    for dir in [
        "crates/dynamics/src",
        "crates/gas/src",
        "crates/balance/src",
        "case/src",
        "runner/src",
        "report/src",
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
