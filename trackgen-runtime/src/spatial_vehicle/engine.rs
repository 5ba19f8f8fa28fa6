//! An engine whose speed is a state, driving a differential's box: the
//! planar vehicle's engine, converter, scheduled ranges and lock-up
//! clutch ([`EngineDynamics`](crate::vehicle::EngineDynamics),
//! [`Driveline::engine_state`]) with the whole engine on the box.
//!
//! The box turns at the sprockets' mean speed `ω̄`, so the converter's
//! turbine turns at `n ω̄` (`n` the range's reduction with the final
//! drive's) and the box takes `f n T_t`, `f` the gearbox's and final
//! drive's efficiencies (the planar side's share is 0.5; the box's is the
//! whole, 1), halved to each axle by the differential. The driver's speed
//! controller asks the box's torque, as it asks a planar sprocket's; the
//! governor, the converter, the shifts and the lock-up are the planar
//! vehicle's, one owner of each law ([`engine_drive`]).
//!
//! A steer unit is driven by the engine too: what it draws, `Q Δω` where
//! positive, loads the engine's shaft by `Q Δω / ω_e` beside the
//! converter's pump ([`Driveline::loaded_engine_state`]), so a turn slows
//! the engine that drives it, and the governor fuels for it. A steer
//! drive geared to the engine ([`FullSteer::Engine`](super::FullSteer::Engine))
//! holds the sprockets' speed difference at `s k ω_e` from that same
//! engine speed.
//!
//! The gearbox shifts and the clutch locks at the end of an accepted step
//! ([`SpatialSystem::after_step`](super::SpatialSystem::after_step)), as
//! the planar vehicle's do.

use thiserror::Error;

use crate::integrate::SimulationError;
use crate::vehicle::{
    AtSprocket, Drive, Driveline, Engaged, EngineSide, IDEAL_DOWNSHIFT, IDEAL_SHIFT_TIME,
    Powertrain, PowertrainError, engine_drive,
};

/// A powertrain that makes no engine whose speed is a state.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum SpatialEngineError {
    /// A figure out of its range.
    #[error(transparent)]
    Powertrain(#[from] PowertrainError),
    /// Not an engine through a converter with its dynamics declared.
    #[error(
        "an engine whose speed is a state needs an engine through a torque converter with its \
         inertia declared (`engine_inertia` in `powertrain {{ … }}`)"
    )]
    NoDynamics,
}

/// An engine whose speed is a state, driving a differential's box, and
/// its gearbox's and lock-up clutch's state.
#[derive(Debug, Clone, PartialEq)]
pub struct SpatialEngine {
    /// The converter driveline with the whole engine on the box.
    powertrain: Powertrain,
    /// The range engaged (a scheduled gearbox).
    engaged: Option<Engaged>,
    /// Whether the lock-up clutch is engaged.
    locked: bool,
    /// The box's torque at rest, forward and in reverse, N m.
    stall: (f64, f64),
}

/// What the engine gives the box at one instant.
#[derive(Debug, Clone, Copy)]
pub(super) struct BoxDrive {
    /// The box's torque, N m (planar sense).
    pub torque: f64,
    /// The rates of the controller's integral (rad/s), the engine's speed
    /// (rad/s²) and the locked driveline's twist (rad/s).
    pub rates: [f64; 3],
    /// The engine's side: its speed, torque, range, converter and
    /// powers.
    pub side: EngineSide,
}

