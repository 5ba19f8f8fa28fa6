//! The mobility engineer's standard events for a declared vehicle.
//!
//! ```text
//! cargo run --release --example mobility -- --vehicle m113 [--out FOLDER]
//!     [--events ride,half-round,step,gap,ditch,barrier,grade,soil] [--json] [--quick]
//!     [--slice K/N | --merge FILE…]
//! ```
//!
//! Runs the events of `trackgen::mobility` (each a limit found by
//! bracketing over runs, the vehicle driven through its engine) in parallel
//! on every core, and writes to `out/mobility/<vehicle>/` (or `--out`):
//! `<event>.csv` (one row per result: the parameter, the limit, its unit
//! and the runs it took), `trials.csv` (every run), `summary.svg` (the
//! curves of the events the set ran that have one: ride-limiting speed
//! against roughness, half-round speed against height, speed against
//! grade, drawbar pull against slip on each soil),
//! `<event>-limit.svg` (the vehicle at its
//! steepest on the largest step, gap, ditch and barrier it crossed) and
//! `report.html` (the tables, the curves and the pictures in one file). It prints a summary table; with `--json`, one
//! JSON object per result per line (`event`, `parameter`, `quantity`,
//! `value`, `relation` (`=`, `>` beyond the range, `<` before it,
//! `stalled`, `failed`), `unit`, `runs`, `failure`; SI units: roughness and heights in m,
//! speeds in m/s, grades as rise over run). `--quick`: one parameter per
//! event at loose search tolerances, a smoke test.
//!
//! A set too large for one machine splits into slices that run anywhere
//! (a cluster's array job), and a merge puts them back together:
//!
//! * `mobility --vehicle m113 --slice K/N --out DIR` runs the tasks `i`
//!   (an event at one parameter, in the order above) with `i mod N = K − 1`
//!   (interleaved, so each slice has fast and slow ones) and writes their
//!   results, trials included, to `DIR/slice-K-of-N.jsonl`;
//! * `mobility --vehicle m113 --merge DIR/slice-*.jsonl --out DIR` checks
//!   that the slices hold every task of that set exactly once (a missing
//!   or repeated task is an error naming it; give the merge the slices'
//!   `--events` and `--quick`) and writes what one machine would have:
//!   the CSVs, the curves, the report. The numbers are the same: every
//!   task is deterministic and independent.
//!
//! A run that fails is reported as a failure (the event, its parameter,
//! the time and the cause) and the other events still run; the command
//! then exits with status 1. A vehicle that stalls where a speed is
//! searched is reported as `stalled`, with where it stopped.

use std::fmt::Write as _;
use std::fs;
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::time::Instant;

use clap::{Parser, ValueEnum};
use indicatif::{ProgressBar, ProgressStyle};
use plotters::prelude::*;
use rayon::prelude::*;
use trackgen::contact::soil::SoilPreset;
use trackgen::mobility::search::{Limit, Search};
use trackgen::mobility::{
    EventError, EventSettings, Footprint, Published, grade, obstacle, quantity, ride, soil,
};
use trackgen::vehicle::{Powertrain, Vehicle};
use trackgen::vehicles::{m113, marder};

#[derive(Parser, Debug)]
#[command(about = "The standard pitch-plane mobility events for a declared vehicle")]
struct Args {
    /// The vehicle.
    #[arg(long, value_enum, default_value_t = Which::M113)]
    vehicle: Which,
    /// The events, comma-separated: ride, half-round, step, gap, ditch,
    /// barrier, grade, soil (default: all).
    #[arg(long, value_delimiter = ',', value_parser = event_name)]
    events: Option<Vec<&'static str>>,
    /// Where to write, default out/mobility/<vehicle>.
    #[arg(long)]
    out: Option<PathBuf>,
    /// One JSON object per result per line on stdout.
    #[arg(long)]
    json: bool,
    /// One parameter per event at loose tolerances: a smoke test.
    #[arg(long)]
    quick: bool,
    /// Run only slice K of N (1 ≤ K ≤ N): the tasks whose index i has
    /// i mod N = K − 1; writes `slice-K-of-N.jsonl` in `--out`.
    #[arg(long, value_name = "K/N", value_parser = parse_slice, requires = "out")]
    slice: Option<(usize, usize)>,
    /// Merge slices' `.jsonl` files (every task exactly once) into the
    /// set's outputs in `--out`.
    #[arg(long, value_name = "FILE", num_args = 1.., conflicts_with = "slice", requires = "out")]
    merge: Vec<PathBuf>,
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

#[derive(Clone, Copy, Debug, ValueEnum)]
enum Which {
    M113,
    Marder,
}

/// Every event, in the order they are reported.
const EVENTS: [&str; 8] = [
    "ride",
    "half-round",
    "step",
    "gap",
    "ditch",
    "barrier",
    "grade",
    "soil",
];

fn event_name(s: &str) -> Result<&'static str, String> {
    EVENTS
        .iter()
        .find(|e| **e == s)
        .copied()
        .ok_or_else(|| format!("unknown event `{s}`: the events are {}", EVENTS.join(", ")))
}

