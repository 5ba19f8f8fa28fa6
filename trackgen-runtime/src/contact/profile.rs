//! Terrain as a **polyline**: points `(x, z)` in metres whose x never
//! decreases, so that two consecutive points at one x are a **vertical
//! face** (a step, a trench wall). Beyond its ends the ground is flat at
//! the end heights.
//!
//! The obstacles of the mobility events (the NATO Reference Mobility
//! Model's obstacle-crossing events and the next-generation NRMM's
//! benchmark, NATO ET-148, 2016; the guide's "Terrain, obstacles and
//! roughness"): a half-round of radius = height, a step, a gap with
//! vertical walls, trapezoidal ditches and barriers; with grades, and
//! courses of run-in, obstacle and run-out) cannot be
//! written as a height function `z = h(x)`: a vertical face has no height
//! at its x. They are polylines, built here by [`Course`] and
//! [`Obstacle`], read from a CSV file by [`Profile::read_csv`], or made by
//! the random roughness generator (`super::roughness`).
//!
//! # Invariants
//!
//! Every [`Profile`] holds, checked by [`Profile::new`] and the CSV reader:
//!
//! * at least 2 points, every coordinate finite;
//! * x never decreases, `x[i] ≤ x[i+1]`; equal x is a vertical face;
//! * no three consecutive points share one x (one vertical face per x),
//!   and no point repeats the one before it (a face of zero height has no
//!   direction);
//! * the last x exceeds the first (the profile spans a positive length);
//! * at most [`MAX_POINTS`] points.
//!
//! Segment `i` joins points `i` and `i + 1`; it is vertical when their x
//! are equal.
//!
//! # Lookups: a uniform bucket index
//!
//! Every query (the segment under an x, the height, the segments and
//! corners in a range) is stateless and starts from a count of the points
//! at or left of an x, found without scanning or searching the whole
//! course. At construction the span `[x_first, x_last]` is cut into `B`
//! buckets of equal width, and a point or query at `x` falls in bucket
//! `b(x) = clamp(⌊(x − x_first) · (B / span)⌋, 0, B − 1)`, one function used
//! both to build the index and to look up. The index stores, for each
//! bucket `b`, `starts[b]`: the number of points whose bucket is before
//! `b`. So:
//!
//! * **invariant**: the points of bucket `b` are exactly the indices
//!   `starts[b] .. starts[b + 1]`, and the first segment that can contain
//!   an x of bucket `b` is segment `starts[b] − 1` (or 0);
//! * because `b` is non-decreasing in `x` (a subtraction, a multiplication
//!   by a positive number, `floor` and `clamp` are all monotone, rounding
//!   included), every point of an earlier bucket lies strictly left of any
//!   x of bucket `b` and every point of a later bucket strictly right of
//!   it, so the count of points `≤ x` (or `< x`) lies in
//!   `starts[b] ..= starts[b + 1]` and is found among the points of that
//!   one bucket (a binary search over them alone). No rounding can put a
//!   point on the wrong side.
//!
//! `B` is `span / (shortest non-vertical segment)`, kept between the
//! number of segments and the larger of four times it and 65536: one
//! bucket per segment on an evenly spaced course (a rough course, a
//! surveyed profile), and on an obstacle course of a few hundred points
//! (a half-round's facets among long flats) enough that the shortest
//! segments get a bucket each, so a lookup is O(1). Where the spacing
//! varies more than that allows, a bucket holding `k` points costs
//! O(log k). The index costs 4 bytes per bucket.
//!
//! # Which side at a vertical face
//!
//! A height function cannot be both the top and the bottom of a face at
//! the face's x. [`Profile::segment_at`] and
//! [`Profile::height_and_slope`] are **right-continuous**: at any x they
//! use the non-vertical segment whose half-open range `[x_i, x_{i+1})`
//! holds it. Those ranges partition `[x_first, x_last)` exactly, so every
//! x has one surface, never two and never none, found by the same count as
//! every other query with no comparison of heights; a point exactly at a
//! step up is on the top it is about to climb, one exactly at a step down
//! on the bottom it is about to drop to, and `h(x)` is the limit from the
//! right everywhere. It is the convention of `Terrain::Table` (a knot
//! belongs to the segment it starts), and its formula: a profile without
//! vertical faces gives the heights and slopes of a table through the same
//! points (but at the first point itself, where the table takes the flat's
//! slope, 0).
//! Contact with the face itself and with its top and bottom edges does not
//! go through the height: [`Profile::segments_in`] returns the face as a
//! segment and [`Profile::corners_in`] its convex edge, both closed at
//! their ends.
//!
//! # File format
//!
//! [`Profile::read_csv`] and [`Profile::from_csv_reader`] read UTF-8 text,
//! one record a line (`\n` or `\r\n`):
//!
//! * the first record is the header `x,z` (ASCII case ignored), metres;
//! * then one point a line, `x,z`, two decimal numbers as Rust's
//!   `f64::from_str` reads them (`1`, `-0.25`, `1.5e-3`; `inf` and `NaN`
//!   read, then fail the check for finite values), exactly two fields; no
//!   quotes, no other separator, no comment after a point;
//! * spaces and tabs around a field or a line are ignored; blank lines and
//!   lines whose first non-blank character is `#` (comments) are skipped
//!   anywhere, before the header too; a UTF-8 byte-order mark at the start
//!   is skipped; the last line may or may not end in a newline.
//!
//! An error names the file, the line (1-based, as an editor shows it) and
//! what is wrong ([`ParseProblem`]). [`Profile::write_csv`] writes the
//! format back with each number in the shortest form that reads back to
//! the same bits.

use std::io::{self, Read, Write};
use std::path::Path;

use thiserror::Error;

use crate::trig::sin_cos;

#[cfg(test)]
mod tests;

/// The most points a profile holds: its bucket index counts them in `u32`.
pub const MAX_POINTS: usize = u32::MAX as usize;

