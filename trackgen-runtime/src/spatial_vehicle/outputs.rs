//! What a spatial run shows at a state, as a vehicle engineer reads a
//! turn: the hull's heading, pitch, roll and yaw rate, the centre of mass's motion and
//! acceleration (lateral in the hull's heading), the radius of its path,
//! and per side the sprocket's speed, torque and power, the brake's
//! torque and power, the belt's speed,
//! the track's slip and its own speed round the hull, the ground's
//! force and yaw moment on the track, and the track's tensions.

use crate::vehicle::EngineSide;
use nalgebra::Vector3;

use super::{MassCentre, SpatialSystem, TrackTensions};
use crate::integrate::SimulationError;
use crate::multibody::{ChassisModel, TrackModel};

/// One side's drive and ground at a state.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SideOutputs {
    /// The sprocket's speed relative to the frame, rad/s (planar sense:
    /// driving forward turns it negative).
    pub sprocket_speed: f64,
    /// The driveline's torque on it, N m (planar sense): the drive's, the
    /// steer unit's and the brake's.
    pub sprocket_torque: f64,
    /// The driveline's power into it, W: torque times speed.
    pub sprocket_power: f64,
    /// The steering brake's part of the torque, N m (0 without brakes).
    pub brake_torque: f64,
    /// The brake's power, W: its torque times the speed (never positive
    /// while it slips; what its elastic stage stores and gives back while
    /// it holds).
    pub brake_power: f64,
    /// The belt's speed, m/s: how fast the ground run moves rearward
    /// along the hull, the sprocket's speed times its rolling radius
    /// (forward driving positive).
    pub belt_speed: f64,
    /// The speed of the track's centre line over the ground along the
    /// hull's heading, m/s: the centre of mass's, less the yaw rate times
    /// the track's lateral place from it (the links' centroid, to the
    /// left positive).
    pub ground_speed: f64,
    /// The slip `1 − v/u` (`v` the ground speed, `u` the belt's):
    /// positive driving, negative skidding, NaN where the belt stands.
    /// It counts the track sliding on the ground and the sprocket jumping
    /// the track's teeth alike: [`track_speed`](Self::track_speed) tells
    /// them apart.
    pub slip: f64,
    /// How fast the track runs rearward under the hull at its patch on
    /// the ground, m/s: the ground speed less the patch's own speed along
    /// the hull's heading (its links' velocities weighed by their ground
    /// load). The belt's speed while the sprocket holds the track's
    /// teeth, less while it jumps them; the ground speed while the patch
    /// grips. NaN with nothing on the ground.
    pub track_speed: f64,
    /// The ground's force on the track, N (world axes).
    pub ground_force: Vector3<f64>,
    /// The ground's moment on the track about the vertical through the
    /// centre of mass, N m (counter-clockwise seen from above).
    pub ground_yaw_moment: f64,
    /// The track's tensions: either side of the sprocket, and the
    /// largest.
    pub tensions: TrackTensions,
}

/// What the vehicle shows at a state ([`SpatialSystem::outputs`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SpatialOutputs {
    /// The hull's heading (its plane's yaw), rad.
    pub heading: f64,
    /// The frame's pitch in the hull's plane, rad (nose up positive).
    pub pitch: f64,
    /// The hull's plane's roll about its heading, rad (the left side up
    /// positive, a turn right about the forward axis).
    pub roll: f64,
    /// The hull's rate of turning about the vertical, rad/s (to the left
    /// positive).
    pub yaw_rate: f64,
    /// The centre of mass: where, how fast.
    pub centre: MassCentre,
    /// The centre of mass's acceleration, m/s² (world axes): the ground's
    /// force over the mass, plus gravity (the only other external force).
    pub acceleration: Vector3<f64>,
    /// Its component to the hull's left in the horizontal plane, m/s².
    pub lateral_acceleration: f64,
    /// The radius of the centre of mass's path, m: its horizontal speed
    /// over the yaw rate's size (infinite driving straight).
    pub turn_radius: f64,
    /// The right side's, then the left's.
    pub sides: [SideOutputs; 2],
    /// The engine's side where an engine whose speed is a state drives
    /// the differential: its speed, torque, range, lock-up, converter and
    /// powers (the whole engine's).
    pub engine: Option<EngineSide>,
    /// Its range as a run records it
    /// ([`Driveline::gear_number`](crate::vehicle::Driveline::gear_number):
    /// from 1, −1 in reverse); NaN without such an engine.
    pub gear: f64,
}

