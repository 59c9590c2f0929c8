//! Case files: TOML in, validated [`Case`]s out. Units are converted once, here
//! ([`units`]); `[gas]`, `[friction]` and `[gear]` are read by their own modules; a `[sweep]`
//! is expanded into one case per point ([`sweep`]). The runner schedules the cases and writes
//! their results; nothing here steps a machine.

pub mod balance;
pub mod case;
pub mod digest;
pub mod error;
pub mod friction;
pub mod gas;
pub mod gear;
mod gear_speed;
mod input_field;
pub mod json_schema;
pub mod machine_motion;
pub mod masses;
pub mod mechanism_table;
pub mod optimize;
mod output_metrics;
pub mod plausible;
pub mod quantity;
pub mod read_once;
pub mod schema;
pub mod setup;
pub mod stage_registry;
pub mod sweep;
pub mod units;
mod unread;

pub use case::Case;
pub use error::{CaseError, Machine};
