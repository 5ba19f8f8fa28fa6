//! The main job (`cargo run --release -p trackgen-cli`) runs, briefly,
//! and writes what it says it writes.
//!
//! A 0.3 s run exits 0 and writes
//! `m113.csv`, `all.csv`, `all.arrow`, `m113.svg`, `frame.svg` and
//! `animation.html`; the CSVs are a header and rows of finite numbers,
//! one row per output time from 0 to the duration; the Arrow file holds
//! the same columns and the same values as `all.csv` (CSV numbers are
//! written in their shortest round-trip form, so they compare exactly);
//! the SVGs and the page are whole documents. A dip (a negative bump
//! height) and a ramp of 0 s (a step in speed) run: the step asks for the
//! drive's whole 20 kN m at t = 0, where a ramp asks for nothing. Every
//! bad option (an unknown integrator or flag, a number that is not one,
//! NaN, a zero or negative duration, a value out of its range) exits
//! non-zero before the run, without a panic, with nothing on stdout (no
//! summary) and no files, and stderr names the option and its allowed
//! range.
//!
//! The binary is cargo's `CARGO_BIN_EXE_trackgen`, built with this test.
//! Outputs go to folders under `CARGO_TARGET_TMPDIR`. Output times are
//! multiples of the 0.01 s output interval computed in `f64`, so the last
//! time is the duration to 1e-9 s and no gap exceeds 0.01 s by more than
//! that; a missing or extra sample is off by 0.01 s.

#[path = "support/arrow.rs"]
mod arrow;
#[path = "../../tests/it/support/programs.rs"]
mod programs;

use std::path::{Path, PathBuf};

use programs::{Csv, assert_rejected, assert_success, check_svg, run, scratch, text};
use trackgen::multibody::RecursiveModel;
use trackgen::vehicles::{m113::M113Chassis, m113::M113Track};

/// The main job's binary.
fn main_job() -> PathBuf {
    PathBuf::from(env!("CARGO_BIN_EXE_trackgen"))
}

const M113_FILES: [&str; 6] = [
    "m113.csv",
    "all.csv",
    "all.arrow",
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
            "engine_load",
            "tension",
            "ground_normal",
            "seat_ax",
            "seat_az"
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
    check_arrow_equals_csv(&dir.join("all.arrow"), &all);
    check_svg(&dir.join("m113.svg"));
    check_svg(&dir.join("frame.svg"));
    let html = std::fs::read_to_string(dir.join("animation.html")).unwrap();
    assert!(html.contains("<html"), "animation.html is no HTML page");
    assert!(
        html.trim_end().ends_with("</html>"),
        "animation.html is truncated"
    );
}

/// The Arrow IPC file at `path` has the columns and the values of `csv`.
fn check_arrow_equals_csv(path: &Path, csv: &Csv) {
    let (names, rows) = arrow::read(path);
    assert_eq!(names, csv.header, "{}: columns", path.display());
    assert_eq!(rows.len(), csv.rows.len(), "{}: rows", path.display());
    for (i, (a, c)) in rows.iter().zip(&csv.rows).enumerate() {
        assert_eq!(a, c, "{}: row {i} differs from the CSV", path.display());
    }
}

#[test]
fn m113_short_run_writes_its_outputs() {
    let m113 = main_job();
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
    // The books are printed, and within the bound of the default tolerance
    // 1e-3 (EnergyBalance::bound_for_tolerance: 1e-2), so no warning.
    let stdout = text(&out.stdout);
    let residual: f64 = stdout
        .split("(residual ")
        .nth(1)
        .and_then(|r| r.split_whitespace().next())
        .and_then(|r| r.parse().ok())
        .unwrap_or_else(|| panic!("no energy residual in:\n{stdout}"));
    assert!(residual.abs() < 1e-2, "residual {residual}");
    assert!(!stdout.contains("warning"), "{stdout}");
    check_m113_outputs(&dir, 0.3);
}

