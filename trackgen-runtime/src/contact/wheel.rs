//! Where wheel rims (road wheels, idler, rollers: circles) meet the shoes'
//! inner running faces (segments).

use nalgebra::Vector2;

use super::{BodyState, Contact, ShoeGeometry};

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
