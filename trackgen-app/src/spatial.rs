//! The main job in 3-D (`spatial`): the vehicle with both tracks and its
//! hull floating in space, assembled on its course (the profile laid
//! across its whole width, or each track on its own), settled, driven to a target speed by a speed
//! controller on each sprocket (or one on a differential, steered by its
//! brakes or a steer unit), over the course's bump, then steered through
//! a turn by a driver holding a heading.
//!
//! Writes `spatial.csv` (one row per output interval: the hull's pose and
//! motion, the centre of mass's, and per side the sprocket's speed,
//! torque and power, the steering brake's torque and power, the belt's and the ground's speeds, slip, and the
//! ground's force and yaw moment, the track's tensions), `spatial.arrow`
//! (the same, and the ground's force on every shoe) and `spatial.svg`
//! (the path seen from above, and the heading against time).

use std::error::Error;
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::time::Instant;

use indicatif::{ProgressBar, ProgressStyle};
use trackgen::integrate::{Integrator, Stats};
use trackgen::nalgebra::DVector;
use trackgen::ride::{Biquad, Section};
use trackgen::scenario::{Scenario, Soil};
use trackgen::simulate::{CsvSink, EnergyBalance, March, Sink, Tee, Thinned};
use trackgen::spatial_vehicle::{
    DrivelineAsked, HeadingHold, SPATIAL_COLUMNS, SideBooks, SpatialEnergy, SpatialGround,
    SpatialLaws, SpatialOutputs, SpatialSimulated, SpatialVehicleSystem, drive_as_asked, on_ground,
    spatial_row,
};
use trackgen::terrain::course::CourseSpec;
use trackgen::vehicle::speed_ramp;
use trackgen_arrow::ArrowSink;

use crate::cli::{self, CourseArgs, within};
use crate::console::say;
use crate::offered::Offered;
use crate::spatial_driveline::DrivelineKind;
use crate::spatial_frames::Frames;
use crate::spatial_rows::{shoe_columns, shoe_forces};

