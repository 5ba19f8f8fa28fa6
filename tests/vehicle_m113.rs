//! The default vehicle driving: physics checks on the M113 with contact,
//! suspension and drive (each a number that could fail).

use trackgen::RecursiveModel;
use trackgen::assembly::AssemblyError;
use trackgen::closure::ClosureMethod;
use trackgen::contact::sprocket::ToothProfile;
use trackgen::contact::{ShoeGeometry, Terrain, TerrainError};
use trackgen::integrate::Integrator;
use trackgen::simulate::{Output, Results, simulate};
use trackgen::vehicle::{Drive, VehicleConfig, VehicleSystem, assemble};
use trackgen::vehicles::m113::{self, M113Chassis, M113Track};

fn integrator() -> Integrator {
    Integrator::Dopri5 {
        rtol: 1e-6,
        atol: 1e-6,
        max_step: 0.01,
    }
}

/// Runs the M113 on flat ground for `duration` s under `drive`.
fn run(drive: Drive, duration: f64) -> Results {
    let mut system =
        m113::system(Terrain::Flat { height: 0.0 }, drive).expect("the M113 assembles");
    simulate(
        &mut system,
        integrator(),
        0.0,
        duration,
        Output::Every(0.01),
    )
    .expect("the run completes")
}

fn weight() -> f64 {
    let mass: f64 = M113Track
        .description()
        .bodies
        .iter()
        .chain(M113Chassis.description().bodies.iter())
        .map(|b| b.mass)
        .sum();
    mass * 9.81
}

/// Mean of a column over `t0 ≤ t ≤ t1`.
fn mean(results: &Results, column: &str, t0: f64, t1: f64) -> f64 {
    let v = results.column(column).unwrap();
    let picked: Vec<f64> = results
        .times()
        .iter()
        .zip(v)
        .filter(|(t, _)| (t0..=t1).contains(*t))
        .map(|(_, v)| v)
        .collect();
    picked.iter().sum::<f64>() / picked.len() as f64
}

/// Static equilibrium on flat ground, the sprocket free: after settling,
/// the ground carries the vehicle's weight (the mean normal force over the
/// last 0.5 s within 1 %; the shoes ring at a few hundred N about it), and
/// the chassis is at rest (speed and pitch rate, averaged over the last
/// 0.5 s, below 1 cm/s and 0.01 rad/s).
#[test]
fn settles_into_static_equilibrium() {
    let results = run(Drive::Free, 4.0);
    let normal = mean(&results, "ground_normal", 2.0, 4.0);
    let w = weight();
    assert!(
        (normal - w).abs() < 0.01 * w,
        "ground normal {normal:.0} N, weight {w:.0} N"
    );
    let speed = mean(&results, "speed", 2.0, 4.0);
    let pitch_rate = mean(&results, "chassis.omega_chassis", 2.0, 4.0);
    assert!(
        speed.abs() < 0.01 && pitch_rate.abs() < 0.01,
        "speed {speed}, pitch rate {pitch_rate}"
    );
}

/// A driven run: the motor's work equals the change of energy (kinetic,
/// gravity, springs, contact) plus the work dissipated by contact damping,
/// friction and the arm dampers, within 2 % of the work (measured 6e-7 of
/// it on this flat run at the main job's settings; the bump course, with
/// its transients, closes to 0.3 %). Also: the vehicle reaches the commanded speed
/// (within 5 % over the last second), and no shoe sinks into the ground
/// deeper than 15 mm, or into a rim or sprocket tooth deeper than 10 mm
/// (static penetrations are 2-4 mm; the settling drop and the start of the
/// drive press harder).
#[test]
fn driven_run_balances_energy_reaches_speed_and_stays_shallow() {
    let results = run(
        m113::speed_drive(|t| 2.0 * ((t - 0.5) / 1.5).clamp(0.0, 1.0)),
        4.0,
    );
    let last = results.last().unwrap();
    let work = last.get("motor_work").unwrap();
    let energy = results.column("energy").unwrap();
    let change = energy.last().unwrap() - energy[0];
    let dissipated = last.get("dissipated").unwrap();
    assert!(work > 1e4, "the motor works: {work} J");
    assert!(
        (work - change - dissipated).abs() < 0.02 * work,
        "W {work:.0} J, ΔE {change:.0} J, dissipated {dissipated:.0} J"
    );
    let speed = mean(&results, "speed", 3.0, 4.0);
    assert!((speed - 2.0).abs() < 0.05 * 2.0, "speed {speed}");
    let deepest = |c: &str| results.column(c).unwrap().into_iter().fold(0.0, f64::max);
    assert!(
        deepest("ground_penetration") < 0.015,
        "ground {}",
        deepest("ground_penetration")
    );
    assert!(
        deepest("wheel_penetration") < 0.010,
        "wheels {}",
        deepest("wheel_penetration")
    );
    assert!(
        deepest("sprocket_penetration") < 0.010,
        "sprocket {}",
        deepest("sprocket_penetration")
    );
    assert!(
        results
            .column("track.closure_error")
            .unwrap()
            .iter()
            .all(|&c| c < 1e-10)
    );
}

