//! What the fixed-step methods share: the step, the slope carried from one
//! step to the next, and cubic Hermite dense output over the last step.

use nalgebra::DVector;

use super::{OdeSystem, Stats};
use crate::integrate::SimulationError;

/// A step's end points and slopes, for cubic Hermite dense output (third
/// order, enough for output between fixed steps).
#[derive(Debug, Clone)]
struct HermiteStep {
    t0: f64,
    t1: f64,
    y0: DVector<f64>,
    y1: DVector<f64>,
    f0: DVector<f64>,
    f1: DVector<f64>,
}

impl HermiteStep {
    fn evaluate(&self, t: f64) -> DVector<f64> {
        let h = self.t1 - self.t0;
        if h == 0.0 {
            return self.y1.clone();
        }
        let s = (t - self.t0) / h;
        let (s2, s3) = (s * s, s * s * s);
        let h00 = 2.0 * s3 - 3.0 * s2 + 1.0;
        let h10 = s3 - 2.0 * s2 + s;
        let h01 = -2.0 * s3 + 3.0 * s2;
        let h11 = s3 - s2;
        &self.y0 * h00 + &self.f0 * (h10 * h) + &self.y1 * h01 + &self.f1 * (h11 * h)
    }
}

/// The state of a fixed-step method between steps.
#[derive(Debug, Clone)]
pub(crate) struct FixedStep {
    pub h: f64,
    /// Whether `slope` holds `f` at the current state (the next step's
    /// first slope, so dense output costs nothing extra).
    f_now: bool,
    /// `f` at the current state, once [`start`](Self::start) has run.
    pub slope: DVector<f64>,
    last: HermiteStep,
    pub stats: Stats,
}

impl FixedStep {
    pub fn new(h: f64, dimension: usize) -> Self {
        let z = DVector::zeros(dimension);
        FixedStep {
            h,
            f_now: false,
            slope: z.clone(),
            last: HermiteStep {
                t0: 0.0,
                t1: 0.0,
                y0: z.clone(),
                y1: z.clone(),
                f0: z.clone(),
                f1: z,
            },
            stats: Stats::default(),
        }
    }

    /// `f(t, y)` into `out`, counted and checked.
    pub fn eval(
        &mut self,
        system: &mut dyn OdeSystem,
        t: f64,
        y: &DVector<f64>,
        out: &mut DVector<f64>,
    ) -> Result<(), SimulationError> {
        super::evaluate(system, &mut self.stats, t, y, out)
    }

    /// Makes [`slope`](Self::slope) the slope at the step's start: carried
    /// over, or evaluated.
    pub fn start(
        &mut self,
        system: &mut dyn OdeSystem,
        t: f64,
        y: &DVector<f64>,
    ) -> Result<(), SimulationError> {
        if !self.f_now {
            super::evaluate(system, &mut self.stats, t, y, &mut self.slope)?;
            self.f_now = true;
        }
        Ok(())
    }

    /// Accepts the step `(t, y) → (t + h, y1)`, whose start's slope is
    /// [`slope`](Self::slope): evaluates the slope at its end, keeps both
    /// for dense output, and moves `(t, y)` on.
    pub fn finish(
        &mut self,
        system: &mut dyn OdeSystem,
        (t, y): (&mut f64, &mut DVector<f64>),
        (h, y1): (f64, &DVector<f64>),
    ) -> Result<(), SimulationError> {
        super::evaluate(system, &mut self.stats, *t + h, y1, &mut self.last.f1)?;
        self.last.t0 = *t;
        self.last.t1 = *t + h;
        self.last.y0.copy_from(y);
        self.last.y1.copy_from(y1);
        std::mem::swap(&mut self.last.f0, &mut self.slope);
        self.slope.copy_from(&self.last.f1);
        *t += h;
        y.copy_from(y1);
        self.stats.accepted += 1;
        Ok(())
    }

    pub fn interpolate(&self, t: f64) -> DVector<f64> {
        self.last.evaluate(t)
    }

    pub fn restart(&mut self) {
        self.f_now = false;
        self.stats.restarts += 1;
    }
}
