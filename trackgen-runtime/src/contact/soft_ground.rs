//! Link-ground contact on soft soil: the shoes' ground points pressing a
//! deformable terrain (the laws of [`soil`](crate::terrain::soil)), which keeps
//! the rut they leave.
//!
//! Each ground point carries a patch of the shoe's ground face (its area
//! `patch_area`, m²). Under the undisturbed surface `y = h(x)` of the base
//! [`Terrain`] a point at height `y` is sunk by `z = h(x) − y`; the
//! pressure on its patch follows the ground's memory at `x`
//! ([`SoilMemory::pressure`]: Bekker beyond the deepest earlier sinkage,
//! elastic back from it), plus the damping `R ż`. The shear stress is
//! Janosi–Hanamoto's at that pressure and at the shear displacement `j`
//! the point has slipped over the soil since it sank into it (signed,
//! `j̇` = the slip velocity along the surface), opposing that
//! displacement: the shear is a function of how far the shoe has
//! sheared the soil, as in Wong's derivation (`j = i x`), not of the
//! instantaneous direction of slip. (Chrono's SCM grows `j` with the
//! slip's magnitude and opposes the instantaneous slip; under a tracked
//! vehicle the shoes rock as the road wheels roll over them, their ground
//! points' slip turning back and forth at a few cm/s about a mean of the
//! same size, and a shear that turns with it cancels itself: measured,
//! the M113 pulled a fifth of Wong's drawbar pull at 2 % slip.) Small
//! reversals are elastic: the shear work they do is given back, so the
//! work booked as dissipated can dip by that much; the shear's work is
//! dissipated as it is done when the shoe lifts.
//!
//! The memory is the patch under each ground point while the point bears
//! on the soil (a shoe on the ground stays over the soil it pressed, but
//! for its slip, so the patch moves with it), and a rut grid ([`Rut`]) of
//! cells `cell` metres long along x, interpolated linearly between cell
//! centres, between contacts: a point touching down takes up the rut's
//! memory where it lands, and leaves its patch in the rut when it lifts.
//! [`SoftGround::press`] brings both up to date after each accepted step
//! (the memory is history, not state: within a step it is fixed); a point
//! pressing its patch deeper sees the same pressure before and after, so
//! the force has no jump at the step.
//!
//! The ground's contacts are those [`ground`](super::ground) detection finds
//! below the undisturbed surface; [`SoftGround::respond`] is the soil's law
//! at each. [`VehicleSystem`](crate::vehicle::VehicleSystem) drives on it when
//! [`VehicleConfig::soil`](crate::vehicle::VehicleConfig::soil) is set:
//! the shear displacements are integrated states, and the rut is pressed
//! after every accepted step. Checked on its own in `tests/soft_ground.rs`
//! (forces against the laws, energy books along any motion, the rut) and
//! under vehicles in `tests/vehicle_soil.rs`.

use nalgebra::Vector2;

use super::tangent::{
    ForceTangent, GeometryTangent, PoseRow, PoseRows2, dot_rows, loads, unit_tangent, velocity,
};
use super::{BodyState, Contact, ContactForce, ContactJacobian, ShoeGeometry};
use crate::terrain::Terrain;
use crate::terrain::soil::{ShearLaw, Soil, SoilError, SoilMemory};

