//! An output folder's files, each written whole: a file, a file replaced by a rename (a
//! reader sees the old or the new one), a case's folder made in a temporary folder beside it
//! and moved onto it as a whole, and the removal of the temporaries of runs that were killed.
//! The runner's results, the reports and the gear calculator's files are all written so.
//!
//! The bounded reader of every file the program reads is `cardan-files`'s, re-exported here
//! for the readers of output folders.

use anyhow::Context;
use std::fs::File;
use std::io::Write;
use std::path::{Path, PathBuf};

pub use cardan_files::{
    kind_of, open_regular, read_limited, read_text, Limit, CASE_FILE, DATA_TABLE, GEAR_FILE,
    PER_STEP_FILE, RESULT_RECORD,
};

/// Writes `contents` to `path`. No fsync: a case folder appears whole by a rename, and waiting
/// for the disk would cost more than the computation of a small case (10 000 pump cases of
/// 720 steps: 13.4 s with one fsync per case, 6.7 s without); durability across a power cut is not promised.
pub fn write_file(path: &Path, contents: &[u8]) -> anyhow::Result<()> {
    let mut f = File::create(path).with_context(|| format!("create {}", path.display()))?;
    f.write_all(contents)?;
    Ok(())
}

/// A fresh, empty temporary folder beside `dir`, to be moved onto it by [`replace_dir`].
pub fn temporary_dir(dir: &Path) -> anyhow::Result<PathBuf> {
    let parent = dir.parent().context("no parent folder")?;
    std::fs::create_dir_all(parent).with_context(|| format!("create {}", parent.display()))?;
    let name = dir.file_name().context("no folder name")?.to_string_lossy();
    let tmp = parent.join(format!(".{name}.tmp-{}", std::process::id()));
    if tmp.exists() {
        std::fs::remove_dir_all(&tmp)?;
    }
    std::fs::create_dir(&tmp).with_context(|| format!("create {}", tmp.display()))?;
    Ok(tmp)
}

/// Writes `contents` to `path` through a temporary file beside it that is then renamed onto
/// it: a reader sees the old file or the new one, never half of one, and a symbolic link at
/// `path` is replaced by the file, not followed.
pub fn write_file_replacing(path: &Path, contents: &[u8]) -> anyhow::Result<()> {
    let name = path.file_name().context("no file name")?.to_string_lossy();
    let tmp = path.with_file_name(format!(".{name}.tmp-{}", std::process::id()));
    write_file(&tmp, contents)?;
    std::fs::rename(&tmp, path).with_context(|| {
        let _ = std::fs::remove_file(&tmp);
        format!("rename to {}", path.display())
    })
}

/// Moves the finished folder `tmp` onto `dir`, replacing whatever was there as a whole. A
/// concurrent run replacing the same folder (moving it aside, or putting its own in place
/// between our two renames) is retried: the last run to finish wins, whole.
pub fn replace_dir(tmp: &Path, dir: &Path) -> anyhow::Result<()> {
    let name = dir.file_name().context("no folder name")?.to_string_lossy();
    let old = dir.with_file_name(format!(".{name}.old-{}", std::process::id()));
    for _ in 0..20 {
        if old.symlink_metadata().is_ok() {
            std::fs::remove_dir_all(&old).with_context(|| format!("remove {}", old.display()))?;
        }
        match std::fs::rename(dir, &old) {
            Ok(()) => {}
            // Nothing there, or another run has just moved it aside.
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => {}
            Err(e) => {
                return Err(e).with_context(|| format!("move {} aside", dir.display()));
            }
        }
        match std::fs::rename(tmp, dir) {
            Ok(()) => {
                if old.symlink_metadata().is_ok() {
                    std::fs::remove_dir_all(&old)
                        .with_context(|| format!("remove {}", old.display()))?;
                }
                return Ok(());
            }
            // Another run put its folder in place between the two renames (and may since
            // have moved it aside again): again, while ours is still there to move.
            Err(_) if tmp.is_dir() => continue,
            Err(e) => return Err(e).with_context(|| format!("rename to {}", dir.display())),
        }
    }
    anyhow::bail!(
        "another run keeps replacing {} at the same time; run one at a time on one output folder",
        dir.display()
    )
}

/// The process id in the name of a temporary entry this crate makes (`.NAME.tmp-PID`,
/// `.NAME.old-PID`), if `name` is one.
fn temporary_owner(name: &str) -> Option<u32> {
    let rest = name.strip_prefix('.')?;
    let (stem, pid) = rest.rsplit_once('-')?;
    if !(stem.ends_with(".tmp") || stem.ends_with(".old")) {
        return None;
    }
    pid.parse().ok()
}

/// Whether process `pid` is alive; `None` where this cannot be told (no `/proc`).
fn alive(pid: u32) -> Option<bool> {
    if !Path::new("/proc/self").exists() {
        return None;
    }
    Some(Path::new("/proc").join(pid.to_string()).exists())
}

/// The temporary folders and files (`.NAME.tmp-PID`, `.NAME.old-PID`) in `dir` left by runs
/// that ended without cleaning up (killed): those whose process is no longer alive, with
/// that process's id. Those of a live process (another run at work) are not listed, nor is
/// anything where the liveness of a process cannot be told.
pub fn stale_temporaries(dir: &Path) -> Vec<(PathBuf, u32)> {
    let Ok(entries) = std::fs::read_dir(dir) else {
        return Vec::new();
    };
    let mut stale: Vec<(PathBuf, u32)> = entries
        .flatten()
        .filter_map(|entry| {
            let pid = temporary_owner(&entry.file_name().to_string_lossy())?;
            (pid != std::process::id() && alive(pid) == Some(false)).then(|| (entry.path(), pid))
        })
        .collect();
    stale.sort();
    stale
}

/// Removes from `dir` the [`stale_temporaries`] of runs that ended without cleaning up.
/// Returns what was removed.
pub fn remove_stale_temporaries(dir: &Path) -> Vec<PathBuf> {
    let mut removed = Vec::new();
    for (path, pid) in stale_temporaries(dir) {
        let gone = match path.symlink_metadata() {
            Ok(t) if t.is_dir() => std::fs::remove_dir_all(&path),
            _ => std::fs::remove_file(&path),
        };
        match gone {
            Ok(()) => {
                tracing::info!(path = %path.display(), pid, "removed the leftover of an ended run");
                removed.push(path);
            }
            Err(e) => {
                tracing::warn!(path = %path.display(), "cannot remove the leftover of an ended run: {e}")
            }
        }
    }
    removed
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn temporary_names_are_told_apart() {
        assert_eq!(temporary_owner(".k.tmp-123"), Some(123));
        assert_eq!(temporary_owner(".my-case.old-9"), Some(9));
        assert_eq!(temporary_owner(".index.html.tmp-77"), Some(77));
        assert_eq!(temporary_owner("k.tmp-123"), None);
        assert_eq!(temporary_owner(".k-123"), None);
        assert_eq!(temporary_owner(".k.tmp-x"), None);
    }
}
