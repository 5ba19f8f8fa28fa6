//! The derivative of a body tree's forward dynamics in recursive
//! coordinates, densely (formulation §1-3): for a chassis (a handful of bodies),
//! and as the independent route the linear-time derivative of a track is
//! tested against.
//!
//! With `H` the velocity transform (`q̇ = H q̇_i`, absolute velocities of
//! every body), `a = H q̈_i + γ` the absolute accelerations and `r = F − M a`
//! what the joints (and the loop, if any) must carry, the equations
//! `M_i q̈_i = Hᵀ (F − M γ)` (eqs. (15)-(16)) differentiate along a direction
//! `(δq_i, δq̇_i, δF)` into
//!
//! ```text
//! M_i δq̈_i = δHᵀ r + Hᵀ (δF − M δa₀),    δa₀ = δH q̈_i + δγ
//! ```
//!
//! (`δa₀` the change of the absolute accelerations at fixed `q̈_i`). Each
//! body's position is a sum of terms of one angle each,
//! `Rᵇ = Rᵖ + Aᵖ ūₚ − Aᵇ ūᵇ`, so `∂²R/∂θⱼ∂θₖ` vanishes for `j ≠ k` and
//! `δHᵀ r` is diagonal in the angles: `sₖ δθₖ`, with `sₖ = Σ_b rᵇ·∂²Rᵇ/∂θₖ²`
//! worked out once. A track closed by a constraint adds the multiplier
//! form (formulation §2): `[M_i C_qᵀ; C_q 0]`, right sides
//! `−δC_qᵀ λ` and `δγ_c − δC_q q̈_i`.

use nalgebra::{DMatrix, DVector, Vector2};

use crate::multibody::DynamicsError;
use crate::multibody::{BodyLoad, Closure, TreeDescription};
use crate::planar::{Rotation, perp};

/// One direction along which to differentiate a tree: the changes of its
/// recursive coordinates `δq_i`, their rates `δq̇_i` (each `DOF` long, or
/// empty) and of the loads besides gravity (one per body, or empty).
#[derive(Debug, Clone, Copy, Default)]
pub struct TreeDirection<'a> {
    /// `δq_i`.
    pub coordinates: &'a [f64],
    /// `δq̇_i`.
    pub rates: &'a [f64],
    /// `δF`, one per body.
    pub loads: &'a [BodyLoad],
}

/// A body tree's dynamics factored at a state (`M_i` by LU, with the
/// loop's multiplier rows for a constrained track), for the derivative of
/// its accelerations along any number of directions.
#[derive(Debug, Clone)]
pub struct TreeTangent {
    description: TreeDescription,
    dof: usize,
    /// Each body's rotation and `ω` at the state.
    rotation: Vec<Rotation>,
    omega: Vec<f64>,
    /// `H`, rows `(ẋ, ẏ, ω)` per body.
    h: DMatrix<f64>,
    /// The top `DOF` rows of `M_i⁻¹` (or of the multiplier form's
    /// inverse: `DOF × (DOF + 2)`), from its LU factors; whether the last
    /// factorisation succeeded.
    inverse: DMatrix<f64>,
    factored: bool,
    /// The accelerations' response to the bodies' loads, `M_i⁻¹ Hᵀ`
    /// (`DOF × 3m`; through the multiplier form for a constrained track).
    response: DMatrix<f64>,
    /// `q̈_i` and the loop's `λ` (constrained track).
    qdd: DVector<f64>,
    lambda: Vector2<f64>,
    /// `sₖ` per angle.
    s: Vec<f64>,
    /// The loop's spans `d̄ʲ` turned, `Aʲ d̄ʲ` (constrained track).
    spans: Vec<Vector2<f64>>,
    constrained: bool,
}

impl TreeTangent {
    /// The tangent of the tree `description` (its loop closed as declared:
    /// by the multiplier form when constrained; a penalty joint's force is
    /// a load the caller gives).
    pub fn new(description: &TreeDescription) -> TreeTangent {
        let m = description.len();
        let constrained = description
            .loop_joint
            .is_some_and(|j| j.closure == Closure::Partitioned);
        TreeTangent {
            description: description.clone(),
            dof: m + 2,
            rotation: vec![Rotation::from_sin_cos((0.0, 1.0)); m],
            omega: vec![0.0; m],
            h: DMatrix::zeros(3 * m, m + 2),
            inverse: DMatrix::zeros(m + 2, m + 2),
            factored: false,
            response: DMatrix::zeros(m + 2, 3 * m),
            qdd: DVector::zeros(m + 2),
            lambda: Vector2::zeros(),
            s: vec![0.0; m],
            spans: Vec::new(),
            constrained,
        }
    }

    /// `H` at the factored rotations ([`TreeDescription::velocity_transform`]).
    fn velocity_transform(&mut self) {
        self.description
            .velocity_transform(&self.rotation, &mut self.h);
    }

