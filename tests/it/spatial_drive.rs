//! The spatial vehicle driven by its two sprockets (`SideDrives`): the
//! books with the drives' work, the mirror of a turn, a turn moved
//! rigidly, a straight run that stays straight, and the momentum the
//! ground's forces give.
//!
//! Each run starts the `Twin` from its assembled rest on level ground and
//! integrates it with Dormand–Prince at rtol 1e-7 (`max_step` 1 ms), or,
//! where two runs are compared to 1e-9, with RK4 at a fixed 0.1 ms: an
//! adaptive method's accepted steps may differ between the two by a
//! rejection near its threshold, and the runs then by its tolerance.

use trackgen::integrate::{Integrator, OdeSystem};
use trackgen::nalgebra::{DVector, Vector3};
use trackgen::spatial::Side;
use trackgen::spatial_vehicle::{
    DrivelineError, SideDrives, SideOutputs, SpatialOutputs, SpatialSystem,
};
use trackgen::terrain::field::HeightField;
use trackgen::vehicle::{Drive, DriveError};

use crate::support::twin::{States, System, at_rest, belt, mirror, on, run, spatial, sticking};

/// Dormand–Prince at rtol 1e-7.
const ADAPTIVE: Integrator = Integrator::Dopri5 {
    rtol: 1e-7,
    atol: 1e-9,
    max_step: 1e-3,
};

/// RK4 at a fixed 0.1 ms.
const FIXED: Integrator = Integrator::Rk4 { step: 1e-4 };

/// The `Twin` with its sprockets driven.
fn driven(drives: SideDrives) -> System {
    SpatialSystem::new(spatial())
        .with_drives(drives)
        .expect("drives that make controllers")
}

/// `a` and `b` equal to `tol` of the larger's size (or of 1).
fn same(a: &[f64], b: &[f64], tol: f64, what: &str) {
    let scale = a.iter().chain(b).fold(1.0_f64, |m, v| m.max(v.abs()));
    for (i, (x, y)) in a.iter().zip(b).enumerate() {
        assert!((x - y).abs() <= tol * scale, "{what}[{i}]: {x} against {y}");
    }
}

/// `system` driven from rest for `end` s into a left turn: its books
/// hold the drives' work to 1e-6 of it (at rtol 1e-7 the integrator's
/// error is about 1e-8 of the energies it moves; a misbooked drive — its
/// power read at the sprocket's absolute speed rather than relative to
/// the frame, or its reaction left off the frame — is of the order of the
/// work itself), and it has turned left. Its final state.
fn turned_with_books(system: &mut System, end: f64) -> DVector<f64> {
    let start = at_rest(0.0, (0.0, 0.0));
    let y0 = system.state(&start.0, &start.1, &start.2);
    let before = system.energy(y0.as_slice());
    let y = run(system, &start, end, ADAPTIVE);
    let after = system.energy(y.as_slice());
    assert!(after.driven > 100.0, "{after:?}");
    assert!(
        (after.total() - before.total()).abs() < 1e-6 * after.driven,
        "{} J against {} J, {} J driven, {} J dissipated",
        after.total(),
        before.total(),
        after.driven,
        after.dissipated
    );
    let (hull, ..) = system.states(y.as_slice());
    assert!(hull.pose.yaw > 1e-4, "yaw {}", hull.pose.yaw);
    y
}

/// Driven into a turn (the right belt asked 1.2 m/s, the left 0.4 m/s,
/// over 0.2 s), the vehicle's books hold the drives' work
/// ([`turned_with_books`]), and the right sprocket, faster, takes more
/// torque.
#[test]
fn a_turn_keeps_its_books() {
    let mut system = driven(SideDrives {
        right: belt(1.2, 0.2),
        left: belt(0.4, 0.2),
    });
    let y = turned_with_books(&mut system, 0.4);
    let drive = system.drive_state(0.4, y.as_slice()).expect("the drives");
    assert!(
        drive.torque[0] < drive.torque[1] && drive.torque[0] < 0.0,
        "{drive:?}"
    );
}

