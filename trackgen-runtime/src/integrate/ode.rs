//! What a system offers a method, and what a method offers a run: the
//! contract between the systems (`y' = f(t, y)`, optionally with their
//! own linear solves) and the integrators.

use nalgebra::DVector;

use super::SimulationError;

/// A first-order system `y' = f(t, y)` whose evaluation may fail (a
/// failed Newton-Raphson recovery, a singular matrix, a non-finite value).
///
/// States are plain slices, so a system made of subsystems hands each its
/// part of `y` and `dy` without copying.
pub trait OdeSystem {
    /// Length of `y`.
    fn dimension(&self) -> usize;

    /// Writes `f(t, y)` into `dy` (both of length
    /// [`dimension`](Self::dimension)). An error rejects the step in an
    /// adaptive integrator (which retries a shorter one) and ends the run
    /// in a fixed-step one.
    fn derivative(&mut self, t: f64, y: &[f64], dy: &mut [f64]) -> Result<(), SimulationError>;

    /// Whether component `i` feeds nothing back: a running integral such as
    /// the energy books, which no other component's rate reads. A linearly
    /// implicit method leaves such components out of its Jacobian (their
    /// rows may be large or kinked where a dissipation law switches branch,
    /// and would only spoil their own quadrature) and integrates them with
    /// its stages' explicit weights. None by default.
    fn is_quadrature(&self, i: usize) -> bool {
        let _ = i;
        false
    }

    /// Whether component `i` is a passive quadrature: a figure derived
    /// from the state (the engine's work, behind the converter) whose
    /// accuracy follows the steps the rest asks, left out of the step's
    /// error and every other norm, so that recording it changes no
    /// answer. A passive component is a quadrature too. None by default.
    fn is_passive(&self, i: usize) -> bool {
        let _ = i;
        false
    }

    /// Writes `∂f/∂y` at `(t, y)` (whose `f` is `slope`) into `jacobian`,
    /// column-major, and returns `true`; or returns `false` (the default)
    /// and leaves it to the integrator's differences. Only the linearly
    /// implicit methods ask.
    fn jacobian(
        &mut self,
        t: f64,
        y: &[f64],
        slope: &[f64],
        jacobian: &mut [f64],
    ) -> Result<bool, SimulationError> {
        let _ = (t, y, slope, jacobian);
        Ok(false)
    }

    /// The system's own linear solves for a linearly implicit method, if
    /// it has them at its current settings ([`ImplicitSolve`]); `None`
    /// (the default) leaves the method to a Jacobian and a dense
    /// factorisation.
    fn implicit(&mut self) -> Option<&mut dyn ImplicitSolve> {
        None
    }
}

/// A system's own linear solves for a linearly implicit method:
/// `(I − a W) x = b` for a matrix `W` the system chooses, built from its
/// structure instead of a dense Jacobian. A Rosenbrock-W method
/// ([`Ros34pw2`](super::Ros34pw2)) keeps its order for any `W`; a `W` that holds the
/// system's stiff modes keeps it stable at steps far beyond them.
pub trait ImplicitSolve {
    /// Takes `W` at `(t, y)`.
    fn linearise(&mut self, t: f64, y: &[f64]) -> Result<(), SimulationError>;

    /// Factors `I − a W` for the shift `a` (s) at the last linearisation.
    fn factor(&mut self, t: f64, a: f64) -> Result<(), SimulationError>;

    /// Solves `(I − a W) x = b` in place (`b` in, `x` out), with the last
    /// factorisation.
    fn solve(&mut self, t: f64, b: &mut [f64]) -> Result<(), SimulationError>;
}

/// `f(t, y)` into `dy`, counted, with `y` and `f` checked for NaN or
/// infinite components.
pub(crate) fn evaluate(
    system: &mut dyn OdeSystem,
    stats: &mut Stats,
    t: f64,
    y: &DVector<f64>,
    dy: &mut DVector<f64>,
) -> Result<(), SimulationError> {
    // One check for every system: a NaN stage state is this integrator's
    // business (a rejected step), not each right-hand side's.
    if !all_finite(y.as_slice()) {
        return Err(SimulationError::NonFinite {
            t,
            what: "the state",
        });
    }
    stats.evaluations += 1;
    system.derivative(t, y.as_slice(), dy.as_mut_slice())?;
    if all_finite(dy.as_slice()) {
        Ok(())
    } else {
        Err(SimulationError::NonFinite {
            t,
            what: "the derivative",
        })
    }
}

/// Whether every value is finite: `v − v` is 0 for a finite `v` and NaN for
/// an infinity or a NaN, so their sum is 0 exactly when all are. Summed in
/// four lanes without early exit, so it vectorises.
// `v − v` is meant: 0 for a finite `v`, NaN otherwise.
#[allow(clippy::eq_op)]
pub(crate) fn all_finite(values: &[f64]) -> bool {
    let mut lanes = [0.0f64; 4];
    let chunks = values.chunks_exact(4);
    let rest = chunks.remainder();
    for chunk in chunks {
        for (lane, v) in lanes.iter_mut().zip(chunk) {
            *lane += v - v;
        }
    }
    let total = rest
        .iter()
        .fold(lanes.iter().sum::<f64>(), |t, v| t + (v - v));
    total == 0.0
}

/// Counters of an integration.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct Stats {
    /// Evaluations of `f`.
    pub evaluations: u64,
    /// Accepted steps.
    pub accepted: u64,
    /// Rejected steps (error too large, or `f` failed).
    pub rejected: u64,
    /// Restarts after the state was changed between steps.
    pub restarts: u64,
    /// Accepted steps made by a linearly implicit method (all of a
    /// Rosenbrock run's; those after a switch of an [`Auto`](super::Auto) run).
    pub implicit: u64,
}

/// A one-step method driven step by step.
pub trait Stepper {
    /// Advances `(t, y)` by one accepted step, never past `t_limit`.
    fn step(
        &mut self,
        system: &mut dyn OdeSystem,
        t: &mut f64,
        y: &mut DVector<f64>,
        t_limit: f64,
    ) -> Result<(), SimulationError>;

    /// `y(t)` for `t` within the last accepted step (dense output).
    fn interpolate(&self, t: f64) -> DVector<f64>;

    /// Forgets cached derivatives: the state was changed between steps.
    fn restart(&mut self);

    /// Counters so far.
    fn stats(&self) -> Stats;

    /// The stiffness checks that chose the method ([`Auto`](super::Auto)); none for a
    /// fixed method.
    fn checks(&self) -> &[Check] {
        &[]
    }
}

/// A stiffness check of an [`Auto`](super::Auto) run.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Check {
    /// When, s.
    pub t: f64,
    /// The stiffest rate, 1/s.
    pub stiffest: f64,
    /// The stiffness ratio ([`stiffness_ratio`](super::auto::stiffness_ratio)).
    pub ratio: f64,
    /// Whether the linearly implicit method runs from here.
    pub implicit: bool,
}
