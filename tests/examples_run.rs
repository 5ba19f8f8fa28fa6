//! The examples run, briefly, and write what they say they write.
//!
//! * `m113` (the CLI of examples/m113/): a 0.3 s run exits 0 and writes
//!   `m113.csv`, `all.csv`, `m113.svg`, `frame.svg` and `animation.html`;
//!   the CSVs are a header and rows of finite numbers, one row per output
//!   time from 0 to the duration; the SVGs and the page are whole
//!   documents. Bad options (an unknown integrator, a speed that is not a
//!   number, an unknown flag, a negative duration, a zero tolerance) exit
//!   non-zero, without a panic, with a message on stderr naming the
//!   problem.
//! * `closed_chain`: its 10 s run (it has no option to shorten it; 0.2 s of
//!   wall time in the dev profile) writes `results.csv`, `shape.svg` and
//!   `history.svg` under `out/closed_chain/` in its working directory,
//!   holds the loop closed and conserves energy; with `--no-switching` it
//!   stops early, exits non-zero and still writes the results so far.
//! * `sweep` (no options; ~4 s in the dev profile on two cores): six rows,
//!   one per grid point, every one a finished run with finite figures.
//! * `model_timing`: the generated track dynamics agree with the reference
//!   route, and the chassis alone falls freely.
//!
//! The binaries are target/<profile>/examples/<name>, next to this test's
//! own deps/ folder. `cargo test` (all targets) builds them before running
//! the tests; run alone (`cargo test --test examples_run`) it does not, so
//! each test first asks cargo to build its example in this test's profile
//! (a no-op when it is fresh), which also keeps a stale binary from being
//! tested. Outputs go to folders under `CARGO_TARGET_TMPDIR`.
//!
//! Tolerances. Output times are multiples of the 0.01 s output interval
//! computed in `f64`, so the last time is the duration to 1e-9 s and no
//! gap exceeds 0.01 s by more than that; a missing or extra sample is off
//! by 0.01 s. The closed chain's own report (dopri5 at rtol = atol =
//! 1e-11, with switching) is a closure error of 5e-13 m and an energy drift
//! of 2e-12: the bounds 1e-9 m and 1e-7 (relative) leave three to four
//! orders for platform differences and still fail at once for a loop that
//! opens or a solver that leaks energy (O(1e-3) or worse). The reference
//! route agrees with the generated dynamics to 2e-12 (rounding in a
//! 66-coordinate solve); the bound is 1e-9.

mod support;

use std::collections::BTreeSet;
use std::path::{Path, PathBuf};
use std::process::{Command, Output};
use std::sync::Mutex;

use trackgen::RecursiveModel;
use trackgen::vehicles::m113::{M113Chassis, M113Track};

/// The output interval every example records at (`Output::Every(0.01)`).
const INTERVAL: f64 = 0.01;
/// Slack on output times: `f64` arithmetic on multiples of the interval.
const TIME_SLACK: f64 = 1e-9;

/// The example's binary, built by cargo first in this test's profile.
fn example(name: &str) -> PathBuf {
    // One cargo at a time from this process (they would queue on cargo's
    // lock anyway).
    static CARGO: Mutex<()> = Mutex::new(());
    let _one = CARGO.lock().unwrap_or_else(|e| e.into_inner());
    let exe = std::env::current_exe().expect("the test's own path");
    // target/<profile>/deps/examples_run-<hash>
    let profile_dir = exe
        .parent()
        .and_then(Path::parent)
        .expect("the test binary lives in target/<profile>/deps");
    let mut build = Command::new(env!("CARGO"));
    build
        .args(["build", "--quiet", "--example", name])
        .current_dir(env!("CARGO_MANIFEST_DIR"));
    match profile_dir.file_name().and_then(|n| n.to_str()) {
        Some("debug") | None => {}
        Some("release") => {
            build.arg("--release");
        }
        Some(other) => {
            build.args(["--profile", other]);
        }
    }
    let built = build.output().expect("cargo runs");
    assert!(
        built.status.success(),
        "cargo build --example {name} failed:\n{}",
        String::from_utf8_lossy(&built.stderr)
    );
    let binary = profile_dir
        .join("examples")
        .join(format!("{name}{}", std::env::consts::EXE_SUFFIX));
    assert!(binary.is_file(), "no binary at {}", binary.display());
    binary
}

