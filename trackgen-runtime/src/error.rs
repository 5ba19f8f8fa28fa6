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
    /// The simulation was set up wrongly (before any step).
    #[error("invalid simulation set-up: {0}")]
    Setup(String),
}

impl SimulationError {
    /// The simulation time at which the error happened (`None` for a set-up
    /// error).
    pub fn time(&self) -> Option<f64> {
        match self {
            SimulationError::NonFinite { t, .. }
            | SimulationError::NonFiniteRecord { t, .. }
            | SimulationError::NewtonFailed { t, .. }
            | SimulationError::BranchJump { t, .. }
            | SimulationError::StepSizeUnderflow { t, .. }
            | SimulationError::SingularPartition { t, .. }
            | SimulationError::SingularMatrix { t, .. }
            | SimulationError::Dynamics { t, .. } => Some(*t),
            SimulationError::Setup(_) => None,
        }
    }
}
