//! A wheel's rim against a shoe's running face in space: a road wheel,
//! idler or roller of the hull's side, turning in its own plane, on a
//! link of the track, which moves in the track's plane; the two planes
//! are parallel at rest and apart when the track slides or twists against
//! the running gear (the guide's "The formulation", §6).
//!
//! **Geometry.** The rim is the cylinder of radius `r` about the wheel's
//! axle (the line through its centre `c` along its plane's normal `a`).
//! The face point taken is the one of the face `[p₀, p₁]` nearest that
//! line, `p = p₀ + s (p₁ − p₀)`, `s` clipped to the face; its distance
//! from the axle `d = |P (p − c)|` (`P = I − a aᵀ`) gives the penetration
//! `δ = r − d` and the unit normal `n = P (p − c)/d`, the direction the
//! rim pushes the link. Because `s` minimises the distance itself, the
//! penetration's rate is `δ̇ = −n · v` exactly, with `v` the velocity of
//! the link's material point at `p` less the wheel's there (the axle's
//! turning included): the normal law's power is exactly `−F δ̇`, as in
//! the plane. Friction acts along `t = n × a`, the rim's tangent, which in
//! the plane (`a` the plane's normal, pointing left) is `n` turned a
//! quarter counter-clockwise: with the planes one, the contact is the
//! planar one ([`wheel`](super::wheel)) to the last bit of its geometry.
//!
//! **The guide.** The shoe's centre guide, a point `g` fixed on the link,
//! runs between the wheel's two halves with `play` each way: where the
//! rim touches, its offset across the wheel's plane `e = (g − c) · a`
//! beyond the play is resisted by a spring-damper along `a`
//! ([`GuideLaw`]) acting at `g`, pushing the link back toward the wheel's
//! plane. `g` being a material point, `ė = v_g · a` exactly (`v_g` its
//! velocity less the wheel's material point's there), and the guide's
//! power is its law's.

use nalgebra::Vector3;

use super::ContactLaws;
use crate::laws::ParameterError;

/// A wheel in space.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SpaceWheel {
    /// Its centre, world frame, m.
    pub centre: Vector3<f64>,
    /// Its axle: the unit normal of its plane (the hull's lateral axis,
    /// pointing left).
    pub axle: Vector3<f64>,
    /// Its rim's radius, m.
    pub radius: f64,
    /// Its centre's velocity, m/s.
    pub velocity: Vector3<f64>,
    /// Its angular velocity, world frame, rad/s.
    pub angular_velocity: Vector3<f64>,
}

/// A link's running face in space: the segment wheels run on, on the
/// link's inner side, and the link's motion.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SpaceFace {
    /// The face's ends, world frame, m.
    pub ends: [Vector3<f64>; 2],
    /// The link's inward unit normal in its plane (the side the wheels
    /// are on).
    pub inward: Vector3<f64>,
    /// The link's centre guide, world frame, m: the point that runs
    /// between a wheel's halves.
    pub guide: Vector3<f64>,
    /// The link's centroid, m.
    pub centroid: Vector3<f64>,
    /// Its velocity, m/s.
    pub velocity: Vector3<f64>,
    /// Its angular velocity, world frame, rad/s.
    pub angular_velocity: Vector3<f64>,
}

/// A rim on a face.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RimContact {
    /// The face point, world frame, m.
    pub point: Vector3<f64>,
    /// The unit normal: from the axle to the point, normal to the axle;
    /// the direction the rim pushes the link.
    pub normal: Vector3<f64>,
    /// The wheel's axle, unit.
    pub axle: Vector3<f64>,
    /// Penetration `δ = r − d` (> 0), m.
    pub depth: f64,
    /// The link's material point's velocity at the point less the
    /// wheel's, m/s.
    pub velocity: Vector3<f64>,
    /// The link's guide, m.
    pub guide: Vector3<f64>,
    /// The guide's offset across the wheel's plane, `(g − c) · a`, m.
    pub offset: f64,
    /// The guide's rate across the wheel's plane, `ė = v_g · a`, m/s.
    pub offset_rate: f64,
}