/// An empty folder of this test's own.
fn scratch(case: &str) -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR"))
        .join("examples_run")
        .join(case);
    if dir.exists() {
        std::fs::remove_dir_all(&dir).expect("clear the scratch folder");
    }
    std::fs::create_dir_all(&dir).expect("create the scratch folder");
    dir
}

fn run(binary: &Path, args: &[&str], cwd: &Path) -> Output {
    Command::new(binary)
        .args(args)
        .current_dir(cwd)
        .output()
        .unwrap_or_else(|e| panic!("{} does not start: {e}", binary.display()))
}

fn text(bytes: &[u8]) -> String {
    String::from_utf8_lossy(bytes).into_owned()
}

/// Fails with the example's own output when it did not succeed.
fn assert_success(what: &str, out: &Output) {
    assert!(
        out.status.success(),
        "{what}: exit {:?}\nstdout:\n{}\nstderr:\n{}",
        out.status.code(),
        text(&out.stdout),
        text(&out.stderr)
    );
}

/// A rejected run: a non-zero exit code (not a signal), no panic, and
/// stderr naming the problem with every one of `mentions`.
fn assert_rejected(what: &str, out: &Output, mentions: &[&str]) {
    let stderr = text(&out.stderr);
    assert!(
        matches!(out.status.code(), Some(c) if c != 0),
        "{what}: expected a non-zero exit, got {:?}\nstdout:\n{}\nstderr:\n{stderr}",
        out.status.code(),
        text(&out.stdout)
    );
    assert!(
        !stderr.contains("panicked"),
        "{what}: a panic, not an error:\n{stderr}"
    );
    for m in mentions {
        assert!(
            stderr.contains(m),
            "{what}: stderr does not mention {m:?}:\n{stderr}"
        );
    }
}

/// A CSV of numbers: its header and rows.
struct Csv {
    header: Vec<String>,
    rows: Vec<Vec<f64>>,
}

impl Csv {
    /// Reads `path`: a header of distinct, non-empty names, then rows of as
    /// many finite numbers.
    fn read(path: &Path) -> Csv {
        let content =
            std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        let mut lines = content.lines();
        let header: Vec<String> = lines
            .next()
            .unwrap_or_else(|| panic!("{}: empty", path.display()))
            .split(',')
            .map(str::to_owned)
            .collect();
        assert!(
            header.iter().all(|h| !h.trim().is_empty()),
            "{}: empty column name in {header:?}",
            path.display()
        );
        let distinct: BTreeSet<_> = header.iter().collect();
        assert_eq!(
            distinct.len(),
            header.len(),
            "{}: repeated column names",
            path.display()
        );
        let rows: Vec<Vec<f64>> = lines
            .enumerate()
            .map(|(i, line)| {
                let row: Vec<f64> = line
                    .split(',')
                    .zip(&header)
                    .map(|(v, name)| {
                        let x: f64 = v.trim().parse().unwrap_or_else(|e| {
                            panic!("{} row {}: {name} = {v:?}: {e}", path.display(), i + 1)
                        });
                        assert!(
                            x.is_finite(),
                            "{} row {}: {name} = {x}",
                            path.display(),
                            i + 1
                        );
                        x
                    })
                    .collect();
                assert_eq!(
                    line.split(',').count(),
                    header.len(),
                    "{} row {}: field count",
                    path.display(),
                    i + 1
                );
                row
            })
            .collect();
        assert!(!rows.is_empty(), "{}: no rows", path.display());
        Csv { header, rows }
    }

