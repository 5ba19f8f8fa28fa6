//! A vehicle in motion: track and chassis coupled by contact (formulation §3-4),
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
mod books;
mod brake;
mod config;
mod converter;
mod declared;
mod drive;
mod engine;
mod engine_drive;
mod engine_state;
mod error;
mod fitted;
mod forces;
mod geometry;
mod implicit;
mod jacobian;
mod layout;
mod linearisation;
mod powertrain;
mod powertrain_error;
mod record;
mod shift;
mod system;
mod tables;
mod workspace;

pub use brake::{Brake, BrakeError};
pub use config::VehicleConfig;
pub use converter::{Driveline, OperatingPoint};
pub use declared::{Vehicle, VehicleDynamics, build};
pub use drive::{Drive, DriveError, DriveSlopes, TorqueCap, speed_ramp};
pub use engine::EngineDynamics;
pub(crate) use engine_drive::{AtSprocket, engine_drive};
pub use engine_state::{
    COUPLING_BAND, EngineState, IDEAL_DOWNSHIFT, IDEAL_SHIFT_TIME, LOCKUP_RELEASE,
};
pub use error::{BuildError, ConfigError, DrawbarError};
pub use fitted::{
    BEARING_BAND, ContactFit, ContactLawSet, DeclaredContact, DeclaredPair, GROUND_DAMPING_RATIO,
    GROUND_DEPTH, GROUND_MU, RIM_DAMPING_RATIO, RIM_DEPTH, RIM_FRICTION_RATE, RIM_MU,
    TANGENTIAL_DAMPING_RATIO,
};
pub use geometry::Geometry;
pub use layout::StateLayout;
pub use powertrain::{EngineSide, Powertrain};
pub use powertrain_error::PowertrainError;
pub use record::VehicleRecord;
pub(crate) use record::seated_run;
pub use shift::{Engaged, Shift};
pub use system::VehicleSystem;

/// The slip of a track driving at `track_speed` (m/s, its mean speed,
/// [`track_speed`](crate::contact::sprocket::track_speed)) under a hull
/// moving at `speed` (m/s): `1 − v / v_t`, 0 for a track that carries the
/// hull at its own speed, positive when the track spins faster (driving),
/// negative when the hull outruns it. NaN for a track at rest.
pub fn slip(speed: f64, track_speed: f64) -> f64 {
    if track_speed == 0.0 {
        f64::NAN
    } else {
        1.0 - speed / track_speed
    }
}
