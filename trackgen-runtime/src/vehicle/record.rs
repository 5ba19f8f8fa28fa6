//! What a vehicle records, by name and value together, and the spans'
//! tensions it reads off the sprocket.

use nalgebra::Vector2;

use crate::contact::BodyState;
use crate::system::record;

record! {
    /// What a vehicle records at each output time, after its track's and
    /// chassis' own columns (`track.…`, `chassis.…`).
    pub struct VehicleRecord {
        /// Chassis centroid x, m.
        x,
        /// Chassis centroid y, m.
        y,
        /// Chassis pitch, rad (counter-clockwise: nose up driving forward).
        pitch,
        /// Chassis centroid speed along x, m/s.
        speed,
        /// Sprocket speed relative to the chassis, rad/s (negative driving
        /// forward).
        sprocket_speed,
        /// The track's mean speed relative to the chassis, m/s (positive
        /// driving forward): one pitch per tooth,
        /// [`track_speed`](crate::contact::sprocket::track_speed). A track
        /// that does not slip carries the chassis at this speed; the slip
        /// is [`slip`](super::slip)`(speed, track_speed)`.
        track_speed,
        /// The drive's torque on the sprocket, N m.
        sprocket_torque,
        /// The drive's torque over the most the powertrain gives at the
        /// sprocket's speed ([`Powertrain::limit`](super::Powertrain::limit)):
        /// 1 at full load, where the engine, not the controller, sets the
        /// speed; 0 without a powertrain.
        engine_load,
        /// Tension in the joint after the configured link, N.
        tension,
        /// Tension in the span leaving the sprocket's seated run on the
        /// tight side, N.
        tension_tight,
        /// Tension on the slack side, N.
        tension_slack,
        /// The ground's normal force on the track, N.
        ground_normal,
        /// The deepest ground contact, m.
        ground_penetration,
        /// The deepest rim contact, m.
        wheel_penetration,
        /// The deepest tooth contact, m.
        sprocket_penetration,
        /// The ground's normal force on the hull, N (0 without a declared
        /// hull, or clear of the ground).
        hull_normal,
        /// The deepest hull contact, m: a hull corner below the ground, or
        /// a terrain corner inside the hull.
        hull_penetration,
        /// Mechanical energy: kinetic, gravity, springs, contacts, J.
        energy,
        /// The motor's work since the start, J.
        motor_work,
        /// The work dissipated since the start, J.
        dissipated,
        /// This side's share of the engine's work since the start, J: the
        /// motor's work plus what the converter and the gears lost on the
        /// way ([`Powertrain::engine_side`](super::Powertrain::engine_side));
        /// the motor's work itself without a powertrain.
        engine_work,
        /// This side's share of the engine's power, W (0 while the drive
        /// brakes).
        engine_power,
        /// This side's share of the converter's output power (the
        /// turbine's), W; the engine's without a converter.
        turbine_power,
        /// The engine's speed, rad/s (0 where the powertrain defines none,
        /// or the engine gives nothing: without a powertrain, with a
        /// power limit, or braking).
        engine_speed,
        /// The engine's torque, N m (the whole engine's; 0 as
        /// `engine_speed`).
        engine_torque,
        /// The gear or range engaged, numbered from 1, −1 in reverse (0
        /// without gears):
        /// while a shift takes its time, the range whose torque the
        /// sprocket gets (the lesser of the two).
        gear,
        /// The converter's speed ratio, turbine over pump (1 locked; 0
        /// without a converter, as the next two).
        speed_ratio,
        /// The converter's torque ratio, turbine over pump (1 locked).
        torque_ratio,
        /// The converter's efficiency, `speed_ratio · torque_ratio`.
        converter_efficiency,
        /// 1 with the converter's lock-up clutch engaged, else 0.
        locked,
        /// The driver's seat ([`ChassisModel::SEAT`](crate::multibody::ChassisModel::SEAT)),
        /// x, m.
        seat_x,
        /// The seat's y, m.
        seat_y,
        /// The seat's acceleration along the frame's x axis (forward), m/s²:
        /// kinematic, `R̈ + θ̈ ⟂(A s̄) − θ̇² A s̄` turned into the frame's axes
        /// (zero at rest: gravity is not in it).
        seat_ax,
        /// The seat's acceleration along the frame's y axis (up), m/s².
        seat_az,
    }
}

/// How far a joint may sit from the sprocket's pitch circle and count as
/// seated in a gap, m.
const SEATED: f64 = 0.02;

/// The joints just before and just after the run of joints seated on the
/// sprocket (within [`SEATED`] of its pitch circle), in link order; when
/// none is (the track has jumped the teeth), the joint nearest the pitch
/// circle stands for the run, so that a run that goes on has span
/// tensions to record. `None` only if every joint is seated. The loop is
/// numbered counter-clockwise and runs clockwise round the chassis when
/// driving forward, so the joint after the seated run is on the tight
/// span (the top run, pulled into the sprocket) and the one before it on
/// the slack span.
///
/// `links` are the links' states, `forward_joints` every link's `ū2`,
/// `centre` and `radius` the sprocket's centre and pitch radius (m);
/// `offsets` is scratch (one per link).
pub(super) fn sprocket_spans(
    links: &[BodyState],
    forward_joints: &[Vector2<f64>],
    (centre, radius): (Vector2<f64>, f64),
    offsets: &mut Vec<f64>,
) -> Option<(usize, usize)> {
    offsets.clear();
    offsets.extend(
        links
            .iter()
            .zip(forward_joints)
            .map(|(link, u2)| ((link.point(*u2) - centre).norm() - radius).abs()),
    );
    seated_run(offsets)
}

/// [`sprocket_spans`] from each joint's distance to the sprocket's pitch
/// circle, m (`offsets`, in link order; joint `j` the one ahead of link
/// `j`): the one owner of the seating rule, in the plane and in space.
pub(crate) fn seated_run(offsets: &[f64]) -> Option<(usize, usize)> {
    let n = offsets.len();
    let nearest = offsets.iter().copied().fold(f64::INFINITY, f64::min);
    let seated = |j: usize| offsets[j] < SEATED || offsets[j] <= nearest;
    let first = (0..n).find(|&j| seated(j) && !seated((j + n - 1) % n))?;
    let last = (0..n)
        .map(|k| (first + k) % n)
        .take_while(|&j| seated(j))
        .last()?;
    Some(((first + n - 1) % n, (last + 1) % n))
}
