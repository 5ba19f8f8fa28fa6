//! The linearisation of a vehicle's equations at a state and the modes it
//! vibrates in: eigenvalues as natural frequencies and damping ratios,
//! eigenvectors named by what moves most.

use nalgebra::{Complex, DMatrix, DVector, Vector2};

use super::{AnalysisError, state_jacobian};
use crate::integrate::OdeSystem;
use crate::multibody::PartKind;
use crate::vehicle::VehicleDynamics;

/// What share of a mode's kinetic energy a body or a motion holds.
#[derive(Debug, Clone, PartialEq)]
pub struct Share {
    /// What moves: `hull bounce`, `hull pitch`, `hull surge`, `road wheel
    /// rw3 on its arm`, `idler idler on its tensioner`, `sprocket`, `upper
    /// track span (links 29–41)` or `(link 10)` (above the wheels' centres at rest, or
    /// `lower`: the run on the ground and round the wheels).
    pub what: String,
    /// Its share of the mode's kinetic energy, 0 to 1.
    pub fraction: f64,
}

/// A mode of the linearised vehicle: an eigenvalue `λ` of the state matrix
/// (one of each conjugate pair, `Im λ ≥ 0`) and its shape.
#[derive(Debug, Clone, PartialEq)]
pub struct Mode {
    /// The eigenvalue, 1/s.
    pub eigenvalue: Complex<f64>,
    /// The undamped natural frequency `|λ| / 2π`, Hz.
    pub frequency: f64,
    /// The damped frequency `Im λ / 2π`, Hz: that of the free response (0
    /// for an overdamped, real mode).
    pub damped_frequency: f64,
    /// The damping ratio `−Re λ / |λ|` (1 or more: no oscillation).
    pub damping_ratio: f64,
    /// What moves most (the largest of [`shares`](Self::shares)).
    pub name: String,
    /// Who holds the mode's kinetic energy, largest first (those above 1 %).
    pub shares: Vec<Share>,
    /// The mode's displacement over the state (coordinates only; rates,
    /// integral and tangential states zero), real at the phase where its
    /// largest coordinate peaks, that coordinate scaled to 1.
    pub shape: DVector<f64>,
    /// The eigenvector over the whole state (zero for the books), at the
    /// phase and scale of [`shape`](Self::shape): the linear free response
    /// from `y + ε Re v` (rates included) is `ε Re(v e^{λt})`.
    pub vector: DVector<Complex<f64>>,
}

impl Mode {
    /// Whether the free response oscillates (`Im λ > 0`).
    pub fn oscillates(&self) -> bool {
        self.damped_frequency > 0.0
    }
}

/// The oscillating mode holding the largest share of its kinetic energy
/// in `motion` (a [`Share::what`]: `hull bounce`, `hull pitch`, `sprocket`
/// …), if any holds some: where the hull's modes mix with the track's
/// spans, the mode a test rig would call the hull's pitch even when a span
/// holds more of it.
pub fn mode_of<'m>(modes: &'m [Mode], motion: &str) -> Option<&'m Mode> {
    modes
        .iter()
        .filter(|m| m.oscillates() && m.share_of(motion) > 0.0)
        .max_by(|a, b| a.share_of(motion).total_cmp(&b.share_of(motion)))
}

impl Mode {
    /// The share of its kinetic energy `motion` holds (0 if none).
    pub fn share_of(&self, motion: &str) -> f64 {
        self.shares
            .iter()
            .find(|s| s.what == motion)
            .map_or(0.0, |s| s.fraction)
    }
}

/// The state matrix `A = ∂f/∂y` at `(t, y)` over the states `states`
/// (rows and columns, in that order): the linearisation `δẏ = A δy`. The
/// system's exact Jacobian where it gives one ([`OdeSystem::jacobian`]: a
/// vehicle on rigid ground closed by partitioning), central differences
/// ([`state_jacobian`]) otherwise.
pub fn linearise<S: OdeSystem + ?Sized>(
    system: &mut S,
    t: f64,
    y: &[f64],
    states: &[usize],
) -> Result<DMatrix<f64>, AnalysisError> {
    let n = y.len();
    let mut slope = vec![0.0; n];
    system.derivative(t, y, &mut slope)?;
    let mut full = vec![0.0; n * n];
    if system.jacobian(t, y, &slope, &mut full)? {
        return Ok(DMatrix::from_fn(states.len(), states.len(), |r, c| {
            full[states[c] * n + states[r]]
        }));
    }
    Ok(state_jacobian(system, t, y, states)?.select_rows(states))
}

