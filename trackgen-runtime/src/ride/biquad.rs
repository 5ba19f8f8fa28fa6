//! Second-order sections: continuous ([`Section`]), discrete ([`Biquad`],
//! direct form II transposed) by the bilinear transform with prewarping,
//! and fixed-length cascades of them ([`Cascade`]).

use std::f64::consts::PI;

/// A continuous second-order section
/// `H(s) = (num[0] s² + num[1] s + num[2]) / (den[0] s² + den[1] s + den[2])`,
/// `s` in rad/s. A first-order section has `num[0] = den[0] = 0`.
///
/// Invariant (not checked): the denominator is Hurwitz (its coefficients
/// of one sign, `den[1] ≠ 0` unless it is a constant), so the section and
/// its bilinear image are stable.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Section {
    /// Numerator coefficients, highest power of `s` first.
    pub num: [f64; 3],
    /// Denominator coefficients, highest power of `s` first.
    pub den: [f64; 3],
}

impl Section {
    /// `H(s) = 1`.
    pub const IDENTITY: Section = Section {
        num: [0.0, 0.0, 1.0],
        den: [0.0, 0.0, 1.0],
    };

    /// Second-order low-pass `ω² / (s² + ω s/Q + ω²)`, `ω = 2π f_hz`
    /// (Butterworth at `Q = 1/√2`).
    pub fn lowpass(f_hz: f64, q: f64) -> Section {
        let w = 2.0 * PI * f_hz;
        Section {
            num: [0.0, 0.0, w * w],
            den: [1.0, w / q, w * w],
        }
    }

    /// Second-order high-pass `s² / (s² + ω s/Q + ω²)`, `ω = 2π f_hz`.
    pub fn highpass(f_hz: f64, q: f64) -> Section {
        let w = 2.0 * PI * f_hz;
        Section {
            num: [1.0, 0.0, 0.0],
            den: [1.0, w / q, w * w],
        }
    }

    /// The continuous magnitude `|H(j2πf)|`, `f` in Hz.
    pub fn response(&self, f_hz: f64) -> f64 {
        let w = 2.0 * PI * f_hz;
        let at = |c: &[f64; 3]| (c[2] - c[0] * w * w).hypot(c[1] * w);
        at(&self.num) / at(&self.den)
    }
}

/// One discrete second-order section
/// `(b0 + b1 z⁻¹ + b2 z⁻²) / (1 + a1 z⁻¹ + a2 z⁻²)` in direct form II
/// transposed (two state variables; the usual floating-point form, e.g.
/// SciPy's `lfilter`), keeping the continuous [`Section`] it came from.
/// In `f64` a section with poles close to `z = 1` keeps its response to
/// about `4ε/θ²` relative at `θ = 2πf·dt`: 10⁻¹⁰ for the 0.4 Hz high-pass
/// at 0.5 Hz and 1 ms.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Biquad {
    b: [f64; 3],
    a: [f64; 2],
    state: [f64; 2],
    section: Section,
    dt: f64,
    prewarp_hz: f64,
}

