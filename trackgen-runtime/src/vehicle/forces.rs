//! Stages 2 and 3 of a vehicle's evaluation: contact detection, then the
//! force elements, each giving its load with what it stores and
//! dissipates, booked in one place ([`EnergyBooks`]).

use nalgebra::SVector;

use super::books::EnergyBooks;
use super::engine_drive::{AtSprocket, engine_drive};
use super::workspace::Workspace;
use super::{Engaged, EngineSide, Geometry, Powertrain, VehicleConfig, arms};
use crate::contact::outline::{self, Outline, TERRAIN_CORNER};
use crate::contact::soft_ground::SoftGround;
use crate::contact::{ContactJacobian, GroundFriction, ground, sprocket, wheel};
use crate::integrate::SimulationError;
use crate::multibody::{BodyLoad, ChassisModel, PartKind};

/// The fraction of a statically loaded point's sliding deflection that is
/// the unit of its stiction state ([`stiction_scale`]). The deflection is
/// integrated apart from the point's position, so its numerical creep
/// does work the books see: the unit must be small enough that the error
/// control holds that creep below the books' bound, and no smaller than
/// it needs to be, since every tenfold costs steps. The measurements that
/// chose a tenth are in docs/experiments/stiction-unit.md.
pub(super) const STICTION_UNIT_FRACTION: f64 = 0.1;

/// The unit (m) in which a vehicle integrates its ground points' stiction
/// deflections: [`STICTION_UNIT_FRACTION`] of the deflection at which a
/// point under its static load (`fit`'s) slides, `μ F / k`. A deflection
/// of a tenth of a millimetre holds hundreds of newtons; in metres,
/// against an absolute tolerance made for positions (1e-3 m), it would
/// not be controlled at all (the books at Bogacki-Shampine 1e-2 were off
/// by more than the work). In this unit its error is controlled as a
/// fraction of the force it holds. 1 for regularised friction (no
/// states) and on soft soil (the shear displacement, of the order of the
/// soil's `K`, is integrated in m).
pub(super) fn stiction_scale(friction: &GroundFriction, ground_load: f64) -> f64 {
    match friction {
        GroundFriction::Stiction(s) if s.stiffness > 0.0 => {
            (STICTION_UNIT_FRACTION * s.mu.max(0.1) * ground_load / s.stiffness)
                .max(f64::MIN_POSITIVE)
        }
        _ => 1.0,
    }
}

/// The outlines sharp terrain meets: the shoes' (the hull of their ground
/// points and inner face; `None` for a shoe of no area) and the hull's
/// (`None` when the declaration gives none).
#[derive(Debug, Clone)]
pub(super) struct Outlines {
    pub shoe: Option<Outline>,
    pub hull: Option<Outline>,
}

/// Stage 2, detection: every contact of the links (their states in
/// `work`) with the ground and with each part, into `work.contacts`; on
/// rigid ground the terrain's sharp corners inside the shoes too
/// ([`outline`]); and the hull's with the ground and the rims' with sharp
/// corners into `work.chassis_contacts`.
pub(super) fn detect<C: ChassisModel<DC>, const DC: usize>(
    work: &mut Workspace,
    config: &VehicleConfig,
    geometry: &Geometry,
    outlines: &Outlines,
) {
    let Workspace {
        links,
        parts,
        contacts,
        chassis_contacts,
        ..
    } = work;
    contacts.clear();
    chassis_contacts.clear();
    let shoe = &geometry.shoe;
    let clear = ground::clear_of(&config.terrain, links, shoe);
    ground::detect_culled(&config.terrain, links, shoe, &clear, contacts);
    if config.soil.is_none()
        && let Some(outline) = &outlines.shoe
    {
        outline::detect_track_corners(&config.terrain, links, (outline, &clear), contacts);
    }
    if let Some(hull) = &outlines.hull {
        outline::detect_hull(&config.terrain, &parts[0], hull, chassis_contacts);
    }
    for part in C::PARTS {
        let body = &parts[part.body];
        outline::detect_rim(
            &config.terrain,
            (body, part.body, part.radius),
            chassis_contacts,
        );
        if part.kind == PartKind::Sprocket {
            sprocket::detect((body, part.body), &geometry.sprocket, links, shoe, contacts);
        } else {
            wheel::detect((body, part.body, part.radius), links, shoe, contacts);
        }
    }
}

