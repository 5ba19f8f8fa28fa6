//! The turning event (`mobility::turning`) on the spatial light carrier
//! (`Twin`) on firm level ground, against the general theory of skid
//! steering (Wong & Chiang, 2001; `steering::SkidSteer`) fed what `steer`
//! feeds it: the planar model's shoe loads at rest, both tracks loaded
//! alike, the ground's `μ` and the rolling resistance a straight run
//! shows, at the belt speeds the event drives.
//!
//! The event asks for the belts a full steer gives at the crawl (1 m/s
//! mean): a steer unit of minimum ratio 2.31 (the M113A3's first range)
//! turns the outer belt 2.31 times as fast as the inner; a braked
//! differential holds the inner belt; the pivot turns them at ±1 m/s.
//! Each run's belts are checked to be those (1 %), its radius larger than
//! the kinematic one (slip only opens a turn), and its yaw rate and
//! radius within 5 % of the theory's: `spatial_turn` holds the model to
//! the theory within 5 % with the run's own loads, and at a crawl the
//! loads move little from rest. Measured: the steer unit's turn 0.351
//! rad/s on 2.85 m (theory 0.352, 2.84), the braked one 0.895 rad/s on
//! 1.11 m (0.903, 1.11), the pivot 0.890 rad/s (0.888): within 0.9 %.
//! A ratio of 1 or less, or not finite, is refused before anything
//! runs.

use trackgen::analysis::{EquilibriumOptions, equilibrium};
use trackgen::mobility::turning::{SteadyTurnRun, pivot, smallest_radius};
use trackgen::mobility::{EventError, EventSettings};
use trackgen::multibody::RecursiveModel;
use trackgen::spatial::SpatialVehicle;
use trackgen::spatial_vehicle::SpatialVehicleSystem;
use trackgen::steering::{SkidSteer, SteadyTurn, TrackLoad};
use trackgen::terrain::Terrain;
use trackgen::vehicle::{Powertrain, Vehicle, VehicleDynamics};

use crate::support::twin::{MU, Twin, firm};

/// The event's settings: the crawl at 1 m/s, an engine whose envelope
/// never binds at it (50 kW and 5 kN m a side).
fn settings() -> EventSettings {
    EventSettings::new(Powertrain::Power {
        power: 50e3,
        max_torque: 5e3,
    })
}

/// The rolling resistance of the light carrier on firm ground, its
/// running gear's losses at the belt over its weight: 0.02, measured by
/// `spatial_turn` driven straight at 1.2 m/s.
const ROLLING: f64 = 0.02;

/// The theory's vehicle as `steer` builds it: the planar model at rest,
/// its shoe loads about their centre, on both tracks at the gauge.
fn theory() -> SkidSteer {
    let mut planar =
        Twin::system(Terrain::Flat { height: 0.0 }, Twin::speed_drive(|_| 0.0)).expect("builds");
    let rest = equilibrium(&mut planar, &EquilibriumOptions::default()).expect("rests");
    let points = planar
        .ground_loads(rest.t, rest.state.as_slice())
        .expect("the loads at rest");
    let load: f64 = points.iter().map(|p| p.1).sum();
    // The loads carry what the ground carries at rest (under the
    // carrier's regularised friction too, whose points keep no state).
    assert!(
        (load / rest.ground_force - 1.0).abs() < 1e-9,
        "{load} N of {} N",
        rest.ground_force
    );
    let centre = points.iter().map(|p| p.0.x * p.1).sum::<f64>() / load;
    let along: Vec<(f64, f64)> = points.iter().map(|p| (p.0.x - centre, p.1)).collect();
    let run = TrackLoad::from_points(0.5 * Twin::layout().gauge, &along);
    let gravity = <<Twin as Vehicle>::System as VehicleDynamics>::track_description()
        .gravity
        .norm();
    SkidSteer {
        mass: 2.0 * rest.weight / gravity,
        friction: MU,
        rolling_resistance: 0.0,
        belt_resistance: ROLLING,
        tracks: [run.clone(), run.mirrored()],
    }
}

/// The theory's turn at the run's belts (the theory takes them left,
/// right), a belt within 1 mm/s of standing taken as standing.
fn theory_at(vehicle: &SkidSteer, run: &SteadyTurnRun) -> SteadyTurn {
    let belt = |u: f64| if u.abs() < 1e-3 { 0.0 } else { u };
    vehicle
        .drive([belt(run.belts[1]), belt(run.belts[0])])
        .expect("the theory's turn")
}

