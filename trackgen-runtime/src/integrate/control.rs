//! The step-size control the adaptive methods share: the step to try, its
//! growth after an accepted step (Gustafsson's PI controller, as in
//! Hairer's DOPRI5) and its cut after a rejected one, and the underflow
//! that ends a run.

use crate::integrate::SimulationError;

const SAFETY: f64 = 0.9;
/// PI controller: `β = 0.04`, `α = 1/(q+1) − 0.75 β` (Hairer's DOPRI5).
const BETA: f64 = 0.04;
const MIN_FACTOR: f64 = 0.2;
const MAX_FACTOR: f64 = 5.0;
/// A step whose right-hand side failed is retried this much shorter.
const FAILURE_FACTOR: f64 = 0.25;

/// The step of an adaptive method between its attempts.
#[derive(Debug, Clone)]
pub(crate) struct StepControl {
    /// The next step to try, s; 0 until the method picks a first one.
    pub h: f64,
    /// Largest step, s.
    pub max_step: f64,
    /// Order `q` of the error estimate: the error scales as `h^(q+1)`.
    error_order: f64,
    /// The last accepted step's error norm, for PI control.
    previous_error: f64,
}

impl StepControl {
    pub fn new(max_step: f64, error_order: f64) -> Self {
        StepControl {
            h: 0.0,
            max_step,
            error_order,
            previous_error: 1e-4,
        }
    }

    /// The step to try from `t`, never past `t_limit`; an underflow error if
    /// it is too short to move `t`.
    pub fn next(&self, t: f64, t_limit: f64) -> Result<f64, SimulationError> {
        let h = self.h.min(self.max_step).min(t_limit - t);
        if h <= 1e-14 * t.abs().max(1.0) {
            return Err(SimulationError::StepSizeUnderflow {
                t,
                step: h,
                cause: None,
            });
        }
        Ok(h)
    }

    /// After accepting a step `h` whose error norm is `err` (≤ 1): the
    /// previous error damps the step's growth, which keeps a step limited
    /// by stability from being rejected every other time; after a rejection
    /// in the same call the step does not grow at once.
    pub fn accept(&mut self, h: f64, err: f64, rejected_last: bool) {
        let err = err.max(1e-10);
        let alpha = 1.0 / (self.error_order + 1.0) - 0.75 * BETA;
        let factor = (SAFETY * err.powf(-alpha) * self.previous_error.powf(BETA))
            .clamp(MIN_FACTOR, MAX_FACTOR);
        self.previous_error = err.max(1e-4);
        self.h = h * if rejected_last {
            factor.min(1.0)
        } else {
            factor
        };
    }

    /// After rejecting a step `h` from `t`: its error norm was too large
    /// (`Ok`), or the attempt failed (`Err`: a failed Newton-Raphson, a
    /// non-finite value, a singular matrix), and a step too short to try
    /// again returns that failure as an underflow's cause.
    pub fn reject(
        &mut self,
        t: f64,
        h: f64,
        outcome: Result<f64, SimulationError>,
    ) -> Result<(), SimulationError> {
        match outcome {
            Ok(err) => {
                let factor = if err.is_finite() {
                    (SAFETY * err.powf(-1.0 / (self.error_order + 1.0))).clamp(MIN_FACTOR, 1.0)
                } else {
                    MIN_FACTOR
                };
                self.h = h * factor;
                Ok(())
            }
            Err(cause) => {
                self.h = h * FAILURE_FACTOR;
                if self.h <= 1e-14 * t.abs().max(1.0) {
                    return Err(SimulationError::StepSizeUnderflow {
                        t,
                        step: self.h,
                        cause: Some(Box::new(cause)),
                    });
                }
                Ok(())
            }
        }
    }
}