/// The drive's place on the chassis: the sprocket's body, its pitch
/// radius (m: where the seated joints lie) and its rolling radius (m:
/// the track's mean speed per unit of its speed,
/// [`track_speed`](crate::contact::sprocket::track_speed)).
#[derive(Debug, Clone, Copy)]
pub(super) struct Sprocket {
    pub body: usize,
    pub pitch_radius: f64,
    pub rolling_radius: f64,
    /// The powertrain's torque at rest, N m ([`VehicleConfig::stall_torque`]),
    /// found once when the vehicle is built: the powertrain does not
    /// change in a run (a brake removes it, and then nothing caps).
    pub stall: f64,
    /// The powertrain's torque at rest in reverse, N m (as `stall`
    /// without a reverse range).
    pub stall_reverse: f64,
    /// A scheduled gearbox's range, kept by the run as it shifts
    /// ([`Shift::next`](super::Shift::next)); `None`: shifted ideally.
    pub engaged: Option<Engaged>,
    /// Whether the lock-up clutch of an engine whose speed is a state is
    /// engaged, kept by the run ([`Driveline::lockup_next`](super::Driveline::lockup_next)).
    pub locked: bool,
}

impl Sprocket {
    /// The stall torque and the gearbox's state at `t`: the engaged range
    /// and whether the driver asks reverse (then the reverse stall).
    #[inline]
    pub fn gearbox(&self, config: &VehicleConfig, t: f64) -> (f64, (Option<Engaged>, bool)) {
        // Without a powertrain nothing reads it: the driver's demand is
        // not evaluated for it.
        let reverse = config.powertrain.is_some() && config.drive.asks_reverse(t);
        let stall = if reverse {
            self.stall_reverse
        } else {
            self.stall
        };
        (stall, (self.engaged, reverse))
    }

    /// What [`engine_drive`] reads of the sprocket at `t` turning at
    /// `omega` (rad/s).
    #[inline]
    pub(super) fn at(&self, config: &VehicleConfig, t: f64, omega: f64) -> AtSprocket {
        let (stall, gearbox) = self.gearbox(config, t);
        AtSprocket {
            omega,
            rolling_radius: self.rolling_radius,
            stall,
            gearbox,
            locked: self.locked,
        }
    }

    /// The sprocket's speed relative to the chassis, rad/s.
    #[inline]
    pub fn omega<const DC: usize>(&self, qdc: &SVector<f64, DC>) -> f64 {
        self.omega_of(qdc.as_slice())
    }

    /// [`omega`](Self::omega) from the chassis' rates as a slice.
    #[inline]
    pub fn omega_of(&self, qdc: &[f64]) -> f64 {
        qdc[2 + self.body] - qdc[2]
    }
}

/// The ground points' tangential states at an evaluation: one per ground
/// point, link by link; stiction deflections in units of `scale` m (see
/// [`stiction_scale`]) on rigid ground, the soil's shear displacements on
/// `soil`; empty with regularised friction.
#[derive(Clone, Copy)]
pub(super) struct TangentialStates<'a> {
    /// The soil, on soft ground.
    pub soil: Option<&'a SoftGround>,
    /// Ground points per link.
    pub per_link: usize,
    /// The states.
    pub values: &'a [f64],
    /// The unit of a stiction deflection, m (1 on soil).
    pub scale: f64,
}

/// The chassis and the drive at an evaluation.
#[derive(Clone, Copy)]
pub(super) struct ChassisState<'a, const DC: usize> {
    /// The chassis' `q_i` and `q̇_i`.
    pub q: &'a SVector<f64, DC>,
    /// The chassis' rates.
    pub qd: &'a SVector<f64, DC>,
    /// The drive's sprocket, if the chassis has one.
    pub sprocket: Option<Sprocket>,
    /// The drive controller's integral, rad.
    pub integral: f64,
    /// The engine's speed (rad/s) and the locked driveline's twist (rad),
    /// where they are states (else not read).
    pub engine: (f64, f64),
}

