//! Contact between the track and the world (paper part II, which we design
//! here; spec §4): the normal and friction laws, the terrain, and the three
//! contact pairs — link and ground, link and wheel (road wheels, idler,
//! rollers), link pins and sprocket teeth; and the terramechanics laws of
//! soft soil ([`soil`]).
//!
//! Every pair evaluates forces from positions and velocities only, and
//! returns them as [`BodyLoad`](crate::BodyLoad)s on both bodies, so the
//! subsystems stay decoupled everywhere else (spec §3).

pub mod ground;
pub mod law;
pub mod shoe;
pub mod soft_ground;
pub mod soil;
pub mod sprocket;
pub mod terrain;
pub mod wheel;

pub use law::{Friction, NormalLaw};
pub use shoe::ShoeGeometry;
pub use terrain::{Terrain, TerrainError};

use nalgebra::Vector2;

/// A body in motion: where it is and how fast it moves.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BodyState {
    /// Centroid, m.
    pub position: Vector2<f64>,
    /// Angle, rad.
    pub angle: f64,
    /// Centroid velocity, m/s.
    pub velocity: Vector2<f64>,
    /// Angular velocity, rad/s.
    pub omega: f64,
    /// `sin` and `cos` of the angle, computed once.
    sin: f64,
    cos: f64,
}

impl BodyState {
    /// A body at `position` (m) and `angle` (rad), moving at `velocity`
    /// (m/s) and `omega` (rad/s).
    pub fn new(position: Vector2<f64>, angle: f64, velocity: Vector2<f64>, omega: f64) -> Self {
        Self::with_sin_cos(position, angle, angle.sin_cos(), velocity, omega)
    }

    /// [`new`](Self::new), given `(sin θ, cos θ)` already.
    pub fn with_sin_cos(
        position: Vector2<f64>,
        angle: f64,
        (sin, cos): (f64, f64),
        velocity: Vector2<f64>,
        omega: f64,
    ) -> Self {
        BodyState {
            position,
            angle,
            velocity,
            omega,
            sin,
            cos,
        }
    }

    /// `(sin θ, cos θ)`.
    pub fn sin_cos(&self) -> (f64, f64) {
        (self.sin, self.cos)
    }

    /// The global offset `A ū` of body point `ū` from the centroid.
    #[inline]
    pub fn arm(&self, local: Vector2<f64>) -> Vector2<f64> {
        Vector2::new(
            self.cos * local.x - self.sin * local.y,
            self.sin * local.x + self.cos * local.y,
        )
    }

    /// Global position of body point `ū`.
    #[inline]
    pub fn point(&self, local: Vector2<f64>) -> Vector2<f64> {
        self.position + self.arm(local)
    }

    /// Velocity of the material point at global offset `arm` from the
    /// centroid: `Ṙ + ω × arm`.
    #[inline]
    pub fn velocity_at(&self, arm: Vector2<f64>) -> Vector2<f64> {
        self.velocity + Vector2::new(-arm.y, arm.x) * self.omega
    }
}

/// Calls `f(i, link)` for every link whose centroid is within `reach` (m)
/// of `centre`, in order, and for any whose distance is not a number (so a
/// NaN state shows as a NaN force). The distances are compared 64 links at
/// a time into a bit mask without branches, then the few links near are
/// visited: a wheel is near a handful of a track's links, and a branch per
/// link mispredicts at the edges of every run of them.
#[inline]
pub(crate) fn each_near(
    links: &[BodyState],
    centre: Vector2<f64>,
    reach: f64,
    mut f: impl FnMut(usize, &BodyState),
) {
    let reach2 = reach * reach;
    for (chunk, block) in links.chunks(64).enumerate() {
        let mut near = 0u64;
        for (k, link) in block.iter().enumerate() {
            let (dx, dy) = (link.position.x - centre.x, link.position.y - centre.y);
            // `!(d² > r²)`: true for NaN.
            near |= u64::from(!(dx * dx + dy * dy > reach2)) << k;
        }
        while near != 0 {
            let k = near.trailing_zeros() as usize;
            near &= near - 1;
            f(chunk * 64 + k, &block[k]);
        }
    }
}

/// One contact's force on the first body of the pair, at a global point.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactForce {
    /// Contact point, m.
    pub point: Vector2<f64>,
    /// Force on the first body (the track link), N.
    pub force: Vector2<f64>,
    /// Normal component (≥ 0), N.
    pub normal: f64,
    /// Penetration, m.
    pub penetration: f64,
    /// Power the contact dissipates (damping and friction), W.
    pub dissipation: f64,
    /// Elastic energy stored in the contact, J.
    pub potential: f64,
}

impl ContactForce {
    /// A contact's force from its laws: normal `n` (unit, on the first
    /// body), relative velocity `v` of the first body's point against the
    /// second's.
    pub(crate) fn evaluate(
        normal_law: &NormalLaw,
        friction: &Friction,
        point: Vector2<f64>,
        n: Vector2<f64>,
        penetration: f64,
        v: Vector2<f64>,
    ) -> ContactForce {
        let rate = -v.dot(&n);
        let fn_ = normal_law.force(penetration, rate);
        let t = Vector2::new(-n.y, n.x);
        let slip = v.dot(&t);
        let ft = friction.force(fn_, slip);
        // Power lost: the normal force beyond its elastic part times the
        // closing rate, and friction against slip.
        let dissipation = (fn_ - normal_law.elastic_force(penetration)) * rate - ft * slip;
        ContactForce {
            point,
            force: n * fn_ + t * ft,
            normal: fn_,
            penetration,
            dissipation,
            potential: normal_law.potential(penetration),
        }
    }
}

/// A contact between a link and another body (a wheel, the sprocket) at
/// `point` with `normal` (unit, on the link): the force from the laws on the
/// relative velocity, added to the link's load and, reversed, to the
/// other's.
pub(crate) fn exchange(
    (normal_law, friction): (&NormalLaw, &Friction),
    (link, link_load): (&BodyState, &mut crate::model::BodyLoad),
    (other, other_load): (&BodyState, &mut crate::model::BodyLoad),
    (point, normal, penetration): (Vector2<f64>, Vector2<f64>, f64),
) -> ContactForce {
    use crate::model::BodyLoad;
    let (link_arm, other_arm) = (point - link.position, point - other.position);
    let relative = link.velocity_at(link_arm) - other.velocity_at(other_arm);
    let contact =
        ContactForce::evaluate(normal_law, friction, point, normal, penetration, relative);
    *link_load = link_load.plus(BodyLoad::force_at(contact.force, link_arm));
    *other_load = other_load.plus(BodyLoad::force_at(-contact.force, other_arm));
    contact
}
