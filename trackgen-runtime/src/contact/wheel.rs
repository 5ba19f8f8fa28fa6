//! Link-wheel contact: a wheel's rim (a circle) against the shoes' inner
//! running faces (segments). Road wheels, idler and rollers.

use nalgebra::Vector2;

use super::{BodyState, ContactForce, Friction, NormalLaw, ShoeGeometry};
use crate::model::BodyLoad;

/// The contact laws between rims and shoes.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct WheelContact {
    /// Normal law.
    pub normal: NormalLaw,
    /// Friction.
    pub friction: Friction,
}

impl WheelContact {
    /// Forces between the wheel (its state, and its radius in m) and every
    /// link near it: on
    /// the links into `link_loads`, the reactions into `wheel_load`.
    ///
    /// Only links whose bounding circle reaches the rim are examined.
    pub fn apply(
        &self,
        (wheel, radius): (&BodyState, f64),
        links: &[BodyState],
        shoe: &ShoeGeometry,
        link_loads: &mut [BodyLoad],
        wheel_load: &mut BodyLoad,
        mut each: impl FnMut(usize, &ContactForce),
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
            let penetration = radius - distance;
            if penetration <= 0.0 || distance == 0.0 {
                return;
            }
            let normal = to_face / distance;
            let contact = super::exchange(
                (&self.normal, &self.friction),
                (link, &mut link_loads[i]),
                (wheel, wheel_load),
                (point, normal, penetration),
            );
            each(i, &contact);
        });
    }
}
