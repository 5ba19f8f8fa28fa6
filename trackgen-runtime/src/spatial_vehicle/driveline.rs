//! How the drive reaches the two sprockets: each sprocket its own drive
//! ([`SideDrives`], a robot's two motors), or one drive through a
//! differential between the sprocket axles, steered by brakes on the
//! axles or by a steer unit that holds the two sprockets' speed ratio
//! ([`Differential`]).
//!
//! **The differential** (Willis's formula with the ordinary ratio
//! `t₀ = −1`, the form of Project Chrono's `ChTrackDrivelineBDS`, whose
//! `ChShaftsPlanetary` joins the differential's box to the two axles):
//! the box turns at the axles' mean speed `ω̄ = (ω_R + ω_L)/2` and its
//! torque `τ` reaches each axle halved. Its gears and box are massless
//! here (their inertia is small beside the vehicle's reflected to the
//! sprocket), so the split is exact at every instant and the box's power
//! `τ ω̄` is the two axles' `τ/2 (ω_R + ω_L)`. Left alone it lets the
//! two sprockets run at any speeds about that mean: a differential steers
//! by what holds one side back.
//!
//! **Steering brakes** (the braked differential: the driver brakes the
//! inner axle, and the differential sends what the brake takes from it to
//! the outer one). Each brake holds by stiction, as the parking brake
//! does ([`Brake`](crate::vehicle::Brake)): the ground's stiction law
//! ([`Stiction`]) in rotation, with the brake's torque as its limit, its
//! deflection `φ` a state: `τ = −(k φ + c ω)` while it holds, the limit
//! against the slip beyond; released, its deflection relaxes through the
//! damper. What it stores and dissipates goes to the books.
//!
//! **A steer unit** (the hydrostatically controlled differential of the
//! M113A3's Allison X200-4, whose minimum steer ratios are published per
//! range: US Army Ordnance subcourse OD1714, lesson 1): it drives the two
//! axles apart with equal and opposite torques `±Q` (its power `Q (ω_R −
//! ω_L)` drawn from the engine, part of what the engine gives), holding
//! the speed difference at `s q ω̄` for a steering input `s` in `[−1, 1]`,
//! `q = 2 (ρ − 1)/(ρ + 1)` so that full steer turns the outer sprocket `ρ`
//! times as fast as the inner (the minimum steer ratio). In the real
//! transmission the steer speed is the engine's times the input, and the
//! ratio it makes falls with the range's gear; held against the
//! sprockets' mean speed, as here, it is the ratio of the range in use.
//! The unit is a PI controller on the speed difference (the hydrostatic
//! loop's stiffness and leak), limited to its largest torque (the relief
//! valve's). It cannot pivot the vehicle from rest (the mean speed is
//! zero there).
//!
//! **In neutral** ([`FullSteer::Neutral`]) no range drives the differential's
//! box, while the steer drive, geared to the engine, still turns the two
//! sprockets apart: the X200-4 pivots the vehicle (OD1714). The unit then
//! holds the speed difference at `s k ω_e`, `ω_e` the engine's speed held
//! by its governor and `k` the steer drive's ratio, whatever the
//! sprockets' mean. The box's drive says what holds the mean: free, it
//! settles where the two tracks' resistances balance, and the vehicle
//! creeps toward the side that resists less as it turns; held at rest,
//! the tracks turn at equal and opposite speeds and the vehicle pivots
//! about its centre. The published minimum steer ratios give `k`: in
//! range `r`, locked up, the sprockets' mean turns at `ω̄ = ω_e / N_r`
//! (`N_r` the range's reduction with the final drive), so full steer's
//! `q_r ω̄` is `(q_r / N_r) ω_e`, and a steer drive geared to the engine
//! makes `q_r / N_r` the same in every range
//! ([`steer_drive_ratio`]: the X200-4's four agree within 0.9 % of
//! their mean).

use thiserror::Error;

use super::{SpatialEngine, SteeringError};
use crate::laws::{ParameterError, Stiction, TangentialResponse};
use crate::vehicle::{Drive, DriveError, Powertrain};

/// How many states the driveline keeps ([`SpatialSystem`](super::SpatialSystem)'s docs): three of its
/// drive and brakes or steer unit, then the engine's speed and twist.
pub(super) const DRIVELINE: usize = 5;
/// Where the engine's speed sits among the driveline's states (its
/// twist next).
pub(super) const ENGINE_SPEED: usize = 3;

