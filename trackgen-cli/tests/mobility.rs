//! The `mobility` subcommand of the main binary (`trackgen mobility`)
//! answers its events, writes what it says it writes, refuses what it
//! cannot answer, and its slices merge into the whole set.
//!
//! The binary is cargo's `CARGO_BIN_EXE_trackgen`, built with this test;
//! outputs go to folders under `CARGO_TARGET_TMPDIR`.

#[path = "../../tests/it/support/programs.rs"]
mod programs;
#[path = "../../tests/it/support/x200.rs"]
mod x200;

use std::path::{Path, PathBuf};
use std::process::Output;

use programs::{assert_success, run, scratch};

/// `trackgen mobility ARGS…` run in `cwd`.
fn mobility(args: &[&str], cwd: &Path) -> Output {
    let binary = PathBuf::from(env!("CARGO_BIN_EXE_trackgen"));
    let mut all = vec!["mobility"];
    all.extend_from_slice(args);
    run(&binary, &all, cwd)
}

/// `mobility --quick --events EVENTS --json --out DIR`, which must
/// succeed: its standard output and the JSON results on it.
fn quick_json(events: &str, dir: &Path) -> (String, Vec<serde_json::Value>) {
    let out = mobility(
        &[
            "--quick",
            "--events",
            events,
            "--json",
            "--out",
            dir.to_str().unwrap(),
        ],
        dir,
    );
    assert_success(&format!("mobility --quick --events {events}"), &out);
    let stdout = String::from_utf8_lossy(&out.stdout).to_string();
    let results = stdout
        .lines()
        .filter(|l| l.starts_with('{'))
        .map(|l| serde_json::from_str(l).unwrap_or_else(|e| panic!("{l}: {e}")))
        .collect();
    (stdout, results)
}

/// `mobility --quick --events ride,half-round,soil --json`: one result per
/// speed event and the soil's two rows, each a JSON line with the fields the issue names (SI units), a
/// CSV per event, the trials, the curves and the report written; the
/// ride's limit is a speed the search ran between 1 m/s and the top speed
/// (its trials bracket it: the largest passing trial is below 6 W and
/// the smallest failing one above); an unknown event is refused naming
/// the events; a set of obstacles alone writes no curves.
#[test]
fn mobility_answers_its_events_and_refuses_an_unknown_one() {
    let dir = scratch("mobility");
    let (stdout, results) = quick_json("ride,half-round,soil", &dir);
    // The ride, the half-round, and the soil's two rows (the resistance,
    // the slip at 0.2 of the weight).
    assert_eq!(results.len(), 4, "{stdout}");
    assert_eq!(results[2]["quantity"], "motion resistance / weight");
    assert_eq!(results[3]["quantity"], "slip");
    for (result, event) in results.iter().zip(["ride", "half-round"]) {
        assert_eq!(result["event"], event);
        assert_eq!(result["unit"], "m/s");
        assert!(result["runs"].as_u64().unwrap() >= 2, "{result}");
        assert_eq!(result["parameter"]["unit"], "m");
    }
    let ride = &results[0];
    let speed = ride["value"].as_f64().expect("a ride-limiting speed");
    assert!(speed > 1.0 && speed < 20.0, "{speed} m/s");
    let trials = std::fs::read_to_string(dir.join("trials.csv")).unwrap();
    let ride_trials: Vec<(f64, f64, bool)> = trials
        .lines()
        .skip(1)
        .filter(|l| l.starts_with("ride,"))
        .map(|l| {
            let f: Vec<&str> = l.split(',').collect();
            (f[4].parse().unwrap(), f[5].parse().unwrap(), f[6] == "true")
        })
        .collect();
    let passed = ride_trials
        .iter()
        .filter(|t| t.2)
        .map(|t| t.0)
        .fold(0.0, f64::max);
    let failed = ride_trials
        .iter()
        .filter(|t| !t.2)
        .map(|t| t.0)
        .fold(f64::INFINITY, f64::min);
    assert!(
        passed < speed && speed < failed,
        "{passed} < {speed} < {failed}"
    );
    for t in &ride_trials {
        assert_eq!(t.2, t.1 < 6.0, "trial {t:?}: passes below 6 W");
    }
    for file in ["ride.csv", "half-round.csv", "summary.svg", "report.html"] {
        let len = std::fs::metadata(dir.join(file))
            .map(|m| m.len())
            .unwrap_or(0);
        assert!(len > 100, "{file}: {len} bytes");
    }
    // A set of obstacles alone has no curve: no blank `summary.svg`, the
    // report and the vehicle at the limit still written.
    let obstacles = dir.join("obstacles");
    let out = mobility(
        &[
            "--quick",
            "--events",
            "step",
            "--out",
            obstacles.to_str().unwrap(),
        ],
        &dir,
    );
    assert_success("mobility --events step", &out);
    assert!(!obstacles.join("summary.svg").exists());
    for file in ["step.csv", "step-limit.svg", "report.html"] {
        assert!(obstacles.join(file).exists(), "{file}");
    }
    // Every run's integrator is the option's: Bogacki-Shampine at a
    // tenth of its default tolerance finds the same step to the quick
    // search's 0.1 m (its runs differ: the trials' figures are not the
    // default's bit for bit).
    let step = |extra: &[&str]| {
        let mut args = vec!["--quick", "--events", "step", "--json"];
        args.extend_from_slice(extra);
        let out = mobility(&args, &dir);
        assert_success("mobility --events step --json", &out);
        let stdout = String::from_utf8_lossy(&out.stdout).to_string();
        let line = stdout.lines().find(|l| l.starts_with('{')).unwrap();
        let result: serde_json::Value = serde_json::from_str(line).unwrap();
        (
            result["value"].as_f64().unwrap(),
            result["relation"].clone(),
        )
    };
    let (default, relation) = step(&[]);
    assert_eq!(relation, "=");
    let (tight, relation) = step(&["--integrator", "bs23", "--tolerance", "1e-4"]);
    assert_eq!(relation, "=");
    assert!(
        (tight - default).abs() <= 0.1,
        "step {default} m by default, {tight} m at 1e-4"
    );
    let refused = mobility(&["--integrator", "rk45"], &dir);
    assert_eq!(refused.status.code(), Some(2));
    let stderr = String::from_utf8_lossy(&refused.stderr);
    assert!(stderr.contains("rk45"), "{stderr}");
    let refused = mobility(&["--events", "ride,mud"], &dir);
    assert!(!refused.status.success());
    let stderr = String::from_utf8_lossy(&refused.stderr);
    assert!(stderr.contains("unknown event `mud`"), "{stderr}");
}

