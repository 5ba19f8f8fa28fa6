//! Link-ground contact: each shoe's ground points against the terrain.

use nalgebra::Vector2;

use super::{BodyState, ContactForce, Friction, NormalLaw, ShoeGeometry, Terrain};
use crate::model::BodyLoad;

/// The ground: a terrain profile with its contact laws.
#[derive(Debug, Clone, PartialEq)]
pub struct GroundContact {
    /// The profile.
    pub terrain: Terrain,
    /// Normal law per contact point.
    pub normal: NormalLaw,
    /// Friction per contact point.
    pub friction: Friction,
}

impl GroundContact {
    /// Forces on the links from the ground, added to `loads` (one per
    /// link); every active contact is passed to `each`.
    ///
    /// Links whose bounding circle clears the highest terrain beneath them
    /// are skipped without looking at their points, so the cost is one
    /// comparison per link plus the links actually near the ground.
    pub fn apply(
        &self,
        links: &[BodyState],
        shoe: &ShoeGeometry,
        loads: &mut [BodyLoad],
        mut each: impl FnMut(usize, &ContactForce),
    ) {
        let extent = shoe.extent();
        for (i, link) in links.iter().enumerate() {
            let x = link.position.x;
            if link.position.y - extent > self.terrain.max_height(x - extent, x + extent) {
                continue;
            }
            for local in &shoe.ground_points {
                let arm = link.arm(*local);
                let point = link.position + arm;
                let (h, slope) = self.terrain.height_and_slope(point.x);
                let normal = Vector2::new(-slope, 1.0) / (1.0 + slope * slope).sqrt();
                let penetration = (h - point.y) * normal.y;
                if penetration <= 0.0 {
                    continue;
                }
                let velocity = link.velocity_at(arm);
                let contact = ContactForce::evaluate(
                    &self.normal,
                    &self.friction,
                    point,
                    normal,
                    penetration,
                    velocity,
                );
                loads[i] = loads[i].plus(BodyLoad::force_at(contact.force, arm));
                each(i, &contact);
            }
        }
    }
}
