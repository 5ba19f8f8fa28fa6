//! A declared spatial vehicle as one system the applications drive
//! without naming its trees' sizes: the declaration's `tracks` block
//! implements [`SpatialVehicleSystem`] (its `Spatial` the concrete
//! [`SpatialSystem`]), and every [`SpatialSystem`] is a
//! [`SpatialSimulated`]: assembled on a course, driven and steered, read
//! out.

use nalgebra::{DVector, SVector, Vector2, Vector3};

use super::{
    Driveline, DrivelineError, EngineEnvelope, GroundForce, HeadingHold, SideBooks, SideDrives,
    SpatialEnergy, SpatialLaws, SpatialOutputs, SpatialScene, SpatialSystem, SteeringError,
    TreeState,
};
use crate::assembly::{SideError, assemble_on_grounds};
use crate::contact::axial::GuideLaw;
use crate::contact::rut_grid::RutPatch;
use crate::integrate::{OdeSystem, SimulationError};
use crate::multibody::{ChassisModel, TrackModel};
use crate::spatial::{PlanePose, PlaneRates, SpatialError, SpatialVehicle};
use crate::terrain::Terrain;
use crate::terrain::field::HeightField;
use crate::vehicle::DrawbarError;
use crate::vehicle::{Drive, Vehicle};

/// The gap the assembly leaves between the lower track and the ground, m
/// (the planar main job's).
const CLEARANCE: f64 = 1e-3;

/// A spatial vehicle in time, whatever its trees' sizes.
pub trait SpatialSimulated: OdeSystem + Send {
    /// The vehicle assembled on `terrain` (extruded across the vehicle),
    /// heading along `x` with its hull's centroid over `x = 0`, its
    /// tracks 1 mm above the ground at their lowest, at rest, nothing
    /// dissipated or driven yet; each tensioner's spring set where the
    /// assembly put its arm ([`SpatialDynamics::set_tensioners`](super::SpatialDynamics::set_tensioners)).
    fn assembled(&mut self, terrain: &Terrain) -> Result<DVector<f64>, SideError> {
        self.assembled_on((terrain, terrain))
    }

    /// [`assembled`](Self::assembled) with each track on its own ground
    /// (`grounds`: the profile under the right track, under the left):
    /// the hull lowered until the first track is 1 mm above its ground,
    /// the other resting as its wheels put it.
    fn assembled_on(&mut self, grounds: (&Terrain, &Terrain)) -> Result<DVector<f64>, SideError>;

    /// The state `y` of the vehicle at rest heading along `x` set on a
    /// side slope turned `roll` rad about `x` ([`SpatialSystem::rolled`]).
    fn rolled(&self, y: &[f64], roll: f64) -> DVector<f64>;

    /// Drives the sprockets by `drives` from now on; settings that make
    /// no controller are refused.
    fn set_drives(&mut self, drives: SideDrives) -> Result<(), DrivelineError>;

    /// Drives the sprockets through `driveline` from now on
    /// ([`SpatialSystem::with_driveline`]).
    fn set_driveline(&mut self, driveline: Driveline) -> Result<(), DrivelineError>;

    /// Steers by `hold` from now on (a drive on each side must be a speed
    /// drive).
    fn set_steering(&mut self, hold: HeadingHold) -> Result<(), SteeringError>;

    /// Caps the drive by an engine's full-load `envelope` from now on
    /// (`None`: no cap; [`SpatialSystem::with_envelope`]).
    fn set_envelope(&mut self, envelope: Option<EngineEnvelope>);

    /// Pulls the hull back by a drawbar load of `pull` N from now on
    /// ([`SpatialSystem::with_drawbar_pull`]); a pull that is not a
    /// number is refused.
    fn set_drawbar_pull(&mut self, pull: f64) -> Result<(), DrawbarError>;

    /// The ruts pressed so far, for a picture
    /// ([`SpatialDynamics::rut_patches`](super::SpatialDynamics::rut_patches));
    /// none on rigid ground.
    fn rut_patches(&self, cells: usize) -> Vec<RutPatch>;

    /// The engine driving the differential, its speed a state, if one
    /// does ([`SpatialSystem::engine`]).
    fn engine(&self) -> Option<&super::SpatialEngine>;

    /// `y` with the differential's engine (if its speed is a state) at
    /// its idle speed ([`SpatialSystem::start_engine`]).
    fn start_engine(&self, y: &mut [f64]);

