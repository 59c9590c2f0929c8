//! `xtask-gen`, run by `cargo xtask readme` and `cargo xtask schema` (the launcher `xtask`
//! runs it through cargo, so that `cargo xtask run` builds none of this):
//!
//! - `readme [--check]`: writes the generated tables of README.md and docs/ from the
//!   registries, or with `--check` exits 1 if they are stale.
//! - `schema [--check]`: writes the JSON Schemas of case files (and gear files) into
//!   `schema/` from the typed schema, or with `--check` exits 1 if they are stale.

use std::path::{Path, PathBuf};
use std::process::ExitCode;

const USAGE: &str = "usage: cargo xtask readme [--check]\n       cargo xtask schema [--check]";

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let check = args.get(1).map(String::as_str) == Some("--check");
    match args.first().map(String::as_str) {
        Some("readme") => readme(check),
        Some("schema") => schema(check),
        _ => {
            eprintln!("{USAGE}");
            ExitCode::from(2)
        }
    }
}

fn readme(check: bool) -> ExitCode {
    let documents = match xtask_gen::regenerate_all(&root()) {
        Ok(d) => d,
        Err(e) => {
            eprintln!("error: {e}");
            return ExitCode::FAILURE;
        }
    };
    let mut status = ExitCode::SUCCESS;
    for (path, text, fresh) in documents {
        if fresh == text {
            continue;
        }
        if check {
            eprintln!(
                "{}'s generated tables are stale: run `cargo xtask readme`",
                path.display()
            );
            status = ExitCode::FAILURE;
        } else if let Err(e) = std::fs::write(&path, fresh) {
            eprintln!("error: {}: {e}", path.display());
            status = ExitCode::FAILURE;
        }
    }
    status
}

fn schema(check: bool) -> ExitCode {
    let mut status = ExitCode::SUCCESS;
    for (path, fresh) in xtask_gen::schemas() {
        let path = root().join(path);
        if std::fs::read_to_string(&path).ok().as_deref() == Some(fresh.as_str()) {
            continue;
        }
        if check {
            eprintln!("{} is stale: run `cargo xtask schema`", path.display());
            status = ExitCode::FAILURE;
            continue;
        }
        let written = path
            .parent()
            .map_or(Ok(()), std::fs::create_dir_all)
            .and_then(|()| std::fs::write(&path, fresh));
        if let Err(e) = written {
            eprintln!("error: {}: {e}", path.display());
            status = ExitCode::FAILURE;
        }
    }
    status
}
