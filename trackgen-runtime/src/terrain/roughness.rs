//! Random roughness: seeded courses with the ISO 8608 displacement PSD, by
//! road class or by a target detrended RMS elevation, as a [`Profile`].
//!
//! # Spectrum
//!
//! ISO 8608:2016, *Mechanical vibration — Road surface profiles —
//! Reporting of measured data*, §5 and annex C: the one-sided displacement
//! PSD `G_d(n) = G_d(n₀) (n / n₀)^−2` (m³), `n` in cycles/m,
//! `n₀ =` [`N0`] `= 0.1` cycles/m, with the classes' geometric means
//! `G_d(n₀) = 16·10⁻⁶ m³` for A and 4 times more per class up to H,
//! `262144·10⁻⁶ m³` ([`Iso8608Class::gd_n0`]). A course by target RMS
//! ([`Spectrum::DetrendedRms`]) has the same shape, scaled so that its
//! detrended RMS elevation (below) equals the target.
//!
//! # Synthesis
//!
//! The sum of cosines with random phases of Agostinacchio, Ciampa & Olita,
//! "The vibrations induced by surface irregularities in road pavements – a
//! Matlab® approach", Eur. Transp. Res. Rev. 6 (2014) 267–275,
//! doi:10.1007/s12544-013-0127-8, their eq. (8):
//!
//! ```text
//! z(x) = Σ_i √(2 G_d(n_i) Δn) cos(2π n_i x + φ_i),   φ_i uniform in [0, 2π),
//! ```
//!
//! with `n_i = i Δn`. Here the profile is sampled at `x_k = k Δx` over a
//! period of `N` samples (`N` a power of two) and `Δn = 1 / (N Δx)`, so
//! `n_i x_k = (i k mod N) / N` exactly and
//! `z_k = Re Σ_i c_i e^{2πi (ik mod N)/N}` with `c_i = a_i e^{iφ_i}`,
//! `a_i = √(2 G_d(n_i) Δn)`: the real part of an inverse DFT, computed by
//! a radix-2 FFT in O(N log N) (checked against the direct sum in the
//! tests). Each cosine's mean square over the period is `a_i² / 2`, so the
//! course's RMS is, in closed form, `σ = √(Σ_i G_d(n_i) Δn)`
//! ([`RoughSamples::rms`]).
//!
//! # Band
//!
//! The lines are those with `n_min ≤ n_i ≤ n_max` and `1 ≤ i < N/2`
//! (strictly below the Nyquist frequency `1 / (2 Δx)` of the spacing,
//! whose line would lose its sine part). The default band,
//! [`DEFAULT_BAND`], is `[0.05, 10]` cycles/m (wavelengths 20 m to
//! 0.1 m): ISO 8608:2016 notes that spatial frequencies need not in
//! general be measured below 0.01 cycles/m for on-road vehicles and
//! 0.05 cycles/m for off-road vehicles, and recommends 10 cycles/m as the
//! upper limit for general on-road measurements (the tyre's enveloping
//! filters shorter waves; a track bridges them too). At 5 cm spacing the
//! Nyquist frequency is 10 cycles/m, so the highest line is just below it.
//! `N` is the least power of two at least the course's sample count and
//! `8 / (n_min Δx)`, so that `Δn ≤ n_min / 8` (eight or more lines per
//! `n_min` of band at the long-wave end, however short the course); the
//! course is the first samples of the period.
//!
//! # Detrending
//!
//! The RMS elevation of the mobility literature is taken after removing
//! the long-wave trend. [`detrended_rms`] removes a **centred moving
//! average** over a base length `B`: with `h = round(B / (2 Δx))` and a
//! window of `m = 2h + 1` samples (spanning `2h Δx ≈ B`),
//! `r_k = z_k − (1/m) Σ_{|j|≤h} z_{k+j}` for every `k` whose window lies in
//! the samples, and the detrended RMS is `√(mean r_k²)`. The base length
//! defaults to 10 ft, [`DETRENDING_BASE_LENGTH`] = 3.048 m. Sources, and
//! what could not be confirmed: the US Army's roughness is "the RMS
//! deviation of terrain elevation from the local (detrended) average",
//! from ride courses sampled at about 1 ft "with wavelengths over 10 ft
//! filtered out" (the MAVS simulator's documentation, Mississippi State
//! University, citing Durst, Mason, McKinley & Baylot, "Predicting RMS
//! surface roughness using fractal dimension and PSD parameters",
//! J. Terramechanics 48 (2011) 105–111); the SEDRIS EDCS attribute
//! TERRAIN_ROUGHNESS_ROOT_MEAN_SQUARE defines it as the RMS of elevations
//! at about 0.3 m spacing "after removing the trend surface". The NRMM's
//! own definition (Ahlvin & Haley, NRMM II, 1992) was not available to
//! check: the filter's form (a moving average rather than another
//! high-pass) and the centred window are this module's assumption, and
//! the base length is a parameter.
//!
//! # Determinism
//!
//! The same [`RoughCourse`] gives the same samples bit for bit on any
//! machine: the phases come from [`SplitMix64`] (integer arithmetic only),
//! and the rest is IEEE 754 `+ − × ÷ √` (exactly rounded; Rust neither
//! fuses multiply-adds nor reorders sums) in a fixed order, conversions
//! between integers and floats, and `crate::trig::sin_cos`, whose
//! arguments here are all in `[0, 2π]` where it is branch-free fdlibm
//! arithmetic. No libm transcendental is called.
//!
//! # Run-in
//!
//! The samples start at `x₀` ([`RoughCourse::start`]): a flat run-in of
//! height 0 ([`RoughCourse::run_in`]), then the roughness faded in by a
//! raised cosine `w = (1 − cos(π s / T)) / 2` over a taper of length `T`
//! ([`RoughCourse::taper`]), then the full roughness over
//! [`RoughCourse::length`]: the vehicle starts on flat ground, not on a
//! cliff.

