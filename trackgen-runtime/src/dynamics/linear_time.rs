//! Linear-time forward dynamics of a track (formulation §5): each link's absolute
//! accelerations and the joint forces `λ` as unknowns. The joint forces
//! solve a block-tridiagonal system with 2 × 2 blocks (cyclic for a closed
//! loop, handled by bordering), so the cost is O(n) instead of the dense
//! O(n³) of `M_i q̈_i = Q_i`.
//!
//! With `D⁺ⱼ = [A_θʲ ū2ʲ | I₂]`, `D⁻ₖ = [A_θᵏ ū1ᵏ | I₂]` and
//! `Wᵢ = diag(1/Jᵢ, 1/mᵢ, 1/mᵢ)`:
//!
//! ```text
//! aᵢ = Wᵢ (Fᵢ + D⁺ᵢᵀ λᵢ − D⁻ᵢᵀ λᵢ₋₁)
//! D⁺ⱼ aⱼ − D⁻ₖ aₖ = κⱼ,   κⱼ = Aʲ ū2ʲ ωⱼ² − Aᵏ ū1ᵏ ωₖ²      (joint j: link j → k)
//! ```

use nalgebra::{Matrix2, Matrix2x3, SVector, Vector2};

use crate::multibody::DynamicsError;
use crate::multibody::{BodyLoad, Closure, TrackModel};

/// The per-link constants of a chain.
#[derive(Debug, Clone)]
struct Link {
    inv_mass: f64,
    inv_inertia: f64,
    mass: f64,
    u1: Vector2<f64>,
    u2: Vector2<f64>,
}

/// Per-link values at a state.
#[derive(Debug, Clone, Copy, Default)]
struct Kinematics {
    /// `A_θ ū1`, `A_θ ū2`.
    p1: Vector2<f64>,
    p2: Vector2<f64>,
    /// Applied force and moment, gravity included.
    force: Vector2<f64>,
    moment: f64,
}

/// Linear-time forward dynamics for one track model, with its scratch
/// space allocated once.
#[derive(Debug, Clone)]
pub struct LinearTimeSolver {
    links: Vec<Link>,
    gravity: Vector2<f64>,
    closure: Closure,
    kin: Vec<Kinematics>,
    /// Joint blocks: diagonal, the coupling to the previous joint, and the
    /// right side, for joints 0 … n−2 (and the closing joint n−1).
    diagonal: Vec<Matrix2<f64>>,
    lower: Vec<Matrix2<f64>>,
    rhs: Vec<Vector2<f64>>,
    /// Elimination: the reduced diagonal's inverse and the right sides
    /// (with the two bordering columns alongside).
    inverse: Vec<Matrix2<f64>>,
    reduced: Vec<Matrix2x3<f64>>,
    lambda: Vec<Vector2<f64>>,
}

/// The inverse of a 2 × 2 matrix, if it is regular.
#[inline(always)]
fn inverse2(m: &Matrix2<f64>) -> Option<Matrix2<f64>> {
    let det = m[(0, 0)] * m[(1, 1)] - m[(0, 1)] * m[(1, 0)];
    (det != 0.0 && det.is_finite())
        .then(|| Matrix2::new(m[(1, 1)], -m[(0, 1)], -m[(1, 0)], m[(0, 0)]) / det)
}

#[inline(always)]
fn outer(a: Vector2<f64>, b: Vector2<f64>) -> Matrix2<f64> {
    a * b.transpose()
}

impl LinearTimeSolver {
    /// A solver for the track `model`.
    pub fn new<M: TrackModel<D>, const D: usize>(model: &M) -> Self {
        let description = model.description();
        let joint = description.loop_joint.expect("a track has a loop joint");
        let n = description.len();
        let links = (0..n)
            .map(|i| {
                let body = &description.bodies[i];
                let u1 = if i == 0 { joint.first_u1 } else { body.at_self };
                let u2 = if i + 1 == n {
                    joint.last_u2
                } else {
                    description.bodies[i + 1].at_parent
                };
                Link {
                    inv_mass: 1.0 / body.mass,
                    inv_inertia: 1.0 / body.inertia,
                    mass: body.mass,
                    u1,
                    u2,
                }
            })
            .collect();
        LinearTimeSolver {
            links,
            gravity: description.gravity,
            closure: joint.closure,
            kin: vec![Kinematics::default(); n],
            diagonal: vec![Matrix2::zeros(); n],
            lower: vec![Matrix2::zeros(); n],
            rhs: vec![Vector2::zeros(); n],
            inverse: vec![Matrix2::zeros(); n],
            reduced: vec![Matrix2x3::zeros(); n],
            lambda: vec![Vector2::zeros(); n],
        }
    }

