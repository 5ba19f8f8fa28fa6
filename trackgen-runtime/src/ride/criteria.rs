//! The three ride criteria a mobility study measures at the driver's seat
//! (absorbed power, ISO 2631-1 weighted acceleration, peak vertical
//! acceleration; the guide's "The seat and the ride") as streaming filters
//! with running statistics.

use std::f64::consts::{FRAC_1_SQRT_2, PI};

use super::biquad::{Biquad, Cascade, Section};
use super::{FT_PER_M, G};

/// Running mean of the square: a sum and a count, O(1) memory. The sum
/// is of positive terms, so its relative rounding error stays below
/// `n·ε` (10⁻¹⁰ at 10⁶ samples).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
struct MeanSquare {
    sum: f64,
    n: u64,
}

impl MeanSquare {
    fn add(&mut self, y: f64) {
        self.sum += y * y;
        self.n += 1;
    }

    fn mean(&self) -> f64 {
        if self.n == 0 {
            0.0
        } else {
            self.sum / self.n as f64
        }
    }
}

/// Vertical absorbed power (Pradko & Lee; Lee & Pradko, "Analytical
/// analysis of human vibration", SAE 680091, 1968) in the form published
/// with Project Chrono (`ChAbsorbedPowerVertical`,
/// `src/chrono/utils/ChFilters.cpp`):
///
/// `H(s) = 14.5 s (s + 44) / ((s + 63)(s² + 24 s + 750))`
///
/// applied to the vertical acceleration in ft/s² (the input, in m/s², is
/// multiplied by [`FT_PER_M`] inside); the absorbed power in W is the mean
/// of the squared output over the samples measured, so a sine of
/// amplitude `A` ft/s² at `f` gives `|H(j2πf)|² A²/2`.
///
/// Discretisation: two biquads, `s/(s + 63)` prewarped at its corner
/// `63/2π` = 10.03 Hz and `14.5 (s + 44)/(s² + 24 s + 750)` prewarped at its
/// natural frequency `√750/2π` = 4.36 Hz (next to the 4.4 Hz peak of
/// `|H|`). Chrono applies the plain bilinear transform to the whole
/// third-order `H` at once; at 1 ms the two differ by less than
/// 4·10⁻⁴ in `|H|` below 20 Hz (the prewarp's rescaling of the 10 Hz
/// stage, 3.3·10⁻⁴). Chrono integrates the squared output by the
/// trapezoidal rule, divides by the elapsed time, and fades the input in
/// over 0.2–0.5 s; here the mean is over samples (the same to one sample
/// in the count) and the run-in is cut by
/// [`AbsorbedPower::start_measuring`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AbsorbedPower {
    filter: Cascade<2>,
    stats: MeanSquare,
}

impl AbsorbedPower {
    /// The filter at sample interval `dt` (s), at rest, measuring.
    ///
    /// # Panics
    /// If `dt` is not positive and finite or 10.03 Hz is not below
    /// Nyquist (`dt` ≥ 0.0498 s).
    pub fn new(dt: f64) -> AbsorbedPower {
        let high = Section {
            num: [0.0, 1.0, 0.0],
            den: [0.0, 1.0, 63.0],
        };
        let resonance = Section {
            num: [0.0, 14.5, 14.5 * 44.0],
            den: [1.0, 24.0, 750.0],
        };
        AbsorbedPower {
            filter: Cascade::new([
                Biquad::bilinear(high, dt, 63.0 / (2.0 * PI)),
                Biquad::bilinear(resonance, dt, 750f64.sqrt() / (2.0 * PI)),
            ]),
            stats: MeanSquare::default(),
        }
    }

    /// Takes one sample of the vertical acceleration (m/s²); returns the
    /// filter's output (its square is the instantaneous power in W).
    #[inline]
    pub fn push(&mut self, a_mps2: f64) -> f64 {
        let y = self.filter.push(a_mps2 * FT_PER_M);
        self.stats.add(y);
        y
    }

    /// The absorbed power in W: the mean of the squared output over the
    /// samples pushed since [`AbsorbedPower::new`],
    /// [`AbsorbedPower::reset`] or [`AbsorbedPower::start_measuring`];
    /// 0 before any.
    pub fn power(&self) -> f64 {
        self.stats.mean()
    }

    /// The number of samples in [`AbsorbedPower::power`].
    pub fn samples(&self) -> u64 {
        self.stats.n
    }

    /// Restarts the mean, keeping the filter's state: call it at the end
    /// of the run-in so the start-up transient is not measured.
    pub fn start_measuring(&mut self) {
        self.stats = MeanSquare::default();
    }

    /// Back to rest: the filter's state and the mean are cleared.
    pub fn reset(&mut self) {
        self.filter.reset();
        self.start_measuring();
    }

