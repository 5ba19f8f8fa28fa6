//! Soft soil under the shoes in space: the planar soft ground's laws
//! ([`soft_ground`](super::soft_ground): Bekker's pressure beyond the
//! deepest earlier sinkage and elastic back from it, Janosi–Hanamoto's
//! shear at the shear displacement, the soil's damping and its books) at
//! each of a shoe's ground points across its width, with two things that
//! the plane does not have:
//!
//! - the shear displacement `j` is a vector in the surface's tangent
//!   plane (its forward and left tangents, as a stiction deflection in
//!   space: [`SpaceContact`]), integrated from the point's slip there, and
//!   the shear stress `(c + p tan φ)(1 − e^{−|j|/K})` opposes it: soil
//!   sheared sideways in a turn resists the turn as soil sheared back
//!   resists the drive. Near `j = 0` the stress is `−(c + p tan φ) j / K`
//!   to first order, smooth through it.
//! - the rut is an area ([`RutGrid`]), so the tracks may turn and cross
//!   their own or the other's rut.
//!
//! Each point carries half the planar point's patch (the shoe's width by
//! its pitch over its ground points), and Bekker's width is the shoe's:
//! two points sinking alike press as the planar point does, so a
//! vehicle driven straight over level soil is its planar model's.
//!
//! What each point's memory and its displacement's start are, between
//! accepted steps ([`SoftSpace::press_point`]): as on the plane, a point
//! bearing on the soil carries its patch's memory and imprints it on the
//! rut as it deepens, and leaves it there when it lifts, over its
//! footprint: along the link its share of the shoe (as the planar
//! point's), across its half of the shoe. A point's shear
//! displacement is its state less the state it had when it last rose
//! above the undisturbed surface (its `origin`): the displacement since it
//! sank in, Wong's `j`, without the integrator's state being reset. A
//! link passed over as far above the ground ([`SoftSpace::passed_over`])
//! has its points' memory marked stale; a stale point found in the ground
//! at an evaluation reads the rut where it is.

use nalgebra::{Vector2, Vector3};

use super::ShoeGeometry;
use super::rut_grid::RutGrid;
use super::soft_ground::{DEFAULT_RUT_CELL, yielding};
use super::space::{SpaceContact, SpaceForce};
use crate::terrain::soil::{ShearLaw, Soil, SoilError, SoilMemory};

/// Soft soil under both tracks in space, and what it remembers.
#[derive(Debug, Clone, PartialEq)]
pub struct SoftSpace {
    soil: Soil,
    shear: ShearLaw,
    /// The track's width `b`, m (Bekker's).
    width: f64,
    /// Each side's (right, left) patch per point, m²: half the planar
    /// point's, `b p / n / 2` for pitch `p` and `n` ground points.
    patch_area: [f64; 2],
    /// What the ground remembers between contacts.
    pub rut: RutGrid,
    /// Each side's (right, left) share of the shoe per ground point along
    /// the link, in the shoe's order: its middle and length, m
    /// ([`ShoeGeometry::ground_shares`]).
    shares: [Vec<(f64, f64)>; 2],
    /// Each side's points (right, left): link by link, the shoe's points
    /// in order, each as two across the width.
    sides: [Vec<Patch>; 2],
}

/// The soil under one point, and where its shear displacement starts.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
struct Patch {
    memory: SoilMemory,
    /// Whether it bears on the soil.
    loaded: bool,
    /// Whether `memory` is out of date (the rut's where the point is
    /// holds).
    stale: bool,
    /// The shear state when the point last rose above the undisturbed
    /// surface, m.
    origin: Vector2<f64>,
}

impl SoftSpace {
    /// Soft ground of `soil` under tracks of `shoe`s (Bekker's width its
    /// declared `width`, its ground points) whose pitches are `pitches` m
    /// (right, left), with `links` links a side (right, left); rut cells
    /// of [`DEFAULT_RUT_CELL`]. The soil is checked, and a shoe with no
    /// width (or none above 0), or a pitch not above 0, is refused.
    pub fn new(
        soil: Soil,
        shoe: &ShoeGeometry,
        pitches: [f64; 2],
        links: [usize; 2],
    ) -> Result<SoftSpace, SoilError> {
        soil.check()?;
        let width = shoe.width.ok_or(SoilError::OutOfRange {
            name: "track width",
            value: f64::NAN,
            allowed: "declared with the shoe (its `width`)",
        })?;
        for (name, value) in [
            ("track width", width),
            ("right shoe length", pitches[0]),
            ("left shoe length", pitches[1]),
        ] {
            if !(value > 0.0 && value.is_finite()) {
                return Err(SoilError::OutOfRange {
                    name,
                    value,
                    allowed: "positive",
                });
            }
        }
        let points = shoe.ground_points.len();
        let fresh = Patch {
            stale: true,
            ..Patch::default()
        };
        Ok(SoftSpace {
            soil,
            shear: soil.shear_law(),
            width,
            patch_area: pitches.map(|p| 0.5 * width * p / points.max(1) as f64),
            shares: pitches.map(|p| shoe.ground_shares(p)),
            rut: RutGrid::new(DEFAULT_RUT_CELL),
            sides: links.map(|n| vec![fresh; 2 * points * n]),
        })
    }

    /// The memory the point `slot` of side `side` (0 right, 1 left)
    /// presses at `at`: its patch's, or the rut's there while the patch
    /// is stale.
    fn memory_at(&self, side: usize, slot: usize, at: Vector3<f64>) -> SoilMemory {
        let patch = &self.sides[side][slot];
        if patch.stale {
            self.rut.memory(at.xy())
        } else {
            patch.memory
        }
    }

