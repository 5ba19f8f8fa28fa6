//! Contact between the track and the world (paper part II, which we design
//! here; formulation §4), in two stages:
//!
//! 1. **Detection** ([`ground`], [`wheel`], [`sprocket`]): from the bodies'
//!    states, every [`Contact`] — which link and which other body, the
//!    point, how deep, which way the normal force pushes and how fast the
//!    link's point moves against the other's. Geometry only: the assembly
//!    measures its start with the same functions.
//! 2. **Response** ([`ContactLaws::respond`], and on soft soil
//!    [`soft_ground`]): the laws ([`crate::laws`]) turn each contact into a
//!    [`ContactForce`] — the force with the elastic energy it stores and
//!    the power it dissipates — applied to both bodies' loads.
//!
//! The pairs: the shoes' ground points against a terrain, the shoes' inner
//! faces against wheel rims (road wheels, idler, rollers), the shoes' pins
//! against the sprocket's teeth; and the terramechanics laws of soft soil
//! ([`soil`](crate::terrain::soil)). In space, a shoe's point against a
//! height field ([`space`]), and on soft soil ([`soft_space`], its rut
//! an area: [`rut_grid`]); a wheel's rim on a shoe's face and a shoe's
//! pin on the sprocket's teeth across their two planes, with the track's
//! centre guide ([`axial`]). Forces come from positions and velocities only, as
//! [`BodyLoad`](crate::multibody::BodyLoad)s on both bodies, so the subsystems stay
//! decoupled everywhere else (formulation §3).

pub mod axial;
mod detect;
pub mod ground;
pub mod outline;
mod respond;
pub mod rut_grid;
pub mod shoe;
pub mod soft_ground;
pub mod soft_space;
pub mod space;
pub mod sprocket;
pub(crate) mod tangent;
pub mod wheel;

pub use detect::Contact;
pub use respond::{ContactForce, ContactLaws, GroundFriction, GroundLaws};
pub use shoe::ShoeGeometry;
pub use tangent::{ContactJacobian, GeometryTangent};

use nalgebra::Vector2;

use crate::planar::{Rotation, spin};

/// A body in motion: where it is and how fast it moves, its rotation
/// computed once.
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
    /// `A(θ)`, by its `(sin θ, cos θ)`.
    rotation: Rotation,
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
        sin_cos: (f64, f64),
        velocity: Vector2<f64>,
        omega: f64,
    ) -> Self {
        BodyState {
            position,
            angle,
            velocity,
            omega,
            rotation: Rotation::from_sin_cos(sin_cos),
        }
    }

    /// The body at rest: no velocity.
    pub fn at_rest(position: Vector2<f64>, angle: f64) -> Self {
        Self::new(position, angle, Vector2::zeros(), 0.0)
    }

    /// `(sin θ, cos θ)`.
    pub fn sin_cos(&self) -> (f64, f64) {
        self.rotation.sin_cos()
    }

    /// `A(θ)`.
    pub fn rotation(&self) -> Rotation {
        self.rotation
    }

    /// The global offset `A ū` of body point `ū` from the centroid.
    #[inline]
    pub fn arm(&self, local: Vector2<f64>) -> Vector2<f64> {
        self.rotation.apply(local)
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
        self.velocity + spin(self.omega, arm)
    }
}

