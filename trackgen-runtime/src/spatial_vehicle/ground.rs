//! The shoes on the ground in space: each planar ground point of each
//! shoe as two points across its width, each with half the point's law
//! (half its normal stiffness and damping, half its stiction's spring
//! and damper): a mirrored vehicle's two sides are its planar model's
//! side.
//!
//! A link whose ground points all lie above the highest ground under
//! the whole track ([`HeightField::max_height`] over the links' box) is
//! passed over with one comparison, as the planar route culls its links:
//! none of its points can touch, so the same numbers come out as from
//! testing each (its stiction deflections relax as a point off the
//! ground's do).

use nalgebra::{Vector2, Vector3};

use super::{Bodies, GroundForce, SpatialDynamics};
use crate::contact::space::{SpaceContact, SpaceForce};
use crate::contact::{GroundFriction, GroundLaws};
use crate::laws::{NormalLaw, Stiction};
use crate::multibody::{ChassisModel, TrackModel};
use crate::spatial::{Side, SpatialLoad};

/// How far a link must clear the highest ground before it is passed
/// over, m: more than the rounding of a height or a point's place (a few
/// ulps of metres) can move either, so a passed-over point is above the
/// ground by the same test the contact makes.
const CLEARANCE_MARGIN: f64 = 1e-6;

impl<H, const DH: usize, R, const DR: usize, L, const DL: usize>
    SpatialDynamics<'_, H, DH, R, DR, L, DL>
where
    H: ChassisModel<DH>,
    R: TrackModel<DR>,
    L: TrackModel<DL>,
{
    /// The shoes on the ground: each planar ground point as two across
    /// the width, each with half its law; with stiction, each point's
    /// deflection from `deflections` and its rate into `rates` (a point
    /// off the ground relaxing); on soft soil, the soil's laws
    /// ([`on_soil`](Self::on_soil)). What they store and dissipate; each
    /// point on the ground into `found`, if given, as of `side`.
    pub(super) fn ground(
        &self,
        side: Side,
        links: &Bodies,
        loads: &mut [SpatialLoad],
        (deflections, rates): (&[f64], &mut [f64]),
        mut found: Option<&mut Vec<GroundForce>>,
    ) -> (f64, f64) {
        if let Some(soil) = &self.soil {
            return self.on_soil(soil, side, links, loads, (deflections, rates), found);
        }
        // Half of each law: the normal law's stiffness and damping, and
        // a stiction's spring and damper (its limit, `μ` times the halved
        // normal force, halves with it); regularised friction is a
        // multiple of the normal force already.
        let stiction = match self.laws.ground.friction {
            GroundFriction::Stiction(law) => Some(Stiction {
                stiffness: 0.5 * law.stiffness,
                damping: 0.5 * law.damping,
                ..law
            }),
            GroundFriction::Regularised(_) => None,
        };
        let half = GroundLaws {
            normal: share(self.laws.ground.normal, 0.5),
            friction: stiction.map_or(self.laws.ground.friction, GroundFriction::Stiction),
        };
        let across = self.across();
        let points = self.shoe.ground_points.len();
        let clear_above = self.clear_above(links, across);
        let (mut potential, mut dissipation) = (0.0, 0.0);
        let mut i = 0;
        // The run of passed-over links since `clear_from` relaxes in one
        // pass when it ends (the track's whole upper run at once).
        let mut clear_from = None;
        for k in 0..links.len() {
            if links.centroid(k).z > clear_above {
                if stiction.is_some() {
                    clear_from.get_or_insert(i);
                    i += 4 * points;
                }
                continue;
            }
            if let (Some(law), Some(from)) = (stiction, clear_from.take()) {
                let books = (&mut potential, &mut dissipation);
                relax(&law, &deflections[from..i], &mut rates[from..], books);
            }
            for p in &self.shoe.ground_points {
                for lateral in [-across, across] {
                    let z = match stiction {
                        Some(_) => Vector2::new(deflections[i], deflections[i + 1]),
                        None => Vector2::zeros(),
                    };
                    let x = links.point_across(k, *p, lateral);
                    match SpaceContact::at(&self.field, x, links.velocity_at(k, x)) {
                        Some(contact) => {
                            let force = half.respond_in_space(&contact, z);
                            let books = (&mut potential, &mut dissipation);
                            land(
                                links,
                                (&mut *loads, &mut found),
                                (side, k, x),
                                &force,
                                books,
                            );
                            if stiction.is_some() {
                                rates[i..i + 2].copy_from_slice(force.rate.as_slice());
                            }
                        }
                        None => {
                            if let Some(law) = stiction {
                                let books = (&mut potential, &mut dissipation);
                                relax(&law, &deflections[i..i + 2], &mut rates[i..], books);
                            }
                        }
                    }
                    if stiction.is_some() {
                        i += 2;
                    }
                }
            }
        }
        if let (Some(law), Some(from)) = (stiction, clear_from) {
            let books = (&mut potential, &mut dissipation);
            relax(&law, &deflections[from..i], &mut rates[from..], books);
        }
        (potential, dissipation)
    }

    /// How far each of a planar ground point's two points lies from the
    /// shoe's middle across it, m: `w/(2√3)`, the two-point Gauss rule
    /// over the shoe's width `w` (0 where it declares none).
    pub(super) fn across(&self) -> f64 {
        self.shoe.width.unwrap_or(0.0) / (2.0 * 3.0_f64.sqrt())
    }

    /// The height a link's centroid must be above for none of its ground
    /// points to reach the ground: the highest ground under the box of
    /// every link's points, plus the farthest point's reach from its
    /// centroid and the margin. Infinite (nothing passed over) for a
    /// state that is not a number.
    pub(super) fn clear_above(&self, links: &Bodies, across: f64) -> f64 {
        let reach = self
            .shoe
            .ground_points
            .iter()
            .map(|p| (p.norm_squared() + across * across).sqrt())
            .fold(0.0, f64::max);
        let (mut low, mut high) = (
            Vector2::repeat(f64::INFINITY),
            Vector2::repeat(-f64::INFINITY),
        );
        for at in links.centroids() {
            let xy = at.xy();
            low = low.inf(&xy);
            high = high.sup(&xy);
        }
        if low.x > high.x {
            return f64::INFINITY;
        }
        let top = self.field.max_height(
            (low.x - reach, high.x + reach),
            (low.y - reach, high.y + reach),
        );
        top + reach + CLEARANCE_MARGIN
    }
}

