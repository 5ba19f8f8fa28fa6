//! `spatial --driveline`'s choices, as the command line lists them: the
//! runtime's [`DrivelineKind`](trackgen::spatial_vehicle::DrivelineKind)
//! (`trackgen::spatial_vehicle::asked_driveline` builds the driveline).

use trackgen::spatial_vehicle::DrivelineKind as Kind;

/// How the drive reaches the sprockets.
#[derive(clap::ValueEnum, Clone, Copy, Debug, PartialEq, Eq)]
pub enum DrivelineKind {
    /// A speed controller on each sprocket (the vehicle's declared
    /// gains), the driver moving their targets apart.
    Sides,
    /// One speed controller on a differential (twice a side's gains and
    /// limit), the driver braking the inner sprocket.
    Brakes,
    /// One speed controller on a differential with a steer unit holding
    /// the sprockets' speed ratio, at most `--steer-ratio`.
    SteerRatio,
    /// The differential in neutral (`--speed 0`: its box held at rest),
    /// its steer unit turning the sprockets apart at the steer drive's
    /// speed with the engine at its rated speed: a pivot about the
    /// vehicle's centre (the X200-4's; the vehicle's published steer
    /// ratios and its converter powertrain's ranges give the steer
    /// drive's ratio).
    NeutralPivot,
}

impl From<DrivelineKind> for Kind {
    fn from(kind: DrivelineKind) -> Kind {
        match kind {
            DrivelineKind::Sides => Kind::Sides,
            DrivelineKind::Brakes => Kind::Brakes,
            DrivelineKind::SteerRatio => Kind::SteerRatio,
            DrivelineKind::NeutralPivot => Kind::NeutralPivot,
        }
    }
}
