//! The engine whose speed is a state on a spatial differential's box
//! (`SpatialEngine`): what it takes, and its gearbox and lock-up clutch
//! between steps against the schedule's own figures. Its run against the
//! planar engine's is `spatial_straight`'s; the steer drive geared to it,
//! `spatial_driveline`'s.

use trackgen::spatial_vehicle::{SpatialEngine, SpatialEngineError};
use trackgen::vehicle::{Drive, Engaged, Powertrain};
use trackgen::vehicles::m113;

/// A speed drive asking the box forward at 3 m/s: it never asks reverse.
fn forward() -> Drive {
    Drive::Speed {
        target: Box::new(|_| 3.0),
        proportional: 1.0,
        integral: 1.0,
        max_torque: 1.0,
    }
}

/// The M113A3's powertrain makes an engine whose speed is a state: the
/// whole engine on the box (its share 1, the planar side's 0.5), its
/// declared schedule kept, the lowest range engaged and unlocked, idle at
/// its map's first speed; its rated power the map's largest `T ω`
/// (205 kW, the 6V53T's 275 hp at 2800 rpm, to 0.1 %: the map's
/// point there is the published torque scaled to that power).
#[test]
fn the_m113a3s_powertrain_makes_an_engine_on_the_box() {
    let Powertrain::Converter(declared) = m113::powertrain() else {
        unreachable!("the M113A3's powertrain is a converter's")
    };
    let engine = SpatialEngine::new(m113::powertrain()).expect("an engine with dynamics");
    let d = engine.driveline();
    assert_eq!(declared.share, 0.5);
    assert_eq!(d.share, 1.0);
    assert_eq!(d.shift, declared.shift);
    assert_eq!(engine.engaged(), Some(Engaged::LOWEST));
    assert!(!engine.locked());
    assert_eq!(engine.idle(), declared.engine[0].0);
    let published = 275.0 * 745.699_872;
    let rated = engine.rated_power();
    assert!((rated / published - 1.0).abs() < 1e-3, "{rated} W");
    let scan = (0..=4000)
        .map(|i| {
            let w = declared.engine[0].0
                + (declared.engine[declared.engine.len() - 1].0 - declared.engine[0].0) * i as f64
                    / 4000.0;
            trackgen::vehicle::Driveline::full_load(&declared.engine, w) * w
        })
        .fold(0.0, f64::max);
    assert!(scan <= rated * (1.0 + 1e-12), "{scan} > {rated}");
    assert!(scan >= rated * (1.0 - 1e-6), "{scan} < {rated}");
}

/// A powertrain without an engine whose speed can be a state is refused,
/// and so are figures out of their range, each with its cause.
#[test]
fn a_powertrain_without_engine_dynamics_is_refused() {
    let power = Powertrain::Power {
        power: 1e5,
        max_torque: 1e4,
    };
    assert_eq!(
        SpatialEngine::new(power).err(),
        Some(SpatialEngineError::NoDynamics)
    );
    let mut quasi_static = m113::powertrain();
    if let Powertrain::Converter(d) = &mut quasi_static {
        d.dynamics = None;
    }
    let error = SpatialEngine::new(quasi_static).expect_err("no inertia");
    assert_eq!(error, SpatialEngineError::NoDynamics);
    assert!(error.to_string().contains("engine_inertia"), "{error}");
    let mut bad = m113::powertrain();
    if let Powertrain::Converter(d) = &mut bad {
        d.final_drive = -1.0;
    }
    assert!(matches!(
        SpatialEngine::new(bad),
        Err(SpatialEngineError::Powertrain(_))
    ));
}

/// Between steps the gearbox shifts where its schedule says, with the
/// turbine at the range's reduction times the box's speed: up past the
/// first range's upshift speed (not just below it), the shift done after
/// the shift time (not before), and down again only below the second
/// range's downshift speed (the hysteresis). The first range never locks
/// up (the X200-4 locks in ranges 2–4).
#[test]
fn the_box_shifts_by_its_schedule() {
    let mut engine = SpatialEngine::new(m113::powertrain()).expect("an engine");
    let d = engine.driveline().clone();
    let shift = d.shift.clone().expect("a schedule");
    let drive = forward();
    let idle = engine.idle();
    // The box's speed (rad/s, forward negative) at which the turbine
    // turns at `input` in range `r`.
    let at = |input: f64, r: usize| -input / d.reduction(r);
    assert!(!engine.after_step(0.0, (at(shift.up[0] * 0.999, 0), idle), &drive));
    assert_eq!(engine.engaged(), Some(Engaged::LOWEST));
    assert!(engine.after_step(1.0, (at(shift.up[0] * 1.001, 0), idle), &drive));
    assert_eq!(
        engine.engaged(),
        Some(Engaged {
            range: 1,
            from: Some((0, 1.0 + shift.time))
        })
    );
    assert!(!engine.locked(), "no lock-up while shifting");
    let speed = at(shift.up[0] * 1.001, 0);
    assert!(!engine.after_step(1.0 + 0.5 * shift.time, (speed, idle), &drive));
    engine.after_step(1.0 + shift.time, (speed, idle), &drive);
    assert_eq!(
        engine.engaged(),
        Some(Engaged {
            range: 1,
            from: None
        })
    );
    // In the second range, between its downshift and the first's upshift:
    // it stays (the hysteresis).
    let between = at(0.5 * (shift.down[1] + shift.up[0]), 1);
    engine.after_step(3.0, (between, 1e3), &drive);
    assert_eq!(engine.engaged().map(|e| e.range), Some(1));
    engine.after_step(4.0, (at(shift.down[1] * 0.999, 1), idle), &drive);
    assert_eq!(engine.engaged().map(|e| e.range), Some(0));
    assert!(!engine.locked());
}
