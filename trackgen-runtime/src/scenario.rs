//! One owner of a run: what a run is made of besides the vehicle — the
//! course (the ground's shape), the soil (its strength), the drive's speed
//! profile and whether it goes through the engine, the integrator and its
//! tolerance, the output interval, the duration and where it starts —
//! with the main job's figures as its [`Default`]. The main job, the FMU
//! and a user's own code build their runs from it, so that a default run
//! is the same run everywhere.
//!
//! Every part a user names in words parses through [`FromStr`]: a course
//! (`"flat"`, `"half-round:0.2"`, `"rough:1in"`, `"file:course.csv"`,
//! `"bump:0.1"`),
//! a soil (`"rigid"`, `"dry-sand"`, …), a method (`"auto"`, `"bs23"`, …) and
//! a start (`"assembled"`, `"equilibrium"`), each error naming the bad
//! token.

use std::fmt;
use std::path::PathBuf;
use std::str::FromStr;

use crate::integrate::Integrator;
use crate::simulate::{Output, RunReport, Sink, StreamFailure, simulate_into};
use crate::system::Simulated;
use crate::terrain::Terrain;
use crate::terrain::course::{self, CourseError, CourseSpec};
use crate::terrain::soil::SoilPreset;
use crate::vehicle::{Drive, Powertrain, Vehicle, VehicleConfig, speed_ramp};

/// A run's course, soil, drive, integrator, output and duration.
#[derive(Clone, Debug, PartialEq)]
pub struct Scenario {
    /// The ground's shape.
    pub course: CourseSpec,
    /// The ground's strength.
    pub soil: Soil,
    /// The speed the drive holds after the ramp, m/s (negative: reverse).
    pub speed: f64,
    /// Settling time before the drive starts, s.
    pub settle: f64,
    /// The ramp from rest to `speed`, s (0: a step).
    pub ramp: f64,
    /// Whether the drive goes through the vehicle's powertrain as well as
    /// its speed controller (the engine's envelope caps the torque).
    pub engine: bool,
    /// A drawbar load on the hull from the start, N (negative: a push;
    /// [`VehicleConfig::drawbar_pull`]).
    pub drawbar_pull: f64,
    /// The integrator.
    pub method: Method,
    /// Its tolerance, relative and absolute; `None`: the method's default
    /// ([`Integrator::DEFAULT_EXPLICIT_TOLERANCE`],
    /// [`Integrator::DEFAULT_IMPLICIT_TOLERANCE`]).
    pub tolerance: Option<f64>,
    /// The output interval, s.
    pub output_every: f64,
    /// Simulated time, s.
    pub duration: f64,
    /// Where the run starts.
    pub start: Start,
}

impl Scenario {
    /// The main job's bump: its height, m (a cosine 1 m wide).
    pub const BUMP_HEIGHT: f64 = 0.1;
    /// The main job's bump: where its centre is, m.
    pub const BUMP_AT: f64 = 12.0;
    /// Where an obstacle starts when none is said, m.
    pub const OBSTACLE_AT: f64 = 12.0;
    /// The main job's target speed, m/s.
    pub const SPEED: f64 = 3.0;
    /// The main job's settling time, s.
    pub const SETTLE: f64 = 1.0;
    /// The main job's ramp, s.
    pub const RAMP: f64 = 2.0;
    /// The main job's output interval, s.
    pub const OUTPUT_EVERY: f64 = 0.01;
    /// The main job's simulated time, s.
    pub const DURATION: f64 = 8.0;

