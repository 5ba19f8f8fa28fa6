//! Parked across a side slope on its brakes: the `Twin` (3.5 t, gauge
//! 1.8 m) set down across a 30 % side slope (the M113's published side
//! slope), both sprockets braked, on firm ground with stiction (`support::twin::firm`, the steady turns'). Once it
//! has settled onto the slope ([`SETTLE`]), its hull moves less than 1 mm
//! over the next 10 s: stiction holds without creep
//! (`μ = 0.7` against the slope's `tan φ = 0.3`), and a brake holds by an
//! elastic stage, not a rate (`vehicle::Brake`). Measured: under the
//! regularised friction instead the same vehicle slides down the slope at
//! 45 mm/s.

use trackgen::contact::sprocket::rolling_radius;
use trackgen::integrate::{Integrator, OdeSystem};
use trackgen::multibody::RecursiveModel;
use trackgen::nalgebra::{Vector2, Vector3};
use trackgen::spatial_vehicle::SideDrives;
use trackgen::terrain::field::HeightField;
use trackgen::vehicle::{Brake, Vehicle};

use crate::support::twin::{System, TRACK, Twin, across_slope, firm, on};

/// The slope, rise over run across the vehicle.
const SIDE_SLOPE: f64 = 0.3;

/// How long the vehicle settles onto the slope before it is watched, s:
/// set down 1 mm above it from rest, it drops onto its suspension and
/// its tracks shift within the guides' play. Measured (printed): the
/// hull's root moves 10 mm forward, 2.8 mm downhill and 7.6 mm down in
/// that time, most of it in the first 3 s (12 mm forward by then, then
/// back); the bound is on what follows.
const SETTLE: f64 = 5.0;

/// The hull's root's place at `y`, m.
fn hull_at(system: &System, y: &[f64]) -> Vector3<f64> {
    system.states(y).0.pose.origin
}

#[test]
fn parked_across_a_30_percent_side_slope_the_hull_holds_within_a_millimetre() {
    // Each side's share of the vehicle's mass reflected through its
    // sprocket sets the brake's damping (`Brake::parking`: ratio 0.5);
    // its limit is the torque of half that share's weight at the
    // sprocket (the pull of a 30° slope).
    let start = across_slope(SIDE_SLOPE);
    let field = HeightField::level().tilted(Vector2::new(0.0, SIDE_SLOPE));
    let free = on(field, firm(), SideDrives::free());
    let mass = free
        .mass_centre(free.state(&start.0, &start.1, &start.2).as_slice())
        .mass;
    let pitch = TRACK.description().pitch().expect("one pitch");
    let radius = rolling_radius(Twin::geometry().sprocket.teeth, pitch);
    let hold = 0.5 * mass * free.dynamics.hull.gravity() * 0.5 * radius;
    let brake = Brake::parking(hold, 0.5 * mass * radius * radius, 0.0);
    let mut system = free
        .with_drives(SideDrives {
            right: brake.as_drive(),
            left: brake.as_drive(),
        })
        .expect("brakes that make controllers");
    let mut y = system.state(&start.0, &start.1, &start.2);
    let mut stepper = Integrator::Bs23 {
        rtol: 1e-6,
        atol: 1e-6,
        max_step: 1e-3,
    }
    .stepper(system.dimension());
    let mut t = 0.0;
    while t < SETTLE {
        stepper
            .step(&mut system, &mut t, &mut y, SETTLE)
            .expect("the run");
    }
    let settled = hull_at(&system, y.as_slice());
    let dropped = settled
        - hull_at(
            &system,
            system.state(&start.0, &start.1, &start.2).as_slice(),
        );
    println!(
        "settling: the hull's root moved ({:.2}, {:.2}, {:.2}) mm in {SETTLE} s",
        1e3 * dropped.x,
        1e3 * dropped.y,
        1e3 * dropped.z,
    );
    // The farthest the root gets from where it settled, at every
    // accepted step of the next 10 s.
    let mut farthest: f64 = 0.0;
    for end in (1..=10).map(|k| SETTLE + k as f64) {
        while t < end {
            stepper
                .step(&mut system, &mut t, &mut y, end)
                .expect("the run");
            farthest = farthest.max((hull_at(&system, y.as_slice()) - settled).norm());
        }
        let moved = hull_at(&system, y.as_slice()) - settled;
        println!(
            "then at {end:4.1} s: ({:.3}, {:.3}, {:.3}) mm",
            1e3 * moved.x,
            1e3 * moved.y,
            1e3 * moved.z
        );
    }
    assert!(
        farthest < 1e-3,
        "the hull moved up to {:.3} mm in 10 s on the brakes",
        1e3 * farthest
    );
}

