//! The multiplier form of formulation §2 as an integration method: all `n + 2`
//! coordinates integrated, the closure kept by Baumgarte stabilisation
//! during a step and by projection after it.

use nalgebra::{Matrix2, SMatrix, SVector, Vector2};

use crate::multibody::TrackModel;

/// Settings of the multiplier method.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MultiplierOptions {
    /// Baumgarte rate `ω` (1/s, default 10): the acceleration equation
    /// becomes `C_q q̈ = γ_c − 2ω Ċ − ω² C`, so drift decays critically
    /// damped within about `5/ω`. 0 turns stabilisation off.
    pub baumgarte: f64,
    /// Project `q_i` onto `C = 0` and `q̇_i` onto `C_q q̇ = 0` after every
    /// step (default `true`). The projection is least-squares in the
    /// angles; each restarts the integrator.
    pub projection: bool,
    /// Projection stops when `|C|` is below this fraction of the loop's
    /// length (default 1e-13).
    pub tolerance: f64,
}

impl Default for MultiplierOptions {
    fn default() -> Self {
        MultiplierOptions {
            baumgarte: 10.0,
            projection: true,
            tolerance: 1e-13,
        }
    }
}

impl MultiplierOptions {
    /// Baumgarte's stabilisation `2ω Ċ + ω² C` at the closure `C` and its
    /// rate `Ċ`: the acceleration equation is `C_q q̈ = γ_c − 2ω Ċ − ω² C`.
    pub fn stabilisation(&self, c: Vector2<f64>, c_rate: Vector2<f64>) -> Vector2<f64> {
        let omega = self.baumgarte;
        c_rate * (2.0 * omega) + c * (omega * omega)
    }
}

/// Why a projection onto the closure failed.
#[derive(Debug, Clone, Copy, PartialEq, thiserror::Error)]
pub enum ProjectionFailure {
    /// `C_q C_qᵀ` is singular (every link of the loop parallel).
    #[error("C_q C_qᵀ is singular (every link of the loop parallel)")]
    Singular,
    /// Gauss-Newton did not reach the tolerance.
    #[error("Gauss-Newton left |C| = {residual:e} m after {iterations} iterations")]
    NotConverged {
        /// Iterations taken.
        iterations: usize,
        /// `|C|` at the last iterate, m.
        residual: f64,
    },
}

/// Gauss-Newton iterations of [`project`] before giving up.
const PROJECTION_ITERATIONS: usize = 20;

/// Projects `(q_i, q̇_i)` onto the closure manifold: Gauss-Newton steps
/// `q ← q − C_qᵀ (C_q C_qᵀ)⁻¹ C` until `|C| ≤ tolerance` (m), then
/// `q̇ ← q̇ − C_qᵀ (C_q C_qᵀ)⁻¹ C_q q̇`.
pub fn project<M: TrackModel<D>, const D: usize>(
    model: &M,
    q: &mut SVector<f64, D>,
    qd: &mut SVector<f64, D>,
    tolerance: f64,
) -> Result<(), ProjectionFailure> {
    let correction =
        |cq: &SMatrix<f64, 2, D>, v: Vector2<f64>| -> Result<SVector<f64, D>, ProjectionFailure> {
            let gram: Matrix2<f64> = cq * cq.transpose();
            Ok(cq.transpose() * (gram.try_inverse().ok_or(ProjectionFailure::Singular)? * v))
        };
    let mut iterations = 0;
    loop {
        let c = model.closure(q);
        if c.norm() <= tolerance {
            break;
        }
        if iterations == PROJECTION_ITERATIONS || !c.norm().is_finite() {
            return Err(ProjectionFailure::NotConverged {
                iterations,
                residual: c.norm(),
            });
        }
        *q -= correction(&model.closure_jacobian(q), c)?;
        iterations += 1;
    }
    let cq = model.closure_jacobian(q);
    *qd -= correction(&cq, cq * *qd)?;
    Ok(())
}