/// The bucket index may hold this many buckets however few the points
/// (256 KiB), four per segment beyond.
const MIN_BUCKET_CAP: f64 = 65536.0;

/// The largest length of a course piece or width of an obstacle, m
/// (100 km): a bound that catches a unit mistake, not a physical limit.
pub const MAX_LENGTH: f64 = 1e5;

/// The largest height or depth of an obstacle, m.
pub const MAX_HEIGHT: f64 = 100.0;

/// The largest |x| or |z| a course starts at, m.
pub const MAX_COORDINATE: f64 = 1e6;

/// The largest |slope| (rise over run) of a grade: 10, a 1000 % grade
/// (84°).
pub const MAX_SLOPE: f64 = 10.0;

/// How far a half-round's polygon may lie inside its circle, m: 0.1 mm.
/// Its facet count is chosen from the radius so that every facet's
/// sagitta is at most this (see [`Course::half_round`]).
pub const HALF_ROUND_TOLERANCE: f64 = 1e-4;

/// A terrain polyline, flat beyond its ends (see the [module
/// docs](self) for its invariants, the bucket index behind every lookup
/// and the side taken at a vertical face).
#[derive(Debug, Clone, PartialEq)]
pub struct Profile {
    /// Point abscissae, m, non-decreasing.
    x: Vec<f64>,
    /// Point heights, m.
    z: Vec<f64>,
    index: BucketIndex,
    /// The vertices that are sharp convex corners ([`SHARP_TURN`]), in
    /// order: found once, so that contact finds those over a range in
    /// O(log n) plus the ones there.
    sharp: Vec<usize>,
    /// Their vertices `(x, z)`, m, in the same order: contact wants the
    /// points alone.
    sharp_points: Vec<(f64, f64)>,
    /// `sharp_before[j]`: how many sharp corners have a vertex index
    /// below `j` (`n + 1` entries), so that the bucket lookup of a range's
    /// vertices gives its sharp corners in O(1).
    sharp_before: Vec<u32>,
}

/// `sin` of the least turn of the ground at a convex corner that contact
/// treats as a sharp edge against bodies' outlines
/// ([`outline`](super::outline)): 10°. A gentler corner between two
/// ground points 0.12 m apart (the M113's) stands at most
/// `0.06 tan 5° ≈ 5 mm` above their chord, within the ground contact's own
/// penetration (9 mm on the M113 driving), so the ground points carry it.
pub const SHARP_TURN: f64 = 0.173_648_177_666_930_33;

/// The point of a terrain's boundary nearest to a point below it
/// ([`Profile::nearest_boundary`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Nearest {
    /// `(x, z)`, m.
    pub point: (f64, f64),
    /// Its distance from the point below, m: how deep that point is.
    pub distance: f64,
    /// Whether it is a vertex of the polyline (an end of its segment):
    /// the direction to it then turns as the point below moves.
    pub on_vertex: bool,
}

/// Uniform buckets over `[x_first, x_last]` (see the module docs).
#[derive(Debug, Clone, PartialEq)]
struct BucketIndex {
    /// `x_first`, m.
    origin: f64,
    /// Buckets per metre, `B / span` (0 when that overflows: then one
    /// bucket holds every point and lookups are binary searches).
    scale: f64,
    /// `B − 1`.
    last: usize,
    /// `starts[b]`: how many points lie in buckets before `b`;
    /// `B + 1` entries, `starts[0] = 0`, `starts[B] = n`.
    starts: Vec<u32>,
}

impl BucketIndex {
    fn new(x: &[f64]) -> BucketIndex {
        let n = x.len();
        let origin = x[0];
        let span = x[n - 1] - origin;
        let segments = (n - 1) as f64;
        let shortest = x
            .windows(2)
            .map(|w| w[1] - w[0])
            .filter(|&d| d > 0.0)
            .fold(f64::INFINITY, f64::min);
        let wanted = (span / shortest).ceil();
        // `clamp` on floats: `wanted` is finite and ≥ 1, or +∞ (clamped).
        let most = (4.0 * segments).max(MIN_BUCKET_CAP);
        let buckets = wanted.clamp(segments, most) as usize;
        let mut scale = buckets as f64 / span;
        let mut last = buckets - 1;
        if !scale.is_finite() {
            // A span so short that B / span overflows: one bucket.
            scale = 0.0;
            last = 0;
        }
        let mut index = BucketIndex {
            origin,
            scale,
            last,
            starts: vec![0; last + 2],
        };
        for &xi in x {
            let b = index.bucket(xi);
            index.starts[b + 1] += 1;
        }
        for b in 1..index.starts.len() {
            index.starts[b] += index.starts[b - 1];
        }
        index
    }

    /// `b(x)`: non-decreasing in `x`; 0 for NaN (callers handle NaN
    /// first).
    #[inline]
    fn bucket(&self, x: f64) -> usize {
        let t = ((x - self.origin) * self.scale).floor();
        if t >= self.last as f64 {
            self.last
        } else if t >= 0.0 {
            t as usize
        } else {
            0
        }
    }

    /// The points of `x`'s bucket, as an index range.
    #[inline]
    fn range(&self, x: f64) -> (usize, usize) {
        let b = self.bucket(x);
        (self.starts[b] as usize, self.starts[b + 1] as usize)
    }
}

/// A segment of a profile, from `start` to `end` (left to right; a
/// vertical one from the lower or upper end as the polyline runs).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Segment {
    /// `Some(i)`: segment `i` of the polyline, from point `i` to point
    /// `i + 1`. `None`: a piece of the flat extension before the first
    /// point or after the last (see [`Profile::segments_in`]).
    pub index: Option<usize>,
    /// `(x, z)`, m.
    pub start: (f64, f64),
    /// `(x, z)`, m; `end.0 ≥ start.0`.
    pub end: (f64, f64),
}

