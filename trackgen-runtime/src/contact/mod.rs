//! Contact between the track and the world (paper part II, which we design
//! here; spec §4): the normal and friction laws, the terrain, and the three
//! contact pairs — link and ground, link and wheel (road wheels, idler,
//! rollers), link pins and sprocket teeth; and the terramechanics laws of
//! soft soil ([`soil`]).
//!
//! Every pair evaluates forces from positions and velocities only, and
//! returns them as [`BodyLoad`](crate::BodyLoad)s on both bodies, so the
//! subsystems stay decoupled everywhere else (spec §3).

pub mod ground;
pub mod law;
pub mod shoe;
pub mod soft_ground;
pub mod soil;
pub mod sprocket;
pub mod terrain;
pub mod wheel;

pub use law::{Friction, NormalLaw};
pub use shoe::ShoeGeometry;
pub use terrain::{Terrain, TerrainError};

use nalgebra::Vector2;

/// A body in motion: where it is and how fast it moves.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BodyState {
    /// Centroid, m.
    pub position: Vector2<f64>,
    /// Angle, rad.
    pub angle: f64,
    /// Centroid velocity, m/s.
    pub velocity: Vector2<f64>,
    /// Angular velocity, rad/s.
    pub omega: f64,
    /// `sin` and `cos` of the angle, computed once.
    sin: f64,
    cos: f64,
}

impl BodyState {
    /// A body at `position` (m) and `angle` (rad), moving at `velocity`
    /// (m/s) and `omega` (rad/s).
    pub fn new(position: Vector2<f64>, angle: f64, velocity: Vector2<f64>, omega: f64) -> Self {
        Self::with_sin_cos(position, angle, angle.sin_cos(), velocity, omega)
    }

    /// [`new`](Self::new), given `(sin θ, cos θ)` already.
    pub fn with_sin_cos(
        position: Vector2<f64>,
        angle: f64,
        (sin, cos): (f64, f64),
        velocity: Vector2<f64>,
        omega: f64,
    ) -> Self {
        BodyState {
            position,
            angle,
            velocity,
            omega,
            sin,
            cos,
        }
    }

    /// `(sin θ, cos θ)`.
    pub fn sin_cos(&self) -> (f64, f64) {
        (self.sin, self.cos)
    }

    /// The global offset `A ū` of body point `ū` from the centroid.
    #[inline]
    pub fn arm(&self, local: Vector2<f64>) -> Vector2<f64> {
        crate::planar::rotate_by((self.sin, self.cos), local)
    }

    /// Global position of body point `ū`.
    #[inline]
    pub fn point(&self, local: Vector2<f64>) -> Vector2<f64> {
        self.position + self.arm(local)
    }

    /// Velocity of the material point at global offset `arm` from the
    /// centroid: `Ṙ + ω × arm`.
    #[inline]
    pub fn velocity_at(&self, arm: Vector2<f64>) -> Vector2<f64> {
        self.velocity + Vector2::new(-arm.y, arm.x) * self.omega
    }
}

/// Calls `f(i, link)` for every link whose centroid is within `reach` (m)
/// of `centre`, in order, and for any whose distance is not a number (so a
/// NaN state shows as a NaN force). The distances are compared 64 links at
/// a time into a bit mask without branches ([`near_mask`]), then the few
/// links near are visited: a wheel is near a handful of a track's links,
/// and a branch per link mispredicts at the edges of every run of them.
#[inline]
pub(crate) fn each_near(
    links: &[BodyState],
    centre: Vector2<f64>,
    reach: f64,
    mut f: impl FnMut(usize, &BodyState),
) {
    let reach2 = reach * reach;
    for (chunk, block) in links.chunks(64).enumerate() {
        let mut near = near_mask(block, centre, reach2);
        while near != 0 {
            let k = near.trailing_zeros() as usize;
            near &= near - 1;
            f(chunk * 64 + k, &block[k]);
        }
    }
}

/// Bit `k` set where `!(|r_k − centre|² > reach2)` for the (at most 64)
/// links of `block`: the link is near, or its distance is NaN.
///
/// Two links at a time in SSE2 on x86-64 (every x86-64 processor has it):
/// the culling is a twentieth of a vehicle's evaluation, and a link per
/// iteration, its position loaded from a 64-byte state, half the speed.
/// The comparison is the same either way (`cmpngt` is `!(a > b)`, true for
/// NaN), so the mask is the same bits; [`near_mask_portable`] is the
/// definition, and the unit test holds them equal.
#[inline]
fn near_mask(block: &[BodyState], centre: Vector2<f64>, reach2: f64) -> u64 {
    debug_assert!(block.len() <= 64);
    #[cfg(all(target_arch = "x86_64", target_feature = "sse2"))]
    {
        // SAFETY: the `cfg` has just established SSE2.
        unsafe { near_mask_sse2(block, centre, reach2) }
    }
    #[cfg(not(all(target_arch = "x86_64", target_feature = "sse2")))]
    near_mask_portable(block, centre, reach2)
}

/// [`near_mask`] a link at a time, in plain arithmetic.
#[inline]
fn near_mask_portable(block: &[BodyState], centre: Vector2<f64>, reach2: f64) -> u64 {
    let mut near = 0u64;
    for (k, link) in block.iter().enumerate() {
        let (dx, dy) = (link.position.x - centre.x, link.position.y - centre.y);
        // `!(d² > r²)`: true for NaN.
        near |= u64::from(!(dx * dx + dy * dy > reach2)) << k;
    }
    near
}

