//! Why a simulation stopped early, and run settings that make no run: the
//! errors of the time layer. A failure of a lower layer (the dynamics, the
//! loop's recovery) is wrapped with the time it happened at.

use thiserror::Error;

use crate::closure::RecoveryError;
use crate::multibody::DynamicsError;

/// Why a simulation stopped early. Every variant carries the simulation
/// time `t` (s) at which it happened.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum SimulationError {
    /// A state or derivative component became NaN or infinite.
    #[error("non-finite value in {what} at t = {t} s")]
    NonFinite {
        /// Time, s.
        t: f64,
        /// Which quantity.
        what: &'static str,
    },
    /// A recorded quantity came out NaN or infinite from a finite state
    /// (forces that overflow on an absurd terrain, a singular solve): the
    /// results hold numbers only, so the run stops with the rows so far.
    #[error("non-finite value of the recorded `{column}` at t = {t} s")]
    NonFiniteRecord {
        /// Time, s.
        t: f64,
        /// The column's name.
        column: String,
    },
    /// The adaptive integrator's step fell below what `t` can resolve.
    #[error("step size underflow at t = {t} s (step {step:e} s){}", cause.as_ref().map(|c| format!(": {c}")).unwrap_or_default())]
    StepSizeUnderflow {
        /// Time, s.
        t: f64,
        /// The step that was too small, s.
        step: f64,
        /// The failure that kept shrinking the step, if any.
        cause: Option<Box<SimulationError>>,
    },
    /// A linear system of the method was singular.
    #[error("singular matrix ({what}) at t = {t} s")]
    SingularMatrix {
        /// Time, s.
        t: f64,
        /// Which matrix.
        what: &'static str,
    },
    /// The loop's dependent coordinates could not be recovered
    /// ([`RecoveryError`]).
    #[error(transparent)]
    Recovery(#[from] RecoveryError),
    /// Forward dynamics failed.
    #[error("dynamics failed at t = {t} s: {source}")]
    Dynamics {
        /// Time, s.
        t: f64,
        /// The failure.
        source: DynamicsError,
    },
    /// A state handed to a system had the wrong number of values (a
    /// programming error of the caller).
    #[error("a state of {got} values for a system of {expected} at t = {t} s")]
    StateLength {
        /// Time, s.
        t: f64,
        /// Values given.
        got: usize,
        /// The system's dimension.
        expected: usize,
    },
    /// A system recorded a row of the wrong width (a programming error of
    /// its [`Simulated::observe`](crate::system::Simulated::observe)).
    #[error("the system recorded {got} values at t = {t} s for its {expected} columns")]
    RecordWidth {
        /// Time, s.
        t: f64,
        /// Values recorded.
        got: usize,
        /// Columns named.
        expected: usize,
    },
    /// The system stopped the run for a reason of its own (a condition a
    /// user-defined [`OdeSystem`](crate::integrate::OdeSystem) watches).
    #[error("the system stopped the run at t = {t} s: {reason}")]
    Stopped {
        /// Time, s.
        t: f64,
        /// Why, in words.
        reason: &'static str,
    },
    /// The run's settings make no run (before any step).
    #[error("invalid run settings: {0}")]
    Settings(#[from] SettingsError),
}

/// Run settings that would hang a run or make it meaningless.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum SettingsError {
    /// The interval is not from a finite start to a later finite end.
    #[error("the run must go from a finite t0 to a later finite t_end, got {t0} to {t_end}")]
    Interval {
        /// Start, s.
        t0: f64,
        /// End, s.
        t_end: f64,
    },
    /// A fixed step that is not finite and positive (or too small to
    /// advance t).
    #[error("the step must be finite and positive, got {step}")]
    Step {
        /// The step, s.
        step: f64,
    },
    /// Tolerances negative, not finite, or both zero.
    #[error(
        "tolerances must be non-negative, finite and not both zero, got rtol {rtol}, atol {atol}"
    )]
    Tolerances {
        /// Relative tolerance.
        rtol: f64,
        /// Absolute tolerance.
        atol: f64,
    },
    /// One of [`Integrator::Auto`](crate::integrate::Integrator::Auto)'s
    /// tolerances not positive and finite (each is its method's relative
    /// and absolute tolerance at once, so zero leaves nothing).
    #[error(
        "{name} must be positive and finite (it is its method's rtol and atol at once), got {value}"
    )]
    Tolerance {
        /// Which: `explicit_tolerance` or `implicit_tolerance`.
        name: &'static str,
        /// What was given.
        value: f64,
    },
    /// A largest step that is not positive.
    #[error("max_step must be positive, got {max_step}")]
    MaxStep {
        /// The largest step, s.
        max_step: f64,
    },
    /// An output interval that is not finite and positive.
    #[error("the output interval must be finite and positive, got {interval}")]
    OutputInterval {
        /// The interval, s.
        interval: f64,
    },
    /// Output times not finite, or decreasing.
    #[error("output times must be finite and non-decreasing")]
    OutputTimes,
}

impl SimulationError {
    /// The simulation time at which the error happened (`None` for bad
    /// settings).
    pub fn time(&self) -> Option<f64> {
        match self {
            SimulationError::NonFinite { t, .. }
            | SimulationError::NonFiniteRecord { t, .. }
            | SimulationError::StepSizeUnderflow { t, .. }
            | SimulationError::SingularMatrix { t, .. }
            | SimulationError::Dynamics { t, .. }
            | SimulationError::StateLength { t, .. }
            | SimulationError::RecordWidth { t, .. }
            | SimulationError::Stopped { t, .. } => Some(*t),
            SimulationError::Recovery(e) => Some(e.time()),
            SimulationError::Settings(_) => None,
        }
    }
}