use std::f64::consts::{PI, TAU};

use thiserror::Error;

use super::profile::{Profile, ProfileError};
use crate::trig::sin_cos;

#[cfg(test)]
mod tests;

/// ISO 8608's reference spatial frequency `n₀`, cycles/m.
pub const N0: f64 = 0.1;

/// The base length of the detrending, m: 10 ft (see the module docs).
pub const DETRENDING_BASE_LENGTH: f64 = 3.048;

/// The default band of spatial frequencies, cycles/m (see the module
/// docs).
pub const DEFAULT_BAND: Band = Band {
    n_min: 0.05,
    n_max: 10.0,
};

/// The sample spacing of a course, m: 5 cm, as the NG-NRMM's courses are
/// sampled; the default band's shortest wavelength (0.1 m) is two samples.
pub const SPACING: f64 = 0.05;

/// The longest period synthesised, in samples: 2²² (210 km at 5 cm).
pub const MAX_PERIOD: usize = 1 << 22;

/// SplitMix64, the generator of Steele, Lea & Flood, "Fast splittable
/// pseudorandom number generators", OOPSLA 2014
/// (doi:10.1145/2660193.2660195), with the constants of Vigna's reference
/// `splitmix64.c`: a 64-bit counter advanced by the golden-ratio
/// increment, each output a bijective mix of it. Integer arithmetic only,
/// so the same seed gives the same stream everywhere (seed 1234567 gives
/// 6457827717110365317, 3203168211198807973, … as the reference does).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct SplitMix64 {
    state: u64,
}

impl SplitMix64 {
    /// A generator seeded with `seed`.
    pub const fn new(seed: u64) -> SplitMix64 {
        SplitMix64 { state: seed }
    }

    /// The next 64 bits.
    pub fn next_u64(&mut self) -> u64 {
        self.state = self.state.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.state;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// A uniform number in `[0, 1)`: the top 53 bits times `2⁻⁵³`
    /// (exact).
    pub fn next_f64(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 * (1.0 / (1u64 << 53) as f64)
    }
}

/// An ISO 8608 road class.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Iso8608Class {
    /// `G_d(n₀) = 16·10⁻⁶ m³`.
    A,
    /// `64·10⁻⁶ m³`.
    B,
    /// `256·10⁻⁶ m³`.
    C,
    /// `1024·10⁻⁶ m³`.
    D,
    /// `4096·10⁻⁶ m³`.
    E,
    /// `16384·10⁻⁶ m³`.
    F,
    /// `65536·10⁻⁶ m³`.
    G,
    /// `262144·10⁻⁶ m³`.
    H,
}

impl Iso8608Class {
    /// Every class, A to H.
    pub const ALL: [Iso8608Class; 8] = [
        Iso8608Class::A,
        Iso8608Class::B,
        Iso8608Class::C,
        Iso8608Class::D,
        Iso8608Class::E,
        Iso8608Class::F,
        Iso8608Class::G,
        Iso8608Class::H,
    ];