/// Drive the vehicle in 3-D: both tracks and the hull, settled, driven
/// to speed over the course, then turned by a driver holding a heading.
///
/// Writes `spatial.csv`, `spatial.arrow` and `spatial.svg`.
#[derive(clap::Args, Debug)]
#[command(allow_negative_numbers = true)]
pub struct SpatialArgs {
    /// The vehicle (the application's first by default).
    #[arg(long, value_name = "NAME")]
    pub vehicle: Option<String>,
    /// Target forward speed, m/s, from -20 to 20 (negative: in reverse).
    #[arg(long, default_value_t = Scenario::SPEED, value_name = "M/S", value_parser = cli::speed)]
    pub speed: f64,
    /// The course, across the vehicle's whole width.
    #[command(flatten)]
    pub course: CourseArgs,
    /// The ground under the left track alone: a terrain profile file as
    /// `--course-file`'s, in place of the course there (the two blended
    /// across the ground between the tracks). The profiles run along x: a
    /// turn takes the tracks off them (`--turn 0` drives straight).
    #[arg(long, value_name = "FILE.csv")]
    pub left_course_file: Option<PathBuf>,
    /// The ground under the right track alone, as `--left-course-file`.
    #[arg(long, value_name = "FILE.csv")]
    pub right_course_file: Option<PathBuf>,
    /// The ground as heights on a grid instead of a course: an ESRI ASCII
    /// grid file (`.asc`, as GIS tools export a surveyed surface), x along
    /// the course and y to its left, bilinear between the nodes. An error
    /// names the line.
    #[arg(
        long,
        value_name = "FILE.asc",
        conflicts_with_all = ["course_file", "roughness", "obstacle", "left_course_file", "right_course_file"]
    )]
    pub field_file: Option<PathBuf>,
    /// The turn, degrees to the left (negative: to the right), from -360
    /// to 360; 0 drives straight.
    #[arg(long, default_value_t = TURN, value_name = "DEG", value_parser = turn)]
    pub turn: f64,
    /// When the turn starts, s: 0 to 1e6.
    #[arg(long, default_value_t = TURN_AT, value_name = "SECONDS", value_parser = cli::non_negative_seconds)]
    pub turn_at: f64,
    /// How long the heading wanted takes to turn, s: 0 to 1e6 (0: a step,
    /// the driver steering as hard as the belts allow).
    #[arg(long, default_value_t = TURN_TIME, value_name = "SECONDS", value_parser = cli::non_negative_seconds)]
    pub turn_time: f64,
    /// Settling time before driving, s: 0 to 1e6.
    #[arg(long, default_value_t = Scenario::SETTLE, value_name = "SECONDS", value_parser = cli::non_negative_seconds)]
    pub settle: f64,
    /// Time to ramp the speed up, s: 0 to 1e6 (0: a step).
    #[arg(long, default_value_t = Scenario::RAMP, value_name = "SECONDS", value_parser = cli::non_negative_seconds)]
    pub ramp: f64,
    /// Simulated time, s: more than 0, at most 1e6.
    #[arg(long, default_value_t = DURATION, value_name = "SECONDS", value_parser = cli::duration)]
    pub duration: f64,
    /// The output interval, s, from 1e-4 to 1.
    #[arg(long, default_value_t = Scenario::OUTPUT_EVERY, value_name = "SECONDS", value_parser = cli::output_interval)]
    pub output_every: f64,
    /// Bogacki-Shampine's tolerance, relative and absolute, from 1e-12 to
    /// 0.1 (the books are held to 10 × it).
    #[arg(long, default_value_t = Integrator::DEFAULT_EXPLICIT_TOLERANCE, value_name = "TOL", value_parser = cli::tolerance)]
    pub tolerance: f64,
    /// A side slope across the course, rise over run to the left (the
    /// ground `z = s y` added to the course), from -1 to 1; the vehicle
    /// is set on it at rest, heading along the course.
    #[arg(long, default_value_t = 0.0, value_name = "S", value_parser = side_slope)]
    pub side_slope: f64,
    /// A drawbar load, N, from -1e6 to 1e6: a force pulling the hull back
    /// along its heading, level, at its centroid, from the start
    /// (negative: a push); its work is booked as dissipated.
    #[arg(long, default_value_t = 0.0, value_name = "N", value_parser = cli::drawbar_pull)]
    pub drawbar_pull: f64,
    /// The soil: `rigid`, or a soil of Wong's table (Bekker–Wong soft
    /// soil over the same ground, the tracks leaving their ruts):
    /// dry-sand, sandy-loam, clay, heavy-clay, lete-sand, snow.
    #[arg(long, default_value = "rigid", value_name = "SOIL", value_parser = cli::soil)]
    pub soil: Soil,
    /// How the drive reaches the sprockets.
    #[arg(long, value_enum, default_value_t = DrivelineKind::Sides)]
    pub driveline: DrivelineKind,
    /// The steer unit's minimum steer ratio (`--driveline steer-ratio`),
    /// 1.01 to 100; default the vehicle's first published one.
    #[arg(long, value_name = "RATIO", value_parser = cli::speed_ratio)]
    pub steer_ratio: Option<f64>,
    /// Drive through the vehicle's engine. On a differential (`brakes`,
    /// `steer-ratio`), an engine whose inertia is declared has its speed
    /// as a state: its governor, torque converter, scheduled ranges and
    /// lock-up drive the box (the planar `--engine`'s), and a steer unit
    /// draws its power from it; with published steer ratios and no
    /// `--steer-ratio`, the steer unit is the steer drive geared to that
    /// engine. Otherwise (a drive on each side, or no engine inertia) the
    /// engine's full-load envelope caps each side's drive, or twice a
    /// side's the box's.
    #[arg(long)]
    pub engine: bool,
    /// Output folder (created if missing); default `out/<vehicle>`.
    #[arg(long, value_name = "DIR", value_parser = cli::folder)]
    pub out: Option<PathBuf>,
}

