//! Closing the track loop (spec §2): three methods.
//!
//! * **Generalised coordinate partitioning** ([`partitioning`], the
//!   default): two angles are dependent; only the other `n` coordinates are
//!   integrated, and the dependent pair follows from `C = 0` by
//!   Newton-Raphson and from `C_q q̇ = 0`. The pair is switched whenever its
//!   block `C_d` degrades (paper eq. (21)), and every switch is recorded.
//! * **Multipliers** ([`multipliers`]): all `n + 2` coordinates are
//!   integrated with the multiplier form of spec §2, with Baumgarte
//!   stabilisation and a projection onto `C = 0`, `C_q q̇ = 0` after each
//!   step.
//! * **Penalty** ([`penalty`], paper Fig. 5): the closing joint is cut and
//!   replaced by a spring-damper; the chain is open and the loop closes only
//!   as well as the spring is stiff.

pub mod multipliers;
pub mod partitioning;
pub mod penalty;

pub use multipliers::{MultiplierOptions, ProjectionFailure};
pub use partitioning::PartitionOptions;
pub use penalty::PenaltyJoint;

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