    fn column(&self, name: &str) -> Vec<f64> {
        let k = self
            .header
            .iter()
            .position(|h| h == name)
            .unwrap_or_else(|| panic!("no column {name:?} in {:?}", self.header));
        self.rows.iter().map(|r| r[k]).collect()
    }

    /// The time column `t` comes first, starts at 0, increases by at most
    /// the output interval, and ends at `end`.
    fn check_times(&self, what: &str, end: f64) -> Vec<f64> {
        assert_eq!(self.header[0], "t", "{what}: the first column is the time");
        let t = self.column("t");
        assert_eq!(t[0], 0.0, "{what}: starts at t = 0");
        for w in t.windows(2) {
            let dt = w[1] - w[0];
            assert!(
                dt > 0.0 && dt <= INTERVAL + TIME_SLACK,
                "{what}: times {} then {}",
                w[0],
                w[1]
            );
        }
        let last = *t.last().unwrap();
        assert!(
            (last - end).abs() <= TIME_SLACK,
            "{what}: ends at t = {last}, not {end}"
        );
        t
    }
}

/// A whole SVG document that draws something.
fn check_svg(path: &Path) {
    let s = std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    let s = s.trim();
    assert!(
        s.starts_with("<svg") || s.starts_with("<?xml"),
        "{}: starts {:?}",
        path.display(),
        &s[..s.len().min(40)]
    );
    assert!(s.ends_with("</svg>"), "{}: truncated", path.display());
    assert!(
        s.contains("<polyline") || s.contains("<polygon") || s.contains("<path"),
        "{}: draws no lines",
        path.display()
    );
}

const M113_FILES: [&str; 5] = [
    "m113.csv",
    "all.csv",
    "m113.svg",
    "frame.svg",
    "animation.html",
];

/// Checks the five outputs of an `m113` run of `duration` in `dir`.
fn check_m113_outputs(dir: &Path, duration: f64) {
    for f in M113_FILES {
        assert!(dir.join(f).is_file(), "{f} not written");
    }
    let main = Csv::read(&dir.join("m113.csv"));
    assert_eq!(
        main.header,
        [
            "t",
            "x",
            "y",
            "pitch",
            "speed",
            "sprocket_torque",
            "sprocket_speed",
            "tension",
            "ground_normal"
        ],
        "m113.csv columns"
    );
    let t = main.check_times("m113.csv", duration);
    let all = Csv::read(&dir.join("all.csv"));
    let t_all = all.check_times("all.csv", duration);
    assert_eq!(t, t_all, "m113.csv and all.csv sample the same times");
    assert!(
        all.header.len() > 2 * (M113Track::BODIES + M113Chassis::BODIES),
        "all.csv has every coordinate and rate: {} columns",
        all.header.len()
    );
    check_svg(&dir.join("m113.svg"));
    check_svg(&dir.join("frame.svg"));
    let html = std::fs::read_to_string(dir.join("animation.html")).unwrap();
    assert!(html.contains("<html"), "animation.html is no HTML page");
    assert!(
        html.trim_end().ends_with("</html>"),
        "animation.html is truncated"
    );
}

#[test]
fn m113_short_run_writes_its_outputs() {
    let m113 = example("m113");
    let dir = scratch("m113");
    let out = run(
        &m113,
        &[
            "--duration",
            "0.3",
            "--settle",
            "0.1",
            "--ramp",
            "0.1",
            "--out",
            dir.to_str().unwrap(),
        ],
        &dir,
    );
    assert_success("m113 --duration 0.3", &out);
    assert!(
        text(&out.stdout).contains("wrote "),
        "m113 reports what it wrote:\n{}",
        text(&out.stdout)
    );
    check_m113_outputs(&dir, 0.3);
}

