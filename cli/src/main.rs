//! `cardan`: runs and checks case files.
//!
//! Exit codes: 0 every case ran (or checked) and was written; 1 at least one path, case file or
//! case failed (the others still ran; the failures are listed on stderr); 2 the command line
//! itself is wrong.

use cardan_runner::run::{load_batch, RunOptions};
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
    Run(RunArgs),
    /// Gather the output folders of the N shards of one run (`cardan run --shard K/N`) into
    /// what one run writes; shards of other inputs or another program are refused.
    Merge {
        /// The shards' output folders, one per shard.
        #[arg(required_unless_present = "from_list")]
        dirs: Vec<PathBuf>,
        /// Also the folders listed in FILE, one a line (relative ones from FILE's folder):
        /// what `cardan slurm`'s merge job passes, beyond the limit of a command line.
        #[arg(long, value_name = "FILE")]
        from_list: Option<PathBuf>,
        /// Output folder; each case's and sweep's folder in it is replaced as a whole.
        #[arg(long, default_value = "out")]
        out: PathBuf,
    },
    /// Write the Slurm job scripts that run PATHS as N shards (one job array) and merge them
    /// into OUT (a dependent job): OUT.slurm/run.sbatch, merge.sbatch, submit.sh (see
    /// docs/cluster.md); with --submit, submit them.
    Slurm(SlurmArgs),
    /// Read and validate every case under PATHS without running them.
    Check {
        /// Case files, or folders searched recursively for *.toml.
        #[arg(required = true)]
        paths: Vec<PathBuf>,
        /// Pass cases whose per-step files would exceed the size limit, as `run --allow-large`
        /// runs them.
        #[arg(long)]
        allow_large: bool,
    },
    /// Rate one spur gear pair (external or internal) from a gear file and write
    /// OUT/NAME/gear.json and report.md; exit 1 if the file is bad or the pair cannot work
    /// (a blocking check fails or a safety factor is below required_safety_factor, default 1).
    Gear {
        /// The gear file (TOML; see docs/gear-calculator.md).
        file: PathBuf,
        /// Output folder; the pair's folder in it is replaced as a whole.
        #[arg(long, default_value = "out")]
        out: PathBuf,
    },
}

/// `cardan run`'s options.
#[derive(clap::Args)]
struct RunArgs {
    /// Case files, or folders searched recursively for *.toml.
    #[arg(required = true)]
    paths: Vec<PathBuf>,
    /// Output folder; each case's folder in it is replaced as a whole.
    #[arg(long, default_value = "out")]
    out: PathBuf,
    /// Worker threads (default: one per core; more than the cores are capped to them).
    #[arg(long)]
    jobs: Option<usize>,
    /// Write no per-step CSV, whatever the cases' output tables say.
    #[arg(long)]
    no_csv: bool,
    /// Write every case's per-step NPY file (binary, column after column, with
    /// MECHANISM.columns.json), whatever the cases' output tables say.
    #[arg(long)]
    npy: bool,
    /// Run only the cases whose name matches PATTERN (`*` matches anything; without `*`,
    /// any name containing PATTERN).
    #[arg(long, value_name = "PATTERN")]
    only: Option<String>,
    /// No progress bar (it shows on a terminal when a run takes more than a second).
    #[arg(long)]
    quiet: bool,
    /// Write no comparison reports (report.md, report.html and plots/ per case and sweep,
    /// OUT/index.html).
    #[arg(long)]
    no_report: bool,
    /// Run cases whose per-step files would exceed 10 GB (estimated from steps, columns
    /// and bytes per value as the case's [output] asks); without it they are refused.
    #[arg(long)]
    allow_large: bool,
    /// Keep every case folder an earlier (killed) run left complete, written by this
    /// program from the same input (its run.json), and run the rest.
    #[arg(long)]
    resume: bool,
    /// Run only the K-th of N parts of the cases (sweeps expanded; parts balanced by
    /// expected cost), for `cardan merge` to gather (see docs/cluster.md).
    #[arg(long, value_name = "K/N", value_parser = cardan_runner::run::shard::parse_shard)]
    shard: Option<(usize, usize)>,
}

