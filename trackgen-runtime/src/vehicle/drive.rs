//! What turns the sprocket: a torque schedule or a speed controller,
//! capped by the powertrain where it pushes the way the driver asks.
//!
//! The cap is continuous in the sprocket's speed: a torque pushing the
//! way the driver asks is held to the powertrain's torque at the
//! sprocket's speed while the sprocket turns that way, and to its torque
//! at rest (the stall torque) while the vehicle forces it back (rolling
//! back down a grade it cannot climb, pushed back by an obstacle). A
//! cap that let go at `ω = 0` (a torque "braking" a sprocket forced back)
//! would jump there from the stall torque to the controller's limit, and
//! a stalled vehicle chatters across that jump at tiny steps. A torque
//! against the asked direction is the brakes', uncapped.

use thiserror::Error;

use crate::integrate::SimulationError;

/// Settings of a drive that make no controller.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum DriveError {
    /// A gain is NaN or infinite.
    #[error(
        "the speed drive's gains must be finite, got proportional {proportional}, integral {integral}"
    )]
    Gains {
        /// N m s/rad.
        proportional: f64,
        /// N m/rad.
        integral: f64,
    },
    /// The torque limit is NaN or negative.
    #[error("the speed drive's torque limit must be zero or more, got {max_torque}")]
    TorqueLimit {
        /// N m.
        max_torque: f64,
    },
}

/// The main job's target speed (m/s) against time (s): 0 while the
/// vehicle settles for `settle` s, then a linear ramp to `speed` m/s over
/// `ramp` s; a ramp of 0 s is a step at the end of settling.
pub fn speed_ramp(settle: f64, ramp: f64, speed: f64) -> impl Fn(f64) -> f64 + Send + 'static {
    move |t: f64| {
        if ramp > 0.0 {
            speed * ((t - settle) / ramp).clamp(0.0, 1.0)
        } else if t >= settle {
            speed
        } else {
            0.0
        }
    }
}

/// The sprocket drive: its torque acts on the sprocket and, reversed, on
/// the chassis frame.
pub enum Drive {
    /// No drive torque.
    Free,
    /// A torque (N m) as a function of time (s).
    Torque(Box<dyn Fn(f64) -> f64 + Send>),
    /// A PI controller on the sprocket's speed relative to the chassis,
    /// tracking a forward speed `target(t)` (m/s): driving forward, the
    /// loop (numbered counter-clockwise) runs clockwise round the chassis,
    /// so the sprocket's wanted speed is `−target / r` with `r` its rolling
    /// radius `N p / (2π)`, the track's mean speed per unit of sprocket
    /// speed ([`track_speed`](crate::contact::sprocket::track_speed)). The torque is limited to `±max_torque` and the integral
    /// held while the limit is active (anti-windup). A target that is NaN
    /// or infinite stops a run ([`Drive::checked_torque`]); gains must be
    /// finite and the limit zero or more ([`Drive::check`]).
    Speed {
        /// Forward speed wanted, m/s, as a function of time (s).
        target: Box<dyn Fn(f64) -> f64 + Send>,
        /// Proportional gain, N m s/rad.
        proportional: f64,
        /// Integral gain, N m/rad.
        integral: f64,
        /// Torque limit, N m.
        max_torque: f64,
    },
}

/// The powertrain's cap on the sprocket's torque at its speed
/// ([`Powertrain::limit`](super::Powertrain::limit)): a torque pushing the
/// way the driver asks is held to `value`, N m, while the sprocket turns
/// that way or rests (`value`'s slope with `|ω|` is `slope`, N m s/rad),
/// and to `stall`, N m (the torque at rest), while the sprocket is forced
/// the other way.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TorqueCap {
    /// N m, ≥ 0 (∞: no powertrain).
    pub value: f64,
    /// N m s/rad.
    pub slope: f64,
    /// The cap at rest, N m (∞: no powertrain).
    pub stall: f64,
}

