//! A design sweep: the default vehicle over a grid of target speeds and
//! bump heights, every run independent, in parallel on all cores (rayon).
//!
//! `cargo run --release --example sweep` runs the whole grid and prints a
//! row per grid point (set `RAYON_NUM_THREADS` to choose the cores);
//! `--grid small` runs three of its points, for a quick check.
//!
//! Beyond one machine: the runs share nothing, so the grid is cut into
//! slices that run anywhere, and a merge puts their rows back together.
//!
//! * `sweep --slice K/N --out slice-K.csv` runs slice `K` of `N`
//!   (`1 ≤ K ≤ N`): the grid points whose index `i` (counted from 0 in
//!   grid order) has `i mod N = K − 1`. Round robin rather than blocks,
//!   so that every slice gets a mix of fast and slow variants. Its rows
//!   go to the CSV file.
//! * `sweep --merge slice-1.csv … slice-N.csv --out sweep.csv` checks that
//!   the slices hold every grid point exactly once (a missing point, a
//!   point twice, or a point of another grid is an error naming it) and
//!   writes the rows in grid order: the same file, bit for bit, as
//!   `sweep --out sweep.csv` on one machine. Give the merge the slices'
//!   `--grid`.
//! * `tools/slurm-sweep.sh` runs the slices as a Slurm job array, and the
//!   merge as a job that waits for them.
//!
//! The CSV: `index,speed,bump,max_pitch,max_ground,error`: the grid index,
//! the target speed (m/s), the bump height (m), the largest pitch (°) and
//! ground force (N) after the first second, and, for a run that failed,
//! the error (with the figures left empty). Numbers are written in the
//! shortest form that reads back to the same `f64`, so a merged file
//! compares exactly with a single machine's. Wall times are printed but
//! not written: they differ from run to run.
//!
//! A failed run does not stop the others: its row carries the error, every
//! row is written, and the exit code is 1. The CSV is written as
//! `FILE.partial` and renamed to `FILE` when complete, so an existing
//! `FILE` is always a whole slice.

use std::fs::File;
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::time::Instant;

use clap::{Parser, ValueEnum};
use rayon::prelude::*;
use trackgen::integrate::Integrator;
use trackgen::simulate::{Output, simulate};
use trackgen::terrain::Terrain;
use trackgen::vehicle::Vehicle;
use trackgen::vehicles::m113::M113;

/// `println!` that ignores a closed stdout (a log gone, `| head`): the
/// report is a courtesy, the rows in the CSV are the results.
macro_rules! say {
    ($($arg:tt)*) => {{
        use std::io::Write as _;
        let _ = writeln!(std::io::stdout(), $($arg)*);
    }};
}

/// Bump heights of the grids, m.
const BUMPS: [f64; 3] = [0.05, 0.1, 0.15];
/// The CSV's columns.
const HEADER: [&str; 6] = ["index", "speed", "bump", "max_pitch", "max_ground", "error"];

/// Drive the M113 over bumps: a grid of target speeds and bump heights.
#[derive(Parser, Debug)]
#[command(about)]
struct Args {
    /// Run only slice K of N (1 ≤ K ≤ N): the grid points whose index i
    /// (from 0) has i mod N = K − 1. Needs --out.
    #[arg(long, value_name = "K/N", value_parser = parse_slice, requires = "out")]
    slice: Option<Slice>,
    /// Merge the CSV files of slices (each grid point exactly once) into
    /// --out, in grid order; runs nothing.
    #[arg(long, value_name = "FILE", num_args = 1.., conflicts_with = "slice", requires = "out")]
    merge: Vec<PathBuf>,
    /// Write the rows to this CSV file: the grid's, the slice's, or the
    /// merged slices'.
    #[arg(long, value_name = "FILE")]
    out: Option<PathBuf>,
    /// Which grid: `full` (2 and 4 m/s, 6 runs) or `small` (4 m/s only,
    /// 3 runs: a quick check). A merge must name the slices' grid.
    #[arg(long, value_enum, default_value_t = Grid::Full)]
    grid: Grid,
}

