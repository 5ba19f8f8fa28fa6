//! Why a profile cannot be built or read.

use std::io;

use thiserror::Error;

use super::limits::MAX_POINTS;

/// A profile that cannot be built or read.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum ProfileError {
    /// The file (or reader) could not be opened or read.
    #[error("{file}: cannot read the profile: {message}")]
    File {
        /// The file's path, or the name given to the reader.
        file: String,
        /// The I/O error's kind.
        kind: io::ErrorKind,
        /// The I/O error's message.
        message: String,
    },
    /// A line of a profile file is wrong.
    #[error("{file}:{line}: {problem}")]
    Parse {
        /// The file's path, or the name given to the reader.
        file: String,
        /// The line, 1-based.
        line: usize,
        /// What is wrong.
        problem: ParseProblem,
    },
    /// A point given to [`Profile::new`](super::Profile::new) breaks an invariant.
    #[error("profile point {index}: {problem}")]
    Point {
        /// The point's index, 0-based.
        index: usize,
        /// What is wrong.
        problem: PointProblem,
    },
    /// Fewer than 2 points.
    #[error("a profile needs at least 2 points, got {0}")]
    TooFewPoints(usize),
    /// Every point at one x.
    #[error("a profile must span a positive length: all its points are at x = {0} m")]
    NoLength(f64),
    /// More than [`MAX_POINTS`] points.
    #[error("a profile holds at most {MAX_POINTS} points, got {0}")]
    TooManyPoints(usize),
    /// A parameter of a course piece or obstacle out of its range.
    #[error("{shape}: {parameter} = {value} is outside its range {allowed}")]
    Parameter {
        /// The piece (`"half-round"`, `"ditch"`, …).
        shape: &'static str,
        /// The parameter (`"radius"`, `"wall_angle"`, …).
        parameter: &'static str,
        /// Its value.
        value: f64,
        /// The allowed range, with its unit.
        allowed: &'static str,
    },
}

/// What is wrong with a line of a profile file.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum ParseProblem {
    /// Nothing but blank and comment lines: no header.
    #[error("no header `x,z`: the file is empty or holds only blank and comment lines")]
    Empty,
    /// The first record is a point, not the header.
    #[error("no header: the first record `{0}` is a point; a profile file starts with `x,z`")]
    MissingHeader(String),
    /// The first record is neither the header nor a point.
    #[error("the header is `{0}`, not `x,z`")]
    WrongHeader(String),
    /// A point line with other than two fields.
    #[error("{0} field(s); a point is two, `x,z`")]
    FieldCount(usize),
    /// A field that is not a number.
    #[error("{column} is {}, not a number", quoted(text))]
    NotANumber {
        /// `"x"` or `"z"`.
        column: &'static str,
        /// The field (its first 40 characters).
        text: String,
    },
    /// A point that breaks an invariant.
    #[error(transparent)]
    Point(PointProblem),
    /// The file ends with fewer than 2 points (named at its last point,
    /// or at the header when it has none).
    #[error("the file ends after {0} point(s); a profile needs at least 2")]
    TooFewPoints(usize),
    /// Every point at one x (named at the last point).
    #[error("all points are at x = {0} m; a profile must span a positive length")]
    NoLength(f64),
    /// More than [`MAX_POINTS`] points.
    #[error("more than {MAX_POINTS} points")]
    TooManyPoints,
}

/// A point that breaks a profile's invariants.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum PointProblem {
    /// NaN or infinite.
    #[error("x = {x} m, z = {z} m: not finite")]
    NonFinite {
        /// m.
        x: f64,
        /// m.
        z: f64,
    },
    /// x less than the previous point's.
    #[error("x = {x} m decreases: the previous point is at x = {previous} m")]
    Decreasing {
        /// m.
        x: f64,
        /// The previous point's x, m.
        previous: f64,
    },
    /// The third consecutive point at one x.
    #[error(
        "a third point at x = {x} m: one vertical face per x (two consecutive points at one x)"
    )]
    ThirdAtOneX {
        /// m.
        x: f64,
    },
    /// The same point as the previous one.
    #[error("({x}, {z}) repeats the previous point")]
    Repeated {
        /// m.
        x: f64,
        /// m.
        z: f64,
    },
}

/// What makes a checked sequence of points not a profile.
pub(super) enum Whole {
    TooFew(usize),
    NoLength(f64),
    TooMany(usize),
}

/// `` `text` ``, or "empty".
pub(super) fn quoted(text: &str) -> String {
    if text.is_empty() {
        "empty".to_owned()
    } else {
        format!("`{text}`")
    }
}
