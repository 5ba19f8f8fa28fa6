//! Runtime of [trackgen](https://docs.rs/trackgen): everything that does not
//! depend on a particular vehicle, in layers that import only downward
//! (`tests/layers.rs` holds them to it):
//!
//! 1. **core**: [`planar`] (the rotation, kept as its `(sin, cos)`; the
//!    cross product), the trigonometry ([`sin_cos_each`]), the switch to
//!    AVX2 builds of the hot loops (`wide`), the typed errors, [`laws`]
//!    (every force law with its energy terms) and [`model`] (the traits generated code implements, the run-time
//!    description of the same body tree, the closing joint);
//! 2. [`dynamics`]: forward dynamics at a given state (the dense
//!    cross-check, the linear-time route as declared);
//! 3. [`closure`]: the three ways of closing the track loop in time
//!    (partitioning with switching, multipliers, penalty);
//! 4. [`integrate`]: RK4, Dormand-Prince 5(4), Bogacki-Shampine 3(2),
//!    Rosenbrock ROS2;
//! 5. [`system`]: a track, a body tree or two side by side as systems a
//!    simulation runs;
//! 6. [`contact`]: terrain, detection of the link-ground, link-wheel and
//!    sprocket contacts, their response, soft soil;
//! 7. [`assembly`]: wrapping a track round its wheels and placing a
//!    vehicle at t = 0;
//! 8. [`vehicle`]: a declared vehicle as a type, the one recipe that
//!    builds it, and its evaluation in stages;
//! 9. [`simulate`]: the driver, results and sinks (CSV, Arrow IPC, running
//!    summaries), with typed errors that keep the results.
//!
//! With the `oracle` feature, `reference` (the textbook route: dense `H`
//! of the paper's eq. (6) and (11), `Hᵀ M H`, `Hᵀ (Q − M γ)`), the generic
//! `dynamics::LinearTimeSolver` and the dense partitioned equations are
//! built too: the independent routes the tests hold the generated code to.
//!
//! Conventions follow `shared/spec/recursive-formulation.md` §0: planar, SI
//! units, `A(θ)` the rotation matrix, body frames at the centroid, recursive
//! coordinates `q_i = [R¹, θ¹ … θⁿ]` (the root's centroid, then the
//! absolute angle of every body).

#![warn(missing_docs)]

pub mod analysis;
pub mod assembly;
pub mod closure;
pub mod contact;
pub mod dynamics;
pub mod integrate;
pub mod laws;
pub mod model;
pub mod planar;
#[cfg(feature = "oracle")]
pub mod reference;
pub mod simulate;
pub mod system;
pub mod vehicle;

mod error;
mod trig;
mod wide;

pub use dynamics::Accelerations;
pub use error::{DynamicsError, SettingsError, SimulationError};
pub use model::{
    ArmSpring, BodyDescription, BodyLoad, ChassisModel, ChassisPart, ClosingJoint, Closure,
    LoopJoint, PartKind, RecursiveModel, TrackModel, TreeDescription,
};
pub use planar::{rotate, rotate_derivative};
pub use trig::{sin_cos, sin_cos_each};
pub use vehicle::{Vehicle, VehicleDynamics};

/// The kernels and types that generated code names by absolute path, and
/// nothing else. Not part of the public API: it may change in any release.
#[doc(hidden)]
pub mod __private {
    pub use ::core;
    pub use ::nalgebra;

    pub use crate::contact::ShoeGeometry;
    pub use crate::contact::sprocket::ToothProfile;
    /// The generated linear-time solve's per-thread tables and steps.
    pub mod elimination {
        pub use crate::dynamics::elimination::{JointTerms, LinkTerms, Sweep, back, with_tables};
    }
    pub use crate::DynamicsError;
    pub use crate::contact::{ContactLaws, Terrain};
    pub use crate::laws::{Friction, NormalLaw};
    pub use crate::laws::{PenaltyJoint, TorsionSpring};
    pub use crate::model::{
        ArmSpring, BodyDescription, BodyLoad, ChassisModel, ChassisPart, ClosingJoint, Closure,
        LoopJoint, PartKind, RecursiveModel, TrackModel, TreeDescription,
    };
    pub use crate::trig::{sin_cos, sin_cos_each};
    pub use crate::vehicle::{
        ContactFit, DeclaredContact, DeclaredPair, Drive, Geometry, Vehicle, VehicleConfig,
        VehicleSystem,
    };
}
