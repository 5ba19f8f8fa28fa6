//! Running a program of the workspace (an example, the main job) and
//! reading what it wrote: shared by the facade's tests of the examples
//! and the main job's own tests (`trackgen-cli/tests/main_job.rs`
//! includes this file).
#![allow(dead_code)]

use std::collections::BTreeSet;
use std::path::{Path, PathBuf};
use std::process::{Command, Output};

/// The output interval every example records at (`Output::Every(0.01)`).
pub const INTERVAL: f64 = 0.01;
/// Slack on output times: `f64` arithmetic on multiples of the interval.
pub const TIME_SLACK: f64 = 1e-9;

/// An empty folder of this test's own.
pub fn scratch(case: &str) -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR"))
        .join("programs")
        .join(case);
    if dir.exists() {
        std::fs::remove_dir_all(&dir).expect("clear the scratch folder");
    }
    std::fs::create_dir_all(&dir).expect("create the scratch folder");
    dir
}

pub fn run(binary: &Path, args: &[&str], cwd: &Path) -> Output {
    Command::new(binary)
        .args(args)
        .current_dir(cwd)
        .output()
        .unwrap_or_else(|e| panic!("{} does not start: {e}", binary.display()))
}

pub fn text(bytes: &[u8]) -> String {
    String::from_utf8_lossy(bytes).into_owned()
}

/// Fails with the example's own output when it did not succeed.
pub fn assert_success(what: &str, out: &Output) {
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
pub fn assert_rejected(what: &str, out: &Output, mentions: &[&str]) {
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
pub struct Csv {
    /// The column names.
    pub header: Vec<String>,
    /// The rows, one number per column.
    pub rows: Vec<Vec<f64>>,
}

impl Csv {
    /// Reads `path`: a header of distinct, non-empty names, then rows of as
    /// many finite numbers.
    pub fn read(path: &Path) -> Csv {
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

    pub fn column(&self, name: &str) -> Vec<f64> {
        let k = self
            .header
            .iter()
            .position(|h| h == name)
            .unwrap_or_else(|| panic!("no column {name:?} in {:?}", self.header));
        self.rows.iter().map(|r| r[k]).collect()
    }

    /// The time column `t` comes first, starts at 0, increases by at most
    /// the output interval, and ends at `end`.
    pub fn check_times(&self, what: &str, end: f64) -> Vec<f64> {
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
pub fn check_svg(path: &Path) {
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
