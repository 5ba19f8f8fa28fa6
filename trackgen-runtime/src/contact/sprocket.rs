//! Sprocket engagement: where the shoes' pins meet an arc tooth profile,
//! so that drive torque becomes track tension.
//!
//! The profile is a circle of radius `addendum` with a circular gap cut
//! between every two teeth: gap `k` is the arc of radius `arc_radius`
//! centred at `arc_centre_radius` from the sprocket centre, at angle
//! `θ_s + (k + ½)·2π/teeth`. Tooth material is what lies inside the
//! addendum circle and outside every gap. A pin (a cylinder) reaching into
//! a tooth is pushed out the shorter way: back toward its gap's arc centre
//! `g` (depth `|p − g| + r_pin − r_arc`) or radially out across the tip
//! circle (depth `r_add + r_pin − |p − c|`), so the force grows from zero
//! wherever a pin enters.

use nalgebra::Vector2;

use super::tangent::{GeometryTangent, LINK, OTHER, body_point, dot_rows, unit_vector};
use super::{BodyState, Contact, ShoeGeometry};

pub use trackgen_sprocket::{ProfileProblem, pitch_radius};

/// The track's mean speed, m/s, driven by a sprocket of `teeth` teeth
/// turning at `omega` (rad/s) on links of `pitch` (m): one pitch per tooth
/// passing, `N p ω / (2π)`. A seated joint moves at `ω R` on the pitch
/// circle, but the chain leaves the sprocket along the polygon's chords,
/// so over a turn it advances by the polygon's perimeter `N p`, not by
/// `2π R` (1.6 % less for 10 teeth; chordal action). The one measure of
/// track speed: a slip is measured against it, and the speed drive aims
/// for it.
pub fn track_speed(teeth: u32, pitch: f64, omega: f64) -> f64 {
    rolling_radius(teeth, pitch) * omega
}

/// The sprocket's rolling radius, m: its mean track speed per unit of its
/// speed, `N p / (2π)` ([`track_speed`]).
pub fn rolling_radius(teeth: u32, pitch: f64) -> f64 {
    teeth as f64 * pitch / (2.0 * std::f64::consts::PI)
}

/// An arc tooth profile, m.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ToothProfile {
    /// Number of teeth.
    pub teeth: u32,
    /// Tip circle radius.
    pub addendum: f64,
    /// Distance of each gap arc's centre from the sprocket centre.
    pub arc_centre_radius: f64,
    /// Radius of each gap arc.
    pub arc_radius: f64,
}

impl ToothProfile {
    /// A profile of `teeth` teeth for shoes of `pitch` (m, pin to pin) in
    /// the M113's proportions: with `R = p / (2 sin(π/teeth))` the pitch
    /// radius, the tip circle at `R + 0.073 p`, gap arcs centred
    /// `R + 0.33 p` out, each of radius 0.48 of the chord between
    /// neighbouring arc centres (so neighbouring gaps never meet). For the
    /// M113 (`p` = 0.154 m, 10 teeth) this gives 0.2605, 0.300 and
    /// 0.089 m, its figures.
    pub fn scaled(teeth: u32, pitch: f64) -> ToothProfile {
        let radii = trackgen_sprocket::scaled(teeth, pitch);
        ToothProfile {
            teeth,
            addendum: radii.addendum,
            arc_centre_radius: radii.arc_centre_radius,
            arc_radius: radii.arc_radius,
        }
    }

