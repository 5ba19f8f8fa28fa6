//! What every body tree records: its coordinates and rates, its energy
//! and its momentum.

use nalgebra::{SVector, Vector2};

use super::record;
use crate::multibody::RecursiveModel;
use crate::planar::cross;

record! {
    /// The mechanical quantities a body tree records after its coordinates
    /// and rates.
    pub struct Mechanics {
        /// Kinetic energy, J.
        kinetic,
        /// Potential energy (gravity, and a penalty spring's), J.
        potential,
        /// Their sum, J.
        energy,
        /// Linear momentum, x, kg m/s.
        momentum_x,
        /// Linear momentum, y, kg m/s.
        momentum_y,
        /// Angular momentum about the global origin, kg m²/s.
        angular_momentum,
    }
}

/// Linear and angular momentum of a body tree.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Momentum {
    /// `Σ mᵇ Ṙᵇ`, kg m/s.
    pub linear: Vector2<f64>,
    /// `Σ (mᵇ Rᵇ × Ṙᵇ + Jᵇ ωᵇ)` about the global origin, kg m²/s.
    pub angular: f64,
}

/// The momentum of `model` at `(q_i, q̇_i)`, from the generated positions
/// and velocities (eq. (4), (7)) and the declared masses.
pub fn momentum<M: RecursiveModel<D>, const D: usize>(
    model: &M,
    masses: &[(f64, f64)],
    q: &SVector<f64, D>,
    qd: &SVector<f64, D>,
) -> Momentum {
    let n = M::BODIES;
    let mut r = vec![Vector2::zeros(); n];
    let mut v = vec![Vector2::zeros(); n];
    model.body_positions(q, &mut r);
    model.body_velocities(q, qd, &mut v);
    let mut linear = Vector2::zeros();
    let mut angular = 0.0;
    for b in 0..n {
        let (m, j) = masses[b];
        linear += v[b] * m;
        angular += m * cross(r[b], v[b]) + j * qd[2 + b];
    }
    Momentum { linear, angular }
}

/// `(m, J)` of every body, from the model's description.
pub(crate) fn masses<M: RecursiveModel<D>, const D: usize>(model: &M) -> Vec<(f64, f64)> {
    model
        .description()
        .bodies
        .iter()
        .map(|b| (b.mass, b.inertia))
        .collect()
}

/// Column names `prefix_0 …` for a coordinate vector: `R_x, R_y`, then one
/// angle per body named by `angle(b)`.
pub(crate) fn coordinate_columns(
    n: usize,
    rate: bool,
    angle: impl Fn(usize) -> String,
) -> Vec<String> {
    let (rx, ry) = if rate { ("vx", "vy") } else { ("x", "y") };
    [rx.to_string(), ry.to_string()]
        .into_iter()
        .chain((0..n).map(|b| {
            if rate {
                format!("omega_{}", angle(b))
            } else {
                format!("theta_{}", angle(b))
            }
        }))
        .collect()
}

/// Columns of a body tree: coordinates, rates (bodies named by `name`),
/// then [`Mechanics::COLUMNS`].
pub(crate) fn mechanics_columns(n: usize, name: impl Fn(usize) -> String) -> Vec<String> {
    let mut c = coordinate_columns(n, false, &name);
    c.extend(coordinate_columns(n, true, &name));
    c.extend(Mechanics::COLUMNS.iter().map(|c| c.to_string()));
    c
}

/// The values of [`mechanics_columns`]: `q_i`, `q̇_i`, kinetic and
/// potential energy (with `extra_potential` added, J), their sum, momentum.
pub(crate) fn record_mechanics<M: RecursiveModel<D>, const D: usize>(
    model: &M,
    masses: &[(f64, f64)],
    q: &SVector<f64, D>,
    qd: &SVector<f64, D>,
    extra_potential: f64,
    row: &mut Vec<f64>,
) {
    row.extend(q.iter().chain(qd.iter()));
    let kinetic = model.kinetic_energy(q, qd);
    let potential = model.potential_energy(q) + extra_potential;
    let p = momentum(model, masses, q, qd);
    Mechanics {
        kinetic,
        potential,
        energy: kinetic + potential,
        momentum_x: p.linear.x,
        momentum_y: p.linear.y,
        angular_momentum: p.angular,
    }
    .extend_row(row);
}
