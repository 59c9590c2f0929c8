//! `cardan slurm`: the job scripts that run a batch on a Slurm cluster as one job array of N
//! shards (`cardan run --shard K/N --resume`, one array task each) and a merge job that
//! starts when every task has ended (`cardan merge`, refusing an incomplete set of shards);
//! see docs/cluster.md. The scripts name the program, the case paths and the folders by
//! absolute paths: the compute nodes must see them (a shared file system). The merge job
//! reads the shards' folders from a list file (`shards.txt`, `cardan merge --from-list`),
//! not its command line: 100 000 folders would pass the system's limit on a command's
//! arguments ("Argument list too long").

use std::path::{Path, PathBuf};

/// What the job scripts run.
#[derive(Debug, Clone)]
pub struct Job {
    /// The `cardan` program the tasks run.
    pub program: PathBuf,
    /// The case files and folders.
    pub paths: Vec<PathBuf>,
    /// The merged output folder.
    pub out: PathBuf,
    /// The number of shards (array tasks).
    pub shards: usize,
    /// `#SBATCH --partition`.
    pub partition: Option<String>,
    /// `#SBATCH --time` (Slurm's forms: minutes, MM:SS, HH:MM:SS, D-HH...).
    pub time: Option<String>,
    /// `#SBATCH --account`: the account the jobs are charged to.
    pub account: Option<String>,
    /// `#SBATCH --mem`: the memory of each task's node share and of the merge (Slurm's form:
    /// a whole number with an optional unit K, M, G or T, megabytes without one).
    pub mem: Option<String>,
    /// `#SBATCH --cpus-per-task` of the array: each task's CPUs, used by `cardan run --jobs N`.
    /// `None`: Slurm's default, one CPU a task, and `cardan run`'s default threads.
    pub cpus_per_task: Option<usize>,
    /// Further `#SBATCH` lines of both scripts, each one option as `sbatch` takes it
    /// (`--qos=high`), checked by [`check_option`].
    pub sbatch_options: Vec<String>,
}

/// The most shards (array tasks): 4 000 000, the largest job array Slurm allows
/// (`MaxArraySize` is at most 4 000 001, slurm.conf(5); its default, 1001, allows 1000 and
/// `sbatch` says so).
pub const MAX_SHARDS: usize = 4_000_000;

/// The list of the shards' folders the merge job reads, in [`folder`].
pub const SHARD_LIST: &str = "shards.txt";

/// The scripts, each a file of [`folder`].
#[derive(Debug, Clone, PartialEq)]
pub struct Scripts {
    /// `run.sbatch`: the job array, one shard per task.
    pub run: String,
    /// `merge.sbatch`: the merge.
    pub merge: String,
    /// `submit.sh`: submits the array, then the merge depending on it.
    pub submit: String,
    /// `shards.txt` ([`SHARD_LIST`]): the shards' folders, one a line, for the merge.
    pub shards: String,
}

/// The folder of the scripts, the shards' outputs and the logs: `<out>.slurm` beside `out`.
pub fn folder(out: &Path) -> PathBuf {
    let name = out
        .file_name()
        .map_or("out".into(), |n| n.to_string_lossy());
    out.with_file_name(format!("{name}.slurm"))
}

/// `text` quoted for the shell: in single quotes, each single quote written `'\''`.
fn quote(text: &Path) -> String {
    format!("'{}'", text.to_string_lossy().replace('\'', r"'\''"))
}

/// Refuses an `#SBATCH` value that could break out of its line or the script.
fn check_value(flag: &str, value: &str) -> Result<(), String> {
    if value.is_empty()
        || !value
            .chars()
            .all(|c| c.is_ascii_alphanumeric() || "_-.:,+".contains(c))
    {
        return Err(format!(
            "--{flag} {value:?}: only letters, digits and _ - . : , + are allowed"
        ));
    }
    Ok(())
}

/// The options `cardan slurm` writes itself (each script's own, or those of a flag of its
/// own): `--sbatch-option` may not set them again.
const OWN_OPTIONS: &[(&str, &str)] = &[
    ("--array", "the scripts' own (one task per shard)"),
    (
        "--output",
        "the scripts' own (the logs go to OUT.slurm/logs)",
    ),
    ("--job-name", "the scripts' own"),
    (
        "--dependency",
        "submit.sh's own (the merge waits for the array)",
    ),
    ("--partition", "use --partition"),
    ("--time", "use --time"),
    ("--account", "use --account"),
    ("--mem", "use --mem"),
    (
        "--cpus-per-task",
        "use --cpus-per-task (the tasks' `cardan run --jobs` follows it)",
    ),
];

