//! The equations of a vehicle at rest and their unknowns: what
//! [`equilibrium`](super::equilibrium) solves and
//! [`equilibrium_sensitivity`](super::equilibrium_sensitivity)
//! differentiates.

use nalgebra::{DMatrix, DVector};

use super::{AnalysisError, step_for};
use crate::multibody::PartKind;
use crate::vehicle::{StateLayout, VehicleDynamics};

/// The statics of a vehicle at a state: which coordinates are unknown,
/// which accelerations must vanish, and, where the ground holds with
/// stiction, the ground points whose shared tangential deflection is one
/// more unknown (each point's Coulomb limit taken at that state).
pub(super) struct Statics {
    pub layout: StateLayout,
    /// Indices into the state: every coordinate but the free ones (the
    /// chassis' x, the sprocket's angle, each other wheel's spin), then
    /// the drive's integral.
    unknowns: Vec<usize>,
    /// Indices into the state's rates: each acceleration in the order of
    /// its coordinate among the unknowns, then the sprocket's (beside the
    /// integral that holds it), then, with friction holding, the chassis'
    /// along x (beside the deflection).
    equations: Vec<usize>,
    /// With stiction on rigid ground: the tangential states of the ground
    /// points in contact, which share one deflection (an unknown paired
    /// with the chassis' x), each with the largest it holds at rest.
    friction: Option<Vec<(usize, f64)>>,
}

impl Statics {
    /// The statics of `system` at `y`; with `friction` (and stiction
    /// states), the points touching the ground at `y` share a deflection.
    pub fn at<S: VehicleDynamics>(
        system: &mut S,
        t: f64,
        y: &DVector<f64>,
        friction: bool,
    ) -> Result<Statics, AnalysisError> {
        let layout = system.layout();
        let sprocket = layout.sprocket_angle().ok_or(AnalysisError::NoSprocket)?;
        // A wheel's spin on its axle: round rims turn freely at rest.
        let spins: Vec<usize> = S::parts()
            .iter()
            .filter(|p| p.kind != PartKind::Sprocket)
            .map(|p| 2 + p.body)
            .collect();
        let held = |c: usize| c == 0 || spins.contains(&c);
        let sprocket_rate = sprocket - layout.chassis.start + layout.chassis_rates.start;
        let unknowns = layout
            .chassis
            .clone()
            .filter(|&i| !held(i - layout.chassis.start) && i != sprocket)
            .chain(layout.track.clone())
            .chain([layout.integral])
            .collect();
        let mut equations: Vec<usize> = layout
            .chassis_rates
            .clone()
            .filter(|&i| !held(i - layout.chassis_rates.start) && i != sprocket_rate)
            .chain(layout.track_rates.clone())
            .chain([sprocket_rate])
            .collect();
        let friction = if friction && system.holds_by_stiction() && !layout.tangential.is_empty() {
            equations.push(layout.chassis_rates.start);
            let limits = system.stiction_limits(t, y.as_slice())?;
            Some(
                layout
                    .tangential
                    .clone()
                    .zip(limits)
                    .filter_map(|(i, limit)| limit.map(|l| (i, l)))
                    .collect(),
            )
        } else {
            None
        };
        Ok(Statics {
            layout,
            unknowns,
            equations,
            friction,
        })
    }

    /// The unknowns' values at `y` (the shared deflection read where it
    /// is least likely held back by a point's limit: at the point that
    /// holds most).
    pub fn read(&self, y: &DVector<f64>) -> DVector<f64> {
        let shared = self.friction.as_ref().map(|points| {
            points
                .iter()
                .max_by(|a, b| a.1.total_cmp(&b.1))
                .map_or(0.0, |&(i, _)| y[i])
        });
        DVector::from_iterator(
            self.len(),
            self.unknowns.iter().map(|&i| y[i]).chain(shared),
        )
    }

    /// `y` with the unknowns `u`: every ground point in contact takes the
    /// shared deflection up to what it holds (a lightly loaded point at
    /// its Coulomb limit: beyond it, it would slide back to it), every
    /// other one none (off the ground a deflection relaxes, so at rest it
    /// is zero).
    pub fn write(&self, u: &DVector<f64>, y: &mut DVector<f64>) {
        for (k, &i) in self.unknowns.iter().enumerate() {
            y[i] = u[k];
        }
        if let Some(points) = &self.friction {
            for i in self.layout.tangential.clone() {
                y[i] = 0.0;
            }
            let shared = u[self.unknowns.len()];
            for &(i, limit) in points {
                y[i] = shared.clamp(-limit, limit);
            }
        }
    }

    /// How many unknowns (and equations).
    pub fn len(&self) -> usize {
        self.unknowns.len() + usize::from(self.friction.is_some())
    }

    /// The accelerations that must vanish, at `y`.
    pub fn residual<S: VehicleDynamics>(
        &self,
        system: &mut S,
        t: f64,
        y: &DVector<f64>,
    ) -> Result<DVector<f64>, AnalysisError> {
        let mut rates = DVector::zeros(y.len());
        system.derivative(t, y.as_slice(), rates.as_mut_slice())?;
        Ok(DVector::from_iterator(
            self.equations.len(),
            self.equations.iter().map(|&i| rates[i]),
        ))
    }

    /// `∂r/∂u` at `y`: the system's exact Jacobian's rows of the
    /// equations and columns of the unknowns where it gives one
    /// ([`OdeSystem::jacobian`]) and friction holds nothing; else central
    /// differences ([`step_for`]; the shared deflection, in the stiction
    /// states' unit, the same way). Held by friction, each ground point's
    /// deflection is clipped at its Coulomb limit, and the rest has points
    /// at their limits: differences that straddle the clip let Newton's
    /// method settle there, the one-sided exact derivative makes it cycle
    /// (measured on a 30 % grade: a residual stalled at 6.6e-8 against
    /// the tolerance 1e-8, where the differences converge in 31
    /// iterations).
    ///
    /// [`OdeSystem::jacobian`]: crate::integrate::OdeSystem::jacobian
    pub fn jacobian<S: VehicleDynamics>(
        &self,
        system: &mut S,
        t: f64,
        y: &DVector<f64>,
    ) -> Result<DMatrix<f64>, AnalysisError> {
        let n = y.len();
        let (mut slope, mut full) = (vec![0.0; n], vec![0.0; n * n]);
        system.derivative(t, y.as_slice(), &mut slope)?;
        if self.friction.is_none() && system.jacobian(t, y.as_slice(), &slope, &mut full)? {
            let mut jacobian = DMatrix::zeros(self.equations.len(), self.len());
            for (row, &r) in self.equations.iter().enumerate() {
                for (k, &c) in self.unknowns.iter().enumerate() {
                    jacobian[(row, k)] = full[c * n + r];
                }
            }
            return Ok(jacobian);
        }
        let u = self.read(y);
        let mut jacobian = DMatrix::zeros(self.equations.len(), self.len());
        let mut moved = y.clone();
        for k in 0..self.len() {
            let h = step_for(u[k]);
            let mut at = |shift: f64| -> Result<DVector<f64>, AnalysisError> {
                let mut v = u.clone();
                v[k] += shift;
                self.write(&v, &mut moved);
                self.residual(system, t, &moved)
            };
            let column = (at(h)? - at(-h)?) / (2.0 * h);
            jacobian.set_column(k, &column);
        }
        Ok(jacobian)
    }

    /// The name of equation `k`'s state, for errors.
    pub fn equation_name(&self, k: usize, points: usize) -> String {
        self.layout.name(self.equations[k], points)
    }
}
