//! The spatial vehicle as a system in time: its three trees' coordinates
//! and quasi-velocities in one state, with the energy its force elements
//! dissipate and the work the drives do integrated beside them (the
//! books).
//!
//! A tree of `D` planar coordinates holds `2 D + 6` values: its root's
//! centroid in the world (3), its plane's yaw and roll, its bodies'
//! angles (`D − 2`), then its quasi-velocities in the plane (`D`) and
//! across it (3). The state is the hull's, the right track's, the left
//! track's, each track's ground points' stiction deflections (m, none
//! under regularised friction: [`SpatialDynamics::ground_states`]), the
//! driveline's five states, the energy dissipated so far and the work
//! the drive has done so far (J), then each side's books (J, right then
//! left: [`SideBooks`]' five, in its fields' order; passive, so keeping
//! them moves no step). The driveline's first three states are, with a
//! drive on each side, the right's and the left's controller integrals
//! (rad) and an unused 0; with a differential, its drive's integral
//! (rad), then the right and the left steering brakes' deflections (rad)
//! or the steer unit's integral (rad) and an unused 0. The last two are
//! the engine's speed (rad/s) and its locked driveline's twist (rad) where
//! an engine whose speed is a state drives the differential
//! ([`SpatialEngine`](super::SpatialEngine)); else they stay 0 and are
//! passive, so that they move no step either. Each
//! track's loop is
//! held by Baumgarte's stabilisation of its planar closure
//! ([`MultiplierOptions`]'s rate), which the plane's motion leaves
//! unchanged.

use nalgebra::{DVector, SVector, Vector2, Vector3};

use super::driveline::{DRIVELINE, ENGINE_SPEED};
use super::{
    DriveState, Driveline, DrivelineError, Driver, EngineEnvelope, GroundForce, HeadingHold,
    LoadScratch, MassCentre, SideDrives, SpatialDynamics, SteeringError, TreeState,
};
use crate::closure::MultiplierOptions;
use crate::integrate::{OdeSystem, SimulationError};
use crate::multibody::{ChassisModel, ClosingJoint, RecursiveModel, TrackModel};
use crate::spatial::{FloatingTree, PlaneMotion, PlanePose, PlaneRates};
use crate::vehicle::DrawbarError;
use crate::vehicle::Drive;

/// Where the energy dissipated sits from the driveline's first state.
const DISSIPATED: usize = DRIVELINE;
/// Where the drive's work sits.
const DRIVEN: usize = DRIVELINE + 1;
/// Where the sides' books start.
const SIDES: usize = DRIVELINE + 2;
/// Where the drawbar's work sits, after the sides' books.
const DRAWN: usize = SIDES + 2 * SideBooks::VALUES;

/// The spatial vehicle in time.
pub struct SpatialSystem<'m, H, const DH: usize, R, const DR: usize, L, const DL: usize> {
    /// Its dynamics at a state.
    pub dynamics: SpatialDynamics<'m, H, DH, R, DR, L, DL>,
    pub(super) driveline: Driveline,
    pub(super) steering: Option<HeadingHold>,
    pub(super) envelope: Option<EngineEnvelope>,
    /// The drawbar load on the hull, N ([`set_drawbar_pull`](Self::set_drawbar_pull)).
    drawbar_pull: f64,
    closure: MultiplierOptions,
    scratch: LoadScratch,
}

/// Where the spatial vehicle's energy is, J.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SpatialEnergy {
    /// The bodies' kinetic energy.
    pub kinetic: f64,
    /// Gravity's potential, from the world's `z = 0`.
    pub gravity: f64,
    /// What the force elements store.
    pub stored: f64,
    /// What they have dissipated since the start, and what the drawbar
    /// load has taken out.
    pub dissipated: f64,
    /// The work the drive (and a steer unit) has done since the start.
    pub driven: f64,
    /// Of [`dissipated`](Self::dissipated), the work the drawbar load
    /// has taken out since the start (`∫ P (ĥ · v) dt`).
    pub drawbar: f64,
}

