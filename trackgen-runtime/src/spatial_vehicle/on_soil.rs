//! The shoes on soft soil in space: each planar ground point of each shoe
//! as two points across its width, each pressing half the planar point's
//! patch under the soil's laws ([`SoftSpace`]); its state its shear
//! displacement in the ground's plane. After each accepted step the
//! soil's memory is brought up to the points ([`SpatialDynamics::press_soil`]).
//!
//! A link above the highest ground under its track is passed over with
//! one comparison, as on rigid ground: none of its points touches, so
//! none shears the soil (its states' rates are zero).

use nalgebra::Vector2;

use super::ground::land;
use super::{Bodies, GroundForce, SpatialDynamics, TreeState};
use crate::contact::rut_grid::RutPatch;
use crate::contact::soft_space::SoftSpace;
use crate::contact::space::SpaceContact;
use crate::multibody::{ChassisModel, TrackModel};
use crate::spatial::{Side, SpatialLoad};

/// The unit direction of `axis` in the ground's plane (`x̂` for an axis
/// standing on end): the way a link's patches lie on the rut, the way a
/// picture looks along the hull.
pub(super) fn horizontal(axis: nalgebra::Vector3<f64>) -> Vector2<f64> {
    let along = axis.xy();
    let length = along.norm();
    if length > 1e-9 {
        along / length
    } else {
        Vector2::x()
    }
}

impl<H, const DH: usize, R, const DR: usize, L, const DL: usize>
    SpatialDynamics<'_, H, DH, R, DR, L, DL>
where
    H: ChassisModel<DH>,
    R: TrackModel<DR>,
    L: TrackModel<DL>,
{
    /// [`ground`](Self::ground) on soft soil: side `side`'s shoes on
    /// `soil`, each point's shear displacement from `shears` and its rate
    /// (the slip in the ground's plane below the undisturbed surface,
    /// else zero) into `rates`. What they store and dissipate; each
    /// point the soil bears into `found`, if given.
    pub(super) fn on_soil(
        &self,
        soil: &SoftSpace,
        side: Side,
        links: &Bodies,
        loads: &mut [SpatialLoad],
        (shears, rates): (&[f64], &mut [f64]),
        mut found: Option<&mut Vec<GroundForce>>,
    ) -> (f64, f64) {
        let across = self.across();
        let per_link = 2 * self.shoe.ground_points.len();
        let clear_above = self.clear_above(links, across);
        let s = side.index();
        let (mut potential, mut dissipation) = (0.0, 0.0);
        let mut slot = 0;
        for k in 0..links.len() {
            if links.centroid(k).z > clear_above {
                rates[2 * slot..2 * (slot + per_link)].fill(0.0);
                slot += per_link;
                continue;
            }
            for p in &self.shoe.ground_points {
                for lateral in [-across, across] {
                    let x = links.point_across(k, *p, lateral);
                    let state = Vector2::new(shears[2 * slot], shears[2 * slot + 1]);
                    let rate = match SpaceContact::at(&self.field, x, links.velocity_at(k, x)) {
                        None => Vector2::zeros(),
                        Some(contact) => {
                            let (force, rate) = soil.respond(s, slot, &contact, state);
                            if let Some(force) = force {
                                let books = (&mut potential, &mut dissipation);
                                land(
                                    links,
                                    (&mut *loads, &mut found),
                                    (side, k, x),
                                    &force,
                                    books,
                                );
                            }
                            rate
                        }
                    };
                    rates[2 * slot..2 * slot + 2].copy_from_slice(rate.as_slice());
                    slot += 1;
                }
            }
        }
        (potential, dissipation)
    }

    /// After an accepted step, the tracks at `(right, left)` with their
    /// points' shear states `shears` (right, left): what the soil remembers
    /// brought up to every point ([`SoftSpace::press_point`],
    /// [`SoftSpace::passed_over`]). Whether a force changed (the
    /// integrator must restart); `false` on rigid ground.
    pub(super) fn press_soil(
        &mut self,
        t: f64,
        (right, left): (&TreeState<DR>, &TreeState<DL>),
        shears: [&[f64]; 2],
    ) -> bool {
        let Some(mut soil) = self.soil.take() else {
            return false;
        };
        soil.rut.at_time(t);
        let tracks = [
            Bodies::at(&self.right, right.parts()),
            Bodies::at(&self.left, left.parts()),
        ];
        let width = self.shoe.width.unwrap_or(0.0);
        let across = self.across();
        let mut changed = false;
        for (s, links) in tracks.iter().enumerate() {
            let clear_above = self.clear_above(links, across);
            let mut slot = 0;
            for k in 0..links.len() {
                let forward = horizontal(links.axis(k, 0));
                let passed = links.centroid(k).z > clear_above;
                for (point, p) in self.shoe.ground_points.iter().enumerate() {
                    // The middle of the point's share of the shoe along.
                    let share = Vector2::new(soil.share_middle(s, point), p.y);
                    for lateral in [-across, across] {
                        let at = links.point_across(k, *p, lateral);
                        // The middle of its share, on its half across.
                        let half = links.point_across(k, share, lateral.signum() * 0.25 * width);
                        let footprint = (half.xy(), forward);
                        let state = Vector2::new(shears[s][2 * slot], shears[s][2 * slot + 1]);
                        if passed {
                            soil.passed_over((s, slot), footprint, state);
                        } else {
                            let z = self.field.height(at.x, at.y) - at.z;
                            changed |= soil.press_point((s, slot), (at, z), footprint, state);
                        }
                        slot += 1;
                    }
                }
            }
        }
        self.soil = Some(soil);
        changed
    }

    /// The soft soil and what it remembers, on soil.
    pub fn soil(&self) -> Option<&SoftSpace> {
        self.soil.as_ref()
    }

    /// The ruts pressed so far in squares of `cells` × `cells` of the
    /// rut's cells, each with when it was first pressed
    /// ([`RutGrid::patches`](crate::contact::rut_grid::RutGrid::patches));
    /// none on rigid ground.
    pub fn rut_patches(&self, cells: usize) -> Vec<RutPatch> {
        self.soil
            .as_ref()
            .map_or_else(Vec::new, |soil| soil.rut.patches(cells))
    }

    /// The ground's height at `(x, y)` as it is now, m: the height
    /// field's, less on soft soil the plastic sinkage the soil remembers
    /// there (the rut's floor).
    pub fn surface(&self, x: f64, y: f64) -> f64 {
        let height = self.field.height(x, y);
        match &self.soil {
            Some(soil) => height - soil.rut.memory(Vector2::new(x, y)).plastic,
            None => height,
        }
    }
}