/// The modes of `system` linearised at `(t, y)` (an
/// [equilibrium](super::equilibrium)'s state, usually), lowest natural
/// frequency first: the eigenvalues of the state matrix over every state
/// with dynamics ([`StateLayout::dynamic`](crate::vehicle::StateLayout::dynamic):
/// coordinates, rates, the drive's integral and the stiction deflections;
/// not the books), one of each conjugate pair, those with `|λ|` below
/// 10⁻⁶ /s (free motions: rolling along level ground) left out. Each is
/// named by the body or motion holding most of its kinetic energy
/// (`½ m |δr|² + ½ I δθ²` per body, from the mode's displacement expanded
/// through the loop closure).
pub fn modes<S: VehicleDynamics>(
    system: &mut S,
    t: f64,
    y: &DVector<f64>,
) -> Result<Vec<Mode>, AnalysisError> {
    let layout = system.layout();
    let states: Vec<usize> = layout.dynamic().collect();
    let a = linearise(system, t, y.as_slice(), &states)?;
    let n = states.len();
    let dense = faer::Mat::<f64>::from_fn(n, n, |i, j| a[(i, j)]);
    let eigen = dense.eigen().map_err(|_| AnalysisError::Eigen)?;
    let (values, vectors) = (eigen.S().column_vector(), eigen.U());
    let positions: Vec<(usize, usize)> = states
        .iter()
        .enumerate()
        .filter(|(_, i)| layout.track.contains(i) || layout.chassis.contains(i))
        .map(|(k, &i)| (k, i))
        .collect();
    let bodies = Bodies::<S>::new();
    let mut modes = Vec::new();
    for k in 0..n {
        let lambda = Complex::new(values[k].re, values[k].im);
        if lambda.im < 0.0 || lambda.norm() < 1e-6 {
            continue;
        }
        let component = |r: usize| Complex::new(vectors[(r, k)].re, vectors[(r, k)].im);
        let peak = positions
            .iter()
            .map(|&(r, _)| component(r))
            .max_by(|a, b| a.norm().total_cmp(&b.norm()))
            .unwrap_or(Complex::new(1.0, 0.0));
        let mut shape = DVector::zeros(y.len());
        let mut vector = DVector::from_element(y.len(), Complex::new(0.0, 0.0));
        if peak.norm() > 0.0 {
            let phase = peak.conj() / (peak.norm() * peak.norm());
            for (r, &i) in states.iter().enumerate() {
                vector[i] = component(r) * phase;
            }
            for &(_, i) in &positions {
                shape[i] = vector[i].re;
            }
        }
        let shares = bodies.shares(system, t, y, &shape)?;
        let norm = lambda.norm();
        modes.push(Mode {
            eigenvalue: lambda,
            frequency: norm / std::f64::consts::TAU,
            damped_frequency: lambda.im / std::f64::consts::TAU,
            damping_ratio: -lambda.re / norm,
            name: shares
                .first()
                .map_or_else(|| "drive or contact state".to_string(), |s| s.what.clone()),
            shares,
            shape,
            vector,
        });
    }
    modes.sort_by(|a, b| a.frequency.total_cmp(&b.frequency));
    Ok(modes)
}

/// The bodies' masses and how their kinetic energy is grouped into named
/// motions.
struct Bodies<S> {
    track: Vec<(f64, f64)>,
    chassis: Vec<(f64, f64)>,
    /// The group of each chassis body (0: the hull, split three ways).
    groups: Vec<String>,
    _system: std::marker::PhantomData<S>,
}

impl<S: VehicleDynamics> Bodies<S> {
    fn new() -> Self {
        let masses = |d: crate::multibody::TreeDescription| -> Vec<(f64, f64)> {
            d.bodies.iter().map(|b| (b.mass, b.inertia)).collect()
        };
        let chassis = masses(S::chassis_description());
        let mut groups: Vec<String> = (0..chassis.len())
            .map(|b| format!("chassis body {b}"))
            .collect();
        for part in S::parts() {
            let what = match part.kind {
                PartKind::Sprocket => "sprocket".to_string(),
                PartKind::Idler => format!("idler {}", part.name),
                PartKind::RoadWheel => format!("road wheel {}", part.name),
                PartKind::Roller => format!("roller {}", part.name),
            };
            match &part.arm {
                Some(arm) => {
                    let on = if part.kind == PartKind::Idler {
                        " on its tensioner"
                    } else {
                        " on its arm"
                    };
                    groups[part.body] = format!("{what}{on}");
                    groups[arm.body] = groups[part.body].clone();
                }
                None => groups[part.body] = what,
            }
        }
        Bodies {
            track: masses(S::track_description()),
            chassis,
            groups,
            _system: std::marker::PhantomData,
        }
    }

