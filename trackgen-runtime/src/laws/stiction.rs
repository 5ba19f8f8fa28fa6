//! Friction with stiction: an elastic tangential contact with a Coulomb
//! limit.
//!
//! The tangential spring-dashpot with history of discrete-element contact
//! (Cundall & Strack, *Géotechnique* 29(1), 1979; the form with the
//! dashpot inside the Coulomb limit is Luding's, *Granular Matter* 10,
//! 2008, §2.4), written in rate form so that its history is an integrated
//! state, as this project's integrators need: a Kelvin-Voigt element
//! (stiffness `k`, damping `c`) in series with a rigid Coulomb slider.
//! The contact point's slip velocity `v` (of the body's material point
//! against the ground, along the tangent) is the element's stretch rate
//! `ż` plus the slider's slip rate `s`:
//!
//! * **sticking**, `|k z + c v| ≤ μ F_n`: the slider holds, `s = 0`,
//!   `ż = v`, the force on the body is `−(k z + c v)`. A body at rest
//!   under a tangential load below the limit stays at rest: the spring
//!   holds the load at a deflection `z = F/k`, and nothing creeps (a
//!   regularised Coulomb law needs a sliding speed to carry any load);
//! * **sliding**, beyond: the element's force is held at the limit,
//!   `k z + c ż = σ μ F_n` (`σ` the sign of `k z + c v`), so
//!   `s = σ (|k z + c v| − μ F_n)/c` and `ż = v − s`; the force on the
//!   body is `−σ μ F_n`, Coulomb's exactly.
//!
//! The force is continuous across the two (the slip rate grows from zero),
//! never exceeds `μ F_n` — when the normal force falls the deflection
//! relaxes at once through the damper, and a contact that lifts
//! (`F_n = 0`) pushes nothing, its deflection relaxing as `ż = −k z/c`.
//! Energy: the spring stores `½ k z²`; the power dissipated is
//! `c ż² + μ F_n |s|` (the damper and the slider), never negative, and the
//! power the body puts in, `−F v`, is exactly their sum with the stored
//! energy's rate, so the books balance by construction.

use super::ParameterError;

/// A deflection this close to 0 (m) has relaxed ([`Stiction::relax`]).
///
/// Off the ground a deflection decays as `e^(−k t / c)` and never reaches
/// 0: some 350 time constants `c/k` into a flight (under two seconds on
/// the M113's fitted laws) it is below `10⁻¹⁵⁴` m, where its stored
/// energy `½ k z²` underflows to a subnormal number, and then the state
/// itself goes subnormal. Arithmetic on subnormals takes a microcode
/// assist on x86 (about a hundred times an ordinary operation) in every
/// vector operation that carries one: on the M113's main job, one ground
/// point's state relaxing there cost 2.5 % of the run's wall time
/// (measured by running it with the processor flushing subnormals to 0,
/// with the same output files). So the law stops the deflection here:
/// `10⁻¹⁵⁰` m leaves a stored energy of `½ k · 10⁻³⁰⁰` J and a force of
/// `k · 10⁻¹⁵⁰` N when the point lands, neither of which a sum of
/// forces or energies of ordinary size can register.
pub const RELAXED: f64 = 1e-150;

/// The elastic-Coulomb tangential law of a contact point.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Stiction {
    /// Friction coefficient `μ` (static and sliding alike).
    pub mu: f64,
    /// Tangential stiffness `k`, N/m: the load a sticking contact carries
    /// per metre of deflection.
    pub stiffness: f64,
    /// Tangential damping `c`, N s/m (positive: the slider's slip rate is
    /// the excess force over it).
    pub damping: f64,
}

/// What [`Stiction`] gives at a state.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TangentialResponse {
    /// The force on the body along the tangent, N (opposing its slip).
    pub force: f64,
    /// `ż`, the deflection's rate, m/s.
    pub rate: f64,
    /// Elastic energy in the spring, `½ k z²`, J.
    pub potential: f64,
    /// Power dissipated by the damper and the slider, W.
    pub dissipation: f64,
    /// Whether the contact slides.
    pub sliding: bool,
}

/// The first derivatives of [`Stiction::respond`] (or
/// [`Stiction::relax`]) with respect to the deflection `z`, the slip
/// velocity `v` and the normal force `F_n`.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct TangentialSlopes {
    /// `(∂F/∂z, ∂F/∂v, ∂F/∂F_n)`: N/m, N s/m, 1.
    pub force: [f64; 3],
    /// `(∂ż/∂z, ∂ż/∂v, ∂ż/∂F_n)`: 1/s, 1, m/(N s).
    pub rate: [f64; 3],
}