impl Segment {
    /// Whether it is a vertical face (`start.0 == end.0`).
    pub fn is_vertical(&self) -> bool {
        self.start.0 == self.end.0
    }

    /// Rise over run; ±∞ for a vertical face.
    pub fn slope(&self) -> f64 {
        (self.end.1 - self.start.1) / (self.end.0 - self.start.0)
    }

    /// Its unit direction from `start` to `end`.
    pub fn direction(&self) -> (f64, f64) {
        unit(self.end.0 - self.start.0, self.end.1 - self.start.1)
    }
}

/// A convex corner of a profile: a vertex where the ground, followed left
/// to right with the solid below, turns downward (clockwise) — the top
/// edge of a step, the lips of a trench, a barrier's top edges, the
/// vertices of a half-round's crest.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Corner {
    /// The vertex's index in the profile.
    pub index: usize,
    /// The vertex, `(x, z)` in m.
    pub point: (f64, f64),
    /// Unit direction of the edge arriving at the vertex (left to right);
    /// `(1, 0)` at the first point, where the flat extension arrives.
    pub incoming: (f64, f64),
    /// Unit direction of the edge leaving the vertex; `(1, 0)` at the last
    /// point.
    pub outgoing: (f64, f64),
}

impl Corner {
    /// Sine of the angle the ground turns through at the corner,
    /// `−(incoming × outgoing)`: positive, in (0, 1]. With
    /// [`turn_cos`](Self::turn_cos) it gives the turn in (0, π): 90° at a
    /// step's top edge, a small angle at a half-round's facet or on a fine
    /// rough course.
    pub fn turn_sin(&self) -> f64 {
        self.incoming.1 * self.outgoing.0 - self.incoming.0 * self.outgoing.1
    }

    /// Cosine of the turn, `incoming · outgoing`.
    pub fn turn_cos(&self) -> f64 {
        self.incoming.0 * self.outgoing.0 + self.incoming.1 * self.outgoing.1
    }

    /// Whether the ground turns by more than [`SHARP_TURN`]'s angle here.
    pub fn is_sharp(&self) -> bool {
        self.turn_sin() > SHARP_TURN || self.turn_cos() < 0.0
    }
}

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
    /// A point given to [`Profile::new`] breaks an invariant.
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
enum Whole {
    TooFew(usize),
    NoLength(f64),
    TooMany(usize),
}

/// The running check of a profile's points, one at a time (shared by
/// [`Profile::new`] and the reader).
#[derive(Default)]
struct PointCheck {
    previous: Option<(f64, f64)>,
    /// Whether the last segment is vertical.
    vertical: bool,
}

impl PointCheck {
    #[inline]
    fn next(&mut self, x: f64, z: f64) -> Result<(), PointProblem> {
        if !(x.is_finite() && z.is_finite()) {
            return Err(PointProblem::NonFinite { x, z });
        }
        if let Some((px, pz)) = self.previous {
            if x < px {
                return Err(PointProblem::Decreasing { x, previous: px });
            }
            let vertical = x == px;
            if vertical && self.vertical {
                return Err(PointProblem::ThirdAtOneX { x });
            }
            if vertical && z == pz {
                return Err(PointProblem::Repeated { x, z });
            }
            self.vertical = vertical;
        }
        self.previous = Some((x, z));
        Ok(())
    }
}

impl Profile {
    /// A profile through `points` `(x, z)` (m), checked: the invariants of
    /// the [module docs](self).
    pub fn new(points: Vec<(f64, f64)>) -> Result<Profile, ProfileError> {
        let mut check = PointCheck::default();
        let (mut x, mut z) = (
            Vec::with_capacity(points.len()),
            Vec::with_capacity(points.len()),
        );
        for (index, &(px, pz)) in points.iter().enumerate() {
            check
                .next(px, pz)
                .map_err(|problem| ProfileError::Point { index, problem })?;
            x.push(px);
            z.push(pz);
        }
        Profile::from_checked(x, z).map_err(|whole| match whole {
            Whole::TooFew(n) => ProfileError::TooFewPoints(n),
            Whole::NoLength(x) => ProfileError::NoLength(x),
            Whole::TooMany(n) => ProfileError::TooManyPoints(n),
        })
    }

    /// Points that passed [`PointCheck`] one by one: the whole-profile
    /// checks, then the index.
    fn from_checked(x: Vec<f64>, z: Vec<f64>) -> Result<Profile, Whole> {
        let n = x.len();
        if n < 2 {
            return Err(Whole::TooFew(n));
        }
        if n > MAX_POINTS {
            return Err(Whole::TooMany(n));
        }
        if x[n - 1] <= x[0] {
            return Err(Whole::NoLength(x[0]));
        }
        let index = BucketIndex::new(&x);
        let mut profile = Profile {
            x,
            z,
            index,
            sharp: Vec::new(),
            sharp_points: Vec::new(),
            sharp_before: Vec::new(),
        };
        profile.sharp = (0..n)
            .filter(|&j| profile.corner(j).is_some_and(|c| c.is_sharp()))
            .collect();
        profile.sharp_points = profile
            .sharp
            .iter()
            .map(|&j| (profile.x[j], profile.z[j]))
            .collect();
        let mut before = vec![0u32; n + 1];
        for &j in &profile.sharp {
            before[j + 1] = 1;
        }
        for j in 1..=n {
            before[j] += before[j - 1];
        }
        profile.sharp_before = before;
        Ok(profile)
    }

    /// How many points (≥ 2).
    pub fn point_count(&self) -> usize {
        self.x.len()
    }

    /// Point `i`, `(x, z)` in m.
    ///
    /// # Panics
    /// If `i ≥ point_count()`.
    pub fn point(&self, i: usize) -> (f64, f64) {
        (self.x[i], self.z[i])
    }

    /// The points' x, m, non-decreasing.
    pub fn xs(&self) -> &[f64] {
        &self.x
    }

