//! A per-step NPY file (NPY 1.0, `<f8`, Fortran order), written block by block in place
//! ([`NpyFile`]), and its preamble ([`npy_header`]).

use anyhow::{bail, Context};
use std::fs::File;
use std::io::{Seek, SeekFrom, Write};
use std::path::{Path, PathBuf};

/// An NPY 1.0 file of a rows × columns array of little-endian f64 in Fortran order (column
/// after column), written block by block in place: column `c`'s rows `r0..` start at byte
/// `header + 8·(c·rows + r0)`.
pub(super) struct NpyFile {
    path: PathBuf,
    file: File,
    rows: usize,
    columns: usize,
    header: u64,
    /// Rows written so far.
    written: usize,
    bytes: Vec<u8>,
}

/// The NPY 1.0 preamble for a `rows` × `columns` f64 array in Fortran order: magic, version,
/// header length, the header dictionary padded with spaces to a multiple of 64 bytes and ended
/// by a newline (NumPy's `numpy.lib.format`).
pub fn npy_header(rows: usize, columns: usize) -> Vec<u8> {
    let dict = format!("{{'descr': '<f8', 'fortran_order': True, 'shape': ({rows}, {columns}), }}");
    let unpadded = 10 + dict.len() + 1;
    let len = unpadded.div_ceil(64) * 64;
    let mut h = b"\x93NUMPY\x01\x00".to_vec();
    h.extend_from_slice(&((len - 10) as u16).to_le_bytes());
    h.extend_from_slice(dict.as_bytes());
    h.resize(len - 1, b' ');
    h.push(b'\n');
    h
}

impl NpyFile {
    pub(super) fn create(path: &Path, rows: usize, columns: usize) -> anyhow::Result<Self> {
        let mut file = File::create(path).with_context(|| format!("create {}", path.display()))?;
        let header = npy_header(rows, columns);
        file.write_all(&header)?;
        let size = header.len() as u64 + 8 * (rows as u64) * (columns as u64);
        file.set_len(size)
            .with_context(|| format!("size {} to {size} bytes", path.display()))?;
        Ok(Self {
            path: path.to_path_buf(),
            file,
            rows,
            columns,
            header: header.len() as u64,
            written: 0,
            bytes: Vec::new(),
        })
    }

    pub(super) fn write(&mut self, block: &[f64]) -> anyhow::Result<()> {
        let n = block.len() / self.columns;
        if self.written + n > self.rows {
            bail!(
                "{}: more rows than the {} announced",
                self.path.display(),
                self.rows
            );
        }
        for c in 0..self.columns {
            self.bytes.clear();
            for row in block.chunks_exact(self.columns) {
                self.bytes.extend_from_slice(&row[c].to_le_bytes());
            }
            let at = self.header + 8 * (c * self.rows + self.written) as u64;
            self.file.seek(SeekFrom::Start(at))?;
            self.file
                .write_all(&self.bytes)
                .with_context(|| format!("write {}", self.path.display()))?;
        }
        self.written += n;
        Ok(())
    }

    pub(super) fn finish(self, rows: usize) -> anyhow::Result<()> {
        if self.written != rows {
            bail!(
                "{}: {} rows written of the {rows} announced",
                self.path.display(),
                self.written
            );
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn npy_header_is_aligned_and_names_the_shape() {
        for (r, c) in [(1, 1), (7201, 143), (10_000_001, 999)] {
            let h = npy_header(r, c);
            assert_eq!(h.len() % 64, 0);
            assert_eq!(&h[..8], b"\x93NUMPY\x01\x00");
            assert_eq!(u16::from_le_bytes([h[8], h[9]]) as usize, h.len() - 10);
            assert_eq!(*h.last().unwrap(), b'\n');
            let text = std::str::from_utf8(&h[10..]).unwrap();
            assert!(text.contains(&format!("'shape': ({r}, {c})")), "{text}");
            assert!(text.contains("'fortran_order': True"));
        }
    }
}
