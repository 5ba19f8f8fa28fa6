//! A vehicle in motion: track and chassis integrated together, coupled by
//! contact, with sprung arms, a drive and rigid ground or soft soil; its
//! evaluation in stages over a [`Workspace`].

mod between_steps;
mod dynamics;
mod observe;

use nalgebra::{DVector, SVector, Vector2};

use super::declared::sealed::Build;
use super::forces::{self, ChassisState, Outlines, Sprocket, TangentialStates};
use super::implicit::Implicit;
use super::jacobian::Tangent;
use super::layout::track_coordinates;
use super::linearisation::{GroundPoints, Linearisation};
use super::workspace::Workspace;
use super::{
    BuildError, ConfigError, ContactFit, Geometry, Powertrain, StateLayout, VehicleConfig, arms,
};
use crate::assembly::{self, Assembled};
use crate::contact::GroundFriction;
use crate::contact::outline::Outline;
use crate::contact::soft_ground::SoftGround;
use crate::contact::sprocket::{pitch_radius, rolling_radius};
use crate::integrate::SimulationError;
use crate::integrate::{ImplicitSolve, OdeSystem};
use crate::multibody::{ChassisModel, PartKind, TrackModel, TreeDescription};
use crate::system::{Pair, Simulated, TrackSystem, TreeSystem};

/// A vehicle: its track and chassis integrated together, coupled by the
/// contact forces, with sprung arms and a drive. Built by
/// [`build`](super::build) (or `Name::system`), or at given coordinates by
/// [`new`](Self::new).
///
/// State: the track's, the chassis' `[q_i, q̇_i]`, then the drive
/// controller's integral (rad), the motor's work and the dissipated work
/// (J, integrated alongside so the energy balance is exact to the
/// integration tolerance); then a tangential state per shoe ground point,
/// link by link: on rigid ground with stiction its deflection `z` (m,
/// [`Stiction`](crate::laws::Stiction)), on soft soil its shear
/// displacement `j` (m), grown by the point's slip speed while it is in
/// the soil and reset when it leaves it; none with regularised friction.
///
/// Every recorded quantity is finite: one that is not (see
/// [`observe`](Simulated::observe)) stops the run with a
/// [`SimulationError::NonFiniteRecord`] naming it.
pub struct VehicleSystem<T: TrackModel<DT>, const DT: usize, C: ChassisModel<DC>, const DC: usize> {
    /// Track and chassis, their states side by side.
    bodies: Pair<TrackSystem<T, DT>, TreeSystem<C, DC>>,
    config: VehicleConfig,
    geometry: Geometry,
    /// The soil under the track and its memory, on soft soil.
    soil: Option<SoftGround>,
    /// The drive's sprocket, if the chassis has one.
    sprocket: Option<Sprocket>,
    /// The unit of the stiction states, m ([`forces::stiction_scale`]).
    stiction_scale: f64,
    /// `ū2` of every link: the joint to the next.
    forward_joints: Vec<Vector2<f64>>,
    /// The shoes' and the hull's outlines, against the terrain's sharp
    /// corners.
    outlines: Outlines,
    /// What an evaluation works in, allocated once.
    work: Workspace,
    /// The linearly implicit integrator's own solves
    /// ([`ImplicitSolve`]), made at their first use.
    implicit: Option<Implicit>,
    /// The exact Jacobian's factored derivatives, made at their first use.
    tangent: Option<Tangent>,
    /// Where each quantity sits in the state (the track's integrated
    /// coordinates as at the start; [`layout`](super::VehicleDynamics::layout)
    /// gives them for the pair of the moment).
    layout: StateLayout,
    y0: DVector<f64>,
}

/// How deep below the ground the assembly puts the shoes, m (negative:
/// 1 mm above it).
const START_CLEARANCE: f64 = 0.001;