    /// The target speed's range, m/s (negative: reverse).
    pub const SPEED_RANGE: Range = Range::closed(-20.0, 20.0, "from -20 to 20 m/s");
    /// A bump's height's range, m (negative: a dip).
    pub const BUMP_HEIGHT_RANGE: Range =
        Range::closed(-0.5, 0.5, "from -0.5 to 0.5 m (negative: a dip)");
    /// The range of where a bump or an obstacle is, m.
    pub const POSITION_RANGE: Range = Range::closed(-1e4, 1e4, "from -10000 to 10000 m");
    /// A random course's rough length's range, m.
    pub const COURSE_LENGTH_RANGE: Range = Range::closed(10.0, 1e5, "from 10 to 100000 m");
    /// The settling time's and the ramp's range, s.
    pub const TIME_RANGE: Range = Range::closed(0.0, 1e6, "from 0 to 1e6 s");
    /// The simulated time's range, s.
    pub const DURATION_RANGE: Range =
        Range::open_below(0.0, 1e6, "more than 0 s and at most 1e6 s");
    /// The output interval's range, s.
    pub const OUTPUT_EVERY_RANGE: Range = Range::closed(1e-4, 1.0, "from 1e-4 to 1 s");
    /// A drawbar load's range, N (negative: a push): a hundred tonnes'
    /// weight either way, past any vehicle here.
    pub const DRAWBAR_RANGE: Range = Range::closed(-1e6, 1e6, "from -1e6 to 1e6 N");
    /// A given tolerance's range.
    pub const TOLERANCE_RANGE: Range = Range::closed(1e-12, 0.1, "from 1e-12 to 0.1");
    /// [`Method::Rk4`]'s step's range, s.
    pub const RK4_STEP_RANGE: Range = Range::open_below(0.0, f64::MAX, "more than 0 s, finite");

    /// Every figure of the scenario in its range (the ranges above, which
    /// the main job's options and the FMU's parameters are held to as
    /// well): the first that is not, named.
    pub fn check(&self) -> Result<(), ScenarioError> {
        Self::SPEED_RANGE.check("speed", self.speed)?;
        Self::TIME_RANGE.check("settle", self.settle)?;
        Self::TIME_RANGE.check("ramp", self.ramp)?;
        Self::OUTPUT_EVERY_RANGE.check("output_every", self.output_every)?;
        Self::DURATION_RANGE.check("duration", self.duration)?;
        Self::DRAWBAR_RANGE.check("drawbar pull", self.drawbar_pull)?;
        if let Some(tolerance) = self.tolerance {
            Self::TOLERANCE_RANGE.check("tolerance", tolerance)?;
        }
        if let Method::Rk4 { step } = self.method {
            Self::RK4_STEP_RANGE.check("rk4 step", step)?;
        }
        match self.course {
            CourseSpec::Bump { at, height } => {
                Self::POSITION_RANGE.check("bump at", at)?;
                Self::BUMP_HEIGHT_RANGE.check("bump height", height)?;
            }
            CourseSpec::Obstacle { at, .. } => {
                Self::POSITION_RANGE.check("obstacle at", at)?;
            }
            CourseSpec::Rough { length, .. } => {
                Self::COURSE_LENGTH_RANGE.check("course length", length)?;
            }
            CourseSpec::Flat | CourseSpec::File(_) | CourseSpec::Laid(_) => {}
        }
        Ok(())
    }

