//! Ride criteria at the driver's seat: streaming filters over a uniformly
//! sampled acceleration and the running figures computed from their
//! output (the guide's "The seat and the ride" states each filter and its
//! published source).
//!
//! - [`AbsorbedPower`]: vertical absorbed power in W (Pradko & Lee, in the
//!   form published with Project Chrono); the random-terrain ride limit
//!   is 6 W;
//! - [`IsoWeighting`]: ISO 2631-1:1997 Annex A weightings `W_k`
//!   (vertical) and `W_d` (horizontal) and the weighted r.m.s.
//!   acceleration in m/s²;
//! - [`PeakVertical`]: peak of the vertical acceleration after a 4-pole
//!   30 Hz Butterworth low-pass, in g; the half-round obstacle limit is
//!   2.5 g;
//! - [`Welch`]: the acceleration's spectrum, and [`Spectrum::absorbed`]
//!   the absorbed power each frequency carries, with the lines that carry
//!   most ([`Spectrum::lines`]) named when they are the shoe passage's.
//!
//! Each is built from continuous second-order sections ([`Section`]),
//! discretised one by one by the bilinear transform with prewarping into
//! [`Biquad`]s (direct form II transposed) chained in a [`Cascade`]. Every
//! type here is `Copy` with a fixed size: `push` costs O(1) time and the
//! memory does not grow with the number of samples. Each filter reports
//! its continuous `|H(j2πf)|` and its discrete `|H(e^{j2πf·dt})|` so the
//! discretisation error can be read at any frequency.
//!
//! **Why bilinear with prewarping.** The bilinear transform
//! `s = K (z − 1)/(z + 1)` maps the left half-plane onto the unit disc
//! (a stable section stays stable), turns each second-order section into
//! one biquad, and maps the whole imaginary axis once onto the unit
//! circle, so there is no aliasing: the discrete magnitude is *exactly*
//! the continuous one at a warped frequency,
//! `|H_d(e^{jωT})| = |H(jΩ)|` with `Ω = K tan(ωT/2)`. Choosing
//! `K = ω_p / tan(ω_p T/2)` makes `Ω = ω` at the prewarp frequency `ω_p`
//! (Oppenheim & Schafer, *Discrete-Time Signal Processing*, "filter design
//! by the bilinear transformation"). Elsewhere the relative frequency
//! error is `ε(f) = ln[tan(πf T)/(πf T)] − ln[tan(πf_p T)/(πf_p T)]
//! ≈ π²T²(f² − f_p²)/3`, and the magnitude error of a section is its
//! log-log slope times `ε`. Impulse invariance aliases and cannot
//! represent sections whose numerator is of the denominator's degree (the
//! high-pass, the upward step); matched-z keeps poles and zeros but not
//! the gain shape between them (errors of order `ωT`); forward or backward
//! Euler move the poles' damping by order `ωT`. The bilinear error is of
//! order `(ωT)²` and vanishes at `f_p`.
//!
//! Every section is prewarped at its own pole natural frequency (stated on
//! each filter), so corners and resonances sit exactly where the
//! continuous ones do, the 100 Hz band limit of ISO 2631-1 included (at
//! `T` = 1 ms it is at 0.2 of Nyquist; unprewarped, its digital corner
//! would fall at 97.0 Hz). Measured at `T` = 1 ms (`tests.rs`),
//! `max |H_d/H − 1|`: absorbed power 1.3·10⁻³, `W_k` 0.65·10⁻³,
//! `W_d` 1.3·10⁻³ over 0.5–20 Hz (0.04 of Nyquist); the peak filter
//! 0.72·10⁻³ over 0.5–30 Hz (0.06 of Nyquist); all three criteria within
//! 1 % up to 40 Hz (0.08 of Nyquist). The error scales as `T²`.
//!
//! **Inputs.** Accelerations in m/s², sampled every `dt` seconds. The
//! absorbed-power and ISO filters have zero gain at 0 Hz, so a constant
//! gravity term does not matter to them; the peak filter passes 0 Hz, so
//! feed it the kinematic acceleration (zero at rest), not an
//! accelerometer's specific force. Run-in is excluded with
//! `start_measuring` (statistics restart, filter state kept): the
//! next-generation NRMM's random-course benchmark (NATO ET-148, 2016)
//! excludes each course's first 100 m.

mod biquad;
mod criteria;
mod spectrum;
#[cfg(test)]
mod tests;

pub use biquad::{Biquad, Cascade, Section};
pub use criteria::{AbsorbedPower, IsoWeighting, PeakVertical};
pub use spectrum::{Line, Spectrum, SpectrumError, Welch};

/// Feet per metre (exact: 1 ft = 0.3048 m), the conversion applied inside
/// [`AbsorbedPower`] (Chrono's `meter_to_ft = 3.280839895`).
pub const FT_PER_M: f64 = 1.0 / 0.3048;

/// Standard gravity in m/s² (exact, CGPM 1901): 1 g, the unit of
/// [`PeakVertical`]'s figures.
pub const G: f64 = 9.80665;
