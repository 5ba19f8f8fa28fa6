//! What every event shares: its settings, the vehicle's footprint, and a
//! run of the vehicle over a course under its powertrain.

use nalgebra::Vector2;

use super::EventError;
use super::search::{Search, Trial, confirm, interpolate, scan_then_bisect};
use crate::integrate::SimulationError;
use crate::scenario::{Method, Scenario};
use crate::simulate::{RideFigures, RideSink, RunError, RunReport, Sink, SinkError};
use crate::spatial_vehicle::EngineEnvelope;
use crate::system::Simulated;
use crate::terrain::Terrain;
use crate::terrain::course::CourseSpec;
use crate::terrain::profile::{Course, Obstacle, Profile, ProfileError};
use crate::vehicle::{Powertrain, Vehicle, VehicleConfig, VehicleDynamics, build};

/// How the events drive the vehicle and read their criteria. Every event
/// takes these; [`new`](Self::new) gives the defaults the mobility
/// literature's events use (NRMM and the NG-NRMM benchmark, NATO
/// ET-148, 2016; the 6 W absorbed power of Pradko & Lee, SAE 680091,
/// 1968; the guide's "Mobility events").
#[derive(Debug, Clone, PartialEq)]
pub struct EventSettings {
    /// The engine and driveline at the sprocket: it caps the speed
    /// controller's torque, so the vehicle's power sets the speeds it
    /// reaches.
    pub powertrain: Powertrain,
    /// The run every trial is made from: its integrator (method and
    /// tolerance) is every trial's; each event lays its own course and
    /// sets its own drive, duration and rows, and drives through
    /// [`powertrain`](Self::powertrain) where it asks for the engine.
    pub scenario: Scenario,
    /// The speed of a crawl, m/s: steps, gaps, ditches, barriers and
    /// grades are driven at it (the controller asks for it, the engine
    /// gives what it can).
    pub crawl: f64,
    /// The speed ramp's acceleration, m/s², to the speed asked.
    pub acceleration: f64,
    /// The length of rough ground the ride is measured over, m (after
    /// the whole vehicle is on it).
    pub ride_distance: f64,
    /// The rows' interval for the ride criteria, s (at most
    /// [`RideSink::MAX_INTERVAL`](crate::simulate::RideSink::MAX_INTERVAL)).
    pub ride_interval: f64,
    /// The absorbed power that limits the ride, W (6 W: the NRMM's
    /// ride-limiting criterion).
    pub absorbed_power_limit: f64,
    /// The peak vertical seat acceleration that limits the half-round
    /// speed, g (2.5 g).
    pub peak_limit: f64,
    /// The most speed any event asks for, m/s: the search's end where the
    /// powertrain itself sets none.
    pub max_speed: f64,
    /// Speed searches stop when the bracket is this narrow, m/s.
    pub speed_tolerance: f64,
    /// The half-round's speed search first steps up by this, m/s, to the
    /// first speed over the limit, then bisects: its figure is not
    /// monotone in speed ([`scan_then_bisect`](super::search::scan_then_bisect)).
    pub speed_scan: f64,
    /// Height, width and depth searches stop at this, m.
    pub length_tolerance: f64,
    /// Grade searches stop at this, rise over run.
    pub grade_tolerance: f64,
    /// Each search's final bracket is run again at the scenario's
    /// integrator tolerance times this ([`confirm`](super::search::confirm)),
    /// and the search goes on at that tolerance where a verdict changes;
    /// `None`: answers at the scenario's tolerance alone.
    pub confirm_factor: Option<f64>,
}