/// One answer: a limit, a quantity at a parameter, or why there is none.
#[derive(Debug, Clone)]
struct Row {
    event: &'static str,
    /// What was held fixed, with its unit (`roughness 0.0254 m`), or
    /// empty.
    parameter: Option<(&'static str, f64, &'static str)>,
    /// What was found and its unit.
    quantity: &'static str,
    value: f64,
    /// `=`, `>` (beyond the searched range), `<` (before it), or, without
    /// an answer, `stalled` or `failed`.
    relation: &'static str,
    unit: &'static str,
    runs: usize,
    wall: f64,
    search: Option<Search>,
    /// Why there is no answer.
    failure: Option<String>,
}

/// What a task found: a limit's search, or a curve: quantities at
/// parameters from `runs` runs.
enum Found {
    Limit(Search),
    Curve {
        points: Vec<Point>,
        runs: usize,
        /// The search behind the first point, if it is a limit.
        search: Option<Search>,
    },
}

/// A curve's point: what was held fixed, the quantity, its value, how the
/// value stands (`=`, or why there is none) and its unit.
type Point = (Parameter, &'static str, f64, &'static str, &'static str);

/// What was held fixed: its name, value and unit.
type Parameter = Option<(&'static str, f64, &'static str)>;

/// One piece of work: an event at one parameter, and what it reports.
struct Task<'a> {
    event: &'static str,
    parameter: Option<(&'static str, f64, &'static str)>,
    quantity: &'static str,
    unit: &'static str,
    run: Box<dyn Fn() -> Result<Found, EventError> + Send + Sync + 'a>,
}

impl Task<'_> {
    /// Runs it: its rows, with the wall time it took.
    fn rows(&self) -> Vec<Row> {
        let start = Instant::now();
        let found = (self.run)();
        let wall = start.elapsed().as_secs_f64();
        let row = |value, relation, runs, search, failure| Row {
            event: self.event,
            parameter: self.parameter,
            quantity: self.quantity,
            value,
            relation,
            unit: self.unit,
            runs,
            wall,
            search,
            failure,
        };
        match found {
            Ok(Found::Limit(s)) => vec![row(
                s.limit.value(),
                s.limit.relation(),
                s.runs(),
                Some(s),
                None,
            )],
            Ok(Found::Curve {
                points,
                runs,
                mut search,
            }) => points
                .into_iter()
                .enumerate()
                .map(|(k, (parameter, quantity, value, relation, unit))| Row {
                    parameter,
                    quantity,
                    unit,
                    // The runs and the time are the curve's, on its first row.
                    runs: if k == 0 { runs } else { 0 },
                    wall: if k == 0 { wall } else { 0.0 },
                    ..row(value, relation, 0, search.take(), None)
                })
                .collect(),
            Err(e) => {
                let relation = match e {
                    EventError::Stalled { .. } => "stalled",
                    _ => "failed",
                };
                vec![row(f64::NAN, relation, 0, None, Some(e.to_string()))]
            }
        }
    }
}

