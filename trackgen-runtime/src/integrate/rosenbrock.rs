use nalgebra::{DMatrix, DVector};

use super::differences::forward_jacobian;
use super::fixed_step::FixedStep;
use super::{OdeSystem, Stats, Stepper};
use crate::integrate::SimulationError;

/// `γ = 1 + 1/√2` of ROS2.
const GAMMA: f64 = 1.0 + std::f64::consts::FRAC_1_SQRT_2;

/// ROS2 (Verwer, Spee, Blom & Hundsdorfer, SIAM J. Sci. Comput. 20, 1999),
/// a two-stage linearly implicit (Rosenbrock-W) method:
///
/// ```text
/// (I − γ h J) k₁ = f(tₙ, yₙ)
/// (I − γ h J) k₂ = f(tₙ + h, yₙ + h k₁) − 2 k₁
/// yₙ₊₁ = yₙ + h (3/2 k₁ + 1/2 k₂)
/// ```
///
/// L-stable, and second order for *any* matrix `J`, so the Jacobian is
/// taken by forward differences once per step. Fixed step. Each step costs
/// `dimension + 2` evaluations of `f` and one LU factorisation (its
/// matrices are allocated per step, a small cost beside those): it pays off
/// when the stiffest mode (contact, penalty springs) forces an explicit
/// method to steps far below the accuracy the motion needs.
#[derive(Debug, Clone)]
pub struct Rosenbrock2 {
    state: FixedStep,
}

impl Rosenbrock2 {
    /// A stepper with step `h` (s) for `dimension` components.
    pub fn new(h: f64, dimension: usize) -> Self {
        Rosenbrock2 {
            state: FixedStep::new(h, dimension),
        }
    }

    /// `∂f/∂y` by forward differences.
    fn jacobian(
        &mut self,
        system: &mut dyn OdeSystem,
        t: f64,
        y: &DVector<f64>,
        f0: &DVector<f64>,
    ) -> Result<DMatrix<f64>, SimulationError> {
        let n = y.len();
        let mut jac = DMatrix::zeros(n, n);
        forward_jacobian(
            system,
            &mut self.state.stats,
            (t, y, f0),
            |_| false,
            &mut y.clone(),
            &mut DVector::zeros(n),
            jac.as_mut_slice(),
        )?;
        Ok(jac)
    }
}

impl Stepper for Rosenbrock2 {
    fn step(
        &mut self,
        system: &mut dyn OdeSystem,
        t: &mut f64,
        y: &mut DVector<f64>,
        t_limit: f64,
    ) -> Result<(), SimulationError> {
        let h = self.state.h.min(t_limit - *t);
        self.state.start(system, *t, y)?;
        let f0 = self.state.slope.clone();
        let jac = self.jacobian(system, *t, y, &f0)?;
        let n = y.len();
        let w = DMatrix::<f64>::identity(n, n) - jac * (GAMMA * h);
        let lu = w.lu();
        let singular = || SimulationError::SingularMatrix {
            t: *t,
            what: "I − γhJ of the Rosenbrock step",
        };
        let k1 = lu.solve(&f0).ok_or_else(singular)?;
        let mut f1 = DVector::zeros(n);
        self.state.eval(system, *t + h, &(&*y + &k1 * h), &mut f1)?;
        let k2 = lu.solve(&(f1 - &k1 * 2.0)).ok_or_else(singular)?;
        let y1 = &*y + (&k1 * 1.5 + &k2 * 0.5) * h;
        self.state.finish(system, (t, y), (h, &y1))
    }

    fn interpolate(&self, t: f64) -> DVector<f64> {
        self.state.interpolate(t)
    }

    fn restart(&mut self) {
        self.state.restart();
    }

    fn stats(&self) -> Stats {
        Stats {
            implicit: self.state.stats.accepted,
            ..self.state.stats
        }
    }
}
