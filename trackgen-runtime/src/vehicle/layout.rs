//! Where each quantity sits in a vehicle's state `y`: what an analysis of
//! the state (its Jacobian, an equilibrium, the modes) needs to know of it.

use std::ops::Range;

/// The places in a vehicle's state `y` ([`VehicleSystem`](super::VehicleSystem)'s
/// layout): the track's integrated coordinates and their rates, the
/// chassis' coordinates and rates, the drive's integral, the books' three
/// quadratures, the engine's speed (where it is a state) and the ground
/// points' tangential states.
#[derive(Debug, Clone, PartialEq)]
pub struct StateLayout {
    /// The track's integrated coordinates, indices into `y`; their rates
    /// follow at [`track_rates`](Self::track_rates).
    pub track: Range<usize>,
    /// The `q_i` index (`x¹, y¹, θ¹ … θⁿ`: 0 is `x¹`, `2 + k` link `k + 1`'s
    /// angle) of each integrated track coordinate: all of them, or under
    /// partitioning all but the dependent pair.
    pub track_coordinates: Vec<usize>,
    /// The track's integrated rates.
    pub track_rates: Range<usize>,
    /// The chassis' coordinates `q_i` (`x, y, θ` of the frame, then every
    /// other body's absolute angle).
    pub chassis: Range<usize>,
    /// The chassis' rates.
    pub chassis_rates: Range<usize>,
    /// The speed drive's integral, rad.
    pub integral: usize,
    /// The books' quadratures: the motor's work, the dissipated work and
    /// the engine's work (this side's share), J. They feed nothing back.
    pub books: [usize; 3],
    /// The engine's speed, rad/s, where the powertrain makes it a state
    /// ([`EngineDynamics`](super::EngineDynamics)); the locked driveline's
    /// twist, rad at the turbine, follows it.
    pub engine: Option<usize>,
    /// The ground points' tangential states (stiction deflections or soil
    /// shear displacements), link by link; empty with regularised friction.
    pub tangential: Range<usize>,
    /// The sprocket's chassis body, if the chassis has one: its coordinate
    /// is `chassis.start + 2 + body`.
    pub sprocket: Option<usize>,
}

/// Where each part of the state starts, for the solves' loops: a copy of
/// [`StateLayout`]'s first indices, which it owns.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Starts {
    /// The track's integrated coordinates (their rates follow).
    pub track: usize,
    /// The chassis' coordinates (their rates follow).
    pub chassis: usize,
    /// The drive's integral.
    pub integral: usize,
    /// The engine's speed, if a state (the driveline's twist follows).
    pub engine: Option<usize>,
    /// The first tangential state.
    pub tangential: usize,
}

/// The `q_i` indices a track integrates: all `dof` of them, or under
/// partitioning with the dependent `pair` (links numbered from 1) all but
/// the pair's angles.
pub(crate) fn track_coordinates(dof: usize, pair: Option<[usize; 2]>) -> Vec<usize> {
    match pair {
        Some(pair) => (0..dof)
            .filter(|&c| c < 2 || !pair.contains(&(c - 1)))
            .collect(),
        None => (0..dof).collect(),
    }
}

impl StateLayout {
    /// The one layout of a vehicle's state: the track's integrated
    /// coordinates `track_coordinates` (`q_i` indices) and their rates,
    /// the chassis' `chassis_dof` coordinates and rates, the drive's
    /// integral, the books' three quadratures, the engine's speed and the
    /// locked driveline's twist if they are states (`engine`), then
    /// `tangential` tangential states.
    pub(crate) fn new(
        track_coordinates: Vec<usize>,
        chassis_dof: usize,
        tangential: usize,
        sprocket: Option<usize>,
        engine: bool,
    ) -> StateLayout {
        let nt = track_coordinates.len();
        let chassis = 2 * nt;
        let integral = chassis + 2 * chassis_dof;
        let first_tangential = integral + 4 + 2 * usize::from(engine);
        StateLayout {
            track: 0..nt,
            track_coordinates,
            track_rates: nt..2 * nt,
            chassis: chassis..chassis + chassis_dof,
            chassis_rates: chassis + chassis_dof..integral,
            integral,
            books: [integral + 1, integral + 2, integral + 3],
            engine: engine.then_some(integral + 4),
            tangential: first_tangential..first_tangential + tangential,
            sprocket,
        }
    }

    /// The state's length.
    pub fn dimension(&self) -> usize {
        self.tangential.end
    }

    /// The bodies' states: the track's and the chassis' coordinates and
    /// rates, `0..integral`.
    pub fn bodies(&self) -> std::ops::Range<usize> {
        0..self.integral
    }

    /// The first index of each part.
    pub(crate) fn starts(&self) -> Starts {
        Starts {
            track: self.track.start,
            chassis: self.chassis.start,
            integral: self.integral,
            engine: self.engine,
            tangential: self.tangential.start,
        }
    }

    /// The coordinates of every body, track then chassis: indices into `y`.
    pub fn positions(&self) -> impl Iterator<Item = usize> + '_ {
        self.track.clone().chain(self.chassis.clone())
    }

    /// The rates, in the order of [`positions`](Self::positions).
    pub fn rates(&self) -> impl Iterator<Item = usize> + '_ {
        self.track_rates.clone().chain(self.chassis_rates.clone())
    }

    /// The states with dynamics: all but the books' quadratures (whose
    /// eigenvalues are zero and whose rows, powers of the order of the
    /// drive's torque, feed nothing back).
    pub fn dynamic(&self) -> impl Iterator<Item = usize> + '_ {
        (0..self.tangential.end).filter(|i| !self.books.contains(i))
    }

    /// The index into `y` of the sprocket's angle, if there is a sprocket.
    pub fn sprocket_angle(&self) -> Option<usize> {
        self.sprocket.map(|b| self.chassis.start + 2 + b)
    }

    /// A name for state `i`, for tables: `track θ12`, `track ẏ1`,
    /// `chassis q3'`, `drive integral`, `stiction link 4 point 2`.
    pub fn name(&self, i: usize, points: usize) -> String {
        let track = |k: usize| match self.track_coordinates[k] {
            0 => "x1".to_string(),
            1 => "y1".to_string(),
            c => format!("θ{}", c - 1),
        };
        match i {
            i if self.track.contains(&i) => format!("track {}", track(i - self.track.start)),
            i if self.track_rates.contains(&i) => {
                format!("track {}'", track(i - self.track_rates.start))
            }
            i if self.chassis.contains(&i) => format!("chassis q{}", i - self.chassis.start),
            i if self.chassis_rates.contains(&i) => {
                format!("chassis q{}'", i - self.chassis_rates.start)
            }
            i if i == self.integral => "drive integral".to_string(),
            i if i == self.books[0] => "motor work".to_string(),
            i if i == self.books[1] => "dissipated work".to_string(),
            i if i == self.books[2] => "engine work".to_string(),
            i if Some(i) == self.engine => "engine speed".to_string(),
            i if self.engine.is_some_and(|e| i == e + 1) => "driveline twist".to_string(),
            i => {
                let k = i - self.tangential.start;
                let points = points.max(1);
                format!(
                    "ground point: link {} point {}",
                    k / points + 1,
                    k % points + 1
                )
            }
        }
    }
}
