//! Turning (the guide's "Mobility events"), in 3-D for a vehicle declared
//! with a `tracks` block: the smallest radius it turns on firm level
//! ground at a crawl, and the pivot turn.
//!
//! Each is a **steady turn** ([`steady_turn`]): the vehicle assembled at
//! rest on level ground, settled for [`SETTLE`] s, each sprocket brought
//! to its belt speed by the vehicle's speed drive over [`RAMP`] s (capped
//! by the engine's envelope where one is given), then averaged over
//! stretches of [`WINDOW`] s until two stretches' yaw rates agree to
//! [`STEADY`] (or [`LONGEST`] s have run, the turn reported as not
//! steady): the yaw rate (the heading's change over the stretch), the
//! centre of mass's speed, the path's radius (speed over yaw rate), each
//! sprocket's torque and power, and the belts' speeds.
//!
//! - **The smallest radius** ([`smallest_radius`]): full steer at the
//!   settings' crawl (the belts' mean). A transmission with a steer unit
//!   turns the outer sprocket at most `ρ` times as fast as the inner (its
//!   lowest range's minimum steer ratio, the M113A3's X200-4 2.31: US
//!   Army Ordnance subcourse OD1714): the belts `2 v ρ/(ρ + 1)` and
//!   `2 v/(ρ + 1)`, whose kinematic radius (no slip) is
//!   `B/2 (ρ + 1)/(ρ − 1)`. Without a published ratio, the braked
//!   differential's full steer: the inner belt held, the outer at `2 v`,
//!   kinematically `B/2`. The tracks slip, so the radius run is larger.
//!   The radius is asked while moving, so a geared steer's is its lowest
//!   range's ratio's; the X200-4's pivot in neutral is a
//!   steer unit's in neutral ([`FullSteer::Neutral`](crate::spatial_vehicle::FullSteer::Neutral)).
//! - **The pivot turn** ([`pivot`]): the belts at `±v`, the vehicle
//!   turning about its centre (`v` the neutral pivot's at full steer for
//!   a transmission with published steer ratios, else the crawl): its yaw
//!   rate and the sprockets' power,
//!   what skid-steering's moment of turning resistance costs (the theory
//!   of Wong & Chiang, "A general theory for skid steering of tracked
//!   vehicles on firm ground", Proc. IMechE Part D 215, 2001; Steeds'
//!   estimate `μ_t W L / 4`).

use super::runs::{envelope, spatial_failure, spatial_setup};
use super::stretch::{run_to, watch};
use super::{EventError, EventSettings};
use crate::integrate::{Integrator, OdeSystem};
use crate::spatial_vehicle::{
    EngineEnvelope, SideDrives, SpatialLaws, SpatialSimulated, SpatialVehicleSystem, SteerDrive,
    on_course,
};
use crate::terrain::Terrain;
use crate::terrain::field::HeightField;

/// The event's name in results.
pub const EVENT: &str = "turning";

/// The settling before the belts start, s.
pub const SETTLE: f64 = 1.0;
/// The belts' ramp from rest, s.
pub const RAMP: f64 = 2.0;
/// The stretch averaged over, s.
pub const WINDOW: f64 = 1.5;
/// When the first stretch starts, s: a second after the ramp.
const FIRST: f64 = SETTLE + RAMP + 1.0;
/// The yaw rates of two stretches running this close (relative) make
/// the turn steady.
pub const STEADY: f64 = 0.01;
/// The longest run, s: a turn not steady by then is reported as such.
pub const LONGEST: f64 = 40.0;

/// What a steady turn of the spatial vehicle showed, averaged over its
/// last stretch.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SteadyTurnRun {
    /// The yaw rate, rad/s (left positive).
    pub yaw_rate: f64,
    /// The centre of mass's horizontal speed, m/s.
    pub speed: f64,
    /// The path's radius, m: the distance travelled over the heading's
    /// change (the speed over the yaw rate's size).
    pub radius: f64,
    /// The belts' speeds (right, left), m/s, forward positive.
    pub belts: [f64; 2],
    /// The sprockets' torques (right, left), N m, planar sense (driving
    /// forward negative).
    pub torques: [f64; 2],
    /// The sprockets' powers (right, left), W.
    pub powers: [f64; 2],
    /// When the stretch averaged ended, s.
    pub until: f64,
    /// Whether the turn was steady: its yaw rate within [`STEADY`] of the
    /// stretch's before.
    pub steady: bool,
}

/// The pivot turn ([`pivot`]): the belts' speed asked and the turn.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PivotTurn {
    /// The belts' speed asked, m/s: the right forward, the left back.
    pub belts: f64,
    /// The turn.
    pub run: SteadyTurnRun,
}