impl Stiction {
    /// [`respond`](Self::respond)'s first derivatives at the same
    /// arguments. Sticking, `F = −(k z + c v)` and `ż = v`; sliding,
    /// `F = −σ μ F_n` and `ż = v − σ(|k z + c v| − μ F_n)/c = (σ μ F_n −
    /// k z)/c`, which no longer depends on `v`.
    #[inline]
    pub fn slopes(&self, z: f64, v: f64, normal: f64) -> TangentialSlopes {
        let (k, c) = (self.stiffness, self.damping);
        let stick = k * z + c * v;
        let limit = self.mu * normal;
        if stick.abs() <= limit {
            return TangentialSlopes {
                force: [-k, -c, 0.0],
                rate: [0.0, 1.0, 0.0],
            };
        }
        let sigma = stick.signum();
        TangentialSlopes {
            force: [0.0, 0.0, -sigma * self.mu],
            rate: [-k / c, 0.0, sigma * self.mu / c],
        }
    }

    /// [`relax`](Self::relax)'s first derivatives: only `∂ż/∂z = −k/c`,
    /// also within [`RELAXED`] of 0, where the law has stopped: the slope
    /// of the relaxation that got it there, the one every difference
    /// quotient of a representable step sees, and the relaxation mode a
    /// linearisation at rest must keep (a lifted point's deflection is
    /// exactly 0 there).
    #[inline]
    pub fn relax_slopes(&self) -> TangentialSlopes {
        TangentialSlopes {
            force: [0.0; 3],
            rate: [-self.stiffness / self.damping, 0.0, 0.0],
        }
    }

    /// The energy the elastic stage stores at deflection `z` (m), J:
    /// `½ k z²`.
    #[inline]
    pub fn potential(&self, z: f64) -> f64 {
        0.5 * self.stiffness * z * z
    }

    /// The law at deflection `z` (m), slip velocity `v` (m/s, the body's
    /// point against the ground along the tangent) and normal force
    /// `normal` (N, ≥ 0).
    #[inline]
    pub fn respond(&self, z: f64, v: f64, normal: f64) -> TangentialResponse {
        let (k, c) = (self.stiffness, self.damping);
        let potential = self.potential(z);
        let stick = k * z + c * v;
        let limit = self.mu * normal;
        if stick.abs() <= limit {
            return TangentialResponse {
                force: -stick,
                rate: v,
                potential,
                dissipation: c * v * v,
                sliding: false,
            };
        }
        let sigma = stick.signum();
        let slip = (stick.abs() - limit) / c;
        let rate = v - sigma * slip;
        TangentialResponse {
            force: -sigma * limit,
            rate,
            potential,
            dissipation: c * rate * rate + limit * slip,
            sliding: true,
        }
    }

    /// The law off contact: no force, the deflection relaxing through the
    /// damper, `ż = −k z / c`, its energy dissipated; a deflection within
    /// [`RELAXED`] of 0 has relaxed, and stays (rate, energy and power 0).
    #[inline]
    pub fn relax(&self, z: f64) -> TangentialResponse {
        if z.abs() < RELAXED {
            return TangentialResponse {
                force: 0.0,
                rate: 0.0,
                potential: 0.0,
                dissipation: 0.0,
                sliding: true,
            };
        }
        let rate = -self.stiffness * z / self.damping;
        TangentialResponse {
            force: 0.0,
            rate,
            potential: 0.5 * self.stiffness * z * z,
            dissipation: self.damping * rate * rate,
            sliding: true,
        }
    }

    /// [`relax`](Self::relax) for each of `deflections` (m), its rate into
    /// `rates` (m/s, from the start); what they store (J) and dissipate
    /// (W) in all. Each rate is `relax`'s to the bit; the sums are taken in
    /// four lanes (each lane in order, then the lanes in turn), so they
    /// may differ from `relax`'s added one by one in the last bits, and
    /// the four chains of additions run side by side.
    #[inline]
    pub fn relax_each(&self, deflections: &[f64], rates: &mut [f64]) -> (f64, f64) {
        let (mut stored, mut lost) = ([0.0; 4], [0.0; 4]);
        for (j, (&z, rate)) in deflections.iter().zip(rates.iter_mut()).enumerate() {
            let relaxing = self.relax(z);
            *rate = relaxing.rate;
            stored[j % 4] += relaxing.potential;
            lost[j % 4] += relaxing.dissipation;
        }
        (
            (stored[0] + stored[1]) + (stored[2] + stored[3]),
            (lost[0] + lost[1]) + (lost[2] + lost[3]),
        )
    }

    /// A coefficient of zero or more, a positive stiffness and damping, all
    /// finite.
    pub fn check(&self) -> Result<(), ParameterError> {
        ParameterError::check("mu", self.mu, 0.0, false)?;
        ParameterError::check("tangential stiffness", self.stiffness, 0.0, true)?;
        ParameterError::check("tangential damping", self.damping, 0.0, true)
    }
}
