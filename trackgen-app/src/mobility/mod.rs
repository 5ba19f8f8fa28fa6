//! The `mobility` subcommand: the mobility engineer's standard events for
//! the vehicle.
//!
//! ```text
//! <app> mobility [--vehicle NAME] [--out FOLDER]
//!     [--events ride,half-round,step,gap,ditch,barrier,grade,soil,side-slope,turning,cornering]
//!     [--json] [--quick] [--no-confirm]
//!     [--slice K/N | --merge FILE…]
//! ```
//!
//! Runs the events of `trackgen::mobility` (each a limit found by
//! bracketing over runs, the vehicle driven through its engine; the side
//! slope, the turns and the cornering in 3-D, for a vehicle declared with
//! both tracks) in parallel on every core, the costliest events first, and writes to `out/mobility/<vehicle>/` (or `--out`):
//! `<event>.csv` (one row per result: the parameter, the limit, its unit
//! and the runs it took), `trials.csv` (every run), `summary.svg` (the
//! curves of the events the set ran that have one: ride-limiting speed
//! against roughness, half-round speed against height, speed against
//! grade, drawbar pull against slip on each soil), `<event>-limit.svg`
//! (the vehicle at its steepest on the largest step, gap, ditch and
//! barrier it crossed) and `report.html` (the tables, the curves and the
//! pictures in one file). It prints a summary table and, where the
//! application was given the real vehicle's published figures, each beside
//! the answer; with `--json`, one JSON object per result per line
//! (`event`, `parameter`, `quantity`, `value`, `relation` (`=`, `>` beyond
//! the range, `<` before it, `stalled`, `failed`), `unit`, `runs`,
//! `confirmed_at`, `moved_from`, `failure`; SI units: roughness and heights in m, speeds in m/s, grades
//! as rise over run). `--quick`: one parameter per event at loose search
//! tolerances, a smoke test.
//!
//! A set too large for one machine splits into slices that run anywhere
//! (a cluster's array job), and a merge puts them back together:
//!
//! * `mobility --slice K/N --out DIR` runs the tasks `i` (an event at one
//!   parameter, in the order above) with `i mod N = K − 1` (interleaved,
//!   so each slice has fast and slow ones) and writes their results,
//!   trials included, to `DIR/slice-K-of-N.jsonl`;
//! * `mobility --merge DIR/slice-*.jsonl --out DIR` checks that the slices
//!   hold every task of that set exactly once (a missing or repeated task
//!   is an error naming it; give the merge the slices' `--events` and
//!   `--quick`) and writes what one machine would have: the CSVs, the
//!   curves, the report. The numbers are the same: every task is
//!   deterministic and independent.
//!
//! A run that fails is reported as a failure (the event, its parameter,
//! the time and the cause) and the other events still run; the command
//! then exits with status 1. A vehicle that stalls where a speed is
//! searched is reported as `stalled`, with where it stopped.

mod files;
mod slices;
mod tasks;
mod text;

use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::time::Instant;

use indicatif::{ProgressBar, ProgressStyle};
use rayon::prelude::*;
use trackgen::mobility::{EventSettings, Footprint, Published};
use trackgen::scenario::Method;
use trackgen::vehicle::Vehicle;

use crate::cli::{named, tolerance};
use crate::offered::Offered;
use files::write_all;
use tasks::{EVENTS, Row, SPATIAL, event_name, tasks};
use text::{json, print_against, print_summary};

