use nalgebra::DVector;

use super::{Output, Results, SimulationError, SimulationFailure, Switch};
use crate::integrate::{Integrator, OdeSystem};

/// A system a simulation can run: an [`OdeSystem`] that also knows its
/// initial state, what to record, and what to do between steps.
pub trait Simulated: OdeSystem {
    /// The state at the start.
    fn initial_state(&self) -> DVector<f64>;

    /// Names of the recorded quantities.
    fn columns(&self) -> Vec<String>;

    /// Appends the recorded quantities at `(t, y)` to `row`.
    fn observe(
        &mut self,
        t: f64,
        y: &DVector<f64>,
        row: &mut Vec<f64>,
    ) -> Result<(), SimulationError>;

    /// Called after every accepted step; may change the coordinates of the
    /// state (re-partitioning, projection). Returns whether it did, so the
    /// integrator restarts.
    fn after_step(&mut self, _t: f64, _y: &mut DVector<f64>) -> Result<bool, SimulationError> {
        Ok(false)
    }

    /// Re-partitionings so far.
    fn switches(&self) -> Vec<Switch> {
        Vec::new()
    }
}

/// Integrates `system` from `t0` to `t_end` (s), recording at `output`.
///
/// On failure the error comes with every sample recorded before it.
// The failure carries the results by design; it is the rare path.
#[allow(clippy::result_large_err)]
pub fn simulate(
    system: &mut dyn Simulated,
    integrator: Integrator,
    t0: f64,
    t_end: f64,
    output: Output,
) -> Result<Results, SimulationFailure> {
    let mut results = Results::new(system.columns());
    let mut stepper = integrator.stepper(system.dimension());
    let outcome = run(system, stepper.as_mut(), t0, t_end, &output, &mut results);
    results.switches = system.switches();
    results.stats = stepper.stats();
    match outcome {
        Ok(()) => Ok(results),
        Err(error) => Err(SimulationFailure { error, results }),
    }
}

fn run(
    system: &mut dyn Simulated,
    stepper: &mut dyn crate::integrate::Stepper,
    t0: f64,
    t_end: f64,
    output: &Output,
    results: &mut Results,
) -> Result<(), SimulationError> {
    let mut row = Vec::new();
    let mut record =
        |system: &mut dyn Simulated, t: f64, y: &DVector<f64>, results: &mut Results| {
            row.clear();
            system.observe(t, y, &mut row)?;
            results.push(t, &row);
            Ok::<(), SimulationError>(())
        };
    let mut t = t0;
    let mut y = system.initial_state();
    if !y.iter().all(|v| v.is_finite()) {
        return Err(SimulationError::NonFinite {
            t,
            what: "the initial state",
        });
    }
    let mut next = 0;
    if matches!(output, Output::Steps) {
        record(system, t, &y, results)?;
    }
    while output.time(t0, next).is_some_and(|to| to <= t0) {
        record(system, t, &y, results)?;
        next += 1;
    }
    // Times closer to the end than this are the end.
    let eps = 1e-12 * t_end.abs().max(1.0);
    while t < t_end - eps {
        let t_old = t;
        stepper.step(system, &mut t, &mut y, t_end)?;
        if !y.iter().all(|v| v.is_finite()) {
            return Err(SimulationError::NonFinite {
                t,
                what: "the state",
            });
        }
        if t >= t_end - eps {
            t = t_end;
        }
        while let Some(to) = output.time(t0, next).filter(|&to| to <= t + eps) {
            if to > t_old {
                let yo = if (to - t).abs() <= eps {
                    y.clone()
                } else {
                    stepper.interpolate(to)
                };
                record(system, to.min(t), &yo, results)?;
            }
            next += 1;
        }
        if matches!(output, Output::Steps) {
            record(system, t, &y, results)?;
        }
        if system.after_step(t, &mut y)? {
            stepper.restart();
        }
    }
    Ok(())
}
