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
//! Every derivative is a row over the [`INPUTS`](ContactJacobian::INPUTS) of a contact: the link's
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

use std::ops::AddAssign;

use nalgebra::{Matrix2, Matrix2x3, RowVector2, SMatrix, Vector2};

use super::{BodyState, Contact, ContactLaws, GroundFriction, GroundLaws};
use crate::planar::perp;

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

/// The derivative of a scalar over a contact's [`INPUTS`](ContactJacobian::INPUTS).
pub type Row = SMatrix<f64, 1, INPUTS>;
/// The derivative of a load `(F_x, F_y, M)`, a row per component.
pub type Rows3 = SMatrix<f64, 3, INPUTS>;

/// How many pose coordinates a contact's geometry depends on: the link's
/// `(x, y, θ)` (columns 0–2) and the other body's (3–5).
pub const POSES: usize = 6;
/// The geometry's column of the link's `x`.
pub const LINK: usize = 0;
/// The geometry's column of the other body's `x`.
pub const OTHER: usize = 3;
/// The derivative of a scalar over the two poses.
pub type PoseRow = SMatrix<f64, 1, POSES>;
/// The derivative of a planar vector over the two poses.
pub type PoseRows2 = SMatrix<f64, 2, POSES>;

/// The derivatives of a contact's geometry with the two bodies' poses
/// (what each detector gives beside its contact; velocities do not move
/// it).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GeometryTangent {
    /// `∂p`, m per unit of each pose coordinate.
    pub point: PoseRows2,
    /// `∂δ`.
    pub depth: PoseRow,
    /// `∂g`.
    pub gradient: PoseRows2,
}

/// A contact's load and rate to first order: their derivatives over the
/// contact's [`INPUTS`](Self::INPUTS) columns.
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

impl ContactJacobian {
    /// How many quantities a contact's force depends on, its columns: two
    /// bodies' poses and rates (3 + 3 each) and a tangential deflection.
    pub const INPUTS: usize = INPUTS;
    /// The column of the link's `x` (then `y`, `θ`).
    pub const LINK_POSE: usize = LINK_POSE;
    /// The column of the link's `ẋ` (then `ẏ`, `ω`).
    pub const LINK_RATE: usize = LINK_RATE;
    /// The column of the other body's `x` (then `y`, `θ`).
    pub const OTHER_POSE: usize = OTHER_POSE;
    /// The column of the other body's `ẋ` (then `ẏ`, `ω`).
    pub const OTHER_RATE: usize = OTHER_RATE;
    /// The column of the ground point's tangential deflection `z` (m).
    pub const DEFLECTION: usize = DEFLECTION;

    /// No change.
    pub const ZERO: ContactJacobian = ContactJacobian {
        link: Rows3::from_array_storage(nalgebra::ArrayStorage([[0.0; 3]; INPUTS])),
        other: Rows3::from_array_storage(nalgebra::ArrayStorage([[0.0; 3]; INPUTS])),
        rate: Row::from_array_storage(nalgebra::ArrayStorage([[0.0; 1]; INPUTS])),
    };
}

/// `⟂` of a vector's derivative, row-wise.
#[inline]
fn perp_rows(m: &PoseRows2) -> PoseRows2 {
    let mut out = PoseRows2::zeros();
    out.set_row(0, &(-m.row(1)));
    out.set_row(1, &m.row(0));
    out
}

/// `∂(a · b)` for a constant `a`: `a_x ∂b_x + a_y ∂b_y`.
#[inline]
pub(crate) fn dot_rows(a: Vector2<f64>, m: &PoseRows2) -> PoseRow {
    m.row(0) * a.x + m.row(1) * a.y
}

