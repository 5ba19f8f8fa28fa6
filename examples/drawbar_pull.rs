//! Drawbar pull against slip on soft soil: the M113 (one side) pulling a
//! set of drawbar loads at a track speed of 1.5 m/s, each run in parallel
//! (rayon), beside Wong's curve for a track under uniform pressure.
//!
//! ```text
//! cargo run --release --example drawbar_pull -- [--soil dry-sand] [--out out/drawbar] [--quick]
//! ```
//!
//! For each load `F` (N, pulling the chassis back at its centroid) the
//! vehicle starts at rest, its track speed ramped to 1.5 m/s over the
//! first second, and runs 10 s; over the last 4 s the mean forward speed
//! `v` and the track's mean speed `v_t = N p ω / (2π)` (one pitch per
//! tooth: the recorded `track_speed`) give the true slip
//! `i = 1 − v / v_t` (`trackgen::vehicle::slip`). In steady motion the
//! drawbar pull equals `F`.
//!
//! Wong's drawbar pull for the same vehicle is the tractive effort of a
//! track under uniform pressure less the compaction resistance,
//! `F(i) − R_c` (spec "Closed-form checks"): weight `W` from the ground
//! force at rest, width 0.381 m, contact length from the shoes bearing at
//! rest (`Soil::tractive_effort`, `Soil::compaction_resistance`).
//!
//! Writes `drawbar_pull.csv` (`drawbar_pull_n,slip,speed,track_speed,
//! wong_n`) and `drawbar_pull.svg` (the points over Wong's curve), and
//! prints the table. `--quick`: two loads, 3 s each, for a smoke test.

use std::error::Error;
use std::path::PathBuf;

use clap::Parser;
use plotters::prelude::*;
use rayon::prelude::*;
use trackgen::integrate::Integrator;
use trackgen::simulate::{Output, Results, simulate};
use trackgen::terrain::{Terrain, soil::SoilPreset};
use trackgen::vehicle::{Drive, Vehicle, slip};
use trackgen::vehicles::{m113, m113::M113};

/// Drawbar pull against slip on soft soil, beside Wong's curve.
#[derive(Parser, Debug)]
#[command(about)]
struct Args {
    /// Soil preset.
    #[arg(long, default_value = "dry-sand", value_parser = soil)]
    soil: SoilPreset,
    /// Output folder (created if missing).
    #[arg(long, default_value = "out/drawbar")]
    out: PathBuf,
    /// Two loads, 3 s each (a smoke test).
    #[arg(long)]
    quick: bool,
}

fn soil(s: &str) -> Result<SoilPreset, String> {
    s.parse()
        .map_err(|e: trackgen::terrain::soil::SoilError| e.to_string())
}

/// Track speed, m/s.
const TRACK_SPEED: f64 = 1.5;

/// How long each load is held, s, and the steady end over which the
/// speeds are averaged, s. The track reaches its speed at 1 s; the hull's
/// sinkage and the soil under the shoes take seconds more to settle: a
/// 6 s hold averaged over its last 2 s still carried that transient
/// (slips 0.027 at 0.7 of the Coulomb limit and 0.025 at 0.8), 10 s over
/// the last 4 s gives the same slips as 12 s over the last 6 s to 0.001
/// at every load below the Coulomb limit (past it the track digs in).
const HOLD: f64 = 10.0;
const STEADY: f64 = 4.0;

fn run(preset: SoilPreset, drive: Drive, pull: f64, duration: f64) -> Result<Results, String> {
    let mut config = M113::declared_config(Terrain::Flat { height: 0.0 }, drive);
    config.soil = Some(preset.soil());
    config.drawbar_pull = pull;
    let mut system = M113::system_with(config).map_err(|e| e.to_string())?;
    let integrator = Integrator::Bs23 {
        rtol: 1e-4,
        atol: 1e-4,
        max_step: 0.01,
    };
    simulate(&mut system, integrator, 0.0, duration, Output::Every(0.01))
        .map_err(|f| f.error.to_string())
}

/// Mean of `column` over the last `span` s.
fn tail_mean(results: &Results, column: &str, span: f64) -> f64 {
    let t = results.times();
    let end = *t.last().unwrap_or(&0.0);
    let values = results.column(column).unwrap_or_default();
    let kept: Vec<f64> = t
        .iter()
        .zip(values)
        .filter(|(t, _)| **t >= end - span)
        .map(|(_, v)| v)
        .collect();
    kept.iter().sum::<f64>() / kept.len() as f64
}

