use nalgebra::DVector;

use super::Simulated;
use crate::closure::Switch;
use crate::integrate::OdeSystem;
use crate::integrate::SimulationError;

/// Two subsystems integrated together, their states side by side in one
/// vector: the chassis and the track of a vehicle (formulation §3: assembled
/// separately, coupled only through the forces between them). Each
/// subsystem works on its own part of the state, in place: nothing is
/// copied per evaluation. Columns are prefixed with the subsystems' names.
pub struct Pair<A, B> {
    first: A,
    second: B,
    names: (String, String),
}

impl<A: Simulated, B: Simulated> Pair<A, B> {
    /// `first` and `second`, named for their columns (`track.energy`).
    pub fn new(first: A, first_name: &str, second: B, second_name: &str) -> Self {
        Pair {
            first,
            second,
            names: (first_name.to_string(), second_name.to_string()),
        }
    }

    /// The first subsystem.
    pub fn first(&self) -> &A {
        &self.first
    }

    /// The second subsystem.
    pub fn second(&self) -> &B {
        &self.second
    }

    /// Both subsystems, to change.
    pub(crate) fn parts_mut(&mut self) -> (&mut A, &mut B) {
        (&mut self.first, &mut self.second)
    }

    /// The first subsystem's part of a state and the second's.
    pub(crate) fn split<'y>(&self, y: &'y [f64]) -> (&'y [f64], &'y [f64]) {
        y.split_at(self.first.dimension())
    }

    /// [`split`](Self::split), to change.
    pub(crate) fn split_mut<'y>(&self, y: &'y mut [f64]) -> (&'y mut [f64], &'y mut [f64]) {
        y.split_at_mut(self.first.dimension())
    }
}

impl<A: Simulated, B: Simulated> OdeSystem for Pair<A, B> {
    fn dimension(&self) -> usize {
        self.first.dimension() + self.second.dimension()
    }

    fn derivative(&mut self, t: f64, y: &[f64], dy: &mut [f64]) -> Result<(), SimulationError> {
        let (ya, yb) = self.split(y);
        let (da, db) = self.split_mut(dy);
        self.first.derivative(t, ya, da)?;
        self.second.derivative(t, yb, db)
    }
}

impl<A: Simulated, B: Simulated> Simulated for Pair<A, B> {
    fn initial_state(&self) -> DVector<f64> {
        let (a, b) = (self.first.initial_state(), self.second.initial_state());
        DVector::from_iterator(a.len() + b.len(), a.iter().chain(b.iter()).copied())
    }

    fn columns(&self) -> Vec<String> {
        let (a, b) = &self.names;
        let first = self.first.columns().into_iter().map(|c| format!("{a}.{c}"));
        let second = self
            .second
            .columns()
            .into_iter()
            .map(|c| format!("{b}.{c}"));
        first.chain(second).collect()
    }

    fn observe(&mut self, t: f64, y: &[f64], row: &mut Vec<f64>) -> Result<(), SimulationError> {
        let (ya, yb) = self.split(y);
        self.first.observe(t, ya, row)?;
        self.second.observe(t, yb, row)
    }

    fn after_step(
        &mut self,
        t: f64,
        y: &mut [f64],
        switched: &mut dyn FnMut(Switch),
    ) -> Result<bool, SimulationError> {
        let (ya, yb) = self.split_mut(y);
        // Each subsystem changes its part in place, so a failure of the
        // second leaves the first's (logged) change in the state.
        let first = self.first.after_step(t, ya, switched)?;
        let second = self.second.after_step(t, yb, switched)?;
        Ok(first || second)
    }
}