    /// The class's geometric-mean `G_d(n₀)`, m³: `16·10⁻⁶ · 4^k` for the
    /// k-th class from A (k = 0); each class spans a factor 4 around it.
    pub fn gd_n0(self) -> f64 {
        16e-6 * (1u64 << (2 * self as u32)) as f64
    }

    /// The class of a letter `A`–`H` (either case).
    pub fn from_letter(letter: char) -> Option<Iso8608Class> {
        let k = (letter.to_ascii_uppercase() as u32).checked_sub('A' as u32)?;
        Iso8608Class::ALL.get(k as usize).copied()
    }

    /// The class's letter.
    pub fn letter(self) -> char {
        (b'A' + self as u8) as char
    }
}

/// `G_d(n) = gd_n0 (n / n₀)^−2`, m³, for `n` in cycles/m.
pub fn iso8608_psd(gd_n0: f64, n: f64) -> f64 {
    gd_n0 * (N0 / n) * (N0 / n)
}

/// What roughness a course has.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Spectrum {
    /// ISO 8608's PSD for a class.
    Iso8608(Iso8608Class),
    /// ISO 8608's shape, scaled so that the course's detrended RMS
    /// elevation over its fully rough part equals `rms`.
    DetrendedRms {
        /// Target, m (1 in = 0.0254 m; the NG-NRMM courses are 1 to 4 in);
        /// `0 < rms ≤ 1`.
        rms: f64,
        /// The detrending's base length, m (see [`detrended_rms`];
        /// [`DETRENDING_BASE_LENGTH`] is the literature's 10 ft).
        base_length: f64,
    },
}

/// A band of spatial frequencies, cycles/m: `0 < n_min < n_max`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Band {
    /// Lowest line's frequency at least, cycles/m (longest wavelength
    /// `1 / n_min`).
    pub n_min: f64,
    /// Highest line's frequency at most, cycles/m (clipped below the
    /// spacing's Nyquist frequency).
    pub n_max: f64,
}

/// A random course to generate: see the module docs for the spectrum,
/// synthesis, band, run-in and determinism. Build it with
/// [`new`](Self::new) and the `with_` methods (or set the fields); every
/// value is checked by [`samples`](Self::samples).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RoughCourse {
    /// The roughness.
    pub spectrum: Spectrum,
    /// Length of the fully rough part, m: `0 < length ≤ 1e6`.
    pub length: f64,
    /// Sample spacing, m: `0.001 ≤ spacing ≤ 10`.
    pub spacing: f64,
    /// The seed of the phases.
    pub seed: u64,
    /// x of the first sample, m: `|start| ≤ 1e6`.
    pub start: f64,
    /// Flat run-in at height 0, m: `0 ≤ run_in ≤ 1e5`.
    pub run_in: f64,
    /// Raised-cosine fade-in after the run-in, m: `0 ≤ taper ≤ 1e5` (0: the
    /// roughness starts at once, a jump of up to a few RMS between two
    /// samples when there is a run-in).
    pub taper: f64,
    /// The band of spatial frequencies.
    pub band: Band,
}

/// The samples of a generated course, with what the synthesis used.
#[derive(Debug, Clone, PartialEq)]
pub struct RoughSamples {
    /// x of sample 0, m; sample `k` is at `start + k · spacing`.
    pub start: f64,
    /// m.
    pub spacing: f64,
    /// Heights, m: the run-in's zeros, the taper, the fully rough part.
    pub heights: Vec<f64>,
    /// Index of the first fully rough sample (the first past the taper).
    pub rough_from: usize,
    /// The synthesis period `N`, samples (a power of two).
    pub period: usize,
    /// Line spacing `Δn = 1 / (N Δx)`, cycles/m.
    pub dn: f64,
    /// The first and last line `i` used (`n_i = i Δn`).
    pub lines: (usize, usize),
    /// The spectrum's `G_d(n₀)` as synthesised, m³ (for a target RMS,
    /// the scale found squared).
    pub gd_n0: f64,
    /// The closed-form RMS of the fully rough part, `√(Σ G_d(n_i) Δn)`,
    /// m.
    pub rms: f64,
}

