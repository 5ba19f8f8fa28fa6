//! The closing joint as the linear-time route (spec §5) sees it, and that
//! route for a model as declared.

use nalgebra::{SVector, Vector2};

use super::Accelerations;
use crate::DynamicsError;
use crate::model::{BodyLoad, Closure, TrackModel};

/// How the joint between link n and link 1 enters a track's linear-time
/// dynamics ([`TrackModel::linear_time_dynamics`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum ClosingJoint {
    /// A constraint: the loop stays closed, `C_q q̈ = γ_c − stabilisation`
    /// (zero for the plain equations; Baumgarte's `2ω Ċ + ω² C` under
    /// multipliers, [`MultiplierOptions::stabilisation`](crate::closure::MultiplierOptions::stabilisation)).
    Constrained {
        /// m/s².
        stabilisation: Vector2<f64>,
    },
    /// Cut: an open chain. `force` (N) acts across the cut, on link n at
    /// `ū2ⁿ` and reversed on link 1 at `ū1¹`: zero for an open chain, the
    /// spring-damper's force for a penalty joint
    /// ([`PenaltyJoint::force`](crate::closure::PenaltyJoint::force)).
    Cut {
        /// N.
        force: Vector2<f64>,
    },
}

impl ClosingJoint {
    /// An open chain: cut, nothing across the cut.
    pub const OPEN: ClosingJoint = ClosingJoint::Cut {
        force: Vector2::new(0.0, 0.0),
    };

    /// The closed loop, unstabilised.
    pub const CLOSED: ClosingJoint = ClosingJoint::Constrained {
        stabilisation: Vector2::new(0.0, 0.0),
    };
}

/// Forward dynamics of `model` as declared (a constrained loop, an open
/// chain, or its declared penalty joint), by the generated linear-time
/// route (spec §5): the same accelerations as
/// [`forward_dynamics`](super::forward_dynamics) in O(n), with the closing
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
