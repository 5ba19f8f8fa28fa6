//! Placing a declared vehicle at t = 0: chassis on the ground at its design
//! position, idler tensioner set to take up the track's slack, track
//! wrapped round its wheels, sprocket turned so that a gap holds a joint.

use nalgebra::{SVector, Vector2};

use super::{
    AssemblyError, LinkCounts, PitchCircle, START_PENETRATION, SlackLimit, Touching, excess,
    links_round, wrap, wrap_at,
};
use crate::contact::sprocket::{self, ToothProfile};
use crate::contact::{BodyState, Contact, ShoeGeometry, ground, wheel};
use crate::multibody::{ChassisModel, ChassisPart, PartKind, TrackModel};
use crate::terrain::Terrain;

/// Initial coordinates of a vehicle.
#[derive(Debug, Clone, PartialEq)]
pub struct Assembled<const DT: usize, const DC: usize> {
    /// Track `q_i`.
    pub track: SVector<f64, DT>,
    /// Chassis `q_i`.
    pub chassis: SVector<f64, DC>,
    /// The tensioner as set: its arm's body and the angle (rad, from the
    /// declared position) at which the track fits. A track adjuster sets
    /// the spring's rest angle there too (as
    /// [`build`](crate::vehicle::build) does).
    pub tensioner: Option<(usize, f64)>,
}

/// The upper run's sag when a tensioner takes up the rest, as a fraction
/// of its longest span: nearly tight, as a tensioned track runs.
const TENSIONED_SAG: f64 = 0.005;

/// The sag curvature (1/m) that makes the longest upper span of `wheels`
/// sag [`TENSIONED_SAG`] of its length (`s ≈ κ L²/8`).
fn tensioned(wheels: &[PitchCircle]) -> f64 {
    let longest = super::longest_upper_span(wheels);
    if longest > 0.0 {
        8.0 * TENSIONED_SAG / longest
    } else {
        0.0
    }
}

/// The points of a tensioner's travel tried before bisecting: the belt's
/// length need not be monotone in a swing arm's angle, so the travel is
/// scanned for the bracket nearest the declared position.
const TRAVEL_SAMPLES: usize = 48;

