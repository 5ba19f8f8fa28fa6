//! Link-ground contact on soft soil: the shoes' ground points pressing a
//! deformable terrain (the laws of [`soil`](super::soil)), which keeps
//! the rut they leave.
//!
//! Each ground point carries a patch of the shoe's ground face (its area
//! `patch_area`, m²). Under the undisturbed surface `y = h(x)` of the base
//! [`Terrain`] a point at height `y` is sunk by `z = h(x) − y`; the
//! pressure on its patch follows the ground's memory at `x`
//! ([`SoilMemory::pressure`]: Bekker beyond the deepest earlier sinkage,
//! elastic back from it), plus the damping `R ż` while pressing. The
//! shear stress is Janosi–Hanamoto's at that pressure and at the shear
//! displacement `j` the point has accumulated while on the ground,
//! opposing the slip (as Chrono's SCM: `j` grows with the slip's
//! magnitude, so the shear always dissipates; the direction is regularised
//! over `slip_speed` so that it turns smoothly through zero slip).
//!
//! The memory is a rut grid ([`Rut`]) of cells `cell` metres long along x,
//! interpolated linearly between cell centres so the force is continuous
//! as a point moves; [`SoftGround::press`] writes the sinkage of every
//! point into it after each accepted step (the memory is history, not
//! state: within a step it is fixed).
//!
//! [`VehicleSystem`](crate::vehicle::VehicleSystem) does not use it yet:
//! it drives on rigid terrain only. This pair is checked on its own
//! (`tests/soft_ground.rs`: forces against the laws, energy books along
//! any motion, the rut).

use std::collections::BTreeMap;

use nalgebra::Vector2;

use super::soil::{Soil, SoilError, SoilMemory};
use super::{BodyState, ContactForce, ShoeGeometry, Terrain};
use crate::model::BodyLoad;

/// The plastic memory of the ground along x: a [`SoilMemory`] per cell of
/// `cell` m, fresh soil where nothing has pressed. Cells are stored only
/// where the track has been, so memory grows with the distance travelled
/// (16 bytes per cell: 0.8 MB per km at the default 2 cm).
#[derive(Debug, Clone, PartialEq)]
pub struct Rut {
    cell: f64,
    cells: BTreeMap<i64, SoilMemory>,
}

/// Default rut cell, m: a sixth of the M113's 0.12 m ground-point spacing,
/// so the rut resolves the shoe's footprint, and small against the
/// sinkages of interest (cm).
pub const DEFAULT_RUT_CELL: f64 = 0.02;

impl Rut {
    /// Fresh ground, remembered in cells of `cell` m.
    pub fn new(cell: f64) -> Rut {
        Rut {
            cell,
            cells: BTreeMap::new(),
        }
    }

    /// The cell length, m.
    pub fn cell(&self) -> f64 {
        self.cell
    }

    fn at(&self, i: i64) -> SoilMemory {
        self.cells.get(&i).copied().unwrap_or_default()
    }

    /// The memory at `x`, interpolated linearly between cell centres.
    pub fn memory(&self, x: f64) -> SoilMemory {
        self.memory_and_slope(x).0
    }

    /// [`memory`](Self::memory) and the slope of the plastic sinkage along
    /// x (the rut floor's `dz_p/dx`).
    pub fn memory_and_slope(&self, x: f64) -> (SoilMemory, f64) {
        let u = x / self.cell - 0.5;
        let i = u.floor();
        let w = u - i;
        let (a, b) = (self.at(i as i64), self.at(i as i64 + 1));
        (
            SoilMemory {
                plastic: a.plastic + w * (b.plastic - a.plastic),
                yield_pressure: a.yield_pressure + w * (b.yield_pressure - a.yield_pressure),
            },
            (b.plastic - a.plastic) / self.cell,
        )
    }

    /// Presses the cell holding `x` to sinkage `z` (m) under a track of
    /// width `width` (m); returns whether the memory changed.
    pub fn press(&mut self, soil: &Soil, x: f64, z: f64, width: f64) -> bool {
        let i = (x / self.cell).floor() as i64;
        let old = self.at(i);
        let new = old.pressed_to(soil, z, width);
        if new != old {
            self.cells.insert(i, new);
        }
        new != old
    }

    /// The plastic sinkage (m) along x, cell by cell, in order of x: the
    /// rut's profile, for output.
    pub fn profile(&self) -> impl Iterator<Item = (f64, f64)> + '_ {
        self.cells
            .iter()
            .map(|(i, m)| ((*i as f64 + 0.5) * self.cell, m.plastic))
    }
}

/// Soft ground under the track.
#[derive(Debug, Clone, PartialEq)]
pub struct SoftGround {
    /// The soil.
    pub soil: Soil,
    /// The undisturbed surface.
    pub terrain: Terrain,
    /// The track's width `b`, m (Bekker's law needs it; the planar model
    /// does not otherwise see it).
    pub width: f64,
    /// The ground-face area each ground point carries, m² (the shoe's
    /// ground face over its number of ground points).
    pub patch_area: f64,
    /// Slip speed over which the shear's direction turns, m/s.
    pub slip_speed: f64,
    /// What the ground remembers.
    pub rut: Rut,
}