/// The turn's default angle, degrees.
pub const TURN: f64 = 90.0;
/// When it starts by default, s: past the default bump at the default
/// speed.
pub const TURN_AT: f64 = 8.0;
/// How long it takes by default, s.
pub const TURN_TIME: f64 = 4.0;
/// The default simulated time, s: the turn and 2 s after it.
pub const DURATION: f64 = 14.0;
/// A spatial vehicle set on its ground: the system, its state, and what
/// to say of the ground.
type Grounded<V> = (<V as SpatialVehicleSystem>::Spatial, DVector<f64>, String);

/// The vehicle set on the ground `args` ask for (a grid file, else the
/// course with each track's own file where given), and what to say of
/// it.
fn on_the_ground<V: SpatialVehicleSystem>(
    args: &SpatialArgs,
) -> Result<Grounded<V>, Box<dyn Error>> {
    let ground = match &args.field_file {
        Some(path) => SpatialGround::GridFile(path.clone()),
        None => SpatialGround::Course {
            course: args.course.spec(args.speed, args.duration),
            sides: [&args.right_course_file, &args.left_course_file]
                .map(|file| file.as_ref().map(|path| CourseSpec::File(path.clone()))),
        },
    };
    let laws = SpatialLaws {
        soil: args.soil.soil(),
        ..V::declared_laws()
    };
    let (system, y, _) = on_ground::<V>(laws, &ground, args.side_slope)?;
    Ok((system, y, ground.describe()))
}

fn side_slope(s: &str) -> Result<f64, String> {
    within(
        s,
        trackgen::scenario::Range::closed(-1.0, 1.0, "from -1 to 1"),
        "a side slope",
    )
}

fn turn(s: &str) -> Result<f64, String> {
    within(
        s,
        trackgen::scenario::Range::closed(-360.0, 360.0, "from -360 to 360 degrees"),
        "a turn",
    )
}

/// `spatial` for the vehicle `V`: exits 1, saying why, when the run cannot
/// be made or stops early (the rows up to then kept).
pub fn main<V: SpatialVehicleSystem>(entry: &Offered, args: &SpatialArgs) -> ExitCode {
    match drive::<V>(entry, args) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::FAILURE
        }
    }
}

/// The cut-off of the low-pass filter (second-order Butterworth) the
/// summary reads the lateral acceleration through, Hz: a turn's own
/// motion is below 1 Hz, while the rows carry the track's vibration
/// (its shoes pass the wheels at 20 Hz at 3 m/s), whose peaks would
/// otherwise be reported as the turn's and move with the last bit of the
/// run (the file keeps the acceleration unfiltered).
const LATERAL_FILTER_HZ: f64 = 2.0;

/// What the run showed, gathered row by row.
struct Summary {
    /// The smallest turn radius, m, and the largest lateral acceleration's
    /// size, m/s², filtered, while turning.
    radius: Option<f64>,
    lateral: f64,
    /// The lateral acceleration's filter, fed every row.
    filter: Biquad,
    /// Each track's largest tension, N, and when, s (right, left).
    tension: [(f64, f64); 2],
    /// Through an engine whose speed is a state: what it did.
    engine: Option<EngineSeen>,
    first: Option<SpatialOutputs>,
    last: Option<SpatialOutputs>,
}

impl Summary {
    /// Nothing seen yet, the rows `dt` (s) apart.
    fn new(dt: f64) -> Summary {
        let low_pass = Section::lowpass(LATERAL_FILTER_HZ, std::f64::consts::FRAC_1_SQRT_2);
        Summary {
            radius: None,
            lateral: 0.0,
            filter: Biquad::bilinear(low_pass, dt, 0.0),
            tension: [(f64::NEG_INFINITY, f64::NAN); 2],
            engine: None,
            first: None,
            last: None,
        }
    }