    /// Whether this profile can drive a track whose links have joints
    /// `joints` (`ū1`, `ū2`, link frame) and whose shoes have pins `shoe`:
    /// the rules of [`trackgen_sprocket::Engagement::check`], the same the
    /// compiler applies to a declaration.
    pub fn check(
        &self,
        joints: (Vector2<f64>, Vector2<f64>),
        shoe: &ShoeGeometry,
    ) -> Result<(), ProfileProblem> {
        let pins: Vec<(f64, f64)> = shoe.pins.iter().map(|p| (p.x, p.y)).collect();
        trackgen_sprocket::Engagement {
            teeth: self.teeth,
            radii: trackgen_sprocket::Radii {
                addendum: self.addendum,
                arc_centre_radius: self.arc_centre_radius,
                arc_radius: self.arc_radius,
            },
            joints: [(joints.0.x, joints.0.y), (joints.1.x, joints.1.y)],
            pins: &pins,
            pin_radius: shoe.pin_radius,
        }
        .check()
    }

    /// The angular pitch of the teeth, rad.
    pub fn pitch_angle(&self) -> f64 {
        2.0 * std::f64::consts::PI / self.teeth as f64
    }

    /// The centre of the gap nearest to global point `p`: of the gaps at
    /// `θ_s + (k + ½) β` (`β = 2π/teeth`), the one whose direction from the
    /// sprocket's centre is closest to `p`'s.
    pub fn nearest_gap(&self, sprocket: &BodyState, p: Vector2<f64>) -> Vector2<f64> {
        Gaps::of(self).nearest(sprocket, p)
    }
}

/// What finding a profile's nearest gap needs, computed once per
/// evaluation: the angular pitch `β`, the rotation by it, and the gaps'
/// directions in the sprocket's frame.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Gaps {
    pitch: f64,
    turn: (f64, f64),
    arc_centre_radius: f64,
    /// The index of `directions[0]`.
    first: f64,
    /// How many of `directions` hold a gap's.
    len: usize,
    /// `(sin, cos)` of `(k + ½) β` for every index `k` the rough angle can
    /// give, `first ≤ k < first + len`: one vectorised pass per evaluation
    /// instead of a `sin_cos` per pin, the same numbers (the same angles,
    /// the same function).
    directions: [(f64, f64); GAP_TABLE],
}

/// The most gap directions a [`Gaps`] holds: enough for 60 teeth. A
/// sprocket of more computes each pin's gap direction instead, the same
/// numbers.
const GAP_TABLE: usize = 64;

impl Gaps {
    /// The profile's gaps: they turn with the sprocket but do not depend
    /// on its angle, so a vehicle finds them once.
    pub(crate) fn of(profile: &ToothProfile) -> Gaps {
        let pitch = profile.pitch_angle();
        // The rough angle is within (−π, π] to 2e-3 rad, so k is within
        // [−teeth/2 − 1, teeth/2]; a margin of one more each way.
        let half = (profile.teeth / 2) as usize;
        let first = -(half as f64) - 2.0;
        let len = 2 * half + 4;
        let mut directions = [(0.0, 0.0); GAP_TABLE];
        let len = if len <= GAP_TABLE {
            let mut angles = [0.0; GAP_TABLE];
            for (i, angle) in angles[..len].iter_mut().enumerate() {
                *angle = (first + i as f64 + 0.5) * pitch;
            }
            crate::trig::sin_cos_each(&angles[..len], &mut directions[..len]);
            len
        } else {
            0
        };
        Gaps {
            pitch,
            turn: crate::trig::sin_cos(pitch),
            arc_centre_radius: profile.arc_centre_radius,
            first,
            len,
            directions,
        }
    }

    /// `(sin, cos)` of `(k + ½) β`: from the table, or computed for an
    /// index beyond it (a NaN index computes, giving NaN).
    #[inline]
    fn direction(&self, k: f64) -> (f64, f64) {
        let index = k - self.first;
        if index >= 0.0 && index < self.len as f64 {
            self.directions[index as usize]
        } else {
            crate::trig::sin_cos((k + 0.5) * self.pitch)
        }
    }

