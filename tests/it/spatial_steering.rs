//! The declared spatial vehicle as the applications build it, and a
//! driver steering it: the route every application takes (the
//! declaration's `SpatialVehicleSystem`, `SpatialSimulated::assembled`)
//! builds the same system and start as the tests' own route, bit for
//! bit; a driver holding a heading (`HeadingHold`) turns the `Twin`
//! through the angle it is asked, a right turn mirroring a left.

use trackgen::integrate::{Integrator, OdeSystem};
use trackgen::spatial_vehicle::{
    DrivelineError, HeadingHold, SideDrives, SpatialOutputs, SpatialSimulated,
    SpatialVehicleSystem, SteeringError,
};
use trackgen::terrain::Terrain;
use trackgen::terrain::field::HeightField;
use trackgen::vehicle::Drive;

use crate::support::twin::{Twin, assembled, at_rest, belt, firm, laws, on};

/// The declaration's system on level ground, assembled by
/// `SpatialSimulated::assembled`, is the tests' system at their start
/// with its tensioners set as the assembly set them: the same state and
/// the same right-hand side, bit for bit.
#[test]
fn the_declared_route_builds_the_tests_system() {
    let mut generic = <Twin as SpatialVehicleSystem>::spatial(laws(), HeightField::level())
        .expect("the spatial vehicle");
    let y = generic
        .assembled(&Terrain::Flat { height: 0.0 })
        .expect("both sides assemble");
    let mut own = on(HeightField::level(), laws(), SideDrives::free());
    let tensioners = assembled().tensioners;
    assert!(tensioners.iter().all(Option::is_some), "{tensioners:?}");
    own.dynamics.set_tensioners(tensioners);
    let start = at_rest(0.0, (0.0, 0.0));
    let y_own = own.state(&start.0, &start.1, &start.2);
    assert_eq!(y, y_own);
    let (mut dy, mut dy_own) = (vec![0.0; y.len()], vec![0.0; y.len()]);
    generic.derivative(0.0, y.as_slice(), &mut dy).expect("f");
    own.derivative(0.0, y.as_slice(), &mut dy_own).expect("f");
    assert_eq!(dy, dy_own);
    // The declared laws: the declaration's contact, the guides at its
    // play.
    let declared = Twin::declared_laws();
    assert_eq!(declared.ground, laws().ground);
    assert_eq!(declared.guide.play, laws().guide.play);
}

/// The `Twin`'s heading after a turn of `angle` rad asked from t = 0.5 s
/// over 1.5 s, at belts held to 1.2 m/s: its final heading, rad, at 3 s,
/// and what it shows then.
fn turned(angle: f64) -> (f64, SpatialOutputs) {
    let mut system = on(
        HeightField::level(),
        firm(),
        SideDrives {
            right: belt(1.2, 0.5),
            left: belt(1.2, 0.5),
        },
    )
    .with_steering(HeadingHold::turn(angle, (0.5, 1.5), 1.5, 1.8))
    .expect("a driver");
    let start = at_rest(0.0, (0.0, 0.0));
    let method = Integrator::Bs23 {
        rtol: 1e-4,
        atol: 1e-4,
        max_step: 2e-3,
    };
    let y = crate::support::twin::run(&mut system, &start, 3.0, method);
    let shown = system.outputs(3.0, y.as_slice()).expect("the outputs");
    (system.states(y.as_slice()).0.pose.yaw, shown)
}

