//! Shared helpers of the integration tests.
#![allow(dead_code)]

use trackgen::nalgebra::{DMatrix, DVector, SMatrix, SVector};

/// Norm-wise relative agreement: `max |a − b| ≤ rel · max(|b|_max, floor)`.
/// Comparing against the largest entry (not entry by entry) is the right
/// scale for rounding error in sums of products: an entry that is the
/// small difference of large terms carries the large terms' error.
pub fn assert_close(label: &str, got: &[f64], want: &[f64], rel: f64, floor: f64) {
    assert_eq!(got.len(), want.len(), "{label}: length");
    let scale = want.iter().fold(floor, |m, v| m.max(v.abs()));
    let (worst, at) = got
        .iter()
        .zip(want)
        .enumerate()
        .map(|(i, (g, w))| ((g - w).abs(), i))
        .fold((0.0f64, 0), |a, b| if b.0 > a.0 { b } else { a });
    assert!(
        worst <= rel * scale && got.iter().all(|g| g.is_finite()),
        "{label}: entry {at} differs by {worst:e} (got {}, want {}), allowed {:e}",
        got[at],
        want[at],
        rel * scale
    );
}

pub fn dvec<const D: usize>(v: &SVector<f64, D>) -> DVector<f64> {
    DVector::from_column_slice(v.as_slice())
}

pub fn dmat<const D: usize>(m: &SMatrix<f64, D, D>) -> DMatrix<f64> {
    DMatrix::from_column_slice(D, D, m.as_slice())
}

/// A deterministic generator for test states where proptest is not used.
pub struct Lcg(u64);

impl Lcg {
    pub fn new(seed: u64) -> Self {
        Lcg(seed
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407))
    }

    /// Uniform in `[lo, hi)`.
    pub fn uniform(&mut self, lo: f64, hi: f64) -> f64 {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        lo + (hi - lo) * ((self.0 >> 11) as f64 / (1u64 << 53) as f64)
    }

    pub fn state<const D: usize>(&mut self) -> (SVector<f64, D>, SVector<f64, D>) {
        let q = SVector::from_fn(|i, _| {
            if i < 2 {
                self.uniform(-2.0, 2.0)
            } else {
                self.uniform(-3.2, 3.2)
            }
        });
        let qd = SVector::from_fn(|_, _| self.uniform(-3.0, 3.0));
        (q, qd)
    }
}