    /// The gap nearest `p`: its index from a rough angle of `p` in the
    /// sprocket's frame (within 2e-3 rad, far less than half a tooth), then
    /// exactly, the largest cosine among it and its two neighbours.
    #[inline]
    fn nearest(&self, sprocket: &BodyState, p: Vector2<f64>) -> Vector2<f64> {
        // Adding 1.5·2⁵² rounds to an integer without a library call.
        const TO_INT: f64 = 6_755_399_441_055_744.0;
        let local = sprocket.rotation().apply_inverse(p - sprocket.position);
        let (x, y) = (local.x, local.y);
        let k = (rough_angle(y, x) / self.pitch - 0.5 + TO_INT) - TO_INT;
        let (sin, cos) = self.direction(k);
        let (sb, cb) = self.turn;
        let mut best = (cos, sin);
        for candidate in [
            (cos * cb - sin * sb, sin * cb + cos * sb),
            (cos * cb + sin * sb, sin * cb - cos * sb),
        ] {
            if candidate.0 * x + candidate.1 * y > best.0 * x + best.1 * y {
                best = candidate;
            }
        }
        let direction = sprocket.rotation().apply(Vector2::new(best.0, best.1));
        sprocket.position + direction * self.arc_centre_radius
    }
}

/// `atan2(y, x)` within 2e-3 rad: `atan z ≈ π/4 z − z (|z| − 1)(0.2447 +
/// 0.0663 |z|)` on `|z| ≤ 1` (Rajan et al., 2006), by octant. NaN for NaN.
#[inline]
fn rough_angle(y: f64, x: f64) -> f64 {
    use std::f64::consts::{FRAC_PI_2, FRAC_PI_4, PI};
    let atan = |z: f64| FRAC_PI_4 * z - z * (z.abs() - 1.0) * (0.2447 + 0.0663 * z.abs());
    if x.abs() >= y.abs() {
        let a = atan(y / x);
        if x >= 0.0 {
            a
        } else if y >= 0.0 {
            a + PI
        } else {
            a - PI
        }
    } else {
        FRAC_PI_2.copysign(y) - atan(x / y)
    }
}

/// The contacts of the sprocket `body` (its state) with the pins of every
/// link near it, appended to `out`. A pin reaching into a tooth is pushed
/// out the shorter way: back toward its gap's arc centre (depth
/// `|p − g| + r_pin − r_arc`) or radially out across the tip circle (depth
/// `r_add + r_pin − |p − c|`), so the force grows from zero wherever a pin
/// enters.
pub fn detect(
    (sprocket, body): (&BodyState, usize),
    profile: &ToothProfile,
    links: &[BodyState],
    shoe: &ShoeGeometry,
    out: &mut Vec<Contact>,
) {
    let reach = profile.addendum + shoe.extent();
    let pin_reach = profile.addendum + shoe.pin_radius;
    let gaps = Gaps::of(profile);
    super::each_near(links, sprocket.position, reach, |i, link| {
        for (k, local) in shoe.pins.iter().enumerate() {
            let pin = link.position + link.arm(*local);
            if (pin - sprocket.position).norm_squared() > pin_reach * pin_reach {
                continue;
            }
            if let Some(tooth) = in_tooth(profile, &gaps, sprocket, pin, shoe.pin_radius) {
                out.push(super::between(
                    (i, link),
                    (body, sprocket),
                    (k, tooth.point, tooth.normal, tooth.depth),
                ));
            }
        }
    });
}

/// A pin in a tooth: how deep, the unit normal pushing the pin out, and
/// the point on the profile, m.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PinInTooth {
    /// Penetration (> 0), m.
    pub depth: f64,
    /// The direction the tooth pushes the pin, unit.
    pub normal: Vector2<f64>,
    /// The point on the profile, m.
    pub point: Vector2<f64>,
}

impl ToothProfile {
    /// Where a pin of `pin_radius` (m) centred at `pin` (m, the
    /// sprocket's plane) reaches into a tooth of this profile on
    /// `sprocket`, by [`detect`]'s rule; `None` where it touches none.
    pub fn pin_in_tooth(
        &self,
        sprocket: &BodyState,
        pin: Vector2<f64>,
        pin_radius: f64,
    ) -> Option<PinInTooth> {
        self.pin_in_tooth_among(&Gaps::of(self), sprocket, pin, pin_radius)
    }