/// The two sprockets' drives.
pub struct SideDrives {
    /// The right sprocket's.
    pub right: Drive,
    /// The left sprocket's.
    pub left: Drive,
}

impl SideDrives {
    /// Both sprockets free.
    pub fn free() -> SideDrives {
        SideDrives {
            right: Drive::Free,
            left: Drive::Free,
        }
    }

    /// Why either drive's settings make no controller
    /// ([`Drive::check`]).
    pub fn check(&self) -> Result<(), DriveError> {
        self.right.check()?;
        self.left.check()
    }

    /// The drives right then left.
    pub(super) fn each(&self) -> [&Drive; 2] {
        [&self.right, &self.left]
    }
}

/// The driver's steering input against time (s): −1 full right to 1 full
/// left (0 straight).
pub type SteerInput = Box<dyn Fn(f64) -> f64 + Send>;

/// How the drive reaches the two sprockets.
pub enum Driveline {
    /// Each sprocket its own drive.
    Sides(SideDrives),
    /// One drive through a differential, steered.
    Differential(Differential),
}

/// One drive into a differential between the sprocket axles, and how it
/// steers.
pub struct Differential {
    /// The drive on the differential's box: its speed the axles' mean,
    /// its torque halved to each (a speed drive's target is the belts'
    /// mean speed, its gains and limit the box's, twice a side's).
    pub drive: Drive,
    /// What steers it.
    pub steer: DifferentialSteer,
    /// The driver's steering input, if no heading is held
    /// ([`HeadingHold`](super::HeadingHold) steers through the same
    /// brakes or unit when one is).
    pub input: SteerInput,
    /// The engine driving the box, its speed a state
    /// ([`SpatialEngine`]): the drive's demand is then asked of it, and
    /// the box gets what its converter and range give. `None`: the drive
    /// is the box's own (capped by an envelope, if one is set).
    pub engine: Option<SpatialEngine>,
}

/// What steers a differential.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum DifferentialSteer {
    /// A brake on each axle.
    Brakes(SteeringBrakes),
    /// A steer unit holding the sprockets' speed difference: their ratio
    /// in a range, the steer drive's difference in neutral.
    Unit(SteerUnit),
}

/// A steering brake on each sprocket axle: an input `s` brakes the left
/// axle with `s` times the largest torque (a left turn), `−s` the right.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SteeringBrakes {
    /// Each brake's largest torque, N m, > 0.
    pub max_torque: f64,
    /// Its elastic stage's stiffness, N m/rad, > 0.
    pub stiffness: f64,
    /// Its elastic stage's damping, N m s/rad, > 0.
    pub damping: f64,
    /// For a driver holding a heading: the error, m/s, of the gauge times
    /// the heading's rate against the belts' speed difference asked
    /// ([`HeadingHold::difference`](super::HeadingHold::difference)) at
    /// which the inner brake is fully on, > 0; less brakes in
    /// proportion.
    pub band: f64,
    /// The error, m/s, inside which such a driver leaves the brakes at
    /// rest, ≥ 0 (the band counts from its edge). The hull's yaw rate
    /// carries the tracks' ripple, and a driver braking on all of it
    /// spent 2.3 times the side drives' work on the M113's straight run
    /// (0.05 m/s of dead band: 1.02 times).
    pub dead_band: f64,
}

/// A steer unit: equal and opposite torques on the two axles holding
/// their speed difference at `s` times full steer's for a steering input
/// `s`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SteerUnit {
    /// What full steer holds the difference at.
    pub full_steer: FullSteer,
    /// The PI controller's proportional gain on the speed difference,
    /// N m s/rad, ≥ 0.
    pub proportional: f64,
    /// Its integral gain, N m/rad, ≥ 0.
    pub integral: f64,
    /// Its largest torque on each axle, N m, > 0.
    pub max_torque: f64,
}

