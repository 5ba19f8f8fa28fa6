use nalgebra::DVector;

use super::hermite::HermiteStep;
use super::{OdeSystem, Stats, Stepper};
use crate::simulate::SimulationError;

/// Classical fourth-order Runge-Kutta with a fixed step. The slope at the
/// end of a step is the next step's first stage, so dense output (cubic
/// Hermite) costs nothing extra.
#[derive(Debug, Clone)]
pub struct Rk4 {
    h: f64,
    /// `f` at the current state, if still valid.
    f_now: Option<DVector<f64>>,
    last: HermiteStep,
    stats: Stats,
}

impl Rk4 {
    /// A stepper with step `h` (s) for `dimension` components.
    pub fn new(h: f64, dimension: usize) -> Self {
        Rk4 {
            h,
            f_now: None,
            last: HermiteStep::empty(dimension),
            stats: Stats::default(),
        }
    }

    fn eval(
        &mut self,
        system: &mut dyn OdeSystem,
        t: f64,
        y: &DVector<f64>,
    ) -> Result<DVector<f64>, SimulationError> {
        super::evaluate(system, &mut self.stats, t, y)
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
        // A last step shorter than h lands exactly on t_limit.
        let h = self.h.min(t_limit - *t);
        let k1 = match self.f_now.take() {
            Some(f) => f,
            None => self.eval(system, *t, y)?,
        };
        let k2 = self.eval(system, *t + 0.5 * h, &(&*y + &k1 * (0.5 * h)))?;
        let k3 = self.eval(system, *t + 0.5 * h, &(&*y + &k2 * (0.5 * h)))?;
        let k4 = self.eval(system, *t + h, &(&*y + &k3 * h))?;
        let y1 = &*y + (&k1 + &k2 * 2.0 + &k3 * 2.0 + &k4) * (h / 6.0);
        let f1 = self.eval(system, *t + h, &y1)?;
        self.last = HermiteStep {
            t0: *t,
            t1: *t + h,
            y0: y.clone(),
            y1: y1.clone(),
            f0: k1,
            f1: f1.clone(),
        };
        self.f_now = Some(f1);
        *t += h;
        *y = y1;
        self.stats.accepted += 1;
        Ok(())
    }

    fn interpolate(&self, t: f64) -> DVector<f64> {
        self.last.evaluate(t)
    }

    fn restart(&mut self) {
        self.f_now = None;
        self.stats.restarts += 1;
    }

    fn stats(&self) -> Stats {
        self.stats
    }
}
