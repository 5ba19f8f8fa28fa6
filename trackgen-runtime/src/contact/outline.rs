//! Sharp terrain against a body's outline: a profile's convex corners
//! (a step's top edge, a trench's lips, a barrier's top edges) inside a
//! shoe's or the hull's convex outline, and the hull's own corners below
//! the ground.
//!
//! A shoe touches the ground at its declared ground points; a corner
//! sharper than [`SHARP_TURN`](crate::terrain::profile::SHARP_TURN) between two of them would pass into the
//! shoe unseen. Here it is seen: a corner `c` inside a body's outline is
//! as deep as its distance to the nearest side,
//! `δ = minᵢ nᵢ·(c − aᵢ)` (`nᵢ` the side's inward unit normal, `aᵢ` a
//! point of it, both turning with the body), and pushes the body along
//! that side's inward normal at the body's material point on `c`. That
//! force is exactly the gradient of the potential of `δ`: moving the body
//! by `(dR, dθ)` changes `δ` by `−nᵢ·(dR + dθ ⟂(c − R))`, which is what a
//! point contact at `c` along `nᵢ` gives ([`tangent`]), so the energy
//! books close with it. The hull's corners meet the ground as the shoes'
//! ground points do ([`ground::penetration`](super::ground)).
//!
//! The law: the ground's normal law, and Coulomb friction regularised as
//! the rims' (a corner has no stiction state); see
//! [`VehicleConfig::corner_laws`](crate::vehicle::VehicleConfig::corner_laws).

use nalgebra::Vector2;

use super::tangent::{GeometryTangent, LINK, PoseRows2, body_point};
use super::{BodyState, Contact, ShoeGeometry};
use crate::planar::perp;
use crate::terrain::Terrain;
use crate::terrain::profile::Profile;

pub use super::detect::TERRAIN_CORNER;

/// A convex outline on a body: its corners counter-clockwise in the
/// body's frame (m, from its centroid), each side's inward unit normal,
/// and the radius of the circle about the centroid that holds it (for
/// culling).
#[derive(Debug, Clone, PartialEq)]
pub struct Outline {
    corners: Vec<Vector2<f64>>,
    normals: Vec<Vector2<f64>>,
    radius: f64,
}

impl Outline {
    /// The outline through `corners` (body frame, m), listed round it in
    /// either direction; an error if they make no convex polygon
    /// ([`trackgen_sprocket::convex_outline`]'s rule, the compiler's too).
    pub fn new(corners: &[Vector2<f64>]) -> Result<Outline, trackgen_sprocket::OutlineProblem> {
        let listed: Vec<(f64, f64)> = corners.iter().map(|c| (c.x, c.y)).collect();
        let ccw: Vec<Vector2<f64>> = trackgen_sprocket::convex_outline(&listed)?
            .into_iter()
            .map(|(x, y)| Vector2::new(x, y))
            .collect();
        let n = ccw.len();
        let normals = (0..n)
            .map(|i| perp(ccw[(i + 1) % n] - ccw[i]).normalize())
            .collect();
        let radius = ccw.iter().map(|c| c.norm()).fold(0.0, f64::max);
        Ok(Outline {
            corners: ccw,
            normals,
            radius,
        })
    }

    /// The smallest convex outline holding a shoe's features: its ground
    /// points and its inner face's ends (the pins are inside the links'
    /// bodies). `None` if they span no area (a shoe of one ground point
    /// on its pitch line, say).
    pub fn of_shoe(shoe: &ShoeGeometry) -> Option<Outline> {
        let mut points: Vec<Vector2<f64>> = shoe.ground_points.clone();
        points.extend(shoe.inner_face);
        Outline::new(&convex_hull(points)).ok()
    }

    /// The corners, counter-clockwise, body frame (m).
    pub fn corners(&self) -> &[Vector2<f64>] {
        &self.corners
    }

    /// The radius about the body's centroid that holds the outline, m.
    pub fn radius(&self) -> f64 {
        self.radius
    }

    /// How deep the body-frame point `p` is inside, and the side it is
    /// nearest (its inward normal, body frame); `None` outside or on the
    /// outline.
    pub fn depth(&self, p: Vector2<f64>) -> Option<(f64, Vector2<f64>)> {
        let mut deepest: Option<(f64, Vector2<f64>)> = None;
        for (corner, normal) in self.corners.iter().zip(&self.normals) {
            let d = normal.dot(&(p - corner));
            if d <= 0.0 {
                return None;
            }
            if deepest.is_none_or(|(best, _)| d < best) {
                deepest = Some((d, *normal));
            }
        }
        deepest
    }
}

