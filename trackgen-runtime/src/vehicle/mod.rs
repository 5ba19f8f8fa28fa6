//! A vehicle in motion: track and chassis coupled by contact (spec §3-4),
//! sprung arms, a sprocket drive, on rigid ground or soft soil.
//!
//! * [`Vehicle`]: a declared vehicle as a type; [`build`] makes any of them
//!   from a [`VehicleConfig`] by one recipe, and [`VehicleDynamics`] is what
//!   any of them offers in motion.
//! * [`VehicleSystem`]: the evaluation, in stages over a long-lived
//!   workspace (rapier's shape): kinematics (every body's state, its
//!   rotation computed once) → contact detection → force elements (each
//!   contact law, the arms, the drive, the drawbar, the soil: each gives
//!   its load with the energy it stores and the power it dissipates, so
//!   the energy books balance by construction) → dynamics (the track's and
//!   the chassis' generated O(n) solves).

pub mod arms;
mod config;
mod declared;
mod drive;
mod error;
mod forces;
mod record;
mod system;
mod workspace;

pub use config::VehicleConfig;
pub use declared::{Geometry, Vehicle, VehicleDynamics, build};
pub use drive::{Drive, DriveError};
pub use error::{BuildError, ConfigError};
pub use record::VehicleRecord;
pub use system::VehicleSystem;
