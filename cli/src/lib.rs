//! The `cardan` command's own parts: the Slurm job scripts of `cardan slurm`. The gear file
//! format of `cardan gear` is the crate `cardan-gear-file` (the Python package reads gear files
//! through it without building the command); the runner keeps case files, scheduling and outputs.

pub mod slurm;