    /// Forward dynamics of `model` as declared (the model this solver was
    /// built for): a constrained loop with its closing joint, an open
    /// chain, or a declared penalty joint's spring-damper. The same
    /// accelerations as [`dense_forward_dynamics`](super::dense_forward_dynamics), in
    /// O(n).
    pub fn forward_dynamics<M: TrackModel<D>, const D: usize>(
        &mut self,
        model: &M,
        q: &SVector<f64, D>,
        qd: &SVector<f64, D>,
        loads: &[BodyLoad],
    ) -> Result<super::Accelerations<SVector<f64, D>>, DynamicsError> {
        let penalty = match self.closure {
            Closure::Penalty(joint) => {
                Some(joint.force(model.closure(q), model.closure_jacobian(q) * qd))
            }
            _ => None,
        };
        let constrained = self.closure.is_constrained();
        let (qdd, multipliers) =
            self.accelerations(q, qd, loads, constrained, Vector2::zeros(), penalty)?;
        // λ of formulation §2 is minus the force the closing joint puts on link n.
        Ok(super::Accelerations {
            qdd,
            multipliers: multipliers.map(|f| -f),
        })
    }

    /// `q̈_i` of the track at `(q_i, q̇_i)` under the loads (one per link, or
    /// none), with the closing joint `constrained` or cut. A constrained
    /// loop gets `C_q q̈ = γ_c − stabilisation` (Baumgarte: `2ω Ċ + ω² C`;
    /// zero for the plain equations); a cut one may carry a penalty
    /// spring's force (on link n at ū2ⁿ, reversed on link 1 at ū1¹).
    /// When constrained, also returns the closing joint's `λ` of formulation §5:
    /// the force it puts on link n (link 1 gets the opposite).
    pub fn accelerations<const D: usize>(
        &mut self,
        q: &SVector<f64, D>,
        qd: &SVector<f64, D>,
        loads: &[BodyLoad],
        constrained: bool,
        stabilisation: Vector2<f64>,
        penalty_force: Option<Vector2<f64>>,
    ) -> Result<(SVector<f64, D>, Option<Vector2<f64>>), DynamicsError> {
        self.accelerations_with_trig(
            q,
            qd,
            loads,
            constrained,
            stabilisation,
            penalty_force,
            None,
        )
    }

    /// [`accelerations`](Self::accelerations), given each link's
    /// `(sin θ, cos θ)` when the caller has them already (one per link).
    #[allow(clippy::too_many_arguments)]
    pub fn accelerations_with_trig<const D: usize>(
        &mut self,
        q: &SVector<f64, D>,
        qd: &SVector<f64, D>,
        loads: &[BodyLoad],
        constrained: bool,
        stabilisation: Vector2<f64>,
        penalty_force: Option<Vector2<f64>>,
        trig: Option<&[(f64, f64)]>,
    ) -> Result<(SVector<f64, D>, Option<Vector2<f64>>), DynamicsError> {
        let n = self.links.len();
        if D != n + 2 {
            return Err(DynamicsError::WrongLength {
                what: "coordinates",
                expected: n + 2,
                got: D,
            });
        }
        if trig.is_some_and(|t| t.len() != n) {
            return Err(DynamicsError::WrongLength {
                what: "trig",
                expected: n,
                got: trig.map_or(0, <[_]>::len),
            });
        }
        if !loads.is_empty() && loads.len() != n {
            return Err(DynamicsError::WrongLength {
                what: "loads",
                expected: n,
                got: loads.len(),
            });
        }
        let closed = constrained;
        if closed && n < 3 {
            return Err(DynamicsError::WrongLength {
                what: "links of a closed loop (at least 3)",
                expected: 3,
                got: n,
            });
        }
        self.link_kinematics(q, loads, penalty_force, trig);
        self.joint_blocks(qd, closed, stabilisation);
        let closing = self.eliminate(closed)?;
        Ok((self.link_accelerations(closed), closing))
    }