/// `∂(R + offset)` of a point fixed on a body whose pose starts at column
/// `pose`, at global offset `offset = A ū` from its centroid:
/// `[I | ⟂offset]` (`∂(A ū)/∂θ = ⟂(A ū)`).
#[inline]
pub(crate) fn body_point(offset: Vector2<f64>, pose: usize) -> PoseRows2 {
    let mut m = PoseRows2::zeros();
    m[(0, pose)] = 1.0;
    m[(1, pose + 1)] = 1.0;
    m[(0, pose + 2)] = -offset.y;
    m[(1, pose + 2)] = offset.x;
    m
}

/// The derivative of a unit vector `u = d/|d|` from `d`'s: `(∂d − u (u·∂d))/|d|`.
#[inline]
pub(crate) fn unit_vector(u: Vector2<f64>, length: f64, d: &PoseRows2) -> PoseRows2 {
    (d - u * dot_rows(u, d)) / length
}

/// `∂(p − R)` of a contact point's arm from a body whose pose starts at
/// geometry column `pose`.
#[inline]
fn arm_of(point: &PoseRows2, pose: usize) -> PoseRows2 {
    let mut d = *point;
    d[(0, pose)] -= 1.0;
    d[(1, pose + 1)] -= 1.0;
    d
}

/// The relative velocity `v` of the two material points at the contact
/// to first order: its change with the poses (the points' arms turning,
/// `ω ⟂(∂p − ∂R)` for each body) — with the rates it is `[I | ⟂arm]`
/// for the link and the reverse for the other body.
pub(super) fn velocity(
    point: &PoseRows2,
    link: &BodyState,
    other: Option<&BodyState>,
) -> PoseRows2 {
    let mut dv = perp_rows(&arm_of(point, LINK)) * link.omega;
    if let Some(other) = other {
        dv -= perp_rows(&arm_of(point, OTHER)) * other.omega;
    }
    dv
}

/// A contact force's derivatives: with the poses, with the relative
/// velocity `v` (2 × 2), with the deflection; and the deflection's rate's.
pub(super) struct ForceTangent {
    pub force: Vector2<f64>,
    pub by_pose: PoseRows2,
    pub by_velocity: Matrix2<f64>,
    pub by_deflection: Vector2<f64>,
    pub rate_by_pose: PoseRow,
    pub rate_by_velocity: RowVector2<f64>,
    pub rate_by_deflection: f64,
}

/// The contact's gradient norm `|g|`, its unit tangent `t = ⟂g/|g|` and
/// their derivatives with the poses (neither depends on `v`).
fn tangent_of(contact: &Contact, geometry: &GeometryTangent) -> (PoseRow, Vector2<f64>, PoseRows2) {
    unit_tangent(contact.gradient, &geometry.gradient)
}

/// For a gradient `g` changing by `dg` with the poses: `∂|g|`, the unit
/// tangent `t = ⟂g/|g|` and `∂t`.
pub(super) fn unit_tangent(g: Vector2<f64>, dg: &PoseRows2) -> (PoseRow, Vector2<f64>, PoseRows2) {
    let norm = g.norm();
    let d_norm = dot_rows(g, dg) / norm;
    let d_tangent = (perp_rows(dg) - perp(g) * (d_norm / norm)) / norm;
    (d_norm, perp(g) / norm, d_tangent)
}

/// The normal force per unit gradient `N` and its derivatives with the
/// poses and with `v` (through the closing rate `δ̇ = −v·g`).
fn normal_part(
    law: &crate::laws::NormalLaw,
    contact: &Contact,
    geometry: &GeometryTangent,
    dv: &PoseRows2,
) -> (f64, PoseRow, RowVector2<f64>) {
    let rate = contact.rate();
    let d_rate = -(dot_rows(contact.gradient, dv) + dot_rows(contact.velocity, &geometry.gradient));
    let normal = law.force(contact.depth, rate);
    let (by_depth, by_rate) = law.slopes(contact.depth, rate);
    (
        normal,
        geometry.depth * by_depth + d_rate * by_rate,
        -contact.gradient.transpose() * by_rate,
    )
}