    /// The target speed (m/s) against time (s): 0 while settling, then a
    /// linear ramp to [`speed`](Self::speed) over [`ramp`](Self::ramp)
    /// seconds (a step at the end of settling if 0).
    pub fn speed_profile(&self) -> impl Fn(f64) -> f64 + Send + 'static {
        speed_ramp(self.settle, self.ramp, self.speed)
    }

    /// When the drive reaches its speed, s: where the ride is measured from.
    pub fn at_speed(&self) -> f64 {
        self.settle + self.ramp
    }

    /// The explicit methods' tolerance: given, or the default.
    pub fn explicit_tolerance(&self) -> f64 {
        self.tolerance
            .unwrap_or(Integrator::DEFAULT_EXPLICIT_TOLERANCE)
    }

    /// ROS34PW2's tolerance: given, or the default.
    pub fn implicit_tolerance(&self) -> f64 {
        self.tolerance
            .unwrap_or(Integrator::DEFAULT_IMPLICIT_TOLERANCE)
    }

    /// The integrator at the chosen tolerance, steps of at most
    /// [`Integrator::DEFAULT_MAX_STEP`].
    pub fn integrator(&self) -> Integrator {
        let max_step = Integrator::DEFAULT_MAX_STEP;
        let (explicit, implicit) = (self.explicit_tolerance(), self.implicit_tolerance());
        match self.method {
            Method::Auto => Integrator::Auto {
                explicit_tolerance: explicit,
                implicit_tolerance: implicit,
                max_step,
            },
            Method::Bs23 => Integrator::Bs23 {
                rtol: explicit,
                atol: explicit,
                max_step,
            },
            Method::Dopri5 => Integrator::Dopri5 {
                rtol: explicit,
                atol: explicit,
                max_step,
            },
            Method::Ros34pw2 => Integrator::Ros34pw2 {
                rtol: implicit,
                atol: implicit,
                max_step,
            },
            Method::Rk4 { step } => Integrator::Rk4 { step },
        }
    }

    /// The tolerance the energy books are held to after a run whose
    /// integrator made `implicit` of its accepted steps with ROS34PW2: the
    /// loosest method's that ran.
    pub fn books_tolerance(&self, implicit: u64) -> f64 {
        match self.method {
            Method::Ros34pw2 => self.implicit_tolerance(),
            Method::Auto if implicit > 0 => self.implicit_tolerance(),
            _ => self.explicit_tolerance(),
        }
    }

    /// Simulates `system` through this scenario's time: from 0 to
    /// [`duration`](Self::duration) with its [`integrator`](Self::integrator),
    /// rows every [`output_every`](Self::output_every) into `sink`,
    /// `progress` told the time as the run goes. A failed run returns
    /// its error with the report of what was computed up to then
    /// ([`simulate_into`]).
    #[allow(clippy::result_large_err)]
    pub fn simulate_into(
        &self,
        system: &mut dyn Simulated,
        sink: &mut dyn Sink,
        progress: &mut dyn FnMut(f64),
    ) -> Result<RunReport, StreamFailure> {
        simulate_into(
            system,
            self.integrator(),
            0.0,
            self.duration,
            Output::Every(self.output_every),
            sink,
            progress,
        )
    }

    /// The course's ground: [`CourseSpec::terrain`].
    pub fn terrain(&self) -> Result<Terrain, CourseError> {
        self.course.terrain()
    }

    /// The vehicle `V`'s declared configuration on `terrain` with `drive`,
    /// on this scenario's soil, and through `powertrain` where given.
    pub fn config_with<V: Vehicle>(
        &self,
        terrain: Terrain,
        drive: Drive,
        powertrain: Option<Powertrain>,
    ) -> VehicleConfig {
        let mut config = V::declared_config(terrain, drive);
        if let Some(soil) = self.soil.soil() {
            config.soil = Some(soil);
        }
        config.drawbar_pull = self.drawbar_pull;
        config.powertrain = powertrain;
        config
    }

    /// The vehicle `V`'s configuration for this scenario on `terrain`:
    /// [`config_with`](Self::config_with) the declared speed controller on
    /// [`speed_profile`](Self::speed_profile), through `powertrain` where
    /// [`engine`](Self::engine) is set (`None` there: the controller
    /// alone).
    pub fn config<V: Vehicle>(
        &self,
        terrain: Terrain,
        powertrain: Option<Powertrain>,
    ) -> VehicleConfig {
        let drive = V::speed_drive(self.speed_profile());
        self.config_with::<V>(terrain, drive, powertrain.filter(|_| self.engine))
    }
}

