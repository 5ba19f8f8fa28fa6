//! What the engine can give at the sprocket: the torque a drive may ask
//! for, as a function of the sprocket's speed.

use super::PowertrainError;
use super::converter::{Driveline, engine_torque, table};

/// The engine and the driveline behind a sprocket, as the largest torque
/// they give it at each sprocket speed ([`limit`](Self::limit)). A drive
/// asks for what it wants; while the torque drives the sprocket (it turns
/// the sprocket the way it already turns, or starts it), the powertrain
/// caps it there. Braking torque is the brake's and the controller's.
#[derive(Debug, Clone, PartialEq)]
pub enum Powertrain {
    /// A power and a torque limit at the sprocket:
    /// `|τ| ≤ min(τ_max, P / |ω|)`. Power and torque are what reaches this
    /// sprocket (its side's share of the engine's, after the driveline's
    /// losses).
    Power {
        /// W, more than 0.
        power: f64,
        /// N m, more than 0.
        max_torque: f64,
    },
    /// An engine's full-load torque map through a gearbox whose gears are
    /// chosen ideally (at each speed the gear giving the most torque), as
    /// a mobility model's tractive-effort envelope does: at sprocket speed
    /// `ω`, `max_g fraction · T(ω / r_g) / r_g` over the gears `r_g`
    /// whose engine speed `ω / r_g` is on the map. Below the speed of the
    /// map's largest torque the clutch slips, the engine held at that
    /// speed: a start or a crawl gets the map's largest torque through the
    /// lowest gear (no torque converter's multiplication: the figures give
    /// none); beyond the map's last speed the engine gives nothing.
    Engine {
        /// Full-load engine torque, N m, against engine speed, rad/s:
        /// speeds increasing, at least two points; torque linear between
        /// them (negative values, a cut-off's, count as no drive).
        map: Vec<(f64, f64)>,
        /// The forward gears' overall ratios, sprocket speed over engine
        /// speed (the final drive included), each more than 0.
        ratios: Vec<f64>,
        /// The fraction of the engine's torque times speed that reaches
        /// this sprocket: the driveline's efficiency times this side's
        /// share (0.5 of a two-track vehicle's), in (0, 1].
        fraction: f64,
    },
    /// An engine through a torque converter (with a lock-up clutch), a
    /// range gearbox and a final drive, at full load with the range chosen
    /// ideally (at each speed the range giving the most torque): at rest
    /// the converter multiplies the engine's stall torque by its stall
    /// torque ratio. See [`Driveline`].
    Converter(Box<Driveline>),
}

impl Powertrain {
    /// Every figure in its range.
    pub fn check(&self) -> Result<(), PowertrainError> {
        match self {
            Powertrain::Power { power, max_torque } => {
                for (what, value) in [("power", *power), ("max_torque", *max_torque)] {
                    if !(value.is_finite() && value > 0.0) {
                        return Err(PowertrainError::Limit { what, value });
                    }
                }
                Ok(())
            }
            Powertrain::Engine {
                map,
                ratios,
                fraction,
            } => {
                table(map, "engine's full-load torque", |_| true)?;
                if ratios.is_empty() {
                    return Err(PowertrainError::Ratio {
                        gear: 0,
                        ratio: f64::NAN,
                    });
                }
                for (gear, &ratio) in ratios.iter().enumerate() {
                    if !(ratio.is_finite() && ratio > 0.0) {
                        return Err(PowertrainError::Ratio { gear, ratio });
                    }
                }
                if !(*fraction > 0.0 && *fraction <= 1.0) {
                    return Err(PowertrainError::Fraction(*fraction));
                }
                Ok(())
            }
            Powertrain::Converter(driveline) => driveline.check(),
        }
    }

    /// The largest driving torque at sprocket speed `|ω|` (`speed`, rad/s,
    /// ≥ 0), N m, and its slope with `|ω|`, N m s/rad.
    pub fn limit(&self, speed: f64) -> (f64, f64) {
        match self {
            Powertrain::Power { power, max_torque } => {
                if speed * max_torque > *power {
                    (power / speed, -power / (speed * speed))
                } else {
                    (*max_torque, 0.0)
                }
            }
            Powertrain::Engine {
                map,
                ratios,
                fraction,
            } => {
                let mut best = (0.0, 0.0);
                let peak = peak_of(map);
                for &ratio in ratios {
                    let engine = speed / ratio;
                    let (torque, slope) = map_at(map, peak, engine);
                    let (torque, slope) = (
                        fraction * torque / ratio,
                        fraction * slope / (ratio * ratio),
                    );
                    if torque > best.0 {
                        best = (torque, slope);
                    }
                }
                best
            }
            Powertrain::Converter(driveline) => {
                let (torque, slope, _) = driveline.envelope(speed);
                (torque, slope)
            }
        }
    }

    /// The most power it gives the sprocket, W: `P`, or the map's largest
    /// `fraction · T ω` (at one of its points: between two the product of
    /// linear pieces is checked at its vertex too).
    pub fn max_power(&self) -> f64 {
        match self {
            Powertrain::Power { power, .. } => *power,
            Powertrain::Engine { map, fraction, .. } => {
                let mut best: f64 = 0.0;
                for w in map.windows(2) {
                    let ((w0, t0), (w1, t1)) = (w[0], w[1]);
                    best = best.max(w0 * t0).max(w1 * t1);
                    // T ω with T linear in ω peaks where d(Tω)/dω = 0.
                    let slope = (t1 - t0) / (w1 - w0);
                    if slope < 0.0 {
                        let peak = (slope * w0 - t0) / (2.0 * slope);
                        if (w0..=w1).contains(&peak) {
                            best = best.max(peak * (t0 + slope * (peak - w0)));
                        }
                    }
                }
                fraction * best
            }
            Powertrain::Converter(driveline) => driveline.max_power(),
        }
    }
}

/// The map's point of largest torque (the first, if several), once per
/// [`Powertrain::limit`] for all its gears.
fn peak_of(map: &[(f64, f64)]) -> Option<(f64, f64)> {
    map.iter()
        .copied()
        .reduce(|best, p| if p.1 > best.1 { p } else { best })
}

/// The map's torque at engine speed `w` and its slope: linear between the
/// points, none beyond the last (a negative torque, a cut-off's, is none);
/// below the speed of the map's largest torque, `peak`, that torque (slope
/// 0): the clutch slips with the engine held at its peak torque, as it
/// does at a start or a crawl.
fn map_at(map: &[(f64, f64)], peak: Option<(f64, f64)>, w: f64) -> (f64, f64) {
    let Some(peak) = peak else {
        return (0.0, 0.0);
    };
    if w <= peak.0 {
        return (peak.1.max(0.0), 0.0);
    }
    engine_torque(map, w)
}
