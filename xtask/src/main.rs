//! Project tasks (`cargo xtask ...`, the alias of `.cargo/config.toml`).
//!
//! - `cargo xtask run [--profile NAME] <case files or folders>... [--out DIR] [cardan run
//!   options]`: builds the `cardan` command (release by default: `target/release/cardan`;
//!   `--profile max-speed` for benchmarks and large sweeps, `target/max-speed/cardan`), cargo's
//!   progress shown, and runs `cardan run` with the other arguments; its exit code is returned
//!   (0 all written, 1 some failed, 2 usage).
//! - `cargo xtask readme [--check]`: writes the generated tables of README.md and docs/ from
//!   the registries, or with `--check` exits 1 if they are stale.
//! - `cargo xtask schema [--check]`: writes the JSON Schemas of case files (and gear files)
//!   into `schema/` from the typed schema, or with `--check` exits 1 if they are stale.
//!
//! This launcher has no dependencies, so that `cargo xtask run` on a fresh clone builds it in
//! about a second and then the `cardan` binary alone (issue 38.1); `readme` and `schema` run the
//! package `xtask-gen` (xtask/gen), which needs the workspace's crates, through cargo.

use std::path::{Path, PathBuf};
use std::process::{Command, ExitCode};

const USAGE: &str = "usage: cargo xtask run [--profile release|max-speed] <case files or folders>... [--out DIR] [--jobs N] [--no-csv] ...\n       cargo xtask readme [--check]\n       cargo xtask schema [--check]";

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("..")
}

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    match args.first().map(String::as_str) {
        Some("run") => run(&args[1..]),
        Some("readme" | "schema") => cargo(&["run", "--package", "xtask-gen", "--"], &args),
        _ => {
            eprintln!("{USAGE}");
            ExitCode::from(2)
        }
    }
}

/// `cargo xtask run`: the `cardan` binary of the profile asked for (release by default), built
/// with cargo's progress on the terminal, then `cardan run` with the rest of `args`.
fn run(args: &[String]) -> ExitCode {
    let (profile, args) = match args {
        [flag, name, rest @ ..] if flag == "--profile" => (name.as_str(), rest),
        [flag, ..] if flag == "--profile" => {
            eprintln!("error: --profile needs a name (release or max-speed)\n{USAGE}");
            return ExitCode::from(2);
        }
        _ => ("release", args),
    };
    let profile = format!("--profile={profile}");
    let mut cargo_args = vec!["run", profile.as_str(), "--package", "cardan", "--", "run"];
    cargo_args.extend(args.iter().map(String::as_str));
    cargo(&cargo_args, &[])
}

/// Runs cargo (the one that runs this task) with `args` then `rest`, on the workspace's
/// manifest; its exit code.
fn cargo(args: &[&str], rest: &[String]) -> ExitCode {
    let cargo = std::env::var("CARGO").unwrap_or_else(|_| "cargo".into());
    let status = Command::new(cargo)
        .args(args.iter().take_while(|a| **a != "--"))
        .arg("--manifest-path")
        .arg(root().join("Cargo.toml"))
        .args(args.iter().skip_while(|a| **a != "--"))
        .args(rest)
        .status();
    match status {
        Ok(s) => ExitCode::from(s.code().map_or(1, |c| c.clamp(0, 255) as u8)),
        Err(e) => {
            eprintln!("error: cannot run cargo: {e}");
            ExitCode::FAILURE
        }
    }
}