impl RimContact {
    /// The rim of `wheel` on `face`: `None` where the rim is on the face's
    /// outer side or does not reach it.
    pub fn detect(wheel: &SpaceWheel, face: &SpaceFace) -> Option<RimContact> {
        let a = wheel.axle;
        let across = |v: Vector3<f64>| v - a * a.dot(&v);
        let [p0, p1] = face.ends;
        if (wheel.centre - p0).dot(&face.inward) <= 0.0 {
            return None;
        }
        let along = p1 - p0;
        let (u, w) = (across(along), across(p0 - wheel.centre));
        let s = match u.norm_squared() {
            0.0 => 0.0,
            uu => (-w.dot(&u) / uu).clamp(0.0, 1.0),
        };
        let point = p0 + along * s;
        let radial = across(point - wheel.centre);
        let distance = radial.norm();
        let depth = wheel.radius - distance;
        if depth <= 0.0 || distance == 0.0 {
            return None;
        }
        // The link's material point at `x` less the wheel's there.
        let relative = |x: Vector3<f64>| {
            face.velocity + face.angular_velocity.cross(&(x - face.centroid))
                - wheel.velocity
                - wheel.angular_velocity.cross(&(x - wheel.centre))
        };
        Some(RimContact {
            point,
            normal: radial / distance,
            axle: a,
            depth,
            velocity: relative(point),
            guide: face.guide,
            offset: (face.guide - wheel.centre).dot(&a),
            offset_rate: relative(face.guide).dot(&a),
        })
    }

    /// The closing rate `δ̇ = −v · n`, m/s.
    pub fn rate(&self) -> f64 {
        -self.velocity.dot(&self.normal)
    }

    /// The rim's unit tangent `t = n × a`, along which friction acts.
    pub fn tangent(&self) -> Vector3<f64> {
        self.normal.cross(&self.axle)
    }
}

/// The centre guide against the wheel's halves: a spring-damper across
/// the wheel's plane beyond a dead band.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GuideLaw {
    /// The play each way before the guide bears, m (≥ 0).
    pub play: f64,
    /// N/m (> 0).
    pub stiffness: f64,
    /// N s/m (≥ 0).
    pub damping: f64,
}

impl GuideLaw {
    /// Each parameter in its range: a finite play of zero or more, a
    /// positive stiffness, a damping of zero or more.
    pub fn check(&self) -> Result<(), ParameterError> {
        ParameterError::check("play", self.play, 0.0, false)?;
        ParameterError::check("stiffness", self.stiffness, 0.0, true)?;
        ParameterError::check("damping", self.damping, 0.0, false)
    }
}

/// What a [`RimContact`] gives under a rim's laws and the guide.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RimForce {
    /// The rim's force on the link at the point, world frame, N (the
    /// wheel takes its reverse there).
    pub force: Vector3<f64>,
    /// The normal force (≥ 0), N.
    pub normal: f64,
    /// The guide's force on the link along the axle, at the guide, N
    /// (the wheel takes its reverse there).
    pub guide: f64,
    /// Elastic energy stored (the rim's and the guide's), J.
    pub potential: f64,
    /// Power dissipated, W.
    pub dissipation: f64,
}

impl ContactLaws {
    /// The force of a rim in space: the normal law at `δ` and `δ̇` along
    /// `n`, friction under it along `t` against the slip `v · t`; and the
    /// guide's force along the axle beyond its play.
    pub fn respond_rim(&self, rim: &RimContact, guide: &GuideLaw) -> RimForce {
        let normal = self.normal.respond(rim.depth, rim.rate());
        let tangent = rim.tangent();
        let friction = self
            .friction
            .respond(normal.force, rim.velocity.dot(&tangent));
        let side = rim.offset.signum();
        let excess = rim.offset.abs() - guide.play;
        let (pushed, guide_potential, guide_loss) = if excess > 0.0 {
            let rate = side * rim.offset_rate;
            let elastic = guide.stiffness * excess;
            let force = (elastic + guide.damping * rate).max(0.0);
            (force, 0.5 * elastic * excess, (force - elastic) * rate)
        } else {
            (0.0, 0.0, 0.0)
        };
        let along = -side * pushed;
        RimForce {
            force: rim.normal * normal.force + tangent * friction.force,
            normal: normal.force,
            guide: along,
            potential: normal.potential + guide_potential,
            dissipation: normal.dissipation + friction.dissipation + guide_loss,
        }
    }
}
