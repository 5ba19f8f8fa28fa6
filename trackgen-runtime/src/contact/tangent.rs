//! A contact's force to first order in the states of the two bodies it
//! joins: what a vehicle's exact Jacobian, and the matrix of its linearly
//! implicit integrator, need of each contact beside its load.
//!
//! Detection gives a contact's geometry (point `p`, penetration `δ`,
//! gradient `g`) from the two bodies' poses, and each detector gives its
//! derivatives too ([`GeometryTangent`]: [`ground::tangent`],
//! [`wheel::tangent`], [`sprocket::tangent`]). The relative velocity
//! `v = Ṙ_L + ω_L ⟂(p − R_L) − Ṙ_O − ω_O ⟂(p − R_O)` of the two material
//! points at `p` follows from `p`'s derivative. The laws' slopes
//! ([`NormalLaw::slopes`], [`Friction::slopes`], [`Stiction::slopes`]) then
//! give the force's by the chain rule through the same formulas
//! [`ContactLaws::respond`] and [`GroundLaws::respond`] evaluate.
//!
//! Every derivative is a row over the [`INPUTS`] of a contact: the link's
//! pose `(x, y, θ)` and rates `(ẋ, ẏ, ω)`, the other body's pose and rates
//! (none for the ground), and the ground point's tangential deflection `z`
//! (stiction's state).
//!
//! [`ground::tangent`]: super::ground::tangent
//! [`wheel::tangent`]: super::wheel::tangent
//! [`sprocket::tangent`]: super::sprocket::tangent
//! [`NormalLaw::slopes`]: crate::laws::NormalLaw::slopes
//! [`Friction::slopes`]: crate::laws::Friction::slopes
//! [`Stiction::slopes`]: crate::laws::Stiction::slopes

use nalgebra::{SMatrix, Vector2};

use super::{BodyState, Contact, ContactLaws, GroundFriction, GroundLaws};

/// How many quantities a contact's force depends on: two bodies' poses and
/// rates (3 + 3 each) and a tangential deflection.
pub const INPUTS: usize = 13;
/// The column of the link's `x` (then `y`, `θ`).
pub const LINK_POSE: usize = 0;
/// The column of the link's `ẋ` (then `ẏ`, `ω`).
pub const LINK_RATE: usize = 3;
/// The column of the other body's `x` (then `y`, `θ`).
pub const OTHER_POSE: usize = 6;
/// The column of the other body's `ẋ` (then `ẏ`, `ω`).
pub const OTHER_RATE: usize = 9;
/// The column of the ground point's tangential deflection `z` (m).
pub const DEFLECTION: usize = 12;

/// The derivative of a scalar over a contact's [`INPUTS`].
pub type Row = SMatrix<f64, 1, INPUTS>;
/// The derivative of a planar vector, a row per component.
pub type Rows2 = SMatrix<f64, 2, INPUTS>;
/// The derivative of a load `(F_x, F_y, M)`, a row per component.
pub type Rows3 = SMatrix<f64, 3, INPUTS>;

/// The derivatives of a contact's geometry with the two bodies' poses (the
/// rate columns are zero): what each detector gives beside its contact.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GeometryTangent {
    /// `∂p`, m per unit of each input.
    pub point: Rows2,
    /// `∂δ`.
    pub depth: Row,
    /// `∂g`.
    pub gradient: Rows2,
}

impl GeometryTangent {
    /// No change.
    pub const ZERO: GeometryTangent = GeometryTangent {
        point: Rows2::from_array_storage(nalgebra::ArrayStorage([[0.0; 2]; INPUTS])),
        depth: Row::from_array_storage(nalgebra::ArrayStorage([[0.0; 1]; INPUTS])),
        gradient: Rows2::from_array_storage(nalgebra::ArrayStorage([[0.0; 2]; INPUTS])),
    };
}

/// A contact's load and rate to first order: their derivatives over the
/// contact's [`INPUTS`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactJacobian {
    /// `∂(F_x, F_y, M)` of the load on the link (the moment about its
    /// centroid).
    pub link: Rows3,
    /// `∂(F_x, F_y, M)` of the load on the other body (about its
    /// centroid); zero for the ground.
    pub other: Rows3,
    /// `∂ż` of the tangential deflection's rate (stiction); zero otherwise.
    pub rate: Row,
}

/// `⟂v = (−v_y, v_x)`.
#[inline]
pub(crate) fn perp(v: Vector2<f64>) -> Vector2<f64> {
    Vector2::new(-v.y, v.x)
}