impl RoughSamples {
    /// x of sample `k`, m.
    pub fn x(&self, k: usize) -> f64 {
        self.start + k as f64 * self.spacing
    }

    /// The fully rough part's heights, m.
    pub fn rough(&self) -> &[f64] {
        &self.heights[self.rough_from..]
    }

    /// The samples as a polyline profile.
    pub fn profile(&self) -> Result<Profile, ProfileError> {
        Profile::new(
            self.heights
                .iter()
                .enumerate()
                .map(|(k, &z)| (self.x(k), z))
                .collect(),
        )
    }
}

/// A course or detrending that cannot be made.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum RoughnessError {
    /// A parameter out of its range.
    #[error("roughness: {parameter} = {value} is outside its range {allowed}")]
    Parameter {
        /// Which (`"spacing"`, …).
        parameter: &'static str,
        /// Its value.
        value: f64,
        /// The allowed range, with its unit.
        allowed: &'static str,
    },
    /// The period would exceed [`MAX_PERIOD`] samples.
    #[error(
        "roughness: the course needs a period of {needed} samples (its own samples, and 8 / (n_min · spacing)); at most {MAX_PERIOD}"
    )]
    TooManySamples {
        /// Samples needed.
        needed: f64,
    },
    /// No line in the band below the Nyquist frequency.
    #[error(
        "roughness: no line n_i = i·{dn} cycles/m in the band [{n_min}, {n_max}] cycles/m below the spacing's Nyquist frequency {nyquist} cycles/m"
    )]
    EmptyBand {
        /// cycles/m.
        n_min: f64,
        /// cycles/m.
        n_max: f64,
        /// `1 / (2 Δx)`, cycles/m.
        nyquist: f64,
        /// The line spacing, cycles/m.
        dn: f64,
    },
    /// Fewer samples than one detrending window.
    #[error(
        "detrending: {samples} samples are fewer than one window of {window} (base length {base_length} m at {spacing} m spacing)"
    )]
    TooShort {
        /// Samples given.
        samples: usize,
        /// Samples in the window, `2 round(B / 2Δx) + 1`.
        window: usize,
        /// m.
        base_length: f64,
        /// m.
        spacing: f64,
    },
    /// The samples' detrended RMS is zero or not finite: nothing to scale
    /// to a target.
    #[error("roughness: the unscaled course's detrended RMS is {0} m; cannot scale it")]
    Degenerate(f64),
    /// The samples do not make a profile.
    #[error(transparent)]
    Profile(#[from] ProfileError),
}

/// `Ok` if `ok`, else the parameter's error.
fn check(
    ok: bool,
    parameter: &'static str,
    value: f64,
    allowed: &'static str,
) -> Result<(), RoughnessError> {
    if ok {
        Ok(())
    } else {
        Err(RoughnessError::Parameter {
            parameter,
            value,
            allowed,
        })
    }
}

/// The RMS of `samples` (heights at `spacing` m) after removing a centred
/// moving average over `base_length` m: the detrending of the module docs.
/// With `h = round(base_length / (2 spacing))` (at least 1) and
/// `m = 2h + 1`, the residual `z_k − mean(z_{k−h} … z_{k+h})` is taken at
/// every `k` in `h .. len − h`, and the result is the root of its mean
/// square, m. A straight line has none: its residuals are rounding.
///
/// Errors: `spacing` not in `[0.001, 10]` m, `base_length` not in
/// `[spacing, 1e5]` m, or fewer samples than one window. A non-finite
/// sample makes the result non-finite.
pub fn detrended_rms(
    samples: &[f64],
    spacing: f64,
    base_length: f64,
) -> Result<f64, RoughnessError> {
    let ok = (0.001..=10.0).contains(&spacing);
    check(ok, "spacing", spacing, "0.001 m ≤ spacing ≤ 10 m")?;
    let ok = base_length >= spacing && base_length <= 1e5;
    let allowed = "spacing ≤ base_length ≤ 1e5 m";
    check(ok, "base_length", base_length, allowed)?;
    let h = ((base_length / (2.0 * spacing)).round() as usize).max(1);
    let m = 2 * h + 1;
    if samples.len() < m {
        return Err(RoughnessError::TooShort {
            samples: samples.len(),
            window: m,
            base_length,
            spacing,
        });
    }
    let count = samples.len() - 2 * h;
    let mut sum = 0.0;
    let mut squares = 0.0;
    for k in h..samples.len() - h {
        // The window's sum slides, recomputed afresh every m steps so
        // that its rounding cannot accumulate.
        if (k - h).is_multiple_of(m) {
            sum = samples[k - h..=k + h].iter().sum();
        } else {
            sum += samples[k + h] - samples[k - h - 1];
        }
        let r = samples[k] - sum / m as f64;
        squares += r * r;
    }
    Ok((squares / count as f64).sqrt())
}