fn main() -> Result<(), Box<dyn Error>> {
    let args = Args::parse();
    let soil = args.soil.soil();
    // The vehicle at rest: its weight on the soil and its contact length.
    let rest = run(args.soil, M113::speed_drive(|_| 0.0), 0.0, 3.0)?;
    let weight = tail_mean(&rest, "ground_normal", 0.5);
    let length = contact_length(&rest);
    let compaction = soil.compaction_resistance(weight, m113::TRACK_WIDTH, length);
    let limit = m113::TRACK_WIDTH * length * soil.cohesion + weight * soil.tan_phi();
    let (loads, duration): (Vec<f64>, f64) = if args.quick {
        (vec![0.2 * limit, 0.6 * limit], 3.0)
    } else {
        (
            [0.1, 0.25, 0.4, 0.55, 0.7, 0.8, 0.88, 0.94]
                .map(|f| f * limit)
                .to_vec(),
            HOLD,
        )
    };
    println!(
        "M113 on {} soil: W = {weight:.0} N on {length:.2} m of track {:.3} m wide; Coulomb limit {limit:.0} N, compaction resistance {compaction:.0} N",
        args.soil,
        m113::TRACK_WIDTH
    );
    let rows: Vec<Result<(f64, f64, f64, f64), String>> = loads
        .par_iter()
        .map(|&pull| {
            let drive = M113::speed_drive(|t| TRACK_SPEED * t.clamp(0.0, 1.0));
            let results = run(args.soil, drive, pull, duration)?;
            let speed = tail_mean(&results, "speed", STEADY);
            let track_speed = tail_mean(&results, "track_speed", STEADY);
            Ok((pull, slip(speed, track_speed), speed, track_speed))
        })
        .collect();
    std::fs::create_dir_all(&args.out)?;
    let mut csv = String::from("drawbar_pull_n,slip,speed,track_speed,wong_n\n");
    let mut points = Vec::new();
    println!(
        "{:>12} {:>8} {:>10} {:>12} {:>10}",
        "pull (N)", "slip", "v (m/s)", "Wong (N)", "error"
    );
    for row in rows {
        let (pull, slip, speed, track_speed) = row?;
        let wong = soil.tractive_effort(weight, m113::TRACK_WIDTH, length, slip) - compaction;
        println!(
            "{pull:12.0} {slip:8.3} {speed:10.3} {wong:12.0} {:9.1} %",
            100.0 * (pull - wong) / wong
        );
        csv += &format!("{pull},{slip},{speed},{track_speed},{wong}\n");
        points.push((slip, pull));
    }
    std::fs::write(args.out.join("drawbar_pull.csv"), csv)?;
    plot(
        &args.out.join("drawbar_pull.svg"),
        &points,
        |i| soil.tractive_effort(weight, m113::TRACK_WIDTH, length, i) - compaction,
        args.soil,
    )?;
    println!(
        "wrote {}/{{drawbar_pull.csv, drawbar_pull.svg}}",
        args.out.display()
    );
    Ok(())
}

/// The length of track bearing on the soil at the last sample: the shoes'
/// ground points below the undisturbed surface, each carrying half a
/// pitch.
fn contact_length(results: &Results) -> f64 {
    use trackgen::multibody::RecursiveModel;
    use trackgen::nalgebra::{SVector, Vector2};
    let columns = results.columns();
    let start = columns.iter().position(|c| c == "track.x").expect("track");
    let last = results.sample(results.len() - 1);
    let q = SVector::<f64, { M113::TRACK_DOF }>::from_column_slice(
        &last.values[start..start + M113::TRACK_DOF],
    );
    let mut centres = vec![Vector2::zeros(); 64];
    m113::M113Track.body_positions(&q, &mut centres);
    let shoe = M113::geometry().shoe;
    let bearing = centres
        .iter()
        .enumerate()
        .flat_map(|(j, c)| {
            shoe.ground_points
                .iter()
                .map(move |g| c + trackgen::planar::rotate(q[2 + j], *g))
        })
        .filter(|p| p.y < 0.0)
        .count();
    bearing as f64 * m113::SHOE_PITCH / 2.0
}

fn plot(
    path: &std::path::Path,
    points: &[(f64, f64)],
    wong: impl Fn(f64) -> f64,
    preset: SoilPreset,
) -> Result<(), Box<dyn Error>> {
    let root = SVGBackend::new(path, (800, 520)).into_drawing_area();
    root.fill(&WHITE)?;
    let top = points
        .iter()
        .map(|p| p.1)
        .chain((1..=100).map(|k| wong(k as f64 / 100.0)))
        .fold(0.0, f64::max)
        * 1.1
        / 1e3;
    let mut chart = ChartBuilder::on(&root)
        .caption(
            format!("M113 drawbar pull on {preset} soil"),
            ("sans-serif", 20),
        )
        .margin(12)
        .x_label_area_size(40)
        .y_label_area_size(60)
        .build_cartesian_2d(0.0..1.0, 0.0..top)?;
    chart
        .configure_mesh()
        .x_desc("slip")
        .y_desc("drawbar pull (kN)")
        .draw()?;
    chart
        .draw_series(LineSeries::new(
            (1..=100).map(|k| {
                let i = k as f64 / 100.0;
                (i, wong(i) / 1e3)
            }),
            BLUE.stroke_width(2),
        ))?
        .label("Wong: uniform pressure, F(i) − R_c")
        .legend(|(x, y)| PathElement::new(vec![(x, y), (x + 18, y)], BLUE));
    chart
        .draw_series(
            points
                .iter()
                .map(|&(i, f)| Circle::new((i, f / 1e3), 5, RED.filled())),
        )?
        .label("simulated (trackgen)")
        .legend(|(x, y)| Circle::new((x + 9, y), 5, RED.filled()));
    chart
        .configure_series_labels()
        .position(SeriesLabelPosition::LowerRight)
        .background_style(WHITE.mix(0.9))
        .border_style(BLACK)
        .draw()?;
    root.present()?;
    Ok(())
}