impl<H, const DH: usize, R, const DR: usize, L, const DL: usize>
    SpatialSystem<'_, H, DH, R, DR, L, DL>
where
    H: ChassisModel<DH>,
    R: TrackModel<DR>,
    L: TrackModel<DL>,
{
    /// What the vehicle shows at time `t` and state `y`; a drive whose
    /// demand is not finite is the run's error, as in the run
    /// ([`drive_state`](Self::drive_state)).
    pub fn outputs(&self, t: f64, y: &[f64]) -> Result<SpatialOutputs, SimulationError> {
        let (hull, ..) = self.states(y);
        let d = &self.dynamics;
        let drive = d.drive(t, &hull, self.driver(y))?;
        // One evaluation of the right-hand side: every body in the world
        // once, for the centre of mass, the hull's yaw rate, the ground's
        // forces and the patches' speeds, and the joint forces the
        // tensions are read from.
        let (scratch, motions) = self.evaluated(t, y)?;
        let tensions = self.tensions_in(&scratch, &motions);
        let bodies = &scratch.bodies;
        let centre = d.mass_centre_of(bodies);
        let heading = hull.pose.yaw;
        let yaw_rate = bodies[0].spin(0).z;
        let (forward, leftward) = (
            Vector3::new(heading.cos(), heading.sin(), 0.0),
            Vector3::new(-heading.sin(), heading.cos(), 0.0),
        );
        let mut force = [Vector3::zeros(); 2];
        let mut moment = [0.0; 2];
        let links = [bodies[1].velocities(), bodies[2].velocities()];
        // The patch's speed along the heading, times the load, and the load.
        let mut patch = [(0.0, 0.0); 2];
        for point in d.ground_forces_of([&bodies[1], &bodies[2]], self.deflections(y)) {
            let s = point.side.index();
            let arm = point.at - centre.position;
            force[s] += point.force;
            moment[s] += arm.x * point.force.y - arm.y * point.force.x;
            patch[s].0 += links[s][point.link].dot(&forward) * point.force.z;
            patch[s].1 += point.force.z;
        }
        let lateral = [
            lateral_place(bodies[1].centroids(), d.right.masses(), &centre, &leftward),
            lateral_place(bodies[2].centroids(), d.left.masses(), &centre, &leftward),
        ];
        let along = centre.velocity.dot(&forward);
        let sides = [0, 1].map(|s| {
            let (speed, torque) = (drive.speed[s], drive.torque[s]);
            let belt_speed = d.sprockets[s].map_or(0.0, |p| -speed * p.rolling_radius);
            let ground_speed = along - yaw_rate * lateral[s];
            SideOutputs {
                sprocket_speed: speed,
                sprocket_torque: torque,
                sprocket_power: torque * speed,
                brake_torque: drive.brake[s],
                brake_power: drive.brake[s] * speed,
                belt_speed,
                ground_speed,
                slip: if belt_speed == 0.0 {
                    f64::NAN
                } else {
                    1.0 - ground_speed / belt_speed
                },
                track_speed: ground_speed - patch[s].0 / patch[s].1,
                ground_force: force[s],
                ground_yaw_moment: moment[s],
                tensions: tensions[s],
            }
        });
        let gravity = Vector3::new(0.0, 0.0, -d.hull.gravity());
        let acceleration = (force[0] + force[1]) / centre.mass + gravity;
        let horizontal = centre.velocity.xy().norm();
        Ok(SpatialOutputs {
            heading,
            pitch: hull.pose.planar[2],
            roll: hull.pose.roll,
            yaw_rate,
            centre,
            acceleration,
            lateral_acceleration: acceleration.dot(&leftward),
            turn_radius: horizontal / yaw_rate.abs(),
            sides,
            engine: drive.engine,
            gear: match (drive.engine, self.engine()) {
                (Some(side), Some(engine)) => engine.driveline().gear_number(side.gear),
                _ => f64::NAN,
            },
        })
    }
}

/// A track's mass-weighted centroid's place to the hull's left of the
/// centre of mass, m.
fn lateral_place(
    at: &[Vector3<f64>],
    masses: &[f64],
    centre: &MassCentre,
    leftward: &Vector3<f64>,
) -> f64 {
    let mass: f64 = masses.iter().sum();
    let weighted: Vector3<f64> = at.iter().zip(masses).map(|(p, m)| *m * p).sum();
    (weighted / mass - centre.position).dot(leftward)
}
