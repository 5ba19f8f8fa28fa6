//! The secondary joint of the paper's Fig. 5: the closing joint cut, a
//! spring-damper across the cut. [`PenaltyJoint`] is the one owner of its
//! law: the force, the elastic energy and the power it dissipates; the
//! generated code of a penalty-closed track calls it too.

use nalgebra::{SMatrix, SVector, Vector2};

use super::{ParameterError, Response};

/// A spring-damper between the two points of the cut closing joint,
/// `P_n = Rⁿ + Aⁿ ū2ⁿ` on link n and `P_1 = R¹ + A¹ ū1¹` on link 1.
/// Their gap is the closure `C = P_n − P_1` (formulation §2) and its rate
/// `Ċ = C_q q̇`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PenaltyJoint {
    /// `k`, N/m.
    pub stiffness: f64,
    /// `c`, N s/m.
    pub damping: f64,
}

impl PenaltyJoint {
    /// The force on link n at `P_n`, N: `F = −k C − c Ċ`; link 1 takes
    /// `−F` at `P_1`.
    #[inline]
    pub fn force(&self, gap: Vector2<f64>, rate: Vector2<f64>) -> Vector2<f64> {
        -gap * self.stiffness - rate * self.damping
    }

    /// The spring's elastic energy `½ k |C|²`, J.
    #[inline]
    pub fn energy(&self, gap: Vector2<f64>) -> f64 {
        0.5 * self.stiffness * gap.norm_squared()
    }

    /// The power the damper dissipates, `c |Ċ|²`, W.
    #[inline]
    pub fn dissipation(&self, rate: Vector2<f64>) -> f64 {
        self.damping * rate.norm_squared()
    }

    /// Force, energy and dissipation together.
    #[inline]
    pub fn respond(&self, gap: Vector2<f64>, rate: Vector2<f64>) -> Response<Vector2<f64>> {
        Response {
            force: self.force(gap, rate),
            potential: self.energy(gap),
            dissipation: self.dissipation(rate),
        }
    }

    /// Its generalised forces `C_qᵀ F` at `(q_i, q̇_i)`: `C_qᵀ` maps the
    /// force at the gap to generalised forces by virtual work.
    pub fn generalized_forces<const D: usize>(
        &self,
        cq: &SMatrix<f64, 2, D>,
        gap: Vector2<f64>,
        qd: &SVector<f64, D>,
    ) -> SVector<f64, D> {
        cq.transpose() * self.force(gap, cq * qd)
    }

    /// A spring that closes the loop: stiffness positive and damping zero
    /// or more, both finite.
    pub fn check(&self) -> Result<(), ParameterError> {
        ParameterError::check("stiffness", self.stiffness, 0.0, true)?;
        ParameterError::check("damping", self.damping, 0.0, false)
    }
}