fn tasks<'a, V: Vehicle>(
    settings: &'a EventSettings,
    footprint: &'a Footprint,
    events: &[&'static str],
    quick: bool,
) -> Vec<Task<'a>> {
    const INCH: f64 = 0.0254;
    let pick = |all: &'static [f64], one: &'static [f64]| if quick { one } else { all };
    let roughnesses = pick(&[0.5, 1.0, 1.5, 2.0, 3.0, 4.0], &[1.0]);
    let heights = pick(&[4.0, 6.0, 8.0, 10.0, 12.0], &[8.0]);
    let grades = pick(&[0.1, 0.2, 0.3, 0.4, 0.5, 0.6], &[0.1]);
    let mut out: Vec<Task<'a>> = Vec::new();
    for &event in events {
        let task = |parameter, quantity, unit, run| Task {
            event,
            parameter,
            quantity,
            unit,
            run,
        };
        match event {
            "ride" => {
                for &r in roughnesses {
                    let roughness = ride::Roughness {
                        rms: r * INCH,
                        seed: 1,
                    };
                    out.push(task(
                        Some(("roughness", r * INCH, "m")),
                        "ride-limiting speed",
                        "m/s",
                        Box::new(move || {
                            ride::limiting_speed::<V>(settings, footprint, roughness)
                                .map(Found::Limit)
                        }),
                    ));
                }
            }
            "half-round" => {
                for &h in heights {
                    out.push(task(
                        Some(("height", h * INCH, "m")),
                        "speed at the peak limit",
                        "m/s",
                        Box::new(move || {
                            obstacle::half_round_speed::<V>(settings, footprint, h * INCH)
                                .map(Found::Limit)
                        }),
                    ));
                }
            }
            "step" | "gap" | "ditch" | "barrier" => {
                let (search, quantity): (fn(&EventSettings, &Footprint) -> _, _) = match event {
                    "step" => (obstacle::step::<V>, quantity::HIGHEST_STEP),
                    "gap" => (obstacle::gap::<V>, quantity::WIDEST_GAP),
                    "ditch" => (obstacle::ditch::<V>, quantity::DEEPEST_DITCH),
                    _ => (obstacle::barrier::<V>, quantity::HIGHEST_BARRIER),
                };
                out.push(task(
                    None,
                    quantity,
                    "m",
                    Box::new(move || search(settings, footprint).map(Found::Limit)),
                ));
            }
            // One task: the steepest grade first, then the speed on each
            // grade no steeper (a steady speed up a steeper one is 0: it
            // is not climbed even from a crawl at full load), so the runs
            // that would only stall are not made.
            "grade" => {
                out.push(task(
                    None,
                    quantity::TOP_SPEED,
                    "m/s",
                    Box::new(move || {
                        let run = grade::top_speed::<V>(settings, footprint)?;
                        Ok(Found::Curve {
                            points: vec![(None, quantity::TOP_SPEED, run.speed, "=", "m/s")],
                            runs: 1,
                            search: None,
                        })
                    }),
                ));
                out.push(task(
                    None,
                    quantity::STEEPEST_GRADE,
                    "rise over run",
                    Box::new(move || {
                        let steepest = grade::steepest::<V>(settings, footprint)?;
                        let climbed = match steepest.limit {
                            Limit::Found { passed, .. } => passed,
                            Limit::Beyond { end } => end,
                            Limit::Before { .. } => 0.0,
                        };
                        let mut runs = steepest.runs();
                        let mut points = vec![(
                            None,
                            quantity::STEEPEST_GRADE,
                            steepest.limit.value(),
                            steepest.limit.relation(),
                            "rise over run",
                        )];
                        for &g in grades {
                            let parameter = Some(("grade", g, "rise over run"));
                            if g > climbed {
                                points.push((
                                    parameter,
                                    "speed at full power",
                                    0.0,
                                    "stalls",
                                    "m/s",
                                ));
                                continue;
                            }
                            let climb = grade::speed_on::<V>(settings, footprint, g)?;
                            runs += 1;
                            points.push((
                                parameter,
                                "speed at full power",
                                climb.speed,
                                "=",
                                "m/s",
                            ));
                        }
                        Ok(Found::Curve {
                            points,
                            runs,
                            search: Some(steepest),
                        })
                    }),
                ));
            }
            "soil" => {
                let soils: &[SoilPreset] = if quick {
                    &[SoilPreset::DrySand]
                } else {
                    &[SoilPreset::DrySand, SoilPreset::Clay]
                };
                let fractions = pick(&[0.1, 0.2, 0.3, 0.4, 0.5], &[0.2]);
                for &preset in soils {
                    out.push(task(
                        None,
                        "drawbar curve",
                        "",
                        Box::new(move || {
                            let curve = soil::drawbar_curve::<V>(settings, preset, fractions)?;
                            let name = preset.name();
                            let mut points = vec![(
                                Some((name, 0.0, "drawbar pull / weight")),
                                "motion resistance / weight",
                                curve[0].resistance_coefficient(),
                                if curve[0].held { "=" } else { "not held" },
                                "",
                            )];
                            for p in &curve[1..] {
                                // A load the drive could not hold is no point
                                // of the soil's curve.
                                points.push((
                                    Some((name, p.pull / curve[0].weight, "drawbar pull / weight")),
                                    "slip",
                                    if p.held && p.slip < 1.0 {
                                        p.slip
                                    } else {
                                        f64::NAN
                                    },
                                    // A slip of 1 or more: the load drags the
                                    // vehicle back, beyond what the soil holds.
                                    match (p.held, p.slip < 1.0) {
                                        (false, _) => "not held",
                                        (true, false) => "dragged back",
                                        (true, true) => "=",
                                    },
                                    "",
                                ));
                            }
                            Ok(Found::Curve {
                                runs: curve.len(),
                                points,
                                search: None,
                            })
                        }),
                    ));
                }
            }
            _ => unreachable!("events are parsed from EVENTS"),
        }
    }
    out
}

