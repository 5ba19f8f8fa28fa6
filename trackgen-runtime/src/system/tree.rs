use nalgebra::{DVector, SVector};

use super::Simulated;
use super::loads::Loads;
use super::mechanics::{masses, mechanics_columns, record_mechanics};
use crate::integrate::OdeSystem;
use crate::integrate::SimulationError;
use crate::multibody::{BodyLoad, ChassisModel, RecursiveModel};

/// A body tree without constraints in motion: a chassis (formulation §3), an open
/// chain, or a track closed by its declared penalty joint. The state is
/// `y = [q_i, q̇_i]`; the accelerations come from the model's generated
/// O(n) [`tree_dynamics`](RecursiveModel::tree_dynamics).
pub struct TreeSystem<M: RecursiveModel<D>, const D: usize> {
    model: M,
    /// Every body's `(sin θ, cos θ)` at the last evaluation.
    trig: Vec<(f64, f64)>,
    y0: DVector<f64>,
    loads: Loads<D>,
    masses: Vec<(f64, f64)>,
    names: Vec<String>,
}

impl<M: RecursiveModel<D>, const D: usize> TreeSystem<M, D> {
    /// The tree starting at `(q_i, q̇_i)`.
    pub fn new(model: M, q: SVector<f64, D>, qd: SVector<f64, D>) -> Self {
        let y0 = DVector::from_iterator(2 * D, q.iter().chain(qd.iter()).copied());
        let masses = masses(&model);
        let names = (0..M::BODIES).map(|b| b.to_string()).collect();
        TreeSystem {
            model,
            trig: vec![(0.0, 1.0); M::BODIES],
            y0,
            loads: Loads::new(M::BODIES),
            masses,
            names,
        }
    }

    /// Names bodies in column names (`theta_<name>`), instead of their
    /// index.
    ///
    /// # Panics
    /// If there is not one name per body (a programming error).
    pub fn with_body_names(mut self, names: Vec<String>) -> Self {
        assert_eq!(names.len(), M::BODIES, "one name per body");
        self.names = names;
        self
    }

    /// Applied loads besides gravity.
    pub fn with_loads(
        mut self,
        loads: impl FnMut(f64, &SVector<f64, D>, &SVector<f64, D>, &mut [BodyLoad]) + Send + 'static,
    ) -> Self {
        self.loads.set_function(Box::new(loads));
        self
    }

    /// The compiled model.
    pub fn model(&self) -> &M {
        &self.model
    }

    /// `(q_i, q̇_i)` of a state `y = [q_i, q̇_i]`.
    pub(crate) fn split(y: &[f64]) -> (SVector<f64, D>, SVector<f64, D>) {
        (
            SVector::from_column_slice(&y[..D]),
            SVector::from_column_slice(&y[D..2 * D]),
        )
    }

    /// Loads from outside the subsystem (contact with another), added to
    /// gravity and the load function until set again.
    pub(crate) fn set_external(&mut self, loads: &[BodyLoad]) {
        self.loads.set_external(loads);
    }

    /// [`derivative`](OdeSystem::derivative) given every body's
    /// `(sin θ, cos θ)` at `y`, worked out already by the caller (a
    /// vehicle's contact pass needs them too).
    pub(crate) fn derivative_with_trig(
        &mut self,
        t: f64,
        y: &[f64],
        trig: &[(f64, f64)],
        dy: &mut [f64],
    ) -> Result<(), SimulationError> {
        derivative_at(&self.model, &mut self.loads, trig, t, y, dy)
    }
}

/// `ẏ = [q̇_i, q̈_i]` at `y = [q_i, q̇_i]`, with the bodies' trigonometry.
fn derivative_at<M: RecursiveModel<D>, const D: usize>(
    model: &M,
    loads: &mut Loads<D>,
    trig: &[(f64, f64)],
    t: f64,
    y: &[f64],
    dy: &mut [f64],
) -> Result<(), SimulationError> {
    let (q, qd) = TreeSystem::<M, D>::split(y);
    let loads = loads.fill(t, &q, &qd);
    let mut qdd = SVector::zeros();
    model
        .tree_dynamics(trig, &qd, loads, &mut qdd)
        .map_err(|source| SimulationError::Dynamics { t, source })?;
    dy[..D].copy_from_slice(&y[D..2 * D]);
    dy[D..].copy_from_slice(qdd.as_slice());
    Ok(())
}

impl<M: ChassisModel<D>, const D: usize> TreeSystem<M, D> {
    /// A chassis starting at `(q_i, q̇_i)`, its columns named after the
    /// frame (`chassis`), the declared parts (`theta_sprocket`, …) and
    /// their arms (`theta_rw1_arm`).
    pub fn chassis(model: M, q: SVector<f64, D>, qd: SVector<f64, D>) -> Self {
        let mut names: Vec<String> = (0..M::BODIES).map(|b| b.to_string()).collect();
        names[0] = "chassis".to_string();
        for part in M::PARTS {
            names[part.body] = part.name.to_string();
            if let Some(arm) = &part.arm {
                names[arm.body] = format!("{}_arm", part.name);
            }
        }
        Self::new(model, q, qd).with_body_names(names)
    }
}

impl<M: RecursiveModel<D>, const D: usize> OdeSystem for TreeSystem<M, D> {
    fn dimension(&self) -> usize {
        2 * D
    }

    fn derivative(&mut self, t: f64, y: &[f64], dy: &mut [f64]) -> Result<(), SimulationError> {
        crate::trig::sin_cos_each(&y[2..D], &mut self.trig);
        derivative_at(&self.model, &mut self.loads, &self.trig, t, y, dy)
    }
}

impl<M: RecursiveModel<D>, const D: usize> Simulated for TreeSystem<M, D> {
    fn initial_state(&self) -> DVector<f64> {
        self.y0.clone()
    }

    fn columns(&self) -> Vec<String> {
        mechanics_columns(M::BODIES, |b| self.names[b].clone())
    }

    fn observe(&mut self, _t: f64, y: &[f64], row: &mut Vec<f64>) -> Result<(), SimulationError> {
        let (q, qd) = Self::split(y);
        record_mechanics(&self.model, &self.masses, &q, &qd, 0.0, row);
        Ok(())
    }
}
