use nalgebra::{DVector, SVector, Vector2};

use super::Drive;
use crate::closure::ClosureMethod;
use crate::contact::ground::GroundContact;
use crate::contact::sprocket::{SprocketContact, ToothProfile, pitch_radius};
use crate::contact::wheel::WheelContact;
use crate::contact::{BodyState, ContactForce, Friction, NormalLaw, ShoeGeometry, Terrain};
use crate::integrate::OdeSystem;
use crate::model::{ArmSpring, BodyLoad, ChassisModel, PartKind, TrackModel};
use crate::simulate::{Pair, Simulated, SimulationError, Switch, TrackSystem, TreeSystem};
use crate::suspension::{add_arm_torques_of, arm_dissipation_of, arm_energy_of, declared_arms};

/// How a vehicle meets the world: shoe geometry, the three contact pairs,
/// the arms' springs and the drive. Nothing here enters the mass matrix:
/// every field can be changed at run time, between runs, without
/// recompiling (a vehicle declared with `model!` gives its declared values
/// from `Name::config`).
#[derive(Debug)]
pub struct VehicleConfig {
    /// The shoes' contact features.
    pub shoe: ShoeGeometry,
    /// Track on terrain.
    pub ground: GroundContact,
    /// Track on road wheels, idler and rollers.
    pub wheels: WheelContact,
    /// Track on sprocket teeth.
    pub sprocket: SprocketContact,
    /// The sprocket drive.
    pub drive: Drive,
    /// The link (numbered from 1) whose joint to the next is recorded as
    /// `tension`.
    pub tension_link: usize,
    /// The arms' torsion springs and dampers, one per arm of the chassis
    /// (any order), replacing the rates compiled into the chassis model;
    /// `None` runs with the compiled ones ([`ChassisModel::PARTS`]).
    pub arms: Option<Vec<ArmSpring>>,
}

impl VehicleConfig {
    /// The default normal law of shoes on the ground: Hunt-Crossley,
    /// `k` = 2e6 N/m per shoe point, exponent 1, `χ` = 2 s/m (see
    /// [`m113`](Self::m113) for why).
    pub const GROUND_LAW: NormalLaw = NormalLaw::HuntCrossley {
        stiffness: 2e6,
        exponent: 1.0,
        chi: 2.0,
    };
    /// The default friction of shoes on the ground: μ = 0.8 over 0.1 m/s
    /// of slip.
    pub const GROUND_FRICTION: Friction = Friction { mu: 0.8, slip: 0.1 };
    /// The default normal law of the track on wheel rims and sprocket
    /// teeth: Hunt-Crossley, `k` = 1e7 N/m, exponent 1, `χ` = 0.5 s/m.
    pub const RIM_LAW: NormalLaw = NormalLaw::HuntCrossley {
        stiffness: 1e7,
        exponent: 1.0,
        chi: 0.5,
    };
    /// The default friction of the track on rims and teeth: μ = 0.4 over
    /// 0.5 m/s of slip.
    pub const RIM_FRICTION: Friction = Friction { mu: 0.4, slip: 0.5 };

    /// A vehicle with these shoes and sprocket teeth on `terrain`, driven
    /// by `drive`, with the default contact laws ([`GROUND_LAW`](Self::GROUND_LAW),
    /// [`GROUND_FRICTION`](Self::GROUND_FRICTION), [`RIM_LAW`](Self::RIM_LAW)
    /// and [`RIM_FRICTION`](Self::RIM_FRICTION) on wheels and sprocket),
    /// tension recorded at link 1 and the arms' compiled springs.
    pub fn new(
        shoe: ShoeGeometry,
        profile: ToothProfile,
        terrain: Terrain,
        drive: Drive,
    ) -> VehicleConfig {
        VehicleConfig {
            shoe,
            ground: GroundContact {
                terrain,
                normal: Self::GROUND_LAW,
                friction: Self::GROUND_FRICTION,
            },
            wheels: WheelContact {
                normal: Self::RIM_LAW,
                friction: Self::RIM_FRICTION,
            },
            sprocket: SprocketContact {
                profile,
                normal: Self::RIM_LAW,
                friction: Self::RIM_FRICTION,
            },
            drive,
            tension_link: 1,
            arms: None,
        }
    }

