//! Obstacles (the NRMM's obstacle events; the guide's "Mobility
//! events"): the speed over a
//! half-round at which the seat's peak vertical acceleration reaches the
//! limit (2.5 g), and the largest step, gap, ditch and barrier crossed
//! from a crawl at full power.

use super::runs::{
    Footprint, Probe, SpeedTrial, confirmed, drive, measure_ride, obstacle_course, ramp,
    search_speed,
};
use super::search::{Limit, Search, Trial, bisect};
use super::{EventError, EventSettings};
use crate::scene::{Ground, Picture, Scene};
use crate::simulate::{Sink, SinkError};
use crate::terrain::Terrain;
use crate::terrain::profile::Obstacle;
use crate::vehicle::Vehicle;

/// The half-round event's name in results.
pub const HALF_ROUND: &str = "half-round";

/// One run over a half-round.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HalfRoundPoint {
    /// The speed asked, m/s.
    pub speed_asked: f64,
    /// The mean speed from the track's front 1 m before the obstacle to
    /// its rear 3 m past it, m/s.
    pub speed: f64,
    /// The largest vertical seat acceleration after the 30 Hz low-pass,
    /// g ([`PeakVertical`](crate::ride::PeakVertical)).
    pub peak_g: f64,
    /// Whether the vehicle stalled on the obstacle.
    pub stalled: bool,
    /// How far the hull got, m.
    pub reached: f64,
}

/// `V` over a half-round of `height` (m, its radius) at the speed asked,
/// `speed` (m/s), reached on the flat before it: the seat's peak.
pub fn half_round_at<V: Vehicle>(
    settings: &EventSettings,
    footprint: &Footprint,
    height: f64,
    speed: f64,
) -> Result<HalfRoundPoint, EventError> {
    settings.check(HALF_ROUND)?;
    let ramp_distance = speed * speed / (2.0 * settings.acceleration);
    let at = footprint.front + ramp_distance + 3.0;
    let (profile, far) = obstacle_course(
        HALF_ROUND,
        footprint,
        at,
        &Obstacle::HalfRound { radius: height },
    )?;
    let x0 = at - 1.0 - footprint.front;
    let x1 = far + 3.0 - footprint.rear;
    let run = measure_ride::<V>(
        settings,
        HALF_ROUND,
        Terrain::profile(profile),
        speed,
        (x0, x1),
    )?;
    Ok(HalfRoundPoint {
        speed_asked: speed,
        speed: run.speed,
        peak_g: run.figures.peak_g,
        stalled: run.stalled,
        reached: run.reached,
    })
}

/// The lowest speed over a half-round of `height` (m) at which the seat's
/// peak reaches the settings' limit: from 1 m/s up by the settings'
/// `speed_scan` to the first speed over it, then bisection (the peak is
/// not monotone in speed: the M113's over 10 in is 2.40 g at 3.4 m/s,
/// 3.96 g at 4.6 and 2.57 g at 10.5), up to the powertrain's top speed. Each trial's figure is the peak, g; a vehicle
/// that does not get over is [`EventError::Stalled`], neither a pass nor
/// a limit.
pub fn half_round_speed<V: Vehicle>(
    settings: &EventSettings,
    footprint: &Footprint,
    height: f64,
) -> Result<Search, EventError> {
    check_length(HALF_ROUND, "the height (m)", height, 2.0)?;
    search_speed(
        settings,
        footprint,
        (HALF_ROUND, Some(settings.speed_scan)),
        settings.peak_limit,
        |settings, speed| {
            let point = half_round_at::<V>(settings, footprint, height, speed)?;
            Ok(SpeedTrial {
                figure: point.peak_g,
                stalled: point.stalled,
                reached: point.reached,
            })
        },
    )
}

