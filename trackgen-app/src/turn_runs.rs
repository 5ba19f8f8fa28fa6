//! Steady turns run on the spatial vehicle (`steer --spatial`): each at
//! the belt speeds the general theory gives a turn, on firm level
//! ground, so that what the vehicle does in 3-D stands beside what the
//! theory estimates from its loads at rest.
//!
//! A run assembles the vehicle at rest, lets it settle, brings each
//! sprocket to its belt speed by the vehicle's speed drive over a ramp,
//! and averages what it shows over the last stretch, once the turn is
//! steady: the yaw rate (the heading's change over the stretch), the
//! centre of mass's speed and the path's radius (speed over yaw rate),
//! each sprocket's torque and power, and the belts' speeds.

use rayon::prelude::*;
use trackgen::integrate::{Integrator, OdeSystem};
use trackgen::spatial_vehicle::{SideDrives, SpatialSimulated, SpatialVehicleSystem};
use trackgen::terrain::Terrain;
use trackgen::terrain::field::HeightField;

/// The settling before the belts start, s.
const SETTLE: f64 = 1.0;
/// The belts' ramp from rest, s.
const RAMP: f64 = 2.0;
/// When the averages start, s: the turn steady (the spatial tests'
/// carrier settles within 2 s of its ramp; a turn 2 s further moved its
/// averages by under 0.5 %).
const STEADY: f64 = 5.0;
/// When the run ends, s.
const END: f64 = 8.0;

/// What a steady turn of the spatial vehicle showed, averaged over time.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RunTurn {
    /// The yaw rate, rad/s (left positive).
    pub yaw_rate: f64,
    /// The centre of mass's horizontal speed, m/s.
    pub speed: f64,
    /// The path's radius, m: the speed over the yaw rate's size.
    pub radius: f64,
    /// The belts' speeds (right, left), m/s, forward positive.
    pub belts: [f64; 2],
    /// The sprockets' torques (right, left), N m, planar sense (driving
    /// forward negative).
    pub torques: [f64; 2],
    /// The sprockets' powers (right, left), W.
    pub powers: [f64; 2],
}

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

/// One steady turn at `belts` (right, left, m/s).
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
    let mut stepper = Integrator::Bs23 {
        rtol: Integrator::DEFAULT_EXPLICIT_TOLERANCE,
        atol: Integrator::DEFAULT_EXPLICIT_TOLERANCE,
        max_step: Integrator::DEFAULT_MAX_STEP,
    }
    .stepper(system.dimension());
    let mut t = 0.0;
    while t < STEADY {
        stepper.step(&mut system, &mut t, &mut y, STEADY)?;
    }
    let heading = system.outputs(t, y.as_slice())?.heading;
    let mut sums = RunTurn {
        yaw_rate: 0.0,
        speed: 0.0,
        radius: 0.0,
        belts: [0.0; 2],
        torques: [0.0; 2],
        powers: [0.0; 2],
    };
    while t < END {
        let before = t;
        stepper.step(&mut system, &mut t, &mut y, END)?;
        let dt = t - before;
        let out = system.outputs(t, y.as_slice())?;
        sums.speed += dt * out.centre.velocity.xy().norm();
        for s in 0..2 {
            sums.belts[s] += dt * out.sides[s].belt_speed;
            sums.torques[s] += dt * out.sides[s].sprocket_torque;
            sums.powers[s] += dt * out.sides[s].sprocket_power;
        }
    }
    let window = END - STEADY;
    let last = system.outputs(t, y.as_slice())?;
    let yaw_rate = (last.heading - heading) / window;
    let speed = sums.speed / window;
    Ok(RunTurn {
        yaw_rate,
        speed,
        radius: speed / yaw_rate.abs(),
        belts: sums.belts.map(|v| v / window),
        torques: sums.torques.map(|v| v / window),
        powers: sums.powers.map(|v| v / window),
    })
}

/// Runs each of the theory's `turns` on the spatial model by `run`
/// (turning left: the right belt the outer, at the theory's belt
/// speeds), prints what each run showed beside the theory and writes
/// `file`; the theory's torques are its shear times the sprockets'
/// rolling radius `sprocket` (m). A run that fails is reported as failed
/// and the others kept.
pub(crate) fn compare(
    run: crate::offered::TurnRuns,
    turns: &[(crate::steer::Asked, trackgen::steering::SteadyTurn)],
    sprocket: f64,
    file: &std::path::Path,
) -> Result<(), Box<dyn std::error::Error>> {
    use crate::console::say;
    let belts: Vec<[f64; 2]> = turns
        .iter()
        .map(|(_, turn)| {
            let [outer, inner] = turn.outer_inner();
            [outer.belt_speed, inner.belt_speed]
        })
        .collect();
    say!(
        "the same turns in 3-D (both tracks, the hull in space; each sprocket held at the theory's belt speed, settled {SETTLE} s, ramped over {RAMP} s, averaged from {STEADY} to {END} s):"
    );
    say!(
        "  asked        radius m (theory)    yaw rad/s (theory)    torque out/in kN m (theory)          power out/in kW"
    );
    let runs = run(&belts);
    let mut w = csv::Writer::from_path(file)?;
    w.write_record([
        "asked",
        "outer_belt_speed",
        "inner_belt_speed",
        "radius",
        "theory_radius",
        "yaw_rate",
        "theory_yaw_rate",
        "outer_sprocket_torque",
        "theory_outer_sprocket_torque",
        "inner_sprocket_torque",
        "theory_inner_sprocket_torque",
        "outer_power",
        "inner_power",
    ])?;
    for ((asked, turn), ran) in turns.iter().zip(runs) {
        let [outer, inner] = turn.outer_inner();
        let theory = [outer.thrust * sprocket, inner.thrust * sprocket];
        let ran = match ran {
            Ok(ran) => ran,
            Err(e) => {
                say!("  {:10}   the run failed: {e}", asked.label());
                continue;
            }
        };
        // The run's torques in the theory's sense: driving forward positive.
        let torque = [-ran.torques[0], -ran.torques[1]];
        say!(
            "  {:10}   {:8.3} ({:7.3})   {:8.4} ({:8.4})   {:7.2} {:7.2} ({:7.2} {:7.2})   {:7.1} {:7.1}",
            asked.label(),
            ran.radius,
            turn.radius,
            ran.yaw_rate,
            turn.yaw_rate,
            torque[0] / 1e3,
            torque[1] / 1e3,
            theory[0] / 1e3,
            theory[1] / 1e3,
            ran.powers[0] / 1e3,
            ran.powers[1] / 1e3
        );
        let row = [
            ran.belts[0],
            ran.belts[1],
            ran.radius,
            turn.radius,
            ran.yaw_rate,
            turn.yaw_rate,
            torque[0],
            theory[0],
            torque[1],
            theory[1],
            ran.powers[0],
            ran.powers[1],
        ];
        let mut record = vec![asked.label()];
        record.extend(row.iter().map(|v| format!("{v}")));
        w.write_record(record)?;
    }
    w.flush()?;
    Ok(())
}
