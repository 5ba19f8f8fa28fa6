//! A drawbar load in space: a force of the pull's size pulling the hull
//! back along its heading, level with the ground's datum, at the frame's
//! centroid (the planar vehicle's drawbar, `VehicleConfig::drawbar_pull`,
//! a horizontal force at the chassis' centroid, turned with the hull).
//! The power it takes out, `P (ĥ · v)`, is booked as dissipated, and
//! apart as the drawbar's work ([`SpatialEnergy::drawbar`](super::SpatialEnergy::drawbar)).
//! A mirrored vehicle under a pull `P` runs as its planar side under
//! `P/2`.

use nalgebra::Vector3;

use super::{Bodies, SpatialLoads, TreeState};
use crate::multibody::{ChassisModel, TrackModel};
use crate::spatial::plane_rotation;

impl<H, const DH: usize, R, const DR: usize, L, const DL: usize>
    super::SpatialDynamics<'_, H, DH, R, DR, L, DL>
where
    H: ChassisModel<DH>,
    R: TrackModel<DR>,
    L: TrackModel<DL>,
{
    /// A drawbar `pull` (N) on the frame (`frame`'s body 0) added to
    /// `loads`: along the hull's heading `ĥ`, the level direction of its
    /// plane's `ξ` axis, backwards. The power it takes out, `pull (ĥ · v)`
    /// (W, `v` the frame's centroid's velocity); 0 with no pull, nothing
    /// added.
    pub(super) fn apply_drawbar(
        &self,
        pull: f64,
        (hull, frame): (&TreeState<DH>, &Bodies),
        loads: &mut SpatialLoads,
    ) -> f64 {
        if pull == 0.0 {
            return 0.0;
        }
        let heading: Vector3<f64> = plane_rotation(hull.pose.yaw, hull.pose.roll)
            .column(0)
            .into();
        loads.hull[0].force -= heading * pull;
        pull * heading.dot(&frame.velocity(0))
    }
}

/// The heading's level direction needs no roll: `plane_rotation`'s first
/// column is `(cos ψ, sin ψ, 0)` at any roll (checked below).
#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_heading_is_level_at_any_roll() {
        for (yaw, roll) in [(0.3, 0.0), (0.3, 0.4), (-2.0, -1.1)] {
            let x: Vector3<f64> = plane_rotation(yaw, roll).column(0).into();
            let (s, c) = f64::sin_cos(yaw);
            assert_eq!(x, Vector3::new(c, s, 0.0));
        }
    }
}