/// One attempt at an obstacle from a crawl.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Crossing {
    /// Whether the track's rear got 1 m past the obstacle's far end.
    pub crossed: bool,
    /// How far the hull got, m, from where the track's rear would be at
    /// the obstacle's far end plus 1 m (0 or more: crossed).
    pub margin: f64,
    /// Whether it stopped: less than [`STALL_DISTANCE`](super::STALL_DISTANCE)
    /// in [`STALL_TIME`](super::STALL_TIME).
    pub stalled: bool,
    /// The largest pitch magnitude on the way, rad.
    pub max_pitch: f64,
}

/// `V` driven at the obstacle from a crawl (the settings' `crawl` speed
/// asked, the powertrain at full load where it must): whether it crosses.
pub fn cross<V: Vehicle>(
    settings: &EventSettings,
    footprint: &Footprint,
    event: &'static str,
    obstacle: &Obstacle,
    parameter: f64,
) -> Result<Crossing, EventError> {
    attempt::<V>(settings, footprint, event, obstacle, parameter).map(|(crossing, ..)| crossing)
}

/// [`cross`], with the run's steepest moment and the ground it ran on.
fn attempt<V: Vehicle>(
    settings: &EventSettings,
    footprint: &Footprint,
    event: &'static str,
    obstacle: &Obstacle,
    parameter: f64,
) -> Result<(Crossing, Steepest, Terrain), EventError> {
    settings.check(event)?;
    let crawl = settings.crawl;
    let ramp_time = crawl / settings.acceleration;
    let at = footprint.front + 0.5 * crawl * ramp_time + 1.0;
    let (profile, far) = obstacle_course(event, footprint, at, obstacle)?;
    let terrain = Terrain::profile(profile);
    let goal = far + 1.0 - footprint.rear;
    let mut steepest = Steepest::new(Probe::new(goal));
    // At the crawl, with time for slowing on the obstacle; a stall ends
    // the run sooner.
    let duration = ramp_time + 4.0 * goal / crawl + 10.0;
    drive::<V>(
        settings,
        terrain.clone(),
        ramp(crawl, settings.acceleration),
        duration,
        0.01,
        &mut steepest,
        (event, parameter, "m"),
    )?;
    let probe = &steepest.probe;
    let crossing = Crossing {
        crossed: probe.x >= goal,
        margin: probe.reached - goal,
        stalled: probe.stalled,
        max_pitch: probe.max_pitch,
    };
    Ok((crossing, steepest, terrain))
}

/// A crossing's [`Probe`], keeping the row where the hull's pitch was
/// largest: the vehicle's steepest moment on the obstacle, drawn at the
/// limit.
struct Steepest {
    probe: Probe,
    columns: Vec<String>,
    /// The time and the values of the row of the largest pitch so far
    /// (the probe's [`max_pitch`](Probe::max_pitch)).
    t: f64,
    row: Vec<f64>,
}

impl Steepest {
    fn new(probe: Probe) -> Steepest {
        Steepest {
            probe,
            columns: Vec::new(),
            t: f64::NAN,
            row: Vec::new(),
        }
    }

    /// The vehicle `V` at its steepest moment on `terrain`, labelled
    /// `label`; `None` before any row.
    fn picture<V: Vehicle>(&self, terrain: Terrain, label: String) -> Option<Picture> {
        let mut frame = Scene::of::<V>().frame_of_row(self.t, &self.columns, &self.row)?;
        frame.label = label;
        let ground = Ground {
            terrain,
            rut: Vec::new(),
        };
        Some(Picture { frame, ground })
    }
}

impl Sink for Steepest {
    fn begin(&mut self, columns: &[String]) -> Result<(), SinkError> {
        self.columns = columns.to_vec();
        self.probe.begin(columns)
    }

    fn row(&mut self, t: f64, values: &[f64]) -> Result<(), SinkError> {
        let largest = self.probe.max_pitch;
        let outcome = self.probe.row(t, values);
        if self.row.is_empty() || self.probe.max_pitch > largest {
            self.t = t;
            self.row.clear();
            self.row.extend_from_slice(values);
        }
        outcome
    }

    fn finish(&mut self) -> Result<(), SinkError> {
        self.probe.finish()
    }
}

