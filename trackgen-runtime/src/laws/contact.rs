//! Normal and tangential contact laws: a contact's force from its
//! penetration `δ` and slip, with the energy it stores and the power it
//! dissipates.

use super::{ParameterError, Response};

/// Normal force from penetration `δ` (m) and its rate `δ̇` (m/s, positive
/// closing). The force never pulls: it is clipped at zero.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum NormalLaw {
    /// `F = k δ + c δ̇` (Kelvin-Voigt): stiffness `k` (N/m) and damping `c`
    /// (N s/m).
    KelvinVoigt {
        /// N/m.
        stiffness: f64,
        /// N s/m.
        damping: f64,
    },
    /// `F = k δⁿ (1 + χ δ̇)` (Hunt & Crossley 1975): no force jump at
    /// impact; `χ` (s/m) sets the restitution (`χ ≈ 3(1 − e)/(2 v₀)`).
    HuntCrossley {
        /// N/mⁿ.
        stiffness: f64,
        /// n (1.5 for Hertzian contact).
        exponent: f64,
        /// s/m.
        chi: f64,
    },
}

impl NormalLaw {
    /// The normal force, N (0 when not in contact).
    pub fn force(&self, penetration: f64, rate: f64) -> f64 {
        if penetration <= 0.0 {
            return 0.0;
        }
        let f = match *self {
            NormalLaw::KelvinVoigt { stiffness, damping } => {
                stiffness * penetration + damping * rate
            }
            NormalLaw::HuntCrossley {
                stiffness,
                exponent,
                chi,
            } => stiffness * power(penetration, exponent) * (1.0 + chi * rate),
        };
        // Clip a pulling force, but let a NaN through (`f64::max` would
        // turn it into a silent zero, hiding a broken state).
        if f < 0.0 { 0.0 } else { f }
    }
}

impl NormalLaw {
    /// `(∂F/∂δ, ∂F/∂δ̇)` of [`force`](Self::force) at penetration `δ` (m)
    /// closing at `rate` (m/s): N/m and N s/m. Zero out of contact and
    /// where the force is clipped (it does not pull), as the force itself
    /// is flat there.
    #[inline]
    pub fn slopes(&self, penetration: f64, rate: f64) -> (f64, f64) {
        // A NaN force counts as clipped, as `force` itself would give it.
        let force = self.force(penetration, rate);
        if penetration <= 0.0 || force.is_nan() || force <= 0.0 {
            return (0.0, 0.0);
        }
        match *self {
            NormalLaw::KelvinVoigt { stiffness, damping } => (stiffness, damping),
            NormalLaw::HuntCrossley {
                stiffness,
                exponent,
                chi,
            } => {
                let elastic = stiffness * power(penetration, exponent);
                (
                    exponent * elastic / penetration * (1.0 + chi * rate),
                    elastic * chi,
                )
            }
        }
    }

    /// The elastic part of the force, N (what a penetration at rest gives).
    pub fn elastic_force(&self, penetration: f64) -> f64 {
        if penetration <= 0.0 {
            return 0.0;
        }
        match *self {
            NormalLaw::KelvinVoigt { stiffness, .. } => stiffness * penetration,
            NormalLaw::HuntCrossley {
                stiffness,
                exponent,
                ..
            } => stiffness * power(penetration, exponent),
        }
    }

    /// The elastic energy at a penetration, J: the integral of
    /// [`elastic_force`](Self::elastic_force).
    pub fn potential(&self, penetration: f64) -> f64 {
        if penetration <= 0.0 {
            return 0.0;
        }
        match *self {
            NormalLaw::KelvinVoigt { stiffness, .. } => 0.5 * stiffness * penetration * penetration,
            NormalLaw::HuntCrossley {
                stiffness,
                exponent,
                ..
            } => stiffness * penetration * power(penetration, exponent) / (exponent + 1.0),
        }
    }
}

/// Regularised Coulomb friction: `F_t = −μ F_n v / √(v² + v_s²)`, smooth
/// through zero slip, reaching 0.89 μ F_n at `v = 2 v_s`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Friction {
    /// Friction coefficient μ.
    pub mu: f64,
    /// Slip velocity of the regularisation `v_s`, m/s. Smaller is closer
    /// to Coulomb and stiffer to integrate (slope `μ F_n / v_s`).
    pub slip: f64,
}

