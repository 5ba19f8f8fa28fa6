//! Ride figures streamed from a run's rows: the seat's acceleration
//! through the criteria of [`ride`](crate::ride), in O(1) memory.

use super::{Sink, SinkError};
use crate::ride::{AbsorbedPower, IsoWeighting, PeakVertical, Spectrum, Welch};

/// The most the rows' spacing may differ from the sink's `dt`, relative:
/// output times are multiples of the interval computed in `f64`.
const SPACING_SLACK: f64 = 1e-6;

/// The ride at a seat over a run: the four figures a mobility engineer
/// reads off it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RideFigures {
    /// Absorbed power (vertical; Pradko & Lee), W: the 6 W ride limit's
    /// figure.
    pub absorbed_power: f64,
    /// ISO 2631-1 `W_k`-weighted RMS of the vertical acceleration, m/s².
    pub wk_rms: f64,
    /// ISO 2631-1 `W_d`-weighted RMS of the longitudinal acceleration,
    /// m/s².
    pub wd_rms: f64,
    /// The largest vertical acceleration after the 30 Hz low-pass, in g:
    /// the half-round's 2.5 g limit's figure.
    pub peak_g: f64,
    /// The samples measured (those from the start of the measurement).
    pub samples: u64,
}

/// Why a [`RideSink`] cannot be made: its sample interval resolves too
/// little of the band the criteria weigh.
#[derive(Debug, Clone, Copy, PartialEq, thiserror::Error)]
#[error(
    "ride figures need rows at most {max} s apart (the ISO 2631-1 band reaches 100 Hz), got {dt} s"
)]
pub struct RideIntervalError {
    /// The interval asked for, s.
    pub dt: f64,
    /// The largest allowed, s.
    pub max: f64,
}

/// A stretch of ground to measure over: the hull's `x` (the column `x`)
/// from `x0` to `x1`, m.
#[derive(Debug, Clone, Copy)]
struct Stretch {
    x0: f64,
    x1: f64,
}

/// A sink that runs the seat's recorded acceleration through the ride
/// criteria as the rows arrive: the vertical column (`seat_az` by
/// default) through the absorbed power, `W_k` and the peak and into its
/// spectrum ([`spectrum`](Self::spectrum)), the longitudinal one
/// (`seat_ax`) through `W_d`. The filters run from the
/// first row, so their state has settled when the measurement starts at
/// [`from`](Self::from) (a speed ramp, a run-in). The rows must be evenly
/// spaced by the `dt` it was made for (the run's `Output::Every(dt)`): a
/// row off that spacing is refused.
#[derive(Debug, Clone)]
pub struct RideSink {
    columns: [String; 2],
    at: Option<[usize; 2]>,
    stretch: Option<Stretch>,
    ended: bool,
    dt: f64,
    from: f64,
    last: Option<f64>,
    measuring: bool,
    absorbed: AbsorbedPower,
    wk: IsoWeighting,
    wd: IsoWeighting,
    peak: PeakVertical,
    spectrum: Welch,
    /// The column `x`, if the run has one, and the first and last
    /// measured (t, x): the mean speed over the measurement.
    x: Option<usize>,
    travel: Option<[(f64, f64); 2]>,
}

impl RideSink {
    /// The least span of a spectrum's segment, s: its bins are at most
    /// 0.25 Hz apart, finer than a hull's pitch and bounce (1–4 Hz) are
    /// wide.
    pub const SPECTRUM_SEGMENT: f64 = 4.0;

    /// The largest row interval the criteria take, s: 2 ms, a Nyquist
    /// frequency of 250 Hz, well above the 100 Hz band limit of ISO
    /// 2631-1's weightings (the filters are exact to a part in a thousand
    /// there: `ride`'s docs).
    pub const MAX_INTERVAL: f64 = 2e-3;

    /// Ride figures of the columns `seat_az` (vertical) and `seat_ax`
    /// (longitudinal), m/s², for rows `dt` s apart, measured from time
    /// `from` (s) on.
    pub fn new(dt: f64, from: f64) -> Result<RideSink, RideIntervalError> {
        Self::of_columns("seat_az", "seat_ax", dt, from)
    }

    /// [`new`](Self::new) for other columns.
    pub fn of_columns(
        vertical: &str,
        longitudinal: &str,
        dt: f64,
        from: f64,
    ) -> Result<RideSink, RideIntervalError> {
        if !(dt > 0.0 && dt <= Self::MAX_INTERVAL) {
            return Err(RideIntervalError {
                dt,
                max: Self::MAX_INTERVAL,
            });
        }
        Ok(RideSink {
            columns: [vertical.to_string(), longitudinal.to_string()],
            at: None,
            stretch: None,
            ended: false,
            dt,
            from,
            last: None,
            measuring: false,
            absorbed: AbsorbedPower::new(dt),
            wk: IsoWeighting::wk(dt),
            wd: IsoWeighting::wd(dt),
            peak: PeakVertical::new(dt),
            spectrum: Welch::new(dt, Welch::segment_for(dt, Self::SPECTRUM_SEGMENT))
                .expect("a positive interval and a power-of-two segment"),
            x: None,
            travel: None,
        })
    }