    fn add(&mut self, t: f64, out: &SpatialOutputs, turning: bool) {
        let lateral = self.filter.push(out.lateral_acceleration);
        for (kept, side) in self.tension.iter_mut().zip(&out.sides) {
            if side.tensions.largest > kept.0 {
                *kept = (side.tensions.largest, t);
            }
        }
        if let Some(side) = &out.engine {
            let seen = self.engine.get_or_insert(EngineSeen {
                power: (f64::NEG_INFINITY, f64::NAN),
                speed: f64::NEG_INFINITY,
                ranges: (f64::INFINITY, f64::NEG_INFINITY),
                rows: 0,
                locked: 0,
            });
            if side.engine_power > seen.power.0 {
                seen.power = (side.engine_power, t);
            }
            seen.speed = seen.speed.max(side.engine_speed);
            seen.ranges = (seen.ranges.0.min(out.gear), seen.ranges.1.max(out.gear));
            seen.rows += 1;
            seen.locked += usize::from(side.locked == Some(true));
        }
        if turning {
            self.radius = Some(
                self.radius
                    .map_or(out.turn_radius, |r| r.min(out.turn_radius)),
            );
            self.lateral = self.lateral.max(lateral.abs());
        }
        self.first.get_or_insert(*out);
        self.last = Some(*out);
    }
}

/// What an engine whose speed is a state did over the rows.
struct EngineSeen {
    /// Its largest power, W, and when, s.
    power: (f64, f64),
    /// Its fastest speed, rad/s.
    speed: f64,
    /// The lowest and highest range recorded (from 1, −1 in reverse).
    ranges: (f64, f64),
    /// The rows seen, and those with the lock-up clutch engaged.
    rows: usize,
    locked: usize,
}