    /// Each body's absolute acceleration at fixed `q̈_i` from the velocity
    /// terms, and its change along `(δθ, δω)` of every angle (`dtheta`,
    /// `domega`, one per body; `None` for the plain `γ`): by the tree,
    /// `R̈ᵇ = R̈ᵖ + A_θᵖ ūₚ θ̈ᵖ − Aᵖ ūₚ ωₚ² − A_θᵇ ūᵇ θ̈ᵇ + Aᵇ ūᵇ ωᵇ²`.
    fn translational(
        &self,
        qdd: &DVector<f64>,
        change: Option<(&[f64], &[f64])>,
    ) -> Vec<Vector2<f64>> {
        let bodies = &self.description.bodies;
        let m = bodies.len();
        let mut out = vec![Vector2::zeros(); m];
        for b in 0..m {
            let Some(p) = bodies[b].parent else {
                out[b] = match change {
                    None => Vector2::new(qdd[0], qdd[1]),
                    Some(_) => Vector2::zeros(),
                };
                continue;
            };
            // A joint term `A ū` on body `k`, entering with `sign`.
            let term = |k: usize, u: Vector2<f64>, sign: f64| -> Vector2<f64> {
                let arm = self.rotation[k].apply(u);
                let (acc, w) = (qdd[2 + k], self.omega[k]);
                match change {
                    None => (perp(arm) * acc - arm * (w * w)) * sign,
                    Some((dtheta, domega)) => {
                        ((-arm * acc - perp(arm) * (w * w)) * dtheta[k]
                            - arm * (2.0 * w * domega[k]))
                            * sign
                    }
                }
            };
            out[b] = out[p] + term(p, bodies[b].at_parent, 1.0) + term(b, bodies[b].at_self, -1.0);
        }
        out
    }

    /// Factors the dynamics at `(q_i, q̇_i)` under `loads` besides gravity
    /// (one per body, or none), and solves them there.
    pub fn factor(
        &mut self,
        q: &[f64],
        qd: &[f64],
        loads: &[BodyLoad],
    ) -> Result<(), DynamicsError> {
        let m = self.description.len();
        let dof = self.dof;
        self.factored = false;
        for b in 0..m {
            self.rotation[b] = Rotation::from_sin_cos(q[2 + b].sin_cos());
            self.omega[b] = qd[2 + b];
        }
        self.velocity_transform();
        let bodies = self.description.bodies.clone();
        let mass = |row: usize| -> f64 {
            let body = &bodies[row / 3];
            if row % 3 == 2 {
                body.inertia
            } else {
                body.mass
            }
        };
        // `M_i = Hᵀ M H` (eq. (15)).
        let mut weighted = self.h.clone();
        for (r, mut row) in weighted.row_iter_mut().enumerate() {
            row *= mass(r);
        }
        let transform = self.h.transpose();
        let matrix = &transform * weighted;
        // The applied loads, gravity included, less `M γ`.
        let gamma = self.translational(&DVector::zeros(dof), None);
        let mut applied = DVector::zeros(3 * m);
        for b in 0..m {
            let load = loads.get(b).copied().unwrap_or(BodyLoad::ZERO);
            let f = self.description.gravity * bodies[b].mass + load.force;
            applied[3 * b] = f.x;
            applied[3 * b + 1] = f.y;
            applied[3 * b + 2] = load.moment;
        }
        let mut reduced = applied.clone();
        for b in 0..m {
            reduced[3 * b] -= bodies[b].mass * gamma[b].x;
            reduced[3 * b + 1] -= bodies[b].mass * gamma[b].y;
        }
        let forces = &transform * reduced;
        if self.constrained {
            self.spans = self
                .description
                .link_spans()
                .unwrap_or_default()
                .iter()
                .zip(&self.rotation)
                .map(|(d, r)| r.apply(*d))
                .collect();
            let mut kkt = DMatrix::zeros(dof + 2, dof + 2);
            kkt.view_mut((0, 0), (dof, dof)).copy_from(&matrix);
            for (j, span) in self.spans.iter().enumerate() {
                let column = perp(*span);
                for r in 0..2 {
                    kkt[(dof + r, 2 + j)] = column[r];
                    kkt[(2 + j, dof + r)] = column[r];
                }
            }
            let gamma_c: Vector2<f64> = self
                .spans
                .iter()
                .zip(&self.omega)
                .map(|(s, w)| s * (w * w))
                .sum();
            let mut rhs = DVector::zeros(dof + 2);
            rhs.rows_mut(0, dof).copy_from(&forces);
            rhs[dof] = gamma_c.x;
            rhs[dof + 1] = gamma_c.y;
            let lu = kkt.lu();
            let x = lu.solve(&rhs).ok_or(DynamicsError::SingularClosure)?;
            self.qdd = x.rows(0, dof).into_owned();
            self.lambda = Vector2::new(x[dof], x[dof + 1]);
            let inverse = lu.try_inverse().ok_or(DynamicsError::SingularClosure)?;
            self.inverse = inverse.rows(0, dof).into_owned();
        } else {
            let lu = matrix.lu();
            self.qdd = lu.solve(&forces).ok_or(DynamicsError::SingularClosure)?;
            self.inverse = lu.try_inverse().ok_or(DynamicsError::SingularClosure)?;
        }
        self.response = self.inverse.columns(0, dof) * &transform;
        self.factored = true;
        // What the joints carry, `r = F − M a`, and `sₖ = Σ rᵇ·∂²Rᵇ/∂θₖ²`
        // (`∂²R/∂θ² = −A ū` of every lever: minus the lever turned back).
        let accel = self.translational(&self.qdd.clone(), None);
        self.s.fill(0.0);
        for b in 0..m {
            let r = Vector2::new(applied[3 * b], applied[3 * b + 1]) - accel[b] * bodies[b].mass;
            for k in 0..m {
                let lever = Vector2::new(self.h[(3 * b, 2 + k)], self.h[(3 * b + 1, 2 + k)]);
                // lever = ⟂(A u) ⇒ ∂lever/∂θ = −A u = ⟂(lever).
                self.s[k] += r.dot(&perp(lever));
            }
        }
        if self.constrained {
            // The loop's force −λ on the closure: `−δC_qᵀ λ`, diagonal too.
            for (k, span) in self.spans.iter().enumerate() {
                self.s[k] += span.dot(&self.lambda);
            }
        }
        Ok(())
    }

