//! Every file the program reads, read through one bounded reader ([`read_limited`],
//! [`open_regular`]): a regular file only (a FIFO, a device such as `/dev/zero` or a folder is
//! refused before it is opened, so neither an endless read nor a blocked open), and no more
//! bytes than the [`Limit`] of its kind (issue 36). Its own crate, at the bottom: the case
//! reader, the reports, the runner and the command line all read through it.

use std::fs::File;
use std::io::Read;
use std::path::Path;

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

#[cfg(test)]
mod tests {
    use super::*;

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
