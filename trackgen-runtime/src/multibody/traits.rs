use nalgebra::{DMatrix, DVector, SMatrix, SVector, Vector2};

use super::{BodyLoad, ChassisPart, ClosingJoint, Closure, TreeDescription};
use crate::multibody::DynamicsError;

/// A body tree in recursive coordinates, compiled to code (formulation §1, §3).
///
/// `DOF` is the number of recursive coordinates: the root's centroid `R`
/// (2) plus the absolute angle of each of the [`BODIES`](Self::BODIES)
/// bodies, `q_i = [R_x, R_y, θ_0 … θ_{n−1}]`. Absolute coordinates are
/// `q = [R_0 … R_{n−1}, θ_0 … θ_{n−1}]` (3n), as in the paper's eq. (6).
///
/// The methods fill fixed-size matrices the caller provides: `M_i` is
/// `8 · DOF²` bytes (34.8 KB at 64 links, 8 MB at 1000). The runtime's own
/// callers keep it on the stack only up to
/// [`STACK_MATRIX_BYTES`](crate::dynamics::STACK_MATRIX_BYTES) and on the
/// heap beyond, so every size runs on a 2 MiB thread; a caller of
/// [`mass_matrix`](Self::mass_matrix) on a large model should do the same.
///
/// Slices passed to or filled by these methods have one entry per body; the
/// methods panic on a wrong length (a programming error, not a state).
pub trait RecursiveModel<const DOF: usize> {
    /// Number of bodies, `DOF − 2`.
    const BODIES: usize;

    /// The model's parameters as data, for the reference route and for
    /// inspection.
    fn description(&self) -> TreeDescription;

    /// Centroid positions `Rᵇ` from `q_i` (eq. (4); eq. (8) for the
    /// chassis).
    fn body_positions(&self, q: &SVector<f64, DOF>, out: &mut [Vector2<f64>]);

    /// Centroid velocities `Ṙᵇ = (H̄₁ H̄ₙ q̇_i)ᵇ`, evaluated as the
    /// structured product of eq. (7): a running sum over the bidiagonal
    /// blocks, O(n). The angular velocities are `q̇_i[2..]` (`H_θ`).
    fn body_velocities(
        &self,
        q: &SVector<f64, DOF>,
        qd: &SVector<f64, DOF>,
        out: &mut [Vector2<f64>],
    );

    /// Positions and velocities together, sharing the trigonometry (what
    /// contact needs at every evaluation).
    fn body_states(
        &self,
        q: &SVector<f64, DOF>,
        qd: &SVector<f64, DOF>,
        positions: &mut [Vector2<f64>],
        velocities: &mut [Vector2<f64>],
    ) {
        self.body_positions(q, positions);
        self.body_velocities(q, qd, velocities);
    }

    /// [`body_states`](Self::body_states) given every body's
    /// `(sin θ, cos θ)` already (one per body, in body order).
    fn body_states_with_trig(
        &self,
        trig: &[(f64, f64)],
        q: &SVector<f64, DOF>,
        qd: &SVector<f64, DOF>,
        positions: &mut [Vector2<f64>],
        velocities: &mut [Vector2<f64>],
    ) {
        let _ = trig;
        self.body_states(q, qd, positions, velocities);
    }

    /// Quadratic velocity terms `γ_Rᵇ` (eq. (14)); `γ_θ = 0`.
    fn velocity_terms(
        &self,
        q: &SVector<f64, DOF>,
        qd: &SVector<f64, DOF>,
        out: &mut [Vector2<f64>],
    );

    /// The mass matrix `M_i = Hᵀ M H` (eq. (15)), from the closed forms of
    /// formulation §1.
    fn mass_matrix(&self, q: &SVector<f64, DOF>, out: &mut SMatrix<f64, DOF, DOF>);

    /// The generalised forces `Q_i = Hᵀ (Q − M γ)` (eq. (16)) of gravity,
    /// the given loads (one per body, or an empty slice for none) and, for a
    /// penalty-closed track, the secondary joint's spring-damper; O(n) by
    /// running sums (formulation §1).
    fn generalized_forces(
        &self,
        q: &SVector<f64, DOF>,
        qd: &SVector<f64, DOF>,
        loads: &[BodyLoad],
        out: &mut SVector<f64, DOF>,
    );

    /// `M_i` and `Q_i` together, sharing the trigonometry.
    fn equations_of_motion(
        &self,
        q: &SVector<f64, DOF>,
        qd: &SVector<f64, DOF>,
        loads: &[BodyLoad],
        mass: &mut SMatrix<f64, DOF, DOF>,
        forces: &mut SVector<f64, DOF>,
    ) {
        self.mass_matrix(q, mass);
        self.generalized_forces(q, qd, loads, forces);
    }