impl Default for Scenario {
    /// The main job's: the M113's defaults, a 0.1 m bump 12 m ahead on
    /// rigid ground, settled for 1 s and driven to 3 m/s over 2 s by the
    /// speed controller, `auto` at its default tolerances, rows every
    /// 10 ms, 8 s from the assembled start.
    fn default() -> Self {
        Scenario {
            course: CourseSpec::Bump {
                at: Self::BUMP_AT,
                height: Self::BUMP_HEIGHT,
            },
            soil: Soil::Rigid,
            speed: Self::SPEED,
            settle: Self::SETTLE,
            ramp: Self::RAMP,
            engine: false,
            drawbar_pull: 0.0,
            method: Method::Auto,
            tolerance: None,
            output_every: Self::OUTPUT_EVERY,
            duration: Self::DURATION,
            start: Start::Assembled,
        }
    }
}

/// A figure's allowed values: finite, from `lo` (or above it) to `hi`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Range {
    /// The least value.
    pub lo: f64,
    /// Whether `lo` itself is refused.
    pub lo_excluded: bool,
    /// The greatest value.
    pub hi: f64,
    /// The range in words, for an error: `from -20 to 20 m/s`.
    pub what: &'static str,
}

impl Range {
    /// From `lo` to `hi`, both allowed.
    pub const fn closed(lo: f64, hi: f64, what: &'static str) -> Range {
        Range {
            lo,
            lo_excluded: false,
            hi,
            what,
        }
    }

    /// Above `lo`, to `hi`.
    pub const fn open_below(lo: f64, hi: f64, what: &'static str) -> Range {
        Range {
            lo,
            lo_excluded: true,
            hi,
            what,
        }
    }

    /// Whether `value` is in it (a NaN or an infinity never is).
    pub fn contains(&self, value: f64) -> bool {
        value.is_finite()
            && value <= self.hi
            && if self.lo_excluded {
                value > self.lo
            } else {
                value >= self.lo
            }
    }

    /// `value` if it is in the range, else the error naming `setting`.
    pub fn check(&self, setting: &'static str, value: f64) -> Result<f64, ScenarioError> {
        if self.contains(value) {
            Ok(value)
        } else {
            Err(ScenarioError {
                setting,
                value,
                range: self.what,
            })
        }
    }
}

/// A scenario's figure out of its range.
#[derive(Clone, Copy, Debug, PartialEq, thiserror::Error)]
#[error("the scenario's {setting} is {value}, out of range: {range}")]
pub struct ScenarioError {
    /// Which figure.
    pub setting: &'static str,
    /// Its value.
    pub value: f64,
    /// Its range in words.
    pub range: &'static str,
}

/// What the ground is made of.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Soil {
    /// Rigid: the contact laws of the vehicle's declaration.
    Rigid,
    /// Soft soil of Wong's table (Bekker–Wong), leaving a rut.
    Soft(SoilPreset),
}

impl Soil {
    /// The soil's laws, for a run's configuration: none on rigid ground
    /// (the declared contact laws), else the preset's
    /// ([`SoilPreset::soil`]).
    pub fn soil(self) -> Option<crate::terrain::soil::Soil> {
        match self {
            Soil::Rigid => None,
            Soil::Soft(preset) => Some(preset.soil()),
        }
    }
}

impl FromStr for Soil {
    type Err = String;

    /// `rigid`, or a soil's name ([`SoilPreset::names`]).
    fn from_str(s: &str) -> Result<Self, String> {
        if s == "rigid" {
            return Ok(Soil::Rigid);
        }
        s.parse()
            .map(Soil::Soft)
            .map_err(|_| format!("`{s}` is no soil; one of rigid, {}", SoilPreset::names()))
    }
}

impl fmt::Display for Soil {
    /// `rigid ground`, `dry-sand soil`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Soil::Rigid => f.write_str("rigid ground"),
            Soil::Soft(soil) => write!(f, "{soil} soil"),
        }
    }
}