impl TorqueCap {
    /// No powertrain: nothing caps the drive but its own limit.
    pub const NONE: TorqueCap = TorqueCap {
        value: f64::INFINITY,
        slope: 0.0,
        stall: f64::INFINITY,
    };

    /// The cap on a torque of `torque`'s sign at sprocket speed `omega`,
    /// N m, and its slope with `ω`, N m s/rad: `value` while the sprocket
    /// turns the torque's way (or rests), `stall` (flat) while forced the
    /// other way.
    fn at(self, torque: f64, omega: f64) -> (f64, f64) {
        if torque * omega >= 0.0 {
            (self.value, self.slope * torque.signum() * omega.signum())
        } else {
            (self.stall, 0.0)
        }
    }

    /// `torque` capped if it pushes the way the driver asks (`direction`'s
    /// sign; a torque against it brakes, uncapped); whether it was, and
    /// the capped torque's slope with `omega`.
    fn apply(self, torque: f64, omega: f64, direction: f64) -> (f64, Option<f64>) {
        if torque * direction > 0.0 {
            let (cap, slope) = self.at(torque, omega);
            if torque.abs() > cap {
                return (cap.copysign(torque), Some(slope));
            }
        }
        (torque, None)
    }

    /// How much of the cap `torque` uses at sprocket speed `omega`: its
    /// size over the cap while it pushes the way the driver asks
    /// (`direction`'s sign; 1 when capped), 0 while it brakes or without
    /// a powertrain.
    pub fn load(self, torque: f64, omega: f64, direction: f64) -> f64 {
        let (cap, _) = self.at(torque, omega);
        if torque * direction > 0.0 && cap.is_finite() && cap > 0.0 {
            (torque.abs() / cap).min(1.0)
        } else {
            0.0
        }
    }
}

impl Drive {
    /// The torque (N m) at time `t` for sprocket speed `omega` (rad/s,
    /// relative to the chassis), pitch radius `radius` (m) and controller
    /// integral `state` (rad), and the integral's rate, with no
    /// powertrain.
    ///
    /// A NaN or infinite target speed or scheduled torque gives a NaN or
    /// unbounded torque here; [`checked_torque`](Self::checked_torque)
    /// refuses it.
    pub fn torque(&self, t: f64, omega: f64, radius: f64, state: f64) -> (f64, f64) {
        let (torque, rate, _) = self.law(self.demand(t), omega, radius, state, TorqueCap::NONE);
        (torque, rate)
    }

    /// [`torque`](Self::torque) under the powertrain's `cap`, refusing a
    /// target speed (a speed drive) or a scheduled torque (a torque drive)
    /// that is NaN or infinite at `t`: [`SimulationError::NonFinite`]
    /// naming it.
    pub fn checked_torque(
        &self,
        t: f64,
        omega: f64,
        radius: f64,
        state: f64,
        cap: TorqueCap,
    ) -> Result<(f64, f64), SimulationError> {
        let (torque, rate, _, _) = self.checked_law(t, omega, radius, state, cap)?;
        Ok((torque, rate))
    }

    /// [`checked_torque`](Self::checked_torque) with a speed drive's
    /// target moved by `trim` m/s (a driver's steering: each side's belt
    /// apart from the speed wanted); other drives take no trim.
    pub fn checked_torque_trimmed(
        &self,
        (t, trim): (f64, f64),
        omega: f64,
        radius: f64,
        state: f64,
        cap: TorqueCap,
    ) -> Result<(f64, f64), SimulationError> {
        let demand = self.checked_demand(t)?;
        let demand = match self {
            Drive::Speed { .. } => demand + trim,
            _ => demand,
        };
        let (torque, rate, _) = self.law(demand, omega, radius, state, cap);
        Ok((torque, rate))
    }

