//! What a vehicle's equations tell beyond a forward run: the Jacobian of
//! its right-hand side ([`state_jacobian`]), where it rests
//! ([`equilibrium`]), its linearisation there and the modes it vibrates in
//! ([`modes`]), and how its rest changes with a spring rate
//! ([`equilibrium_sensitivity`]); the spatial vehicle's rest and modes
//! ([`settle`], [`spatial_modes`]).
//!
//! The state Jacobian is taken by central differences of the compiled
//! right-hand side (each column two evaluations, the step stated in
//! [`state_jacobian`]); the track's and the chassis' own derivatives are
//! exact ([`crate::dynamics::derivative`]) and checked against Pinocchio's.

mod equilibrium;
mod error;
mod jacobian;
mod modes;
mod sensitivity;
mod spatial_modes;
mod statics;

pub use equilibrium::{Equilibrium, EquilibriumOptions, equilibrium};
pub use error::AnalysisError;
pub use jacobian::{state_jacobian, step_for};
pub use modes::{Mode, Share, linearise, mode_of, modes};
pub use sensitivity::{ArmSensitivity, equilibrium_sensitivity};
pub use spatial_modes::{SpatialMode, SpatialRest, settle, spatial_mode_of, spatial_modes};
