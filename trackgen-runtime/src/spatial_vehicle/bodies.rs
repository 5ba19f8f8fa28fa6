//! Every body of a tree in the world at a state, as the force elements
//! read it: each centroid, orientation, velocity and angular velocity.

use nalgebra::{Vector2, Vector3};

use crate::multibody::RecursiveModel;
use crate::spatial::{FloatingTree, PlaneMotion, PlanePose, PlaneRates, SpatialLoad, WorldMotion};

/// Every body's world motion: centroid, orientation, velocity, angular
/// velocity ([`WorldMotion`]). Kept between evaluations, refilled in
/// place ([`fill`](Self::fill)).
#[derive(Default)]
pub(super) struct Bodies {
    world: WorldMotion,
}

impl Bodies {
    /// `tree`'s bodies at `state` (its pose and rates), their `motion` in
    /// their plane found already, into these bodies, their vectors'
    /// storage kept.
    pub(super) fn fill<M: RecursiveModel<D>, const D: usize>(
        &mut self,
        tree: &FloatingTree<'_, M, D>,
        motion: &PlaneMotion,
        (pose, rates): (&PlanePose<D>, &PlaneRates<D>),
    ) {
        tree.world_into(motion, pose, rates, &mut self.world);
    }

    /// `tree`'s bodies at `state`, new ([`FloatingTree::world`]).
    pub(super) fn at<M: RecursiveModel<D>, const D: usize>(
        tree: &FloatingTree<'_, M, D>,
        (pose, rates): (&PlanePose<D>, &PlaneRates<D>),
    ) -> Bodies {
        Bodies {
            world: tree.world(pose, rates),
        }
    }

    /// How many bodies.
    pub(super) fn len(&self) -> usize {
        self.world.positions.len()
    }

    /// Body `k`'s centroid, m.
    #[inline]
    pub(super) fn centroid(&self, k: usize) -> Vector3<f64> {
        self.world.positions[k]
    }

    /// Every centroid, m.
    pub(super) fn centroids(&self) -> &[Vector3<f64>] {
        &self.world.positions
    }

    /// Every centroid's velocity, m/s.
    pub(super) fn velocities(&self) -> &[Vector3<f64>] {
        &self.world.velocities
    }

    /// Body `k`'s velocity, m/s.
    #[inline]
    pub(super) fn velocity(&self, k: usize) -> Vector3<f64> {
        self.world.velocities[k]
    }

    /// Body `k`'s angular velocity, rad/s.
    #[inline]
    pub(super) fn spin(&self, k: usize) -> Vector3<f64> {
        self.world.angular_velocities[k]
    }

    /// Body `k`'s axis `i` (0 its `x`, 1 the plane's normal, 2 its `y`).
    #[inline]
    pub(super) fn axis(&self, k: usize, i: usize) -> Vector3<f64> {
        self.world.orientations[k].column(i).into()
    }

    /// The world point of body `k`'s local point `(p.x, across, p.y)`:
    /// along its `x`, the plane's normal and its `y`. Always inlined: the
    /// rims' and teeth's loops call it a million times a second, and left
    /// to the compiler's choice it was called out of line once the
    /// tensions called it too (1.8 % more instructions per evaluation).
    #[inline(always)]
    pub(super) fn point_across(&self, k: usize, p: Vector2<f64>, across: f64) -> Vector3<f64> {
        self.world.positions[k] + self.world.orientations[k] * Vector3::new(p.x, across, p.y)
    }

    /// The world point of body `k`'s local planar point `p`.
    #[inline(always)]
    pub(super) fn point(&self, k: usize, p: Vector2<f64>) -> Vector3<f64> {
        self.point_across(k, p, 0.0)
    }

    /// The velocity of body `k`'s material point at `x`.
    #[inline]
    pub(super) fn velocity_at(&self, k: usize, x: Vector3<f64>) -> Vector3<f64> {
        self.world.velocities[k]
            + self.world.angular_velocities[k].cross(&(x - self.world.positions[k]))
    }

    /// Adds `force` at `x` to body `k`'s load.
    #[inline]
    pub(super) fn push(
        &self,
        loads: &mut [SpatialLoad],
        k: usize,
        force: Vector3<f64>,
        x: Vector3<f64>,
    ) {
        loads[k].force += force;
        loads[k].moment += (x - self.world.positions[k]).cross(&force);
    }

    /// The bodies whose centroids are within `reach2` (m², squared) of
    /// `centre`, or at a distance that is not a number (so a NaN state
    /// shows as a NaN force), in order. The distances are compared 64
    /// bodies at a time into a bit mask without branches: a wheel is near
    /// a handful of a track's links, and a branch per link mispredicts at
    /// the edges of every run of them.
    pub(super) fn near(
        &self,
        centre: Vector3<f64>,
        reach2: f64,
    ) -> impl Iterator<Item = usize> + '_ {
        let centroids = &self.world.positions;
        centroids
            .chunks(64)
            .enumerate()
            .flat_map(move |(chunk, block)| {
                let mut near = near_mask(block, centre, reach2);
                std::iter::from_fn(move || {
                    (near != 0).then(|| {
                        let k = near.trailing_zeros() as usize;
                        near &= near - 1;
                        chunk * 64 + k
                    })
                })
            })
    }
}

/// Bit `k` set where body `k` of a block (at most 64) is within `reach2`
/// of `centre`, or at a distance that is not a number: `!(d² > r²)`, `d²`
/// summed `x`, `y`, `z` in turn as `Vector3::norm_squared` sums.
#[inline(always)]
fn near_mask(block: &[Vector3<f64>], centre: Vector3<f64>, reach2: f64) -> u64 {
    let mut near = 0u64;
    for (k, p) in block.iter().enumerate() {
        let (dx, dy, dz) = (p.x - centre.x, p.y - centre.y, p.z - centre.z);
        #[allow(clippy::neg_cmp_op_on_partial_ord)]
        let close = !(dx * dx + dy * dy + dz * dz > reach2);
        near |= u64::from(close) << k;
    }
    near
}