/// `run`'s yaw rate and radius within 5 % of `theory`'s.
fn agrees(what: &str, run: &SteadyTurnRun, theory: &SteadyTurn) {
    println!(
        "{what}: yaw rate {:.4} (theory {:.4}) rad/s, radius {:.3} (theory {:.3}) m, belts {:?}, \
         steady {} at {:.1} s",
        run.yaw_rate, theory.yaw_rate, run.radius, theory.radius, run.belts, run.steady, run.until
    );
    assert!(run.steady, "{what}: not steady by {} s", run.until);
    assert!(
        (run.yaw_rate / theory.yaw_rate - 1.0).abs() < 0.05,
        "{what}: yaw rate {} against {}",
        run.yaw_rate,
        theory.yaw_rate
    );
    if run.radius > 0.1 {
        assert!(
            (run.radius / theory.radius - 1.0).abs() < 0.05,
            "{what}: radius {} against {}",
            run.radius,
            theory.radius
        );
    }
}

#[test]
fn the_smallest_turns_and_the_pivot_follow_the_theory() {
    let settings = settings();
    let vehicle = theory();
    let half = 0.5 * Twin::layout().gauge;
    let (unit, braked, pivoted) = std::thread::scope(|scope| {
        let unit = scope.spawn(|| smallest_radius::<Twin>(&settings, firm(), Some(2.31)));
        let braked = scope.spawn(|| smallest_radius::<Twin>(&settings, firm(), None));
        let pivoted = pivot::<Twin>(&settings, firm()).expect("the pivot");
        assert_eq!(pivoted.belts, 1.0, "without steer ratios, the crawl");
        let pivoted = pivoted.run;
        (
            unit.join().unwrap().expect("the steer unit's turn"),
            braked.join().unwrap().expect("the braked turn"),
            pivoted,
        )
    });
    // The steer unit's full steer: the belts 2 ρ/(ρ + 1) and 2/(ρ + 1).
    let [outer, inner] = unit.run.belts;
    assert!(
        (outer / inner / 2.31 - 1.0).abs() < 0.01,
        "{:?}",
        unit.run.belts
    );
    assert!(
        (0.5 * (outer + inner) - 1.0).abs() < 0.01,
        "{:?}",
        unit.run.belts
    );
    assert!((unit.kinematic - half * 3.31 / 1.31).abs() < 1e-12);
    assert!(unit.run.radius > unit.kinematic, "{unit:?}");
    agrees(
        "steer unit, ρ 2.31",
        &unit.run,
        &theory_at(&vehicle, &unit.run),
    );
    // The braked differential's: the inner belt held, the outer at 2 m/s.
    assert!(braked.run.belts[1].abs() < 0.01, "{:?}", braked.run.belts);
    assert!(
        (braked.run.belts[0] - 2.0).abs() < 0.02,
        "{:?}",
        braked.run.belts
    );
    assert_eq!(braked.kinematic, half);
    assert!(braked.run.radius > half, "{braked:?}");
    agrees(
        "inner belt held",
        &braked.run,
        &theory_at(&vehicle, &braked.run),
    );
    // The pivot: ±1 m/s, about the centre.
    assert!((pivoted.belts[0] - 1.0).abs() < 0.01 && (pivoted.belts[1] + 1.0).abs() < 0.01);
    assert!(pivoted.radius < 0.05 * half, "{pivoted:?}");
    agrees("pivot", &pivoted, &theory_at(&vehicle, &pivoted));
}

/// With the M113A3's converter powertrain, which declares the X200-4's
/// published steer ratios, the `Twin` pivots in neutral at full steer: its belts
/// asked at `±k ω_e r / 2`, `k` the mean of each range's `q_r / N_r`
/// (computed here from the published figures), `ω_e` the 6V53T's rated
/// 2800 rpm and `r` the `Twin`'s rolling radius, to 1e-12; run there
/// within 1 %, and turning as the theory does within 5 %.
#[test]
fn with_published_steer_ratios_the_pivot_is_the_neutral_one() {
    use trackgen::vehicles::m113;
    let settings = EventSettings::new(m113::powertrain());
    let turn = pivot::<Twin>(&settings, firm()).expect("the neutral pivot");
    let (asked, pivoted) = (turn.belts, turn.run);
    let k = crate::support::x200::steer_drive_ratio();
    let pitch = crate::support::twin::TRACK
        .description()
        .pitch()
        .expect("one pitch");
    let r = trackgen::contact::sprocket::rolling_radius(Twin::geometry().sprocket.teeth, pitch);
    let want = 0.5 * k * m113::ENGINE_RATED_SPEED * r;
    assert!((asked / want - 1.0).abs() < 1e-12, "{asked} against {want}");
    for (belt, sign) in pivoted.belts.iter().zip([1.0, -1.0]) {
        assert!((belt / (sign * asked) - 1.0).abs() < 0.01, "{pivoted:?}");
    }
    agrees("neutral pivot", &pivoted, &theory_at(&theory(), &pivoted));
}