    /// The shares of the kinetic energy of a motion along `shape` at `y`,
    /// largest first, those above 1 %.
    fn shares(
        &self,
        system: &mut S,
        t: f64,
        y: &DVector<f64>,
        shape: &DVector<f64>,
    ) -> Result<Vec<Share>, AnalysisError> {
        // The bodies' displacements by a central difference through the
        // loop closure: a displacement of 10⁻⁶ of the shape's unit.
        let h = 1e-6;
        let (qt_plus, qc_plus) = system.coordinates(t, (y + shape * h).as_slice())?;
        let (qt_minus, qc_minus) = system.coordinates(t, (y - shape * h).as_slice())?;
        let centroids = |q: &DVector<f64>, n: usize, track: bool| {
            let mut out = vec![Vector2::zeros(); n];
            if track {
                S::track_positions(q.as_slice(), &mut out);
            } else {
                S::chassis_positions(q.as_slice(), &mut out);
            }
            out
        };
        let (nt, nc) = (self.track.len(), self.chassis.len());
        let dr_track: Vec<Vector2<f64>> = centroids(&qt_plus, nt, true)
            .iter()
            .zip(centroids(&qt_minus, nt, true))
            .map(|(p, m)| (p - m) / (2.0 * h))
            .collect();
        let dr_chassis: Vec<Vector2<f64>> = centroids(&qc_plus, nc, false)
            .iter()
            .zip(centroids(&qc_minus, nc, false))
            .map(|(p, m)| (p - m) / (2.0 * h))
            .collect();
        let dtheta = |plus: &DVector<f64>, minus: &DVector<f64>, b: usize| {
            (plus[2 + b] - minus[2 + b]) / (2.0 * h)
        };
        let mut groups: Vec<(String, f64)> = Vec::new();
        let mut add = |what: &str, e: f64| match groups.iter_mut().find(|g| g.0 == what) {
            Some(g) => g.1 += e,
            None => groups.push((what.to_string(), e)),
        };
        let (m, i) = self.chassis[0];
        add("hull surge", m * dr_chassis[0].x.powi(2));
        add("hull bounce", m * dr_chassis[0].y.powi(2));
        add("hull pitch", i * dtheta(&qc_plus, &qc_minus, 0).powi(2));
        for (b, (&(m, i), dr)) in self.chassis.iter().zip(&dr_chassis).enumerate().skip(1) {
            let e = m * dr.norm_squared() + i * dtheta(&qc_plus, &qc_minus, b).powi(2);
            add(&self.groups[b], e);
        }
        let link_energy: Vec<f64> = (0..nt)
            .map(|b| {
                let (m, i) = self.track[b];
                m * dr_track[b].norm_squared() + i * dtheta(&qt_plus, &qt_minus, b).powi(2)
            })
            .collect();
        let track_total: f64 = link_energy.iter().sum();
        if track_total > 0.0 {
            let (a, b) = span_holding_half(&link_energy);
            // Above the wheels' centres or below them, at rest.
            let (qt, qc) = system.coordinates(t, y.as_slice())?;
            let links = centroids(&qt, nt, true);
            let bodies = centroids(&qc, nc, false);
            let axles = (1..nc).map(|b| bodies[b].y).sum::<f64>() / (nc.max(2) - 1) as f64;
            let run: Vec<usize> = if a <= b {
                (a..=b).collect()
            } else {
                (a..nt).chain(0..=b).collect()
            };
            let height = run.iter().map(|&k| links[k].y).sum::<f64>() / run.len() as f64;
            let side = if height > axles { "upper" } else { "lower" };
            let which = if a == b {
                format!("link {}", a + 1)
            } else {
                format!("links {}–{}", a + 1, b + 1)
            };
            add(&format!("{side} track span ({which})"), track_total);
        }
        let total: f64 = groups.iter().map(|g| g.1).sum();
        if total <= 0.0 {
            return Ok(Vec::new());
        }
        let mut shares: Vec<Share> = groups
            .into_iter()
            .map(|(what, e)| Share {
                what,
                fraction: e / total,
            })
            .filter(|s| s.fraction > 0.01)
            .collect();
        shares.sort_by(|a, b| b.fraction.total_cmp(&a.fraction));
        Ok(shares)
    }
}

/// The shortest run of links (round the loop) that holds half the energy,
/// grown from the link holding most: `(first, last)`, 0-based, `last` may
/// be below `first` when the run wraps past the last link.
fn span_holding_half(energy: &[f64]) -> (usize, usize) {
    let n = energy.len();
    let total: f64 = energy.iter().sum();
    let peak = (0..n)
        .max_by(|&a, &b| energy[a].total_cmp(&energy[b]))
        .unwrap_or(0);
    let (mut first, mut last, mut held) = (peak, peak, energy[peak]);
    let mut grown = 1;
    while held < 0.5 * total && grown < n {
        let before = (first + n - 1) % n;
        let after = (last + 1) % n;
        if energy[before] > energy[after] {
            first = before;
            held += energy[before];
        } else {
            last = after;
            held += energy[after];
        }
        grown += 1;
    }
    (first, last)
}
