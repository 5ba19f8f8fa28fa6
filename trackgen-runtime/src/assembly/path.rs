//! A closed belt path made of pieces of constant curvature (arcs on the
//! wheels, straight or sagging spans between them), parametrised by arc
//! length, and the chord search that lays joints along it.

use nalgebra::Vector2;

use crate::planar::perp;

/// A wheel the track wraps, as its pitch circle: the circle the joints lie
/// on where the track runs round it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PitchCircle {
    /// Centre, global frame, m.
    pub centre: Vector2<f64>,
    /// Radius, m.
    pub radius: f64,
}

/// A piece of constant curvature, from its start point and unit tangent.
///
/// Written from the start point rather than a centre so that a nearly
/// straight span (a sag of tiny curvature, a centre kilometres away) loses
/// no precision: the point at arc length `u` is
/// `start + t·sin(κu)/κ + n·(1 − cos κu)/κ` with `n` the left normal,
/// each term evaluated through `sinc` so that `κ → 0` is the straight line.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Piece {
    pub start: Vector2<f64>,
    /// Unit tangent at the start.
    pub tangent: Vector2<f64>,
    /// Signed curvature, 1/m: positive turns left (counter-clockwise).
    pub curvature: f64,
    /// Arc length, m.
    pub length: f64,
}

/// `sin(x)/x`, exact to rounding near 0.
fn sinc(x: f64) -> f64 {
    if x.abs() < 1e-4 {
        1.0 - x * x / 6.0
    } else {
        x.sin() / x
    }
}

/// `asin(x)/x`, exact to rounding near 0 (`|x| ≤ 1`).
pub(crate) fn asinc(x: f64) -> f64 {
    if x.abs() < 1e-4 {
        1.0 + x * x / 6.0
    } else {
        x.asin() / x
    }
}

impl Piece {
    /// A straight piece from `from` to `to`.
    pub fn line(from: Vector2<f64>, to: Vector2<f64>) -> Piece {
        let d = to - from;
        let length = d.norm();
        Piece {
            start: from,
            tangent: if length > 0.0 {
                d / length
            } else {
                Vector2::x()
            },
            curvature: 0.0,
            length,
        }
    }

    /// The point and unit tangent at arc length `u` from the start.
    pub fn at(&self, u: f64) -> (Vector2<f64>, Vector2<f64>) {
        let k = self.curvature;
        let half = 0.5 * k * u;
        // sin(ku)/k and (1 − cos ku)/k = 2 sin²(ku/2)/k, without dividing
        // by a tiny k.
        let along = u * sinc(2.0 * half);
        let across = u * half.sin() * sinc(half);
        let normal = perp(self.tangent);
        let (s, c) = (k * u).sin_cos();
        (
            self.start + self.tangent * along + normal * across,
            self.tangent * c + normal * s,
        )
    }

    /// The smallest arc length `u` in `[from, length]` at which the piece
    /// leaves the circle of radius `reach` about `centre`, given that the
    /// point at `from` is inside it (or on it). `None` if the piece ends
    /// inside.
    ///
    /// The squared distance along a piece of constant curvature shorter
    /// than a turn crosses the circle at most twice, once going out, so
    /// with the start inside and the end outside there is one crossing;
    /// Newton's method on it, kept inside the bracket by bisection,
    /// converges in a few steps.
    pub fn exit(&self, centre: Vector2<f64>, reach: f64, from: f64) -> Option<f64> {
        let f = |u: f64| {
            let (p, t) = self.at(u);
            let d = p - centre;
            (d.norm_squared() - reach * reach, 2.0 * d.dot(&t))
        };
        let (mut lo, mut hi) = (from, self.length);
        if f(hi).0 < 0.0 {
            return None;
        }
        let tolerance = 1e-15 * reach.max(self.length);
        // Start from the straight-line estimate.
        let (p, t) = self.at(lo);
        let d = p - centre;
        let b = d.dot(&t);
        let mut u = lo + (-b + (b * b - d.norm_squared() + reach * reach).max(0.0).sqrt());
        if !(u > lo && u < hi) {
            u = 0.5 * (lo + hi);
        }
        for _ in 0..100 {
            let (value, slope) = f(u);
            if value < 0.0 {
                lo = u;
            } else {
                hi = u;
            }
            let newton = u - value / slope;
            let next = if slope > 0.0 && newton > lo && newton < hi {
                newton
            } else {
                0.5 * (lo + hi)
            };
            if (next - u).abs() <= tolerance || hi - lo <= tolerance {
                return Some(next);
            }
            u = next;
        }
        Some(u)
    }
}

/// A closed path, parametrised by arc length from the start of its first
/// piece.
#[derive(Debug, Clone)]
pub(crate) struct Path {
    pub pieces: Vec<Piece>,
    length: f64,
}

/// A place on a path: the piece, and the arc length into it.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Place {
    pub piece: usize,
    pub along: f64,
    /// Whole turns of the path already run (a track longer than its path
    /// wraps past the start).
    pub laps: usize,
}

impl Path {
    pub fn new(pieces: Vec<Piece>) -> Path {
        let length = pieces.iter().map(|p| p.length).sum();
        Path { pieces, length }
    }

    pub fn length(&self) -> f64 {
        self.length
    }

    pub fn point(&self, place: Place) -> Vector2<f64> {
        self.pieces[place.piece].at(place.along).0
    }

    /// The arc length from the path's start to `place`, laps included.
    pub fn arc_length(&self, place: Place) -> f64 {
        place.laps as f64 * self.length
            + self.pieces[..place.piece]
                .iter()
                .map(|p| p.length)
                .sum::<f64>()
            + place.along
    }

    /// The first place after `from` that is `chord` (m) from the point at
    /// `from`: where the next joint of a link of that pitch lands.
    pub fn next_joint(&self, from: Place, chord: f64) -> Place {
        let centre = self.point(from);
        let mut place = from;
        // Two laps at most: a chord never spans more than the whole path
        // once the search has left its first piece.
        for _ in 0..2 * self.pieces.len() + 1 {
            if let Some(along) = self.pieces[place.piece].exit(centre, chord, place.along) {
                return Place { along, ..place };
            }
            place = if place.piece + 1 == self.pieces.len() {
                Place {
                    piece: 0,
                    along: 0.0,
                    laps: place.laps + 1,
                }
            } else {
                Place {
                    piece: place.piece + 1,
                    along: 0.0,
                    ..place
                }
            };
        }
        // A chord longer than the path's extent: nowhere on it.
        Place {
            along: f64::INFINITY,
            ..place
        }
    }
}
