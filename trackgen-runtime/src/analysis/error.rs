//! Why an analysis of a vehicle could not be done.

use thiserror::Error;

use crate::integrate::SimulationError;
use crate::vehicle::BuildError;

/// Why an equilibrium, a linearisation or the modes could not be found.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum AnalysisError {
    /// The right-hand side could not be evaluated at a state the analysis
    /// needed (a loop closure that failed to recover, say).
    #[error("the right-hand side could not be evaluated: {0}")]
    Evaluation(#[from] SimulationError),
    /// A vehicle rebuilt with a changed parameter could not be built.
    #[error("the vehicle could not be rebuilt: {0}")]
    Build(#[from] BuildError),
    /// The equilibrium holds the sprocket by the speed drive's integral;
    /// this drive has none.
    #[error(
        "an equilibrium holds the sprocket by the speed drive's integral, and this vehicle's drive is {drive}: give it a speed drive with target 0 (`V::speed_drive(|_| 0.0)`)"
    )]
    NoHold {
        /// What the drive is.
        drive: &'static str,
    },
    /// The speed drive asks for motion at the time of the equilibrium.
    #[error(
        "the speed drive asks for {target} m/s at t = {t} s: a vehicle at rest needs a target of 0 there"
    )]
    Moving {
        /// The target speed, m/s.
        target: f64,
        /// The time, s.
        t: f64,
    },
    /// The vehicle has no sprocket to hold.
    #[error("the chassis has no sprocket: nothing holds the track from running round")]
    NoSprocket,
    /// The vehicle is on soft soil, whose rest depends on how it got there
    /// (the rut it pressed).
    #[error(
        "an equilibrium is found on rigid ground only: on soft soil the rest depends on the rut the vehicle pressed (simulate the settling instead)"
    )]
    SoftSoil,
    /// Newton's method did not bring the accelerations to zero.
    #[error(
        "no equilibrium: after {iterations} Newton iterations the largest acceleration is {residual:.3e} (in `{state}`); on a slope or under a drawbar pull there is none without friction holding"
    )]
    NotConverged {
        /// Iterations done.
        iterations: usize,
        /// The largest acceleration left, m/s² or rad/s².
        residual: f64,
        /// The state whose acceleration it is.
        state: String,
    },
    /// The Jacobian of the equilibrium's equations is singular: a motion
    /// that nothing resists (a vehicle that touches no ground, a track that
    /// runs free).
    #[error(
        "the equilibrium's Jacobian is singular: a motion nothing resists (no ground under the vehicle?)"
    )]
    Singular,
    /// The eigen-decomposition of the state matrix failed.
    #[error("the eigen-decomposition of the state matrix did not converge")]
    Eigen,
    /// An arm index that is no arm of the vehicle.
    #[error("arm {arm} is not an arm of the vehicle (it has {arms})")]
    NoArm {
        /// The index asked for.
        arm: usize,
        /// The vehicle's arms.
        arms: usize,
    },
}