/// The whole steps of spacing that cover `t` steps: `t` rounded up, or to
/// the nearest integer when within `1e-9` relative of it (so that a
/// length of 10 km at 0.05 m is 200000 steps, whichever way the division
/// rounds).
fn whole_steps(t: f64) -> f64 {
    let r = t.round();
    if (t - r).abs() <= 1e-9 * r.max(1.0) {
        r
    } else {
        t.ceil()
    }
}

/// In place, `a_k ← Σ_i a_i e^{+2πi ik/N}` (the inverse DFT without its
/// `1/N`), `N = a.len()` a power of two: iterative radix-2
/// decimation in time, twiddles `e^{2πi m/N}` from `sin_cos`, complex
/// numbers as `(re, im)`. A fixed sequence of IEEE operations.
fn inverse_fft(a: &mut [(f64, f64)]) {
    let n = a.len();
    assert!(n.is_power_of_two(), "FFT length {n} is not a power of two");
    if n == 1 {
        return;
    }
    let bits = n.trailing_zeros();
    for i in 0..n {
        let j = i.reverse_bits() >> (usize::BITS - bits);
        if i < j {
            a.swap(i, j);
        }
    }
    let twiddles: Vec<(f64, f64)> = (0..n / 2)
        .map(|m| {
            let (s, c) = sin_cos(TAU * (m as f64 / n as f64));
            (c, s)
        })
        .collect();
    let mut len = 2;
    while len <= n {
        let half = len / 2;
        let stride = n / len;
        for block in a.chunks_exact_mut(len) {
            let (lo, hi) = block.split_at_mut(half);
            for (j, (u, v)) in lo.iter_mut().zip(hi.iter_mut()).enumerate() {
                let w = twiddles[j * stride];
                let t = (v.0 * w.0 - v.1 * w.1, v.0 * w.1 + v.1 * w.0);
                *v = (u.0 - t.0, u.1 - t.1);
                *u = (u.0 + t.0, u.1 + t.1);
            }
        }
        len *= 2;
    }
}

impl RoughCourse {
    /// A course of `length` m of full roughness at `spacing` m, phases from
    /// `seed`; starting at x = 0 with no run-in or taper, in the
    /// [`DEFAULT_BAND`].
    pub fn new(spectrum: Spectrum, length: f64, spacing: f64, seed: u64) -> RoughCourse {
        RoughCourse {
            spectrum,
            length,
            spacing,
            seed,
            start: 0.0,
            run_in: 0.0,
            taper: 0.0,
            band: DEFAULT_BAND,
        }
    }

    /// Starting at `x`, m.
    pub fn starting_at(self, start: f64) -> RoughCourse {
        RoughCourse { start, ..self }
    }

    /// A flat run-in of `run_in` m, then a fade-in over `taper` m.
    pub fn with_run_in(self, run_in: f64, taper: f64) -> RoughCourse {
        RoughCourse {
            run_in,
            taper,
            ..self
        }
    }

    /// In `band` (cycles/m).
    pub fn with_band(self, band: Band) -> RoughCourse {
        RoughCourse { band, ..self }
    }

    fn check(&self) -> Result<(), RoughnessError> {
        let ok = self.length > 0.0 && self.length <= 1e6;
        check(ok, "length", self.length, "0 < length ≤ 1e6 m")?;
        let ok = (0.001..=10.0).contains(&self.spacing);
        check(ok, "spacing", self.spacing, "0.001 m ≤ spacing ≤ 10 m")?;
        let ok = self.start.abs() <= 1e6;
        check(ok, "start", self.start, "|start| ≤ 1e6 m")?;
        let ok = (0.0..=1e5).contains(&self.run_in);
        check(ok, "run_in", self.run_in, "0 ≤ run_in ≤ 1e5 m")?;
        let ok = (0.0..=1e5).contains(&self.taper);
        check(ok, "taper", self.taper, "0 ≤ taper ≤ 1e5 m")?;
        let Band { n_min, n_max } = self.band;
        let ok = n_min > 0.0 && n_min.is_finite();
        check(ok, "n_min", n_min, "0 < n_min, finite (cycles/m)")?;
        let ok = n_max > n_min && n_max.is_finite();
        check(ok, "n_max", n_max, "n_min < n_max, finite (cycles/m)")?;
        if let Spectrum::DetrendedRms { rms, base_length } = self.spectrum {
            let ok = rms > 0.0 && rms <= 1.0;
            check(ok, "rms", rms, "0 < rms ≤ 1 m")?;
            let ok = base_length >= self.spacing && base_length <= 1e5;
            let allowed = "spacing ≤ base_length ≤ 1e5 m";
            check(ok, "base_length", base_length, allowed)?;
        }
        Ok(())
    }