    /// Each link's lever arms `⟂(A ū1)`, `⟂(A ū2)` and its applied force
    /// and moment (gravity, `loads`, the penalty joint's force on the last
    /// link and its reaction on the first).
    fn link_kinematics<const D: usize>(
        &mut self,
        q: &SVector<f64, D>,
        loads: &[BodyLoad],
        penalty_force: Option<Vector2<f64>>,
        trig: Option<&[(f64, f64)]>,
    ) {
        let n = self.links.len();
        // Per link: lever arms, applied loads.
        for i in 0..n {
            let link = &self.links[i];
            // One sine and cosine per link.
            let (sin, cos) = match trig {
                Some(t) => t[i],
                None => q[2 + i].sin_cos(),
            };
            let turn = |u: Vector2<f64>| Vector2::new(cos * u.x - sin * u.y, sin * u.x + cos * u.y);
            let (a1, a2) = (turn(link.u1), turn(link.u2));
            let load = loads.get(i).copied().unwrap_or(BodyLoad::ZERO);
            self.kin[i] = Kinematics {
                p1: Vector2::new(-a1.y, a1.x),
                p2: Vector2::new(-a2.y, a2.x),
                force: self.gravity * link.mass + load.force,
                moment: load.moment,
            };
        }
        if let Some(f) = penalty_force {
            // On link n at ū2ⁿ, and the reaction on link 1 at ū1¹.
            let (last, first) = (self.kin[n - 1], self.kin[0]);
            self.kin[n - 1].force += f;
            self.kin[n - 1].moment += last.p2.dot(&f);
            self.kin[0].force -= f;
            self.kin[0].moment -= first.p1.dot(&f);
        }
    }

    /// The joints' 2×2 blocks of `D W Dᵀ` (diagonal, and the coupling to
    /// the joint before) and their right sides, with `stabilisation` on
    /// the closing joint's.
    fn joint_blocks<const D: usize>(
        &mut self,
        qd: &SVector<f64, D>,
        closed: bool,
        stabilisation: Vector2<f64>,
    ) {
        let n = self.links.len();
        // Joint j joins link j to link k = j + 1 (the closing joint, n − 1,
        // joins link n − 1 to link 0).
        let joints = if closed { n } else { n - 1 };
        // Link j's side of joint j (its ū2) and link k's side (its ū1).
        let ahead = self
            .links
            .iter()
            .zip(self.kin.iter())
            .zip(qd.iter().skip(2));
        let behind = self
            .links
            .iter()
            .zip(self.kin.iter())
            .zip(qd.iter().skip(2))
            .cycle()
            .skip(1);
        let blocks = self
            .diagonal
            .iter_mut()
            .zip(self.lower.iter_mut())
            .zip(self.rhs.iter_mut());
        for ((((lj, kj), &wj), ((lk, kk), &wk)), ((diagonal, lower), rhs)) in
            ahead.zip(behind).zip(blocks).take(joints)
        {
            let identity = Matrix2::identity();
            *diagonal = outer(kj.p2, kj.p2) * lj.inv_inertia
                + outer(kk.p1, kk.p1) * lk.inv_inertia
                + identity * (lj.inv_mass + lk.inv_mass);
            *lower = -(outer(kj.p2, kj.p1) * lj.inv_inertia + identity * lj.inv_mass);
            let (a2, a1) = (
                Vector2::new(kj.p2.y, -kj.p2.x),
                Vector2::new(kk.p1.y, -kk.p1.x),
            );
            let kappa = a2 * (wj * wj) - a1 * (wk * wk);
            *rhs = kappa - (kj.p2 * (kj.moment * lj.inv_inertia) + kj.force * lj.inv_mass)
                + (kk.p1 * (kk.moment * lk.inv_inertia) + kk.force * lk.inv_mass);
        }
        if closed {
            self.rhs[n - 1] -= stabilisation;
        }
    }

