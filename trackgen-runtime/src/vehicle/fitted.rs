//! Contact laws that fit the vehicle declared: where a declaration leaves
//! a law out, its stiffness, damping and friction regularisation follow
//! from the vehicle's own weight, shoes and wheels, by stated rules, so a
//! 120 kg robot and a 25-tonne carrier each get laws of their own size
//! (the rules: [`ContactFit`]).

use super::Geometry;
use crate::contact::{ContactLaws, GroundFriction, GroundLaws};
use crate::laws::{Friction, NormalLaw, Stiction};
use crate::multibody::{ChassisPart, PartKind, TreeDescription};

/// The mean static penetration of a ground point the ground's stiffness is
/// fitted to, m.
pub const GROUND_DEPTH: f64 = 1e-3;
/// The damping ratio of a shoe bouncing on its ground points.
pub const GROUND_DAMPING_RATIO: f64 = 0.4;
/// The damping ratio of a shoe's tangential spring on the ground
/// (critical: a shoe does not ring along the ground).
pub const TANGENTIAL_DAMPING_RATIO: f64 = 1.0;
/// The static penetration of a rim (or tooth) contact the rims' stiffness
/// is fitted to, m.
pub const RIM_DEPTH: f64 = 5e-4;
/// The damping ratio of a shoe on one rim contact.
pub const RIM_DAMPING_RATIO: f64 = 0.1;
/// The rate of the rims' friction slope on a shoe, 1/s.
pub const RIM_FRICTION_RATE: f64 = 250.0;
/// How far above the lowest rim a wheel's rim may reach and still bear on
/// the ground at rest, m.
pub const BEARING_BAND: f64 = 0.05;
/// The default friction coefficient of shoes on the ground.
pub const GROUND_MU: f64 = 0.8;
/// The default friction coefficient of the track on rims and teeth.
pub const RIM_MU: f64 = 0.4;

/// The figures of a vehicle its fitted contact laws are made from.
///
/// The rules (the figures from the compiled model at its design position):
///
/// * **Ground, normal**: the weight `W` shared by the ground points under
///   the bearing wheels (those whose rims reach within
///   [`BEARING_BAND`] of the lowest: their span `L` plus a rim radius
///   each way holds `L / p` shoes of `n_p` points) sinks them
///   [`GROUND_DEPTH`] (1 mm): `k = W p / (n_p L δ)`. Hunt-Crossley,
///   exponent 1, with `χ` giving a shoe bouncing on its points the damping
///   ratio [`GROUND_DAMPING_RATIO`] (0.4) at that depth:
///   `χ = 2 ζ √(n_p k m_s) / (n_p k δ)`.
/// * **Ground, friction**: stiction ([`Stiction`]), `μ` = 0.8, the
///   tangential stiffness the normal law's at the static depth (`k`, or
///   `k δⁿ⁻¹`), its damping critical for a shoe on its points
///   ([`TANGENTIAL_DAMPING_RATIO`]): `c = 2 ζ √(n_p k_t m_s) / n_p`.
/// * **Rims and teeth, normal**: a bearing wheel's share of the weight on
///   two contacts sinks each [`RIM_DEPTH`] (0.5 mm):
///   `k = W / (2 N δ_r)`; `χ` for the damping ratio [`RIM_DAMPING_RATIO`]
///   (0.1) of a shoe on one such contact.
/// * **Rims and teeth, friction**: `μ` = 0.4, regularised over the slip
///   speed at which its slope `μ F/v_s` on a shoe (`F` a contact's static
///   load) is [`RIM_FRICTION_RATE`] (250 /s): `v_s = μ F / (m_s λ)`. The
///   slope is a shoe's stiffest mode under a loaded rim, and sets an
///   explicit integrator's step; its friction only spins the wheels up and
///   rubs the flanks.
///
/// For the M113 at Chrono's masses (55.7 kN, 21 shoes on 3.28 m of
/// ground, 18 kg shoes) the rules give a ground stiffness of 1.3e6 N/m per
/// point (`χ` 2.1 s/m), rims 1.1e7 N/m (`χ` 0.53 s/m, `v_s` 0.50 m/s):
/// close to the figures its declaration gives by hand (2e6, 2, 1e7, 0.5,
/// 0.5).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactFit {
    /// The vehicle's weight, N.
    pub weight: f64,
    /// The mean shoe (link) mass, kg.
    pub shoe_mass: f64,
    /// Ground points per shoe.
    pub points_per_shoe: usize,
    /// Ground points bearing at rest.
    pub bearing_points: f64,
    /// Wheels bearing on the ground at rest.
    pub bearing_wheels: usize,
}