impl EventSettings {
    /// The defaults under `powertrain`: Bogacki-Shampine with the main
    /// job's automatic choice at its tolerances (1e-3 explicit, 1e-2
    /// implicit), a crawl of 1 m/s reached at 1 m/s², the ride measured
    /// over 100 m with rows every 2 ms against 6 W, the half-round against
    /// 2.5 g, speeds up to 20 m/s searched to 0.1 m/s, lengths to 0.01 m,
    /// grades to 0.01, each search's bracket confirmed at a tenth of the
    /// integrator's tolerance.
    pub fn new(powertrain: Powertrain) -> EventSettings {
        EventSettings {
            powertrain,
            scenario: Scenario {
                engine: true,
                ..Scenario::default()
            },
            crawl: 1.0,
            acceleration: 1.0,
            ride_distance: 100.0,
            ride_interval: 2e-3,
            absorbed_power_limit: 6.0,
            peak_limit: 2.5,
            max_speed: 20.0,
            speed_tolerance: 0.1,
            speed_scan: 2.0,
            length_tolerance: 0.01,
            grade_tolerance: 0.01,
            confirm_factor: Some(0.1),
        }
    }

    /// The settings a search's answer is confirmed with, and their
    /// integrator tolerance: these, the scenario's tolerance times
    /// [`confirm_factor`](Self::confirm_factor) (of the implicit method's
    /// for ROS34PW2, of the explicit one's otherwise; `auto` takes it for
    /// both). `None` where no confirmation is asked, or the method has no
    /// tolerance (RK4's fixed step).
    pub fn confirming(&self) -> Option<(EventSettings, f64)> {
        let factor = self.confirm_factor?;
        let scenario = &self.scenario;
        let tolerance = factor
            * match scenario.method {
                Method::Rk4 { .. } => return None,
                Method::Ros34pw2 => scenario.implicit_tolerance(),
                Method::Auto | Method::Bs23 | Method::Dopri5 => scenario.explicit_tolerance(),
            };
        let mut tight = self.clone();
        tight.scenario.tolerance = Some(tolerance);
        Some((tight, tolerance))
    }

    /// The settings checked: each figure finite and in its range, the
    /// scenario's among them ([`Scenario::check`]).
    pub(super) fn check(&self, event: &'static str) -> Result<(), EventError> {
        let positive: [(&'static str, f64); 9] = [
            ("the crawl speed (m/s)", self.crawl),
            ("the acceleration (m/s²)", self.acceleration),
            ("the ride distance (m)", self.ride_distance),
            ("the absorbed-power limit (W)", self.absorbed_power_limit),
            ("the peak limit (g)", self.peak_limit),
            ("the largest speed (m/s)", self.max_speed),
            ("the speed tolerance (m/s)", self.speed_tolerance),
            ("the length tolerance (m)", self.length_tolerance),
            ("the grade tolerance", self.grade_tolerance),
        ];
        for (what, value) in positive {
            if !(value.is_finite() && value > 0.0) {
                return Err(EventError::Setting {
                    event,
                    what,
                    range: "finite and more than 0",
                    value,
                });
            }
        }
        if let Some(factor) = self.confirm_factor
            && !(factor > 0.0 && factor < 1.0)
        {
            return Err(EventError::Setting {
                event,
                what: "the confirming tolerance's factor",
                range: "more than 0 and less than 1",
                value: factor,
            });
        }
        let scenario = |s: &Scenario| {
            s.check().map_err(|e| EventError::Setting {
                event,
                what: e.setting,
                range: e.range,
                value: e.value,
            })
        };
        scenario(&self.scenario)?;
        if let Some((tight, _)) = self.confirming() {
            scenario(&tight.scenario)?;
        }
        self.powertrain
            .check()
            .map_err(|source| EventError::Powertrain { event, source })
    }

    /// A trial's run: the settings' [`scenario`](Self::scenario) on the
    /// course `terrain`, for `duration` s with rows every `interval` s.
    pub fn trial(&self, terrain: Terrain, duration: f64, interval: f64) -> Scenario {
        Scenario {
            course: CourseSpec::Laid(terrain),
            duration,
            output_every: interval,
            ..self.scenario.clone()
        }
    }

    /// The fastest the powertrain drives the sprocket, converted to the
    /// track's speed at `radius` (m, the sprocket's rolling radius), at
    /// most [`max_speed`](Self::max_speed): beyond the top gear's cut-off
    /// the engine gives no torque.
    pub fn top_speed(&self, radius: f64) -> f64 {
        let gives = |omega: f64| self.powertrain.limit(omega).0 > 0.0;
        let ceiling = self.max_speed / radius;
        if gives(ceiling) {
            return self.max_speed;
        }
        // The driving envelope is one interval from rest: bisect its end.
        let (mut low, mut high) = (0.0, ceiling);
        for _ in 0..60 {
            let middle = 0.5 * (low + high);
            if gives(middle) {
                low = middle;
            } else {
                high = middle;
            }
        }
        low * radius
    }
}

/// Where the vehicle stands as assembled: its track's extent along x, m,
/// relative to the chassis' centroid at x = 0.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Footprint {
    /// The rearmost link centroid's x, m.
    pub rear: f64,
    /// The foremost link centroid's x, m.
    pub front: f64,
    /// The sprocket's rolling radius, m (track speed per rad/s).
    pub sprocket_radius: f64,
}

