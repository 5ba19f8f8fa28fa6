//! The side slope (the guide's "Mobility events"), in 3-D for a vehicle
//! declared with a `tracks` block: the steepest slope across which the
//! vehicle, driven along the slope's contour at a crawl and holding its
//! heading, keeps its line.
//!
//! A trial sets the vehicle down at rest across a side slope `s` (rise
//! over run: the ground `z = s y`, the vehicle heading along `x`, its
//! right side downhill), lets it settle for [`SETTLE`] s on its speed
//! drives held at rest, ramps both belts to the settings' crawl at their
//! acceleration while the driver holds heading 0
//! ([`HeadingHold::driver`]), runs on for [`RUN_IN`] s, and then watches
//! it over [`MEASURED`] m along the contour. Its **drift** is the farthest
//! its centre of mass gets downhill of where that stretch began, over the
//! stretch's length. It holds the slope while the drift stays at most
//! [`DRIFT`] and its roll within [`TIPPED`] of the slope's (it has not
//! started to tip over).
//!
//! Friction is the same in every direction, on the ground as in the
//! model: a belt slipping along its path slips across it too, so a
//! driven vehicle creeps downhill at a rate that grows with the slope,
//! and slides away where the slope's pull `W sin φ` reaches what the
//! ground holds across, `μ W cos φ`. No vehicle holds a slope steeper
//! than `tan φ = μ`; it tips over before that where its centre of mass
//! stands higher than half its gauge over `μ`. The side slopes published
//! for tracked vehicles (the M113's 30 %) are ratings, not measured
//! sliding limits: their sources give no criterion.

use super::runs::{confirmed, slope_setting, spatial_failure, spatial_setup};
use super::search::{Search, Trial, bisect};
use super::stretch::{advance, run_to};
use super::{EventError, EventSettings};
use crate::integrate::{Integrator, OdeSystem};
use crate::spatial_vehicle::{
    HeadingHold, SideDrives, SpatialLaws, SpatialSimulated, SpatialVehicleSystem, on_course,
};
use crate::terrain::Terrain;

/// The event's name in results.
pub const EVENT: &str = "side-slope";

/// How long the vehicle settles onto the slope before it is driven, s
/// (the main job's settling time).
pub const SETTLE: f64 = 1.0;

/// How long it runs at the crawl before it is watched, s: its belts'
/// speed controllers and the driver take up the ramp's end.
pub const RUN_IN: f64 = 1.0;

/// The stretch watched, m along the contour.
pub const MEASURED: f64 = 5.0;

/// The largest drift (downhill over along) of a slope held: 5 %, a
/// crab of about 3° that a driver steers out without thinking of it.
/// Measured on the M113 (μ = 0.8): 0.1 % at a 10 % slope, 1.6 % at 55 %,
/// 2.9 % at 71.9 %, 5.5 % at 74.7 % and 56 % at 77.5 %: the criterion
/// sits on the knee, within a few hundredths of `μ`.
pub const DRIFT: f64 = 0.05;

/// How far the hull's roll may stray from the slope's, rad (0.35 rad,
/// 20°), before the vehicle counts as tipping over.
pub const TIPPED: f64 = 0.35;

/// The searched slopes, rise over run: from 10 % to 100 % (45°).
pub const RANGE: (f64, f64) = (0.1, 1.0);

/// One trial across a slope.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Traverse {
    /// The farthest downhill the centre of mass got over the stretch, m,
    /// from where the stretch began.
    pub downhill: f64,
    /// How far it went along the contour over the stretch, m.
    pub along: f64,
    /// The hull's roll's largest departure from the slope's, rad.
    pub roll_error: f64,
    /// Whether it held the slope: drift at most [`DRIFT`], roll within
    /// [`TIPPED`].
    pub held: bool,
}

impl Traverse {
    /// Its drift: downhill over along (infinite if it did not move along).
    pub fn drift(&self) -> f64 {
        if self.along > 0.0 {
            self.downhill / self.along
        } else {
            f64::INFINITY
        }
    }
}

/// `V` under `laws` driven at the settings' crawl along the contour of a
/// side slope of `slope` (rise over run, more than 0 and at most 2), as
/// the module describes. The run stops as soon as the drift or the roll
/// decides the trial; a run that fails is the event's error, with the
/// slope and the time.
pub fn traverse<V: SpatialVehicleSystem>(
    settings: &EventSettings,
    laws: SpatialLaws,
    slope: f64,
) -> Result<Traverse, EventError> {
    settings.check(EVENT)?;
    slope_setting(EVENT, "the side slope (rise over run)", slope)?;
    let (mut system, mut y, _) = on_course::<V>(laws, &Terrain::Flat { height: 0.0 }, slope)
        .map_err(|e| spatial_setup(EVENT, e))?;
    let (crawl, acceleration) = (settings.crawl, settings.acceleration);
    let ramp = move |t: f64| (acceleration * (t - SETTLE)).clamp(0.0, crawl);
    system
        .set_drives(SideDrives {
            right: V::speed_drive(ramp),
            left: V::speed_drive(ramp),
        })
        .map_err(|e| spatial_setup(EVENT, e))?;
    system
        .set_steering(HeadingHold::driver(0.0, (0.0, 0.0), V::layout().gauge))
        .map_err(|e| spatial_setup(EVENT, e))?;
    let tolerance = settings.scenario.explicit_tolerance();
    let mut stepper = Integrator::bs23(tolerance).stepper(system.dimension());
    let mut t = 0.0;
    let failed = spatial_failure(EVENT, slope, "rise over run");
    let watch = SETTLE + crawl / acceleration + RUN_IN;
    run_to(&mut system, &mut *stepper, (&mut t, &mut y), watch, &failed)?;
    let start = system.outputs(t, y.as_slice()).map_err(|e| failed(t, e))?;
    let end = watch + MEASURED / crawl;
    let bound = DRIFT * MEASURED;
    let mut trial = Traverse {
        downhill: 0.0,
        along: 0.0,
        roll_error: 0.0,
        held: false,
    };
    while t < end && trial.downhill <= bound && trial.roll_error <= TIPPED {
        advance(&mut system, &mut *stepper, (&mut t, &mut y), end, &failed)?;
        let now = system.outputs(t, y.as_slice()).map_err(|e| failed(t, e))?;
        let moved = now.centre.position - start.centre.position;
        // The left is uphill: downhill is along −y.
        trial.downhill = trial.downhill.max(-moved.y);
        trial.along = moved.x;
        trial.roll_error = trial.roll_error.max((now.roll - slope.atan()).abs());
    }
    trial.held = t >= end && trial.drift() <= DRIFT && trial.roll_error <= TIPPED;
    Ok(trial)
}

/// The steepest side slope `V` holds under `laws` ([`traverse`]),
/// searched over [`RANGE`] to the settings' grade tolerance and confirmed
/// at their tighter integrator tolerance. Each trial's figure is its
/// drift.
pub fn steepest<V: SpatialVehicleSystem>(
    settings: &EventSettings,
    laws: SpatialLaws,
) -> Result<Search, EventError> {
    let trial = |settings: &EventSettings, slope| {
        let run = traverse::<V>(settings, laws, slope)?;
        Ok(Trial {
            parameter: slope,
            figure: run.drift(),
            passed: run.held,
        })
    };
    let tolerance = settings.grade_tolerance;
    let search = bisect(RANGE.0, RANGE.1, tolerance, |p| trial(settings, p))?;
    confirmed(settings, search, RANGE, tolerance, trial)
}