    /// The points' heights, m.
    pub fn zs(&self) -> &[f64] {
        &self.z
    }

    /// Every point, `(x, z)` in m, left to right.
    pub fn points(&self) -> impl ExactSizeIterator<Item = (f64, f64)> + '_ {
        self.x.iter().copied().zip(self.z.iter().copied())
    }

    /// `(x_first, x_last)`, m: the polyline's extent (flat beyond).
    pub fn x_range(&self) -> (f64, f64) {
        (self.x[0], self.x[self.x.len() - 1])
    }

    /// Segment `i`, from point `i` to point `i + 1`; `None` past the last.
    pub fn segment(&self, i: usize) -> Option<Segment> {
        (i + 1 < self.x.len()).then(|| self.segment_unchecked(i))
    }

    #[inline]
    fn segment_unchecked(&self, i: usize) -> Segment {
        Segment {
            index: Some(i),
            start: (self.x[i], self.z[i]),
            end: (self.x[i + 1], self.z[i + 1]),
        }
    }

    /// How many points have `x_j ≤ x` (the bucket lookup of the module
    /// docs). Not for NaN.
    #[inline]
    fn count_le(&self, x: f64) -> usize {
        let (lo, hi) = self.index.range(x);
        lo + self.x[lo..hi].partition_point(|&xj| xj <= x)
    }

    /// How many points have `x_j < x`. Not for NaN.
    #[inline]
    fn count_lt(&self, x: f64) -> usize {
        let (lo, hi) = self.index.range(x);
        lo + self.x[lo..hi].partition_point(|&xj| xj < x)
    }

    /// The non-vertical segment under `x`: the one whose half-open range
    /// `[x_i, x_{i+1})` holds `x` (at a vertical face's x, the segment
    /// leaving its far end, to the right; see the module docs for why).
    /// `None` outside `[x_first, x_last)`, where the ground is the flat
    /// extension, and for NaN. O(1) on evenly spaced points.
    pub fn segment_at(&self, x: f64) -> Option<Segment> {
        if x.is_nan() {
            return None;
        }
        let p = self.count_le(x);
        (p > 0 && p < self.x.len()).then(|| self.segment_unchecked(p - 1))
    }

    /// `h(x)`, m: [`height_and_slope`](Self::height_and_slope)'s first
    /// half.
    pub fn height(&self, x: f64) -> f64 {
        self.height_and_slope(x).0
    }

    /// `(h(x), h'(x))` of the non-vertical part: on the segment of
    /// [`segment_at`](Self::segment_at), `z_i + s (x − x_i)` with
    /// `s = (z_{i+1} − z_i) / (x_{i+1} − x_i)` (the form `Terrain::Table`
    /// uses, so the same bits); left of the first point `(z_first, 0)`;
    /// at and right of the last `(z_last, 0)`; `(NaN, NaN)` for NaN.
    pub fn height_and_slope(&self, x: f64) -> (f64, f64) {
        if x.is_nan() {
            return (f64::NAN, f64::NAN);
        }
        let n = self.x.len();
        let p = self.count_le(x);
        if p == 0 {
            return (self.z[0], 0.0);
        }
        if p == n {
            return (self.z[n - 1], 0.0);
        }
        let i = p - 1;
        let slope = (self.z[i + 1] - self.z[i]) / (self.x[i + 1] - self.x[i]);
        (self.z[i] + slope * (x - self.x[i]), slope)
    }

    /// Every segment of the ground overlapping the closed range
    /// `[x0, x1]`, vertical faces included, left to right: what contact
    /// detection of a body's outline against the terrain walks.
    ///
    /// A polyline segment is included when its closed x-range meets
    /// `[x0, x1]` (touching at an end counts). Where the range reaches
    /// beyond the polyline, the flat extension is included as a segment
    /// with `index: None`: from `(x0, z_first)` to the first point when
    /// `x0 < x_first`, from the last point to `(x1, z_last)` when
    /// `x1 > x_last` (so each has a positive length). An empty range
    /// (`x0 > x1`, or NaN) yields nothing. O(1) to start, then O(1) per
    /// segment.
    pub fn segments_in(&self, x0: f64, x1: f64) -> impl Iterator<Item = Segment> + '_ {
        let n = self.x.len();
        let (first, last) = self.x_range();
        let valid = x0 <= x1;
        let before = (valid && x0 < first).then(|| Segment {
            index: None,
            start: (x0, self.z[0]),
            end: (first, self.z[0]),
        });
        let after = (valid && x1 > last).then(|| Segment {
            index: None,
            start: (last, self.z[n - 1]),
            end: (x1, self.z[n - 1]),
        });
        let range = if valid {
            let lo = self.count_lt(x0).max(1) - 1;
            let hi = self.count_le(x1).min(n - 1);
            lo..hi.max(lo)
        } else {
            0..0
        };
        before
            .into_iter()
            .chain(range.map(move |i| self.segment_unchecked(i)))
            .chain(after)
    }

    /// The convex corner at vertex `j` (see [`Corner`]), or `None` if the
    /// ground does not turn downward there (a straight or concave vertex)
    /// or `j` is past the last point. The first and last points are
    /// corners when the polyline leaves or meets the flat extension
    /// turning downward.
    pub fn corner(&self, j: usize) -> Option<Corner> {
        let n = self.x.len();
        if j >= n {
            return None;
        }
        let incoming = if j == 0 {
            (1.0, 0.0)
        } else {
            unit(self.x[j] - self.x[j - 1], self.z[j] - self.z[j - 1])
        };
        let outgoing = if j + 1 == n {
            (1.0, 0.0)
        } else {
            unit(self.x[j + 1] - self.x[j], self.z[j + 1] - self.z[j])
        };
        let cross = incoming.0 * outgoing.1 - incoming.1 * outgoing.0;
        (cross < 0.0).then_some(Corner {
            index: j,
            point: (self.x[j], self.z[j]),
            incoming,
            outgoing,
        })
    }

    /// The convex corners whose vertex lies in the closed range
    /// `[x0, x1]`, left to right, with their adjacent edges' directions.
    /// Every vertex where the ground turns downward is one, however small
    /// the turn (a fine rough course has many of a degree or less): filter
    /// by [`Corner::turn_sin`] where only sharp edges matter. An empty
    /// range yields nothing. O(1) to start, then O(1) per vertex in the
    /// range.
    pub fn corners_in(&self, x0: f64, x1: f64) -> impl Iterator<Item = Corner> + '_ {
        let range = if x0 <= x1 {
            let lo = self.count_lt(x0);
            lo..self.count_le(x1).max(lo)
        } else {
            0..0
        };
        range.filter_map(move |j| self.corner(j))
    }

    /// The sharp convex corners ([`Corner::is_sharp`]) whose vertex lies
    /// in `[x0, x1]`, left to right: O(log n) to start (they are listed
    /// when the profile is made), then O(1) each.
    pub fn sharp_corners_in(&self, x0: f64, x1: f64) -> impl Iterator<Item = Corner> + '_ {
        let range = self.sharp_range(x0, x1);
        self.sharp[range].iter().filter_map(|&j| self.corner(j))
    }

    /// As [`sharp_corners_in`](Self::sharp_corners_in), their vertices
    /// `(x, z)` (m) alone: what contact needs, without the edges'
    /// directions.
    pub fn sharp_points_in(&self, x0: f64, x1: f64) -> impl Iterator<Item = (f64, f64)> + '_ {
        self.sharp_points[self.sharp_range(x0, x1)].iter().copied()
    }

    /// Where the sharp corners in `[x0, x1]` are in the lists (empty for
    /// an empty range): the vertices' range by the bucket lookup, then
    /// [`sharp_before`](Self::sharp_before)'s counts, O(1) on evenly
    /// spaced points.
    fn sharp_range(&self, x0: f64, x1: f64) -> std::ops::Range<usize> {
        // NaN compares false: an empty range.
        if x0.partial_cmp(&x1).is_none_or(|o| o.is_gt()) {
            return 0..0;
        }
        let start = self.sharp_before[self.count_lt(x0)] as usize;
        let end = self.sharp_before[self.count_le(x1)] as usize;
        start..end.max(start)
    }

    /// The highest point of the ground over the closed range `[x0, x1]`,
    /// m, for culling: the heights at both ends and every vertex in the
    /// range (both ends of a vertical face at `x0` or `x1` included).
    /// `−∞` for an empty range (`x0 > x1`, or NaN). O(number of segments
    /// in the range).
    pub fn max_height(&self, x0: f64, x1: f64) -> f64 {
        // Written so that NaN, like x0 > x1, is an empty range.
        let range = x0 <= x1;
        if !range {
            return f64::NEG_INFINITY;
        }
        let lo = self.count_lt(x0);
        let hi = self.count_le(x1).max(lo);
        self.z[lo..hi]
            .iter()
            .fold(self.height(x0).max(self.height(x1)), |m, &z| m.max(z))
    }

    /// The point of the terrain's boundary nearest to `(x, y)`, a point
    /// below the surface (`y < h(x)`): `None` on or above it. The boundary
    /// is every segment, vertical faces included, and the flat extensions
    /// beyond the ends; its nearest point lies within the vertical depth
    /// `h(x) − y` of the point (the surface straight above is on it), so
    /// only the segments over `[x − d, x + d]` are looked at. Ties go to
    /// the first segment in order of x, so the answer is the same however
    /// it is asked.
    pub fn nearest_boundary(&self, x: f64, y: f64) -> Option<Nearest> {
        let vertical = self.height(x) - y;
        if vertical.is_nan() || vertical <= 0.0 {
            return None;
        }
        let mut best: Option<Nearest> = None;
        for segment in self.segments_in(x - vertical, x + vertical) {
            let (a, b) = (segment.start, segment.end);
            let (dx, dy) = (b.0 - a.0, b.1 - a.1);
            let length_squared = dx * dx + dy * dy;
            let along = if length_squared > 0.0 {
                (((x - a.0) * dx + (y - a.1) * dy) / length_squared).clamp(0.0, 1.0)
            } else {
                0.0
            };
            let point = (a.0 + along * dx, a.1 + along * dy);
            let (ex, ey) = (point.0 - x, point.1 - y);
            let distance = (ex * ex + ey * ey).sqrt();
            if best.is_none_or(|b| distance < b.distance) {
                best = Some(Nearest {
                    point,
                    distance,
                    on_vertex: along == 0.0 || along == 1.0,
                });
            }
        }
        best
    }

    /// Reads a profile file (see the module docs for the format). Errors
    /// name the path.
    pub fn read_csv(path: impl AsRef<Path>) -> Result<Profile, ProfileError> {
        let path = path.as_ref();
        let name = path.display().to_string();
        match std::fs::read(path) {
            Ok(bytes) => parse_csv(&bytes, &name),
            Err(e) => Err(file_error(&name, &e)),
        }
    }

    /// Reads a profile in the file format from `reader`; errors name it
    /// `name` (a path, or what the caller calls the source).
    pub fn from_csv_reader(mut reader: impl Read, name: &str) -> Result<Profile, ProfileError> {
        let mut bytes = Vec::new();
        reader
            .read_to_end(&mut bytes)
            .map_err(|e| file_error(name, &e))?;
        parse_csv(&bytes, name)
    }

    /// Writes the profile in the file format: the header, then one point a
    /// line, each number in the shortest form that reads back to the same
    /// bits (`-0.0` included).
    pub fn write_csv(&self, writer: impl Write) -> io::Result<()> {
        let mut out = io::BufWriter::new(writer);
        out.write_all(b"x,z\n")?;
        for (x, z) in self.points() {
            writeln!(out, "{x:?},{z:?}")?;
        }
        out.flush()
    }
}