/// Where a side's share of the work went since the start, J: what the
/// driveline put into its sprocket and what its brake and its force
/// elements dissipated. A side's books do not balance alone (the hull
/// carries work from one side to the other); the two sides' losses and
/// the drawbar's work add up to [`SpatialEnergy::dissipated`].
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct SideBooks {
    /// `∫ τ ω dt` at the sprocket (the drive's share, a steer unit's and
    /// the brake's torque together): negative where the side was held
    /// back more than driven.
    pub sprocket_work: f64,
    /// Lost in the ground under the track.
    pub ground: f64,
    /// Lost in the rims, the guides and the sprocket's teeth.
    pub running_gear: f64,
    /// Lost in the side's arms' dampers.
    pub suspension: f64,
    /// Lost in the side's steering brake.
    pub brake: f64,
}

impl SideBooks {
    /// How many values a side's books take in the state.
    const VALUES: usize = 5;

    fn from_values(v: &[f64]) -> SideBooks {
        SideBooks {
            sprocket_work: v[0],
            ground: v[1],
            running_gear: v[2],
            suspension: v[3],
            brake: v[4],
        }
    }

    /// What these books gained since `before` (a run's share of them).
    pub fn since(&self, before: &SideBooks) -> SideBooks {
        SideBooks {
            sprocket_work: self.sprocket_work - before.sprocket_work,
            ground: self.ground - before.ground,
            running_gear: self.running_gear - before.running_gear,
            suspension: self.suspension - before.suspension,
            brake: self.brake - before.brake,
        }
    }

    /// Everything the side lost, J.
    pub fn lost(&self) -> f64 {
        self.ground + self.running_gear + self.suspension + self.brake
    }
}

impl SpatialEnergy {
    /// The books' balance: what is in the bodies, stored and dissipated,
    /// less the drives' work; constant.
    pub fn total(&self) -> f64 {
        self.held() + self.dissipated - self.driven
    }

    /// What the vehicle holds: kinetic, gravity's and stored, J.
    pub fn held(&self) -> f64 {
        self.kinetic + self.gravity + self.stored
    }
}

/// A tree's `2 D + 6` values as its state.
fn tree_state<const D: usize>(y: &[f64]) -> TreeState<D> {
    let mut planar = SVector::<f64, D>::zeros();
    planar.as_mut_slice()[2..].copy_from_slice(&y[5..D + 3]);
    TreeState {
        pose: PlanePose {
            origin: Vector3::new(y[0], y[1], y[2]),
            yaw: y[3],
            roll: y[4],
            planar,
        },
        rates: PlaneRates {
            planar: SVector::from_column_slice(&y[D + 3..2 * D + 3]),
            across: Vector3::new(y[2 * D + 3], y[2 * D + 4], y[2 * D + 5]),
        },
    }
}

/// A tree's state into its `2 D + 6` values.
fn put_tree<const D: usize>(state: &TreeState<D>, y: &mut [f64]) {
    y[..3].copy_from_slice(state.pose.origin.as_slice());
    (y[3], y[4]) = (state.pose.yaw, state.pose.roll);
    y[5..D + 3].copy_from_slice(&state.pose.planar.as_slice()[2..]);
    y[D + 3..2 * D + 3].copy_from_slice(state.rates.planar.as_slice());
    y[2 * D + 3..2 * D + 6].copy_from_slice(state.rates.across.as_slice());
}