fn main() -> ExitCode {
    let args = Args::parse();
    match args.vehicle {
        Which::M113 => run::<m113::M113>(&args, "m113", m113::powertrain(), &m113::PUBLISHED),
        Which::Marder => run::<marder::Marder>(&args, "marder", marder::powertrain(), &[]),
    }
}

fn run<V: Vehicle>(
    args: &Args,
    name: &str,
    powertrain: Powertrain,
    published: &[Published],
) -> ExitCode {
    let mut settings = EventSettings::new(powertrain);
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
    let events: Vec<&'static str> = args.events.clone().unwrap_or_else(|| EVENTS.to_vec());
    let work = tasks::<V>(&settings, &footprint, &events, args.quick);
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
    let chosen: Vec<usize> = (0..work.len())
        .filter(|i| args.slice.is_none_or(|(k, n)| i % n == k - 1))
        .collect();
    let started = Instant::now();
    let bar = ProgressBar::new(chosen.len() as u64);
    if let Ok(style) =
        ProgressStyle::with_template("{bar:40} {pos}/{len} results  {elapsed_precise}")
    {
        bar.set_style(style);
    }
    // Each task is deterministic and independent: the results do not
    // depend on the order rayon runs them in. The workers take them from
    // one queue in the set's order (`par_bridge`), the long ride searches
    // first, so that the short ones fill in beside them at the end
    // (longest first; measured on the M113's set, 61.5 s split in halves
    // by `par_iter`, 58.6 s so).
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
    args: &Args,
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

fn parameter_text(row: &Row) -> String {
    match row.parameter {
        Some((what, value, unit)) => format!("{what} {value:.4} {unit}"),
        None => String::new(),
    }
}

/// The value with its relation: `5.416`, `> 20.000`, `< 1.000`, `0.000
/// (stalls)`, or the word for no answer (`stalled`, `failed`, …).
fn value_text(r: &Row) -> String {
    match r.relation {
        "=" => format!("{:.3}", r.value),
        ">" | "<" => format!("{} {:.3}", r.relation, r.value),
        word if r.value.is_finite() => format!("{:.3} ({word})", r.value),
        word => word.to_string(),
    }
}

fn print_summary(name: &str, rows: &[Row], wall: f64) {
    let runs: usize = rows.iter().map(|r| r.runs).sum();
    eprintln!(
        "{name}: {} results from {runs} runs in {wall:.1} s of wall time",
        rows.len()
    );
    println!(
        "{:<11} {:<28} {:<26} {:>12}  {:<14} {:>5} {:>8}",
        "event", "parameter", "quantity", "value", "unit", "runs", "wall s"
    );
    for r in rows {
        println!(
            "{:<11} {:<28} {:<26} {:>12}  {:<14} {:>5} {:>8.1}",
            r.event,
            parameter_text(r),
            r.quantity,
            value_text(r),
            r.unit,
            r.runs,
            r.wall
        );
    }
}

/// A published figure beside the set's answer to it.
struct Against<'a> {
    figure: &'a Published,
    /// The answer as the table prints it, or `not run`.
    answer: String,
    /// The answer over the published value (NaN if none).
    ratio: f64,
    /// Agrees, misses (by how much; the guide's "Against the real
    /// vehicle" gives the cause measured), or not run.
    verdict: String,
}

/// Each published figure with the set's answer to it: the row of that
/// quantity with no parameter.
fn against<'a>(published: &'a [Published], rows: &[Row]) -> Vec<Against<'a>> {
    published
        .iter()
        .map(|figure| {
            let row = rows
                .iter()
                .find(|r| r.quantity == figure.quantity && r.parameter.is_none());
            let Some(r) = row else {
                return Against {
                    figure,
                    answer: "not run".into(),
                    ratio: f64::NAN,
                    verdict: "not run".into(),
                };
            };
            let c = figure.compare(r.value);
            let verdict = if c.agrees {
                format!(
                    "agrees within {:.0} %",
                    100.0 * trackgen::mobility::AGREEMENT
                )
            } else if c.ratio.is_finite() {
                format!(
                    "misses by {:+.0} % (the guide, Mobility events, \"Against the real \
                     vehicle\", gives the cause)",
                    100.0 * (c.ratio - 1.0)
                )
            } else {
                format!("no answer ({})", r.relation)
            };
            Against {
                figure,
                answer: value_text(r),
                ratio: c.ratio,
                verdict,
            }
        })
        .collect()
}

/// The published figures beside the answers, on standard output after
/// the table.
fn print_against(published: &[Published], rows: &[Row]) {
    let against = against(published, rows);
    if against.is_empty() {
        return;
    }
    println!("\nagainst the real vehicle:");
    for Against {
        figure,
        answer,
        ratio,
        verdict,
    } in against
    {
        println!(
            "{:<26} {:>12} against {:>8.3} {:<14} ratio {ratio:.2}: {verdict}\n{:<26} source: {}",
            figure.quantity, answer, figure.value, figure.unit, "", figure.source
        );
    }
}

