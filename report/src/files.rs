//! An output folder's files, each written whole: a file, a file replaced by a rename (a
//! reader sees the old or the new one), a case's folder made in a temporary folder beside it
//! and moved onto it as a whole, and the removal of the temporaries of runs that were killed.
//! The runner's results, the reports and the gear calculator's files are all written so.
//!
//! And every file the program reads, read through one bounded reader ([`read_limited`],
//! [`open_regular`]): a regular file only (a FIFO, a device such as `/dev/zero` or a folder
//! is refused before it is opened, so neither an endless read nor a blocked open), and no
//! more bytes than the [`Limit`] of its kind.

use anyhow::Context;
use std::fs::File;
use std::io::{Read, Write};
use std::path::{Path, PathBuf};

/// What kind of file a read is, and the most bytes a file of that kind may hold. The caps are
/// far above any file the program is meant to read and far below the memory of a machine
/// that runs it: they stop a mistaken path (a log, a disk image, a file still growing) from
/// taking the machine's memory.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Limit {
    /// The kind, as a message says it: "a case file".
    pub what: &'static str,
    /// The most bytes it may hold.
    pub bytes: u64,
}

/// A case file (TOML written by hand or by a script): 16 MiB. The shipped ones are a few
/// kB; the largest a sweep's lists of values make stays far below.
pub const CASE_FILE: Limit = Limit {
    what: "a case file",
    bytes: 16 << 20,
};

/// A gear file of `cardan gear` (TOML): 16 MiB, as a case file.
pub const GEAR_FILE: Limit = Limit {
    what: "a gear file",
    bytes: 16 << 20,
};

/// A measured table a case reads (a pressure trace's CSV): 256 MiB. A trace at 0.01° over
/// 720° is 72 000 rows, about 2 MB; the cap leaves room for a recorder's export of many
/// cycles at a fine resolution.
pub const DATA_TABLE: Limit = Limit {
    what: "a data table",
    bytes: 256 << 20,
};

/// A record the program wrote into an output folder and reads back (`summary.json`,
/// `run.json`, `shard.json`, a table's `sweep.json`, `sweep.csv`): 1 GiB. The largest is a
/// `sweep.csv` of a sweep's 100 000 point folders (`MAX_EXPANDED`) with some hundred metric
/// columns of at most 24 bytes each, about 700 MB.
pub const RESULT_RECORD: Limit = Limit {
    what: "a result record",
    bytes: 1 << 30,
};

/// A per-step file read back (a mechanism's CSV, a table's NPY columns): no cap beyond
/// the file system's. The run wrote it under its own size limit (10 GB, `--allow-large`
/// lifts it); the reader streams or keeps only the columns it needs. Still a regular file.
pub const PER_STEP_FILE: Limit = Limit {
    what: "a per-step file",
    bytes: u64::MAX,
};

/// What the file system entry of `meta` is, as a message says it: "a FIFO", "a folder".
pub fn kind_of(meta: &std::fs::Metadata) -> &'static str {
    let t = meta.file_type();
    if t.is_file() {
        return "a regular file";
    }
    if t.is_dir() {
        return "a folder";
    }
    #[cfg(unix)]
    {
        use std::os::unix::fs::FileTypeExt;
        if t.is_fifo() {
            return "a FIFO";
        }
        if t.is_char_device() {
            return "a character device";
        }
        if t.is_block_device() {
            return "a block device";
        }
        if t.is_socket() {
            return "a socket";
        }
    }
    "not a file"
}

/// The error of a read refused: `kind` InvalidInput, `why` its message.
fn refused(why: String) -> std::io::Error {
    std::io::Error::new(std::io::ErrorKind::InvalidInput, why)
}

/// The cap `limit` as a message says it: "16 MiB".
fn cap_text(limit: Limit) -> String {
    match limit.bytes {
        b if b >= 1 << 30 && b % (1 << 30) == 0 => format!("{} GiB", b >> 30),
        b if b >= 1 << 20 && b % (1 << 20) == 0 => format!("{} MiB", b >> 20),
        b => format!("{b} bytes"),
    }
}

