//! The `cardan` command's own parts: the gear file format of `cardan gear` (the runner keeps
//! case files, scheduling and outputs).

pub mod gear_file;
