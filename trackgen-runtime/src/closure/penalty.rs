//! The secondary joint of the paper's Fig. 5, chosen at run time: the
//! closing joint cut, a spring-damper across the cut.

use nalgebra::{SMatrix, SVector, Vector2};

/// The spring-damper's generalised forces `C_qᵀ F` with
/// `F = −k C − c Ċ` (on link n; `−F` on link 1). The gap `C = P_n − P_1`
/// and its rate `Ċ = C_q q̇` make `C_qᵀ` the map from the force to
/// generalised forces by virtual work.
pub fn forces<const D: usize>(
    cq: &SMatrix<f64, 2, D>,
    gap: Vector2<f64>,
    qd: &SVector<f64, D>,
    stiffness: f64,
    damping: f64,
) -> SVector<f64, D> {
    let force = -gap * stiffness - (cq * qd) * damping;
    cq.transpose() * force
}

/// The spring's potential energy `½ k |C|²`, J.
pub fn energy(gap: Vector2<f64>, stiffness: f64) -> f64 {
    0.5 * stiffness * gap.norm_squared()
}
