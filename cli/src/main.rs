//! `cardan`: runs and checks case files.
//!
//! Exit codes: 0 every case ran (or checked) and was written; 1 at least one path, case file or
//! case failed (the others still ran; the failures are listed on stderr); 2 the command line
//! itself is wrong.

use cardan_runner::run::{load_cases, RunOptions};
use clap::{Parser, Subcommand};
use std::path::PathBuf;
use std::process::ExitCode;

#[derive(Parser)]
#[command(
    name = "cardan",
    version,
    about = "Kinematics, loads and summaries of reciprocating mechanisms (the slider-crank, the cardan gear and their relatives) from TOML case files",
    after_help = "Exit codes: 0 all cases succeeded; 1 some path, case file or case failed (the others still ran); 2 usage error.\nLogs: set RUST_LOG (e.g. RUST_LOG=info)."
)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Run every case under PATHS and write OUT/CASE/summary.json and MECHANISM.csv.
    Run {
        /// Case files, or folders searched recursively for *.toml.
        #[arg(required = true)]
        paths: Vec<PathBuf>,
        /// Output folder; each case's folder in it is replaced as a whole.
        #[arg(long, default_value = "out")]
        out: PathBuf,
        /// Worker threads (default: one per core).
        #[arg(long)]
        jobs: Option<usize>,
        /// Write no per-step CSV, whatever the cases' output tables say.
        #[arg(long)]
        no_csv: bool,
    },
    /// Read and validate every case under PATHS without running them.
    Check {
        /// Case files, or folders searched recursively for *.toml.
        #[arg(required = true)]
        paths: Vec<PathBuf>,
    },
}

fn main() -> ExitCode {
    tracing_subscriber::fmt()
        .with_env_filter(
            tracing_subscriber::EnvFilter::try_from_default_env().unwrap_or_else(|_| "warn".into()),
        )
        .with_writer(std::io::stderr)
        .init();
    let cli = Cli::parse();
    let (ok, failures) = match cli.command {
        Command::Run {
            paths,
            out,
            jobs,
            no_csv,
        } => {
            if jobs == Some(0) {
                eprintln!("error: --jobs must be at least 1");
                return ExitCode::from(2);
            }
            let started = std::time::Instant::now();
            let options = RunOptions {
                jobs,
                csv: no_csv.then_some(false),
            };
            let report = cardan_runner::run_paths(&paths, &out, options);
            for (name, dir) in &report.written {
                println!("ok      {name} -> {}", dir.display());
            }
            println!(
                "{} case(s) written to {}, {} failed, in {:.2} s",
                report.written.len(),
                out.display(),
                report.failures.len(),
                started.elapsed().as_secs_f64()
            );
            (report.written.len(), report.failures)
        }
        Command::Check { paths } => {
            let (cases, failures) = load_cases(&paths);
            for c in &cases {
                println!("valid   {} ({})", c.name, c.file.display());
            }
            println!("{} case(s) valid, {} failed", cases.len(), failures.len());
            (cases.len(), failures)
        }
    };
    if failures.is_empty() && ok > 0 {
        ExitCode::SUCCESS
    } else {
        eprintln!("\nfailures:");
        for f in &failures {
            eprintln!("  {f}");
        }
        ExitCode::FAILURE
    }
}