/// `--modes --start equilibrium`: the rest and the table printed, the run
/// starts there (it stands still until the drive starts: the hull's
/// height over the settling time moves less than a micrometre), and
/// `modes.csv` holds modes with finite frequencies, lowest first, the
/// hull's bounce and pitch among them; `modes.svg` is drawn.
#[test]
fn m113_finds_its_rest_and_modes() {
    let m113 = main_job();
    let dir = scratch("m113_modes");
    let out = run(
        &m113,
        &[
            "--modes",
            "--start",
            "equilibrium",
            "--duration",
            "0.3",
            "--settle",
            "0.2",
            "--ramp",
            "0.1",
            "--out",
            dir.to_str().unwrap(),
        ],
        &dir,
    );
    assert_success("m113 --modes --start equilibrium", &out);
    let stdout = text(&out.stdout);
    assert!(
        stdout.contains("at rest in ") && stdout.contains("hull bounce"),
        "{stdout}"
    );
    let csv = std::fs::read_to_string(dir.join("modes.csv")).expect("modes.csv");
    let mut lines = csv.lines();
    assert!(lines.next().unwrap().starts_with("frequency_hz,"), "{csv}");
    let frequencies: Vec<f64> = lines
        .map(|l| l.split(',').next().unwrap().parse().unwrap())
        .collect();
    assert!(frequencies.len() > 100, "{} modes", frequencies.len());
    assert!(frequencies.iter().all(|f| f.is_finite() && *f > 0.0));
    assert!(frequencies.windows(2).all(|w| w[0] <= w[1]), "lowest first");
    assert!(csv.contains("hull pitch") && csv.contains("hull bounce"));
    check_svg(&dir.join("modes.svg"));
    let page = std::fs::read_to_string(dir.join("modes.html")).expect("modes.html");
    assert!(
        page.contains("mode 1: ") && page.contains("mode 6: "),
        "modes.html plays six modes"
    );
    let main = Csv::read(&dir.join("m113.csv"));
    let settling: Vec<f64> = main
        .column("t")
        .iter()
        .zip(main.column("y"))
        .filter(|(t, _)| **t <= 0.2)
        .map(|(_, y)| y)
        .collect();
    let moved = settling
        .iter()
        .map(|v| (v - settling[0]).abs())
        .fold(0.0, f64::max);
    assert!(moved < 1e-6, "the hull moved {moved} m while held at rest");
}

