//! # trackgen
//!
//! A model compiler for the dynamics of planar tracked vehicles. Declare a
//! vehicle (or a free track) with [`model!`]; the macro generates
//! specialised, unrolled code for its dynamics in the recursive coordinates
//! of Shin, Choi & Yi, *Dynamic Analysis of Multibody Tracked Vehicles (I)*
//! (the mathematics, corrected, is the guide's chapter "The formulation",
//! whose sections the code cites as "formulation §n").
//! The runtime's modules, re-exported here, evaluate, integrate and
//! analyse it.
//!
//! ```
//! use trackgen::multibody::{RecursiveModel, TrackModel};
//! use trackgen::nalgebra::SVector;
//!
//! trackgen::model! {
//!     /// A four-link loop of identical 0.154 m links.
//!     pub track Loop4 {
//!         links: 4,
//!         link { mass: 18.02, inertia: 0.04, u1: (-0.077, 0.0), u2: (0.077, 0.0) },
//!         closure: partitioned,
//!     }
//! }
//!
//! // A square: the loop closes.
//! let q = SVector::<f64, 6>::from([0.0, 0.0, 0.0, 1.5707963267948966, 3.141592653589793, -1.5707963267948966]);
//! assert!(Loop4.closure(&q).norm() < 1e-15);
//! // The dense cross-check: falling freely as a whole.
//! let a = trackgen::dynamics::dense_forward_dynamics(&Loop4, &q, &SVector::zeros(), &[]).unwrap();
//! assert!((a.qdd[1] + 9.81).abs() < 1e-12);
//! ```
//!
//! The declaration's syntax, keys, units and defaults are [`model!`]'s
//! documentation; what it generates, how to simulate it and the rest are
//! in the guide (`book/`, built with `mdbook build book`).
//! [`vehicles::m113`] is the default vehicle, declared this way.
//!
//! ## The surface
//!
//! One path per item: the macro, the runtime's modules by physical role
//! (lowest first), [`nalgebra`] and the declared [`vehicles`].
//!
//! * [`planar`], [`trig`]: rotations kept as `(sin, cos)`, the cross
//!   product; the trigonometry generated code uses, bit for bit;
//! * [`laws`]: force laws with their energy terms;
//! * [`multibody`]: the traits generated code implements, descriptions,
//!   loads, [`DynamicsError`](multibody::DynamicsError);
//! * [`contact`]: terrain, contact detection and response, soft soil;
//! * [`dynamics`], [`closure`]: forward dynamics at a state, closing the
//!   loop in time; [`spatial`]: a planar chain floating in space;
//! * [`integrate`]: the integrators,
//!   [`SimulationError`](integrate::SimulationError);
//! * [`system`], [`assembly`]: subsystems a simulation runs, placing a
//!   vehicle at t = 0; [`spatial_vehicle`]: the spatial vehicle's force
//!   elements and forward dynamics;
//! * [`vehicle`]: [`Vehicle`](vehicle::Vehicle), its configuration and the
//!   one recipe that builds it;
//! * [`simulate`], [`analysis`]: runs, results and sinks; equilibrium,
//!   modes, sensitivities;
//! * [`steering`]: the steady skid-steered turn on firm ground (the
//!   general theory of Wong & Chiang).
//!
//! With the `oracle` feature, `reference` (the textbook route) too.

#![warn(missing_docs)]

// Generated code names `::trackgen`; this lets the crate declare vehicles too.
extern crate self as trackgen;

pub mod vehicles;

#[doc = include_str!("../book/src/declaring.md")]
pub use trackgen_macros::model;

pub use trackgen_runtime::{
    analysis, assembly, closure, contact, dynamics, integrate, laws, mobility, multibody, planar,
    ride, scenario, scene, simulate, spatial, spatial_vehicle, steering, system, terrain, trig,
    vehicle,
};

#[cfg(feature = "oracle")]
pub use trackgen_runtime::reference;

/// nalgebra, the linear algebra trackgen's types are made of.
pub use trackgen_runtime::__private::nalgebra;

/// Paths the generated code uses. Not public API.
#[doc(hidden)]
pub mod __private {
    pub use trackgen_runtime::__private::*;
}

/// README's and the guide's Rust blocks, compiled (and run, where not
/// marked `no_run`) as doctests, so the documentation shows code that
/// builds. (The chapter on declaring is [`model!`]'s own documentation.)
#[cfg(doctest)]
mod guide {
    #[doc = include_str!("../README.md")]
    struct Readme;
    #[doc = include_str!("../book/src/introduction.md")]
    struct Introduction;
    #[doc = include_str!("../book/src/generated.md")]
    struct Generated;
    #[doc = include_str!("../book/src/simulating.md")]
    struct Simulating;
    #[doc = include_str!("../book/src/contact.md")]
    struct Contact;
    #[doc = include_str!("../book/src/friction.md")]
    struct Friction;
    #[doc = include_str!("../book/src/equilibrium.md")]
    struct Equilibrium;
    #[doc = include_str!("../book/src/soil.md")]
    struct Soil;
    #[doc = include_str!("../book/src/terrain.md")]
    struct Terrain;
    #[doc = include_str!("../book/src/mobility.md")]
    struct Mobility;
    #[doc = include_str!("../book/src/fmu.md")]
    struct Fmu;
    #[doc = include_str!("../book/src/formulation.md")]
    struct Formulation;
    #[doc = include_str!("../book/src/architecture.md")]
    struct Architecture;
    #[doc = include_str!("../book/src/testing.md")]
    struct Testing;
    #[doc = include_str!("../book/src/examples.md")]
    struct Examples;
}
