//! First derivatives of the forward dynamics, exact: `∂q̈_i/∂q_i`,
//! `∂q̈_i/∂q̇_i` and `∂q̈_i/∂F` (the loads), for a track by its linear-time
//! route differentiated ([`ChainTangent`], O(n) per direction, so the
//! whole `∂q̈/∂(q, q̇)` is O(n²)) and for any body tree densely
//! ([`TreeTangent`]: a chassis, and the independent route for tracks).
//!
//! Both are *tangents*: factored once at a state, then asked for the
//! derivative along as many directions as the caller needs (a vehicle's
//! Jacobian asks for one per state component, each with the loads its
//! force elements change along it). [`track_jacobian`] and
//! [`tree_jacobian`] give the two matrices under constant loads.

mod chain;
mod tree;

pub use chain::{ChainDirection, ChainDirections, ChainTangent};
pub use tree::{TreeDirection, TreeTangent};

use nalgebra::{DMatrix, SVector, Vector2};

use crate::multibody::DynamicsError;
use crate::multibody::{BodyLoad, ClosingJoint, Closure, RecursiveModel, TrackModel};
use crate::planar::Rotation;

/// `∂q̈_i/∂q_i` and `∂q̈_i/∂q̇_i` at a state, `DOF × DOF` each (rows the
/// accelerations, columns the coordinate varied).
#[derive(Debug, Clone, PartialEq)]
pub struct StateJacobian {
    /// `∂q̈_i/∂q_i`.
    pub coordinates: DMatrix<f64>,
    /// `∂q̈_i/∂q̇_i`.
    pub rates: DMatrix<f64>,
}

/// The derivative of a cut closing joint's penalty force
/// (`F = −k C − c Ċ`, [`PenaltyJoint`](crate::laws::PenaltyJoint)) along
/// `δθ`, `δω` of the links, given each link's span turned, `Aʲ d̄ʲ`:
/// `∂C/∂θⱼ = A_θʲ d̄ʲ`, `∂Ċ/∂θⱼ = −Aʲ d̄ʲ ωⱼ`, `∂Ċ/∂ωⱼ = A_θʲ d̄ʲ`.
pub fn penalty_force_change(
    joint: &crate::laws::PenaltyJoint,
    spans: &[Vector2<f64>],
    omega: &[f64],
    (dtheta, domega): (&[f64], &[f64]),
) -> Vector2<f64> {
    let (mut dgap, mut drate) = (Vector2::zeros(), Vector2::zeros());
    for (j, span) in spans.iter().enumerate() {
        let (t, w) = (
            dtheta.get(j).copied().unwrap_or(0.0),
            domega.get(j).copied().unwrap_or(0.0),
        );
        let column = Vector2::new(-span.y, span.x);
        dgap += column * t;
        drate += column * w - span * (omega[j] * t);
    }
    joint.force(dgap, drate)
}

