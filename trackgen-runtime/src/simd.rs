//! Loops compiled wider where the processor allows: one switch for every
//! hot loop of the crate, instead of a copy of it at each.
//!
//! The crate is built for baseline x86-64 (SSE2: two `f64` per vector
//! operation), so its binaries run on any x86-64 processor. [`run`] runs a
//! closure compiled for AVX2 (four per operation) where the processor has
//! it. Only the width of the vector operations changes, not which
//! operations run or in what order (no fused multiply-add is enabled, and
//! Rust neither contracts `a * b + c` nor reorders sums), so the results
//! are the same bits on every processor: by construction, and seen on the
//! main job (its files byte for byte the same before and after).

/// `f()`, compiled for AVX2 when the processor has it (checked once and
/// cached by the standard library), else as built.
///
/// What `f` calls inline is compiled with it; a function it calls out of
/// line keeps its own build. So the closure's body should be the loops
/// themselves or an `#[inline(always)]` function holding them.
#[inline(always)]
pub(crate) fn run<R>(f: impl FnOnce() -> R) -> R {
    #[cfg(target_arch = "x86_64")]
    if std::arch::is_x86_feature_detected!("avx2") {
        // SAFETY: the processor has AVX2, checked just above.
        return unsafe { avx2(f) };
    }
    f()
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
fn avx2<R>(f: impl FnOnce() -> R) -> R {
    f()
}