/// What a declaration gives of one contact pair; `None` takes the fitted
/// default.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct DeclaredPair {
    /// The normal law.
    pub normal: Option<NormalLaw>,
    /// `μ`.
    pub mu: Option<f64>,
    /// The regularisation speed, m/s (on the ground: regularised Coulomb
    /// friction instead of stiction).
    pub slip: Option<f64>,
    /// The ground's tangential stiffness, N/m.
    pub tangential_stiffness: Option<f64>,
    /// The ground's tangential damping, N s/m.
    pub tangential_damping: Option<f64>,
}

/// What a declaration gives of its contact.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct DeclaredContact {
    /// Shoes on the ground.
    pub ground: DeclaredPair,
    /// Shoes' inner faces on rims.
    pub wheels: DeclaredPair,
    /// Pins on teeth.
    pub sprocket: DeclaredPair,
}

/// A vehicle's contact laws: the declared, the rest fitted.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactLawSet {
    /// Shoes on the ground.
    pub ground: GroundLaws,
    /// Shoes' inner faces on rims.
    pub wheels: ContactLaws,
    /// Pins on teeth.
    pub sprocket: ContactLaws,
}

impl ContactFit {
    /// The figures of the vehicle whose track and chassis are described by
    /// `track` and `chassis` (with its `parts`), and whose shoe is
    /// `geometry`'s, at the design position.
    pub fn of(
        track: &TreeDescription,
        chassis: &TreeDescription,
        parts: &[ChassisPart],
        geometry: &Geometry,
    ) -> ContactFit {
        let g = track.gravity.norm();
        let mass: f64 = track
            .bodies
            .iter()
            .chain(&chassis.bodies)
            .map(|b| b.mass)
            .sum();
        let links = track.bodies.len().max(1);
        let shoe_mass = track.bodies.iter().map(|b| b.mass).sum::<f64>() / links as f64;
        let points_per_shoe = geometry.shoe.ground_points.len().max(1);
        let pitch = track.pitch().unwrap_or_else(|_| {
            track.link_spans().map_or(0.0, |s| {
                s.iter().map(|d| d.norm()).sum::<f64>() / links as f64
            })
        });
        // The parts' centres at the design position, in the chassis frame.
        let centres = chassis_centres(chassis);
        let rims: Vec<(f64, f64, f64)> = parts
            .iter()
            .filter(|p| p.kind != PartKind::Sprocket)
            .map(|p| (centres[p.body].0, centres[p.body].1, p.radius))
            .collect();
        let lowest = rims
            .iter()
            .map(|&(_, y, r)| y - r)
            .fold(f64::INFINITY, f64::min);
        let bearing: Vec<&(f64, f64, f64)> = rims
            .iter()
            .filter(|&&(_, y, r)| y - r <= lowest + BEARING_BAND)
            .collect();
        let front = bearing
            .iter()
            .map(|w| w.0 + w.2)
            .fold(f64::NEG_INFINITY, f64::max);
        let rear = bearing
            .iter()
            .map(|w| w.0 - w.2)
            .fold(f64::INFINITY, f64::min);
        let length = (front - rear).max(pitch);
        ContactFit {
            weight: mass * g,
            shoe_mass,
            points_per_shoe,
            bearing_points: (length / pitch).max(1.0) * points_per_shoe as f64,
            bearing_wheels: bearing.len().max(1),
        }
    }

    /// The static load of a ground point, N.
    pub fn ground_load(&self) -> f64 {
        self.weight / self.bearing_points
    }

