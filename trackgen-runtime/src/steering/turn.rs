//! The steady turn: the instantaneous centres where the tracks' shear,
//! their rolling resistance and the centripetal force balance, by
//! Newton's method on the closed forms of the module `shear` with
//! their exact derivatives.

use nalgebra::{Matrix3, Matrix3x5, Matrix5x3, Vector2, Vector3};

use super::shear::{unit_density, unit_shear};
use super::{SkidSteer, SteeringError, TrackLoad, check};

/// Newton stops when the forces balance to this fraction of the weight
/// (and the moment to it times the run's length).
const BALANCE: f64 = 1e-12;
/// The most Newton iterations.
const ITERATIONS: usize = 100;

/// One side of a [`SteadyTurn`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SideInTurn {
    /// The belt speed, m/s: how fast the ground run moves rearward along
    /// the hull (the sprocket's speed times its pitch radius).
    pub belt_speed: f64,
    /// The ground's shear along the track, N: the thrust the sprocket
    /// gives (forward positive; a braking track's is negative).
    pub thrust: f64,
    /// The ground's shear across the track, N (to the left positive).
    pub lateral: f64,
    /// The ground's rolling resistance on the track, N along the hull.
    pub resistance: f64,
    /// The running gear's losses as a force on the belt, N along the
    /// hull: `−f_b N` against the belt's motion round the hull, none where
    /// it stands ([`SkidSteer::belt_resistance`]).
    pub belt_loss: f64,
    /// The sprocket's power, W: [`sprocket_force`](Self::sprocket_force)
    /// times the belt speed (negative where the sprocket brakes its
    /// track).
    pub power: f64,
    /// The track's instantaneous centre's distance from its centre line,
    /// m (toward the right positive): where it slips or skids.
    pub offset: f64,
    /// The slip, `1 − v/u`: `v` the speed of the track's centre line over
    /// the ground along the hull, `u` the belt speed (positive driving,
    /// negative skidding; NaN where the belt stands).
    pub slip: f64,
}

/// A steady turn on firm level ground.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SteadyTurn {
    /// The yaw rate, rad/s (positive turning left).
    pub yaw_rate: f64,
    /// The velocity of the centre of gravity in the hull's frame, m/s:
    /// forward and to the left (its sideslip).
    pub velocity: Vector2<f64>,
    /// The turn's centre in the hull's frame, m.
    pub centre: Vector2<f64>,
    /// The radius of the centre of gravity's path, m.
    pub radius: f64,
    /// The left side and the right.
    pub sides: [SideInTurn; 2],
    /// The moment of turning resistance, N m: the moment of the ground's
    /// lateral shear about the centre of gravity, against the turn.
    pub resisting_moment: f64,
    /// The power the ground's friction dissipates, W.
    pub dissipation: f64,
    /// The power the rolling resistance dissipates, W: the ground's and
    /// the running gear's.
    pub rolling_loss: f64,
    /// Newton iterations taken.
    pub iterations: usize,
}

impl SideInTurn {
    /// The force the sprocket gives the belt along the hull, N: the
    /// ground's shear and the running gear's losses, `thrust −
    /// belt_loss` (its torque is this times its pitch radius).
    pub fn sprocket_force(&self) -> f64 {
        self.thrust - self.belt_loss
    }
}

impl SteadyTurn {
    /// The sprocket speed ratio, the outer belt's speed over the inner's
    /// (negative in a pivot turn, infinite where the inner belt stands).
    pub fn speed_ratio(&self) -> f64 {
        let [outer, inner] = self.outer_inner();
        outer.belt_speed / inner.belt_speed
    }

    /// The outer side and the inner (the right and the left turning left).
    pub fn outer_inner(&self) -> [SideInTurn; 2] {
        let [left, right] = self.sides;
        if self.yaw_rate > 0.0 {
            [right, left]
        } else {
            [left, right]
        }
    }
}

/// A trial of the turn: the centres' longitudinal place `x_c` (m), each
/// track's offset `d` (m), the forward speed `V_x` (m/s) and the yaw rate
/// `ω` (rad/s).
#[derive(Debug, Clone, Copy)]
struct Trial {
    centre: f64,
    offsets: [f64; 2],
    speed: f64,
    yaw_rate: f64,
}