/// A ground point's `force` at `x` on link `k` of `links`, side `side`:
/// onto the link's load, into `found` if given, and what it stores and
/// dissipates into the books. The one route of every ground point's
/// force, on rigid ground and on soil.
#[inline]
pub(super) fn land(
    links: &Bodies,
    (loads, found): (&mut [SpatialLoad], &mut Option<&mut Vec<GroundForce>>),
    (side, k, x): (Side, usize, Vector3<f64>),
    force: &SpaceForce,
    (potential, dissipation): (&mut f64, &mut f64),
) {
    links.push(loads, k, force.force, x);
    if let Some(found) = found.as_mut() {
        found.push(GroundForce {
            side,
            link: k,
            at: x,
            force: force.force,
        });
    }
    *potential += force.potential;
    *dissipation += force.dissipation;
}

/// Each of `deflections` relaxing off the ground, its rate into `rates`
/// (from the start); what they store and dissipate added to the books.
#[inline]
fn relax(
    law: &Stiction,
    deflections: &[f64],
    rates: &mut [f64],
    (potential, dissipation): (&mut f64, &mut f64),
) {
    let (stored, lost) = law.relax_each(deflections, rates);
    *potential += stored;
    *dissipation += lost;
}

/// The normal law with `fraction` of its stiffness (and of a
/// Kelvin–Voigt law's damping): a share of a point's contact.
fn share(law: NormalLaw, fraction: f64) -> NormalLaw {
    match law {
        NormalLaw::KelvinVoigt { stiffness, damping } => NormalLaw::KelvinVoigt {
            stiffness: stiffness * fraction,
            damping: damping * fraction,
        },
        NormalLaw::HuntCrossley {
            stiffness,
            exponent,
            chi,
        } => NormalLaw::HuntCrossley {
            stiffness: stiffness * fraction,
            exponent,
            chi,
        },
    }
}