/// `mobility --quick --events side-slope --json` for the M113 (declared
/// with both tracks): one result, the steepest side slope, bracketed by
/// its trials (each passing trial's drift at most the event's 5 %, each
/// failing one's over it or its roll off), no steeper than the closed
/// form allows on its ground (`tan φ ≤ μ = 0.8`, plus the quick search's
/// 0.1), and set beside the published 30 % with the ratio.
#[test]
fn mobility_finds_the_steepest_side_slope_in_3d() {
    let dir = scratch("mobility-side-slope");
    let (stdout, results) = quick_json("side-slope", &dir);
    assert_eq!(results.len(), 1, "{stdout}");
    let result = &results[0];
    assert_eq!(result["event"], "side-slope");
    assert_eq!(result["quantity"], "steepest side slope");
    assert_eq!(result["unit"], "rise over run");
    assert_eq!(result["relation"], "=");
    let slope = result["value"].as_f64().unwrap();
    assert!(slope > 0.1 && slope <= 0.8 + 0.1, "{slope}");
    let trials = std::fs::read_to_string(dir.join("trials.csv")).unwrap();
    let trials: Vec<(f64, f64, bool)> = trials
        .lines()
        .skip(1)
        .map(|l| {
            let f: Vec<&str> = l.split(',').collect();
            (f[4].parse().unwrap(), f[5].parse().unwrap(), f[6] == "true")
        })
        .collect();
    assert_eq!(trials.len() as u64, result["runs"].as_u64().unwrap());
    for &(parameter, drift, passed) in &trials {
        assert_eq!(passed, parameter < slope, "trial at {parameter}");
        if passed {
            assert!(drift <= 0.05, "held at {parameter} drifting {drift}");
        }
    }
    let against = stdout
        .lines()
        .find(|l| l.starts_with("steepest side slope"))
        .unwrap_or_else(|| panic!("no published side slope: {stdout}"));
    let ratio = format!("ratio {:.2}", slope / 0.30);
    assert!(against.contains(&ratio), "{against}");
}

