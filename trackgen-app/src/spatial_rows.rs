//! What `spatial` records: the rows of `spatial.csv` (the vehicle's
//! motion, and each side's drive, ground and tensions) and of
//! `spatial.arrow` (the same, then the ground's force on every shoe).

use trackgen::spatial_vehicle::{GroundForce, SpatialOutputs};

/// The CSV's columns after the time: SI units, angles in rad, sides `r_`
/// and `l_`; the engine's last (the whole engine's; the range from 1, −1
/// in reverse; `locked` 1 or 0), NaN unless an engine whose speed is a
/// state drives the differential (`--engine`).
pub const COLUMNS: [&str; 55] = [
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

/// One row of [`COLUMNS`].
pub fn record(out: &SpatialOutputs) -> [f64; COLUMNS.len()] {
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

/// The columns `spatial.arrow` adds after [`COLUMNS`]: the ground's force
/// on every shoe, N (world axes), the right track's links then the
/// left's, each numbered from 1 as the declaration numbers its links
/// (`r_shoe_1_fx`, `r_shoe_1_fy`, `r_shoe_1_fz`, …).
pub fn shoe_columns((right, left): (usize, usize)) -> Vec<String> {
    let side = |prefix: &'static str, links: usize| {
        (1..=links)
            .flat_map(move |k| ["fx", "fy", "fz"].map(|axis| format!("{prefix}_shoe_{k}_{axis}")))
    };
    side("r", right).chain(side("l", left)).collect()
}

/// The ground's force on every shoe from its points' `forces`, appended
/// to `row` in [`shoe_columns`]' order (`shoes` links right and left).
pub fn shoe_forces(forces: &[GroundForce], (right, left): (usize, usize), row: &mut Vec<f64>) {
    let start = row.len();
    row.resize(start + 3 * (right + left), 0.0);
    for point in forces {
        let first = match point.side.index() {
            0 => start,
            _ => start + 3 * right,
        };
        let at = first + 3 * point.link;
        for i in 0..3 {
            row[at + i] += point.force[i];
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use trackgen::nalgebra::Vector3;
    use trackgen::spatial::Side;

    /// Each point's force lands on its own side's and link's three
    /// columns, points of one link summed, the row's start kept.
    #[test]
    fn each_point_lands_on_its_shoes_columns() {
        let point = |side, link, f: [f64; 3]| GroundForce {
            side,
            link,
            at: Vector3::zeros(),
            force: Vector3::from(f),
        };
        let forces = [
            point(Side::Right, 1, [1.0, 2.0, 3.0]),
            point(Side::Right, 1, [10.0, 20.0, 30.0]),
            point(Side::Left, 0, [-1.0, 0.0, 5.0]),
        ];
        let columns = shoe_columns((2, 3));
        let mut row = vec![7.0];
        shoe_forces(&forces, (2, 3), &mut row);
        assert_eq!(row.len(), 1 + columns.len());
        let at = |name: &str| 1 + columns.iter().position(|c| c == name).unwrap();
        assert_eq!(row[0], 7.0);
        assert_eq!(row[at("r_shoe_2_fx")], 11.0);
        assert_eq!(row[at("r_shoe_2_fz")], 33.0);
        assert_eq!(row[at("l_shoe_1_fx")], -1.0);
        assert_eq!(row[at("l_shoe_1_fz")], 5.0);
        assert_eq!(row.iter().sum::<f64>(), 7.0 + 66.0 + 4.0);
    }
}
