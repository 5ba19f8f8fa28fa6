//! Each track's tensions at a state, as a vehicle engineer reads them:
//! the spans either side of the sprocket (the tight one it pulls, the
//! slack one it pays out) and the largest anywhere. They come from the
//! joint forces the track's forward dynamics finds
//! ([`joint_tensions`]), the run of joints seated on the sprocket by the
//! planar vehicle's rule ([`seated_run`]), each joint's distance to the
//! pitch circle taken in the sprocket's plane.

use nalgebra::Vector2;

use super::{LoadScratch, SpatialSystem};
use crate::integrate::{OdeSystem, SimulationError};
use crate::multibody::{ChassisModel, TrackModel, TreeDescription, joint_tensions};
use crate::spatial::PlaneMotion;
use crate::vehicle::seated_run;

/// A track's tensions at a state, N (positive pulling).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TrackTensions {
    /// The tight span's: the first joint past the run seated on the
    /// sprocket (the span it pulls driving forward: the top run where
    /// the sprocket is at the front). NaN without a sprocket.
    pub tight: f64,
    /// The slack span's: the last joint before the seated run (the span
    /// it pays out). NaN without a sprocket.
    pub slack: f64,
    /// The largest of every joint's.
    pub largest: f64,
}

impl<H, const DH: usize, R, const DR: usize, L, const DL: usize>
    SpatialSystem<'_, H, DH, R, DR, L, DL>
where
    H: ChassisModel<DH>,
    R: TrackModel<DR>,
    L: TrackModel<DL>,
{
    /// Each track's tensions at time `t` and state `y` (right, left),
    /// from an evaluation of the right-hand side there: what stops the
    /// run there (a drive's demand not finite, dynamics that cannot be
    /// solved) is the error.
    pub fn tensions(&self, t: f64, y: &[f64]) -> Result<[TrackTensions; 2], SimulationError> {
        let (scratch, motions) = self.evaluated(t, y)?;
        Ok(self.tensions_in(&scratch, &motions))
    }

    /// The right-hand side evaluated at `t` and `y` into a workspace of
    /// its own: what it found (the bodies in the world, the loads, the
    /// joint forces) and the trees' motions in their planes, for what the
    /// vehicle shows there.
    pub(super) fn evaluated(
        &self,
        t: f64,
        y: &[f64],
    ) -> Result<(LoadScratch, [PlaneMotion; 3]), SimulationError> {
        let mut scratch = LoadScratch::default();
        let mut dy = vec![0.0; self.dimension()];
        let motions = self.evaluate(t, y, &mut dy, &mut scratch)?;
        Ok((scratch, motions))
    }

    /// [`tensions`](Self::tensions) from an evaluation's `scratch` and
    /// `motions` ([`evaluated`](Self::evaluated)).
    pub(super) fn tensions_in(
        &self,
        scratch: &LoadScratch,
        motions: &[PlaneMotion; 3],
    ) -> [TrackTensions; 2] {
        let d = &self.dynamics;
        let descriptions = [d.right.model().description(), d.left.model().description()];
        [0, 1].map(|s| {
            let tensions: Vec<f64> = joint_tensions(
                &scratch.joint_forces[s],
                &descriptions[s].link_spans().unwrap_or_default(),
                motions[1 + s].trig(),
            )
            .collect();
            let largest = tensions.iter().copied().fold(f64::NEG_INFINITY, f64::max);
            let spans = d.sprockets[s].and_then(|sprocket| {
                let (frame, links) = (&scratch.bodies[0], &scratch.bodies[1 + s]);
                let centre = frame.centroid(sprocket.body);
                let normal = frame.axis(sprocket.body, 1);
                let offsets: Vec<f64> = forward_joints(&descriptions[s])
                    .iter()
                    .enumerate()
                    .map(|(k, u2)| {
                        let r = links.point(k, *u2) - centre;
                        ((r - r.dot(&normal) * normal).norm() - sprocket.pitch_radius).abs()
                    })
                    .collect();
                seated_run(&offsets)
            });
            let (tight, slack) = match spans {
                Some((before, after)) => (tensions[after], tensions[before]),
                None => (f64::NAN, f64::NAN),
            };
            TrackTensions {
                tight,
                slack,
                largest,
            }
        })
    }
}

/// Every link's forward joint `ū2` in its own frame, m (none for a tree
/// that is no track).
fn forward_joints(description: &TreeDescription) -> Vec<Vector2<f64>> {
    description
        .joints()
        .map(|joints| joints.into_iter().map(|(_, u2)| u2).collect())
        .unwrap_or_default()
}