/// Andrew's monotone chain: the convex hull of `points`, counter-clockwise,
/// collinear points dropped.
fn convex_hull(mut points: Vec<Vector2<f64>>) -> Vec<Vector2<f64>> {
    points.sort_by(|a, b| a.x.total_cmp(&b.x).then(a.y.total_cmp(&b.y)));
    points.dedup();
    if points.len() < 3 {
        return points;
    }
    let cross = |o: Vector2<f64>, a: Vector2<f64>, b: Vector2<f64>| {
        (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x)
    };
    let mut hull: Vec<Vector2<f64>> = Vec::with_capacity(2 * points.len());
    for pass in 0..2 {
        let start = hull.len();
        let ordered: Box<dyn Iterator<Item = &Vector2<f64>>> = if pass == 0 {
            Box::new(points.iter())
        } else {
            Box::new(points.iter().rev())
        };
        for &p in ordered {
            while hull.len() >= start + 2
                && cross(hull[hull.len() - 2], hull[hull.len() - 1], p) <= 0.0
            {
                hull.pop();
            }
            hull.push(p);
        }
        hull.pop();
    }
    hull
}

/// The sharp convex corners of `terrain` between `x0` and `x1` (m): a
/// profile's corners turning by more than [`SHARP_TURN`](crate::terrain::profile::SHARP_TURN)'s angle
/// ([`Profile::sharp_corners_in`]); none on a closed form (they are
/// smooth).
pub fn sharp_corners(
    terrain: &Terrain,
    x0: f64,
    x1: f64,
) -> impl Iterator<Item = Vector2<f64>> + '_ {
    let profile: Option<&Profile> = match terrain {
        Terrain::Profile(profile) => Some(profile),
        _ => None,
    };
    profile
        .into_iter()
        .flat_map(move |p| p.sharp_points_in(x0, x1))
        .map(|(x, z)| Vector2::new(x, z))
}

/// Every sharp terrain corner inside a body's `outline`, the body in
/// `state`, appended to `out` as a contact of the body's material point
/// on the corner (`feature` [`TERRAIN_CORNER`], `link` as given: the
/// body's index among its kind).
pub fn detect_corners(
    terrain: &Terrain,
    (state, index): (&BodyState, usize),
    outline: &Outline,
    out: &mut Vec<Contact>,
) {
    let r = outline.radius;
    for corner in sharp_corners(terrain, state.position.x - r, state.position.x + r) {
        push_corner(corner, (state, index), outline, out);
    }
}

/// As [`detect_corners`] for every link of a track not `clear` of the
/// ground (the ground points' culling test, found once per evaluation:
/// its circle holds the outline's), each looking
/// only at the sharp corners within its outline's circle (`O(log n)` to
/// find them): a comparison per link plus the links near the ground.
pub fn detect_track_corners(
    terrain: &Terrain,
    links: &[BodyState],
    (outline, clear): (&Outline, &impl Fn(&BodyState) -> bool),
    out: &mut Vec<Contact>,
) {
    let Terrain::Profile(profile) = terrain else {
        return;
    };
    let r = outline.radius;
    for (i, link) in links.iter().enumerate() {
        if clear(link) {
            continue;
        }
        let x = link.position.x;
        for (cx, cz) in profile.sharp_points_in(x - r, x + r) {
            let corner = Vector2::new(cx, cz);
            if (link.position - corner).norm_squared() < r * r {
                push_corner(corner, (link, i), outline, out);
            }
        }
    }
}

fn push_corner(
    corner: Vector2<f64>,
    (state, index): (&BodyState, usize),
    outline: &Outline,
    out: &mut Vec<Contact>,
) {
    let arm = corner - state.position;
    let Some((depth, normal)) = outline.depth(state.rotation().apply_inverse(arm)) else {
        return;
    };
    out.push(Contact {
        link: index,
        other: None,
        feature: TERRAIN_CORNER,
        point: corner,
        arm,
        depth,
        gradient: state.arm(normal),
        gradient_norm: 1.0,
        velocity: state.velocity_at(arm),
    });
}