impl SpatialEngine {
    /// The engine of `powertrain` (one side's figures, as a declaration
    /// gives them: its share is set to the whole for the box), in its
    /// lowest range, unlocked; a gearbox without a schedule shifts by
    /// the ideal one ([`Driveline::ideal_schedule`]) as the planar
    /// vehicle's does. Refused: figures out of their range, or a
    /// powertrain that is not an engine through a converter with its
    /// inertia declared.
    pub fn new(powertrain: Powertrain) -> Result<SpatialEngine, SpatialEngineError> {
        powertrain.check()?;
        let Powertrain::Converter(mut driveline) = powertrain else {
            return Err(SpatialEngineError::NoDynamics);
        };
        if driveline.dynamics.is_none() {
            return Err(SpatialEngineError::NoDynamics);
        }
        driveline.share = 1.0;
        if driveline.shift.is_none() {
            driveline.shift = driveline.ideal_schedule(IDEAL_DOWNSHIFT, IDEAL_SHIFT_TIME);
        }
        let engaged = driveline.shift.as_ref().map(|_| Engaged::LOWEST);
        let powertrain = Powertrain::Converter(driveline);
        let stall = powertrain.stall_torques();
        Ok(SpatialEngine {
            powertrain,
            engaged,
            locked: false,
            stall,
        })
    }

    /// The converter driveline, its share the whole engine's.
    pub fn driveline(&self) -> &Driveline {
        match &self.powertrain {
            Powertrain::Converter(d) => d,
            _ => unreachable!("a spatial engine is a converter driveline"),
        }
    }

    /// The engine's idle speed, rad/s (its map's first): where a run
    /// starts it.
    pub fn idle(&self) -> f64 {
        self.driveline().engine[0].0
    }

    /// The engine's rated power, W: its full-load map's largest `T ω`,
    /// at its [`rated_speed`](Driveline::rated_speed).
    pub fn rated_power(&self) -> f64 {
        let d = self.driveline();
        let speed = d.rated_speed();
        Driveline::full_load(&d.engine, speed) * speed
    }

    /// The range engaged (0-based) and whether a shift is under way.
    pub fn engaged(&self) -> Option<Engaged> {
        self.engaged
    }

    /// Whether the lock-up clutch is engaged.
    pub fn locked(&self) -> bool {
        self.locked
    }

    /// What the engine gives the box driven by `drive` at time `t`, the
    /// box turning at `mean` (rad/s) on sprockets of mean rolling radius
    /// `radius` (m), the controller's integral at `integral` (rad), the
    /// engine at `speed` (rad/s) and the driveline twisted by `twist`
    /// (rad), a steer unit drawing `steering` W from it.
    pub(super) fn drive(
        &self,
        (drive, t): (&Drive, f64),
        (mean, radius): (f64, f64),
        integral: f64,
        (speed, twist, steering): (f64, f64, f64),
    ) -> Result<BoxDrive, SimulationError> {
        let reverse = drive.asks_reverse(t);
        let at = AtSprocket {
            omega: mean,
            rolling_radius: radius,
            stall: if reverse { self.stall.1 } else { self.stall.0 },
            gearbox: (self.engaged, reverse),
            locked: self.locked,
        };
        let accessory = if steering > 0.0 && speed > 0.0 {
            steering / speed
        } else {
            0.0
        };
        let d = engine_drive(
            &self.powertrain,
            drive,
            t,
            at,
            integral,
            (speed, twist, accessory),
        )?;
        Ok(BoxDrive {
            torque: d.torque,
            rates: [d.integral_rate, d.engine_rate, d.twist_rate],
            side: d.side,
        })
    }

    /// After an accepted step at time `t` with the box turning at `mean`
    /// (rad/s), the engine at `speed` (rad/s) and the driver of `drive`
    /// asking what it asks: the gearbox shifted and the lock-up clutch
    /// engaged or released as the planar sprocket's are
    /// ([`Driveline::gearbox_next`], the box as the gearbox's output).
    /// Whether either changed (the integrator must then restart).
    pub fn after_step(&mut self, t: f64, (mean, speed): (f64, f64), drive: &Drive) -> bool {
        let now = (self.engaged, self.locked);
        let next =
            self.driveline()
                .gearbox_next(t, now, (mean, Some(speed)), drive.asks_reverse(t));
        (self.engaged, self.locked) = next;
        next != now
    }
}
