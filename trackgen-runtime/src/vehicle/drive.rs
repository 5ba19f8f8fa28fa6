//! What turns the sprocket: a torque schedule or a speed controller.

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
    /// so the sprocket's wanted speed is `−target / r` with `r` its pitch
    /// radius. The torque is limited to `±max_torque` and the integral
    /// held while the limit is active (anti-windup).
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

impl Drive {
    /// The torque (N m) at time `t` for sprocket speed `omega` (rad/s,
    /// relative to the chassis), pitch radius `radius` (m) and controller
    /// integral `state` (rad), and the integral's rate.
    pub fn torque(&self, t: f64, omega: f64, radius: f64, state: f64) -> (f64, f64) {
        match self {
            Drive::Free => (0.0, 0.0),
            Drive::Torque(f) => (f(t), 0.0),
            Drive::Speed {
                target,
                proportional,
                integral,
                max_torque,
            } => {
                let error = -target(t) / radius - omega;
                let wanted = proportional * error + integral * state;
                let torque = wanted.clamp(-max_torque, *max_torque);
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
