//! Initial assembly of a track: wrap the links around the sprocket, idler,
//! road wheels and return rollers so that the loop closes at t = 0
//! (formulation §4).
//!
//! The belt path runs counter-clockwise round the wheels'
//! pitch circles: arcs on the wheels it touches, straight spans on the
//! lower run, and on the upper run spans that sag with one curvature, as a
//! hanging chain's do, resting on the return rollers. Joints are laid
//! along it one link pitch apart (chords, not arcs: each found where the
//! path leaves the circle of one pitch about the joint before). The sag's
//! curvature is solved so that the last joint lands on the first; what is
//! left (rounding) is closed by the simulation's Newton-Raphson. A vehicle
//! with a tensioner sets the tensioner instead, with the upper run nearly
//! tight ([`assemble`]).
//!
//! When the track does not fit, the error says by how much, and which
//! link counts would.

mod belt;
mod error;
mod path;
mod sides;
mod vehicle;

use nalgebra::{SVector, Vector2};

use crate::multibody::TrackModel;
pub(crate) use belt::longest_upper_span;
pub use error::{AssemblyError, LinkCounts, START_PENETRATION, SlackLimit, Touching};
pub use path::PitchCircle;
use path::{Path, Place};
pub use sides::{AssembledSides, SideError, assemble_on_grounds, assemble_sides};
pub use vehicle::{Assembled, assemble};

/// The most the upper run may sag: a quarter of a span's length, below
/// the tight span (and never onto a wheel that does not carry it). More
/// slack than that is a track too long for its wheels.
pub const MAX_SAG: f64 = 0.25;

/// A wrapped track.
#[derive(Debug, Clone, PartialEq)]
pub struct Wrap<const D: usize> {
    /// `q_i`, link 1 starting where the belt reaches the first wheel it
    /// touches.
    pub q: SVector<f64, D>,
    /// The joints' positions, m: one more than the links, the last on the
    /// first (to rounding).
    pub joints: Vec<Vector2<f64>>,
    /// The upper run's sag curvature, 1/m (0: tight).
    pub sag_curvature: f64,
    /// The wheels the belt touches, by index in the list given: a wheel
    /// inside the belt (a road wheel above its neighbours, a return roller
    /// below a tight upper run) is not among them.
    pub touching: Vec<usize>,
}

/// The links' pitches, m.
pub(crate) fn pitches<M: TrackModel<D>, const D: usize>(model: &M) -> Vec<f64> {
    model
        .description()
        .link_spans()
        .expect("a track has link spans")
        .iter()
        .map(|d| d.norm())
        .collect()
}

/// Lays joints one pitch apart along `path` from its start; returns them
/// and the arc length where the joint after the last link lands.
fn lay(path: &Path, pitches: &[f64]) -> (Vec<Vector2<f64>>, f64) {
    let mut place = Place {
        piece: 0,
        along: 0.0,
        laps: 0,
    };
    let mut joints = Vec::with_capacity(pitches.len() + 1);
    joints.push(path.point(place));
    for &pitch in pitches {
        place = path.next_joint(place, pitch);
        if !place.along.is_finite() {
            return (joints, f64::INFINITY);
        }
        joints.push(path.point(place));
    }
    (joints, path.arc_length(place))
}

/// How many links of `pitch` go round `path`, as a real number: whole
/// chords, and the fraction of the next that the path's end is.
fn links_along(path: &Path, pitch: f64) -> f64 {
    let mut place = Place {
        piece: 0,
        along: 0.0,
        laps: 0,
    };
    let mut s = 0.0;
    for k in 0..1_000_000 {
        let next = path.next_joint(place, pitch);
        let t = path.arc_length(next);
        if !t.is_finite() {
            return f64::INFINITY;
        }
        if t >= path.length() {
            return k as f64 + (path.length() - s) / (t - s);
        }
        (place, s) = (next, t);
    }
    f64::INFINITY
}

/// A set of wheels checked for wrapping: at least two, none inside
/// another.
fn check_wheels(wheels: &[PitchCircle]) -> Result<(), AssemblyError> {
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
    Ok(())
}

/// How far the joints of links with `pitches` overshoot the belt round
/// `wheels` with the upper run sagging at curvature `kappa` (m of belt:
/// the arc length past the start where the joint after the last link
/// lands; negative if the track is short; `−∞` if the run cannot sag
/// that much).
pub(crate) fn excess(wheels: &[PitchCircle], kappa: f64, pitches: &[f64]) -> f64 {
    match belt::belt(wheels, kappa) {
        Some(b) => lay(&b.path, pitches).1 - b.path.length(),
        None => f64::NEG_INFINITY,
    }
}

/// Links of `pitch` round `wheels` at sag curvature `kappa` (see
/// [`LinkCounts`]).
pub(crate) fn links_round(wheels: &[PitchCircle], kappa: f64, pitch: f64) -> f64 {
    belt::belt(wheels, kappa).map_or(f64::NAN, |b| links_along(&b.path, pitch))
}

/// The mean of `pitches`, m.
pub(crate) fn mean(pitches: &[f64]) -> f64 {
    pitches.iter().sum::<f64>() / pitches.len() as f64
}