/// Stage 3, the force elements at time `t`, into `work`'s loads and
/// books: every contact's law (rigid ground, or the soil) with the ground
/// points' `tangential` states, the arms' springs and dampers, the
/// drawbar and the drive.
pub(super) fn respond<const DC: usize>(
    work: &mut Workspace,
    t: f64,
    config: &VehicleConfig,
    tangential: TangentialStates<'_>,
    chassis: ChassisState<'_, DC>,
) -> Result<(), SimulationError> {
    let TangentialStates {
        soil,
        per_link: points,
        values: tangential,
        scale,
    } = tangential;
    let ChassisState {
        q: qc,
        qd: qdc,
        sprocket,
        integral,
        engine,
    } = chassis;
    let Workspace {
        parts,
        contacts,
        chassis_contacts,
        track_loads,
        chassis_loads,
        tangential_rate,
        ground_normal,
        books,
        ..
    } = work;
    track_loads.fill(BodyLoad::ZERO);
    chassis_loads.fill(BodyLoad::ZERO);
    tangential_rate.fill(0.0);
    ground_normal.fill(None);
    *books = EnergyBooks::default();
    let sprocket_body = sprocket.map(|s| s.body);
    let corner_laws = config.corner_laws();
    for contact in contacts.iter() {
        let link_load = &mut track_loads[contact.link];
        match (contact.other, contact.ground_point_slot(points), soil) {
            // A terrain corner in a shoe: no tangential state.
            (None, None, _) => {
                let force = corner_laws.respond(contact);
                force.apply(contact, link_load, None);
                books.ground(&force);
            }
            (None, Some(slot), None) => {
                let z = tangential.get(slot).map_or(0.0, |w| w * scale);
                let (force, rate) = config.ground.respond(contact, z);
                if let Some(r) = tangential_rate.get_mut(slot) {
                    *r = rate / scale;
                    ground_normal[slot] = Some(force.normal);
                }
                force.apply(contact, link_load, None);
                books.ground(&force);
            }
            (None, Some(slot), Some(soil)) => {
                let (force, rate) = soil.respond(contact, points, tangential[slot]);
                tangential_rate[slot] = rate;
                // Below the surface the point shears the soil, bearing or
                // not: its state is coupled to its link.
                ground_normal[slot] = Some(force.map_or(0.0, |f| f.normal));
                if let Some(force) = force {
                    force.apply(contact, link_load, None);
                    books.ground(&force);
                }
            }
            (Some(body), ..) => {
                let on_teeth = Some(body) == sprocket_body;
                let laws = if on_teeth {
                    &config.sprocket
                } else {
                    &config.wheels
                };
                let force = laws.respond(contact);
                let other = (&mut chassis_loads[body], parts[body].position);
                force.apply(contact, link_load, Some(other));
                let depth = books.contact(&force);
                let deepest = if on_teeth {
                    &mut books.sprocket_penetration
                } else {
                    &mut books.wheel_penetration
                };
                *deepest = deepest.max(depth);
            }
        }
    }
    for contact in chassis_contacts.iter() {
        let force = corner_laws.respond(contact);
        force.apply(contact, &mut chassis_loads[contact.link], None);
        if contact.link == 0 {
            books.hull(&force);
        } else {
            let depth = books.contact(&force);
            books.wheel_penetration = books.wheel_penetration.max(depth);
        }
    }
    // Ground points off the ground: their stiction deflections relax.
    if let (None, GroundFriction::Stiction(stiction)) = (soil, config.ground.friction) {
        for ((w, rate), normal) in tangential
            .iter()
            .zip(tangential_rate.iter_mut())
            .zip(ground_normal.iter())
        {
            if normal.is_none() {
                let relaxing = stiction.relax(w * scale);
                *rate = relaxing.rate / scale;
                books.potential += relaxing.potential;
                books.dissipation += relaxing.dissipation;
            }
        }
    }
    let arm_books = arms::apply(&config.arms, qc, qdc, chassis_loads);
    books.arm_potential = arm_books.potential;
    // The drawbar pulls the chassis back at its centroid; the power it
    // takes out, `F v`, is booked as dissipated.
    chassis_loads[0].force.x -= config.drawbar_pull;
    books.dissipation += config.drawbar_pull * qdc[0];
    books.dissipation += arm_books.dissipation;
    if let Some(sprocket) = sprocket {
        drive(
            &sprocket,
            config,
            t,
            qdc,
            (integral, engine),
            chassis_loads,
            books,
        )?;
    }
    Ok(())
}

