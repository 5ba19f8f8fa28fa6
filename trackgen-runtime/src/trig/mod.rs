//! The sine and cosine of every body's angle, the one transcendental
//! function of the dynamics: each evaluation of a vehicle takes one pair
//! per body, and the C library's `sincos` neither inlines nor vectorises.
//!
//! [`sin_cos`] is the C library's method without its branches: the
//! argument reduced by `π/2` in three parts (Cody & Waite, with the
//! constants and the tail correction of fdlibm's `__ieee754_rem_pio2`),
//! then fdlibm's minimax kernels `__kernel_sin` and `__kernel_cos` on
//! `[−π/4, π/4]` (error below 2⁻⁵⁸ relative), and the quadrant chosen by
//! selects, not jumps. Its results are within one unit in the last place
//! of the exact values for `|x| ≤` [`FAST_RANGE`] (tested against the
//! standard library's, which are within one unit too); beyond it, and for
//! infinities, it is `f64::sin_cos`. Being branch-free, a loop of them
//! vectorises.
//!
//! The polynomial coefficients and reduction constants are fdlibm's:
//!
//! ```text
//! Copyright (C) 1993 by Sun Microsystems, Inc. All rights reserved.
//!
//! Developed at SunPro, a Sun Microsystems, Inc. business.
//! Permission to use, copy, modify, and distribute this
//! software is freely granted, provided that this notice
//! is preserved.
//! ```

/// The largest `|x|` reduced here, rad: `2¹⁹ π/2`, fdlibm's bound for the
/// three-part reduction (a track's links turn through 2π each lap; an
/// hour at 3 m/s on the M113 is ~7000 rad).
pub const FAST_RANGE: f64 = 823_549.6;

// The constants by their bits, as fdlibm gives them.
const INV_PIO2: f64 = std::f64::consts::FRAC_2_PI;
/// π/2 in parts: the first 33 bits, the next 33, the next 33 and the rest.
const PIO2_1: f64 = f64::from_bits(0x3FF9_21FB_5440_0000);
const PIO2_2: f64 = f64::from_bits(0x3DD0_B461_1A60_0000);
const PIO2_3: f64 = f64::from_bits(0x3BA3_198A_2E00_0000);
const PIO2_3T: f64 = f64::from_bits(0x397B_839A_2520_49C1);
/// `1.5 · 2⁵²`: adding it rounds to an integer held in the low mantissa
/// bits.
const TO_INT: f64 = 6_755_399_441_055_744.0;

const S1: f64 = f64::from_bits(0xBFC5_5555_5555_5549);
const S2: f64 = f64::from_bits(0x3F81_1111_1110_F8A6);
const S3: f64 = f64::from_bits(0xBF2A_01A0_19C1_61D5);
const S4: f64 = f64::from_bits(0x3EC7_1DE3_57B1_FE7D);
const S5: f64 = f64::from_bits(0xBE5A_E5E6_8A2B_9CEB);
const S6: f64 = f64::from_bits(0x3DE5_D93A_5ACF_D57C);

const C1: f64 = f64::from_bits(0x3FA5_5555_5555_554C);
const C2: f64 = f64::from_bits(0xBF56_C16C_16C1_5177);
const C3: f64 = f64::from_bits(0x3EFA_01A0_19CB_1590);
const C4: f64 = f64::from_bits(0xBE92_7E4F_809C_52AD);
const C5: f64 = f64::from_bits(0x3E21_EE9E_BDB4_B1C4);
const C6: f64 = f64::from_bits(0xBDA8_FAE9_BE88_38D4);

/// `(sin x, cos x)`, within one unit in the last place (see the module
/// docs); `f64::sin_cos` beyond 2¹⁹ π/2 (fdlibm's bound for the three-part
/// reduction).
#[inline]
pub fn sin_cos(x: f64) -> (f64, f64) {
    if x.abs() > FAST_RANGE {
        return x.sin_cos();
    }
    reduced_sin_cos(x)
}

