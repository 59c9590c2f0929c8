//! `cardan run --resume` after a real kill at a random moment, `--shard` and `cardan merge`
//! through the command line, and `cardan slurm`'s script (issue 26).

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::process::Command;

fn configs() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../configs")
}

fn cardan() -> Command {
    Command::new(env!("CARGO_BIN_EXE_cardan"))
}

/// Every file under `dir` and its bytes.
fn tree(dir: &Path) -> BTreeMap<String, Vec<u8>> {
    fn walk(dir: &Path, prefix: &str, out: &mut BTreeMap<String, Vec<u8>>) {
        for entry in std::fs::read_dir(dir).unwrap() {
            let entry = entry.unwrap();
            let name = format!("{prefix}{}", entry.file_name().to_string_lossy());
            if entry.file_type().unwrap().is_dir() {
                walk(&entry.path(), &format!("{name}/"), out);
            } else {
                out.insert(name, std::fs::read(entry.path()).unwrap());
            }
        }
    }
    let mut out = BTreeMap::new();
    walk(dir, "", &mut out);
    out
}

fn assert_same(expected: &Path, actual: &Path, context: &str) {
    let (a, b) = (tree(expected), tree(actual));
    let keys_a: Vec<&String> = a.keys().collect();
    let keys_b: Vec<&String> = b.keys().collect();
    assert_eq!(keys_a, keys_b, "{context}: not the same files");
    for (k, v) in &a {
        assert!(b[k] == *v, "{context}: {k} differs");
    }
}

fn run(args: &[&std::ffi::OsStr]) -> std::process::Output {
    cardan().args(args).output().unwrap()
}

/// `cardan merge SHARDS... --out OUT`.
fn merge(shards: &[&Path], out: &Path) -> std::process::Output {
    cardan()
        .arg("merge")
        .args(shards)
        .arg("--out")
        .arg(out)
        .output()
        .unwrap()
}

/// A run of the shipped configs killed (SIGKILL) at a random moment, then resumed, equals a
/// single run byte for byte; the moment is in the failure message.
#[test]
fn a_run_killed_at_a_random_moment_and_resumed_equals_one_run() {
    let tmp = tempfile::tempdir().unwrap();
    let single = tmp.path().join("single");
    let out = run(&[
        "run".as_ref(),
        configs().as_os_str(),
        "--out".as_ref(),
        single.as_os_str(),
        "--quiet".as_ref(),
    ]);
    assert!(out.status.success(), "{out:?}");
    let nanos = std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .unwrap()
        .subsec_nanos();
    for round in 0..2u32 {
        let killed = tmp.path().join(format!("killed{round}"));
        let delay_ms = 100 + u64::from((nanos >> (round * 8)) % 2500);
        let mut child = cardan()
            .arg("run")
            .arg(configs())
            .arg("--out")
            .arg(&killed)
            .args(["--quiet", "--jobs", "1"])
            .stdout(std::process::Stdio::null())
            .stderr(std::process::Stdio::null())
            .spawn()
            .unwrap();
        std::thread::sleep(std::time::Duration::from_millis(delay_ms));
        let _ = child.kill();
        let _ = child.wait();
        let out = run(&[
            "run".as_ref(),
            configs().as_os_str(),
            "--out".as_ref(),
            killed.as_os_str(),
            "--quiet".as_ref(),
            "--resume".as_ref(),
        ]);
        assert!(out.status.success(), "killed after {delay_ms} ms: {out:?}");
        assert_same(&single, &killed, &format!("killed after {delay_ms} ms"));
    }
}