/// The grids: every target speed with every bump height, speeds
/// outermost.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
enum Grid {
    /// 2 and 4 m/s over 0.05, 0.1 and 0.15 m.
    Full,
    /// 4 m/s over 0.05, 0.1 and 0.15 m.
    Small,
}

impl Grid {
    /// The grid points, `(speed, bump)`, in index order.
    fn points(self) -> Vec<(f64, f64)> {
        let speeds: &[f64] = match self {
            Grid::Full => &[2.0, 4.0],
            Grid::Small => &[4.0],
        };
        speeds
            .iter()
            .flat_map(|&s| BUMPS.map(move |b| (s, b)))
            .collect()
    }
}

/// Slice `k` of `n`, `1 ≤ k ≤ n`.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Slice {
    k: usize,
    n: usize,
}

impl Slice {
    fn holds(&self, index: usize) -> bool {
        index % self.n == self.k - 1
    }
}

fn parse_slice(s: &str) -> Result<Slice, String> {
    let (k, n) = s
        .split_once('/')
        .ok_or_else(|| "expected K/N, slice K of N, like 1/4".to_string())?;
    let whole = |v: &str, name: &str| {
        v.trim()
            .parse::<usize>()
            .map_err(|_| format!("{name} in K/N must be a whole number, got {v:?}"))
    };
    let (k, n) = (whole(k, "K")?, whole(n, "N")?);
    if n == 0 || k == 0 || k > n {
        return Err(format!("K/N needs 1 ≤ K ≤ N, got K = {k}, N = {n}"));
    }
    Ok(Slice { k, n })
}

/// What a run found.
#[derive(Debug, Clone, Copy)]
struct Figures {
    /// Largest pitch after the first second, degrees.
    max_pitch: f64,
    /// Largest ground force after the first second, N.
    max_ground: f64,
}

/// One grid point's outcome.
#[derive(Debug, Clone)]
struct Row {
    index: usize,
    speed: f64,
    bump: f64,
    figures: Result<Figures, String>,
    /// Wall time of the run, s (not written to the CSV).
    wall: Option<f64>,
}

fn run(speed: f64, bump: f64) -> Result<Figures, String> {
    let terrain = Terrain::Bump {
        centre: 8.0,
        width: 1.0,
        height: bump,
    };
    let drive = M113::speed_drive(move |t: f64| speed * ((t - 0.5) / 1.5).clamp(0.0, 1.0));
    let mut system = M113::system(terrain, drive).map_err(|e| e.to_string())?;
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
    Ok(Figures {
        max_pitch: max_abs("pitch").to_degrees(),
        max_ground: max_abs("ground_normal"),
    })
}

fn main() -> ExitCode {
    let args = Args::parse();
    let outcome = if args.merge.is_empty() {
        sweep(&args)
    } else {
        merge(
            args.grid,
            &args.merge,
            args.out.as_deref().expect("clap requires --out"),
        )
    };
    match outcome {
        Ok(true) => ExitCode::SUCCESS,
        Ok(false) => ExitCode::FAILURE,
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::FAILURE
        }
    }
}

