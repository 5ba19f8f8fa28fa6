//! The polyline itself: its points, its bucket index, and every query
//! contact makes of it.

use super::error::{PointProblem, ProfileError, Whole};
use super::limits::MAX_POINTS;

/// The bucket index may hold this many buckets however few the points
/// (256 KiB), four per segment beyond.
const MIN_BUCKET_CAP: f64 = 65536.0;

/// A terrain polyline, flat beyond its ends (see the [module
/// docs](super) for its invariants, the bucket index behind every lookup
/// and the side taken at a vertical face).
#[derive(Debug, Clone, PartialEq)]
pub struct Profile {
    /// Point abscissae, m, non-decreasing.
    x: Vec<f64>,
    /// Point heights, m.
    z: Vec<f64>,
    pub(super) index: BucketIndex,
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
/// ([`outline`](crate::contact::outline)): 10°. A gentler corner between two
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
pub(super) struct BucketIndex {
    /// `x_first`, m.
    origin: f64,
    /// Buckets per metre, `B / span` (0 when that overflows: then one
    /// bucket holds every point and lookups are binary searches).
    scale: f64,
    /// `B − 1`.
    last: usize,
    /// `starts[b]`: how many points lie in buckets before `b`;
    /// `B + 1` entries, `starts[0] = 0`, `starts[B] = n`.
    pub(super) starts: Vec<u32>,
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

/// The running check of a profile's points, one at a time (shared by
/// [`Profile::new`] and the reader).
#[derive(Default)]
pub(super) struct PointCheck {
    previous: Option<(f64, f64)>,
    /// Whether the last segment is vertical.
    vertical: bool,
}

impl PointCheck {
    #[inline]
    pub(super) fn next(&mut self, x: f64, z: f64) -> Result<(), PointProblem> {
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
    /// the [module docs](super).
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
    pub(super) fn from_checked(x: Vec<f64>, z: Vec<f64>) -> Result<Profile, Whole> {
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
}

/// `(dx, dz)` scaled to unit length, without overflow or underflow.
fn unit(dx: f64, dz: f64) -> (f64, f64) {
    let m = dx.abs().max(dz.abs());
    let (a, b) = (dx / m, dz / m);
    let l = (a * a + b * b).sqrt();
    (a / l, b / l)
}
