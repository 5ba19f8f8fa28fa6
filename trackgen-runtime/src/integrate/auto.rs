//! How stiff a system is at a state, and an integrator that follows it:
//! Bogacki-Shampine while accuracy sets the step, ROS34PW2 while the
//! stiffest mode would (`Integrator::Auto`, the main job's `--integrator
//! auto`).
//!
//! The stiffness of a vehicle moves with its loads: the Marder assembled
//! at rest has its stiffest rate at 3.4e3 /s, settled on the ground at
//! 5.8e3 /s, and driving at 2 m/s at 1.2e4 /s (the idler spinning against
//! its rim's friction under the track's tension). So the choice is made at
//! the start and made again every [`CHECK_EVERY`] seconds of the run, and
//! after [`CHECK_AFTER_STEPS`] steps however short.

use nalgebra::DVector;

use super::{Check, Embedded, OdeSystem, Ros34pw2, Stats, Stepper};
use crate::integrate::SimulationError;

/// Power iterations of [`stiffest_rate`]: on the vehicles the estimate
/// settles within 1 % by 30 (their two stiffest rates 15 % apart), one
/// evaluation each.
pub const POWER_ITERATIONS: usize = 40;

/// The largest magnitude `|λ|` (1/s) among the eigenvalues of `∂f/∂y` at
/// `(t, y)`, over the components with dynamics (the quadratures, which
/// feed nothing back, left out): by power iteration on Jacobian-vector
/// products, each a forward difference of `f` along the iterate (of length
/// 1e-7 of the state's). On the Marder driving at 2 m/s it gives
/// 1.2058e4 /s, the eigen-decomposition of its Jacobian 1.2058e4.
pub fn stiffest_rate<S: OdeSystem + ?Sized>(
    system: &mut S,
    t: f64,
    y: &[f64],
) -> Result<f64, SimulationError> {
    let n = y.len();
    let live: Vec<bool> = (0..n).map(|i| !system.is_quadrature(i)).collect();
    let mut f0 = vec![0.0; n];
    system.derivative(t, y, &mut f0)?;
    // A start that excites every component, deterministic.
    let mut v: Vec<f64> = (0..n)
        .map(|i| {
            if live[i] {
                1.0 + 0.5 * ((i * 7919) % 13) as f64 / 13.0
            } else {
                0.0
            }
        })
        .collect();
    let norm = |v: &[f64]| v.iter().map(|x| x * x).sum::<f64>().sqrt();
    let epsilon = 1e-7 * norm(y).max(1.0);
    let (mut shifted, mut slope) = (vec![0.0; n], vec![0.0; n]);
    let mut rate = 0.0;
    for _ in 0..POWER_ITERATIONS {
        let length = norm(&v);
        if !(length > 0.0 && length.is_finite()) {
            break;
        }
        v.iter_mut().for_each(|x| *x /= length);
        for ((s, &y), &v) in shifted.iter_mut().zip(y).zip(&v) {
            *s = y + epsilon * v;
        }
        system.derivative(t, &shifted, &mut slope)?;
        for (i, ((w, &f), &f0)) in v.iter_mut().zip(&slope).zip(&f0).enumerate() {
            *w = if live[i] { (f - f0) / epsilon } else { 0.0 };
        }
        rate = norm(&v);
    }
    Ok(rate)
}

/// Bogacki-Shampine's step where accuracy alone sets it on a tracked
/// vehicle, s, at tolerance 1e-3: the M113's mean step on its main job
/// (0.74 ms; `examples/step_limit`: without its stiff modes the step does
/// not lengthen), scaled as `tol^(1/3)` (third order).
pub const ACCURACY_STEP_AT_1E_3: f64 = 0.74e-3;

/// Bogacki-Shampine's stability on the negative real axis, `|h λ| ≤ 2.51`.
pub const EXPLICIT_STABILITY: f64 = 2.51;

/// The stiffness ratio (Bogacki-Shampine's accuracy step over its stable
/// step) above which the linearly implicit method takes over. From the
/// costs measured on the Marder (`cargo bench -p trackgen-benches --bench
/// implicit`; docs/experiments/auto-integrator.md):
/// a ROS34PW2 step costs about 12 evaluations of `f` (4 of them, the
/// linearisation, the factorisation and 4 solves) and is 2.4 times
/// Bogacki-Shampine's accuracy step (1.8 ms against 0.74 ms), so it costs
/// 5 evaluations per accuracy step where Bogacki-Shampine, held to its
/// stable step, costs 3 × the ratio: ROS34PW2 wins above 5/3.
pub const IMPLICIT_ABOVE: f64 = 1.6;

/// The ratio below which the explicit method takes over again (hysteresis
/// against switching back and forth on a ratio near [`IMPLICIT_ABOVE`]).
pub const EXPLICIT_BELOW: f64 = 1.3;

/// Seconds of simulated time between two checks of the stiffness.
pub const CHECK_EVERY: f64 = 1.0;