/// The branch-free method, for `|x| ≤ FAST_RANGE` (or NaN, which it
/// returns).
#[inline(always)]
fn reduced_sin_cos(x: f64) -> (f64, f64) {
    // n = round(x · 2/π); its low bits give the quadrant.
    let shifted = x * INV_PIO2 + TO_INT;
    let quadrant = shifted.to_bits();
    let n = shifted - TO_INT;
    // y = x − n π/2 as the unevaluated sum y0 + y1, with π/2 to 151 bits
    // as PIO2_1 + PIO2_2 + PIO2_3 + PIO2_3T (fdlibm's third round): the
    // first three have 33 bits, so their products with n < 2²⁰ are exact,
    // x − n·PIO2_1 is exact (Sterbenz), and the rounding of the next two
    // subtractions is kept by TwoSum, so no cancellation loses bits.
    let t = x - n * PIO2_1;
    let (s1, e1) = two_sum(t, -(n * PIO2_2));
    let (s2, e2) = two_sum(s1, -(n * PIO2_3));
    let tail = e1 + e2 - n * PIO2_3T;
    let y0 = s2 + tail;
    let y1 = (s2 - y0) + tail;
    let (s, c) = (kernel_sin(y0, y1), kernel_cos(y0, y1));
    // Quadrant 0: (s, c); 1: (c, −s); 2: (−s, −c); 3: (−c, s). As bit
    // operations, so that a loop of them vectorises (SSE2 has no 64-bit
    // compares): swap when bit 0 of n is set, then flip the sine's sign by
    // bit 1 of n and the cosine's by bit 1 of n + 1.
    let swap = 0u64.wrapping_sub(quadrant & 1);
    let (s, c) = (s.to_bits(), c.to_bits());
    let sin = (c & swap) | (s & !swap);
    let cos = (s & swap) | (c & !swap);
    (
        f64::from_bits(sin ^ ((quadrant >> 1) << 63)),
        f64::from_bits(cos ^ (((quadrant + 1) >> 1) << 63)),
    )
}

/// [`sin_cos`] of every angle (rad) into `out`: one vectorised pass, then
/// the standard library for any beyond 2¹⁹ π/2.
///
/// On x86-64 processors with AVX2 the pass runs four angles at a time
/// (chosen at run time); the arithmetic is the same operations in the same
/// order (no fused multiply-add), so the results are the same bits either
/// way.
///
/// # Panics
/// If the slices differ in length.
pub fn sin_cos_each(angles: &[f64], out: &mut [(f64, f64)]) {
    assert_eq!(angles.len(), out.len(), "one output per angle");
    // Four numbers at a time where the processor allows (the same bits).
    crate::simd::run(
        #[inline(always)]
        || each(angles, out),
    );
}

#[inline(always)]
fn each(angles: &[f64], out: &mut [(f64, f64)]) {
    for (o, &x) in out.iter_mut().zip(angles) {
        *o = reduced_sin_cos(x);
    }
    for (o, &x) in out.iter_mut().zip(angles) {
        if x.abs() > FAST_RANGE {
            *o = x.sin_cos();
        }
    }
}

/// `a + b` as the rounded sum and its exact error (Knuth's TwoSum).
#[inline(always)]
fn two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    let bb = s - a;
    (s, (a - (s - bb)) + (b - bb))
}

/// fdlibm's `__kernel_sin(x, y, 1)`: `sin(x + y)` for `|x| ≤ π/4`, `y` the
/// tail of `x`.
#[inline(always)]
fn kernel_sin(x: f64, y: f64) -> f64 {
    let z = x * x;
    let w = z * z;
    let r = S2 + z * (S3 + z * S4) + z * w * (S5 + z * S6);
    let v = z * x;
    x - ((z * (0.5 * y - v * r) - y) - v * S1)
}

/// fdlibm's `__kernel_cos(x, y)`: `cos(x + y)` for `|x| ≤ π/4`.
#[inline(always)]
fn kernel_cos(x: f64, y: f64) -> f64 {
    let z = x * x;
    let w = z * z;
    let r = z * (C1 + z * (C2 + z * C3)) + w * w * (C4 + z * (C5 + z * C6));
    let hz = 0.5 * z;
    let w = 1.0 - hz;
    w + (((1.0 - w) - hz) + (z * r - x * y))
}

#[cfg(test)]
mod tests;
