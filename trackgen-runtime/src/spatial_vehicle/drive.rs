//! Each side's sprocket drive: the planar vehicle's [`Drive`] per side
//! (a torque schedule, or a speed controller tracking a belt speed), its
//! torque acting on the side's sprocket about its axle and, reversed, on
//! the frame. Two drives commanded apart steer the vehicle by skid
//! steering, as a robot's independent sprocket motors do.
//!
//! A planar torque `τ` (counter-clockwise in the track's plane seen from
//! the right, positive) is the moment `−τ η` in space, `η` the plane's
//! normal pointing left (as the arms' springs, `spatial_vehicle`'s
//! docs); its power on the sprocket and the frame together is `τ ω`,
//! `ω` the sprocket's speed relative to the frame, the planar vehicle's.

use nalgebra::Vector3;

use super::{HeadingHold, SpatialDynamics, SpatialLoads, TreeState};
use crate::integrate::SimulationError;
use crate::multibody::{ChassisModel, TrackModel};
use crate::spatial::plane_rotation;
use crate::vehicle::{Drive, DriveError, TorqueCap};

/// The two sprockets' drives.
pub struct SideDrives {
    /// The right sprocket's.
    pub right: Drive,
    /// The left sprocket's.
    pub left: Drive,
}

impl SideDrives {
    /// Both sprockets free.
    pub fn free() -> SideDrives {
        SideDrives {
            right: Drive::Free,
            left: Drive::Free,
        }
    }

    /// Why either drive's settings make no controller
    /// ([`Drive::check`]).
    pub fn check(&self) -> Result<(), DriveError> {
        self.right.check()?;
        self.left.check()
    }

    /// The drives right then left.
    pub(super) fn each(&self) -> [&Drive; 2] {
        [&self.right, &self.left]
    }
}

/// What the drives do at a state: per side (right, left).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct DriveState {
    /// The sprocket's speed relative to the frame, rad/s (planar sense:
    /// driving forward turns it negative).
    pub speed: [f64; 2],
    /// The drive's torque on it, N m (planar sense).
    pub torque: [f64; 2],
    /// Each speed controller's integral's rate, rad/s.
    pub integral_rate: [f64; 2],
}

impl DriveState {
    /// The power the drives put in, W: `Σ τ ω`.
    pub fn power(&self) -> f64 {
        self.torque[0] * self.speed[0] + self.torque[1] * self.speed[1]
    }
}

impl<H, const DH: usize, R, const DR: usize, L, const DL: usize>
    SpatialDynamics<'_, H, DH, R, DR, L, DL>
where
    H: ChassisModel<DH>,
    R: TrackModel<DR>,
    L: TrackModel<DL>,
{
    /// What the drives do at time `t` and the hull's state, with each
    /// controller's `integrals` (rad, right then left) and the driver's
    /// `steering`, if any (the right belt's target `+Δu/2`, the left's
    /// `−Δu/2`, [`HeadingHold::difference`]): a side without a sprocket
    /// takes no torque; a drive's demand or a heading wanted that is not
    /// finite stops the run ([`Drive::checked_torque`]).
    pub fn drive(
        &self,
        t: f64,
        hull: &TreeState<DH>,
        (drives, steering, integrals): (&SideDrives, Option<&HeadingHold>, [f64; 2]),
    ) -> Result<DriveState, SimulationError> {
        let qd = &hull.rates.planar;
        let difference = match steering {
            None => 0.0,
            Some(hold) => {
                hold.difference(t, hull.pose.yaw, self.gauge)
                    .ok_or(SimulationError::NonFinite {
                        t,
                        what: "the steering's heading",
                    })?
            }
        };
        let mut state = DriveState::default();
        for (s, drive) in drives.each().into_iter().enumerate() {
            let Some(sprocket) = self.sprockets[s] else {
                continue;
            };
            let omega = qd[2 + sprocket.body] - qd[2];
            // Right (index 0) outside in a left turn.
            let trim = [0.5, -0.5][s] * difference;
            let (torque, rate) = drive.checked_torque_trimmed(
                (t, trim),
                omega,
                sprocket.rolling_radius,
                integrals[s],
                TorqueCap::NONE,
            )?;
            state.speed[s] = omega;
            state.torque[s] = torque;
            state.integral_rate[s] = rate;
        }
        Ok(state)
    }

    /// The drives' torques (`drive`'s) added to the sprockets' and the
    /// frame's `loads`.
    pub fn apply_drive(&self, hull: &TreeState<DH>, drive: &DriveState, loads: &mut SpatialLoads) {
        let eta: Vector3<f64> = plane_rotation(hull.pose.yaw, hull.pose.roll)
            .column(1)
            .into();
        for (s, sprocket) in self.sprockets.iter().enumerate() {
            if let Some(sprocket) = sprocket {
                loads.hull[sprocket.body].moment -= eta * drive.torque[s];
                loads.hull[0].moment += eta * drive.torque[s];
            }
        }
    }
}
