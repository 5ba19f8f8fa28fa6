//! Initial assembly of a track: wrap the links around the sprocket, idler
//! and road wheels so that the loop closes at t = 0 (spec §4).
//!
//! The belt path is the convex wrap of the wheels' pitch circles (outer
//! tangents and arcs), run counter-clockwise. Joints are laid along it one
//! link pitch apart (chords, not arcs). A track longer than the wrap takes
//! up the slack in one span, which sags as a circular arc; the sag is
//! found by bisection so that the last joint lands on the first. What is
//! left (rounding) is closed by the simulation's Newton-Raphson.

mod path;

use nalgebra::{SVector, Vector2};
use thiserror::Error;

use crate::model::TrackModel;
use path::{Path, Piece, ccw_sweep, outer_tangent, sag_arc};

/// A wheel the track wraps, as its pitch circle: the circle the joints lie
/// on where the track runs round it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PitchCircle {
    /// Centre, global frame, m.
    pub centre: Vector2<f64>,
    /// Radius, m.
    pub radius: f64,
}

/// Why a track cannot be wrapped.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum AssemblyError {
    /// Fewer than two wheels to wrap.
    #[error("a track needs at least two wheels to wrap, got {0}")]
    TooFewWheels(usize),
    /// One wheel's pitch circle lies inside another's.
    #[error("wheel {a} and wheel {b} are one inside the other: centres {distance:.3} m apart")]
    WheelInside {
        /// First wheel (index in the wrap order).
        a: usize,
        /// Second wheel.
        b: usize,
        /// Centre distance, m.
        distance: f64,
    },
    /// The track is too short to go round the wheels.
    #[error(
        "the track is too short to wrap the wheels: {links} links reach {track:.3} m, the wrap needs {wrap:.3} m"
    )]
    TrackTooShort {
        /// Number of links.
        links: usize,
        /// The track's length, m (sum of pitches).
        track: f64,
        /// The wrap's length, m.
        wrap: f64,
    },
    /// The track is so long that its slack would sag more than a quarter of
    /// the span.
    #[error(
        "the track is too long for the wheels: {track:.3} m of track for a {wrap:.3} m wrap sags more than a quarter of the span"
    )]
    TrackTooLong {
        /// m.
        track: f64,
        /// m.
        wrap: f64,
    },
    /// The sagging span index is not a span.
    #[error("sag span {0} does not exist (spans are numbered from 0, one after each wheel)")]
    NoSuchSpan(usize),
    /// The assembled start puts a shoe deeper than
    /// [`START_PENETRATION`](crate::vehicle::START_PENETRATION) into a
    /// wheel, the sprocket or the ground.
    #[error(
        "the assembled track starts {:.1} mm inside {what} (link {link}); a start may be at most {:.0} mm deep: the wrap does not fit this layout",
        depth * 1e3,
        crate::vehicle::START_PENETRATION * 1e3
    )]
    StartsInside {
        /// What the shoe is inside (`the ground`, `road wheel \`rw3\``, …).
        what: String,
        /// The link, numbered from 1.
        link: usize,
        /// How deep, m.
        depth: f64,
    },
    /// The terrain to place the vehicle on is invalid (a NaN or infinite
    /// parameter, a bad table).
    #[error(transparent)]
    Terrain(#[from] crate::contact::TerrainError),
}

/// The closed belt path with span `sag_span` sagging by `sag` (m).
fn belt(wheels: &[PitchCircle], sag_span: usize, sag: f64) -> Path {
    let m = wheels.len();
    let tangents: Vec<(Vector2<f64>, Vector2<f64>)> = (0..m)
        .map(|i| {
            let (a, b) = (wheels[i], wheels[(i + 1) % m]);
            outer_tangent((a.centre, a.radius), (b.centre, b.radius))
        })
        .collect();
    let mut pieces = Vec::with_capacity(2 * m);
    for i in 0..m {
        let wheel = wheels[i];
        let arrive = tangents[(i + m - 1) % m].1;
        let (leave, next) = tangents[i];
        let (start, sweep) = ccw_sweep(wheel.centre, arrive, leave);
        pieces.push(Piece::Arc {
            centre: wheel.centre,
            radius: wheel.radius,
            start,
            sweep,
        });
        pieces.push(if i == sag_span {
            sag_arc(leave, next, sag)
        } else {
            Piece::Line {
                from: leave,
                to: next,
            }
        });
    }
    Path::new(pieces)
}

/// Whether the belt from wheel `i − 1` to `i + 1` passes outside wheel `i`:
/// the tangents would meet it turning the wrong way (a near-full sweep).
fn off_hull(wheels: &[PitchCircle], i: usize) -> bool {
    let m = wheels.len();
    let (prev, this, next) = (wheels[(i + m - 1) % m], wheels[i], wheels[(i + 1) % m]);
    let arrive = outer_tangent((prev.centre, prev.radius), (this.centre, this.radius)).1;
    let leave = outer_tangent((this.centre, this.radius), (next.centre, next.radius)).0;
    let (_, sweep) = ccw_sweep(this.centre, arrive, leave);
    sweep > std::f64::consts::PI * 1.5 && sweep < 2.0 * std::f64::consts::PI - 1e-9
}

