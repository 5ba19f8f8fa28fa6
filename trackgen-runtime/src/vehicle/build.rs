//! Why a vehicle could not be built from its configuration.

use thiserror::Error;

use crate::assembly::AssemblyError;
use crate::simulate::SimulationError;

/// The error of a declared vehicle's one-call constructor
/// (`Name::system`, `Name::system_with`): its track does not fit its
/// wheels, or the configuration makes no vehicle.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum BuildError {
    /// No start could be assembled ([`assemble`](super::assemble)).
    #[error(transparent)]
    Assembly(#[from] AssemblyError),
    /// The configuration was refused ([`VehicleSystem::new`](super::VehicleSystem::new):
    /// a [`SimulationError::Setup`]).
    #[error(transparent)]
    Setup(#[from] SimulationError),
}
