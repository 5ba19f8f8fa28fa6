//! The belt path round a set of wheels' pitch circles: arcs on the wheels
//! it touches, joined by straight spans, except on the upper run, whose
//! spans sag.
//!
//! A chain hanging under its weight `w` per metre with horizontal tension
//! `H` has curvature `w/H` wherever it is nearly horizontal, the same in
//! every span between its supports; so the sag of a span of length `L` is
//! about `w L²/(8H)`, the long spans sagging most. The upper run here
//! sags with one curvature `κ` (1/m) in every span: each span is a
//! circular arc of radius `1/κ`, tangent to both supports' pitch circles
//! (so the belt turns smoothly from wheel to span and never cuts into the
//! wheel it leaves), bending the other way to the wheels. `κ = 0` is the
//! tight belt of outer tangents.
//!
//! A wheel the belt would run round the wrong way (a road wheel above the
//! line of its neighbours, a return roller below a tight upper run) is not
//! touched: it drops out and the belt spans past it.

use std::f64::consts::PI;

use nalgebra::Vector2;

use super::path::{Path, Piece, PitchCircle, asinc};

/// Whether the span from `a` to `b` is on the upper run: heading backwards
/// (−x, as the upper run of a counter-clockwise loop does) within 60° of
/// the horizontal, so that the wheels are below it and its sag, under
/// gravity (−y), is towards them.
pub(crate) fn upper(a: &PitchCircle, b: &PitchCircle) -> bool {
    let d = b.centre - a.centre;
    d.x < -0.5 * d.norm()
}

/// Where the belt leaves `a` and reaches `b` running from `a` to `b` with
/// both circles on its left, and the span between: straight for `κ = 0`,
/// otherwise an arc of curvature `κ` bending right (sagging), tangent to
/// both circles from outside. `None` if no such arc exists (so much sag
/// that its circle cannot touch both from outside).
fn span(a: &PitchCircle, b: &PitchCircle, kappa: f64) -> Option<Span> {
    let d = b.centre - a.centre;
    let distance = d.norm();
    let u = d / distance;
    let right = Vector2::new(u.y, -u.x);
    let (ra, rb) = (a.radius, b.radius);
    // The sag circle's centre m is 1/κ + r_a from a and 1/κ + r_b from b;
    // its component along u, divided by each of those distances, gives the
    // cosines below (written in κ, so that κ → 0 is the outer tangent,
    // cos = (r_a − r_b)/D).
    let shared = (ra - rb) * (2.0 + kappa * (ra + rb)) / (2.0 * distance);
    let cos_a = (0.5 * kappa * distance + shared) / (1.0 + kappa * ra);
    let cos_b = (-0.5 * kappa * distance + shared) / (1.0 + kappa * rb);
    if !(cos_a.abs() <= 1.0 && cos_b.abs() <= 1.0) {
        return None;
    }
    let wa = u * cos_a + right * (1.0 - cos_a * cos_a).sqrt();
    let wb = u * cos_b + right * (1.0 - cos_b * cos_b).sqrt();
    let (leave, reach) = (a.centre + wa * ra, b.centre + wb * rb);
    // The tight span: the outer tangent, its outward normal `w0`.
    let cos_0 = (ra - rb) / distance;
    let w0 = u * cos_0 + right * (1.0 - cos_0 * cos_0).max(0.0).sqrt();
    let tight = ((b.centre + w0 * rb) - (a.centre + w0 * ra)).norm();
    if kappa == 0.0 {
        return Some(Span {
            leave,
            reach,
            piece: Piece::line(leave, reach),
            tight,
            dip: 0.0,
        });
    }
    // The deepest point of the sag circle below the tight line: its
    // centre m = a + (1/κ + r_a) w_a is (1/κ + r_a)(w_a · w0) − r_a out
    // from the line, so the dip is (1/κ + r_a)(1 − w_a · w0), with
    // 1 − cos θ = |w_a − w0|²/2 to keep the digits of a small sag.
    let dip = (1.0 / kappa + ra) * 0.5 * (wa - w0).norm_squared();
    // The arc from `leave` to `reach` on the sag circle, less than half a
    // turn: its length from the chord, `c · asin(κc/2)/(κc/2)`.
    let chord = (reach - leave).norm();
    let x = 0.5 * kappa * chord;
    if x > 1.0 {
        return None;
    }
    let piece = Piece {
        start: leave,
        tangent: Vector2::new(-wa.y, wa.x),
        curvature: -kappa,
        length: chord * asinc(x),
    };
    Some(Span {
        leave,
        reach,
        piece,
        tight,
        dip,
    })
}

