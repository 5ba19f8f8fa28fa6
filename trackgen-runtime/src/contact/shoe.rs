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
    /// Each ground point's share of the shoe's ground face along the
    /// link, for a track of pitch `pitch` m: the face between the
    /// midpoints to its neighbouring points, the first and last points
    /// sharing theirs with the previous and the next shoe's, `pitch` away.
    /// Its middle along the link's x and its length, m, in the points'
    /// order. The shares tile the track: no gap, no overlap, the lengths
    /// adding up to the pitch (what a point presses into a rut).
    pub fn ground_shares(&self, pitch: f64) -> Vec<(f64, f64)> {
        let along: Vec<f64> = self.ground_points.iter().map(|p| p.x).collect();
        let mut order: Vec<usize> = (0..along.len()).collect();
        order.sort_by(|&a, &b| along[a].total_cmp(&along[b]));
        let mut out = vec![(0.0, 0.0); along.len()];
        for (rank, &i) in order.iter().enumerate() {
            let before = match rank {
                0 => along[order[order.len() - 1]] - pitch,
                _ => along[order[rank - 1]],
            };
            let after = match order.get(rank + 1) {
                Some(&j) => along[j],
                None => along[order[0]] + pitch,
            };
            let (from, to) = (0.5 * (before + along[i]), 0.5 * (along[i] + after));
            out[i] = (0.5 * (from + to), to - from);
        }
        out
    }

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

#[cfg(test)]
mod tests {
    use super::*;

    fn shoe(along: &[f64]) -> ShoeGeometry {
        ShoeGeometry {
            ground_points: along.iter().map(|x| Vector2::new(*x, -0.03)).collect(),
            inner_face: [Vector2::new(-0.07, 0.03), Vector2::new(0.07, 0.03)],
            pins: Vec::new(),
            pin_radius: 0.0,
            width: None,
        }
    }

    /// The M113's two ground points at ±60 mm on a 154 mm shoe each take
    /// half the shoe, the front half and the rear; unevenly spaced points
    /// in any order share the face between the midpoints, the lengths
    /// adding up to the pitch.
    #[test]
    fn each_point_takes_its_share_of_the_shoe() {
        let close =
            |a: (f64, f64), b: (f64, f64)| (a.0 - b.0).abs() < 1e-15 && (a.1 - b.1).abs() < 1e-15;
        let two = shoe(&[-0.06, 0.06]).ground_shares(0.154);
        assert!(close(two[0], (-0.0385, 0.077)), "{two:?}");
        assert!(close(two[1], (0.0385, 0.077)), "{two:?}");
        // Sorted: −0.05 [−0.1, −0.02], 0.01 [−0.02, 0.03], 0.05 [0.03, 0.1].
        let three = shoe(&[0.05, -0.05, 0.01]).ground_shares(0.2);
        assert!(close(three[1], (-0.06, 0.08)), "{three:?}");
        assert!(close(three[2], (0.005, 0.05)), "{three:?}");
        assert!(close(three[0], (0.065, 0.07)), "{three:?}");
        let total: f64 = three.iter().map(|s| s.1).sum();
        assert!((total - 0.2).abs() < 1e-15);
    }
}