/// A way of solving for the turn: from three unknowns to the trial, with
/// the trial's derivatives in them (rows `x_c`, `d_left`, `d_right`,
/// `V_x`, `ω`).
type Unknowns<'a> = dyn Fn(&Vector3<f64>) -> (Trial, Matrix5x3<f64>) + 'a;

impl SkidSteer {
    /// The steady turn at `yaw_rate` (rad/s, nonzero; positive to the
    /// left) with the centre of gravity moving forward at `forward_speed`
    /// (m/s; 0 for a pivot turn): the belt speeds, thrusts and powers it
    /// takes.
    pub fn turn(&self, yaw_rate: f64, forward_speed: f64) -> Result<SteadyTurn, SteeringError> {
        self.check()?;
        check(
            "the yaw rate (rad/s)",
            "finite and nonzero",
            yaw_rate,
            yaw_rate != 0.0,
        )?;
        check("the forward speed (m/s)", "finite", forward_speed, true)?;
        // Unknowns: x_c and both offsets. The guess: the centres abreast
        // of the centre of gravity, each offset a twentieth of the run
        // toward the slip that drives the outer track and brakes the inner.
        let mut guess = Vector3::zeros();
        for (j, track) in self.tracks.iter().enumerate() {
            guess[1 + j] = -0.05 * track.length() * (yaw_rate * track.lateral).signum();
        }
        let unknowns = |z: &Vector3<f64>| {
            let trial = Trial {
                centre: z[0],
                offsets: [z[1], z[2]],
                speed: forward_speed,
                yaw_rate,
            };
            let mut by = Matrix5x3::zeros();
            by.fixed_view_mut::<3, 3>(0, 0).fill_with_identity();
            (trial, by)
        };
        self.solve(guess, &unknowns, (yaw_rate, forward_speed))
    }

    /// The steady turn the belt speeds drive (m/s, the left belt's and
    /// the right's; not equal): its yaw rate, speed and radius.
    pub fn drive(&self, belt_speeds: [f64; 2]) -> Result<SteadyTurn, SteeringError> {
        self.check()?;
        for u in belt_speeds {
            check("a belt speed (m/s)", "finite", u, true)?;
        }
        let [ul, ur] = belt_speeds;
        check(
            "the belt speeds' difference (m/s)",
            "nonzero (equal speeds drive straight)",
            ul - ur,
            ul != ur,
        )?;
        let lateral = [self.tracks[0].lateral, self.tracks[1].lateral];
        // Unknowns: x_c, the forward speed and the yaw rate; each offset
        // follows from its belt, d = y − (V_x − u)/ω. The guess: the
        // kinematic turn (no slip) at half its yaw rate.
        let kinematic = (ur - ul) / (lateral[0] - lateral[1]);
        let guess = Vector3::new(0.0, 0.5 * (ul + ur), 0.5 * kinematic);
        let unknowns = |z: &Vector3<f64>| {
            let (speed, yaw_rate) = (z[1], z[2]);
            let mut by = Matrix5x3::zeros();
            by[(0, 0)] = 1.0;
            by[(3, 1)] = 1.0;
            by[(4, 2)] = 1.0;
            let mut offsets = [0.0; 2];
            for j in 0..2 {
                let slip = speed - belt_speeds[j];
                offsets[j] = lateral[j] - slip / yaw_rate;
                by[(1 + j, 1)] = -1.0 / yaw_rate;
                by[(1 + j, 2)] = slip / (yaw_rate * yaw_rate);
            }
            let trial = Trial {
                centre: z[0],
                offsets,
                speed,
                yaw_rate,
            };
            (trial, by)
        };
        self.solve(guess, &unknowns, (0.5 * kinematic, 0.5 * (ul + ur)))
    }