    /// After an accepted step to `(t, y)`: the engine's gearbox shifted
    /// and its clutch locked where their rules say; whether the
    /// integrator must restart ([`SpatialSystem::after_step`]).
    fn after_step(&mut self, t: f64, y: &[f64]) -> bool;

    /// The sprockets' rolling radius, m: the mean of the two sides' (NaN
    /// without sprockets).
    fn rolling_radius(&self) -> f64;

    /// What the vehicle shows at `t` and `y` ([`SpatialSystem::outputs`]).
    fn outputs(&self, t: f64, y: &[f64]) -> Result<SpatialOutputs, SimulationError>;

    /// The vehicle drawn at `t` and `y`, its hull by `outline`
    /// ([`SpatialSystem::scene`]).
    fn scene(&self, t: f64, y: &[f64], outline: &[Vector2<f64>]) -> SpatialScene;

    /// Where its energy is at `y` ([`SpatialSystem::energy`]).
    fn energy(&self, y: &[f64]) -> SpatialEnergy;

    /// Each side's books at `y`, right then left
    /// ([`SpatialSystem::side_books`]).
    fn side_books(&self, y: &[f64]) -> [SideBooks; 2];

    /// What the ground gives each of the tracks' ground points at `y`
    /// ([`SpatialSystem::ground_forces`]).
    fn ground_forces(&self, y: &[f64]) -> Vec<GroundForce>;

    /// How many of the state's values, from the first, have dynamics: the
    /// trees, the ground's deflections and the driveline's states; not
    /// the books (the energy dissipated, the drive's work) after them.
    fn dynamic_states(&self) -> usize;

    /// Where the hull's root body's six rates sit in the state: along its
    /// plane and up it (m/s), its pitch rate, its rate across the plane
    /// (m/s), its roll and its yaw rate (rad/s), in that order
    /// ([`HULL_MOTIONS`]).
    fn hull_rates(&self) -> [usize; 6];

    /// `y` with every tree's rates set to zero (the ground's deflections,
    /// the driveline's states and the books kept).
    fn stilled(&self, y: &[f64]) -> DVector<f64>;
}

/// The hull's six motions, as [`SpatialSimulated::hull_rates`] orders
/// their rates.
pub const HULL_MOTIONS: [&str; 6] = [
    "hull surge",
    "hull bounce",
    "hull pitch",
    "hull sway",
    "hull roll",
    "hull yaw",
];

/// A tree standing upright at yaw 0 with its planar coordinates `q` (its
/// root's place in the plane moved into the pose's origin, `lateral` m
/// along `y`), at rest.
fn upright<const D: usize>(q: &SVector<f64, D>, lateral: f64) -> TreeState<D> {
    let mut planar = *q;
    (planar[0], planar[1]) = (0.0, 0.0);
    TreeState {
        pose: PlanePose {
            origin: Vector3::new(q[0], lateral, q[1]),
            yaw: 0.0,
            roll: 0.0,
            planar,
        },
        rates: PlaneRates {
            planar: SVector::zeros(),
            across: Vector3::zeros(),
        },
    }
}

impl<H, const DH: usize, R, const DR: usize, L, const DL: usize> SpatialSimulated
    for SpatialSystem<'static, H, DH, R, DR, L, DL>