    /// The M113's contact (shoes and sprocket of `shared/spec/m113.md`,
    /// friction 0.8 on the ground and 0.4 on wheels and sprocket) on
    /// `terrain`, driven by `drive`: [`new`](Self::new) with
    /// [`ShoeGeometry::m113`] and [`ToothProfile::m113`]. The vehicle
    /// declared in `trackgen::vehicles::m113` gives the same from its
    /// declaration (`M113::config`).
    ///
    /// Normal laws are Hunt-Crossley with exponent 1 (`F = k δ (1 + χ δ̇)`:
    /// no force jump when a contact opens or closes, which would make an
    /// adaptive integrator stumble at each of the thousands of contact
    /// changes of a run). Stiffnesses: ground 2e6 N/m per shoe point, rims
    /// and teeth 1e7 N/m, so static penetrations stay within a few
    /// millimetres. The `χ` (2 and 0.5 s/m) damp the contacts without
    /// making the light shoes' rotation the stiffest mode of the model.
    /// Friction is regularised over 0.1 m/s of slip on the ground, where it
    /// carries the traction, and over 0.5 m/s on rims and teeth, where it
    /// only spins the wheels up and rubs the flanks: the friction slope
    /// `μ F_n / v_s` on an 18 kg shoe under a loaded rim is the stiffest mode
    /// of the model, and sets the explicit integrator's step (measured: the
    /// step grows 1.75× from 0.2 to 0.5 m/s; without rim friction at all,
    /// 2×).
    pub fn m113(terrain: Terrain, drive: Drive) -> VehicleConfig {
        Self::new(ShoeGeometry::m113(), ToothProfile::m113(), terrain, drive)
    }
}

impl VehicleConfig {
    /// Moves the rest angle of the tensioner's spring to where the
    /// assembly set the arm (`assembled.tensioner`), as a track adjuster
    /// does: the tensioner then pushes with its declared preload at the
    /// start, and the track's tension comes from that preload, not from a
    /// spring wound up by however far the assembly swung the arm. In
    /// `τ = preload − k φ`, the preload becomes `preload + k φ₀` (the
    /// arms' compiled rates are copied into [`arms`](Self::arms) first if
    /// it is `None`). Nothing changes without a tensioner.
    pub fn adjust_tensioner<C: ChassisModel<DC>, const DC: usize, const DT: usize>(
        &mut self,
        assembled: &super::Assembled<DT, DC>,
    ) {
        let Some((body, angle)) = assembled.tensioner else {
            return;
        };
        let arms = self
            .arms
            .get_or_insert_with(|| declared_arms::<C, DC>().copied().collect());
        for arm in arms.iter_mut().filter(|a| a.body == body) {
            arm.preload += arm.stiffness * angle;
        }
    }
}

/// The arms' springs a vehicle runs with: `arms` if given, checked to be
/// one per arm of `C` with finite rates, stiffness and damping zero or
/// more; otherwise the compiled ones.
fn checked_arms<C: ChassisModel<DC>, const DC: usize>(
    arms: Option<&[ArmSpring]>,
) -> Result<Vec<ArmSpring>, SimulationError> {
    let declared: Vec<ArmSpring> = declared_arms::<C, DC>().copied().collect();
    let Some(arms) = arms else {
        return Ok(declared);
    };
    let mut bodies: Vec<usize> = arms.iter().map(|a| a.body).collect();
    let mut expected: Vec<usize> = declared.iter().map(|a| a.body).collect();
    bodies.sort_unstable();
    expected.sort_unstable();
    if bodies != expected {
        return Err(SimulationError::Setup(format!(
            "the configured arms act on bodies {bodies:?}; the chassis has arms at bodies {expected:?}"
        )));
    }
    for arm in arms {
        let rates_ok = arm.stiffness >= 0.0 && arm.damping >= 0.0;
        let finite = [arm.stiffness, arm.damping, arm.preload]
            .iter()
            .all(|v| v.is_finite());
        if !(rates_ok && finite) {
            return Err(SimulationError::Setup(format!(
                "the arm at body {} needs finite stiffness and damping of zero or more and a finite preload, \
                 got stiffness {}, damping {}, preload {}",
                arm.body, arm.stiffness, arm.damping, arm.preload
            )));
        }
    }
    Ok(arms.to_vec())
}

