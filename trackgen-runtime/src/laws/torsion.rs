//! The torsion spring-damper of a sprung arm (a road wheel's torsion bar,
//! an idler's tensioner): `τ = preload − k φ − c φ̇` about the pivot, with
//! `φ` the arm's angle from its design position.

use super::{ParameterError, Response};

/// A torsion spring-damper: stiffness, damping and the torque at the
/// design position.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TorsionSpring {
    /// `k`, N m/rad.
    pub stiffness: f64,
    /// `c`, N m s/rad.
    pub damping: f64,
    /// Torque at the design position, N m (counter-clockwise on the arm).
    pub preload: f64,
}

impl TorsionSpring {
    /// The torque on the arm at deflection `phi` (rad) and rate `rate`
    /// (rad/s), N m: `preload − k φ − c φ̇`.
    #[inline]
    pub fn torque(&self, phi: f64, rate: f64) -> f64 {
        self.preload - self.stiffness * phi - self.damping * rate
    }

    /// `(∂τ/∂φ, ∂τ/∂φ̇) = (−k, −c)`: N m/rad, N m s/rad.
    #[inline]
    pub fn slopes(&self) -> (f64, f64) {
        (-self.stiffness, -self.damping)
    }

    /// The spring's potential `½ k φ² − preload φ`, J (zero at the design
    /// position), whose negative gradient is the elastic torque.
    #[inline]
    pub fn energy(&self, phi: f64) -> f64 {
        0.5 * self.stiffness * phi * phi - self.preload * phi
    }

    /// The power the damper dissipates, `c φ̇²`, W.
    #[inline]
    pub fn dissipation(&self, rate: f64) -> f64 {
        self.damping * rate * rate
    }

    /// Torque, energy and dissipation together.
    #[inline]
    pub fn respond(&self, phi: f64, rate: f64) -> Response<f64> {
        Response {
            force: self.torque(phi, rate),
            potential: self.energy(phi),
            dissipation: self.dissipation(rate),
        }
    }

    /// Rates of zero or more and a preload, all finite.
    pub fn check(&self) -> Result<(), ParameterError> {
        ParameterError::check("stiffness", self.stiffness, 0.0, false)?;
        ParameterError::check("damping", self.damping, 0.0, false)?;
        ParameterError::check("preload", self.preload, f64::NEG_INFINITY, false)
    }
}