/// What a steer unit's full steer holds the sprockets' speed difference
/// at.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum FullSteer {
    /// In a range: the outer sprocket at most this many times as fast as
    /// the inner (the minimum steer ratio `ρ`, > 1), against their mean:
    /// `q ω̄`, `q` = [`span`]`(ρ)`.
    Ratio(f64),
    /// In neutral: this difference, rad/s (> 0), whatever their mean (the
    /// steer drive's `k ω_e`, [`SteerDrive::full_difference`]): a pivot,
    /// the box's drive free or holding the mean at rest.
    Neutral(f64),
    /// In any range, a steer drive geared to the engine whose speed is a
    /// state ([`Differential::engine`]): `k ω_e`, `k` this ratio (> 0,
    /// [`SteerDrive::ratio`]), whatever the range and the converter's
    /// slip. With the converter locked in range `r` it is `q_r ω̄`, the
    /// range's minimum steer ratio; through the unlocked converter, at a
    /// crawl, the engine turns faster than the box and the turn is
    /// tighter.
    Engine(f64),
}

/// `q`: a steer unit's speed difference at full steer over the sprockets'
/// mean speed for the minimum steer ratio `rho`, `2 (ρ − 1)/(ρ + 1)` (the
/// outer sprocket at `ω̄ (1 + q/2)`, the inner at `ω̄ (1 − q/2)`).
pub fn span(rho: f64) -> f64 {
    2.0 * (rho - 1.0) / (rho + 1.0)
}

/// Published steer ratios that no steer drive geared to the engine makes.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum SteerRatiosError {
    /// Not one ratio per range.
    #[error("{ratios} minimum steer ratios for {ranges} ranges: one per range is needed")]
    Count {
        /// How many ratios.
        ratios: usize,
        /// How many ranges.
        ranges: usize,
    },
    /// A ratio or a reduction out of its range.
    #[error("range {range}: {source}")]
    Figure {
        /// The range, 1-based.
        range: usize,
        /// Which figure, and its range.
        source: ParameterError,
    },
}

/// The steer drive's ratio `k` that the minimum steer ratios `ratios` of
/// ranges whose overall reductions (engine over sprocket speed, the
/// final drive's included) are `reductions` imply: each range's
/// `q_r / N_r` (`q_r = 2 (ρ_r − 1)/(ρ_r + 1)`, the sprockets' speed
/// difference at full steer over their mean), their mean, and the largest
/// departure of one from it as a fraction of it. Full steer turns the
/// sprockets `k ω_e` apart (rad/s) with the engine at `ω_e`: in range `r`
/// with the converter locked the mean is `ω_e / N_r`, so a steer drive
/// geared to the engine makes every range's `q_r / N_r` the same.
pub fn steer_drive_ratio(
    ratios: &[f64],
    reductions: &[f64],
) -> Result<(f64, f64), SteerRatiosError> {
    if ratios.len() != reductions.len() || ratios.is_empty() {
        return Err(SteerRatiosError::Count {
            ratios: ratios.len(),
            ranges: reductions.len(),
        });
    }
    let mut each = Vec::with_capacity(ratios.len());
    for (r, (&rho, &n)) in ratios.iter().zip(reductions).enumerate() {
        let figure = |source| SteerRatiosError::Figure {
            range: r + 1,
            source,
        };
        ParameterError::check("minimum steer ratio", rho, 1.0, true).map_err(figure)?;
        ParameterError::check("overall reduction", n, 0.0, true).map_err(figure)?;
        each.push(span(rho) / n);
    }
    let k = each.iter().sum::<f64>() / each.len() as f64;
    let departure = each.iter().fold(0.0_f64, |m, e| m.max((e / k - 1.0).abs()));
    Ok((k, departure))
}

/// A transmission's steer drive, geared to its engine: what turns the
/// sprockets apart in neutral ([`FullSteer::Neutral`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SteerDrive {
    /// Its ratio `k`: the sprockets' speed difference at full steer over
    /// the engine's speed ([`steer_drive_ratio`]).
    pub ratio: f64,
    /// The largest departure of one range's `q_r / N_r` from `k`, as a
    /// fraction of it.
    pub departure: f64,
    /// The engine's speed it turns at, rad/s: its rated speed, the
    /// governor at full throttle ([`Driveline::rated_speed`](crate::vehicle::Driveline::rated_speed)).
    pub engine_speed: f64,
}

impl SteerDrive {
    /// The steer drive that `powertrain`'s minimum steer ratios
    /// ([`Powertrain::steer_ratios`]) imply for its ranges; `None` where
    /// it declares none or has no ranges (a converter's).
    pub fn of(powertrain: &Powertrain) -> Result<Option<SteerDrive>, SteerRatiosError> {
        let Powertrain::Converter(converter) = powertrain else {
            return Ok(None);
        };
        let ratios = &converter.steer_ratios;
        if ratios.is_empty() {
            return Ok(None);
        }
        let reductions: Vec<f64> = (0..converter.ranges.len())
            .map(|r| converter.reduction(r))
            .collect();
        let (ratio, departure) = steer_drive_ratio(ratios, &reductions)?;
        Ok(Some(SteerDrive {
            ratio,
            departure,
            engine_speed: converter.rated_speed(),
        }))
    }

