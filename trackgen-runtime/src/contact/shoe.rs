//! Where a track shoe touches the world, in link coordinates.
//!
//! Link frames follow the declaration: x from the joint `ū1` to `ū2`, y to
//! the left. Links are numbered so that the loop runs counter-clockwise
//! (seen with x forward and y up): the left of every link is the inside
//! of the loop, where the wheels run, and the right is the ground side.

use nalgebra::Vector2;

/// The contact features of a track shoe, link frame, m.
#[derive(Debug, Clone, PartialEq)]
pub struct ShoeGeometry {
    /// Points of the ground face (grouser tips, pad corners).
    pub ground_points: Vec<Vector2<f64>>,
    /// The inner running face, a segment: road wheels, idler and rollers
    /// roll on it.
    pub inner_face: [Vector2<f64>; 2],
    /// Centres of the cylinders the sprocket teeth engage.
    pub pins: Vec<Vector2<f64>>,
    /// Radius of those cylinders, m.
    pub pin_radius: f64,
    /// The track's width across the shoe, m, if declared: what soft soil's
    /// pressure–sinkage law needs (the planar model does not otherwise see
    /// it).
    pub width: Option<f64>,
}

impl ShoeGeometry {
    /// Distance from the pitch line to the inner face, m: how far the
    /// track's pitch line runs outside a wheel's rim.
    pub fn inner_offset(&self) -> f64 {
        0.5 * (self.inner_face[0].y + self.inner_face[1].y)
    }

    /// The largest distance of any feature from the link centroid, m: the
    /// radius of the link's bounding circle for culling.
    /// Every contact pair culls with it at every evaluation, so the
    /// squares are compared and one root taken per kind of feature.
    #[inline]
    pub fn extent(&self) -> f64 {
        // The largest squared distance (a NaN skipped, as `f64::max` skips
        // it, by a comparison); one root per kind of feature, the faces'
        // taken after their maximum (the root is monotonic and correctly
        // rounded, so the same bits as the larger of two roots).
        let farthest2 = |points: &[Vector2<f64>]| {
            points
                .iter()
                .map(|p| p.norm_squared())
                .fold(0.0, |m, d| if d > m { d } else { m })
        };
        let faces2 = farthest2(&self.ground_points);
        let inner2 = farthest2(&self.inner_face);
        let faces = (if inner2 > faces2 { inner2 } else { faces2 }).sqrt();
        let pins = if self.pins.is_empty() {
            0.0
        } else {
            farthest2(&self.pins).sqrt() + self.pin_radius
        };
        faces.max(pins)
    }
}
