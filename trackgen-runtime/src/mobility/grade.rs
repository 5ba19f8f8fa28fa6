//! Grades (the NG-NRMM's grade event; the guide's "Mobility events"): the
//! steepest grade climbed from
//! a crawl, and the speed held up a grade at full power.

use super::runs::{Footprint, Probe, confirmed, drive, obstacle_course, ramp, slope_setting};
use super::search::{Search, Trial, bisect};
use super::{EventError, EventSettings};
use crate::terrain::Terrain;
use crate::terrain::profile::Obstacle;
use crate::vehicle::Vehicle;

/// The event's name in results.
pub const EVENT: &str = "grade";

/// How far up the grade the track's rear must get, m, for the grade to
/// count as climbed.
pub const CLIMB: f64 = 5.0;

/// A grade of `slope` (rise over run) starting at `at` (m), long enough
/// for `up` m of climb beyond the track's front.
fn course(footprint: &Footprint, at: f64, slope: f64, up: f64) -> Result<Terrain, EventError> {
    let length = up + footprint.length() + 10.0;
    let (profile, _) = obstacle_course(EVENT, footprint, at, &Obstacle::Grade { slope, length })?;
    Ok(Terrain::profile(profile))
}

/// One attempt at a grade.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Climb {
    /// Whether the track's rear got [`CLIMB`] m (horizontally) up it.
    pub climbed: bool,
    /// The hull's mean speed along the slope over the climb's last 10 m
    /// (horizontally), m/s: its speed along x times `√(1 + slope²)` (0
    /// stalled; NaN for a climb shorter than 10 m, or one slower than the
    /// run waits for).
    pub speed: f64,
    /// Whether it stopped.
    pub stalled: bool,
}

/// `V` asked for `speed` (m/s) at a grade of `slope` (rise over run),
/// the grade starting 1 m ahead of the track's front: whether its rear
/// gets `climb` m (horizontally) up it, and its speed over the last 10 m.
/// The run waits for a climb as slow as `slowest` (m/s) on average; a
/// stall ends it sooner.
pub fn climb<V: Vehicle>(
    settings: &EventSettings,
    footprint: &Footprint,
    slope: f64,
    (speed, slowest): (f64, f64),
    climb: f64,
) -> Result<Climb, EventError> {
    settings.check(EVENT)?;
    slope_setting(EVENT, "the grade (rise over run)", slope)?;
    let at = footprint.front + 1.0;
    let terrain = course(footprint, at, slope, climb)?;
    let goal = at + climb - footprint.rear;
    let ramp_time = speed / settings.acceleration;
    let duration = ramp_time + goal / slowest + 5.0;
    let target = ramp(speed, settings.acceleration);
    drive_to::<V>(settings, terrain, target, goal, duration, slope)
}

/// `V` driven on `terrain` asking for `target` (m/s against s) until its
/// hull's x reaches `goal` (m), it stalls or `duration` (s) passes:
/// whether it got there, and its mean speed along the grade `slope` over
/// the last 10 m (0 if it stalled). A failure names the grade.
fn drive_to<V: Vehicle>(
    settings: &EventSettings,
    terrain: Terrain,
    target: impl Fn(f64) -> f64 + Send + 'static,
    goal: f64,
    duration: f64,
    slope: f64,
) -> Result<Climb, EventError> {
    let mut probe = Probe::new(goal);
    probe.mark_at = goal - 10.0;
    drive::<V>(
        settings,
        terrain,
        target,
        duration,
        0.01,
        &mut probe,
        (EVENT, slope, "rise over run"),
    )?;
    Ok(Climb {
        climbed: probe.x >= goal,
        speed: if probe.stalled {
            0.0
        } else {
            // The last 10 m are on the grade: the path is `√(1 + g²)` of
            // its run.
            probe.speed_since_mark() * (1.0 + slope * slope).sqrt()
        },
        stalled: probe.stalled,
    })
}

/// The steepest grade climbed from a crawl, searched over `[0.05, 1.2]`
/// (5 to 120 %) to the settings' `grade_tolerance`. Each trial's figure is
/// 1 if it climbed, 0 if not.
pub fn steepest<V: Vehicle>(
    settings: &EventSettings,
    footprint: &Footprint,
) -> Result<Search, EventError> {
    let trial = |settings: &EventSettings, slope| {
        // At a tenth of the crawl the climb still finishes.
        let crawl = (settings.crawl, settings.crawl / 10.0);
        let c = climb::<V>(settings, footprint, slope, crawl, CLIMB)?;
        Ok(Trial {
            parameter: slope,
            figure: f64::from(u8::from(c.climbed)),
            passed: c.climbed,
        })
    };
    let (range, tolerance) = ((0.05, 1.2), settings.grade_tolerance);
    let search = bisect(range.0, range.1, tolerance, |p| trial(settings, p))?;
    confirmed(settings, search, range, tolerance, trial)
}

/// How far the top-speed run goes, m: the speed's last rise is slow (the
/// engine's surplus vanishes as the speed nears the top), and the M113 is
/// within 0.3 % of its top speed after some 600 m.
pub const TOP_SPEED_RUN: f64 = 800.0;

/// The top speed on level ground at full power: `V` asked at once for the
/// powertrain's reach ([`EventSettings::top_speed`]) on flat ground, its
/// mean speed over the last 10 m of [`TOP_SPEED_RUN`] m. What it gives is
/// where the engine's full-load envelope (its governor's droop, in the
/// highest range) meets the running gear's resistance: the model has no
/// air drag.
pub fn top_speed<V: Vehicle>(
    settings: &EventSettings,
    footprint: &Footprint,
) -> Result<Climb, EventError> {
    settings.check(EVENT)?;
    let top = settings.top_speed(footprint.sprocket_radius);
    let goal = TOP_SPEED_RUN;
    // At a fifth of the reach the run still gets there; a stall ends it
    // sooner.
    let duration = 5.0 * goal / top + 5.0;
    let flat = Terrain::Flat { height: 0.0 };
    drive_to::<V>(settings, flat, ramp(top, 1e3), goal, duration, 0.0)
}

/// The speed held up a grade of `slope` at full power: `V` asked at once
/// for the powertrain's top speed (the engine, at full load, sets the
/// torque) up a grade long enough for 100 m of climb beyond its track's
/// length, its mean speed along the slope over the last 10 m. At the speeds a grade
/// leaves (a few m/s), 100 m is several times the distance the speed
/// takes to settle (`m v² / P`, some 10 m). A vehicle that stalls holds 0.
pub fn speed_on<V: Vehicle>(
    settings: &EventSettings,
    footprint: &Footprint,
    slope: f64,
) -> Result<Climb, EventError> {
    let top = settings.top_speed(footprint.sprocket_radius);
    let at_once = EventSettings {
        acceleration: 1e3,
        ..settings.clone()
    };
    // Asked for the top speed, the climb still finishes at a quarter of
    // the crawl (a grade near the steepest the vehicle holds).
    let speeds = (top, settings.crawl / 4.0);
    climb::<V>(
        &at_once,
        footprint,
        slope,
        speeds,
        footprint.length() + 100.0,
    )
}
