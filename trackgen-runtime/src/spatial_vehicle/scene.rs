//! The spatial vehicle drawn at a state ([`SpatialScene`]): where a
//! picture of it needs its hull, its tracks' joints and its wheels in the
//! world, from the same bodies the force elements read, and the ground
//! under its right track as it is at that instant (on soft soil, with
//! the rut pressed so far).

use nalgebra::{Vector2, Vector3};

use super::on_soil::horizontal;
use super::{Bodies, SpatialSystem};
use crate::multibody::{ChassisModel, RecursiveModel, TrackModel};
use crate::spatial::FloatingTree;

/// The spatial vehicle at one instant, in the world, m.
#[derive(Debug, Clone, PartialEq)]
pub struct SpatialScene {
    /// The time, s.
    pub t: f64,
    /// The hull's centroid.
    pub centre: Vector3<f64>,
    /// The hull's axes: forward, to its left (its plane's normal) and up.
    pub axes: [Vector3<f64>; 3],
    /// The hull's side view (its outline, in its plane).
    pub outline: Vec<Vector3<f64>>,
    /// The hull's top view: the outline's length between the tracks'
    /// inner edges, four corners.
    pub top: [Vector3<f64>; 4],
    /// Each track's joints round its loop (each link's rear joint, the
    /// first again at the end), right then left.
    pub tracks: [Vec<Vector3<f64>>; 2],
    /// The tracks' width: the shoe's declared width, or 0.3 of the gauge
    /// where it declares none (a picture's assumption).
    pub track_width: f64,
    /// Each wheel, roller, sprocket and idler: its centre, its radius and
    /// its side (0 right, 1 left).
    pub wheels: Vec<(Vector3<f64>, f64, usize)>,
    /// The ground under the right track's centre plane seen from the
    /// right: along the hull's horizontal heading from the centroid (from
    /// −[`FLOOR_REACH`] to +[`FLOOR_REACH`] every [`FLOOR_STEP`]) and its
    /// height from the centroid's, m; on soft soil the rut's floor as the
    /// soil remembers it now.
    pub floor: Vec<Vector2<f64>>,
}

/// How far ahead of and behind the hull's centroid a scene's
/// [`floor`](SpatialScene::floor) reaches, m.
pub const FLOOR_REACH: f64 = 6.0;
/// The floor's samples, m apart.
pub const FLOOR_STEP: f64 = 0.1;

impl<H, const DH: usize, R, const DR: usize, L, const DL: usize>
    SpatialSystem<'_, H, DH, R, DR, L, DL>
where
    H: ChassisModel<DH>,
    R: TrackModel<DR>,
    L: TrackModel<DL>,
{
    /// The vehicle at time `t` and state `y`, its hull drawn with
    /// `outline` (in the chassis' centroid frame, m: `scene::outline`'s).
    pub fn scene(&self, t: f64, y: &[f64], outline: &[Vector2<f64>]) -> SpatialScene {
        let (hull, right, left, _) = self.states(y);
        let d = &self.dynamics;
        let frame = Bodies::at(&d.hull, (&hull.pose, &hull.rates));
        let axes = [0, 1, 2].map(|i| frame.axis(0, i));
        // The axes are forward, the plane's normal (left) and the hull's
        // `y` (up): the outline's points are along the first and third.
        let outline: Vec<Vector3<f64>> = outline.iter().map(|p| frame.point(0, *p)).collect();
        let (front, rear) = outline_extent(&frame, &outline);
        let width = d.shoe.width.unwrap_or(0.3 * d.gauge);
        let half = 0.5 * (d.gauge - width);
        let centre = frame.centroid(0);
        let top = [(front, half), (front, -half), (rear, -half), (rear, half)]
            .map(|(x, across)| centre + axes[0] * x + axes[1] * across);
        let wheels = H::PARTS
            .iter()
            .zip(&d.sides)
            .map(|(part, side)| (frame.centroid(part.body), part.radius, side.index()))
            .collect();
        let forward = horizontal(axes[0]);
        let under_right = centre.xy() - axes[1].xy() * (0.5 * d.gauge);
        let n = (2.0 * FLOOR_REACH / FLOOR_STEP).round() as usize;
        let floor = (0..=n)
            .map(|i| {
                let u = -FLOOR_REACH + i as f64 * FLOOR_STEP;
                let at = under_right + forward * u;
                Vector2::new(u, d.surface(at.x, at.y) - centre.z)
            })
            .collect();
        SpatialScene {
            t,
            centre,
            axes,
            outline,
            top,
            tracks: [
                joints(&d.right, (&right.pose, &right.rates)),
                joints(&d.left, (&left.pose, &left.rates)),
            ],
            wheels,
            track_width: width,
            floor,
        }
    }
}

/// The outline's reach forward and back of the hull's centroid along its
/// forward axis, m.
fn outline_extent(frame: &Bodies, outline: &[Vector3<f64>]) -> (f64, f64) {
    let (centre, forward) = (frame.centroid(0), frame.axis(0, 0));
    outline
        .iter()
        .map(|p| (p - centre).dot(&forward))
        .fold((f64::MIN, f64::MAX), |(front, rear), x| {
            (front.max(x), rear.min(x))
        })
}

/// A track's joints in the world: each link's rear joint, round the loop
/// and back to the first.
fn joints<M: RecursiveModel<D>, const D: usize>(
    tree: &FloatingTree<'_, M, D>,
    state: (
        &crate::spatial::PlanePose<D>,
        &crate::spatial::PlaneRates<D>,
    ),
) -> Vec<Vector3<f64>> {
    let links = Bodies::at(tree, state);
    let description = tree.model().description();
    let Some(rear) = description.joints() else {
        return links.centroids().to_vec();
    };
    let mut at: Vec<Vector3<f64>> = (0..links.len())
        .map(|k| links.point(k, rear[k].0))
        .collect();
    if let Some(&first) = at.first() {
        at.push(first);
    }
    at
}
