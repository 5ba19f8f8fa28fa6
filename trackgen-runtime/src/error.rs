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
