//! Time integrators for the first-order systems `y' = f(t, y)` that a
//! simulation assembles.
//!
//! Four methods, each a [`Stepper`] driven one step at a time, because a
//! simulation must act between steps: re-partition the closed track and
//! restart ([`Stepper::restart`]), write dense output, and stop with the
//! results kept when something fails.
//!
//! * [`Rk4`]: classical fourth-order Runge-Kutta, fixed step.
//! * [`Dopri5`]: Dormand-Prince 5(4), adaptive with `rtol`/`atol`, FSAL,
//!   and its fourth-order continuous extension for dense output; the same
//!   engine ([`Embedded`]) runs Bogacki-Shampine 3(2), three evaluations a
//!   step, for loose tolerances.
//! * [`Rosenbrock2`]: the linearly implicit ROS2 of Verwer et al. (1999),
//!   L-stable and second order for any Jacobian (a W-method), fixed step:
//!   for the stiff contact and penalty forces, where explicit methods need
//!   steps of the order of the stiffest period.
//! * [`Ros34pw2`]: Rang & Angermann's ROS34PW2, a Rosenbrock-W method of
//!   order 3(2), adaptive, with dense output; its Jacobian and
//!   factorisation serve several steps ([`JacobianReuse`]).
//!
//! Why not a crate: `ode_solvers` 0.6 builds on nalgebra 0.34 (ours is
//! 0.35), integrates a whole interval per call with an infallible `&self`
//! right-hand side, and has no stiff method; `diffsol` brings faer and a
//! problem-builder API sized for large sparse systems. Neither gives a
//! fallible right-hand side that rejects a step (a Newton-Raphson failure
//! of the closure must shrink the step, not abort) together with a restart
//! after re-partitioning; the methods themselves are a page each.

pub mod auto;
mod control;
mod differences;
mod embedded;
mod error;
mod fixed_step;
mod integrator;
mod ode;
mod rk4;
mod rosenbrock;
mod rosenbrock_w;

pub use auto::Auto;
pub use embedded::{Dopri5, Embedded};
pub use error::{SettingsError, SimulationError};
pub use integrator::Integrator;
pub use ode::{Check, ImplicitSolve, OdeSystem, Stats, Stepper};
pub(crate) use ode::{all_finite, evaluate};
pub use rk4::Rk4;
pub use rosenbrock::Rosenbrock2;
pub use rosenbrock_w::{JacobianReuse, LinearAlgebraWork, Ros34pw2};
