//! A parked vehicle on a grade: driven onto a ramp, stopped, its sprocket
//! held by the speed controller (target 0), then watched.
//!
//! ```text
//! cargo run --release --example grade_hold -- [--vehicle m113|marder] [--quick] [--out DIR]
//! ```
//!
//! For grades of 10, 30 and 60 % it prints how far the hull moves along
//! the slope over the 10 s after it has settled, with the ground's
//! friction as declared (stiction) and as regularised Coulomb friction
//! (`μ` over 0.1 m/s, what the ground had before), and writes
//! `grade_hold.csv` and `grade_hold.svg`: the hull's position along the
//! slope from the moment it stops. `--quick`: the 30 % grade only, a
//! shorter watch, for a smoke test. (A grade beyond `μ` cannot be
//! climbed to park on; `tests/grade_hold.rs` restarts the parked vehicle
//! on ice instead, and it slides.)

use std::error::Error;
use std::path::PathBuf;

use plotters::prelude::*;
use trackgen::contact::GroundFriction;
use trackgen::integrate::Integrator;
use trackgen::laws::Friction;
use trackgen::simulate::{Output, Results, simulate};
use trackgen::terrain::Terrain;
use trackgen::vehicle::{Vehicle, VehicleDynamics};
use trackgen::vehicles::{m113::M113, marder::Marder};

/// Where the ramp starts, m of x ahead of the chassis centroid's start.
const RAMP_START: f64 = 3.0;
/// The climbing speed, m/s.
const CLIMB: f64 = 1.0;
/// How long the speed controller is given to catch the hull after the
/// stop before the watch begins, s.
const SETTLE: f64 = 4.0;

/// One run: the hull's distance along the slope (m) against the time since
/// the stop (s), and the energy books' residual.
struct Parked {
    grade: f64,
    friction: &'static str,
    /// (t − t_stop, s − s_stop) samples.
    path: Vec<(f64, f64)>,
    /// The hull's travel along the slope over the watch, m.
    moved: f64,
    books: f64,
}

/// When to stop: once the rearmost wheel is past the ramp's start.
fn stop_time<V: Vehicle>() -> f64 {
    let parts = V::System::parts();
    let chassis = V::System::chassis_description();
    let mut centres = vec![trackgen::nalgebra::Vector2::zeros(); chassis.len()];
    V::System::chassis_positions(&vec![0.0; V::System::chassis_dof()], &mut centres);
    let rear = parts
        .iter()
        .map(|p| centres[p.body].x - p.radius)
        .fold(f64::INFINITY, f64::min);
    // Up the slope at CLIMB along it (about as fast along x), with a margin.
    1.5 + (RAMP_START - rear + 1.0) / CLIMB
}

fn park<V: Vehicle>(grade: f64, regularised: bool, watch: f64) -> Result<Parked, Box<dyn Error>> {
    let stop = stop_time::<V>();
    let target = move |t: f64| {
        let up = ((t - 0.5) / 1.0).clamp(0.0, 1.0);
        let down = ((stop + 1.0 - t) / 1.0).clamp(0.0, 1.0);
        CLIMB * up.min(down)
    };
    let terrain = Terrain::Ramp {
        height: 0.0,
        start: RAMP_START,
        slope: grade,
    };
    let mut config = V::declared_config(terrain, V::speed_drive(target));
    if regularised {
        let mu = config.ground.friction.mu();
        config.ground.friction = GroundFriction::Regularised(Friction { mu, slip: 0.1 });
    }
    let mut vehicle = V::system_with(config)?;
    let end = stop + 1.0 + SETTLE + watch;
    let integrator = Integrator::Bs23 {
        rtol: 1e-4,
        atol: 1e-4,
        max_step: 0.01,
    };
    let results = simulate(&mut vehicle, integrator, 0.0, end, Output::Every(0.02))
        .map_err(|f| f.error.to_string())?;
    let along = along_slope(&results, grade);
    let t0 = stop + 1.0;
    let at = |t: f64| {
        let i = results
            .times()
            .partition_point(|&s| s < t)
            .min(along.len() - 1);
        along[i]
    };
    let s0 = at(t0);
    let path = results
        .times()
        .iter()
        .zip(&along)
        .filter(|(t, _)| **t >= t0)
        .map(|(t, s)| (t - t0, s - s0))
        .collect();
    Ok(Parked {
        grade,
        friction: if regularised {
            "regularised"
        } else {
            "stiction"
        },
        path,
        moved: at(end) - at(t0 + SETTLE),
        books: results.energy_balance().map_or(f64::NAN, |b| b.residual()),
    })
}

/// The hull's centroid along the slope of `grade`, m, at every sample.
fn along_slope(results: &Results, grade: f64) -> Vec<f64> {
    let norm = (1.0 + grade * grade).sqrt();
    let (x, y) = (
        results.column("x").unwrap_or_default(),
        results.column("y").unwrap_or_default(),
    );
    x.iter()
        .zip(&y)
        .map(|(x, y)| (x + grade * y) / norm)
        .collect()
}