fn drive<V: SpatialVehicleSystem>(
    entry: &Offered,
    args: &SpatialArgs,
) -> Result<(), Box<dyn Error>> {
    let layout = V::layout();
    let assembling = Instant::now();
    let (mut system, mut y, ground_said) = on_the_ground::<V>(args)?;
    let assembly = assembling.elapsed().as_secs_f64();
    let target = || -> Box<dyn Fn(f64) -> f64 + Send> {
        Box::new(speed_ramp(args.settle, args.ramp, args.speed))
    };
    let asked = DrivelineAsked {
        driveline: args.driveline.into(),
        steer_ratio: args.steer_ratio,
        engine: args.engine,
        speed: args.speed,
        powertrain: entry.engine(),
    };
    let driven = drive_as_asked::<V>(&mut system, y.as_mut_slice(), &asked, target)?;
    let angle = args.turn.to_radians();
    system.set_steering(HeadingHold::driver(
        angle,
        (args.turn_at, args.turn_time),
        layout.gauge,
    ))?;
    system.set_drawbar_pull(args.drawbar_pull)?;
    let shoes = (V::RIGHT_TRACK_DOF - 2, V::LEFT_TRACK_DOF - 2);
    say!(
        "{} in 3-D: {} + {} shoes (right, left), gauge {:.3} m; assembled in {:.0} ms",
        V::NAME,
        shoes.0,
        shoes.1,
        layout.gauge,
        assembly * 1e3
    );
    say!("driven through {driven}");
    crate::report::say_drawbar(args.drawbar_pull, " along its heading");
    say!(
        "settle {:.1} s, then to {:.1} m/s in {:.1} s; {} on {}; turning {:.0}° {} from t = {:.1} s over {:.1} s; {:.1} s in all",
        args.settle,
        args.speed,
        args.ramp,
        ground_said,
        args.soil,
        args.turn.abs(),
        if args.turn >= 0.0 { "left" } else { "right" },
        args.turn_at,
        args.turn_time,
        args.duration
    );
    let dir = args
        .out
        .clone()
        .unwrap_or_else(|| PathBuf::from("out").join(entry.name()));
    std::fs::create_dir_all(&dir)?;
    let mut csv = CsvSink::create(dir.join("spatial.csv"))?;
    let mut thinned = Thinned::new(PICTURE_ROWS);
    let mut sink = Tee::new().and(&mut csv).and(&mut thinned);
    sink.begin(&SPATIAL_COLUMNS.map(String::from))?;
    let mut arrow = ArrowSink::create(dir.join("spatial.arrow"))?;
    let mut wide: Vec<String> = SPATIAL_COLUMNS.map(String::from).to_vec();
    wide.extend(shoe_columns(shoes));
    arrow.begin(&wide)?;
    let mut wide_row = Vec::with_capacity(wide.len());
    let mut march = March::from_state(
        Integrator::bs23(args.tolerance),
        y.clone(),
        0.0,
        args.duration,
    )?;
    let before = Books::at(&system, y.as_slice());
    let bar = ProgressBar::new((args.duration * 1000.0) as u64);
    bar.set_style(ProgressStyle::with_template(
        "{bar:40} {pos:>5}/{len} ms simulated  {elapsed_precise}  eta {eta}",
    )?);
    let mut summary = Summary::new(args.output_every);
    let mut frames = Frames::new::<V>(args.duration);
    let started = Instant::now();
    let mut row = 0u64;
    let mut rows = RowTimes::new(args.output_every, args.duration);
    let mut due = vec![(0.0, y)];
    let outcome = 'run: loop {
        for (at, state) in due.drain(..) {
            let out = match system.outputs(at, state.as_slice()) {
                Ok(out) => out,
                Err(e) => break 'run Err(e),
            };
            let turning = at >= args.turn_at && at <= args.turn_at + args.turn_time;
            summary.add(at, &out, turning && angle != 0.0);
            frames.offer(&system, at, state.as_slice());
            let values = spatial_row(&out);
            sink.row(at, &values)?;
            wide_row.clear();
            wide_row.extend_from_slice(&values);
            shoe_forces(
                &system.ground_forces(state.as_slice()),
                shoes,
                &mut wide_row,
            );
            arrow.row(at, &wide_row)?;
            row += 1;
        }
        if march.finished() {
            break Ok(());
        }
        if let Err(e) = march.step(&mut system) {
            break Err(e);
        }
        rows.within(&march, &mut due);
        // A shift or the lock-up changes the right-hand side: the rows
        // within the step are read first, from the step as it was taken.
        if system.after_step(march.time(), march.state().as_slice()) {
            march.restart();
        }
        bar.set_position((march.time() * 1000.0) as u64);
    };
    bar.finish_and_clear();
    let wall = started.elapsed().as_secs_f64();
    sink.finish()?;
    drop(sink);
    arrow.finish()?;
    let t = march.time();
    let books = Books::at(&system, march.state().as_slice()).since(&before);
    report(&summary, (t, wall), &march.stats(), &books, args);
    frames.take_ruts(&system);
    let mut written = vec!["spatial.csv", "spatial.arrow"];
    written.extend(pictures(&dir, &thinned, &frames, V::NAME)?);
    say!(
        "wrote {}/{{{}}} ({row} rows)",
        dir.display(),
        written.join(", ")
    );
    outcome
        .map_err(|e| format!("the run stopped early: {e} (rows up to t = {t:.4} s written)").into())
}

/// The run's pictures into `dir`: the path from above (`spatial.svg`,
/// from the `thinned` rows) and the page that plays its `frames`, each
/// over the ground as it was then (`animation.html`); the files written.
fn pictures(
    dir: &Path,
    thinned: &Thinned,
    frames: &Frames,
    name: &str,
) -> Result<Vec<&'static str>, Box<dyn Error>> {
    let mut written = Vec::new();
    let kept = thinned.results();
    if kept.len() >= 2 {
        let column = |name| kept.column(name).unwrap_or_default();
        let path: Vec<_> = (kept.times().iter().zip(column("x")).zip(column("y")))
            .zip(column("heading"))
            .map(|(((t, x), y), heading)| (*t, x, y, heading))
            .collect();
        draw(&dir.join("spatial.svg"), &path, name)?;
        written.push("spatial.svg");
    }
    if frames.write(&dir.join("animation.html"), name)? {
        written.push("animation.html");
    }
    Ok(written)
}

/// The rows' times: every `every` s from 0, and the end. The rows are
/// read by the integrator's dense output (the planar main job's rule),
/// so that the steps are the error control's, not cut at the rows.
struct RowTimes {
    every: f64,
    end: f64,
    /// The rows due so far (the start's first).
    queued: u64,
}