impl SoftGround {
    /// Soft ground of `soil` over `terrain` for a track `width` m wide
    /// whose shoes have ground faces `shoe_length` m long carried by the
    /// shoe's ground points; direction of shear regularised over 0.05 m/s;
    /// rut cells of [`DEFAULT_RUT_CELL`]. The soil is checked.
    pub fn new(
        soil: Soil,
        terrain: Terrain,
        width: f64,
        shoe_length: f64,
        shoe: &ShoeGeometry,
    ) -> Result<SoftGround, SoilError> {
        soil.check()?;
        for (name, value) in [("track width", width), ("shoe length", shoe_length)] {
            if !(value > 0.0 && value.is_finite()) {
                return Err(SoilError::OutOfRange {
                    name,
                    value,
                    allowed: "positive",
                });
            }
        }
        Ok(SoftGround {
            soil,
            terrain,
            width,
            patch_area: width * shoe_length / shoe.ground_points.len().max(1) as f64,
            slip_speed: 0.05,
            rut: Rut::new(DEFAULT_RUT_CELL),
        })
    }

    /// At a point at `point` moving at `velocity`: the pressure with
    /// damping and without (Pa), the sinkage `z` (m) and its rate (m/s),
    /// the memory there, and the surface's gradient `g = (−h′, 1)`.
    fn state(
        &self,
        point: Vector2<f64>,
        velocity: Vector2<f64>,
    ) -> (f64, f64, f64, f64, SoilMemory, Vector2<f64>) {
        let (h, slope) = self.terrain.height_and_slope(point.x);
        let z = h - point.y;
        let (memory, floor_slope) = self.rut.memory_and_slope(point.x);
        let elastic = memory.pressure(&self.soil, z, self.width);
        // Reloading a rut, the stored energy `A K_e (z − z_p(x))²/2` also
        // changes along x where the rut's floor slopes: its gradient adds
        // a push `p z_p′` along x (the rut's wall resisting the shoe that
        // climbs out of it). Pressing fresh ground, the pressure does not
        // depend on the memory.
        let wall = if z > memory.deepest(&self.soil) {
            0.0
        } else {
            floor_slope
        };
        let g = Vector2::new(wall - slope, 1.0);
        // ż = −v·g, exact over any profile (as on rigid ground), so the
        // force `g p A` is the gradient of the stored energy.
        let rate = -velocity.dot(&g);
        let damping = if elastic > 0.0 {
            self.soil.damping * rate.max(0.0)
        } else {
            0.0
        };
        (elastic + damping, elastic, z, rate, memory, g)
    }

    /// Forces on the links from the soil, added to `loads` (one per link).
    /// `shear` holds each ground point's shear displacement `j` (m; link
    /// by link, the shoe's points in order), `shear_rate` receives `ż`
    /// of each: the slip speed while the point is loaded, 0 otherwise.
    /// Every loaded point is passed to `each`.
    pub fn apply(
        &self,
        links: &[BodyState],
        shoe: &ShoeGeometry,
        loads: &mut [BodyLoad],
        shear: &[f64],
        shear_rate: &mut [f64],
        mut each: impl FnMut(usize, &ContactForce),
    ) {
        let points = shoe.ground_points.len();
        for (i, link) in links.iter().enumerate() {
            for (k, local) in shoe.ground_points.iter().enumerate() {
                let slot = i * points + k;
                shear_rate[slot] = 0.0;
                let arm = link.arm(*local);
                let point = link.position + arm;
                let velocity = link.velocity_at(arm);
                let (p, elastic, z, rate, memory, g) = self.state(point, velocity);
                if p <= 0.0 {
                    continue;
                }
                let t = Vector2::new(g.y, -g.x) / g.norm();
                let slip = velocity.dot(&t);
                let direction = slip / slip.hypot(self.slip_speed);
                let tau = self.soil.shear_stress(p, shear[slot]);
                let tangential = -tau * self.patch_area * direction;
                let force = g * (p * self.patch_area) + t * tangential;
                shear_rate[slot] = slip.abs();
                loads[i] = loads[i].plus(BodyLoad::force_at(force, arm));
                // Pressing fresh ground (beyond the deepest sinkage), the
                // work goes into plastic flow except what the elastic
                // spring-back `p²/(2 K_e)` per unit area stores: with
                // p = B(z) = k zⁿ, that is B ż (1 − B′/K_e), B′ = n B / z.
                let plastic = if z > memory.deepest(&self.soil) {
                    elastic * (1.0 - self.soil.n * elastic / z / self.soil.unloading_stiffness)
                } else {
                    0.0
                };
                each(
                    i,
                    &ContactForce {
                        point,
                        force,
                        normal: p * self.patch_area * g.norm(),
                        penetration: z,
                        dissipation: ((p - elastic) + plastic) * rate * self.patch_area
                            - tangential * slip,
                        potential: self.patch_area * elastic * elastic
                            / (2.0 * self.soil.unloading_stiffness),
                    },
                );
            }
        }
    }

    /// After an accepted step: presses the rut wherever a point has sunk
    /// deeper than the ground remembers, and resets the shear displacement
    /// of every point that has left the ground. Returns whether anything
    /// changed (the integrator must then restart).
    pub fn press(&mut self, links: &[BodyState], shoe: &ShoeGeometry, shear: &mut [f64]) -> bool {
        let points = shoe.ground_points.len();
        let mut changed = false;
        for (i, link) in links.iter().enumerate() {
            for (k, local) in shoe.ground_points.iter().enumerate() {
                let point = link.point(*local);
                let z = self.terrain.height(point.x) - point.y;
                let loaded = self.rut.memory(point.x).pressure(&self.soil, z, self.width) > 0.0;
                if loaded {
                    changed |= self.rut.press(&self.soil, point.x, z, self.width);
                } else if shear[i * points + k] != 0.0 {
                    shear[i * points + k] = 0.0;
                    changed = true;
                }
            }
        }
        changed
    }
}