/// The quantities a vehicle records after its track's and chassis' own.
const RECORDED: [&str; 16] = [
    "x",
    "y",
    "pitch",
    "speed",
    "sprocket_speed",
    "sprocket_torque",
    "tension",
    "tension_tight",
    "tension_slack",
    "ground_normal",
    "ground_penetration",
    "wheel_penetration",
    "sprocket_penetration",
    "energy",
    "motor_work",
    "dissipated",
];

/// What the contacts did at one evaluation.
#[derive(Debug, Clone, Copy, Default)]
struct ContactSummary {
    ground_normal: f64,
    ground_penetration: f64,
    wheel_penetration: f64,
    sprocket_penetration: f64,
    potential: f64,
    dissipation: f64,
    torque: f64,
    integral_rate: f64,
}

impl ContactSummary {
    /// Books a contact's energy terms; returns its penetration.
    fn book(&mut self, contact: &ContactForce) -> f64 {
        self.potential += contact.potential;
        self.dissipation += contact.dissipation;
        contact.penetration
    }
}

/// A vehicle: its track and chassis integrated together, coupled by the
/// contact forces, with sprung arms and a drive.
///
/// Every recorded quantity is finite: one that is not (see
/// [`observe`](Simulated::observe)) stops the run with a
/// [`SimulationError::NonFinite`] naming it.
///
/// State: the track's, the chassis' `[q_i, q̇_i]`, then the drive
/// controller's integral (rad), the motor's work and the dissipated work
/// (J, integrated alongside so the energy balance is exact to the
/// integration tolerance).
pub struct VehicleSystem<T: TrackModel<DT>, const DT: usize, C: ChassisModel<DC>, const DC: usize> {
    /// Track and chassis, their states side by side.
    bodies: Pair<TrackSystem<T, DT>, TreeSystem<C, DC>>,
    config: VehicleConfig,
    /// Index of the sprocket in `C::PARTS`.
    sprocket: Option<usize>,
    sprocket_radius: f64,
    /// The arms' springs in force: the configuration's, or the compiled.
    arms: Vec<ArmSpring>,
    /// `ū2` of every link: the joint to the next.
    forward_joints: Vec<Vector2<f64>>,
    /// What an evaluation works in, allocated once.
    scratch: Scratch,
    y0: DVector<f64>,
}

/// The buffers of an evaluation.
struct Scratch {
    track_loads: Vec<BodyLoad>,
    chassis_loads: Vec<BodyLoad>,
    links: Vec<BodyState>,
    parts: Vec<BodyState>,
    /// `(sin θ, cos θ)` of every chassis body.
    part_trig: Vec<(f64, f64)>,
    positions: Vec<Vector2<f64>>,
    velocities: Vec<Vector2<f64>>,
}

/// The drive's integral, the motor's work and the dissipated work: the
/// three states a vehicle integrates after its bodies'.
const EXTRA_STATES: usize = 3;

