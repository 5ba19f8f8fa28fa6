//! The closing joint as the linear-time route (formulation §5) sees it.

use nalgebra::Vector2;

/// How the joint between link n and link 1 enters a track's linear-time
/// dynamics ([`TrackModel::linear_time_dynamics`](super::TrackModel::linear_time_dynamics)).
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
    /// ([`PenaltyJoint::force`](crate::laws::PenaltyJoint::force)).
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
