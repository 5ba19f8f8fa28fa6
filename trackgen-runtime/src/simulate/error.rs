//! A failed run: its error and what it kept up to it (the results, or a
//! streamed run's report).

use std::fmt;

use thiserror::Error;

use super::{Results, SinkError};
use crate::integrate::SimulationError;

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

/// Why a streamed run stopped early.
#[derive(Debug, Error)]
pub enum RunError {
    /// The simulation failed (the same errors as [`simulate`](super::simulate)).
    #[error(transparent)]
    Simulation(#[from] SimulationError),
    /// The sink refused a row, or could not be written to.
    #[error("writing the results failed at t = {t} s: {source}")]
    Sink {
        /// The time of the row, s (the start for `begin`, the last row's
        /// time for `finish`).
        t: f64,
        /// The sink's error.
        source: SinkError,
    },
}

impl RunError {
    /// The simulation time at which it happened (`None` for a set-up
    /// error).
    pub fn time(&self) -> Option<f64> {
        match self {
            RunError::Simulation(e) => e.time(),
            RunError::Sink { t, .. } => Some(*t),
        }
    }
}