/// One steady turn of `V` under `laws` on firm level ground with its
/// belts at `belts` (right, left, m/s, forward positive), integrated by
/// Bogacki-Shampine at `tolerance`, its drive capped by `envelope` if
/// given: stretches of [`WINDOW`] s from a second after the ramp until
/// two running yaw rates agree to [`STEADY`], or [`LONGEST`] s. A run
/// that fails is the event's error, with the outer belt's speed and the
/// time.
pub fn steady_turn<V: SpatialVehicleSystem>(
    laws: SpatialLaws,
    belts: [f64; 2],
    envelope: Option<EngineEnvelope>,
    tolerance: f64,
) -> Result<SteadyTurnRun, EventError> {
    let flat = Terrain::Flat { height: 0.0 };
    let (mut system, mut y, _) =
        on_course::<V>(laws, &flat, 0.0).map_err(|e| spatial_setup(EVENT, e))?;
    let ramp = |speed: f64| move |t: f64| speed * ((t - SETTLE) / RAMP).clamp(0.0, 1.0);
    system
        .set_drives(SideDrives {
            right: V::speed_drive(ramp(belts[0])),
            left: V::speed_drive(ramp(belts[1])),
        })
        .map_err(|e| spatial_setup(EVENT, e))?;
    system.set_envelope(envelope);
    let fastest = belts[0].abs().max(belts[1].abs());
    let failed = spatial_failure(EVENT, fastest, "m/s (the faster belt)");
    let mut stepper = Integrator::bs23(tolerance).stepper(system.dimension());
    let mut t = 0.0;
    run_to(&mut system, &mut *stepper, (&mut t, &mut y), FIRST, &failed)?;
    let mut before: Option<SteadyTurnRun> = None;
    loop {
        let stretch = watch(
            &mut system,
            &mut *stepper,
            (&mut t, &mut y),
            WINDOW,
            &failed,
        )?;
        let (yaw_rate, speed) = (stretch.yaw_rate(), stretch.speed());
        let steady = before.is_some_and(|b| {
            (yaw_rate - b.yaw_rate).abs() <= STEADY * yaw_rate.abs().max(b.yaw_rate.abs())
        });
        let turn = SteadyTurnRun {
            yaw_rate,
            speed,
            radius: stretch.radius(),
            belts: stretch.belts,
            torques: stretch.torques,
            powers: stretch.powers,
            until: t,
            steady,
        };
        if steady || t + WINDOW > LONGEST {
            return Ok(turn);
        }
        before = Some(turn);
    }
}

/// The smallest turn at a crawl ([`smallest_radius`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SmallestTurn {
    /// The steer unit's minimum steer ratio it was asked at, or `None`
    /// for the braked differential's (the inner belt held).
    pub ratio: Option<f64>,
    /// The radius without slip, m: `B/2 (ρ + 1)/(ρ − 1)`, or `B/2`.
    pub kinematic: f64,
    /// The run.
    pub run: SteadyTurnRun,
}

/// A left turn's belts (right, left, m/s) at mean speed `v` at full steer:
/// the steer unit's `ratio` or, without one, the inner belt held.
fn full_steer(v: f64, ratio: Option<f64>) -> [f64; 2] {
    match ratio {
        Some(rho) => [2.0 * v * rho / (rho + 1.0), 2.0 * v / (rho + 1.0)],
        None => [2.0 * v, 0.0],
    }
}

/// The smallest radius `V` turns under `laws` at the settings' crawl
/// (the belts' mean speed) at full steer: its steer unit's minimum steer
/// `ratio` (more than 1, finite), or the braked differential's full
/// steer without one; its drive capped by the settings' powertrain, at
/// the settings' tolerance. A ratio out of range is refused before
/// anything runs.
pub fn smallest_radius<V: SpatialVehicleSystem>(
    settings: &EventSettings,
    laws: SpatialLaws,
    ratio: Option<f64>,
) -> Result<SmallestTurn, EventError> {
    settings.check(EVENT)?;
    if let Some(rho) = ratio
        && !(rho.is_finite() && rho > 1.0)
    {
        return Err(EventError::Setting {
            event: EVENT,
            what: "the minimum steer ratio",
            range: "finite and more than 1",
            value: rho,
        });
    }
    let envelope = envelope(settings, EVENT)?;
    let half = V::layout().gauge / 2.0;
    let kinematic = ratio.map_or(half, |rho| half * (rho + 1.0) / (rho - 1.0));
    let tolerance = settings.scenario.explicit_tolerance();
    let run = steady_turn::<V>(
        laws,
        full_steer(settings.crawl, ratio),
        Some(envelope),
        tolerance,
    )?;
    Ok(SmallestTurn {
        ratio,
        kinematic,
        run,
    })
}

/// The pivot turn of `V` under `laws` (the right belt forward: a turn to
/// the left about the vehicle's centre), its drive capped by the
/// settings' powertrain, at the settings' tolerance. A transmission whose
/// minimum steer ratios the powertrain declares for its ranges
/// ([`Powertrain::steer_ratios`](crate::vehicle::Powertrain::steer_ratios))
/// pivots in neutral at full steer: its belts at `±k ω_e r / 2`
/// ([`SteerDrive`]: the steer drive's ratio, the engine at its rated
/// speed, `r` the sprockets' rolling radius); any other vehicle at plus
/// and minus the settings' crawl.
pub fn pivot<V: SpatialVehicleSystem>(
    settings: &EventSettings,
    laws: SpatialLaws,
) -> Result<PivotTurn, EventError> {
    settings.check(EVENT)?;
    let envelope = envelope(settings, EVENT)?;
    let v = match SteerDrive::of(&settings.powertrain).map_err(|e| spatial_setup(EVENT, e))? {
        Some(drive) => {
            let system =
                V::spatial(laws, HeightField::level()).map_err(|e| spatial_setup(EVENT, e))?;
            0.5 * drive.full_difference() * system.rolling_radius()
        }
        None => settings.crawl,
    };
    let run = steady_turn::<V>(
        laws,
        [v, -v],
        Some(envelope),
        settings.scenario.explicit_tolerance(),
    )?;
    Ok(PivotTurn { belts: v, run })
}
