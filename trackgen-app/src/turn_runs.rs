//! Steady turns run on the spatial vehicle (`steer --spatial`): each at
//! the belt speeds the general theory gives a turn, on firm level
//! ground, so that what the vehicle does in 3-D stands beside what the
//! theory estimates from its loads at rest.
//!
//! A run assembles the vehicle at rest, lets it settle, brings each
//! sprocket to its belt speed by the vehicle's speed drive over a ramp,
//! and averages what it shows over stretches of 1.5 s until two
//! stretches' yaw rates agree to 1 % (or 40 s have run: a turn not
//! steady by then is reported so): the yaw rate (the heading's change
//! over the stretch), the centre of mass's speed and the path's radius
//! (speed over yaw rate), each sprocket's torque and power, and the
//! belts' speeds.

use rayon::prelude::*;

use crate::offered::RunTurn;
use trackgen::integrate::{Integrator, OdeSystem};
use trackgen::spatial_vehicle::{SideDrives, SpatialSimulated, SpatialVehicleSystem};
use trackgen::terrain::Terrain;
use trackgen::terrain::field::HeightField;

/// The settling before the belts start, s.
pub(crate) const SETTLE: f64 = 1.0;
/// The belts' ramp from rest, s.
pub(crate) const RAMP: f64 = 2.0;
/// The stretch averaged over, s.
pub(crate) const WINDOW: f64 = 1.5;
/// When the first stretch starts, s: a second after the ramp.
const FIRST: f64 = SETTLE + RAMP + 1.0;
/// The yaw rates of two stretches running this close (relative) make
/// the turn steady.
const STEADY: f64 = 0.01;
/// The longest run, s: a turn not steady by then is reported as such.
const LONGEST: f64 = 40.0;

/// The steady turns of `V` at each pair of belt speeds (right, left,
/// m/s), run side by side; a run that fails is its error in words.
pub(crate) fn run_turns<V: SpatialVehicleSystem>(
    belts: &[[f64; 2]],
) -> Vec<Result<RunTurn, String>> {
    belts
        .par_iter()
        .map(|&pair| run_turn::<V>(pair).map_err(|e| e.to_string()))
        .collect()
}

/// One steady turn at `belts` (right, left, m/s): stretches of
/// [`WINDOW`] from [`FIRST`] on until two running yaw rates agree to
/// [`STEADY`], or [`LONGEST`] s.
fn run_turn<V: SpatialVehicleSystem>(
    belts: [f64; 2],
) -> Result<RunTurn, Box<dyn std::error::Error + Send + Sync>> {
    let flat = Terrain::Flat { height: 0.0 };
    let mut system = V::spatial(V::declared_laws(), HeightField::level())?;
    let mut y = system.assembled(&flat)?;
    let ramp = |speed: f64| move |t: f64| speed * ((t - SETTLE) / RAMP).clamp(0.0, 1.0);
    system.set_drives(SideDrives {
        right: V::speed_drive(ramp(belts[0])),
        left: V::speed_drive(ramp(belts[1])),
    })?;
    let mut stepper =
        Integrator::bs23(Integrator::DEFAULT_EXPLICIT_TOLERANCE).stepper(system.dimension());
    let mut t = 0.0;
    while t < FIRST {
        stepper.step(&mut system, &mut t, &mut y, FIRST)?;
    }
    let mut before: Option<RunTurn> = None;
    loop {
        let (start, end) = (t, t + WINDOW);
        let heading = system.outputs(t, y.as_slice())?.heading;
        let (mut speed, mut belts, mut torques, mut powers) = (0.0, [0.0; 2], [0.0; 2], [0.0; 2]);
        while t < end {
            let was = t;
            stepper.step(&mut system, &mut t, &mut y, end)?;
            let dt = t - was;
            let out = system.outputs(t, y.as_slice())?;
            speed += dt * out.centre.velocity.xy().norm();
            for s in 0..2 {
                belts[s] += dt * out.sides[s].belt_speed;
                torques[s] += dt * out.sides[s].sprocket_torque;
                powers[s] += dt * out.sides[s].sprocket_power;
            }
        }
        let span = t - start;
        let yaw_rate = (system.outputs(t, y.as_slice())?.heading - heading) / span;
        let speed = speed / span;
        let steady = before.is_some_and(|b| {
            (yaw_rate - b.yaw_rate).abs() <= STEADY * yaw_rate.abs().max(b.yaw_rate.abs())
        });
        let turn = RunTurn {
            yaw_rate,
            speed,
            radius: speed / yaw_rate.abs(),
            belts: belts.map(|v| v / span),
            torques: torques.map(|v| v / span),
            powers: powers.map(|v| v / span),
            until: t,
            steady,
        };
        if steady || t + WINDOW > LONGEST {
            return Ok(turn);
        }
        before = Some(turn);
    }
}
