use nalgebra::SVector;

use super::LoadFn;
use crate::multibody::BodyLoad;

/// The loads on a subsystem's bodies at an evaluation: those set from
/// outside (contact with another subsystem), plus the user's load function.
pub(crate) struct Loads<const D: usize> {
    function: Option<LoadFn<D>>,
    external: Vec<BodyLoad>,
    current: Vec<BodyLoad>,
}

impl<const D: usize> Loads<D> {
    pub fn new(bodies: usize) -> Self {
        Loads {
            function: None,
            external: vec![BodyLoad::ZERO; bodies],
            current: vec![BodyLoad::ZERO; bodies],
        }
    }

    pub fn set_function(&mut self, function: LoadFn<D>) {
        self.function = Some(function);
    }

    /// Loads from outside the subsystem, kept until set again.
    pub fn set_external(&mut self, loads: &[BodyLoad]) {
        self.external.copy_from_slice(loads);
    }

    /// The loads at `(t, q_i, q̇_i)`: the external ones, then the function's
    /// additions (without a function, the external ones as they are).
    pub fn fill(&mut self, t: f64, q: &SVector<f64, D>, qd: &SVector<f64, D>) -> &[BodyLoad] {
        let Some(f) = &mut self.function else {
            return &self.external;
        };
        self.current.copy_from_slice(&self.external);
        f(t, q, qd, &mut self.current);
        &self.current
    }
}