/// The vehicle's mirror across its centre plane: a state with the world's
/// `y` reversed, each tree's yaw and roll and its rates across its plane
/// reversed, the hull's right and left bodies and the two tracks
/// exchanged.
fn mirrored(system: &System, y: &[f64]) -> States {
    mirror(&trees(system, y))
}

/// The three trees at `y`.
fn trees(system: &System, y: &[f64]) -> States {
    let (hull, right, left, _) = system.states(y);
    (hull, right, left)
}

/// Every value of a state's three trees (and the ground's
/// deflections, zero), in one vector: not the driveline's three states
/// nor the two books.
fn values(system: &System, states: &States) -> DVector<f64> {
    let y = system.state(&states.0, &states.1, &states.2);
    y.rows(0, system.dimension() - 5).into_owned()
}

/// A left turn (the right belt faster) and the right turn with the belts'
/// speeds exchanged end mirror images of each other after 0.3 s, to
/// 1e-9 of the state's size: the model, its contacts and its drives hold
/// no preferred side.
#[test]
fn a_left_turn_mirrors_the_right_turn() {
    let start = at_rest(0.0, (0.0, 0.0));
    let mut left_turn = driven(SideDrives {
        right: belt(1.2, 0.2),
        left: belt(0.4, 0.2),
    });
    let mut right_turn = driven(SideDrives {
        right: belt(0.4, 0.2),
        left: belt(1.2, 0.2),
    });
    let a = run(&mut left_turn, &start, 0.3, FIXED);
    let b = run(&mut right_turn, &start, 0.3, FIXED);
    let (hull, ..) = left_turn.states(a.as_slice());
    assert!(hull.pose.yaw > 1e-4, "a turn: yaw {}", hull.pose.yaw);
    let mirror = mirrored(&left_turn, a.as_slice());
    same(
        values(&right_turn, &trees(&right_turn, b.as_slice())).as_slice(),
        values(&left_turn, &mirror).as_slice(),
        1e-9,
        "the right turn against the left turn's mirror",
    );
    // What the turns show is mirrored too: the yaw rate and everything
    // sideways reversed, the sides exchanged, the rest the same.
    let (l, r) = (
        left_turn.outputs(0.3, a.as_slice()).expect("the outputs"),
        right_turn.outputs(0.3, b.as_slice()).expect("the outputs"),
    );
    let shown = |o: &SpatialOutputs, mirror: bool| {
        let m = if mirror { -1.0 } else { 1.0 };
        let (near, far) = if mirror { (1, 0) } else { (0, 1) };
        let side = |s: &SideOutputs| {
            [
                s.sprocket_speed,
                s.sprocket_torque,
                s.sprocket_power,
                s.belt_speed,
                s.ground_speed,
                s.slip,
                s.track_speed,
                s.ground_force.x,
                m * s.ground_force.y,
                s.ground_force.z,
                m * s.ground_yaw_moment,
            ]
        };
        let mut v = vec![
            m * o.yaw_rate,
            m * o.lateral_acceleration,
            o.acceleration.x,
            o.acceleration.z,
            o.turn_radius,
        ];
        v.extend(side(&o.sides[near]));
        v.extend(side(&o.sides[far]));
        v
    };
    same(
        &shown(&r, false),
        &shown(&l, true),
        1e-9,
        "the turns' outputs",
    );
    assert!(l.yaw_rate > 0.0 && l.lateral_acceleration > 0.0, "{l:?}");
    assert!(
        l.sides[0].slip > l.sides[1].slip,
        "the outer track slips more (still speeding up, both drive): {l:?}"
    );
}

