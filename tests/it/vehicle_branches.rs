//! The vehicle's other branches: the three closure methods, every
//! integrator, the torque drive, the speed controller's limit and
//! anti-windup, and the declared penalty joint's tensions.
//!
//! Tolerances, and why:
//! - **Closure methods agree**: the M113 driven from rest for 1.5 s under
//!   partitioning, multipliers and a run-time penalty spring (k = 1e8 N/m)
//!   at Dormand-Prince 1e-6, on the M113 as it ships (its tensioner set):
//!   final speed and position agree within 2e-3 relative (measured 1.3e-4
//!   and 2.6e-5 for the penalty joint, which opens by a fraction of a
//!   millimetre, 8e-7 for multipliers: contact makes the runs drift apart
//!   at the integrator's tolerance); each closes its energy books within
//!   1e-5 of the work (measured 2.4e-7–9.5e-7; the multipliers' Baumgarte
//!   and projection work is not in the books, and measured below that);
//!   the constrained methods keep `|C|` below 1e-10 m, the penalty gap
//!   stays below 1 mm. The recorded tension (from each method's joint
//!   forces): under multipliers within 0.1 % of the largest tension sample
//!   by sample (measured below 0.01 %: the same equations, stabilised); the
//!   penalty joint's 2 kHz ringing is aliased by the 0.01 s samples, so
//!   only its mean over the run, within 0.5 % (measured 0.06 %; 0.4 % on
//!   the slack track the tests once ran).
//! - **Integrators on the vehicle**: a torque-driven start of 0.3 s under
//!   Bogacki-Shampine (1e-3), RK4 (2e-4 s) and ROS2 agrees with
//!   Dormand-Prince 1e-7 in final speed within 1e-3 relative (Bs23, RK4:
//!   a global error of the order of Bogacki-Shampine's local tolerance;
//!   measured 7.5e-5 and 4.9e-5, the stiction law's switch between stick
//!   and slip costing RK4 its order) — the speed is the integral of the net
//!   force, and each method is stable and consistent at these settings.
//!   ROS2 (linearly implicit, L-stable, second order) is checked by
//!   convergence: its speed error must fall by at least 3 when the step
//!   halves from 1 ms to 0.5 ms (second order: 4; measured 5.7, 8.1e-3 →
//!   1.4e-3 m/s). It damps the stiff contact modes numerically, which the
//!   energy books see as unbooked dissipation (349 J at 1 ms): that
//!   residual must fall too, by at least 1.5 (measured 2.0; it is not yet
//!   in the asymptotic regime at these steps).
//! - **Torque drive**: the recorded torque is the schedule to rounding
//!   (1e-12 N m), and the motor's integrated work equals the trapezoid
//!   rule of `τ ω` over the 1 ms samples within 1e-4 (the rule's error,
//!   `h² |(τω)″|/12` per unit time, is below 1e-5 of the work here).
//! - **Torque limit**: the torque never exceeds the limit (exact: it is
//!   clamped) and stays at it for over 0.2 s after a step command; with
//!   the integral held while saturated, the track's mean speed (the
//!   recorded `track_speed`, what the controller aims for) overshoots the
//!   command by less than 15 % (measured 6.6 %; the same step without a
//!   limit overshoots 38 %, and a wound-up integral of the error over the
//!   1 s of saturation, ~3 rad × 6000 N m/rad, would hold the full torque
//!   long past the target), and its mean over the last second is within
//!   3 % of the command (the chassis' surge moves it ±4 %).
//! - **Penalty tensions**: the tensions of a declared penalty chain (the
//!   spring's force across the cut) equal those of the same links declared
//!   open with the spring's force applied as loads, to 1e-10 relative (both
//!   are the same joint-force solve with the force entering in different
//!   places).

use crate::support;

use trackgen::closure::{ClosureMethod, MultiplierOptions};
use trackgen::dynamics::dense_forward_dynamics;
use trackgen::integrate::Integrator;
use trackgen::laws::PenaltyJoint;
use trackgen::multibody::{BodyLoad, ClosingJoint, RecursiveModel, TrackModel};
use trackgen::nalgebra::{SVector, Vector2};
use trackgen::simulate::{Output, Results, simulate};
use trackgen::terrain::Terrain;
use trackgen::vehicle::{Drive, Vehicle};
use trackgen::vehicles::{m113, m113::M113};

