//! Generalised coordinate partitioning with switching of the dependent
//! pair (formulation §2; Wehage & Haug; the paper's eqs. (18)-(21)).

#[cfg(feature = "oracle")]
use nalgebra::{DMatrix, DVector, Matrix2};
use nalgebra::{SMatrix, SVector, Vector2};

use super::{ClosureError, RecoveryError};
use crate::multibody::TrackModel;

/// A change of the dependent coordinates of a partitioned track (formulation §2).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Switch {
    /// Time, s.
    pub t: f64,
    /// The dependent links before (numbered from 1).
    pub from: [usize; 2],
    /// The dependent links after.
    pub to: [usize; 2],
    /// `|sin|` between the columns of `C_d` of the old pair, which fell
    /// below the switching threshold.
    pub conditioning: f64,
    /// The same for the new pair.
    pub new_conditioning: f64,
}

/// Settings of the partitioning method.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PartitionOptions {
    /// Re-partition automatically (default `true`).
    pub switching: bool,
    /// Re-partition when the conditioning of `C_d` — `|sin|` of the angle
    /// between its two columns, 1 for perpendicular links, 0 for parallel
    /// ones — falls below this (default 0.5). Errors in the independent
    /// velocities reach the dependent ones amplified by up to
    /// `1/|sin|`, and Newton-Raphson's basin shrinks likewise; below 0.5
    /// (links within 30° of parallel) both are more than twice their best.
    /// A higher threshold switches more often, each switch restarting the
    /// integrator; a closed loop always has a pair near 1 to switch to.
    pub switch_below: f64,
    /// With switching off, stop with
    /// [`SingularPartition`](super::RecoveryError::SingularPartition)
    /// when the conditioning falls below this (default 0.01: a hundredfold
    /// amplification).
    pub singular_below: f64,
    /// Newton-Raphson stops when `|C|` is below this fraction of the loop's
    /// length `Σ |d̄ʲ|` (default 1e-13).
    pub newton_tolerance: f64,
    /// Newton-Raphson iterations before failing (default 20; it usually
    /// takes 1–3).
    pub newton_max_iterations: usize,
    /// The dependent links at the start, numbered from 1 (default: the
    /// best-conditioned pair).
    pub initial_pair: Option<[usize; 2]>,
}

impl Default for PartitionOptions {
    fn default() -> Self {
        PartitionOptions {
            switching: true,
            switch_below: 0.5,
            singular_below: 0.01,
            newton_tolerance: 1e-13,
            newton_max_iterations: 20,
            initial_pair: None,
        }
    }
}

/// The column of `C_q` under link `j`'s angle: `A_θʲ d̄ʲ`.
fn column<const D: usize>(cq: &SMatrix<f64, 2, D>, link: usize) -> Vector2<f64> {
    cq.fixed_view::<2, 1>(0, 2 + link).into_owned()
}

/// The angle columns `A_θʲ d̄ʲ` of `C_q`, one per link.
pub(crate) fn columns<const D: usize>(cq: &SMatrix<f64, 2, D>) -> Vec<Vector2<f64>> {
    (0..D - 2).map(|j| column(cq, j)).collect()
}

/// `|sin|` of the angle between the columns of `C_d` for dependent links
/// `pair` (0-based), from the angle columns of `C_q`: 1 at best, 0
/// singular (eq. (21)).
pub(crate) fn conditioning(columns: &[Vector2<f64>], pair: [usize; 2]) -> f64 {
    let (a, b) = (columns[pair[0]], columns[pair[1]]);
    let det = a.x * b.y - a.y * b.x;
    let norms = a.norm() * b.norm();
    if norms > 0.0 {
        (det / norms).abs()
    } else {
        0.0
    }
}

/// The best-conditioned pair of links (0-based) and its conditioning.
pub(crate) fn best_pair(columns: &[Vector2<f64>]) -> ([usize; 2], f64) {
    let n = columns.len();
    let mut best = ([0, 1.min(n - 1)], -1.0);
    for j in 0..n {
        for k in j + 1..n {
            let c = conditioning(columns, [j, k]);
            if c > best.1 {
                best = ([j, k], c);
            }
        }
    }
    best
}

/// `C_d`, the 2 × 2 block of `C_q` under the dependent angles.
#[cfg(feature = "oracle")]
fn block<const D: usize>(cq: &SMatrix<f64, 2, D>, pair: [usize; 2]) -> Matrix2<f64> {
    Matrix2::from_columns(&[column(cq, pair[0]), column(cq, pair[1])])
}

