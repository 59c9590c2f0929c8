//! A model that cannot be set up for a mechanism: the case field at fault and why.

/// A stage that cannot be set up for a mechanism (a loss model, a gear pair): the case field at
/// fault and why.
#[derive(Debug, Clone, PartialEq)]
pub struct SetupError {
    pub field: String,
    pub rule: String,
}

impl std::fmt::Display for SetupError {
    fn fmt(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
        write!(f, "{}: {}", self.field, self.rule)
    }
}