#[test]
fn m113_runs_with_dopri5() {
    let m113 = example("m113");
    let dir = scratch("m113_dopri5");
    let out = run(
        &m113,
        &[
            "--integrator",
            "dopri5",
            "--duration",
            "0.1",
            "--settle",
            "0.05",
            "--ramp",
            "0.05",
            "--out",
            dir.to_str().unwrap(),
        ],
        &dir,
    );
    assert_success("m113 --integrator dopri5", &out);
    check_m113_outputs(&dir, 0.1);
}

#[test]
fn m113_rejects_bad_options() {
    let m113 = example("m113");
    let dir = scratch("m113_bad");
    let out_dir = dir.join("out");
    let out_arg = out_dir.to_str().unwrap();
    // Short runs, in case an option were wrongly accepted.
    const SHORT: [&str; 6] = ["--duration", "0.05", "--settle", "0.0", "--ramp", "0.05"];
    let case = |args: &[&str]| run(&m113, &[args, &["--out", out_arg]].concat(), &dir);

    let out = case(&[&SHORT[..], &["--integrator", "rk9"]].concat());
    assert_rejected("--integrator rk9", &out, &["rk9", "integrator"]);
    assert!(
        !out_dir.join("m113.csv").exists(),
        "a rejected integrator writes no results"
    );

    let out = case(&[&SHORT[..], &["--speed", "abc"]].concat());
    assert_rejected("--speed abc", &out, &["abc", "--speed"]);

    let out = case(&[&SHORT[..], &["--frobnicate"]].concat());
    assert_rejected("--frobnicate", &out, &["--frobnicate"]);

    // Values that parse but make no run.
    let out = case(&["--duration=-1"]);
    assert_rejected("--duration=-1", &out, &["t_end", "-1"]);
    let out = case(&[&SHORT[..], &["--tolerance", "0"]].concat());
    assert_rejected("--tolerance 0", &out, &["tolerance"]);
}

#[test]
fn closed_chain_runs_and_writes_its_outputs() {
    let closed_chain = example("closed_chain");
    let dir = scratch("closed_chain");
    let out = run(&closed_chain, &[], &dir);
    assert_success("closed_chain", &out);
    let stdout = text(&out.stdout);
    assert!(
        stdout.contains("switches; energy drift"),
        "no summary:\n{stdout}"
    );
    let written = dir.join("out/closed_chain");
    let results = Csv::read(&written.join("results.csv"));
    results.check_times("results.csv", 10.0);
    // The state: t, R (2), 32 angles, then their rates, and the records.
    assert_eq!(&results.header[..4], ["t", "x", "y", "theta_1"]);
    assert!(results.header.iter().any(|h| h == "theta_32"));
    let closure = results.column("closure_error");
    let worst = support::max_abs(closure.iter().copied());
    assert!(worst <= 1e-9, "the loop opens: |C| up to {worst:e} m");
    let energy = results.column("energy");
    let drift = support::max_abs(energy.iter().map(|e| (e - energy[0]) / energy[0]));
    assert!(energy[0] > 0.0 && drift <= 1e-7, "energy drift {drift:e}");
    check_svg(&written.join("shape.svg"));
    check_svg(&written.join("history.svg"));
}

#[test]
fn closed_chain_without_switching_stops_early_and_keeps_its_results() {
    let closed_chain = example("closed_chain");
    let dir = scratch("closed_chain_no_switching");
    let out = run(&closed_chain, &["--no-switching"], &dir);
    assert!(
        matches!(out.status.code(), Some(c) if c != 0),
        "a singular partition must fail the run: exit {:?}",
        out.status.code()
    );
    let stdout = text(&out.stdout);
    assert!(
        stdout.contains("switching off") && stdout.contains("stopped early"),
        "no explanation:\n{stdout}\n{}",
        text(&out.stderr)
    );
    let results = Csv::read(&dir.join("out/closed_chain/results.csv"));
    let t = results.column("t");
    let last = *t.last().unwrap();
    assert!(
        last > 0.0 && last < 10.0,
        "results up to the stop: last t = {last}"
    );
    for w in t.windows(2) {
        assert!(w[1] > w[0], "times increase");
    }
}

