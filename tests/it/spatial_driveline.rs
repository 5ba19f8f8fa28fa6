//! The spatial vehicle driven through a differential (`Driveline`):
//! straight, it is the two side drives it halves; steered by its brakes
//! or its steer unit, a left turn mirrors the right one and the books
//! hold the drive's work with what the brakes store and dissipate; a
//! steering input out of range, or a figure out of its range, is refused.
//! Its steady turns against the general theory of skid steering are in
//! `spatial_turn`.
//!
//! Runs compared to 1e-9 use RK4 at a fixed 0.1 ms (an adaptive method's
//! accepted steps may differ between two runs by a rejection near its
//! threshold); the books use Dormand–Prince at rtol 1e-7, as
//! `spatial_drive`'s do.

use std::f64::consts::FRAC_PI_4;

use trackgen::integrate::{Integrator, OdeSystem, SimulationError};
use trackgen::nalgebra::DVector;
use trackgen::spatial_vehicle::{
    Differential, DifferentialSteer, Driveline, DrivelineError, FullSteer, HeadingHold, SideBooks,
    SideDrives, SpatialEngine, SpatialSimulated, SpatialSystem, SteerUnit, SteeringBrakes,
};
use trackgen::vehicle::{Drive, Powertrain};

use crate::support::twin::{States, System, at_rest, belt, mirror, run, spatial};

/// RK4 at a fixed 0.1 ms.
const FIXED: Integrator = Integrator::Rk4 { step: 1e-4 };

/// Dormand–Prince at rtol 1e-7.
const ADAPTIVE: Integrator = Integrator::Dopri5 {
    rtol: 1e-7,
    atol: 1e-9,
    max_step: 1e-3,
};

/// The differential's box held at a mean belt speed of `speed` m/s,
/// reached over `ramp` s: [`belt`]'s controller on each side, summed
/// (gains and limit twice a side's).
pub fn box_drive(speed: f64, ramp: f64) -> Drive {
    Drive::Speed {
        target: Box::new(move |t| speed * (t / ramp).min(1.0)),
        proportional: 800.0,
        integral: 8000.0,
        max_torque: 6000.0,
    }
}

/// Steering brakes for the `Twin` (3.6 t; about 1 kN m on a sprocket in
/// a turn): 3 kN m each, the elastic stage by the parking brake's rule
/// (`k = 100 T`, `c = √(k J)` with `J` the vehicle's mass reflected to a
/// sprocket, about 100 kg m²), fully on at 0.5 m/s of error in the belts'
/// difference.
pub fn brakes() -> DifferentialSteer {
    let stiffness = 100.0 * 3000.0;
    DifferentialSteer::Brakes(SteeringBrakes {
        max_torque: 3000.0,
        stiffness,
        damping: (stiffness * 100.0_f64).sqrt(),
        band: 0.5,
        dead_band: 0.0,
    })
}

/// A steer unit of minimum steer ratio `ratio` for the `Twin`: a PI on
/// the sprockets' speed difference stiffer than a side's drive (2 kN m
/// per rad/s), limited to 3 kN m.
pub fn steer_unit(ratio: f64) -> DifferentialSteer {
    DifferentialSteer::Unit(SteerUnit {
        full_steer: FullSteer::Ratio(ratio),
        proportional: 2000.0,
        integral: 2e4,
        max_torque: 3000.0,
    })
}

/// A steer unit in neutral for the `Twin`: [`steer_unit`]'s gains, its
/// full steer turning the sprockets `full_difference` rad/s apart, up to
/// 5 kN m (a pivot's turning resistance on a sprocket is about 2 kN m,
/// `spatial_turn`).
pub fn neutral(full_difference: f64) -> DifferentialSteer {
    DifferentialSteer::Unit(SteerUnit {
        full_steer: FullSteer::Neutral(full_difference),
        proportional: 2000.0,
        integral: 2e4,
        max_torque: 5000.0,
    })
}

