//! Why a vehicle could not be built: its track does not fit its wheels, or
//! its configuration makes no vehicle.

use thiserror::Error;

use super::{BrakeError, DriveError, PowertrainError};
use crate::assembly::AssemblyError;
use crate::closure::ClosureError;
use crate::laws::ParameterError;
use crate::multibody::PitchError;
use crate::terrain::TerrainError;
use crate::terrain::soil::SoilError;

/// A configuration that makes no vehicle ([`VehicleConfig`](super::VehicleConfig)
/// checked against the compiled model).
#[derive(Debug, Clone, PartialEq, Error)]
pub enum ConfigError {
    /// The link whose tension is recorded is not a link.
    #[error("tension_link {link} is not a link (1 to {links})")]
    TensionLink {
        /// The link asked for (numbered from 1).
        link: usize,
        /// The number of links.
        links: usize,
    },
    /// The terrain is invalid.
    #[error(transparent)]
    Terrain(#[from] TerrainError),
    /// The drive's settings make no controller.
    #[error(transparent)]
    Drive(#[from] DriveError),
    /// The powertrain's figures make no drive.
    #[error("powertrain: {0}")]
    Powertrain(#[from] PowertrainError),
    /// The brake's figures.
    #[error(transparent)]
    Brake(#[from] BrakeError),
    /// The arms configured are not one per arm of the chassis.
    #[error(
        "the configured arms act on bodies {configured:?}; the chassis has arms at bodies {declared:?}"
    )]
    Arms {
        /// The bodies of the configured arms, sorted.
        configured: Vec<usize>,
        /// The bodies of the chassis' arms, sorted.
        declared: Vec<usize>,
    },
    /// An arm's spring-damper has a rate out of range.
    #[error("the arm at body {body}: {source}")]
    Arm {
        /// The arm's body in the chassis tree.
        body: usize,
        /// Which rate, and its value.
        source: ParameterError,
    },
    /// A contact pair's law has a parameter out of range.
    #[error("the {pair} contact: {source}")]
    Contact {
        /// `ground`, `wheels` or `sprocket`.
        pair: &'static str,
        /// Which parameter, and its value.
        source: ParameterError,
    },
    /// The soil is invalid.
    #[error(transparent)]
    Soil(#[from] SoilError),
    /// Soft soil needs the track's width, which the declaration does not
    /// give.
    #[error("soft soil needs the track's width: declare `width` (m) in the vehicle's `shoe`")]
    NoTrackWidth,
    /// The declared hull is no convex outline (a declaration whose numbers
    /// the compiler could not check).
    #[error("the hull's outline: {0}")]
    Hull(trackgen_sprocket::OutlineProblem),
    /// The drawbar pull is not a number.
    #[error(transparent)]
    Drawbar(#[from] DrawbarError),
    /// The track's links differ in length where one pitch is assumed.
    #[error(transparent)]
    Pitch(#[from] PitchError),
    /// The sprocket profile's teeth are not the compiled sprocket's.
    #[error("the tooth profile has {profile} teeth; the declared sprocket has {declared}")]
    Teeth {
        /// The profile's count.
        profile: u32,
        /// The compiled count.
        declared: u32,
    },
    /// The sprocket's profile cannot drive the track (its gaps, or the
    /// shoes' pins in them), with what would.
    #[error(transparent)]
    Profile(#[from] crate::contact::sprocket::ProfileProblem),
    /// The loop cannot be closed as asked.
    #[error(transparent)]
    Closure(#[from] ClosureError),
}

/// Why [`build`](super::build) gave no vehicle.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum BuildError {
    /// No start could be assembled ([`assemble`](crate::assembly::assemble)).
    #[error(transparent)]
    Assembly(#[from] AssemblyError),
    /// The configuration was refused.
    #[error(transparent)]
    Config(#[from] ConfigError),
}

/// A drawbar pull that is not a number, in the plane or in space.
#[derive(Debug, Clone, Copy, PartialEq, Error)]
#[error("drawbar_pull {pull} N is not a finite number")]
pub struct DrawbarError {
    /// The pull, N.
    pub pull: f64,
}

impl DrawbarError {
    /// `pull` (N) if it is a finite number: a drawbar load (negative: a
    /// push). The one rule of a drawbar load, planar and spatial.
    pub fn check(pull: f64) -> Result<f64, DrawbarError> {
        if pull.is_finite() {
            Ok(pull)
        } else {
            Err(DrawbarError { pull })
        }
    }
}