/// `∂q̈_i/∂(q_i, q̇_i)` of a track as declared (a constrained loop, an
/// open chain, or its declared penalty joint, whose force's own change is
/// included) under loads besides gravity that do not change (one per
/// link, or none): by [`ChainTangent`], one O(n) direction per column,
/// swept together ([`ChainTangent::directions`]).
pub fn track_jacobian<M: TrackModel<D>, const D: usize>(
    model: &M,
    q: &SVector<f64, D>,
    qd: &SVector<f64, D>,
    loads: &[BodyLoad],
) -> Result<StateJacobian, DynamicsError> {
    let description = model.description();
    let mut tangent = ChainTangent::new(&description).ok_or(DynamicsError::WrongLength {
        what: "a track's loop joint",
        expected: 1,
        got: 0,
    })?;
    let n = M::BODIES;
    let trig: Vec<(f64, f64)> = (0..n).map(|i| q[2 + i].sin_cos()).collect();
    let omega: Vec<f64> = qd.as_slice()[2..].to_vec();
    let penalty = match M::CLOSURE {
        Closure::Penalty(joint) => Some(joint),
        _ => None,
    };
    let closing = match (M::CLOSURE, penalty) {
        (_, Some(joint)) => ClosingJoint::Cut {
            force: joint.force(model.closure(q), model.closure_jacobian(q) * qd),
        },
        (Closure::Partitioned, _) => ClosingJoint::CLOSED,
        _ => ClosingJoint::OPEN,
    };
    tangent.factor(&trig, &omega, loads, closing)?;
    let spans: Vec<Vector2<f64>> = description
        .link_spans()
        .unwrap_or_default()
        .iter()
        .zip(&trig)
        .map(|(d, t)| Rotation::from_sin_cos(*t).apply(*d))
        .collect();
    let mut jacobian = StateJacobian {
        coordinates: DMatrix::zeros(D, D),
        rates: DMatrix::zeros(D, D),
    };
    // Every link's angle, then every link's rate, each a unit direction:
    // the columns of the identity, link-major, through the chain's sweeps
    // at once. R¹ and Ṙ¹ enter only through loads, which do not change
    // here.
    let identity: Vec<f64> = (0..n * n)
        .map(|e| if e / n == e % n { 1.0 } else { 0.0 })
        .collect();
    let mut unit = vec![0.0; n];
    let mut columns = vec![0.0; D * n];
    for rates in [false, true] {
        let closing: Vec<Vector2<f64>> = match penalty {
            Some(joint) => (0..n)
                .map(|j| {
                    unit.fill(0.0);
                    unit[j] = 1.0;
                    let (angles, rates_of) = if rates {
                        (&[][..], &unit[..])
                    } else {
                        (&unit[..], &[][..])
                    };
                    penalty_force_change(&joint, &spans, &omega, (angles, rates_of))
                })
                .collect(),
            None => Vec::new(),
        };
        let (angles, rates_of) = if rates {
            (&[][..], &identity[..])
        } else {
            (&identity[..], &[][..])
        };
        tangent.directions(
            &ChainDirections {
                columns: n,
                angles,
                rates: rates_of,
                loads: &[],
                closing: &closing,
            },
            &mut columns,
        );
        let target = if rates {
            &mut jacobian.rates
        } else {
            &mut jacobian.coordinates
        };
        // `columns` holds row r of direction j at r·n + j.
        for j in 0..n {
            for r in 0..D {
                target[(r, 2 + j)] = columns[r * n + j];
            }
        }
    }
    Ok(jacobian)
}

/// `∂q̈_i/∂(q_i, q̇_i)` of a body tree (a chassis; a track's loop as
/// declared, a penalty joint's force left to the loads) under loads
/// besides gravity that do not change: by [`TreeTangent`], densely.
pub fn tree_jacobian<M: RecursiveModel<D>, const D: usize>(
    model: &M,
    q: &SVector<f64, D>,
    qd: &SVector<f64, D>,
    loads: &[BodyLoad],
) -> Result<StateJacobian, DynamicsError> {
    let mut tangent = TreeTangent::new(&model.description());
    tangent.factor(q.as_slice(), qd.as_slice(), loads)?;
    let mut jacobian = StateJacobian {
        coordinates: DMatrix::zeros(D, D),
        rates: DMatrix::zeros(D, D),
    };
    let mut unit = vec![0.0; D];
    let mut column = vec![0.0; D];
    for j in 0..D {
        unit.fill(0.0);
        unit[j] = 1.0;
        tangent.direction(
            &TreeDirection {
                coordinates: &unit,
                ..Default::default()
            },
            &mut column,
        );
        jacobian
            .coordinates
            .set_column(j, &nalgebra::DVector::from_column_slice(&column));
        tangent.direction(
            &TreeDirection {
                rates: &unit,
                ..Default::default()
            },
            &mut column,
        );
        jacobian
            .rates
            .set_column(j, &nalgebra::DVector::from_column_slice(&column));
    }
    Ok(jacobian)
}
