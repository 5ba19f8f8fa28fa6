//! Which of a tree's bodies are near a point: the running gear's broad
//! phase in space (every rim, guide and sprocket against every link of
//! its side's track, each evaluation).
//!
//! The centroids are kept a coordinate to an array ([`Centroids`]), so
//! four bodies' squared distances are three loads, three subtractions,
//! three products and two sums in AVX: compared one body at a time the
//! broad phase was some 7 % of the 3-D M113's evaluation (ten parts a
//! side against 64 links). Every build compares the same numbers in the
//! same order (`d² = (dx² + dy²) + dz²`, no fused multiply-add; `cmpngt`
//! is `!(d² > r²)`, true for NaN, so a NaN state is looked at and shows
//! as a NaN force): [`near_mask_portable`] is the definition, and the
//! unit test holds every build equal to it.

use nalgebra::Vector3;

/// Every body's centroid, a coordinate to an array, m.
#[derive(Debug, Clone, Default)]
pub(super) struct Centroids {
    x: Vec<f64>,
    y: Vec<f64>,
    z: Vec<f64>,
}

impl Centroids {
    /// These centroids set to `positions`, their storage kept.
    pub(super) fn fill(&mut self, positions: &[Vector3<f64>]) {
        for (coordinate, i) in [&mut self.x, &mut self.y, &mut self.z].into_iter().zip(0..) {
            coordinate.clear();
            coordinate.extend(positions.iter().map(|p| p[i]));
        }
    }

    /// The bodies whose centroids are within `reach2` (m², squared) of
    /// `centre`, or at a distance that is not a number, in order.
    pub(super) fn near(&self, centre: Vector3<f64>, reach2: f64) -> Near<'_> {
        Near {
            centroids: self,
            centre,
            reach2,
            next_block: 0,
            block: 0,
            mask: 0,
        }
    }
}

/// The bodies near a point ([`Centroids::near`]): each block of 64
/// compared at once into a mask, its bits walked in order.
pub(super) struct Near<'a> {
    centroids: &'a Centroids,
    centre: Vector3<f64>,
    reach2: f64,
    /// The first body of the next block to compare.
    next_block: usize,
    /// The first body of the block whose mask is being walked.
    block: usize,
    mask: u64,
}

impl Iterator for Near<'_> {
    type Item = usize;

    #[inline]
    fn next(&mut self) -> Option<usize> {
        let c = self.centroids;
        while self.mask == 0 {
            let start = self.next_block;
            if start >= c.x.len() {
                return None;
            }
            let end = (start + 64).min(c.x.len());
            let block = [&c.x, &c.y, &c.z].map(|v| &v[start..end]);
            self.mask = near_mask(block, self.centre, self.reach2);
            (self.block, self.next_block) = (start, end);
        }
        let k = self.mask.trailing_zeros() as usize;
        self.mask &= self.mask - 1;
        Some(self.block + k)
    }
}

/// Bit `k` set where body `k` of a block (at most 64, its coordinates'
/// arrays of one length) is within `reach2` of `centre`, or at a
/// distance that is not a number: four bodies at a time in AVX where the
/// processor has it, else two in SSE2.
#[inline]
fn near_mask(block: [&[f64]; 3], centre: Vector3<f64>, reach2: f64) -> u64 {
    debug_assert!(block[0].len() <= 64);
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

/// [`near_mask`] a body at a time from `from`, in plain arithmetic, its
/// bits counted from `from`.
#[inline]
// `!(d² > r²)` is meant: true for NaN.
#[allow(clippy::neg_cmp_op_on_partial_ord)]
fn near_mask_portable_from(
    [x, y, z]: [&[f64]; 3],
    from: usize,
    centre: Vector3<f64>,
    reach2: f64,
) -> u64 {
    let mut near = 0u64;
    for k in from..x.len() {
        let (dx, dy, dz) = (x[k] - centre.x, y[k] - centre.y, z[k] - centre.z);
        near |= u64::from(!(dx * dx + dy * dy + dz * dz > reach2)) << k;
    }
    near
}

/// [`near_mask`] a body at a time, in plain arithmetic: the definition
/// (on x86-64, the tests' alone).
#[cfg_attr(
    all(target_arch = "x86_64", target_feature = "sse2", not(test)),
    allow(dead_code)
)]
fn near_mask_portable(block: [&[f64]; 3], centre: Vector3<f64>, reach2: f64) -> u64 {
    near_mask_portable_from(block, 0, centre, reach2)
}

