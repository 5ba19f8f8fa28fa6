//! The command line: every option is checked when it is parsed, with a
//! message naming the option and its allowed range.

use std::path::PathBuf;

use clap::builder::{PossibleValuesParser, TypedValueParser};
use trackgen::scenario::{Method, Range, Scenario, Soil, Start};
use trackgen::terrain::course::{self, CourseSpec, Roughness};
use trackgen::terrain::profile::Obstacle;

/// Drive the vehicle over a bump (or through a dip), a terrain file, a
/// random course or an obstacle.
///
/// Streams every recorded quantity to `all.csv` and `all.arrow` as it runs
/// (memory stays flat however long the run), the main quantities to
/// `<vehicle>.csv`; then draws `<vehicle>.svg`, `frame.svg` and
/// `animation.html`.
#[derive(clap::Args, Debug)]
#[command(allow_negative_numbers = true)]
pub struct RunArgs {
    /// The vehicle (the application's first by default).
    #[arg(long, value_name = "NAME")]
    pub vehicle: Option<String>,
    /// Target forward speed, m/s, from -20 to 20 (negative: in reverse).
    #[arg(long, default_value_t = Scenario::SPEED, value_name = "M/S", value_parser = speed)]
    pub speed: f64,
    /// The course: a bump (the default), a terrain file, a random
    /// course or an obstacle.
    #[command(flatten)]
    pub course: CourseArgs,
    /// The soil: `rigid`, or a soil of Wong's table (Bekker–Wong soft
    /// soil over the same profile, leaving a rut): dry-sand, sandy-loam,
    /// clay, heavy-clay, lete-sand, snow.
    #[arg(long, alias = "terrain", default_value = "rigid", value_name = "SOIL", value_parser = soil)]
    pub soil: Soil,
    /// The output interval, s, from 1e-4 to 1 (ride figures want 1–2 ms:
    /// they are printed when it is at most 2 ms).
    #[arg(long, default_value_t = Scenario::OUTPUT_EVERY, value_name = "SECONDS", value_parser = output_interval)]
    pub output_every: f64,
    /// Drive through the vehicle's engine as well as its speed controller:
    /// its full-load envelope (the M113's: the M113A3's engine through its
    /// torque converter, ranges and final drive; the Marder's: its engine
    /// map through ideally shifted gears) caps the sprocket's torque, so
    /// the vehicle's power, not the controller's target, sets its speed
    /// where they disagree (the `engine_load` column is 1 there).
    #[arg(long)]
    pub engine: bool,
    /// A drawbar load, N, from -1e6 to 1e6: a horizontal force pulling
    /// the hull back at its centroid from the start (negative: a push);
    /// its work is booked as dissipated.
    #[arg(long, default_value_t = 0.0, value_name = "N", value_parser = drawbar_pull)]
    pub drawbar_pull: f64,
    /// Simulated time, s: more than 0, at most 1e6.
    #[arg(long, default_value_t = Scenario::DURATION, value_name = "SECONDS", value_parser = duration)]
    pub duration: f64,
    /// Settling time before driving, s: 0 to 1e6.
    #[arg(long, default_value_t = Scenario::SETTLE, value_name = "SECONDS", value_parser = non_negative_seconds)]
    pub settle: f64,
    /// Time to ramp the speed up, s: 0 to 1e6 (0: a step).
    #[arg(long, default_value_t = Scenario::RAMP, value_name = "SECONDS", value_parser = non_negative_seconds)]
    pub ramp: f64,
    /// Integrator tolerance, relative and absolute, from 1e-12 to 0.1;
    /// default 1e-3 for Bogacki-Shampine and Dormand-Prince, 1e-2 for
    /// ROS34PW2 (the two close the books to about 1e-3 of the motor's
    /// work: the M113 with Bogacki-Shampine at 1e-3, the Marder with
    /// ROS34PW2 at 1e-2); `auto` runs each method at its own. The books
    /// are held to 10 × the tolerance of the loosest method that ran.
    #[arg(long, value_name = "TOL", value_parser = tolerance)]
    pub tolerance: Option<f64>,
    /// Integrator: `auto` runs Bogacki-Shampine while accuracy sets its
    /// step and ROS34PW2 while the stiffest mode would (checked at the
    /// start and every second), and says which it ran.
    #[arg(long, default_value = "auto", value_name = "METHOD", value_parser = named(&Method::NAMED))]
    pub integrator: Method,
    /// Where the run starts: `assembled` (the track wrapped, shoes 1 mm
    /// above the ground, then `--settle` seconds of settling) or
    /// `equilibrium` (at rest on the ground, found by Newton's method: no
    /// ringing left; the settling time still passes before the drive
    /// starts, `--settle 0` to drive at once).
    #[arg(long, default_value = "assembled", value_name = "START", value_parser = named(&Start::NAMED))]
    pub start: Start,
    /// Also find the vehicle's modes at rest: print the lowest, write
    /// `modes.csv` (every mode), `modes.svg` (the vehicle displaced along
    /// the six lowest) and `modes.html` (a page playing them).
    #[arg(long)]
    pub modes: bool,
    /// Output folder (created if missing); default `out/<vehicle>`.
    #[arg(long, value_name = "DIR", value_parser = folder)]
    pub out: Option<PathBuf>,
}

