//! Generalised coordinate partitioning with switching of the dependent
//! pair (spec §2; Wehage & Haug; the paper's eqs. (18)-(21)).

use nalgebra::{DMatrix, DVector, Matrix2, SMatrix, SVector, Vector2};

use crate::model::TrackModel;

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
pub fn conditioning<const D: usize>(cq: &SMatrix<f64, 2, D>, pair: [usize; 2]) -> f64 {
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
pub fn best_pair<const D: usize>(cq: &SMatrix<f64, 2, D>) -> ([usize; 2], f64) {
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
pub fn recover_positions<M: TrackModel<D>, const D: usize>(
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
pub fn recover<const D: usize>(
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
pub fn recover_velocities<const D: usize>(
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

/// The accelerations of the partitioned equations
/// `(Bᵀ M_i B) z̈ = Bᵀ (Q_i − M_i β)`, `q̈_i = B z̈ + β`, with
/// `B = [I ; −C_d⁻¹ C_z]` and `β = [0 ; C_d⁻¹ γ_c]` (spec §2). `None` if a
/// matrix is singular.
pub fn accelerations<const D: usize>(
    mass: &SMatrix<f64, D, D>,
    forces: &SVector<f64, D>,
    cq: &SMatrix<f64, 2, D>,
    gamma_c: &Vector2<f64>,
    pair: [usize; 2],
    independent: &[usize],
) -> Option<SVector<f64, D>> {
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
pub fn independent_coordinates(dof: usize, pair: [usize; 2]) -> Vec<usize> {
    (0..dof)
        .filter(|&c| c != 2 + pair[0] && c != 2 + pair[1])
        .collect()
}