/// Steps after which the stiffness is checked again, however little time
/// they took: a problem that turns stiff between two checks makes the
/// explicit method's steps tiny, and is caught this many steps in.
pub const CHECK_AFTER_STEPS: u64 = 2000;

/// The stiffness ratio at `(t, y)`: Bogacki-Shampine's accuracy step at
/// `tolerance` over the step its stability allows, with the stiffest rate.
pub fn stiffness_ratio<S: OdeSystem + ?Sized>(
    system: &mut S,
    (t, y): (f64, &[f64]),
    tolerance: f64,
) -> Result<(f64, f64), SimulationError> {
    let stiffest = stiffest_rate(system, t, y)?;
    let accuracy_step = ACCURACY_STEP_AT_1E_3 * (tolerance / 1e-3).cbrt();
    Ok((accuracy_step * stiffest / EXPLICIT_STABILITY, stiffest))
}

/// Bogacki-Shampine or ROS34PW2, whichever the stiffness calls for,
/// checked at the start, every [`CHECK_EVERY`] s and every
/// [`CHECK_AFTER_STEPS`] steps ([`Check`]s kept).
/// A switch restarts the method taking over (as after a re-partition).
pub struct Auto {
    explicit: Embedded,
    implicit: Ros34pw2,
    explicit_tolerance: f64,
    /// Whether the implicit method runs now, and made the last step.
    using_implicit: bool,
    last_implicit: bool,
    next_check: f64,
    /// Accepted steps at the last check.
    checked_at_step: u64,
    checks: Vec<Check>,
    /// Evaluations of the stiffness checks.
    probes: u64,
}

impl Auto {
    /// Bogacki-Shampine at `explicit_tolerance` and ROS34PW2 at
    /// `implicit_tolerance` (relative and absolute alike), steps up to
    /// `max_step` (s), for `dimension` components.
    pub fn new(
        explicit_tolerance: f64,
        implicit_tolerance: f64,
        max_step: f64,
        dimension: usize,
    ) -> Auto {
        Auto {
            explicit: Embedded::bogacki_shampine(
                explicit_tolerance,
                explicit_tolerance,
                max_step,
                dimension,
            ),
            implicit: Ros34pw2::new(implicit_tolerance, implicit_tolerance, max_step, dimension),
            explicit_tolerance,
            using_implicit: false,
            last_implicit: false,
            next_check: f64::NEG_INFINITY,
            checked_at_step: 0,
            checks: Vec::new(),
            probes: 0,
        }
    }

    /// Checks the stiffness at `(t, y)` and switches if it calls for the
    /// other method. A state where the check cannot evaluate keeps the
    /// method running.
    fn check(&mut self, system: &mut dyn OdeSystem, t: f64, y: &DVector<f64>) {
        self.next_check = t + CHECK_EVERY;
        self.checked_at_step = self.stats().accepted;
        let before = self.probes;
        self.probes += POWER_ITERATIONS as u64 + 1;
        let Ok((ratio, stiffest)) =
            stiffness_ratio(system, (t, y.as_slice()), self.explicit_tolerance)
        else {
            self.probes = before;
            return;
        };
        let implicit = if self.using_implicit {
            ratio >= EXPLICIT_BELOW
        } else {
            ratio > IMPLICIT_ABOVE
        };
        if implicit != self.using_implicit || self.checks.is_empty() {
            if implicit {
                self.implicit.restart();
            } else {
                self.explicit.restart();
            }
        }
        self.using_implicit = implicit;
        self.checks.push(Check {
            t,
            stiffest,
            ratio,
            implicit,
        });
    }
}

impl Stepper for Auto {
    fn step(
        &mut self,
        system: &mut dyn OdeSystem,
        t: &mut f64,
        y: &mut DVector<f64>,
        t_limit: f64,
    ) -> Result<(), SimulationError> {
        if *t >= self.next_check
            || self.stats().accepted >= self.checked_at_step + CHECK_AFTER_STEPS
        {
            self.check(system, *t, y);
        }
        self.last_implicit = self.using_implicit;
        if self.using_implicit {
            self.implicit.step(system, t, y, t_limit)
        } else {
            self.explicit.step(system, t, y, t_limit)
        }
    }

    fn interpolate(&self, t: f64) -> DVector<f64> {
        if self.last_implicit {
            self.implicit.interpolate(t)
        } else {
            self.explicit.interpolate(t)
        }
    }

    fn restart(&mut self) {
        if self.using_implicit {
            self.implicit.restart();
        } else {
            self.explicit.restart();
        }
    }

    fn stats(&self) -> Stats {
        let (e, i) = (self.explicit.stats(), self.implicit.stats());
        Stats {
            evaluations: e.evaluations + i.evaluations + self.probes,
            accepted: e.accepted + i.accepted,
            rejected: e.rejected + i.rejected,
            restarts: e.restarts + i.restarts,
            implicit: i.accepted,
        }
    }

    fn checks(&self) -> &[Check] {
        &self.checks
    }
}