/// `(dx, dz)` scaled to unit length, without overflow or underflow.
fn unit(dx: f64, dz: f64) -> (f64, f64) {
    let m = dx.abs().max(dz.abs());
    let (a, b) = (dx / m, dz / m);
    let l = (a * a + b * b).sqrt();
    (a / l, b / l)
}

fn file_error(name: &str, e: &io::Error) -> ProfileError {
    ProfileError::File {
        file: name.to_owned(),
        kind: e.kind(),
        message: e.to_string(),
    }
}

/// A field or line for an error message: its first 40 characters.
fn excerpt(bytes: &[u8]) -> String {
    let text = String::from_utf8_lossy(bytes);
    let mut chars = text.chars();
    let head: String = chars.by_ref().take(40).collect();
    if chars.next().is_some() {
        head + "…"
    } else {
        head
    }
}

/// `` `text` ``, or "empty".
fn quoted(text: &str) -> String {
    if text.is_empty() {
        "empty".to_owned()
    } else {
        format!("`{text}`")
    }
}

/// Whether `line` is the header `x,z`.
fn is_header(line: &[u8]) -> bool {
    let mut fields = line.split(|&b| b == b',').map(<[u8]>::trim_ascii);
    matches!(
        (fields.next(), fields.next(), fields.next()),
        (Some(x), Some(z), None) if x.eq_ignore_ascii_case(b"x") && z.eq_ignore_ascii_case(b"z")
    )
}