/// Refuses an `--sbatch-option` that is not one long option (`--name` or `--name=value`)
/// written in the characters `sbatch` options take: no white space, line break, quote or shell
/// metacharacter (an `#SBATCH` line is read by `sbatch`, and a line break would start a line
/// of shell), and none of the options the scripts or a flag of their own set (`--array`,
/// `--output`, `--account`, ...).
pub fn check_option(option: &str) -> Result<(), String> {
    let refuse = |why: &str| Err(format!("--sbatch-option {option:?}: {why}"));
    let (name, value) = option.split_once('=').unwrap_or((option, ""));
    let long = name.len() > 2
        && name.starts_with("--")
        && name[2..]
            .chars()
            .all(|c| c.is_ascii_alphanumeric() || c == '-');
    if !long {
        return refuse("must be one long option, --NAME or --NAME=VALUE (e.g. --qos=high)");
    }
    if !value
        .chars()
        .all(|c| c.is_ascii_alphanumeric() || "_-.:,+=/@%".contains(c))
    {
        return refuse(
            "its value may hold only letters, digits and _ - . : , + = / @ % (no space, quote, line break or shell metacharacter)",
        );
    }
    let name = name.to_ascii_lowercase();
    if let Some((_, why)) = OWN_OPTIONS.iter().find(|(own, _)| *own == name) {
        return refuse(&format!("{name} is not passed through: {why}"));
    }
    Ok(())
}

/// Refuses an `--mem` other than Slurm's form: a whole number with an optional unit (K, M, G,
/// T; megabytes without one), sbatch(1).
fn check_mem(mem: &str) -> Result<(), String> {
    let digits = mem.trim_end_matches(['K', 'M', 'G', 'T', 'k', 'm', 'g', 't']);
    let unit = mem.len() - digits.len();
    if digits.is_empty() || unit > 1 || !digits.chars().all(|c| c.is_ascii_digit()) {
        return Err(format!(
            "--mem {mem:?}: a whole number with an optional unit K, M, G or T (e.g. 4G, 500M; megabytes without one)"
        ));
    }
    Ok(())
}

/// The `#SBATCH` lines of both scripts, every value checked.
fn shared_options(job: &Job) -> Result<String, String> {
    let mut options = String::new();
    if let Some(p) = &job.partition {
        check_value("partition", p)?;
        options.push_str(&format!("#SBATCH --partition={p}\n"));
    }
    if let Some(t) = &job.time {
        check_value("time", t)?;
        options.push_str(&format!("#SBATCH --time={t}\n"));
    }
    if let Some(a) = &job.account {
        check_value("account", a)?;
        options.push_str(&format!("#SBATCH --account={a}\n"));
    }
    if let Some(m) = &job.mem {
        check_mem(m)?;
        options.push_str(&format!("#SBATCH --mem={m}\n"));
    }
    for o in &job.sbatch_options {
        check_option(o)?;
        options.push_str(&format!("#SBATCH {o}\n"));
    }
    Ok(options)
}

/// The scripts of `job`.
pub fn scripts(job: &Job) -> Result<Scripts, String> {
    if job.shards == 0 {
        return Err("--shards must be at least 1".into());
    }
    if job.shards > MAX_SHARDS {
        return Err(format!(
            "--shards {}: at most {MAX_SHARDS} (the largest job array Slurm allows; its default MaxArraySize allows 1000)",
            job.shards
        ));
    }
    let options = shared_options(job)?;
    // The array's CPUs a task, and the run's threads to match.
    let (cpus, jobs) = match job.cpus_per_task {
        Some(0) => return Err("--cpus-per-task must be at least 1".into()),
        Some(c) => (
            format!("#SBATCH --cpus-per-task={c}\n"),
            format!(" --jobs {c}"),
        ),
        None => (String::new(), String::new()),
    };
    let dir = folder(&job.out);
    let n = job.shards;
    let program = quote(&job.program);
    let shard = |k: &str| format!("{}/shard-{k}", quote(&dir));
    let paths: Vec<String> = job.paths.iter().map(|p| quote(p)).collect();
    let run = format!(
        "#!/bin/bash\n\
         # The {n} shards of the batch, one array task each (cardan slurm; docs/cluster.md).\n\
         # A task run again (requeued, or by hand) resumes: finished cases are kept.\n\
         #SBATCH --job-name=cardan-shards\n\
         #SBATCH --array=1-{n}\n\
         #SBATCH --output={logs}/shard-%a.log\n\
         {options}\
         {cpus}\
         set -eu\n\
         exec {program} run {paths} --out {out} --shard \"$SLURM_ARRAY_TASK_ID/{n}\" --resume --quiet{jobs}\n",
        logs = quote(&dir.join("logs")),
        paths = paths.join(" "),
        out = shard("\"$SLURM_ARRAY_TASK_ID\""),
    );
    let mut shards = String::new();
    for k in 1..=n {
        shards.push_str(&dir.join(format!("shard-{k}")).to_string_lossy());
        shards.push('\n');
    }
    let merge = format!(
        "#!/bin/bash\n\
         # Gathers the {n} shards into what one run writes, once every array task has ended;\n\
         # refuses (exit 1) if a shard is missing: run its task again, then this.\n\
         #SBATCH --job-name=cardan-merge\n\
         #SBATCH --output={logs}/merge.log\n\
         {options}\
         set -eu\n\
         exec {program} merge --from-list {list} --out {out}\n",
        logs = quote(&dir.join("logs")),
        list = quote(&dir.join(SHARD_LIST)),
        out = quote(&job.out),
    );
    let submit = format!(
        "#!/bin/sh\n\
         # Submits the shards' job array, then the merge, which starts when every task has\n\
         # ended (afterany: a task with a failed case still leaves its shard to merge).\n\
         set -eu\n\
         cd {dir}\n\
         mkdir -p logs\n\
         array=$(sbatch --parsable run.sbatch)\n\
         array=${{array%%;*}}\n\
         merge=$(sbatch --parsable --dependency=afterany:$array merge.sbatch)\n\
         echo \"job array $array ({n} shards), merge job ${{merge%%;*}}\"\n",
        dir = quote(&dir),
    );
    Ok(Scripts {
        run,
        merge,
        submit,
        shards,
    })
}

