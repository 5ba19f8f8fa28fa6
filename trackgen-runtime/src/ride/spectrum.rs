//! The spectrum of a seat's acceleration, and which lines carry its
//! absorbed power.
//!
//! **Estimate.** Welch's method (P. D. Welch, "The use of fast Fourier
//! transform for the estimation of power spectra", *IEEE Trans. Audio
//! Electroacoust.* 15(2), 1967, 70–73): segments of `N` samples
//! overlapping by half, each less its mean, times a Hann window
//! `w_n = sin²(πn/N)`; the one-sided density
//! `S_k = c_k |X_k|² / (f_s Σw_n²)` at `f_k = k f_s / N`, `c_k = 2` but at
//! `k = 0` and `N/2` (1), averaged over the segments. With this scaling
//! `Σ_k S_k Δf` is the mean square of the windowed samples (Parseval), so
//! the spectrum of a stationary signal sums to its variance. It is
//! streamed: a segment is transformed as soon as it fills, and the
//! memory is that of one segment whatever the run's length.
//!
//! **Absorbed power by frequency.** The absorbed power is the mean square
//! of the acceleration through `H` ([`AbsorbedPower`]), so bin `k` carries
//! `S_k |H(j2πf_k)|² Δf` of it (in W, with `S` in (ft/s²)²/Hz):
//! [`Spectrum::absorbed`]. Their sum equals the time-domain figure to
//! within the estimate's leakage and variance (tested against the filter)
//! and its resolution bias: the window spreads a tone over a bin each
//! side, where `|H|²` differs, so a line at `f` is weighed high by about
//! `(Δf/f)²/3` where `|H|²` rises as `f²` (below 4 Hz): 0.5 % at 2 Hz with
//! the 0.244 Hz bins of 4 s segments at 1 ms.
//!
//! **Lines.** A tracked vehicle's seat is shaken at the frequencies its
//! running gear passes things: a shoe's joint every pitch `p` of travel,
//! so the shoe passage `v/p` and its harmonics (the track's polygon on
//! the sprocket and the idler, the joints under the road wheels), beside
//! the hull's own modes. [`Spectrum::lines`] finds the peaks that carry the
//! most absorbed power and [`Line::name`] tells the shoe passage's
//! harmonics from the rest.

use std::f64::consts::PI;
use std::sync::Arc;

use rustfft::num_complex::Complex;
use rustfft::{Fft, FftPlanner};

use super::{AbsorbedPower, FT_PER_M};

/// Why a [`Welch`] estimate cannot be made.
#[derive(Debug, Clone, Copy, PartialEq, thiserror::Error)]
pub enum SpectrumError {
    /// The sample interval is not positive and finite.
    #[error("a spectrum needs a sample interval more than 0 s, got {0} s")]
    Interval(f64),
    /// The segment is not a power of two of at least 16 samples.
    #[error("a spectrum's segment must be a power of two of at least 16 samples, got {0}")]
    Segment(usize),
}

/// Welch's averaged, Hann-windowed periodogram of a uniformly sampled
/// signal, streamed (P. D. Welch, *IEEE Trans. Audio Electroacoust.*
/// 15(2), 1967): segments of `N` samples overlapping by half, each less
/// its mean, times `w_n = sin²(πn/N)`; the one-sided density
/// `S_k = c_k |X_k|² / (f_s Σw_n²)` (`c_k = 2` but at `k = 0` and `N/2`),
/// averaged, so that `Σ S_k Δf` is the windowed samples' mean square. A
/// segment is transformed when it fills: one segment's memory.
#[derive(Clone)]
pub struct Welch {
    dt: f64,
    window: Vec<f64>,
    window_power: f64,
    /// The last samples, at most one segment: a segment is transformed
    /// when it fills, then its first half is dropped.
    buffer: Vec<f64>,
    sum: Vec<f64>,
    segments: u64,
    fft: Arc<dyn Fft<f64>>,
    work: Vec<Complex<f64>>,
}

impl std::fmt::Debug for Welch {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Welch")
            .field("dt", &self.dt)
            .field("segment", &self.window.len())
            .field("segments", &self.segments)
            .finish_non_exhaustive()
    }
}

