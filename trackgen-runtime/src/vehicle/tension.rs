//! Joint forces along the track, from the accelerations (Newton's second
//! law link by link).

use nalgebra::{Matrix2, SVector, Vector2};

use crate::model::{BodyLoad, TrackModel};

/// The tension (N, positive pulling) in every joint `i → i+1` of a closed
/// track (the last is the closing joint `n → 1`), given `q̈_i` and the loads
/// (besides gravity) that produced it.
///
/// The closing joint's force `λ` follows from the multiplier form
/// `M_i q̈_i + C_qᵀ λ = Q_i` (spec §2) by least squares; then each link's
/// `mᵢ aᵢ = Fᵢ + f⁻ᵢ + f⁺ᵢ` gives the force from the next link, `aᵢ`
/// being `H q̈_i + γ`. The tension is that force along the link's `d̄`.
pub fn tensions<M: TrackModel<D>, const D: usize>(
    model: &M,
    q: &SVector<f64, D>,
    qd: &SVector<f64, D>,
    qdd: &SVector<f64, D>,
    loads: &[BodyLoad],
) -> Option<Vec<f64>> {
    let n = M::BODIES;
    // On the heap: a 1000-link track's `M_i` is 8 MB.
    let mut mass = crate::dynamics::zeroed_matrix::<D>();
    let mut forces = SVector::<f64, D>::zeros();
    model.equations_of_motion(q, qd, loads, &mut mass, &mut forces);
    let cq = model.closure_jacobian(q);
    let gram: Matrix2<f64> = cq * cq.transpose();
    let lambda = gram.try_inverse()? * (cq * (forces - &*mass * qdd));
    let description = model.description();
    let spans = description.link_spans()?;
    let mut accel = vec![Vector2::zeros(); n];
    let mut gamma = vec![Vector2::zeros(); n];
    model.body_velocities(q, qdd, &mut accel);
    model.velocity_terms(q, qd, &mut gamma);
    // The constraint C = P_n − P_1 pushes link 1 by +λ at its ū1. A
    // declared penalty joint is in Q_i already (so λ ≈ 0): its spring-damper
    // pushes link 1 by −F_pen.
    let mut from_previous = match description.loop_joint.map(|j| j.closure) {
        Some(crate::model::Closure::Penalty(joint)) => -joint.force(model.closure(q), cq * qd),
        _ => lambda,
    };
    let mut out = Vec::with_capacity(n);
    for i in 0..n {
        let body = &description.bodies[i];
        let applied =
            description.gravity * body.mass + loads.get(i).map_or(Vector2::zeros(), |l| l.force);
        let from_next = (accel[i] + gamma[i]) * body.mass - applied - from_previous;
        let axis = crate::planar::rotate(q[2 + i], spans[i]).normalize();
        out.push(from_next.dot(&axis));
        from_previous = -from_next;
    }
    Some(out)
}
