//! Profiles extruded along an axle against a shoe in space: a wheel's rim
//! on a shoe's running face, and the sprocket's teeth on a shoe's pins. A
//! road wheel, idler, roller or sprocket of the hull's side turns in its
//! own plane; a link of the track moves in the track's plane; the two
//! planes are parallel at rest and apart when the track slides or twists
//! against the running gear (the guide's "The formulation", §6). Both
//! contacts are [`AxialContact`]s: normal to the axle, their penetration's
//! rate the closing velocity along the normal, friction along the
//! profile's tangent, as in the plane ([`ContactLaws::respond_axial`]).
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
//! **The teeth.** The sprocket's profile ([`ToothProfile`]) is extruded
//! along its axle: a pin's centre `p` (on the pin's axis, in the track's
//! plane) is taken along the axle into the sprocket's plane, where the
//! planar rule finds the tooth it is in
//! ([`ToothProfile::pin_in_tooth`]); the depth, the normal and the point
//! on the profile come back into space at the pin's place along the axle.
//! The depth being the planar one of the sprocket's body-fixed coordinates
//! of `p`, its rate is again `−n · v` exactly.
//!
//! **The guide.** The shoe's centre guide, a horn standing `h` inward
//! from the running face and carried by the link at a point `g`, runs
//! between the wheel's two halves with `play` each way: its offset
//! across the wheel's plane `e = (g − c) · a` beyond the play, `x = |e| −
//! play`, is resisted by a spring-damper along `a` ([`GuideLaw`]) acting
//! at `g`, pushing the link back toward the wheel's plane. The horn bears
//! on the wheel over the part of its height the rim overlaps: with the
//! face at `δ` into the rim (`δ < 0`: short of it), the overlap
//! `ρ = clamp((δ + h)/h, 0, 1)` scales the law, so the guide engages
//! continuously as a link comes onto a wheel and lets go as it leaves
//! (a guide that acted only while the rim touched would drop its stored
//! energy whenever a link left the rim with its guide pressed). Its
//! potential `½ k x² ρ(δ)` then also pushes the link out along the rim's
//! normal, `½ k x² ρ'(δ)`, at the face's point nearest the axle. `g`
//! being a material point, `ė = v_g · a` exactly (`v_g` its velocity less
//! the wheel's material point's there), `δ̇ = −n · v` as for the rim, and
//! the guide's power is its law's.

use nalgebra::Vector3;

use super::sprocket::{Gaps, ToothProfile};
use super::{BodyState, ContactLaws};
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

/// A contact of a link's feature with a profile extruded along an axle
/// (a wheel's rim, the sprocket's teeth): the normal is normal to the
/// axle, and the penetration's rate is the closing velocity along it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AxialContact {
    /// The contact point, world frame, m.
    pub point: Vector3<f64>,
    /// The unit normal, normal to the axle: the direction the profile
    /// pushes the link.
    pub normal: Vector3<f64>,
    /// The profile's axle, unit.
    pub axle: Vector3<f64>,
    /// Penetration (> 0), m.
    pub depth: f64,
    /// The link's material point's velocity at the point less the
    /// profile's body's, m/s.
    pub velocity: Vector3<f64>,
}

impl AxialContact {
    /// The closing rate `δ̇ = −v · n`, m/s.
    pub fn rate(&self) -> f64 {
        -self.velocity.dot(&self.normal)
    }

    /// The profile's unit tangent `t = n × a`, along which friction acts
    /// (in the plane: `n` turned a quarter counter-clockwise).
    pub fn tangent(&self) -> Vector3<f64> {
        self.normal.cross(&self.axle)
    }
}

/// A rim on a face: the contact, and where the shoe's guide is against
/// the wheel's plane.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RimContact {
    /// The rim's contact with the face.
    pub contact: AxialContact,
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
        Self::near(wheel, face, 0.0)
    }

    /// The rim of `wheel` and `face` within `reach` (m, ≥ 0) of touching:
    /// the contact's depth more than `−reach` (negative: a gap), where a
    /// guide horn of that height overlaps the wheel. `None` where the rim
    /// is on the face's outer side or further away.
    #[inline(always)]
    pub fn near(wheel: &SpaceWheel, face: &SpaceFace, reach: f64) -> Option<RimContact> {
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
        if depth <= -reach || distance == 0.0 {
            return None;
        }
        let relative = |x: Vector3<f64>| {
            relative_velocity(
                face,
                (wheel.centre, wheel.velocity, wheel.angular_velocity),
                x,
            )
        };
        Some(RimContact {
            contact: AxialContact {
                point,
                normal: radial / distance,
                axle: a,
                depth,
                velocity: relative(point),
            },
            guide: face.guide,
            offset: (face.guide - wheel.centre).dot(&a),
            offset_rate: relative(face.guide).dot(&a),
        })
    }
}