/// The pitch circles of the wheels `parts` (of the chassis' `PARTS`) in
/// wrap order (counter-clockwise), each with its index in `parts`.
fn pitch_circles<C: ChassisModel<DC>, const DC: usize>(
    chassis: &C,
    parts: &[ChassisPart],
    qc: &SVector<f64, DC>,
    pitch: f64,
    shoe: &ShoeGeometry,
    profile: &ToothProfile,
) -> Vec<(usize, PitchCircle)> {
    let mut centres = vec![Vector2::zeros(); C::BODIES];
    chassis.body_positions(qc, &mut centres);
    let mut circles: Vec<(usize, PitchCircle)> = parts
        .iter()
        .enumerate()
        .map(|(i, part)| {
            let radius = match part.kind {
                // The joints sit in the gaps: a regular polygon of the pitch.
                PartKind::Sprocket => sprocket::pitch_radius(profile.teeth, pitch),
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
    let mut qc = SVector::<f64, DC>::zeros();
    qc[0] = x;
    let mut side = Gear::tensioned(track, chassis, C::PARTS, &mut qc, shoe, profile)?;
    let drop = side.drop(shoe, terrain, clearance);
    side.lower(&mut qc, drop);
    let qt = side.wrap(track, &mut qc, profile)?;
    check_start(track, chassis, C::PARTS, (&qt, &qc), shoe, profile, terrain)?;
    Ok(Assembled {
        track: qt,
        chassis: qc,
        tensioner: side.tensioner,
    })
}

/// One side's running gear being assembled: its parts, their pitch
/// circles in wrap order with the tensioner set, and how the upper run is
/// to sag.
pub(super) struct Gear<'p> {
    parts: &'p [ChassisPart],
    /// Each circle with its index in `parts`.
    circles: Vec<(usize, PitchCircle)>,
    /// The upper run's sag curvature where a tensioner took up the slack
    /// (1/m); `None`: the track sags as it will.
    sag: Option<f64>,
    /// The tensioner as set: its arm's body and angle, rad.
    pub(super) tensioner: Option<(usize, f64)>,
}

impl<'p> Gear<'p> {
    /// The side of `parts` at the chassis' coordinates `qc`, its
    /// tensioner (the first idler on an arm among `parts`) swung so that
    /// `track` fits with the upper run nearly tight; `qc` takes the arm's
    /// angle.
    pub(super) fn tensioned<
        T: TrackModel<DT>,
        const DT: usize,
        C: ChassisModel<DC>,
        const DC: usize,
    >(
        track: &T,
        chassis: &C,
        parts: &'p [ChassisPart],
        qc: &mut SVector<f64, DC>,
        shoe: &ShoeGeometry,
        profile: &ToothProfile,
    ) -> Result<Gear<'p>, AssemblyError> {
        let pitch = track.description().pitch()?;
        let tensioner = parts
            .iter()
            .find(|p| p.kind == PartKind::Idler)
            .and_then(|p| p.arm);
        let mut sag = None;
        let mut set = None;
        if let Some(arm) = tensioner {
            let (phi, kappa) = set_tensioner(
                track,
                |phi| {
                    let mut q = *qc;
                    q[2 + arm.body] = phi;
                    pitch_circles(chassis, parts, &q, pitch, shoe, profile)
                        .iter()
                        .map(|c| c.1)
                        .collect()
                },
                arm.travel,
            )?;
            qc[2 + arm.body] = phi;
            sag = Some(kappa);
            set = Some((arm.body, phi));
        }
        Ok(Gear {
            parts,
            circles: pitch_circles(chassis, parts, qc, pitch, shoe, profile),
            sag,
            tensioner: set,
        })
    }

    /// How far (m) the chassis must come down for this side's lowest
    /// wheel's shoes to rest `clearance` above the terrain.
    pub(super) fn drop(&self, shoe: &ShoeGeometry, terrain: &Terrain, clearance: f64) -> f64 {
        let depth = -shoe.ground_points.iter().map(|p| p.y).fold(0.0, f64::min);
        self.circles
            .iter()
            .map(|(_, c)| c.centre.y - c.radius - depth - terrain.height(c.centre.x) - clearance)
            .fold(f64::INFINITY, f64::min)
    }

    /// The chassis (`qc`) and this side's circles brought down by `drop`.
    pub(super) fn lower<const DC: usize>(&mut self, qc: &mut SVector<f64, DC>, drop: f64) {
        qc[1] -= drop;
        for (_, c) in &mut self.circles {
            c.centre.y -= drop;
        }
    }

    /// The track wrapped round this side's circles, and the sprocket (if
    /// the side has one) turned in `qc` so that a gap holds a joint.
    pub(super) fn wrap<T: TrackModel<DT>, const DT: usize, const DC: usize>(
        &self,
        track: &T,
        qc: &mut SVector<f64, DC>,
        profile: &ToothProfile,
    ) -> Result<SVector<f64, DT>, AssemblyError> {
        let wheels: Vec<PitchCircle> = self.circles.iter().map(|c| c.1).collect();
        let wrapped = match self.sag {
            Some(kappa) => wrap_at(track, &wheels, kappa)?,
            None => wrap(track, &wheels)?,
        };
        let (qt, joints) = (wrapped.q, wrapped.joints);
        let sprocket = self
            .circles
            .iter()
            .position(|(i, _)| self.parts[*i].kind == PartKind::Sprocket);
        if let Some(s) = sprocket {
            let part = &self.parts[self.circles[s].0];
            let (centre, radius) = (wheels[s].centre, wheels[s].radius);
            let off = |p: &Vector2<f64>| ((p - centre).norm() - radius).abs();
            let nearest = joints
                .iter()
                .min_by(|a, b| off(a).total_cmp(&off(b)))
                .expect("joints");
            let psi = (nearest - centre).y.atan2((nearest - centre).x);
            qc[2 + part.body] = psi - 0.5 * profile.pitch_angle();
        }
        Ok(qt)
    }
}

/// The tensioner's angle (rad, from the declared position, within
/// `travel`) at which the track fits `wheels(angle)` with the upper run
/// nearly tight ([`TENSIONED_SAG`]): the root nearest the declared
/// position; and that sag's curvature, 1/m. If none, the track is too long or too short for the travel,
/// and the error names the link counts that fit somewhere in it.
fn set_tensioner<T: TrackModel<DT>, const DT: usize>(
    track: &T,
    wheels: impl Fn(f64) -> Vec<PitchCircle>,
    (low, high): (f64, f64),
) -> Result<(f64, f64), AssemblyError> {
    let pitches = super::pitches(track);
    let fit = |phi: f64| {
        let w = wheels(phi);
        excess(&w, tensioned(&w), &pitches)
    };
    let angles: Vec<f64> = (0..=TRAVEL_SAMPLES)
        .map(|i| low + (high - low) * i as f64 / TRAVEL_SAMPLES as f64)
        .chain([0.0_f64.clamp(low, high)])
        .collect();
    let mut samples: Vec<(f64, f64)> = angles.iter().map(|&a| (a, fit(a))).collect();
    samples.sort_by(|a, b| a.0.total_cmp(&b.0));
    // The sign change nearest the declared position.
    let bracket = samples
        .windows(2)
        .filter(|w| (w[0].1 >= 0.0) != (w[1].1 >= 0.0))
        .min_by(|a, b| {
            let distance = |w: &[(f64, f64)]| w[0].0.abs().min(w[1].0.abs());
            distance(a).total_cmp(&distance(b))
        });
    if let Some(w) = bracket {
        let phi = super::bisect(w[0], w[1], &fit);
        let gap = fit(phi).abs();
        if gap > super::LANDING {
            return Err(AssemblyError::Unclosed {
                links: pitches.len(),
                gap,
            });
        }
        let w = wheels(phi);
        return Ok((phi, tensioned(&w)));
    }
    let pitch = super::mean(&pitches);
    let counts: Vec<f64> = angles
        .iter()
        .map(|&a| {
            let w = wheels(a);
            links_round(&w, tensioned(&w), pitch)
        })
        .filter(|n| n.is_finite())
        .collect();
    let fits = LinkCounts {
        pitch,
        tight: counts.iter().copied().fold(f64::INFINITY, f64::min),
        slack: counts.iter().copied().fold(f64::NEG_INFINITY, f64::max),
    };
    let links = pitches.len();
    if samples.iter().all(|s| s.1 >= 0.0) {
        Err(AssemblyError::TrackTooLong {
            links,
            long: samples.iter().map(|s| s.1).fold(f64::INFINITY, f64::min),
            limit: SlackLimit::Tensioner,
            fits,
        })
    } else {
        Err(AssemblyError::TrackTooShort {
            links,
            short: -samples
                .iter()
                .map(|s| s.1)
                .fold(f64::NEG_INFINITY, f64::max),
            fits,
        })
    }
}

/// The deepest contact of the assembled start, by contact
/// [detection](crate::contact) (geometry only, no law), checked against
/// [`START_PENETRATION`].
pub(super) fn check_start<
    T: TrackModel<DT>,
    const DT: usize,
    C: ChassisModel<DC>,
    const DC: usize,
>(
    track: &T,
    chassis: &C,
    parts: &[ChassisPart],
    (qt, qc): (&SVector<f64, DT>, &SVector<f64, DC>),
    shoe: &ShoeGeometry,
    profile: &ToothProfile,
    terrain: &Terrain,
) -> Result<(), AssemblyError> {
    let at_rest = |positions: &[Vector2<f64>], angles: &[f64]| -> Vec<BodyState> {
        positions
            .iter()
            .zip(angles)
            .map(|(r, a)| BodyState::at_rest(*r, *a))
            .collect()
    };
    let mut r = vec![Vector2::zeros(); T::BODIES];
    track.body_positions(qt, &mut r);
    let links = at_rest(&r, &qt.as_slice()[2..]);
    let mut r = vec![Vector2::zeros(); C::BODIES];
    chassis.body_positions(qc, &mut r);
    let bodies = at_rest(&r, &qc.as_slice()[2..]);
    let mut contacts: Vec<Contact> = Vec::new();
    ground::detect(terrain, &links, shoe, &mut contacts);
    let mut touching = vec![Touching::Ground; contacts.len()];
    for part in parts {
        let body = &bodies[part.body];
        if part.kind == PartKind::Sprocket {
            sprocket::detect((body, part.body), profile, &links, shoe, &mut contacts);
        } else {
            wheel::detect((body, part.body, part.radius), &links, shoe, &mut contacts);
        }
        touching.resize(
            contacts.len(),
            Touching::Part {
                kind: part.kind,
                name: part.name,
            },
        );
    }
    // The first of the deepest, in detection order.
    let deepest = contacts
        .iter()
        .zip(touching)
        .filter(|(c, _)| c.depth > START_PENETRATION)
        .fold(None::<(&Contact, Touching)>, |best, (c, what)| match best {
            Some(b) if b.0.depth >= c.depth => Some(b),
            _ => Some((c, what)),
        });
    match deepest {
        Some((c, what)) => Err(AssemblyError::StartsInside {
            what,
            link: c.link + 1,
            depth: c.depth,
        }),
        None => Ok(()),
    }
}