/// Refuses a job whose scripts would fail on the cluster for a reason known now: a case path
/// that does not exist or is neither a file nor a folder, an `--out` (or its scripts' folder)
/// that exists and is not a folder, a folder name that cannot be a line of [`SHARD_LIST`].
pub fn check_paths(job: &Job) -> Result<(), String> {
    for p in &job.paths {
        match std::fs::metadata(p) {
            Ok(m) if m.is_file() || m.is_dir() => {}
            Ok(m) => {
                return Err(format!(
                    "{}: not a case file or folder ({}): no scripts written",
                    p.display(),
                    cardan_report::files::kind_of(&m)
                ))
            }
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => {
                return Err(format!(
                    "{}: no such file or folder: no scripts written",
                    p.display()
                ))
            }
            Err(e) => return Err(format!("{}: {e}: no scripts written", p.display())),
        }
    }
    for (flag, p) in [("--out", job.out.clone()), ("--out", folder(&job.out))] {
        if let Ok(m) = std::fs::metadata(&p) {
            if !m.is_dir() {
                return Err(format!(
                    "{flag} {}: is {}, not a folder: no scripts written",
                    p.display(),
                    cardan_report::files::kind_of(&m)
                ));
            }
        }
    }
    if folder(&job.out).to_string_lossy().contains(['\n', '\r']) {
        return Err(format!(
            "--out {:?}: a line break in the folder's name cannot be listed in {SHARD_LIST}",
            job.out
        ));
    }
    Ok(())
}

/// The folders listed in the list file `file` ([`SHARD_LIST`]; `cardan merge --from-list`):
/// one a line, blank lines skipped; a relative one is taken from the list file's folder.
/// Read as any file the program reads (a regular file, at most 1 GiB).
pub fn read_list(file: &Path) -> Result<Vec<PathBuf>, String> {
    let text = cardan_report::files::read_text(file, cardan_report::files::RESULT_RECORD)
        .map_err(|e| format!("--from-list {}: cannot read: {e}", file.display()))?;
    let base = file.parent().unwrap_or(Path::new("."));
    let dirs: Vec<PathBuf> = text
        .lines()
        .map(|l| l.trim_end_matches('\r'))
        .filter(|l| !l.trim().is_empty())
        .map(|l| base.join(l))
        .collect();
    if dirs.is_empty() {
        return Err(format!("--from-list {}: lists no folder", file.display()));
    }
    Ok(dirs)
}

