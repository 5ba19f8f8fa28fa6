//! Typed errors of the leaf computations: forward dynamics and a
//! simulation step. A leaf module, so that the integrators report a
//! [`SimulationError`] without depending on the simulation driver.

use thiserror::Error;

/// Why forward dynamics could not be evaluated at a state.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum DynamicsError {
    /// The mass matrix `M_i` is not positive definite (Cholesky failed).
    /// With positive masses and inertias this only happens for non-finite
    /// coordinates.
    #[error("the mass matrix M_i is not positive definite (non-finite state?)")]
    MassMatrixNotPositiveDefinite,
    /// The 2 × 2 matrix `C_q M_i⁻¹ C_qᵀ` of the multiplier form is singular:
    /// the closure rows are dependent, which happens when every link of the
    /// loop is parallel (a fully stretched loop).
    #[error("the closure constraints are singular (C_q M_i⁻¹ C_qᵀ not invertible)")]
    SingularClosure,
    /// A 2 × 2 block of the joint-force system of the linear-time route
    /// (spec §5) is singular. The system is positive definite for finite
    /// states of an open chain; a closed loop's last block is singular when
    /// the loop is fully stretched (every link parallel).
    #[error(
        "the joint-force system of the linear-time dynamics is singular at joint {joint} (a stretched loop, or a non-finite state)"
    )]
    SingularJointSystem {
        /// The joint (0-based; joint `j` joins link `j + 1` to the next, the
        /// last is the closing joint).
        joint: usize,
    },
    /// A slice argument has the wrong length.
    #[error("{what}: expected {expected} entries, got {got}")]
    WrongLength {
        /// Which argument.
        what: &'static str,
        /// The number of bodies of the model.
        expected: usize,
        /// What was passed.
        got: usize,
    },
}

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
    /// Newton-Raphson on the loop closure `C(z, d) = 0` did not converge.
    #[error(
        "Newton-Raphson on the loop closure failed at t = {t} s: |C| = {residual:e} m after {iterations} iterations"
    )]
    NewtonFailed {
        /// Time, s.
        t: f64,
        /// Iterations taken.
        iterations: usize,
        /// `|C|` at the last iterate, m.
        residual: f64,
    },
    /// Newton-Raphson converged, but to the mirror configuration of the
    /// dependent pair (the closure has two solutions for two angles): the
    /// step was too long.
    #[error("the dependent links {} and {} jumped by {jump:.2} rad at t = {t} s (mirror solution of the closure)", pair[0], pair[1])]
    BranchJump {
        /// Time, s.
        t: f64,
        /// The dependent links (numbered from 1).
        pair: [usize; 2],
        /// The larger change of the two angles from the last accepted
        /// step, rad.
        jump: f64,
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
    /// The dependent pair's block `C_d` became singular while switching was
    /// off (paper eq. (21): the two links nearly parallel).
    #[error("singular partition at t = {t} s: links {} and {} are nearly parallel (|sin| = {conditioning:e}) and switching is off", pair[0], pair[1])]
    SingularPartition {
        /// Time, s.
        t: f64,
        /// The dependent links (numbered from 1).
        pair: [usize; 2],
        /// `|sin|` of the angle between the two columns of `C_d`.
        conditioning: f64,
    },
    /// A linear system of the method was singular.
    #[error("singular matrix ({what}) at t = {t} s")]
    SingularMatrix {
        /// Time, s.
        t: f64,
        /// Which matrix.
        what: &'static str,
    },
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
            | SimulationError::NewtonFailed { t, .. }
            | SimulationError::BranchJump { t, .. }
            | SimulationError::StepSizeUnderflow { t, .. }
            | SimulationError::SingularPartition { t, .. }
            | SimulationError::SingularMatrix { t, .. }
            | SimulationError::Dynamics { t, .. }
            | SimulationError::StateLength { t, .. }
            | SimulationError::RecordWidth { t, .. }
            | SimulationError::Stopped { t, .. } => Some(*t),
            SimulationError::Settings(_) => None,
        }
    }
}
