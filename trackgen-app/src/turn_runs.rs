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
use trackgen::integrate::{Integrator, OdeSystem};
use trackgen::spatial_vehicle::{SideDrives, SpatialSimulated, SpatialVehicleSystem};
use trackgen::terrain::Terrain;
use trackgen::terrain::field::HeightField;

/// The settling before the belts start, s.
const SETTLE: f64 = 1.0;
/// The belts' ramp from rest, s.
const RAMP: f64 = 2.0;
/// The stretch averaged over, s.
const WINDOW: f64 = 1.5;
/// When the first stretch starts, s: a second after the ramp.
const FIRST: f64 = SETTLE + RAMP + 1.0;
/// The yaw rates of two stretches running this close (relative) make
/// the turn steady.
const STEADY: f64 = 0.01;
/// The longest run, s: a turn not steady by then is reported as such.
const LONGEST: f64 = 40.0;

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
    /// When the stretch averaged ended, s.
    pub until: f64,
    /// Whether the turn was steady: its yaw rate within 1 % of the
    /// stretch's before.
    pub steady: bool,
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
    let mut stepper = Integrator::Bs23 {
        rtol: Integrator::DEFAULT_EXPLICIT_TOLERANCE,
        atol: Integrator::DEFAULT_EXPLICIT_TOLERANCE,
        max_step: Integrator::DEFAULT_MAX_STEP,
    }
    .stepper(system.dimension());
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
        "the same turns in 3-D (both tracks, the hull in space; each sprocket held at the theory's belt speed, settled {SETTLE} s, ramped over {RAMP} s, averaged over {WINDOW} s once two such stretches' yaw rates agree to 1 %):"
    );
    say!(
        "  asked        radius m (theory)    yaw rad/s (theory)    torque out/in kN m (theory)          power out/in kW   steady by"
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
        "until",
        "steady",
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
            "  {:10}   {:8.3} ({:7.3})   {:8.4} ({:8.4})   {:7.2} {:7.2} ({:7.2} {:7.2})   {:7.1} {:7.1}   {}",
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
            ran.powers[1] / 1e3,
            if ran.steady {
                format!("{:.1} s", ran.until)
            } else {
                format!("not steady by {:.0} s", ran.until)
            }
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
            ran.until,
            if ran.steady { 1.0 } else { 0.0 },
        ];
        let mut record = vec![asked.label()];
        record.extend(row.iter().map(|v| format!("{v}")));
        w.write_record(record)?;
    }
    w.flush()?;
    Ok(())
}