/// The standard pitch-plane mobility events for the vehicle, each a limit
/// found over runs through its engine, with their CSVs, curves, pictures
/// and a report.
#[derive(clap::Args, Debug)]
pub struct MobilityArgs {
    /// The vehicle (the application's first by default).
    #[arg(long, value_name = "NAME")]
    pub vehicle: Option<String>,
    /// The events, comma-separated: ride, half-round, step, gap, ditch,
    /// barrier, grade, soil, side-slope, turning, cornering (default: all;
    /// the last three, in 3-D, for a vehicle declared with a `tracks`
    /// block).
    #[arg(long, value_delimiter = ',', value_parser = event_name)]
    pub events: Option<Vec<&'static str>>,
    /// Where to write, default out/mobility/<vehicle>.
    #[arg(long)]
    pub out: Option<PathBuf>,
    /// One JSON object per result per line on stdout.
    #[arg(long)]
    pub json: bool,
    /// One parameter per event at loose tolerances, unconfirmed: a smoke
    /// test.
    #[arg(long)]
    pub quick: bool,
    /// Answers at the integrator's tolerance alone: no search's final
    /// bracket run again at a tenth of it (the default confirms each
    /// answer so, and searches on at that tolerance where a verdict
    /// changes).
    #[arg(long)]
    pub no_confirm: bool,
    /// Every run's integrator, as `run --integrator` takes it: `auto`
    /// (the default), `bs23`, `dopri5` or `ros34pw2`. With `--tolerance`,
    /// how far an answer moves with the integration is measured.
    #[arg(long, default_value = "auto", value_name = "METHOD", value_parser = named(&Method::NAMED))]
    pub integrator: Method,
    /// Every run's integrator tolerance, relative and absolute, from
    /// 1e-12 to 0.1, as `run --tolerance` takes it (default: each
    /// method's own).
    #[arg(long, value_name = "TOL", value_parser = tolerance)]
    pub tolerance: Option<f64>,
    /// Run only slice K of N (1 ≤ K ≤ N): the tasks whose index i has
    /// i mod N = K − 1; writes `slice-K-of-N.jsonl` in `--out`.
    #[arg(long, value_name = "K/N", value_parser = parse_slice, requires = "out")]
    pub slice: Option<(usize, usize)>,
    /// Merge slices' `.jsonl` files (every task exactly once) into the
    /// set's outputs in `--out`.
    #[arg(long, value_name = "FILE", num_args = 1.., conflicts_with = "slice", requires = "out")]
    pub merge: Vec<PathBuf>,
}

/// `K/N`, slice K of N.
fn parse_slice(s: &str) -> Result<(usize, usize), String> {
    let usage = "a slice is K/N, slice K of N with 1 ≤ K ≤ N, like 2/8";
    let (k, n) = s.split_once('/').ok_or(usage)?;
    let (k, n): (usize, usize) = (
        k.trim().parse().map_err(|_| usage)?,
        n.trim().parse().map_err(|_| usage)?,
    );
    if k >= 1 && k <= n {
        Ok((k, n))
    } else {
        Err(format!("`{s}`: {usage}"))
    }
}

/// `mobility` for the vehicle `V`: exits 1 when a run failed (the other
/// events still answered) or the outputs could not be written.
pub fn main<V: Vehicle>(entry: &Offered, args: &MobilityArgs) -> ExitCode {
    match entry.engine() {
        Ok(powertrain) => run::<V>(args, entry, powertrain),
        Err(e) => {
            eprintln!("error: the mobility events drive through the engine: {e}");
            ExitCode::FAILURE
        }
    }
}