    /// The driver's demand at `t` (a speed drive's target speed, a torque
    /// drive's scheduled torque), refused if NaN or infinite.
    fn checked_demand(&self, t: f64) -> Result<f64, SimulationError> {
        let demand = self.demand(t);
        if !demand.is_finite() {
            let what = match self {
                Drive::Speed { .. } => "the drive's target speed",
                _ => "the drive's torque schedule",
            };
            return Err(SimulationError::NonFinite { t, what });
        }
        Ok(demand)
    }

    /// [`checked_torque`](Self::checked_torque)'s torque and integral
    /// rate with their [`slopes`](Self::slopes), and the way the driver
    /// asks the sprocket to turn as a sign (0: to stand), from one reading
    /// of the driver's demand.
    pub(super) fn checked_law(
        &self,
        t: f64,
        omega: f64,
        radius: f64,
        state: f64,
        cap: TorqueCap,
    ) -> Result<(f64, f64, DriveSlopes, f64), SimulationError> {
        let demand = self.checked_demand(t)?;
        let (torque, rate, slopes) = self.law(demand, omega, radius, state, cap);
        Ok((torque, rate, slopes, self.direction(demand, radius)))
    }

    /// Why the settings of the drive make no controller: gains that are NaN
    /// or infinite, a torque limit that is NaN or negative.
    pub fn check(&self) -> Result<(), DriveError> {
        if let Drive::Speed {
            proportional,
            integral,
            max_torque,
            ..
        } = self
        {
            if !(proportional.is_finite() && integral.is_finite()) {
                return Err(DriveError::Gains {
                    proportional: *proportional,
                    integral: *integral,
                });
            }
            if max_torque.is_nan() || *max_torque < 0.0 {
                return Err(DriveError::TorqueLimit {
                    max_torque: *max_torque,
                });
            }
        }
        Ok(())
    }

    /// The first derivatives of [`checked_torque`](Self::checked_torque)'s
    /// torque and integral rate with respect to the sprocket's speed `ω`
    /// and the controller's integral `s`, at the same arguments: a speed
    /// drive's `∂τ/∂ω = −P`, `∂τ/∂s = I`, `∂ṡ/∂ω = −1`; zero where the
    /// torque is at its own limit (the integral then held), the cap's
    /// slope `∂τ/∂ω = sign(τ) sign(ω) ∂cap/∂|ω|` where the powertrain caps
    /// it; a torque schedule's only where capped; zero for a free
    /// sprocket.
    pub fn slopes(
        &self,
        t: f64,
        omega: f64,
        radius: f64,
        state: f64,
        cap: TorqueCap,
    ) -> DriveSlopes {
        self.law(self.demand(t), omega, radius, state, cap).2
    }

    /// How much of the powertrain's cap the drive's `torque` (N m) uses at
    /// `t` at sprocket speed `omega` (rad/s, pitch radius `radius` m):
    /// [`TorqueCap::load`] in the direction the driver asks.
    pub fn engine_load(&self, t: f64, torque: f64, omega: f64, radius: f64, cap: TorqueCap) -> f64 {
        cap.load(torque, omega, self.direction(self.demand(t), radius))
    }

    /// Whether the driver asks the vehicle backwards at `t`: a target
    /// speed below 0, or a scheduled torque turning the sprocket as when
    /// reversing (positive: driving forward turns it negative).
    pub fn asks_reverse(&self, t: f64) -> bool {
        self.direction(self.demand(t), 1.0) > 0.0
    }

    /// The way the driver asks the sprocket to turn, as a sign (0: to
    /// stand): the target speed's (the sprocket turns as `−v / r`) or the
    /// scheduled torque's.
    fn direction(&self, demand: f64, radius: f64) -> f64 {
        let asked = match self {
            Drive::Free => 0.0,
            Drive::Torque(_) => demand,
            Drive::Speed { .. } => -demand / radius,
        };
        if asked > 0.0 {
            1.0
        } else if asked < 0.0 {
            -1.0
        } else {
            0.0
        }
    }

