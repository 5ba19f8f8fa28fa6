//! A contact's response: the normal law and friction turn a detected
//! [`Contact`] into a force with its energy terms, applied to both
//! bodies' loads.

use nalgebra::Vector2;

use super::Contact;
use crate::laws::{Friction, NormalLaw, ParameterError, Stiction};
use crate::multibody::BodyLoad;

/// The laws of one contact pair: normal law and friction.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactLaws {
    /// The normal law.
    pub normal: NormalLaw,
    /// The friction.
    pub friction: Friction,
}

/// One contact's force on the link, with what it stores and dissipates.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactForce {
    /// Contact point, m.
    pub point: Vector2<f64>,
    /// Force on the link, N (the other body takes its reverse).
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

impl ContactLaws {
    /// The force of `contact` under these laws: the normal law at the
    /// penetration and its rate `δ̇ = −v·g` gives the force along `g`;
    /// friction, under the normal force `F |g|`, acts along the tangent
    /// against the slip `v·t`. The power lost is the normal force beyond
    /// its elastic part times the closing rate, and friction against slip.
    #[inline]
    pub fn respond(&self, contact: &Contact) -> ContactForce {
        let rate = contact.rate();
        let normal = self.normal.respond(contact.depth, rate);
        let tangent = contact.tangent();
        let slip = contact.velocity.dot(&tangent);
        let friction = self
            .friction
            .respond(normal.force * contact.gradient_norm, slip);
        ContactForce {
            point: contact.point,
            force: contact.gradient * normal.force + tangent * friction.force,
            normal: normal.force * contact.gradient_norm,
            penetration: contact.depth,
            dissipation: normal.dissipation + friction.dissipation,
            potential: normal.potential,
        }
    }

    /// Zero coefficients and rates of zero or more, finite.
    pub fn check(&self) -> Result<(), ParameterError> {
        self.normal.check()?;
        self.friction.check()
    }
}

/// The friction of the shoes on rigid ground: elastic with a Coulomb limit
/// ([`Stiction`], holding a parked vehicle on a grade; its deflection is a
/// state per ground point), or regularised Coulomb ([`Friction`], no
/// state, sliding at any load).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum GroundFriction {
    /// Stiction: a tangential spring-damper with a Coulomb limit.
    Stiction(Stiction),
    /// Regularised Coulomb friction.
    Regularised(Friction),
}

impl GroundFriction {
    /// The friction coefficient `μ`.
    pub fn mu(&self) -> f64 {
        match self {
            GroundFriction::Stiction(s) => s.mu,
            GroundFriction::Regularised(f) => f.mu,
        }
    }

    /// The same law with coefficient `mu`.
    pub fn with_mu(self, mu: f64) -> GroundFriction {
        match self {
            GroundFriction::Stiction(s) => GroundFriction::Stiction(Stiction { mu, ..s }),
            GroundFriction::Regularised(f) => GroundFriction::Regularised(Friction { mu, ..f }),
        }
    }

    /// Whether each ground point carries a tangential state.
    pub fn has_state(&self) -> bool {
        matches!(self, GroundFriction::Stiction(_))
    }

    /// Every parameter in its range.
    pub fn check(&self) -> Result<(), ParameterError> {
        match self {
            GroundFriction::Stiction(s) => s.check(),
            GroundFriction::Regularised(f) => f.check(),
        }
    }
}

/// The laws of the shoes on rigid ground: normal law and friction.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GroundLaws {
    /// The normal law.
    pub normal: NormalLaw,
    /// The friction.
    pub friction: GroundFriction,
}

impl GroundLaws {
    /// The force of a ground contact whose point's tangential deflection
    /// is `z` (m, along the surface's forward tangent; unused by
    /// regularised friction), and `ż`: the normal law along the
    /// surface's gradient, friction along the surface, under the normal
    /// force `F |g|`.
    #[inline]
    pub fn respond(&self, contact: &Contact, z: f64) -> (ContactForce, f64) {
        let stiction = match self.friction {
            GroundFriction::Regularised(friction) => {
                let laws = ContactLaws {
                    normal: self.normal,
                    friction,
                };
                return (laws.respond(contact), 0.0);
            }
            GroundFriction::Stiction(stiction) => stiction,
        };
        let rate = contact.rate();
        let normal = self.normal.respond(contact.depth, rate);
        let forward = -contact.tangent();
        let slip = contact.velocity.dot(&forward);
        let normal_force = normal.force * contact.gradient_norm;
        let tangential = stiction.respond(z, slip, normal_force);
        let force = ContactForce {
            point: contact.point,
            force: contact.gradient * normal.force + forward * tangential.force,
            normal: normal_force,
            penetration: contact.depth,
            dissipation: normal.dissipation + tangential.dissipation,
            potential: normal.potential + tangential.potential,
        };
        (force, tangential.rate)
    }

    /// Every parameter in its range.
    pub fn check(&self) -> Result<(), ParameterError> {
        self.normal.check()?;
        self.friction.check()
    }
}

impl ContactForce {
    /// Adds the force to the link's load at the contact's arm and its
    /// reverse to the other body's (if any) at the point's offset from
    /// that body's centroid `other_position`.
    #[inline]
    pub fn apply(
        &self,
        contact: &Contact,
        link_load: &mut BodyLoad,
        other: Option<(&mut BodyLoad, Vector2<f64>)>,
    ) {
        *link_load = link_load.plus(BodyLoad::force_at(self.force, contact.arm));
        if let Some((load, position)) = other {
            *load = load.plus(BodyLoad::force_at(-self.force, contact.point - position));
        }
    }
}
