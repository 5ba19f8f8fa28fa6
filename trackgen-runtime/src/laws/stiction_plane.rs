//! [`Stiction`] in the ground's plane: the same elastic-Coulomb law with
//! a two-component deflection and slip, isotropic (the Coulomb limit is a
//! circle, `|k z + c v| ≤ μ F_n`), for a contact point that may slide
//! along and across a track at once (a shoe in a turn: the lateral slip
//! that resists the turn; Wong & Chiang's general theory of skid
//! steering rests on the same isotropy).
//!
//! With the trial force `f = k z + c v` (vectors in the plane):
//!
//! * **sticking**, `|f| ≤ μ F_n`: `ż = v`, the force on the body `−f`;
//! * **sliding**: the force on the body `−μ F_n f̂` (`f̂ = f/|f|`), the
//!   slider slipping at `s = (|f| − μ F_n)/c · f̂` along the trial force,
//!   and `ż = v − s = (μ F_n f̂ − k z)/c`.
//!
//! The stored energy is `½ k |z|²` and the dissipation `c |ż|² + μ F_n |s|`,
//! and `−F·v` equals their sum with the stored energy's rate exactly, as
//! for the law along one tangent, which this is when `z` and `v` lie along
//! one line (along an axis the same force and rate bit for bit, the same
//! energies to rounding).

use nalgebra::{Matrix2, Vector2};

use super::Stiction;

/// What [`Stiction::respond_in_plane`] gives at a state.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PlaneTangentialResponse {
    /// The force on the body in the plane, N (its size at most `μ F_n`).
    pub force: Vector2<f64>,
    /// `ż`, the deflection's rate, m/s.
    pub rate: Vector2<f64>,
    /// Elastic energy in the spring, `½ k |z|²`, J.
    pub potential: f64,
    /// Power dissipated by the damper and the slider, W.
    pub dissipation: f64,
    /// Whether the contact slides.
    pub sliding: bool,
}

/// The first derivatives of [`Stiction::respond_in_plane`] with respect
/// to the deflection `z`, the slip velocity `v` and the normal force
/// `F_n`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PlaneTangentialSlopes {
    /// `∂F/∂z` (N/m), `∂F/∂v` (N s/m), `∂F/∂F_n` (1).
    pub force: (Matrix2<f64>, Matrix2<f64>, Vector2<f64>),
    /// `∂ż/∂z` (1/s), `∂ż/∂v` (1), `∂ż/∂F_n` (m/(N s)).
    pub rate: (Matrix2<f64>, Matrix2<f64>, Vector2<f64>),
}

impl Stiction {
    /// The law in the plane at deflection `z` (m), slip velocity `v` (m/s,
    /// the body's point against the ground) and normal force `normal` (N,
    /// ≥ 0).
    #[inline]
    pub fn respond_in_plane(
        &self,
        z: Vector2<f64>,
        v: Vector2<f64>,
        normal: f64,
    ) -> PlaneTangentialResponse {
        let (k, c) = (self.stiffness, self.damping);
        let potential = 0.5 * k * z.norm_squared();
        let trial = k * z + c * v;
        let limit = self.mu * normal;
        let size = trial.norm();
        if size <= limit {
            return PlaneTangentialResponse {
                force: -trial,
                rate: v,
                potential,
                dissipation: c * v.norm_squared(),
                sliding: false,
            };
        }
        let along = trial / size;
        let slip = (size - limit) / c;
        let rate = v - slip * along;
        PlaneTangentialResponse {
            force: -limit * along,
            rate,
            potential,
            dissipation: c * rate.norm_squared() + limit * slip,
            sliding: true,
        }
    }

    /// [`respond_in_plane`](Self::respond_in_plane)'s first derivatives at
    /// the same arguments. Sticking, `F = −(k z + c v)`, `ż = v`; sliding,
    /// with `P = (I − f̂ f̂ᵀ)/|f|` the turning of `f̂` with `f`:
    /// `∂F/∂z = −μ F_n k P`, `∂F/∂v = −μ F_n c P`, `∂F/∂F_n = −μ f̂`, and
    /// `ż = (μ F_n f̂ − k z)/c`: `∂ż/∂z = −(k/c) I + μ F_n (k/c) P`,
    /// `∂ż/∂v = μ F_n P`, `∂ż/∂F_n = μ f̂ / c`.
    #[inline]
    pub fn slopes_in_plane(
        &self,
        z: Vector2<f64>,
        v: Vector2<f64>,
        normal: f64,
    ) -> PlaneTangentialSlopes {
        let (k, c) = (self.stiffness, self.damping);
        let trial = k * z + c * v;
        let limit = self.mu * normal;
        let size = trial.norm();
        let one = Matrix2::identity();
        if size <= limit {
            return PlaneTangentialSlopes {
                force: (-k * one, -c * one, Vector2::zeros()),
                rate: (Matrix2::zeros(), one, Vector2::zeros()),
            };
        }
        let along = trial / size;
        let turning = (one - along * along.transpose()) / size;
        PlaneTangentialSlopes {
            force: (-limit * k * turning, -limit * c * turning, -self.mu * along),
            rate: (
                -(k / c) * one + limit * (k / c) * turning,
                limit * turning,
                self.mu * along / c,
            ),
        }
    }
}
