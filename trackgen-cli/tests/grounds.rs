//! `spatial` with each track on its own ground (`--left-course-file`,
//! `--right-course-file`): the M113 driven straight at 2 m/s for 5 s over
//! a ramp 80 mm high under its left track alone rolls to the right (the
//! left side up, roll positive: measured 0.0287 rad, between a fifth of
//! and the rigid bound `atan(0.08 / 2.159)` = 0.0370 rad, the whole track
//! lifted) and comes back (past level by at most a tenth of that:
//! 0.0014 rad), and says which ground each track has; a side file that
//! is not a profile is refused, naming its line.
//!
//! The binary is cargo's `CARGO_BIN_EXE_trackgen`; outputs go to folders
//! under `CARGO_TARGET_TMPDIR`.

#[path = "../../tests/it/support/programs.rs"]
mod programs;

use std::path::{Path, PathBuf};

use programs::{assert_rejected, assert_success, run, scratch, text};

fn binary() -> PathBuf {
    PathBuf::from(env!("CARGO_BIN_EXE_trackgen"))
}

fn path(p: &Path) -> &str {
    p.to_str().expect("a UTF-8 scratch path")
}

/// `spatial` straight at 2 m/s for 5 s into `out`, with `more` options.
fn spatial(dir: &Path, out: &str, more: &[&str]) -> (PathBuf, String) {
    let out = dir.join(out);
    let mut args = vec![
        "spatial",
        "--speed",
        "2",
        "--turn",
        "0",
        "--duration",
        "5",
        "--out",
    ];
    args.push(path(&out));
    args.extend_from_slice(more);
    let ran = run(&binary(), &args, dir);
    assert_success("spatial", &ran);
    (out, text(&ran.stdout) + &text(&ran.stderr))
}

/// The column `name` of a CSV file (whose other columns may hold NaN:
/// `spatial.csv`'s turn radius on a straight run).
fn column(file: &Path, name: &str) -> Vec<f64> {
    let text = std::fs::read_to_string(file).expect("the CSV");
    let mut lines = text.lines();
    let at = lines
        .next()
        .expect("a header")
        .split(',')
        .position(|c| c == name)
        .unwrap_or_else(|| panic!("no column {name}"));
    lines
        .map(|l| {
            l.split(',')
                .nth(at)
                .expect("a value")
                .parse()
                .expect("a number")
        })
        .collect()
}

#[test]
fn each_track_takes_its_own_ground() {
    let dir = scratch("grounds");
    let level = dir.join("level.csv");
    std::fs::write(&level, "x,z\n-20,0\n60,0\n").unwrap();
    let ramp = dir.join("ramp.csv");
    std::fs::write(&ramp, "x,z\n-20,0\n3,0\n4,0.08\n5,0.08\n6,0\n60,0\n").unwrap();
    let (left, said) = spatial(
        &dir,
        "left",
        &[
            "--course-file",
            path(&level),
            "--left-course-file",
            path(&ramp),
        ],
    );
    assert!(
        said.contains("under the left track the profile of"),
        "{said}"
    );
    let roll = column(&left.join("spatial.csv"), "roll");
    let most = roll.iter().fold(0.0_f64, |m, &r| m.max(r));
    let least = roll.iter().fold(0.0_f64, |m, &r| m.min(r));
    // The rigid bound: the whole left track 80 mm up across the 2.159 m
    // gauge.
    let rigid = (0.08_f64 / 2.159).atan();
    assert!(
        most > 0.2 * rigid && most < rigid,
        "roll at most {most} rad"
    );
    assert!(least > -0.1 * most, "rolled the other way: {least} rad");
    let bad = dir.join("bad.csv");
    std::fs::write(&bad, "x,z\n0,0\n1,oops\n").unwrap();
    let refused = run(
        &binary(),
        &[
            "spatial",
            "--right-course-file",
            path(&bad),
            "--out",
            path(&dir.join("bad")),
        ],
        &dir,
    );
    assert_rejected("a bad side file", &refused, &["bad.csv:3"]);
}

/// `--field-file`: heights on a grid (an ESRI ASCII grid) with a ridge
/// 80 mm high and 1 m long across x = 3.5–4.5 m under the left half alone
/// rolls the M113 to the right as the ramp under its left track does
/// (between a fifth of and the rigid bound); a hole (the no-data value)
/// is refused naming its line.
#[test]
fn a_height_field_from_a_grid_file_is_driven_over() {
    let dir = scratch("grid");
    let (nx, ny) = (161, 9);
    let mut text = format!(
        "ncols {nx}\nnrows {ny}\nxllcenter -20\nyllcenter -2\ncellsize 0.5\nNODATA_value -9999\n"
    );
    for j in (0..ny).rev() {
        let y = -2.0 + 0.5 * j as f64;
        let row: Vec<String> = (0..nx)
            .map(|i| {
                let x = -20.0 + 0.5 * i as f64;
                let up = y > 0.0 && (3.5..=4.5).contains(&x);
                if up { "0.08" } else { "0" }.to_string()
            })
            .collect();
        text.push_str(&row.join(" "));
        text.push('\n');
    }
    let grid = dir.join("ridge.asc");
    std::fs::write(&grid, &text).unwrap();
    let (out, said) = spatial(&dir, "ridge", &["--field-file", path(&grid)]);
    assert!(said.contains("the height field of"), "{said}");
    let roll = column(&out.join("spatial.csv"), "roll");
    let most = roll.iter().fold(0.0_f64, |m, &r| m.max(r));
    let rigid = (0.08_f64 / 2.159).atan();
    assert!(
        most > 0.2 * rigid && most < rigid,
        "roll at most {most} rad"
    );
    let holed = dir.join("holed.asc");
    std::fs::write(&holed, text.replacen("0.08", "-9999", 1)).unwrap();
    let refused = run(
        &binary(),
        &[
            "spatial",
            "--field-file",
            path(&holed),
            "--out",
            path(&dir.join("holed")),
        ],
        &dir,
    );
    assert_rejected(
        "a grid with a hole",
        &refused,
        &["holed.asc:", "a hole in the field"],
    );
}