    /// The underlying filter (input in ft/s²).
    pub fn filter(&self) -> &Cascade<2> {
        &self.filter
    }

    /// The continuous `|H(j2πf)|`, per ft/s² (its square is in
    /// W/(ft/s²)²: 0.2081 at 4.4 Hz).
    pub fn response_continuous(&self, f_hz: f64) -> f64 {
        self.filter.response_continuous(f_hz)
    }

    /// The discrete `|H(e^{j2πf·dt})|`, per ft/s².
    pub fn response_discrete(&self, f_hz: f64) -> f64 {
        self.filter.response_discrete(f_hz)
    }
}

/// An ISO 2631-1:1997 frequency weighting (its Annex A, with `s = j2πf`,
/// `ω_i = 2πf_i`) and the weighted r.m.s.
/// acceleration (ISO 2631-1:1997, 6.4.1): the square root of the mean of
/// the squared weighted acceleration over the samples measured.
///
/// Stages, each prewarped at its pole natural frequency:
/// 1. band-limiting high-pass `s²/(s² + √2 ω₁ s + ω₁²)`, f₁ = 0.4 Hz;
/// 2. band-limiting low-pass `ω₂²/(s² + √2 ω₂ s + ω₂²)`, f₂ = 100 Hz
///    (0.2 of Nyquist at 1 ms; prewarped at 100 Hz its corner stays
///    there, and below 20 Hz its error is under 1.1·10⁻⁴: its log-slope
///    `2(f/f₂)⁴/(1 + (f/f₂)⁴) ≤ 0.0032` times its frequency warp
///    `ln[tan(πf₂dt)/(πf₂dt)] = 0.033`);
/// 3. a-v transition `(1 + s/ω₃)/(1 + s/(Q₄ω₄) + (s/ω₄)²)`, at f₄;
/// 4. `W_k` only: upward step
///    `(s² + ω₅ s/Q₅ + ω₅²)/(s² + ω₆ s/Q₆ + ω₆²)`, at f₆; `W_d` has
///    the identity here.
///
/// `W_k` (vertical): f₃ = f₄ = 12.5 Hz, Q₄ = 0.63, f₅ = 2.37 Hz,
/// Q₅ = 0.91, f₆ = 3.35 Hz, Q₆ = 0.91. `W_d` (horizontal): f₃ = f₄ =
/// 2.0 Hz, Q₄ = 0.63. Chrono's `ChISO2631_1_Wk`/`Wd` chain the same stages
/// with the plain bilinear transform.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct IsoWeighting {
    filter: Cascade<4>,
    stats: MeanSquare,
}

impl IsoWeighting {
    /// `W_k`, for vertical acceleration, at sample interval `dt` (s).
    ///
    /// # Panics
    /// If `dt` is not positive and finite or 100 Hz is not below Nyquist
    /// (`dt` ≥ 5 ms).
    pub fn wk(dt: f64) -> IsoWeighting {
        let w5 = 2.0 * PI * 2.37;
        let w6 = 2.0 * PI * 3.35;
        let step = Section {
            num: [1.0, w5 / 0.91, w5 * w5],
            den: [1.0, w6 / 0.91, w6 * w6],
        };
        IsoWeighting::with(dt, 12.5, 12.5, 0.63, Biquad::bilinear(step, dt, 3.35))
    }

    /// `W_d`, for horizontal acceleration, at sample interval `dt` (s).
    ///
    /// # Panics
    /// As [`IsoWeighting::wk`].
    pub fn wd(dt: f64) -> IsoWeighting {
        let identity = Biquad::bilinear(Section::IDENTITY, dt, 0.0);
        IsoWeighting::with(dt, 2.0, 2.0, 0.63, identity)
    }

    fn with(dt: f64, f3: f64, f4: f64, q4: f64, last: Biquad) -> IsoWeighting {
        let (w3, w4) = (2.0 * PI * f3, 2.0 * PI * f4);
        let transition = Section {
            num: [0.0, 1.0 / w3, 1.0],
            den: [1.0 / (w4 * w4), 1.0 / (q4 * w4), 1.0],
        };
        IsoWeighting {
            filter: Cascade::new([
                Biquad::bilinear(Section::highpass(0.4, FRAC_1_SQRT_2), dt, 0.4),
                Biquad::bilinear(Section::lowpass(100.0, FRAC_1_SQRT_2), dt, 100.0),
                Biquad::bilinear(transition, dt, f4),
                last,
            ]),
            stats: MeanSquare::default(),
        }
    }

    /// Takes one sample of acceleration (m/s²); returns the weighted
    /// acceleration (m/s²).
    #[inline]
    pub fn push(&mut self, a_mps2: f64) -> f64 {
        let y = self.filter.push(a_mps2);
        self.stats.add(y);
        y
    }