    /// The sprockets' speed difference at full steer, rad/s: `k ω_e`.
    pub fn full_difference(&self) -> f64 {
        self.ratio * self.engine_speed
    }
}

/// A driveline that makes no driveline.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum DrivelineError {
    /// A drive's settings make no controller.
    #[error(transparent)]
    Drive(#[from] DriveError),
    /// A figure out of its range.
    #[error("the {what}: {source}")]
    Figure {
        /// The brakes' or the steer unit's.
        what: &'static str,
        /// Which figure, and its range.
        source: ParameterError,
    },
    /// A differential joins both sprockets.
    #[error("a differential drives both sides' sprockets: the {side} side has none")]
    NoSprocket {
        /// `right` or `left`.
        side: &'static str,
    },
    /// The heading already held cannot be steered through it.
    #[error(transparent)]
    Steering(#[from] SteeringError),
    /// A steer drive geared to the engine without an engine whose speed
    /// is a state.
    #[error(
        "a steer drive geared to the engine (FullSteer::Engine) needs the differential's engine          (Differential::engine)"
    )]
    NoEngine,
}

impl Differential {
    /// A differential whose box is driven toward `target` (m/s of the
    /// belts' mean against time) by a speed drive of twice `side`'s gains
    /// and limit (`side` a side's speed drive: the box drives both
    /// sides), steered by a steer unit whose full steer is `full_steer`
    /// (a range's minimum steer ratio; or in neutral, with `target` at
    /// rest, the steer drive's difference: a pivot about the vehicle's
    /// centre) with half `side`'s gains (its torque acts on both
    /// sprockets, `±Q`, so their speed difference moves as under the two
    /// side drives) and `side`'s limit, its input 0 (a driver holding a
    /// heading steers through it). `None` where `side` is not a speed
    /// drive.
    pub fn with_steer_unit(
        side: &Drive,
        target: Box<dyn Fn(f64) -> f64 + Send>,
        full_steer: FullSteer,
    ) -> Option<Differential> {
        let Drive::Speed {
            proportional,
            integral,
            max_torque,
            ..
        } = *side
        else {
            return None;
        };
        Some(Differential {
            drive: Drive::Speed {
                target,
                proportional: 2.0 * proportional,
                integral: 2.0 * integral,
                max_torque: 2.0 * max_torque,
            },
            steer: DifferentialSteer::Unit(SteerUnit {
                full_steer,
                proportional: 0.5 * proportional,
                integral: 0.5 * integral,
                max_torque,
            }),
            input: Box::new(|_| 0.0),
            engine: None,
        })
    }
}

impl SteerUnit {
    /// The sprockets' speed difference `ω_R − ω_L` at full left steer,
    /// rad/s, with their mean at `mean` rad/s and the engine at
    /// `engine_speed` rad/s (planar sense: forward turns them negative,
    /// and a left turn slows the left sprocket; a steer drive geared to
    /// the engine turns them as forward unless the mean runs backward).
    pub fn full_difference(&self, mean: f64, engine_speed: f64) -> f64 {
        match self.full_steer {
            FullSteer::Ratio(rho) => span(rho) * mean,
            FullSteer::Neutral(difference) => -difference,
            FullSteer::Engine(k) => {
                let difference = k * engine_speed;
                if mean > 0.0 { difference } else { -difference }
            }
        }
    }

    /// The unit's PI law on the speed difference, as a speed drive on a
    /// unit radius whose target, the difference wanted, comes as its trim
    /// (one owner of the PI law and its anti-windup: [`Drive`]).
    pub(super) fn controller(&self) -> Drive {
        Drive::Speed {
            target: Box::new(|_| 0.0),
            proportional: self.proportional,
            integral: self.integral,
            max_torque: self.max_torque,
        }
    }