    /// Newton's method with a halving line search on the balance,
    /// forces scaled by the weight and the moment by the weight times the
    /// longer run.
    fn solve(
        &self,
        mut z: Vector3<f64>,
        unknowns: &Unknowns<'_>,
        (yaw_rate, speed): (f64, f64),
    ) -> Result<SteadyTurn, SteeringError> {
        let weight = self.load();
        let length = self
            .tracks
            .iter()
            .map(|t| t.length())
            .fold(0.0, f64::max)
            .max(1e-3);
        let scale = Vector3::new(1.0 / weight, 1.0 / weight, 1.0 / (weight * length));
        let size = |t: &Trial| {
            let r = self.balance(t).residual.component_mul(&scale);
            if r.iter().all(|x| x.is_finite()) {
                r.amax()
            } else {
                f64::INFINITY
            }
        };
        let mut last = f64::NAN;
        for iteration in 0..ITERATIONS {
            let (trial, by) = unknowns(&z);
            let balance = self.balance(&trial);
            let residual = balance.residual.component_mul(&scale);
            last = residual.amax();
            if last <= BALANCE {
                return Ok(self.figures(&trial, iteration));
            }
            let jacobian = Matrix3::from_diagonal(&scale) * balance.jacobian() * by;
            let Some(step) = jacobian.lu().solve(&-residual) else {
                break;
            };
            let mut length = 1.0;
            loop {
                let next = z + step * length;
                if size(&unknowns(&next).0) < last || length < 1e-10 {
                    z = next;
                    break;
                }
                length *= 0.5;
            }
        }
        Err(SteeringError::NoSolution {
            yaw_rate,
            speed,
            iterations: ITERATIONS,
            residual: last,
        })
    }

    /// The balance of the ground's shear, the rolling resistance and the
    /// centripetal force at a trial: along and across the hull (N) and
    /// the moment about the centre of gravity (N m), with derivatives.
    fn balance(&self, t: &Trial) -> Balance {
        let Trial {
            centre,
            offsets,
            speed,
            yaw_rate,
        } = *t;
        let spin = yaw_rate.signum();
        let mut b = Balance {
            residual: Vector3::new(
                -self.mass * yaw_rate * yaw_rate * centre,
                -self.mass * yaw_rate * speed,
                0.0,
            ),
            by_centre: Vector3::new(-self.mass * yaw_rate * yaw_rate, 0.0, 0.0),
            by_offset: [Vector3::zeros(); 2],
            by_speed: Vector3::new(0.0, -self.mass * yaw_rate, 0.0),
            by_yaw_rate: Vector3::new(
                -2.0 * self.mass * yaw_rate * centre,
                -self.mass * speed,
                0.0,
            ),
        };
        for (j, track) in self.tracks.iter().enumerate() {
            let (y, d) = (track.lateral, offsets[j]);
            let resistance = self.resistance(track, speed - yaw_rate * y);
            b.residual += Vector3::new(resistance, 0.0, -y * resistance);
            let shear = self.shear(track, centre, d, spin);
            let [along, across, turning] = shear.forces;
            b.residual += Vector3::new(along, across, turning + centre * across - y * along);
            let [along_c, across_c, turning_c] = shear.by_centre;
            b.by_centre += Vector3::new(
                along_c,
                across_c,
                turning_c + across + centre * across_c - y * along_c,
            );
            let [along_d, across_d, turning_d] = shear.by_offset;
            b.by_offset[j] += Vector3::new(
                along_d,
                across_d,
                turning_d + centre * across_d - y * along_d,
            );
        }
        b
    }

    /// The ground's shear on `track`'s run at a trial, summed over its
    /// stretches: the forces along and across it (N) and the moment of the
    /// force across about the centres' cross line (N m), each for a turn
    /// of sign `spin`, with their derivatives in the centres' place `x_c`
    /// and in the offset `d`; and the dissipation per unit yaw rate (J).
    fn shear(&self, track: &TrackLoad, centre: f64, d: f64, spin: f64) -> TrackShear {
        let mut sum = TrackShear::default();
        for s in track.stretches.iter().filter(|s| s.load > 0.0) {
            let q = self.friction * s.load / (s.to - s.from);
            let k = q * spin;
            let (a, e) = (s.from - centre, s.to - centre);
            let unit = unit_shear(a, e, d);
            // x_c moves both ends: minus the integrands' difference.
            let (lo, hi) = (unit_density(a, d), unit_density(e, d));
            for i in 0..3 {
                sum.by_centre[i] -= k * (hi[i] - lo[i]);
            }
            let forces = [unit.along, unit.across, unit.moment];
            let by_offset = [unit.along_d, unit.across_d, unit.moment_d];
            for i in 0..3 {
                sum.forces[i] += k * forces[i];
                sum.by_offset[i] += k * by_offset[i];
            }
            sum.dissipation += q * unit.dissipation;
        }
        sum
    }