/// What a turn shows (`SpatialSystem::outputs`) against independent
/// routes: the centre of mass's acceleration against the rate of its
/// velocity (`SpatialSystem::mass_centre`) over two RK4 steps of 10 µs
/// from the state (the one-sided second-order difference, its error
/// `h² |a''|/3` with the steps' own: 2e-6 m/s² apart, measured; bound
/// 1e-5 g);
/// each side's ground force and yaw moment against the sums over its
/// points (`SpatialSystem::ground_forces`, the moment by the cross
/// product).
#[test]
fn a_turns_outputs_are_what_newton_and_the_state_say() {
    let mut system = driven(SideDrives {
        right: belt(1.2, 0.2),
        left: belt(0.4, 0.2),
    });
    let start = at_rest(0.0, (0.0, 0.0));
    let y0 = run(&mut system, &start, 0.3, FIXED);
    let shown = system.outputs(0.3, y0.as_slice()).expect("the outputs");
    let h = 1e-5;
    let mut stepper = Integrator::Rk4 { step: h }.stepper(system.dimension());
    let (mut t, mut y) = (0.3, y0.clone());
    let mut velocities = vec![system.mass_centre(y.as_slice()).velocity];
    for k in 1..=2 {
        let end = 0.3 + k as f64 * h;
        stepper
            .step(&mut system, &mut t, &mut y, end)
            .expect("the step");
        velocities.push(system.mass_centre(y.as_slice()).velocity);
    }
    let rate = (-3.0 * velocities[0] + 4.0 * velocities[1] - velocities[2]) / (2.0 * h);
    let g = 9.81;
    assert!(
        (shown.acceleration - rate).amax() < 1e-5 * g,
        "{} against {}",
        shown.acceleration,
        rate
    );
    let centre = system.mass_centre(y0.as_slice()).position;
    let points = system.ground_forces(y0.as_slice());
    for (s, side) in [Side::Right, Side::Left].into_iter().enumerate() {
        let mine = points.iter().filter(|p| p.side == side);
        let force: Vector3<f64> = mine.clone().map(|p| p.force).sum();
        let moment: f64 = mine.map(|p| (p.at - centre).cross(&p.force).z).sum();
        let out = &shown.sides[s];
        assert!((out.ground_force - force).amax() < 1e-9 * force.norm());
        assert!((out.ground_yaw_moment - moment).abs() < 1e-9 * force.norm());
    }
    println!(
        "acceleration {} against the velocity's rate {} (apart {:.1e} m/s²)",
        shown.acceleration,
        rate,
        (shown.acceleration - rate).amax()
    );
}

/// The same turn started 1.1 rad round and 40 m, −7 m away ends where
/// the first one ends turned and moved alike, to 1e-9: the level ground
/// and the model have no preferred place or heading.
#[test]
fn a_turn_moved_rigidly_is_the_same_turn() {
    let (heading, shift) = (1.1, (40.0, -7.0));
    let drives = || SideDrives {
        right: belt(1.2, 0.2),
        left: belt(0.4, 0.2),
    };
    let (mut here, mut there) = (driven(drives()), driven(drives()));
    let a = run(&mut here, &at_rest(0.0, (0.0, 0.0)), 0.3, FIXED);
    let b = run(&mut there, &at_rest(heading, shift), 0.3, FIXED);
    let (s, c) = heading.sin_cos();
    let mut moved = trees(&here, a.as_slice());
    for origin in [
        &mut moved.0.pose.origin,
        &mut moved.1.pose.origin,
        &mut moved.2.pose.origin,
    ] {
        *origin = Vector3::new(
            c * origin.x - s * origin.y + shift.0,
            s * origin.x + c * origin.y + shift.1,
            origin.z,
        );
    }
    moved.0.pose.yaw += heading;
    moved.1.pose.yaw += heading;
    moved.2.pose.yaw += heading;
    same(
        values(&there, &trees(&there, b.as_slice())).as_slice(),
        values(&here, &moved).as_slice(),
        1e-9,
        "the turn moved against the turn",
    );
}

/// Both belts asked the same speed, the mirrored vehicle runs straight:
/// after 0.4 s its hull has not yawed, rolled or moved sideways (below
/// 1e-9), and it has moved forward.
#[test]
fn equal_belts_run_straight() {
    let mut system = driven(SideDrives {
        right: belt(0.8, 0.2),
        left: belt(0.8, 0.2),
    });
    let start = at_rest(0.0, (0.0, 0.0));
    let y = run(&mut system, &start, 0.4, ADAPTIVE);
    let (hull, ..) = system.states(y.as_slice());
    assert!(
        hull.pose.origin.x - start.0.pose.origin.x > 0.05,
        "{hull:?}"
    );
    assert!(
        hull.pose.origin.y.abs() < 1e-9
            && hull.pose.yaw.abs() < 1e-9
            && hull.pose.roll.abs() < 1e-9,
        "{hull:?}"
    );
}

