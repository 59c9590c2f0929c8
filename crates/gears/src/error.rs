//! The crate's error type.

use thiserror::Error;

/// Everything that can go wrong in this crate. Nothing here panics on bad input: constructors
/// and rating functions return one of these instead.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum GearError {
    /// An input violates a rule of the model (field name, the rule, the offending value).
    #[error("invalid input `{field}` = {value}: {rule}")]
    InvalidInput {
        /// Name of the offending field or argument.
        field: &'static str,
        /// The rule it breaks.
        rule: &'static str,
        /// The value given.
        value: f64,
    },
    /// An iterative solution did not converge.
    #[error("{what} did not converge")]
    NoConvergence {
        /// What was being solved.
        what: &'static str,
    },
    /// A table look-up fell outside the tabulated range or hit an illegible cell.
    #[error("table look-up failed: {0}")]
    OutsideTable(String),
    /// A design requirement cannot be met within the model's range of validity.
    #[error("requirement cannot be met: {0}")]
    Unreachable(String),
    /// One or more geometry checks failed; the text lists each failure with its remedy.
    #[error("gear pair checks failed:\n{0}")]
    ChecksFailed(String),
}

/// Returns `InvalidInput` unless `ok` holds.
pub(crate) fn require(
    ok: bool,
    field: &'static str,
    rule: &'static str,
    value: f64,
) -> Result<(), GearError> {
    if ok {
        Ok(())
    } else {
        Err(GearError::InvalidInput { field, rule, value })
    }
}

/// Requires a finite, strictly positive value.
pub(crate) fn positive(field: &'static str, value: f64) -> Result<(), GearError> {
    require(
        value.is_finite() && value > 0.0,
        field,
        "must be finite and > 0",
        value,
    )
}

/// Requires a finite, non-negative value.
pub(crate) fn non_negative(field: &'static str, value: f64) -> Result<(), GearError> {
    require(
        value.is_finite() && value >= 0.0,
        field,
        "must be finite and >= 0",
        value,
    )
}

/// Requires a finite value.
pub(crate) fn finite(field: &'static str, value: f64) -> Result<(), GearError> {
    require(value.is_finite(), field, "must be finite", value)
}