/// The hull's corners below the ground, appended to `out` as the shoes'
/// ground points are ([`ground`](super::ground)'s law of depth: vertical
/// on a closed form, the distance to the nearest edge on a profile), with
/// `feature` the corner's index; then the terrain's sharp corners inside
/// the hull.
pub fn detect_hull(terrain: &Terrain, frame: &BodyState, hull: &Outline, out: &mut Vec<Contact>) {
    // Culled by the corners' box: the terrain touches the hull only where
    // it rises above the lowest corner within the hull's x-range (a
    // convex outline's lowest and outermost points are corners).
    // A NaN pose is looked at (and its force is NaN): `min` and `max` skip
    // a NaN corner, so one is noted apart.
    let (mut low, mut high, mut bottom) = (f64::INFINITY, f64::NEG_INFINITY, f64::INFINITY);
    let mut lost = false;
    for local in &hull.corners {
        let point = frame.position + frame.arm(*local);
        low = low.min(point.x);
        high = high.max(point.x);
        bottom = bottom.min(point.y);
        lost |= point.x.is_nan() || point.y.is_nan();
    }
    if !lost && bottom > terrain.max_height(low, high) {
        return;
    }
    for (k, local) in hull.corners.iter().enumerate() {
        let arm = frame.arm(*local);
        let point = frame.position + arm;
        if let Some((depth, gradient, gradient_norm)) = super::ground::penetration(terrain, point) {
            out.push(Contact {
                link: 0,
                other: None,
                feature: k,
                point,
                arm,
                depth,
                gradient,
                gradient_norm,
                velocity: frame.velocity_at(arm),
            });
        }
    }
    detect_corners(terrain, (frame, 0), hull, out);
}

/// The terrain's sharp corners inside a rim (a road wheel's, the idler's, a
/// roller's, the sprocket's: a circle of `radius` m about the body's
/// centre), appended to `out` with `link` the body's index: as deep as
/// `radius − |c − C|` and pushing the body straight away from the corner,
/// `n = (C − c)/|C − c|` (the force's line passes through the centre: the
/// normal force turns nothing, friction does). The track is usually
/// between rim and ground; this is for a corner that comes up between
/// two shoes, or a rim off the track.
#[inline]
pub fn detect_rim(
    terrain: &Terrain,
    (body, index, radius): (&BodyState, usize, f64),
    out: &mut Vec<Contact>,
) {
    let Terrain::Profile(profile) = terrain else {
        return;
    };
    let x = body.position.x;
    for (cx, cz) in profile.sharp_points_in(x - radius, x + radius) {
        let corner = Vector2::new(cx, cz);
        let arm = corner - body.position;
        let distance = arm.norm();
        if distance >= radius || distance == 0.0 {
            continue;
        }
        out.push(Contact {
            link: index,
            other: None,
            feature: TERRAIN_CORNER,
            point: corner,
            arm,
            depth: radius - distance,
            gradient: -arm / distance,
            gradient_norm: 1.0,
            velocity: body.velocity_at(arm),
        });
    }
}

/// The derivatives of a terrain corner's contact ([`detect_corners`]'s)
/// with the body's pose: the contact point is the corner, fixed (`∂p =
/// 0`: the force's arm `c − R` moves with `−∂R` alone); the depth changes
/// as the body's material point there moves, `−n·[I | ⟂(c − R)]`; the
/// side's normal turns with the body, `∂n = ⟂n ∂θ`.
pub fn tangent(contact: &Contact) -> GeometryTangent {
    let material = body_point(contact.arm, LINK);
    let n = contact.gradient;
    let depth = material.row(0) * -n.x - material.row(1) * n.y;
    let point = PoseRows2::zeros();
    let mut gradient = PoseRows2::zeros();
    let turned = perp(n);
    gradient[(0, LINK + 2)] = turned.x;
    gradient[(1, LINK + 2)] = turned.y;
    GeometryTangent {
        point,
        depth,
        gradient,
    }
}

/// The derivatives of a rim's contact with a terrain corner
/// ([`detect_rim`]'s) with the body's pose: the contact point is the
/// corner, fixed; the depth `r − |c − C|` changes as `−n·∂C` (the
/// material point's turning, `⟂(c − C)`, is square to `n`); the normal
/// `n = (C − c)/|C − c|` turns as the centre moves past the corner,
/// `∂n = (I − n nᵀ) ∂C / |C − c|`, and not with the body's angle.
pub fn rim_tangent(contact: &Contact) -> GeometryTangent {
    let material = body_point(contact.arm, LINK);
    let n = contact.gradient;
    let depth = material.row(0) * -n.x - material.row(1) * n.y;
    let mut gradient = PoseRows2::zeros();
    let distance = contact.arm.norm();
    if distance > 0.0 {
        let turning = (nalgebra::Matrix2::identity() - n * n.transpose()) / distance;
        gradient.fixed_view_mut::<2, 2>(0, LINK).copy_from(&turning);
    }
    GeometryTangent {
        point: PoseRows2::zeros(),
        depth,
        gradient,
    }
}

#[cfg(test)]
mod tests;
