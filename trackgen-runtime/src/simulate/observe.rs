use nalgebra::{SVector, Vector2};

use crate::model::RecursiveModel;
use crate::planar::cross;

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

/// Names of the mechanical quantities every body tree records after its
/// coordinates and rates.
const MECHANICS: [&str; 6] = [
    "kinetic",
    "potential",
    "energy",
    "momentum_x",
    "momentum_y",
    "angular_momentum",
];

/// Columns of a body tree: coordinates, rates (bodies named by `name`),
/// then [`MECHANICS`].
pub(crate) fn mechanics_columns(n: usize, name: impl Fn(usize) -> String) -> Vec<String> {
    let mut c = coordinate_columns(n, false, &name);
    c.extend(coordinate_columns(n, true, &name));
    c.extend(MECHANICS.map(String::from));
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
    row.extend([
        kinetic,
        potential,
        kinetic + potential,
        p.linear.x,
        p.linear.y,
        p.angular,
    ]);
}