    fn check(&self) -> Result<(), ParameterError> {
        match self.full_steer {
            FullSteer::Ratio(rho) => ParameterError::check("minimum steer ratio", rho, 1.0, true)?,
            FullSteer::Neutral(d) => ParameterError::check("full-steer difference", d, 0.0, true)?,
            FullSteer::Engine(k) => ParameterError::check("steer drive's ratio", k, 0.0, true)?,
        }
        ParameterError::check("proportional gain", self.proportional, 0.0, false)?;
        ParameterError::check("integral gain", self.integral, 0.0, false)?;
        ParameterError::check("largest torque", self.max_torque, 0.0, true)
    }
}

impl SteeringBrakes {
    /// Brakes of `max_torque` N m each on sprockets carrying `inertia`
    /// kg m² (the vehicle's mass reflected to one), their elastic stage
    /// the parking brake's ([`Brake::parking`](crate::vehicle::Brake::parking):
    /// 10 mrad of wind-up at the largest torque, damping ratio 0.5), fully
    /// on at `band` m/s of a driver's error beyond a dead band of
    /// `dead_band` m/s.
    pub fn by_parking_rule(
        max_torque: f64,
        inertia: f64,
        (band, dead_band): (f64, f64),
    ) -> SteeringBrakes {
        let parking = crate::vehicle::Brake::parking(max_torque, inertia, 0.0);
        SteeringBrakes {
            max_torque,
            stiffness: parking.stiffness,
            damping: parking.damping,
            band,
            dead_band,
        }
    }

    /// The brake's law in rotation: the ground's stiction law with the
    /// applied torque as its limit (`μ = 1`).
    pub(super) fn law(&self) -> Stiction {
        Stiction {
            mu: 1.0,
            stiffness: self.stiffness,
            damping: self.damping,
        }
    }

    /// The brake at deflection `phi` (rad) on an axle turning at `omega`
    /// (rad/s, relative to the frame), applied with `torque` N m: its
    /// torque on the axle (as a force on the body in [`Stiction`]), the
    /// deflection's rate, what it stores and dissipates; released, the
    /// deflection relaxing.
    pub(super) fn respond(&self, phi: f64, omega: f64, torque: f64) -> TangentialResponse {
        if torque > 0.0 {
            self.law().respond(phi, omega, torque)
        } else {
            self.law().relax(phi)
        }
    }

    fn check(&self) -> Result<(), ParameterError> {
        ParameterError::check("largest torque", self.max_torque, 0.0, true)?;
        ParameterError::check("band", self.band, 0.0, true)?;
        ParameterError::check("dead band", self.dead_band, 0.0, false)?;
        self.law().check()
    }
}

impl Driveline {
    /// Why the driveline's settings make none: a drive that makes no
    /// controller ([`Drive::check`]), a brake's or the steer unit's
    /// figure out of its range.
    pub fn check(&self) -> Result<(), DrivelineError> {
        match self {
            Driveline::Sides(drives) => Ok(drives.check()?),
            Driveline::Differential(d) => {
                d.drive.check()?;
                if let (DifferentialSteer::Unit(unit), None) = (&d.steer, &d.engine)
                    && let FullSteer::Engine(_) = unit.full_steer
                {
                    return Err(DrivelineError::NoEngine);
                }
                match &d.steer {
                    DifferentialSteer::Brakes(b) => {
                        b.check().map_err(|source| DrivelineError::Figure {
                            what: "steering brakes",
                            source,
                        })
                    }
                    DifferentialSteer::Unit(u) => {
                        u.check().map_err(|source| DrivelineError::Figure {
                            what: "steer unit",
                            source,
                        })
                    }
                }
            }
        }
    }