/// Lays joints one pitch apart along `path` from its start; returns them
/// and the arc length where the joint after the last link lands.
fn lay(path: &Path, pitches: &[f64]) -> (Vec<Vector2<f64>>, f64) {
    let mut joints = vec![path.at(0.0)];
    let mut s = 0.0;
    for &pitch in pitches {
        let from = *joints.last().unwrap();
        // The chord is never longer than the arc, and on a pitch circle
        // no shorter than 2/π of it.
        let (mut lo, mut hi) = (s + pitch * (1.0 - 1e-12), s + pitch * 1.6);
        for _ in 0..100 {
            let mid = 0.5 * (lo + hi);
            if (path.at(mid) - from).norm() < pitch {
                lo = mid
            } else {
                hi = mid
            }
        }
        s = 0.5 * (lo + hi);
        joints.push(path.at(s));
    }
    (joints, s)
}

/// How far the joints overshoot the belt when laid with `sag` (m) in span
/// `sag_span`: the arc length past the path's end where the joint after
/// the last link lands (m; negative if the track is too short).
pub fn excess<M: TrackModel<D>, const D: usize>(
    model: &M,
    wheels: &[PitchCircle],
    sag_span: usize,
    sag: f64,
) -> f64 {
    let touching = hull(wheels);
    let path = belt(&touching, span_among(wheels, &touching, sag_span), sag);
    let (_, landed) = lay(&path, &pitches(model));
    landed - path.length()
}

fn pitches<M: TrackModel<D>, const D: usize>(model: &M) -> Vec<f64> {
    model
        .description()
        .link_spans()
        .expect("a track has link spans")
        .iter()
        .map(|d| d.norm())
        .collect()
}

/// Span `sag_span` of `wheels` (the stretch after that wheel), counted among
/// the wheels the belt touches; if its wheel dropped out, the span after
/// the last touching wheel before it.
fn span_among(wheels: &[PitchCircle], touching: &[PitchCircle], sag_span: usize) -> usize {
    let m = wheels.len();
    (0..m)
        .map(|back| wheels[(sag_span % m + m - back) % m])
        .find_map(|w| touching.iter().position(|t| *t == w))
        .unwrap_or(0)
}

/// The wheels the belt touches: those inside the convex wrap drop out.
fn hull(wheels: &[PitchCircle]) -> Vec<PitchCircle> {
    let mut wheels = wheels.to_vec();
    while let Some(i) = (0..wheels.len()).find(|&i| wheels.len() > 2 && off_hull(&wheels, i)) {
        wheels.remove(i);
    }
    wheels
}

/// Wraps the track of `model` around `wheels` (pitch circles, in
/// counter-clockwise order round the loop), the slack sagging in span
/// `sag_span` (the stretch from wheel `i` to wheel `i + 1`; default the
/// longest). Returns `q_i` with link 1 starting where the belt reaches
/// wheel 0 (the start of its arc), and the joints' positions.
pub fn wrap<M: TrackModel<D>, const D: usize>(
    model: &M,
    wheels: &[PitchCircle],
    sag_span: Option<usize>,
) -> Result<(SVector<f64, D>, Vec<Vector2<f64>>), AssemblyError> {
    let m = wheels.len();
    if m < 2 {
        return Err(AssemblyError::TooFewWheels(m));
    }
    for a in 0..m {
        for b in a + 1..m {
            let distance = (wheels[a].centre - wheels[b].centre).norm();
            let needed = (wheels[a].radius - wheels[b].radius).abs();
            if distance <= needed.max(1e-9) {
                return Err(AssemblyError::WheelInside { a, b, distance });
            }
        }
    }
    let sag_span = match sag_span {
        Some(i) if i >= m => return Err(AssemblyError::NoSuchSpan(i)),
        Some(i) => i,
        None => (0..m)
            .max_by(|&a, &b| {
                let span = |i: usize| (wheels[(i + 1) % m].centre - wheels[i].centre).norm();
                span(a).total_cmp(&span(b))
            })
            .unwrap(),
    };
    // The sagging span, counted among the wheels the belt touches.
    let touching = hull(wheels);
    let sag_span = span_among(wheels, &touching, sag_span);
    let wheels = &touching[..];
    let m = wheels.len();
    let pitches = pitches(model);
    let track: f64 = pitches.iter().sum();
    let span_length = (wheels[(sag_span + 1) % m].centre - wheels[sag_span].centre).norm();
    let excess = |sag: f64| {
        let path = belt(wheels, sag_span, sag);
        let (_, landed) = lay(&path, &pitches);
        (landed - path.length(), path)
    };
    let (short, tight) = excess(0.0);
    if short < 0.0 {
        return Err(AssemblyError::TrackTooShort {
            links: pitches.len(),
            track,
            wrap: tight.length(),
        });
    }
    let max_sag = span_length / 4.0;
    if excess(max_sag).0 > 0.0 {
        return Err(AssemblyError::TrackTooLong {
            track,
            wrap: tight.length(),
        });
    }
    let (mut lo, mut hi) = (0.0, max_sag);
    for _ in 0..100 {
        let mid = 0.5 * (lo + hi);
        if excess(mid).0 > 0.0 {
            lo = mid
        } else {
            hi = mid
        }
    }
    let path = belt(wheels, sag_span, 0.5 * (lo + hi));
    let (joints, _) = lay(&path, &pitches);
    let description = model.description();
    let spans = description.link_spans().expect("a track has link spans");
    let mut q = SVector::<f64, D>::zeros();
    for (j, span) in spans.iter().enumerate() {
        let chord = joints[j + 1] - joints[j];
        q[2 + j] = chord.y.atan2(chord.x) - span.y.atan2(span.x);
    }
    let first = description
        .loop_joint
        .expect("a track has a loop joint")
        .first_u1;
    let root = joints[0] - crate::planar::rotate(q[2], first);
    q[0] = root.x;
    q[1] = root.y;
    Ok((q, joints))
}