/// The system's own start across a slope (`SpatialSystem::rolled`, what
/// `spatial --side-slope` sets the vehicle down with) is the tests' own
/// (`support::twin::across_slope`, each tree turned by its own
/// rotation), bit for bit, and every value of the state the trees do not
/// hold is kept.
#[test]
fn the_systems_start_across_a_slope_is_the_tests_own() {
    let level = crate::support::twin::at_rest(0.0, (0.0, 0.0));
    let system = on(HeightField::level(), firm(), SideDrives::free());
    let mut y = system.state(&level.0, &level.1, &level.2);
    let n = y.len();
    y[n - 1] = 7.0;
    let rolled = system.rolled(y.as_slice(), SIDE_SLOPE.atan());
    let own = across_slope(SIDE_SLOPE);
    let mut expected = system.state(&own.0, &own.1, &own.2);
    expected[n - 1] = 7.0;
    assert_eq!(rolled, expected);
}

/// The side-slope event's trial (`mobility::side_slope::traverse`)
/// against the closed form that bounds it: with friction the same in
/// every direction the ground holds at most `μ N` across, so no vehicle
/// holds a slope steeper than `tan φ = μ`. The `Twin` on firm ground
/// (stiction, `μ = 0.7`) and on ground of half that friction, each
/// driven along the contour at the events' crawl:
///
/// - at 5 % past `μ` it slides away (its drift past the event's 5 %:
///   the trial fails);
/// - at 85 % of `μ` it holds (the M113 creeps 2.9 % at 90 % of its
///   `μ = 0.8` and holds to 93 %; the drive's own pull along the path
///   and the sprung hull's sway take the rest).
///
/// The limit moves with the ground's friction, as the closed form says:
/// the experiment behind the guide's account of the event's answer
/// against the published side slope.
#[test]
fn a_side_slope_is_held_below_the_grounds_friction_and_not_past_it() {
    use trackgen::contact::GroundFriction;
    use trackgen::laws::Stiction;
    use trackgen::mobility::EventSettings;
    use trackgen::mobility::side_slope::{DRIFT, traverse};
    use trackgen::vehicle::Powertrain;

    // The side slope drives on the speed drives alone: the settings'
    // powertrain is not used.
    let settings = EventSettings::new(Powertrain::Power {
        power: 1e5,
        max_torque: 1e4,
    });
    for mu in [crate::support::twin::MU, crate::support::twin::MU / 2.0] {
        let mut laws = firm();
        let GroundFriction::Stiction(stiction) = laws.ground.friction else {
            unreachable!("the firm laws stick")
        };
        laws.ground.friction = GroundFriction::Stiction(Stiction { mu, ..stiction });
        let below = traverse::<Twin>(&settings, laws, 0.85 * mu).expect("the run below");
        let past = traverse::<Twin>(&settings, laws, 1.05 * mu).expect("the run past");
        println!(
            "μ {mu}: drift {:.4} at 0.85 μ (roll off by {:.3} rad), {:.4} at 1.05 μ",
            below.drift(),
            below.roll_error,
            past.drift()
        );
        assert!(below.held, "μ {mu}: not held at 0.85 μ: {below:?}");
        assert!(!past.held, "μ {mu}: held past μ: {past:?}");
        assert!(past.drift() > DRIFT);
    }
}