/// The belt between two wheels.
#[derive(Debug, Clone, Copy)]
struct Span {
    /// Where it leaves the first wheel.
    leave: Vector2<f64>,
    /// Where it reaches the second.
    reach: Vector2<f64>,
    piece: Piece,
    /// The length of the tight span (the outer tangent), m.
    tight: f64,
    /// How far it sags below the tight span at its deepest, m.
    dip: f64,
}

/// How far (m) a wheel must stand out past the span its neighbours make
/// to be touched: a row of equal wheels on a line stands out by rounding
/// either way, and is the same belt whether touched or not.
const PROTRUDES: f64 = 1e-12;

impl Span {
    /// How far `wheel` stands out past the span, outwards (m; negative if
    /// the span passes outside it): past the tangent line, or into the sag
    /// circle, whose centre is `1/κ` to the right of the start.
    fn protrusion(&self, wheel: &PitchCircle) -> f64 {
        let t = self.piece.tangent;
        let right = Vector2::new(t.y, -t.x);
        let k = -self.piece.curvature;
        if k == 0.0 {
            (wheel.centre - self.leave).dot(&right) + wheel.radius
        } else {
            let centre = self.leave + right / k;
            1.0 / k + wheel.radius - (wheel.centre - centre).norm()
        }
    }

    /// Whether the span passes inside `wheel` (by more than rounding).
    fn cuts(&self, wheel: &PitchCircle) -> bool {
        let (c, r) = (wheel.centre, wheel.radius);
        let k = -self.piece.curvature;
        let nearest = if k == 0.0 {
            let d = self.reach - self.leave;
            let t = ((c - self.leave).dot(&d) / d.norm_squared()).clamp(0.0, 1.0);
            (self.leave + d * t - c).norm()
        } else {
            // The sag circle's centre, to the right of the start tangent;
            // the arc is under half a turn, so the wheel's nearest point
            // on the circle is on the arc when it lies between the ends.
            let t = self.piece.tangent;
            let m = self.leave + Vector2::new(t.y, -t.x) / k;
            let cross = |a: Vector2<f64>, b: Vector2<f64>| a.x * b.y - a.y * b.x;
            let (a, b, v) = (self.leave - m, self.reach - m, c - m);
            let between = cross(a, v) * cross(a, b) >= 0.0 && cross(v, b) * cross(a, b) >= 0.0;
            if between {
                (v.norm() - 1.0 / k).abs()
            } else {
                (c - self.leave).norm().min((c - self.reach).norm())
            }
        };
        nearest < r * (1.0 - 1e-12)
    }
}

/// The counter-clockwise angle, in `[0, 2π)`, from radius direction `from`
/// to `to` of a wheel; arriving and leaving at the same point (to
/// rounding) is no turn at all.
fn sweep(from: Vector2<f64>, to: Vector2<f64>) -> f64 {
    let angle = (from.x * to.y - from.y * to.x)
        .atan2(from.dot(&to))
        .rem_euclid(2.0 * PI);
    if angle > 2.0 * PI - 1e-9 { 0.0 } else { angle }
}

/// A belt round a set of wheels.
pub(crate) struct Belt {
    /// Starting where it reaches the first wheel it touches.
    pub path: Path,
    /// The wheels it touches, in order.
    pub touching: Vec<PitchCircle>,
    /// The deepest sag of a span below the tight span, as a fraction of
    /// the tight span's length.
    pub sag: f64,
    /// Whether a sagging span passes through a wheel other than the two it
    /// joins (a road wheel below the upper run).
    pub cuts: bool,
}