    /// The weighted r.m.s. acceleration in m/s² over the samples pushed
    /// since construction, [`IsoWeighting::reset`] or
    /// [`IsoWeighting::start_measuring`]; 0 before any.
    pub fn rms(&self) -> f64 {
        self.stats.mean().sqrt()
    }

    /// The number of samples in [`IsoWeighting::rms`].
    pub fn samples(&self) -> u64 {
        self.stats.n
    }

    /// Restarts the r.m.s., keeping the filter's state (end of run-in).
    pub fn start_measuring(&mut self) {
        self.stats = MeanSquare::default();
    }

    /// Back to rest: the filter's state and the r.m.s. are cleared.
    pub fn reset(&mut self) {
        self.filter.reset();
        self.start_measuring();
    }

    /// The underlying filter.
    pub fn filter(&self) -> &Cascade<4> {
        &self.filter
    }

    /// The continuous `|W(j2πf)|`, band limiting included.
    pub fn response_continuous(&self, f_hz: f64) -> f64 {
        self.filter.response_continuous(f_hz)
    }

    /// The discrete `|W(e^{j2πf·dt})|`.
    pub fn response_discrete(&self, f_hz: f64) -> f64 {
        self.filter.response_discrete(f_hz)
    }
}

/// Peak vertical acceleration for the half-round obstacle criterion
/// (the NATO Reference Mobility Model's 2.5 g limit): a 4-pole
/// Butterworth low-pass at 30 Hz, then the running extremes of the output,
/// in g. This is the 30 Hz variant the mobility events use; Chrono's
/// `ChISO2631_Shock_SeatCushionLogger::GetLegacyAz` first passes a 4-pole
/// 75 Hz stage (and a 0.2–0.5 s fade-in), then this 30 Hz one, and takes
/// the signed maximum ([`PeakVertical::max_g`]).
///
/// The two sections are `ω²/(s² + ω s/Q + ω²)` with `ω = 2π·30`,
/// `Q = 1/(2 cos(π/8))` and `1/(2 cos(3π/8))`, both prewarped at 30 Hz, so
/// the digital −3 dB point is exactly 30 Hz. The input is the kinematic
/// acceleration (zero at rest): the filter passes 0 Hz.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PeakVertical {
    filter: Cascade<2>,
    max: f64,
    min: f64,
}

impl PeakVertical {
    /// The cut-off frequency in Hz.
    pub const CUTOFF_HZ: f64 = 30.0;

    /// The filter at sample interval `dt` (s), at rest, measuring.
    ///
    /// # Panics
    /// If `dt` is not positive and finite or 30 Hz is not below Nyquist
    /// (`dt` ≥ 16.7 ms).
    pub fn new(dt: f64) -> PeakVertical {
        let f = PeakVertical::CUTOFF_HZ;
        let stage = |k: f64| {
            let q = 0.5 / (k * PI / 8.0).cos();
            Biquad::bilinear(Section::lowpass(f, q), dt, f)
        };
        PeakVertical {
            filter: Cascade::new([stage(1.0), stage(3.0)]),
            max: f64::NEG_INFINITY,
            min: f64::INFINITY,
        }
    }

    /// Takes one sample of the vertical acceleration (m/s²); returns the
    /// filtered acceleration (m/s²).
    #[inline]
    pub fn push(&mut self, a_mps2: f64) -> f64 {
        let y = self.filter.push(a_mps2);
        self.max = self.max.max(y);
        self.min = self.min.min(y);
        y
    }

    /// The peak `max |a_filtered|` in g over the samples measured; 0
    /// before any.
    pub fn peak_g(&self) -> f64 {
        self.max.max(-self.min).max(0.0) / G
    }

    /// The largest filtered acceleration in g (signed, upward positive,
    /// as Chrono's `GetLegacyAz`); −∞ before any sample.
    pub fn max_g(&self) -> f64 {
        self.max / G
    }

    /// The smallest filtered acceleration in g (signed); +∞ before any
    /// sample.
    pub fn min_g(&self) -> f64 {
        self.min / G
    }

    /// Restarts the extremes, keeping the filter's state (end of run-in).
    pub fn start_measuring(&mut self) {
        self.max = f64::NEG_INFINITY;
        self.min = f64::INFINITY;
    }

    /// Back to rest: the filter's state and the extremes are cleared.
    pub fn reset(&mut self) {
        self.filter.reset();
        self.start_measuring();
    }

    /// The underlying filter.
    pub fn filter(&self) -> &Cascade<2> {
        &self.filter
    }

    /// The continuous `|H(j2πf)| = 1/√(1 + (f/30)⁸)`.
    pub fn response_continuous(&self, f_hz: f64) -> f64 {
        self.filter.response_continuous(f_hz)
    }

    /// The discrete `|H(e^{j2πf·dt})|`.
    pub fn response_discrete(&self, f_hz: f64) -> f64 {
        self.filter.response_discrete(f_hz)
    }
}
