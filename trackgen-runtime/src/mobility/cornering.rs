//! Cornering (the guide's "Mobility events"), in 3-D for a vehicle
//! declared with a `tracks` block: the fastest steady turn the vehicle
//! holds on a circle of a given radius on firm level ground, and the
//! lateral acceleration it reaches there: its lateral limit, set by its
//! grip, its engine or its driver's steering.
//!
//! A trial at speed `v` on radius `R`: the vehicle assembled at rest on
//! level ground, settled [`SETTLE`] s, its belts ramped to `v` at the
//! settings' acceleration through the settings' powertrain: where the
//! vehicle's transmission publishes its minimum steer ratio, through a
//! differential with a steer unit (which carries the inner side's power
//! to the outer, as the M113A3's X200-4 does). An engine that declares
//! its inertia then drives the box with its speed a state
//! ([`SpatialEngine`]: its converter, scheduled ranges and lock-up) and
//! the unit is the steer drive geared to it
//! ([`FullSteer::Engine`], its ratio the one the first range's published
//! ratio makes through that range's reduction), so that the steer at
//! speed is the range's; otherwise the unit holds the first range's
//! ratio, the drive capped by the engine's envelope
//! ([`EngineEnvelope`](crate::spatial_vehicle::EngineEnvelope)). Without
//! a published ratio, a speed drive on each
//! side (each with half the engine). Meanwhile a driver
//! ([`HeadingHold::driver`]'s gain and largest belt difference) holds the
//! heading wanted: still until the speed is reached, then turning left
//! at `v / R`. After [`RUN_IN`] s it is watched over stretches of
//! [`WINDOW`] s, at most [`STRETCHES`] of them. It **holds** the corner
//! when two stretches running have their path's radius (the distance
//! the centre of mass travelled over the heading's change) within
//! [`KEPT`] of `R` and their speed within [`KEPT`] of `v`: it keeps its
//! speed on the circle. (A vehicle short of power slows and the driver's
//! heading falls behind: its path may still be near the circle, at a
//! lower speed.) (Two stretches'
//! yaw rates agreeing to 1 %, the steady turns' test, fails on a gentle
//! circle at a crawl: there the tracks' ripple is more than 1 % of the
//! yaw rate.) Past its
//! limit it cannot: its belts slide out (the grip: no steady turn's
//! lateral acceleration passes `μ g`), its engine cannot hold the outer
//! belt's speed (the path tightens and slows), or its driver's largest
//! belt difference cannot turn it that fast.
//!
//! The fastest speed held is searched by bisection from 1 m/s to the
//! speed at which the circle asks for the lateral acceleration `μ g`
//! that the ground's friction allows any steady turn (the shoes' `μ`;
//! the settings' largest speed if less), to the settings' speed
//! tolerance, and confirmed at their tighter integrator tolerance. Each trial's figure is its lateral
//! acceleration (the speed times the yaw rate, m/s²) over its last
//! stretch.

use super::runs::{confirmed, envelope, spatial_failure, spatial_setup};
use super::search::{Search, Trial, bisect};
use super::stretch::{run_to, watch};
use super::{EventError, EventSettings};
use crate::integrate::{Integrator, OdeSystem};
use crate::spatial_vehicle::{
    Differential, Driveline, FullSteer, HeadingHold, SideDrives, SpatialEngine, SpatialLaws,
    SpatialSimulated, SpatialVehicleSystem, SteeringError, on_course, steer_drive_ratio,
};
use crate::terrain::Terrain;
use crate::vehicle::VehicleDynamics;

/// The event's name in results.
pub const EVENT: &str = "cornering";

/// How long the vehicle settles before it is driven, s.
pub const SETTLE: f64 = 1.0;
/// How long it turns at the speed before it is watched, s: the heavy
/// Marder at a crawl on its side drives takes some 8 s to settle onto
/// the circle (its path's radius 59, 9.4, 7.7, 11.6, 12.9 and 14.0 m
/// over the first 1.5 s stretches, asked 15 m), the M113 under 2 s.
pub const RUN_IN: f64 = 4.0;
/// A stretch watched, s.
pub const WINDOW: f64 = 1.5;
/// The most stretches watched: a trial not held by then fails.
pub const STRETCHES: usize = 8;
/// How far the path's radius may stray from the circle's, and the speed
/// from the one asked (relative).
pub const KEPT: f64 = 0.1;
/// The slowest speed searched, m/s.
pub const SLOWEST: f64 = 1.0;

/// A corner asked: the circle's radius (m), and the minimum steer ratio
/// of the steer unit the vehicle turns through (`None`: its side
/// drives).
pub type Circle = (f64, Option<f64>);

/// One trial on a circle.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Corner {
    /// The centre of mass's speed over the last stretch, m/s.
    pub speed: f64,
    /// The yaw rate over it, rad/s.
    pub yaw_rate: f64,
    /// The path's radius, m: the speed over the yaw rate.
    pub radius: f64,
    /// Whether it held the corner.
    pub held: bool,
}

impl Corner {
    /// The lateral acceleration, m/s²: the speed times the yaw rate.
    pub fn lateral_acceleration(&self) -> f64 {
        self.speed * self.yaw_rate.abs()
    }
}

