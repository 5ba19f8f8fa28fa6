use nalgebra::allocator::Allocator;
use nalgebra::{
    Cholesky, DefaultAllocator, Dim, Matrix, OMatrix, OVector, Storage, U1, U2, Vector2,
};

use crate::multibody::DynamicsError;

/// Accelerations at a state.
#[derive(Debug, Clone, PartialEq)]
pub struct Accelerations<V> {
    /// `q̈_i`, the second derivatives of the recursive coordinates.
    pub qdd: V,
    /// `λ`, the closing joint's multipliers (N; minus the force the joint
    /// exerts on link n), for a loop closed by a constraint.
    pub multipliers: Option<Vector2<f64>>,
}

pub(crate) fn solve_open<D: Dim>(
    mass: OMatrix<f64, D, D>,
    forces: &OVector<f64, D>,
) -> Result<Accelerations<OVector<f64, D>>, DynamicsError>
where
    DefaultAllocator: Allocator<D, D> + Allocator<D>,
{
    let chol = Cholesky::new(mass).ok_or(DynamicsError::MassMatrixNotPositiveDefinite)?;
    Ok(Accelerations {
        qdd: chol.solve(forces),
        multipliers: None,
    })
}

pub(crate) fn solve_closed<D: Dim, S: Storage<f64, U2, D>>(
    mass: OMatrix<f64, D, D>,
    forces: &OVector<f64, D>,
    cq: &Matrix<f64, U2, D, S>,
    gamma_c: &Vector2<f64>,
) -> Result<Accelerations<OVector<f64, D>>, DynamicsError>
where
    DefaultAllocator:
        Allocator<D, D> + Allocator<D> + Allocator<D, U2> + Allocator<U2, D> + Allocator<U1, D>,
{
    let chol = Cholesky::new(mass).ok_or(DynamicsError::MassMatrixNotPositiveDefinite)?;
    let y = chol.solve(forces);
    let x = chol.solve(&cq.transpose());
    let schur = cq * &x;
    let rhs = cq * &y - gamma_c;
    let lambda = schur
        .cholesky()
        .map(|c| c.solve(&rhs))
        .ok_or(DynamicsError::SingularClosure)?;
    Ok(Accelerations {
        qdd: y - x * lambda,
        multipliers: Some(lambda),
    })
}
