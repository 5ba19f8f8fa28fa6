use nalgebra::DVector;

use super::{Simulated, SimulationError, Switch};
use crate::integrate::OdeSystem;

/// Two subsystems integrated together, their states concatenated: the
/// chassis and the track of a vehicle (spec §3: assembled separately,
/// coupled only through the forces between them). Columns are prefixed
/// with the subsystems' names.
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

    fn split(&self, y: &DVector<f64>) -> (DVector<f64>, DVector<f64>) {
        let n = self.first.dimension();
        (
            y.rows(0, n).into_owned(),
            y.rows(n, y.len() - n).into_owned(),
        )
    }
}

impl<A: Simulated, B: Simulated> OdeSystem for Pair<A, B> {
    fn dimension(&self) -> usize {
        self.first.dimension() + self.second.dimension()
    }

    fn derivative(
        &mut self,
        t: f64,
        y: &DVector<f64>,
        dy: &mut DVector<f64>,
    ) -> Result<(), SimulationError> {
        let (ya, yb) = self.split(y);
        let (mut da, mut db) = (DVector::zeros(ya.len()), DVector::zeros(yb.len()));
        self.first.derivative(t, &ya, &mut da)?;
        self.second.derivative(t, &yb, &mut db)?;
        dy.rows_mut(0, da.len()).copy_from(&da);
        dy.rows_mut(da.len(), db.len()).copy_from(&db);
        Ok(())
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

    fn observe(
        &mut self,
        t: f64,
        y: &DVector<f64>,
        row: &mut Vec<f64>,
    ) -> Result<(), SimulationError> {
        let (ya, yb) = self.split(y);
        self.first.observe(t, &ya, row)?;
        self.second.observe(t, &yb, row)
    }

    fn after_step(&mut self, t: f64, y: &mut DVector<f64>) -> Result<bool, SimulationError> {
        let (mut ya, mut yb) = self.split(y);
        let n = ya.len();
        // Each subsystem's change is written back at once, so a failure of
        // the second leaves the first's (recorded) change in the state.
        let first = self.first.after_step(t, &mut ya)?;
        if first {
            y.rows_mut(0, n).copy_from(&ya);
        }
        let second = self.second.after_step(t, &mut yb)?;
        if second {
            y.rows_mut(n, yb.len()).copy_from(&yb);
        }
        Ok(first || second)
    }

    fn switches(&self) -> Vec<Switch> {
        let mut s = self.first.switches();
        s.extend(self.second.switches());
        s.sort_by(|a, b| a.t.total_cmp(&b.t));
        s
    }
}
