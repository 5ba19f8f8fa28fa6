//! A vehicle's energy books at one evaluation: what every force element
//! stored, dissipated and did, summed in one place so that the work of
//! the drive balances the change of energy plus the dissipated work by
//! construction (each element gives its load with its energy terms).

use super::EngineSide;
use crate::contact::ContactForce;

/// What the force elements did at one evaluation: the energy books' terms
/// (elastic energy stored, power dissipated, the drive's torque) and what
/// the vehicle records of its contacts.
#[derive(Debug, Clone, Copy, Default)]
pub(super) struct EnergyBooks {
    /// The normal force of the ground on the track, summed, N.
    pub ground_normal: f64,
    /// The deepest ground contact, m.
    pub ground_penetration: f64,
    /// The deepest rim contact, m.
    pub wheel_penetration: f64,
    /// The deepest tooth contact, m.
    pub sprocket_penetration: f64,
    /// The normal force of the ground on the hull, summed, N.
    pub hull_normal: f64,
    /// The deepest hull contact, m.
    pub hull_penetration: f64,
    /// Elastic energy in the contacts (and soil), J.
    pub potential: f64,
    /// Elastic energy in the arms' springs, J.
    pub arm_potential: f64,
    /// Power dissipated: contacts, soil, arm dampers, drawbar, W.
    pub dissipation: f64,
    /// The drive's torque on the sprocket, N m.
    pub torque: f64,
    /// The share of the powertrain's cap the drive uses
    /// ([`TorqueCap::load`](super::drive::TorqueCap::load)): 1 at full
    /// load, 0 braking or without a powertrain; through an engine whose
    /// speed is a state, the governor's fuel.
    pub engine_load: f64,
    /// The rate of the drive controller's integral, rad/s.
    pub integral_rate: f64,
    /// The engine's acceleration (rad/s²) and the locked driveline's twist
    /// rate (rad/s), where they are states (0 otherwise).
    pub engine_rate: [f64; 2],
    /// The elastic energy of the locked driveline's twist, this side's
    /// share, J (an engine whose speed is a state; 0 otherwise).
    pub twist_energy: f64,
    /// The engine's side of the drive ([`Powertrain::engine_side`](super::Powertrain::engine_side)):
    /// its `engine_power` is the engine work's rate. Without a powertrain
    /// the drive is its own engine (its power is the sprocket's); braking,
    /// the engine gives nothing ([`EngineSide::IDLE`]).
    pub engine: EngineSide,
}

impl EnergyBooks {
    /// Books a contact's energy terms; returns its penetration.
    #[inline]
    pub fn contact(&mut self, force: &ContactForce) -> f64 {
        self.potential += force.potential;
        self.dissipation += force.dissipation;
        force.penetration
    }

    /// Books a contact of the hull with the ground.
    #[inline]
    pub fn hull(&mut self, force: &ContactForce) {
        self.hull_normal += force.normal;
        let depth = self.contact(force);
        self.hull_penetration = self.hull_penetration.max(depth);
    }

    /// Books a ground contact.
    #[inline]
    pub fn ground(&mut self, force: &ContactForce) {
        self.ground_normal += force.normal;
        let depth = self.contact(force);
        self.ground_penetration = self.ground_penetration.max(depth);
    }
}
