//! A vehicle in motion: track and chassis coupled by contact (spec §3-4),
//! sprung arms, a sprocket drive, on a terrain.

mod assemble;
mod build;
mod config;
mod drive;
mod system;

pub use assemble::{Assembled, START_PENETRATION, assemble};
pub use build::BuildError;
pub use config::VehicleConfig;
pub use drive::Drive;
pub use system::VehicleSystem;