impl<T, const DT: usize, C, const DC: usize> VehicleSystem<T, DT, C, DC>
where
    T: TrackModel<DT>,
    C: ChassisModel<DC>,
{
    /// The vehicle starting at rest at `start` (the coordinates
    /// [`assemble`](crate::assembly::assemble) gives, changed at will) with
    /// `geometry`, run by `config`, its loop closed by `config.closure`.
    /// If the start set a tensioner, its spring's rest angle is moved to
    /// where the arm was set (a track adjuster's job: the tensioner then
    /// pushes with its declared preload, `τ = preload − k φ` becoming
    /// `preload + k φ₀ − k φ`).
    ///
    /// A [`ConfigError`] for a configuration that makes no vehicle
    /// ([`VehicleConfig::check`], and against the compiled model: a tension
    /// link that is not a link, arms that are not one per arm of the
    /// chassis, a profile whose teeth are not the sprocket's, links of
    /// different lengths, soil without a declared track width, a loop that
    /// cannot be closed as asked). A target speed or torque schedule that
    /// turns NaN or infinite stops the run when the drive meets it
    /// ([`Drive::checked_torque`](super::Drive::checked_torque)).
    pub fn new(
        track: T,
        chassis: C,
        start: &Assembled<DT, DC>,
        geometry: Geometry,
        mut config: VehicleConfig,
    ) -> Result<Self, ConfigError> {
        let description = track.description();
        check::<T, DT, C, DC>(&geometry, &config, &description)?;
        if let Some(Powertrain::Converter(driveline)) = config.powertrain.as_mut()
            && driveline.dynamics.is_some()
            && driveline.shift.is_none()
        {
            // An engine whose speed is a state shifts by a schedule.
            driveline.shift =
                driveline.ideal_schedule(super::IDEAL_DOWNSHIFT, super::IDEAL_SHIFT_TIME);
        }
        if let Some((body, angle)) = start.tensioner {
            for arm in config.arms.iter_mut().filter(|a| a.body == body) {
                arm.spring.preload += arm.spring.stiffness * angle;
            }
        }
        let pitch = description.pitch()?;
        let soil = match config.soil {
            None => None,
            Some(soil) => {
                let width = geometry.shoe.width.ok_or(ConfigError::NoTrackWidth)?;
                let mut ground = SoftGround::new(soil, width, pitch, &geometry.shoe)?;
                if let Some(rut) = &config.rut {
                    ground.rut = rut.clone();
                }
                Some(ground)
            }
        };
        let tangential_states = if soil.is_some() || config.ground.friction.has_state() {
            T::BODIES * geometry.shoe.ground_points.len()
        } else {
            0
        };
        let (stall, stall_reverse) = config.stall_torque();
        let sprocket = C::PARTS
            .iter()
            .find(|p| p.kind == PartKind::Sprocket)
            .map(|part| Sprocket {
                body: part.body,
                pitch_radius: pitch_radius(part.teeth, pitch),
                rolling_radius: rolling_radius(part.teeth, pitch),
                stall,
                stall_reverse,
                engaged: config.first_engaged(),
                locked: false,
            });
        let chassis_description = chassis.description();
        let fit = ContactFit::of(&description, &chassis_description, C::PARTS, &geometry);
        let stiction_scale = if soil.is_some() {
            1.0
        } else {
            forces::stiction_scale(&config.ground.friction, fit.ground_load())
        };
        let forward_joints = description
            .joints()
            .map(|joints| joints.into_iter().map(|(_, u2)| u2).collect())
            .unwrap_or_else(|| vec![Vector2::zeros(); T::BODIES]);
        let hull: Vec<Vector2<f64>> = C::HULL.iter().map(|&[x, y]| Vector2::new(x, y)).collect();
        let outlines = Outlines {
            shoe: Outline::of_shoe(&geometry.shoe),
            hull: if hull.is_empty() {
                None
            } else {
                Some(Outline::new(&hull).map_err(ConfigError::Hull)?)
            },
        };
        let track = TrackSystem::new(track, start.track, SVector::zeros(), config.closure)?;
        let chassis = TreeSystem::chassis(chassis, start.chassis, SVector::zeros());
        let bodies = Pair::new(track, "track", chassis, "chassis");
        let idle = engine_idle(&config);
        let layout = StateLayout::new(
            track_coordinates(DT, bodies.first().dependent_pair()),
            DC,
            tangential_states,
            sprocket.map(|s| s.body),
            idle.is_some(),
        );
        debug_assert_eq!(layout.integral, bodies.dimension());
        let start = bodies.initial_state();
        let mut y0 = DVector::zeros(layout.dimension());
        y0.as_mut_slice()[layout.bodies()].copy_from_slice(start.as_slice());
        if let (Some(i), Some(idle)) = (layout.engine, idle) {
            // The engine starts idling, the vehicle at rest, the driveline
            // untwisted.
            y0[i] = idle;
            y0[i + 1] = 0.0;
        }
        Ok(VehicleSystem {
            bodies,
            config,
            geometry,
            soil,
            sprocket,
            stiction_scale,
            forward_joints,
            outlines,
            work: Workspace::new(T::BODIES, C::BODIES, tangential_states),
            implicit: None,
            tangent: None,
            layout,
            y0,
        })
    }

    /// The track subsystem.
    pub fn track(&self) -> &TrackSystem<T, DT> {
        self.bodies.first()
    }

    /// The chassis subsystem.
    pub fn chassis(&self) -> &TreeSystem<C, DC> {
        self.bodies.second()
    }

    /// The bodies' part of a state; the drive's integral, the motor's
    /// work, the dissipated work and the engine's work; the ground points'
    /// tangential states.
    fn split<'y>(&self, y: &'y [f64]) -> (&'y [f64], [f64; 4], &'y [f64]) {
        let l = &self.layout;
        (
            &y[l.bodies()],
            [y[l.integral], y[l.books[0]], y[l.books[1]], y[l.books[2]]],
            &y[l.tangential.clone()],
        )
    }

    /// The engine's speed (rad/s) and the locked driveline's twist (rad)
    /// in `y`, where they are states (0 else: not read).
    fn engine_state(&self, y: &[f64]) -> (f64, f64) {
        self.layout.engine.map_or((0.0, 0.0), |i| (y[i], y[i + 1]))
    }

    /// The loads at a state, stage by stage: the track's coordinates
    /// recovered (kept by the track system) and the chassis', every body's
    /// state (kinematics), the contacts (detection), the loads of every
    /// force element with their books (in the workspace), given to both
    /// subsystems. Returns the chassis' `(q_i, q̇_i)`.
    #[allow(clippy::type_complexity)]
    fn evaluate(
        &mut self,
        t: f64,
        y: &[f64],
    ) -> Result<(SVector<f64, DC>, SVector<f64, DC>), SimulationError> {
        self.work.at = None;
        self.work.accelerated = false;
        let (bodies, [integral, ..], tangential) = self.split(y);
        let (yt, yc) = self.bodies.split(bodies);
        self.bodies.parts_mut().0.recover(t, yt)?;
        let (qc, qdc) = TreeSystem::<C, DC>::split(yc);
        let track = self.bodies.first();
        let (qt, qdt, link_trig) = track.recovered();
        self.work.kinematics(
            (track.model(), link_trig),
            (qt, qdt),
            self.bodies.second().model(),
            (&qc, &qdc),
        );
        forces::detect::<C, DC>(&mut self.work, &self.config, &self.geometry, &self.outlines);
        let points = self.geometry.shoe.ground_points.len();
        let engine = self.engine_state(y);
        forces::respond(
            &mut self.work,
            t,
            &self.config,
            TangentialStates {
                soil: self.soil.as_ref(),
                per_link: points,
                values: tangential,
                scale: self.stiction_scale,
            },
            ChassisState {
                q: &qc,
                qd: &qdc,
                sprocket: self.sprocket,
                integral,
                engine,
            },
        )?;
        let (track, chassis) = self.bodies.parts_mut();
        track.set_external(&self.work.track_loads);
        chassis.set_external(&self.work.chassis_loads);
        self.work.at = Some(t);
        self.work.state.clear();
        self.work.state.extend_from_slice(y);
        Ok((qc, qdc))
    }

    /// [`evaluate`](Self::evaluate), unless the workspace holds `(t, y)`'s
    /// evaluation already (a linearisation right after the step's first
    /// evaluation, at the same state).
    fn evaluated(
        &mut self,
        t: f64,
        y: &[f64],
    ) -> Result<(SVector<f64, DC>, SVector<f64, DC>), SimulationError> {
        if self.work.at == Some(t) && self.work.state == y {
            let yc = self.bodies.split(&y[..self.bodies.dimension()]).1;
            return Ok(TreeSystem::<C, DC>::split(yc));
        }
        self.evaluate(t, y)
    }
}