/// A field as a number.
#[inline]
fn number(field: &[u8], column: &'static str) -> Result<f64, ParseProblem> {
    let field = field.trim_ascii();
    std::str::from_utf8(field)
        .ok()
        .and_then(|s| s.parse::<f64>().ok())
        .ok_or_else(|| ParseProblem::NotANumber {
            column,
            text: excerpt(field),
        })
}

/// A point line, `x,z`.
#[inline]
fn point(line: &[u8]) -> Result<(f64, f64), ParseProblem> {
    let Some(comma) = line.iter().position(|&b| b == b',') else {
        return Err(ParseProblem::FieldCount(1));
    };
    let (fx, fz) = (&line[..comma], &line[comma + 1..]);
    let more = fz.iter().filter(|&&b| b == b',').count();
    if more > 0 {
        return Err(ParseProblem::FieldCount(2 + more));
    }
    Ok((number(fx, "x")?, number(fz, "z")?))
}

/// The reader proper: one pass over the lines, each point checked as it
/// comes.
fn parse_csv(bytes: &[u8], name: &str) -> Result<Profile, ProfileError> {
    let error = |line, problem| ProfileError::Parse {
        file: name.to_owned(),
        line,
        problem,
    };
    let bytes = bytes.strip_prefix(b"\xEF\xBB\xBF").unwrap_or(bytes);
    // About 20 bytes a point on a long course.
    let capacity = bytes.len() / 16;
    let (mut x, mut z) = (Vec::with_capacity(capacity), Vec::with_capacity(capacity));
    let mut check = PointCheck::default();
    let mut header = false;
    // The last line with any text (a comment counts), and the last record.
    let (mut last_text, mut last_record) = (1, 1);
    for (i, raw) in bytes.split(|&b| b == b'\n').enumerate() {
        let line_no = i + 1;
        let line = raw.trim_ascii();
        if line.is_empty() {
            continue;
        }
        last_text = line_no;
        if line[0] == b'#' {
            continue;
        }
        last_record = line_no;
        if !header {
            if !is_header(line) {
                let problem = if point(line).is_ok() {
                    ParseProblem::MissingHeader(excerpt(line))
                } else {
                    ParseProblem::WrongHeader(excerpt(line))
                };
                return Err(error(line_no, problem));
            }
            header = true;
            continue;
        }
        let (px, pz) = point(line).map_err(|p| error(line_no, p))?;
        check
            .next(px, pz)
            .map_err(|p| error(line_no, ParseProblem::Point(p)))?;
        x.push(px);
        z.push(pz);
    }
    if !header {
        return Err(error(last_text, ParseProblem::Empty));
    }
    Profile::from_checked(x, z).map_err(|whole| {
        let problem = match whole {
            Whole::TooFew(n) => ParseProblem::TooFewPoints(n),
            Whole::NoLength(x) => ParseProblem::NoLength(x),
            Whole::TooMany(_) => ParseProblem::TooManyPoints,
        };
        error(last_record, problem)
    })
}

/// An obstacle of the mobility events (NRMM and NG-NRMM, NATO ET-148,
/// 2016; the guide's "Obstacle courses"), for
/// [`Course::then`] and [`Obstacle::course`]. Lengths in m; each is
/// range-checked when it is laid (the ranges are in [`Course`]'s methods).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Obstacle {
    /// [`Course::half_round`].
    HalfRound {
        /// Radius = height, m.
        radius: f64,
    },
    /// [`Course::step`].
    Step {
        /// m; up if positive, down if negative.
        height: f64,
    },
    /// [`Course::gap`].
    Gap {
        /// m.
        width: f64,
        /// m.
        depth: f64,
    },
    /// [`Course::ditch`].
    Ditch {
        /// m.
        depth: f64,
        /// m.
        bottom_width: f64,
        /// From the horizontal, degrees, in (0, 90].
        wall_angle: f64,
    },
    /// [`Course::barrier`].
    Barrier {
        /// m.
        height: f64,
        /// m.
        top_width: f64,
        /// From the horizontal, degrees, in (0, 90].
        wall_angle: f64,
    },
    /// [`Course::grade`].
    Grade {
        /// Rise over run.
        slope: f64,
        /// Horizontal run, m.
        length: f64,
    },
}

