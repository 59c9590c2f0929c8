//! The files a case file's cases read (a pressure trace), read and parsed once for all of
//! them: the points of a sweep share one parsed copy instead of each reading and holding its
//! own (issue 36.10: 8 points of a large trace took 1.56 GB against 0.41 GB for one, and the
//! time of 8 reads). A memo travels with the case file's reading (a [`crate::sweep::Sweep`]
//! holds one for its points); there is no global cache. It holds the gear pairs' bending
//! geometry factors computed from the tooth form too ([`cardan_gears::BendingJMemo`]): a
//! sweep over the speed or the rod length searches its pair's tooth roots once, not at every
//! point (issue 37: 4 % of a table point's time).

use std::any::Any;
use std::collections::HashMap;
use std::path::{Path, PathBuf};
use std::sync::{Arc, Mutex};

/// One file read and parsed: the digest of its bytes (for the input hash) and what its
/// reader made of them.
type Entry = (String, Arc<dyn Any + Send + Sync>);

/// The files read so far, by path and by what they were parsed as, and the bending geometry
/// factors computed so far.
#[derive(Default, Clone)]
pub struct ReadOnce {
    read: Arc<Mutex<HashMap<(PathBuf, String), Entry>>>,
    bending_j: Arc<cardan_gears::BendingJMemo>,
}

impl std::fmt::Debug for ReadOnce {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let count = self.read.lock().map_or(0, |m| m.len());
        write!(f, "ReadOnce({count} files)")
    }
}

impl ReadOnce {
    /// The gear pairs' bending geometry factors computed from the tooth form so far.
    pub(crate) fn bending_j(&self) -> &cardan_gears::BendingJMemo {
        &self.bending_j
    }

    /// The file `path` parsed as `kind` (a parse that depends on the case, such as a trace's
    /// cycle, says it in `kind`), with the digest of its bytes: read by `read` (bytes, digest
    /// and parsed value, or the error) the first time, the kept value after. A failed read is
    /// not kept: each case that reads the file reports it.
    pub fn get<T: Any + Send + Sync, E>(
        &self,
        path: &Path,
        kind: &str,
        read: impl FnOnce() -> Result<(String, T), E>,
    ) -> Result<(String, Arc<T>), E> {
        // Held while reading: the points of a sweep on other threads wait for the one read
        // instead of each starting its own.
        let mut read_files = self.read.lock().unwrap_or_else(|e| e.into_inner());
        let key = (path.to_path_buf(), kind.to_string());
        if let Some((digest, value)) = read_files.get(&key) {
            if let Ok(value) = Arc::clone(value).downcast::<T>() {
                return Ok((digest.clone(), value));
            }
        }
        let (digest, value) = read()?;
        let value = Arc::new(value);
        read_files.insert(key, (digest.clone(), value.clone()));
        Ok((digest, value))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_file_is_read_once_per_kind_and_a_failure_is_not_kept() {
        let memo = ReadOnce::default();
        let reads = std::cell::Cell::new(0);
        let read = |v: u32| {
            reads.set(reads.get() + 1);
            Ok::<_, ()>(("d".to_string(), v))
        };
        let path = Path::new("trace.csv");
        assert_eq!(*memo.get(path, "360", || read(1)).unwrap().1, 1);
        assert_eq!(*memo.get(path, "360", || read(2)).unwrap().1, 1);
        assert_eq!(*memo.get(path, "720", || read(3)).unwrap().1, 3);
        assert_eq!(reads.get(), 2);
        let other = Path::new("other.csv");
        assert!(memo.get::<u32, _>(other, "360", || Err("no")).is_err());
        assert_eq!(*memo.get(other, "360", || read(4)).unwrap().1, 4);
    }
}
