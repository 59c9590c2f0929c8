//! Every TOML example in README.md and docs/ is read as a user would use it (issue 22: the
//! README's own example case was refused). A block with a `name` is a whole case file; a
//! block that starts with a table (`[sweep]`, `[friction]`, `[gear]`) is added to the README's
//! first example case (as an engine where it sets engine losses).

use cardan_case::case;
use std::path::{Path, PathBuf};

/// The ```toml blocks of `file`, with the line each starts on.
fn toml_blocks(file: &Path) -> Vec<(usize, String)> {
    let text = std::fs::read_to_string(file).unwrap();
    let mut blocks = Vec::new();
    let mut current: Option<(usize, String)> = None;
    for (n, line) in text.lines().enumerate() {
        match &mut current {
            None if line.trim_start().starts_with("```toml") => {
                current = Some((n + 1, String::new()))
            }
            Some(_) if line.trim_start().starts_with("```") => blocks.extend(current.take()),
            Some((_, b)) => {
                b.push_str(line);
                b.push('\n');
            }
            None => {}
        }
    }
    blocks
}

fn markdown_files(root: &Path) -> Vec<PathBuf> {
    let mut files = vec![root.join("README.md")];
    let mut dirs = vec![root.join("docs")];
    while let Some(d) = dirs.pop() {
        for e in std::fs::read_dir(d).unwrap() {
            let p = e.unwrap().path();
            if p.is_dir() {
                dirs.push(p);
            } else if p.extension().is_some_and(|x| x == "md") {
                files.push(p);
            }
        }
    }
    files.sort();
    files
}

#[test]
fn every_toml_example_in_the_documentation_is_accepted() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    let readme = toml_blocks(&root.join("README.md"));
    let (_, base) = readme
        .iter()
        .find(|(_, b)| b.contains("\nname = ") || b.starts_with("name = "))
        .expect("README.md has an example case")
        .clone();
    let dir = tempfile::tempdir().unwrap();
    let mut checked = 0;
    for file in markdown_files(&root) {
        for (line, block) in toml_blocks(&file) {
            let whole = block.lines().any(|l| l.starts_with("name = "));
            let text = if whole {
                block.clone()
            } else {
                // The base case without the tables the fragment brings (and, made an engine,
                // without its pump's gas).
                let table = block.lines().find(|l| l.starts_with('[')).unwrap_or("");
                let engine = block.contains("valve_train");
                let mut kept = String::new();
                let mut skipping = false;
                for l in base.lines() {
                    if l.starts_with('[') {
                        let header = l.split('#').next().unwrap().trim();
                        skipping = header == table || (engine && header == "[gas]");
                    }
                    if !skipping {
                        kept.push_str(l);
                        kept.push('\n');
                    }
                }
                if engine {
                    kept = kept.replacen("machine = \"pump\"", "machine = \"engine\"", 1);
                }
                format!("{kept}\n{block}")
            };
            let path = dir.path().join(format!("example-{checked}.toml"));
            std::fs::write(&path, &text).unwrap();
            // An optimisation (docs/optimisation.md) is read as `cardan run` reads it.
            let read = if text.contains("\n[optimize]") {
                let table = case::toml_table(&path, &text).unwrap();
                cardan_case::optimize::Optimization::define(&path, table).map(|_| ())
            } else {
                case::load_file(&path).map(|_| ())
            };
            if let Err(e) = read {
                panic!(
                    "{}:{line}: the example is refused: {e}\n{text}",
                    file.display()
                );
            }
            checked += 1;
        }
    }
    assert!(checked >= 5, "only {checked} examples found");
}
