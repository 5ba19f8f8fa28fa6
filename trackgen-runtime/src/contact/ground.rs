//! Where the shoes' ground points meet the terrain.

use nalgebra::{Matrix2, Vector2};

use super::tangent::{GeometryTangent, LINK, PoseRows2, body_point};
use super::{BodyState, Contact, ShoeGeometry};
use crate::terrain::Terrain;
use crate::terrain::profile::Profile;

/// Every shoe ground point below `terrain`, link by link and the shoe's
/// points in order, appended to `out`.
///
/// Penetration is measured vertically, `δ = h(x) − y`: continuous over
/// kinks, and its exact rate is `−v·g` with `g = (−h′, 1)`, so the elastic
/// force `g F(δ)` is exactly the gradient of the contact's potential and
/// the energy books balance on any terrain.
///
/// Links whose bounding circle clears the highest terrain under the whole
/// track are skipped without looking at their points, so
/// the cost is one comparison per link plus the links actually near the
/// ground.
///
/// On a polyline ([`Terrain::Profile`]) a point below the surface is as
/// deep as its distance to the nearest edge, vertical faces included
/// ([`Profile::nearest_boundary`](crate::terrain::profile::Profile::nearest_boundary)), and is pushed along the unit normal
/// toward it, `g = n`: a face pushes sideways, as a wall does, where the
/// vertical depth would lift the point onto the step it meets. The depth
/// is a distance function, continuous, with `∂δ/∂p = −n`, so the elastic
/// force is the gradient of the potential there too.
pub fn detect(terrain: &Terrain, links: &[BodyState], shoe: &ShoeGeometry, out: &mut Vec<Contact>) {
    detect_culled(terrain, links, shoe, &clear_of(terrain, links, shoe), out);
}

/// [`detect`] with the culling test given ([`clear_of`]'s, found once for
/// every pass over the links of an evaluation).
pub(crate) fn detect_culled(
    terrain: &Terrain,
    links: &[BodyState],
    shoe: &ShoeGeometry,
    clear: &impl Fn(&BodyState) -> bool,
    out: &mut Vec<Contact>,
) {
    for (i, link) in links.iter().enumerate() {
        if clear(link) {
            continue;
        }
        for (k, local) in shoe.ground_points.iter().enumerate() {
            let arm = link.arm(*local);
            let point = link.position + arm;
            let Some((depth, gradient, gradient_norm)) = penetration(terrain, point) else {
                continue;
            };
            out.push(Contact {
                link: i,
                other: None,
                feature: k,
                point,
                arm,
                depth,
                gradient,
                gradient_norm,
                velocity: link.velocity_at(arm),
            });
        }
    }
}

/// How deep `point` is in the ground, the gradient of that depth and its
/// norm; `None` above it. A closed form's depth is `h(p_x) − p_y`, its
/// gradient `(−h′, 1)`; a polyline's depth is the distance to the nearest
/// edge, its gradient that edge's unit normal towards the surface.
///
/// Inlined into the contact passes (it runs per ground point and
/// evaluation); the polyline's search stays out of line.
#[inline]
pub(super) fn penetration(
    terrain: &Terrain,
    point: Vector2<f64>,
) -> Option<(f64, Vector2<f64>, f64)> {
    if let Terrain::Profile(profile) = terrain {
        return profile_penetration(profile, point);
    }
    let (h, slope) = terrain.height_and_slope(point.x);
    let depth = h - point.y;
    if depth <= 0.0 {
        return None;
    }
    let gradient = Vector2::new(-slope, 1.0);
    Some((depth, gradient, gradient.norm()))
}

/// [`penetration`] on a polyline: the distance to the nearest edge, the
/// edge's unit normal towards the surface.
#[inline(never)]
fn profile_penetration(profile: &Profile, point: Vector2<f64>) -> Option<(f64, Vector2<f64>, f64)> {
    let nearest = profile.nearest_boundary(point.x, point.y)?;
    if nearest.distance <= 0.0 {
        return None;
    }
    let normal = (Vector2::new(nearest.point.0, nearest.point.1) - point) / nearest.distance;
    Some((nearest.distance, normal, 1.0))
}

/// The derivatives of a ground contact's geometry ([`detect`]'s) with the
/// link's pose: the point `p = R + A ū` moves as `[I | ⟂(A ū)]`, the depth
/// `δ = h(p_x) − p_y` as `h′ ∂p_x − ∂p_y`, the gradient `(−h′, 1)` as
/// `(−h″ ∂p_x, 0)`. On a polyline the depth is the distance `|c − p|` to
/// the nearest point `c` of the boundary and the gradient its unit
/// normal `n = (c − p)/δ`: `∂δ = −n·∂p`; `n` is fixed on an edge and
/// turns about a vertex, `∂n = −(I − n nᵀ) ∂p / δ`.
pub fn tangent(terrain: &Terrain, contact: &Contact) -> GeometryTangent {
    let point = body_point(contact.arm, LINK);
    if let Terrain::Profile(profile) = terrain {
        let n = contact.gradient;
        let depth = point.row(0) * -n.x - point.row(1) * n.y;
        let mut gradient = PoseRows2::zeros();
        let on_vertex = profile
            .nearest_boundary(contact.point.x, contact.point.y)
            .is_some_and(|c| c.on_vertex);
        if on_vertex && contact.depth > 0.0 {
            let projector = Matrix2::identity() - n * n.transpose();
            gradient = -(projector * point) / contact.depth;
        }
        return GeometryTangent {
            point,
            depth,
            gradient,
        };
    }
    let slope = -contact.gradient.x;
    let curvature = terrain.curvature(contact.point.x);
    let mut gradient = PoseRows2::zeros();
    gradient.set_row(0, &(point.row(0) * -curvature));
    GeometryTangent {
        point,
        depth: point.row(0) * slope - point.row(1),
        gradient,
    }
}

/// A test of whether a link's bounding circle clears the highest point of
/// `terrain` under the whole track (found once, over the track's extent):
/// such a link touches nothing, so a contact pass costs one comparison
/// per link plus the links actually near the ground. A NaN position
/// compares false and is looked at: its force is NaN, and the run stops
/// with the cause.
#[inline]
pub(crate) fn clear_of(
    terrain: &Terrain,
    links: &[BodyState],
    shoe: &ShoeGeometry,
) -> impl Fn(&BodyState) -> bool {
    let extent = shoe.extent();
    // The links' x-range. A NaN compares false and is skipped, as
    // `f64::min` would skip it, but in one `minsd` where `f64::min`'s rule
    // for NaN takes five instructions (this fold was 1 % of the M113's
    // main job).
    let (low, high) = links
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), l| {
            let x = l.position.x;
            (if x < lo { x } else { lo }, if x > hi { x } else { hi })
        });
    let highest = terrain.max_height(low - extent, high + extent);
    move |link| link.position.y - extent > highest
}
