//! A run advanced one accepted step at a time by its caller: the loop every
//! run ([`simulate`](super::simulate), [`simulate_into`](super::simulate_into))
//! makes, and what a co-simulation master drives (an FMU's `doStep`), so
//! that a run driven from outside takes the same steps as a native one.

use nalgebra::DVector;

use super::Output;
use crate::closure::Switch;
use crate::integrate::{
    Check, Integrator, OdeSystem, SettingsError, SimulationError, Stats, Stepper,
};
use crate::system::Simulated;

/// The integration of one run between its start and its end time: the
/// time, the state and the integrator's memory (step size, cached
/// derivatives, the stiffness checks).
///
/// The order of a step is fixed: [`step`](Self::step) (never past the end
/// time), then the outputs within it by dense output
/// ([`state_at`](Self::state_at)), then [`settle`](Self::settle) (the
/// system's [`after_step`](Simulated::after_step): re-partitioning,
/// projection). A caller that keeps that order takes, bit for bit, the
/// steps a native run takes.
pub struct March {
    stepper: Box<dyn Stepper>,
    t: f64,
    t_previous: f64,
    y: DVector<f64>,
    t_end: f64,
    eps: f64,
}

impl March {
    /// A run of `system` from its initial state at `t0` to `t_end` (s).
    /// Settings that would hang the run and a non-finite initial state are
    /// errors before any step.
    pub fn start(
        system: &dyn Simulated,
        integrator: Integrator,
        t0: f64,
        t_end: f64,
    ) -> Result<March, SimulationError> {
        March::from_state(integrator, system.initial_state(), t0, t_end)
    }

    /// A run of a system of `y.len()` states from `y` at `t0` to `t_end`
    /// (s): for a system that is no [`Simulated`] (a spatial vehicle, whose
    /// start is assembled on its course). The same checks as
    /// [`start`](Self::start)'s.
    pub fn from_state(
        integrator: Integrator,
        y: DVector<f64>,
        t0: f64,
        t_end: f64,
    ) -> Result<March, SimulationError> {
        validate(integrator, t0, t_end)?;
        if !y.iter().all(|v| v.is_finite()) {
            return Err(SimulationError::NonFinite {
                t: t0,
                what: "the initial state",
            });
        }
        Ok(March {
            stepper: integrator.stepper(y.len()),
            t: t0,
            t_previous: t0,
            y,
            t_end,
            // Times closer than this are the same time.
            eps: 1e-12 * t_end.abs().max(t0.abs()).max(1.0),
        })
    }

    /// The time reached, s.
    pub fn time(&self) -> f64 {
        self.t
    }

    /// The time the last step started from, s.
    pub fn step_start(&self) -> f64 {
        self.t_previous
    }

    /// The end time, s.
    pub fn end(&self) -> f64 {
        self.t_end
    }

    /// The state at [`time`](Self::time).
    pub fn state(&self) -> &DVector<f64> {
        &self.y
    }

    /// Two times this close are one time (s): `1e-12` of the run's
    /// largest time, at least `1e-12` s.
    pub fn eps(&self) -> f64 {
        self.eps
    }

    /// The run has reached its end time.
    pub fn finished(&self) -> bool {
        self.t >= self.t_end - self.eps
    }

    /// One accepted step, never past the end time (a step ending within
    /// [`eps`](Self::eps) of it ends on it). A non-finite state is an error
    /// at the step's end.
    pub fn step(&mut self, system: &mut dyn OdeSystem) -> Result<(), SimulationError> {
        self.t_previous = self.t;
        self.stepper
            .step(system, &mut self.t, &mut self.y, self.t_end)?;
        if !crate::integrate::all_finite(self.y.as_slice()) {
            return Err(SimulationError::NonFinite {
                t: self.t,
                what: "the state",
            });
        }
        if self.t >= self.t_end - self.eps {
            self.t = self.t_end;
        }
        Ok(())
    }

    /// The state at `t` within the last step (dense output; the state
    /// itself at its end).
    pub fn state_at(&self, t: f64) -> DVector<f64> {
        if (t - self.t).abs() <= self.eps {
            self.y.clone()
        } else {
            self.stepper.interpolate(t)
        }
    }

    /// After a step: the system's [`after_step`](Simulated::after_step),
    /// telling `switched` of every re-partitioning; the integrator
    /// restarts if it changed the state.
    pub fn settle(
        &mut self,
        system: &mut dyn Simulated,
        switched: &mut dyn FnMut(Switch),
    ) -> Result<(), SimulationError> {
        if system.after_step(self.t, self.y.as_mut_slice(), switched)? {
            self.stepper.restart();
        }
        Ok(())
    }

    /// The integrator restarts (its step size kept): for a system whose
    /// right-hand side changed between steps (a spatial vehicle's gearbox
    /// shifted), where [`settle`](Self::settle) is not its rule.
    pub fn restart(&mut self) {
        self.stepper.restart();
    }

    /// Goes on from the state `y` at `t` (s) instead, the integrator
    /// restarted (its step size kept): for a master that changed the
    /// system's inputs at `t`, within the last step, so the rest of the
    /// step taken with the old inputs is dropped.
    pub fn restart_at(&mut self, t: f64, y: DVector<f64>) {
        self.t = t;
        self.t_previous = t;
        self.y = y;
        self.stepper.restart();
    }

    /// The integrator's counters so far.
    pub fn stats(&self) -> Stats {
        self.stepper.stats()
    }

    /// The stiffness checks that chose the method so far.
    pub fn checks(&self) -> &[Check] {
        self.stepper.checks()
    }

    /// The run's integrator (for its counters when it failed to start).
    pub(super) fn into_parts(self) -> (Stats, Vec<Check>) {
        (self.stepper.stats(), self.stepper.checks().to_vec())
    }
}

/// Settings that would hang a run or make it meaningless are errors before
/// any step.
pub(super) fn validate(integrator: Integrator, t0: f64, t_end: f64) -> Result<(), SettingsError> {
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
    Ok(())
}

/// An output schedule that would hang a run or make it meaningless is an
/// error before any step.
pub(super) fn validate_output(t0: f64, output: &Output) -> Result<(), SettingsError> {
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
