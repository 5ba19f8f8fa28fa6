//! An automatic gearbox's shift schedule: which range a converter
//! driveline is in, shifting with hysteresis on its input speed, and the
//! torque it passes while a shift takes its time.
//!
//! The form is Project Chrono's `ChAutomaticTransmissionShafts` (its shift
//! points, per gear, an upshift and a downshift speed of the gearbox's
//! input shaft): in range `r` the gearbox shifts up once its input (the
//! converter's turbine) turns faster than `up[r]`, and down once slower
//! than `down[r]`. The band between them is the hysteresis: after an
//! upshift the input turns slower by the ranges' ratio, and the schedule
//! is refused if that lands below the next range's downshift speed (it
//! would hunt). A shift takes `time`: a power-shift gearbox hands the
//! torque from one clutch to the other, and until the handover is done
//! the sprocket gets the lesser of the two ranges' torques.

use super::PowertrainError;

/// A shift schedule ([`Driveline::shift`](super::Driveline::shift)):
/// speeds in rad/s of the gearbox's input (the turbine), one per range,
/// lowest range first.
#[derive(Debug, Clone, PartialEq)]
pub struct Shift {
    /// The input speed above which each range shifts up (the highest
    /// range's is not read), rad/s.
    pub up: Vec<f64>,
    /// The input speed below which each range shifts down (the lowest
    /// range's is not read), rad/s.
    pub down: Vec<f64>,
    /// How long a shift takes, s (≥ 0): until it is done the sprocket gets
    /// the lesser of the two ranges' torques.
    pub time: f64,
}

/// The range a scheduled gearbox is in: what a run keeps of its shifts.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Engaged {
    /// The range engaged (0-based).
    pub range: usize,
    /// While a shift takes its time: the range it shifts from, and the
    /// time (s) the shift is done.
    pub from: Option<(usize, f64)>,
}

impl Engaged {
    /// The lowest range, no shift under way: where a run starts.
    pub const LOWEST: Engaged = Engaged {
        range: 0,
        from: None,
    };
}

impl Shift {
    /// Every figure in its range for a gearbox of `ranges` (its
    /// reductions, lowest range first): one speed per range, finite and ≥
    /// 0, each range's downshift below its upshift, an upshift landing
    /// above the next range's downshift (no hunting), and a time ≥ 0.
    pub fn check(&self, ranges: &[f64]) -> Result<(), PowertrainError> {
        let n = ranges.len();
        let problem = |range: usize, what: &'static str| PowertrainError::Shift { range, what };
        for (what, speeds) in [
            ("upshift speeds", &self.up),
            ("downshift speeds", &self.down),
        ] {
            if speeds.len() != n {
                return Err(problem(speeds.len().min(n), what));
            }
            if let Some(range) = speeds.iter().position(|s| !(s.is_finite() && *s >= 0.0)) {
                return Err(problem(range, what));
            }
        }
        for r in 1..n {
            if self.down[r] >= self.up[r] && r + 1 < n {
                return Err(problem(
                    r,
                    "downshift speed (at or above its upshift speed)",
                ));
            }
            // After the upshift from r − 1 the input turns at
            // `up[r − 1] · ranges[r] / ranges[r − 1]`.
            if self.up[r - 1] * ranges[r] / ranges[r - 1] <= self.down[r] {
                return Err(problem(
                    r,
                    "downshift speed (an upshift lands below it: it would hunt)",
                ));
            }
        }
        if !(self.time.is_finite() && self.time >= 0.0) {
            return Err(problem(0, "shift time"));
        }
        Ok(())
    }

    /// The gearbox `engaged` at time `t` (s) with its input in the
    /// engaged range at `input` rad/s (≥ 0): a shift under way whose time
    /// has come is done; else, no shift under way, an input past the
    /// range's upshift speed shifts up (below its downshift speed, down),
    /// starting a shift of [`time`](Self::time). `None`: nothing changes.
    pub fn next(&self, engaged: Engaged, input: f64, t: f64) -> Option<Engaged> {
        if let Some((_, done)) = engaged.from {
            return (t >= done).then_some(Engaged {
                range: engaged.range,
                from: None,
            });
        }
        let r = engaged.range;
        let to = if r + 1 < self.up.len() && input > self.up[r] {
            r + 1
        } else if r > 0 && input < self.down[r] {
            r - 1
        } else {
            return None;
        };
        Some(Engaged {
            range: to,
            from: (self.time > 0.0).then_some((r, t + self.time)),
        })
    }
}