impl Welch {
    /// An estimate over segments of `segment` samples (a power of two, at
    /// least 16) taken every `dt` s: bins `1 / (segment·dt)` Hz apart.
    pub fn new(dt: f64, segment: usize) -> Result<Welch, SpectrumError> {
        if !(dt.is_finite() && dt > 0.0) {
            return Err(SpectrumError::Interval(dt));
        }
        if segment < 16 || !segment.is_power_of_two() {
            return Err(SpectrumError::Segment(segment));
        }
        let n = segment as f64;
        let window: Vec<f64> = (0..segment)
            .map(|i| (PI * i as f64 / n).sin().powi(2))
            .collect();
        let window_power = window.iter().map(|w| w * w).sum();
        Ok(Welch {
            dt,
            window,
            window_power,
            buffer: Vec::with_capacity(segment),
            sum: vec![0.0; segment / 2 + 1],
            segments: 0,
            fft: FftPlanner::new().plan_fft_forward(segment),
            work: vec![Complex::default(); segment],
        })
    }

    /// The least power-of-two segment that spans at least `seconds` at
    /// `dt` (bins at most `1/seconds` Hz apart), at least 16 samples.
    pub fn segment_for(dt: f64, seconds: f64) -> usize {
        let samples = (seconds / dt).ceil();
        if samples.is_finite() && samples > 16.0 {
            (samples as usize).next_power_of_two()
        } else {
            16
        }
    }

    /// Takes one sample.
    pub fn push(&mut self, x: f64) {
        self.buffer.push(x);
        if self.buffer.len() == self.window.len() {
            self.transform();
            self.buffer.drain(..self.window.len() / 2);
        }
    }

    fn transform(&mut self) {
        let n = self.window.len();
        let mean = self.buffer.iter().sum::<f64>() / n as f64;
        for ((w, x), c) in self.window.iter().zip(&self.buffer).zip(&mut self.work) {
            *c = Complex::new(w * (x - mean), 0.0);
        }
        self.fft.process(&mut self.work);
        let scale = self.dt / self.window_power;
        for (k, s) in self.sum.iter_mut().enumerate() {
            let twice = if k == 0 || k == n / 2 { 1.0 } else { 2.0 };
            *s += twice * scale * self.work[k].norm_sqr();
        }
        self.segments += 1;
    }

    /// The segments averaged so far.
    pub fn segments(&self) -> u64 {
        self.segments
    }

    /// The estimate over the segments complete so far; `None` before the
    /// first.
    pub fn spectrum(&self) -> Option<Spectrum> {
        if self.segments == 0 {
            return None;
        }
        let count = self.segments as f64;
        Some(Spectrum {
            df: 1.0 / (self.window.len() as f64 * self.dt),
            psd: self.sum.iter().map(|s| s / count).collect(),
            segments: self.segments,
        })
    }
}

/// A one-sided power spectral density: bin `k` at `k·df` Hz.
#[derive(Debug, Clone, PartialEq)]
pub struct Spectrum {
    /// The bins' spacing, Hz.
    pub df: f64,
    /// The density at each bin, in the signal's unit squared per Hz
    /// ((m/s²)²/Hz for an acceleration in m/s²).
    pub psd: Vec<f64>,
    /// The segments averaged.
    pub segments: u64,
}

impl Spectrum {
    /// Bin `k`'s frequency, Hz.
    pub fn frequency(&self, k: usize) -> f64 {
        k as f64 * self.df
    }

    /// `Σ S_k Δf`: the signal's mean square (its variance, the mean
    /// removed).
    pub fn mean_square(&self) -> f64 {
        self.psd.iter().sum::<f64>() * self.df
    }

