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

mod course;
mod error;
mod file;
mod limits;
mod polyline;
#[cfg(test)]
mod tests;

pub use course::{Course, HALF_ROUND_TOLERANCE, Obstacle};
pub use error::{ParseProblem, PointProblem, ProfileError};
pub use limits::{MAX_COORDINATE, MAX_HEIGHT, MAX_LENGTH, MAX_POINTS, MAX_SLOPE};
pub use polyline::{Corner, Nearest, Profile, SHARP_TURN, Segment};
