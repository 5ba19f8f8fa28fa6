//! # trackgen
//!
//! A model compiler for the dynamics of planar tracked vehicles. Declare a
//! vehicle (or a free track) with [`model!`]; the macro generates
//! specialised, unrolled code for its dynamics in the recursive coordinates
//! of Shin, Choi & Yi, *Dynamic Analysis of Multibody Tracked Vehicles (I)*
//! (the mathematics, corrected, is `shared/spec/recursive-formulation.md`).
//! The runtime ([`trackgen_runtime`], re-exported here) evaluates and
//! integrates it.
//!
//! ```
//! use trackgen::nalgebra::SVector;
//! use trackgen::{RecursiveModel, TrackModel};
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
//! let a = trackgen::dynamics::forward_dynamics(&Loop4, &q, &SVector::zeros(), &[]).unwrap();
//! // Falling freely as a whole.
//! assert!((a.qdd[1] + 9.81).abs() < 1e-12);
//! ```
//!
//! ## The declaration
//!
//! `model! { … }` holds any number of items, each `track` or `vehicle`,
//! with doc comments, attributes and visibility. Units are SI. Every
//! number is a literal, arithmetic on literals, or any constant expression
//! (`SHOE_PITCH / 2.0`); the macro checks what it can evaluate and has
//! rustc assert the rest at compile time.
//!
//! ```text
//! pub track Name {
//!     links: 64,                       // integer literal; ≥ 3 when closed
//!     link { mass: 18.02,              // kg          template for all links
//!            inertia: 0.04,            // kg m², about the centroid
//!            u1: (-0.077, 0.0),        // m, joint to the previous link (ū1), link frame
//!            u2: (0.077, 0.0) },       // m, joint to the next link (ū2)
//!     link[2..=64 by 2] { mass: 20.0 },// overrides, 1-based: `[3]`, `[1, 5]`, `[a..b]`, `[a..=b by k]`
//!     closure: partitioned,            // default | open | penalty { stiffness: 1e7, damping: 1e3 }
//!     gravity: (0.0, -9.81),           // m/s², default (0, −9.81)
//! }
//!
//! pub vehicle Name {
//!     gravity: (0.0, -9.81),
//!     chassis { mass: 3909.62, inertia: 13643.8, centroid: (-2.006, 0.406) },
//!     sprocket drive { at: (0.0, 0.0), mass: 27.68, inertia: 0.883, radius: 0.245, teeth: 10 },
//!     idler front    { at: (-3.95, -0.12), mass: 25.76, inertia: 1.12, radius: 0.255 },
//!     road_wheel rw1 { at: (-0.74, -0.215), mass: 35.56, inertia: 2.16, radius: 0.305,
//!         arm { pivot: (-0.452, -0.081),     // optional: the part hangs from a sprung arm
//!               mass: 75.26, inertia: 0.77,  // kg, kg m² (centroid midway pivot–wheel)
//!               stiffness: 2.5e4,            // N m/rad, torsion spring about the pivot
//!               damping: 500.0,              // N m s/rad
//!               preload: 1e4 } },            // N m, counter-clockwise at the design angle
//!     roller r1      { at: (…), mass: …, inertia: …, radius: … },
//!     track { links: 64, link { … }, closure: partitioned },
//! }
//! ```
//!
//! Part positions `at` are in the drawing frame whose origin the chassis
//! `centroid` is given in (default: the chassis centroid itself).
//!
//! ## What is generated
//!
//! A `track Name` becomes a unit struct `Name` implementing
//! [`RecursiveModel`] and [`TrackModel`]. A `vehicle Name` becomes `Name`,
//! `NameTrack` (as a track) and `NameChassis` ([`RecursiveModel`] and
//! [`ChassisModel`], with a body-index constant per part, `NameChassis::RW1`,
//! and per arm, `NameChassis::RW1_ARM`). [`vehicles::m113`] is the default
//! vehicle, declared this way.
//! Run `cargo expand` (or read the insta snapshots in
//! `trackgen-macros/src/snapshots/`) to see the code.

#![warn(missing_docs)]

// Generated code names `::trackgen`; this lets the crate declare vehicles too.
extern crate self as trackgen;

pub mod vehicles;

pub use trackgen_macros::model;
pub use trackgen_runtime::*;

/// nalgebra, the linear algebra trackgen's types are made of.
pub use trackgen_runtime::__private::nalgebra;

/// Paths the generated code uses. Not public API.
#[doc(hidden)]
pub mod __private {
    pub use trackgen_runtime as runtime;
    pub use trackgen_runtime::__private::*;
}