/// The loads' derivatives over the [`INPUTS`](ContactJacobian::INPUTS), into `out`, from the force
/// on the link's: the link takes `F` at its arm `p − R_L`, the other body
/// `−F` at `p − R_O`; the rates enter through `v`, `∂v/∂(ṘL, ωL) =
/// [I | ⟂arm_L]` and the reverse for the other body.
pub(super) fn loads(
    contact: &Contact,
    geometry: &GeometryTangent,
    (link, other): (&BodyState, Option<&BodyState>),
    tangent: &ForceTangent,
    out: &mut ContactJacobian,
) {
    let force = tangent.force;
    // ∂F over the 13 inputs, and the moment rows.
    let mut by_input = SMatrix::<f64, 2, INPUTS>::zeros();
    by_input
        .fixed_columns_mut::<3>(LINK_POSE)
        .copy_from(&tangent.by_pose.fixed_columns::<3>(LINK));
    by_input
        .fixed_columns_mut::<3>(OTHER_POSE)
        .copy_from(&tangent.by_pose.fixed_columns::<3>(OTHER));
    let rates = |arm: Vector2<f64>| Matrix2x3::new(1.0, 0.0, -arm.y, 0.0, 1.0, arm.x);
    let arm_link = contact.point - link.position;
    by_input
        .fixed_columns_mut::<3>(LINK_RATE)
        .copy_from(&(tangent.by_velocity * rates(arm_link)));
    by_input.set_column(DEFLECTION, &tangent.by_deflection);
    let arm_other = other.map(|o| contact.point - o.position);
    if let Some(arm) = arm_other {
        by_input
            .fixed_columns_mut::<3>(OTHER_RATE)
            .copy_from(&(-(tangent.by_velocity * rates(arm))));
    }
    // ∂(arm × F) = ∂arm × F + arm × ∂F, with ∂arm only over the poses.
    let moment = |arm: Vector2<f64>, pose: usize| -> Row {
        let d_arm = arm_of(&geometry.point, pose);
        let mut row = by_input.row(1) * arm.x - by_input.row(0) * arm.y;
        let turning = d_arm.row(0) * force.y - d_arm.row(1) * force.x;
        row.fixed_columns_mut::<3>(LINK_POSE)
            .add_assign(&turning.fixed_columns::<3>(LINK));
        row.fixed_columns_mut::<3>(OTHER_POSE)
            .add_assign(&turning.fixed_columns::<3>(OTHER));
        row
    };
    out.link.fixed_rows_mut::<2>(0).copy_from(&by_input);
    out.link.set_row(2, &moment(arm_link, LINK));
    match arm_other {
        Some(arm) => {
            out.other.fixed_rows_mut::<2>(0).copy_from(&(-by_input));
            out.other.set_row(2, &(-moment(arm, OTHER)));
        }
        None => out.other = Rows3::zeros(),
    }
    let mut rate = Row::zeros();
    rate.fixed_columns_mut::<3>(LINK_POSE)
        .copy_from(&tangent.rate_by_pose.fixed_columns::<3>(LINK));
    rate.fixed_columns_mut::<3>(LINK_RATE)
        .copy_from(&(tangent.rate_by_velocity * rates(arm_link)));
    rate[DEFLECTION] = tangent.rate_by_deflection;
    out.rate = rate;
}