    /// The rolling resistance on `track`, N along the hull, when its
    /// centre line moves over the ground at `v` (m/s) along the hull.
    fn resistance(&self, track: &TrackLoad, v: f64) -> f64 {
        if v == 0.0 {
            0.0
        } else {
            -self.rolling_resistance * track.load() * v.signum()
        }
    }

    /// What a turn found at `t` gives.
    fn figures(&self, t: &Trial, iterations: usize) -> SteadyTurn {
        let Trial {
            centre,
            offsets,
            speed,
            yaw_rate,
        } = *t;
        let spin = yaw_rate.signum();
        let velocity = Vector2::new(speed, -yaw_rate * centre);
        let mut sides = [SIDE_AT_REST; 2];
        let (mut resisting_moment, mut dissipation, mut rolling_loss) = (0.0, 0.0, 0.0);
        for (j, track) in self.tracks.iter().enumerate() {
            let (y, d) = (track.lateral, offsets[j]);
            let shear = self.shear(track, centre, d, spin);
            let [thrust, lateral, turning] = shear.forces;
            resisting_moment -= turning + centre * lateral;
            dissipation += yaw_rate.abs() * shear.dissipation;
            let ground = speed - yaw_rate * y;
            let resistance = self.resistance(track, ground);
            rolling_loss -= resistance * ground;
            // A belt asked to stand comes back from the centres as
            // rounding: it stands (its losses turn over at standstill).
            let belt_speed = speed - yaw_rate * (y - d);
            let scale = speed.abs() + (yaw_rate * y).abs() + (yaw_rate * d).abs();
            let belt_speed = if belt_speed.abs() <= 1e-12 * scale {
                0.0
            } else {
                belt_speed
            };
            let belt_loss = if belt_speed == 0.0 {
                0.0
            } else {
                -self.belt_resistance * track.load() * belt_speed.signum()
            };
            rolling_loss -= belt_loss * belt_speed;
            sides[j] = SideInTurn {
                belt_speed,
                thrust,
                lateral,
                resistance,
                belt_loss,
                power: (thrust - belt_loss) * belt_speed,
                offset: d,
                slip: if belt_speed == 0.0 {
                    f64::NAN
                } else {
                    1.0 - ground / belt_speed
                },
            };
        }
        SteadyTurn {
            yaw_rate,
            velocity,
            centre: Vector2::new(centre, speed / yaw_rate),
            radius: velocity.norm() / yaw_rate.abs(),
            sides,
            resisting_moment: resisting_moment * spin,
            dissipation,
            rolling_loss,
            iterations,
        }
    }
}

const SIDE_AT_REST: SideInTurn = SideInTurn {
    belt_speed: 0.0,
    thrust: 0.0,
    lateral: 0.0,
    resistance: 0.0,
    belt_loss: 0.0,
    power: 0.0,
    offset: 0.0,
    slip: f64::NAN,
};

/// [`SkidSteer::shear`]: along, across, the moment of the force across.
#[derive(Default)]
struct TrackShear {
    forces: [f64; 3],
    by_centre: [f64; 3],
    by_offset: [f64; 3],
    dissipation: f64,
}

/// The balance of forces at a trial and its partial derivatives.
struct Balance {
    /// Along, across (N) and the moment about the centre of gravity
    /// (N m).
    residual: Vector3<f64>,
    /// In the centres' longitudinal place `x_c`.
    by_centre: Vector3<f64>,
    /// In each track's offset `d`.
    by_offset: [Vector3<f64>; 2],
    /// In the forward speed and the yaw rate where they appear outside
    /// the offsets (the centripetal force).
    by_speed: Vector3<f64>,
    by_yaw_rate: Vector3<f64>,
}

impl Balance {
    /// The derivatives as a matrix, columns `x_c`, `d_left`, `d_right`,
    /// `V_x`, `ω`.
    fn jacobian(&self) -> Matrix3x5<f64> {
        Matrix3x5::from_columns(&[
            self.by_centre,
            self.by_offset[0],
            self.by_offset[1],
            self.by_speed,
            self.by_yaw_rate,
        ])
    }
}
