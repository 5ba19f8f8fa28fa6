use nalgebra::{DMatrix, DVector, Matrix2xX, Vector2};

use crate::dynamics::{Accelerations, solve_closed, solve_open};
use crate::multibody::DynamicsError;
use crate::multibody::{BodyLoad, Closure, TreeDescription};
use crate::planar::{rotate, rotate_derivative};

/// A body tree evaluated by the textbook route (see the [module
/// docs](crate::reference)).
#[derive(Debug, Clone)]
pub struct ReferenceModel {
    tree: TreeDescription,
    /// For each body, the bodies on the path from the root to it, root
    /// first, itself last.
    paths: Vec<Vec<usize>>,
}

impl ReferenceModel {
    /// Builds the reference route for a tree.
    ///
    /// # Panics
    /// If a body's parent does not precede it (the description is not in
    /// topological order), or a non-root body has no parent.
    pub fn new(tree: TreeDescription) -> Self {
        let mut paths: Vec<Vec<usize>> = Vec::with_capacity(tree.len());
        for (b, body) in tree.bodies.iter().enumerate() {
            let path = match body.parent {
                None => {
                    assert_eq!(b, 0, "only body 0 may be the root");
                    vec![0]
                }
                Some(p) => {
                    assert!(p < b, "body {b}: parent {p} must precede it");
                    let mut path = paths[p].clone();
                    path.push(b);
                    path
                }
            };
            paths.push(path);
        }
        ReferenceModel { tree, paths }
    }

    /// The description this model evaluates.
    pub fn description(&self) -> &TreeDescription {
        &self.tree
    }

    /// Number of bodies.
    pub fn bodies(&self) -> usize {
        self.tree.len()
    }

    /// Number of recursive coordinates.
    pub fn dof(&self) -> usize {
        self.tree.dof()
    }

    fn angle(q: &DVector<f64>, b: usize) -> f64 {
        q[2 + b]
    }

    /// The lever of body `k` in the path of body `b`: from `k`'s joint with
    /// its parent to the point where the path leaves `k` (the next body's
    /// joint, or `b`'s centroid when `k = b`), in `k`'s frame. These are the
    /// `ū2¹`, `d̄ʲ`, `−ū1ⁱ` of eq. (6) and the `ū_iᶜ` of eq. (11).
    fn lever(&self, b: usize, pos: usize) -> Vector2<f64> {
        let path = &self.paths[b];
        let k = path[pos];
        let leave = match path.get(pos + 1) {
            Some(&next) => self.tree.bodies[next].at_parent,
            None => Vector2::zeros(),
        };
        leave - self.tree.bodies[k].at_self
    }

    /// Centroid positions (eq. (4), eq. (8)).
    pub fn positions(&self, q: &DVector<f64>) -> Vec<Vector2<f64>> {
        let root = Vector2::new(q[0], q[1]);
        (0..self.bodies())
            .map(|b| {
                (0..self.paths[b].len()).fold(root, |r, pos| {
                    r + rotate(Self::angle(q, self.paths[b][pos]), self.lever(b, pos))
                })
            })
            .collect()
    }

    /// The dense velocity transform `H` (3n × (n + 2)), eq. (6) / (11):
    /// block row `b` has `I` under `R` and `A_θᵏ (lever of k)` under `θᵏ`
    /// for every `k` on the path to `b`.
    pub fn velocity_transform(&self, q: &DVector<f64>) -> DMatrix<f64> {
        let n = self.bodies();
        let mut h = DMatrix::zeros(3 * n, n + 2);
        for b in 0..n {
            h[(2 * b, 0)] = 1.0;
            h[(2 * b + 1, 1)] = 1.0;
            for (pos, &k) in self.paths[b].iter().enumerate() {
                let col = rotate_derivative(Self::angle(q, k), self.lever(b, pos));
                h[(2 * b, 2 + k)] += col.x;
                h[(2 * b + 1, 2 + k)] += col.y;
            }
            h[(2 * n + b, 2 + b)] = 1.0;
        }
        h
    }

    /// `γ = Ḣ q̇_i` (eq. (14)), using `d(A_θ)/dθ = −A`.
    pub fn gamma(&self, q: &DVector<f64>, qd: &DVector<f64>) -> DVector<f64> {
        let n = self.bodies();
        let mut g = DVector::zeros(3 * n);
        for b in 0..n {
            for (pos, &k) in self.paths[b].iter().enumerate() {
                let w = qd[2 + k];
                let term = -rotate(Self::angle(q, k), self.lever(b, pos)) * (w * w);
                g[2 * b] += term.x;
                g[2 * b + 1] += term.y;
            }
        }
        g
    }

    /// The diagonal of `M = diag(m_1 I₂ … m_n I₂, J_1 … J_n)` (eq. (12)).
    fn mass_diagonal(&self) -> DVector<f64> {
        let n = self.bodies();
        DVector::from_fn(3 * n, |r, _| {
            if r < 2 * n {
                self.tree.bodies[r / 2].mass
            } else {
                self.tree.bodies[r - 2 * n].inertia
            }
        })
    }

    /// `M_i = Hᵀ M H` (eq. (15)).
    pub fn mass_matrix(&self, q: &DVector<f64>) -> DMatrix<f64> {
        let h = self.velocity_transform(q);
        let mh = DMatrix::from_diagonal(&self.mass_diagonal()) * &h;
        h.transpose() * mh
    }