/// A drive whose settings make no controller is refused when the system
/// is made: a gain that is not finite, a negative torque limit.
#[test]
fn a_drive_that_is_no_controller_is_refused() {
    let bad = Drive::Speed {
        target: Box::new(|_| 1.0),
        proportional: f64::NAN,
        integral: 1.0,
        max_torque: 1.0,
    };
    let refused = SpatialSystem::new(spatial()).with_drives(SideDrives {
        right: Drive::Free,
        left: bad,
    });
    assert!(matches!(
        refused,
        Err(DrivelineError::Drive(DriveError::Gains { .. }))
    ));
    let negative = Drive::Speed {
        target: Box::new(|_| 1.0),
        proportional: 1.0,
        integral: 1.0,
        max_torque: -1.0,
    };
    let refused = SpatialSystem::new(spatial()).with_drives(SideDrives {
        right: negative,
        left: Drive::Free,
    });
    assert!(matches!(
        refused,
        Err(DrivelineError::Drive(DriveError::TorqueLimit { .. }))
    ));
}

/// The `Twin` on level ground with stiction, its right belt asked
/// 1.2 m/s and its left 0.4 m/s over 0.2 s: a left turn.
fn turning_on_stiction() -> System {
    on(
        HeightField::level(),
        sticking(),
        SideDrives {
            right: belt(1.2, 0.2),
            left: belt(0.4, 0.2),
        },
    )
}

/// With stiction on the ground (two deflections per ground point, in the
/// ground's plane), a driven turn keeps its books to 1e-6 of the drives'
/// work as under regularised friction: the deflections' springs store
/// what they are given, their dampers and sliders dissipate the rest.
#[test]
fn a_turn_on_stiction_keeps_its_books() {
    let mut system = turning_on_stiction();
    assert_eq!(
        system.dynamics.ground_states(),
        [2 * 2 * 2 * 55, 2 * 2 * 2 * 55]
    );
    turned_with_books(&mut system, 0.3);
}

/// The ground is the only thing outside the vehicle but gravity: over a
/// driven turn on stiction from rest, the centre of mass's momentum
/// (`SpatialSystem::mass_centre`) changes by the impulse of every ground
/// point's force (`SpatialSystem::ground_forces`) and of the weight, by
/// the trapezoidal rule over the accepted steps, to 1e-4 of the weight's
/// impulse in each direction. The rule's own error at steps of at most
/// 0.2 ms is 9e-6 of it (vertical; 3e-6 at 0.1 ms, so second order); a
/// ground point left out or a body's mass miscounted is of the order of
/// the impulse itself.
#[test]
fn the_ground_forces_move_the_centre_of_mass() {
    let mut system = turning_on_stiction();
    let start = at_rest(0.0, (0.0, 0.0));
    let mut y = system.state(&start.0, &start.1, &start.2);
    let resultant = |system: &System, y: &DVector<f64>| -> Vector3<f64> {
        system
            .ground_forces(y.as_slice())
            .iter()
            .map(|point| point.force)
            .sum()
    };
    let mut stepper = Integrator::Dopri5 {
        rtol: 1e-7,
        atol: 1e-9,
        max_step: 2e-4,
    }
    .stepper(system.dimension());
    let before = system.mass_centre(y.as_slice());
    let (mut t, end) = (0.0, 0.3);
    let mut force = resultant(&system, &y);
    let mut impulse = Vector3::zeros();
    while t < end {
        let from = t;
        stepper
            .step(&mut system, &mut t, &mut y, end)
            .expect("the run");
        let next = resultant(&system, &y);
        impulse += 0.5 * (t - from) * (force + next);
        force = next;
    }
    let after = system.mass_centre(y.as_slice());
    let weight = before.mass * system.dynamics.hull.gravity();
    let gained = before.mass * (after.velocity - before.velocity);
    let expected = impulse - Vector3::new(0.0, 0.0, weight * end);
    assert!(gained.xy().norm() > 100.0, "it moves: {gained}");
    for i in 0..3 {
        assert!(
            (gained[i] - expected[i]).abs() < 1e-4 * weight * end,
            "momentum {gained} N s against the impulses' {expected} N s"
        );
    }
}