impl Footprint {
    /// The vehicle `V` assembled on flat ground, measured.
    pub fn of<V: Vehicle>(event: &'static str) -> Result<Footprint, EventError> {
        let config = V::declared_config(Terrain::Flat { height: 0.0 }, V::speed_drive(|_| 0.0));
        let mut system =
            build::<V>(config).map_err(|source| EventError::Build { event, source })?;
        let y0 = system.initial_state();
        let (track, _) = system
            .coordinates(0.0, y0.as_slice())
            .map_err(|e| run_error(event, 0.0, "", e.into()))?;
        let mut links = vec![Vector2::zeros(); V::TRACK_DOF - 2];
        V::System::track_positions(track.as_slice(), &mut links);
        let xs = links.iter().map(|p| p.x);
        let rear = xs.clone().fold(f64::INFINITY, f64::min);
        let front = xs.fold(f64::NEG_INFINITY, f64::max);
        Ok(Footprint {
            rear,
            front,
            sprocket_radius: system.sprocket_rolling_radius(),
        })
    }

    /// The track's length on the ground and above it, front to rear, m.
    pub fn length(&self) -> f64 {
        self.front - self.rear
    }
}

/// A run of `V` on `terrain`, its speed controller asking for `target`
/// (m/s against s) under the settings' powertrain, for `duration` s, rows
/// every `interval` s into `sink`.
pub(super) fn drive<V: Vehicle>(
    settings: &EventSettings,
    terrain: Terrain,
    target: impl Fn(f64) -> f64 + Send + 'static,
    duration: f64,
    interval: f64,
    sink: &mut dyn Sink,
    what: (&'static str, f64, &'static str),
) -> Result<RunReport, EventError> {
    let scenario = settings.trial(terrain.clone(), duration, interval);
    let powertrain = Some(settings.powertrain.clone()).filter(|_| scenario.engine);
    let config = scenario.config_with::<V>(terrain, V::speed_drive(target), powertrain);
    run_config::<V>(&scenario, config, sink, what)
}

/// A run of `V` built from `config` through `scenario`'s time, integrator
/// and rows into `sink`; a failure names `(event, parameter, unit)`.
pub(super) fn run_config<V: Vehicle>(
    scenario: &Scenario,
    config: VehicleConfig,
    sink: &mut dyn Sink,
    (event, parameter, unit): (&'static str, f64, &'static str),
) -> Result<RunReport, EventError> {
    let mut system = build::<V>(config).map_err(|source| EventError::Build { event, source })?;
    scenario
        .simulate_into(&mut system, sink, &mut |_| {})
        .map_err(|failure| run_error(event, parameter, unit, failure.error))
}

