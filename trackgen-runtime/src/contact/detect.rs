//! What detection finds: a contact between a link and the world, as
//! geometry and kinematics, before any law.

use nalgebra::Vector2;

/// A contact of a link's feature with the ground, a wheel's rim or the
/// sprocket's teeth: found by [`ground`](super::ground),
/// [`wheel`](super::wheel) or [`sprocket`](super::sprocket) detection, turned
/// into a force by [`ContactLaws::respond`](super::ContactLaws::respond)
/// (or the soil's law).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Contact {
    /// The link, 0-based.
    pub link: usize,
    /// The other body's index in the chassis tree (a wheel, the sprocket),
    /// `None` for the ground.
    pub other: Option<usize>,
    /// Which of the link's features touches: the index of the shoe's
    /// ground point (ground) or pin (teeth); 0 for the inner face (rims).
    pub feature: usize,
    /// The contact point, global frame, m.
    pub point: Vector2<f64>,
    /// The point's offset from the link's centroid, global frame, m (the
    /// moment arm of the force on the link).
    pub arm: Vector2<f64>,
    /// Penetration `δ` (> 0), m.
    pub depth: f64,
    /// `g = −∂δ/∂p`: the direction the normal force pushes the link, of
    /// length [`gradient_norm`](Self::gradient_norm). Unit for rims and
    /// teeth; `(−h′, 1)` on a terrain `y = h(x)`, whose penetration is
    /// measured vertically, so that `F(δ) g` is exactly the gradient of the
    /// contact's potential on any profile.
    pub gradient: Vector2<f64>,
    /// `|g|`, kept as computed (1 exactly for rims and teeth).
    pub gradient_norm: f64,
    /// The velocity of the link's material point at the contact, relative
    /// to the other body's material point there, m/s. The penetration's
    /// rate is `δ̇ = −v · g`.
    pub velocity: Vector2<f64>,
}

/// [`Contact::feature`] of a terrain corner inside a body's outline
/// ([`outline`](super::outline)): the body's own features are numbered
/// from 0.
pub const TERRAIN_CORNER: usize = usize::MAX;

impl Contact {
    /// Where this contact's tangential state sits among a track's ground
    /// points (`per_link` to a link): `link · per_link + feature` for a
    /// shoe's ground point on the ground; `None` for a rim, a tooth or a
    /// terrain corner, which have none. The one place that knows it.
    #[inline]
    pub fn ground_point_slot(&self, per_link: usize) -> Option<usize> {
        (self.other.is_none() && self.feature != TERRAIN_CORNER)
            .then(|| self.link * per_link + self.feature)
    }

    /// The closing rate `δ̇ = −v · g`, m/s.
    #[inline]
    pub fn rate(&self) -> f64 {
        -self.velocity.dot(&self.gradient)
    }

    /// The unit tangent along which friction acts: `g` turned a quarter
    /// counter-clockwise, over `|g|`.
    #[inline]
    pub fn tangent(&self) -> Vector2<f64> {
        Vector2::new(-self.gradient.y, self.gradient.x) / self.gradient_norm
    }
}