    /// The target speed (m/s) or the scheduled torque (N m) at `t`.
    fn demand(&self, t: f64) -> f64 {
        match self {
            Drive::Free => 0.0,
            Drive::Torque(f) => f(t),
            Drive::Speed { target, .. } => target(t),
        }
    }

    /// The drive's law at `demand` (the target speed or the scheduled
    /// torque), in one place: the torque (N m), the controller integral's
    /// rate (rad/s, held at 0 while the torque is limited the way the
    /// error pushes: no wind-up), and their slopes ([`slopes`](Self::slopes)).
    fn law(
        &self,
        demand: f64,
        omega: f64,
        radius: f64,
        state: f64,
        cap: TorqueCap,
    ) -> (f64, f64, DriveSlopes) {
        let direction = self.direction(demand, radius);
        match self {
            Drive::Free => (0.0, 0.0, DriveSlopes::default()),
            Drive::Torque(_) => {
                let (torque, capped) = cap.apply(demand, omega, direction);
                let slopes = DriveSlopes {
                    torque: [capped.unwrap_or(0.0), 0.0, 0.0, 0.0],
                    ..DriveSlopes::default()
                };
                (torque, 0.0, slopes)
            }
            Drive::Speed {
                proportional,
                integral,
                max_torque,
                ..
            } => {
                let error = -demand / radius - omega;
                let wanted = proportional * error + integral * state;
                let own_limited = wanted.abs() > *max_torque;
                let (torque, capped) = cap.apply(within(wanted, *max_torque), omega, direction);
                let held = torque != wanted && wanted.signum() == error.signum();
                let slopes = DriveSlopes {
                    torque: match capped {
                        Some(slope) => [slope, 0.0, 0.0, 0.0],
                        None if own_limited => [0.0; 4],
                        None => [-proportional, *integral, 0.0, 0.0],
                    },
                    rate: if held {
                        [0.0; 4]
                    } else {
                        [-1.0, 0.0, 0.0, 0.0]
                    },
                    ..DriveSlopes::default()
                };
                (torque, if held { 0.0 } else { error }, slopes)
            }
        }
    }
}

/// `wanted` held to `±max_torque`. Not `clamp`, which panics on a NaN or
/// negative limit (refused by `check` when a vehicle is built); a NaN
/// stays NaN.
fn within(wanted: f64, max_torque: f64) -> f64 {
    if wanted > max_torque {
        max_torque
    } else if wanted < -max_torque {
        -max_torque
    } else {
        wanted
    }
}

impl std::fmt::Debug for Drive {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Drive::Free => write!(f, "Free"),
            Drive::Torque(_) => write!(f, "Torque(..)"),
            Drive::Speed {
                proportional,
                integral,
                max_torque,
                ..
            } => f
                .debug_struct("Speed")
                .field("proportional", proportional)
                .field("integral", integral)
                .field("max_torque", max_torque)
                .finish_non_exhaustive(),
        }
    }
}

/// [`Drive::slopes`]: the drive's torque, its controller's integral rate
/// and, through an engine whose speed is a state
/// ([`EngineDynamics`](super::EngineDynamics)), the engine's acceleration
/// and the locked driveline's twist rate, to first order over the drive's
/// four states: the sprocket's speed `ω`, the controller's integral `s`,
/// the engine's speed `ω_e` and the driveline's twist `z` (the last two's
/// columns and rows zero without such an engine).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct DriveSlopes {
    /// `(∂τ/∂ω, ∂τ/∂s, ∂τ/∂ω_e, ∂τ/∂z)`: N m s/rad, N m/rad, N m s/rad,
    /// N m/rad.
    pub torque: [f64; 4],
    /// `∂ṡ` over the same: 1, 1/s, 1, 1/s.
    pub rate: [f64; 4],
    /// `∂ω̇_e` over the same: 1/s, 1/s², 1/s, 1/s².
    pub engine: [f64; 4],
    /// `∂ż` over the same: 1, 1/s, 1, 1/s.
    pub twist: [f64; 4],
}