/// A tree's coordinates' rates and its accelerations into `dy`.
fn put_rates<M: RecursiveModel<D>, const D: usize>(
    tree: &FloatingTree<'_, M, D>,
    state: &TreeState<D>,
    (planar, across): &(SVector<f64, D>, Vector3<f64>),
    dy: &mut [f64],
) {
    let (velocity, yaw, roll, angles) = tree.coordinate_rates(&state.pose, &state.rates);
    dy[..3].copy_from_slice(velocity.as_slice());
    (dy[3], dy[4]) = (yaw, roll);
    dy[5..D + 3].copy_from_slice(&angles.as_slice()[2..]);
    dy[D + 3..2 * D + 3].copy_from_slice(planar.as_slice());
    dy[2 * D + 3..2 * D + 6].copy_from_slice(across.as_slice());
}

/// Why a driver holding a heading cannot steer through `driveline`: a
/// drive on each side, not both speed drives (the driver moves their
/// targets). A differential steers through its brakes or steer unit.
fn steerable(driveline: &Driveline) -> Result<(), SteeringError> {
    let speed = |d: &Drive| matches!(d, Drive::Speed { .. });
    match driveline {
        Driveline::Sides(drives) if !(speed(&drives.right) && speed(&drives.left)) => {
            Err(SteeringError::NotSpeedDrives)
        }
        _ => Ok(()),
    }
}

/// A track's loop held by Baumgarte's stabilisation of its planar closure
/// (which the plane's turning about its normal leaves unchanged).
fn closing<T: TrackModel<D>, const D: usize>(
    track: &T,
    (motion, state): (&PlaneMotion, &TreeState<D>),
    options: &MultiplierOptions,
) -> ClosingJoint {
    // From the links' sines and cosines found once for the evaluation.
    let (c, rate) = track.closure_and_rate(motion.trig(), &state.rates.planar);
    ClosingJoint::Constrained {
        stabilisation: options.stabilisation(c, rate),
    }
}

impl<'m, H, const DH: usize, R, const DR: usize, L, const DL: usize>
    SpatialSystem<'m, H, DH, R, DR, L, DL>
