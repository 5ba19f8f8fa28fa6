//! The brake on the sprocket: a torque limit on the sprocket's rotation
//! relative to the hull, holding by stiction.

use thiserror::Error;

use super::drive::Drive;

/// A brake on the sprocket, applied from a time on (the driver's or a
/// schedule's): from then its torque replaces the drive's and the engine
/// is declutched. It holds by stiction as a friction brake does: an
/// elastic stage (the ground's stiction law, a spring-dashpot in series
/// with a Coulomb slider: Cundall & Strack, *Géotechnique* 29(1), 1979;
/// the guide's "Friction with stiction") of stiffness `k` and damping `c` on the
/// sprocket's rotation since the brake was applied, `φ`, gives
/// `τ = −k φ − c ω`; at `|τ| = T` it slips, `φ` held (the drive's
/// integral state is `φ`'s negative, its anti-windup the slip). While
/// `|τ| < T` nothing creeps: `φ` is a rotation, not a rate.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Brake {
    /// The largest torque it holds before it slips, N m, ≥ 0.
    pub max_torque: f64,
    /// The elastic stage's stiffness, N m/rad, > 0.
    pub stiffness: f64,
    /// The elastic stage's damping, N m s/rad, ≥ 0.
    pub damping: f64,
    /// When it is applied, s: at the first accepted step at or after it.
    pub from: f64,
}

/// A brake's figure out of its range.
#[derive(Debug, Clone, Copy, PartialEq, Error)]
#[error("the brake's {what} must be {range}, got {value}")]
pub struct BrakeError {
    /// `max_torque`, `stiffness`, `damping` or `from`.
    pub what: &'static str,
    /// Its range.
    pub range: &'static str,
    /// What was given.
    pub value: f64,
}

impl Brake {
    /// A parking brake of `max_torque` (N m) applied at `from` (s), its
    /// elastic stage stiff enough that holding `max_torque` turns the
    /// sprocket 10 mrad (`k = 100 T`) and damped to ring out within a few
    /// of its periods on a sprocket of inertia `inertia` (kg m², the
    /// vehicle's mass reflected through it: `c = √(k J)`, damping ratio
    /// 0.5).
    pub fn parking(max_torque: f64, inertia: f64, from: f64) -> Brake {
        let stiffness = 100.0 * max_torque;
        Brake {
            max_torque,
            stiffness,
            damping: (stiffness * inertia).sqrt(),
            from,
        }
    }

    /// Every figure in its range.
    pub fn check(&self) -> Result<(), BrakeError> {
        let out = |what, range, value| Err(BrakeError { what, range, value });
        if !(self.max_torque.is_finite() && self.max_torque >= 0.0) {
            return out("max_torque", "finite and 0 or more (N m)", self.max_torque);
        }
        if !(self.stiffness.is_finite() && self.stiffness > 0.0) {
            return out(
                "stiffness",
                "finite and more than 0 (N m/rad)",
                self.stiffness,
            );
        }
        if !(self.damping.is_finite() && self.damping >= 0.0) {
            return out("damping", "finite and 0 or more (N m s/rad)", self.damping);
        }
        if self.from.is_nan() {
            return out("from", "a time (s)", self.from);
        }
        Ok(())
    }

    /// The brake as the drive law it is: a PI on the sprocket's speed with
    /// target 0, its proportional gain the damping, its integral gain the
    /// stiffness, its limit the brake's (the integral, started at 0 when
    /// the brake is applied, is `−φ`). Applied from the start of a run,
    /// as a spatial vehicle's side takes it
    /// ([`SideDrives`](crate::spatial_vehicle::SideDrives)); `from` is the
    /// planar vehicle's schedule, not read here.
    pub fn as_drive(&self) -> Drive {
        Drive::Speed {
            target: Box::new(|_| 0.0),
            proportional: self.damping,
            integral: self.stiffness,
            max_torque: self.max_torque,
        }
    }
}