/// Runs the grid, or a slice of it; whether every run succeeded.
fn sweep(args: &Args) -> Result<bool, String> {
    // Create the output first, next to its final name: a path that cannot
    // be written fails now, not after the runs; the file gets its name
    // when every row is in, so a slice's CSV is never half written.
    let out = match &args.out {
        Some(path) => {
            let partial = partial(path);
            let file = File::create(&partial)
                .map_err(|e| format!("cannot create {}: {e}", partial.display()))?;
            Some((file, partial, path))
        }
        None => None,
    };
    let grid = args.grid.points();
    let points: Vec<(usize, (f64, f64))> = grid
        .iter()
        .copied()
        .enumerate()
        .filter(|(i, _)| args.slice.is_none_or(|s| s.holds(*i)))
        .collect();
    let threads = rayon::current_num_threads();
    match args.slice {
        None => say!("{} runs on {threads} thread(s)", points.len()),
        Some(s) => say!(
            "{} runs (slice {}/{} of a {}-point grid) on {threads} thread(s)",
            points.len(),
            s.k,
            s.n,
            grid.len()
        ),
    }
    let started = Instant::now();
    let rows: Vec<Row> = points
        .par_iter()
        .map(|&(index, (speed, bump))| {
            let started = Instant::now();
            let figures = run(speed, bump);
            Row {
                index,
                speed,
                bump,
                figures,
                wall: Some(started.elapsed().as_secs_f64()),
            }
        })
        .collect();
    let wall = started.elapsed().as_secs_f64();
    // The rows first: a closed stdout must not lose them.
    let written = match out {
        Some((file, partial, path)) => {
            write_rows(file, &rows)
                .map_err(|e| format!("cannot write {}: {e}", partial.display()))?;
            std::fs::rename(&partial, path).map_err(|e| {
                format!(
                    "cannot rename {} to {}: {e}",
                    partial.display(),
                    path.display()
                )
            })?;
            Some(path)
        }
        None => None,
    };
    print_table(&rows);
    let serial: f64 = rows
        .iter()
        .filter(|r| r.figures.is_ok())
        .filter_map(|r| r.wall)
        .sum();
    say!(
        "sweep wall {wall:.2} s; sum of run walls {serial:.2} s; speed-up {:.2} on {threads} thread(s)",
        serial / wall
    );
    if let Some(path) = written {
        say!("wrote {} rows to {}", rows.len(), path.display());
    }
    Ok(rows.iter().all(|r| r.figures.is_ok()))
}

/// `FILE.partial` for `FILE`: where its rows go until they are all in.
fn partial(path: &Path) -> PathBuf {
    let mut name = path.as_os_str().to_owned();
    name.push(".partial");
    PathBuf::from(name)
}

fn print_table(rows: &[Row]) {
    say!(
        "{:>8} {:>8} {:>14} {:>16} {:>9}",
        "speed",
        "bump",
        "max pitch",
        "max ground force",
        "run wall"
    );
    for r in rows {
        match (&r.figures, r.wall) {
            (Ok(f), Some(wall)) => say!(
                "{:>6.1} m/s {:>5.2} m {:>12.2}° {:>14.0} N {:>7.2} s",
                r.speed,
                r.bump,
                f.max_pitch,
                f.max_ground,
                wall
            ),
            (Ok(f), None) => say!(
                "{:>6.1} m/s {:>5.2} m {:>12.2}° {:>14.0} N",
                r.speed,
                r.bump,
                f.max_pitch,
                f.max_ground
            ),
            (Err(e), _) => say!("{:>6.1} m/s {:>5.2} m failed: {e}", r.speed, r.bump),
        }
    }
}

fn write_rows(file: File, rows: &[Row]) -> csv::Result<()> {
    let mut w = csv::Writer::from_writer(file);
    w.write_record(HEADER)?;
    for r in rows {
        let (pitch, ground, error) = match &r.figures {
            Ok(f) => (f.max_pitch.to_string(), f.max_ground.to_string(), ""),
            Err(e) => (String::new(), String::new(), e.as_str()),
        };
        w.write_record([
            &r.index.to_string(),
            &r.speed.to_string(),
            &r.bump.to_string(),
            &pitch,
            &ground,
            error,
        ])?;
    }
    w.flush()?;
    Ok(())
}