/// Whether `steer` is a steer unit in neutral.
pub fn in_neutral(steer: &DifferentialSteer) -> bool {
    matches!(
        steer,
        DifferentialSteer::Unit(SteerUnit {
            full_steer: FullSteer::Neutral(_),
            ..
        })
    )
}

/// The box's drive for `steer`: free in neutral, else [`box_drive`] to a
/// mean belt of 1.2 m/s over 0.2 s.
fn box_for(steer: DifferentialSteer) -> Drive {
    if in_neutral(&steer) {
        Drive::Free
    } else {
        box_drive(1.2, 0.2)
    }
}

/// The `Twin` driven through a differential: `drive` on its box, steered
/// by `steer` at the input `input(t)`.
pub fn through(
    drive: Drive,
    steer: DifferentialSteer,
    input: impl Fn(f64) -> f64 + Send + 'static,
) -> System {
    SpatialSystem::new(spatial())
        .with_driveline(Driveline::Differential(Differential {
            drive,
            steer,
            input: Box::new(input),
            engine: None,
        }))
        .expect("a driveline in range")
}

/// A steering input ramped to `lever` over 0.2 s.
fn ramped(lever: f64) -> impl Fn(f64) -> f64 + Send + 'static {
    move |t| lever * (t / 0.2).min(1.0)
}

/// Every value of the three trees at `y` (no driveline states, no books).
fn trees(system: &System, y: &[f64]) -> DVector<f64> {
    let (hull, right, left, _) = system.states(y);
    tree_values(system, &(hull, right, left))
}

/// Every value of `states`, as the state holds them.
fn tree_values(system: &System, states: &States) -> DVector<f64> {
    let y = system.state(&states.0, &states.1, &states.2);
    y.rows(0, system.dynamic_states() - 3).into_owned()
}

/// `a` and `b` equal to `tol` of the larger's size (or of 1).
fn same(a: &[f64], b: &[f64], tol: f64, what: &str) {
    let scale = a.iter().chain(b).fold(1.0_f64, |m, v| m.max(v.abs()));
    for (i, (x, y)) in a.iter().zip(b).enumerate() {
        assert!((x - y).abs() <= tol * scale, "{what}[{i}]: {x} against {y}");
    }
}

/// Driven straight with no steering, a differential under a drive of
/// twice a side's gains and limit moves the (mirror-symmetric) `Twin` as
/// the two side drives do, to 1e-9 of the state after 0.3 s of RK4: its
/// box turns at the axles' mean and halves its torque, the brakes
/// released hold nothing, and the steer unit holding the sprockets
/// together pushes only the round-off between them.
#[test]
fn driven_straight_a_differential_is_the_two_drives_it_halves() {
    let start = at_rest(0.0, (0.0, 0.0));
    let mut sides = SpatialSystem::new(spatial())
        .with_drives(SideDrives {
            right: belt(1.2, 0.2),
            left: belt(1.2, 0.2),
        })
        .expect("drives");
    let reference = run(&mut sides, &start, 0.3, FIXED);
    let moved = trees(&sides, reference.as_slice());
    let (hull, ..) = sides.states(reference.as_slice());
    assert!(
        hull.pose.origin.x > start.0.pose.origin.x + 0.05,
        "it moves"
    );
    for (name, steer) in [("brakes", brakes()), ("steer unit", steer_unit(2.31))] {
        let mut system = through(box_drive(1.2, 0.2), steer, |_| 0.0);
        let y = run(&mut system, &start, 0.3, FIXED);
        same(
            trees(&system, y.as_slice()).as_slice(),
            moved.as_slice(),
            1e-9,
            name,
        );
        let drive = system.drive_state(0.3, y.as_slice()).expect("the drive");
        assert_eq!(drive.brake, [0.0, 0.0], "{name}: {drive:?}");
    }
}

