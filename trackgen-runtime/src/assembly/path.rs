//! The closed belt path around a set of wheels: outer tangent lines and
//! wrap arcs, one span optionally sagging as a circular arc.

use nalgebra::Vector2;

/// A piece of the path.
#[derive(Debug, Clone, Copy)]
pub(crate) enum Piece {
    Line {
        from: Vector2<f64>,
        to: Vector2<f64>,
    },
    /// Positive sweep is counter-clockwise, rad.
    Arc {
        centre: Vector2<f64>,
        radius: f64,
        start: f64,
        sweep: f64,
    },
}

impl Piece {
    pub fn length(&self) -> f64 {
        match *self {
            Piece::Line { from, to } => (to - from).norm(),
            Piece::Arc { radius, sweep, .. } => radius * sweep.abs(),
        }
    }

    pub fn at(&self, s: f64) -> Vector2<f64> {
        match *self {
            Piece::Line { from, to } => {
                from + (to - from) * (s / self.length().max(f64::MIN_POSITIVE))
            }
            Piece::Arc {
                centre,
                radius,
                start,
                sweep,
            } => {
                let a = start + sweep.signum() * s / radius;
                centre + Vector2::new(a.cos(), a.sin()) * radius
            }
        }
    }
}

/// A closed path, parametrised by arc length.
#[derive(Debug, Clone)]
pub(crate) struct Path {
    pieces: Vec<Piece>,
    starts: Vec<f64>,
    length: f64,
}

impl Path {
    pub fn new(pieces: Vec<Piece>) -> Path {
        let mut starts = Vec::with_capacity(pieces.len());
        let mut length = 0.0;
        for p in &pieces {
            starts.push(length);
            length += p.length();
        }
        Path {
            pieces,
            starts,
            length,
        }
    }

    pub fn length(&self) -> f64 {
        self.length
    }

    /// The point at arc length `s` (taken modulo the length).
    pub fn at(&self, s: f64) -> Vector2<f64> {
        let s = s.rem_euclid(self.length);
        let i = self
            .starts
            .partition_point(|&start| start <= s)
            .saturating_sub(1);
        self.pieces[i].at(s - self.starts[i])
    }
}

/// The points where the outer tangent from circle A to circle B touches
/// them, for a path running from A to B with both circles on its left.
pub(crate) fn outer_tangent(
    a: (Vector2<f64>, f64),
    b: (Vector2<f64>, f64),
) -> (Vector2<f64>, Vector2<f64>) {
    let d = b.0 - a.0;
    let l = d.norm();
    let u = d / l;
    let right = Vector2::new(u.y, -u.x);
    let cos = (a.1 - b.1) / l;
    let sin = (1.0 - cos * cos).max(0.0).sqrt();
    let n = u * cos + right * sin;
    (a.0 + n * a.1, b.0 + n * b.1)
}

/// The counter-clockwise angle from `from` to `to` about `centre`, in
/// `[0, 2π)`.
pub(crate) fn ccw_sweep(centre: Vector2<f64>, from: Vector2<f64>, to: Vector2<f64>) -> (f64, f64) {
    let a0 = (from - centre).y.atan2((from - centre).x);
    let a1 = (to - centre).y.atan2((to - centre).x);
    let sweep = (a1 - a0).rem_euclid(2.0 * std::f64::consts::PI);
    // Collinear neighbours: arriving and leaving at the same point is no
    // wrap at all, whichever side rounding puts it.
    (
        a0,
        if sweep > 2.0 * std::f64::consts::PI - 1e-9 {
            0.0
        } else {
            sweep
        },
    )
}

/// A circular arc from `p` to `q` bulging `sag` (m) to the left of the
/// chord (inwards for a counter-clockwise loop).
pub(crate) fn sag_arc(p: Vector2<f64>, q: Vector2<f64>, sag: f64) -> Piece {
    if sag <= 0.0 {
        return Piece::Line { from: p, to: q };
    }
    let chord = q - p;
    let c = chord.norm();
    let radius = (c * c / 4.0 + sag * sag) / (2.0 * sag);
    let u = chord / c;
    let right = Vector2::new(u.y, -u.x);
    let centre = (p + q) / 2.0 + right * (radius - sag);
    let a0 = (p - centre).y.atan2((p - centre).x);
    let half = (c / (2.0 * radius)).clamp(-1.0, 1.0).asin();
    // Bulging left of the chord, with the centre on the right: clockwise;
    // past a semicircle (sag > c/2) the short way round is the wrong way.
    let sweep = if sag <= c / 2.0 {
        2.0 * half
    } else {
        2.0 * std::f64::consts::PI - 2.0 * half
    };
    Piece::Arc {
        centre,
        radius,
        start: a0,
        sweep: -sweep,
    }
}