use support::vehicle::{Books, m113_with};
use support::{Lcg, assert_close, max_abs, max_of};

fn flat() -> Terrain {
    Terrain::Flat { height: 0.0 }
}

fn run(system: &mut m113::M113System, integrator: Integrator, duration: f64) -> Results {
    simulate(system, integrator, 0.0, duration, Output::Every(0.01)).expect("the run completes")
}

fn last(results: &Results, column: &str) -> f64 {
    results.last().unwrap().get(column).unwrap()
}

/// Partitioning, multipliers and a run-time penalty joint drive the
/// vehicle the same way, each with closed energy books.
#[test]
fn closure_methods_agree_on_the_vehicle() {
    let drive = || M113::speed_drive(|t| 2.0 * ((t - 0.3) / 0.5).clamp(0.0, 1.0));
    let integrator = Integrator::Dopri5 {
        rtol: 1e-6,
        atol: 1e-6,
        max_step: 0.01,
    };
    let methods = [
        ("partitioning", ClosureMethod::Declared),
        (
            "multipliers",
            ClosureMethod::Multipliers(MultiplierOptions::default()),
        ),
        (
            "penalty",
            ClosureMethod::Penalty(PenaltyJoint {
                stiffness: 1e8,
                damping: 1e4,
            }),
        ),
    ];
    let mut finals = Vec::new();
    let mut tensions = Vec::new();
    for (name, method) in methods {
        let mut system = m113_with(flat(), drive(), method);
        let results = run(&mut system, integrator, 1.5);
        let books = Books::of(&results);
        eprintln!("{name}: books {:.2e} of the work", books.relative());
        assert!(
            books.relative() < 1e-5 && books.least_dissipation_step >= 0.0,
            "{name}: residual {:e} of the work, least dissipation step {:e} J",
            books.relative(),
            books.least_dissipation_step
        );
        let gap = max_of(results.column("track.closure_error").unwrap());
        let allowed = if name == "penalty" { 1e-3 } else { 1e-10 };
        assert!(gap < allowed, "{name}: closure error {gap:e} m");
        let tension = results.column("tension").unwrap();
        assert!(tension.iter().all(|t| t.is_finite()), "{name}: tensions");
        finals.push((name, last(&results, "speed"), last(&results, "x")));
        tensions.push(tension);
    }
    // The tension in link 1's joint from each method's joint forces.
    // Multipliers solve the same equations (their Baumgarte term and
    // projection aside): sample by sample within 0.1 % of the largest
    // tension (measured below 0.01 %). A penalty joint of 1e8 N/m on 18 kg links
    // rings at ~2 kHz, which the 0.01 s samples alias, so only its mean
    // over the run is the same: within 0.5 % (measured 0.06 %).
    let scale = max_abs(tensions[0].iter().copied());
    let mean = |t: &[f64]| t.iter().sum::<f64>() / t.len() as f64;
    let worst = max_abs(tensions[0].iter().zip(&tensions[1]).map(|(a, b)| a - b));
    eprintln!(
        "multipliers: tension within {:.2} % of the largest; penalty: mean within {:.2} %",
        100.0 * worst / scale,
        100.0 * (mean(&tensions[0]) - mean(&tensions[2])).abs() / mean(&tensions[0]).abs()
    );
    assert!(
        worst <= 1e-3 * scale,
        "multipliers: tension off by {worst:e} N of {scale:e} N"
    );
    let (a, b) = (mean(&tensions[0]), mean(&tensions[2]));
    assert!(
        (a - b).abs() <= 5e-3 * a.abs(),
        "penalty: mean tension {b} N, partitioning {a} N"
    );
    let (_, speed, x) = finals[0];
    assert!(speed > 1.5, "the vehicle drives: {speed} m/s");
    for &(name, v, p) in &finals[1..] {
        eprintln!(
            "{name}: speed {:.1e}, x {:.1e} relative to partitioning",
            (v - speed).abs() / speed,
            (p - x).abs() / x.abs()
        );
        assert!(
            (v - speed).abs() < 2e-3 * speed && (p - x).abs() < 2e-3 * x.abs(),
            "{name}: speed {v} and x {p}, partitioning {speed} and {x}"
        );
    }
}