impl<T, const DT: usize, C, const DC: usize> VehicleSystem<T, DT, C, DC>
where
    T: TrackModel<DT>,
    C: ChassisModel<DC>,
{
    /// The drive's sprocket and slopes, and a lifted ground point's
    /// relaxation rate, at the evaluation the workspace holds.
    fn slopes(
        &self,
        t: f64,
        qdc: &SVector<f64, DC>,
        (integral, engine): (f64, (f64, f64)),
    ) -> Result<DriveAndRelaxation, SimulationError> {
        let drive = match self.sprocket {
            None => None,
            Some(s) => {
                let omega = s.omega(qdc);
                let slopes = match &self.config.powertrain {
                    Some(p @ Powertrain::Converter(driveline)) if driveline.dynamics.is_some() => {
                        let at = s.at(&self.config, t, omega);
                        super::engine_drive::engine_drive(
                            p,
                            &self.config.drive,
                            t,
                            at,
                            integral,
                            (engine.0, engine.1, 0.0),
                        )?
                        .slopes
                    }
                    _ => {
                        let (stall, gearbox) = s.gearbox(&self.config, t);
                        let cap = self.config.torque_cap(omega, stall, gearbox);
                        self.config
                            .drive
                            .slopes(t, omega, s.rolling_radius, integral, cap)
                    }
                };
                Some((s.body, slopes))
            }
        };
        let relaxation = match (&self.soil, self.config.ground.friction) {
            (None, GroundFriction::Stiction(stiction)) => Some(stiction.relax_slopes().rate[0]),
            _ => None,
        };
        Ok((drive, relaxation))
    }

    /// What the exact Jacobian and the own `W` both start from at `(t,
    /// y)`: the evaluation there, every force element's Jacobian beside
    /// its load (`vehicle/forces.rs`), every chassis body's rotation
    /// (`work.part_rotations`), the drive's and the deflections' slopes.
    /// A track not closed by partitioning is refused, `what` naming the
    /// caller.
    fn linearised(
        &mut self,
        t: f64,
        y: &[f64],
        what: &'static str,
    ) -> Result<Linearised<DC>, SimulationError> {
        let (qc, qdc) = self.evaluated(t, y)?;
        let (_, [integral, ..], tangential) = self.split(y);
        let points = self.geometry.shoe.ground_points.len();
        forces::linearise(
            &mut self.work,
            &self.config,
            &self.geometry,
            self.sprocket,
            TangentialStates {
                soil: self.soil.as_ref(),
                per_link: points,
                values: tangential,
                scale: self.stiction_scale,
            },
        );
        let Some(pair) = self.track().dependent_pair() else {
            return Err(SimulationError::SingularMatrix { t, what });
        };
        let rotations = &mut self.work.part_rotations;
        rotations.clear();
        rotations.extend(
            self.work
                .part_trig
                .iter()
                .map(|&t| crate::planar::Rotation::from_sin_cos(t)),
        );
        let (drive, relaxation) = self.slopes(t, &qdc, (integral, self.engine_state(y)))?;
        Ok(Linearised {
            chassis: (qc, qdc),
            pair,
            drive,
            relaxation,
        })
    }

    /// The exact `∂f/∂y` at `(t, y)` into `out` (column-major), the track
    /// closed by partitioning, on rigid ground or soil.
    fn exact_jacobian(
        &mut self,
        t: f64,
        y: &[f64],
        out: &mut [f64],
    ) -> Result<(), SimulationError> {
        let Linearised {
            chassis: (qc, qdc),
            pair,
            drive,
            relaxation,
        } = self.linearised(
            t,
            y,
            "the vehicle's exact Jacobian (its track is not closed by partitioning)",
        )?;
        let points = self.geometry.shoe.ground_points.len();
        let starts = self.layout.starts();
        let dimension = self.y0.len();
        let tangent = match &mut self.tangent {
            Some(tangent) => tangent,
            slot => slot.insert(
                Tangent::new(
                    &self.bodies.first().model().description(),
                    &self.bodies.second().model().description(),
                    starts,
                )
                .ok_or(SimulationError::SingularMatrix {
                    t,
                    what: "the vehicle's exact Jacobian (its track is not a loop)",
                })?,
            ),
        };
        let (qt, qdt, trig) = self.bodies.first().recovered();
        let at = Linearisation {
            track: (qt.as_slice(), qdt.as_slice(), trig),
            pair: [pair[0] - 1, pair[1] - 1],
            chassis: (qc.as_slice(), qdc.as_slice(), &self.work.part_rotations),
            contacts: &self.work.contacts,
            jacobians: &self.work.jacobians,
            chassis_contacts: (&self.work.chassis_contacts, &self.work.chassis_jacobians),
            arms: &self.config.arms,
            drive,
            points: GroundPoints {
                per_link: points,
                unit: self.stiction_scale,
                touching: &self.work.ground_normal,
                relaxation,
            },
        };
        tangent
            .jacobian(
                &at,
                (&self.work.track_loads, &self.work.chassis_loads),
                dimension,
                out,
            )
            .map_err(|source| SimulationError::Dynamics { t, source })
    }
}