/// The integrators a scenario names.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Method {
    /// Bogacki-Shampine while accuracy sets its step, ROS34PW2 while the
    /// stiffest mode would ([`Integrator::Auto`]).
    Auto,
    /// Bogacki-Shampine 3(2).
    Bs23,
    /// Dormand-Prince 5(4).
    Dopri5,
    /// ROS34PW2, linearly implicit (Rosenbrock-W 3(2)).
    Ros34pw2,
    /// The classical fourth-order Runge–Kutta method at a fixed step, s,
    /// without error control (the tolerance is not used): to compare with
    /// a fixed-step tool, or to see what an explicit method does at a
    /// step too long for the contact's stiffness. Named `rk4:STEP`; not
    /// among the main job's choices.
    Rk4 {
        /// The step, s.
        step: f64,
    },
}

impl Method {
    /// Every method with its name, in the order help lists them.
    pub const NAMED: [(&'static str, Method); 4] = [
        ("auto", Method::Auto),
        ("bs23", Method::Bs23),
        ("dopri5", Method::Dopri5),
        ("ros34pw2", Method::Ros34pw2),
    ];
}

impl FromStr for Method {
    type Err = String;

    /// `auto`, `bs23`, `dopri5`, `ros34pw2`, or `rk4:STEP` (s, in
    /// [`Scenario::RK4_STEP_RANGE`]).
    fn from_str(s: &str) -> Result<Self, String> {
        if let Some(step) = s.strip_prefix("rk4:") {
            return step
                .trim()
                .parse::<f64>()
                .ok()
                .filter(|h| Scenario::RK4_STEP_RANGE.contains(*h))
                .map(|step| Method::Rk4 { step })
                .ok_or_else(|| {
                    format!(
                        "`{step}` in `{s}` is no step (s, {})",
                        Scenario::RK4_STEP_RANGE.what
                    )
                });
        }
        named(&Method::NAMED, s, "integrator")
    }
}

/// Where a run starts.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Start {
    /// As assembled: the track wrapped and tensioned, shoes 1 mm above the
    /// ground.
    Assembled,
    /// At rest on the ground ([`equilibrium`](crate::analysis::equilibrium)).
    Equilibrium,
}

impl Start {
    /// Every start with its name.
    pub const NAMED: [(&'static str, Start); 2] = [
        ("assembled", Start::Assembled),
        ("equilibrium", Start::Equilibrium),
    ];
}

impl FromStr for Start {
    type Err = String;