impl ContactLaws {
    /// The first derivatives of [`respond`](Self::respond)'s loads (applied
    /// as [`ContactForce::apply`](super::ContactForce::apply) applies them)
    /// over the contact's [`INPUTS`](ContactJacobian::INPUTS), into `out`, given the geometry's
    /// derivatives and the states of the link and of the other body
    /// (`None`: the ground).
    pub fn linearise(
        &self,
        contact: &Contact,
        geometry: &GeometryTangent,
        link: &BodyState,
        other: Option<&BodyState>,
        out: &mut ContactJacobian,
    ) {
        let dv = velocity(&geometry.point, link, other);
        let (normal, d_normal, normal_by_v) = normal_part(&self.normal, contact, geometry, &dv);
        let (d_norm, tangent, d_tangent) = tangent_of(contact, geometry);
        let (v, g) = (contact.velocity, contact.gradient);
        let slip = v.dot(&tangent);
        let d_slip = dot_rows(tangent, &dv) + dot_rows(v, &d_tangent);
        let total = normal * contact.gradient_norm;
        let d_total = d_normal * contact.gradient_norm + d_norm * normal;
        let friction = self.friction.force(total, slip);
        let (by_normal, by_slip) = self.friction.slopes(total, slip);
        let d_friction = d_total * by_normal + d_slip * by_slip;
        let friction_by_v =
            normal_by_v * (contact.gradient_norm * by_normal) + tangent.transpose() * by_slip;
        let force_tangent = ForceTangent {
            force: g * normal + tangent * friction,
            by_pose: geometry.gradient * normal
                + g * d_normal
                + d_tangent * friction
                + tangent * d_friction,
            by_velocity: g * normal_by_v + tangent * friction_by_v,
            by_deflection: Vector2::zeros(),
            rate_by_pose: PoseRow::zeros(),
            rate_by_velocity: RowVector2::zeros(),
            rate_by_deflection: 0.0,
        };
        loads(contact, geometry, (link, other), &force_tangent, out);
    }
}

impl GroundLaws {
    /// The first derivatives of [`respond`](Self::respond)'s load on the
    /// link and of the deflection's rate, over the contact's [`INPUTS`](ContactJacobian::INPUTS)
    /// (the deflection `z`, m, in column [`DEFLECTION`](ContactJacobian::DEFLECTION)), into `out`.
    pub fn linearise(
        &self,
        contact: &Contact,
        z: f64,
        geometry: &GeometryTangent,
        link: &BodyState,
        out: &mut ContactJacobian,
    ) {
        let stiction = match self.friction {
            GroundFriction::Regularised(friction) => {
                let laws = ContactLaws {
                    normal: self.normal,
                    friction,
                };
                return laws.linearise(contact, geometry, link, None, out);
            }
            GroundFriction::Stiction(stiction) => stiction,
        };
        let dv = velocity(&geometry.point, link, None);
        let (normal, d_normal, normal_by_v) = normal_part(&self.normal, contact, geometry, &dv);
        let (d_norm, tangent, d_tangent) = tangent_of(contact, geometry);
        let (forward, d_forward) = (-tangent, -d_tangent);
        let v = contact.velocity;
        let slip = v.dot(&forward);
        let d_slip = dot_rows(forward, &dv) + dot_rows(v, &d_forward);
        let slip_by_v = forward.transpose();
        let total = normal * contact.gradient_norm;
        let d_total = d_normal * contact.gradient_norm + d_norm * normal;
        let total_by_v = normal_by_v * contact.gradient_norm;
        let tangential = stiction.respond(z, slip, total);
        let slopes = stiction.slopes(z, slip, total);
        let [f_z, f_slip, f_normal] = slopes.force;
        let [r_z, r_slip, r_normal] = slopes.rate;
        let d_tangential = d_slip * f_slip + d_total * f_normal;
        let tangential_by_v = slip_by_v * f_slip + total_by_v * f_normal;
        let g = contact.gradient;
        let force_tangent = ForceTangent {
            force: g * normal + forward * tangential.force,
            by_pose: geometry.gradient * normal
                + g * d_normal
                + d_forward * tangential.force
                + forward * d_tangential,
            by_velocity: g * normal_by_v + forward * tangential_by_v,
            by_deflection: forward * f_z,
            rate_by_pose: d_slip * r_slip + d_total * r_normal,
            rate_by_velocity: slip_by_v * r_slip + total_by_v * r_normal,
            rate_by_deflection: r_z,
        };
        loads(contact, geometry, (link, None), &force_tangent, out);
    }
}
