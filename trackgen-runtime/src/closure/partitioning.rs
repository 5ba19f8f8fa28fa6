//! Generalised coordinate partitioning with switching of the dependent
//! pair (spec §2; Wehage & Haug; the paper's eqs. (18)-(21)).

use nalgebra::{DMatrix, DVector, Matrix2, SMatrix, SVector, Vector2};

use crate::model::TrackModel;
use crate::simulate::{SimulationError, Switch};

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
    /// [`SingularPartition`](crate::simulate::SimulationError::SingularPartition)
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

/// `|sin|` of the angle between the columns of `C_d` for dependent links
/// `pair` (0-based): 1 at best, 0 singular (eq. (21)).
pub(crate) fn conditioning<const D: usize>(cq: &SMatrix<f64, 2, D>, pair: [usize; 2]) -> f64 {
    let (a, b) = (column(cq, pair[0]), column(cq, pair[1]));
    let det = a.x * b.y - a.y * b.x;
    let norms = a.norm() * b.norm();
    if norms > 0.0 {
        (det / norms).abs()
    } else {
        0.0
    }
}

/// The best-conditioned pair of links (0-based) and its conditioning.
pub(crate) fn best_pair<const D: usize>(cq: &SMatrix<f64, 2, D>) -> ([usize; 2], f64) {
    let n = D - 2;
    let mut best = ([0, 1.min(n - 1)], -1.0);
    for j in 0..n {
        for k in j + 1..n {
            let c = conditioning(cq, [j, k]);
            if c > best.1 {
                best = ([j, k], c);
            }
        }
    }
    best
}

/// `C_d`, the 2 × 2 block of `C_q` under the dependent angles.
fn block<const D: usize>(cq: &SMatrix<f64, 2, D>, pair: [usize; 2]) -> Matrix2<f64> {
    Matrix2::from_columns(&[column(cq, pair[0]), column(cq, pair[1])])
}

/// Solves `C(q) = 0` for the dependent angles by Newton-Raphson, the others
/// fixed. Returns `Err((iterations, |C|))` if it does not converge to
/// `tolerance` (m).
pub(crate) fn recover_positions<M: TrackModel<D>, const D: usize>(
    model: &M,
    q: &mut SVector<f64, D>,
    pair: [usize; 2],
    tolerance: f64,
    max_iterations: usize,
) -> Result<usize, (usize, f64)> {
    let spans = model
        .description()
        .link_spans()
        .expect("a track has link spans");
    recover(&spans, q, None, pair, tolerance, max_iterations, None)
}

/// [`recover_positions`] and [`recover_velocities`] in one pass, from the
/// links' spans `d̄ʲ` (spec §2: `C = Σ Aʲ d̄ʲ`): one sine and cosine per
/// link, then Newton-Raphson on the two dependent angles alone (the other
/// links' part of `C` is fixed), then `ḋ = −C_d⁻¹ C_z ż` if `qd` is given.
/// Every link's final `(sin θ, cos θ)` goes to `trig` if given.
pub(crate) fn recover<const D: usize>(
    spans: &[Vector2<f64>],
    q: &mut SVector<f64, D>,
    qd: Option<&mut SVector<f64, D>>,
    pair: [usize; 2],
    tolerance: f64,
    max_iterations: usize,
    mut trig: Option<&mut [(f64, f64)]>,
) -> Result<usize, (usize, f64)> {
    let rotate = |(s, c): (f64, f64), d: Vector2<f64>| {
        (
            Vector2::new(c * d.x - s * d.y, s * d.x + c * d.y),
            Vector2::new(-s * d.x - c * d.y, c * d.x - s * d.y),
        )
    };
    let turn = |theta: f64, d: Vector2<f64>| rotate(theta.sin_cos(), d);
    // The independent links' share of C and of C_q q̇.
    let (mut rest, mut rate) = (Vector2::zeros(), Vector2::zeros());
    for (j, d) in spans.iter().enumerate() {
        if j != pair[0] && j != pair[1] {
            let sc = q[2 + j].sin_cos();
            if let Some(trig) = trig.as_deref_mut() {
                trig[j] = sc;
            }
            let (a, a_theta) = rotate(sc, *d);
            rest += a;
            if let Some(qd) = &qd {
                rate += a_theta * qd[2 + j];
            }
        }
    }
    let (dk, dl) = (spans[pair[0]], spans[pair[1]]);
    let mut iteration = 0;
    let columns = loop {
        let ((ak, jk), (al, jl)) = (turn(q[2 + pair[0]], dk), turn(q[2 + pair[1]], dl));
        let c = rest + ak + al;
        let residual = c.norm();
        if residual <= tolerance {
            break Matrix2::from_columns(&[jk, jl]);
        }
        if iteration == max_iterations || !residual.is_finite() {
            return Err((iteration, residual));
        }
        let step = Matrix2::from_columns(&[jk, jl])
            .try_inverse()
            .map(|inv| inv * c)
            .ok_or((iteration, residual))?;
        q[2 + pair[0]] -= step.x;
        q[2 + pair[1]] -= step.y;
        iteration += 1;
    };
    if let Some(trig) = trig {
        trig[pair[0]] = q[2 + pair[0]].sin_cos();
        trig[pair[1]] = q[2 + pair[1]].sin_cos();
    }
    if let Some(qd) = qd {
        let dependent = columns.try_inverse().ok_or((iteration, 0.0))? * rate;
        qd[2 + pair[0]] = -dependent.x;
        qd[2 + pair[1]] = -dependent.y;
    }
    Ok(iteration)
}

