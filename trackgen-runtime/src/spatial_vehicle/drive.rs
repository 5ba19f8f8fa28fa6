//! What the driveline ([`Driveline`]) does at a state: each side's
//! drive (the planar vehicle's [`Drive`](crate::vehicle::Drive) per
//! side), or the differential's drive halved with its brakes or steer
//! unit; its torque acting on each side's sprocket about its axle and,
//! reversed, on the frame.
//!
//! A planar torque `τ` (counter-clockwise in the track's plane seen from
//! the right, positive) is the moment `−τ η` in space, `η` the plane's
//! normal pointing left (as the arms' springs, `spatial_vehicle`'s
//! docs); its power on the sprocket and the frame together is `τ ω`,
//! `ω` the sprocket's speed relative to the frame, the planar vehicle's.

use nalgebra::Vector3;

use super::driveline::DRIVELINE;
use super::{
    Differential, DifferentialSteer, Driveline, EngineEnvelope, HeadingHold, SideDrives,
    SpatialDynamics, SpatialLoads, TreeState,
};
use crate::integrate::SimulationError;
use crate::multibody::{ChassisModel, TrackModel};
use crate::spatial::plane_rotation;
use crate::vehicle::{EngineSide, TorqueCap};

/// What drives the sprockets at a state: the driveline, the driver holding
/// a heading (if one is), the engine's envelope (if any) and the
/// driveline's five states
/// ([`SpatialSystem`](super::SpatialSystem)'s docs).
#[derive(Clone, Copy)]
pub struct Driver<'a> {
    /// How the drive reaches the sprockets.
    pub driveline: &'a Driveline,
    /// The driver holding a heading.
    pub steering: Option<&'a HeadingHold>,
    /// The engine's full-load envelope capping the drive.
    pub envelope: Option<&'a EngineEnvelope>,
    /// The driveline's states.
    pub states: [f64; DRIVELINE],
}

/// What the driveline does at a state: per side (right, left).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct DriveState {
    /// The sprocket's speed relative to the frame, rad/s (planar sense:
    /// driving forward turns it negative).
    pub speed: [f64; 2],
    /// The driveline's torque on it, N m (planar sense): the drive's
    /// share, the steer unit's and the brake's together.
    pub torque: [f64; 2],
    /// The steering brake's part of it, N m.
    pub brake: [f64; 2],
    /// The power the drive and the steer unit put in, W: the books'
    /// driven work's rate.
    pub driven: f64,
    /// The power the brakes dissipate, W.
    pub dissipation: f64,
    /// Each side's brake's part of it, W (right, left).
    pub braked: [f64; 2],
    /// The rates of the driveline's five states
    /// ([`SpatialSystem`](super::SpatialSystem)'s docs).
    pub rates: [f64; DRIVELINE],
    /// The engine's side where an engine whose speed is a state drives
    /// the differential ([`SpatialEngine`](super::SpatialEngine)): its
    /// speed, torque, range, converter and powers (the whole engine's).
    pub engine: Option<EngineSide>,
}

impl DriveState {
    /// The power the driveline puts into the sprockets, W: `Σ τ ω` (the
    /// drive's and the steer unit's less what the brakes take).
    pub fn power(&self) -> f64 {
        self.side_power(0) + self.side_power(1)
    }

    /// The power the driveline puts into side `s`'s sprocket (0 right, 1
    /// left), W: `τ ω`, its brake's torque included.
    pub fn side_power(&self, s: usize) -> f64 {
        self.torque[s] * self.speed[s]
    }
}

impl<H, const DH: usize, R, const DR: usize, L, const DL: usize>
    SpatialDynamics<'_, H, DH, R, DR, L, DL>
