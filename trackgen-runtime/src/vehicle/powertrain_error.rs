//! What makes a powertrain's figures give no drive.

use thiserror::Error;

/// A powertrain that gives no drive.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum PowertrainError {
    /// A power or torque limit not finite and positive.
    #[error("the powertrain's {what} must be finite and more than 0, got {value}")]
    Limit {
        /// Which: `power` or `max_torque`.
        what: &'static str,
        /// What was given.
        value: f64,
    },
    /// No gears, or a ratio not finite and positive.
    #[error("the gearbox needs ratios finite and more than 0 (gear {gear}: {ratio})")]
    Ratio {
        /// The gear (0-based).
        gear: usize,
        /// Its ratio.
        ratio: f64,
    },
    /// A fraction outside (0, 1].
    #[error("the driveline's fraction must be in (0, 1], got {0}")]
    Fraction(f64),
    /// A table (the engine's full-load torque, the converter's capacity
    /// factor or torque ratio) of fewer than two points, or with its axis
    /// not increasing from a value ≥ 0 (the engine's from one > 0), or a
    /// value not finite or out of its range (`K > 0`, `TR ≥ 0`).
    #[error(
        "the {what} table needs two or more finite points of increasing abscissa, each value in range (at point {point})"
    )]
    Table {
        /// Which table.
        what: &'static str,
        /// The offending point (0-based).
        point: usize,
    },
    /// A converter map whose first point is not at speed ratio 0 (stall).
    #[error("the converter's {what} map must start at speed ratio 0 (stall), not {first}")]
    ConverterStart {
        /// Which map: `capacity factor` or `torque ratio`.
        what: &'static str,
        /// Its first speed ratio.
        first: f64,
    },
    /// A point of the torque-ratio map where the converter would give more
    /// power than it takes (`SR · TR > 1`).
    #[error(
        "the converter's efficiency SR·TR is {efficiency} at torque-ratio point {point}: more than 1"
    )]
    ConverterEfficiency {
        /// The point (0-based).
        point: usize,
        /// Its `SR · TR`.
        efficiency: f64,
    },
    /// A final drive's reduction not finite and more than 0.
    #[error("the final drive's reduction must be finite and more than 0, got {0}")]
    FinalDrive(f64),
    /// A lock-up range that is not one of the gearbox's.
    #[error("lock-up in range {range} (0-based), but the gearbox has {ranges} ranges")]
    LockupRange {
        /// The range named.
        range: usize,
        /// How many there are.
        ranges: usize,
    },
    /// A lock-up speed ratio outside (0, 1].
    #[error("the lock-up clutch's speed ratio must be in (0, 1], got {0}")]
    LockupSpeedRatio(f64),
    /// A shift schedule's figure out of its range: a speed list not one
    /// per range, a speed not finite or below 0, a downshift speed at or
    /// above its range's upshift speed or above where the upshift before
    /// it lands (the gearbox would hunt), a shift time below 0.
    #[error("the shift schedule's {what} for range {range} (0-based) is out of its range")]
    Shift {
        /// The range (0-based).
        range: usize,
        /// Which figure, and why.
        what: &'static str,
    },
    /// Minimum steer ratios that are not one per forward range.
    #[error("{count} minimum steer ratios for {ranges} ranges: one per range is needed")]
    SteerRatios {
        /// How many ratios.
        count: usize,
        /// How many ranges.
        ranges: usize,
    },
    /// A minimum steer ratio not finite and more than 1 (at 1 the sprockets
    /// turn alike: no steer).
    #[error(
        "range {range}'s (0-based) minimum steer ratio must be finite and more than 1, got {ratio}"
    )]
    SteerRatio {
        /// The range (0-based).
        range: usize,
        /// Its ratio.
        ratio: f64,
    },
    /// A stage's efficiency or the side's share outside (0, 1].
    #[error("the driveline's {what} must be in (0, 1], got {value}")]
    Stage {
        /// Which: `gearbox_efficiency`, `final_drive_efficiency` or `share`.
        what: &'static str,
        /// What was given.
        value: f64,
    },
}
