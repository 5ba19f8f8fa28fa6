//! The main job (`run`): the vehicle assembled on its course, settled
//! under gravity, driven up to a target speed by a speed-controlled
//! sprocket (or through its engine), with its files streamed as the run
//! goes and its report at the end.
//!
//! Writes to the output folder: `all.csv` and `all.arrow` (every recorded
//! quantity, CSV and Arrow IPC), `<vehicle>.csv` (chassis position, pitch
//! and speed, sprocket torque and speed, tension in link 1, ground normal
//! force); at the end, from a bounded selection of rows: `<vehicle>.svg`
//! (plots), `frame.svg` (the vehicle at the bump), `animation.html`.
//! Memory stays flat however long the run. Lines printed to a closed pipe
//! are dropped; the run and its files go on.

use std::error::Error;
use std::process::ExitCode;
use std::time::Instant;

use indicatif::{ProgressBar, ProgressStyle};
use trackgen::multibody::PartKind;
use trackgen::scenario::{Scenario, Start};
use trackgen::scene::{self, Scene};
use trackgen::simulate::{Background, RideSink, StreamFailure};
use trackgen::system::Simulated;
use trackgen::vehicle::{Vehicle, VehicleDynamics};

use crate::cli::RunArgs;
use crate::console::say;
use crate::modes;
use crate::offered::Offered;
use crate::outputs::Outputs;
use crate::report;

/// `run` for the vehicle `V`: exits 1, saying why, when the run cannot be
/// made or stops early (the rows up to then kept).
pub fn main<V: Vehicle>(entry: &Offered, args: &RunArgs) -> ExitCode {
    match drive::<V>(entry, args) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::FAILURE
        }
    }
}

/// What the vehicle is, from its declared parts: `M113 (one side): 64
/// shoes, sprocket, 5 road wheels on torsion arms, idler on a tensioner
/// arm`.
fn about<V: Vehicle>() -> String {
    type S<V> = <V as Vehicle>::System;
    let parts = S::<V>::parts();
    let count = |kind| parts.iter().filter(|p| p.kind == kind).count();
    let mut words = vec![
        format!("{} shoes", S::<V>::track_dof() - 2),
        "sprocket".to_string(),
    ];
    let wheels = count(PartKind::RoadWheel);
    let sprung = parts
        .iter()
        .all(|p| p.kind != PartKind::RoadWheel || p.arm.is_some());
    let plural = |n: usize| if n == 1 { "" } else { "s" };
    words.push(format!(
        "{wheels} road wheel{}{}",
        plural(wheels),
        if sprung {
            if wheels == 1 {
                " on a torsion arm"
            } else {
                " on torsion arms"
            }
        } else {
            ""
        }
    ));
    match count(PartKind::Roller) {
        0 => {}
        n => words.push(format!("{n} return roller{}", plural(n))),
    }
    for idler in parts.iter().filter(|p| p.kind == PartKind::Idler) {
        words.push(match idler.arm {
            Some(_) => "idler on a tensioner arm".to_string(),
            None => "idler".to_string(),
        });
    }
    format!("{} (one side): {}", V::NAME, words.join(", "))
}

/// Says what the run will do: the soil, the speed profile, the course,
/// the duration and a drawbar load.
fn announce(scenario: &Scenario) {
    let ramp = if scenario.ramp > 0.0 {
        format!("in {:.1} s", scenario.ramp)
    } else {
        "at once".to_string()
    };
    say!(
        "on {}: settle {:.1} s, then to {:.1} m/s {ramp}; {}; {:.1} s in all",
        scenario.soil,
        scenario.settle,
        scenario.speed,
        scenario.course.describe(),
        scenario.duration
    );
    crate::report::say_drawbar(scenario.drawbar_pull, "");
}