fn json(row: &Row) -> String {
    let number = |v: f64| v.is_finite().then_some(v);
    serde_json::json!({
        "event": row.event,
        "parameter": row.parameter.map(|(name, value, unit)| {
            serde_json::json!({"name": name, "value": number(value), "unit": unit})
        }),
        "quantity": row.quantity,
        "value": number(row.value),
        "relation": row.relation,
        "unit": row.unit,
        "runs": row.runs,
        "failure": row.failure,
    })
    .to_string()
}

fn write_all(
    dir: &Path,
    name: &str,
    published: &[Published],
    rows: &[Row],
    wall: f64,
) -> Result<Vec<String>, Box<dyn std::error::Error>> {
    fs::create_dir_all(dir)?;
    let mut files = Vec::new();
    for event in EVENTS {
        let mine: Vec<&Row> = rows.iter().filter(|r| r.event == event).collect();
        if mine.is_empty() {
            continue;
        }
        let file = format!("{event}.csv");
        let mut w = csv::Writer::from_path(dir.join(&file))?;
        w.write_record([
            "parameter",
            "parameter_value",
            "parameter_unit",
            "quantity",
            "relation",
            "value",
            "unit",
            "runs",
            "wall_s",
            "failure",
        ])?;
        for r in mine {
            let (p, pv, pu) = r
                .parameter
                .map_or(("", String::new(), ""), |(a, b, c)| (a, b.to_string(), c));
            w.write_record([
                p,
                &pv,
                pu,
                r.quantity,
                r.relation,
                &r.value.to_string(),
                r.unit,
                &r.runs.to_string(),
                &format!("{:.3}", r.wall),
                r.failure.as_deref().unwrap_or(""),
            ])?;
        }
        w.flush()?;
        files.push(file);
    }
    let mut w = csv::Writer::from_path(dir.join("trials.csv"))?;
    w.write_record([
        "event",
        "fixed",
        "fixed_value",
        "trial",
        "parameter",
        "figure",
        "passed",
    ])?;
    for r in rows {
        let (p, pv) = r
            .parameter
            .map_or(("", String::new()), |(a, b, _)| (a, b.to_string()));
        for (k, t) in r.search.iter().flat_map(|s| s.trials.iter()).enumerate() {
            w.write_record([
                r.event,
                p,
                &pv,
                &k.to_string(),
                &t.parameter.to_string(),
                &t.figure.to_string(),
                &t.passed.to_string(),
            ])?;
        }
    }
    w.flush()?;
    files.push("trials.csv".into());
    // Only a set with an event that has a curve draws them.
    let svg = curves(rows)?;
    if let Some(svg) = &svg {
        fs::write(dir.join("summary.svg"), svg)?;
        files.push("summary.svg".into());
    }
    // The vehicle at each obstacle's limit: a picture per search that
    // drew one.
    for r in rows {
        if let Some(picture) = r.search.as_ref().and_then(|s| s.picture.as_ref()) {
            let file = format!("{}-limit.svg", r.event);
            fs::write(dir.join(&file), picture)?;
            files.push(file);
        }
    }
    fs::write(
        dir.join("report.html"),
        report(
            name,
            published,
            rows,
            wall,
            svg.as_deref().unwrap_or_default(),
        ),
    )?;
    files.push("report.html".into());
    Ok(files)
}