impl Obstacle {
    /// The course of a mobility event: from `(0, 0)` a flat run-in of
    /// `run_in` m, the obstacle, a flat run-out of `run_out` m.
    pub fn course(&self, run_in: f64, run_out: f64) -> Result<Profile, ProfileError> {
        Course::new()
            .flat(run_in)?
            .then(self)?
            .flat(run_out)?
            .profile()
    }
}

/// A course laid left to right, each piece starting where the last ended
/// (its x and height): `Course::new().flat(20.0)?.step(0.3)?.flat(20.0)?
/// .profile()?`.
///
/// Every argument is range-checked; an error names the piece, the
/// parameter and its allowed range ([`ProfileError::Parameter`]). The
/// bounds beyond the physical ones (positive widths, angles up to 90°) are
/// sanity bounds that catch a unit mistake: lengths and widths up to
/// [`MAX_LENGTH`], heights and depths up to [`MAX_HEIGHT`].
///
/// Vertical pieces laid one after another at one x (a step, then a gap's
/// first wall) merge into one face, as the ground they describe has one
/// (a wall of zero thickness holds no material); a face that merges to
/// zero height disappears.
#[derive(Debug, Clone, PartialEq)]
pub struct Course {
    points: Vec<(f64, f64)>,
}

impl Default for Course {
    fn default() -> Self {
        Course::new()
    }
}

/// `Ok` if `ok`, else the parameter's error.
fn check(
    ok: bool,
    shape: &'static str,
    parameter: &'static str,
    value: f64,
    allowed: &'static str,
) -> Result<(), ProfileError> {
    if ok {
        Ok(())
    } else {
        Err(ProfileError::Parameter {
            shape,
            parameter,
            value,
            allowed,
        })
    }
}

/// `0 < v ≤ hi` (false for NaN).
fn positive_up_to(v: f64, hi: f64) -> bool {
    v > 0.0 && v <= hi
}

impl Course {
    /// A course starting at `(0, 0)`.
    pub fn new() -> Course {
        Course {
            points: vec![(0.0, 0.0)],
        }
    }

    /// A course starting at `(x, z)`, m; `|x|, |z| ≤ 1e6` m
    /// ([`MAX_COORDINATE`]).
    pub fn starting_at(x: f64, z: f64) -> Result<Course, ProfileError> {
        let ok = |v: f64| v.abs() <= MAX_COORDINATE;
        check(ok(x), "course", "start x", x, "|x| ≤ 1e6 m")?;
        check(ok(z), "course", "start z", z, "|z| ≤ 1e6 m")?;
        Ok(Course {
            points: vec![(x, z)],
        })
    }

    /// Where the course ends so far, `(x, z)` in m.
    pub fn end(&self) -> (f64, f64) {
        self.points[self.points.len() - 1]
    }

    /// Adds a point, merging consecutive vertical pieces at one x.
    fn push(&mut self, x: f64, z: f64) {
        let n = self.points.len();
        let (lx, lz) = self.points[n - 1];
        if x == lx {
            if n >= 2 && self.points[n - 2].0 == x {
                self.points[n - 1].1 = z;
                if self.points[n - 2].1 == z {
                    self.points.pop();
                }
                return;
            }
            if z == lz {
                return;
            }
        }
        self.points.push((x, z));
    }

    /// Flat ground, `0 < length ≤ 1e5` m: a run-in or run-out.
    pub fn flat(mut self, length: f64) -> Result<Course, ProfileError> {
        let ok = positive_up_to(length, MAX_LENGTH);
        check(ok, "flat", "length", length, "0 < length ≤ 1e5 m")?;
        let (x, z) = self.end();
        self.push(x + length, z);
        Ok(self)
    }

    /// A half-round obstacle: a half cylinder of radius = height,
    /// `0 < radius ≤ 100` m, `2 radius` long, as a polygon inscribed in
    /// the circle, its vertices on it.
    ///
    /// `n` facets (even, so that the crest `(x + r, z + r)` is a vertex)
    /// each span π/n of the circle; a facet's sagitta
    /// `r (1 − cos(π / 2n)) ≤ r (π / 2n)² / 2` is at most
    /// [`HALF_ROUND_TOLERANCE`] (0.1 mm) when
    /// `n ≥ π / (2 √(2 · 0.1 mm / r))`, the count used: 26 facets for a
    /// 2 in (0.0508 m) radius, 98 for 30 in (0.762 m). The vertices are
    /// mirrored about the crest; the crest and both feet are exact.
    pub fn half_round(mut self, radius: f64) -> Result<Course, ProfileError> {
        let ok = positive_up_to(radius, MAX_HEIGHT);
        check(ok, "half-round", "radius", radius, "0 < radius ≤ 100 m")?;
        let r = radius;
        let n = half_round_facets(r);
        let (x, z) = self.end();
        let centre = x + r;
        // Vertex k at angle π − kπ/n: (centre − r cos(kπ/n), z + r sin(kπ/n)).
        let offsets: Vec<(f64, f64)> = (1..n / 2)
            .map(|k| {
                let (s, c) = sin_cos(k as f64 * std::f64::consts::PI / n as f64);
                (r * c, r * s)
            })
            .collect();
        for &(dx, dz) in &offsets {
            self.push(centre - dx, z + dz);
        }
        self.push(centre, z + r);
        for &(dx, dz) in offsets.iter().rev() {
            self.push(centre + dx, z + dz);
        }
        self.push(centre + r, z);
        Ok(self)
    }

    /// A step: a vertical face of `height` m, up if positive, down if
    /// negative; `0 < |height| ≤ 100` m.
    pub fn step(mut self, height: f64) -> Result<Course, ProfileError> {
        let ok = positive_up_to(height.abs(), MAX_HEIGHT);
        check(ok, "step", "height", height, "0 < |height| ≤ 100 m")?;
        let (x, z) = self.end();
        self.push(x, z + height);
        Ok(self)
    }

