//! What a spatial run records at a state: one row of numbers, the same
//! for the applications' `spatial.csv` and the spatial FMU's outputs.

use super::SpatialOutputs;

/// The recorded columns after the time (`spatial.csv`'s, the spatial
/// FMU's outputs): SI units, angles in rad, sides `r_`
/// and `l_`; the engine's last (the whole engine's; the range from 1, −1
/// in reverse; `locked` 1 or 0), NaN unless an engine whose speed is a
/// state drives the differential.
pub const SPATIAL_COLUMNS: [&str; 55] = [
    "x",
    "y",
    "z",
    "heading",
    "pitch",
    "roll",
    "yaw_rate",
    "vx",
    "vy",
    "vz",
    "ax",
    "ay",
    "az",
    "lateral_acceleration",
    "turn_radius",
    "r_sprocket_speed",
    "r_sprocket_torque",
    "r_sprocket_power",
    "r_brake_torque",
    "r_brake_power",
    "r_belt_speed",
    "r_ground_speed",
    "r_slip",
    "r_track_speed",
    "r_ground_fx",
    "r_ground_fy",
    "r_ground_fz",
    "r_ground_yaw_moment",
    "r_tension_tight",
    "r_tension_slack",
    "r_tension_largest",
    "l_sprocket_speed",
    "l_sprocket_torque",
    "l_sprocket_power",
    "l_brake_torque",
    "l_brake_power",
    "l_belt_speed",
    "l_ground_speed",
    "l_slip",
    "l_track_speed",
    "l_ground_fx",
    "l_ground_fy",
    "l_ground_fz",
    "l_ground_yaw_moment",
    "l_tension_tight",
    "l_tension_slack",
    "l_tension_largest",
    "engine_speed",
    "engine_torque",
    "engine_power",
    "turbine_power",
    "gear",
    "speed_ratio",
    "torque_ratio",
    "locked",
];

/// One row of [`SPATIAL_COLUMNS`] from what the vehicle shows.
pub fn spatial_row(out: &SpatialOutputs) -> [f64; SPATIAL_COLUMNS.len()] {
    let c = &out.centre;
    let mut row = vec![
        c.position.x,
        c.position.y,
        c.position.z,
        out.heading,
        out.pitch,
        out.roll,
        out.yaw_rate,
        c.velocity.x,
        c.velocity.y,
        c.velocity.z,
        out.acceleration.x,
        out.acceleration.y,
        out.acceleration.z,
        out.lateral_acceleration,
        out.turn_radius,
    ];
    for side in &out.sides {
        row.extend([
            side.sprocket_speed,
            side.sprocket_torque,
            side.sprocket_power,
            side.brake_torque,
            side.brake_power,
            side.belt_speed,
            side.ground_speed,
            side.slip,
            side.track_speed,
            side.ground_force.x,
            side.ground_force.y,
            side.ground_force.z,
            side.ground_yaw_moment,
            side.tensions.tight,
            side.tensions.slack,
            side.tensions.largest,
        ]);
    }
    row.extend(match out.engine {
        Some(e) => [
            e.engine_speed,
            e.engine_torque,
            e.engine_power,
            e.turbine_power,
            out.gear,
            e.speed_ratio,
            e.torque_ratio,
            f64::from(u8::from(e.locked == Some(true))),
        ],
        None => [f64::NAN; 8],
    });
    row.try_into().expect("one value per column")
}