    /// `q̈_i` at the factored state.
    pub fn accelerations(&self) -> &DVector<f64> {
        &self.qdd
    }

    /// The derivative of `q̈_i` along `direction`, into `out` (`DOF` long).
    pub fn direction(&self, direction: &TreeDirection<'_>, out: &mut [f64]) {
        let m = self.description.len();
        let dof = self.dof;
        let zeros = vec![0.0; dof];
        let dq = if direction.coordinates.is_empty() {
            &zeros
        } else {
            direction.coordinates
        };
        let dqd = if direction.rates.is_empty() {
            &zeros
        } else {
            direction.rates
        };
        let (dtheta, domega) = (&dq[2..], &dqd[2..]);
        let changed = self.translational(&self.qdd, Some((dtheta, domega)));
        let bodies = &self.description.bodies;
        let mut w = DVector::zeros(3 * m);
        for b in 0..m {
            let load = direction.loads.get(b).copied().unwrap_or(BodyLoad::ZERO);
            let f = load.force - changed[b] * bodies[b].mass;
            w[3 * b] = f.x;
            w[3 * b + 1] = f.y;
            w[3 * b + 2] = load.moment;
        }
        if !self.factored {
            out.fill(f64::NAN);
            return;
        }
        // `M_i⁻¹ (Hᵀ w + s δθ)`, through the kept inverse.
        let mut solution = &self.response * w;
        for (k, &change) in dtheta.iter().enumerate().take(m) {
            if change != 0.0 {
                solution.axpy(self.s[k] * change, &self.inverse.column(2 + k), 1.0);
            }
        }
        if self.constrained {
            // δγ_c − δC_q q̈: `Σ (A_θ d̄ ω² δθ + 2 A d̄ ω δω) + Σ A d̄ θ̈ δθ`.
            let mut dgamma = Vector2::zeros();
            for (k, span) in self.spans.iter().enumerate() {
                let (wk, acc) = (self.omega[k], self.qdd[2 + k]);
                dgamma += perp(*span) * (wk * wk * dtheta[k])
                    + span * (2.0 * wk * domega[k] + acc * dtheta[k]);
            }
            solution.axpy(dgamma.x, &self.inverse.column(dof), 1.0);
            solution.axpy(dgamma.y, &self.inverse.column(dof + 1), 1.0);
        }
        out.copy_from_slice(solution.as_slice());
    }

    /// The derivative of `q̈_i` along directions that change the loads
    /// alone (`δq_i = δq̇_i = 0`): `M_i δq̈_i = Hᵀ δF`, the load term of
    /// [`TreeTangent::direction`], for every column of `loads` (`3m × k`,
    /// rows `(F_x, F_y, M)` per body) at once, through `M_i⁻¹ Hᵀ` kept
    /// from the factorisation; the columns of the returned `DOF × k`
    /// matrix, NaN where the factorisation failed.
    pub fn load_directions(&self, loads: &DMatrix<f64>) -> DMatrix<f64> {
        if !self.factored {
            return DMatrix::from_element(self.dof, loads.ncols(), f64::NAN);
        }
        &self.response * loads
    }
}