    /// A gap (trench) with vertical walls, `width` (`0 < width ≤ 1e5` m)
    /// and `depth` (`0 < depth ≤ 100` m); the ground continues at the
    /// starting height.
    pub fn gap(mut self, width: f64, depth: f64) -> Result<Course, ProfileError> {
        let ok = positive_up_to(width, MAX_LENGTH);
        check(ok, "gap", "width", width, "0 < width ≤ 1e5 m")?;
        let ok = positive_up_to(depth, MAX_HEIGHT);
        check(ok, "gap", "depth", depth, "0 < depth ≤ 100 m")?;
        let (x, z) = self.end();
        self.push(x, z - depth);
        self.push(x + width, z - depth);
        self.push(x + width, z);
        Ok(self)
    }

    /// A trapezoidal ditch: `depth` (`0 < depth ≤ 100` m), `bottom_width`
    /// (`0 < bottom_width ≤ 1e5` m) and `wall_angle` from the horizontal
    /// in degrees, `0 < wall_angle ≤ 90` (90: vertical walls, a gap). Each
    /// wall runs `depth / tan(wall_angle)`; the top width is
    /// `bottom_width + 2 depth / tan(wall_angle)`, the cross-section
    /// `depth (bottom_width + depth / tan(wall_angle))`.
    pub fn ditch(
        self,
        depth: f64,
        bottom_width: f64,
        wall_angle: f64,
    ) -> Result<Course, ProfileError> {
        let ok = positive_up_to(depth, MAX_HEIGHT);
        check(ok, "ditch", "depth", depth, "0 < depth ≤ 100 m")?;
        let ok = positive_up_to(bottom_width, MAX_LENGTH);
        let allowed = "0 < bottom_width ≤ 1e5 m";
        check(ok, "ditch", "bottom_width", bottom_width, allowed)?;
        let ok = positive_up_to(wall_angle, 90.0);
        let allowed = "0 < wall_angle ≤ 90 degrees";
        check(ok, "ditch", "wall_angle", wall_angle, allowed)?;
        Ok(self.trapezoid(-depth, bottom_width, wall_angle))
    }

    /// A trapezoidal barrier: `height` (`0 < height ≤ 100` m),
    /// `top_width` (`0 < top_width ≤ 1e5` m) and `wall_angle` from the
    /// horizontal in degrees, `0 < wall_angle ≤ 90` (90: vertical walls).
    /// Each wall runs `height / tan(wall_angle)`; the cross-section is
    /// `height (top_width + height / tan(wall_angle))`.
    pub fn barrier(
        self,
        height: f64,
        top_width: f64,
        wall_angle: f64,
    ) -> Result<Course, ProfileError> {
        let ok = positive_up_to(height, MAX_HEIGHT);
        check(ok, "barrier", "height", height, "0 < height ≤ 100 m")?;
        let ok = positive_up_to(top_width, MAX_LENGTH);
        let allowed = "0 < top_width ≤ 1e5 m";
        check(ok, "barrier", "top_width", top_width, allowed)?;
        let ok = positive_up_to(wall_angle, 90.0);
        let allowed = "0 < wall_angle ≤ 90 degrees";
        check(ok, "barrier", "wall_angle", wall_angle, allowed)?;
        Ok(self.trapezoid(height, top_width, wall_angle))
    }

    /// A wall up (`rise > 0`) or down, a flat of `width`, a wall back.
    fn trapezoid(mut self, rise: f64, width: f64, wall_angle: f64) -> Course {
        let run = if wall_angle == 90.0 {
            0.0
        } else {
            let (s, c) = sin_cos(wall_angle * (std::f64::consts::PI / 180.0));
            rise.abs() * c / s
        };
        let (x, z) = self.end();
        let (x1, x2) = (x + run, x + run + width);
        self.push(x1, z + rise);
        self.push(x2, z + rise);
        self.push(x2 + run, z);
        self
    }

    /// A grade: `slope` rise over run (`|slope| ≤ 10`, negative for a
    /// descent) over a horizontal run of `length` m (`0 < length ≤ 1e5`);
    /// it ends `slope · length` higher.
    pub fn grade(mut self, slope: f64, length: f64) -> Result<Course, ProfileError> {
        let ok = slope.abs() <= MAX_SLOPE;
        check(ok, "grade", "slope", slope, "|slope| ≤ 10 (rise over run)")?;
        let ok = positive_up_to(length, MAX_LENGTH);
        check(ok, "grade", "length", length, "0 < length ≤ 1e5 m")?;
        let (x, z) = self.end();
        self.push(x + length, z + slope * length);
        Ok(self)
    }

    /// Lays `obstacle` (by its method above).
    pub fn then(self, obstacle: &Obstacle) -> Result<Course, ProfileError> {
        match *obstacle {
            Obstacle::HalfRound { radius } => self.half_round(radius),
            Obstacle::Step { height } => self.step(height),
            Obstacle::Gap { width, depth } => self.gap(width, depth),
            Obstacle::Ditch {
                depth,
                bottom_width,
                wall_angle,
            } => self.ditch(depth, bottom_width, wall_angle),
            Obstacle::Barrier {
                height,
                top_width,
                wall_angle,
            } => self.barrier(height, top_width, wall_angle),
            Obstacle::Grade { slope, length } => self.grade(slope, length),
        }
    }

    /// The course as a profile, checked like any other (a course of one
    /// step and nothing else, for one, spans no length).
    pub fn profile(self) -> Result<Profile, ProfileError> {
        Profile::new(self.points)
    }
}

/// The facet count of a half-round of radius `r` (see
/// [`Course::half_round`]): even, at least 2.
fn half_round_facets(r: f64) -> usize {
    let n = (std::f64::consts::PI / (2.0 * (2.0 * HALF_ROUND_TOLERANCE / r).sqrt())).ceil();
    let n = (n as usize).max(2);
    n + n % 2
}