fn torque_start() -> Drive {
    Drive::Torque(Box::new(|t| -3000.0 * (t / 0.2).min(1.0)))
}

/// Every integrator drives the vehicle: the explicit ones to the same
/// speed as a tight Dormand-Prince; ROS2 with books that converge at its
/// order.
#[test]
fn every_integrator_drives_the_vehicle() {
    let duration = 0.3;
    let exact = {
        let mut system = m113_with(flat(), torque_start(), ClosureMethod::Declared);
        last(
            &run(&mut system, Integrator::dopri5(1e-7), duration),
            "speed",
        )
    };
    assert!(exact > 0.2, "the torque drives the vehicle: {exact} m/s");
    for (name, integrator) in [
        (
            "bs23",
            Integrator::Bs23 {
                rtol: 1e-3,
                atol: 1e-3,
                max_step: 0.01,
            },
        ),
        ("rk4", Integrator::Rk4 { step: 2e-4 }),
    ] {
        let mut system = m113_with(flat(), torque_start(), ClosureMethod::Declared);
        let results = run(&mut system, integrator, duration);
        let speed = last(&results, "speed");
        eprintln!(
            "{name}: speed off by {:.2e} of {exact}",
            (speed - exact).abs() / exact
        );
        assert!(
            (speed - exact).abs() < 1e-3 * exact,
            "{name}: speed {speed}, Dormand-Prince 1e-7 {exact}"
        );
        assert!(Books::of(&results).least_dissipation_step >= 0.0);
    }
    // ROS2 at 1 ms and 0.5 ms: second order in the speed.
    let ros2 = |step: f64| {
        let mut system = m113_with(flat(), torque_start(), ClosureMethod::Declared);
        let results = run(&mut system, Integrator::Rosenbrock2 { step }, duration);
        (
            (last(&results, "speed") - exact).abs(),
            Books::of(&results).residual,
        )
    };
    let ((coarse, coarse_books), (fine, fine_books)) = (ros2(1e-3), ros2(5e-4));
    eprintln!(
        "ROS2: speed error {coarse:.3e} -> {fine:.3e} m/s ({:.2}), books {coarse_books:.0} -> {fine_books:.0} J ({:.2})",
        coarse / fine,
        coarse_books / fine_books
    );
    assert!(
        fine < coarse / 3.0 && fine < 0.05 * exact,
        "ROS2 speed error {coarse:e} m/s at 1 ms, {fine:e} m/s at 0.5 ms"
    );
    assert!(
        fine_books < coarse_books / 1.5,
        "ROS2 books: residual {coarse_books:e} J at 1 ms, {fine_books:e} J at 0.5 ms"
    );
}

/// A torque schedule: the recorded torque is the schedule, and the motor's
/// work is the integral of torque times sprocket speed.
#[test]
fn torque_drive_does_the_work_of_its_schedule() {
    let mut system = m113_with(flat(), torque_start(), ClosureMethod::Declared);
    let results = simulate(
        &mut system,
        Integrator::dopri5(1e-7),
        0.0,
        0.4,
        Output::Every(0.001),
    )
    .unwrap();
    let (t, torque, omega, work) = (
        results.times(),
        results.column("sprocket_torque").unwrap(),
        results.column("sprocket_speed").unwrap(),
        results.column("motor_work").unwrap(),
    );
    let schedule = t.iter().map(|t| -3000.0 * (t / 0.2).min(1.0));
    assert!(max_abs(torque.iter().zip(schedule).map(|(a, b)| a - b)) < 1e-12);
    let trapezoid: f64 = (1..t.len())
        .map(|k| 0.5 * (torque[k] * omega[k] + torque[k - 1] * omega[k - 1]) * (t[k] - t[k - 1]))
        .sum();
    let w = *work.last().unwrap();
    assert!(w > 100.0, "the motor works: {w} J");
    assert!(
        (trapezoid - w).abs() < 1e-4 * w,
        "work {w} J, trapezoid of τω {trapezoid} J"
    );
}