/// The plastic memory of the ground along x: a [`SoilMemory`] per cell of
/// `cell` m, fresh soil where nothing has pressed. The cells are one
/// contiguous run from the first to the last the track has pressed (a
/// lookup is an index, not a search), so memory grows with the distance
/// travelled: 16 bytes per cell, 0.8 MB per km at the default 2 cm.
#[derive(Debug, Clone, PartialEq)]
pub struct Rut {
    cell: f64,
    /// Index of `cells[0]`.
    first: i64,
    cells: Vec<SoilMemory>,
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
            first: 0,
            cells: Vec::new(),
        }
    }

    /// The cell length, m.
    pub fn cell(&self) -> f64 {
        self.cell
    }

    fn at(&self, i: i64) -> SoilMemory {
        usize::try_from(i.wrapping_sub(self.first))
            .ok()
            .and_then(|k| self.cells.get(k))
            .copied()
            .unwrap_or_default()
    }

    /// The memory at `x`, interpolated linearly between cell centres.
    pub fn memory(&self, x: f64) -> SoilMemory {
        self.memory_and_slope(x).0
    }

    /// [`memory`](Self::memory) and the slope of the plastic sinkage along
    /// x (the rut floor's `dz_p/dx`).
    pub fn memory_and_slope(&self, x: f64) -> (SoilMemory, f64) {
        let (memory, slope) = self.memory_and_slopes(x);
        (memory, slope.plastic)
    }

    /// [`memory`](Self::memory) and its derivative along x, both fields
    /// (per m): constant between cell centres.
    pub fn memory_and_slopes(&self, x: f64) -> (SoilMemory, SoilMemory) {
        let u = x / self.cell - 0.5;
        let i = u.floor();
        let w = u - i;
        let (a, b) = (self.at(i as i64), self.at(i as i64 + 1));
        (
            SoilMemory {
                plastic: a.plastic + w * (b.plastic - a.plastic),
                yield_pressure: a.yield_pressure + w * (b.yield_pressure - a.yield_pressure),
            },
            SoilMemory {
                plastic: (b.plastic - a.plastic) / self.cell,
                yield_pressure: (b.yield_pressure - a.yield_pressure) / self.cell,
            },
        )
    }

    /// Presses the ground at `x` to sinkage `z` (m) under a track of
    /// width `width` (m), over one cell; returns whether the memory
    /// changed.
    pub fn press(&mut self, soil: &Soil, x: f64, z: f64, width: f64) -> bool {
        let i = (x / self.cell).floor() as i64;
        let old = self.at(i);
        let new = old.pressed_to(soil, z, width);
        if new != old {
            *self.cell_mut(i) = new;
        }
        new != old
    }

    /// Leaves `memory` in the cells whose centres lie under a patch
    /// `length` m long centred at `x` (at least the cell holding `x`),
    /// where it is deeper than what they remember.
    pub fn imprint(&mut self, x: f64, length: f64, memory: SoilMemory, soil: &Soil) {
        let first = ((x - 0.5 * length) / self.cell - 0.5).ceil() as i64;
        let last = ((x + 0.5 * length) / self.cell - 0.5).floor() as i64;
        let held = (x / self.cell).floor() as i64;
        let (first, last) = (first.min(held), last.max(held));
        for i in first..=last {
            let cell = self.cell_mut(i);
            if memory.deepest(soil) > cell.deepest(soil) {
                *cell = memory;
            }
        }
    }

    /// The cell `i`, created fresh (with every cell between it and the
    /// others) if the track has not been there.
    fn cell_mut(&mut self, i: i64) -> &mut SoilMemory {
        if self.cells.is_empty() {
            self.first = i;
        } else if i < self.first {
            let grow = (self.first - i) as usize;
            self.cells
                .splice(0..0, std::iter::repeat_n(SoilMemory::default(), grow));
            self.first = i;
        }
        let k = (i - self.first) as usize;
        if k >= self.cells.len() {
            self.cells.resize(k + 1, SoilMemory::default());
        }
        &mut self.cells[k]
    }

    /// The plastic sinkage (m) along x, cell by cell, in order of x, over
    /// the cells the track has pressed: the rut's profile, for output.
    pub fn profile(&self) -> impl Iterator<Item = (f64, f64)> + '_ {
        self.cells
            .iter()
            .enumerate()
            .filter(|(_, m)| **m != SoilMemory::default())
            .map(|(k, m)| {
                (
                    (self.first + k as i64) as f64 * self.cell + 0.5 * self.cell,
                    m.plastic,
                )
            })
    }
}

/// Soft ground under the track: the soil, and what it remembers. Its
/// undisturbed surface is the vehicle's terrain, passed in.
#[derive(Debug, Clone, PartialEq)]
pub struct SoftGround {
    /// The soil.
    pub soil: Soil,
    /// Its shear laws, `tan φ` worked out once.
    shear: ShearLaw,
    /// The track's width `b`, m (Bekker's law needs it; the planar model
    /// does not otherwise see it).
    pub width: f64,
    /// The ground-face area each ground point carries, m² (the shoe's
    /// ground face over its number of ground points).
    pub patch_area: f64,
    /// What the ground remembers between contacts.
    pub rut: Rut,
    /// Each ground point's share of the shoe along the link: its middle
    /// and length, m ([`ShoeGeometry::ground_shares`]): where and how
    /// long a patch it leaves in the rut.
    shares: Vec<(f64, f64)>,
    /// What the ground under each shoe ground point remembers while the
    /// point bears on it (link by link, the shoe's points in order; empty
    /// until the first [`press`](Self::press)).
    patches: Vec<Patch>,
}