    /// [`pin_in_tooth`](Self::pin_in_tooth) with this profile's gaps
    /// found already ([`Gaps::of`]).
    pub(crate) fn pin_in_tooth_among(
        &self,
        gaps: &Gaps,
        sprocket: &BodyState,
        pin: Vector2<f64>,
        pin_radius: f64,
    ) -> Option<PinInTooth> {
        in_tooth(self, gaps, sprocket, pin, pin_radius)
    }
}

/// Inside the addendum circle, outside the gap's arc: in a tooth. The pin
/// leaves it the shorter way, back into the gap or out across the tip
/// circle.
#[inline]
fn in_tooth(
    profile: &ToothProfile,
    gaps: &Gaps,
    sprocket: &BodyState,
    pin: Vector2<f64>,
    pin_radius: f64,
) -> Option<PinInTooth> {
    let gap = gaps.nearest(sprocket, pin);
    let (out_of_gap, radial) = (pin - gap, pin - sprocket.position);
    let (distance, from_centre) = (out_of_gap.norm(), radial.norm());
    let into_flank = distance + pin_radius - profile.arc_radius;
    let into_tip = profile.addendum + pin_radius - from_centre;
    if into_flank <= 0.0 || into_tip <= 0.0 || distance == 0.0 || from_centre == 0.0 {
        return None;
    }
    Some(if into_flank <= into_tip {
        PinInTooth {
            depth: into_flank,
            normal: -out_of_gap / distance,
            point: gap + out_of_gap / distance * profile.arc_radius,
        }
    } else {
        PinInTooth {
            depth: into_tip,
            normal: radial / from_centre,
            point: sprocket.position + radial / from_centre * profile.addendum,
        }
    })
}

/// The derivatives of a tooth contact's geometry ([`detect`]'s) with the
/// link's and the sprocket's poses, on the branch detection took: on a
/// gap's flank (the pin against the arc about the gap's centre `g`, which
/// turns with the sprocket) `δ = |p − g| + r_pin − r_arc` along
/// `−(p − g)/|p − g|`; across the tip circle `δ = r_add + r_pin − |p − c|`
/// along `(p − c)/|p − c|`. The nearest gap is the same for small changes.
pub fn tangent(
    contact: &Contact,
    link: &BodyState,
    sprocket: &BodyState,
    profile: &ToothProfile,
    shoe: &ShoeGeometry,
) -> GeometryTangent {
    let pin_arm = link.arm(shoe.pins[contact.feature]);
    let pin = link.position + pin_arm;
    let d_pin = body_point(pin_arm, LINK);
    let gap = profile.nearest_gap(sprocket, pin);
    let (out_of_gap, radial) = (pin - gap, pin - sprocket.position);
    let (distance, from_centre) = (out_of_gap.norm(), radial.norm());
    let into_flank = distance + shoe.pin_radius - profile.arc_radius;
    let into_tip = profile.addendum + shoe.pin_radius - from_centre;
    if into_flank <= into_tip {
        let d_gap = body_point(gap - sprocket.position, OTHER);
        let d_out = d_pin - d_gap;
        let u = out_of_gap / distance;
        let d_u = unit_vector(u, distance, &d_out);
        GeometryTangent {
            point: d_gap + d_u * profile.arc_radius,
            depth: dot_rows(u, &d_out),
            gradient: -d_u,
        }
    } else {
        let d_centre = body_point(Vector2::zeros(), OTHER);
        let d_radial = d_pin - d_centre;
        let u = radial / from_centre;
        let d_u = unit_vector(u, from_centre, &d_radial);
        GeometryTangent {
            point: d_centre + d_u * profile.addendum,
            depth: -dot_rows(u, &d_radial),
            gradient: d_u,
        }
    }
}