/// The speed controller at its torque limit: clamped, and with the
/// integral held while saturated, no large overshoot afterwards.
#[test]
fn speed_drive_saturates_without_winding_up() {
    let limit = 2500.0;
    let drive = Drive::Speed {
        target: Box::new(|t| if t < 0.3 { 0.0 } else { 1.5 }),
        proportional: 3000.0,
        integral: 6000.0,
        max_torque: limit,
    };
    let mut system = m113_with(flat(), drive, ClosureMethod::Declared);
    let results = run(
        &mut system,
        Integrator::Dopri5 {
            rtol: 1e-6,
            atol: 1e-6,
            max_step: 0.01,
        },
        4.0,
    );
    let torque = results.column("sprocket_torque").unwrap();
    assert!(
        max_abs(torque.iter().copied()) <= limit,
        "torque beyond the limit"
    );
    let saturated = torque.iter().filter(|t| t.abs() == limit).count();
    assert!(saturated > 20, "saturated at {saturated} samples only");
    // What the controller aims for: the track's mean speed.
    let track_speed = results.column("track_speed").unwrap();
    let peak = max_of(track_speed.iter().copied());
    eprintln!(
        "saturated at {saturated} samples; track speed peaks {:.1} % over the command",
        100.0 * (peak / 1.5 - 1.0)
    );
    assert!(peak < 1.5 * 1.15, "track speed overshoots to {peak} m/s");
    let end = support::vehicle::mean(&track_speed[track_speed.len() - 100..]);
    assert!(
        (end - 1.5).abs() < 0.03 * 1.5,
        "track speed over the last second {end} m/s"
    );
}

/// The controller law itself, at hand-picked states: proportional plus
/// integral below the limit; clamped, with the integral held, beyond it
/// in the error's direction; unwinding when the error turns.
#[test]
fn speed_drive_law_by_hand() {
    let drive = Drive::Speed {
        target: Box::new(|_| 2.0),
        proportional: 100.0,
        integral: 50.0,
        max_torque: 1000.0,
    };
    let radius = 0.25;
    // Wanted sprocket speed −2 / 0.25 = −8 rad/s.
    let (torque, rate) = drive.torque(0.0, -7.0, radius, 2.0);
    assert_eq!((torque, rate), (-100.0 + 50.0 * 2.0, -1.0));
    let (torque, rate) = drive.torque(0.0, 0.0, radius, -10.0);
    assert_eq!((torque, rate), (-1000.0, 0.0), "saturated: integral held");
    let (torque, rate) = drive.torque(0.0, -9.0, radius, -30.0);
    assert_eq!(
        (torque, rate),
        (-1000.0, 1.0),
        "saturated against the error: integral unwinds"
    );
    let free = Drive::Free.torque(0.0, 3.0, radius, 1.0);
    assert_eq!(free, (0.0, 0.0));
    let schedule = Drive::Torque(Box::new(|t| 10.0 * t)).torque(2.0, 3.0, radius, 1.0);
    assert_eq!(schedule, (20.0, 0.0));
}

trackgen::model! {
    /// Eight 0.154 m links closed by a declared spring-damper.
    pub track Sprung8 {
        links: 8,
        link { mass: 18.02, inertia: 0.04, u1: (-0.077, 0.0), u2: (0.077, 0.0) },
        link[3] { mass: 25.0, inertia: 0.06, u1: (-0.05, 0.01), u2: (0.104, -0.01) },
        closure: penalty { stiffness: 2e6, damping: 3e3 },
    }

    /// The same links, open.
    pub track Open8 {
        links: 8,
        link { mass: 18.02, inertia: 0.04, u1: (-0.077, 0.0), u2: (0.077, 0.0) },
        link[3] { mass: 25.0, inertia: 0.06, u1: (-0.05, 0.01), u2: (0.104, -0.01) },
        closure: open,
    }
}