    /// Forward dynamics of the tree without constraints, in O(n),
    /// generated: `q̈_i` from every body's `(sin θ, cos θ)` (`trig`, one per
    /// body), `q̇_i` and the loads besides gravity (one per body, or none).
    /// A chassis eliminates its joint forces from the leaves (formulation §5's
    /// route on a tree; `trackgen-macros/src/codegen/articulated.rs`); a
    /// track is its [`linear_time_dynamics`](TrackModel::linear_time_dynamics)
    /// with the closing joint cut (its declared penalty spring across the
    /// cut). The same accelerations as
    /// [`dense_open_dynamics`](crate::dynamics::dense_open_dynamics), the dense cross-check.
    ///
    /// # Panics
    /// If `trig` is not one per body, or `loads` neither one per body nor
    /// empty (a programming error).
    fn tree_dynamics(
        &self,
        trig: &[(f64, f64)],
        qd: &SVector<f64, DOF>,
        loads: &[BodyLoad],
        qdd: &mut SVector<f64, DOF>,
    ) -> Result<(), DynamicsError>;

    /// Kinetic energy `Σ ½ mᵇ |Ṙᵇ|² + ½ Jᵇ ωᵇ²`, J, summed from the
    /// absolute velocities.
    fn kinetic_energy(&self, q: &SVector<f64, DOF>, qd: &SVector<f64, DOF>) -> f64;

    /// Potential energy, J: gravity `−Σ mᵇ g·Rᵇ` (zero at `R = 0`), plus
    /// `½ k |C|²` of a penalty closing joint.
    fn potential_energy(&self, q: &SVector<f64, DOF>) -> f64;

    /// The dense velocity transform `H` (3n × DOF) of eq. (6), for
    /// inspection: column `k` is `q̇` for `q̇_i = e_k`, from
    /// [`body_velocities`](Self::body_velocities). Rows follow
    /// `q = [R_0 … R_{n−1}, θ_0 … θ_{n−1}]`.
    fn velocity_transform(&self, q: &SVector<f64, DOF>) -> DMatrix<f64> {
        let n = Self::BODIES;
        let mut h = DMatrix::zeros(3 * n, DOF);
        let mut v = vec![Vector2::zeros(); n];
        for k in 0..DOF {
            let e = SVector::<f64, DOF>::from_fn(|r, _| if r == k { 1.0 } else { 0.0 });
            self.body_velocities(q, &e, &mut v);
            for (b, vb) in v.iter().enumerate() {
                h[(2 * b, k)] = vb.x;
                h[(2 * b + 1, k)] = vb.y;
            }
            if k >= 2 {
                h[(2 * n + k - 2, k)] = 1.0;
            }
        }
        h
    }

    /// `γ` (3n) in the row order of [`velocity_transform`](Self::velocity_transform).
    fn gamma(&self, q: &SVector<f64, DOF>, qd: &SVector<f64, DOF>) -> DVector<f64> {
        let n = Self::BODIES;
        let mut g = vec![Vector2::zeros(); n];
        self.velocity_terms(q, qd, &mut g);
        DVector::from_fn(3 * n, |r, _| if r < 2 * n { g[r / 2][r % 2] } else { 0.0 })
    }
}

/// A track: a chain of links with a loop-closing joint between link `n` and
/// link 1 (formulation §2).
pub trait TrackModel<const DOF: usize>: RecursiveModel<DOF> {
    /// How the loop is closed.
    const CLOSURE: Closure;

    /// `C(q_i) = Σ Aʲ d̄ʲ = P_n − P_1`, the gap at the closing joint, m.
    fn closure(&self, q: &SVector<f64, DOF>) -> Vector2<f64>;

    /// `C_q = [0₂ₓ₂ | A_θʲ d̄ʲ …]`.
    fn closure_jacobian(&self, q: &SVector<f64, DOF>) -> SMatrix<f64, 2, DOF>;

    /// `γ_c = Σ Aʲ d̄ʲ ωʲ²`, so that `C_q q̈_i = γ_c`.
    fn closure_gamma(&self, q: &SVector<f64, DOF>, qd: &SVector<f64, DOF>) -> Vector2<f64>;

