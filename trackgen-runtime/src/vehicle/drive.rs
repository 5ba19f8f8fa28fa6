//! What turns the sprocket: a torque schedule or a speed controller,
//! capped by the powertrain where it drives.

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

/// The powertrain's cap on a driving torque at the sprocket's speed
/// ([`Powertrain::limit`](super::Powertrain::limit)): a torque that turns
/// the sprocket the way it turns (or starts it) is held to `value`, N m,
/// whose slope with `|ω|` is `slope`, N m s/rad.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TorqueCap {
    /// N m, ≥ 0 (∞: no powertrain).
    pub value: f64,
    /// N m s/rad.
    pub slope: f64,
}

impl TorqueCap {
    /// No powertrain: nothing caps the drive but its own limit.
    pub const NONE: TorqueCap = TorqueCap {
        value: f64::INFINITY,
        slope: 0.0,
    };

    /// `torque` capped: held to `±value` if it drives the sprocket turning
    /// at `omega` (the same sign, or the sprocket at rest); whether it was.
    fn apply(self, torque: f64, omega: f64) -> (f64, bool) {
        if drives(torque, omega) && torque.abs() > self.value {
            (self.value.copysign(torque), true)
        } else {
            (torque, false)
        }
    }

    /// How much of the cap `torque` uses at sprocket speed `omega`: its
    /// size over the cap while it drives the sprocket (1 when capped), 0
    /// while it brakes (the powertrain gives no braking torque) or without
    /// a powertrain.
    pub fn load(self, torque: f64, omega: f64) -> f64 {
        if drives(torque, omega) && self.value.is_finite() && self.value > 0.0 {
            (torque.abs() / self.value).min(1.0)
        } else {
            0.0
        }
    }
}

/// Whether `torque` drives a sprocket turning at `omega`: turns it the way
/// it already turns, or starts it.
fn drives(torque: f64, omega: f64) -> bool {
    torque * omega > 0.0 || (omega == 0.0 && torque != 0.0)
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
        self.respond(self.demand(t), omega, radius, state, TorqueCap::NONE)
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
        let demand = self.demand(t);
        if !demand.is_finite() {
            let what = match self {
                Drive::Speed { .. } => "the drive's target speed",
                _ => "the drive's torque schedule",
            };
            return Err(SimulationError::NonFinite { t, what });
        }
        Ok(self.respond(demand, omega, radius, state, cap))
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
        let capped_slope = |torque: f64| cap.slope * torque.signum() * omega.signum();
        match self {
            Drive::Free => DriveSlopes::default(),
            Drive::Torque(f) => {
                let (_, capped) = cap.apply(f(t), omega);
                DriveSlopes {
                    torque: if capped {
                        [capped_slope(f(t)), 0.0]
                    } else {
                        [0.0, 0.0]
                    },
                    rate: [0.0, 0.0],
                }
            }
            Drive::Speed {
                proportional,
                integral,
                max_torque,
                ..
            } => {
                let demand = self.demand(t);
                let error = -demand / radius - omega;
                let wanted = proportional * error + integral * state;
                let (torque, _) = self.respond(demand, omega, radius, state, cap);
                let own = torque.abs() >= *max_torque && wanted.abs() > *max_torque;
                let limited = torque != wanted;
                // As `respond` holds the integral.
                let held = limited && wanted.signum() == error.signum();
                DriveSlopes {
                    torque: if !limited {
                        [-proportional, *integral]
                    } else if own {
                        [0.0, 0.0]
                    } else {
                        [capped_slope(torque), 0.0]
                    },
                    rate: if held { [0.0, 0.0] } else { [-1.0, 0.0] },
                }
            }
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

    fn respond(
        &self,
        demand: f64,
        omega: f64,
        radius: f64,
        state: f64,
        cap: TorqueCap,
    ) -> (f64, f64) {
        match self {
            Drive::Free => (0.0, 0.0),
            Drive::Torque(_) => (cap.apply(demand, omega).0, 0.0),
            Drive::Speed {
                proportional,
                integral,
                max_torque,
                ..
            } => {
                let error = -demand / radius - omega;
                let wanted = proportional * error + integral * state;
                // Not `clamp`, which panics on a NaN or negative limit
                // (refused by `check` when a vehicle is built); a NaN
                // stays NaN.
                let torque = if wanted > *max_torque {
                    *max_torque
                } else if wanted < -max_torque {
                    -max_torque
                } else {
                    wanted
                };
                let (torque, _) = cap.apply(torque, omega);
                let saturated = wanted != torque && wanted.signum() == error.signum();
                (torque, if saturated { 0.0 } else { error })
            }
        }
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

/// [`Drive::slopes`]: the drive's torque and its controller's integral
/// rate to first order.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct DriveSlopes {
    /// `(∂τ/∂ω, ∂τ/∂s)`: N m s/rad, N m/rad.
    pub torque: [f64; 2],
    /// `(∂ṡ/∂ω, ∂ṡ/∂s)`: 1, 1/s.
    pub rate: [f64; 2],
}