impl RowTimes {
    /// Rows `every` s apart up to `end` s, the start's due already.
    fn new(every: f64, end: f64) -> RowTimes {
        RowTimes {
            every,
            end,
            queued: 1,
        }
    }

    fn time(&self, k: u64) -> f64 {
        (k as f64 * self.every).min(self.end)
    }

    /// The rows within the step `march` just took, each with its state
    /// (by dense output, the step's end's own within `march`'s
    /// [`eps`](March::eps)), onto `due`.
    fn within(&mut self, march: &March, due: &mut Vec<(f64, DVector<f64>)>) {
        let t = march.time();
        while self.time(self.queued) <= t + march.eps() && self.time(self.queued - 1) < self.end {
            let at = self.time(self.queued).min(t);
            due.push((at, march.state_at(at)));
            self.queued += 1;
        }
    }
}

/// The books at a state: where the energy is, and each side's.
struct Books {
    energy: SpatialEnergy,
    sides: [SideBooks; 2],
}

impl Books {
    fn at(system: &dyn SpatialSimulated, y: &[f64]) -> Books {
        Books {
            energy: system.energy(y),
            sides: system.side_books(y),
        }
    }

    /// A run's balance from `before` to these, each side's share, and the
    /// drawbar load's work (J).
    fn since(&self, before: &Books) -> Since {
        let (after, before_energy) = (&self.energy, &before.energy);
        let balance = EnergyBalance {
            motor_work: after.driven - before_energy.driven,
            energy_change: after.held() - before_energy.held(),
            dissipated: after.dissipated - before_energy.dissipated,
        };
        (
            balance,
            [0, 1].map(|s| self.sides[s].since(&before.sides[s])),
            after.drawbar - before_energy.drawbar,
        )
    }
}

/// A run's books ([`Books::since`]): the balance, each side's share and
/// the drawbar's work, J.
type Since = (EnergyBalance, [SideBooks; 2], f64);

/// Prints the run's time, its steps, the turn and the books, in all and
/// per side.
fn report(
    summary: &Summary,
    (t, wall): (f64, f64),
    stats: &Stats,
    (books, sides, drawbar): &Since,
    args: &SpatialArgs,
) {
    say!(
        "ran {t:.2} s in {wall:.2} s wall ({:.1}× real time): {} steps ({} rejected), {} evaluations",
        t / wall,
        stats.accepted,
        stats.rejected,
        stats.evaluations
    );
    if let Some(last) = &summary.last {
        say!(
            "at the end: heading {:.1}° (asked {:.1}°), speed {:.2} m/s, pitch {:.2}°, roll {:.2}°",
            last.heading.to_degrees(),
            args.turn,
            last.centre.velocity.xy().norm(),
            last.pitch.to_degrees(),
            last.roll.to_degrees()
        );
    }
    if let (Some(first), Some(last), true) = (&summary.first, &summary.last, args.side_slope != 0.0)
    {
        // The slope rises to the world's left (`+y`) for a positive `s`.
        let across = (last.centre.position.y - first.centre.position.y) * args.side_slope.signum();
        say!(
            "across the {:.0} % side slope: the centre of mass moved {:.3} m {} and {:.2} m along the course",
            100.0 * args.side_slope.abs(),
            across.abs(),
            if across > 0.0 { "uphill" } else { "downhill" },
            last.centre.position.x - first.centre.position.x
        );
    }
    if let Some(radius) = summary.radius {
        say!(
            "in the turn: smallest radius {radius:.2} m, largest lateral acceleration {:.2} m/s² ({:.3} g; low-passed at {LATERAL_FILTER_HZ} Hz)",
            summary.lateral,
            summary.lateral / 9.80665
        );
    }
    let [(right, right_at), (left, left_at)] = summary.tension;
    if right.is_finite() && left.is_finite() {
        say!(
            "the tracks' largest tension: right {:.1} kN (at {right_at:.2} s), left {:.1} kN (at {left_at:.2} s)",
            right / 1e3,
            left / 1e3
        );
    }
    if let Some(e) = &summary.engine {
        say!(
            "the engine: at most {:.1} kW (at {:.2} s), {:.0} rpm at the fastest, ranges {} to {}, locked up in {:.0} % of the rows",
            e.power.0 / 1e3,
            e.power.1,
            e.speed * 30.0 / std::f64::consts::PI,
            e.ranges.0,
            e.ranges.1,
            100.0 * e.locked as f64 / e.rows as f64
        );
    }
    let bound = EnergyBalance::bound_for_tolerance(args.tolerance);
    say!(
        "books: the drives' work {:.1} kJ, held {:+.1} kJ, dissipated {:.1} kJ: residual {:.1e} (bound {bound:.0e})",
        books.motor_work / 1e3,
        books.energy_change / 1e3,
        books.dissipated / 1e3,
        books.residual()
    );
    if args.drawbar_pull != 0.0 {
        say!("  the drawbar: {:.1} kJ of the dissipated", drawbar / 1e3);
    }
    for (name, side) in ["right", "left"].iter().zip(sides) {
        say!(
            "  {name}: into its sprocket {:.1} kJ; lost in the ground {:.1}, the running gear {:.1}, the suspension {:.1}, the brake {:.1} kJ",
            side.sprocket_work / 1e3,
            side.ground / 1e3,
            side.running_gear / 1e3,
            side.suspension / 1e3,
            side.brake / 1e3
        );
    }
    if let Some(warning) = crate::report::books_warning(books, args.tolerance) {
        say!("{warning}");
    }
}

