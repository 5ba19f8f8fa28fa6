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
    /// Links whose bounding circle clears the highest terrain under the
    /// whole track are skipped without looking at their points, so the cost
    /// is one comparison per link plus the links actually near the ground
    /// (the terrain's highest point is found once, over the track's
    /// extent).
    pub fn apply(
        &self,
        links: &[BodyState],
        shoe: &ShoeGeometry,
        loads: &mut [BodyLoad],
        mut each: impl FnMut(usize, &ContactForce),
    ) {
        let clear = clear_of(&self.terrain, links, shoe);
        for (i, link) in links.iter().enumerate() {
            if clear(link) {
                continue;
            }
            for local in &shoe.ground_points {
                let arm = link.arm(*local);
                let point = link.position + arm;
                let (h, slope) = self.terrain.height_and_slope(point.x);
                // Penetration below the profile, δ = h(x) − y: continuous
                // over kinks, and its exact rate is −v·g with g = (−h′, 1),
                // so the elastic force g·F(δ) is exactly the gradient of
                // the contact's potential and the energy books balance on
                // any terrain.
                let penetration = h - point.y;
                if penetration <= 0.0 {
                    continue;
                }
                let velocity = link.velocity_at(arm);
                let g = Vector2::new(-slope, 1.0);
                let rate = -velocity.dot(&g);
                let normal = self.normal.force(penetration, rate);
                let tangent = Vector2::new(g.y, -g.x) / g.norm();
                let slip = velocity.dot(&tangent);
                let friction = self.friction.force(normal * g.norm(), slip);
                let force = g * normal + tangent * friction;
                let contact = ContactForce {
                    point,
                    force,
                    normal: normal * g.norm(),
                    penetration,
                    dissipation: (normal - self.normal.elastic_force(penetration)) * rate
                        - friction * slip,
                    potential: self.normal.potential(penetration),
                };
                loads[i] = loads[i].plus(BodyLoad::force_at(force, arm));
                each(i, &contact);
            }
        }
    }
}

/// A test of whether a link's bounding circle clears the highest point of
/// `terrain` under the whole track (found once, over the track's extent):
/// such a link touches nothing, so a contact pass costs one comparison
/// per link plus the links actually near the ground. A NaN position
/// compares false and is looked at: its force is NaN, and the run stops
/// with the cause.
pub(crate) fn clear_of(
    terrain: &Terrain,
    links: &[BodyState],
    shoe: &ShoeGeometry,
) -> impl Fn(&BodyState) -> bool {
    let extent = shoe.extent();
    let (low, high) = links
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), l| {
            (lo.min(l.position.x), hi.max(l.position.x))
        });
    let highest = terrain.max_height(low - extent, high + extent);
    move |link| link.position.y - extent > highest
}
