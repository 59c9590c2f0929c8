//! A per-step CSV file, written block by block ([`CsvFile`]).

use anyhow::Context;
use std::fs::File;
use std::io::{BufWriter, Write};
use std::path::{Path, PathBuf};

/// CSV text: numbers only, no quoting; a NaN (a quantity undefined at the step) is an empty
/// cell; each number the shortest text that reads back to it (zmij), or rounded to
/// `significant_digits`.
pub(super) struct CsvFile {
    path: PathBuf,
    out: BufWriter<File>,
    significant_digits: Option<usize>,
    line: Vec<u8>,
}

impl CsvFile {
    pub(super) fn create(
        path: &Path,
        header: &[String],
        significant_digits: Option<usize>,
    ) -> anyhow::Result<Self> {
        let file = File::create(path).with_context(|| format!("create {}", path.display()))?;
        let mut out = BufWriter::with_capacity(1 << 18, file);
        writeln!(out, "{}", header.join(","))?;
        Ok(Self {
            path: path.to_path_buf(),
            out,
            significant_digits,
            line: Vec::new(),
        })
    }

    pub(super) fn write(&mut self, block: &[f64], columns: usize) -> anyhow::Result<()> {
        let mut buffer = zmij::Buffer::new();
        for row in block.chunks_exact(columns) {
            self.line.clear();
            for (k, &v) in row.iter().enumerate() {
                if k > 0 {
                    self.line.push(b',');
                }
                if v.is_nan() {
                    continue;
                }
                match self.significant_digits {
                    Some(d) => write!(self.line, "{:.*e}", d - 1, v)?,
                    None => self.line.extend_from_slice(buffer.format(v).as_bytes()),
                }
            }
            self.line.push(b'\n');
            self.out
                .write_all(&self.line)
                .with_context(|| format!("write {}", self.path.display()))?;
        }
        Ok(())
    }

    pub(super) fn finish(mut self) -> anyhow::Result<()> {
        self.out
            .flush()
            .with_context(|| format!("write {}", self.path.display()))
    }
}
