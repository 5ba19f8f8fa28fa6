//! The method a run uses, chosen by value, and the stepper it builds.

use super::{Auto, Dopri5, Embedded, Rk4, Ros34pw2, Rosenbrock2, Stepper};

/// Which integrator, with its settings.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Integrator {
    /// [`Rk4`] with a fixed step, s.
    Rk4 {
        /// Step, s.
        step: f64,
    },
    /// [`Dopri5`], adaptive.
    Dopri5 {
        /// Relative tolerance per component.
        rtol: f64,
        /// Absolute tolerance per component.
        atol: f64,
        /// Largest step, s (`f64::INFINITY` for none).
        max_step: f64,
    },
    /// Bogacki-Shampine 3(2), adaptive: three evaluations a step, for
    /// loose tolerances where stability, not accuracy, sets the step.
    Bs23 {
        /// Relative tolerance per component.
        rtol: f64,
        /// Absolute tolerance per component.
        atol: f64,
        /// Largest step, s (`f64::INFINITY` for none).
        max_step: f64,
    },
    /// [`Ros34pw2`], adaptive, linearly implicit: for vehicles whose step
    /// an explicit method's stability sets.
    Ros34pw2 {
        /// Relative tolerance per component.
        rtol: f64,
        /// Absolute tolerance per component.
        atol: f64,
        /// Largest step, s (`f64::INFINITY` for none).
        max_step: f64,
    },
    /// [`Auto`]: Bogacki-Shampine while accuracy sets the step, ROS34PW2
    /// while the stiffest mode would, checked at the start and every
    /// second.
    Auto {
        /// Bogacki-Shampine's tolerance, relative and absolute.
        explicit_tolerance: f64,
        /// ROS34PW2's tolerance, relative and absolute.
        implicit_tolerance: f64,
        /// Largest step, s (`f64::INFINITY` for none).
        max_step: f64,
    },
    /// [`Rosenbrock2`] with a fixed step, s.
    Rosenbrock2 {
        /// Step, s.
        step: f64,
    },
}

impl Integrator {
    /// What a run uses unless told otherwise (the main job, the mobility
    /// events, the FMU): [`Auto`](Integrator::Auto) at
    /// [`DEFAULT_EXPLICIT_TOLERANCE`](Self::DEFAULT_EXPLICIT_TOLERANCE) and
    /// [`DEFAULT_IMPLICIT_TOLERANCE`](Self::DEFAULT_IMPLICIT_TOLERANCE),
    /// steps of at most [`DEFAULT_MAX_STEP`](Self::DEFAULT_MAX_STEP).
    pub const DEFAULT: Integrator = Integrator::Auto {
        explicit_tolerance: Self::DEFAULT_EXPLICIT_TOLERANCE,
        implicit_tolerance: Self::DEFAULT_IMPLICIT_TOLERANCE,
        max_step: Self::DEFAULT_MAX_STEP,
    };
    /// The explicit methods' default tolerance, relative and absolute: the
    /// M113 with Bogacki-Shampine closes its books to about 1e-3 of the
    /// motor's work at it.
    pub const DEFAULT_EXPLICIT_TOLERANCE: f64 = 1e-3;
    /// ROS34PW2's default tolerance, relative and absolute: the Marder
    /// closes its books to about 1e-3 at it.
    pub const DEFAULT_IMPLICIT_TOLERANCE: f64 = 1e-2;
    /// The default longest step, s: the rows of a run every 10 ms are
    /// never interpolated across more.
    pub const DEFAULT_MAX_STEP: f64 = 0.01;

    /// Dormand-Prince with `rtol = atol = tol` and no step limit.
    pub fn dopri5(tol: f64) -> Self {
        Integrator::Dopri5 {
            rtol: tol,
            atol: tol,
            max_step: f64::INFINITY,
        }
    }

    /// Bogacki-Shampine with `rtol = atol = tol` and steps of at most
    /// [`DEFAULT_MAX_STEP`](Self::DEFAULT_MAX_STEP): what the 3-D main job
    /// and its turns run at `tol`.
    pub fn bs23(tol: f64) -> Self {
        Integrator::Bs23 {
            rtol: tol,
            atol: tol,
            max_step: Self::DEFAULT_MAX_STEP,
        }
    }

    /// A stepper for a system of `dimension` components.
    pub fn stepper(self, dimension: usize) -> Box<dyn Stepper> {
        match self {
            Integrator::Rk4 { step } => Box::new(Rk4::new(step, dimension)),
            Integrator::Dopri5 {
                rtol,
                atol,
                max_step,
            } => Box::new(Dopri5::new(rtol, atol, max_step, dimension)),
            Integrator::Bs23 {
                rtol,
                atol,
                max_step,
            } => Box::new(Embedded::bogacki_shampine(rtol, atol, max_step, dimension)),
            Integrator::Ros34pw2 {
                rtol,
                atol,
                max_step,
            } => Box::new(Ros34pw2::new(rtol, atol, max_step, dimension)),
            Integrator::Auto {
                explicit_tolerance,
                implicit_tolerance,
                max_step,
            } => Box::new(Auto::new(
                explicit_tolerance,
                implicit_tolerance,
                max_step,
                dimension,
            )),
            Integrator::Rosenbrock2 { step } => Box::new(Rosenbrock2::new(step, dimension)),
        }
    }
}