/// Steered left by its brakes (the left braked at half the input's
/// range), its steer unit (full steer, ratio 2.31) or its steer unit in
/// neutral (a pivot), and right by the opposite input, the `Twin` ends
/// the mirror image of itself after 0.3 s, to 1e-9 of the state's size.
#[test]
fn a_left_turn_through_a_differential_mirrors_the_right_turn() {
    let start = at_rest(0.0, (0.0, 0.0));
    for (name, steer, lever) in [
        ("brakes", brakes(), 0.5),
        ("steer unit", steer_unit(2.31), 1.0),
        ("neutral", neutral(8.0), 1.0),
    ] {
        let mut left = through(box_for(steer), steer, ramped(lever));
        let mut right = through(box_for(steer), steer, ramped(-lever));
        let a = run(&mut left, &start, 0.3, FIXED);
        let b = run(&mut right, &start, 0.3, FIXED);
        let (hull, ..) = left.states(a.as_slice());
        assert!(
            hull.pose.yaw > 1e-4,
            "{name}: a left turn, yaw {}",
            hull.pose.yaw
        );
        let (h, r, l, _) = left.states(a.as_slice());
        same(
            trees(&right, b.as_slice()).as_slice(),
            tree_values(&left, &mirror(&(h, r, l))).as_slice(),
            1e-9,
            name,
        );
        // Each side's books are the mirrored turn's other side's.
        let values = |b: &SideBooks| {
            [
                b.sprocket_work,
                b.ground,
                b.running_gear,
                b.suspension,
                b.brake,
            ]
        };
        let [l_right, l_left] = left.side_books(a.as_slice());
        let [r_right, r_left] = right.side_books(b.as_slice());
        same(&values(&l_right), &values(&r_left), 1e-9, name);
        same(&values(&l_left), &values(&r_right), 1e-9, name);
    }
}

/// A turn through a differential keeps its books (the drive's work, and
/// the steer unit's, against the energy in the bodies, the force
/// elements and the brakes' elastic stages and what all of them
/// dissipate) to 1e-6 of the work at rtol 1e-7 (a brake's power left
/// out of the books, or its stored energy, is of the order of the
/// work), and turns left. The left brake holds the left sprocket back
/// (its torque against the sprocket's forward turning); the steer unit
/// pushes the right sprocket forward and the left one back, and the
/// power it takes from the left side returns through the right. In
/// neutral the unit alone drives: a pivot, both sides taking work.
#[test]
fn a_turn_through_a_differential_keeps_its_books() {
    let start = at_rest(0.0, (0.0, 0.0));
    for (name, steer, lever) in [
        ("brakes", brakes(), 0.5),
        ("steer unit", steer_unit(2.31), 1.0),
        ("neutral", neutral(8.0), 1.0),
    ] {
        let mut system = through(box_for(steer), steer, ramped(lever));
        let y0 = system.state(&start.0, &start.1, &start.2);
        let before = system.energy(y0.as_slice());
        let y = run(&mut system, &start, 0.6, ADAPTIVE);
        let after = system.energy(y.as_slice());
        assert!(after.driven > 100.0, "{name}: {after:?}");
        let residual = (after.total() - before.total()) / after.driven;
        println!("{name}: {after:?}, residual {residual:.2e}");
        assert!(residual.abs() < 1e-6, "{name}: residual {residual:e}");
        // Every loss is one side's: the sides' add up to the books' (the
        // same terms integrated apart, to rounding).
        let sides = system.side_books(y.as_slice());
        println!("{name}: {sides:?}");
        let lost = sides[0].lost() + sides[1].lost();
        let dissipated = after.dissipated - before.dissipated;
        assert!(
            (lost - dissipated).abs() < 1e-9 * dissipated,
            "{name}: {lost} against {dissipated}"
        );
        // The outer (right) side takes more work than the inner, whose
        // brake alone dissipates; pivoting, each side takes work.
        if name == "neutral" {
            assert!(sides.iter().all(|s| s.sprocket_work > 10.0), "{sides:?}");
        } else {
            assert!(sides[0].sprocket_work > sides[1].sprocket_work, "{sides:?}");
        }
        assert_eq!(sides[0].brake, 0.0, "{name}");
        assert_eq!(sides[1].brake > 0.0, name == "brakes", "{sides:?}");
        let (hull, ..) = system.states(y.as_slice());
        assert!(hull.pose.yaw > 1e-3, "{name}: yaw {}", hull.pose.yaw);
        let drive = system.drive_state(0.6, y.as_slice()).expect("the drive");
        println!("{name}: {drive:?}");
        // Driving forward turns a sprocket negative.
        assert!(drive.speed[0] < drive.speed[1], "{name}: {drive:?}");
        match steer {
            DifferentialSteer::Brakes(_) => {
                assert!(drive.brake[1] > 0.0 && drive.brake[0] == 0.0, "{drive:?}");
                assert!(drive.dissipation > 0.0, "{drive:?}");
            }
            DifferentialSteer::Unit(_) => {
                assert!(drive.torque[0] < drive.torque[1], "{drive:?}");
                assert_eq!(drive.brake, [0.0, 0.0]);
            }
        }
        if name == "neutral" {
            // The right sprocket forward, the left back.
            assert!(drive.speed[0] < 0.0 && drive.speed[1] > 0.0, "{drive:?}");
        }
    }
}