    /// What the driveline's states (five) hold at `states`: the energy
    /// its brakes' elastic stages store, J (the engine's and its
    /// driveline's twist are behind the sprockets, where the books are
    /// kept).
    pub fn stored(&self, states: [f64; DRIVELINE]) -> f64 {
        match self {
            Driveline::Differential(Differential {
                steer: DifferentialSteer::Brakes(b),
                ..
            }) => b.law().potential(states[1]) + b.law().potential(states[2]),
            _ => 0.0,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Full steer holds the outer sprocket at `ω̄ (1 + q/2)` and the inner
    /// at `ω̄ (1 − q/2)`: their ratio is the minimum steer ratio asked, to
    /// rounding, for the X200-4's four and a few others.
    #[test]
    fn full_steer_turns_the_sprockets_at_the_minimum_steer_ratio() {
        for ratio in [1.01, 1.22, 1.32, 1.58, 2.31, 10.0, 100.0] {
            let unit = SteerUnit {
                full_steer: FullSteer::Ratio(ratio),
                proportional: 1.0,
                integral: 1.0,
                max_torque: 1.0,
            };
            // Forward at a mean of −1 rad/s: the right sprocket outside.
            let q = -unit.full_difference(-1.0, 0.0);
            let held = (1.0 + 0.5 * q) / (1.0 - 0.5 * q);
            assert!((held / ratio - 1.0).abs() < 1e-13, "{ratio}: {held}");
        }
    }

    /// A transmission whose minimum steer ratios come from one steer
    /// drive geared to the engine (`ρ_r = (2 + k N_r)/(2 − k N_r)`) gives
    /// that drive's ratio back to rounding, with no departure.
    #[test]
    fn ratios_made_by_one_steer_drive_give_its_ratio_back() {
        let k = 0.05;
        let reductions = [15.9, 8.97, 5.6, 3.99];
        let ratios = reductions.map(|n| (2.0 + k * n) / (2.0 - k * n));
        let (found, departure) = steer_drive_ratio(&ratios, &reductions).expect("in range");
        assert!((found / k - 1.0).abs() < 1e-14, "{found}");
        assert!(departure < 1e-14, "{departure}");
    }

    /// The Allison X200-4's published minimum steer ratios (2.31, 1.58,
    /// 1.32, 1.22 in ranges 1–4 of 4.16, 2.34, 1.46, 1.04:1; US Army
    /// Ordnance subcourse OD1714) are one steer drive's: each range's
    /// `q_r / N_r` within 0.9 % of their mean (measured 0.87 %: within
    /// what the ratios' two decimals carry, 0.2–2 % of each `q_r`),
    /// whatever the final drive, while the `q_r` themselves span a factor
    /// of 4.
    #[test]
    fn the_x200_4s_steer_ratios_are_one_steer_drive_geared_to_the_engine() {
        let ratios = [2.31, 1.58, 1.32, 1.22];
        for final_drive in [1.0, 3.833] {
            let reductions = [4.16, 2.34, 1.46, 1.04].map(|n| n * final_drive);
            let (k, departure) = steer_drive_ratio(&ratios, &reductions).expect("in range");
            assert!(departure < 0.009, "{departure}");
            let first = 2.0 * (2.31 - 1.0) / (2.31 + 1.0) / reductions[0];
            assert!((first / k - 1.0).abs() < 0.009, "{first} against {k}");
        }
    }

    /// Not one ratio per range, a ratio of 1 or less, or a reduction of 0
    /// is refused, naming the range.
    #[test]
    fn steer_ratios_that_no_steer_drive_makes_are_refused() {
        assert!(matches!(
            steer_drive_ratio(&[2.0, 1.5], &[4.0]),
            Err(SteerRatiosError::Count {
                ratios: 2,
                ranges: 1
            })
        ));
        assert!(matches!(
            steer_drive_ratio(&[], &[]),
            Err(SteerRatiosError::Count { .. })
        ));
        assert!(matches!(
            steer_drive_ratio(&[2.0, 1.0], &[4.0, 2.0]),
            Err(SteerRatiosError::Figure { range: 2, .. })
        ));
        let error = steer_drive_ratio(&[2.0, 1.5], &[4.0, 0.0]).expect_err("a zero reduction");
        assert!(error.to_string().starts_with("range 2: "), "{error}");
    }

    /// The brakes by the parking rule take the parking brake's elastic
    /// stage (`k = 100 T`, `c = √(k J)`), and a released brake's law
    /// relaxes its deflection through the damper, pushing nothing.
    #[test]
    fn steering_brakes_take_the_parking_brakes_stage_and_relax_released() {
        let brakes = SteeringBrakes::by_parking_rule(2000.0, 50.0, (0.5, 0.0));
        assert_eq!(brakes.stiffness, 2e5);
        assert_eq!(brakes.damping, (2e5_f64 * 50.0).sqrt());
        let released = brakes.respond(0.01, 3.0, 0.0);
        assert_eq!(released.force, 0.0);
        assert_eq!(released.rate, -brakes.stiffness * 0.01 / brakes.damping);
        let holding = brakes.respond(0.001, 0.0, 2000.0);
        assert_eq!(holding.force, -200.0);
        assert!(!holding.sliding);
    }
}