/// `--shard` and `cardan merge` from the command line: the merge equals the single run; a
/// shard count of 0, K above N and `--shard` with `--only` are usage errors (exit 2); a merge
/// of an incomplete set of shards, or with a shard killed before its end, fails (exit 1).
#[test]
fn shards_from_the_command_line_merge_into_one_run() {
    let tmp = tempfile::tempdir().unwrap();
    let file = configs().join("sweeps/karhula-pump-speed-sweep.toml");
    assert!(file.is_file());
    let single = tmp.path().join("single");
    run_single(&file, &single);
    let shards: Vec<PathBuf> = (1..=2).map(|k| tmp.path().join(format!("s{k}"))).collect();
    for (k, dir) in shards.iter().enumerate() {
        let spec = format!("{}/2", k + 1);
        let out = run(&[
            "run".as_ref(),
            file.as_os_str(),
            "--out".as_ref(),
            dir.as_os_str(),
            "--quiet".as_ref(),
            "--shard".as_ref(),
            spec.as_ref(),
        ]);
        assert!(out.status.success(), "{out:?}");
    }
    let merged = tmp.path().join("merged");
    let out = merge(&[&shards[0], &shards[1]], &merged);
    assert!(out.status.success(), "{out:?}");
    assert_same(&single, &merged, "merged");
    let out = merge(&[&shards[0]], &tmp.path().join("m2"));
    assert_eq!(out.status.code(), Some(1), "{out:?}");
    assert!(String::from_utf8_lossy(&out.stderr).contains("2/2"));
    // A shard whose task was killed before its end (a Slurm task cancelled, timed out, on a
    // failed node: its record, written last, is missing): refused, said so, nothing written.
    std::fs::remove_file(shards[1].join("shard.json")).unwrap();
    let m3 = tmp.path().join("m3");
    let out = merge(&[&shards[0], &shards[1]], &m3);
    assert_eq!(out.status.code(), Some(1), "{out:?}");
    let said = String::from_utf8_lossy(&out.stderr);
    assert!(
        said.contains(&*shards[1].to_string_lossy())
            && said.contains("did not finish")
            && said.contains("--resume"),
        "{said}"
    );
    assert!(!m3.exists(), "a refused merge wrote {}", m3.display());
    for bad in [
        &["--shard", "0/2"][..],
        &["--shard", "3/2"],
        &["--shard", "1/2", "--only", "x"],
    ] {
        let mut args: Vec<&std::ffi::OsStr> = vec!["run".as_ref(), file.as_os_str()];
        args.extend(bad.iter().map(std::ffi::OsStr::new));
        assert_eq!(run(&args).status.code(), Some(2), "{bad:?}");
    }
}

