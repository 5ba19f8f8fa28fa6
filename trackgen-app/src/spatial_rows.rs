//! What `spatial` records: the rows of `spatial.csv` (the vehicle's
//! motion, and each side's drive, ground and tensions: the runtime's
//! [`SPATIAL_COLUMNS`](trackgen::spatial_vehicle::SPATIAL_COLUMNS)) and of
//! `spatial.arrow` (the same, then the ground's force on every shoe).

use trackgen::spatial_vehicle::GroundForce;

/// The columns `spatial.arrow` adds after [`SPATIAL_COLUMNS`](trackgen::spatial_vehicle::SPATIAL_COLUMNS): the ground's force
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