fn run<V: Vehicle>(
    args: &MobilityArgs,
    entry: &Offered,
    powertrain: trackgen::vehicle::Powertrain,
) -> ExitCode {
    let (name, published) = (entry.name(), entry.figures());
    let mut settings = EventSettings::new(powertrain);
    settings.scenario.method = args.integrator;
    settings.scenario.tolerance = args.tolerance;
    if args.no_confirm || args.quick {
        settings.confirm_factor = None;
    }
    if args.quick {
        settings.speed_tolerance = 1.0;
        settings.length_tolerance = 0.1;
        settings.grade_tolerance = 0.1;
        settings.ride_distance = 30.0;
    }
    let footprint = match Footprint::of::<V>("mobility") {
        Ok(f) => f,
        Err(e) => {
            eprintln!("error: {e}");
            return ExitCode::FAILURE;
        }
    };
    // The side slope and the turns are 3-D events: in the default set
    // where the vehicle has a spatial model, refused where one is asked
    // for and there is none.
    let events: Vec<&'static str> = args.events.clone().unwrap_or_else(|| {
        (EVENTS.iter().copied())
            .filter(|e| !SPATIAL.contains(e) || entry.spatial_events.is_some())
            .collect()
    });
    if let (Some(event), None) = (
        events.iter().find(|e| SPATIAL.contains(e)),
        entry.spatial_events,
    ) {
        eprintln!(
            "error: the {event} event runs the vehicle in 3-D: `{name}` is declared without a \
             `tracks` block"
        );
        return ExitCode::FAILURE;
    }
    let spatial = entry.spatial_events;
    let work = tasks::<V>(&settings, &footprint, &events, args.quick, spatial);
    let dir = args
        .out
        .clone()
        .unwrap_or_else(|| Path::new("out/mobility").join(name));
    if !args.merge.is_empty() {
        return match slices::merge(&args.merge, work.len()) {
            Ok((rows, wall)) => finish(args, name, published, &dir, &rows, wall),
            Err(e) => {
                eprintln!("error: {e}");
                ExitCode::FAILURE
            }
        };
    }
    let mut chosen: Vec<usize> = (0..work.len())
        .filter(|i| args.slice.is_none_or(|(k, n)| i % n == k - 1))
        .collect();
    // The costliest events first (`tasks::QUEUE`); an event's own tasks
    // in the set's order (the sort is stable).
    chosen.sort_by_key(|&i| tasks::queue_rank(work[i].event()));
    let started = Instant::now();
    let bar = ProgressBar::new(chosen.len() as u64);
    if let Ok(style) =
        ProgressStyle::with_template("{bar:40} {pos}/{len} results  {elapsed_precise}")
    {
        bar.set_style(style);
    }
    // Each task is deterministic and independent: the results do not
    // depend on the order rayon runs them in. The workers take them from
    // one queue (`par_bridge`), the longest first, so that the short ones
    // fill in beside them at the end (measured on the M113's set, 61.5 s
    // split in halves by `par_iter`, 58.6 s so).
    let mut done: Vec<(usize, Vec<Row>)> = chosen
        .iter()
        .par_bridge()
        .map(|&i| {
            let rows = work[i].rows();
            bar.inc(1);
            (i, rows)
        })
        .collect();
    done.sort_by_key(|(i, _)| *i);
    bar.finish_and_clear();
    let wall = started.elapsed().as_secs_f64();
    if let Some((k, n)) = args.slice {
        let path = dir.join(format!("slice-{k}-of-{n}.jsonl"));
        return match slices::write(&path, &done, wall) {
            Ok(()) => {
                let rows: Vec<Row> = done.into_iter().flat_map(|(_, r)| r).collect();
                print_summary(name, &rows, wall);
                eprintln!(
                    "wrote {} (slice {k} of {n}: {} of {} tasks)",
                    path.display(),
                    chosen.len(),
                    work.len()
                );
                if rows.iter().any(|r| r.relation == "failed") {
                    ExitCode::FAILURE
                } else {
                    ExitCode::SUCCESS
                }
            }
            Err(e) => {
                eprintln!("error: writing {}: {e}", path.display());
                ExitCode::FAILURE
            }
        };
    }
    let rows: Vec<Row> = done.into_iter().flat_map(|(_, r)| r).collect();
    finish(args, name, published, &dir, &rows, wall)
}

/// The set's outputs, summary and exit status from its rows.
fn finish(
    args: &MobilityArgs,
    name: &str,
    published: &[Published],
    dir: &Path,
    rows: &[Row],
    wall: f64,
) -> ExitCode {
    let rows = rows.to_vec();
    let written = write_all(dir, name, published, &rows, wall);
    print_summary(name, &rows, wall);
    print_against(published, &rows);
    if args.json {
        for row in &rows {
            println!("{}", json(row));
        }
    }
    for row in &rows {
        if let Some(why) = &row.failure {
            eprintln!("{}: {why}", row.relation);
        }
    }
    // A stall is an answer about the vehicle; a failed run is not.
    let failed = rows.iter().any(|r| r.relation == "failed");
    match written {
        Ok(files) => eprintln!("wrote {}/{{{}}}", dir.display(), files.join(", ")),
        Err(e) => {
            eprintln!("error: writing {}: {e}", dir.display());
            return ExitCode::FAILURE;
        }
    }
    if failed {
        ExitCode::FAILURE
    } else {
        ExitCode::SUCCESS
    }
}