/// The ride of a run over a stretch of ground.
#[derive(Debug, Clone, Copy)]
pub(super) struct Measured {
    /// The seat's figures over the stretch.
    pub figures: RideFigures,
    /// The hull's mean speed over it, m/s.
    pub speed: f64,
    /// The length measured, m.
    pub measured: f64,
    /// Whether the hull stalled, or the run ended before the stretch's
    /// end.
    pub stalled: bool,
    /// The furthest the hull got, m.
    pub reached: f64,
}

/// `V` asked for `speed` (m/s, reached at the settings' acceleration) on
/// `terrain`, the seat's ride measured while the hull's x is in `stretch`
/// (m); the run ends at the stretch's end, or when the hull stalls. Its
/// time limit lets the hull cover the stretch at a quarter of the speed
/// asked (the engine may give less): a limit reached short of the
/// stretch's end counts as a stall.
pub(super) fn measure_ride<V: Vehicle>(
    settings: &EventSettings,
    event: &'static str,
    terrain: Terrain,
    speed: f64,
    (x0, x1): (f64, f64),
) -> Result<Measured, EventError> {
    let duration = speed / settings.acceleration + 4.0 * x1.max(1.0) / speed + 10.0;
    let mut probe = Probe::new(x1);
    let sink = RideSink::new(settings.ride_interval, 0.0).map_err(|_| EventError::Setting {
        event,
        what: "the ride interval (s)",
        range: "more than 0 and at most 0.002",
        value: settings.ride_interval,
    })?;
    probe.ride = Some(sink.over_stretch(x0, x1));
    drive::<V>(
        settings,
        terrain,
        ramp(speed, settings.acceleration),
        duration,
        settings.ride_interval,
        &mut probe,
        (event, speed, "m/s"),
    )?;
    let figures = probe.figures().expect("the probe measured the ride");
    let time = figures.samples as f64 * settings.ride_interval;
    let measured = (probe.x.min(x1) - x0).max(0.0);
    Ok(Measured {
        figures,
        speed: if time > 0.0 { measured / time } else { 0.0 },
        measured,
        stalled: probe.stalled || probe.x < x1,
        reached: probe.reached,
    })
}

/// What a run at a speed gives a speed search: the criterion's figure,
/// whether the vehicle stalled, and how far its hull got (m).
pub(super) struct SpeedTrial {
    pub figure: f64,
    pub stalled: bool,
    pub reached: f64,
}