/// `cardan slurm`'s options.
#[derive(clap::Args)]
struct SlurmArgs {
    /// Case files, or folders searched recursively for *.toml.
    #[arg(required = true)]
    paths: Vec<PathBuf>,
    /// The number of shards: array tasks.
    #[arg(long)]
    shards: usize,
    /// The merged output folder; the scripts, shards and logs go to OUT.slurm beside it.
    #[arg(long, default_value = "out")]
    out: PathBuf,
    /// The Slurm partition (#SBATCH --partition).
    #[arg(long)]
    partition: Option<String>,
    /// Each job's time limit (#SBATCH --time, e.g. 30:00 or 2:00:00).
    #[arg(long)]
    time: Option<String>,
    /// The account the jobs are charged to (#SBATCH --account).
    #[arg(long)]
    account: Option<String>,
    /// Each job's memory (#SBATCH --mem, e.g. 4G or 500M; megabytes without a unit).
    #[arg(long)]
    mem: Option<String>,
    /// CPUs of each array task (#SBATCH --cpus-per-task=N); each task then runs
    /// `cardan run --jobs N`. Default: Slurm's, one CPU a task.
    #[arg(long, value_name = "N")]
    cpus_per_task: Option<usize>,
    /// One more #SBATCH option of both scripts, as sbatch takes it (e.g. --qos=high);
    /// repeatable. No spaces, quotes or shell metacharacters.
    #[arg(long, value_name = "OPTION", allow_hyphen_values = true)]
    sbatch_option: Vec<String>,
    /// Submit the scripts (sbatch) once written.
    #[arg(long)]
    submit: bool,
}

/// `cardan gear`: 0 the pair works and was written; 1 the file is bad (nothing written) or the
/// pair cannot work (written, with the reasons and remedies on stderr: a blocking check, a
/// safety factor below `required_safety_factor`, a figure that is not finite). Warnings (rules
/// of thumb such as undercut) go to stderr whatever the verdict.
fn gear(file: &std::path::Path, out: &std::path::Path) -> ExitCode {
    match cardan_gear_file::run(file, out) {
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::FAILURE
        }
        Ok(run) => {
            let failures = run.report.failures();
            for w in run.report.warnings() {
                eprintln!(
                    "warning: {}: gear pair \"{}\": {w}",
                    file.display(),
                    run.report.input.name
                );
            }
            println!(
                "{}  {} -> {}",
                if failures.is_empty() {
                    "ok    "
                } else {
                    "FAILED"
                },
                run.report.input.name,
                run.dir.display()
            );
            if failures.is_empty() {
                ExitCode::SUCCESS
            } else {
                eprintln!(
                    "{}: gear pair \"{}\" cannot work:",
                    file.display(),
                    run.report.input.name
                );
                for f in &failures {
                    eprintln!("  {f}");
                }
                ExitCode::FAILURE
            }
        }
    }
}

/// `cardan slurm`: 0 the scripts were written (and submitted); 1 they could not be (or
/// `sbatch` failed); 2 a bad option.
fn slurm(args: SlurmArgs) -> ExitCode {
    let absolute = |p: &PathBuf| std::path::absolute(p).unwrap_or_else(|_| p.clone());
    let job = cardan::slurm::Job {
        program: std::env::current_exe().unwrap_or_else(|_| "cardan".into()),
        paths: args.paths.iter().map(absolute).collect(),
        out: absolute(&args.out),
        shards: args.shards,
        partition: args.partition,
        time: args.time,
        account: args.account,
        mem: args.mem,
        cpus_per_task: args.cpus_per_task,
        sbatch_options: args.sbatch_option,
    };
    let (shards, submit) = (job.shards, args.submit);
    if let Err(e) = cardan::slurm::scripts(&job) {
        eprintln!("error: {e}");
        return ExitCode::from(2);
    }
    if let Err(e) = cardan::slurm::check_paths(&job) {
        eprintln!("error: {e}");
        return ExitCode::FAILURE;
    }
    let dir = match cardan::slurm::write(&job) {
        Ok(dir) => dir,
        Err(e) => {
            eprintln!("error: {e}");
            return ExitCode::FAILURE;
        }
    };
    println!(
        "job scripts for {shards} shard(s) written to {} (submit: sh {}/submit.sh)",
        dir.display(),
        dir.display()
    );
    if !submit {
        return ExitCode::SUCCESS;
    }
    match std::process::Command::new("sh")
        .arg(dir.join("submit.sh"))
        .status()
    {
        Ok(s) if s.success() => ExitCode::SUCCESS,
        Ok(s) => {
            eprintln!("error: submit.sh (sbatch) failed: {s}");
            ExitCode::FAILURE
        }
        Err(e) => {
            eprintln!("error: cannot run submit.sh: {e}");
            ExitCode::FAILURE
        }
    }
}