#[test]
fn sweep_prints_a_row_per_variant() {
    let sweep = example("sweep");
    let dir = scratch("sweep");
    let out = run(&sweep, &[], &dir);
    assert_success("sweep", &out);
    let stdout = text(&out.stdout);
    assert!(!stdout.contains("failed"), "a variant failed:\n{stdout}");
    assert!(stdout.starts_with("6 runs on "), "header:\n{stdout}");
    // `   2.0 m/s  0.05 m         1.12°          73406 N    1.15 s`
    let rows: Vec<(f64, f64, f64, f64, f64)> = stdout
        .lines()
        .filter(|l| l.contains(" m/s ") && l.trim_end().ends_with(" s"))
        .map(|l| {
            let f: Vec<&str> = l.split_whitespace().collect();
            assert_eq!(f.len(), 9, "row {l:?}");
            assert_eq!(
                (f[1], f[3], f[6], f[8]),
                ("m/s", "m", "N", "s"),
                "units in {l:?}"
            );
            let num = |s: &str| -> f64 {
                let x: f64 = s
                    .trim_end_matches('°')
                    .parse()
                    .unwrap_or_else(|e| panic!("{s:?} in {l:?}: {e}"));
                assert!(x.is_finite(), "{s:?} in {l:?}");
                x
            };
            (num(f[0]), num(f[2]), num(f[4]), num(f[5]), num(f[7]))
        })
        .collect();
    assert_eq!(rows.len(), 6, "one row per variant:\n{stdout}");
    let grid: BTreeSet<(u64, u64)> = rows
        .iter()
        .map(|r| ((r.0 * 10.0).round() as u64, (r.1 * 100.0).round() as u64))
        .collect();
    let want: BTreeSet<(u64, u64)> = [20, 40]
        .into_iter()
        .flat_map(|s| [5, 10, 15].map(|b| (s, b)))
        .collect();
    assert_eq!(grid, want, "the speed × bump grid");
    // After settling the ground carries the vehicle's weight on average,
    // so the largest ground force is at least about that weight.
    let weight: f64 = M113Track
        .description()
        .bodies
        .iter()
        .chain(&M113Chassis.description().bodies)
        .map(|b| b.mass)
        .sum::<f64>()
        * 9.81;
    for &(speed, bump, pitch, ground, wall) in &rows {
        assert!(
            pitch > 0.0 && pitch < 45.0,
            "{speed} m/s over {bump} m: max pitch {pitch}°"
        );
        assert!(
            ground > 0.9 * weight && ground < 10.0 * weight,
            "{speed} m/s over {bump} m: max ground force {ground} N against a weight of {weight:.0} N"
        );
        assert!(wall > 0.0, "{speed} m/s over {bump} m: wall time {wall}");
    }
}

#[test]
fn model_timing_agrees_with_the_reference_route() {
    let model_timing = example("model_timing");
    let dir = scratch("model_timing");
    let out = run(&model_timing, &[], &dir);
    assert_success("model_timing", &out);
    let stdout = text(&out.stdout);
    let after = |key: &str| -> f64 {
        let rest = stdout
            .split(key)
            .nth(1)
            .unwrap_or_else(|| panic!("no {key:?} in:\n{stdout}"));
        let word = rest
            .split_whitespace()
            .next()
            .unwrap()
            .trim_end_matches(',');
        word.parse()
            .unwrap_or_else(|e| panic!("{key:?} {word:?}: {e}"))
    };
    let diff = after("max relative difference ");
    assert!(
        diff.is_finite() && diff <= 1e-9,
        "generated vs reference: {diff:e}"
    );
    let closure = after("closure |C| = ");
    assert!(
        closure <= 1e-12,
        "the timing state is on the closure: {closure:e}"
    );
    let fall = after("ÿ = ");
    assert_eq!(fall, -9.81, "the chassis alone falls freely");
}
