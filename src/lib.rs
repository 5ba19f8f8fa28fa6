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
//!     sprocket drive { at: (0.0, 0.0), mass: 27.68, inertia: 0.883, radius: 0.245,
//!         teeth: 10,                         // integer literal, ≥ 3
//!         tip_radius: 0.2605,                // m, optional (default below)
//!         gap_radius: 0.089,                 // m, optional: radius of the arc between two teeth
//!         gap_centre: 0.3 },                 // m, optional: that arc's centre from the sprocket's
//!     idler front    { at: (-3.95, -0.12), mass: 25.76, inertia: 1.12, radius: 0.255 },
//!     road_wheel lead { at: (-0.74, -0.215), mass: 35.56, inertia: 2.16, radius: 0.305,
//!         arm { pivot: (-0.452, -0.081),     // optional: the part hangs from a sprung arm
//!               mass: 75.26, inertia: 0.77,  // kg, kg m² (centroid midway pivot–wheel)
//!               stiffness: 2.5e4,            // N m/rad, torsion spring about the pivot
//!               damping: 500.0,              // N m s/rad
//!               preload: 1e4 } },            // N m, counter-clockwise at the design angle; default 0
//!     road_wheel rw[4] {                     // four parts rw1..rw4 from one block
//!         at: [(-1.4, -0.215), (-2.07, -0.215), (-2.74, -0.215), (-3.41, -0.215)],
//!         mass: 35.56, inertia: 2.16, radius: 0.305,
//!         arm { pivot_offset: (0.288, 0.134), // m, pivot from each wheel's centre
//!               mass: 75.26, inertia: 0.77, stiffness: 2.5e4, damping: 500.0 } },
//!     roller r[2]    { at: [(…), (…)], mass: …, inertia: …, radius: … },
//!     track { links: 64, link { … }, closure: partitioned },
//!
//!     // What makes it run (optional; with it, `Name::system` exists):
//!     shoe {                                  // link frame, m (x from ū1 to ū2, y inward)
//!         ground_points: [(-0.06, -0.03), (0.06, -0.03)], // where the shoe meets the ground
//!         inner_offset: 0.03,                 // > 0: pitch line to the face wheels run on
//!         pins: [(0.0535, 0.0), (-0.061, 0.0)], // centres of what the teeth engage
//!         pin_radius: 0.015 },                // > 0
//!     contact {                               // optional, each pair and key optional
//!         ground   { stiffness: 2e6, chi: 2.0, mu: 0.8, slip: 0.1 },
//!         wheels   { stiffness: 1e7, chi: 0.5, mu: 0.4, slip: 0.5 },
//!         sprocket { stiffness: 1e7, damping: 2e4 },   // Kelvin-Voigt instead
//!     },
//!     drive { proportional: 3000.0, integral: 6000.0, max_torque: 2e4 }, // optional
//! }
//! ```
//!
//! Part positions `at` are in the drawing frame whose origin the chassis
//! `centroid` is given in (default: the chassis centroid itself). An arm
//! gives its `pivot` in that frame, or its `pivot_offset` from its part's
//! centre; the arms of a repeated block share one `pivot_offset`.
//!
//! ### Running keys, units and defaults
//!
//! * `shoe` (four keys required, `width` optional): `ground_points` (m, a non-empty
//!   list), `inner_offset` (m, positive; the running face spans the first
//!   link's `u1.x` to `u2.x` at this height), `pins` (m, a non-empty list),
//!   `pin_radius` (m, positive), `width` (m, positive: the track's width,
//!   which soft soil needs). Without a `shoe` the vehicle has its
//!   dynamics only, and `contact` or `drive` is an error.
//! * Sprocket profile: `tip_radius`, `gap_radius`, `gap_centre` (m,
//!   positive; the gaps must reach inside the tip circle and be wider
//!   than the pins). Each one left out takes
//!   [`ToothProfile::scaled`](contact::sprocket::ToothProfile::scaled)
//!   from the pitch `p = |u2 − u1|` and `teeth`: with
//!   `R = p / (2 sin(π/teeth))`, tip `R + 0.073 p`, gap centre
//!   `R + 0.33 p`, gap radius 0.48 of the chord between neighbouring gap
//!   centres (the M113's proportions).
//! * `contact` pairs `ground` (shoe ground points on the terrain),
//!   `wheels` (inner face on road wheels, idler, rollers) and `sprocket`
//!   (pins on teeth), each part of each optional. A normal law is
//!   `stiffness` (N/mⁿ, positive) with `chi` (s/m, ≥ 0) and `exponent`
//!   (positive, default 1): Hunt-Crossley `F = k δⁿ (1 + χ δ̇)`; or
//!   `stiffness` (N/m) with `damping` (N s/m, ≥ 0): Kelvin-Voigt.
//!   Friction: `mu` (≥ 0). On the ground friction has stiction
//!   ([`laws::Stiction`], a parked vehicle holds on a grade), with
//!   optional `tangential_stiffness` (N/m, positive) and
//!   `tangential_damping` (N s/m, positive); `slip` (m/s, ≥ 0) there asks
//!   for regularised Coulomb friction instead. Rims and teeth take
//!   regularised friction, `mu` and `slip`. What is left out is fitted to
//!   the vehicle declared, by the rules of
//!   [`vehicle::ContactFit`] (the rules, stated there: the ground's points sink
//!   1 mm under the weight, a shoe bounces on them with damping ratio
//!   0.4, its tangential spring the normal law's secant, critically
//!   damped; rims sink 0.5 mm, damping ratio 0.1; `μ` 0.8 on the ground,
//!   0.4 on rims and teeth).
//! * `drive`: the speed controller of `Name::speed_drive`,
//!   `proportional` (N m s/rad, ≥ 0, default 3000), `integral` (N m/rad,
//!   ≥ 0, default 6000), `max_torque` (N m, positive, default 2e4).
//!
//! Every key is checked where it is written: missing, of the wrong type
//! or out of range, all errors at once.
//!
//! ## What is generated
//!
//! A `track Name` becomes a unit struct `Name` implementing
//! [`RecursiveModel`] and [`TrackModel`]. A `vehicle Name` becomes `Name`,
//! `NameTrack` (as a track) and `NameChassis` ([`RecursiveModel`] and
//! [`ChassisModel`], with a body-index constant per part, `NameChassis::RW1`,
//! and per arm, `NameChassis::RW1_ARM`), the constants `Name::TRACK_DOF`
//! and `Name::CHASSIS_DOF`, and `NameSystem`, its
//! [`VehicleSystem`](vehicle::VehicleSystem). With a `shoe` it is a
//! [`Vehicle`]:
//!
//! * `Name::geometry()`: the shoe and the sprocket's tooth profile, compiled;
//! * `Name::config(terrain, drive) -> VehicleConfig`: the declared contact
//!   laws, friction and arm springs (`arms`), every field public, so that
//!   contact, friction, spring and damper rates, soft soil, the terrain,
//!   the drive and the closure method can be changed at run time, without
//!   recompiling (the masses, inertias and geometry are compiled in);
//! * `Name::speed_drive(target)`: a PI speed drive with the declared gains;
//! * `Name::system(terrain, drive)?` and `Name::system_with(config)?`: the
//!   vehicle built by the runtime's one recipe,
//!   [`vehicle::build`] (chassis centroid at x = 0, shoes
//!   1 mm above the ground, the tensioner set), ready for
//!   [`simulate`](simulate::simulate).
//!
//! After an error in a declaration every one of these items still exists,
//! as a stub, so nothing but the real error is reported.
//!
//! [`vehicles::m113`] is the default vehicle, declared this way.
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
    pub use trackgen_runtime::__private::*;
}

/// README's Rust blocks, compiled (and run, where not marked `no_run`) as
/// doctests, so the README shows code that builds.
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
pub struct ReadmeDoctests;