/// Asked to turn 45° to the left, the driver holds the `Twin` within 1°
/// of it 1 s after the heading wanted stops turning, each track gripping
/// and held by its sprocket's teeth (its gain 1.5/s takes
/// an error out e-fold in 0.67 s, the belts' speed loop in about 0.1 s);
/// asked 45° to the right, the mirror: the same heading reversed, to the
/// integrator's tolerance (1e-4; the two runs' steps differ in their last
/// bits, so they are not mirror images to the bit).
#[test]
fn a_driver_turns_the_vehicle_through_the_angle_asked() {
    let angle = std::f64::consts::FRAC_PI_4;
    let (left, shown) = turned(angle);
    let (right, _) = turned(-angle);
    // After the turn, each track grips and its sprocket holds its teeth:
    // its own speed round the hull (from its links' velocities where the
    // ground loads them) is the hull's over the ground there (from the
    // centre of mass and the yaw rate), to 1 % (measured 0.5 % and
    // 0.05 %: the stiction points' creep); and the belt's (the sprocket's
    // speed times its rolling radius) within 8 % (measured 5.2 % and
    // 1.4 %: the sprocket's speed swings about the track's as each tooth
    // engages, the chordal action), where a sprocket jumping teeth runs
    // ahead by a third (the Marder's outer track in its turn, the
    // guide's "Steering"). The chordal action alone, a seated joint at
    // `θ` within `±π/z` of the sprocket's top carrying the chain at
    // `ω R cos θ` against the belt's `ω N p/(2π)`, spans −4.1 % to
    // +2.1 % of the belt for the `Twin`'s 9 teeth (`cos θ (π/z)/sin(π/z)`);
    // the rest of the 5.2 % is the sprocket swinging on its teeth's
    // compliance, which has no closed form here: the 8 % is set from the
    // measurement, not derived.
    for side in &shown.sides {
        println!(
            "at 3 s: belt {:.4} m/s, track {:.4}, ground {:.4}",
            side.belt_speed, side.track_speed, side.ground_speed
        );
        assert!(
            (side.track_speed - side.ground_speed).abs() < 0.01 * side.belt_speed,
            "{side:?}"
        );
        assert!(
            (side.track_speed - side.belt_speed).abs() < 0.08 * side.belt_speed,
            "{side:?}"
        );
    }
    println!(
        "asked ±{:.2}°, turned {:.3}° and {:.3}°",
        angle.to_degrees(),
        left.to_degrees(),
        right.to_degrees()
    );
    assert!(
        (left - angle).abs() < 1f64.to_radians(),
        "turned {left} rad"
    );
    assert!((right + left).abs() < 1e-4, "left {left}, right {right}");
}

/// A driver cannot steer torque drives, set before it or after, and a
/// setting out of range is refused, naming it.
#[test]
fn a_driver_needs_speed_drives_and_settings_in_range() {
    let torque = || Drive::Torque(Box::new(|_| 0.0));
    let refused = on(
        HeightField::level(),
        laws(),
        SideDrives {
            right: torque(),
            left: belt(1.0, 1.0),
        },
    )
    .with_steering(HeadingHold::turn(1.0, (0.0, 1.0), 1.0, 1.0));
    assert!(matches!(refused, Err(SteeringError::NotSpeedDrives)));
    let system = || {
        on(
            HeightField::level(),
            laws(),
            SideDrives {
                right: belt(1.0, 1.0),
                left: belt(1.0, 1.0),
            },
        )
    };
    let bad_gain = system().with_steering(HeadingHold::turn(1.0, (0.0, 1.0), f64::NAN, 1.0));
    assert!(matches!(bad_gain, Err(SteeringError::Gain { .. })));
    let bad_difference = system().with_steering(HeadingHold::turn(1.0, (0.0, 1.0), 1.0, 0.0));
    assert!(matches!(
        bad_difference,
        Err(SteeringError::Difference { .. })
    ));
    // Drives set after the heading are checked against it as well: a
    // torque drive it cannot steer is refused.
    let steered = system()
        .with_steering(HeadingHold::turn(1.0, (0.0, 1.0), 1.0, 1.0))
        .expect("speed drives steer");
    let refused = steered.with_drives(SideDrives {
        right: belt(1.0, 1.0),
        left: torque(),
    });
    assert!(matches!(
        refused,
        Err(DrivelineError::Steering(SteeringError::NotSpeedDrives))
    ));
}