/// The drive's torque on the sprocket (and its reaction on the frame) at
/// time `t`: the speed controller's, capped by the powertrain in its gear
/// where there is one (through an engine whose speed is a state,
/// [`engine_drive`]); the engine's side, the controller integral's rate
/// and the engine's acceleration into `books`. Part of [`respond`].
#[inline(always)]
fn drive<const DC: usize>(
    sprocket: &Sprocket,
    config: &VehicleConfig,
    t: f64,
    qdc: &SVector<f64, DC>,
    (integral, engine): (f64, (f64, f64)),
    chassis_loads: &mut [BodyLoad],
    books: &mut EnergyBooks,
) -> Result<(), SimulationError> {
    let omega = sprocket.omega(qdc);
    if let Some(p @ Powertrain::Converter(driveline)) = &config.powertrain
        && driveline.dynamics.is_some()
    {
        let at = sprocket.at(config, t, omega);
        let drive = engine_drive(p, &config.drive, t, at, integral, (engine.0, engine.1, 0.0))?;
        books.engine_load = drive.fuel;
        books.engine = drive.side;
        books.engine_rate = [drive.engine_rate, drive.twist_rate];
        books.twist_energy = drive.twist_energy;
        chassis_loads[sprocket.body].moment += drive.torque;
        chassis_loads[0].moment -= drive.torque;
        books.torque = drive.torque;
        books.integral_rate = drive.integral_rate;
        return Ok(());
    }
    books.engine_rate = [0.0; 2];
    books.twist_energy = 0.0;
    let (stall, gearbox) = sprocket.gearbox(config, t);
    let (cap, own) = config.torque_cap_in_gear(omega, stall, gearbox);
    let (torque, rate) =
        config
            .drive
            .checked_torque(t, omega, sprocket.rolling_radius, integral, cap)?;
    books.engine_load = config
        .drive
        .engine_load(t, torque, omega, sprocket.rolling_radius, cap);
    books.engine = match (&config.powertrain, own) {
        // Driving: the torque pushes the way the driver asks, at `ω`
        // signed the torque's way (negative: forced back).
        (Some(powertrain), Some(own)) if books.engine_load > 0.0 => {
            powertrain.engine_side_near(own.gear, own.point, omega * torque.signum(), torque.abs())
        }
        // Braking: the engine gives nothing, the gearbox stays in its
        // range.
        (Some(_), own) => EngineSide {
            gear: own.and_then(|cap| cap.gear),
            ..EngineSide::IDLE
        },
        (None, _) => EngineSide {
            engine_power: torque * omega,
            turbine_power: torque * omega,
            ..EngineSide::IDLE
        },
    };
    chassis_loads[sprocket.body].moment += torque;
    chassis_loads[0].moment -= torque;
    books.torque = torque;
    books.integral_rate = rate;
    Ok(())
}

/// Stage 3 to first order: every contact's Jacobian ([`ContactJacobian`],
/// the derivatives of its loads on both bodies and of its tangential
/// state's rate over the two bodies' states and that state) into
/// `work.jacobians`, one per contact in `work.contacts`'s order, at the
/// state the last [`detect`] saw, with the ground points' `tangential`
/// states (a stiction deflection's column and row stay in metres).
pub(super) fn linearise(
    work: &mut Workspace,
    config: &VehicleConfig,
    geometry: &Geometry,
    sprocket: Option<Sprocket>,
    tangential: TangentialStates<'_>,
) {
    let TangentialStates {
        soil,
        per_link: points,
        values: tangential,
        scale,
    } = tangential;
    let Workspace {
        links,
        parts,
        contacts,
        jacobians,
        chassis_contacts,
        chassis_jacobians,
        ..
    } = work;
    let corner_laws = config.corner_laws();
    jacobians.resize(contacts.len(), ContactJacobian::ZERO);
    let sprocket_body = sprocket.map(|s| s.body);
    for (contact, out) in contacts.iter().zip(jacobians.iter_mut()) {
        let link = &links[contact.link];
        match (contact.other, contact.ground_point_slot(points)) {
            (None, None) => {
                let tangent = outline::tangent(contact);
                corner_laws.linearise(contact, &tangent, link, None, out);
            }
            (None, Some(slot)) => {
                let z = tangential.get(slot).map_or(0.0, |w| w * scale);
                let tangent = ground::tangent(&config.terrain, contact);
                match soil {
                    Some(soil) => soil.linearise(contact, points, z, &tangent, link, out),
                    None => config.ground.linearise(contact, z, &tangent, link, out),
                }
            }
            (Some(body), _) if Some(body) == sprocket_body => {
                let part = &parts[body];
                let profile = &geometry.sprocket;
                let tangent = sprocket::tangent(contact, link, part, profile, &geometry.shoe);
                config
                    .sprocket
                    .linearise(contact, &tangent, link, Some(part), out);
            }
            (Some(body), _) => {
                let part = &parts[body];
                let tangent = wheel::tangent(contact, link, part, &geometry.shoe);
                config
                    .wheels
                    .linearise(contact, &tangent, link, Some(part), out);
            }
        }
    }
    // The chassis' own contacts with the ground, the body in the `link`
    // rows and columns: a terrain corner in the hull turns with it; the
    // hull's corners below the ground meet it as ground points do; a rim
    // pushes straight off a corner.
    chassis_jacobians.resize(chassis_contacts.len(), ContactJacobian::ZERO);
    for (contact, out) in chassis_contacts.iter().zip(chassis_jacobians.iter_mut()) {
        let body = &parts[contact.link];
        let tangent = match (contact.link, contact.feature) {
            (0, TERRAIN_CORNER) => outline::tangent(contact),
            (0, _) => ground::tangent(&config.terrain, contact),
            _ => outline::rim_tangent(contact),
        };
        corner_laws.linearise(contact, &tangent, body, None, out);
    }
}