/// `⟂` of a vector's derivative, row-wise.
#[inline]
fn perp_rows(m: &Rows2) -> Rows2 {
    let mut out = Rows2::zeros();
    out.set_row(0, &(-m.row(1)));
    out.set_row(1, &m.row(0));
    out
}

/// `∂(a · b)` for a constant `a`: `a_x ∂b_x + a_y ∂b_y`.
#[inline]
pub(crate) fn dot_rows(a: Vector2<f64>, m: &Rows2) -> Row {
    m.row(0) * a.x + m.row(1) * a.y
}

/// The unit row `∂x/∂x` of input `column`.
#[inline]
fn unit(column: usize) -> Row {
    let mut r = Row::zeros();
    r[column] = 1.0;
    r
}

/// `∂(R + offset)` of a point fixed on a body whose pose starts at column
/// `pose`, at global offset `offset = A ū` from its centroid:
/// `[I | ⟂offset]` (`∂(A ū)/∂θ = ⟂(A ū)`).
#[inline]
pub(crate) fn body_point(offset: Vector2<f64>, pose: usize) -> Rows2 {
    let mut m = Rows2::zeros();
    m[(0, pose)] = 1.0;
    m[(1, pose + 1)] = 1.0;
    m[(0, pose + 2)] = -offset.y;
    m[(1, pose + 2)] = offset.x;
    m
}

/// The derivative of a unit vector `u = d/|d|` from `d`'s: `(∂d − u (u·∂d))/|d|`.
#[inline]
pub(crate) fn unit_vector(u: Vector2<f64>, length: f64, d: &Rows2) -> Rows2 {
    (d - u * dot_rows(u, d)) / length
}

/// `∂v` of the relative velocity of the two material points at the
/// contact point, from the point's derivative.
fn velocity(point: &Rows2, p: Vector2<f64>, link: &BodyState, other: Option<&BodyState>) -> Rows2 {
    let mut dv = Rows2::zeros();
    let mut add = |body: &BodyState, pose: usize, rate: usize, sign: f64| {
        let arm = p - body.position;
        // `Ṙ + ω ⟂arm`, with the arm `p − R` moving as `∂p − ∂R`.
        dv[(0, rate)] += sign;
        dv[(1, rate + 1)] += sign;
        let lever = perp(arm);
        dv[(0, rate + 2)] += sign * lever.x;
        dv[(1, rate + 2)] += sign * lever.y;
        let mut d_arm = *point;
        d_arm[(0, pose)] -= 1.0;
        d_arm[(1, pose + 1)] -= 1.0;
        dv += perp_rows(&d_arm) * (sign * body.omega);
    };
    add(link, LINK_POSE, LINK_RATE, 1.0);
    if let Some(other) = other {
        add(other, OTHER_POSE, OTHER_RATE, -1.0);
    }
    dv
}

/// The contact's gradient norm `|g|`, its unit tangent `t = ⟂g/|g|` and
/// their derivatives.
fn tangent_of(contact: &Contact, geometry: &GeometryTangent) -> (Row, Vector2<f64>, Rows2) {
    let (g, norm) = (contact.gradient, contact.gradient_norm);
    let d_norm = dot_rows(g, &geometry.gradient) / norm;
    let d_tangent = (perp_rows(&geometry.gradient) - perp(g) * (d_norm / norm)) / norm;
    (d_norm, contact.tangent(), d_tangent)
}

/// The loads' derivatives from the force on the link and its derivative:
/// the link takes `F` at its arm `p − R_L`, the other body `−F` at
/// `p − R_O`.
fn loads(
    contact: &Contact,
    geometry: &GeometryTangent,
    (link, other): (&BodyState, Option<&BodyState>),
    force: Vector2<f64>,
    d_force: &Rows2,
    rate: Row,
) -> ContactJacobian {
    let moment = |arm: Vector2<f64>, pose: usize, sign: f64| {
        let mut d_arm = geometry.point;
        d_arm[(0, pose)] -= 1.0;
        d_arm[(1, pose + 1)] -= 1.0;
        // ∂(arm × F) = ∂arm × F + arm × ∂F.
        (d_arm.row(0) * force.y - d_arm.row(1) * force.x + d_force.row(1) * arm.x
            - d_force.row(0) * arm.y)
            * sign
    };
    let mut on_link = Rows3::zeros();
    on_link.fixed_rows_mut::<2>(0).copy_from(d_force);
    on_link.set_row(2, &moment(contact.point - link.position, LINK_POSE, 1.0));
    let mut on_other = Rows3::zeros();
    if let Some(other) = other {
        on_other.fixed_rows_mut::<2>(0).copy_from(&(-d_force));
        on_other.set_row(2, &moment(contact.point - other.position, OTHER_POSE, -1.0));
    }
    ContactJacobian {
        link: on_link,
        other: on_other,
        rate,
    }
}