/// [`VehicleSystem::linearised`]: the chassis' `(q_i, q̇_i)`, the track's
/// dependent pair (1-based links), the drive's slopes on its sprocket
/// and a lifted point's relaxation rate.
struct Linearised<const DC: usize> {
    chassis: (SVector<f64, DC>, SVector<f64, DC>),
    pair: [usize; 2],
    drive: Option<(usize, super::DriveSlopes)>,
    relaxation: Option<f64>,
}

/// What a configuration must agree with in the compiled model, besides
/// its own ranges.
fn check<T: TrackModel<DT>, const DT: usize, C: ChassisModel<DC>, const DC: usize>(
    geometry: &Geometry,
    config: &VehicleConfig,
    track: &TreeDescription,
) -> Result<(), ConfigError> {
    config.check()?;
    if config.tension_link == 0 || config.tension_link > T::BODIES {
        return Err(ConfigError::TensionLink {
            link: config.tension_link,
            links: T::BODIES,
        });
    }
    config.check_arms(&arms::declared::<C, DC>())?;
    if let Some(part) = C::PARTS.iter().find(|p| p.kind == PartKind::Sprocket) {
        if geometry.sprocket.teeth != part.teeth {
            return Err(ConfigError::Teeth {
                profile: geometry.sprocket.teeth,
                declared: part.teeth,
            });
        }
        if let Some(&joints) = track.joints().as_ref().and_then(|j| j.first()) {
            geometry.sprocket.check(joints, &geometry.shoe)?;
        }
    }
    Ok(())
}

