//! Closing the track loop (formulation §2): three methods.
//!
//! * **Generalised coordinate partitioning** ([`partitioning`], the
//!   default): two angles are dependent; only the other `n` coordinates are
//!   integrated, and the dependent pair follows from `C = 0` by
//!   Newton-Raphson and from `C_q q̇ = 0`. The pair is switched whenever its
//!   block `C_d` degrades (paper eq. (21)), and every switch is recorded.
//! * **Multipliers** ([`multipliers`]): all `n + 2` coordinates are
//!   integrated with the multiplier form of formulation §2, with Baumgarte
//!   stabilisation and a projection onto `C = 0`, `C_q q̇ = 0` after each
//!   step.
//! * **Penalty** ([`PenaltyJoint`], paper Fig. 5): the closing joint is cut and
//!   replaced by a spring-damper; the chain is open and the loop closes only
//!   as well as the spring is stiff.

pub mod multipliers;
pub mod partitioning;

pub use multipliers::{MultiplierOptions, ProjectionFailure};
pub use partitioning::{PartitionOptions, Switch};

use thiserror::Error;

use crate::laws::{ParameterError, PenaltyJoint};

/// Why a track's loop cannot be closed as asked, at the start of a run.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum ClosureError {
    /// A closure method was chosen for a track declared open.
    #[error("the track is declared `closure: open`; declare it `partitioned` to close its loop")]
    DeclaredOpen,
    /// A closure method was chosen for a track declared with a penalty
    /// joint.
    #[error(
        "the track is declared with a penalty joint; declare it `partitioned` to choose the closure method at run time"
    )]
    DeclaredPenalty,
    /// A run-time penalty joint with a parameter out of range.
    #[error("penalty joint: {0}")]
    Penalty(#[from] ParameterError),
    /// The partition's starting pair is not two different links.
    #[error("initial_pair {pair:?}: two different links from 1 to {links}")]
    InitialPair {
        /// The pair asked for (numbered from 1).
        pair: [usize; 2],
        /// The number of links.
        links: usize,
    },
    /// The dependent pair's Newton-Raphson did not close the loop at the
    /// start.
    #[error(
        "the start does not close: Newton-Raphson left |C| = {residual:e} m after {iterations} iterations"
    )]
    StartNotClosed {
        /// Iterations taken.
        iterations: usize,
        /// `|C|` at the last iterate, m.
        residual: f64,
    },
    /// The starting pair's block `C_d` is singular.
    #[error("the starting pair's C_d is singular (the two links parallel)")]
    SingularStart,
    /// The start could not be projected onto the closure (multipliers, a
    /// run-time penalty joint).
    #[error("the initial state cannot be projected onto the loop closure: {0}")]
    Projection(#[from] ProjectionFailure),
}

/// How a simulation closes a track's loop.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub enum ClosureMethod {
    /// As declared: partitioning for `closure: partitioned`, the declared
    /// spring for `penalty { … }`, nothing for `open`.
    #[default]
    Declared,
    /// Generalised coordinate partitioning with switching.
    Partitioning(PartitionOptions),
    /// Multipliers with stabilisation and projection.
    Multipliers(MultiplierOptions),
    /// A spring-damper at the cut joint, chosen at run time (for a track
    /// declared `partitioned`).
    Penalty(PenaltyJoint),
}

/// Why the loop's dependent coordinates could not be recovered at a step
/// (generalised coordinate partitioning, formulation §2; the multipliers'
/// projection). Every variant carries the simulation time `t` (s).
#[derive(Debug, Clone, PartialEq, Error)]
pub enum RecoveryError {
    /// Newton-Raphson on the loop closure `C(z, d) = 0` did not converge.
    #[error(
        "Newton-Raphson on the loop closure failed at t = {t} s: |C| = {residual:e} m after {iterations} iterations"
    )]
    NewtonFailed {
        /// Time, s.
        t: f64,
        /// Iterations taken.
        iterations: usize,
        /// `|C|` at the last iterate, m.
        residual: f64,
    },
    /// Newton-Raphson converged, but to the mirror configuration of the
    /// dependent pair (the closure has two solutions for two angles): the
    /// step was too long.
    #[error("the dependent links {} and {} jumped by {jump:.2} rad at t = {t} s (mirror solution of the closure)", pair[0], pair[1])]
    BranchJump {
        /// Time, s.
        t: f64,
        /// The dependent links (numbered from 1).
        pair: [usize; 2],
        /// The larger change of the two angles from the last accepted
        /// step, rad.
        jump: f64,
    },
    /// The dependent pair's block `C_d` became singular while switching was
    /// off (paper eq. (21): the two links nearly parallel).
    #[error("singular partition at t = {t} s: links {} and {} are nearly parallel (|sin| = {conditioning:e}) and switching is off", pair[0], pair[1])]
    SingularPartition {
        /// Time, s.
        t: f64,
        /// The dependent links (numbered from 1).
        pair: [usize; 2],
        /// `|sin|` of the angle between the two columns of `C_d`.
        conditioning: f64,
    },
}

impl RecoveryError {
    /// The simulation time at which it happened, s.
    pub fn time(&self) -> f64 {
        match self {
            RecoveryError::NewtonFailed { t, .. }
            | RecoveryError::BranchJump { t, .. }
            | RecoveryError::SingularPartition { t, .. } => *t,
        }
    }
}