    /// Absolute applied forces `Q` (3n): gravity, the loads, and the penalty
    /// spring-damper of a penalty-closed track applied at its two joint
    /// points.
    pub fn applied_forces(
        &self,
        q: &DVector<f64>,
        qd: &DVector<f64>,
        loads: &[BodyLoad],
    ) -> DVector<f64> {
        let n = self.bodies();
        check_loads(loads, n);
        let mut f = DVector::zeros(3 * n);
        for (b, body) in self.tree.bodies.iter().enumerate() {
            let mut load = BodyLoad::force(self.tree.gravity * body.mass);
            if let Some(l) = loads.get(b) {
                load = load.plus(*l);
            }
            f[2 * b] += load.force.x;
            f[2 * b + 1] += load.force.y;
            f[2 * n + b] += load.moment;
        }
        if let Some(joint) = self.tree.loop_joint
            && let Closure::Penalty(penalty) = joint.closure
        {
            let last = n - 1;
            let (arm_n, arm_1) = (
                rotate(Self::angle(q, last), joint.last_u2),
                rotate(Self::angle(q, 0), joint.first_u1),
            );
            let r = self.positions(q);
            let v = &self.velocity_transform(q) * qd;
            let point_velocity = |b: usize, arm: Vector2<f64>| {
                Vector2::new(v[2 * b], v[2 * b + 1]) + Vector2::new(-arm.y, arm.x) * qd[2 + b]
            };
            let gap = (r[last] + arm_n) - (r[0] + arm_1);
            let rate = point_velocity(last, arm_n) - point_velocity(0, arm_1);
            let force = penalty.force(gap, rate);
            for (b, arm, sign) in [(last, arm_n, 1.0), (0, arm_1, -1.0)] {
                let l = BodyLoad::force_at(force * sign, arm);
                f[2 * b] += l.force.x;
                f[2 * b + 1] += l.force.y;
                f[2 * n + b] += l.moment;
            }
        }
        f
    }

    /// `Q_i = Hᵀ (Q − M γ)` (eq. (16)).
    pub fn generalized_forces(
        &self,
        q: &DVector<f64>,
        qd: &DVector<f64>,
        loads: &[BodyLoad],
    ) -> DVector<f64> {
        let h = self.velocity_transform(q);
        let mg = self.mass_diagonal().component_mul(&self.gamma(q, qd));
        h.transpose() * (self.applied_forces(q, qd, loads) - mg)
    }

    /// Kinetic energy `½ q̇ᵀ M q̇` with `q̇ = H q̇_i`.
    pub fn kinetic_energy(&self, q: &DVector<f64>, qd: &DVector<f64>) -> f64 {
        let v = self.velocity_transform(q) * qd;
        0.5 * v.component_mul(&v).dot(&self.mass_diagonal())
    }

    /// The closing joint's gap `C = P_n − P_1` from the positions.
    ///
    /// # Panics
    /// If the tree has no loop joint.
    pub fn closure(&self, q: &DVector<f64>) -> Vector2<f64> {
        let joint = self
            .tree
            .loop_joint
            .expect("closure of a tree without a loop joint");
        let n = self.bodies();
        let r = self.positions(q);
        (r[n - 1] + rotate(Self::angle(q, n - 1), joint.last_u2))
            - (r[0] + rotate(Self::angle(q, 0), joint.first_u1))
    }

    /// `C_q` (2 × (n + 2)), as the difference of the two joint points' rows
    /// of the point Jacobians.
    pub fn closure_jacobian(&self, q: &DVector<f64>) -> Matrix2xX<f64> {
        let joint = self
            .tree
            .loop_joint
            .expect("closure of a tree without a loop joint");
        let n = self.bodies();
        let h = self.velocity_transform(q);
        let mut cq = Matrix2xX::zeros(n + 2);
        for (b, u, sign) in [(n - 1, joint.last_u2, 1.0), (0, joint.first_u1, -1.0)] {
            for c in 0..n + 2 {
                cq[(0, c)] += sign * h[(2 * b, c)];
                cq[(1, c)] += sign * h[(2 * b + 1, c)];
            }
            let arm = rotate_derivative(Self::angle(q, b), u);
            cq[(0, 2 + b)] += sign * arm.x;
            cq[(1, 2 + b)] += sign * arm.y;
        }
        cq
    }

    /// `γ_c = −(d/dt C_q) q̇_i`, so that `C_q q̈_i = γ_c`: minus the
    /// quadratic velocity terms of the two joint points.
    pub fn closure_gamma(&self, q: &DVector<f64>, qd: &DVector<f64>) -> Vector2<f64> {
        let joint = self
            .tree
            .loop_joint
            .expect("closure of a tree without a loop joint");
        let n = self.bodies();
        let g = self.gamma(q, qd);
        let point = |b: usize, u: Vector2<f64>| {
            let w = qd[2 + b];
            Vector2::new(g[2 * b], g[2 * b + 1]) - rotate(Self::angle(q, b), u) * (w * w)
        };
        -(point(n - 1, joint.last_u2) - point(0, joint.first_u1))
    }

    /// Forward dynamics `q̈_i` at a state: an open or penalty-closed chain
    /// solves `M_i q̈_i = Q_i`; a constrained loop solves the multiplier form
    /// of formulation §2 and also returns `λ`.
    pub fn forward_dynamics(
        &self,
        q: &DVector<f64>,
        qd: &DVector<f64>,
        loads: &[BodyLoad],
    ) -> Result<Accelerations<DVector<f64>>, DynamicsError> {
        let m = self.mass_matrix(q);
        let f = self.generalized_forces(q, qd, loads);
        match self.tree.loop_joint {
            Some(joint) if joint.closure.is_constrained() => {
                solve_closed(m, &f, &self.closure_jacobian(q), &self.closure_gamma(q, qd))
            }
            _ => solve_open(m, &f),
        }
    }
}

fn check_loads(loads: &[BodyLoad], n: usize) {
    assert!(
        loads.is_empty() || loads.len() == n,
        "expected {n} body loads or none, got {}",
        loads.len()
    );
}