impl Biquad {
    /// The bilinear image of `section` at sample interval `dt` (s),
    /// prewarped at `prewarp_hz`: `s = K (z − 1)/(z + 1)` with
    /// `K = 2π f_p / tan(π f_p dt)`, so that the discrete magnitude equals
    /// the continuous one at `f_p` exactly and, at any `f`, equals the
    /// continuous one at `f_p tan(π f dt)/tan(π f_p dt)`. `prewarp_hz = 0`
    /// is the plain transform, `K = 2/dt`.
    ///
    /// # Panics
    /// If `dt` is not positive and finite, or `prewarp_hz` is not in
    /// `[0, 1/(2 dt))`.
    pub fn bilinear(section: Section, dt: f64, prewarp_hz: f64) -> Biquad {
        assert!(dt > 0.0 && dt.is_finite(), "dt must be positive: {dt}");
        assert!(
            (0.0..0.5 / dt).contains(&prewarp_hz),
            "prewarp frequency {prewarp_hz} Hz is not below Nyquist ({} Hz)",
            0.5 / dt
        );
        let k = if prewarp_hz > 0.0 {
            2.0 * PI * prewarp_hz / (PI * prewarp_hz * dt).tan()
        } else {
            2.0 / dt
        };
        // (c0 s² + c1 s + c2)(z + 1)² at s = K (z − 1)/(z + 1), in powers of z⁻¹.
        let map = |c: &[f64; 3]| {
            let (c0, c1) = (c[0] * k * k, c[1] * k);
            [c0 + c1 + c[2], 2.0 * (c[2] - c0), c0 - c1 + c[2]]
        };
        let (n, d) = (map(&section.num), map(&section.den));
        Biquad {
            b: [n[0] / d[0], n[1] / d[0], n[2] / d[0]],
            a: [d[1] / d[0], d[2] / d[0]],
            state: [0.0; 2],
            section,
            dt,
            prewarp_hz,
        }
    }

    /// Filters one sample.
    #[inline]
    pub fn push(&mut self, x: f64) -> f64 {
        let y = self.b[0] * x + self.state[0];
        self.state[0] = self.b[1] * x - self.a[0] * y + self.state[1];
        self.state[1] = self.b[2] * x - self.a[1] * y;
        y
    }

    /// Clears the state (the input is taken as zero before the next
    /// sample); the coefficients stay.
    pub fn reset(&mut self) {
        self.state = [0.0; 2];
    }

    /// The continuous section this biquad discretises.
    pub fn section(&self) -> &Section {
        &self.section
    }

    /// The sample interval in s.
    pub fn dt(&self) -> f64 {
        self.dt
    }

    /// The prewarp frequency in Hz (0: none).
    pub fn prewarp_hz(&self) -> f64 {
        self.prewarp_hz
    }

    /// The continuous magnitude `|H(j2πf)|` of [`Biquad::section`].
    pub fn response_continuous(&self, f_hz: f64) -> f64 {
        self.section.response(f_hz)
    }

    /// The discrete magnitude `|H(e^{j2πf·dt})|`, `f` in Hz.
    pub fn response_discrete(&self, f_hz: f64) -> f64 {
        let th = 2.0 * PI * f_hz * self.dt;
        let (s1, c1) = th.sin_cos();
        let (s2, c2) = (2.0 * th).sin_cos();
        let num =
            (self.b[0] + self.b[1] * c1 + self.b[2] * c2).hypot(self.b[1] * s1 + self.b[2] * s2);
        let den = (1.0 + self.a[0] * c1 + self.a[1] * c2).hypot(self.a[0] * s1 + self.a[1] * s2);
        num / den
    }
}

/// `N` biquads in series, the first applied first. Fixed size: no
/// allocation, O(N) work per sample.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Cascade<const N: usize> {
    stages: [Biquad; N],
}

impl<const N: usize> Cascade<N> {
    /// Chains `stages` in order.
    pub fn new(stages: [Biquad; N]) -> Cascade<N> {
        Cascade { stages }
    }

    /// Filters one sample through every stage.
    #[inline]
    pub fn push(&mut self, x: f64) -> f64 {
        self.stages.iter_mut().fold(x, |y, s| s.push(y))
    }

    /// Clears every stage's state.
    pub fn reset(&mut self) {
        self.stages.iter_mut().for_each(Biquad::reset);
    }

    /// The stages, first applied first.
    pub fn stages(&self) -> &[Biquad; N] {
        &self.stages
    }

    /// The continuous magnitude: the product of the stages'.
    pub fn response_continuous(&self, f_hz: f64) -> f64 {
        self.stages
            .iter()
            .map(|s| s.response_continuous(f_hz))
            .product()
    }

    /// The discrete magnitude: the product of the stages'.
    pub fn response_discrete(&self, f_hz: f64) -> f64 {
        self.stages
            .iter()
            .map(|s| s.response_discrete(f_hz))
            .product()
    }
}