/// `mobility --quick --events turning --json` for the M113: the smallest
/// radius at a crawl through its steer unit's first-range ratio (2.31,
/// declared with its powertrain) beside its radius without slip, `B/2 (ρ + 1)/(ρ
/// − 1)` at its 2.159 m gauge (to the printed digits), which slip only
/// opens (measured 3.61 m against 2.73 m); and the X200-4's pivot in
/// neutral at full steer, its belts at the steer drive's `±k ω_e r / 2`
/// (k from the published steer ratios over the ranges' reductions, the
/// 6V53T at its rated 2800 rpm, `r` the sprocket's rolling radius: 1.786
/// m/s, checked against the figures to 1e-3), its yaw rate below the
/// kinematic `2 v / B` (measured 1.216 of 1.654 rad/s), its power
/// positive. Each run steady (`=`).
#[test]
fn mobility_turns_the_m113_in_3d() {
    let dir = scratch("mobility-turning");
    let (stdout, results) = quick_json("turning", &dir);
    assert_eq!(results.len(), 4, "{stdout}");
    let value = |quantity: &str| {
        let row = results
            .iter()
            .find(|r| r["quantity"] == quantity)
            .unwrap_or_else(|| panic!("no {quantity}: {stdout}"));
        assert_eq!(row["relation"], "=", "{row}");
        assert_eq!(row["event"], "turning");
        row["value"].as_f64().unwrap()
    };
    let half = 0.5 * 2.159;
    let kinematic = value("radius without slip");
    assert!((kinematic - half * 3.31 / 1.31).abs() < 1e-3, "{kinematic}");
    let radius = value("smallest turning radius");
    assert!(radius > kinematic && radius < 2.0 * kinematic, "{radius}");
    let pivot = results
        .iter()
        .find(|r| r["quantity"] == "pivot turn's yaw rate")
        .expect("the pivot");
    let belts = pivot["parameter"]["value"].as_f64().expect("the belts");
    // The steer drive's ratio from the figures, k = mean(q_r / N_r).
    use trackgen::vehicles::m113;
    let k = x200::steer_drive_ratio();
    // Ten teeth on the shoes' 0.154 m pitch: `N p / (2π)`.
    let rolling = 10.0 * 0.154 / (2.0 * std::f64::consts::PI);
    let want = 0.5 * k * m113::ENGINE_RATED_SPEED * rolling;
    assert!((belts / want - 1.0).abs() < 1e-3, "{belts} against {want}");
    let yaw_rate = value("pivot turn's yaw rate");
    assert!(yaw_rate > 0.0 && yaw_rate < belts / half, "{yaw_rate}");
    assert!(value("pivot turn's power") > 0.0);
}

/// `mobility --slice K/N` and `--merge`: two slices of the quick set, run
/// apart and merged, give the event CSVs and the trials of the whole set
/// run at once (every task is deterministic; the wall times aside); a
/// merge missing a slice names the tasks it lacks, and one given a slice
/// twice names the task and both places.
#[test]
fn mobility_slices_merge_into_the_whole_set() {
    let dir = scratch("mobility-slices");
    let common = ["--quick", "--events", "half-round,soil"];
    let whole = dir.join("whole");
    let args = |extra: &[&str]| {
        let mut v: Vec<String> = common.iter().map(|s| s.to_string()).collect();
        v.extend(extra.iter().map(|s| s.to_string()));
        v
    };
    let run_with = |extra: &[&str]| {
        let v = args(extra);
        let refs: Vec<&str> = v.iter().map(String::as_str).collect();
        mobility(&refs, &dir)
    };
    assert_success("whole", &run_with(&["--out", whole.to_str().unwrap()]));
    let sliced = dir.join("sliced");
    for k in ["1/2", "2/2"] {
        assert_success(
            k,
            &run_with(&["--slice", k, "--out", sliced.to_str().unwrap()]),
        );
    }
    let (one, two) = (
        sliced.join("slice-1-of-2.jsonl"),
        sliced.join("slice-2-of-2.jsonl"),
    );
    let merged = dir.join("merged");
    assert_success(
        "merge",
        &run_with(&[
            "--merge",
            one.to_str().unwrap(),
            two.to_str().unwrap(),
            "--out",
            merged.to_str().unwrap(),
        ]),
    );
    // The CSVs without their wall-time column.
    let without_wall = |path: &std::path::Path| -> Vec<String> {
        let text = std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{path:?}: {e}"));
        let header: Vec<&str> = text.lines().next().unwrap().split(',').collect();
        let wall = header.iter().position(|h| *h == "wall_s");
        text.lines()
            .map(|l| {
                let mut f: Vec<&str> = l.split(',').collect();
                if let Some(w) = wall {
                    f.remove(w);
                }
                f.join(",")
            })
            .collect()
    };
    for file in ["half-round.csv", "soil.csv", "trials.csv"] {
        assert_eq!(
            without_wall(&whole.join(file)),
            without_wall(&merged.join(file)),
            "{file}"
        );
    }
    let missing = run_with(&[
        "--merge",
        one.to_str().unwrap(),
        "--out",
        merged.to_str().unwrap(),
    ]);
    assert!(!missing.status.success());
    let stderr = String::from_utf8_lossy(&missing.stderr);
    assert!(
        stderr.contains("tasks missing from the slices: 1"),
        "{stderr}"
    );
    let twice = run_with(&[
        "--merge",
        one.to_str().unwrap(),
        one.to_str().unwrap(),
        two.to_str().unwrap(),
        "--out",
        merged.to_str().unwrap(),
    ]);
    assert!(!twice.status.success());
    let stderr = String::from_utf8_lossy(&twice.stderr);
    assert!(stderr.contains("is in two slices"), "{stderr}");
}