/// [`near_mask`] two links at a time: both squared distances in one
/// register, compared at once, their two sign bits moved into the mask.
#[cfg(all(target_arch = "x86_64", target_feature = "sse2"))]
#[target_feature(enable = "sse2")]
#[inline]
fn near_mask_sse2(block: &[BodyState], centre: Vector2<f64>, reach2: f64) -> u64 {
    use std::arch::x86_64::{
        _mm_add_pd, _mm_cmpngt_pd, _mm_movemask_pd, _mm_mul_pd, _mm_set_pd, _mm_set1_pd,
        _mm_sub_pd, _mm_unpackhi_pd, _mm_unpacklo_pd,
    };
    let c = _mm_set_pd(centre.y, centre.x);
    let r = _mm_set1_pd(reach2);
    let offset = |link: &BodyState| {
        let d = _mm_sub_pd(_mm_set_pd(link.position.y, link.position.x), c);
        _mm_mul_pd(d, d)
    };
    let mut near = 0u64;
    let pairs = block.chunks_exact(2);
    let odd = pairs.remainder();
    for (k, pair) in pairs.enumerate() {
        let (a, b) = (offset(&pair[0]), offset(&pair[1]));
        // (dx_a² + dy_a², dx_b² + dy_b²), in the scalar order of terms.
        let squared = _mm_add_pd(_mm_unpacklo_pd(a, b), _mm_unpackhi_pd(a, b));
        near |= (_mm_movemask_pd(_mm_cmpngt_pd(squared, r)) as u64) << (2 * k);
    }
    if let [last] = odd {
        near |= near_mask_portable(std::slice::from_ref(last), centre, reach2) << (block.len() - 1);
    }
    near
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The vectorised mask is the plain one, bit for bit, on blocks of
    /// every length from 0 to 64 (odd ones end in a single link), with
    /// links on the reach exactly, NaN and infinite positions among them.
    #[test]
    fn near_mask_is_the_plain_comparison() {
        let centre = Vector2::new(0.3, -0.2);
        let reach2 = 0.25;
        // A deterministic spread of positions round the centre, some at
        // exactly the reach (0.5 along x), some NaN or infinite.
        let position = |k: usize| match k % 11 {
            3 => Vector2::new(centre.x + 0.5, centre.y),
            5 => Vector2::new(f64::NAN, 0.0),
            7 => Vector2::new(0.0, f64::INFINITY),
            _ => {
                let a = k as f64 * 0.7;
                let r = 0.1 + 0.09 * (k % 9) as f64;
                centre + Vector2::new(a.cos(), a.sin()) * r
            }
        };
        let links: Vec<BodyState> = (0..64)
            .map(|k| BodyState::new(position(k), 0.0, Vector2::zeros(), 0.0))
            .collect();
        for len in 0..=64 {
            let block = &links[..len];
            let plain = near_mask_portable(block, centre, reach2);
            assert_eq!(near_mask(block, centre, reach2), plain, "{len} links");
            if len > 8 {
                assert_ne!(plain, 0, "some links near");
                assert_ne!(plain, u64::MAX >> (64 - len), "some links far");
            }
        }
    }
}

/// One contact's force on the first body of the pair, at a global point.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactForce {
    /// Contact point, m.
    pub point: Vector2<f64>,
    /// Force on the first body (the track link), N.
    pub force: Vector2<f64>,
    /// Normal component (≥ 0), N.
    pub normal: f64,
    /// Penetration, m.
    pub penetration: f64,
    /// Power the contact dissipates (damping and friction), W.
    pub dissipation: f64,
    /// Elastic energy stored in the contact, J.
    pub potential: f64,
}

impl ContactForce {
    /// A contact's force from its laws: normal `n` (unit, on the first
    /// body), relative velocity `v` of the first body's point against the
    /// second's.
    pub(crate) fn evaluate(
        normal_law: &NormalLaw,
        friction: &Friction,
        point: Vector2<f64>,
        n: Vector2<f64>,
        penetration: f64,
        v: Vector2<f64>,
    ) -> ContactForce {
        let rate = -v.dot(&n);
        let fn_ = normal_law.force(penetration, rate);
        let t = Vector2::new(-n.y, n.x);
        let slip = v.dot(&t);
        let ft = friction.force(fn_, slip);
        // Power lost: the normal force beyond its elastic part times the
        // closing rate, and friction against slip.
        let dissipation = (fn_ - normal_law.elastic_force(penetration)) * rate - ft * slip;
        ContactForce {
            point,
            force: n * fn_ + t * ft,
            normal: fn_,
            penetration,
            dissipation,
            potential: normal_law.potential(penetration),
        }
    }
}

/// A contact between a link and another body (a wheel, the sprocket) at
/// `point` with `normal` (unit, on the link): the force from the laws on the
/// relative velocity, added to the link's load and, reversed, to the
/// other's.
pub(crate) fn exchange(
    (normal_law, friction): (&NormalLaw, &Friction),
    (link, link_load): (&BodyState, &mut crate::model::BodyLoad),
    (other, other_load): (&BodyState, &mut crate::model::BodyLoad),
    (point, normal, penetration): (Vector2<f64>, Vector2<f64>, f64),
) -> ContactForce {
    use crate::model::BodyLoad;
    let (link_arm, other_arm) = (point - link.position, point - other.position);
    let relative = link.velocity_at(link_arm) - other.velocity_at(other_arm);
    let contact =
        ContactForce::evaluate(normal_law, friction, point, normal, penetration, relative);
    *link_load = link_load.plus(BodyLoad::force_at(contact.force, link_arm));
    *other_load = other_load.plus(BodyLoad::force_at(-contact.force, other_arm));
    contact
}
