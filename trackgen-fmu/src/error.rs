//! What an FMU call can refuse or fail with; each becomes a status and a
//! message through the master's logger.

use thiserror::Error;

/// A refused call or a failed step.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum FmuError {
    /// A value out of its range, or of the wrong kind for its variable.
    #[error("{name} = {value}: {why}")]
    Parameter {
        /// The variable's name.
        name: String,
        /// The value given, as text.
        value: String,
        /// Its range, or why it was refused.
        why: String,
    },
    /// No variable has this value reference, or it is not of this type.
    #[error("no {kind} variable has value reference {value_reference}")]
    ValueReference {
        /// The reference given.
        value_reference: u32,
        /// The type asked for.
        kind: &'static str,
    },
    /// A call not allowed in the instance's state (FMI's state machine).
    #[error("{call} is not allowed {state}")]
    State {
        /// The function called.
        call: &'static str,
        /// The instance's state, in words.
        state: &'static str,
    },
    /// The vehicle could not be built from the parameters.
    #[error("the vehicle cannot be built: {0}")]
    Build(String),
    /// The communication step asked for is not the one the instance can
    /// take.
    #[error("{0}")]
    Step(String),
    /// The run failed: the time and the cause. The outputs stay those of
    /// the last communication point reached.
    #[error("the run failed: {0}")]
    Run(String),
    /// A panic inside the FMU, caught at its boundary.
    #[error("internal error (a panic, caught): {0}")]
    Panic(String),
}