/// Assembles the vehicle `V` for the scenario the options name (through
/// `entry`'s powertrain with `--engine`), runs it, streaming its outputs,
/// and reports.
fn drive<V: Vehicle>(entry: &Offered, args: &RunArgs) -> Result<(), Box<dyn Error>> {
    let scenario = args.scenario();
    scenario.check()?;
    let engine = if scenario.engine {
        Some(entry.engine()?)
    } else {
        None
    };
    let course = &scenario.course;
    let terrain = scenario.terrain()?;
    let assembling = Instant::now();
    let config = || scenario.config::<V>(terrain.clone(), engine.clone());
    let mut system = V::system_with(config())?;
    let assembly = assembling.elapsed().as_secs_f64();
    let about = about::<V>();
    let name = entry.name();
    let title = format!(
        "{} driving {}",
        about.split(':').next().unwrap_or(name),
        course.title()
    );
    let mut outputs = Outputs::create(
        &args.out(name),
        (name, title, Scene::of::<V>()),
        &system.columns(),
        course.focus(),
    )?;

    // The ride at the seat, from the end of the speed ramp on, when the
    // rows resolve its band.
    if scenario.output_every <= RideSink::MAX_INTERVAL {
        outputs.recorders.ride = Some(RideSink::new(scenario.output_every, scenario.at_speed())?);
    }

    say!("{about}");
    say!(
        "assembled (track wrapped, tensioner set) in {:.0} ms",
        assembly * 1e3
    );
    let rest_ground = scene::Ground {
        terrain: terrain.clone(),
        rut: Vec::new(),
    };
    let mut extra_files = Vec::new();
    let mut hull_modes = Vec::new();
    if scenario.start == Start::Equilibrium || args.modes {
        // Finding the rest may switch the track's partition: a run from the
        // assembled start needs a vehicle that has not been moved.
        let mut resting = V::system_with(config())?;
        let (rest, _) = modes::find_rest(&mut resting)?;
        if args.modes {
            (extra_files, hull_modes) =
                modes::report::<V>(&mut resting, &rest, outputs.dir(), &rest_ground)?;
        }
        if scenario.start == Start::Equilibrium {
            system = resting;
            system.set_start(rest.state.as_slice())?;
        }
    }
    announce(&scenario);
    let bar = ProgressBar::new((scenario.duration * 1000.0) as u64);
    bar.set_style(ProgressStyle::with_template(
        "{bar:40} {pos:>5}/{len} ms simulated  {elapsed_precise}  eta {eta}",
    )?);
    let started = Instant::now();
    // The files are written on a second thread while the run goes on. (A
    // failed stream carries its report by value, as the API returns it.)
    #[allow(clippy::result_large_err)]
    let outcome = std::thread::scope(|scope| {
        let recorders = &mut outputs.recorders;
        let mut sink = Background::spawn(scope, move || recorders.sink());
        scenario.simulate_into(&mut system, &mut sink, &mut |t| {
            bar.set_position((t * 1000.0) as u64)
        })
    });
    bar.finish_and_clear();
    let wall = started.elapsed().as_secs_f64();
    let (report, failure) = match outcome {
        Ok(report) => (report, None),
        Err(StreamFailure {
            error,
            report,
            finish,
        }) => (report, Some((error, finish))),
    };
    // A run that stopped at its start has nothing to summarise or draw.
    let started = report.rows >= 2;
    let written = if started {
        let tolerance = scenario.books_tolerance(report.stats.implicit);
        report::print(&outputs.recorders.summary, &report, wall, tolerance);
        if scenario.engine {
            report::engine(&outputs.recorders.summary);
        }
        report::ride(outputs.recorders.ride.as_ref(), scenario.output_every);
        if let Some(ride) = outputs.recorders.ride.as_ref() {
            let pitch = <V as Vehicle>::System::track_description().pitch().ok();
            extra_files.extend(report::seat_spectrum(
                ride,
                pitch,
                &hull_modes,
                outputs.dir(),
            )?);
        }
        let ground = scene::Ground {
            terrain: terrain.clone(),
            rut: system
                .rut()
                .map(|r| r.profile().collect())
                .unwrap_or_default(),
        };
        outputs.draw(&ground)?
    } else {
        outputs.data_files()
    };
    let written = [written, extra_files].concat();
    say!(
        "wrote {}/{{{}}} ({} rows)",
        outputs.dir().display(),
        written.join(", "),
        report.rows
    );
    match failure {
        None => Ok(()),
        Some((error, finish)) => {
            let kept = match (finish, report.last_time) {
                (Some(e), _) => format!("and the files could not be finished: {e}"),
                (None, Some(t)) => format!("rows up to t = {t} s written"),
                (None, None) => "no rows written".to_string(),
            };
            Err(format!("the run stopped early: {error} ({kept})").into())
        }
    }
}