    /// Block elimination and back substitution of the joints' system,
    /// bordered by the closing joint's columns for a closed loop: the
    /// multipliers `λ` of every joint, and the closing joint's.
    fn eliminate(&mut self, closed: bool) -> Result<Option<Vector2<f64>>, DynamicsError> {
        let n = self.links.len();
        // Block elimination over joints 0 … m−1; for a closed loop the
        // closing joint's two columns ride along (bordering).
        let m = n - 1;
        let singular = DynamicsError::SingularClosure;
        let (b0, bm) = (self.lower[0], self.lower[n - 1].transpose());
        let mut previous: Option<(Matrix2<f64>, Matrix2x3<f64>)> = None;
        let rows = self
            .diagonal
            .iter()
            .zip(self.lower.iter())
            .zip(self.rhs.iter());
        let outputs = self.inverse.iter_mut().zip(self.reduced.iter_mut());
        for (j, (((diagonal, lower), rhs), (inverse, reduced))) in
            rows.zip(outputs).take(m).enumerate()
        {
            let mut r = Matrix2x3::zeros();
            r.set_column(0, rhs);
            if closed {
                // Couplings to the closing joint's λ: joint 0 through link
                // 0, joint m − 1 through link m (= n − 1).
                let mut b = Matrix2::zeros();
                if j == 0 {
                    b += b0;
                }
                if j + 1 == m {
                    b += bm;
                }
                r.fixed_view_mut::<2, 2>(0, 1).copy_from(&b);
            }
            let mut diag = *diagonal;
            if let Some((previous_inverse, previous_reduced)) = previous {
                // Coupling to joint j − 1 is `lower`; eliminate it.
                let factor = lower * previous_inverse;
                diag -= factor * lower.transpose();
                r -= factor * previous_reduced;
            }
            *inverse = inverse2(&diag).ok_or(singular.clone())?;
            *reduced = r;
            previous = Some((*inverse, r));
        }
        // Back substitution, in place: x_j = inv_j (r̂_j − lower[j+1]ᵀ x_{j+1}),
        // for the right side and the two bordering columns at once.
        let mut next: Option<Matrix2x3<f64>> = None;
        let rows = self.inverse[..m]
            .iter()
            .zip(self.reduced[..m].iter_mut())
            .zip(self.lower[1..=m].iter());
        for ((inverse, reduced), lower_next) in rows.rev() {
            let mut r = *reduced;
            // The joint after the last of T couples to it only through the
            // bordering columns.
            if let Some(x) = next {
                r -= lower_next.transpose() * x;
            }
            *reduced = inverse * r;
            next = Some(*reduced);
        }
        let solution = &self.reduced;
        Ok(if closed {
            // (C − Bᵀ Z) y = s − Bᵀ x₀, with B's blocks at joints 0 and m−1.
            let (b0, bm) = (self.lower[0], self.lower[n - 1].transpose());
            let mut schur = self.diagonal[n - 1];
            let mut s = self.rhs[n - 1];
            for (block, j) in [(b0, 0), (bm, m - 1)] {
                let z = solution[j].fixed_view::<2, 2>(0, 1).into_owned();
                let x0 = solution[j].column(0).into_owned();
                schur -= block.transpose() * z;
                s -= block.transpose() * x0;
            }
            let y = schur.try_inverse().ok_or(singular)? * s;
            for (lambda, x) in self.lambda.iter_mut().zip(solution.iter()).take(m) {
                let z = x.fixed_view::<2, 2>(0, 1).into_owned();
                *lambda = x.column(0).into_owned() - z * y;
            }
            self.lambda[n - 1] = y;
            Some(y)
        } else {
            for (lambda, x) in self.lambda.iter_mut().zip(solution.iter()).take(m) {
                *lambda = x.column(0).into_owned();
            }
            None
        })
    }

    /// The links' accelerations from their loads and the joints'
    /// multipliers: `aᵢ = Wᵢ (Fᵢ + D⁺ᵢᵀ λᵢ − D⁻ᵢᵀ λᵢ₋₁)`.
    fn link_accelerations<const D: usize>(&self, closed: bool) -> SVector<f64, D> {
        let n = self.links.len();
        // Accelerations: aᵢ = Wᵢ (Fᵢ + D⁺ᵢᵀ λᵢ − D⁻ᵢᵀ λᵢ₋₁).
        let mut qdd = SVector::<f64, D>::zeros();
        for i in 0..n {
            let (link, kin) = (&self.links[i], self.kin[i]);
            let ahead = if i + 1 < n || closed {
                self.lambda[i]
            } else {
                Vector2::zeros()
            };
            let behind = if i > 0 {
                self.lambda[i - 1]
            } else if closed {
                self.lambda[n - 1]
            } else {
                Vector2::zeros()
            };
            qdd[2 + i] = (kin.moment + kin.p2.dot(&ahead) - kin.p1.dot(&behind)) * link.inv_inertia;
            if i == 0 {
                let a = (kin.force + ahead - behind) * link.inv_mass;
                qdd[0] = a.x;
                qdd[1] = a.y;
            }
        }
        qdd
    }
}
