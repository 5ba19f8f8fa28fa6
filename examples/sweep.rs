//! A design sweep: the default vehicle over a grid of target speeds and
//! bump heights, every run independent, in parallel on all cores (rayon).
//!
//! `cargo run --release --example sweep` (set `RAYON_NUM_THREADS` to
//! choose the cores). Beyond one machine: the runs share nothing, so run
//! one process per variant (or per slice of the grid) on each machine and
//! gather the printed rows or CSVs; no communication is needed.

use std::time::Instant;

use rayon::prelude::*;
use trackgen::contact::Terrain;
use trackgen::integrate::Integrator;
use trackgen::simulate::{Output, simulate};
use trackgen::vehicles::m113;

/// One variant's outcome.
struct Row {
    speed: f64,
    bump: f64,
    max_pitch: f64,
    max_ground: f64,
    wall: f64,
}

fn run(speed: f64, bump: f64) -> Result<Row, String> {
    let terrain = Terrain::Bump {
        centre: 8.0,
        width: 1.0,
        height: bump,
    };
    let drive = m113::speed_drive(move |t: f64| speed * ((t - 0.5) / 1.5).clamp(0.0, 1.0));
    let mut system = m113::system(terrain, drive).map_err(|e| e.to_string())?;
    let started = Instant::now();
    let duration = 2.0 + 12.0 / speed;
    let results = simulate(
        &mut system,
        Integrator::Bs23 {
            rtol: 1e-3,
            atol: 1e-3,
            max_step: 0.01,
        },
        0.0,
        duration,
        Output::Every(0.01),
    )
    .map_err(|f| f.to_string())?;
    // After the first second: the settling drop is the same for all.
    let max_abs = |c: &str| {
        let v = results.column(c).unwrap();
        results
            .times()
            .iter()
            .zip(v)
            .filter(|(t, _)| **t > 1.0)
            .fold(0.0, |m: f64, (_, v)| m.max(v.abs()))
    };
    Ok(Row {
        speed,
        bump,
        max_pitch: max_abs("pitch").to_degrees(),
        max_ground: max_abs("ground_normal"),
        wall: started.elapsed().as_secs_f64(),
    })
}

fn main() {
    let grid: Vec<(f64, f64)> = [2.0, 4.0]
        .iter()
        .flat_map(|&s| [0.05, 0.1, 0.15].map(move |b| (s, b)))
        .collect();
    let threads = rayon::current_num_threads();
    println!("{} runs on {threads} thread(s)", grid.len());
    let started = Instant::now();
    let rows: Vec<Result<Row, String>> = grid.par_iter().map(|&(s, b)| run(s, b)).collect();
    let wall = started.elapsed().as_secs_f64();
    println!(
        "{:>8} {:>8} {:>14} {:>16} {:>9}",
        "speed", "bump", "max pitch", "max ground force", "run wall"
    );
    for row in &rows {
        match row {
            Ok(r) => println!(
                "{:>6.1} m/s {:>5.2} m {:>12.2}° {:>14.0} N {:>7.2} s",
                r.speed, r.bump, r.max_pitch, r.max_ground, r.wall
            ),
            Err(e) => println!("failed: {e}"),
        }
    }
    let serial: f64 = rows
        .iter()
        .filter_map(|r| r.as_ref().ok())
        .map(|r| r.wall)
        .sum();
    println!(
        "sweep wall {wall:.2} s; sum of run walls {serial:.2} s; speed-up {:.2} on {threads} thread(s)",
        serial / wall
    );
}
