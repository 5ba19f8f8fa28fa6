//! Placing a declared vehicle at t = 0: chassis on the ground at its design
//! position, idler tensioner set to take up the track's slack, track
//! wrapped round its wheels, sprocket turned so that a gap holds a joint.

use nalgebra::{SVector, Vector2};

use crate::assembly::{AssemblyError, PitchCircle, excess, wrap};
use crate::contact::ground::GroundContact;
use crate::contact::sprocket::{SprocketContact, ToothProfile};
use crate::contact::wheel::WheelContact;
use crate::contact::{BodyState, Friction, NormalLaw, ShoeGeometry, Terrain};
use crate::model::{BodyLoad, ChassisModel, PartKind, TrackModel};

/// Initial coordinates of a vehicle.
#[derive(Debug, Clone, PartialEq)]
pub struct Assembled<const DT: usize, const DC: usize> {
    /// Track `q_i`.
    pub track: SVector<f64, DT>,
    /// Chassis `q_i`.
    pub chassis: SVector<f64, DC>,
}

/// The sag left in the top span when a tensioner takes up the rest, as a
/// fraction of the span.
const TENSIONED_SAG: f64 = 0.005;

/// The wheels' pitch circles in wrap order (counter-clockwise), each with
/// its index in `C::PARTS`.
fn pitch_circles<C: ChassisModel<DC>, const DC: usize>(
    chassis: &C,
    qc: &SVector<f64, DC>,
    pitch: f64,
    shoe: &ShoeGeometry,
    profile: &ToothProfile,
) -> Vec<(usize, PitchCircle)> {
    let mut centres = vec![Vector2::zeros(); C::BODIES];
    chassis.body_positions(qc, &mut centres);
    let mut circles: Vec<(usize, PitchCircle)> = C::PARTS
        .iter()
        .enumerate()
        .map(|(i, part)| {
            let radius = match part.kind {
                // The joints sit in the gaps: a regular polygon of the pitch.
                PartKind::Sprocket => crate::contact::sprocket::pitch_radius(profile.teeth, pitch),
                // The shoes' inner faces (chords) rest on the rim.
                _ => (part.radius + shoe.inner_offset()).hypot(pitch / 2.0),
            };
            (
                i,
                PitchCircle {
                    centre: centres[part.body],
                    radius,
                },
            )
        })
        .collect();
    let middle =
        circles.iter().map(|c| c.1.centre).sum::<Vector2<f64>>() / circles.len().max(1) as f64;
    let angle = |c: &PitchCircle| (c.centre - middle).y.atan2((c.centre - middle).x);
    circles.sort_by(|a, b| angle(&a.1).total_cmp(&angle(&b.1)));
    circles
}

/// Assembles the vehicle with its chassis centroid at `x` (m), the track
/// resting `clearance` (m) above the terrain. If the idler is on an arm,
/// the arm is swung so that the track fits with a nearly straight top span
/// (the tensioner takes up the slack); otherwise the top span sags. An
/// invalid terrain ([`Terrain::check`]) is an error.
pub fn assemble<T: TrackModel<DT>, const DT: usize, C: ChassisModel<DC>, const DC: usize>(
    track: &T,
    chassis: &C,
    shoe: &ShoeGeometry,
    profile: &ToothProfile,
    terrain: &Terrain,
    x: f64,
    clearance: f64,
) -> Result<Assembled<DT, DC>, AssemblyError> {
    terrain.check()?;
    let pitch = track
        .description()
        .link_spans()
        .map_or(0.0, |s| s[0].norm());
    let mut qc = SVector::<f64, DC>::zeros();
    qc[0] = x;
    let sprocket_index = |circles: &[(usize, PitchCircle)]| {
        circles
            .iter()
            .position(|(i, _)| C::PARTS[*i].kind == PartKind::Sprocket)
    };
    let tensioner = C::PARTS
        .iter()
        .find(|p| p.kind == PartKind::Idler)
        .and_then(|p| p.arm);
    if let Some(arm) = tensioner {
        let fits = |phi: f64| {
            let mut q = qc;
            q[2 + arm.body] = phi;
            let circles = pitch_circles(chassis, &q, pitch, shoe, profile);
            let wheels: Vec<PitchCircle> = circles.iter().map(|c| c.1).collect();
            let span = sprocket_index(&circles).unwrap_or(0);
            let length = (wheels[(span + 1) % wheels.len()].centre - wheels[span].centre).norm();
            excess(track, &wheels, span, TENSIONED_SAG * length)
        };
        let (mut lo, mut hi) = (-0.6, 0.6);
        if fits(lo).signum() != fits(hi).signum() {
            for _ in 0..60 {
                let mid = 0.5 * (lo + hi);
                if fits(mid).signum() == fits(lo).signum() {
                    lo = mid
                } else {
                    hi = mid
                }
            }
            qc[2 + arm.body] = 0.5 * (lo + hi);
        }
    }
    let mut circles = pitch_circles(chassis, &qc, pitch, shoe, profile);
    // Down onto the ground: the lowest wheel's shoes touch it.
    let depth = -shoe.ground_points.iter().map(|p| p.y).fold(0.0, f64::min);
    let drop = circles
        .iter()
        .map(|(_, c)| c.centre.y - c.radius - depth - terrain.height(c.centre.x) - clearance)
        .fold(f64::INFINITY, f64::min);
    qc[1] -= drop;
    for (_, c) in &mut circles {
        c.centre.y -= drop;
    }
    let wheels: Vec<PitchCircle> = circles.iter().map(|c| c.1).collect();
    let sprocket = sprocket_index(&circles);
    let (qt, joints) = wrap(track, &wheels, sprocket)?;
    if let Some(s) = sprocket {
        let part = &C::PARTS[circles[s].0];
        let (centre, radius) = (wheels[s].centre, wheels[s].radius);
        let off = |p: &Vector2<f64>| ((p - centre).norm() - radius).abs();
        let nearest = joints
            .iter()
            .min_by(|a, b| off(a).total_cmp(&off(b)))
            .expect("joints");
        let psi = (nearest - centre).y.atan2((nearest - centre).x);
        qc[2 + part.body] = psi - 0.5 * profile.pitch_angle();
    }
    check_start::<T, DT, C, DC>(track, chassis, (&qt, &qc), shoe, profile, terrain)?;
    Ok(Assembled {
        track: qt,
        chassis: qc,
    })
}