/// The curves of the events with a parameter: one panel each; `None`
/// for a set without any (obstacles alone).
fn curves(rows: &[Row]) -> Result<Option<String>, Box<dyn std::error::Error>> {
    let panels: [(&str, &str, &str, f64); 3] = [
        (
            "ride",
            "RMS roughness, in",
            "ride-limiting speed, m/s",
            1.0 / 0.0254,
        ),
        (
            "half-round",
            "half-round height, in",
            "speed at 2.5 g, m/s",
            1.0 / 0.0254,
        ),
        ("grade", "grade, %", "speed at full power, m/s", 100.0),
    ];
    // A panel per event of the set that has a curve, two to a row.
    let ran = |event: &str| rows.iter().any(|r| r.event == event);
    let panels: Vec<_> = panels.iter().filter(|p| ran(p.0)).collect();
    let soil = ran("soil");
    let count = panels.len() + usize::from(soil);
    if count == 0 {
        return Ok(None);
    }
    let (rows_of, columns) = (count.div_ceil(2), count.min(2));
    let mut svg = String::new();
    {
        let size = (600 * columns as u32, 380 * rows_of as u32);
        let root = SVGBackend::with_string(&mut svg, size).into_drawing_area();
        root.fill(&WHITE)?;
        let areas = root.split_evenly((rows_of, columns));
        if soil {
            drawbar_panel(rows, &areas[panels.len()])?;
        }
        for (&(event, x_label, y_label, scale), area) in panels.iter().zip(areas.iter()) {
            let points: Vec<(f64, f64, &str)> = rows
                .iter()
                .filter(|r| r.event == *event)
                .filter_map(|r| {
                    r.parameter
                        .map(|(_, p, _)| (p * scale, r.value, r.relation))
                })
                .filter(|(_, v, _)| v.is_finite())
                .collect();
            let x_max = points.iter().map(|p| p.0).fold(1e-9, f64::max) * 1.1;
            let y_max = points.iter().map(|p| p.1).fold(1e-9, f64::max) * 1.2;
            let mut chart = panel(area, event, (x_label, x_max), (y_label, y_max))?;
            chart.draw_series(LineSeries::new(points.iter().map(|p| (p.0, p.1)), &BLUE))?;
            // A limit beyond the search's range is drawn hollow.
            chart.draw_series(points.iter().map(|p| {
                let style = if p.2 == "=" {
                    BLUE.filled()
                } else {
                    BLUE.stroke_width(2)
                };
                Circle::new((p.0, p.1), 4, style)
            }))?;
        }
        root.present()?;
    }
    Ok(Some(svg))
}

/// One panel of the curves: `caption` over axes from 0 to `x_max` and
/// `y_max`, labelled, its mesh drawn.
fn panel<'a, DB: DrawingBackend>(
    area: &'a DrawingArea<DB, plotters::coord::Shift>,
    caption: &str,
    (x_label, x_max): (&str, f64),
    (y_label, y_max): (&str, f64),
) -> Result<
    ChartContext<
        'a,
        DB,
        Cartesian2d<plotters::coord::types::RangedCoordf64, plotters::coord::types::RangedCoordf64>,
    >,
    Box<dyn std::error::Error>,
>
where
    DB::ErrorType: 'static,
{
    let mut chart = ChartBuilder::on(area)
        .caption(caption, ("sans-serif", 18))
        .margin(12)
        .x_label_area_size(36)
        .y_label_area_size(48)
        .build_cartesian_2d(0.0..x_max, 0.0..y_max)?;
    chart
        .configure_mesh()
        .x_desc(x_label)
        .y_desc(y_label)
        .draw()?;
    Ok(chart)
}

/// The soil event's curves: drawbar pull over weight against slip, a line
/// per soil (from rest: no pull, no slip), the points the drive held with
/// a slip below 1.
fn drawbar_panel<DB: DrawingBackend>(
    rows: &[Row],
    area: &DrawingArea<DB, plotters::coord::Shift>,
) -> Result<(), Box<dyn std::error::Error>>
where
    DB::ErrorType: 'static,
{
    let mut soils: Vec<(&str, Vec<(f64, f64)>)> = Vec::new();
    for r in rows
        .iter()
        .filter(|r| r.event == "soil" && r.quantity == "slip")
    {
        let Some((soil, pull, _)) = r.parameter else {
            continue;
        };
        if !r.value.is_finite() {
            continue;
        }
        match soils.iter_mut().find(|(name, _)| *name == soil) {
            Some((_, points)) => points.push((r.value, pull)),
            None => soils.push((soil, vec![(0.0, 0.0), (r.value, pull)])),
        }
    }
    let x_max = soils
        .iter()
        .flat_map(|(_, p)| p.iter().map(|q| q.0))
        .fold(1e-3, f64::max)
        * 1.1;
    let y_max = soils
        .iter()
        .flat_map(|(_, p)| p.iter().map(|q| q.1))
        .fold(1e-3, f64::max)
        * 1.2;
    let mut chart = panel(
        area,
        "soil",
        ("slip", x_max),
        ("drawbar pull / weight", y_max),
    )?;
    const COLOURS: [RGBColor; 4] = [BLUE, RED, GREEN, MAGENTA];
    for ((soil, points), &colour) in soils.iter().zip(COLOURS.iter().cycle()) {
        chart
            .draw_series(LineSeries::new(points.iter().copied(), colour))?
            .label(*soil)
            .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 16, y)], colour));
        chart.draw_series(points.iter().map(|&p| Circle::new(p, 3, colour.filled())))?;
    }
    if !soils.is_empty() {
        chart
            .configure_series_labels()
            .background_style(WHITE)
            .border_style(BLACK)
            .position(SeriesLabelPosition::LowerRight)
            .draw()?;
    }
    Ok(())
}