/// `cardan check`: every case validated as `cardan run` validates it before stepping, the
/// points of a sweep written as a table each in turn (none kept: a million points are checked
/// in the memory of a few thousand), and a case whose per-step files would pass the size limit
/// refused as the run refuses it; one line per case, one per table sweep. The cases valid,
/// and the failures.
fn check(paths: &[PathBuf], allow_large: bool) -> (usize, Vec<String>) {
    let (batch, mut failures) = load_batch(paths);
    // The run's own refusal of per-step files past the size limit.
    let options = RunOptions {
        allow_large,
        ..RunOptions::default()
    };
    let mut valid = 0;
    for c in &batch.cases {
        match cardan_runner::run::check_size(c, &options) {
            Ok(()) => {
                println!("valid   {} ({})", c.name, c.file.display());
                for note in &c.notes {
                    eprintln!("note: {}: case \"{}\": {note}", c.file.display(), c.name);
                }
                valid += 1;
            }
            Err(e) => failures.push(e),
        }
    }
    for t in &batch.tables {
        match t.check() {
            Ok(n) => {
                println!(
                    "valid   {} ({n} points, a table) ({})",
                    t.sweep.name,
                    t.sweep.file.display()
                );
                valid += n;
            }
            Err(e) => failures.push(e.to_string()),
        }
    }
    for o in &batch.optimizations {
        println!(
            "valid   {} (an optimisation of {} over {} variable(s)) ({})",
            o.name,
            o.mechanisms.join(", "),
            o.variables.len(),
            o.file.display()
        );
        valid += 1;
    }
    println!("{valid} case(s) valid, {} failed", failures.len());
    (valid, failures)
}

/// A progress bar on stderr, drawn only on a terminal and only once a run has lasted a second:
/// the cases finished and, for progress inside a long case, the steps run so far
/// (`cardan_runner::progress`), read four times a second by a thread of its own.
fn progress_bar(quiet: bool) -> indicatif::ProgressBar {
    if quiet {
        return indicatif::ProgressBar::hidden();
    }
    // Nothing is drawn before the first second: short runs stay quiet.
    let bar = indicatif::ProgressBar::hidden();
    bar.set_style(
        indicatif::ProgressStyle::with_template(
            "{elapsed:>4} [{wide_bar}] {pos}/{len} cases, {msg}",
        )
        .expect("a valid template"),
    );
    let shown = bar.clone();
    let start = cardan_runner::progress::steps_run();
    std::thread::spawn(move || {
        std::thread::sleep(std::time::Duration::from_secs(1));
        if !shown.is_finished() {
            shown.set_draw_target(indicatif::ProgressDrawTarget::stderr_with_hz(4));
        }
        while !shown.is_finished() {
            let steps = cardan_runner::progress::steps_run() - start;
            shown.set_message(steps_message(steps, shown.position(), shown.eta()));
            std::thread::sleep(std::time::Duration::from_millis(250));
        }
    });
    bar
}

/// The bar's message: the steps run, and the time left once a case has finished (before, the
/// cases' rate is unknown).
fn steps_message(steps: u64, cases_done: u64, eta: std::time::Duration) -> String {
    let steps = match steps {
        s if s >= 10_000_000 => format!("{:.0} M steps", s as f64 / 1e6),
        s if s >= 1_000_000 => format!("{:.1} M steps", s as f64 / 1e6),
        s if s >= 10_000 => format!("{:.0} k steps", s as f64 / 1e3),
        s => format!("{s} steps"),
    };
    if cases_done == 0 {
        steps
    } else {
        format!("{steps}, {} left", indicatif::HumanDuration(eta))
    }
}

/// `cardan merge`: the shards' folders `dirs` (and those listed in `from_list`) into `out`;
/// the cases and sweeps written and the failures, or the exit code of a list that cannot be
/// read.
fn merge(
    mut dirs: Vec<PathBuf>,
    out: &std::path::Path,
    from_list: Option<PathBuf>,
) -> Result<(usize, Vec<String>), ExitCode> {
    if let Some(list) = from_list {
        match cardan::slurm::read_list(&list) {
            Ok(listed) => dirs.extend(listed),
            Err(e) => {
                eprintln!("error: {e}: nothing merged");
                return Err(ExitCode::FAILURE);
            }
        }
    }
    let started = std::time::Instant::now();
    let report = cardan_runner::run::merge(&dirs, out);
    // The sweeps written as tables: their points are rows, not cases.
    let tables: Vec<usize> = (report.sweeps.iter())
        .filter(|(_, dir, _)| dir.join("sweep.json").is_file())
        .map(|(_, _, points)| *points)
        .collect();
    let rows = match tables.len() {
        0 => String::new(),
        t => format!(
            " and {} point(s) of {t} sweep table(s)",
            tables.iter().sum::<usize>()
        ),
    };
    println!(
        "{} case(s){rows} merged into {} from {} shard(s), {} failed, in {:.2} s",
        report.written.len(),
        out.display(),
        dirs.len(),
        report.failures.len(),
        started.elapsed().as_secs_f64()
    );
    Ok((report.written.len() + report.sweeps.len(), report.failures))
}