/// How deep (m) an assembled start may put a shoe feature into a wheel,
/// the sprocket's teeth or the ground. The wrap lays the joints on pitch
/// circles from which the faces and pins just touch, and the closure's
/// Newton-Raphson moves them by a fraction of a millimetre; 2 mm is well
/// above that and well below what a wrong wrap gives (a sagging span laid
/// through a roller: centimetres), and below the 2–4 mm a shoe sinks under
/// its static load, so a start within it is not a jolt.
pub const START_PENETRATION: f64 = 2e-3;

/// The deepest penetration of each contact pair at the assembled start,
/// checked against [`START_PENETRATION`].
fn check_start<T: TrackModel<DT>, const DT: usize, C: ChassisModel<DC>, const DC: usize>(
    track: &T,
    chassis: &C,
    (qt, qc): (&SVector<f64, DT>, &SVector<f64, DC>),
    shoe: &ShoeGeometry,
    profile: &ToothProfile,
    terrain: &Terrain,
) -> Result<(), AssemblyError> {
    let at_rest = |positions: &[Vector2<f64>], angles: &[f64]| -> Vec<BodyState> {
        positions
            .iter()
            .zip(angles)
            .map(|(r, a)| BodyState::new(*r, *a, Vector2::zeros(), 0.0))
            .collect()
    };
    let mut r = vec![Vector2::zeros(); T::BODIES];
    track.body_positions(qt, &mut r);
    let links = at_rest(&r, &qt.as_slice()[2..]);
    let mut r = vec![Vector2::zeros(); C::BODIES];
    chassis.body_positions(qc, &mut r);
    let bodies = at_rest(&r, &qc.as_slice()[2..]);
    // Geometry only: any law reports the penetration.
    let normal = NormalLaw::KelvinVoigt {
        stiffness: 1.0,
        damping: 0.0,
    };
    let friction = Friction { mu: 0.0, slip: 1.0 };
    let mut loads = vec![BodyLoad::ZERO; T::BODIES];
    let mut other = BodyLoad::ZERO;
    let mut deepest: Option<(String, usize, f64)> = None;
    let mut keep = |what: &dyn Fn() -> String, link: usize, depth: f64| {
        if depth > deepest.as_ref().map_or(START_PENETRATION, |d| d.2) {
            deepest = Some((what(), link + 1, depth));
        }
    };
    GroundContact {
        terrain: terrain.clone(),
        normal,
        friction,
    }
    .apply(&links, shoe, &mut loads, |i, c| {
        keep(&|| "the ground".to_string(), i, c.penetration)
    });
    for part in C::PARTS {
        let body = &bodies[part.body];
        let kind = match part.kind {
            PartKind::Sprocket => "sprocket",
            PartKind::Idler => "idler",
            PartKind::RoadWheel => "road wheel",
            PartKind::Roller => "roller",
        };
        let name = || format!("{kind} `{}`", part.name);
        if part.kind == PartKind::Sprocket {
            SprocketContact {
                profile: *profile,
                normal,
                friction,
            }
            .apply(body, &links, shoe, &mut loads, &mut other, |i, c| {
                keep(&name, i, c.penetration)
            });
        } else {
            WheelContact { normal, friction }.apply(
                (body, part.radius),
                &links,
                shoe,
                &mut loads,
                &mut other,
                |i, c| keep(&name, i, c.penetration),
            );
        }
    }
    match deepest {
        Some((what, link, depth)) => Err(AssemblyError::StartsInside { what, link, depth }),
        None => Ok(()),
    }
}