where
    H: ChassisModel<DH>,
    R: TrackModel<DR>,
    L: TrackModel<DL>,
{
    /// The system of `dynamics`, its sprockets free, its tracks' loops
    /// held at [`MultiplierOptions`]'s default rate.
    pub fn new(dynamics: SpatialDynamics<'m, H, DH, R, DR, L, DL>) -> Self {
        SpatialSystem {
            dynamics,
            driveline: Driveline::Sides(SideDrives::free()),
            steering: None,
            envelope: None,
            drawbar_pull: 0.0,
            closure: MultiplierOptions::default(),
            scratch: LoadScratch::default(),
        }
    }

    /// The system with its sprockets driven by `drives`; settings that
    /// make no controller are refused ([`SideDrives::check`]), and so are
    /// drives a heading already held cannot steer (not both speed drives).
    pub fn with_drives(self, drives: SideDrives) -> Result<Self, DrivelineError> {
        self.with_driveline(Driveline::Sides(drives))
    }

    /// The system with its sprockets driven through `driveline`; settings
    /// out of range, a differential on a vehicle without both sprockets,
    /// or drives on each side that a heading already held
    /// ([`with_steering`](Self::with_steering)) cannot steer, are refused
    /// (the driveline kept as it was).
    pub fn with_driveline(mut self, driveline: Driveline) -> Result<Self, DrivelineError> {
        self.set_driveline(driveline)?;
        Ok(self)
    }

    /// [`with_driveline`](Self::with_driveline) in place.
    pub(super) fn set_driveline(&mut self, driveline: Driveline) -> Result<(), DrivelineError> {
        driveline.check()?;
        if self.steering.is_some() {
            steerable(&driveline)?;
        }
        if let Driveline::Differential(_) = driveline {
            for (sprocket, side) in self.dynamics.sprockets.iter().zip(["right", "left"]) {
                if sprocket.is_none() {
                    return Err(DrivelineError::NoSprocket { side });
                }
            }
        }
        self.driveline = driveline;
        Ok(())
    }

    /// The system with a driver steering it to `hold`'s heading
    /// ([`HeadingHold`]): through its two speed drives, or its
    /// differential's brakes or steer unit; a setting out of range, or a
    /// side without a speed drive, is refused.
    pub fn with_steering(mut self, hold: HeadingHold) -> Result<Self, SteeringError> {
        self.check_steering(&hold)?;
        self.steering = Some(hold);
        Ok(self)
    }

    /// Why `hold` cannot steer this system: a setting out of range, or,
    /// with a drive on each side, a side without a speed drive.
    pub(super) fn check_steering(&self, hold: &HeadingHold) -> Result<(), SteeringError> {
        hold.check()?;
        steerable(&self.driveline)
    }

    /// The system with its drive capped by an engine's full-load
    /// `envelope` ([`EngineEnvelope`]: a side's cap on each side's drive,
    /// twice it on a differential's); `None` takes the cap off.
    pub fn with_envelope(mut self, envelope: Option<EngineEnvelope>) -> Self {
        self.envelope = envelope;
        self
    }

    /// The system with a drawbar load of `pull` N on its hull
    /// (`drawbar`'s force, pulling back along the heading at the frame's
    /// centroid); a pull that is not a number is refused.
    pub fn with_drawbar_pull(mut self, pull: f64) -> Result<Self, DrawbarError> {
        self.set_drawbar_pull(pull)?;
        Ok(self)
    }

    /// [`with_drawbar_pull`](Self::with_drawbar_pull) in place, from now
    /// on (the pull kept as it was where refused).
    pub fn set_drawbar_pull(&mut self, pull: f64) -> Result<(), DrawbarError> {
        self.drawbar_pull = DrawbarError::check(pull)?;
        Ok(())
    }

    /// The driveline, the steering, the engine's envelope and the
    /// driveline's states at `y`, as [`SpatialDynamics::drive`] takes
    /// them.
    pub(super) fn driver(&self, y: &[f64]) -> Driver<'_> {
        Driver {
            driveline: &self.driveline,
            steering: self.steering.as_ref(),
            envelope: self.envelope.as_ref(),
            states: self.driveline_states(y),
        }
    }

    /// Where the trees end in the state and the ground's deflections
    /// begin.
    const TREES: usize = (2 * DH + 6) + (2 * DR + 6) + (2 * DL + 6);

    /// Where the driveline's [`DRIVELINE`] states start in the state,
    /// the ground's deflections ended: then the energy dissipated
    /// ([`DISSIPATED`] on), the drive's work ([`DRIVEN`]) and the sides'
    /// books ([`SIDES`]).
    pub(super) fn driveline_at(&self) -> usize {
        let [r, l] = self.dynamics.ground_states();
        Self::TREES + r + l
    }

    /// Each track's ground deflections in `y` (right, left).
    pub(super) fn deflections<'y>(&self, y: &'y [f64]) -> [&'y [f64]; 2] {
        let r = self.dynamics.ground_states()[0];
        let (right, rest) = y[Self::TREES..self.driveline_at()].split_at(r);
        [right, rest]
    }

    /// Every force element's loads at `y`, the ground's deflections' rates
    /// into `rates` (as many values as the deflections).
    fn loads_at(&self, y: &[f64], rates: &mut [f64]) -> super::SpatialLoads {
        let (hull, right, left, _) = self.states(y);
        let states = (&hull, &right, &left);
        self.loads_in(&self.dynamics.plane_motions(states), states, y, rates)
    }

    /// [`loads_at`](Self::loads_at) with the trees' states in `y` and
    /// their motions in their planes found already.
    fn loads_in(
        &self,
        motions: &[PlaneMotion; 3],
        (hull, right, left): (&TreeState<DH>, &TreeState<DR>, &TreeState<DL>),
        y: &[f64],
        rates: &mut [f64],
    ) -> super::SpatialLoads {
        let r = self.dynamics.ground_states()[0];
        let (right_rates, left_rates) = rates.split_at_mut(r);
        self.dynamics.loads_in(
            motions,
            (hull, right, left),
            self.deflections(y),
            [right_rates, left_rates],
        )
    }

    /// The driveline's five states in `y` (the module's docs).
    pub fn driveline_states(&self, y: &[f64]) -> [f64; DRIVELINE] {
        let b = self.driveline_at();
        std::array::from_fn(|i| y[b + i])
    }

    /// The engine driving the differential, its speed a state, if one
    /// does.
    pub fn engine(&self) -> Option<&super::SpatialEngine> {
        match &self.driveline {
            Driveline::Differential(d) => d.engine.as_ref(),
            Driveline::Sides(_) => None,
        }
    }

    /// `y` with the engine driving the differential (if one does) at its
    /// idle speed: where a run through it starts.
    pub fn start_engine(&self, y: &mut [f64]) {
        if let Some(engine) = self.engine() {
            y[self.driveline_at() + ENGINE_SPEED] = engine.idle();
        }
    }

    /// After an accepted step to `(t, y)`: on soft soil, what the soil
    /// remembers brought up to the shoes (`SpatialDynamics::press_soil`);
    /// the engine's gearbox shifted and its lock-up clutch engaged or
    /// released where their rules say
    /// ([`SpatialEngine::after_step`](super::SpatialEngine::after_step)).
    /// Whether anything changed: the integrator must then restart. A run
    /// on soil or through an engine whose speed is a state calls it after
    /// every step, as the planar vehicle's run calls
    /// [`Simulated::after_step`](crate::system::Simulated::after_step).
    pub fn after_step(&mut self, t: f64, y: &[f64]) -> bool {
        let pressed = if self.dynamics.soil().is_some() {
            let (_, right, left, _) = self.states(y);
            let shears = self.deflections(y);
            self.dynamics.press_soil(t, (&right, &left), shears)
        } else {
            false
        };
        let speed = y[self.driveline_at() + ENGINE_SPEED];
        let Driveline::Differential(d) = &mut self.driveline else {
            return pressed;
        };
        let Some(engine) = d.engine.as_mut() else {
            return pressed;
        };
        let omega = self
            .dynamics
            .sprocket_speeds(&tree_state::<DH>(&y[..2 * DH + 6]));
        engine.after_step(t, (0.5 * (omega[0] + omega[1]), speed), &d.drive) || pressed
    }

    /// What the drives do at time `t` and state `y`.
    pub fn drive_state(&self, t: f64, y: &[f64]) -> Result<DriveState, SimulationError> {
        let (hull, ..) = self.states(y);
        self.dynamics.drive(t, &hull, self.driver(y))
    }

    /// What the ground gives each ground point on it at `y`
    /// ([`SpatialDynamics::ground_forces`]).
    pub fn ground_forces(&self, y: &[f64]) -> Vec<GroundForce> {
        let (_, right, left, _) = self.states(y);
        self.dynamics
            .ground_forces((&right, &left), self.deflections(y))
    }

    /// The vehicle's centre of mass and its velocity at `y`.
    pub fn mass_centre(&self, y: &[f64]) -> MassCentre {
        let (hull, right, left, _) = self.states(y);
        self.dynamics.mass_centre((&hull, &right, &left))
    }

    /// The state of the three trees, nothing dissipated yet.
    pub fn state(
        &self,
        hull: &TreeState<DH>,
        right: &TreeState<DR>,
        left: &TreeState<DL>,
    ) -> DVector<f64> {
        let mut y = DVector::zeros(self.dimension());
        let (h, r) = (2 * DH + 6, 2 * DR + 6);
        put_tree(hull, &mut y.as_mut_slice()[..h]);
        put_tree(right, &mut y.as_mut_slice()[h..h + r]);
        put_tree(left, &mut y.as_mut_slice()[h + r..h + r + 2 * DL + 6]);
        y
    }

    /// The state `y` of a vehicle at rest heading along `x` (each tree's
    /// yaw 0) turned `roll` rad about the world's `x` axis: each tree's
    /// plane rolled, its root's place turned with it, the rest of `y`
    /// kept. Level ground through the origin so turned is the side slope
    /// `tan roll` (the field `z = y tan roll`), so a vehicle assembled at
    /// rest on the level is set on that slope as it sat on the level.
    pub fn rolled(&self, y: &[f64], roll: f64) -> DVector<f64> {
        let (s, c) = roll.sin_cos();
        let turn = nalgebra::Matrix3::new(1.0, 0.0, 0.0, 0.0, c, -s, 0.0, s, c);
        let (mut hull, mut right, mut left, _) = self.states(y);
        for pose in [
            &mut hull.pose.origin,
            &mut right.pose.origin,
            &mut left.pose.origin,
        ] {
            *pose = turn * *pose;
        }
        hull.pose.roll += roll;
        right.pose.roll += roll;
        left.pose.roll += roll;
        let mut turned = DVector::from_column_slice(y);
        let trees = self.state(&hull, &right, &left);
        turned
            .rows_mut(0, Self::TREES)
            .copy_from(&trees.rows(0, Self::TREES));
        turned
    }

    /// The three trees' states in `y`, and the energy dissipated so far.
    pub fn states(&self, y: &[f64]) -> (TreeState<DH>, TreeState<DR>, TreeState<DL>, f64) {
        let (h, r, l) = (2 * DH + 6, 2 * DR + 6, 2 * DL + 6);
        (
            tree_state(&y[..h]),
            tree_state(&y[h..h + r]),
            tree_state(&y[h + r..h + r + l]),
            y[self.driveline_at() + DISSIPATED],
        )
    }

    /// Each side's books at `y` (right, left).
    pub fn side_books(&self, y: &[f64]) -> [SideBooks; 2] {
        let at = self.driveline_at() + SIDES;
        let n = SideBooks::VALUES;
        [
            SideBooks::from_values(&y[at..at + n]),
            SideBooks::from_values(&y[at + n..at + 2 * n]),
        ]
    }

    /// Where the energy is at `y`.
    pub fn energy(&self, y: &[f64]) -> SpatialEnergy {
        let (hull, right, left, dissipated) = self.states(y);
        let d = &self.dynamics;
        let g = d.hull.gravity();
        let height = |at: Vec<Vector3<f64>>, masses: &[f64]| {
            at.iter().zip(masses).map(|(p, m)| m * g * p.z).sum::<f64>()
        };
        SpatialEnergy {
            kinetic: d.hull.kinetic_energy(&hull.pose, &hull.rates)
                + d.right.kinetic_energy(&right.pose, &right.rates)
                + d.left.kinetic_energy(&left.pose, &left.rates),
            gravity: height(d.hull.positions(&hull.pose), d.hull.masses())
                + height(d.right.positions(&right.pose), d.right.masses())
                + height(d.left.positions(&left.pose), d.left.masses()),
            stored: self
                .loads_at(y, &mut vec![0.0; self.driveline_at() - Self::TREES])
                .potential
                + self.driveline.stored(self.driveline_states(y)),
            dissipated,
            driven: y[self.driveline_at() + DRIVEN],
            drawbar: y[self.driveline_at() + DRAWN],
        }
    }
}

