//! The spatial vehicle's modes at rest: its linearisation by central
//! differences over every state with dynamics, and each mode named by
//! the hull's motion that holds most of its kinetic energy.
//!
//! Where the planar vehicle finds its rest by Newton's method, the
//! spatial one settles to it ([`settle`]): run from its assembled start
//! with its sprockets held, its rates then set to zero. What is left of
//! the settling shows as the accelerations at that state
//! ([`SpatialRest::residual`]); the modes are those of the linearisation
//! there.

use nalgebra::{Complex, DVector};

use super::{AnalysisError, linearise};
use crate::integrate::Integrator;
use crate::spatial_vehicle::{HULL_MOTIONS, SpatialSimulated};

/// A mode of the spatial vehicle: an eigenvalue `λ` of the state matrix
/// (one of each conjugate pair, `Im λ ≥ 0`) and the hull's share of it.
#[derive(Debug, Clone, PartialEq)]
pub struct SpatialMode {
    /// The eigenvalue, 1/s.
    pub eigenvalue: Complex<f64>,
    /// The undamped natural frequency `|λ| / 2π`, Hz.
    pub frequency: f64,
    /// The damped frequency `Im λ / 2π`, Hz (0 for a real mode).
    pub damped_frequency: f64,
    /// The damping ratio `−Re λ / |λ|`.
    pub damping_ratio: f64,
    /// Each of the hull's motions' ([`HULL_MOTIONS`]) share of the mode's
    /// kinetic energy, 0 to 1: that rate's own energy (the hull moving
    /// with its running gear as one body), `½ M_ii |v_i|²`, over the sum
    /// of every rate's own (the mass matrix's diagonal in the trees'
    /// quasi-velocities), so that the shares of all rates add to 1.
    pub hull: [f64; 6],
}

impl SpatialMode {
    /// Whether the free response oscillates (`Im λ > 0`).
    pub fn oscillates(&self) -> bool {
        self.damped_frequency > 0.0
    }

    /// The hull's motion holding the largest share, and the share.
    pub fn hull_motion(&self) -> (&'static str, f64) {
        let k = (0..6)
            .max_by(|&a, &b| self.hull[a].total_cmp(&self.hull[b]))
            .unwrap_or(0);
        (HULL_MOTIONS[k], self.hull[k])
    }

    /// The share `motion` (one of [`HULL_MOTIONS`]) holds (0 for a name
    /// that is none of them).
    pub fn share_of(&self, motion: &str) -> f64 {
        HULL_MOTIONS
            .iter()
            .position(|m| *m == motion)
            .map_or(0.0, |k| self.hull[k])
    }
}

/// The oscillating mode holding the largest share of its kinetic energy
/// in the hull's `motion` (`hull bounce`, `hull roll` …), if any does.
pub fn spatial_mode_of<'m>(modes: &'m [SpatialMode], motion: &str) -> Option<&'m SpatialMode> {
    modes
        .iter()
        .filter(|m| m.oscillates() && m.share_of(motion) > 0.0)
        .max_by(|a, b| a.share_of(motion).total_cmp(&b.share_of(motion)))
}

/// A spatial vehicle's state at rest, as [`settle`] found it.
#[derive(Debug, Clone, PartialEq)]
pub struct SpatialRest {
    /// The time it settled to, s.
    pub t: f64,
    /// The state, its rates zero.
    pub y: DVector<f64>,
    /// The largest of the trees' accelerations there (m/s², rad/s²):
    /// what is left of the settling.
    pub residual: f64,
}