/// `cardan run`: the batch run with a progress bar, each case written told on stdout; the
/// number of cases and sweeps written and the failures, or the exit code of a usage error.
fn run(args: RunArgs) -> Result<(usize, Vec<String>), ExitCode> {
    let RunArgs {
        paths,
        out,
        jobs,
        no_csv,
        npy,
        only,
        quiet,
        no_report,
        allow_large,
        resume,
        shard,
    } = args;
    if jobs == Some(0) {
        eprintln!("error: --jobs must be at least 1");
        return Err(ExitCode::from(2));
    }
    if shard.is_some() && only.is_some() {
        eprintln!(
            "error: --shard and --only cannot be combined: a shard is a part of the whole batch"
        );
        return Err(ExitCode::from(2));
    }
    let started = std::time::Instant::now();
    let bar = progress_bar(quiet);
    let progress = bar.clone();
    let options = RunOptions {
        jobs,
        csv: no_csv.then_some(false),
        npy: npy.then_some(true),
        only,
        reports: !no_report,
        allow_large,
        resume,
        shard,
        max_bytes: None,
        progress: Some(std::sync::Arc::new(move |done, total| {
            progress.set_length(total as u64);
            progress.set_position(done as u64);
        })),
    };
    let report = cardan_runner::run_paths(&paths, &out, options);
    bar.finish_and_clear();
    // A sweep's points are told by one line for the sweep, not one each.
    let in_sweep = |dir: &std::path::Path| {
        report
            .sweeps
            .iter()
            .any(|(_, s, _)| dir.parent() == Some(s.as_path()))
    };
    for (name, dir) in &report.written {
        if !in_sweep(dir) {
            println!("ok      {name} -> {}", dir.display());
        }
    }
    for (name, dir, points) in &report.sweeps {
        println!(
            "ok      {name} ({points} point(s) written) -> {}",
            dir.display()
        );
    }
    println!(
        "{} case(s) written to {}{}, {} failed, in {:.2} s",
        report.written.len(),
        out.display(),
        if resume {
            format!(" ({} kept from an earlier run)", report.reused)
        } else {
            String::new()
        },
        report.failures.len(),
        started.elapsed().as_secs_f64()
    );
    let index = out.join("index.html");
    if !no_report && index.is_file() {
        println!("reports: {}", index.display());
    }
    Ok((report.written.len() + report.sweeps.len(), report.failures))
}

fn main() -> ExitCode {
    tracing_subscriber::fmt()
        .with_env_filter(
            tracing_subscriber::EnvFilter::try_from_default_env().unwrap_or_else(|_| "warn".into()),
        )
        .with_writer(std::io::stderr)
        .init();
    // A write past the file-size limit returns an error (EFBIG) that fails its case with a
    // message, instead of a signal that kills the whole run.
    #[cfg(unix)]
    // SAFETY: setting a signal's disposition to "ignore" before any thread starts.
    unsafe {
        libc::signal(libc::SIGXFSZ, libc::SIG_IGN);
    }
    let cli = Cli::parse();
    let (ok, failures) = match cli.command {
        Command::Run(args) => match run(args) {
            Ok(done) => done,
            Err(code) => return code,
        },
        Command::Gear { file, out } => return gear(&file, &out),
        Command::Slurm(args) => return slurm(args),
        Command::Merge {
            dirs,
            out,
            from_list,
        } => match merge(dirs, &out, from_list) {
            Ok(done) => done,
            Err(code) => return code,
        },
        Command::Check { paths, allow_large } => check(&paths, allow_large),
    };
    let failures = if ok == 0 && failures.is_empty() {
        vec![
            "no case to run: no *.toml under the paths, or none whose name matches --only"
                .to_string(),
        ]
    } else {
        failures
    };
    if failures.is_empty() {
        ExitCode::SUCCESS
    } else {
        eprintln!("\nfailures:");
        for f in &failures {
            eprintln!("  {f}");
        }
        ExitCode::FAILURE
    }
}