impl<H, const DH: usize, R, const DR: usize, L, const DL: usize> OdeSystem
    for SpatialSystem<'_, H, DH, R, DR, L, DL>
where
    H: ChassisModel<DH>,
    R: TrackModel<DR>,
    L: TrackModel<DL>,
{
    fn dimension(&self) -> usize {
        self.driveline_at() + DRAWN + 1
    }

    fn derivative(&mut self, t: f64, y: &[f64], dy: &mut [f64]) -> Result<(), SimulationError> {
        if y.len() != self.dimension() || dy.len() != self.dimension() {
            return Err(SimulationError::StateLength {
                t,
                got: y.len(),
                expected: self.dimension(),
            });
        }
        // The scratch is taken for the evaluation and put back, so that
        // the evaluation borrows the system whole.
        let mut scratch = std::mem::take(&mut self.scratch);
        let done = self.evaluate(t, y, dy, &mut scratch);
        self.scratch = scratch;
        done.map(|_| ())
    }

    fn is_quadrature(&self, i: usize) -> bool {
        i >= self.driveline_at() + DISSIPATED || self.is_passive(i)
    }

    fn is_passive(&self, i: usize) -> bool {
        let b = self.driveline_at();
        let engine = b + ENGINE_SPEED..b + DRIVELINE;
        i >= b + SIDES || (self.engine().is_none() && engine.contains(&i))
    }
}