/// A sprocket in space.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SpaceSprocket {
    /// Its centre, world frame, m.
    pub centre: Vector3<f64>,
    /// Its plane's forward and up axes, unit, world frame (its axle, the
    /// plane's normal, is up × forward: left).
    pub axes: [Vector3<f64>; 2],
    /// Its angle in its plane from the forward axis, counter-clockwise
    /// (about the axle's reverse), rad.
    pub angle: f64,
    /// Its centre's velocity, m/s.
    pub velocity: Vector3<f64>,
    /// Its angular velocity, world frame, rad/s.
    pub angular_velocity: Vector3<f64>,
}

impl SpaceSprocket {
    /// The axle: the plane's normal, `ζ × ξ`.
    pub fn axle(&self) -> Vector3<f64> {
        self.axes[1].cross(&self.axes[0])
    }

    /// The contact of the pin of `pin_radius` (m) whose centre is `pin`
    /// (world, m) on link `face` with this sprocket's `profile`: `None`
    /// where it is in no tooth.
    pub fn pin_contact(
        &self,
        profile: &ToothProfile,
        face: &SpaceFace,
        pin: Vector3<f64>,
        pin_radius: f64,
    ) -> Option<AxialContact> {
        let among = (profile, &Gaps::of(profile), &self.in_plane());
        self.pin_contact_among(among, face, pin, pin_radius)
    }

    /// The sprocket in its own plane, centred and turned by its angle:
    /// what the tooth profile's tests take. Its angle's sine and cosine
    /// found once, for every pin near it.
    pub(crate) fn in_plane(&self) -> BodyState {
        BodyState::at_rest(nalgebra::Vector2::zeros(), self.angle)
    }

    /// [`pin_contact`](Self::pin_contact) with the profile's gaps found
    /// already ([`Gaps::of`]) and the sprocket in its plane
    /// ([`in_plane`](Self::in_plane)): a vehicle finds them once, not per
    /// pin.
    pub(crate) fn pin_contact_among(
        &self,
        (profile, gaps, sprocket): (&ToothProfile, &Gaps, &BodyState),
        face: &SpaceFace,
        pin: Vector3<f64>,
        pin_radius: f64,
    ) -> Option<AxialContact> {
        let [xi, zeta] = self.axes;
        let offset = pin - self.centre;
        let local = nalgebra::Vector2::new(offset.dot(&xi), offset.dot(&zeta));
        // Beyond the tip circle by the pin's radius the pin is in no
        // tooth: the tooth test's own `r_add + r_pin − |p| ≤ 0`, the same
        // floating-point numbers, made before the nearest gap is found.
        if local.norm() >= profile.addendum + pin_radius {
            return None;
        }
        let tooth = profile.pin_in_tooth_among(gaps, sprocket, local, pin_radius)?;
        let axle = self.axle();
        let lift = |v: nalgebra::Vector2<f64>| xi * v.x + zeta * v.y;
        let point = self.centre + lift(tooth.point) + axle * offset.dot(&axle);
        Some(AxialContact {
            point,
            normal: lift(tooth.normal),
            axle,
            depth: tooth.depth,
            velocity: relative_velocity(
                face,
                (self.centre, self.velocity, self.angular_velocity),
                point,
            ),
        })
    }
}

/// The link's material point at `x` moving against the other body's
/// (its centroid, velocity and angular velocity) there, m/s.
#[inline]
pub(crate) fn relative_velocity(
    face: &SpaceFace,
    (centre, velocity, angular_velocity): (Vector3<f64>, Vector3<f64>, Vector3<f64>),
    x: Vector3<f64>,
) -> Vector3<f64> {
    face.velocity + face.angular_velocity.cross(&(x - face.centroid))
        - velocity
        - angular_velocity.cross(&(x - centre))
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
    /// The horn's height inward from the running face, m (> 0): the
    /// guide bears in full once the rim touches the face, not at all with
    /// the face this far short of it, in proportion between.
    pub height: f64,
}