    /// The absorbed power each bin carries, W, for a vertical
    /// acceleration in m/s²: `S_k (3.28 ft/m)² |H(j2πf_k)|² Δf` with `H`
    /// the absorbed-power filter's continuous response. Their sum is the
    /// absorbed power.
    pub fn absorbed(&self) -> Vec<f64> {
        // The continuous response does not depend on the sampling.
        let filter = AbsorbedPower::new(1e-3);
        self.psd
            .iter()
            .enumerate()
            .map(|(k, s)| {
                let h = filter.response_continuous(self.frequency(k));
                s * FT_PER_M * FT_PER_M * h * h * self.df
            })
            .collect()
    }

    /// The `most` lines that carry the most of `per_bin` (as
    /// [`absorbed`](Self::absorbed) gives): each a local maximum, with
    /// what its bin and `half_width` bins either side carry (a Hann
    /// window spreads a pure tone over its bin and one each side); lines
    /// closer than that to a larger one are part of it. Largest first.
    pub fn lines(&self, per_bin: &[f64], most: usize, half_width: usize) -> Vec<Line> {
        let n = per_bin.len();
        let around = |k: usize| {
            let (lo, hi) = (k.saturating_sub(half_width), (k + half_width).min(n - 1));
            per_bin[lo..=hi].iter().sum::<f64>()
        };
        let mut peaks: Vec<(usize, f64)> = (1..n.saturating_sub(1))
            .filter(|&k| {
                per_bin[k] > 0.0 && per_bin[k] >= per_bin[k - 1] && per_bin[k] > per_bin[k + 1]
            })
            .map(|k| (k, around(k)))
            .collect();
        peaks.sort_by(|a, b| b.1.total_cmp(&a.1));
        let mut kept: Vec<(usize, f64)> = Vec::new();
        for (k, carried) in peaks {
            if kept.len() == most {
                break;
            }
            if kept.iter().all(|&(j, _)| j.abs_diff(k) > 2 * half_width) {
                kept.push((k, carried));
            }
        }
        kept.into_iter()
            .map(|(k, carried)| Line {
                frequency: self.frequency(k),
                carried,
            })
            .collect()
    }
}

/// A peak of a spectrum and what it carries.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Line {
    /// Its frequency, Hz (its bin's).
    pub frequency: f64,
    /// What its bins carry (W, for [`Spectrum::absorbed`]).
    pub carried: f64,
}

impl Line {
    /// The harmonic of the shoe passage `speed / pitch` (Hz; speed in m/s,
    /// pitch in m) this line is, if it lies within `tolerance` Hz of one
    /// (`k` from 1 to 12, or the half, `k = 1/2`, written as 0.5): a line
    /// the running gear's kinematics sets, which moves with the speed.
    pub fn shoe_harmonic(&self, speed: f64, pitch: f64, tolerance: f64) -> Option<f64> {
        let passage = speed.abs() / pitch;
        if !(passage.is_finite() && passage > 0.0) {
            return None;
        }
        std::iter::once(0.5)
            .chain((1..=12).map(f64::from))
            .find(|k| (k * passage - self.frequency).abs() <= tolerance)
    }

    /// A name for the line: the shoe passage's harmonic it is within
    /// `harmonic` Hz ([`shoe_harmonic`](Self::shoe_harmonic)), else the
    /// nearest of `modes` (frequency in Hz, name) within `mode` Hz, else
    /// `None`.
    pub fn name(
        &self,
        speed: f64,
        pitch: f64,
        modes: &[(f64, String)],
        (harmonic, mode): (f64, f64),
    ) -> Option<String> {
        if let Some(k) = self.shoe_harmonic(speed, pitch, harmonic) {
            let passage = speed.abs() / pitch;
            return Some(if k == 1.0 {
                format!("shoe passage v/p ({passage:.2} Hz)")
            } else if k == 0.5 {
                format!("half the shoe passage, v/2p ({:.2} Hz)", 0.5 * passage)
            } else {
                format!("shoe passage × {k} ({:.2} Hz)", k * passage)
            });
        }
        modes
            .iter()
            .filter(|(f, _)| (f - self.frequency).abs() <= mode)
            .min_by(|a, b| {
                (a.0 - self.frequency)
                    .abs()
                    .total_cmp(&(b.0 - self.frequency).abs())
            })
            .map(|(f, name)| format!("{name} ({f:.2} Hz at rest)"))
    }
}