/// `V` under `laws` driven at `speed` (m/s) round a circle of `radius`
/// (m) to the left, steered through a steer unit of minimum steer
/// `ratio` (on the settings' engine with its speed a state where it
/// declares its inertia, the unit then the steer drive geared to it) or
/// else by its side drives, as the module describes; a
/// radius or a speed not finite and positive, or a ratio not finite and
/// more than 1, is refused, and a run that fails is the event's error,
/// with the speed and the time.
pub fn corner<V: SpatialVehicleSystem>(
    settings: &EventSettings,
    laws: SpatialLaws,
    (radius, ratio): Circle,
    speed: f64,
) -> Result<Corner, EventError> {
    settings.check(EVENT)?;
    for (what, value, range, ok) in [
        (
            "the circle's radius (m)",
            radius,
            "finite and more than 0",
            0.0,
        ),
        ("the speed (m/s)", speed, "finite and more than 0", 0.0),
        (
            "the minimum steer ratio",
            ratio.unwrap_or(2.0),
            "finite and more than 1",
            1.0,
        ),
    ] {
        if !(value.is_finite() && value > ok) {
            return Err(EventError::Setting {
                event: EVENT,
                what,
                range,
                value,
            });
        }
    }
    let envelope = envelope(settings, EVENT)?;
    let engine = match (ratio, SpatialEngine::new(settings.powertrain.clone())) {
        (Some(_), Ok(engine)) => Some(engine),
        _ => None,
    };
    let flat = Terrain::Flat { height: 0.0 };
    let (mut system, mut y, _) =
        on_course::<V>(laws, &flat, 0.0).map_err(|e| spatial_setup(EVENT, e))?;
    let acceleration = settings.acceleration;
    let ramp = move |t: f64| (acceleration * (t - SETTLE)).clamp(0.0, speed);
    let driveline = match (ratio, engine) {
        (Some(ratio), Some(engine)) => {
            // The steer drive the first range's published ratio makes
            // with that range's reduction, geared to the engine.
            let (k, _) = steer_drive_ratio(&[ratio], &[engine.driveline().reduction(0)])
                .map_err(|e| spatial_setup(EVENT, e))?;
            Differential::with_steer_unit(
                &V::speed_drive(|_| 0.0),
                Box::new(ramp),
                FullSteer::Engine(k),
            )
            .map(|mut d| {
                d.engine = Some(engine);
                Driveline::Differential(d)
            })
        }
        (Some(ratio), None) => Differential::with_steer_unit(
            &V::speed_drive(|_| 0.0),
            Box::new(ramp),
            FullSteer::Ratio(ratio),
        )
        .map(Driveline::Differential),
        (None, _) => Some(Driveline::Sides(SideDrives {
            right: V::speed_drive(ramp),
            left: V::speed_drive(ramp),
        })),
    };
    let driveline = driveline.ok_or_else(|| spatial_setup(EVENT, SteeringError::NotSpeedDrives))?;
    system
        .set_driveline(driveline)
        .map_err(|e| spatial_setup(EVENT, e))?;
    if system.engine().is_none() {
        system.set_envelope(Some(envelope));
    }
    system.start_engine(y.as_mut_slice());
    let turning = SETTLE + speed / acceleration;
    let rate = speed / radius;
    let mut driver = HeadingHold::driver(0.0, (0.0, 0.0), V::layout().gauge);
    driver.heading = Box::new(move |t: f64| {
        if t > turning {
            (rate * (t - turning), rate)
        } else {
            (0.0, 0.0)
        }
    });
    system
        .set_steering(driver)
        .map_err(|e| spatial_setup(EVENT, e))?;
    let failed = spatial_failure(EVENT, speed, "m/s");
    let tolerance = settings.scenario.explicit_tolerance();
    let mut stepper = Integrator::bs23(tolerance).stepper(system.dimension());
    let mut t = 0.0;
    let watched = turning + RUN_IN;
    run_to(
        &mut system,
        &mut *stepper,
        (&mut t, &mut y),
        watched,
        &failed,
    )?;
    let mut before = false;
    let mut trial = Corner {
        speed: 0.0,
        yaw_rate: 0.0,
        radius: f64::INFINITY,
        held: false,
    };
    for _ in 0..STRETCHES {
        let stretch = watch(
            &mut system,
            &mut *stepper,
            (&mut t, &mut y),
            WINDOW,
            &failed,
        )?;
        trial = Corner {
            speed: stretch.speed(),
            yaw_rate: stretch.yaw_rate(),
            radius: stretch.radius(),
            held: false,
        };
        let on_circle = (trial.radius / radius - 1.0).abs() <= KEPT
            && (trial.speed / speed - 1.0).abs() <= KEPT;
        if on_circle && before {
            trial.held = true;
            return Ok(trial);
        }
        before = on_circle;
    }
    Ok(trial)
}

/// The fastest steady turn `V` holds under `laws` on a circle of
/// `radius` (m), through a steer unit of minimum steer `ratio` or else
/// its side drives ([`corner`]), searched from [`SLOWEST`] to the grip's
/// speed `√(μ g R)` (or the settings' largest speed) to their speed
/// tolerance and confirmed at their tighter integrator tolerance; each
/// trial's figure its lateral acceleration.
pub fn fastest<V: SpatialVehicleSystem>(
    settings: &EventSettings,
    laws: SpatialLaws,
    (radius, ratio): Circle,
) -> Result<Search, EventError> {
    let trial = |settings: &EventSettings, speed| {
        let run = corner::<V>(settings, laws, (radius, ratio), speed)?;
        Ok(Trial {
            parameter: speed,
            figure: run.lateral_acceleration(),
            passed: run.held,
        })
    };
    // The model's own gravity.
    let g = <V::System as VehicleDynamics>::track_description()
        .gravity
        .norm();
    let grip = (laws.ground.friction.mu() * g * radius).sqrt();
    let range = (SLOWEST, settings.max_speed.min(grip));
    let tolerance = settings.speed_tolerance;
    let search = bisect(range.0, range.1, tolerance, |v| trial(settings, v))?;
    confirmed(settings, search, range, tolerance, trial)
}