/// A steering input outside `[−1, 1]` stops the run with the time and
/// the cause, one that is NaN too; brakes or a steer unit with a figure
/// out of its range are refused before any run.
#[test]
fn bad_steering_is_refused() {
    let start = at_rest(0.0, (0.0, 0.0));
    for (input, what) in [(1.5, "outside"), (f64::NAN, "steering input")] {
        let mut system = through(box_drive(1.2, 0.2), brakes(), move |t| {
            if t < 0.01 { 0.0 } else { input }
        });
        let mut y = system.state(&start.0, &start.1, &start.2);
        let mut stepper = FIXED.stepper(system.dimension());
        let mut t = 0.0;
        let error = loop {
            if let Err(e) = stepper.step(&mut system, &mut t, &mut y, 0.1) {
                break e;
            }
            assert!(t < 0.1, "the run went on");
        };
        assert!(
            matches!(
                error,
                SimulationError::Stopped { t, .. } | SimulationError::NonFinite { t, .. }
                    if (0.01..0.0102).contains(&t)
            ),
            "{error:?}"
        );
        assert!(error.to_string().contains(what), "{error}");
    }
    let refused = |steer: DifferentialSteer| {
        SpatialSystem::new(spatial())
            .with_driveline(Driveline::Differential(Differential {
                drive: box_drive(1.0, 0.2),
                steer,
                input: Box::new(|_| 0.0),
                engine: None,
            }))
            .err()
    };
    let mut unit = SteerUnit {
        full_steer: FullSteer::Ratio(0.9),
        proportional: 1.0,
        integral: 1.0,
        max_torque: 1.0,
    };
    let error = refused(DifferentialSteer::Unit(unit)).expect("a ratio under 1 refused");
    assert!(
        matches!(error, DrivelineError::Figure { .. }) && error.to_string().contains("ratio"),
        "{error}"
    );
    unit.full_steer = FullSteer::Ratio(2.0);
    unit.max_torque = f64::NAN;
    assert!(refused(DifferentialSteer::Unit(unit)).is_some());
    let DifferentialSteer::Brakes(mut b) = brakes() else {
        unreachable!()
    };
    b.band = 0.0;
    assert!(refused(DifferentialSteer::Brakes(b)).is_some());
    assert!(refused(brakes()).is_none());
    let neutral_refused = |steer: DifferentialSteer| {
        SpatialSystem::new(spatial())
            .with_driveline(Driveline::Differential(Differential {
                drive: Drive::Free,
                steer,
                input: Box::new(|_| 0.0),
                engine: None,
            }))
            .err()
    };
    assert!(neutral_refused(neutral(8.0)).is_none());
    for bad in [0.0, -1.0, f64::INFINITY, f64::NAN] {
        let error = neutral_refused(neutral(bad)).expect("a full difference out of range refused");
        assert!(
            matches!(error, DrivelineError::Figure { .. })
                && error.to_string().contains("full-steer difference"),
            "{bad}: {error}"
        );
    }
}