/// The belt round `wheels` (counter-clockwise order) with the upper run
/// sagging at curvature `kappa`. `None` if a span cannot sag that much.
pub(crate) fn belt(wheels: &[PitchCircle], kappa: f64) -> Option<Belt> {
    let mut touching = wheels.to_vec();
    // The belt touches a wheel when the wheel stands out past the span
    // its neighbours would make without it (the convex hull, on the lower
    // run; on the upper, the rollers it comes down onto). Drop the one
    // furthest inside, and look again.
    while touching.len() > 2 {
        let m = touching.len();
        let inside = (0..m)
            .map(|i| {
                let (prev, next) = (&touching[(i + m - 1) % m], &touching[(i + 1) % m]);
                // Only a support of the upper run (both its spans upper)
                // is bridged by a sagging span; any other wheel by the
                // tight one, as on a convex hull.
                let on_upper_run = upper(prev, &touching[i]) && upper(&touching[i], next);
                let sagging = on_upper_run && upper(prev, next);
                let bridge = span(prev, next, if sagging { kappa } else { 0.0 });
                // No span without it (too much sag): keep it.
                (
                    i,
                    bridge.map_or(f64::INFINITY, |s| s.protrusion(&touching[i])),
                )
            })
            .min_by(|a, b| a.1.total_cmp(&b.1));
        match inside {
            Some((i, p)) if p < PROTRUDES => {
                touching.remove(i);
            }
            _ => break,
        }
    }
    {
        let m = touching.len();
        let spans = (0..m)
            .map(|i| {
                let (a, b) = (&touching[i], &touching[(i + 1) % m]);
                span(a, b, if upper(a, b) { kappa } else { 0.0 })
            })
            .collect::<Option<Vec<_>>>()?;
        let sweeps: Vec<f64> = (0..m)
            .map(|i| {
                let centre = touching[i].centre;
                let reach = spans[(i + m - 1) % m].reach;
                let leave = spans[i].leave;
                sweep(reach - centre, leave - centre)
            })
            .collect();
        let mut pieces = Vec::with_capacity(2 * m);
        for i in 0..m {
            let wheel = touching[i];
            let reach = spans[(i + m - 1) % m].reach;
            let radial = (reach - wheel.centre) / wheel.radius;
            pieces.push(Piece {
                start: reach,
                tangent: Vector2::new(-radial.y, radial.x),
                curvature: 1.0 / wheel.radius,
                length: wheel.radius * sweeps[i],
            });
            pieces.push(spans[i].piece);
        }
        let sag = spans.iter().map(|s| s.dip / s.tight).fold(0.0, f64::max);
        // A sagging span must clear every wheel but the two it joins (the
        // upper run can come down onto a road wheel of the lower run).
        let cuts = (0..m).filter(|&i| spans[i].dip > 0.0).any(|i| {
            let ends = [touching[i], touching[(i + 1) % m]];
            wheels
                .iter()
                .filter(|w| !ends.contains(w))
                .any(|w| spans[i].cuts(w))
        });
        Some(Belt {
            path: Path::new(pieces),
            touching,
            sag,
            cuts,
        })
    }
}

/// The length of the longest upper span of the tight belt, m (0 if none).
pub(crate) fn longest_upper_span(wheels: &[PitchCircle]) -> f64 {
    belt(wheels, 0.0).map_or(0.0, |b| {
        let m = b.touching.len();
        (0..m)
            .filter(|&i| upper(&b.touching[i], &b.touching[(i + 1) % m]))
            .map(|i| b.path.pieces[2 * i + 1].length)
            .fold(0.0, f64::max)
    })
}

/// The least sag curvature (1/m) at which some upper span of the belt
/// round `wheels` sags `fraction` of its length below the tight span, or
/// comes down onto a wheel below it that is not its support (or the most
/// at which the belt exists); 0 if there is no upper run.
///
/// The deepest sag grows with the curvature until the belt comes down
/// onto a return roller, which splits the span and drops it, so it is
/// scanned in steps of 5 % from a sag of ~1e-4 of the span before
/// bisecting the first crossing.
pub(crate) fn curvature_for_sag(wheels: &[PitchCircle], fraction: f64) -> f64 {
    let longest = longest_upper_span(wheels);
    if longest <= 0.0 {
        return 0.0;
    }
    let sags = |kappa: f64| belt(wheels, kappa).map(|b| if b.cuts { f64::INFINITY } else { b.sag });
    let mut below = 0.0;
    let mut kappa = 1e-3 / longest;
    for _ in 0..400 {
        match sags(kappa) {
            Some(sag) if sag < fraction => {
                below = kappa;
                kappa *= 1.05;
            }
            _ => break,
        }
    }
    let mut above = kappa;
    for _ in 0..200 {
        let mid = 0.5 * (below + above);
        if mid <= below || mid >= above {
            break;
        }
        match sags(mid) {
            Some(sag) if sag < fraction => below = mid,
            _ => above = mid,
        }
    }
    below
}
