//! A declared vehicle as a type ([`Vehicle`]), what any of them offers in
//! motion whatever its coordinate counts ([`VehicleDynamics`]), and the one
//! recipe that builds any of them ([`build`]).

use nalgebra::{DVector, Vector2};

use super::{BuildError, Drive, Geometry, Powertrain, StateLayout, VehicleConfig};
use crate::contact::soft_ground::Rut;
use crate::integrate::SimulationError;
use crate::multibody::{ChassisPart, TreeDescription};
use crate::system::Simulated;
use crate::terrain::Terrain;

/// A vehicle declared with `trackgen::model!`: its compiled track and
/// chassis, their coordinate counts, its contact geometry and declared
/// configuration. Generated for every `vehicle` with a `shoe`; a vehicle
/// is then one call away ([`system`](Self::system)), and code written for
/// any `V: Vehicle` runs every declared vehicle.
///
/// ```ignore
/// use trackgen::Vehicle;
/// let mut vehicle = M113::system(Terrain::Flat { height: 0.0 }, M113::speed_drive(|_| 2.0))?;
/// ```
pub trait Vehicle: Copy + Default + Send + Sync + 'static {
    /// The name declared.
    const NAME: &'static str;
    /// Track coordinates `q_i` (links + 2).
    const TRACK_DOF: usize;
    /// Chassis coordinates `q_i` (bodies + 2).
    const CHASSIS_DOF: usize;
    /// The compiled track (`NameTrack`, a
    /// [`TrackModel<TRACK_DOF>`](crate::multibody::TrackModel)).
    type Track: Copy + Default + Send + Sync + 'static;
    /// The compiled chassis (`NameChassis`, a
    /// [`ChassisModel<CHASSIS_DOF>`](crate::multibody::ChassisModel)).
    type Chassis: Copy + Default + Send + Sync + 'static;
    /// The vehicle in motion (`NameSystem`).
    type System: VehicleDynamics;

    /// The contact geometry as declared.
    fn geometry() -> Geometry;

    /// The declared contact laws, friction and arm springs on `terrain`,
    /// driven by `drive`: every field public, to change before
    /// [`system_with`](Self::system_with) (no rebuild needed).
    fn declared_config(terrain: Terrain, drive: Drive) -> VehicleConfig;

    /// A PI speed drive with the declared gains and torque limit: `target`
    /// is the forward speed wanted, m/s, against time, s.
    fn speed_drive(target: impl Fn(f64) -> f64 + Send + 'static) -> Drive;

    /// The declared powertrain (`powertrain { … }` in the declaration: an
    /// engine through a torque converter, a range gearbox and a final
    /// drive, [`Powertrain::Converter`]), as this side's sprocket sees it;
    /// `None` where none is declared. A run drives through it when it is
    /// set as [`VehicleConfig::powertrain`].
    fn powertrain() -> Option<Powertrain> {
        None
    }

    /// The vehicle assembled on `terrain` with its
    /// [`declared_config`](Self::declared_config) and `drive`: [`build`]
    /// of that.
    fn system(terrain: Terrain, drive: Drive) -> Result<Self::System, BuildError> {
        build::<Self>(Self::declared_config(terrain, drive))
    }

    /// The vehicle assembled with `config`: [`build`].
    fn system_with(config: VehicleConfig) -> Result<Self::System, BuildError> {
        build::<Self>(config)
    }
}

/// Builds any declared vehicle from a configuration, the one recipe: the
/// configuration checked against the compiled model, the track wrapped
/// round the wheels on `config`'s terrain (chassis centroid at x = 0,
/// shoes 1 mm above the ground, [`assemble`](crate::assembly::assemble)),
/// the tensioner's spring rest angle moved to where the assembly set its
/// arm (a track adjuster's job: the tensioner then pushes with its declared
/// preload), the loop closed by `config.closure`. Ready for
/// [`simulate`](crate::simulate::simulate).
///
/// [`BuildError::Assembly`] when no start fits, [`BuildError::Config`] for
/// a configuration that makes no vehicle.
pub fn build<V: Vehicle>(config: VehicleConfig) -> Result<V::System, BuildError> {
    <V::System as sealed::Build>::build_from(V::geometry(), config)
}

/// [`build`]'s work, which only the runtime's own systems do: a public
/// trait in a private module, so [`VehicleDynamics`] is implemented here
/// and nowhere else.
pub(crate) mod sealed {
    use super::{BuildError, Geometry, VehicleConfig};

    /// Assembling a system of this type from a vehicle's geometry and a
    /// configuration.
    pub trait Build: Sized {
        /// The system assembled on `config`'s terrain (see
        /// [`build`](super::build)).
        fn build_from(geometry: Geometry, config: VehicleConfig) -> Result<Self, BuildError>;
    }
}