/// The speed, from 1 m/s to the powertrain's top speed, at which the
/// figure `run` gives reaches `limit` (passing below it), to the settings'
/// `speed_tolerance`: by ITP interpolation over the range
/// ([`interpolate`](super::search::interpolate)), or with `scan` (m/s)
/// the first such speed, stepping up by it first
/// ([`scan_then_bisect`](super::search::scan_then_bisect)); a stall is
/// [`EventError::Stalled`].
pub(super) fn search_speed(
    settings: &EventSettings,
    footprint: &Footprint,
    (event, scan): (&'static str, Option<f64>),
    limit: f64,
    mut run: impl FnMut(&EventSettings, f64) -> Result<SpeedTrial, EventError>,
) -> Result<Search, EventError> {
    let top = settings.top_speed(footprint.sprocket_radius);
    let start = 1.0_f64.min(top);
    let mut trial = |settings: &EventSettings, speed| {
        let trial = run(settings, speed)?;
        if trial.stalled {
            return Err(EventError::Stalled {
                event,
                parameter: speed,
                unit: "m/s",
                reached: trial.reached,
            });
        }
        Ok(Trial {
            parameter: speed,
            figure: trial.figure,
            passed: trial.figure < limit,
        })
    };
    let tolerance = settings.speed_tolerance;
    let search = match scan {
        Some(step) => scan_then_bisect(start, top, step, tolerance, |p| trial(settings, p)),
        None => interpolate(start, top, tolerance, limit, |p| trial(settings, p)),
    }?;
    confirmed(settings, search, (start, top), tolerance, trial)
}

/// `search`, run from `start` towards `end` to `tolerance`, confirmed by
/// `trial` at the settings' confirming tolerance
/// ([`EventSettings::confirming`], [`confirm`]); as it is where the
/// settings ask for none.
pub(super) fn confirmed(
    settings: &EventSettings,
    search: Search,
    (start, end): (f64, f64),
    tolerance: f64,
    mut trial: impl FnMut(&EventSettings, f64) -> Result<Trial, EventError>,
) -> Result<Search, EventError> {
    match settings.confirming() {
        Some((tight, integrator)) => confirm(search, (start, end), tolerance, integrator, |p| {
            trial(&tight, p)
        }),
        None => Ok(search),
    }
}

/// Flat ground after an obstacle, m.
pub(super) const RUN_OUT: f64 = 40.0;

/// The course of an obstacle event: flat from behind the vehicle to
/// `at` (m), the obstacle, flat for [`RUN_OUT`]; and the obstacle's far
/// end, m.
pub(super) fn obstacle_course(
    event: &'static str,
    footprint: &Footprint,
    at: f64,
    obstacle: &Obstacle,
) -> Result<(Profile, f64), EventError> {
    let laid = || -> Result<(Profile, f64), ProfileError> {
        let from = footprint.rear - 10.0;
        let course = Course::starting_at(from, 0.0)?
            .flat(at - from)?
            .then(obstacle)?;
        let far = course.end().0;
        Ok((course.flat(RUN_OUT)?.profile()?, far))
    };
    laid().map_err(|source| EventError::Course { event, source })
}

/// `slope` (rise over run) as `event` takes it, `what` it is: finite,
/// more than 0 and at most 2; otherwise the setting's error.
pub(super) fn slope_setting(
    event: &'static str,
    what: &'static str,
    slope: f64,
) -> Result<(), EventError> {
    if slope.is_finite() && slope > 0.0 && slope <= 2.0 {
        Ok(())
    } else {
        Err(EventError::Setting {
            event,
            what,
            range: "more than 0 and at most 2",
            value: slope,
        })
    }
}

/// A speed ramp at `acceleration` (m/s²) from rest to `speed` (m/s).
pub(super) fn ramp(speed: f64, acceleration: f64) -> impl Fn(f64) -> f64 + Send + 'static {
    move |t| (acceleration * t).min(speed)
}

/// A failure to set a spatial vehicle up for `event` (its laws, its
/// assembly, its drives or its driver refused), as the event's error.
pub(super) fn spatial_setup(
    event: &'static str,
    source: impl std::error::Error + Send + Sync + 'static,
) -> EventError {
    EventError::Spatial {
        event,
        source: Box::new(source),
    }
}

/// A spatial run of `event` at `parameter` (`unit`) failing at `t`, as
/// the event's error.
pub(super) fn spatial_failure(
    event: &'static str,
    parameter: f64,
    unit: &'static str,
) -> impl Fn(f64, SimulationError) -> EventError {
    move |t, e| EventError::Run {
        event,
        parameter,
        unit,
        time: t,
        source: Box::new(RunError::Simulation(e)),
    }
}

/// The settings' powertrain as a spatial drive's envelope, for `event`.
pub(super) fn envelope(
    settings: &EventSettings,
    event: &'static str,
) -> Result<EngineEnvelope, EventError> {
    EngineEnvelope::new(settings.powertrain.clone())
        .map_err(|source| EventError::Powertrain { event, source })
}

fn run_error(
    event: &'static str,
    parameter: f64,
    unit: &'static str,
    error: RunError,
) -> EventError {
    EventError::Run {
        event,
        parameter,
        unit,
        time: error.time().unwrap_or(f64::NAN),
        source: Box::new(error),
    }
}