/// `system` run from `y` at `t = 0` for `duration` s by Bogacki-Shampine
/// at `tolerance`, its rates then set to zero: a state at rest, with the
/// accelerations left there. The drives the caller set hold it (a speed
/// drive asking 0, or brakes). A failed run is the error.
pub fn settle<S: SpatialSimulated>(
    system: &mut S,
    y: &DVector<f64>,
    duration: f64,
    tolerance: f64,
) -> Result<SpatialRest, AnalysisError> {
    let mut stepper = Integrator::bs23(tolerance).stepper(system.dimension());
    let (mut t, mut y) = (0.0, y.clone());
    while t < duration {
        stepper.step(system, &mut t, &mut y, duration)?;
    }
    let y = system.stilled(y.as_slice());
    let mut slope = vec![0.0; y.len()];
    system.derivative(t, y.as_slice(), &mut slope)?;
    // The trees' accelerations: the rates' rates, where stilling zeroes.
    let ones = system.stilled(&vec![1.0; y.len()]);
    let residual = slope
        .iter()
        .zip(ones.iter())
        .filter(|(_, one)| **one == 0.0)
        .map(|(s, _)| s.abs())
        .fold(0.0, f64::max);
    Ok(SpatialRest { t, y, residual })
}

/// The modes of `system` linearised at `(t, y)` (a [`settle`]d state,
/// usually) with natural frequencies up to `up_to` Hz, lowest first: the
/// eigenvalues of the state matrix over every state with dynamics
/// ([`SpatialSimulated::dynamic_states`]), by central differences
/// ([`linearise`]), one of each conjugate pair, those with `|λ|` below
/// 10⁻⁶ /s left out. Each mode's hull shares are its eigenvector's rates
/// weighted by each rate's own kinetic energy (the vehicle's energy at
/// `y` stilled with that rate alone at 1: the mass matrix's diagonal).
pub fn spatial_modes<S: SpatialSimulated>(
    system: &mut S,
    t: f64,
    y: &DVector<f64>,
    up_to: f64,
) -> Result<Vec<SpatialMode>, AnalysisError> {
    let states: Vec<usize> = (0..system.dynamic_states()).collect();
    let a = linearise(system, t, y.as_slice(), &states)?;
    let n = states.len();
    let dense = faer::Mat::<f64>::from_fn(n, n, |i, j| a[(i, j)]);
    let eigen = dense.eigen().map_err(|_| AnalysisError::Eigen)?;
    let (values, vectors) = (eigen.S().column_vector(), eigen.U());
    let still = system.stilled(y.as_slice());
    // The trees' rates: what stilling zeroes.
    let ones = system.stilled(&vec![1.0; y.len()]);
    let rates: Vec<usize> = (0..n).filter(|&i| ones[i] == 0.0).collect();
    let hull = system.hull_rates();
    // Each rate's own kinetic energy at unit rate, `½ M_ii`: the
    // diagonal of the mass matrix in the trees' quasi-velocities.
    let own: Vec<f64> = rates
        .iter()
        .map(|&i| {
            let mut at = still.clone();
            at[i] = 1.0;
            system.energy(at.as_slice()).kinetic
        })
        .collect();
    let mut modes = Vec::new();
    for k in 0..n {
        let lambda = Complex::new(values[k].re, values[k].im);
        let frequency = lambda.norm() / std::f64::consts::TAU;
        if lambda.im < 0.0 || lambda.norm() < 1e-6 || frequency > up_to {
            continue;
        }
        let energy = |i: usize, m: f64| {
            let v = Complex::new(vectors[(i, k)].re, vectors[(i, k)].im);
            m * v.norm_sqr()
        };
        let total: f64 = rates.iter().zip(&own).map(|(&i, &m)| energy(i, m)).sum();
        let mut shares = [0.0; 6];
        if total > 0.0 {
            for (share, &i) in shares.iter_mut().zip(&hull) {
                let at = rates.iter().position(|&r| r == i);
                *share = at.map_or(0.0, |r| energy(i, own[r]) / total);
            }
        }
        modes.push(SpatialMode {
            eigenvalue: lambda,
            frequency,
            damped_frequency: lambda.im / std::f64::consts::TAU,
            damping_ratio: -lambda.re / lambda.norm(),
            hull: shares,
        });
    }
    modes.sort_by(|a, b| a.frequency.total_cmp(&b.frequency));
    Ok(modes)
}
