//! The thread that writes a crank train's per-step files: the run's thread copies rows into a
//! block ([`Writer`]), a thread of the writer's own formats and writes the blocks into the
//! files ([`Files`]: CSV and/or NPY).

use super::csv::CsvFile;
use super::npy::NpyFile;
use anyhow::Context;
use cardan_case::case::OutputOptions;
use cardan_report::files::write_file;
use std::path::Path;
use std::sync::mpsc::{sync_channel, Receiver, SyncSender};
use std::thread::JoinHandle;

/// Rows per block handed to the writing thread: large enough that the hand-over is rare, small
/// enough that a block (rows × columns × 8 bytes, about 0.5 MB for a cardan gear with every
/// family) stays in the caches.
pub(super) const BLOCK_ROWS: usize = 512;

/// The per-step files of one crank train: the run's thread copies rows into a block, a thread
/// of the writer's own formats and writes the blocks.
pub(super) struct Writer {
    /// The rows of the block being filled, one after the other.
    pub(super) block: Vec<f64>,
    pub(super) columns: usize,
    to_writer: Option<SyncSender<Vec<f64>>>,
    /// Blocks the writer is done with, for reuse.
    spare: Receiver<Vec<f64>>,
    writer: Option<JoinHandle<anyhow::Result<()>>>,
}

impl Writer {
    /// Creates the files `options` asks for in `dir`, named by `label`, for `rows` rows of
    /// `header`, and starts their thread.
    pub(super) fn start(
        dir: &Path,
        label: &str,
        header: &[String],
        rows: usize,
        options: OutputOptions,
    ) -> anyhow::Result<Self> {
        let csv = if options.csv {
            Some(CsvFile::create(
                &dir.join(format!("{label}.csv")),
                header,
                options.significant_digits,
            )?)
        } else {
            None
        };
        let npy = if options.npy {
            let names = dir.join(format!("{label}.columns.json"));
            let json = serde_json::to_string(header)? + "\n";
            write_file(&names, json.as_bytes())?;
            Some(NpyFile::create(
                &dir.join(format!("{label}.npy")),
                rows,
                header.len(),
            )?)
        } else {
            None
        };
        let columns = header.len();
        let (to_writer, blocks) = sync_channel::<Vec<f64>>(2);
        let (give_back, spare) = sync_channel::<Vec<f64>>(3);
        let writer = std::thread::Builder::new()
            .name(format!("{label} writer"))
            .spawn(move || {
                let mut files = Files { csv, npy, columns };
                for block in blocks {
                    files.write(&block)?;
                    // The run may have finished and stopped taking blocks back.
                    let _ = give_back.try_send(block);
                }
                files.finish(rows)
            })
            .context("start the thread writing the per-step files")?;
        Ok(Self {
            block: Vec::with_capacity(BLOCK_ROWS * columns),
            columns,
            to_writer: Some(to_writer),
            spare,
            writer: Some(writer),
        })
    }

    /// Hands the filled rows to the writer.
    pub(super) fn send(&mut self) -> Result<(), String> {
        let next = self
            .spare
            .try_recv()
            .unwrap_or_else(|_| Vec::with_capacity(BLOCK_ROWS * self.columns));
        let block = std::mem::replace(&mut self.block, next);
        self.block.clear();
        let sent = self.to_writer.as_ref().map(|w| w.send(block));
        match sent {
            Some(Ok(())) => Ok(()),
            // The writer stopped: its error says why.
            _ => Err(self
                .join()
                .err()
                .unwrap_or_else(|| "the writer stopped".into())),
        }
    }

    /// Waits for the writer to write everything it was given.
    fn join(&mut self) -> Result<(), String> {
        self.to_writer = None;
        match self.writer.take().map(JoinHandle::join) {
            Some(Ok(Ok(()))) | None => Ok(()),
            Some(Ok(Err(e))) => Err(format!("{e:#}")),
            Some(Err(_)) => Err("the thread writing the per-step files panicked".into()),
        }
    }

    /// Writes out the last rows and waits until every file is complete.
    pub(super) fn finish(mut self) -> anyhow::Result<()> {
        if !self.block.is_empty() {
            self.send().map_err(anyhow::Error::msg)?;
        }
        self.join().map_err(anyhow::Error::msg)
    }
}

impl Drop for Writer {
    /// A run that stopped early (an error) still stops its writer; the files are left
    /// incomplete in the case's temporary folder, which is then removed.
    fn drop(&mut self) {
        let _ = self.join();
    }
}

/// The files the writing thread fills.
struct Files {
    csv: Option<CsvFile>,
    npy: Option<NpyFile>,
    columns: usize,
}

impl Files {
    fn write(&mut self, block: &[f64]) -> anyhow::Result<()> {
        if let Some(c) = &mut self.csv {
            c.write(block, self.columns)?;
        }
        if let Some(n) = &mut self.npy {
            n.write(block)?;
        }
        Ok(())
    }

    fn finish(self, rows: usize) -> anyhow::Result<()> {
        if let Some(c) = self.csv {
            c.finish()?;
        }
        if let Some(n) = self.npy {
            n.finish(rows)?;
        }
        Ok(())
    }
}
