//! Runtime of [trackgen](https://docs.rs/trackgen): everything that does not
//! depend on a particular vehicle, in layers by physical role. A module
//! imports only the modules its layer's edges allow (a graph, not a total
//! order: contact does not need the solvers, nor the solvers contact), each
//! item from the module that defines it, and no two files need each other;
//! `tests/it/layers.rs` reads every file with `syn` and holds the code to
//! this list.
//!
//! 1. **core**: [`planar`] (the rotation, kept as its `(sin, cos)`; the
//!    cross product, `perp`, `spin`), the trigonometry of every body at
//!    once ([`trig`]), and `simd`, the one switch to AVX2 builds of the hot
//!    loops; [`ride`], the ride-quality filters over a sampled acceleration
//!    (absorbed power, ISO 2631-1 weightings, peak after a low-pass), which
//!    need nothing else; [`steering`], the steady skid-steered turn on
//!    firm ground (the general theory of Wong & Chiang, the simplified
//!    theory's criterion), which needs only the standard gravity;
//! 2. [`laws`]: every force law with its energy terms (contact's normal
//!    laws and friction, stiction, the torsion spring, the penalty joint);
//! 3. [`multibody`]: the traits generated code implements, the run-time
//!    description of the same body tree, the loads on its bodies, the
//!    closing joint, [`DynamicsError`](multibody::DynamicsError);
//! 4. [`terrain`]: the ground's shape (closed forms, tables, polylines
//!    with vertical faces, their files, obstacle courses, random
//!    roughness, courses named in words) and its strength (the soils);
//!    [`contact`]: detection of the link-ground, link-wheel and sprocket
//!    contacts against it; their response; soft soil's; each contact's
//!    Jacobian;
//! 5. solvers: [`dynamics`] (forward dynamics at a state: the generated
//!    O(n) route, the dense cross-check, their derivatives, the shifted
//!    chain), [`closure`] (closing the loop in time: partitioning with
//!    switching, multipliers, penalty; [`RecoveryError`](closure::RecoveryError)),
//!    `reference` (feature `oracle`: the textbook route); [`spatial`]
//!    (a planar chain floating in space, over its generated code: the
//!    track of a spatial vehicle);
//! 6. time: [`integrate`] (RK4, Dormand-Prince 5(4), Bogacki-Shampine
//!    3(2), ROS2, ROS34PW2, the automatic choice;
//!    [`SimulationError`](integrate::SimulationError), which wraps the
//!    lower layers' errors with the time they happened at);
//! 7. subsystems: [`system`] (a track, a body tree or two side by side as
//!    systems a simulation runs), [`assembly`] (wrapping a track round its
//!    wheels, placing a vehicle at t = 0, or both sides of a spatial one);
//! 8. [`vehicle`]: a declared vehicle as a type and the one recipe that
//!    builds it; its evaluation in stages over a long-lived workspace
//!    (kinematics → detection → force elements with their energy books →
//!    dynamics), the state's one layout, and the one linearisation that
//!    feeds both the exact Jacobian and ROS34PW2's `W`;
//!    [`spatial_vehicle`] (the spatial vehicle's hull and two tracks as
//!    floating trees: its force elements, each side's drive, its forward
//!    dynamics and its system in time);
//! 9. drivers: [`simulate`] (runs, results, sinks: CSV, Arrow IPC, running
//!    summaries; a failed run keeps what it computed), [`analysis`]
//!    (the state Jacobian, equilibrium, modes, sensitivities) and
//!    [`scene`] (the vehicle's geometry at recorded times, for pictures:
//!    the crate `trackgen-draw` draws it);
//! 10. [`mobility`]: the mobility engineer's events over any declared
//!     vehicle (ride over random terrain, half-round, step, gap, ditch,
//!     barrier, grade), each a limit found by bracketing over runs, the
//!     vehicle drawn at each obstacle's limit; [`scenario`]: one owner of
//!     a run (its course, soil, drive, integrator, output and duration, the
//!     main job's by default), from which the main job and the FMU build
//!     their runs.
//!
//! With the `oracle` feature, `reference` (the textbook route: dense `H`
//! of the paper's eq. (6) and (11), `Hᵀ M H`, `Hᵀ (Q − M γ)`), the generic
//! `dynamics::LinearTimeSolver` and the dense partitioned equations are
//! built too: the independent routes the tests hold the generated code to.
//!
//! Conventions (the guide's chapter "The formulation"): planar, SI
//! units, `A(θ)` the rotation matrix, body frames at the centroid, recursive
//! coordinates `q_i = [R¹, θ¹ … θⁿ]` (the root's centroid, then the
//! absolute angle of every body).

#![warn(missing_docs)]

// 1. core
pub mod planar;
pub mod ride;
mod simd;
pub mod steering;
pub mod trig;
// 2-4. physics
pub mod contact;
pub mod laws;
pub mod multibody;
pub mod terrain;
// 5. solvers
pub mod closure;
pub mod dynamics;
#[cfg(feature = "oracle")]
pub mod reference;
pub mod spatial;
pub mod spatial_vehicle;
// 6. time
pub mod integrate;
// 7. subsystems
pub mod assembly;
pub mod system;
// 8. the vehicle
pub mod vehicle;
// 9. drivers
pub mod analysis;
pub mod mobility;
pub mod scenario;
pub mod scene;
pub mod simulate;

/// The kernels and types that generated code names by absolute path, and
/// nothing else (`tests/it/private_paths.rs` holds it to the snapshots of
/// generated code). Not part of the public API: it may change in any
/// release.
#[doc(hidden)]
pub mod __private {
    pub use ::nalgebra;

    pub use crate::contact::ShoeGeometry;
    pub use crate::contact::sprocket::ToothProfile;
    pub use crate::terrain::Terrain;
    /// The generated linear-time solve's per-thread tables and steps.
    pub mod elimination {
        pub use crate::dynamics::elimination::{JointTerms, LinkTerms, Sweep, back, with_tables};
    }
    pub use crate::laws::{NormalLaw, PenaltyJoint, TorsionSpring};
    pub use crate::multibody::{
        ArmSpring, BodyDescription, BodyLoad, ChassisModel, ChassisPart, ClosingJoint, Closure,
        DynamicsError, LoopJoint, PartKind, RecursiveModel, TrackModel, TreeDescription,
    };
    pub use crate::spatial::{
        OutOfPlaneInertia, Side, SpatialError, SpatialLayout, SpatialVehicle,
    };
    pub use crate::spatial_vehicle::{
        SpatialDynamics, SpatialLaws, SpatialSystem, SpatialVehicleSystem,
    };
    pub use crate::terrain::field::HeightField;
    pub use crate::trig::{sin_cos, sin_cos_each};
    pub use crate::vehicle::{
        ContactFit, DeclaredContact, DeclaredPair, Drive, Driveline, EngineDynamics, Geometry,
        Powertrain, Shift, Vehicle, VehicleConfig, VehicleSystem,
    };
}