/// The accelerations of the dense partitioned equations
/// `(Bᵀ M_i B) z̈ = Bᵀ (Q_i − M_i β)`, `q̈_i = B z̈ + β`, with
/// `B = [I ; −C_d⁻¹ C_z]` and `β = [0 ; C_d⁻¹ γ_c]` (formulation §2), for the
/// dependent links `pair` (0-based). `None` if a matrix is singular.
///
/// O(n³): the cross-check of the simulation, which takes `z̈` from the
/// linear-time route (on the closure manifold the two agree). A test
/// oracle: built with the `oracle` feature.
#[cfg(feature = "oracle")]
pub fn accelerations<const D: usize>(
    mass: &SMatrix<f64, D, D>,
    forces: &SVector<f64, D>,
    cq: &SMatrix<f64, 2, D>,
    gamma_c: &Vector2<f64>,
    pair: [usize; 2],
) -> Option<SVector<f64, D>> {
    let independent = independent_coordinates(D, pair);
    let n = independent.len();
    let inv = block(cq, pair).try_inverse()?;
    let mut b = DMatrix::<f64>::zeros(D, n);
    for (i, &c) in independent.iter().enumerate() {
        b[(c, i)] = 1.0;
        let dep = -(inv * column_any(cq, c));
        b[(2 + pair[0], i)] = dep.x;
        b[(2 + pair[1], i)] = dep.y;
    }
    let mut beta = DVector::<f64>::zeros(D);
    let bd = inv * gamma_c;
    beta[2 + pair[0]] = bd.x;
    beta[2 + pair[1]] = bd.y;
    let m = DMatrix::from_column_slice(D, D, mass.as_slice());
    let f = DVector::from_column_slice(forces.as_slice());
    let mb = &m * &b;
    let reduced = b.transpose() * &mb;
    let rhs = b.transpose() * (f - &m * &beta);
    let zdd = reduced.cholesky()?.solve(&rhs);
    let qdd = b * zdd + beta;
    Some(SVector::from_column_slice(qdd.as_slice()))
}

/// Column `c` of `C_q` (zero for the root's translation).
#[cfg(feature = "oracle")]
fn column_any<const D: usize>(cq: &SMatrix<f64, 2, D>, c: usize) -> Vector2<f64> {
    cq.fixed_view::<2, 1>(0, c).into_owned()
}

/// The coordinates of `q_i` that are integrated for dependent links
/// `pair` (0-based): `R_x, R_y` and every other angle.
pub(crate) fn independent_coordinates(dof: usize, pair: [usize; 2]) -> Vec<usize> {
    (0..dof)
        .filter(|&c| c != 2 + pair[0] && c != 2 + pair[1])
        .collect()
}

/// The partition of a closed track's coordinates as it evolves: the
/// dependent pair, the integrated (independent) coordinates, and where
/// Newton-Raphson starts. The integrated state is `y = [z, ż]`.
#[derive(Debug, Clone)]
pub(crate) struct Partition {
    options: PartitionOptions,
    /// The dependent links, 0-based.
    pair: [usize; 2],
    /// The integrated coordinates of `q_i`: `R_x, R_y` and every angle
    /// but the pair's.
    independent: Vec<usize>,
    /// The dependent angles last accepted: Newton-Raphson's start.
    guess: [f64; 2],
    /// `|C|` at which Newton-Raphson stops, m.
    tolerance: f64,
}

impl Partition {
    /// A partition with these options for a loop of length `loop_length`
    /// (m, `Σ |d̄ʲ|`: the scale of the closure tolerance). The pair is
    /// chosen by [`start`](Self::start).
    pub fn new(options: PartitionOptions, loop_length: f64) -> Partition {
        Partition {
            options,
            pair: [0, 1],
            independent: Vec::new(),
            guess: [0.0; 2],
            tolerance: options.newton_tolerance * loop_length,
        }
    }

    /// The dependent links, 0-based.
    pub fn pair(&self) -> [usize; 2] {
        self.pair
    }

    /// `2 n`: the length of the integrated state.
    pub fn dimension<const D: usize>(&self) -> usize {
        2 * (D - 2)
    }

    /// Chooses the starting pair (the options' `initial_pair`, else the
    /// best-conditioned) and makes `(q_i, q̇_i)` consistent with the
    /// closure: the pair's angles from `C = 0`, its rates from `C_q q̇ = 0`.
    pub fn start<M: TrackModel<D>, const D: usize>(
        &mut self,
        model: &M,
        q: &mut SVector<f64, D>,
        qd: &mut SVector<f64, D>,
    ) -> Result<(), ClosureError> {
        let links = D - 2;
        self.pair = match self.options.initial_pair {
            Some([a, b]) if a != b && (1..=links).contains(&a) && (1..=links).contains(&b) => {
                [a - 1, b - 1]
            }
            Some(pair) => return Err(ClosureError::InitialPair { pair, links }),
            None => best_pair(&columns(&model.closure_jacobian(q))).0,
        };
        self.independent = independent_coordinates(D, self.pair);
        let mut trig = vec![(0.0, 1.0); links];
        self.recover(model, (q, qd), &mut trig)
            .map_err(|(iterations, residual)| {
                if residual == 0.0 {
                    ClosureError::SingularStart
                } else {
                    ClosureError::StartNotClosed {
                        iterations,
                        residual,
                    }
                }
            })?;
        self.guess = [q[2 + self.pair[0]], q[2 + self.pair[1]]];
        Ok(())
    }