/// The contact of link `i` with the chassis body `body` (`other` its
/// state) at `point`, whose unit `normal` pushes the link out, `depth`
/// deep: the arms from both centroids and the relative velocity of the
/// two material points there.
#[inline]
pub(crate) fn between(
    (i, link): (usize, &BodyState),
    (body, other): (usize, &BodyState),
    (feature, point, normal, depth): (usize, Vector2<f64>, Vector2<f64>, f64),
) -> Contact {
    let arm = point - link.position;
    Contact {
        link: i,
        other: Some(body),
        feature,
        point,
        arm,
        depth,
        gradient: normal,
        gradient_norm: 1.0,
        velocity: link.velocity_at(arm) - other.velocity_at(point - other.position),
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
/// Four links at a time in AVX where the processor has it, else two in
/// SSE2 (every x86-64 processor has that): in SSE2 the culling was a
/// sixteenth of the M113's evaluation (six rims and the sprocket against
/// 64 links, 20 instructions a pair; 5 a link in AVX), and
/// a link per iteration, its position loaded from a 64-byte state, is less
/// than half the speed. The comparison is the same each way (`cmpngt` is
/// `!(a > b)`, true for NaN; `d²` is `dx² + dy²` in that order, with no
/// fused multiply-add), so the mask is the same bits;
/// [`near_mask_portable`] is the definition, and the unit test holds every
/// build equal to it.
#[inline]
fn near_mask(block: &[BodyState], centre: Vector2<f64>, reach2: f64) -> u64 {
    debug_assert!(block.len() <= 64);
    #[cfg(all(target_arch = "x86_64", target_feature = "sse2"))]
    {
        if std::arch::is_x86_feature_detected!("avx") {
            // SAFETY: the processor has AVX, checked just above.
            return unsafe { near_mask_avx(block, centre, reach2) };
        }
        // SAFETY: the `cfg` has just established SSE2.
        unsafe { near_mask_sse2(block, centre, reach2) }
    }
    #[cfg(not(all(target_arch = "x86_64", target_feature = "sse2")))]
    near_mask_portable(block, centre, reach2)
}

/// [`near_mask`] a link at a time, in plain arithmetic.
#[inline]
// `!(d² > r²)` is meant: true for NaN, so a NaN state is looked at.
#[allow(clippy::neg_cmp_op_on_partial_ord)]
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

/// [`near_mask`] four links at a time: two pairs of positions in a
/// register each, `(x₀, y₀, x₂, y₂)` and `(x₁, y₁, x₃, y₃)`; unpacked by
/// lane their squares give `(dx₀², dx₁², dx₂², dx₃²)` and the same of
/// `dy`, whose sum is the four squared distances in order. The last
/// `len mod 4` links go [`near_mask_sse2`]'s way.
#[cfg(all(target_arch = "x86_64", target_feature = "sse2"))]
#[target_feature(enable = "avx")]
fn near_mask_avx(block: &[BodyState], centre: Vector2<f64>, reach2: f64) -> u64 {
    use std::arch::x86_64::{
        _CMP_NGT_UQ, _mm_set_pd, _mm256_add_pd, _mm256_cmp_pd, _mm256_movemask_pd, _mm256_mul_pd,
        _mm256_set_m128d, _mm256_set_pd, _mm256_set1_pd, _mm256_sub_pd, _mm256_unpackhi_pd,
        _mm256_unpacklo_pd,
    };
    let c = _mm256_set_pd(centre.y, centre.x, centre.y, centre.x);
    let r = _mm256_set1_pd(reach2);
    let position = |link: &BodyState| _mm_set_pd(link.position.y, link.position.x);
    let mut near = 0u64;
    let quads = block.chunks_exact(4);
    let rest = quads.remainder();
    for (k, quad) in quads.enumerate() {
        let even = _mm256_sub_pd(_mm256_set_m128d(position(&quad[2]), position(&quad[0])), c);
        let odd = _mm256_sub_pd(_mm256_set_m128d(position(&quad[3]), position(&quad[1])), c);
        let (even, odd) = (_mm256_mul_pd(even, even), _mm256_mul_pd(odd, odd));
        let squared = _mm256_add_pd(_mm256_unpacklo_pd(even, odd), _mm256_unpackhi_pd(even, odd));
        // `_CMP_NGT_UQ`: not greater, or unordered (NaN): `cmpngt`.
        let mask = _mm256_movemask_pd(_mm256_cmp_pd::<_CMP_NGT_UQ>(squared, r));
        near |= (mask as u64) << (4 * k);
    }
    if !rest.is_empty() {
        near |= near_mask_sse2(rest, centre, reach2) << (block.len() - rest.len());
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
            #[cfg(all(target_arch = "x86_64", target_feature = "sse2"))]
            {
                // SAFETY: the `cfg` has just established SSE2.
                let sse2 = unsafe { near_mask_sse2(block, centre, reach2) };
                assert_eq!(sse2, plain, "{len} links, SSE2");
                if std::arch::is_x86_feature_detected!("avx") {
                    // SAFETY: the processor has AVX, checked just above.
                    let avx = unsafe { near_mask_avx(block, centre, reach2) };
                    assert_eq!(avx, plain, "{len} links, AVX");
                }
            }
            if len > 8 {
                assert_ne!(plain, 0, "some links near");
                assert_ne!(plain, u64::MAX >> (64 - len), "some links far");
            }
        }
    }
}