/// A driver holding a heading steers through a differential too: asked
/// 45° to the left from 0.5 s over 1.5 s, the `Twin` driven at a mean
/// 1.2 m/s holds within 2° of it at 4 s through its steer unit (the
/// difference asked, up to the unit's ratio; measured 0.9° short) and
/// through its brakes (measured 0.8° short), and pivots to it standing
/// through its steer unit in neutral. A brake turns the vehicle
/// only once its torque passes what the ground's turning resistance
/// needs (about 2 kN m on the `Twin`, `spatial_turn`): a driver braking
/// in proportion to the difference asked, fully at the gauge times
/// 1 rad/s, left the `Twin` 5.7° past the heading, its correcting brake
/// (0.8 kN m) short of that; one braking fully at a third of it (as
/// here) corrects with the brake fully on.
#[test]
fn a_driver_turns_the_vehicle_through_a_differential() {
    let start = at_rest(0.0, (0.0, 0.0));
    let DifferentialSteer::Brakes(mut b) = brakes() else {
        unreachable!()
    };
    b.band = 0.6;
    for (name, steer) in [
        ("brakes", DifferentialSteer::Brakes(b)),
        ("steer unit", steer_unit(2.31)),
        ("neutral", neutral(8.0)),
    ] {
        let drive = if in_neutral(&steer) {
            Drive::Free
        } else {
            box_drive(1.2, 0.5)
        };
        let mut system = through(drive, steer, |_| 0.0)
            .with_steering(HeadingHold::turn(FRAC_PI_4, (0.5, 1.5), 1.5, 1.8))
            .expect("a driver");
        let mut y = system.state(&start.0, &start.1, &start.2);
        let mut stepper = Integrator::Bs23 {
            rtol: 1e-4,
            atol: 1e-4,
            max_step: 2e-3,
        }
        .stepper(system.dimension());
        let mut t = 0.0;
        let mut brake_right = 0.0_f64;
        while t < 4.0 {
            stepper
                .step(&mut system, &mut t, &mut y, 4.0)
                .expect("the run");
            let drive = system.drive_state(t, y.as_slice()).expect("the drive");
            brake_right = brake_right.max(drive.brake[0].abs());
        }
        let heading = system.states(y.as_slice()).0.pose.yaw;
        println!(
            "{name}: heading {:.3}°, right brake at most {brake_right:.1} N m",
            heading.to_degrees()
        );
        assert!(
            (heading - FRAC_PI_4).abs() < 2f64.to_radians(),
            "{name}: heading {heading}"
        );
    }
}

/// The M113A3's engine, converter and ranges with a final drive of 12 on
/// the `Twin` (its box at 1.2 m/s turns the converter's turbine at some
/// 230 rad/s in the first range), and a steer drive of ratio
/// [`STEER_DRIVE`] geared to that engine.
fn engine_twelve() -> SpatialEngine {
    let mut powertrain = trackgen::vehicles::m113::powertrain();
    if let Powertrain::Converter(d) = &mut powertrain {
        d.final_drive = 12.0;
    }
    SpatialEngine::new(powertrain).expect("an engine with dynamics")
}

/// The steer drive's ratio for [`engine_twelve`], rad/s of the sprockets'
/// difference per rad/s of the engine: about a ratio of 2 at the box's
/// 1.2 m/s in the first range.
const STEER_DRIVE: f64 = 0.012;

