//! Project tasks.
//!
//! - `cargo xtask run <case files or folders>... [--out DIR] [cardan run options]`: builds the
//!   `cardan` command in release (cargo's progress shown) and runs `cardan run` with the same
//!   arguments; its exit code is returned (0 all written, 1 some failed, 2 usage).
//! - `cargo xtask readme [--check]`: writes the generated tables of README.md and docs/ from
//!   the registries, or with `--check` exits 1 if they are stale.
//! - `cargo xtask schema [--check]`: writes the JSON Schemas of case files (and gear files)
//!   into `schema/` from the typed schema, or with `--check` exits 1 if they are stale.

use std::path::{Path, PathBuf};
use std::process::{Command, ExitCode};

const USAGE: &str = "usage: cargo xtask run <case files or folders>... [--out DIR] [--jobs N] [--no-csv]\n       cargo xtask readme [--check]\n       cargo xtask schema [--check]";

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("..")
}

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    match args.first().map(String::as_str) {
        Some("run") => run(&args[1..]),
        Some("readme") => readme(args.get(1).map(String::as_str) == Some("--check")),
        Some("schema") => schema(args.get(1).map(String::as_str) == Some("--check")),
        _ => {
            eprintln!("{USAGE}");
            ExitCode::from(2)
        }
    }
}

fn run(args: &[String]) -> ExitCode {
    let cargo = std::env::var("CARGO").unwrap_or_else(|_| "cargo".into());
    let status = Command::new(cargo)
        .args(["run", "--release", "--package", "cardan", "--manifest-path"])
        .arg(root().join("Cargo.toml"))
        .args(["--", "run"])
        .args(args)
        .status();
    match status {
        Ok(s) => ExitCode::from(s.code().map_or(1, |c| c.clamp(0, 255) as u8)),
        Err(e) => {
            eprintln!("error: cannot run cargo: {e}");
            ExitCode::FAILURE
        }
    }
}

fn readme(check: bool) -> ExitCode {
    let documents = match xtask::regenerate_all(&root()) {
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
    for (path, fresh) in xtask::schemas() {
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
