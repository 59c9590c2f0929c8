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
    let mut options = String::new();
    if let Some(p) = &job.partition {
        check_value("partition", p)?;
        options.push_str(&format!("#SBATCH --partition={p}\n"));
    }
    if let Some(t) = &job.time {
        check_value("time", t)?;
        options.push_str(&format!("#SBATCH --time={t}\n"));
    }
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
         set -eu\n\
         exec {program} run {paths} --out {out} --shard \"$SLURM_ARRAY_TASK_ID/{n}\" --resume --quiet\n",
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