fn report(name: &str, published: &[Published], rows: &[Row], wall: f64, svg: &str) -> String {
    let runs: usize = rows.iter().map(|r| r.runs).sum();
    let mut html = String::new();
    let _ = write!(
        html,
        "<!doctype html><html><head><meta charset=\"utf-8\"><title>{name}: mobility</title>\
         <style>body{{font-family:sans-serif;margin:2em}}td,th{{padding:2px 10px;text-align:left}}\
         td.n{{text-align:right}}tr:nth-child(even){{background:#f4f4f4}}</style></head><body>\
         <h1>{name}: pitch-plane mobility events</h1>\
         <p>{} results from {runs} runs in {wall:.1} s of wall time. A limit marked &gt; lies beyond \
         the searched range, &lt; before it; <i>stalled</i>: the vehicle did not get over (hover for where). Events, criteria and what the answers rest on: \
         the guide's Mobility chapter.</p>{svg}<table><tr><th>event</th><th>parameter</th>\
         <th>quantity</th><th>value</th><th>unit</th><th>runs</th><th>wall, s</th></tr>",
        rows.len()
    );
    for r in rows {
        let value = value_text(r).replace('>', "&gt;").replace('<', "&lt;");
        let title = r.failure.as_deref().unwrap_or("").replace('"', "&quot;");
        let _ = write!(
            html,
            "<tr title=\"{title}\"><td>{}</td><td>{}</td><td>{}</td><td class=\"n\">{value}</td><td>{}</td>\
             <td class=\"n\">{}</td><td class=\"n\">{:.1}</td></tr>",
            r.event,
            parameter_text(r),
            r.quantity,
            r.unit,
            r.runs,
            r.wall
        );
    }
    html.push_str("</table>");
    let against = against(published, rows);
    if !against.is_empty() {
        html.push_str(
            "<h2>Against the real vehicle</h2><table><tr><th>quantity</th><th>answer</th>\
             <th>published</th><th>unit</th><th>ratio</th><th>verdict</th><th>source</th></tr>",
        );
        for Against {
            figure,
            answer,
            ratio,
            verdict,
        } in against
        {
            let _ = write!(
                html,
                "<tr><td>{}</td><td class=\"n\">{}</td><td class=\"n\">{:.3}</td><td>{}</td>\
                 <td class=\"n\">{ratio:.2}</td><td>{verdict}</td><td>{}</td></tr>",
                figure.quantity,
                answer.replace('>', "&gt;").replace('<', "&lt;"),
                figure.value,
                figure.unit,
                figure.source
            );
        }
        html.push_str("</table>");
    }
    let pictures: Vec<(&Row, &String)> = rows
        .iter()
        .filter_map(|r| Some((r, r.search.as_ref()?.picture.as_ref()?)))
        .collect();
    if !pictures.is_empty() {
        html.push_str(
            "<h2>At the limits</h2><p>Each obstacle's largest crossed, the vehicle at its \
             steepest moment on it (the largest pitch of that run).</p>",
        );
        for (r, picture) in pictures {
            let _ = write!(
                html,
                "<figure><figcaption>{}: {} {}</figcaption>{picture}</figure>",
                r.quantity,
                value_text(r),
                r.unit
            );
        }
    }
    html.push_str("</body></html>\n");
    html
}

/// Slices of a set: each task's rows, trials included, one JSON object a
/// line; read back exactly (floats in their shortest round-trip form).
mod slices {
    use std::collections::BTreeMap;
    use std::fs;
    use std::path::{Path, PathBuf};

    use serde_json::{Value, json};
    use trackgen::mobility::search::{Limit, Search, Trial};

    use super::Row;

    fn number(v: f64) -> Value {
        serde_json::Number::from_f64(v).map_or(Value::Null, Value::Number)
    }

    fn row_json(r: &Row) -> Value {
        let search = r.search.as_ref().map(|s| {
            let limit = match s.limit {
                Limit::Found {
                    value,
                    passed,
                    failed,
                } => json!({"found": [number(value), number(passed), number(failed)]}),
                Limit::Beyond { end } => json!({"beyond": number(end)}),
                Limit::Before { start } => json!({"before": number(start)}),
            };
            let trials: Vec<Value> = s
                .trials
                .iter()
                .map(|t| json!([number(t.parameter), number(t.figure), t.passed]))
                .collect();
            json!({"limit": limit, "trials": trials, "picture": s.picture})
        });
        json!({
            "event": r.event,
            "parameter": r.parameter.map(|(n, v, u)| json!([n, number(v), u])),
            "quantity": r.quantity,
            "value": number(r.value),
            "relation": r.relation,
            "unit": r.unit,
            "runs": r.runs,
            "wall": number(r.wall),
            "search": search,
            "failure": r.failure,
        })
    }