/// Writes the scripts of `job` into [`folder`] (with its `logs/`); returns the folder.
pub fn write(job: &Job) -> Result<PathBuf, String> {
    let scripts = scripts(job)?;
    let dir = folder(&job.out);
    let write = |name: &str, text: &str| -> Result<(), String> {
        let path = dir.join(name);
        std::fs::write(&path, text).map_err(|e| format!("cannot write {}: {e}", path.display()))?;
        #[cfg(unix)]
        {
            use std::os::unix::fs::PermissionsExt;
            let _ = std::fs::set_permissions(&path, std::fs::Permissions::from_mode(0o755));
        }
        Ok(())
    };
    std::fs::create_dir_all(dir.join("logs"))
        .map_err(|e| format!("cannot create {}: {e}", dir.display()))?;
    write("run.sbatch", &scripts.run)?;
    write("merge.sbatch", &scripts.merge)?;
    write("submit.sh", &scripts.submit)?;
    write(SHARD_LIST, &scripts.shards)?;
    Ok(dir)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn job() -> Job {
        Job {
            program: "/opt/cardan".into(),
            paths: vec!["/data/configs".into()],
            out: "/scratch/out".into(),
            shards: 4,
            partition: None,
            time: None,
            account: None,
            mem: None,
            cpus_per_task: None,
            sbatch_options: Vec::new(),
        }
    }

    /// The `#SBATCH` lines of a script, in order.
    fn sbatch_lines(script: &str) -> Vec<&str> {
        script
            .lines()
            .filter(|l| l.starts_with("#SBATCH "))
            .collect()
    }

    #[test]
    fn account_memory_cpus_and_passed_options_reach_the_scripts() {
        let plain = scripts(&job()).unwrap();
        assert!(!plain.run.contains("--jobs"), "{}", plain.run);
        assert!(!plain.run.contains("--cpus-per-task"), "{}", plain.run);
        let s = scripts(&Job {
            account: Some("proj-42".into()),
            mem: Some("4G".into()),
            cpus_per_task: Some(8),
            sbatch_options: vec!["--qos=high".into(), "--mail-user=me@example.org".into()],
            ..job()
        })
        .unwrap();
        for script in [&s.run, &s.merge] {
            let lines = sbatch_lines(script);
            for line in [
                "#SBATCH --account=proj-42",
                "#SBATCH --mem=4G",
                "#SBATCH --qos=high",
                "#SBATCH --mail-user=me@example.org",
            ] {
                assert!(lines.contains(&line), "{line:?} not in {lines:?}");
            }
        }
        // The CPUs are the array's: each task runs as many threads; the merge is one process.
        assert!(sbatch_lines(&s.run).contains(&"#SBATCH --cpus-per-task=8"));
        assert!(!s.merge.contains("--cpus-per-task"), "{}", s.merge);
        let exec = s.run.lines().last().unwrap();
        assert!(
            exec.starts_with("exec ") && exec.ends_with("--resume --quiet --jobs 8"),
            "{exec}"
        );
        // Every #SBATCH line comes before the first command (sbatch stops reading them there).
        let first_command = s.run.lines().position(|l| l == "set -eu").unwrap();
        let lines: Vec<&str> = s.run.lines().collect();
        let last_option = lines
            .iter()
            .rposition(|l| l.starts_with("#SBATCH"))
            .unwrap();
        assert!(last_option < first_command, "{}", s.run);
    }

    #[test]
    fn a_value_that_could_break_out_of_its_line_is_refused() {
        for bad in [
            "--qos=high\n#SBATCH --x",
            "--qos=a b",
            "--qos=$(reboot)",
            "--qos=a;b",
            "--comment='x'",
            "--qos=`x`",
            "--qos=a|b",
            "--qos=a&b",
            "--qos=a>b",
            "qos=high",
            "-q high",
            "--",
            "--=x",
        ] {
            let e = scripts(&Job {
                sbatch_options: vec![bad.into()],
                ..job()
            })
            .unwrap_err();
            assert!(e.starts_with("--sbatch-option "), "{bad:?}: {e}");
        }
        for (bad, flag) in [
            ("--array=1-3", "--array"),
            ("--output=/tmp/x", "--output"),
            ("--cpus-per-task=4", "use --cpus-per-task"),
            ("--MEM=4G", "use --mem"),
            ("--account=x", "use --account"),
        ] {
            let e = check_option(bad).unwrap_err();
            assert!(e.contains(flag), "{bad:?}: {e}");
        }
        for good in [
            "--qos=high",
            "--exclusive",
            "--constraint=avx2",
            "--gres=gpu:1",
        ] {
            assert_eq!(check_option(good), Ok(()), "{good}");
        }
        let with = |f: fn(&mut Job)| {
            let mut j = job();
            f(&mut j);
            scripts(&j)
        };
        assert!(with(|j| j.account = Some("a\nb".into())).is_err());
        assert!(with(|j| j.account = Some("a b".into())).is_err());
        assert!(with(|j| j.cpus_per_task = Some(0)).is_err());
        for bad in ["", "4 G", "4GB", "G", "-4G", "4.5G", "4G\n"] {
            let e = with_mem(bad);
            assert!(e.is_err(), "--mem {bad:?} accepted");
        }
        for good in ["4000", "4G", "500M", "1T", "0"] {
            assert!(with_mem(good).is_ok(), "--mem {good:?} refused");
        }
    }

    fn with_mem(mem: &str) -> Result<Scripts, String> {
        scripts(&Job {
            mem: Some(mem.into()),
            ..job()
        })
    }
}
