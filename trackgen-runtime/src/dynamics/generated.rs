use nalgebra::{DMatrix, DVector, Matrix2xX, SMatrix, SVector};

use super::dense::{Accelerations, solve_closed, solve_open};
use crate::multibody::DynamicsError;
use crate::multibody::{BodyLoad, RecursiveModel, TrackModel};

/// The largest `M_i`, in bytes, that the dense routes keep on the stack
/// (`8 · DOF²`: up to DOF 90, 88 links): there the solve allocates
/// nothing. A larger `M_i` (8 MB at 1000 links) lives on the heap, and is
/// factorised there.
pub const STACK_MATRIX_BYTES: usize = 64 * 1024;

/// Whether a `DOF × DOF` matrix of `f64` fits [`STACK_MATRIX_BYTES`].
const fn on_stack(dof: usize) -> bool {
    dof.saturating_mul(dof).saturating_mul(8) <= STACK_MATRIX_BYTES
}

/// Forward dynamics of a body tree with no constraints (an open chain, a
/// penalty-closed track, a chassis): solves `M_i q̈_i = Q_i`.
///
/// Small models (`M_i` within [`STACK_MATRIX_BYTES`]) are solved on the
/// stack; larger ones on the heap, so any model the macro accepts runs on
/// a 2 MiB thread.
pub fn dense_open_dynamics<M: RecursiveModel<D>, const D: usize>(
    model: &M,
    q: &SVector<f64, D>,
    qd: &SVector<f64, D>,
    loads: &[BodyLoad],
) -> Result<Accelerations<SVector<f64, D>>, DynamicsError> {
    check_loads::<M, D>(loads)?;
    if on_stack(D) {
        open_on_stack(model, q, qd, loads)
    } else {
        let (mass, forces) = equations_on_heap(model, q, qd, loads);
        from_dynamic(solve_open(mass, &forces)?)
    }
}

/// Forward dynamics of a track as declared: a loop closed by a constraint
/// takes the multiplier form of formulation §2 (and returns `λ`); an open or
/// penalty-closed chain solves `M_i q̈_i = Q_i`.
///
/// As for [`dense_open_dynamics`], `M_i` is on the stack for small tracks and on
/// the heap for large ones.
pub fn dense_forward_dynamics<M: TrackModel<D>, const D: usize>(
    model: &M,
    q: &SVector<f64, D>,
    qd: &SVector<f64, D>,
    loads: &[BodyLoad],
) -> Result<Accelerations<SVector<f64, D>>, DynamicsError> {
    if !M::CLOSURE.is_constrained() {
        return dense_open_dynamics(model, q, qd, loads);
    }
    check_loads::<M, D>(loads)?;
    let cq = model.closure_jacobian(q);
    let gamma_c = model.closure_gamma(q, qd);
    if on_stack(D) {
        closed_on_stack(model, q, qd, loads, &cq, &gamma_c)
    } else {
        let (mass, forces) = equations_on_heap(model, q, qd, loads);
        let cq = Matrix2xX::from_column_slice(cq.as_slice());
        from_dynamic(solve_closed(mass, &forces, &cq, &gamma_c)?)
    }
}

fn check_loads<M: RecursiveModel<D>, const D: usize>(
    loads: &[BodyLoad],
) -> Result<(), DynamicsError> {
    if !loads.is_empty() && loads.len() != M::BODIES {
        return Err(DynamicsError::WrongLength {
            what: "loads",
            expected: M::BODIES,
            got: loads.len(),
        });
    }
    Ok(())
}

// The stack routes are separate functions, never inlined: a frame holds
// every local of its function whichever branch runs, so an `SMatrix` of a
// large model declared in a branch not taken would still overflow.

#[inline(never)]
fn open_on_stack<M: RecursiveModel<D>, const D: usize>(
    model: &M,
    q: &SVector<f64, D>,
    qd: &SVector<f64, D>,
    loads: &[BodyLoad],
) -> Result<Accelerations<SVector<f64, D>>, DynamicsError> {
    let mut mass = SMatrix::<f64, D, D>::zeros();
    let mut forces = SVector::<f64, D>::zeros();
    model.equations_of_motion(q, qd, loads, &mut mass, &mut forces);
    solve_open(mass, &forces)
}

#[inline(never)]
fn closed_on_stack<M: RecursiveModel<D>, const D: usize>(
    model: &M,
    q: &SVector<f64, D>,
    qd: &SVector<f64, D>,
    loads: &[BodyLoad],
    cq: &SMatrix<f64, 2, D>,
    gamma_c: &nalgebra::Vector2<f64>,
) -> Result<Accelerations<SVector<f64, D>>, DynamicsError> {
    let mut mass = SMatrix::<f64, D, D>::zeros();
    let mut forces = SVector::<f64, D>::zeros();
    model.equations_of_motion(q, qd, loads, &mut mass, &mut forces);
    solve_closed(mass, &forces, cq, gamma_c)
}

/// `M_i` and `Q_i` with `M_i` filled on the heap and handed over as a
/// `DMatrix` (one copy, O(n²), beside the O(n³) solve).
fn equations_on_heap<M: RecursiveModel<D>, const D: usize>(
    model: &M,
    q: &SVector<f64, D>,
    qd: &SVector<f64, D>,
    loads: &[BodyLoad],
) -> (DMatrix<f64>, DVector<f64>) {
    let mut mass = zeroed_matrix::<D>();
    let mut forces = SVector::<f64, D>::zeros();
    model.equations_of_motion(q, qd, loads, &mut mass, &mut forces);
    (
        DMatrix::from_column_slice(D, D, mass.as_slice()),
        DVector::from_column_slice(forces.as_slice()),
    )
}

/// A zero `D × D` matrix allocated directly on the heap (`Box::new` of
/// `SMatrix::zeros()` would build it on the stack first).
pub(crate) fn zeroed_matrix<const D: usize>() -> Box<SMatrix<f64, D, D>> {
    let zeroed = Box::<SMatrix<f64, D, D>>::new_zeroed();
    // SAFETY: an `SMatrix<f64, D, D>` is a plain array of `D²` `f64`s (no
    // padding, no invariant to uphold), and all-zero bits are `0.0_f64`.
    unsafe { zeroed.assume_init() }
}

fn from_dynamic<const D: usize>(
    a: Accelerations<DVector<f64>>,
) -> Result<Accelerations<SVector<f64, D>>, DynamicsError> {
    Ok(Accelerations {
        qdd: SVector::from_column_slice(a.qdd.as_slice()),
        multipliers: a.multipliers,
    })
}