/// The tension in every joint (the joint's force on link i along its d̄ⁱ)
/// and q̈_i, from the generated linear-time route's joint forces.
fn joint_tensions<M: TrackModel<D>, const D: usize>(
    model: &M,
    q: &SVector<f64, D>,
    qd: &SVector<f64, D>,
    loads: &[BodyLoad],
    closing: ClosingJoint,
) -> (SVector<f64, D>, Vec<f64>) {
    let n = M::BODIES;
    let trig: Vec<(f64, f64)> = (0..n).map(|i| q[2 + i].sin_cos()).collect();
    let (mut qdd, mut forces) = (SVector::zeros(), vec![Vector2::zeros(); n]);
    model
        .linear_time_dynamics(&trig, qd, loads, closing, &mut qdd, &mut forces)
        .unwrap();
    let spans = model.description().link_spans().unwrap();
    let tensions = (0..n)
        .map(|i| forces[i].dot(&trackgen::planar::rotate(q[2 + i], spans[i]).normalize()))
        .collect();
    (qdd, tensions)
}

/// A penalty joint's tensions: a declared spring-damper's force is read
/// from the state and acts across the cut; the same force applied as loads
/// to the open chain gives the same accelerations and the same tensions in
/// every joint (from the generated route's joint forces, themselves held to
/// Newton's law link by link in `tests/linear_time.rs`), and the closing
/// joint carries the spring's force along the last link.
#[test]
fn declared_penalty_tensions_match_the_open_chain_with_the_spring_as_loads() {
    let (k, c) = (2e6, 3e3);
    let mut rng = Lcg::new(8);
    let joint = Sprung8.description().loop_joint.expect("loop joint");
    let (first_u1, last_u2) = (joint.first_u1, joint.last_u2);
    for _ in 0..20 {
        let (q, qd) = rng.state::<10>();
        let loads: Vec<BodyLoad> = (0..8)
            .map(|_| {
                BodyLoad::force(Vector2::new(
                    rng.uniform(-50.0, 50.0),
                    rng.uniform(-50.0, 50.0),
                ))
                .plus(BodyLoad::moment(rng.uniform(-5.0, 5.0)))
            })
            .collect();
        // The spring across the cut: F = −k C − c Ċ on link n at ū2, −F on
        // link 1 at ū1, with C = P_n − P_1.
        let gap = Sprung8.closure(&q);
        let rate = Sprung8.closure_jacobian(&q) * qd;
        let spring = -gap * k - rate * c;
        let arm = |theta: f64, u: Vector2<f64>| trackgen::planar::rotate(theta, u);
        let mut with_spring = loads.clone();
        with_spring[7] = with_spring[7].plus(BodyLoad::force_at(spring, arm(q[9], last_u2)));
        with_spring[0] = with_spring[0].plus(BodyLoad::force_at(-spring, arm(q[2], first_u1)));

        let sprung = dense_forward_dynamics(&Sprung8, &q, &qd, &loads)
            .unwrap()
            .qdd;
        let open = dense_forward_dynamics(&Open8, &q, &qd, &with_spring)
            .unwrap()
            .qdd;
        assert_close("q̈_i", sprung.as_slice(), open.as_slice(), 1e-10, 1.0);

        let spring_across = ClosingJoint::Cut { force: spring };
        let (fast, got) = joint_tensions(&Sprung8, &q, &qd, &loads, spring_across);
        let (_, want) = joint_tensions(&Open8, &q, &qd, &with_spring, ClosingJoint::OPEN);
        assert_close(
            "generated q̈_i",
            fast.as_slice(),
            sprung.as_slice(),
            1e-10,
            1.0,
        );
        let scale = max_abs(want.iter().copied().chain([spring.norm()]));
        assert_close("joint tensions", &got[..7], &want[..7], 1e-10, scale);
        // The closing joint is the spring: its force F on link n, along
        // link n's axis, is the tension.
        let axis = arm(q[9], Sprung8.description().link_spans().unwrap()[7]).normalize();
        let closing = spring.dot(&axis);
        assert!(
            (got[7] - closing).abs() < 1e-10 * scale,
            "closing joint {} N, spring along the link {closing} N",
            got[7]
        );
    }
}