/// The course a run drives: the bump (the default), a terrain file, a
/// random course or an obstacle (the main job's, in the plane or in 3-D,
/// where every profile lies across the vehicle's whole width).
#[derive(clap::Args, Debug, Clone)]
pub struct CourseArgs {
    /// Bump height, m, from -0.5 to 0.5 (negative: a dip). The bump is a
    /// cosine 1 m wide.
    #[arg(long, default_value_t = Scenario::BUMP_HEIGHT, value_name = "M", value_parser = bump_height)]
    pub bump_height: f64,
    /// Where the bump's centre is, m, from -10000 to 10000 (the chassis
    /// centroid starts at 0 and the vehicle spans about -2.4 to 2.4).
    #[arg(long, default_value_t = Scenario::BUMP_AT, value_name = "M", value_parser = position)]
    pub bump_at: f64,
    /// Drive over a terrain profile read from a CSV file instead of the
    /// bump: a header `x,z`, then one point per line (m), x never
    /// decreasing (two points at one x are a vertical face); `#` starts a
    /// comment line. An error names the line.
    #[arg(long, alias = "terrain-file", value_name = "FILE.csv", conflicts_with_all = ["roughness", "obstacle"])]
    pub course_file: Option<PathBuf>,
    /// Drive over a random course instead of the bump: an ISO 8608 class
    /// (A to H), or a detrended RMS elevation with its unit (1in, 25mm,
    /// 0.03m; up to 0.5 m). Sampled every 5 cm, flat up to x = 5 m, the
    /// roughness fading in over the next 5 m.
    #[arg(long, value_name = "CLASS|RMS", value_parser = course::roughness, conflicts_with = "obstacle")]
    pub roughness: Option<Roughness>,
    /// The random course's seed: the same seed, the same course, bit for
    /// bit.
    #[arg(long, default_value_t = 1, value_name = "N")]
    pub seed: u64,
    /// The random course's length, m, from 10 to 100000 (default: what the
    /// run can cover, 1.2 × |speed| × duration + 20 m).
    #[arg(long, value_name = "M", value_parser = course_length)]
    pub course_length: Option<f64>,
    /// Drive at an obstacle instead of the bump, on flat ground before and
    /// after: half-round:R, step:H (negative: down), gap:WIDTH:DEPTH,
    /// ditch:DEPTH:BOTTOM:ANGLE, barrier:HEIGHT:TOP:ANGLE,
    /// grade:SLOPE:LENGTH (m; angles in degrees from the horizontal, up to
    /// 90; a slope as rise over run). Placed at `--obstacle-at`.
    #[arg(long, value_name = "SPEC", value_parser = course::obstacle)]
    pub obstacle: Option<Obstacle>,
    /// Where the obstacle starts, m, from -10000 to 10000.
    #[arg(long, default_value_t = Scenario::OBSTACLE_AT, value_name = "M", value_parser = position)]
    pub obstacle_at: f64,
}

impl CourseArgs {
    /// The course: a terrain file, a random course or an obstacle if one
    /// is given, else the bump; a random course as long as a run at
    /// `speed` m/s for `duration` s can cover unless its length is given.
    pub fn spec(&self, speed: f64, duration: f64) -> CourseSpec {
        if let Some(path) = &self.course_file {
            CourseSpec::File(path.clone())
        } else if let Some(roughness) = self.roughness {
            let length = self
                .course_length
                .unwrap_or_else(|| course::rough_length(speed, duration))
                .clamp(10.0, 1e5);
            CourseSpec::Rough {
                roughness,
                seed: self.seed,
                length,
            }
        } else if let Some(obstacle) = self.obstacle {
            CourseSpec::Obstacle {
                obstacle,
                at: self.obstacle_at,
            }
        } else {
            CourseSpec::Bump {
                at: self.bump_at,
                height: self.bump_height,
            }
        }
    }
}