    /// The soil's force at a point of side `side` found below the
    /// undisturbed surface, whose shear state is `state` (m, in the
    /// surface's forward and left tangents): the pressure on its patch
    /// (with damping) along the field's gradient and the shear against
    /// its displacement. Returns the force (`None` while the soil bears
    /// nothing there) and the state's rate, the slip in the tangent plane:
    /// below the surface the point shears the soil, bearing or not.
    #[inline]
    pub fn respond(
        &self,
        side: usize,
        slot: usize,
        contact: &SpaceContact,
        state: Vector2<f64>,
    ) -> (Option<SpaceForce>, Vector2<f64>) {
        let soil = &self.soil;
        let area = self.patch_area[side];
        let z = contact.depth;
        let memory = self.memory_at(side, slot, contact.point);
        let elastic = memory.pressure(soil, z, self.width);
        let rate = contact.rate();
        // Damping both ways while the soil bears, never pulling (the
        // planar law's).
        let damping = if elastic > 0.0 {
            (soil.damping * rate).max(-elastic)
        } else {
            0.0
        };
        let p = elastic + damping;
        let (norm, forward, left) = contact.surface();
        let slip = Vector2::new(contact.velocity.dot(&forward), contact.velocity.dot(&left));
        if p <= 0.0 {
            return (None, slip);
        }
        let j = state - self.sides[side][slot].origin;
        let magnitude = j.norm();
        let tangential = if magnitude > 0.0 {
            j * (-self.shear.stress(p, magnitude) * area / magnitude)
        } else {
            Vector2::zeros()
        };
        // Pressing fresh ground, the work goes into plastic flow but for
        // the elastic spring-back (the planar law's `B ż (1 − B′/K_e)`).
        let plastic = if yielding(z, memory.deepest(soil), rate) {
            elastic * (1.0 - soil.n * elastic / z / soil.unloading_stiffness)
        } else {
            0.0
        };
        let force = SpaceForce {
            force: contact.gradient * (p * area) + forward * tangential.x + left * tangential.y,
            normal: p * area * norm,
            rate: slip,
            potential: area * elastic * elastic / (2.0 * soil.unloading_stiffness),
            dissipation: ((p - elastic) + plastic) * rate * area - tangential.dot(&slip),
        };
        (Some(force), slip)
    }

    /// After an accepted step, the point `slot` of side `side` at `at`
    /// (m), sunk `z` m below the undisturbed surface (negative above it),
    /// its footprint centred at `half` (m, in the ground's plane: the
    /// middle of its share of the shoe along the link
    /// ([`share_middle`](Self::share_middle)), of its half of the shoe
    /// across), the shoe heading along the unit `forward` in that
    /// plane, its shear state `state`: what the ground remembers brought
    /// up to it (as the planar
    /// [`SoftGround::press`](super::soft_ground::SoftGround::press) does
    /// for its points). Returns whether the force at this state changed
    /// (a point that did not bear and now would, on the rut's memory where
    /// it is): then the integrator must restart.
    pub fn press_point(
        &mut self,
        (side, slot): (usize, usize),
        (at, z): (Vector3<f64>, f64),
        (half, forward): (Vector2<f64>, Vector2<f64>),
        state: Vector2<f64>,
    ) -> bool {
        let (soil, width) = (&self.soil, self.width);
        let footprint = self.footprint(side, slot);
        let patch = &mut self.sides[side][slot];
        if patch.stale {
            patch.memory = self.rut.memory(at.xy());
            patch.stale = false;
        }
        if patch.memory.pressure(soil, z, width) > 0.0 {
            let pressed = patch.memory.pressed_to(soil, z, width);
            patch.loaded = true;
            if pressed != patch.memory {
                patch.memory = pressed;
                self.rut.imprint(half, forward, footprint, pressed, soil);
            }
            return false;
        }
        if patch.loaded {
            patch.loaded = false;
            self.rut
                .imprint(half, forward, footprint, patch.memory, soil);
        }
        // Above the undisturbed surface the point has left the soil it
        // sheared: its displacement starts again from here.
        if z <= 0.0 {
            patch.origin = state;
        }
        let fresh = self.rut.memory(at.xy());
        patch.memory = fresh;
        fresh.pressure(soil, z, width) > 0.0
    }

    /// After an accepted step, the point `slot` of side `side` on a link
    /// passed over, above every ground under its track: it bears nothing
    /// and shears nothing (what it bore left in the rut under its
    /// footprint where it is now, `half` and `forward` as
    /// [`press_point`](Self::press_point) takes them), its displacement
    /// starts again from `state`, and its memory is read from the rut when
    /// it next meets the ground.
    pub fn passed_over(
        &mut self,
        (side, slot): (usize, usize),
        (half, forward): (Vector2<f64>, Vector2<f64>),
        state: Vector2<f64>,
    ) {
        let footprint = self.footprint(side, slot);
        let patch = &mut self.sides[side][slot];
        if patch.loaded {
            patch.loaded = false;
            self.rut
                .imprint(half, forward, footprint, patch.memory, &self.soil);
        }
        patch.origin = state;
        patch.stale = true;
    }

    /// The middle along the link's x (m) of the share of the shoe that
    /// side `side`'s ground point `point` (in the shoe's order) presses
    /// into the rut: where a caller centres its footprint along the link.
    pub fn share_middle(&self, side: usize, point: usize) -> f64 {
        self.shares[side][point].0
    }

    /// The footprint the point `slot` of side `side` leaves in the rut:
    /// its share of the shoe along the link and its half of the shoe
    /// across (from the middle to the edge), m.
    fn footprint(&self, side: usize, slot: usize) -> (f64, f64) {
        let shares = &self.shares[side];
        (shares[(slot / 2) % shares.len()].1, 0.5 * self.width)
    }
}
