//! The invariants of ARCHITECTURE.md for this crate (the workspace's own architecture test
//! lists other crates' folders): it never depends on the runner or the command line, and no
//! code in its `src` names a mechanism.

use std::path::Path;

fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

#[test]
fn balance_does_not_depend_on_the_runner() {
    let manifest = std::fs::read_to_string(root().join("Cargo.toml")).unwrap();
    let dependencies = manifest.split("[dev-dependencies]").next().unwrap();
    for forbidden in ["cardan-runner", "cardan =", "\ncardan.", "cardan-dynamics"] {
        assert!(
            !dependencies.contains(forbidden),
            "crates/balance depends on {forbidden}"
        );
    }
}

#[test]
fn no_code_in_balance_names_a_mechanism() {
    let mut names = Vec::new();
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
    let mut files = 0;
    for entry in std::fs::read_dir(root().join("src")).unwrap() {
        let path = entry.unwrap().path();
        let text = std::fs::read_to_string(&path).unwrap();
        files += 1;
        for name in &names {
            let in_code = text
                .lines()
                .filter(|l| !l.trim_start().starts_with("//"))
                .any(|l| l.contains(name.as_str()));
            assert!(!in_code, "{} names {name}", path.display());
        }
    }
    assert!(files >= 4);
}
