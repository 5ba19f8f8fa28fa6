//! What changes between steps, after an accepted one: a brake whose time
//! has come, a gear shift, the lock-up clutch, the soil's memory. Each
//! says whether it changed the right-hand side, so that the integrator
//! restarts (`Simulated::after_step` asks them all).

use nalgebra::Vector2;

use super::VehicleSystem;
use crate::contact::BodyState;
use crate::integrate::SimulationError;
use crate::multibody::{ChassisModel, TrackModel};
use crate::vehicle::Powertrain;

impl<T, const DT: usize, C, const DC: usize> VehicleSystem<T, DT, C, DC>
where
    T: TrackModel<DT>,
    C: ChassisModel<DC>,
{
    /// Applies a pending brake whose time has come: its law replaces the
    /// drive from now on, the engine is declutched, and the integral (the
    /// brake's elastic stage, `−φ`) starts at 0. Whether it did (the
    /// integrator then restarts).
    pub(super) fn apply_brake(&mut self, t: f64, y: &mut [f64]) -> bool {
        match self.config.brake {
            Some(brake) if t >= brake.from => {
                self.config.brake = None;
                self.config.drive = brake.as_drive();
                self.config.powertrain = None;
                y[self.layout.integral] = 0.0;
                true
            }
            _ => false,
        }
    }

    /// Shifts a scheduled gearbox and engages or releases an engine's
    /// lock-up clutch (an engine whose speed is a state) at the end of a
    /// step, as [`Driveline::gearbox_next`](crate::vehicle::Driveline::gearbox_next)
    /// says with the sprocket as the gearbox's output. Whether either
    /// changed (the integrator then restarts: the cap or the law changed).
    pub(super) fn shift_and_lock(&mut self, t: f64, y: &[f64]) -> bool {
        let (Some(sprocket), Some(Powertrain::Converter(driveline))) =
            (self.sprocket.as_mut(), self.config.powertrain.as_ref())
        else {
            return false;
        };
        let omega = sprocket.omega_of(&y[self.layout.chassis_rates.clone()]);
        let engine_speed = self.layout.engine.map(|i| y[i]);
        let next = driveline.gearbox_next(
            t,
            (sprocket.engaged, sprocket.locked),
            (omega, engine_speed),
            self.config.drive.asks_reverse(t),
        );
        let changed = next != (sprocket.engaged, sprocket.locked);
        (sprocket.engaged, sprocket.locked) = next;
        changed
    }

    /// After an accepted step on soft soil: the rut pressed wherever a
    /// ground point has sunk deeper than the soil remembers, and the shear
    /// displacement of every point off the ground reset
    /// ([`SoftGround::press`]). Returns whether the right-hand side changed
    /// (the integrator must then restart).
    pub(super) fn press_soil(&mut self, t: f64, y: &mut [f64]) -> Result<bool, SimulationError> {
        let Some(soil) = self.soil.as_mut() else {
            return Ok(false);
        };
        let (bodies, rest) = y.split_at_mut(self.layout.integral);
        let (yt, _) = self.bodies.split(bodies);
        let track = self.bodies.parts_mut().0;
        track.recover(t, yt)?;
        let (qt, _, trig) = track.recovered();
        let positions = &mut self.work.positions[..T::BODIES];
        track.model().body_positions(qt, positions);
        for (b, link) in self.work.links.iter_mut().enumerate() {
            *link =
                BodyState::with_sin_cos(positions[b], qt[2 + b], trig[b], Vector2::zeros(), 0.0);
        }
        Ok(soil.press(
            &self.config.terrain,
            &self.work.links,
            &self.geometry.shoe,
            &mut rest[self.layout.tangential.start - self.layout.integral..],
        ))
    }
}