/// Sets the dependent angular velocities from `C_q q̇ = 0`:
/// `ḋ = −C_d⁻¹ C_z ż`. `None` if `C_d` is singular.
pub(crate) fn recover_velocities<const D: usize>(
    cq: &SMatrix<f64, 2, D>,
    qd: &mut SVector<f64, D>,
    pair: [usize; 2],
) -> Option<()> {
    qd[2 + pair[0]] = 0.0;
    qd[2 + pair[1]] = 0.0;
    let rate = block(cq, pair).try_inverse()? * (cq * *qd);
    qd[2 + pair[0]] = -rate.x;
    qd[2 + pair[1]] = -rate.y;
    Some(())
}

/// The accelerations of the dense partitioned equations
/// `(Bᵀ M_i B) z̈ = Bᵀ (Q_i − M_i β)`, `q̈_i = B z̈ + β`, with
/// `B = [I ; −C_d⁻¹ C_z]` and `β = [0 ; C_d⁻¹ γ_c]` (spec §2), for the
/// dependent links `pair` (0-based). `None` if a matrix is singular.
///
/// O(n³): the cross-check of the simulation, which takes `z̈` from the
/// linear-time route (on the closure manifold the two agree).
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
    ) -> Result<(), SimulationError> {
        let links = D - 2;
        self.pair = match self.options.initial_pair {
            Some([a, b]) if a != b && (1..=links).contains(&a) && (1..=links).contains(&b) => {
                [a - 1, b - 1]
            }
            Some(p) => {
                return Err(SimulationError::Setup(format!(
                    "initial_pair {p:?}: two different links from 1 to {links}"
                )));
            }
            None => best_pair(&model.closure_jacobian(q)).0,
        };
        self.independent = independent_coordinates(D, self.pair);
        recover_positions(
            model,
            q,
            self.pair,
            self.tolerance,
            self.options.newton_max_iterations,
        )
        .map_err(|(iterations, residual)| SimulationError::NewtonFailed {
            t: 0.0,
            iterations,
            residual,
        })?;
        self.guess = [q[2 + self.pair[0]], q[2 + self.pair[1]]];
        recover_velocities(&model.closure_jacobian(q), qd, self.pair).ok_or(
            SimulationError::SingularMatrix {
                t: 0.0,
                what: "C_d at the start",
            },
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

    /// `(q_i, q̇_i)` of `y = [z, ż]`: the dependent angles by
    /// Newton-Raphson from the last accepted ones, their rates from
    /// `C_q q̇ = 0`, every link's `(sin θ, cos θ)` into `trig` if given.
    ///
    /// A jump of the pair by more than π/2 from the last accepted state is
    /// the closure's mirror solution: [`SimulationError::BranchJump`].
    pub fn expand<const D: usize>(
        &self,
        spans: &[Vector2<f64>],
        t: f64,
        y: &[f64],
        trig: Option<&mut [(f64, f64)]>,
    ) -> Result<(SVector<f64, D>, SVector<f64, D>), SimulationError> {
        let n = self.independent.len();
        let mut q = SVector::<f64, D>::zeros();
        let mut qd = SVector::<f64, D>::zeros();
        for (i, &c) in self.independent.iter().enumerate() {
            q[c] = y[i];
            qd[c] = y[n + i];
        }
        let [k, l] = self.pair;
        q[2 + k] = self.guess[0];
        q[2 + l] = self.guess[1];
        recover(
            spans,
            &mut q,
            Some(&mut qd),
            self.pair,
            self.tolerance,
            self.options.newton_max_iterations,
            trig,
        )
        .map_err(|(iterations, residual)| SimulationError::NewtonFailed {
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
            return Err(SimulationError::BranchJump {
                t,
                pair: [k + 1, l + 1],
                jump,
            });
        }
        Ok((q, qd))
    }

    /// After an accepted step at `(q_i, q̇_i)` (expanded from `y`): the
    /// accepted pair becomes Newton-Raphson's start, and if its conditioning
    /// has fallen below the threshold the best-conditioned pair takes over
    /// and `y` is re-packed. Returns the switch made, if any. With
    /// switching off, a pair below `singular_below` is an error.
    pub fn accept<M: TrackModel<D>, const D: usize>(
        &mut self,
        model: &M,
        t: f64,
        q: &SVector<f64, D>,
        qd: &SVector<f64, D>,
        y: &mut [f64],
    ) -> Result<Option<Switch>, SimulationError> {
        let cq = model.closure_jacobian(q);
        let [k, l] = self.pair;
        self.guess = [q[2 + k], q[2 + l]];
        let now = conditioning(&cq, self.pair);
        if !self.options.switching {
            if now < self.options.singular_below {
                return Err(SimulationError::SingularPartition {
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
        let (best, better) = best_pair(&cq);
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
