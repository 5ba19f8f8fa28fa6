//! The mobility engineer's questions, asked of any declared vehicle in
//! its pitch plane (the NATO Reference Mobility Model's events and the
//! next-generation NRMM's benchmark, NATO ET-148, 2016; the guide's
//! "Mobility events"): the ride over random
//! terrain and the speed at which the driver's absorbed power reaches
//! 6 W, the speed over a half-round obstacle at which the seat sees
//! 2.5 g, the highest step and widest gap crossed from a crawl, the
//! steepest grade climbed and the speed on grades at full power, and the
//! drawbar pull against slip and the motion resistance on a soft soil;
//! and, in 3-D for a vehicle declared with both tracks, the steepest side
//! slope held driving along it ([`side_slope`]), the smallest radius
//! turned at a crawl and the pivot turn ([`turning`]), and the fastest
//! steady turn on a circle ([`cornering`]).
//!
//! Every event is a function generic over [`Vehicle`](crate::vehicle::Vehicle),
//! driven by the vehicle's [`Powertrain`](crate::vehicle::Powertrain) through its own speed
//! controller ([`EventSettings`]): the engine, not per-vehicle code,
//! decides the speeds reached (the side slope, generic over
//! [`SpatialVehicleSystem`](crate::spatial_vehicle::SpatialVehicleSystem),
//! runs on the sides' speed drives: at a crawl across a slope the grip
//! is what is asked; the turns on them capped by the powertrain's
//! envelope, [`EngineEnvelope`](crate::spatial_vehicle::EngineEnvelope)).
//! A limit is found by bracketing and
//! bisection ([`search`]) and returned with the trials that found it; a
//! run that fails (the integrator gives up, the ride's rows are refused)
//! is an [`EventError::Run`], never taken for a limit, and a vehicle that
//! stops short of an obstacle's far side is a trial that did not pass,
//! with the distance it reached.

pub mod cornering;
mod error;
pub mod grade;
pub mod obstacle;
mod published;
pub mod quantity;
pub mod ride;
mod runs;
pub mod search;
pub mod side_slope;
pub mod soil;
mod stretch;
pub mod turning;

pub use error::EventError;
pub use published::{AGREEMENT, Comparison, Published};
pub use runs::{EventSettings, Footprint, STALL_DISTANCE, STALL_SPIN_UP, STALL_TIME};