impl<T, const DT: usize, C, const DC: usize> Build for VehicleSystem<T, DT, C, DC>
where
    T: TrackModel<DT> + Default + Send,
    C: ChassisModel<DC> + Default + Send,
{
    fn build_from(geometry: Geometry, config: VehicleConfig) -> Result<Self, BuildError> {
        check::<T, DT, C, DC>(&geometry, &config, &T::default().description())?;
        let start = assembly::assemble(
            &T::default(),
            &C::default(),
            &geometry.shoe,
            &geometry.sprocket,
            &config.terrain,
            0.0,
            START_CLEARANCE,
        )?;
        Ok(Self::new(
            T::default(),
            C::default(),
            &start,
            geometry,
            config,
        )?)
    }
}

impl<T: TrackModel<DT>, const DT: usize, C: ChassisModel<DC>, const DC: usize> OdeSystem
    for VehicleSystem<T, DT, C, DC>
{
    fn dimension(&self) -> usize {
        self.y0.len()
    }

    /// The books' three quadratures (the motor's, the dissipated and the
    /// engine's work).
    fn is_quadrature(&self, i: usize) -> bool {
        self.layout.books.contains(&i)
    }

    /// The engine's work: derived from the state behind the converter,
    /// its accuracy follows the steps the motion and the other two books
    /// ask (recording it changes no answer).
    fn is_passive(&self, i: usize) -> bool {
        i == self.layout.books[2]
    }

    /// The exact `∂f/∂y` (`vehicle/jacobian.rs`: every force element's Jacobian
    /// through the bodies' kinematics and the dynamics' own derivatives),
    /// on rigid ground or soil, with the track closed by partitioning;
    /// `false` for a track closed another way (the integrator then
    /// differences). The books' rows are zero (quadratures: nothing reads
    /// them).
    fn jacobian(
        &mut self,
        t: f64,
        y: &[f64],
        _slope: &[f64],
        jacobian: &mut [f64],
    ) -> Result<bool, SimulationError> {
        if self.track().dependent_pair().is_none() {
            return Ok(false);
        }
        self.exact_jacobian(t, y, jacobian)?;
        Ok(true)
    }

    /// The vehicle's own solves with its track closed by partitioning
    /// (the declared way), on rigid ground or soil; closed another way,
    /// the integrator's dense Jacobian.
    fn implicit(&mut self) -> Option<&mut dyn ImplicitSolve> {
        let own = self.track().dependent_pair().is_some();
        own.then_some(self as &mut dyn ImplicitSolve)
    }

    fn derivative(&mut self, t: f64, y: &[f64], dy: &mut [f64]) -> Result<(), SimulationError> {
        let (_, qdc) = self.evaluate(t, y)?;
        let l = &self.layout;
        let (_, yc) = self.bodies.split(&y[l.bodies()]);
        let (dyt, dyc) = self.bodies.split_mut(&mut dy[l.bodies()]);
        let (track, chassis) = self.bodies.parts_mut();
        track.derivative_recovered(t, dyt)?;
        self.work.accelerated = true;
        // The chassis' trigonometry is the kinematics stage's, at this state.
        chassis.derivative_with_trig(t, yc, &self.work.part_trig, dyc)?;
        let (qt, qdt, _) = self.track().recovered();
        let (books, l) = (&self.work.books, &self.layout);
        dy[l.integral] = books.integral_rate;
        dy[l.books[0]] = books.torque * self.sprocket.map_or(0.0, |s| s.omega(&qdc));
        dy[l.books[1]] = books.dissipation + self.track().closure_energy(qt, qdt).1;
        dy[l.books[2]] = books.engine.engine_power;
        if let Some(i) = l.engine {
            dy[i..i + 2].copy_from_slice(&books.engine_rate);
        }
        dy[l.tangential.clone()].copy_from_slice(&self.work.tangential_rate);
        Ok(())
    }
}

