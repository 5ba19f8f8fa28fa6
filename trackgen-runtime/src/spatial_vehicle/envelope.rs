//! An engine's full-load envelope on the spatial vehicle's driveline: the
//! planar vehicle's [`Powertrain`] (a power and torque limit, an engine's
//! map through ideally shifted gears, or an engine through a torque
//! converter, ranges and a final drive) capping what the drive asks.
//!
//! A [`Powertrain`]'s cap is one sprocket's: its fraction is the
//! driveline's efficiency times the side's share of the engine (0.5).
//! With a drive on each side, each sprocket's drive is capped at its own
//! speed (two halves of the engine, each at its side's speed: the side
//! drives' model of a robot's two motors given the engine's figures).
//! Through a differential the engine drives the box at the sprockets'
//! mean speed `ω̄`, which takes both sides' share: twice a side's cap at
//! `ω̄`, halved to each axle by the differential as the box's torque is.
//!
//! A steer unit (the X200-4's hydrostatic steer) is driven by the engine
//! too: the power it draws, `Q Δω` where positive, is taken from the
//! box's share, its cap at `ω̄` lowered by `Q Δω / |ω̄|`. What the unit
//! carries from the inner sprocket to the outer (regenerative steering)
//! costs the engine nothing; with a drive on each side the inner side's
//! braking is lost to the outer, which gets half the engine at most.
//!
//! The envelope is quasi-static: the range in use is the one that gives
//! the most torque at the speed (the planar [`Powertrain::limit`]),
//! forward both ways, with no engine speed as a state.

use crate::vehicle::{Powertrain, PowertrainError, TorqueCap};

/// An engine's full-load envelope on a spatial driveline.
#[derive(Debug, Clone, PartialEq)]
pub struct EngineEnvelope {
    powertrain: Powertrain,
    /// A side's cap at rest, N m, found once.
    stall: f64,
}

impl EngineEnvelope {
    /// The envelope of `powertrain` (one side's figures, as the planar
    /// vehicle declares them); figures out of their range are refused
    /// ([`Powertrain::check`]).
    pub fn new(powertrain: Powertrain) -> Result<EngineEnvelope, PowertrainError> {
        powertrain.check()?;
        let stall = powertrain.limit(0.0).0;
        Ok(EngineEnvelope { powertrain, stall })
    }

    /// The powertrain it caps by.
    pub fn powertrain(&self) -> &Powertrain {
        &self.powertrain
    }

    /// The cap on one sprocket's drive at its speed `omega` (rad/s,
    /// either sense): the powertrain's [`limit`](Powertrain::limit) at
    /// `|ω|`, its torque at rest while the sprocket is forced back.
    pub fn side(&self, omega: f64) -> TorqueCap {
        let (value, slope) = self.powertrain.limit(omega.abs());
        TorqueCap {
            value,
            slope,
            stall: self.stall,
        }
    }

    /// The cap on a differential's box at the sprockets' mean speed
    /// `mean` (rad/s): both sides' share, twice [`side`](Self::side)'s.
    pub fn differential(&self, mean: f64) -> TorqueCap {
        let side = self.side(mean);
        TorqueCap {
            value: 2.0 * side.value,
            slope: 2.0 * side.slope,
            stall: 2.0 * side.stall,
        }
    }
}
