//! What makes the engine's speed a state of the run: the engine's and the
//! converter pump's inertia, its torque at no fuel, the governor's time
//! constant and the lock-up clutch with the locked driveline's compliance
//! ([`EngineDynamics`]); the law they make is the converter's
//! (`engine_state.rs`).

use super::PowertrainError;
use super::tables::table;
use crate::laws::Stiction;

/// What makes the engine's speed a state of the run
/// ([`Driveline::dynamics`](super::Driveline::dynamics)): the rotating inertia, the engine's torque at
/// no fuel, the governor's time constant and the lock-up clutch.
#[derive(Debug, Clone, PartialEq)]
pub struct EngineDynamics {
    /// The engine's rotating parts with the converter's pump, kg m² (the
    /// whole engine's), more than 0.
    pub inertia: f64,
    /// The engine's torque at no fuel (friction and pumping, ≤ 0), N m,
    /// against engine speed, rad/s: two or more points of increasing speed
    /// from one ≥ 0, linear between them, held beyond the ends.
    pub drag: Vec<(f64, f64)>,
    /// The governor's time constant, s (more than 0): how fast the fuel
    /// brings the engine to the speed that gives the torque asked.
    pub governor_time: f64,
    /// The lock-up clutch's capacity, N m (more than 0): the most torque it
    /// carries before it slips.
    pub lockup_capacity: f64,
    /// The torsional stiffness of the locked driveline at the turbine,
    /// N m/rad (more than 0): what the engine's inertia rings against once
    /// the clutch holds (the gearbox's, final drive's and axles' shafts
    /// reflected to it).
    pub lockup_stiffness: f64,
    /// The locked driveline's torsional damping at the turbine, N m s/rad
    /// (more than 0).
    pub lockup_damping: f64,
}

impl EngineDynamics {
    /// The governor's time constant when none is declared, s: 0.1, the
    /// response of a mechanical flyweight governor with its fuel rack
    /// (an assumption: no figure is published for the vehicles here).
    pub const GOVERNOR_TIME: f64 = 0.1;
    /// The lock-up clutch's capacity when none is declared, as a multiple
    /// of the engine map's largest torque: 1.5, a clutch sized to carry the
    /// engine's torque with a margin (an assumption).
    pub const LOCKUP_MARGIN: f64 = 1.5;
    /// The frequency, Hz, at which the engine rings against a held
    /// turbine through the locked driveline when its stiffness is not
    /// declared: 10, the top of the 2–10 Hz band of a road vehicle's first
    /// driveline mode (its shuffle); no tracked vehicle's figure was found
    /// (an assumption). It sets the stiffness, `J (2π f)²`.
    pub const LOCKUP_FREQUENCY: f64 = 10.0;
    /// The damping ratio of that mode when the damping is not declared: 0.3
    /// (an assumption). It sets the damping, `2 ζ √(k J)`.
    pub const LOCKUP_DAMPING_RATIO: f64 = 0.3;

    /// The locked driveline's stiffness when none is declared, N m/rad:
    /// [`LOCKUP_FREQUENCY`](Self::LOCKUP_FREQUENCY)'s for an engine of
    /// `inertia` (kg m²).
    pub fn lockup_stiffness_for(inertia: f64) -> f64 {
        let omega = 2.0 * std::f64::consts::PI * Self::LOCKUP_FREQUENCY;
        inertia * omega * omega
    }

    /// The locked driveline's damping when none is declared, N m s/rad:
    /// [`LOCKUP_DAMPING_RATIO`](Self::LOCKUP_DAMPING_RATIO) of the
    /// engine's (`inertia`, kg m²) mode on `stiffness` (N m/rad).
    pub fn lockup_damping_for(inertia: f64, stiffness: f64) -> f64 {
        2.0 * Self::LOCKUP_DAMPING_RATIO * (stiffness * inertia).sqrt()
    }

    /// Every figure in its range.
    pub fn check(&self) -> Result<(), PowertrainError> {
        for (what, value) in [
            ("engine_inertia", self.inertia),
            ("governor_time", self.governor_time),
            ("lockup_capacity", self.lockup_capacity),
            ("lockup_stiffness", self.lockup_stiffness),
            ("lockup_damping", self.lockup_damping),
        ] {
            if !(value.is_finite() && value > 0.0) {
                return Err(PowertrainError::Limit { what, value });
            }
        }
        table(&self.drag, "engine's drag", |t| t <= 0.0)
    }

    /// The locked clutch and driveline as an elastic element with a
    /// Coulomb limit: its twist `z` (rad, at the turbine) carries `k z + c
    /// ż` while that is under the clutch's capacity, which it carries,
    /// slipping, beyond (the law of a sticking contact, [`Stiction`], with
    /// the capacity for its `μ F_n`: read with a normal force of the
    /// capacity and `μ = 1`).
    pub fn lockup(&self) -> Stiction {
        Stiction {
            mu: 1.0,
            stiffness: self.lockup_stiffness,
            damping: self.lockup_damping,
        }
    }
}