/// Reads the rows of one slice's CSV.
fn read_rows(path: &Path, grid: &[(f64, f64)]) -> Result<Vec<(Row, u64)>, String> {
    let at = |line: u64| format!("{} line {line}", path.display());
    let mut reader =
        csv::Reader::from_path(path).map_err(|e| format!("cannot read {}: {e}", path.display()))?;
    let header = reader
        .headers()
        .map_err(|e| format!("cannot read {}: {e}", path.display()))?;
    if header.is_empty() {
        return Err(format!("{}: empty", path.display()));
    }
    if header != HEADER.as_slice() {
        return Err(format!(
            "{}: not a sweep CSV: the header is {:?}, not {:?}",
            path.display(),
            header.iter().collect::<Vec<_>>(),
            HEADER
        ));
    }
    let mut rows = Vec::new();
    for record in reader.records() {
        let record = record.map_err(|e| format!("cannot read {}: {e}", path.display()))?;
        let line = record.position().map_or(0, |p| p.line());
        let number = |i: usize| -> Result<f64, String> {
            record[i].parse().map_err(|_| {
                format!(
                    "{}: {} = {:?} is not a number",
                    at(line),
                    HEADER[i],
                    &record[i]
                )
            })
        };
        let index: usize = record[0]
            .parse()
            .map_err(|_| format!("{}: index {:?} is not a grid index", at(line), &record[0]))?;
        let Some(&(speed, bump)) = grid.get(index) else {
            return Err(format!(
                "{}: index {index} is not a grid point (the grid has {}, from 0)",
                at(line),
                grid.len()
            ));
        };
        let (s, b) = (number(1)?, number(2)?);
        if s.to_bits() != speed.to_bits() || b.to_bits() != bump.to_bits() {
            return Err(format!(
                "{}: point {index} is {s} m/s over {b} m, but the grid has {speed} m/s over {bump} m there (a CSV of another grid?)",
                at(line)
            ));
        }
        let figures = if record[5].is_empty() {
            Ok(Figures {
                max_pitch: number(3)?,
                max_ground: number(4)?,
            })
        } else {
            Err(record[5].to_string())
        };
        rows.push((
            Row {
                index,
                speed,
                bump,
                figures,
                wall: None,
            },
            line,
        ));
    }
    Ok(rows)
}

/// Merges slice CSVs into `out` in grid order; whether every run
/// succeeded.
fn merge(grid: Grid, files: &[PathBuf], out: &Path) -> Result<bool, String> {
    let grid = grid.points();
    let mut slots: Vec<Option<(Row, &Path, u64)>> = vec![None; grid.len()];
    for path in files {
        for (row, line) in read_rows(path, &grid)? {
            let index = row.index;
            if let Some((_, first, first_line)) = &slots[index] {
                return Err(format!(
                    "grid point {index} is twice in the slices: {} line {first_line} and {} line {line}",
                    first.display(),
                    path.display()
                ));
            }
            slots[index] = Some((row, path, line));
        }
    }
    let missing: Vec<String> = slots
        .iter()
        .enumerate()
        .filter(|(_, s)| s.is_none())
        .map(|(i, _)| i.to_string())
        .collect();
    if !missing.is_empty() {
        return Err(format!(
            "grid point{} {} (of 0 to {}) {} in none of the {} file(s): a slice missing or unfinished?",
            if missing.len() == 1 { "" } else { "s" },
            missing.join(", "),
            grid.len() - 1,
            if missing.len() == 1 { "is" } else { "are" },
            files.len()
        ));
    }
    let rows: Vec<Row> = slots.into_iter().flatten().map(|(r, _, _)| r).collect();
    let partial = partial(out);
    let file =
        File::create(&partial).map_err(|e| format!("cannot create {}: {e}", partial.display()))?;
    write_rows(file, &rows).map_err(|e| format!("cannot write {}: {e}", partial.display()))?;
    std::fs::rename(&partial, out).map_err(|e| {
        format!(
            "cannot rename {} to {}: {e}",
            partial.display(),
            out.display()
        )
    })?;
    print_table(&rows);
    say!(
        "merged {} rows from {} file(s) into {}",
        rows.len(),
        files.len(),
        out.display()
    );
    Ok(rows.iter().all(|r| r.figures.is_ok()))
}