impl RunArgs {
    /// The run these options name.
    pub fn scenario(&self) -> Scenario {
        Scenario {
            course: self.course.spec(self.speed, self.duration),
            soil: self.soil,
            speed: self.speed,
            settle: self.settle,
            ramp: self.ramp,
            engine: self.engine,
            drawbar_pull: self.drawbar_pull,
            method: self.integrator,
            tolerance: self.tolerance,
            output_every: self.output_every,
            duration: self.duration,
            start: self.start,
        }
    }

    /// The output folder given, or `out/<vehicle>` for the vehicle named
    /// `name`.
    pub fn out(&self, name: &str) -> PathBuf {
        self.out
            .clone()
            .unwrap_or_else(|| PathBuf::from("out").join(name))
    }
}

/// A parser of the names in `table` (listed by `--help`), each parsed by
/// the runtime's `FromStr` of its type.
pub(crate) fn named<T>(table: &[(&'static str, T)]) -> impl TypedValueParser<Value = T>
where
    T: std::str::FromStr<Err = String> + Clone + Send + Sync + 'static,
{
    let names: Vec<&'static str> = table.iter().map(|(name, _)| *name).collect();
    PossibleValuesParser::new(names).try_map(|s: String| s.parse::<T>())
}

/// `rigid`, or a soil of Wong's table.
pub(crate) fn soil(s: &str) -> Result<Soil, String> {
    s.parse()
}

/// A finite number in `range` (the scenario's: [`Scenario::check`] holds
/// a run built in code to the same), or why not, `noun` naming it.
pub(crate) fn within(s: &str, range: Range, noun: &str) -> Result<f64, String> {
    let what = format!("{noun} is {}", range.what);
    let v: f64 = s
        .trim()
        .parse()
        .map_err(|_| format!("`{s}` is not a number; {what}"))?;
    if !v.is_finite() {
        Err(format!("{v} is not a finite number; {what}"))
    } else if range.contains(v) {
        Ok(v)
    } else {
        Err(format!("{v} is out of range; {what}"))
    }
}

pub(crate) fn speed(s: &str) -> Result<f64, String> {
    within(s, Scenario::SPEED_RANGE, "a speed")
}

fn bump_height(s: &str) -> Result<f64, String> {
    within(s, Scenario::BUMP_HEIGHT_RANGE, "a bump height")
}

fn position(s: &str) -> Result<f64, String> {
    within(s, Scenario::POSITION_RANGE, "a position")
}

pub(crate) fn duration(s: &str) -> Result<f64, String> {
    within(s, Scenario::DURATION_RANGE, "a duration")
}

fn course_length(s: &str) -> Result<f64, String> {
    within(s, Scenario::COURSE_LENGTH_RANGE, "a course length")
}

pub(crate) fn output_interval(s: &str) -> Result<f64, String> {
    within(s, Scenario::OUTPUT_EVERY_RANGE, "an output interval")
}

pub(crate) fn non_negative_seconds(s: &str) -> Result<f64, String> {
    within(s, Scenario::TIME_RANGE, "a time")
}

pub(crate) fn drawbar_pull(s: &str) -> Result<f64, String> {
    within(s, Scenario::DRAWBAR_RANGE, "a drawbar pull")
}

pub(crate) fn tolerance(s: &str) -> Result<f64, String> {
    within(s, Scenario::TOLERANCE_RANGE, "a tolerance")
}

pub(crate) fn folder(s: &str) -> Result<PathBuf, String> {
    if s.trim().is_empty() {
        Err("an empty folder name; give a path".to_string())
    } else {
        Ok(PathBuf::from(s))
    }
}

/// A sprocket speed ratio from the command line: 1.01 to 100.
pub(crate) fn speed_ratio(s: &str) -> Result<f64, String> {
    within(
        s,
        trackgen::scenario::Range::closed(1.01, 100.0, "from 1.01 to 100"),
        "a speed ratio",
    )
}