/// Two panels: every run's hull along the slope from the stop (the
/// controller catching it, then holding or not), and the stiction runs'
/// from the start of the watch, in micrometres, against the ±1 mm band.
fn plot(runs: &[Parked], path: &std::path::Path, title: &str) -> Result<(), Box<dyn Error>> {
    let root = SVGBackend::new(path, (900, 760)).into_drawing_area();
    root.fill(&WHITE)?;
    let root = root.titled(title, ("sans-serif", 20))?;
    let (top, bottom) = root.split_vertically(400);
    let t_end = runs
        .iter()
        .flat_map(|r| r.path.last().map(|p| p.0))
        .fold(1.0, f64::max);
    let lo = runs
        .iter()
        .flat_map(|r| r.path.iter().map(|p| p.1 * 1e3))
        .fold(-1.0, f64::min);
    let grades: Vec<f64> = runs.iter().fold(Vec::new(), |mut g, r| {
        if !g.contains(&r.grade) {
            g.push(r.grade);
        }
        g
    });
    let color = |run: &Parked| {
        const COLORS: [RGBColor; 3] = [
            RGBColor(200, 40, 40),
            RGBColor(30, 90, 200),
            RGBColor(20, 140, 60),
        ];
        let k = grades.iter().position(|g| *g == run.grade).unwrap_or(0);
        COLORS[k % COLORS.len()].to_rgba()
    };
    let mut chart = ChartBuilder::on(&top)
        .caption("from the stop: all runs", ("sans-serif", 15))
        .margin(12)
        .x_label_area_size(36)
        .y_label_area_size(70)
        .build_cartesian_2d(0.0..t_end, (lo * 1.05)..(0.05 * -lo))?;
    chart
        .configure_mesh()
        .x_desc("time since the stop (s)")
        .y_desc("hull along the slope (mm)")
        .draw()?;
    for run in runs {
        let c = color(run);
        let label = format!("{:.0} % grade, {}", 100.0 * run.grade, run.friction);
        let points = run.path.iter().map(|&(t, s)| (t, s * 1e3));
        if run.friction == "stiction" {
            chart
                .draw_series(LineSeries::new(points, c.stroke_width(2)))?
                .label(label)
                .legend(move |(x, y)| {
                    PathElement::new(vec![(x, y), (x + 20, y)], c.stroke_width(2))
                });
        } else {
            chart
                .draw_series(DashedLineSeries::new(points, 6, 4, c.stroke_width(1)))?
                .label(label)
                .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], c));
        }
    }
    chart
        .configure_series_labels()
        .position(SeriesLabelPosition::LowerLeft)
        .background_style(WHITE.mix(0.8))
        .border_style(BLACK)
        .draw()?;
    let mut held = ChartBuilder::on(&bottom)
        .caption(
            format!("stiction, from {SETTLE} s after the stop (the watch); dotted: ±1 mm"),
            ("sans-serif", 15),
        )
        .margin(12)
        .x_label_area_size(36)
        .y_label_area_size(70)
        .build_cartesian_2d(SETTLE..t_end, -1100.0..1100.0)?;
    held.configure_mesh()
        .x_desc("time since the stop (s)")
        .y_desc("hull along the slope (µm)")
        .draw()?;
    for bound in [-1000.0, 1000.0] {
        held.draw_series(DashedLineSeries::new(
            [(SETTLE, bound), (t_end, bound)],
            2,
            4,
            BLACK.stroke_width(1),
        ))?;
    }
    for run in runs.iter().filter(|r| r.friction == "stiction") {
        let c = color(run);
        let start = run.path.iter().find(|p| p.0 >= SETTLE).map_or(0.0, |p| p.1);
        held.draw_series(LineSeries::new(
            run.path
                .iter()
                .filter(|p| p.0 >= SETTLE)
                .map(|&(t, s)| (t, (s - start) * 1e6)),
            c.stroke_width(2),
        ))?;
    }
    root.present()?;
    Ok(())
}

fn study<V: Vehicle>(quick: bool, out: PathBuf) -> Result<(), Box<dyn Error>> {
    let (grades, watch): (&[f64], f64) = if quick {
        (&[0.3], 2.0)
    } else {
        (&[0.1, 0.3, 0.6], 10.0)
    };
    let mut runs = Vec::new();
    println!(
        "{} parked with its sprocket held: hull travel along the slope over {watch} s after settling",
        V::NAME
    );
    for &grade in grades {
        for regularised in [false, true] {
            let run = park::<V>(grade, regularised, watch)?;
            println!(
                "  {:>4.0} % grade, {:<11}: {:+9.3} mm  (books {:.1e})",
                100.0 * grade,
                run.friction,
                run.moved * 1e3,
                run.books
            );
            runs.push(run);
        }
    }
    std::fs::create_dir_all(&out)?;
    let mut csv = csv::Writer::from_path(out.join("grade_hold.csv"))?;
    csv.write_record(["grade", "friction", "t", "along_slope"])?;
    for run in &runs {
        for (t, s) in &run.path {
            csv.write_record([
                run.grade.to_string(),
                run.friction.to_string(),
                t.to_string(),
                s.to_string(),
            ])?;
        }
    }
    csv.flush()?;
    let title = format!("{} parked on a grade, sprocket held", V::NAME);
    plot(&runs, &out.join("grade_hold.svg"), &title)?;
    println!("wrote {}/{{grade_hold.csv, grade_hold.svg}}", out.display());
    Ok(())
}

fn main() -> Result<(), Box<dyn Error>> {
    let (mut quick, mut marder, mut out) = (false, false, None);
    let mut args = std::env::args().skip(1);
    while let Some(arg) = args.next() {
        match arg.as_str() {
            "--quick" => quick = true,
            "--vehicle" => match args.next().as_deref() {
                Some("marder") => marder = true,
                Some("m113") => {}
                other => return Err(format!("--vehicle m113|marder, got {other:?}").into()),
            },
            "--out" => out = args.next().map(PathBuf::from),
            _ => {
                return Err(format!(
                    "unknown argument {arg:?} (--quick, --vehicle m113|marder, --out DIR)"
                )
                .into());
            }
        }
    }
    let out = out.unwrap_or_else(|| PathBuf::from("out/grade_hold"));
    if marder {
        study::<Marder>(quick, out)
    } else {
        study::<M113>(quick, out)
    }
}