/// Opens `path` for reading if it is a regular file (symbolic links followed) of at most
/// `limit.bytes`; otherwise an error that says why ("not a regular file (a FIFO)", "larger
/// than the 16 MiB limit for a case file"), the file's name left to the caller. The kind is
/// looked at before opening (opening a FIFO would wait for a writer), and again on the file
/// opened, which is opened without blocking (a FIFO put in its place meanwhile is refused,
/// not waited on). A missing file keeps the system's error (`NotFound`).
pub fn open_regular(path: &Path, limit: Limit) -> std::io::Result<File> {
    let check = |meta: &std::fs::Metadata| -> std::io::Result<()> {
        if !meta.is_file() {
            return Err(refused(format!("not a regular file ({})", kind_of(meta))));
        }
        if meta.len() > limit.bytes {
            return Err(too_large(limit));
        }
        Ok(())
    };
    check(&std::fs::metadata(path)?)?;
    let mut options = std::fs::OpenOptions::new();
    options.read(true);
    #[cfg(unix)]
    {
        use std::os::unix::fs::OpenOptionsExt;
        options.custom_flags(libc::O_NONBLOCK);
    }
    let file = options.open(path)?;
    check(&file.metadata()?)?;
    Ok(file)
}

/// The error of a file larger than `limit`.
fn too_large(limit: Limit) -> std::io::Error {
    refused(format!(
        "larger than the {} limit for {}",
        cap_text(limit),
        limit.what
    ))
}

/// The bytes of the regular file `path`, at most `limit.bytes` of them ([`open_regular`]).
/// Read with a cap of one byte more than the limit, so a file that grows while it is read is
/// refused too.
pub fn read_limited(path: &Path, limit: Limit) -> std::io::Result<Vec<u8>> {
    let file = open_regular(path, limit)?;
    let hint = file.metadata().map_or(0, |m| m.len());
    let mut bytes = Vec::with_capacity(hint.min(limit.bytes) as usize);
    file.take(limit.bytes.saturating_add(1))
        .read_to_end(&mut bytes)?;
    if bytes.len() as u64 > limit.bytes {
        return Err(too_large(limit));
    }
    Ok(bytes)
}

/// The text of the regular file `path` ([`read_limited`]), which must be UTF-8.
pub fn read_text(path: &Path, limit: Limit) -> std::io::Result<String> {
    String::from_utf8(read_limited(path, limit)?).map_err(|_| {
        std::io::Error::new(
            std::io::ErrorKind::InvalidData,
            "stream did not contain valid UTF-8",
        )
    })
}

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

    #[test]
    fn reads_are_bounded_and_regular_files_only() {
        let dir = std::env::temp_dir().join(format!("cardan-files-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let limit = Limit {
            what: "a test file",
            bytes: 8,
        };
        let file = dir.join("eight");
        std::fs::write(&file, b"12345678").unwrap();
        assert_eq!(read_limited(&file, limit).unwrap(), b"12345678");
        std::fs::write(&file, b"123456789").unwrap();
        let e = read_limited(&file, limit).unwrap_err().to_string();
        assert_eq!(e, "larger than the 8 bytes limit for a test file");
        let e = read_text(Path::new("/dev/zero"), limit).unwrap_err();
        assert_eq!(e.to_string(), "not a regular file (a character device)");
        let e = read_text(&dir, limit).unwrap_err();
        assert_eq!(e.to_string(), "not a regular file (a folder)");
        let e = read_text(&dir.join("missing"), limit).unwrap_err();
        assert_eq!(e.kind(), std::io::ErrorKind::NotFound);
        assert_eq!(cap_text(CASE_FILE), "16 MiB");
        assert_eq!(cap_text(RESULT_RECORD), "1 GiB");
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