impl Friction {
    /// `(∂F/∂F_n, ∂F/∂v)` of [`force`](Self::force) under normal force
    /// `normal` (N) at slip speed `slip_velocity` (m/s): the force's share
    /// of the normal force, `−μ v/√(v² + v_s²)`, and the regularisation's
    /// slope, `−μ F_n v_s²/(v² + v_s²)^{3/2}` (N s/m: what makes a rim's
    /// friction stiff, `μ F_n / v_s` at zero slip). Zero for plain Coulomb
    /// friction (`v_s = 0`), whose slope is zero but at zero slip.
    #[inline]
    pub fn slopes(&self, normal: f64, slip_velocity: f64) -> (f64, f64) {
        let (v, s) = (slip_velocity, self.slip.abs());
        let scale = v.hypot(s);
        if scale == 0.0 || s == 0.0 {
            return (0.0, 0.0);
        }
        let share = -self.mu * v / scale;
        let slope = -self.mu * normal * (s / scale) * (s / scale) / scale;
        (share, slope)
    }

    /// The tangential force along the slip direction, N (opposing `slip`).
    #[inline]
    pub fn force(&self, normal: f64, slip_velocity: f64) -> f64 {
        let (v, s) = (slip_velocity.abs(), self.slip.abs());
        // √(v² + v_s²) where the squares cannot overflow or underflow, the
        // C library's `hypot` beyond (several times slower), so the force
        // stays within μ F_n at any slip speed.
        // (A NaN slip passes the test, `max` dropping it, and gives NaN.)
        let scale = if (1e-150..1e150).contains(&v.max(s)) {
            (v * v + s * s).sqrt()
        } else {
            slip_velocity.hypot(self.slip)
        };
        // `slip = 0` is plain Coulomb friction (zero force at zero slip).
        if scale == 0.0 {
            0.0
        } else {
            -self.mu * normal * slip_velocity / scale
        }
    }
}

impl NormalLaw {
    /// The force (N, per unit of the contact's gradient), the elastic
    /// energy (J) and the power dissipated (W, the force beyond its elastic
    /// part times the closing rate) at penetration `δ` (m) closing at
    /// `rate` (m/s).
    #[inline]
    pub fn respond(&self, penetration: f64, rate: f64) -> Response<f64> {
        let force = self.force(penetration, rate);
        Response {
            force,
            potential: self.potential(penetration),
            dissipation: (force - self.elastic_force(penetration)) * rate,
        }
    }

    /// A law that pushes: stiffness positive, exponent positive, damping
    /// (`χ` or `c`) zero or more, all finite.
    pub fn check(&self) -> Result<(), ParameterError> {
        match *self {
            NormalLaw::KelvinVoigt { stiffness, damping } => {
                ParameterError::check("stiffness", stiffness, 0.0, true)?;
                ParameterError::check("damping", damping, 0.0, false)
            }
            NormalLaw::HuntCrossley {
                stiffness,
                exponent,
                chi,
            } => {
                ParameterError::check("stiffness", stiffness, 0.0, true)?;
                ParameterError::check("exponent", exponent, 0.0, true)?;
                ParameterError::check("chi", chi, 0.0, false)
            }
        }
    }
}

impl Friction {
    /// The friction force (N, along the slip direction) under normal force
    /// `normal` (N) at slip speed `slip_velocity` (m/s), and the power it
    /// dissipates, `−F v` (W); it stores nothing.
    #[inline]
    pub fn respond(&self, normal: f64, slip_velocity: f64) -> Response<f64> {
        let force = self.force(normal, slip_velocity);
        Response {
            force,
            potential: 0.0,
            dissipation: -(force * slip_velocity),
        }
    }

    /// A coefficient and a regularisation speed of zero or more, finite.
    pub fn check(&self) -> Result<(), ParameterError> {
        ParameterError::check("mu", self.mu, 0.0, false)?;
        ParameterError::check("slip", self.slip, 0.0, false)
    }
}

/// `x^n`, without `powf` for the common linear law.
#[inline]
fn power(x: f64, n: f64) -> f64 {
    if n == 1.0 { x } else { x.powf(n) }
}