where
    H: ChassisModel<DH> + Sync,
    R: TrackModel<DR> + Sync,
    L: TrackModel<DL> + Sync,
{
    fn assembled_on(&mut self, grounds: (&Terrain, &Terrain)) -> Result<DVector<f64>, SideError> {
        let d = &self.dynamics;
        let sides = assemble_on_grounds(
            d.hull.model(),
            (d.right.model(), d.left.model()),
            &d.sides,
            (&d.shoe, &d.profile),
            grounds,
            0.0,
            CLEARANCE,
        )?;
        let half = d.gauge / 2.0;
        self.dynamics.set_tensioners(sides.tensioners);
        Ok(self.state(
            &upright(&sides.hull, 0.0),
            &upright(&sides.right, -half),
            &upright(&sides.left, half),
        ))
    }

    fn set_drives(&mut self, drives: SideDrives) -> Result<(), DrivelineError> {
        self.set_driveline(Driveline::Sides(drives))
    }

    fn set_driveline(&mut self, driveline: Driveline) -> Result<(), DrivelineError> {
        SpatialSystem::set_driveline(self, driveline)
    }

    fn set_steering(&mut self, hold: HeadingHold) -> Result<(), SteeringError> {
        self.check_steering(&hold)?;
        self.steering = Some(hold);
        Ok(())
    }

    fn set_envelope(&mut self, envelope: Option<EngineEnvelope>) {
        self.envelope = envelope;
    }

    fn set_drawbar_pull(&mut self, pull: f64) -> Result<(), DrawbarError> {
        SpatialSystem::set_drawbar_pull(self, pull)
    }

    fn rut_patches(&self, cells: usize) -> Vec<RutPatch> {
        self.dynamics.rut_patches(cells)
    }

    fn rolled(&self, y: &[f64], roll: f64) -> DVector<f64> {
        SpatialSystem::rolled(self, y, roll)
    }

    fn engine(&self) -> Option<&super::SpatialEngine> {
        SpatialSystem::engine(self)
    }

    fn start_engine(&self, y: &mut [f64]) {
        SpatialSystem::start_engine(self, y)
    }

    fn after_step(&mut self, t: f64, y: &[f64]) -> bool {
        SpatialSystem::after_step(self, t, y)
    }

    fn rolling_radius(&self) -> f64 {
        self.dynamics.mean_rolling_radius()
    }

    fn outputs(&self, t: f64, y: &[f64]) -> Result<SpatialOutputs, SimulationError> {
        SpatialSystem::outputs(self, t, y)
    }

    fn scene(&self, t: f64, y: &[f64], outline: &[Vector2<f64>]) -> SpatialScene {
        SpatialSystem::scene(self, t, y, outline)
    }

    fn energy(&self, y: &[f64]) -> SpatialEnergy {
        SpatialSystem::energy(self, y)
    }

    fn side_books(&self, y: &[f64]) -> [SideBooks; 2] {
        SpatialSystem::side_books(self, y)
    }

    fn ground_forces(&self, y: &[f64]) -> Vec<GroundForce> {
        SpatialSystem::ground_forces(self, y)
    }

    fn dynamic_states(&self) -> usize {
        // The engine's speed and twist follow the drive's own states.
        use super::driveline::{DRIVELINE, ENGINE_SPEED};
        self.driveline_at()
            + if self.engine().is_some() {
                DRIVELINE
            } else {
                ENGINE_SPEED
            }
    }

    fn hull_rates(&self) -> [usize; 6] {
        // A tree's planar rates start at `D + 3` (`v_ξ`, `v_ζ`, the root's
        // angle's), its rates across at `2 D + 3` (`v_η`, `ω_ξ`, `ω_ζ`).
        let (planar, across) = (DH + 3, 2 * DH + 3);
        [
            planar,
            planar + 1,
            planar + 2,
            across,
            across + 1,
            across + 2,
        ]
    }

    fn stilled(&self, y: &[f64]) -> DVector<f64> {
        let mut still = DVector::from_column_slice(y);
        let mut start = 0;
        for d in [DH, DR, DL] {
            still.as_mut_slice()[start + d + 3..start + 2 * d + 6].fill(0.0);
            start += 2 * d + 6;
        }
        still
    }
}

/// A vehicle declared with a `tracks` block as a system in time: the
/// macro implements it with the concrete [`SpatialSystem`] of the
/// vehicle's hull and tracks.
pub trait SpatialVehicleSystem: SpatialVehicle + Vehicle {
    /// The vehicle's spatial system.
    type Spatial: SpatialSimulated;

    /// The vehicle under `laws` on `field`, its sprockets free; laws out
    /// of range are refused ([`SpatialLaws::check`]).
    fn spatial(laws: SpatialLaws, field: HeightField) -> Result<Self::Spatial, SpatialError>;

    /// The declared laws: the declaration's ground, rims and teeth (its
    /// `contact` block, or the fitted defaults), the centre guides at the
    /// declared play with [`GuideLaw::with_play`]'s stiffness, damping
    /// and height.
    fn declared_laws() -> SpatialLaws {
        let config = Self::declared_config(Terrain::Flat { height: 0.0 }, Drive::Free);
        SpatialLaws {
            ground: config.ground,
            wheels: config.wheels,
            sprocket: config.sprocket,
            guide: GuideLaw::with_play(Self::layout().guide_play),
            soil: config.soil,
        }
    }
}
