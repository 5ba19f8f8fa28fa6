//! Why forward dynamics could not be evaluated: the error of every
//! evaluation of a compiled model (generated code returns it).

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
    /// (formulation §5) is singular. The system is positive definite for finite
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
