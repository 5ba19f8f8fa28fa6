use nalgebra::DVector;

use super::fixed_step::FixedStep;
use super::{OdeSystem, Stats, Stepper};
use crate::integrate::SimulationError;

/// Classical fourth-order Runge-Kutta with a fixed step. The slope at the
/// end of a step is the next step's first stage, so dense output (cubic
/// Hermite) costs nothing extra. A step allocates nothing.
#[derive(Debug, Clone)]
pub struct Rk4 {
    state: FixedStep,
    /// Stages 2 to 4, the stage argument, and the solution.
    k: [DVector<f64>; 3],
    argument: DVector<f64>,
    solution: DVector<f64>,
}

impl Rk4 {
    /// A stepper with step `h` (s) for `dimension` components.
    pub fn new(h: f64, dimension: usize) -> Self {
        let z = DVector::zeros(dimension);
        Rk4 {
            state: FixedStep::new(h, dimension),
            k: [z.clone(), z.clone(), z.clone()],
            argument: z.clone(),
            solution: z,
        }
    }
}

impl Stepper for Rk4 {
    fn step(
        &mut self,
        system: &mut dyn OdeSystem,
        t: &mut f64,
        y: &mut DVector<f64>,
        t_limit: f64,
    ) -> Result<(), SimulationError> {
        let Rk4 {
            state: s,
            k: [k2, k3, k4],
            argument,
            solution,
        } = self;
        // A last step shorter than h lands exactly on t_limit.
        let h = s.h.min(t_limit - *t);
        s.start(system, *t, y)?;
        argument.copy_from(y);
        argument.axpy(0.5 * h, &s.slope, 1.0);
        s.eval(system, *t + 0.5 * h, argument, k2)?;
        argument.copy_from(y);
        argument.axpy(0.5 * h, k2, 1.0);
        s.eval(system, *t + 0.5 * h, argument, k3)?;
        argument.copy_from(y);
        argument.axpy(h, k3, 1.0);
        s.eval(system, *t + h, argument, k4)?;
        solution.copy_from(y);
        solution.axpy(h / 6.0, &s.slope, 1.0);
        solution.axpy(h / 3.0, k2, 1.0);
        solution.axpy(h / 3.0, k3, 1.0);
        solution.axpy(h / 6.0, k4, 1.0);
        s.finish(system, (t, y), (h, solution))
    }

    fn interpolate(&self, t: f64) -> DVector<f64> {
        self.state.interpolate(t)
    }

    fn restart(&mut self) {
        self.state.restart();
    }

    fn stats(&self) -> Stats {
        self.state.stats
    }
}