where
    H: ChassisModel<DH>,
    R: TrackModel<DR>,
    L: TrackModel<DL>,
{
    /// What the driveline does at time `t` and the hull's state, with its
    /// three `states`, the engine's envelope capping its drive, and the
    /// driver's `steering`, if any (a belt-speed difference asked for,
    /// [`HeadingHold::difference`]; without one a differential steers by
    /// its input schedule): a side without a sprocket takes no torque; a
    /// drive's demand, a heading wanted or a steering input that is not
    /// finite stops the run
    /// ([`Drive::checked_torque`](crate::vehicle::Drive::checked_torque)),
    /// and so does a steering input outside `[−1, 1]`.
    pub fn drive(
        &self,
        t: f64,
        hull: &TreeState<DH>,
        driver: Driver<'_>,
    ) -> Result<DriveState, SimulationError> {
        let Driver {
            driveline,
            steering,
            envelope,
            states,
        } = driver;
        let asked = match steering {
            None => None,
            Some(hold) => Some(hold.difference(t, hull.pose.yaw, self.gauge).ok_or(
                SimulationError::NonFinite {
                    t,
                    what: "the steering's heading",
                },
            )?),
        };
        let mut state = DriveState {
            speed: self.sprocket_speeds(hull),
            ..DriveState::default()
        };
        match driveline {
            Driveline::Sides(drives) => self.drive_sides(
                t,
                (drives, envelope),
                asked.unwrap_or(0.0),
                states,
                &mut state,
            )?,
            Driveline::Differential(differential) => self.drive_differential(
                t,
                hull,
                (differential, envelope),
                asked,
                states,
                &mut state,
            )?,
        }
        Ok(state)
    }

    /// Each side's drive on its own sprocket, a speed drive's target
    /// trimmed by half the `difference` asked (the right's up, the
    /// left's down), each capped by a side's share of the `envelope` at
    /// its own speed.
    fn drive_sides(
        &self,
        t: f64,
        (drives, envelope): (&SideDrives, Option<&EngineEnvelope>),
        difference: f64,
        states: [f64; DRIVELINE],
        state: &mut DriveState,
    ) -> Result<(), SimulationError> {
        for (s, drive) in drives.each().into_iter().enumerate() {
            let Some(sprocket) = self.sprockets[s] else {
                continue;
            };
            // Right (index 0) outside in a left turn.
            let trim = [0.5, -0.5][s] * difference;
            let cap = envelope.map_or(TorqueCap::NONE, |e| e.side(state.speed[s]));
            let (torque, rate) = drive.checked_torque_trimmed(
                (t, trim),
                state.speed[s],
                sprocket.rolling_radius,
                states[s],
                cap,
            )?;
            state.torque[s] = torque;
            state.rates[s] = rate;
        }
        state.driven = state.power();
        Ok(())
    }

    /// The differential's drive halved to both sprockets, and its brakes
    /// or steer unit, steered by the belt-speed difference `asked` or
    /// else by the input schedule. Through an engine whose speed is a
    /// state, the box's torque is what the engine gives it, loaded by
    /// what the steer unit draws ([`SpatialEngine`](super::SpatialEngine));
    /// else the drive is capped by both sides' share of the `envelope` at
    /// their mean speed, less what the steer unit draws from the engine.
    fn drive_differential(
        &self,
        t: f64,
        hull: &TreeState<DH>,
        (differential, envelope): (&Differential, Option<&EngineEnvelope>),
        asked: Option<f64>,
        states: [f64; DRIVELINE],
        state: &mut DriveState,
    ) -> Result<(), SimulationError> {
        let radius = self.mean_rolling_radius();
        let omega = state.speed;
        let mean = 0.5 * (omega[0] + omega[1]);
        let input = || -> Result<f64, SimulationError> {
            let s = (differential.input)(t);
            if s.is_nan() {
                return Err(SimulationError::NonFinite {
                    t,
                    what: "the steering input",
                });
            }
            if !(-1.0..=1.0).contains(&s) {
                return Err(SimulationError::Stopped {
                    t,
                    reason: "the steering input is outside -1 (full right) to 1 (full left)",
                });
            }
            Ok(s)
        };
        match &differential.steer {
            DifferentialSteer::Brakes(brakes) => {
                // A driver brakes on what the hull does: the difference
                // asked against the gauge times the heading's rate (the
                // belts' difference that turns the hull so without slip),
                // not against the sprockets' speeds, which carry the
                // teeth's and wheels' ripple. Braking on the difference
                // asked alone, a clutch-brake turn overshoots and rings.
                let lever = match asked {
                    Some(asked) => {
                        let yaw_rate = hull.pose.yaw_rate(&hull.rates);
                        let error = asked - self.gauge * yaw_rate;
                        // Inside the dead band the levers rest.
                        let beyond = (error.abs() - brakes.dead_band).max(0.0).copysign(error);
                        (beyond / brakes.band).clamp(-1.0, 1.0)
                    }
                    None => input()?,
                };
                // A left turn (lever > 0) brakes the left axle.
                let applied = [(-lever).max(0.0), lever.max(0.0)].map(|l| l * brakes.max_torque);
                for s in 0..2 {
                    let law = brakes.respond(states[1 + s], omega[s], applied[s]);
                    state.brake[s] = law.force;
                    state.torque[s] += law.force;
                    state.rates[1 + s] = law.rate;
                    state.dissipation += law.dissipation;
                    state.braked[s] = law.dissipation;
                }
            }
            DifferentialSteer::Unit(unit) => {
                let full = unit.full_difference(mean, states[3]);
                let most = full.abs();
                let wanted = match asked {
                    Some(asked) => (-asked / radius).clamp(-most, most),
                    None => input()? * full,
                };
                let difference = omega[0] - omega[1];
                let (torque, rate) = unit.controller().checked_torque_trimmed(
                    (t, -wanted),
                    difference,
                    1.0,
                    states[1],
                    TorqueCap::NONE,
                )?;
                state.torque[0] += torque;
                state.torque[1] -= torque;
                state.driven += torque * difference;
                state.rates[1] = rate;
            }
        }
        // The engine drives the steer unit too: what the unit draws
        // (`Q Δω`, the steering brakes none) loads the engine whose speed
        // is a state, or leaves the box that much less of the envelope's
        // power at the mean speed.
        let steering = state.driven;
        if let Some(engine) = &differential.engine {
            let boxed = engine.drive(
                (&differential.drive, t),
                (mean, radius),
                states[0],
                (states[3], states[4], steering),
            )?;
            state.torque[0] += 0.5 * boxed.torque;
            state.torque[1] += 0.5 * boxed.torque;
            state.driven += boxed.torque * mean;
            [state.rates[0], state.rates[3], state.rates[4]] = boxed.rates;
            state.engine = Some(boxed.side);
            return Ok(());
        }
        let cap = envelope.map_or(TorqueCap::NONE, |e| {
            let mut cap = e.differential(mean);
            if steering > 0.0 && mean != 0.0 {
                cap.value = (cap.value - steering / mean.abs()).max(0.0);
            }
            cap
        });
        let (torque, rate) =
            differential
                .drive
                .checked_torque_trimmed((t, 0.0), mean, radius, states[0], cap)?;
        state.torque[0] += 0.5 * torque;
        state.torque[1] += 0.5 * torque;
        state.driven += torque * mean;
        state.rates[0] = rate;
        Ok(())
    }

    /// Each sprocket's speed relative to the frame, rad/s (right, left;
    /// planar sense: driving forward turns it negative), 0 for a side
    /// without one.
    pub fn sprocket_speeds(&self, hull: &TreeState<DH>) -> [f64; 2] {
        let qd = &hull.rates.planar;
        self.sprockets
            .map(|s| s.map_or(0.0, |sprocket| qd[2 + sprocket.body] - qd[2]))
    }

    /// The two sprockets' mean rolling radius, m (NaN where a side has
    /// none: a differential refuses such a vehicle).
    pub(super) fn mean_rolling_radius(&self) -> f64 {
        let radii = self
            .sprockets
            .map(|s| s.map_or(f64::NAN, |s| s.rolling_radius));
        0.5 * (radii[0] + radii[1])
    }

    /// The driveline's torques (`drive`'s) added to the sprockets' and
    /// the frame's `loads`.
    pub fn apply_drive(&self, hull: &TreeState<DH>, drive: &DriveState, loads: &mut SpatialLoads) {
        let eta: Vector3<f64> = plane_rotation(hull.pose.yaw, hull.pose.roll)
            .column(1)
            .into();
        for (s, sprocket) in self.sprockets.iter().enumerate() {
            if let Some(sprocket) = sprocket {
                loads.hull[sprocket.body].moment -= eta * drive.torque[s];
                loads.hull[0].moment += eta * drive.torque[s];
            }
        }
    }
}
