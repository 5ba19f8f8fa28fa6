//! A point of a shoe against the ground in space
//! ([`HeightField`]): the planar ground contact's laws with a third
//! dimension. The penetration is measured vertically, `δ = z(x, y) − z_p`,
//! as in the plane, so the normal force acts along the field's gradient
//! `g = (−∂z/∂x, −∂z/∂y, 1)` (`F(δ, δ̇) g` is the gradient of the contact's
//! potential on any field) and presses with `F |g|`; friction acts in the
//! surface's tangent plane against the point's slip there, isotropic
//! ([`Stiction::respond_in_plane`](crate::laws::Stiction::respond_in_plane),
//! or regularised Coulomb along the slip), its deflection two components
//! in the plane's forward and left tangents. On level ground and with no
//! motion across the plane it is the planar contact's law.

use nalgebra::{Vector2, Vector3};

use super::respond::{GroundFriction, GroundLaws};
use crate::terrain::field::HeightField;

/// A point in the ground.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SpaceContact {
    /// The point, world frame, m.
    pub point: Vector3<f64>,
    /// Its penetration `δ = z(x, y) − z_p` (> 0), m.
    pub depth: f64,
    /// `g = (−∂z/∂x, −∂z/∂y, 1)`: the direction the normal force pushes.
    pub gradient: Vector3<f64>,
    /// The point's material velocity against the ground, m/s.
    pub velocity: Vector3<f64>,
}

/// What a [`SpaceContact`] gives under [`GroundLaws::respond_in_space`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SpaceForce {
    /// The force on the body at the point, world frame, N.
    pub force: Vector3<f64>,
    /// The normal force `F |g|` (≥ 0), N.
    pub normal: f64,
    /// The deflection's rate in the surface's forward and left tangents,
    /// m/s (zero under regularised friction, which has no deflection).
    pub rate: Vector2<f64>,
    /// Elastic energy stored, J.
    pub potential: f64,
    /// Power dissipated, W.
    pub dissipation: f64,
}

impl SpaceContact {
    /// The point `point` (world, m) moving at `velocity` (m/s) against
    /// `field`: `None` above it.
    #[inline]
    pub fn at(
        field: &HeightField,
        point: Vector3<f64>,
        velocity: Vector3<f64>,
    ) -> Option<SpaceContact> {
        let (height, slope) = field.height_and_gradient(point.x, point.y);
        let depth = height - point.z;
        (depth > 0.0).then(|| SpaceContact {
            point,
            depth,
            gradient: Vector3::new(-slope.x, -slope.y, 1.0),
            velocity,
        })
    }

    /// The closing rate `δ̇ = −v · g`, m/s.
    pub fn rate(&self) -> f64 {
        -self.velocity.dot(&self.gradient)
    }

    /// The surface's unit tangents: forward (in the vertical plane of `x`)
    /// and left, orthogonal, right-handed with the upward normal.
    pub fn tangents(&self) -> (Vector3<f64>, Vector3<f64>) {
        self.tangents_with(self.gradient.norm())
    }

    /// `|g|` and the surface's unit tangents, forward and left
    /// ([`tangents`](Self::tangents)). On level ground (`g = (0, 0, 1)`,
    /// most of any course) they are `1`, `x̂` and `ŷ`, which the general
    /// route gives too (to the sign of a zero component) after a root and
    /// six divisions: not found again per point.
    #[inline]
    pub(crate) fn surface(&self) -> (f64, Vector3<f64>, Vector3<f64>) {
        let g = self.gradient;
        if g.x == 0.0 && g.y == 0.0 {
            return (1.0, Vector3::x(), Vector3::y());
        }
        let norm = g.norm();
        let (forward, left) = self.tangents_with(norm);
        (norm, forward, left)
    }

    /// [`tangents`](Self::tangents) with `|g|` (`norm`) found already.
    /// Where the field does not slope across `x` (`∂z/∂y = 0`, a profile
    /// or a level field), the forward tangent `(1, 0, ∂z/∂x)` has the
    /// same length, summed in the same terms: it is not found again.
    #[inline]
    fn tangents_with(&self, norm: f64) -> (Vector3<f64>, Vector3<f64>) {
        let g = self.gradient;
        let normal = g / norm;
        let forward = Vector3::new(1.0, 0.0, -g.x);
        let along = if g.y == 0.0 { norm } else { forward.norm() };
        let forward = forward / along;
        (forward, normal.cross(&forward))
    }
}

impl GroundLaws {
    /// The force of a ground contact in space whose point's tangential
    /// deflection is `z` (m, in the surface's forward and left tangents;
    /// unused by regularised friction), and its rate.
    pub fn respond_in_space(&self, contact: &SpaceContact, z: Vector2<f64>) -> SpaceForce {
        let rate = contact.rate();
        let normal = self.normal.respond(contact.depth, rate);
        let (norm, forward, left) = contact.surface();
        let pressing = normal.force * norm;
        let slip = Vector2::new(contact.velocity.dot(&forward), contact.velocity.dot(&left));
        let (tangential, deflection_rate, potential, dissipation) = match self.friction {
            GroundFriction::Stiction(stiction) => {
                let r = stiction.respond_in_plane(z, slip, pressing);
                (r.force, r.rate, r.potential, r.dissipation)
            }
            GroundFriction::Regularised(friction) => {
                let speed = slip.norm();
                if speed == 0.0 {
                    (Vector2::zeros(), Vector2::zeros(), 0.0, 0.0)
                } else {
                    let along = friction.force(pressing, speed);
                    (
                        slip * (along / speed),
                        Vector2::zeros(),
                        0.0,
                        -along * speed,
                    )
                }
            }
        };
        SpaceForce {
            force: contact.gradient * normal.force + forward * tangential.x + left * tangential.y,
            normal: pressing,
            rate: deflection_rate,
            potential: normal.potential + potential,
            dissipation: normal.dissipation + dissipation,
        }
    }
}