impl<T: TrackModel<DT>, const DT: usize, C: ChassisModel<DC>, const DC: usize>
    VehicleSystem<T, DT, C, DC>
{
    /// The vehicle starting at rest at the given coordinates (see
    /// [`assemble`](super::assemble)), its loop closed by `closure`.
    ///
    /// A [`SimulationError::Setup`] for a configuration that makes no
    /// vehicle: a terrain that fails [`Terrain::check`], a drive that
    /// fails [`Drive::check`], a tension link that is not a link, a
    /// sprocket of fewer than 3 teeth, configured [`arms`](VehicleConfig::arms)
    /// that are not one per arm of the chassis or have rates that are
    /// negative or not finite. A target speed or torque schedule
    /// that turns NaN or infinite stops the run when the drive meets it
    /// ([`Drive::checked_torque`]).
    pub fn new(
        track: T,
        chassis: C,
        q_track: SVector<f64, DT>,
        q_chassis: SVector<f64, DC>,
        closure: ClosureMethod,
        config: VehicleConfig,
    ) -> Result<Self, SimulationError> {
        if config.tension_link == 0 || config.tension_link > T::BODIES {
            return Err(SimulationError::Setup(format!(
                "tension_link {} is not a link (1 to {})",
                config.tension_link,
                T::BODIES
            )));
        }
        config
            .ground
            .terrain
            .check()
            .map_err(|e| SimulationError::Setup(e.to_string()))?;
        config.drive.check().map_err(SimulationError::Setup)?;
        if config.sprocket.profile.teeth < 3 {
            return Err(SimulationError::Setup(format!(
                "a sprocket needs at least 3 teeth, the profile has {}",
                config.sprocket.profile.teeth
            )));
        }
        let arms = checked_arms::<C, DC>(config.arms.as_deref())?;
        let track = TrackSystem::new(track, q_track, SVector::zeros(), closure)?;
        let chassis = TreeSystem::chassis(chassis, q_chassis, SVector::zeros());
        let sprocket = C::PARTS.iter().position(|p| p.kind == PartKind::Sprocket);
        let pitch = track
            .model()
            .description()
            .link_spans()
            .map_or(0.0, |s| s[0].norm());
        let sprocket_radius = pitch_radius(config.sprocket.profile.teeth, pitch);
        let description = track.model().description();
        let forward_joints = (0..T::BODIES)
            .map(|j| match description.bodies.get(j + 1) {
                Some(next) => next.at_parent,
                None => description
                    .loop_joint
                    .map_or(Vector2::zeros(), |l| l.last_u2),
            })
            .collect();
        let bodies = Pair::new(track, "track", chassis, "chassis");
        let start = bodies.initial_state();
        let y0 = DVector::from_iterator(
            start.len() + EXTRA_STATES,
            start.iter().copied().chain([0.0; EXTRA_STATES]),
        );
        let largest = T::BODIES.max(C::BODIES);
        let resting = BodyState::new(Vector2::zeros(), 0.0, Vector2::zeros(), 0.0);
        Ok(VehicleSystem {
            bodies,
            config,
            sprocket,
            sprocket_radius,
            arms,
            forward_joints,
            scratch: Scratch {
                track_loads: vec![BodyLoad::ZERO; T::BODIES],
                chassis_loads: vec![BodyLoad::ZERO; C::BODIES],
                links: vec![resting; T::BODIES],
                parts: vec![resting; C::BODIES],
                part_trig: vec![(0.0, 1.0); C::BODIES],
                positions: vec![Vector2::zeros(); largest],
                velocities: vec![Vector2::zeros(); largest],
            },
            y0,
        })
    }

    /// The configuration.
    pub fn config(&self) -> &VehicleConfig {
        &self.config
    }

    /// The track subsystem.
    pub fn track(&self) -> &TrackSystem<T, DT> {
        self.bodies.first()
    }

    /// The chassis subsystem.
    pub fn chassis(&self) -> &TreeSystem<C, DC> {
        self.bodies.second()
    }

    /// The sprocket's pitch radius, m: track speed over sprocket speed.
    pub fn sprocket_radius(&self) -> f64 {
        self.sprocket_radius
    }

    /// The bodies' part of a state and the three extra states.
    fn split<'y>(&self, y: &'y [f64]) -> (&'y [f64], [f64; EXTRA_STATES]) {
        let (bodies, extra) = y.split_at(self.bodies.dimension());
        (bodies, [extra[0], extra[1], extra[2]])
    }

    /// Contact, suspension and drive loads at the track's kept recovery
    /// (whose trigonometry the links' states share) and the chassis'
    /// coordinates, into the load buffers.
    fn loads(
        &mut self,
        t: f64,
        (qc, qdc): (&SVector<f64, DC>, &SVector<f64, DC>),
        integral: f64,
    ) -> Result<ContactSummary, SimulationError> {
        let (qt, qdt, link_trig) = self.bodies.first().recovered();
        let Scratch {
            track_loads,
            chassis_loads,
            links,
            parts,
            part_trig,
            positions,
            velocities,
        } = &mut self.scratch;
        let (r, v) = (&mut positions[..T::BODIES], &mut velocities[..T::BODIES]);
        self.bodies
            .first()
            .model()
            .body_states_with_trig(link_trig, qt, qdt, r, v);
        for (b, link) in links.iter_mut().enumerate() {
            *link = BodyState::with_sin_cos(r[b], qt[2 + b], link_trig[b], v[b], qdt[2 + b]);
        }
        let (r, v) = (&mut positions[..C::BODIES], &mut velocities[..C::BODIES]);
        crate::sin_cos_each(&qc.as_slice()[2..], part_trig);
        self.bodies
            .second()
            .model()
            .body_states_with_trig(part_trig, qc, qdc, r, v);
        for (b, part) in parts.iter_mut().enumerate() {
            *part = BodyState::with_sin_cos(r[b], qc[2 + b], part_trig[b], v[b], qdc[2 + b]);
        }
        track_loads.fill(BodyLoad::ZERO);
        chassis_loads.fill(BodyLoad::ZERO);
        let mut s = ContactSummary::default();
        let config = &self.config;
        config
            .ground
            .apply(links, &config.shoe, track_loads, |_, c| {
                s.ground_normal += c.normal;
                let depth = s.book(c);
                s.ground_penetration = s.ground_penetration.max(depth);
            });
        for part in C::PARTS {
            let body = &parts[part.body];
            let load = &mut chassis_loads[part.body];
            if part.kind == PartKind::Sprocket {
                config
                    .sprocket
                    .apply(body, links, &config.shoe, track_loads, load, |_, c| {
                        let depth = s.book(c);
                        s.sprocket_penetration = s.sprocket_penetration.max(depth);
                    });
            } else {
                config.wheels.apply(
                    (body, part.radius),
                    links,
                    &config.shoe,
                    track_loads,
                    load,
                    |_, c| {
                        let depth = s.book(c);
                        s.wheel_penetration = s.wheel_penetration.max(depth);
                    },
                );
            }
        }
        add_arm_torques_of(&self.arms, qc, qdc, chassis_loads);
        s.dissipation += arm_dissipation_of(&self.arms, qdc);
        if let Some(i) = self.sprocket {
            let body = C::PARTS[i].body;
            let omega = qdc[2 + body] - qdc[2];
            let (torque, rate) =
                config
                    .drive
                    .checked_torque(t, omega, self.sprocket_radius, integral)?;
            chassis_loads[body].moment += torque;
            chassis_loads[0].moment -= torque;
            s.torque = torque;
            s.integral_rate = rate;
        }
        Ok(s)
    }

    /// The joints just before and just after the run of joints seated on
    /// the sprocket (within 2 cm of its pitch circle), in link order; when
    /// none is (the track has jumped the teeth), the joint nearest the
    /// pitch circle stands for the run, so that a run that goes on has
    /// span tensions to record. `None` only if every joint is seated. The
    /// loop is numbered counter-clockwise and runs clockwise round the
    /// chassis when driving forward, so the joint after the seated run is
    /// on the tight span (the top run, pulled into the sprocket) and the
    /// one before it on the slack span.
    fn sprocket_spans(
        &self,
        qt: &SVector<f64, DT>,
        qc: &SVector<f64, DC>,
    ) -> Option<(usize, usize)> {
        let part = &C::PARTS[self.sprocket?];
        let mut centres = vec![Vector2::zeros(); C::BODIES];
        self.chassis().model().body_positions(qc, &mut centres);
        let centre = centres[part.body];
        let mut links = vec![Vector2::zeros(); T::BODIES];
        self.track().model().body_positions(qt, &mut links);
        let n = T::BODIES;
        let off: Vec<f64> = (0..n)
            .map(|j| {
                let joint = links[j] + crate::planar::rotate(qt[2 + j], self.forward_joints[j]);
                ((joint - centre).norm() - self.sprocket_radius).abs()
            })
            .collect();
        let nearest = off.iter().copied().fold(f64::INFINITY, f64::min);
        let seated: Vec<bool> = off.iter().map(|&o| o < 0.02 || o <= nearest).collect();
        let first = (0..n).find(|&j| seated[j] && !seated[(j + n - 1) % n])?;
        let last = (0..n)
            .map(|k| (first + k) % n)
            .take_while(|&j| seated[j])
            .last()?;
        Some(((first + n - 1) % n, (last + 1) % n))
    }

    fn sprocket_omega(&self, qdc: &SVector<f64, DC>) -> f64 {
        self.sprocket
            .map_or(0.0, |i| qdc[2 + C::PARTS[i].body] - qdc[2])
    }

    /// The loads at a state: the track's coordinates recovered (kept by
    /// the track system), the chassis', and the contact, suspension and
    /// drive loads there, given to both subsystems.
    #[allow(clippy::type_complexity)]
    fn evaluate(
        &mut self,
        t: f64,
        y: &[f64],
    ) -> Result<(ContactSummary, (SVector<f64, DC>, SVector<f64, DC>)), SimulationError> {
        let (bodies, [integral, ..]) = self.split(y);
        let (yt, yc) = self.bodies.split(bodies);
        self.bodies.parts_mut().0.recover(t, yt)?;
        let (qc, qdc) = TreeSystem::<C, DC>::split(yc);
        let s = self.loads(t, (&qc, &qdc), integral)?;
        let (track, chassis) = self.bodies.parts_mut();
        track.set_external(&self.scratch.track_loads);
        chassis.set_external(&self.scratch.chassis_loads);
        Ok((s, (qc, qdc)))
    }
}