/// A vehicle in motion, whatever its coordinate counts: what generic code
/// over [`Vehicle`] needs of [`V::System`](Vehicle::System) besides
/// simulating it. Implemented by
/// [`VehicleSystem`](super::VehicleSystem) for every track and chassis.
///
/// Sealed: implemented by the runtime's [`VehicleSystem`](super::VehicleSystem)
/// alone, which [`build`] makes.
pub trait VehicleDynamics: Simulated + Send + Sized + sealed::Build {
    /// The configuration it runs with.
    fn config(&self) -> &VehicleConfig;

    /// Its contact geometry.
    fn geometry(&self) -> &Geometry;

    /// The sprocket's pitch radius, m: where the seated joints lie,
    /// `p / (2 sin(π/N))` (0 without a sprocket).
    fn sprocket_pitch_radius(&self) -> f64;

    /// The sprocket's rolling radius, m: the track's mean speed per unit
    /// of sprocket speed, `N p / (2π)`
    /// ([`track_speed`](crate::contact::sprocket::track_speed); 0 without a
    /// sprocket).
    fn sprocket_rolling_radius(&self) -> f64;

    /// The soft soil's memory, if the vehicle drives on soil: the rut it
    /// has left so far.
    fn rut(&self) -> Option<&Rut>;

    /// The arms' torsion springs and dampers it runs with (its
    /// configuration's [`arms`](VehicleConfig::arms)), to change between
    /// runs without rebuilding, or for a
    /// [sensitivity](crate::analysis::equilibrium_sensitivity).
    fn arms_mut(&mut self) -> &mut [crate::multibody::ArmSpring];

    /// Sets the drawbar load (its configuration's
    /// [`drawbar_pull`](VehicleConfig::drawbar_pull), N) from now on: for a
    /// master driving the vehicle between steps (an FMU's input). A value
    /// that is not finite is refused and the load kept.
    fn set_drawbar_pull(&mut self, pull: f64) -> Result<(), super::ConfigError>;

    /// Where each quantity sits in the state.
    fn layout(&self) -> StateLayout;

    /// The full coordinates at the state `y`: the track's `q_i` (its loop
    /// closure recovered under partitioning) and the chassis' `q_i`.
    fn coordinates(
        &mut self,
        t: f64,
        y: &[f64],
    ) -> Result<(DVector<f64>, DVector<f64>), SimulationError>;

    /// Whether the ground holds the shoes with stiction (rigid ground,
    /// [`GroundFriction::Stiction`](crate::contact::GroundFriction::Stiction)):
    /// its tangential states are then the stiction deflections.
    fn holds_by_stiction(&self) -> bool;

    /// What each ground point can hold by stiction at `y`, one per
    /// tangential state (link by link): `None` off the ground, else the
    /// largest deflection it keeps at rest, `μ F_n / k` in the tangential
    /// states' unit (beyond it the point slides). Empty without stiction.
    fn stiction_limits(&mut self, t: f64, y: &[f64]) -> Result<Vec<Option<f64>>, SimulationError>;

    /// The ground's normal load on the track at `y`: every point where a
    /// shoe touches the ground (its ground points and the terrain's
    /// corners in its outline), as (the point, global frame, m; the normal
    /// force, N), link by link. The loads a steering estimate spreads
    /// under the run ([`steering`](crate::steering)).
    fn ground_loads(
        &mut self,
        t: f64,
        y: &[f64],
    ) -> Result<Vec<(Vector2<f64>, f64)>, SimulationError>;

    /// Starts the vehicle from `y` (an [equilibrium](crate::analysis::equilibrium),
    /// say) instead of the assembled state: [`SimulationError::StateLength`]
    /// for a state of the wrong length, [`SimulationError::NonFinite`] for
    /// one that is not finite.
    fn set_start(&mut self, y: &[f64]) -> Result<(), SimulationError>;

    /// The parts pinned to the chassis, as declared.
    fn parts() -> &'static [ChassisPart];

    /// The hull's outline in the chassis frame, m, as declared (`hull:
    /// [(x, y), …]`); empty for a vehicle that declares none.
    fn hull() -> &'static [[f64; 2]];

    /// The track's description (masses and joints).
    fn track_description() -> TreeDescription;

    /// The chassis' description.
    fn chassis_description() -> TreeDescription;

    /// Track coordinates (`q_i`, links + 2).
    fn track_dof() -> usize;

    /// Chassis coordinates (`q_i`, bodies + 2).
    fn chassis_dof() -> usize;

    /// The links' centroids from the track's `q_i` (a slice of
    /// [`track_dof`](Self::track_dof) values: a recorded row's, say), one
    /// per link into `out`.
    fn track_positions(q: &[f64], out: &mut [Vector2<f64>]);

    /// The chassis bodies' centroids from its `q_i`, one per body into
    /// `out`.
    fn chassis_positions(q: &[f64], out: &mut [Vector2<f64>]);
}