/// The soil under one shoe ground point: its memory, carried with the
/// point while it bears on the soil (a shoe on the ground stays over the
/// patch it pressed, but for its slip), and whether it bears.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
struct Patch {
    memory: SoilMemory,
    loaded: bool,
}

impl SoftGround {
    /// Soft ground of `soil` over `terrain` for a track `width` m wide
    /// whose shoes have ground faces `shoe_length` m long carried by the
    /// shoe's ground points;
    /// rut cells of [`DEFAULT_RUT_CELL`]. The soil is checked.
    pub fn new(
        soil: Soil,
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
            shear: soil.shear_law(),
            width,
            patch_area: width * shoe_length / shoe.ground_points.len().max(1) as f64,
            rut: Rut::new(DEFAULT_RUT_CELL),
            shares: shoe.ground_shares(shoe_length),
            patches: Vec::new(),
        })
    }

    /// The memory a point at `x` presses: its patch's while the patches
    /// are kept (from the first [`press`](Self::press) on), with no slope
    /// along x (it moves with the point); before that, the rut's,
    /// interpolated at `x`, with the slope of its floor.
    fn memory_at(&self, slot: usize, x: f64) -> (SoilMemory, f64) {
        match self.patches.get(slot) {
            Some(patch) => (patch.memory, 0.0),
            None => self.rut.memory_and_slope(x),
        }
    }

    /// At a point at `point` moving at `velocity` over ground remembering
    /// `memory` (whose plastic sinkage slopes by `floor_slope` along x):
    /// the pressure with damping and without (Pa), the sinkage `z` (m)
    /// and its rate (m/s), and the surface's gradient `g = (−h′, 1)`.
    fn state(
        &self,
        (z, slope): (f64, f64),
        velocity: Vector2<f64>,
        (memory, floor_slope): (SoilMemory, f64),
    ) -> (f64, f64, f64, Vector2<f64>) {
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
        // Damping both ways while the soil bears (SCM adds R·ż whatever
        // its sign), never pulling: lightly damped, shoes rock on the soil's
        // stiff elastic unloading.
        let damping = if elastic > 0.0 {
            (self.soil.damping * rate).max(-elastic)
        } else {
            0.0
        };
        (elastic + damping, elastic, rate, g)
    }

    /// The soil's force at a ground contact (found by
    /// [`ground::detect`](super::ground::detect) against the undisturbed
    /// surface): the pressure on the point's patch (with damping) along the
    /// surface's gradient, and the Janosi–Hanamoto shear at the point's
    /// shear displacement `shear` (m, signed along the surface's forward
    /// tangent), opposing it. Returns the force (`None` while the soil
    /// bears nothing there) and `j̇`, the slip velocity along the surface:
    /// below the surface the shoe shears the soil it sits in, bearing or
    /// not (between road wheels a shoe may rest lightly in its rut), as
    /// Wong's `j = i x` along the whole contact.
    #[inline]
    pub fn respond(
        &self,
        contact: &Contact,
        points: usize,
        shear: f64,
    ) -> (Option<ContactForce>, f64) {
        let slot = contact.link * points + contact.feature;
        let z = contact.depth;
        let memory = self.memory_at(slot, contact.point.x);
        let (p, elastic, rate, g) = self.state((z, -contact.gradient.x), contact.velocity, memory);
        let t = Vector2::new(g.y, -g.x) / g.norm();
        let slip = contact.velocity.dot(&t);
        if p <= 0.0 {
            return (None, slip);
        }
        // τ(|j|) against the displacement: 1 − e^{−|j|/K} ~ |j|/K near 0,
        // so `τ sign(j)` is smooth through j = 0.
        let tau = self.shear.stress(p, shear);
        let tangential = -tau * self.patch_area * shear.signum();
        let force = g * (p * self.patch_area) + t * tangential;
        // Pressing fresh ground (beyond the deepest sinkage), the work goes
        // into plastic flow except what the elastic spring-back `p²/(2 K_e)`
        // per unit area stores: with p = B(z) = k zⁿ, that is
        // B ż (1 − B′/K_e), B′ = n B / z.
        //
        // A point just pressed (its memory rebuilt from this very sinkage,
        // `z_p + p/K_e = z` to two roundings) and still moving deeper is
        // yielding too: without this, a method that evaluates the force
        // at the pressed state (the first stage after any restart, every
        // stage of a linearly implicit method's step) books no plastic work
        // there (measured: a Rosenbrock run on dry sand lost 13 % of the
        // dissipated work to it).
        let plastic = if yielding(z, memory.0.deepest(&self.soil), rate) {
            elastic * (1.0 - self.soil.n * elastic / z / self.soil.unloading_stiffness)
        } else {
            0.0
        };
        let force = ContactForce {
            point: contact.point,
            force,
            normal: p * self.patch_area * g.norm(),
            penetration: z,
            dissipation: ((p - elastic) + plastic) * rate * self.patch_area - tangential * slip,
            potential: self.patch_area * elastic * elastic / (2.0 * self.soil.unloading_stiffness),
        };
        (Some(force), slip)
    }

    /// After an accepted step: what the ground remembers, brought up to
    /// the links' positions.
    ///
    /// A point bearing on the soil presses its own patch to its sinkage
    /// (the pressure there is the same before and after: Bekker's at the
    /// new yield point) and imprints it on the rut; a point that no longer
    /// bears leaves its patch in the rut and takes up the rut's memory
    /// where it now is, for when it bears again; a point lifted above the
    /// undisturbed surface has its shear displacement reset. Returns whether the force at the links' state changed
    /// (an unloaded point whose new memory would make it bear): then the
    /// integrator must restart.
    pub fn press(
        &mut self,
        terrain: &Terrain,
        links: &[BodyState],
        shoe: &ShoeGeometry,
        shear: &mut [f64],
    ) -> bool {
        let points = shoe.ground_points.len();
        if self.patches.len() != links.len() * points {
            self.patches = links
                .iter()
                .flat_map(|l| shoe.ground_points.iter().map(|g| l.point(*g).x))
                .map(|x| Patch {
                    memory: self.rut.memory(x),
                    loaded: false,
                })
                .collect();
        }
        let mut changed = false;
        for (i, link) in links.iter().enumerate() {
            for (k, local) in shoe.ground_points.iter().enumerate() {
                let slot = i * points + k;
                let point = link.point(*local);
                let z = terrain.height(point.x) - point.y;
                // A patch is written over the point's share of the shoe.
                let (middle, length) = self.shares[k];
                let share = link.point(Vector2::new(middle, local.y)).x;
                let patch = &mut self.patches[slot];
                if patch.memory.pressure(&self.soil, z, self.width) > 0.0 {
                    let pressed = patch.memory.pressed_to(&self.soil, z, self.width);
                    patch.loaded = true;
                    if pressed != patch.memory {
                        patch.memory = pressed;
                        self.rut.imprint(share, length, pressed, &self.soil);
                    }
                    continue;
                }
                if patch.loaded {
                    patch.loaded = false;
                    self.rut.imprint(share, length, patch.memory, &self.soil);
                }
                // Lifted out of the soil (above the undisturbed surface),
                // the shoe has left the soil it sheared.
                if z <= 0.0 {
                    shear[slot] = 0.0;
                }
                let fresh = self.rut.memory(point.x);
                if fresh.pressure(&self.soil, z, self.width) > 0.0 {
                    changed = true;
                }
                self.patches[slot].memory = fresh;
            }
        }
        changed
    }
}