impl GuideLaw {
    /// The guide's stiffness unless a vehicle says otherwise, N/m:
    /// assumed (no published figure found), stiff enough that a side
    /// load of 1e5 N, a 14 t vehicle's whole weight at μ 0.7, bears it
    /// 10 mm beyond its play.
    pub const STIFFNESS: f64 = 1e7;
    /// Its damping, N s/m: assumed, 1e3 (a guide of 15 kg against it
    /// rings at ζ ≈ 0.04).
    pub const DAMPING: f64 = 1e3;
    /// Its horn's height, m: Project Chrono's M113 track shoe's guide box,
    /// 0.075 m high (`M113_TrackShoeSinglePin`; a secondary source).
    pub const HEIGHT: f64 = 0.075;

    /// A guide with `play` m each way and the [`STIFFNESS`](Self::STIFFNESS),
    /// [`DAMPING`](Self::DAMPING) and [`HEIGHT`](Self::HEIGHT) above.
    pub fn with_play(play: f64) -> GuideLaw {
        GuideLaw {
            play,
            stiffness: Self::STIFFNESS,
            damping: Self::DAMPING,
            height: Self::HEIGHT,
        }
    }

    /// Each parameter in its range: a finite play of zero or more, a
    /// positive stiffness, a damping of zero or more, a positive height.
    pub fn check(&self) -> Result<(), ParameterError> {
        ParameterError::check("play", self.play, 0.0, false)?;
        ParameterError::check("stiffness", self.stiffness, 0.0, true)?;
        ParameterError::check("damping", self.damping, 0.0, false)?;
        ParameterError::check("height", self.height, 0.0, true)
    }

    /// The horn's overlap with the rim at the face's depth `depth` into
    /// it (m), `ρ ∈ [0, 1]`, and its slope `dρ/dδ` (1/m).
    fn overlap(&self, depth: f64) -> (f64, f64) {
        let rho = (depth + self.height) / self.height;
        if rho <= 0.0 {
            (0.0, 0.0)
        } else if rho >= 1.0 {
            (1.0, 0.0)
        } else {
            (rho, 1.0 / self.height)
        }
    }
}

/// What an [`AxialContact`] gives under a pair's laws.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AxialForce {
    /// The force on the link at the point, world frame, N (the other body
    /// takes its reverse there).
    pub force: Vector3<f64>,
    /// The normal force (≥ 0), N.
    pub normal: f64,
    /// Elastic energy stored, J.
    pub potential: f64,
    /// Power dissipated, W.
    pub dissipation: f64,
}

/// What the guide gives at a [`RimContact`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GuideForce {
    /// The force on the link along the axle, at the guide, N (the wheel
    /// takes its reverse there).
    pub force: f64,
    /// The force on the link along the rim's normal at the contact's
    /// point, N (≥ 0: the horn's overlap changing with the depth; the
    /// wheel takes its reverse there).
    pub radial: f64,
    /// Elastic energy stored, J.
    pub potential: f64,
    /// Power dissipated, W.
    pub dissipation: f64,
}

impl ContactLaws {
    /// The force of an axial contact: the normal law at `δ` and `δ̇`
    /// along `n`, friction under it along `t` against the slip `v · t`,
    /// as [`respond`](Self::respond) in the plane.
    pub fn respond_axial(&self, contact: &AxialContact) -> AxialForce {
        let normal = self.normal.respond(contact.depth, contact.rate());
        let tangent = contact.tangent();
        let friction = self
            .friction
            .respond(normal.force, contact.velocity.dot(&tangent));
        AxialForce {
            force: contact.normal * normal.force + tangent * friction.force,
            normal: normal.force,
            potential: normal.potential,
            dissipation: normal.dissipation + friction.dissipation,
        }
    }
}

impl GuideLaw {
    /// The guide's force at `rim`: beyond the play, `ρ (k x + c ẋ)`
    /// (never pulling) along the axle, pushing the link back toward the
    /// wheel's plane, with `x = |e| − play` and `ρ` the horn's overlap
    /// with the rim; and `½ k x² ρ'` along the rim's normal.
    pub fn respond(&self, rim: &RimContact) -> GuideForce {
        let side = rim.offset.signum();
        let excess = rim.offset.abs() - self.play;
        let (rho, slope) = self.overlap(rim.contact.depth);
        if excess <= 0.0 || rho == 0.0 {
            return GuideForce {
                force: 0.0,
                radial: 0.0,
                potential: 0.0,
                dissipation: 0.0,
            };
        }
        let rate = side * rim.offset_rate;
        let elastic = self.stiffness * excess;
        let pushed = rho * (elastic + self.damping * rate).max(0.0);
        GuideForce {
            force: -side * pushed,
            radial: 0.5 * elastic * excess * slope,
            potential: 0.5 * elastic * excess * rho,
            dissipation: (pushed - rho * elastic) * rate,
        }
    }
}
