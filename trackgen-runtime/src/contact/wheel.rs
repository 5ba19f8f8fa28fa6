//! Where wheel rims (road wheels, idler, rollers: circles) meet the shoes'
//! inner running faces (segments).

use nalgebra::Vector2;

use super::tangent::{GeometryTangent, LINK, OTHER, PoseRows2, body_point, dot_rows, unit_vector};
use super::{BodyState, Contact, ShoeGeometry};
use crate::planar::perp;

/// The contacts of the wheel `body` (its state, and its rim radius in m)
/// with every link near it, appended to `out`: the face point nearest the
/// rim's centre, pushed out along the line from the centre.
///
/// Only links whose bounding circle reaches the rim are examined, and only
/// faces with the rim on their inner side (the link's left).
pub fn detect(
    (wheel, body, radius): (&BodyState, usize, f64),
    links: &[BodyState],
    shoe: &ShoeGeometry,
    out: &mut Vec<Contact>,
) {
    let reach = radius + shoe.extent();
    super::each_near(links, wheel.position, reach, |i, link| {
        let (a, b) = (
            link.point(shoe.inner_face[0]),
            link.point(shoe.inner_face[1]),
        );
        // The rim must be on the face's inner side (the link's left).
        let inward = link.arm(Vector2::new(0.0, 1.0));
        if (wheel.position - a).dot(&inward) <= 0.0 {
            return;
        }
        let ab = b - a;
        let s = ((wheel.position - a).dot(&ab) / ab.norm_squared()).clamp(0.0, 1.0);
        let point = a + ab * s;
        let to_face = point - wheel.position;
        let distance = to_face.norm();
        let depth = radius - distance;
        if depth <= 0.0 || distance == 0.0 {
            return;
        }
        out.push(super::between(
            (i, link),
            (body, wheel),
            (0, point, to_face / distance, depth),
        ));
    });
}

/// The derivatives of a rim contact's geometry ([`detect`]'s) with the
/// link's and the wheel's poses. The face point nearest the centre `c` is
/// `p = a + (b − a) s` with `s = (c − a)·(b − a)/|b − a|²` inside the face
/// (an end, `a` or `b`, where `s` is clipped); `δ = r − |p − c|` and the
/// normal `(p − c)/|p − c|`.
pub fn tangent(
    contact: &Contact,
    link: &BodyState,
    wheel: &BodyState,
    shoe: &ShoeGeometry,
) -> GeometryTangent {
    let (arm_a, arm_b) = (link.arm(shoe.inner_face[0]), link.arm(shoe.inner_face[1]));
    let (a, b) = (link.position + arm_a, link.position + arm_b);
    let ab = b - a;
    let length2 = ab.norm_squared();
    let s = (wheel.position - a).dot(&ab) / length2;
    let d_centre = body_point(nalgebra::Vector2::zeros(), OTHER);
    let d_a = body_point(arm_a, LINK);
    let point = if s <= 0.0 {
        d_a
    } else if s >= 1.0 {
        body_point(arm_b, LINK)
    } else {
        // The face turns rigidly with the link: ∂(b − a) = ⟂(b − a) ∂θ.
        let mut d_ab = PoseRows2::zeros();
        let turned = perp(ab);
        d_ab[(0, LINK + 2)] = turned.x;
        d_ab[(1, LINK + 2)] = turned.y;
        let d_s = (dot_rows(ab, &(d_centre - d_a)) + dot_rows(wheel.position - a, &d_ab)) / length2;
        d_a + d_ab * s + ab * d_s
    };
    let to_face = contact.point - wheel.position;
    let distance = to_face.norm();
    let normal = to_face / distance;
    let d_offset = point - d_centre;
    GeometryTangent {
        point,
        depth: -dot_rows(normal, &d_offset),
        gradient: unit_vector(normal, distance, &d_offset),
    }
}