/// What an event reads off a run as its rows arrive: the hull's progress,
/// the ride at the seat if asked, and whether the hull reached its goal or
/// stalled, either of which ends the run ([`SinkError::Done`]).
#[derive(Debug, Clone)]
pub(super) struct Probe {
    /// The ride, measured over its stretch.
    pub ride: Option<RideSink>,
    /// The hull's x that ends the run, m.
    pub goal: f64,
    columns: Option<[usize; 2]>,
    /// The engine's speed column, where the record has one.
    engine: Option<usize>,
    /// The hull's x at the last row, m.
    pub x: f64,
    /// The furthest the hull's x reached, m.
    pub reached: f64,
    /// The largest pitch magnitude, rad.
    pub max_pitch: f64,
    /// The hull stalled: the run was ended for it.
    pub stalled: bool,
    /// The time of the last row, s.
    pub t: f64,
    /// `(t, x, ω_e)` of the last stall check.
    check: (f64, f64, f64),
    /// From this hull position on, m, `mark` keeps the first row's
    /// `(t, x)`.
    pub mark_at: f64,
    /// The first row whose hull x reached `mark_at`: `(t, x)`.
    pub mark: Option<(f64, f64)>,
}

/// A hull moving less than this, m, in [`STALL_TIME`] has stalled: 3 cm/s
/// on average, a thirtieth of the crawl — unless its engine's speed rose
/// by more than [`STALL_SPIN_UP`] meanwhile (an engine whose speed is a
/// state, spinning up from idle against an obstacle's face, holds the hull
/// until it gives the converter's stall torque: the hull waits, it has
/// not stalled). Watched from the start: from rest at the events' 1 m/s²
/// a hull covers 1.1 m in the first window.
pub const STALL_DISTANCE: f64 = 0.05;
/// The time over which [`STALL_DISTANCE`] is checked, s.
pub const STALL_TIME: f64 = 1.5;
/// The rise of the engine's speed over [`STALL_TIME`], as a fraction of
/// its speed at the window's start, past which a held hull has not
/// stalled: 0.02.
pub const STALL_SPIN_UP: f64 = 0.02;

impl Probe {
    /// Watches for the hull to reach `goal` (m) or stall.
    pub fn new(goal: f64) -> Probe {
        Probe {
            ride: None,
            goal,
            columns: None,
            engine: None,
            x: f64::NAN,
            reached: f64::NEG_INFINITY,
            max_pitch: 0.0,
            stalled: false,
            t: f64::NAN,
            check: (f64::NAN, f64::NAN, f64::NAN),
            mark_at: f64::INFINITY,
            mark: None,
        }
    }

    /// The hull's mean speed since the mark, m/s (NaN before it).
    pub fn speed_since_mark(&self) -> f64 {
        match self.mark {
            Some((t, x)) if self.t > t => (self.x - x) / (self.t - t),
            _ => f64::NAN,
        }
    }

    /// The ride's figures, if it was measured.
    pub fn figures(&self) -> Option<RideFigures> {
        self.ride.as_ref().map(RideSink::figures)
    }
}

impl Sink for Probe {
    fn begin(&mut self, columns: &[String]) -> Result<(), SinkError> {
        let find = |name: &str| {
            columns
                .iter()
                .position(|c| c == name)
                .ok_or_else(|| SinkError::Columns(format!("mobility: no column `{name}`")))
        };
        self.columns = Some([find("x")?, find("pitch")?]);
        self.engine = columns.iter().position(|c| c == "engine_speed");
        if let Some(ride) = &mut self.ride {
            ride.begin(columns)?;
        }
        Ok(())
    }

