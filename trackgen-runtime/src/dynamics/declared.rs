//! Forward dynamics of a track as declared, by its generated linear-time
//! route.

use nalgebra::{SVector, Vector2};

use super::Accelerations;
use crate::multibody::DynamicsError;
use crate::multibody::{BodyLoad, ClosingJoint, Closure, TrackModel};

/// Forward dynamics of `model` as declared (a constrained loop, an open
/// chain, or its declared penalty joint), by the generated linear-time
/// route (formulation §5): the same accelerations as
/// [`dense_forward_dynamics`](super::dense_forward_dynamics) in O(n), with the closing
/// joint's `λ` for a constrained loop (minus the force it puts on link n,
/// as the multiplier form's).
pub fn track_dynamics<M: TrackModel<D>, const D: usize>(
    model: &M,
    q: &SVector<f64, D>,
    qd: &SVector<f64, D>,
    loads: &[BodyLoad],
) -> Result<Accelerations<SVector<f64, D>>, DynamicsError> {
    let n = M::BODIES;
    let trig: Vec<(f64, f64)> = (0..n).map(|i| q[2 + i].sin_cos()).collect();
    let closing = match M::CLOSURE {
        Closure::Partitioned => ClosingJoint::CLOSED,
        Closure::Open => ClosingJoint::OPEN,
        Closure::Penalty(joint) => ClosingJoint::Cut {
            force: joint.force(model.closure(q), model.closure_jacobian(q) * qd),
        },
    };
    let mut qdd = SVector::zeros();
    let mut joint_forces = vec![Vector2::zeros(); n];
    model.linear_time_dynamics(&trig, qd, loads, closing, &mut qdd, &mut joint_forces)?;
    Ok(Accelerations {
        qdd,
        multipliers: closing_constrained(closing).then(|| -joint_forces[n - 1]),
    })
}

fn closing_constrained(closing: ClosingJoint) -> bool {
    matches!(closing, ClosingJoint::Constrained { .. })
}
