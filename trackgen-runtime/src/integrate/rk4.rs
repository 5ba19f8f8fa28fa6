use nalgebra::DVector;

use super::fixed_step::FixedStep;
use super::{OdeSystem, Stats, Stepper};
use crate::error::SimulationError;

/// Classical fourth-order Runge-Kutta with a fixed step. The slope at the
/// end of a step is the next step's first stage, so dense output (cubic
/// Hermite) costs nothing extra.
#[derive(Debug, Clone)]
pub struct Rk4 {
    state: FixedStep,
}

impl Rk4 {
    /// A stepper with step `h` (s) for `dimension` components.
    pub fn new(h: f64, dimension: usize) -> Self {
        Rk4 {
            state: FixedStep::new(h, dimension),
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
        let s = &mut self.state;
        // A last step shorter than h lands exactly on t_limit.
        let h = s.h.min(t_limit - *t);
        let k1 = s.start(system, *t, y)?;
        let k2 = s.eval(system, *t + 0.5 * h, &(&*y + &k1 * (0.5 * h)))?;
        let k3 = s.eval(system, *t + 0.5 * h, &(&*y + &k2 * (0.5 * h)))?;
        let k4 = s.eval(system, *t + h, &(&*y + &k3 * h))?;
        let y1 = &*y + (&k1 + &k2 * 2.0 + &k3 * 2.0 + &k4) * (h / 6.0);
        s.finish(system, (t, y), (h, y1, k1))
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