/// The largest obstacle `shape(p)` crossed for `p` in `[start, end]` (m),
/// by bisection to the settings' `length_tolerance`. Each trial's figure
/// is [`Crossing::margin`], m. The search's
/// [`picture`](Search::picture) is the vehicle at its steepest moment
/// crossing the largest obstacle it crossed.
pub fn largest_crossed<V: Vehicle>(
    settings: &EventSettings,
    footprint: &Footprint,
    event: &'static str,
    (start, end): (f64, f64),
    shape: impl Fn(f64) -> Obstacle,
) -> Result<Search, EventError> {
    check_length(event, "the search's start (m)", start, end)?;
    // The bracket's passing end is the last passing trial of bisection
    // (and of its confirmation, which ends in bisection or in the
    // bracket's passing end run again).
    let mut last_crossed: Option<(f64, Steepest, Terrain)> = None;
    let mut trial = |settings: &EventSettings, p| {
        let (crossing, steepest, terrain) = attempt::<V>(settings, footprint, event, &shape(p), p)?;
        if crossing.crossed {
            last_crossed = Some((p, steepest, terrain));
        }
        Ok(Trial {
            parameter: p,
            figure: crossing.margin,
            passed: crossing.crossed,
        })
    };
    let tolerance = settings.length_tolerance;
    let search = bisect(start, end, tolerance, |p| trial(settings, p))?;
    let mut search = confirmed(settings, search, (start, end), tolerance, &mut trial)?;
    if let (Limit::Found { passed, .. }, Some((p, steepest, terrain))) =
        (search.limit, last_crossed)
        && p == passed
    {
        let label = format!(
            "{event} {p:.3} m, the largest crossed, at its steepest (t = {:.1} s)",
            steepest.t
        );
        search.picture = steepest.picture::<V>(terrain, label);
    }
    Ok(search)
}

/// The highest step (m) climbed from a crawl, searched over
/// `[0.05, 1.5]` m.
pub fn step<V: Vehicle>(
    settings: &EventSettings,
    footprint: &Footprint,
) -> Result<Search, EventError> {
    largest_crossed::<V>(settings, footprint, "step", (0.05, 1.5), |height| {
        Obstacle::Step { height }
    })
}

/// The widest gap (m; vertical walls, 2 m deep) crossed from a crawl,
/// searched over `[0.1, 4]` m.
pub fn gap<V: Vehicle>(
    settings: &EventSettings,
    footprint: &Footprint,
) -> Result<Search, EventError> {
    largest_crossed::<V>(settings, footprint, "gap", (0.1, 4.0), |width| {
        Obstacle::Gap { width, depth: 2.0 }
    })
}

/// The deepest trapezoidal ditch (m; a 1 m bottom, walls at 45°) crossed
/// from a crawl, searched over `[0.1, 2]` m.
pub fn ditch<V: Vehicle>(
    settings: &EventSettings,
    footprint: &Footprint,
) -> Result<Search, EventError> {
    largest_crossed::<V>(settings, footprint, "ditch", (0.1, 2.0), |depth| {
        Obstacle::Ditch {
            depth,
            bottom_width: 1.0,
            wall_angle: 45.0,
        }
    })
}

/// The highest trapezoidal barrier (m; a 1 m top, walls at 45°) crossed
/// from a crawl, searched over `[0.05, 1.5]` m.
pub fn barrier<V: Vehicle>(
    settings: &EventSettings,
    footprint: &Footprint,
) -> Result<Search, EventError> {
    largest_crossed::<V>(settings, footprint, "barrier", (0.05, 1.5), |height| {
        Obstacle::Barrier {
            height,
            top_width: 1.0,
            wall_angle: 45.0,
        }
    })
}

fn check_length(
    event: &'static str,
    what: &'static str,
    value: f64,
    below: f64,
) -> Result<(), EventError> {
    if value.is_finite() && value > 0.0 && value < below {
        Ok(())
    } else {
        Err(EventError::Setting {
            event,
            what,
            range: "more than 0 and below the search's end",
            value,
        })
    }
}
