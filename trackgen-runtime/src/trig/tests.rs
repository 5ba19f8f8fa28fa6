//! `sin_cos` (fdlibm's kernels after a branch-free three-part reduction)
//! against the standard library's `f64::sin_cos`.
//!
//! Both are within one unit in the last place (ulp) of the exact values,
//! so they may differ by up to two ulps of the result; the test allows
//! exactly that, everywhere in `|x| ≤ FAST_RANGE`: random arguments, the
//! neighbourhoods of multiples of π/2 (where sine or cosine is tiny and a
//! reduction that loses bits would show as many ulps), tiny arguments and
//! signed zeros. Beyond `FAST_RANGE`, infinities and NaN it must be the
//! standard library's result (or NaN for NaN).

use super::{FAST_RANGE, sin_cos};

/// Distance in units in the last place between two finite values of the
/// same sign (or a zero).
fn ulps(a: f64, b: f64) -> u64 {
    if a == b {
        return 0;
    }
    if a.signum() != b.signum() {
        // Across zero: count both sides.
        return ulps(a, 0.0_f64.copysign(a)) + ulps(b, 0.0_f64.copysign(b));
    }
    a.to_bits().abs_diff(b.to_bits())
}

fn check(x: f64, worst: &mut u64) {
    let (s, c) = sin_cos(x);
    let (ss, cc) = x.sin_cos();
    let d = ulps(s, ss).max(ulps(c, cc));
    assert!(
        d <= 2,
        "sin_cos({x:e}) = ({s:e}, {c:e}), std ({ss:e}, {cc:e}): {d} ulps"
    );
    *worst = (*worst).max(d);
}

/// A deterministic generator (no dependency for one test).
struct Lcg(u64);
impl Lcg {
    fn uniform(&mut self, lo: f64, hi: f64) -> f64 {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        lo + (hi - lo) * ((self.0 >> 11) as f64 / (1u64 << 53) as f64)
    }
}

#[test]
fn agrees_with_the_standard_library_within_two_ulps() {
    let mut rng = Lcg(7);
    let mut worst = 0;
    for range in [1.0, 10.0, 1e3, 1e5, FAST_RANGE] {
        for _ in 0..200_000 {
            check(rng.uniform(-range, range), &mut worst);
        }
    }
    // Near multiples of π/2 up to the range, where the reduction cancels:
    // the neighbours of the double nearest k π/2.
    for k in (0..2_000_000_i64).step_by(997).chain([1, 2, 3, 4, 524_287]) {
        let centre = k as f64 * std::f64::consts::FRAC_PI_2;
        if centre > FAST_RANGE {
            continue;
        }
        let mut x = centre;
        for _ in 0..8 {
            check(x, &mut worst);
            check(-x, &mut worst);
            x = f64::from_bits(x.to_bits() + 1);
        }
    }
    for x in [
        0.0,
        -0.0,
        1e-300,
        -1e-300,
        5e-324,
        1e-9,
        std::f64::consts::FRAC_PI_4,
    ] {
        check(x, &mut worst);
    }
    println!("largest difference from std: {worst} ulps");
}

#[test]
fn beyond_the_range_it_is_the_standard_library() {
    for x in [FAST_RANGE * 1.000_001, 1e7, -3e15, 1e300, f64::MAX] {
        assert_eq!(sin_cos(x), x.sin_cos(), "{x}");
    }
    for x in [f64::INFINITY, f64::NEG_INFINITY, f64::NAN] {
        let (s, c) = sin_cos(x);
        assert!(s.is_nan() && c.is_nan(), "{x}: ({s}, {c})");
    }
}