/// A sweep written as a table (`case_folders = false`) split over 3 shards from the command
/// line, as the Slurm tasks run them (`--shard K/3 --resume`): each shard writes a range of its
/// rows, the merge equals the single run byte for byte; a shard run again with `--resume` gives
/// the same; a shard's part missing is refused (exit 1) naming the points, nothing written.
/// (And `cardan check` refuses the sweep with a misspelled `[output] metrics`.)
#[test]
fn a_table_sweep_in_three_shards_merges_into_one_run() {
    let tmp = tempfile::tempdir().unwrap();
    let text = std::fs::read_to_string(configs().join("sweeps/karhula-pump-map-speed-rod.toml"))
        .unwrap()
        .replacen("[output]", "[output]\ncase_folders = false", 1);
    assert!(text.contains("case_folders = false"));
    let file = tmp.path().join("map.toml");
    // `cardan check` refuses a misspelled `[output] metrics`, naming the nearest metric.
    let bad = text.replacen("[output]", "[output]\nmetrics = [\"power_loss_men\"]", 1);
    std::fs::write(&file, bad).unwrap();
    let out = run(&["check".as_ref(), file.as_os_str()]);
    assert_eq!(out.status.code(), Some(1), "{out:?}");
    let said = format!(
        "{}{}",
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(
        said.contains("output.metrics = \"power_loss_men\"")
            && said.contains("did you mean \"power_loss_mean\""),
        "{said}"
    );
    std::fs::write(&file, text).unwrap();
    let single = tmp.path().join("single");
    run_single(&file, &single);
    let shards: Vec<PathBuf> = (1..=3).map(|k| tmp.path().join(format!("s{k}"))).collect();
    let shard_run = |k: usize| {
        let spec = format!("{k}/3");
        let out = run(&[
            "run".as_ref(),
            file.as_os_str(),
            "--out".as_ref(),
            shards[k - 1].as_os_str(),
            "--quiet".as_ref(),
            "--resume".as_ref(),
            "--shard".as_ref(),
            spec.as_ref(),
        ]);
        assert!(out.status.success(), "{out:?}");
    };
    for k in 1..=3 {
        shard_run(k);
    }
    let sweep = "karhula-pump-map-speed-rod";
    for s in &shards {
        let part = std::fs::read_to_string(s.join(sweep).join("sweep.json")).unwrap();
        assert!(part.contains("\"range\""), "{part}");
    }
    let shard_refs: Vec<&Path> = shards.iter().map(PathBuf::as_path).collect();
    let merged = tmp.path().join("merged");
    let out = merge(&shard_refs, &merged);
    assert!(out.status.success(), "{out:?}");
    assert_same(&single, &merged, "merged table");
    shard_run(2);
    let again = tmp.path().join("again");
    let out = merge(&shard_refs, &again);
    assert!(out.status.success(), "{out:?}");
    assert_same(&single, &again, "merged after a shard ran again");
    std::fs::remove_dir_all(shards[1].join(sweep)).unwrap();
    let refused = tmp.path().join("refused");
    let out = merge(&shard_refs, &refused);
    assert_eq!(out.status.code(), Some(1), "{out:?}");
    let said = String::from_utf8_lossy(&out.stderr);
    assert!(
        said.contains("missing") && said.contains("shard 2"),
        "{said}"
    );
    assert!(
        !refused.exists(),
        "a refused merge wrote {}",
        refused.display()
    );
}

/// A shard run again into its folder (a Slurm task requeued) and killed before its end: its
/// old `shard.json` is gone before the rerun replaces anything, so `cardan merge` refuses the
/// folder as unfinished instead of vouching for a mix of old and new outputs by the old record.
/// The kill comes once the record is seen gone (polled), so it lands inside the rerun's work.
#[test]
fn a_shard_rerun_killed_before_its_end_is_refused_by_merge() {
    let tmp = tempfile::tempdir().unwrap();
    let shards: Vec<PathBuf> = (1..=2).map(|k| tmp.path().join(format!("s{k}"))).collect();
    let shard_run = |k: usize| {
        let mut c = cardan();
        c.arg("run")
            .arg(configs())
            .arg("--out")
            .arg(&shards[k - 1])
            .args(["--quiet", "--jobs", "1", "--shard", &format!("{k}/2")]);
        c
    };
    for k in 1..=2 {
        let out = shard_run(k).output().unwrap();
        assert!(out.status.success(), "{out:?}");
    }
    let record = shards[1].join("shard.json");
    assert!(record.is_file());
    let mut child = shard_run(2)
        .stdout(std::process::Stdio::null())
        .stderr(std::process::Stdio::null())
        .spawn()
        .unwrap();
    let start = std::time::Instant::now();
    while record.exists() {
        assert!(
            child.try_wait().unwrap().is_none(),
            "the rerun ended with its old record never removed"
        );
        assert!(start.elapsed().as_secs() < 60, "the old record stayed 60 s");
        std::thread::sleep(std::time::Duration::from_millis(1));
    }
    let _ = child.kill();
    let status = child.wait().unwrap();
    assert!(
        !status.success(),
        "the rerun finished before the kill: {status:?}"
    );
    assert!(!record.exists(), "a killed rerun left a record");
    let merged = tmp.path().join("merged");
    let out = merge(&[&shards[0], &shards[1]], &merged);
    assert_eq!(out.status.code(), Some(1), "{out:?}");
    let said = String::from_utf8_lossy(&out.stderr);
    assert!(said.contains("did not finish"), "{said}");
    assert!(
        !merged.exists(),
        "a refused merge wrote {}",
        merged.display()
    );
}

/// `cardan slurm` writes a job array of N shard tasks and a merge job: their content, and
/// the scripts run by bash as Slurm would run them (each array task with its
/// `SLURM_ARRAY_TASK_ID`, then the merge) give the single run's folder byte for byte.
#[test]
fn slurm_scripts_run_the_shards_and_merge_them_into_one_run() {
    let tmp = tempfile::tempdir().unwrap();
    let file = configs().join("sweeps/karhula-pump-speed-sweep.toml");
    let out = tmp.path().join("merged");
    let written = run(&[
        "slurm".as_ref(),
        file.as_os_str(),
        "--shards".as_ref(),
        "3".as_ref(),
        "--out".as_ref(),
        out.as_os_str(),
        "--partition".as_ref(),
        "debug".as_ref(),
        "--time".as_ref(),
        "10:00".as_ref(),
        "--account".as_ref(),
        "proj-1".as_ref(),
        "--mem".as_ref(),
        "2G".as_ref(),
        "--cpus-per-task".as_ref(),
        "2".as_ref(),
        "--sbatch-option".as_ref(),
        "--qos=normal".as_ref(),
        "--sbatch-option=--exclusive".as_ref(),
    ]);
    assert!(written.status.success(), "{written:?}");
    let dir = tmp.path().join("merged.slurm");
    let read = |name: &str| std::fs::read_to_string(dir.join(name)).unwrap();
    let (array, merge, submit) = (read("run.sbatch"), read("merge.sbatch"), read("submit.sh"));
    for line in [
        "#SBATCH --array=1-3",
        "#SBATCH --partition=debug",
        "#SBATCH --time=10:00",
        "#SBATCH --account=proj-1",
        "#SBATCH --mem=2G",
        "#SBATCH --cpus-per-task=2",
        "#SBATCH --qos=normal",
        "#SBATCH --exclusive",
        "--shard \"$SLURM_ARRAY_TASK_ID/3\" --resume --quiet --jobs 2",
    ] {
        assert!(array.contains(line), "{line:?} not in:\n{array}");
    }
    assert!(array.contains(&*file.to_string_lossy()), "{array}");
    // The merge reads the shards' folders from shards.txt (issue 36.13).
    let list = read("shards.txt");
    assert!(
        merge.contains(" merge --from-list ") && merge.contains("shards.txt"),
        "{merge}"
    );
    assert_eq!(list.lines().count(), 3, "{list}");
    assert!(list.lines().nth(2).unwrap().ends_with("shard-3"), "{list}");
    for line in [
        "#SBATCH --partition=debug",
        "#SBATCH --account=proj-1",
        "#SBATCH --qos=normal",
    ] {
        assert!(merge.contains(line), "{line:?} not in:\n{merge}");
    }
    assert!(
        submit.contains("sbatch --parsable run.sbatch")
            && submit.contains("--dependency=afterany:$array merge.sbatch"),
        "{submit}"
    );
    for name in ["run.sbatch", "merge.sbatch", "submit.sh"] {
        let syntax = Command::new("bash").arg("-n").arg(dir.join(name)).status();
        if let Ok(s) = syntax {
            assert!(s.success(), "{name}: not valid shell");
        }
    }
    // The tasks as Slurm runs them, in any order, then the merge.
    for k in ["2", "3", "1"] {
        let task = Command::new("bash")
            .arg(dir.join("run.sbatch"))
            .env("SLURM_ARRAY_TASK_ID", k)
            .output()
            .unwrap();
        assert!(task.status.success(), "task {k}: {task:?}");
    }
    let merged = Command::new("bash")
        .arg(dir.join("merge.sbatch"))
        .output()
        .unwrap();
    assert!(merged.status.success(), "{merged:?}");
    let single = tmp.path().join("single");
    let out1 = run(&[
        "run".as_ref(),
        file.as_os_str(),
        "--out".as_ref(),
        single.as_os_str(),
        "--quiet".as_ref(),
    ]);
    assert!(out1.status.success(), "{out1:?}");
    assert_same(&single, &out, "slurm scripts");

    // A value that would break out of its #SBATCH line is refused.
    let bad = run(&[
        "slurm".as_ref(),
        file.as_os_str(),
        "--shards".as_ref(),
        "2".as_ref(),
        "--out".as_ref(),
        tmp.path().join("x").as_os_str(),
        "--partition".as_ref(),
        "a\n#SBATCH --x".as_ref(),
    ]);
    assert_eq!(bad.status.code(), Some(2), "{bad:?}");
    let bad = run(&[
        "slurm".as_ref(),
        file.as_os_str(),
        "--shards".as_ref(),
        "2".as_ref(),
        "--out".as_ref(),
        tmp.path().join("x").as_os_str(),
        "--sbatch-option".as_ref(),
        "--qos=high; rm -rf ~".as_ref(),
    ]);
    assert_eq!(bad.status.code(), Some(2), "{bad:?}");
    assert!(
        String::from_utf8_lossy(&bad.stderr).contains("--sbatch-option"),
        "{bad:?}"
    );
    assert!(!tmp.path().join("x.slurm").exists());
}

/// The output of `program args`, stdout and stderr together, or why it could not run.
fn output_of(program: &str, args: &[&str]) -> String {
    match Command::new(program).args(args).output() {
        Ok(o) => format!(
            "{}{}",
            String::from_utf8_lossy(&o.stdout),
            String::from_utf8_lossy(&o.stderr)
        ),
        Err(e) => format!("cannot run {program}: {e}"),
    }
}

/// The jobs' state for a failure message: the queue, the node, each job's record (scontrol,
/// or sacct where the controller has forgotten it) and every log of the jobs.
fn slurm_state(ids: &str, dir: &Path) -> String {
    let mut text = format!(
        "squeue:\n{}\nsinfo:\n{}\nscontrol show job:\n{}\nsacct:\n{}\n",
        output_of("squeue", &["-t", "all", "-j", ids, "-o", "%i %T %r %M"]),
        output_of("sinfo", &["-N", "-l"]),
        ids.split(',')
            .map(|id| output_of("scontrol", &["show", "job", "-o", id]))
            .collect::<String>(),
        output_of(
            "sacct",
            &["-X", "-j", ids, "-o", "JobID,State,ExitCode", "-P"]
        ),
    );
    if let Ok(entries) = std::fs::read_dir(dir.join("logs")) {
        for entry in entries.flatten() {
            let log = std::fs::read_to_string(entry.path()).unwrap_or_default();
            text.push_str(&format!("--- {}:\n{log}\n", entry.path().display()));
        }
    }
    text
}

/// The `JobState` and `ExitCode` of each job (each array task) of `id`, from `scontrol show
/// job` (kept MinJobAge after the end: 300 s by default, an hour on .ci/slurm-cluster's
/// node), else from `sacct` (a cluster with accounting); empty if neither knows the job.
fn job_states(id: &str) -> Vec<(String, String, String)> {
    let field = |line: &str, key: &str| {
        line.split_whitespace()
            .find_map(|f| f.strip_prefix(key))
            .unwrap_or("?")
            .to_string()
    };
    let shown = Command::new("scontrol")
        .args(["show", "job", "-o", id])
        .output();
    if let Some(o) = shown.ok().filter(|o| o.status.success()) {
        return String::from_utf8_lossy(&o.stdout)
            .lines()
            .filter(|l| l.starts_with("JobId="))
            .map(|l| {
                let task = field(l, "ArrayTaskId=");
                let name = if task == "?" {
                    id.to_string()
                } else {
                    format!("{id}_{task}")
                };
                (name, field(l, "JobState="), field(l, "ExitCode="))
            })
            .collect();
    }
    let o = output_of(
        "sacct",
        &["-n", "-X", "-P", "-j", id, "-o", "JobID,State,ExitCode"],
    );
    o.lines()
        .filter_map(|l| {
            let f: Vec<&str> = l.split('|').collect();
            (f.len() == 3).then(|| (f[0].into(), f[1].into(), f[2].into()))
        })
        .collect()
}

/// Opt-in (`CARDAN_SLURM_TEST=1`; a cluster such as `.ci/slurm-cluster start`'s one node,
/// docs/cluster.md): `cardan slurm configs --shards 3 --submit` on the real Slurm; waits for
/// the job array and the dependent merge job (squeue, at most `CARDAN_SLURM_TIMEOUT` seconds,
/// default 900), checks that every array task and the merge COMPLETED with exit code 0, and
/// compares the merged folder with a single run byte for byte (run here, or the folder
/// `CARDAN_SLURM_REFERENCE` names: a single run of the shipped configs). On failure: the
/// jobs' state and logs. Skipped without the opt-in; with it, a missing `sbatch` is a failure.
#[test]
fn a_real_slurm_job_array_merges_into_one_run() {
    if std::env::var("CARDAN_SLURM_TEST").as_deref() != Ok("1") {
        eprintln!("skipped: set CARDAN_SLURM_TEST=1 with Slurm running (docs/cluster.md)");
        return;
    }
    assert!(
        Command::new("sbatch").arg("--version").output().is_ok(),
        "CARDAN_SLURM_TEST=1 but no sbatch on the PATH: start a cluster (.ci/slurm-cluster start)"
    );
    let timeout: u64 = std::env::var("CARDAN_SLURM_TIMEOUT")
        .ok()
        .and_then(|t| t.parse().ok())
        .unwrap_or(900);
    // Under the target folder: the compute node must see it (here, this machine).
    let tmp = tempfile::tempdir_in(env!("CARGO_TARGET_TMPDIR")).unwrap();
    let out = tmp.path().join("merged");
    let dir = tmp.path().join("merged.slurm");
    let started = std::time::Instant::now();
    let submitted = run(&[
        "slurm".as_ref(),
        configs().as_os_str(),
        "--shards".as_ref(),
        "3".as_ref(),
        "--out".as_ref(),
        out.as_os_str(),
        "--submit".as_ref(),
    ]);
    let said = String::from_utf8_lossy(&submitted.stdout).to_string();
    assert!(submitted.status.success(), "{submitted:?}");
    eprintln!("{said}");
    // "job array 12 (3 shards), merge job 13"
    let number = |after: &str| -> String {
        let rest = &said[said
            .find(after)
            .unwrap_or_else(|| panic!("{after:?} not in {said:?}"))
            + after.len()..];
        rest.chars().take_while(char::is_ascii_digit).collect()
    };
    let (array, merge) = (number("job array "), number("merge job "));
    assert!(
        !array.is_empty() && !merge.is_empty(),
        "job ids in {said:?}"
    );
    let ids = format!("{array},{merge}");
    // Until neither job is pending or running (squeue without -t lists only those).
    loop {
        let queued = Command::new("squeue")
            .args(["-h", "-j", &ids, "-o", "%i %T"])
            .output()
            .unwrap();
        if String::from_utf8_lossy(&queued.stdout).trim().is_empty() {
            break;
        }
        assert!(
            started.elapsed().as_secs() < timeout,
            "the jobs not finished after {timeout} s (CARDAN_SLURM_TIMEOUT):\n{}",
            slurm_state(&ids, &dir)
        );
        std::thread::sleep(std::time::Duration::from_secs(1));
    }
    let elapsed = started.elapsed().as_secs_f64();
    let (tasks, merged) = (job_states(&array), job_states(&merge));
    eprintln!("finished in {elapsed:.0} s: {tasks:?} {merged:?}");
    assert_eq!(
        tasks.len(),
        3,
        "the array's tasks: {tasks:?}\n{}",
        slurm_state(&ids, &dir)
    );
    for (job, state, code) in tasks.iter().chain(&merged) {
        assert!(
            state == "COMPLETED" && code == "0:0",
            "job {job}: {state}, exit code {code}\n{}",
            slurm_state(&ids, &dir)
        );
    }
    // The single run: CARDAN_SLURM_REFERENCE's folder if given (CI: the shipped configs'
    // folder `cargo xtask run configs` wrote, the same program in release: the outputs of the
    // two profiles are the same bit for bit), else run here.
    let single = match std::env::var_os("CARDAN_SLURM_REFERENCE") {
        Some(reference) => PathBuf::from(reference),
        None => {
            let single = tmp.path().join("single");
            let out1 = run(&[
                "run".as_ref(),
                configs().as_os_str(),
                "--out".as_ref(),
                single.as_os_str(),
                "--quiet".as_ref(),
            ]);
            assert!(out1.status.success(), "{out1:?}");
            single
        }
    };
    assert_same(&single, &out, "real slurm");
}

/// `cardan run FILE --out SINGLE --quiet`, which must succeed: the single run a merge must equal.
fn run_single(file: &Path, single: &Path) {
    let out = run(&[
        "run".as_ref(),
        file.as_os_str(),
        "--out".as_ref(),
        single.as_os_str(),
        "--quiet".as_ref(),
    ]);
    assert!(out.status.success(), "{out:?}");
}

/// `cardan slurm` refuses what would only fail on the cluster (issue 36.13): a case path that
/// does not exist, an `--out` that is a file or a device (exit 1, nothing written), more
/// shards than Slurm's largest job array (exit 2); and 100 000 shards give a merge job whose
/// command line is short (the folders in shards.txt, which `cardan merge --from-list` reads):
/// run, it refuses the missing shards by name instead of failing with "Argument list too long".
#[test]
fn slurm_refuses_missing_paths_and_bad_outputs_and_merges_many_shards_from_a_list() {
    let tmp = tempfile::tempdir().unwrap();
    let file = configs().join("sweeps/karhula-pump-speed-sweep.toml");
    let slurm = |path: &Path, out: &Path, shards: &str| {
        run(&[
            "slurm".as_ref(),
            path.as_os_str(),
            "--shards".as_ref(),
            shards.as_ref(),
            "--out".as_ref(),
            out.as_os_str(),
        ])
    };
    let stderr = |o: &std::process::Output| String::from_utf8_lossy(&o.stderr).into_owned();

    let missing = tmp.path().join("no-such-cases");
    let out = tmp.path().join("a");
    let o = slurm(&missing, &out, "2");
    assert_eq!(o.status.code(), Some(1), "{o:?}");
    assert!(
        stderr(&o).contains("no-such-cases") && stderr(&o).contains("no such file or folder"),
        "{o:?}"
    );
    assert!(
        !tmp.path().join("a.slurm").exists(),
        "scripts written for a missing path"
    );

    let regular = tmp.path().join("results.txt");
    std::fs::write(&regular, "not a folder").unwrap();
    for bad_out in [regular.as_path(), Path::new("/dev/zero")] {
        let o = slurm(&file, bad_out, "2");
        assert_eq!(
            o.status.code(),
            Some(1),
            "--out {}: {o:?}",
            bad_out.display()
        );
        assert!(
            stderr(&o).contains(&*bad_out.to_string_lossy()) && stderr(&o).contains("not a folder"),
            "{o:?}"
        );
    }
    assert!(!tmp.path().join("results.txt.slurm").exists());

    let o = slurm(&file, &out, "4000001");
    assert_eq!(o.status.code(), Some(2), "{o:?}");

    let many = tmp.path().join("many");
    let o = slurm(&file, &many, "100000");
    assert!(o.status.success(), "{o:?}");
    let dir = tmp.path().join("many.slurm");
    let merge = std::fs::read_to_string(dir.join("merge.sbatch")).unwrap();
    assert!(merge.len() < 4096, "merge.sbatch of {} bytes", merge.len());
    let list = std::fs::read_to_string(dir.join("shards.txt")).unwrap();
    assert_eq!(list.lines().count(), 100_000);
    let merged = Command::new("bash")
        .arg(dir.join("merge.sbatch"))
        .output()
        .unwrap();
    let err = stderr(&merged);
    assert_eq!(merged.status.code(), Some(1), "{err}");
    assert!(!err.contains("Argument list too long"), "{err}");
    assert!(
        err.contains("shard-1") && err.contains("shard.json"),
        "{err}"
    );
    assert!(!many.exists(), "a refused merge wrote {}", many.display());
}

/// `cardan merge --out` that is one of its shards, inside one, or holding one (by another name
/// of the same folder too) is refused (exit 1), naming the shard, with the shards untouched.
#[test]
fn a_merge_into_its_own_shards_is_refused() {
    let tmp = tempfile::tempdir().unwrap();
    let files = [
        configs().join("karhula-pump-r60-l140-a0-w3pi.toml"),
        configs().join("karhula-r60-l140-a0-w3pi.toml"),
    ];
    assert!(files.iter().all(|f| f.is_file()));
    let root = tmp.path().join("shards");
    let shards: Vec<PathBuf> = (1..=2).map(|k| root.join(format!("s{k}"))).collect();
    for (k, dir) in shards.iter().enumerate() {
        let spec = format!("{}/2", k + 1);
        let out = run(&[
            "run".as_ref(),
            files[0].as_os_str(),
            files[1].as_os_str(),
            "--out".as_ref(),
            dir.as_os_str(),
            "--quiet".as_ref(),
            "--no-report".as_ref(),
            "--shard".as_ref(),
            spec.as_ref(),
        ]);
        assert!(out.status.success(), "{out:?}");
    }
    let before: Vec<_> = shards.iter().map(|s| tree(s)).collect();
    let other_name = root.join("s2/../s1");
    for (out, how) in [
        (shards[0].clone(), "is the shard"),
        (other_name, "is the shard"),
        (shards[1].join("merged"), "is inside the shard"),
        (root.clone(), "contains the shard"),
    ] {
        let said = merge(&[&shards[0], &shards[1]], &out);
        assert_eq!(said.status.code(), Some(1), "{}: {said:?}", out.display());
        let stderr = String::from_utf8_lossy(&said.stderr);
        assert!(
            stderr.contains(how) && stderr.contains("choose an --out"),
            "{}: {stderr}",
            out.display()
        );
        let after: Vec<_> = shards.iter().map(|s| tree(s)).collect();
        assert!(before == after, "{}: a shard changed", out.display());
        assert!(!shards[1].join("merged").exists());
    }
    // Beside the shards: merged.
    let said = merge(&[&shards[0], &shards[1]], &tmp.path().join("merged"));
    assert!(said.status.success(), "{said:?}");
}