/// Steady driving up a 25 % slope (so the sprocket carries a real torque,
/// not only rolling resistance): the
/// tension on the tight span exceeds the slack span's by the sprocket
/// torque over its pitch radius, within 10 % (time means over 1 s: the
/// torque ripples as the teeth engage).
#[test]
fn tight_span_tension_matches_sprocket_torque() {
    let terrain = Terrain::Ramp {
        height: 0.0,
        start: 2.5,
        slope: 0.25,
    };
    let a = assemble(
        &M113Track,
        &M113Chassis,
        &ShoeGeometry::m113(),
        &ToothProfile::m113(),
        &terrain,
        0.0,
        0.001,
    )
    .unwrap();
    let drive = m113::speed_drive(|t| 1.5 * ((t - 0.5) / 1.0).clamp(0.0, 1.0));
    let config = VehicleConfig::m113(terrain, drive);
    let mut system = VehicleSystem::new(
        M113Track,
        M113Chassis,
        a.track,
        a.chassis,
        ClosureMethod::Declared,
        config,
    )
    .unwrap();
    let radius = system.sprocket_radius();
    let results = simulate(&mut system, integrator(), 0.0, 6.0, Output::Every(0.01)).unwrap();
    let torque = mean(&results, "sprocket_torque", 5.0, 6.0).abs();
    let tight = mean(&results, "tension_tight", 5.0, 6.0);
    let slack = mean(&results, "tension_slack", 5.0, 6.0);
    let difference = tight - slack;
    assert!(
        torque > 2e3,
        "on the slope the sprocket works: {torque} N m"
    );
    assert!(
        (difference - torque / radius).abs() < 0.1 * torque / radius,
        "tension difference {difference:.0} N, torque / r {:.0} N",
        torque / radius
    );
}

trackgen::model! {
    /// Too few shoes to go round.
    pub vehicle Short {
        chassis { mass: 1000.0, inertia: 500.0 },
        sprocket drive { at: (1.0, 0.0), mass: 20.0, inertia: 1.0, radius: 0.25, teeth: 10 },
        road_wheel rw1 { at: (0.0, -0.2), mass: 30.0, inertia: 2.0, radius: 0.3 },
        idler rear { at: (-1.0, 0.0), mass: 20.0, inertia: 1.0, radius: 0.25 },
        track { links: 20, link { mass: 18.0, inertia: 0.04, u1: (-0.077, 0.0), u2: (0.077, 0.0) } },
    }

    /// A road wheel inside the idler.
    pub vehicle Nested {
        chassis { mass: 1000.0, inertia: 500.0 },
        sprocket drive { at: (1.0, 0.0), mass: 20.0, inertia: 1.0, radius: 0.25, teeth: 10 },
        idler rear { at: (-1.0, 0.0), mass: 20.0, inertia: 1.0, radius: 0.4 },
        road_wheel rw1 { at: (-1.05, 0.0), mass: 30.0, inertia: 2.0, radius: 0.1 },
        track { links: 40, link { mass: 18.0, inertia: 0.04, u1: (-0.077, 0.0), u2: (0.077, 0.0) } },
    }
}

/// Bad inputs are errors that name the problem.
#[test]
fn bad_inputs_are_clear_errors() {
    let flat = Terrain::Flat { height: 0.0 };
    let (shoe, profile) = (ShoeGeometry::m113(), ToothProfile::m113());
    let short = assemble(&ShortTrack, &ShortChassis, &shoe, &profile, &flat, 0.0, 0.0).unwrap_err();
    assert!(
        matches!(short, AssemblyError::TrackTooShort { links: 20, .. }),
        "{short}"
    );
    assert!(short.to_string().contains("too short"));
    let nested = assemble(
        &NestedTrack,
        &NestedChassis,
        &shoe,
        &profile,
        &flat,
        0.0,
        0.0,
    )
    .unwrap_err();
    assert!(
        matches!(nested, AssemblyError::WheelInside { .. }),
        "{nested}"
    );
    assert!(nested.to_string().contains("inside"));
    let table = Terrain::table(vec![(0.0, 0.0), (2.0, 0.1), (1.0, 0.2)]).unwrap_err();
    assert_eq!(
        table,
        TerrainError::OutOfOrder {
            index: 2,
            x: 1.0,
            previous: 2.0
        }
    );
    assert!(table.to_string().contains("out of order"));
    let _ = (Short, Nested);
}