impl<T: TrackModel<DT>, const DT: usize, C: ChassisModel<DC>, const DC: usize> OdeSystem
    for VehicleSystem<T, DT, C, DC>
{
    fn dimension(&self) -> usize {
        self.y0.len()
    }

    fn derivative(&mut self, t: f64, y: &[f64], dy: &mut [f64]) -> Result<(), SimulationError> {
        let (s, (_, qdc)) = self.evaluate(t, y)?;
        let nb = self.bodies.dimension();
        let (_, yc) = self.bodies.split(&y[..nb]);
        let (dy_bodies, extra) = dy.split_at_mut(nb);
        let (dyt, dyc) = self.bodies.split_mut(dy_bodies);
        let (track, chassis) = self.bodies.parts_mut();
        track.derivative_recovered(t, dyt)?;
        chassis.derivative(t, yc, dyc)?;
        let (qt, qdt, _) = self.track().recovered();
        extra[0] = s.integral_rate;
        extra[1] = s.torque * self.sprocket_omega(&qdc);
        extra[2] = s.dissipation + self.track().closure_energy(qt, qdt).1;
        Ok(())
    }
}

impl<T: TrackModel<DT>, const DT: usize, C: ChassisModel<DC>, const DC: usize> Simulated
    for VehicleSystem<T, DT, C, DC>
{
    fn initial_state(&self) -> DVector<f64> {
        self.y0.clone()
    }

    fn columns(&self) -> Vec<String> {
        let mut c = self.bodies.columns();
        c.extend(RECORDED.map(String::from));
        c
    }

    fn observe(&mut self, t: f64, y: &[f64], row: &mut Vec<f64>) -> Result<(), SimulationError> {
        let (bodies, [_, work, dissipated]) = self.split(y);
        self.bodies.observe(t, bodies, row)?;
        let (s, (qc, qdc)) = self.evaluate(t, y)?;
        let (track, _) = self.bodies.parts_mut();
        track.accelerations(t)?;
        let mut all = Vec::with_capacity(T::BODIES);
        track.tensions(&mut all);
        let (qt, qdt, _) = self.track().recovered();
        let (qt, qdt) = (*qt, *qdt);
        let tension = all
            .get(self.config.tension_link - 1)
            .copied()
            .unwrap_or(f64::NAN);
        let (slack, tight) = match self.sprocket_spans(&qt, &qc) {
            Some((before, after)) => (all.get(before).copied(), all.get(after).copied()),
            None => (None, None),
        };
        let (track, chassis) = (self.track().model(), self.chassis().model());
        let energy = track.kinetic_energy(&qt, &qdt)
            + track.potential_energy(&qt)
            + chassis.kinetic_energy(&qc, &qdc)
            + chassis.potential_energy(&qc)
            + arm_energy_of(&self.arms, &qc)
            + s.potential
            + self.track().closure_energy(&qt, &qdt).0;
        row.extend([
            qc[0],
            qc[1],
            qc[2],
            qdc[0],
            self.sprocket_omega(&qdc),
            s.torque,
            tension,
            tight.unwrap_or(f64::NAN),
            slack.unwrap_or(f64::NAN),
            s.ground_normal,
            s.ground_penetration,
            s.wheel_penetration,
            s.sprocket_penetration,
            energy,
            work,
            dissipated,
        ]);
        Ok(())
    }

    fn after_step(
        &mut self,
        t: f64,
        y: &mut [f64],
        switched: &mut dyn FnMut(Switch),
    ) -> Result<bool, SimulationError> {
        let nb = self.bodies.dimension();
        self.bodies.after_step(t, &mut y[..nb], switched)
    }
}