    /// Writes a slice: a line per task, `{"task": i, "wall": s, "rows": […]}`.
    pub fn write(path: &Path, done: &[(usize, Vec<Row>)], wall: f64) -> std::io::Result<()> {
        if let Some(dir) = path.parent() {
            fs::create_dir_all(dir)?;
        }
        let mut text = String::new();
        for (i, rows) in done {
            let line = json!({
                "task": i,
                "slice_wall": number(wall),
                "rows": rows.iter().map(row_json).collect::<Vec<_>>(),
            });
            text.push_str(&line.to_string());
            text.push('\n');
        }
        fs::write(path, text)
    }

    /// The rows' strings live as long as the merge (a short command).
    fn text(v: &Value, what: &str) -> Result<&'static str, String> {
        v.as_str()
            .map(|s| &*Box::leak(s.to_string().into_boxed_str()))
            .ok_or_else(|| format!("`{what}` is not a string"))
    }

    fn float(v: &Value) -> f64 {
        v.as_f64().unwrap_or(f64::NAN)
    }

    fn row_of(v: &Value) -> Result<Row, String> {
        let search = match &v["search"] {
            Value::Null => None,
            s => {
                let limit = &s["limit"];
                let limit = if let Some(f) = limit.get("found") {
                    Limit::Found {
                        value: float(&f[0]),
                        passed: float(&f[1]),
                        failed: float(&f[2]),
                    }
                } else if let Some(end) = limit.get("beyond") {
                    Limit::Beyond { end: float(end) }
                } else if let Some(start) = limit.get("before") {
                    Limit::Before {
                        start: float(start),
                    }
                } else {
                    return Err("a search without its limit".into());
                };
                let trials = s["trials"]
                    .as_array()
                    .ok_or("a search without its trials")?
                    .iter()
                    .map(|t| Trial {
                        parameter: float(&t[0]),
                        figure: float(&t[1]),
                        passed: t[2].as_bool().unwrap_or(false),
                    })
                    .collect();
                let picture = s["picture"].as_str().map(str::to_owned);
                Some(Search {
                    limit,
                    trials,
                    picture,
                })
            }
        };
        let parameter = match &v["parameter"] {
            Value::Null => None,
            p => Some((
                text(&p[0], "parameter")?,
                float(&p[1]),
                text(&p[2], "unit")?,
            )),
        };
        Ok(Row {
            event: text(&v["event"], "event")?,
            parameter,
            quantity: text(&v["quantity"], "quantity")?,
            value: float(&v["value"]),
            relation: text(&v["relation"], "relation")?,
            unit: text(&v["unit"], "unit")?,
            runs: v["runs"].as_u64().unwrap_or(0) as usize,
            wall: float(&v["wall"]),
            search,
            failure: v["failure"].as_str().map(str::to_string),
        })
    }

    /// The set's rows in task order from its slices, and the longest
    /// slice's wall time; an error names the file and line, or the tasks
    /// missing or given twice.
    pub fn merge(files: &[PathBuf], tasks: usize) -> Result<(Vec<Row>, f64), String> {
        let mut found: BTreeMap<usize, (Vec<Row>, String)> = BTreeMap::new();
        let mut wall: f64 = 0.0;
        for file in files {
            let content =
                fs::read_to_string(file).map_err(|e| format!("{}: {e}", file.display()))?;
            for (n, line) in content.lines().enumerate() {
                let at = format!("{}:{}", file.display(), n + 1);
                let v: Value = serde_json::from_str(line).map_err(|e| format!("{at}: {e}"))?;
                let task = v["task"]
                    .as_u64()
                    .ok_or_else(|| format!("{at}: no task index"))?
                    as usize;
                if task >= tasks {
                    return Err(format!(
                        "{at}: task {task}, but this set has {tasks} (give the merge the slices' --events and --quick)"
                    ));
                }
                wall = wall.max(float(&v["slice_wall"]));
                let rows = v["rows"]
                    .as_array()
                    .ok_or_else(|| format!("{at}: no rows"))?
                    .iter()
                    .map(row_of)
                    .collect::<Result<Vec<_>, _>>()
                    .map_err(|e| format!("{at}: {e}"))?;
                if let Some((_, first)) = found.insert(task, (rows, at.clone())) {
                    return Err(format!("task {task} is in two slices: {first} and {at}"));
                }
            }
        }
        let missing: Vec<String> = (0..tasks)
            .filter(|i| !found.contains_key(i))
            .map(|i| i.to_string())
            .collect();
        if !missing.is_empty() {
            return Err(format!(
                "tasks missing from the slices: {} (of {tasks})",
                missing.join(", ")
            ));
        }
        Ok((
            found.into_values().flat_map(|(rows, _)| rows).collect(),
            wall,
        ))
    }
}
