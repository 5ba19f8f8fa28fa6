//! A track's joint tensions from the joint forces its forward dynamics
//! finds ([`TrackModel::linear_time_dynamics`](super::TrackModel::linear_time_dynamics)).

use nalgebra::Vector2;

use crate::planar::Rotation;

/// Every joint's tension, N (positive pulling), in link order: joint `j`
/// joins link `j` to link `j + 1` (0-based; the last is the closing joint
/// `n → 1`), `joint_forces[j]` is its force on link `j` and the tension is
/// that force along the link's axis `A(θ_j) s̄_j / |s̄_j|`, `s̄_j` its span
/// joint to joint in its own frame (`ū2 − ū1`,
/// [`TreeDescription::link_spans`](super::TreeDescription::link_spans))
/// and `trig[j]` its `(sin θ, cos θ)`. For a cut closing joint, the last
/// is the force across the cut.
pub fn joint_tensions<'a>(
    joint_forces: &'a [Vector2<f64>],
    spans: &'a [Vector2<f64>],
    trig: &'a [(f64, f64)],
) -> impl Iterator<Item = f64> + 'a {
    joint_forces
        .iter()
        .zip(spans)
        .zip(trig)
        .map(|((force, span), &trig)| {
            let axis = Rotation::from_sin_cos(trig).apply(*span);
            force.dot(&axis) / span.norm()
        })
}
