//! A failed run: its error and the results kept up to it.

use std::fmt;

use super::Results;
use crate::error::SimulationError;

/// A run that stopped early: the error, and everything computed until then.
#[derive(Debug, Clone)]
pub struct SimulationFailure {
    /// Why it stopped.
    pub error: SimulationError,
    /// The results up to the failure.
    pub results: Results,
}

impl fmt::Display for SimulationFailure {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{} ({} samples kept)", self.error, self.results.len())
    }
}

impl std::error::Error for SimulationFailure {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        Some(&self.error)
    }
}