impl<H, const DH: usize, R, const DR: usize, L, const DL: usize>
    SpatialSystem<'_, H, DH, R, DR, L, DL>
where
    H: ChassisModel<DH>,
    R: TrackModel<DR>,
    L: TrackModel<DL>,
{
    /// The state's derivative at `t` and `y` into `dy` (both of the
    /// system's dimension), through `scratch`, which keeps what it found:
    /// the bodies in the world, the loads and each track's joint forces;
    /// the trees' motions in their planes are handed back.
    pub(super) fn evaluate(
        &self,
        t: f64,
        y: &[f64],
        dy: &mut [f64],
        scratch: &mut LoadScratch,
    ) -> Result<[PlaneMotion; 3], SimulationError> {
        let (hull, right, left, _) = self.states(y);
        let b = self.driveline_at();
        let states = (&hull, &right, &left);
        let motions = self.dynamics.plane_motions(states);
        let drive = self.dynamics.drive(t, &hull, self.driver(y))?;
        let r = self.dynamics.ground_states()[0];
        let (right_rates, left_rates) = dy[Self::TREES..b].split_at_mut(r);
        let deflections = self.deflections(y);
        let d = &self.dynamics;
        d.loads_into(
            &motions,
            states,
            deflections,
            [right_rates, left_rates],
            scratch,
        );
        let LoadScratch {
            bodies: [frame, ..],
            loads,
            joint_forces: [f_right, f_left],
        } = scratch;
        d.apply_drive(&hull, &drive, loads);
        let drawn = d.apply_drawbar(self.drawbar_pull, (&hull, frame), loads);
        let closing = [
            closing(d.right.model(), (&motions[1], &right), &self.closure),
            closing(d.left.model(), (&motions[2], &left), &self.closure),
        ];
        f_right.resize(d.right.masses().len(), Vector2::zeros());
        f_left.resize(d.left.masses().len(), Vector2::zeros());
        let (a_hull, a_right, a_left) = d
            .accelerations_in(&motions, states, (loads, closing), [f_right, f_left])
            .map_err(|source| SimulationError::Dynamics { t, source })?;
        let (h, r, l) = (2 * DH + 6, 2 * DR + 6, 2 * DL + 6);
        put_rates(&d.hull, &hull, &a_hull, &mut dy[..h]);
        put_rates(&d.right, &right, &a_right, &mut dy[h..h + r]);
        put_rates(&d.left, &left, &a_left, &mut dy[h + r..h + r + l]);
        dy[b..b + DRIVELINE].copy_from_slice(&drive.rates);
        dy[b + DISSIPATED] = loads.dissipation + drive.dissipation + drawn;
        dy[b + DRIVEN] = drive.driven;
        dy[b + DRAWN] = drawn;
        let sides = dy[b + SIDES..b + DRAWN].chunks_exact_mut(SideBooks::VALUES);
        for (s, (books, losses)) in sides.zip(&loads.losses).enumerate() {
            books.copy_from_slice(&[
                drive.side_power(s),
                losses.ground,
                losses.running_gear,
                losses.suspension,
                drive.braked[s],
            ]);
        }
        Ok(motions)
    }
}