#[test]
fn a_steer_ratio_out_of_range_is_refused() {
    for ratio in [1.0, 0.5, f64::NAN, f64::INFINITY] {
        match smallest_radius::<Twin>(&settings(), firm(), Some(ratio)) {
            Err(EventError::Setting { event, what, .. }) => {
                assert_eq!(event, "turning");
                assert!(what.contains("steer ratio"), "{what}");
            }
            other => panic!("a ratio of {ratio} was not refused: {other:?}"),
        }
    }
}

/// Cornering through a steer unit with an engine whose speed is a state
/// (the M113A3's engine, converter and ranges with a final drive of 12,
/// so that the light carrier's crawl turns its turbine in the first
/// range): the box driven through the engine, the steer unit the drive
/// geared to it at the ratio a minimum steer ratio of 2 makes through
/// the first range. At 2 m/s on a 10 m circle it holds the circle, its
/// path's radius within the event's 10 % and its lateral acceleration
/// `v²/R` within 10 %, as on its side drives (measured 10.09 m,
/// 0.399 m/s²).
#[test]
fn a_corner_is_held_through_the_engine_s_steer_drive() {
    use trackgen::mobility::cornering::corner;
    let mut powertrain = trackgen::vehicles::m113::powertrain();
    if let Powertrain::Converter(d) = &mut powertrain {
        d.final_drive = 12.0;
    }
    let settings = EventSettings::new(powertrain);
    let run = corner::<Twin>(&settings, Twin::declared_laws(), (10.0, Some(2.0)), 2.0)
        .expect("the corner");
    println!("{run:?}, {:.3} m/s²", run.lateral_acceleration());
    assert!(run.held, "{run:?}");
    assert!((run.radius / 10.0 - 1.0).abs() <= 0.1, "{run:?}");
    assert!(
        (run.lateral_acceleration() / 0.4 - 1.0).abs() <= 0.1,
        "{run:?}"
    );
}

/// Cornering (`mobility::cornering::corner`) on the light carrier's
/// regularised ground (`μ` 0.7), through its side drives: at 2 m/s on a
/// 10 m circle (0.4 m/s², 6 % of `μ g`) it holds the circle, its path's
/// radius within the event's 10 % and its lateral acceleration `v²/R`
/// within 10 % (measured 10.02 m, 0.402 m/s²); at 10 m/s on the same
/// circle (10 m/s², past the `μ g` = 6.9 m/s² that the ground's friction
/// allows any steady turn: the closed form) it cannot (it slid out to a
/// 38 m path at 9.5 m/s). A speed, a radius or a steer ratio out of
/// range is refused before anything runs.
#[test]
fn a_corner_is_held_below_the_grip_and_not_past_it() {
    use trackgen::mobility::cornering::corner;
    let settings = settings();
    let laws = Twin::declared_laws();
    let (slow, fast) = std::thread::scope(|scope| {
        let fast = scope.spawn(|| corner::<Twin>(&settings, laws, (10.0, None), 10.0));
        let slow = corner::<Twin>(&settings, laws, (10.0, None), 2.0).expect("the slow corner");
        (slow, fast.join().unwrap().expect("the fast corner"))
    });
    println!("slow {slow:?}, {:.3} m/s²", slow.lateral_acceleration());
    println!("fast {fast:?}, {:.3} m/s²", fast.lateral_acceleration());
    assert!(slow.held, "{slow:?}");
    assert!((slow.radius / 10.0 - 1.0).abs() <= 0.1, "{slow:?}");
    assert!(
        (slow.lateral_acceleration() / 0.4 - 1.0).abs() <= 0.1,
        "{slow:?}"
    );
    assert!(!fast.held, "held past the grip: {fast:?}");
    let g = trackgen::ride::G;
    assert!(10.0 * 10.0 / 10.0 > MU * g);
    for (circle, speed) in [
        ((0.0, None), 2.0),
        ((10.0, None), f64::NAN),
        ((10.0, Some(1.0)), 2.0),
    ] {
        match corner::<Twin>(&settings, laws, circle, speed) {
            Err(EventError::Setting { event, .. }) => assert_eq!(event, "cornering"),
            other => panic!("{circle:?} at {speed} was not refused: {other:?}"),
        }
    }
}
