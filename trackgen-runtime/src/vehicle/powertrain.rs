//! What the engine can give at the sprocket: the torque a drive may ask
//! for, as a function of the sprocket's speed.

use super::PowertrainError;
use super::converter::{Driveline, OperatingPoint};
use super::shift::Engaged;
use super::tables::{engine_torque, table};

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

    /// The torque at rest, N m, forward and in reverse (reverse as
    /// forward without a reverse range): found once per run, the cap's
    /// stall.
    pub(crate) fn stall_torques(&self) -> (f64, f64) {
        (self.limit(0.0).0, self.cap(0.0, None, true).torque)
    }

    /// The largest driving torque at sprocket speed `|ω|` (`speed`, rad/s,
    /// ≥ 0), N m, and its slope with `|ω|`, N m s/rad.
    pub fn limit(&self, speed: f64) -> (f64, f64) {
        let (torque, slope, _) = self.limit_in_gear(speed);
        (torque, slope)
    }

    /// [`limit`](Self::limit), and the gear (0-based) that gives it: the
    /// range an ideally shifted gearbox is in at that speed (`None` for a
    /// [`Power`](Self::Power) limit, or where no gear drives).
    pub fn limit_in_gear(&self, speed: f64) -> (f64, f64, Option<usize>) {
        let cap = self.cap(speed, None, false);
        (cap.torque, cap.slope, cap.gear)
    }

    /// [`limit_in_gear`](Self::limit_in_gear), with a converter's
    /// full-load point in that gear (for [`engine_side`](Self::engine_side)
    /// to start from); a converter with a shift schedule in the range
    /// `engaged` ([`Driveline::scheduled`]); a converter with a reverse
    /// range in it where the driver asks to `reverse`.
    pub(super) fn cap(&self, speed: f64, engaged: Option<Engaged>, reverse: bool) -> Cap {
        if let (Powertrain::Converter(driveline), true) = (self, reverse)
            && let Some(range) = driveline.reverse_range()
        {
            let (torque, slope, point) = driveline.in_range(range, speed);
            return Cap {
                torque,
                slope,
                gear: Some(range),
                point,
            };
        }
        if let (Powertrain::Converter(driveline), Some(engaged)) = (self, engaged)
            && driveline.shift.is_some()
        {
            let (torque, slope, range, point) = driveline.scheduled(engaged, speed);
            return Cap {
                torque,
                slope,
                gear: Some(range),
                point,
            };
        }
        let (torque, slope, gear) = match self {
            Powertrain::Power { power, max_torque } => {
                if speed * max_torque > *power {
                    (power / speed, -power / (speed * speed), None)
                } else {
                    (*max_torque, 0.0, None)
                }
            }
            Powertrain::Engine {
                map,
                ratios,
                fraction,
            } => {
                let mut best = (0.0, 0.0, None);
                let peak = peak_of(map);
                for (gear, &ratio) in ratios.iter().enumerate() {
                    let engine = speed / ratio;
                    let (torque, slope) = map_at(map, peak, engine);
                    let (torque, slope) = (
                        fraction * torque / ratio,
                        fraction * slope / (ratio * ratio),
                    );
                    if torque > best.0 {
                        best = (torque, slope, Some(gear));
                    }
                }
                best
            }
            Powertrain::Converter(driveline) => {
                let (torque, slope, best) = driveline.envelope_point(speed);
                return Cap {
                    torque,
                    slope,
                    gear: best.map(|(range, _)| range),
                    point: best.map(|(_, point)| point),
                };
            }
        };
        Cap {
            torque,
            slope,
            gear,
            point: None,
        }
    }

    /// The engine's side of a drive that gives the sprocket `torque`
    /// (N m, ≥ 0, pushing the way the driver asks) while it turns at
    /// `speed` (rad/s, positive the way the torque pushes, negative while
    /// the vehicle forces it back) in `gear` (0-based, as
    /// [`limit_in_gear`](Self::limit_in_gear) found it): the engine's
    /// speed and torque, the converter's state, and the power at each
    /// stage for this side.
    ///
    /// Through a [`Converter`](Self::Converter): [`Driveline::part_load`],
    /// the turbine at `n ω` giving `τ / (fraction · n)` (`n` the range's
    /// reduction with the final drive's); this side's share of the
    /// engine's power is `share · T_e ω_e`, of the turbine's
    /// `share · T_t ω_t`, and the sprocket gets the gearbox's and final
    /// drive's efficiencies times the turbine's. The simple forms state no
    /// stages apart: through an [`Engine`](Self::Engine) map the engine's
    /// speed and torque are the gear's (held at the map's peak while the
    /// clutch slips), and with a [`Power`](Self::Power) limit there is no
    /// engine speed; for both the engine's power is booked at the
    /// sprocket, `τ ω`.
    pub fn engine_side(&self, gear: Option<usize>, speed: f64, torque: f64) -> EngineSide {
        self.engine_side_near(gear, None, speed, torque)
    }

    /// [`engine_side`](Self::engine_side) with a converter's full-load
    /// point in `gear` at `|speed|` (`full`, as the cap found it), which
    /// starts the part-load solve while the sprocket turns the torque's
    /// way.
    pub(super) fn engine_side_near(
        &self,
        gear: Option<usize>,
        full: Option<OperatingPoint>,
        speed: f64,
        torque: f64,
    ) -> EngineSide {
        let at_sprocket = EngineSide {
            gear,
            engine_speed: 0.0,
            engine_torque: 0.0,
            speed_ratio: 0.0,
            torque_ratio: 0.0,
            locked: None,
            engine_power: torque * speed,
            turbine_power: torque * speed,
        };
        match (self, gear) {
            (
                Powertrain::Engine {
                    map,
                    ratios,
                    fraction,
                },
                Some(gear),
            ) => {
                let ratio = ratios[gear];
                let held = peak_of(map).map_or(0.0, |p| p.0);
                EngineSide {
                    engine_speed: (speed / ratio).max(held),
                    engine_torque: torque * ratio / fraction,
                    ..at_sprocket
                }
            }
            (Powertrain::Converter(driveline), Some(range)) => {
                let n = driveline.reduction(range);
                let tt = torque / (driveline.fraction() * n);
                let point = match full {
                    Some(full) if speed >= 0.0 => {
                        driveline.part_load_near(range, n * speed, tt, Some(full))
                    }
                    _ => driveline.part_load(range, n * speed, tt),
                };
                let share = driveline.share;
                EngineSide {
                    gear: Some(range),
                    engine_speed: point.engine_speed,
                    engine_torque: point.engine_torque,
                    speed_ratio: point.speed_ratio,
                    torque_ratio: point.torque_ratio,
                    locked: Some(point.locked),
                    engine_power: share * point.engine_torque * point.engine_speed,
                    turbine_power: share * tt * n * speed,
                }
            }
            _ => at_sprocket,
        }
    }

    /// Its transmission's minimum steer ratios, one per forward range
    /// ([`Driveline::steer_ratios`]): empty for a powertrain with no steer
    /// unit declared (every form but a converter's).
    pub fn steer_ratios(&self) -> &[f64] {
        match self {
            Powertrain::Converter(driveline) => &driveline.steer_ratios,
            _ => &[],
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

/// The powertrain's cap at one sprocket speed
/// ([`Powertrain::limit_in_gear`]), with a converter's full-load point in
/// the gear that gives it.
#[derive(Debug, Clone, Copy)]
pub(super) struct Cap {
    /// N m.
    pub torque: f64,
    /// N m s/rad.
    pub slope: f64,
    /// 0-based.
    pub gear: Option<usize>,
    pub point: Option<OperatingPoint>,
}

/// The engine's side of the drive at one instant
/// ([`Powertrain::engine_side`]): what a run records of its powertrain.
/// Speeds in rad/s, torques in N m, powers in W; a figure the powertrain
/// does not define is 0 (a run's results hold numbers only).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct EngineSide {
    /// The gear or range (0-based), if the powertrain has gears.
    pub gear: Option<usize>,
    /// The engine's speed.
    pub engine_speed: f64,
    /// The engine's torque (the whole engine's, both sides').
    pub engine_torque: f64,
    /// The converter's speed ratio `ω_t / ω_p` (1 when locked).
    pub speed_ratio: f64,
    /// The converter's torque ratio `T_t / T_p` (1 when locked).
    pub torque_ratio: f64,
    /// Whether the converter's lock-up clutch is engaged (`None`: no
    /// converter).
    pub locked: Option<bool>,
    /// This side's share of the engine's power.
    pub engine_power: f64,
    /// This side's share of the converter's output (the turbine's) power.
    pub turbine_power: f64,
}

impl Default for EngineSide {
    fn default() -> EngineSide {
        EngineSide::IDLE
    }
}

impl EngineSide {
    /// The engine side of a drive that takes nothing from the engine (no
    /// powertrain, or braking): no power at any stage, no figure.
    pub const IDLE: EngineSide = EngineSide {
        gear: None,
        engine_speed: 0.0,
        engine_torque: 0.0,
        speed_ratio: 0.0,
        torque_ratio: 0.0,
        locked: None,
        engine_power: 0.0,
        turbine_power: 0.0,
    };
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
