use nalgebra::DVector;

use super::march::{March, validate, validate_output};
use super::{Output, Results, RunError, SimulationFailure, Sink};
use crate::integrate::{Check, Integrator, SimulationError, Stats};
use crate::system::Simulated;

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
    simulate_with_progress(system, integrator, t0, t_end, output, &mut |_| {})
}

/// [`simulate`], calling `progress(t)` after every accepted step (for a
/// progress bar).
#[allow(clippy::result_large_err)]
pub fn simulate_with_progress(
    system: &mut dyn Simulated,
    integrator: Integrator,
    t0: f64,
    t_end: f64,
    output: Output,
    progress: &mut dyn FnMut(f64),
) -> Result<Results, SimulationFailure> {
    let mut results = Results::default();
    let (outcome, stats, checks) = drive(
        system,
        integrator,
        t0,
        t_end,
        &output,
        &mut results,
        progress,
    );
    results.stats = stats;
    results.checks = checks;
    match outcome {
        Ok(()) => Ok(results),
        Err(RunError::Simulation(error)) => Err(SimulationFailure { error, results }),
        // Fresh in-memory results take every row the run has checked
        // (its width is checked before the sink sees it): the one error
        // they could give is that width.
        Err(RunError::Sink { t, .. }) => Err(SimulationFailure {
            error: SimulationError::RecordWidth {
                t,
                got: results.columns().len(),
                expected: results.columns().len(),
            },
            results,
        }),
    }
}

/// The run: `sink.begin`, the set-up checks, then the steps and a row at
/// every output time. The caller finishes the sink.
pub(super) fn drive(
    system: &mut dyn Simulated,
    integrator: Integrator,
    t0: f64,
    t_end: f64,
    output: &Output,
    sink: &mut dyn Sink,
    progress: &mut dyn FnMut(f64),
) -> (Result<(), RunError>, Stats, Vec<Check>) {
    let columns = system.columns();
    if let Err(source) = sink.begin(&columns) {
        return (
            Err(RunError::Sink { t: t0, source }),
            Stats::default(),
            Vec::new(),
        );
    }
    let settings = validate(integrator, t0, t_end).and_then(|()| validate_output(t0, output));
    if let Err(error) = settings {
        return (
            Err(SimulationError::from(error).into()),
            Stats::default(),
            Vec::new(),
        );
    }
    let mut march = match March::start(system, integrator, t0, t_end) {
        Ok(march) => march,
        Err(error) => return (Err(error.into()), Stats::default(), Vec::new()),
    };
    let outcome = run(system, &mut march, output, sink, &columns, progress);
    let (stats, checks) = march.into_parts();
    (outcome, stats, checks)
}

fn run(
    system: &mut dyn Simulated,
    march: &mut March,
    output: &Output,
    sink: &mut dyn Sink,
    columns: &[String],
    progress: &mut dyn FnMut(f64),
) -> Result<(), RunError> {
    let width = columns.len();
    let mut row = Vec::with_capacity(width);
    // The columns the sink reads, if not every one: the system may leave
    // the rest unobserved.
    let wanted: Option<Vec<bool>> = sink.reads().map(|read| {
        let mut wanted = vec![false; width];
        for i in read {
            if let Some(w) = wanted.get_mut(i) {
                *w = true;
            }
        }
        wanted
    });
    let mut record = |system: &mut dyn Simulated, t: f64, y: &DVector<f64>, sink: &mut dyn Sink| {
        row.clear();
        match &wanted {
            Some(wanted) => system.observe_some(t, y.as_slice(), wanted, &mut row)?,
            None => system.observe(t, y.as_slice(), &mut row)?,
        }
        if row.len() != width {
            return Err(RunError::Simulation(SimulationError::RecordWidth {
                t,
                got: row.len(),
                expected: width,
            }));
        }
        // Every system's results hold numbers only; the state is finite
        // here (checked after each step), so a NaN is the observation's.
        let read = |i: &usize| wanted.as_ref().is_none_or(|w| w[*i]);
        if let Some(i) = (0..width).filter(read).find(|&i| !row[i].is_finite()) {
            return Err(RunError::Simulation(SimulationError::NonFiniteRecord {
                t,
                column: columns[i].clone(),
            }));
        }
        sink.row(t, &row)
            .map_err(|source| RunError::Sink { t, source })
    };
    let t0 = march.time();
    let eps = march.eps();
    let mut next = 0;
    if matches!(output, Output::Steps) {
        record(system, t0, march.state(), sink)?;
    }
    // Requested times before the start are skipped; one at the start is
    // the initial state.
    while let Some(to) = output.time(t0, next).filter(|&to| to <= t0 + eps) {
        if to >= t0 - eps {
            record(system, t0, march.state(), sink)?;
        }
        next += 1;
    }
    while !march.finished() {
        march.step(system)?;
        let (t_old, t) = (march.step_start(), march.time());
        while let Some(to) = output.time(t0, next).filter(|&to| to <= t + eps) {
            if to > t_old {
                let yo = march.state_at(to);
                record(system, to.min(t), &yo, sink)?;
            }
            next += 1;
        }
        let mut logged = Ok(());
        march.settle(system, &mut |switch| {
            if logged.is_ok() {
                logged = sink.switch(&switch);
            }
        })?;
        logged.map_err(|source| RunError::Sink { t, source })?;
        progress(t);
        // After `settle`: a projection shows in the step's row.
        if matches!(output, Output::Steps) {
            record(system, t, march.state(), sink)?;
        }
    }
    Ok(())
}