/// The rows the picture is drawn from, at most: a run of any length
/// keeps them evenly spaced.
const PICTURE_ROWS: usize = 2000;

/// The path seen from above and the heading against time.
fn draw(file: &Path, path: &[(f64, f64, f64, f64)], name: &str) -> Result<(), Box<dyn Error>> {
    use plotters::prelude::*;
    let root = SVGBackend::new(file, (1000, 480)).into_drawing_area();
    root.fill(&WHITE)?;
    let (top, heading) = root.split_horizontally(520);
    let (x0, x1) = bounds(path.iter().map(|p| p.1));
    let (y0, y1) = bounds(path.iter().map(|p| p.2));
    // One metre the same length both ways: the wider span sets the scale.
    let span = (x1 - x0).max(y1 - y0) / 2.0 + 1.0;
    let (xm, ym) = ((x0 + x1) / 2.0, (y0 + y1) / 2.0);
    let mut chart = ChartBuilder::on(&top)
        .caption(
            format!("{name}: the centre of mass from above"),
            ("sans-serif", 18),
        )
        .margin(10)
        .x_label_area_size(35)
        .y_label_area_size(45)
        .build_cartesian_2d(xm - span..xm + span, ym - span..ym + span)?;
    chart
        .configure_mesh()
        .x_desc("x, m")
        .y_desc("y, m")
        .draw()?;
    chart.draw_series(LineSeries::new(path.iter().map(|p| (p.1, p.2)), &BLUE))?;
    let (t0, t1) = bounds(path.iter().map(|p| p.0));
    let (h0, h1) = bounds(path.iter().map(|p| p.3.to_degrees()));
    let mut chart = ChartBuilder::on(&heading)
        .caption("heading", ("sans-serif", 18))
        .margin(10)
        .x_label_area_size(35)
        .y_label_area_size(45)
        .build_cartesian_2d(t0..t1, h0 - 5.0..h1 + 5.0)?;
    chart
        .configure_mesh()
        .x_desc("t, s")
        .y_desc("heading, °")
        .draw()?;
    chart.draw_series(LineSeries::new(
        path.iter().map(|p| (p.0, p.3.to_degrees())),
        &RED,
    ))?;
    root.present()?;
    Ok(())
}

/// The smallest and largest of `values`.
fn bounds(values: impl Iterator<Item = f64>) -> (f64, f64) {
    values.fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| {
        (lo.min(v), hi.max(v))
    })
}