    /// The static load of a rim contact, N (a bearing wheel's share on
    /// two contacts).
    pub fn rim_load(&self) -> f64 {
        self.weight / (2.0 * self.bearing_wheels as f64)
    }

    /// The fitted normal law of the ground.
    pub fn ground_normal(&self) -> NormalLaw {
        let k = self.ground_load() / GROUND_DEPTH;
        let n = self.points_per_shoe as f64;
        let chi =
            2.0 * GROUND_DAMPING_RATIO * (n * k * self.shoe_mass).sqrt() / (n * k * GROUND_DEPTH);
        NormalLaw::HuntCrossley {
            stiffness: k,
            exponent: 1.0,
            chi,
        }
    }

    /// The fitted normal law of rims and teeth.
    pub fn rim_normal(&self) -> NormalLaw {
        let k = self.rim_load() / RIM_DEPTH;
        let chi = 2.0 * RIM_DAMPING_RATIO * (k * self.shoe_mass).sqrt() / (k * RIM_DEPTH);
        NormalLaw::HuntCrossley {
            stiffness: k,
            exponent: 1.0,
            chi,
        }
    }

    /// The ground's stiction under normal law `normal`: the tangential
    /// stiffness the normal law's secant at the static depth, critically
    /// damped on a shoe; either given instead where declared.
    pub fn stiction(
        &self,
        normal: &NormalLaw,
        mu: f64,
        (stiffness, damping): (Option<f64>, Option<f64>),
    ) -> Stiction {
        let secant = match *normal {
            NormalLaw::HuntCrossley {
                stiffness,
                exponent,
                ..
            } => stiffness * GROUND_DEPTH.powf(exponent - 1.0),
            NormalLaw::KelvinVoigt { stiffness, .. } => stiffness,
        };
        let k = stiffness.unwrap_or(secant);
        let n = self.points_per_shoe as f64;
        let c = damping.unwrap_or_else(|| {
            2.0 * TANGENTIAL_DAMPING_RATIO * (n * k * self.shoe_mass).sqrt() / n
        });
        Stiction {
            mu,
            stiffness: k,
            damping: c,
        }
    }

    /// The rims' (and teeth's) regularisation speed for coefficient `mu`,
    /// m/s.
    pub fn rim_slip(&self, mu: f64) -> f64 {
        mu * self.rim_load() / (self.shoe_mass * RIM_FRICTION_RATE)
    }

    /// The laws of every pair: the declared, the rest by the rules.
    pub fn laws(&self, declared: &DeclaredContact) -> ContactLawSet {
        let d = &declared.ground;
        let normal = d.normal.unwrap_or_else(|| self.ground_normal());
        let mu = d.mu.unwrap_or(GROUND_MU);
        let friction = match d.slip {
            Some(slip) => GroundFriction::Regularised(Friction { mu, slip }),
            None => GroundFriction::Stiction(self.stiction(
                &normal,
                mu,
                (d.tangential_stiffness, d.tangential_damping),
            )),
        };
        let rim = |d: &DeclaredPair| {
            let mu = d.mu.unwrap_or(RIM_MU);
            ContactLaws {
                normal: d.normal.unwrap_or_else(|| self.rim_normal()),
                friction: Friction {
                    mu,
                    slip: d.slip.unwrap_or_else(|| self.rim_slip(mu)),
                },
            }
        };
        ContactLawSet {
            ground: GroundLaws { normal, friction },
            wheels: rim(&declared.wheels),
            sprocket: rim(&declared.sprocket),
        }
    }
}

/// Every chassis body's centroid at the design position (all coordinates
/// zero), from the description: `R^b = R^p + ū_p − ū_b`.
fn chassis_centres(chassis: &TreeDescription) -> Vec<(f64, f64)> {
    let mut out: Vec<(f64, f64)> = Vec::with_capacity(chassis.bodies.len());
    for body in &chassis.bodies {
        let centre = match body.parent {
            Some(p) => {
                let (px, py) = out[p];
                (
                    px + body.at_parent.x - body.at_self.x,
                    py + body.at_parent.y - body.at_self.y,
                )
            }
            None => (0.0, 0.0),
        };
        out.push(centre);
    }
    out
}
