use nalgebra::DVector;

use super::{Output, Results, RunError, SimulationFailure, Sink};
use crate::integrate::{Check, Integrator, SettingsError, SimulationError, Stats};
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
    if let Err(error) = validate(integrator, t0, t_end, output) {
        return (
            Err(SimulationError::from(error).into()),
            Stats::default(),
            Vec::new(),
        );
    }
    let mut stepper = integrator.stepper(system.dimension());
    let outcome = run(
        system,
        stepper.as_mut(),
        t0,
        t_end,
        output,
        sink,
        &columns,
        progress,
    );
    (outcome, stepper.stats(), stepper.checks().to_vec())
}

#[allow(clippy::too_many_arguments)]
fn run(
    system: &mut dyn Simulated,
    stepper: &mut dyn crate::integrate::Stepper,
    t0: f64,
    t_end: f64,
    output: &Output,
    sink: &mut dyn Sink,
    columns: &[String],
    progress: &mut dyn FnMut(f64),
) -> Result<(), RunError> {
    let width = columns.len();
    let mut row = Vec::with_capacity(width);
    let mut record = |system: &mut dyn Simulated, t: f64, y: &DVector<f64>, sink: &mut dyn Sink| {
        row.clear();
        system.observe(t, y.as_slice(), &mut row)?;
        if row.len() != width {
            return Err(RunError::Simulation(SimulationError::RecordWidth {
                t,
                got: row.len(),
                expected: width,
            }));
        }
        // Every system's results hold numbers only; the state is finite
        // here (checked after each step), so a NaN is the observation's.
        if let Some(i) = row.iter().position(|v| !v.is_finite()) {
            return Err(RunError::Simulation(SimulationError::NonFiniteRecord {
                t,
                column: columns[i].clone(),
            }));
        }
        sink.row(t, &row)
            .map_err(|source| RunError::Sink { t, source })
    };
    let mut t = t0;
    let mut y = system.initial_state();
    if !y.iter().all(|v| v.is_finite()) {
        return Err(SimulationError::NonFinite {
            t,
            what: "the initial state",
        }
        .into());
    }
    // Times closer than this are the same time.
    let eps = 1e-12 * t_end.abs().max(t0.abs()).max(1.0);
    let mut next = 0;
    if matches!(output, Output::Steps) {
        record(system, t, &y, sink)?;
    }
    // Requested times before the start are skipped; one at the start is
    // the initial state.
    while let Some(to) = output.time(t0, next).filter(|&to| to <= t0 + eps) {
        if to >= t0 - eps {
            record(system, t, &y, sink)?;
        }
        next += 1;
    }
    while t < t_end - eps {
        let t_old = t;
        stepper.step(system, &mut t, &mut y, t_end)?;
        if !crate::integrate::all_finite(y.as_slice()) {
            return Err(SimulationError::NonFinite {
                t,
                what: "the state",
            }
            .into());
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
                record(system, to.min(t), &yo, sink)?;
            }
            next += 1;
        }
        let mut logged = Ok(());
        let changed = system.after_step(t, y.as_mut_slice(), &mut |switch| {
            if logged.is_ok() {
                logged = sink.switch(&switch);
            }
        })?;
        logged.map_err(|source| RunError::Sink { t, source })?;
        if changed {
            stepper.restart();
        }
        progress(t);
        // After `after_step`: a projection shows in the step's row.
        if matches!(output, Output::Steps) {
            record(system, t, &y, sink)?;
        }
    }
    Ok(())
}

/// Settings that would hang a run or make it meaningless are errors before
/// any step.
fn validate(
    integrator: Integrator,
    t0: f64,
    t_end: f64,
    output: &Output,
) -> Result<(), SettingsError> {
    if !(t0.is_finite() && t_end.is_finite() && t0 < t_end) {
        return Err(SettingsError::Interval { t0, t_end });
    }
    match integrator {
        Integrator::Rk4 { step } | Integrator::Rosenbrock2 { step } => {
            if !(step.is_finite() && step > 0.0 && t0 + step > t0) {
                return Err(SettingsError::Step { step });
            }
        }
        Integrator::Dopri5 {
            rtol,
            atol,
            max_step,
        }
        | Integrator::Bs23 {
            rtol,
            atol,
            max_step,
        }
        | Integrator::Ros34pw2 {
            rtol,
            atol,
            max_step,
        } => {
            if !(rtol >= 0.0
                && atol >= 0.0
                && rtol + atol > 0.0
                && rtol.is_finite()
                && atol.is_finite())
            {
                return Err(SettingsError::Tolerances { rtol, atol });
            }
            if max_step.is_nan() || max_step <= 0.0 {
                return Err(SettingsError::MaxStep { max_step });
            }
        }
        Integrator::Auto {
            explicit_tolerance,
            implicit_tolerance,
            max_step,
        } => {
            // Each is its method's relative and absolute tolerance at once,
            // so each must be positive on its own.
            for (name, value) in [
                ("explicit_tolerance", explicit_tolerance),
                ("implicit_tolerance", implicit_tolerance),
            ] {
                if !(value > 0.0 && value.is_finite()) {
                    return Err(SettingsError::Tolerance { name, value });
                }
            }
            if max_step.is_nan() || max_step <= 0.0 {
                return Err(SettingsError::MaxStep { max_step });
            }
        }
    }
    match output {
        Output::Every(dt) if !(dt.is_finite() && *dt > 0.0 && t0 + dt > t0) => {
            Err(SettingsError::OutputInterval { interval: *dt })
        }
        Output::Times(times)
            if !times.iter().all(|t| t.is_finite()) || times.windows(2).any(|w| w[1] < w[0]) =>
        {
            Err(SettingsError::OutputTimes)
        }
        _ => Ok(()),
    }
}