/// Wraps the track of `model` round `wheels` (pitch circles in
/// counter-clockwise order round the loop), the slack taken up by the
/// upper run's sag (see the module docs); link 1 starts where the belt reaches the
/// first wheel (of those it touches) in the list.
///
/// Errors: fewer than two wheels, one inside another, a track too short
/// for the tight belt or too long for the most sag ([`MAX_SAG`]), the
/// last two naming the link counts that would fit.
pub fn wrap<M: TrackModel<D>, const D: usize>(
    model: &M,
    wheels: &[PitchCircle],
) -> Result<Wrap<D>, AssemblyError> {
    check_wheels(wheels)?;
    let pitches = pitches(model);
    let links = pitches.len();
    let most = belt::curvature_for_sag(wheels, MAX_SAG);
    let fits = || LinkCounts {
        pitch: mean(&pitches),
        tight: links_round(wheels, 0.0, mean(&pitches)),
        slack: links_round(wheels, most, mean(&pitches)),
    };
    let samples: Vec<(f64, f64)> = (0..=SAG_SAMPLES)
        .map(|i| most * i as f64 / SAG_SAMPLES as f64)
        .map(|k| (k, excess(wheels, k, &pitches)))
        .collect();
    let kappa = match first_root(&samples, |k| excess(wheels, k, &pitches)) {
        Some(Ok(kappa)) => kappa,
        Some(Err(gap)) => return Err(AssemblyError::Unclosed { links, gap }),
        None if samples.iter().all(|s| s.1 < 0.0) => {
            return Err(AssemblyError::TrackTooShort {
                links,
                short: -samples
                    .iter()
                    .map(|s| s.1)
                    .fold(f64::NEG_INFINITY, f64::max),
                fits: fits(),
            });
        }
        None => {
            return Err(AssemblyError::TrackTooLong {
                links,
                long: samples.iter().map(|s| s.1).fold(f64::INFINITY, f64::min),
                limit: SlackLimit::Sag,
                fits: fits(),
            });
        }
    };
    wrap_at(model, wheels, kappa)
}

/// The points of the sag's range tried before bisecting: where a joint
/// falls on a wheel's arc moves the landing by a little as the sag grows,
/// so the excess need not fall monotonically at the millimetre level.
const SAG_SAMPLES: usize = 32;

/// Wraps the track of `model` round `wheels` with the upper run sagging
/// at curvature `kappa` (1/m), wherever its last joint lands: for a
/// curvature (or a tensioner setting) already solved for.
pub(crate) fn wrap_at<M: TrackModel<D>, const D: usize>(
    model: &M,
    wheels: &[PitchCircle],
    kappa: f64,
) -> Result<Wrap<D>, AssemblyError> {
    check_wheels(wheels)?;
    let belt = belt::belt(wheels, kappa).ok_or(AssemblyError::TrackTooLong {
        links: model.description().bodies.len(),
        long: f64::INFINITY,
        limit: SlackLimit::Sag,
        fits: LinkCounts {
            pitch: mean(&pitches(model)),
            tight: f64::NAN,
            slack: f64::NAN,
        },
    })?;
    let (joints, _) = lay(&belt.path, &pitches(model));
    let touching = belt
        .touching
        .iter()
        .filter_map(|t| wheels.iter().position(|w| w == t))
        .collect();
    Ok(Wrap {
        q: coordinates(model, &joints),
        joints,
        sag_curvature: kappa,
        touching,
    })
}

/// How far (m of belt) the last joint may land from the first for a
/// solved wrap: the root is bisected to rounding (~1e-15 m); more means
/// the sign change was a jump (the belt's supports changing), not a root.
pub(crate) const LANDING: f64 = 1e-9;

/// The root of `f` in the first interval of `samples` (`(x, f(x))` in
/// increasing `x`) where `f` changes sign and is a root (`|f| ≤`
/// [`LANDING`]), bisected to rounding; `Err(gap)` with the smallest `|f|`
/// found if every sign change is a jump.
pub(crate) fn first_root(
    samples: &[(f64, f64)],
    f: impl Fn(f64) -> f64,
) -> Option<Result<f64, f64>> {
    let mut gap = f64::INFINITY;
    for w in samples
        .windows(2)
        .filter(|w| (w[0].1 >= 0.0) != (w[1].1 >= 0.0))
    {
        let x = bisect(w[0], w[1], &f);
        let landing = f(x).abs();
        if landing <= LANDING {
            return Some(Ok(x));
        }
        gap = gap.min(landing);
    }
    gap.is_finite().then_some(Err(gap))
}

/// The root of `f` between two points `(x, f(x))` where its sign
/// differs, by bisection to rounding.
pub(crate) fn bisect(a: (f64, f64), b: (f64, f64), f: &impl Fn(f64) -> f64) -> f64 {
    let positive_at_a = a.1 >= 0.0;
    let (mut a, mut b) = (a.0, b.0);
    for _ in 0..200 {
        let mid = 0.5 * (a + b);
        if mid == a || mid == b {
            break;
        }
        if (f(mid) >= 0.0) == positive_at_a {
            a = mid
        } else {
            b = mid
        }
    }
    0.5 * (a + b)
}

/// `q_i` putting link `j` from joint `j` to joint `j + 1`.
fn coordinates<M: TrackModel<D>, const D: usize>(
    model: &M,
    joints: &[Vector2<f64>],
) -> SVector<f64, D> {
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
    q
}