    fn row(&mut self, t: f64, values: &[f64]) -> Result<(), SinkError> {
        let Some([x, pitch]) = self.columns else {
            return Err(SinkError::Columns("mobility: a row before `begin`".into()));
        };
        if let Some(ride) = &mut self.ride {
            ride.row(t, values)?;
        }
        let (x, pitch) = (values[x], values[pitch]);
        self.t = t;
        self.x = x;
        self.reached = self.reached.max(x);
        self.max_pitch = self.max_pitch.max(pitch.abs());
        if self.mark.is_none() && x >= self.mark_at {
            self.mark = Some((t, x));
        }
        let ride_done = self.ride.as_ref().is_none_or(RideSink::ended);
        if x >= self.goal && ride_done {
            return Err(SinkError::Done);
        }
        let engine = self.engine.map_or(0.0, |e| values[e]);
        // The first row (NaN before it) starts the watch.
        if self.check.0.is_nan() {
            self.check = (t, x, engine);
        } else if t - self.check.0 >= STALL_TIME {
            let spinning_up = engine > self.check.2 * (1.0 + STALL_SPIN_UP);
            if x - self.check.1 < STALL_DISTANCE && !spinning_up {
                self.stalled = true;
                return Err(SinkError::Done);
            }
            self.check = (t, x, engine);
        }
        Ok(())
    }

    fn finish(&mut self) -> Result<(), SinkError> {
        Ok(())
    }

    /// The hull's `x` and `pitch`, the engine's speed, and what its ride
    /// reads.
    fn reads(&self) -> Option<Vec<usize>> {
        let [x, pitch] = self.columns?;
        let mut read = vec![x, pitch];
        read.extend(self.engine);
        if let Some(ride) = &self.ride {
            read.extend(ride.reads()?);
        }
        Some(read)
    }
}

#[cfg(test)]
mod tests {
    /// A slope is taken from just above 0 to 2; 0, past 2, NaN and
    /// infinity are the setting's error, naming the event.
    #[test]
    fn a_slope_out_of_range_is_the_settings_error() {
        for ok in [1e-9, 0.3, 2.0] {
            assert!(super::slope_setting("grade", "the grade", ok).is_ok());
        }
        for bad in [0.0, -0.1, 2.01, f64::NAN, f64::INFINITY] {
            let e = super::slope_setting("side-slope", "the side slope", bad).unwrap_err();
            assert!(
                e.to_string()
                    .starts_with("side-slope: the side slope must be"),
                "{e}"
            );
        }
    }

    use super::*;

    /// Feeds a probe a held hull (x = 0) every 0.1 s with the engine's
    /// speed `engine(t)` (no column for `None`): the time it called the
    /// hull stalled, if it did within 6 s.
    fn stalled_at(engine: Option<fn(f64) -> f64>) -> Option<f64> {
        let mut probe = Probe::new(10.0);
        let mut columns = vec!["x".to_string(), "pitch".to_string()];
        if engine.is_some() {
            columns.push("engine_speed".to_string());
        }
        probe.begin(&columns).expect("the columns");
        for k in 0..=60 {
            let t = f64::from(k) * 0.1;
            let mut row = vec![0.0, 0.0];
            row.extend(engine.map(|e| e(t)));
            match probe.row(t, &row) {
                Ok(()) => {}
                Err(SinkError::Done) => return probe.stalled.then_some(t),
                Err(e) => panic!("{e}"),
            }
        }
        None
    }

    #[test]
    fn a_held_hull_stalls_unless_its_engine_spins_up() {
        // Rows every 0.1 s: a window closes at the first row 1.5 s (up to
        // rounding, 1.6 s) after it opened.
        let first = stalled_at(None).expect("stalls without an engine column");
        assert!((1.5..=1.6 + 1e-9).contains(&first), "{first}");
        let steady = stalled_at(Some(|_| 200.0)).expect("stalls at a steady engine");
        assert_eq!(steady, first);
        // 3 % a window (over the 2 %) for the first two windows, then
        // steady: stalled one window after the spin-up ends.
        let spin = stalled_at(Some(|t: f64| 100.0 * 1.03f64.powf(t.min(3.2) / 1.5)))
            .expect("stalls once the engine stops spinning up");
        assert!(spin > 2.0 * first, "{spin} against {first}");
        // 1 % a window (under the 2 %): stalled as if steady.
        let slow = stalled_at(Some(|t: f64| 100.0 * 1.01f64.powf(t / 1.5)));
        assert_eq!(slow, Some(first));
    }
}
