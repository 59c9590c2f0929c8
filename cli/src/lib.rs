//! The `cardan` command's own parts: the gear file format of `cardan gear` (the runner keeps
//! case files, scheduling and outputs), and the Slurm job scripts of `cardan slurm`.

pub mod gear_file;
pub mod slurm;