/// Whether a point at sinkage `z` (m) over ground whose deepest sinkage
/// was `deepest` (m), sinking at `rate` (m/s), presses the soil plastically:
/// beyond its deepest, or just pressed to it (`z_p + p/K_e = z` to two
/// roundings) and still moving deeper. [`SoftGround::respond`] books
/// plastic work by it and [`SoftGround::linearise`] takes its slope's side
/// by it.
pub(crate) fn yielding(z: f64, deepest: f64, rate: f64) -> bool {
    let at_yield = (z - deepest).abs() <= 4.0 * f64::EPSILON * deepest.abs();
    z > deepest || (at_yield && rate > 0.0)
}

/// The soil's law to first order: what the vehicle's exact Jacobian and
/// its linearly implicit integrator need of each soft-ground contact.
impl SoftGround {
    /// The first derivatives of [`respond`](Self::respond)'s load on the
    /// link and of the shear displacement's rate `j̇` over the contact's
    /// [`INPUTS`](ContactJacobian::INPUTS) (`j`, m, in column
    /// [`DEFLECTION`](ContactJacobian::DEFLECTION)), into `out`, given the
    /// geometry's derivatives ([`ground::tangent`](super::ground::tangent))
    /// and the link's state.
    ///
    /// The same formulas as `respond`, by the chain rule: the sinkage `z`
    /// and the point's `x` move with the pose (the rut's memory, before
    /// the patches are kept, with `x`: linear between cell centres, so its
    /// slope is constant there); `ż = −v·g`; the pressure `p = p_e + R ż`;
    /// the shear `−(c + p tan φ)(1 − e^{−|j|/K}) A sign j` along the
    /// surface's tangent, whose derivative in `j` is
    /// `−(c + p tan φ) A e^{−|j|/K}/K`, smooth through `j = 0`.
    ///
    /// A point just pressed sits at the deepest sinkage it reached, where
    /// the elastic pressure has a kink (Bekker's slope `n p/z` deeper,
    /// `K_e` back out): the slope is taken on the side the point moves
    /// toward, the side `respond` books its plastic work by.
    pub fn linearise(
        &self,
        contact: &Contact,
        points: usize,
        shear: f64,
        geometry: &GeometryTangent,
        link: &BodyState,
        out: &mut ContactJacobian,
    ) {
        let soil = &self.soil;
        let slot = contact.link * points + contact.feature;
        let (memory, along_x) = match self.patches.get(slot) {
            Some(patch) => (patch.memory, SoilMemory::default()),
            None => self.rut.memory_and_slopes(contact.point.x),
        };
        let (z, dz, dx) = (contact.depth, geometry.depth, geometry.point.row(0));
        let deepest = memory.deepest(soil);
        let fresh = z > deepest;
        // `g = (z_p′ − h′, 1)` reloading a rut (`state`'s wall), whose own
        // derivative is zero between cell centres.
        let wall = if fresh { 0.0 } else { along_x.plastic };
        let g = Vector2::new(wall + contact.gradient.x, 1.0);
        let dg = geometry.gradient;
        let v = contact.velocity;
        let dv = velocity(&geometry.point, link, None);
        let rate = -v.dot(&g);
        let d_rate = -(dot_rows(g, &dv) + dot_rows(v, &dg));
        let rate_by_v = -g.transpose();
        let loading = yielding(z, deepest, rate);
        let (elastic, d_elastic) = if fresh {
            let bekker = soil.bekker_pressure(z, self.width);
            (bekker, dz * (soil.n * bekker / z))
        } else {
            let elastic = soil.unloading_stiffness * (z - memory.plastic);
            if elastic <= 0.0 {
                (0.0, PoseRow::zeros())
            } else if loading {
                (elastic, dz * (soil.n * elastic / z))
            } else {
                (
                    elastic,
                    (dz - dx * along_x.plastic) * soil.unloading_stiffness,
                )
            }
        };
        let damped = soil.damping * rate;
        let bears = elastic > 0.0 && elastic + damped > 0.0;
        // The forward tangent `t = (g_y, −g_x)/|g| = −⟂g/|g|` and the
        // slip `j̇ = v·t`.
        let (_, back, d_back) = unit_tangent(g, &dg);
        let (t, d_t) = (-back, -d_back);
        let d_slip = dot_rows(t, &dv) + dot_rows(v, &d_t);
        let mut tangent = ForceTangent {
            force: Vector2::zeros(),
            by_pose: PoseRows2::zeros(),
            by_velocity: nalgebra::Matrix2::zeros(),
            by_deflection: Vector2::zeros(),
            rate_by_pose: d_slip,
            rate_by_velocity: t.transpose(),
            rate_by_deflection: 0.0,
        };
        if bears {
            let area = self.patch_area;
            let p = elastic + damped;
            let d_p = d_elastic + d_rate * soil.damping;
            let p_by_v = rate_by_v * soil.damping;
            let decay = (-shear.abs() / self.shear.shear_modulus).exp();
            let mobilised = -(-shear.abs() / self.shear.shear_modulus).exp_m1();
            let sign = shear.signum();
            let tangential = -self.shear.strength(p) * mobilised * area * sign;
            let tangential_by_p = -self.shear.tan_phi * mobilised * area * sign;
            let tangential_by_j = -self.shear.strength(p) * area * decay / self.shear.shear_modulus;
            tangent.force = g * (p * area) + t * tangential;
            tangent.by_pose =
                dg * (p * area) + g * (d_p * area) + d_t * tangential + t * (d_p * tangential_by_p);
            tangent.by_velocity = g * (p_by_v * area) + t * (p_by_v * tangential_by_p);
            tangent.by_deflection = t * tangential_by_j;
        }
        loads(contact, geometry, (link, None), &tangent, out);
    }
}
