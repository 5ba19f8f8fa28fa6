//! Every body of a tree in the world at a state, as the force elements
//! read it: each centroid, orientation, velocity and angular velocity,
//! and the centroids again by coordinate for the search of the bodies
//! near a part.

use nalgebra::{Vector2, Vector3};

use crate::multibody::RecursiveModel;
use crate::spatial::{FloatingTree, PlaneMotion, PlanePose, PlaneRates, SpatialLoad, WorldMotion};

/// Every body's world motion: centroid, orientation, velocity, angular
/// velocity ([`WorldMotion`]), and the centroids' coordinates each in a
/// vector of its own. Kept between evaluations, refilled in place
/// ([`fill`](Self::fill)).
#[derive(Default)]
pub(super) struct Bodies {
    world: WorldMotion,
    /// The centroids' `x`, `y` and `z`, m.
    by_axis: [Vec<f64>; 3],
}

impl Bodies {
    /// `tree`'s bodies at `state` (its pose and rates), their `motion` in
    /// their plane found already.
    pub(super) fn of<M: RecursiveModel<D>, const D: usize>(
        tree: &FloatingTree<'_, M, D>,
        motion: &PlaneMotion,
        state: (&PlanePose<D>, &PlaneRates<D>),
    ) -> Bodies {
        let mut bodies = Bodies::default();
        bodies.fill(tree, motion, state);
        bodies
    }

    /// [`of`](Self::of) into these bodies, their vectors' storage kept.
    pub(super) fn fill<M: RecursiveModel<D>, const D: usize>(
        &mut self,
        tree: &FloatingTree<'_, M, D>,
        motion: &PlaneMotion,
        (pose, rates): (&PlanePose<D>, &PlaneRates<D>),
    ) {
        tree.world_into(motion, pose, rates, &mut self.world);
        for (i, axis) in self.by_axis.iter_mut().enumerate() {
            axis.clear();
            axis.extend(self.world.positions.iter().map(|p| p[i]));
        }
    }

    /// [`of`](Self::of) with the tree's motion in its plane found here.
    pub(super) fn at<M: RecursiveModel<D>, const D: usize>(
        tree: &FloatingTree<'_, M, D>,
        (pose, rates): (&PlanePose<D>, &PlaneRates<D>),
    ) -> Bodies {
        Bodies::of(tree, &tree.plane_motion(pose, rates), (pose, rates))
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
    /// along its `x`, the plane's normal and its `y`.
    #[inline]
    pub(super) fn point_across(&self, k: usize, p: Vector2<f64>, across: f64) -> Vector3<f64> {
        self.world.positions[k] + self.world.orientations[k] * Vector3::new(p.x, across, p.y)
    }

    /// The world point of body `k`'s local planar point `p`.
    #[inline]
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
    /// bodies at a time into a bit mask without branches, a coordinate's
    /// vector at a time (four bodies per operation where the processor
    /// has AVX2): a wheel is near a handful of a track's links, and a
    /// branch per link mispredicts at the edges of every run of them.
    pub(super) fn near(
        &self,
        centre: Vector3<f64>,
        reach2: f64,
    ) -> impl Iterator<Item = usize> + '_ {
        let [x, y, z] = &self.by_axis;
        (0..x.len().div_ceil(64)).flat_map(move |chunk| {
            let block = chunk * 64..x.len().min(chunk * 64 + 64);
            let (x, y, z) = (&x[block.clone()], &y[block.clone()], &z[block]);
            let mut near = near_mask([x, y, z], centre, reach2);
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

/// Bit `k` set where body `k` of a block (at most 64, by coordinate) is
/// within `reach2` of `centre`, or at a distance that is not a number:
/// `!(d² > r²)`, `d²` summed `x`, `y`, `z` in turn as
/// `Vector3::norm_squared` sums.
#[inline(always)]
fn near_mask([x, y, z]: [&[f64]; 3], centre: Vector3<f64>, reach2: f64) -> u64 {
    let mut near = 0u64;
    for (k, ((x, y), z)) in x.iter().zip(y).zip(z).enumerate() {
        let (dx, dy, dz) = (x - centre.x, y - centre.y, z - centre.z);
        #[allow(clippy::neg_cmp_op_on_partial_ord)]
        let close = !(dx * dx + dy * dy + dz * dz > reach2);
        near |= u64::from(close) << k;
    }
    near
}
