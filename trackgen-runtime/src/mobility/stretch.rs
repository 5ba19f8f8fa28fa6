//! A stretch of a 3-D run watched ([`watch`]): the turning and cornering
//! events judge a turn by its averages over stretches of a few seconds,
//! each quantity integrated over the steps' lengths (the rectangle rule at
//! each step's end) and divided by the stretch's span.

use nalgebra::DVector;

use super::EventError;
use crate::integrate::{SimulationError, Stepper};
use crate::spatial_vehicle::SpatialSimulated;

/// What a stretch of a run showed: its span, the distance travelled and
/// the heading's change over it (totals), and each side's means.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct Stretch {
    /// Its span, s.
    pub span: f64,
    /// The distance the centre of mass travelled over the ground, m.
    pub travelled: f64,
    /// The heading's change, rad (left positive).
    pub turned: f64,
    /// The belts' mean speeds (right, left), m/s.
    pub belts: [f64; 2],
    /// The sprockets' mean torques (right, left), N m, planar sense.
    pub torques: [f64; 2],
    /// The sprockets' mean powers (right, left), W.
    pub powers: [f64; 2],
}

impl Stretch {
    /// The centre of mass's mean horizontal speed, m/s.
    pub fn speed(&self) -> f64 {
        self.travelled / self.span
    }

    /// The mean yaw rate, rad/s: the heading's change over the span.
    pub fn yaw_rate(&self) -> f64 {
        self.turned / self.span
    }

    /// The path's radius, m: the distance travelled over the heading's
    /// change (infinite on a straight path).
    pub fn radius(&self) -> f64 {
        self.travelled / self.turned.abs()
    }
}

/// One step of `system` by `stepper` from `(t, y)` toward `end`, then
/// the system's [`after_step`](SpatialSimulated::after_step) (the soil
/// pressed, the gearbox's rule), the stepper restarted where it changed
/// the right-hand side: every 3-D event's step. A step that fails is
/// `failed`'s error at the time it failed.
pub(super) fn advance<S: SpatialSimulated>(
    system: &mut S,
    stepper: &mut dyn Stepper,
    (t, y): (&mut f64, &mut DVector<f64>),
    end: f64,
    failed: &impl Fn(f64, SimulationError) -> EventError,
) -> Result<(), EventError> {
    stepper.step(system, t, y, end).map_err(|e| failed(*t, e))?;
    if system.after_step(*t, y.as_slice()) {
        stepper.restart();
    }
    Ok(())
}

/// [`advance`] until `end`.
pub(super) fn run_to<S: SpatialSimulated>(
    system: &mut S,
    stepper: &mut dyn Stepper,
    (t, y): (&mut f64, &mut DVector<f64>),
    end: f64,
    failed: &impl Fn(f64, SimulationError) -> EventError,
) -> Result<(), EventError> {
    while *t < end {
        advance(system, stepper, (&mut *t, &mut *y), end, failed)?;
    }
    Ok(())
}

/// `system` run by `stepper` from `(t, y)` over `window` s, watched: its
/// heading before and after, and each step's quantities times the step's
/// length. A step or an output that fails is `failed`'s error at the
/// time it failed.
pub(super) fn watch<S: SpatialSimulated>(
    system: &mut S,
    stepper: &mut dyn Stepper,
    (t, y): (&mut f64, &mut DVector<f64>),
    window: f64,
    failed: &impl Fn(f64, SimulationError) -> EventError,
) -> Result<Stretch, EventError> {
    let (start, end) = (*t, *t + window);
    let heading = system
        .outputs(*t, y.as_slice())
        .map_err(|e| failed(*t, e))?
        .heading;
    let mut stretch = Stretch {
        span: 0.0,
        travelled: 0.0,
        turned: 0.0,
        belts: [0.0; 2],
        torques: [0.0; 2],
        powers: [0.0; 2],
    };
    while *t < end {
        let was = *t;
        advance(system, stepper, (t, y), end, failed)?;
        let dt = *t - was;
        let out = system
            .outputs(*t, y.as_slice())
            .map_err(|e| failed(*t, e))?;
        stretch.travelled += dt * out.centre.velocity.xy().norm();
        for s in 0..2 {
            stretch.belts[s] += dt * out.sides[s].belt_speed;
            stretch.torques[s] += dt * out.sides[s].sprocket_torque;
            stretch.powers[s] += dt * out.sides[s].sprocket_power;
        }
        stretch.turned = out.heading - heading;
    }
    stretch.span = *t - start;
    for s in 0..2 {
        stretch.belts[s] /= stretch.span;
        stretch.torques[s] /= stretch.span;
        stretch.powers[s] /= stretch.span;
    }
    Ok(stretch)
}