    /// `assembled` or `equilibrium`.
    fn from_str(s: &str) -> Result<Self, String> {
        named(&Start::NAMED, s, "start")
    }
}

/// The value named `s` in `table`, or an error naming `s` and the names.
fn named<T: Copy, const N: usize>(
    table: &[(&'static str, T); N],
    s: &str,
    what: &str,
) -> Result<T, String> {
    table
        .iter()
        .find(|(name, _)| *name == s)
        .map(|(_, value)| *value)
        .ok_or_else(|| {
            let names: Vec<&str> = table.iter().map(|(name, _)| *name).collect();
            format!("`{s}` is no {what}; one of {}", names.join(", "))
        })
}

impl FromStr for CourseSpec {
    type Err = String;

    /// A course in words: `flat`, `bump:HEIGHT[:AT]` (a cosine bump 1 m wide,
    /// centred at `AT`, default [`Scenario::BUMP_AT`]), `file:PATH` (a
    /// profile file), `rough:RMS|CLASS[:SEED[:LENGTH]]` (a random course,
    /// seed 1 and 100 m by default), or an obstacle as
    /// [`course::obstacle`] reads it (`half-round:0.2`, `step:0.5`, …),
    /// optionally `@AT` (default [`Scenario::OBSTACLE_AT`]).
    fn from_str(s: &str) -> Result<Self, String> {
        let number = |part: &str, what: &str| -> Result<f64, String> {
            part.trim()
                .parse::<f64>()
                .ok()
                .filter(|v| v.is_finite())
                .ok_or_else(|| format!("`{part}` in `{s}` is no number ({what})"))
        };
        if s == "flat" {
            return Ok(CourseSpec::Flat);
        }
        if let Some(rest) = s.strip_prefix("bump:") {
            let mut parts = rest.split(':');
            let height = number(parts.next().unwrap_or(""), "the bump's height, m")?;
            let at = match parts.next() {
                Some(p) => number(p, "where the bump's centre is, m")?,
                None => Scenario::BUMP_AT,
            };
            return Ok(CourseSpec::Bump { at, height });
        }
        if let Some(path) = s.strip_prefix("file:") {
            if path.is_empty() {
                return Err(format!("`{s}`: give the file's path after `file:`"));
            }
            return Ok(CourseSpec::File(PathBuf::from(path)));
        }
        if let Some(rest) = s.strip_prefix("rough:") {
            let mut parts = rest.split(':');
            let roughness = course::roughness(parts.next().unwrap_or(""))?;
            let seed = match parts.next() {
                Some(p) => p
                    .trim()
                    .parse::<u64>()
                    .map_err(|_| format!("`{p}` in `{s}` is no seed (a whole number)"))?,
                None => 1,
            };
            let length = match parts.next() {
                Some(p) => number(p, "the course's length, m")?,
                None => 100.0,
            };
            return Ok(CourseSpec::Rough {
                roughness,
                seed,
                length,
            });
        }
        let (obstacle, at) = match s.split_once('@') {
            Some((obstacle, at)) => (obstacle, number(at, "where the obstacle starts, m")?),
            None => (s, Scenario::OBSTACLE_AT),
        };
        let obstacle = course::obstacle(obstacle).map_err(|why| {
            format!(
                "`{s}` is no course: flat, bump:H, file:PATH, rough:RMS, or an obstacle ({why})"
            )
        })?;
        Ok(CourseSpec::Obstacle { obstacle, at })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Each word parses to what it names, and a bad one is refused naming
    /// the bad token.
    #[test]
    fn words_parse_and_bad_ones_are_named() {
        assert_eq!("rigid".parse::<Soil>(), Ok(Soil::Rigid));
        assert_eq!(
            "dry-sand".parse::<Soil>(),
            Ok(Soil::Soft(SoilPreset::DrySand))
        );
        assert!("mud".parse::<Soil>().unwrap_err().contains("`mud`"));
        assert_eq!("ros34pw2".parse::<Method>(), Ok(Method::Ros34pw2));
        assert_eq!(
            "rk4:0.001".parse::<Method>(),
            Ok(Method::Rk4 { step: 0.001 })
        );
        for bad in ["rk4:0", "rk4:-1", "rk4:inf", "rk4:fast"] {
            let e = bad.parse::<Method>().unwrap_err();
            assert!(e.contains(&format!("`{}`", &bad[4..])), "{bad}: {e}");
        }
        let e = "rk45".parse::<Method>().unwrap_err();
        assert!(e.contains("`rk45`") && e.contains("bs23"), "{e}");
        assert_eq!("equilibrium".parse::<Start>(), Ok(Start::Equilibrium));
        assert!("rest".parse::<Start>().unwrap_err().contains("`rest`"));
        assert_eq!("flat".parse::<CourseSpec>(), Ok(CourseSpec::Flat));
        assert_eq!(
            "bump:0.2".parse::<CourseSpec>(),
            Ok(CourseSpec::Bump {
                at: Scenario::BUMP_AT,
                height: 0.2
            })
        );
        assert_eq!(
            "bump:-0.1:5".parse::<CourseSpec>(),
            Ok(CourseSpec::Bump {
                at: 5.0,
                height: -0.1
            })
        );
        assert_eq!(
            "file:ground.csv".parse::<CourseSpec>(),
            Ok(CourseSpec::File("ground.csv".into()))
        );
        assert!(matches!(
            "rough:1in:7".parse::<CourseSpec>(),
            Ok(CourseSpec::Rough {
                seed: 7,
                length: 100.0,
                ..
            })
        ));
        assert!(matches!(
            "half-round:0.2@4".parse::<CourseSpec>(),
            Ok(CourseSpec::Obstacle { at: 4.0, .. })
        ));
        for (bad, token) in [
            ("bump:high", "`high`"),
            ("rough:1in:x", "`x`"),
            ("half-round:0.2@there", "`there`"),
            ("moat:2", "`moat:2`"),
        ] {
            let e = bad.parse::<CourseSpec>().unwrap_err();
            assert!(e.contains(token), "{bad}: {e}");
        }
    }

    /// The default is in range; each figure out of its range (beyond an
    /// end, NaN, infinite, the duration 0) is refused naming it, and the
    /// ends themselves are allowed.
    #[test]
    fn a_scenario_out_of_range_is_refused_naming_the_figure() {
        assert_eq!(Scenario::default().check(), Ok(()));
        let with = |change: fn(&mut Scenario)| {
            let mut s = Scenario::default();
            change(&mut s);
            s.check()
        };
        assert_eq!(with(|s| s.speed = -20.0), Ok(()));
        assert_eq!(with(|s| s.tolerance = Some(1e-12)), Ok(()));
        assert_eq!(with(|s| s.duration = 1e6), Ok(()));
        type Change = fn(&mut Scenario);
        let refused: [(Change, &str); 10] = [
            (|s| s.speed = 20.5, "speed"),
            (|s| s.speed = f64::NAN, "speed"),
            (|s| s.settle = -1.0, "settle"),
            (|s| s.ramp = f64::INFINITY, "ramp"),
            (|s| s.output_every = 2.0, "output_every"),
            (|s| s.duration = 0.0, "duration"),
            (|s| s.tolerance = Some(0.5), "tolerance"),
            (|s| s.method = Method::Rk4 { step: 0.0 }, "rk4 step"),
            (
                |s| {
                    s.course = CourseSpec::Bump {
                        at: 0.0,
                        height: 0.6,
                    }
                },
                "bump height",
            ),
            (
                |s| {
                    s.course = "half-round:0.2@20000".parse().unwrap();
                },
                "obstacle at",
            ),
        ];
        for (change, setting) in refused {
            let e = with(change).unwrap_err();
            assert_eq!(e.setting, setting, "{e}");
            assert!(e.to_string().contains(setting), "{e}");
        }
    }

    /// The default is the main job's: the bump 0.1 m high 12 m ahead,
    /// rigid, 3 m/s after 1 s of settling and a 2 s ramp, `auto` at the
    /// methods' own tolerances (Bogacki-Shampine's 1e-3, ROS34PW2's 1e-2,
    /// steps of at most 10 ms), rows every 10 ms, 8 s.
    #[test]
    fn the_default_is_the_main_jobs() {
        let s = Scenario::default();
        assert_eq!(
            s.course,
            CourseSpec::Bump {
                at: 12.0,
                height: 0.1
            }
        );
        assert_eq!(s.soil, Soil::Rigid);
        assert_eq!((s.speed, s.settle, s.ramp), (3.0, 1.0, 2.0));
        assert_eq!((s.output_every, s.duration), (0.01, 8.0));
        assert_eq!(s.start, Start::Assembled);
        assert!(!s.engine);
        let Integrator::Auto {
            explicit_tolerance,
            implicit_tolerance,
            max_step,
        } = s.integrator()
        else {
            panic!("auto")
        };
        assert_eq!(
            (explicit_tolerance, implicit_tolerance, max_step),
            (1e-3, 1e-2, 0.01)
        );
        assert_eq!(s.books_tolerance(0), 1e-3);
        assert_eq!(s.books_tolerance(1), 1e-2);
        let profile = s.speed_profile();
        assert_eq!((profile(0.5), profile(2.0), profile(9.0)), (0.0, 1.5, 3.0));
    }
}