    /// Generates the course's samples (see the module docs). Errors: a
    /// parameter out of its range, a period over [`MAX_PERIOD`], no line
    /// in the band, or (for a target RMS) a fully rough part shorter than
    /// one detrending window.
    pub fn samples(&self) -> Result<RoughSamples, RoughnessError> {
        self.check()?;
        let dx = self.spacing;
        let ramp = self.run_in + self.taper;
        let steps = whole_steps((ramp + self.length) / dx);
        let needed = (steps + 1.0).max((8.0 / (self.band.n_min * dx)).ceil());
        if needed > MAX_PERIOD as f64 {
            return Err(RoughnessError::TooManySamples { needed });
        }
        let count = steps as usize + 1;
        let period = (needed as usize).next_power_of_two();
        let dn = 1.0 / (period as f64 * dx);
        let first = ((self.band.n_min / dn).ceil() as usize).max(1);
        let last = ((self.band.n_max / dn).floor() as usize).min(period / 2 - 1);
        if first > last {
            return Err(RoughnessError::EmptyBand {
                n_min: self.band.n_min,
                n_max: self.band.n_max,
                nyquist: 0.5 / dx,
                dn,
            });
        }
        let gd_n0 = match self.spectrum {
            Spectrum::Iso8608(class) => class.gd_n0(),
            Spectrum::DetrendedRms { .. } => 1.0,
        };

        // The lines: a phase for every i from 1 (so that a line's phase
        // does not depend on the band), amplitude and phase for those in
        // the band.
        let mut c = vec![(0.0, 0.0); period];
        let mut rng = SplitMix64::new(self.seed);
        let mut variance = 0.0;
        for (i, ci) in c.iter_mut().enumerate().take(last + 1).skip(1) {
            let phase = TAU * rng.next_f64();
            if i < first {
                continue;
            }
            let g_dn = iso8608_psd(gd_n0, i as f64 * dn) * dn;
            let a = (2.0 * g_dn).sqrt();
            let (s, cos) = sin_cos(phase);
            *ci = (a * cos, a * s);
            variance += g_dn;
        }
        inverse_fft(&mut c);

        // The run-in, the taper, the full roughness.
        let mut rough_from = count;
        let mut heights = Vec::with_capacity(count);
        for (k, &(z, _)) in c.iter().enumerate().take(count) {
            let s = k as f64 * dx;
            heights.push(if s < self.run_in {
                0.0
            } else if s < ramp {
                let (_, cos) = sin_cos(PI * ((s - self.run_in) / self.taper));
                z * (0.5 - 0.5 * cos)
            } else {
                rough_from = rough_from.min(k);
                z
            });
        }

        let mut gd_n0 = gd_n0;
        let mut rms = variance.sqrt();
        if let Spectrum::DetrendedRms {
            rms: target,
            base_length,
        } = self.spectrum
        {
            let unscaled = detrended_rms(&heights[rough_from..], dx, base_length)?;
            if !(unscaled > 0.0 && unscaled.is_finite()) {
                return Err(RoughnessError::Degenerate(unscaled));
            }
            let scale = target / unscaled;
            for z in &mut heights {
                *z *= scale;
            }
            gd_n0 = scale * scale;
            rms *= scale;
        }
        Ok(RoughSamples {
            start: self.start,
            spacing: dx,
            heights,
            rough_from,
            period,
            dn,
            lines: (first, last),
            gd_n0,
            rms,
        })
    }

    /// The course as a polyline profile through its samples.
    pub fn profile(&self) -> Result<Profile, RoughnessError> {
        Ok(self.samples()?.profile()?)
    }
}