/// The normal force per unit gradient `N`, its derivative, and the
/// closing rate's derivative, under `law` (the normal law of either kind
/// of contact).
fn normal_part(
    law: &crate::laws::NormalLaw,
    contact: &Contact,
    geometry: &GeometryTangent,
    dv: &Rows2,
) -> (f64, Row) {
    let rate = contact.rate();
    let d_rate = -(dot_rows(contact.gradient, dv) + dot_rows(contact.velocity, &geometry.gradient));
    let normal = law.force(contact.depth, rate);
    let (by_depth, by_rate) = law.slopes(contact.depth, rate);
    (normal, geometry.depth * by_depth + d_rate * by_rate)
}

impl ContactLaws {
    /// The first derivatives of [`respond`](Self::respond)'s loads (applied
    /// as [`ContactForce::apply`](super::ContactForce::apply) applies them)
    /// over the contact's [`INPUTS`], given the geometry's derivatives and
    /// the states of the link and of the other body (`None`: the ground).
    pub fn linearise(
        &self,
        contact: &Contact,
        geometry: &GeometryTangent,
        link: &BodyState,
        other: Option<&BodyState>,
    ) -> ContactJacobian {
        let dv = velocity(&geometry.point, contact.point, link, other);
        let (normal, d_normal) = normal_part(&self.normal, contact, geometry, &dv);
        let (d_norm, tangent, d_tangent) = tangent_of(contact, geometry);
        let (v, g) = (contact.velocity, contact.gradient);
        let slip = v.dot(&tangent);
        let d_slip = dot_rows(tangent, &dv) + dot_rows(v, &d_tangent);
        let total = normal * contact.gradient_norm;
        let d_total = d_normal * contact.gradient_norm + d_norm * normal;
        let friction = self.friction.force(total, slip);
        let (by_normal, by_slip) = self.friction.slopes(total, slip);
        let d_friction = d_total * by_normal + d_slip * by_slip;
        let force = g * normal + tangent * friction;
        let d_force =
            geometry.gradient * normal + g * d_normal + d_tangent * friction + tangent * d_friction;
        loads(
            contact,
            geometry,
            (link, other),
            force,
            &d_force,
            Row::zeros(),
        )
    }
}

impl GroundLaws {
    /// The first derivatives of [`respond`](Self::respond)'s load on the
    /// link and of the deflection's rate, over the contact's [`INPUTS`]
    /// (the deflection `z`, m, in column [`DEFLECTION`]).
    pub fn linearise(
        &self,
        contact: &Contact,
        z: f64,
        geometry: &GeometryTangent,
        link: &BodyState,
    ) -> ContactJacobian {
        let stiction = match self.friction {
            GroundFriction::Regularised(friction) => {
                let laws = ContactLaws {
                    normal: self.normal,
                    friction,
                };
                return laws.linearise(contact, geometry, link, None);
            }
            GroundFriction::Stiction(stiction) => stiction,
        };
        let dv = velocity(&geometry.point, contact.point, link, None);
        let (normal, d_normal) = normal_part(&self.normal, contact, geometry, &dv);
        let (d_norm, tangent, d_tangent) = tangent_of(contact, geometry);
        let (forward, d_forward) = (-tangent, -d_tangent);
        let v = contact.velocity;
        let slip = v.dot(&forward);
        let d_slip = dot_rows(forward, &dv) + dot_rows(v, &d_forward);
        let total = normal * contact.gradient_norm;
        let d_total = d_normal * contact.gradient_norm + d_norm * normal;
        let tangential = stiction.respond(z, slip, total);
        let slopes = stiction.slopes(z, slip, total);
        let along = |[by_z, by_slip, by_normal]: [f64; 3]| {
            unit(DEFLECTION) * by_z + d_slip * by_slip + d_total * by_normal
        };
        let d_tangential = along(slopes.force);
        let force = contact.gradient * normal + forward * tangential.force;
        let d_force = geometry.gradient * normal
            + contact.gradient * d_normal
            + d_forward * tangential.force
            + forward * d_tangential;
        loads(
            contact,
            geometry,
            (link, None),
            force,
            &d_force,
            along(slopes.rate),
        )
    }
}