impl<T: TrackModel<DT>, const DT: usize, C: ChassisModel<DC>, const DC: usize> ImplicitSolve
    for VehicleSystem<T, DT, C, DC>
{
    /// The force elements' Jacobians at `(t, y)` (`vehicle/forces.rs`),
    /// with the chassis' mass matrix and velocity transform and the
    /// track's dependent pair: the vehicle's `W` (`vehicle/implicit.rs`).
    fn linearise(&mut self, t: f64, y: &[f64]) -> Result<(), SimulationError> {
        let Linearised {
            chassis: (qc, qdc),
            pair,
            drive,
            relaxation,
        } = self.linearised(
            t,
            y,
            "the vehicle's own W (its track is not closed by partitioning)",
        )?;
        // The joints' forces at the state, unless the evaluation there
        // solved for them.
        if !self.work.accelerated {
            self.bodies.parts_mut().0.accelerations(t)?;
        }
        let points = self.geometry.shoe.ground_points.len();
        let mut chassis_mass = nalgebra::SMatrix::<f64, DC, DC>::zeros();
        self.chassis().model().mass_matrix(&qc, &mut chassis_mass);
        let starts = self.layout.starts();
        let implicit = match &mut self.implicit {
            Some(implicit) => implicit,
            slot => slot.insert(
                Implicit::new(
                    &self.bodies.first().model().description(),
                    &self.bodies.second().model().description(),
                    starts,
                )
                .ok_or(SimulationError::SingularMatrix {
                    t,
                    what: "the vehicle's own W (its track is not a loop)",
                })?,
            ),
        };
        let track = self.bodies.first();
        let (qt, qdt, trig) = track.recovered();
        let at = Linearisation {
            track: (qt.as_slice(), qdt.as_slice(), trig),
            pair: [pair[0] - 1, pair[1] - 1],
            chassis: (qc.as_slice(), qdc.as_slice(), &self.work.part_rotations),
            contacts: &self.work.contacts,
            jacobians: &self.work.jacobians,
            chassis_contacts: (&self.work.chassis_contacts, &self.work.chassis_jacobians),
            arms: &self.config.arms,
            drive,
            points: GroundPoints {
                per_link: points,
                unit: self.stiction_scale,
                touching: &self.work.ground_normal,
                relaxation,
            },
        };
        implicit
            .linearise(&at, track.joint_forces(), chassis_mass.as_slice())
            .map_err(|source| SimulationError::Dynamics { t, source })
    }

    fn factor(&mut self, t: f64, a: f64) -> Result<(), SimulationError> {
        let implicit = self
            .implicit
            .as_mut()
            .ok_or(SimulationError::SingularMatrix {
                t,
                what: "the vehicle's own W (factored before it was linearised)",
            })?;
        implicit
            .factor(a)
            .map_err(|source| SimulationError::Dynamics { t, source })
    }

    fn solve(&mut self, t: f64, b: &mut [f64]) -> Result<(), SimulationError> {
        let implicit = self
            .implicit
            .as_mut()
            .ok_or(SimulationError::SingularMatrix {
                t,
                what: "the vehicle's own W (solved before it was linearised)",
            })?;
        implicit.solve(b);
        Ok(())
    }
}

/// The drive's sprocket body and slopes, and a lifted ground point's
/// relaxation rate ([`VehicleSystem::slopes`]).
type DriveAndRelaxation = (Option<(usize, super::DriveSlopes)>, Option<f64>);

/// The idle speed an engine whose speed is a state starts at, rad/s (its
/// map's first speed); `None` where the powertrain makes it no state.
fn engine_idle(config: &VehicleConfig) -> Option<f64> {
    match &config.powertrain {
        Some(Powertrain::Converter(driveline)) if driveline.dynamics.is_some() => {
            Some(driveline.engine[0].0)
        }
        _ => None,
    }
}
