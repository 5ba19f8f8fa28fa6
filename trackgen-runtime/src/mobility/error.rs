//! Why an event gave no answer.

use thiserror::Error;

use crate::simulate::RunError;
use crate::terrain::profile::ProfileError;
use crate::terrain::roughness::RoughnessError;
use crate::vehicle::{BuildError, PowertrainError};

/// An event that could not be answered. A run's failure says which event,
/// at which parameter, when and why: it is never a limit.
#[derive(Debug, Error)]
pub enum EventError {
    /// A setting or a parameter out of its range.
    #[error("{event}: {what} must be {range}, got {value}")]
    Setting {
        /// The event: `ride`, `half-round`, `step`, `gap`, `ditch`,
        /// `barrier`, `grade`, `side-slope`, `turning` or `cornering`.
        event: &'static str,
        /// The setting.
        what: &'static str,
        /// Its allowed range, in words with its unit.
        range: &'static str,
        /// What was given.
        value: f64,
    },
    /// The settings' powertrain gives no drive.
    #[error("{event}: {source}")]
    Powertrain {
        /// The event.
        event: &'static str,
        /// Why.
        #[source]
        source: PowertrainError,
    },
    /// The vehicle does not build on the event's course.
    #[error("{event}: the vehicle does not build: {source}")]
    Build {
        /// The event.
        event: &'static str,
        /// Why.
        #[source]
        source: BuildError,
    },
    /// The event's course could not be laid.
    #[error("{event}: the course could not be laid: {source}")]
    Course {
        /// The event.
        event: &'static str,
        /// Why.
        #[source]
        source: ProfileError,
    },
    /// The event's random course could not be made.
    #[error("{event}: the random course could not be made: {source}")]
    Roughness {
        /// The event.
        event: &'static str,
        /// Why.
        #[source]
        source: RoughnessError,
    },
    /// The vehicle stalled where the event asks for a speed (on a ride
    /// course, on a half-round): it did not get over, which is neither a
    /// pass nor a speed limit.
    #[error("{event}: the vehicle stalled at {parameter} {unit}, the hull at x = {reached} m")]
    Stalled {
        /// The event.
        event: &'static str,
        /// The speed asked.
        parameter: f64,
        /// Its unit.
        unit: &'static str,
        /// How far the hull got, m.
        reached: f64,
    },
    /// The spatial vehicle could not be set up for the event: its laws,
    /// its assembly, its drives or its driver refused.
    #[error("{event}: the spatial vehicle could not be set up: {source}")]
    Spatial {
        /// The event.
        event: &'static str,
        /// Why.
        #[source]
        source: Box<dyn std::error::Error + Send + Sync>,
    },
    /// A run failed: the integrator gave up, or a sink refused a row.
    #[error("{event}: the run at {parameter} {unit} failed at t = {time} s: {source}")]
    Run {
        /// The event.
        event: &'static str,
        /// The parameter of the failed run.
        parameter: f64,
        /// Its unit.
        unit: &'static str,
        /// When the run stopped, s (NaN if unknown).
        time: f64,
        /// Why.
        #[source]
        source: Box<RunError>,
    },
}