    /// The model's generated closure recovery for the current pair, from
    /// the dependent angles in `q`: its iterations, or on failure its
    /// iterations and residual (a residual of 0: `C_d` singular).
    fn recover<M: TrackModel<D>, const D: usize>(
        &self,
        model: &M,
        (q, qd): (&mut SVector<f64, D>, &mut SVector<f64, D>),
        trig: &mut [(f64, f64)],
    ) -> Result<usize, (usize, f64)> {
        model.recover_closure(
            q,
            qd,
            self.pair,
            self.tolerance,
            self.options.newton_max_iterations,
            trig,
        )
    }

    /// `[z, ż]` of `(q_i, q̇_i)` into `y` (and so `[ż, z̈]` of
    /// `(q̇_i, q̈_i)`).
    pub fn pack<const D: usize>(&self, q: &SVector<f64, D>, qd: &SVector<f64, D>, y: &mut [f64]) {
        let n = self.independent.len();
        for (i, &c) in self.independent.iter().enumerate() {
            y[i] = q[c];
            y[n + i] = qd[c];
        }
    }

    /// `(q_i, q̇_i)` of `y = [z, ż]` into `q`, `qd`: the dependent angles
    /// by the model's generated Newton-Raphson from the last accepted ones,
    /// their rates from `C_q q̇ = 0`, every link's `(sin θ, cos θ)` into
    /// `trig`.
    ///
    /// A jump of the pair by more than π/2 from the last accepted state is
    /// the closure's mirror solution: [`RecoveryError::BranchJump`].
    pub fn expand<M: TrackModel<D>, const D: usize>(
        &self,
        model: &M,
        t: f64,
        y: &[f64],
        (q, qd): (&mut SVector<f64, D>, &mut SVector<f64, D>),
        trig: &mut [(f64, f64)],
    ) -> Result<(), RecoveryError> {
        let n = self.independent.len();
        for (i, &c) in self.independent.iter().enumerate() {
            q[c] = y[i];
            qd[c] = y[n + i];
        }
        let [k, l] = self.pair;
        q[2 + k] = self.guess[0];
        q[2 + l] = self.guess[1];
        // The pair's rates are recovered, but the recovery takes the loop's
        // rate over every link and then the pair's share out: what was left
        // here would reach the result's last bits, making it depend on the
        // state evaluated before.
        qd[2 + k] = 0.0;
        qd[2 + l] = 0.0;
        self.recover(model, (q, qd), trig)
            .map_err(|(iterations, residual)| RecoveryError::NewtonFailed {
                t,
                iterations,
                residual,
            })?;
        // The start is the last accepted state's pair (never a rejected
        // trial's), so the result does not depend on the call history.
        let jump = (q[2 + k] - self.guess[0])
            .abs()
            .max((q[2 + l] - self.guess[1]).abs());
        if jump > std::f64::consts::FRAC_PI_2 {
            return Err(RecoveryError::BranchJump {
                t,
                pair: [k + 1, l + 1],
                jump,
            });
        }
        Ok(())
    }

    /// After an accepted step at `(q_i, q̇_i)` (expanded from `y`), with
    /// `columns` the angle columns of `C_q` there: the accepted pair
    /// becomes Newton-Raphson's start, and if its conditioning has fallen
    /// below the threshold the best-conditioned pair takes over and `y` is
    /// re-packed. Returns the switch made, if any. With switching off, a
    /// pair below `singular_below` is an error.
    pub fn accept<const D: usize>(
        &mut self,
        t: f64,
        (q, qd): (&SVector<f64, D>, &SVector<f64, D>),
        columns: &[Vector2<f64>],
        y: &mut [f64],
    ) -> Result<Option<Switch>, RecoveryError> {
        let [k, l] = self.pair;
        self.guess = [q[2 + k], q[2 + l]];
        let now = conditioning(columns, self.pair);
        if !self.options.switching {
            if now < self.options.singular_below {
                return Err(RecoveryError::SingularPartition {
                    t,
                    pair: [k + 1, l + 1],
                    conditioning: now,
                });
            }
            return Ok(None);
        }
        if now >= self.options.switch_below {
            return Ok(None);
        }
        let (best, better) = best_pair(columns);
        if best == self.pair {
            return Ok(None);
        }
        let switch = Switch {
            t,
            from: [k + 1, l + 1],
            to: [best[0] + 1, best[1] + 1],
            conditioning: now,
            new_conditioning: better,
        };
        self.pair = best;
        self.independent = independent_coordinates(D, best);
        self.guess = [q[2 + best[0]], q[2 + best[1]]];
        self.pack(q, qd, y);
        Ok(Some(switch))
    }
}