/// The main job, 0.1 s with `--integrator method`: it runs and writes its
/// outputs.
fn m113_runs_with(method: &str) {
    let m113 = main_job();
    let dir = scratch(&format!("m113_{method}"));
    let out = run(
        &m113,
        &[
            "--integrator",
            method,
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
    assert_success(&format!("m113 --integrator {method}"), &out);
    check_m113_outputs(&dir, 0.1);
}

#[test]
fn m113_runs_with_dopri5() {
    m113_runs_with("dopri5");
}

#[test]
fn m113_runs_with_ros34pw2() {
    m113_runs_with("ros34pw2");
}

#[test]
fn m113_takes_a_dip_and_a_step_in_speed() {
    let m113 = main_job();
    let dir = scratch("m113_dip_step");
    let out = run(
        &m113,
        &[
            "--bump-height",
            "-0.1",
            "--bump-at",
            "0.5",
            "--settle",
            "0",
            "--ramp",
            "0",
            "--duration",
            "0.2",
            "--out",
            dir.to_str().unwrap(),
        ],
        &dir,
    );
    assert_success("m113 --bump-height -0.1 --ramp 0", &out);
    assert!(
        text(&out.stdout).contains("dip 0.10 m deep"),
        "{}",
        text(&out.stdout)
    );
    check_m113_outputs(&dir, 0.2);
    // A step: the controller asks at once for more than the drive's
    // limit (`speed_drive`: 20 kN m), so the first row holds the limit.
    let torque = Csv::read(&dir.join("m113.csv")).column("sprocket_torque");
    assert!(
        (torque[0].abs() - 2e4).abs() <= 1e-6,
        "torque at t = 0 with a step: {} N m",
        torque[0]
    );
}

/// `--engine`: the same step, now through the M113A3's engine and
/// converter, the engine's speed a state. The run starts with the engine
/// idling and the turbine at rest: the governor opens the fuel fully at
/// once, and the sprocket gets the converter's stall torque at idle,
/// `f n TR(0) (ω_idle / K(0))²` from the declared tables (the first range's
/// reduction `n`, the stages' efficiencies and the side's share `f`). Then
/// the engine spins up, and at every row the sprocket gets what the
/// converter gives at the recorded engine speed and the turbine's, `f n
/// TR(SR) (ω_e / K(SR))²` with `SR = −n ω / ω_e` (the tables read here),
/// falling to none over the coupling band below `SR = 1`.
#[test]
fn m113_with_its_engine_starts_on_the_engines_torque() {
    let m113 = main_job();
    let dir = scratch("m113_engine");
    let out = run(
        &m113,
        &[
            "--engine",
            "--speed",
            "10",
            "--settle",
            "0",
            "--ramp",
            "0",
            "--duration",
            "1.2",
            "--out",
            dir.to_str().unwrap(),
        ],
        &dir,
    );
    assert_success("m113 --engine", &out);
    let stdout = text(&out.stdout);
    assert!(
        stdout.contains("engine: the engine at full load set the speed"),
        "{stdout}"
    );
    let csv = Csv::read(&dir.join("all.csv"));
    let (torque, load, engine, omega, gear) = (
        csv.column("sprocket_torque"),
        csv.column("engine_load"),
        csv.column("engine_speed"),
        csv.column("sprocket_speed"),
        csv.column("gear"),
    );
    let powertrain = trackgen::vehicles::m113::powertrain();
    let trackgen::vehicle::Powertrain::Converter(d) = &powertrain else {
        panic!("the M113A3 has a converter");
    };
    let idle = d.engine[0].0;
    let f = d.gearbox_efficiency * d.final_drive_efficiency * d.share;
    let n = d.ranges[0] * d.final_drive;
    let table = |points: &[(f64, f64)], x: f64| {
        let i = points
            .iter()
            .position(|p| p.0 > x)
            .unwrap_or(points.len() - 1)
            .max(1);
        let ((x0, y0), (x1, y1)) = (points[i - 1], points[i]);
        y0 + (y1 - y0) * (x.clamp(x0, x1) - x0) / (x1 - x0)
    };
    // The turbine at `−n ω` (forward the sprocket turns negative); turned
    // backwards (the hull rolling back as it settles) the converter is at
    // stall.
    let gives = |we: f64, w: f64| {
        let sr = (-n * w / we).max(0.0);
        let k = table(&d.capacity, sr);
        // No slip, no torque: the coupling band below SR = 1.
        let taper = ((1.0 - sr) / trackgen::vehicle::COUPLING_BAND).clamp(0.0, 1.0);
        f * n * table(&d.torque_ratio, sr) * (we / k) * (we / k) * taper
    };
    assert_eq!(engine[0], idle, "the engine idles at t = 0");
    // Forward drive turns the sprocket clockwise: a negative torque.
    assert!(
        (torque[0] + gives(idle, 0.0)).abs() <= 1e-9 * gives(idle, 0.0),
        "torque at t = 0: {} N m, the converter's stall at idle",
        torque[0]
    );
    for i in 0..torque.len() {
        assert_eq!(
            (load[i], gear[i]),
            (1.0, 1.0),
            "full fuel in the first range, row {i}"
        );
        let want = gives(engine[i], omega[i]);
        assert!(
            (torque[i] + want).abs() <= 1e-9 * want,
            "row {i}: {} N m, the converter's −{want} at {} rad/s",
            torque[i],
            engine[i]
        );
    }
    assert!(
        engine.windows(2).all(|w| w[1] > w[0]),
        "the engine spins up throughout"
    );
    assert!(engine[engine.len() - 1] > 4.0 * idle);
}

/// A negative speed drives in reverse: the chassis ends moving backwards
/// near the command (2 m/s after a 0.3 s ramp and 0.7 s more: within
/// 30 % — the controller overshoots on the way, as forwards) and has
/// moved back.
#[test]
fn m113_drives_in_reverse() {
    let m113 = main_job();
    let dir = scratch("m113_reverse");
    let out = run(
        &m113,
        &[
            "--speed",
            "-2",
            "--settle",
            "0",
            "--ramp",
            "0.3",
            "--duration",
            "2.0",
            "--out",
            dir.to_str().unwrap(),
        ],
        &dir,
    );
    assert_success("m113 --speed -2", &out);
    check_m113_outputs(&dir, 2.0);
    let csv = Csv::read(&dir.join("m113.csv"));
    let (t, speed, x) = (csv.column("t"), csv.column("speed"), csv.column("x"));
    // The speed controller overshoots the step (to −2.74 m/s at 0.9 s)
    // and has settled within ±0.07 m/s of the command after 1.5 s.
    let settled: Vec<f64> = t
        .iter()
        .zip(&speed)
        .filter(|(t, _)| **t >= 1.5)
        .map(|(_, v)| *v)
        .collect();
    let v = settled.iter().sum::<f64>() / settled.len() as f64;
    let moved = x.last().unwrap() - x[0];
    assert!(
        (v + 2.0).abs() <= 0.15,
        "mean speed {v} m/s over the last 0.5 s for -2"
    );
    assert!(moved < -2.0, "moved {moved} m in reverse");
}

/// A run that cannot start (a 0.4 m bump under the vehicle at rest, so
/// the track would start inside the ground) is an error naming why: a
/// non-zero exit, no summary and no files.
#[test]
fn m113_refuses_a_start_inside_the_ground() {
    let m113 = main_job();
    let dir = scratch("m113_start_inside");
    let out_dir = dir.join("out");
    let out = run(
        &m113,
        &[
            "--bump-at",
            "0",
            "--bump-height",
            "0.4",
            "--out",
            out_dir.to_str().unwrap(),
        ],
        &dir,
    );
    assert_rejected(
        "m113 with a bump under the start",
        &out,
        &["inside the ground"],
    );
    assert!(out.stdout.is_empty(), "no summary:\n{}", text(&out.stdout));
    assert!(!out_dir.exists(), "no files are written");
}

/// `--drawbar-pull`: the M113 on dry sand pulled back by 20 kN from the
/// start says so, closes its books within their bound (no warning), and
/// makes less headway in 3 s than free.
#[test]
fn m113_pulls_a_drawbar_load() {
    let m113 = main_job();
    let travel = |pull: &str| {
        let dir = scratch(&format!("m113_drawbar_{pull}"));
        let out = run(
            &m113,
            &[
                "--soil",
                "dry-sand",
                "--drawbar-pull",
                pull,
                "--duration",
                "3",
                "--out",
                dir.to_str().unwrap(),
            ],
            &dir,
        );
        assert_success("m113 --drawbar-pull", &out);
        let said = text(&out.stdout) + &text(&out.stderr);
        assert!(!said.contains("warning"), "{said}");
        let x = Csv::read(&dir.join("m113.csv")).column("x");
        (x[x.len() - 1] - x[0], said)
    };
    let (pulled, said) = travel("20000");
    assert!(
        said.contains("a drawbar load of 20.0 kN pulling the hull back"),
        "{said}"
    );
    let (free, said) = travel("0");
    assert!(!said.contains("drawbar load"), "{said}");
    assert!(pulled < free - 0.05, "pulled {pulled} m, free {free} m");
}

/// `--soil dry-sand`: the M113 on soft soil sinks centimetres (on rigid
/// ground, millimetres) and the run writes its outputs; `--vehicle
/// marder` on rigid ground writes the Marder's.
#[test]
fn m113_drives_on_soft_soil_and_the_marder_runs() {
    let m113 = main_job();
    let dir = scratch("m113_soil");
    let out = run(
        &m113,
        &[
            "--soil",
            "dry-sand",
            "--settle",
            "0.3",
            "--ramp",
            "0.5",
            "--duration",
            "1.0",
            "--out",
            dir.to_str().unwrap(),
        ],
        &dir,
    );
    assert_success("m113 --soil dry-sand", &out);
    assert!(
        text(&out.stdout).contains("on dry-sand soil"),
        "{}",
        text(&out.stdout)
    );
    check_m113_outputs(&dir, 1.0);
    let sinkage = Csv::read(&dir.join("all.csv")).column("ground_penetration");
    let deepest = sinkage.iter().copied().fold(0.0, f64::max);
    assert!(deepest > 0.02, "deepest sinkage {deepest} m on dry sand");
    let dir = scratch("marder");
    let out = run(
        &m113,
        &[
            "--vehicle",
            "marder",
            "--settle",
            "0.2",
            "--ramp",
            "0.3",
            "--duration",
            "0.6",
            "--out",
            dir.to_str().unwrap(),
        ],
        &dir,
    );
    assert_success("m113 --vehicle marder", &out);
    assert!(
        text(&out.stdout).starts_with("Marder"),
        "{}",
        text(&out.stdout)
    );
    for file in [
        "marder.csv",
        "all.csv",
        "all.arrow",
        "marder.svg",
        "frame.svg",
        "animation.html",
    ] {
        assert!(dir.join(file).is_file(), "{file} not written");
    }
    let csv = Csv::read(&dir.join("marder.csv"));
    assert!((csv.column("t").last().unwrap() - 0.6).abs() < 1e-9);
}

#[test]
fn m113_rejects_bad_options() {
    let m113 = main_job();
    let dir = scratch("m113_bad");
    let out_dir = dir.join("out");
    let out_arg = out_dir.to_str().unwrap();
    // Short runs, in case an option were wrongly accepted.
    const SHORT: [&str; 6] = ["--duration", "0.05", "--settle", "0.0", "--ramp", "0.05"];
    let cases: &[(&[&str], &[&str])] = &[
        (
            &["--integrator", "rk9"],
            &["rk9", "--integrator", "bs23", "dopri5"],
        ),
        (&["--speed", "abc"], &["abc", "--speed", "-20 to 20 m/s"]),
        (&["--speed", "nan"], &["--speed", "-20 to 20 m/s"]),
        (&["--speed", "25"], &["--speed", "-20 to 20 m/s"]),
        (&["--frobnicate"], &["--frobnicate"]),
        (&["--duration=-1"], &["--duration", "-1", "more than 0 s"]),
        (
            &["--duration", "-1"],
            &["--duration", "-1", "more than 0 s"],
        ),
        (&["--duration", "0"], &["--duration", "more than 0 s"]),
        (&["--duration", "inf"], &["--duration", "more than 0 s"]),
        (&["--settle", "-1"], &["--settle", "0 to 1e6 s"]),
        (&["--ramp", "nan"], &["--ramp", "0 to 1e6 s"]),
        (&["--tolerance", "0"], &["--tolerance", "1e-12 to 0.1"]),
        (&["--tolerance", "1"], &["--tolerance", "1e-12 to 0.1"]),
        (
            &["--bump-height", "0.6"],
            &["--bump-height", "-0.5 to 0.5 m"],
        ),
        (&["--bump-at", "inf"], &["--bump-at", "-10000 to 10000 m"]),
        (&["--soil", "mud"], &["--soil", "mud", "rigid", "dry-sand"]),
        (
            &["--drawbar-pull", "2e6"],
            &["--drawbar-pull", "-1e6 to 1e6 N"],
        ),
        (
            &["--vehicle", "tiger"],
            &["--vehicle", "tiger", "m113", "marder"],
        ),
        (
            &["--roughness", "Z"],
            &["--roughness", "ISO 8608 class A to H"],
        ),
        (
            &["--roughness", "3ft"],
            &["--roughness", "1in, 25mm, 0.03m"],
        ),
        (&["--roughness", "0.8m"], &["--roughness", "out of range"]),
        (&["--obstacle", "wall:1"], &["--obstacle", "half-round:R"]),
        (
            &["--obstacle", "step:x"],
            &["--obstacle", "not a finite number"],
        ),
        (
            &["--obstacle", "gap:1"],
            &["--obstacle", "takes 2 value(s)"],
        ),
        (
            &["--obstacle", "ditch:1:1:120"],
            &["--obstacle", "wall_angle"],
        ),
        (&["--output-every", "0"], &["--output-every", "1e-4 to 1 s"]),
        (
            &["--course-length", "5"],
            &["--course-length", "10 to 100000 m"],
        ),
        (
            &["--roughness", "C", "--obstacle", "step:0.2"],
            &["--roughness", "--obstacle", "cannot be used with"],
        ),
    ];
    for (bad, mentions) in cases {
        // The short run's settings, less the one under test (clap refuses
        // an option given twice).
        let named = |key: &str| bad.iter().any(|b| b.split('=').next() == Some(key));
        let short: Vec<&str> = SHORT
            .chunks(2)
            .filter(|pair| !named(pair[0]))
            .flatten()
            .copied()
            .collect();
        let args = [&short[..], bad, &["--out", out_arg]].concat();
        let out = run(&m113, &args, &dir);
        let what = bad.join(" ");
        assert_rejected(&what, &out, mentions);
        assert!(
            out.stdout.is_empty(),
            "{what}: nothing is run or summarised, got:\n{}",
            text(&out.stdout)
        );
        assert!(!out_dir.exists(), "{what}: no files are written");
    }
    let out = run(&m113, &["--out", ""], &dir);
    assert_rejected("--out ''", &out, &["--out"]);
}

/// The courses: a terrain file, a random course and an obstacle each run
/// and say what they drove over; a terrain file with a bad line is refused
/// before the run, naming the file and the line (`bad.csv:3`), with no
/// files written.
#[test]
fn m113_drives_a_terrain_file_a_random_course_and_an_obstacle() {
    let m113 = main_job();
    let dir = scratch("m113_courses");
    let file = dir.join("course.csv");
    std::fs::write(&file, "x,z\n-50,0\n10,0\n10,0.15\n60,0.15\n").unwrap();
    let short = ["--duration", "0.3", "--settle", "0.1", "--ramp", "0.1"];
    let cases: [(&[&str], &str); 3] = [
        (&["--course-file", file.to_str().unwrap()], "the profile of"),
        (&["--roughness", "C", "--seed", "7"], "ISO 8608 class C"),
        (
            &["--obstacle", "half-round:0.2"],
            "a half-round 0.20 m high",
        ),
    ];
    for (k, (course, said)) in cases.into_iter().enumerate() {
        let out = dir.join(format!("out{k}"));
        let args = [&short[..], course, &["--out", out.to_str().unwrap()]].concat();
        let run = run(&m113, &args, &dir);
        assert_success(&course.join(" "), &run);
        let stdout = text(&run.stdout);
        assert!(stdout.contains(said), "{course:?}: {stdout}");
        assert!(out.join("m113.csv").is_file(), "{course:?}: m113.csv");
    }
    let bad = dir.join("bad.csv");
    std::fs::write(&bad, "x,z\n0,0\n1,oops\n").unwrap();
    let out = dir.join("out_bad");
    let refused = run(
        &m113,
        &[
            "--course-file",
            bad.to_str().unwrap(),
            "--out",
            out.to_str().unwrap(),
        ],
        &dir,
    );
    assert_rejected("a bad terrain file", &refused, &["bad.csv:3", "oops"]);
    assert!(!out.join("all.csv").exists(), "nothing is run");
}

/// With rows every 1 ms the main job prints the seat's spectrum and
/// writes it: `seat_spectrum.csv` (frequency, the acceleration's density,
/// the absorbed power per bin), whose bins sum to the absorbed power it
/// prints (to its printed digits), within 5 % of the ride figure the
/// filter gives over the same rows (the spectrum averages the complete
/// 4.1 s segments, two over the 6.5 s measured; the filter every row),
/// with a line named as the shoe passage's harmonic on flat ground.
#[test]
fn the_seat_spectrum_is_printed_and_written() {
    let dir = scratch("seat_spectrum");
    let out = run(
        &main_job(),
        &[
            "--bump-height",
            "0",
            "--speed",
            "5",
            "--settle",
            "0.5",
            "--ramp",
            "2",
            "--duration",
            "9",
            "--output-every",
            "0.001",
            "--out",
            dir.to_str().unwrap(),
        ],
        &dir,
    );
    assert_success("m113 --output-every 0.001", &out);
    let stdout = text(&out.stdout);
    let number_after = |label: &str| -> f64 {
        let at = stdout
            .find(label)
            .unwrap_or_else(|| panic!("no `{label}` in:\n{stdout}"));
        stdout[at + label.len()..]
            .split_whitespace()
            .next()
            .and_then(|w| w.parse().ok())
            .unwrap_or_else(|| panic!("no number after `{label}`"))
    };
    let filtered = number_after("s: absorbed power ");
    let printed = number_after("Hz: absorbed power ");
    assert!(stdout.contains("shoe passage v/p"), "{stdout}");
    let csv = Csv::read(&dir.join("seat_spectrum.csv"));
    assert_eq!(
        csv.header,
        ["frequency_hz", "seat_az_psd", "absorbed_power_w"]
    );
    let total: f64 = csv.column("absorbed_power_w").iter().sum();
    assert!(
        (total - printed).abs() <= 0.005,
        "bins {total} W, printed {printed} W"
    );
    assert!(
        (total / filtered - 1.0).abs() < 0.05,
        "spectrum {total} W against the filter's {filtered} W"
    );
    let df = csv.column("frequency_hz")[1];
    assert!((df - 1.0 / 4.096).abs() < 1e-12, "bins {df} Hz apart");
}