    /// Generalised coordinate partitioning's recovery (formulation §2, the
    /// paper's eqs. (18)-(21)), generated with every span `d̄ʲ` folded: the
    /// angles of the dependent `pair` (0-based links) from `C = 0` by
    /// Newton-Raphson, starting from their values in `q`, the others
    /// fixed, to `|C| ≤ tolerance` (m) within `max_iterations`; then their
    /// rates from `C_q q̇ = 0`, the other rates in `qd` fixed. Every link's
    /// `(sin θ, cos θ)` at the result goes to `trig` (one per link).
    ///
    /// Returns the iterations taken, or `Err((iterations, |C|))` when it
    /// does not converge or `C_d` is singular (`|C|` is 0 for a singular
    /// `C_d` at the converged angles).
    ///
    /// # Panics
    /// If `trig` is not one per link or `pair` not two different links.
    fn recover_closure(
        &self,
        q: &mut SVector<f64, DOF>,
        qd: &mut SVector<f64, DOF>,
        pair: [usize; 2],
        tolerance: f64,
        max_iterations: usize,
        trig: &mut [(f64, f64)],
    ) -> Result<usize, (usize, f64)>;

    /// The angle columns of `C_q`, `A_θʲ d̄ʲ` (one per link), from every
    /// link's `(sin θ, cos θ)`: what the conditioning of a dependent pair
    /// (eq. (21)) is measured on.
    fn closure_columns(&self, trig: &[(f64, f64)], out: &mut [Vector2<f64>]);

    /// [`closure`](Self::closure) and its rate `C_q q̇_i` from every
    /// link's `(sin θ, cos θ)` (`trig`, found already) and `q̇_i`:
    /// [`closure_columns`](Self::closure_columns)' `A_θʲ d̄ʲ` give both,
    /// `Aʲ d̄ʲ` being the column turned back a quarter, `(c_y, −c_x)`.
    ///
    /// # Panics
    /// If `trig` is not one per link.
    fn closure_and_rate(
        &self,
        trig: &[(f64, f64)],
        qd: &SVector<f64, DOF>,
    ) -> (Vector2<f64>, Vector2<f64>) {
        // On the stack: this runs once per track and evaluation.
        let mut columns = [Vector2::zeros(); DOF];
        let columns = &mut columns[..trig.len()];
        self.closure_columns(trig, columns);
        let (mut gap, mut rate) = (Vector2::zeros(), Vector2::zeros());
        for (j, column) in columns.iter().enumerate() {
            gap += Vector2::new(column.y, -column.x);
            rate += column * qd[j + 2];
        }
        (gap, rate)
    }

    /// Forward dynamics in O(n) by formulation §5, generated for this track: the
    /// links' absolute accelerations and the joint forces `λ` as unknowns,
    /// the joint forces from a block-tridiagonal system (cyclic for a
    /// constrained loop, solved by bordering), with every per-link
    /// constant (`1/m`, `1/J`, `m g`, the lever arms `ū1`, `ū2`) folded
    /// into the code, and the building of each joint's blocks fused with
    /// their elimination.
    ///
    /// Given every link's `(sin θ, cos θ)` (`trig`, one per link), `q̇_i`,
    /// the loads besides gravity (one per link, or none) and how the
    /// closing joint acts, writes `q̈_i` and every joint's force:
    /// `joint_forces[j]` is the force link `j + 2` exerts on link `j + 1`
    /// (N, links numbered from 1; the last is link 1's on link n: the
    /// closing joint's, or for a cut joint the force across the cut). The
    /// tension of joint `j` is that force along link `j + 1`'s `d̄`.
    ///
    /// # Panics
    /// If `trig` or `joint_forces` is not one per link, or `loads` neither
    /// one per link nor empty (a programming error).
    fn linear_time_dynamics(
        &self,
        trig: &[(f64, f64)],
        qd: &SVector<f64, DOF>,
        loads: &[BodyLoad],
        closing: ClosingJoint,
        qdd: &mut SVector<f64, DOF>,
        joint_forces: &mut [Vector2<f64>],
    ) -> Result<(), DynamicsError>;
}

/// A chassis: a frame with named parts (sprocket, idler, road wheels,
/// rollers) pinned to it (formulation §3).
pub trait ChassisModel<const DOF: usize>: RecursiveModel<DOF> {
    /// The parts, in declaration order.
    const PARTS: &'static [ChassisPart];

    /// The driver's seat: a point of the frame, m, from the frame's
    /// centroid in its axes (x forward, y up), as declared by `seat` (the
    /// centroid itself when the declaration gives none). Ride quality is
    /// measured there.
    const SEAT: [f64; 2];

    /// The hull's outline: the corners of a convex polygon on the frame,
    /// m, from the frame's centroid in its axes, as declared by `hull`
    /// (empty when the declaration gives none: no hull touches anything).
    /// Its contact with the terrain is [`crate::contact::outline`]'s.
    const HULL: &'static [[f64; 2]];
}