/// A steer drive geared to an engine whose speed is a state
/// (`FullSteer::Engine`) holds the sprockets' speed difference at
/// `s k ω_e` from the engine's speed, whatever the range and the
/// converter's slip: the `Twin` crawling at a mean 0.1 m/s in the first
/// range (which does not lock up), steered at half its input, holds it
/// within 1 % on the mean of the last 0.5 s of a 2 s run (measured
/// 0.34 %; its unit ten times as stiff as [`steer_unit`]'s, since at a
/// crawl the shoes' ripple is as slow as the unit's own answer). Through
/// the unlocked converter at a crawl the engine runs at its idle while
/// the box's range alone would turn it slower (`ω_e > N ω̄`), so the turn
/// is tighter than the range's locked ratio (`k N ω̄`) by `1/SR`: more
/// than 1.2 times here (measured 1.64). Without an engine on the box
/// such a unit is refused. Bogacki-Shampine at 1e-6.
#[test]
fn a_steer_drive_geared_to_the_engine_holds_its_difference_from_the_engine_s_speed() {
    let start = at_rest(0.0, (0.0, 0.0));
    let lever = 0.5;
    let engine = engine_twelve();
    let reduction = engine.driveline().reduction(0);
    let unit = |full_steer| {
        DifferentialSteer::Unit(SteerUnit {
            full_steer,
            proportional: 2e4,
            integral: 2e5,
            max_torque: 5000.0,
        })
    };
    let refused = SpatialSystem::new(spatial())
        .with_driveline(Driveline::Differential(Differential {
            drive: box_drive(1.2, 0.2),
            steer: unit(FullSteer::Engine(STEER_DRIVE)),
            input: Box::new(|_| 0.0),
            engine: None,
        }))
        .err();
    assert!(
        matches!(refused, Some(DrivelineError::NoEngine)),
        "{refused:?}"
    );
    let mut system = SpatialSystem::new(spatial())
        .with_driveline(Driveline::Differential(Differential {
            drive: box_drive(0.1, 0.2),
            steer: unit(FullSteer::Engine(STEER_DRIVE)),
            input: Box::new(ramped(lever)),
            engine: Some(engine),
        }))
        .expect("a driveline in range");
    let mut y = system.state(&start.0, &start.1, &start.2);
    system.start_engine(y.as_mut_slice());
    let method = Integrator::Bs23 {
        rtol: 1e-6,
        atol: 1e-6,
        max_step: 1e-3,
    };
    let mut stepper = method.stepper(system.dimension());
    let (mut t, mut sums, mut slip) = (0.0, (0.0, 0.0), f64::INFINITY);
    for k in 1..=200 {
        let next = k as f64 * 0.01;
        while t < next {
            stepper
                .step(&mut system, &mut t, &mut y, next)
                .expect("the run");
            if system.after_step(t, y.as_slice()) {
                stepper.restart();
            }
        }
        if t < 1.5 {
            continue;
        }
        let drive = system.drive_state(t, y.as_slice()).expect("the drive");
        let out = system.outputs(t, y.as_slice()).expect("the outputs");
        let engine = out.engine.expect("an engine on the box");
        assert_eq!(out.gear, 1.0, "the first range at {t}");
        let asked = -lever * STEER_DRIVE * engine.engine_speed;
        let held = drive.speed[0] - drive.speed[1];
        sums.0 += held;
        sums.1 += asked;
        let mean = 0.5 * (drive.speed[0] + drive.speed[1]);
        slip = slip.min(engine.engine_speed / (reduction * mean.abs()));
    }
    let off = sums.0 / sums.1 - 1.0;
    println!("held within {off:.2e} of s k ω_e; ω_e over N ω̄ at least {slip:.4}");
    assert!(
        off.abs() < 0.01,
        "the difference held within {off} of s k ω_e"
    );
    assert!(slip > 1.2, "the converter slips by {slip}");
}
