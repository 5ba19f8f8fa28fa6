//! A vehicle in motion: track and chassis integrated together, coupled by
//! contact, with sprung arms, a drive and rigid ground or soft soil.

use nalgebra::{DVector, SVector, Vector2};

use super::config::{VehicleConfig, checked_arms};
use crate::closure::ClosureMethod;
use crate::contact::soft_ground::Rut;
use crate::contact::sprocket::pitch_radius;
use crate::contact::{BodyState, ContactForce};
use crate::integrate::OdeSystem;
use crate::model::{ArmSpring, BodyLoad, ChassisModel, PartKind, TrackModel};
use crate::simulate::{Pair, Simulated, SimulationError, Switch, TrackSystem, TreeSystem};
use crate::suspension::{add_arm_torques_of, arm_dissipation_of, arm_energy_of};

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
/// integration tolerance); on soft soil, then the shear displacement `j`
/// (m) of every shoe ground point, link by link, grown by the point's
/// slip speed while it bears on the soil and reset when it leaves it.
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
    /// `dj/dt` of every shoe ground point on soft soil.
    shear_rate: Vec<f64>,
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
    /// vehicle: a terrain that fails [`Terrain::check`](crate::contact::Terrain::check), a drive that
    /// fails [`Drive::check`](super::Drive::check), a tension link that is not a link, a
    /// sprocket of fewer than 3 teeth, configured [`arms`](VehicleConfig::arms)
    /// that are not one per arm of the chassis or have rates that are
    /// negative or not finite. A target speed or torque schedule
    /// that turns NaN or infinite stops the run when the drive meets it
    /// ([`Drive::checked_torque`](super::Drive::checked_torque)).
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
        if let Some(soil) = &config.soil {
            soil.soil
                .check()
                .map_err(|e| SimulationError::Setup(e.to_string()))?;
            if soil.terrain != config.ground.terrain {
                return Err(SimulationError::Setup(
                    "the soil's surface is not the ground's terrain: set the soil with VehicleConfig::on_soil after the terrain".to_string(),
                ));
            }
        }
        if !config.drawbar_pull.is_finite() {
            return Err(SimulationError::Setup(format!(
                "drawbar_pull {} N is not a finite number",
                config.drawbar_pull
            )));
        }
        let shear_states = if config.soil.is_some() {
            T::BODIES * config.shoe.ground_points.len()
        } else {
            0
        };
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
            start.len() + EXTRA_STATES + shear_states,
            start
                .iter()
                .copied()
                .chain(std::iter::repeat_n(0.0, EXTRA_STATES + shear_states)),
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
                shear_rate: vec![0.0; shear_states],
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

    /// The bodies' part of a state, the three extra states and the shear
    /// displacements.
    fn split<'y>(&self, y: &'y [f64]) -> (&'y [f64], [f64; EXTRA_STATES], &'y [f64]) {
        let (bodies, extra) = y.split_at(self.bodies.dimension());
        let (extra, shear) = extra.split_at(EXTRA_STATES);
        (bodies, [extra[0], extra[1], extra[2]], shear)
    }

    /// The soft soil's memory, if the vehicle drives on soil: the rut it
    /// has left so far.
    pub fn rut(&self) -> Option<&Rut> {
        self.config.soil.as_ref().map(|s| &s.rut)
    }

    /// Contact, suspension and drive loads at the track's kept recovery
    /// (whose trigonometry the links' states share) and the chassis'
    /// coordinates, into the load buffers.
    fn loads(
        &mut self,
        t: f64,
        (qc, qdc): (&SVector<f64, DC>, &SVector<f64, DC>),
        integral: f64,
        shear: &[f64],
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
            shear_rate,
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
        let mut on_ground = |_: usize, c: &ContactForce| {
            s.ground_normal += c.normal;
            let depth = s.book(c);
            s.ground_penetration = s.ground_penetration.max(depth);
        };
        match &config.soil {
            None => config
                .ground
                .apply(links, &config.shoe, track_loads, on_ground),
            Some(soil) => soil.apply(
                links,
                &config.shoe,
                track_loads,
                shear,
                shear_rate,
                &mut on_ground,
            ),
        }
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
        // The drawbar pulls the chassis back at its centroid; the power it
        // takes out, `F v`, is booked as dissipated.
        chassis_loads[0].force.x -= config.drawbar_pull;
        s.dissipation += config.drawbar_pull * qdc[0];
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
    /// `trig` holds every link's `(sin θ, cos θ)` at `qt`.
    fn sprocket_spans(
        &self,
        (qt, trig): (&SVector<f64, DT>, &[(f64, f64)]),
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
                let joint = links[j] + crate::planar::rotate_by(trig[j], self.forward_joints[j]);
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

    /// After an accepted step on soft soil: the rut pressed wherever a
    /// ground point has sunk deeper than the soil remembers, and the shear
    /// displacement of every point off the ground reset
    /// ([`SoftGround::press`](crate::contact::soft_ground::SoftGround::press)).
    /// Returns whether the right-hand side changed (the integrator must
    /// then restart).
    fn press_soil(&mut self, t: f64, y: &mut [f64]) -> Result<bool, SimulationError> {
        let nb = self.bodies.dimension();
        let (bodies, rest) = y.split_at_mut(nb);
        let (yt, _) = self.bodies.split(bodies);
        let track = self.bodies.parts_mut().0;
        track.recover(t, yt)?;
        let (qt, _, trig) = track.recovered();
        let positions = &mut self.scratch.positions[..T::BODIES];
        track.model().body_positions(qt, positions);
        for (b, link) in self.scratch.links.iter_mut().enumerate() {
            *link =
                BodyState::with_sin_cos(positions[b], qt[2 + b], trig[b], Vector2::zeros(), 0.0);
        }
        let soil = self.config.soil.as_mut().expect("on soil");
        Ok(soil.press(
            &self.scratch.links,
            &self.config.shoe,
            &mut rest[EXTRA_STATES..],
        ))
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
        let (bodies, [integral, ..], shear) = self.split(y);
        let (yt, yc) = self.bodies.split(bodies);
        self.bodies.parts_mut().0.recover(t, yt)?;
        let (qc, qdc) = TreeSystem::<C, DC>::split(yc);
        let s = self.loads(t, (&qc, &qdc), integral, shear)?;
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
        // The chassis' trigonometry is the contact pass's, at this state.
        chassis.derivative_with_trig(t, yc, &self.scratch.part_trig, dyc)?;
        let (qt, qdt, _) = self.track().recovered();
        extra[0] = s.integral_rate;
        extra[1] = s.torque * self.sprocket_omega(&qdc);
        extra[2] = s.dissipation + self.track().closure_energy(qt, qdt).1;
        extra[EXTRA_STATES..].copy_from_slice(&self.scratch.shear_rate);
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
        let (bodies, [_, work, dissipated], _) = self.split(y);
        self.bodies.observe(t, bodies, row)?;
        let (s, (qc, qdc)) = self.evaluate(t, y)?;
        let (track, _) = self.bodies.parts_mut();
        track.accelerations(t)?;
        let mut all = Vec::with_capacity(T::BODIES);
        track.tensions(&mut all);
        let (qt, qdt, trig) = self.track().recovered();
        let (qt, qdt) = (*qt, *qdt);
        let spans = self.sprocket_spans((&qt, trig), &qc);
        let tension = all
            .get(self.config.tension_link - 1)
            .copied()
            .unwrap_or(f64::NAN);
        let (slack, tight) = match spans {
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
        let mut restart = self.bodies.after_step(t, &mut y[..nb], switched)?;
        if self.config.soil.is_some() {
            restart |= self.press_soil(t, y)?;
        }
        Ok(restart)
    }
}