    /// When the measurement starts, s.
    pub fn from(&self) -> f64 {
        self.from
    }

    /// Measures over a stretch of ground rather than from a time on: from
    /// the first row (at or after [`from`](Self::from)) whose hull
    /// position, the column `x` (m), has reached `x0`, to the last row
    /// before it passes `x1`. A ride course is measured over its rough
    /// stretch whatever speed the vehicle actually reaches.
    pub fn over_stretch(self, x0: f64, x1: f64) -> RideSink {
        RideSink {
            stretch: Some(Stretch { x0, x1 }),
            ..self
        }
    }

    /// Whether the measurement has ended: the hull has passed the
    /// stretch's end ([`over_stretch`](Self::over_stretch)).
    pub fn ended(&self) -> bool {
        self.ended
    }

    /// The spectrum of the vertical acceleration over the rows measured
    /// so far (Welch's, segments of at least
    /// [`SPECTRUM_SEGMENT`](Self::SPECTRUM_SEGMENT)); `None` until one
    /// segment has been measured. [`Spectrum::absorbed`] splits the
    /// absorbed power by frequency.
    pub fn spectrum(&self) -> Option<Spectrum> {
        self.spectrum.spectrum()
    }

    /// The mean forward speed over the rows measured so far, m/s, from
    /// the column `x`; `None` without it or before two rows.
    pub fn mean_speed(&self) -> Option<f64> {
        let [(t0, x0), (t1, x1)] = self.travel?;
        (t1 > t0).then(|| (x1 - x0) / (t1 - t0))
    }

    /// The figures over the rows measured so far (NaN, and no samples,
    /// before the measurement starts).
    pub fn figures(&self) -> RideFigures {
        if !self.measuring {
            return RideFigures {
                absorbed_power: f64::NAN,
                wk_rms: f64::NAN,
                wd_rms: f64::NAN,
                peak_g: f64::NAN,
                samples: 0,
            };
        }
        RideFigures {
            absorbed_power: self.absorbed.power(),
            wk_rms: self.wk.rms(),
            wd_rms: self.wd.rms(),
            peak_g: self.peak.peak_g(),
            samples: self.absorbed.samples(),
        }
    }
}

impl Sink for RideSink {
    fn begin(&mut self, columns: &[String]) -> Result<(), SinkError> {
        let find = |name: &str| {
            columns.iter().position(|c| c == name).ok_or_else(|| {
                SinkError::Columns(format!("ride figures: no column `{name}` in the run"))
            })
        };
        self.at = Some([find(&self.columns[0])?, find(&self.columns[1])?]);
        // A stretch needs the hull's `x`; the mean speed takes it where
        // the run has it.
        self.x = match self.stretch {
            Some(_) => Some(find("x")?),
            None => columns.iter().position(|c| c == "x"),
        };
        Ok(())
    }

    fn row(&mut self, t: f64, values: &[f64]) -> Result<(), SinkError> {
        let Some([vertical, longitudinal]) = self.at else {
            return Err(SinkError::Columns(
                "ride figures: a row before `begin`".to_string(),
            ));
        };
        if let Some(last) = self.last
            && ((t - last) - self.dt).abs() > SPACING_SLACK * self.dt
        {
            return Err(SinkError::Columns(format!(
                "ride figures: rows {} s apart at t = {t} s, not every {} s",
                t - last,
                self.dt
            )));
        }
        self.last = Some(t);
        let (Some(&az), Some(&ax)) = (values.get(vertical), values.get(longitudinal)) else {
            return Err(SinkError::width(
                t,
                values.len(),
                vertical.max(longitudinal) + 1,
            ));
        };
        let (reached, passed) = match (&self.stretch, self.x) {
            (Some(Stretch { x0, x1 }), Some(c)) => {
                let x = values.get(c).copied().unwrap_or(f64::NAN);
                (x >= *x0, x > *x1)
            }
            _ => (true, false),
        };
        if passed && self.measuring {
            self.ended = true;
        }
        if self.ended {
            return Ok(());
        }
        if !self.measuring && t >= self.from && reached {
            self.measuring = true;
            self.absorbed.start_measuring();
            self.wk.start_measuring();
            self.wd.start_measuring();
            self.peak.start_measuring();
        }
        self.absorbed.push(az);
        // The spectrum has no filter state to settle: the measured rows
        // only.
        if self.measuring {
            self.spectrum.push(az);
            if let Some(x) = self.x.and_then(|c| values.get(c)).copied() {
                let first = self.travel.map_or((t, x), |[first, _]| first);
                self.travel = Some([first, (t, x)]);
            }
        }
        self.wk.push(az);
        self.wd.push(ax);
        self.peak.push(az);
        Ok(())
    }

    fn finish(&mut self) -> Result<(), SinkError> {
        Ok(())
    }

    /// The seat's two columns and, where the run has it, `x`.
    fn reads(&self) -> Option<Vec<usize>> {
        let [vertical, longitudinal] = self.at?;
        Some(
            [Some(vertical), Some(longitudinal), self.x]
                .into_iter()
                .flatten()
                .collect(),
        )
    }
}
