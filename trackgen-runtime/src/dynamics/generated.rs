use nalgebra::{SMatrix, SVector};

use super::dense::{Accelerations, solve_closed, solve_open};
use crate::DynamicsError;
use crate::model::{BodyLoad, RecursiveModel, TrackModel};

/// Forward dynamics of a body tree with no constraints (an open chain, a
/// penalty-closed track, a chassis): solves `M_i q̈_i = Q_i`.
pub fn open_dynamics<M: RecursiveModel<D>, const D: usize>(
    model: &M,
    q: &SVector<f64, D>,
    qd: &SVector<f64, D>,
    loads: &[BodyLoad],
) -> Result<Accelerations<SVector<f64, D>>, DynamicsError> {
    let (mass, forces) = equations(model, q, qd, loads)?;
    solve_open(mass, &forces)
}

/// Forward dynamics of a track as declared: a loop closed by a constraint
/// takes the multiplier form of spec §2 (and returns `λ`); an open or
/// penalty-closed chain solves `M_i q̈_i = Q_i`.
pub fn forward_dynamics<M: TrackModel<D>, const D: usize>(
    model: &M,
    q: &SVector<f64, D>,
    qd: &SVector<f64, D>,
    loads: &[BodyLoad],
) -> Result<Accelerations<SVector<f64, D>>, DynamicsError> {
    let (mass, forces) = equations(model, q, qd, loads)?;
    if M::CLOSURE.is_constrained() {
        solve_closed(
            mass,
            &forces,
            &model.closure_jacobian(q),
            &model.closure_gamma(q, qd),
        )
    } else {
        solve_open(mass, &forces)
    }
}

#[allow(clippy::type_complexity)]
fn equations<M: RecursiveModel<D>, const D: usize>(
    model: &M,
    q: &SVector<f64, D>,
    qd: &SVector<f64, D>,
    loads: &[BodyLoad],
) -> Result<(SMatrix<f64, D, D>, SVector<f64, D>), DynamicsError> {
    if !loads.is_empty() && loads.len() != M::BODIES {
        return Err(DynamicsError::WrongLength {
            what: "loads",
            expected: M::BODIES,
            got: loads.len(),
        });
    }
    let mut mass = SMatrix::<f64, D, D>::zeros();
    let mut forces = SVector::<f64, D>::zeros();
    model.equations_of_motion(q, qd, loads, &mut mass, &mut forces);
    Ok((mass, forces))
}
