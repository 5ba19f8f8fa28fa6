//! Random-terrain ride (the NATO Reference Mobility Model's event; the
//! guide's "Mobility events"): the absorbed
//! power and ISO 2631-1 weighted accelerations at the driver's seat over
//! a random course of given roughness, and the ride-limiting speed, where
//! the absorbed power reaches the limit (6 W, the NRMM's criterion).

use super::runs::{Footprint, SpeedTrial, measure_ride, search_speed};
use super::search::Search;
use super::{EventError, EventSettings};
use crate::simulate::RideFigures;
use crate::terrain::Terrain;
use crate::terrain::roughness::{DETRENDING_BASE_LENGTH, RoughCourse, SPACING, Spectrum};
use crate::vehicle::Vehicle;

/// The event's name in results.
pub const EVENT: &str = "ride";

/// A random course: its detrended RMS elevation (m, after the mobility
/// literature's detrending over
/// [`DETRENDING_BASE_LENGTH`]) and the seed of its phases.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Roughness {
    /// Detrended RMS elevation, m, more than 0 and at most 0.5.
    pub rms: f64,
    /// The seed: the same seed gives the same course on any machine.
    pub seed: u64,
}

/// The ride at one speed asked.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RidePoint {
    /// The speed asked, m/s.
    pub speed_asked: f64,
    /// The mean speed over the measured stretch, m/s: the engine may give
    /// less than asked.
    pub speed: f64,
    /// The seat's figures over the stretch.
    pub figures: RideFigures,
    /// The length measured, m (the settings' `ride_distance` unless the
    /// vehicle stalled).
    pub measured: f64,
    /// Whether the vehicle stalled on the course.
    pub stalled: bool,
    /// How far the hull got, m.
    pub reached: f64,
}

/// The ride of `V` over `roughness` at the speed asked, `speed` (m/s):
/// from rest on flat ground, the speed reached at the settings'
/// acceleration before the rough stretch begins; measured from where the
/// track's rear is on the rough ground for the settings' `ride_distance`.
pub fn ride_at<V: Vehicle>(
    settings: &EventSettings,
    footprint: &Footprint,
    roughness: Roughness,
    speed: f64,
) -> Result<RidePoint, EventError> {
    settings.check(EVENT)?;
    check_roughness(roughness)?;
    if !(speed.is_finite() && speed > 0.0 && speed <= settings.max_speed) {
        return Err(EventError::Setting {
            event: EVENT,
            what: "the speed (m/s)",
            range: "more than 0 and at most the settings' max_speed",
            value: speed,
        });
    }
    // Rough ground begins 2 m ahead of the track's front where the ramp
    // ends, after a 3 m taper; measured from when the track's rear is on
    // it.
    let ramp_distance = speed * speed / (2.0 * settings.acceleration);
    let taper = 3.0;
    let start = footprint.rear - 10.0;
    let rough_from = footprint.front + ramp_distance + 2.0;
    let x0 = rough_from + taper - footprint.rear;
    let x1 = x0 + settings.ride_distance;
    let length = x1 + footprint.front + 10.0 - rough_from;
    let course = RoughCourse::new(
        Spectrum::DetrendedRms {
            rms: roughness.rms,
            base_length: DETRENDING_BASE_LENGTH,
        },
        length,
        SPACING,
        roughness.seed,
    )
    .starting_at(start)
    .with_run_in(rough_from - start, taper);
    let profile = course.profile().map_err(|source| EventError::Roughness {
        event: EVENT,
        source,
    })?;
    let run = measure_ride::<V>(settings, EVENT, Terrain::profile(profile), speed, (x0, x1))?;
    Ok(RidePoint {
        speed_asked: speed,
        speed: run.speed,
        figures: run.figures,
        measured: run.measured,
        stalled: run.stalled,
        reached: run.reached,
    })
}

/// The ride-limiting speed over `roughness`: the speed asked at which the
/// absorbed power reaches the settings' limit, by ITP interpolation
/// ([`interpolate`](super::search::interpolate): bisection's bracket, in
/// fewer runs where the power rises smoothly with speed) between 1 m/s
/// and the powertrain's top speed (or `max_speed`) to the settings'
/// `speed_tolerance`. Each trial is a [`ride_at`] run; its figure is the
/// absorbed power, W. A course the vehicle cannot cross (it stalls) is
/// [`EventError::Stalled`]: neither a pass nor a limit.
pub fn limiting_speed<V: Vehicle>(
    settings: &EventSettings,
    footprint: &Footprint,
    roughness: Roughness,
) -> Result<Search, EventError> {
    search_speed(
        settings,
        footprint,
        (EVENT, None),
        settings.absorbed_power_limit,
        |settings, speed| {
            let point = ride_at::<V>(settings, footprint, roughness, speed)?;
            Ok(SpeedTrial {
                figure: point.figures.absorbed_power,
                stalled: point.stalled,
                reached: point.reached,
            })
        },
    )
}

fn check_roughness(roughness: Roughness) -> Result<(), EventError> {
    if roughness.rms.is_finite() && roughness.rms > 0.0 && roughness.rms <= 0.5 {
        Ok(())
    } else {
        Err(EventError::Setting {
            event: EVENT,
            what: "the RMS roughness (m)",
            range: "more than 0 and at most 0.5",
            value: roughness.rms,
        })
    }
}
