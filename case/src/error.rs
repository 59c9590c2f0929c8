//! What a case file's reading can go wrong with, and the machine kind every table's reader
//! needs: the bottom of the case crate, imported by every reader and importing none.

use schemars::JsonSchema;
use serde::Deserialize;
use std::path::PathBuf;

/// Why a case file could not become a case.
#[derive(Debug, thiserror::Error)]
pub enum CaseError {
    #[error("{file}: cannot read: {source}")]
    Io {
        file: PathBuf,
        source: std::io::Error,
    },
    /// TOML syntax, a missing field, an unknown key or a value of the wrong type; the message
    /// is the TOML reader's, with the line and column.
    #[error("{file}: {message}")]
    Syntax { file: PathBuf, message: String },
    /// A field of the typed schema that did not read: its path and what is wrong with it.
    #[error("{file}: case \"{case}\": {error}")]
    Field {
        file: PathBuf,
        case: String,
        error: crate::schema::FieldError,
    },
    #[error("{file}: case \"{case}\": {field} = {value}: {rule}")]
    Invalid {
        file: PathBuf,
        case: String,
        field: String,
        value: String,
        rule: String,
    },
}

/// Pump or engine: what the gas does (used by the gas models).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize, JsonSchema, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Machine {
    Pump,
    Engine,
}

impl Machine {
    pub fn name(self) -> &'static str {
        match self {
            Machine::Pump => "pump",
            Machine::Engine => "engine",
        }
    }
}

/// Reports a broken rule: the field, its value, the rule.
pub(crate) type Invalid<'a> = dyn Fn(&str, &dyn std::fmt::Display, &str) -> CaseError + 'a;