/// [`near_mask`] two bodies at a time.
#[cfg(all(target_arch = "x86_64", target_feature = "sse2"))]
#[target_feature(enable = "sse2")]
#[inline]
fn near_mask_sse2(block: [&[f64]; 3], centre: Vector3<f64>, reach2: f64) -> u64 {
    use std::arch::x86_64::{
        _mm_add_pd, _mm_cmpngt_pd, _mm_loadu_pd, _mm_movemask_pd, _mm_mul_pd, _mm_set1_pd,
        _mm_sub_pd,
    };
    let n = block[0].len();
    let pairs = n / 2;
    let c = [centre.x, centre.y, centre.z].map(|c| _mm_set1_pd(c));
    let r = _mm_set1_pd(reach2);
    let mut near = 0u64;
    for k in 0..pairs {
        let d = [0, 1, 2].map(|i| {
            let at = &block[i][2 * k..2 * k + 2];
            // SAFETY: `at` holds two f64s; the load is unaligned.
            let d = _mm_sub_pd(unsafe { _mm_loadu_pd(at.as_ptr()) }, c[i]);
            _mm_mul_pd(d, d)
        });
        let squared = _mm_add_pd(_mm_add_pd(d[0], d[1]), d[2]);
        near |= (_mm_movemask_pd(_mm_cmpngt_pd(squared, r)) as u64) << (2 * k);
    }
    near | near_mask_portable_from(block, 2 * pairs, centre, reach2)
}

/// [`near_mask`] four bodies at a time; the last `len mod 4` a body at
/// a time.
#[cfg(all(target_arch = "x86_64", target_feature = "sse2"))]
#[target_feature(enable = "avx")]
fn near_mask_avx(block: [&[f64]; 3], centre: Vector3<f64>, reach2: f64) -> u64 {
    use std::arch::x86_64::{
        _CMP_NGT_UQ, _mm256_add_pd, _mm256_cmp_pd, _mm256_loadu_pd, _mm256_movemask_pd,
        _mm256_mul_pd, _mm256_set1_pd, _mm256_sub_pd,
    };
    let n = block[0].len();
    let quads = n / 4;
    let c = [centre.x, centre.y, centre.z].map(|c| _mm256_set1_pd(c));
    let r = _mm256_set1_pd(reach2);
    let mut near = 0u64;
    for k in 0..quads {
        let d = [0, 1, 2].map(|i| {
            let at = &block[i][4 * k..4 * k + 4];
            // SAFETY: `at` holds four f64s; the load is unaligned.
            let d = _mm256_sub_pd(unsafe { _mm256_loadu_pd(at.as_ptr()) }, c[i]);
            _mm256_mul_pd(d, d)
        });
        let squared = _mm256_add_pd(_mm256_add_pd(d[0], d[1]), d[2]);
        // `_CMP_NGT_UQ`: not greater, or unordered (NaN): `cmpngt`.
        let mask = _mm256_movemask_pd(_mm256_cmp_pd::<_CMP_NGT_UQ>(squared, r));
        near |= (mask as u64) << (4 * k);
    }
    near | near_mask_portable_from(block, 4 * quads, centre, reach2)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every build's mask is the plain one, bit for bit, on blocks of
    /// every length from 0 to 64 (each remainder of four), with bodies
    /// on the reach exactly, NaN and infinite coordinates among them; and
    /// `near` walks a tree of more than 64 bodies in order.
    #[test]
    fn near_mask_is_the_plain_comparison() {
        let centre = Vector3::new(0.3, -0.2, 0.4);
        let reach2 = 0.25;
        let position = |k: usize| match k % 11 {
            3 => Vector3::new(centre.x, centre.y + 0.5, centre.z),
            5 => Vector3::new(0.0, f64::NAN, 0.0),
            7 => Vector3::new(0.0, 0.0, f64::INFINITY),
            _ => {
                let a = k as f64 * 0.7;
                let r = 0.1 + 0.09 * (k % 9) as f64;
                centre + Vector3::new(a.cos(), a.sin() * 0.6, a.sin() * 0.8) * r
            }
        };
        let positions: Vec<Vector3<f64>> = (0..130).map(position).collect();
        let mut centroids = Centroids::default();
        centroids.fill(&positions);
        for len in 0..=64 {
            let block = [&centroids.x, &centroids.y, &centroids.z].map(|c| &c[..len]);
            let plain = near_mask_portable(block, centre, reach2);
            assert_eq!(near_mask(block, centre, reach2), plain, "{len} bodies");
            #[cfg(all(target_arch = "x86_64", target_feature = "sse2"))]
            {
                // SAFETY: the `cfg` has just established SSE2.
                let sse2 = unsafe { near_mask_sse2(block, centre, reach2) };
                assert_eq!(sse2, plain, "{len} bodies, SSE2");
                if std::arch::is_x86_feature_detected!("avx") {
                    // SAFETY: the processor has AVX, checked just above.
                    let avx = unsafe { near_mask_avx(block, centre, reach2) };
                    assert_eq!(avx, plain, "{len} bodies, AVX");
                }
            }
            if len > 8 {
                assert_ne!(plain, 0, "some bodies near");
                assert_ne!(plain, u64::MAX >> (64 - len), "some bodies far");
            }
        }
        let walked: Vec<usize> = centroids.near(centre, reach2).collect();
        #[allow(clippy::neg_cmp_op_on_partial_ord)]
        let each: Vec<usize> = (0..positions.len())
            .filter(|&k| !((positions[k] - centre).norm_squared() > reach2))
            .collect();
        assert_eq!(walked, each);
    }
}
