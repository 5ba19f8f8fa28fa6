//! The default vehicle driving: physics checks on the M113 with contact,
//! suspension and drive, each a number that could fail.
//!
//! Tolerances, and why:
//! - **Energy books** (`motor_work = ΔE + dissipated`, the largest residual
//!   over the run): 1e-5 of the motor's work at Dormand-Prince 1e-6. Every
//!   term of the books (kinetic, gravity, springs, contacts, work and
//!   dissipation integrals) is integrated with the state under a local
//!   error control of 1e-6, so a run of a few thousand steps closes to a
//!   few 1e-6 of the work; measured 1.7e-6 (6e-7–9e-7 before the ground's
//!   stiction states). A missing force term worth
//!   1e-5 of a 1.6e4 J run (0.16 J) fails. At the main job's settings
//!   (Bogacki-Shampine 1e-3) the bound is 5e-3: a third-order method at a
//!   local tolerance of 1e-3; measured 3.7e-4 over the bump.
//! - **Dissipation never decreases**: every dissipative law (contact
//!   damping, friction, arm dampers) takes energy out at every instant, so
//!   `dissipated` is non-decreasing from sample to sample — exactly, no
//!   tolerance (its rate is ≥ 0.9 J per 0.01 s sample here, far above any
//!   rounding).
//! - **At rest**: after 10 s on flat ground with the drive holding the
//!   sprocket still (a free sprocket lets the vehicle roll away on the
//!   surge of its settling drop, 0.1 m/s after 6 s with the track
//!   tensioned), over the last 0.5 s the chassis' speed stays below
//!   5 mm/s, its vertical speed below 5 mm/s and its pitch rate below
//!   2e-3 rad/s (measured 2.2 mm/s, 3.0 mm/s and 1.4e-3 rad/s: the
//!   pitch-heave mode on the tensioned track halves in about 2.5 s, and
//!   was still 7 mm/s at 6 s), and the mean ground force equals the weight
//!   within 5e-4 (the shoes ring at ±0.6 % about it; measured 3.3e-4).
//! - **Speed**: the track's mean speed `−ω N p / (2π)` (the test computes
//!   it from the recorded sprocket speed, pitch and teeth: one pitch per
//!   tooth) is the recorded `track_speed` (to 1e-12 relative: the same
//!   product) and within 0.5 % of the command (measured 0.04 %; a drive
//!   aiming with the pitch radius, 1.6 % larger, fails), and the slip
//!   `1 − v / v_t` averaged over the last 4 s (one period of the chassis'
//!   surge on the track) within ±0.5 % (measured −0.16 %: the shoes walk,
//!   see `tests/track_speed.rs`).
//! - **Penetration**: ground ≤ 10 mm, rims ≤ 6 mm, sprocket teeth ≤ 4 mm
//!   (measured maxima 7.2, 3.9 and 2.4 mm, at the settling drop and the
//!   start of the drive; static penetrations are a few mm). The teeth
//!   carry the tensioner's preload (20 kN on the idler, about 10 kN in
//!   each run) on top of the drive's pull since the tensioner's spring
//!   rests where the assembly sets it: 1.3 mm before, when the assembled
//!   track ran slack.
//! - **Tension**: on a 25 % slope, the statics of the sprocket with the
//!   links seated on it: `(T_tight − T_slack) r_p = |τ| + M_g`, with `M_g`
//!   the moment of the seated links' weight about the sprocket centre,
//!   computed in the test from the recorded coordinates. The tension's line
//!   of action swings through ±π/N about the tangent as each joint seats
//!   (chordal action), so its mean arm lies in `[r_p sinc(π/N), r_p]`: the
//!   ratio `(T_tight − T_slack) r_p / (|τ| + M_g)` must lie in
//!   `[1, 1/sinc(π/N)] = [1, 1.0166]`, widened by 0.5 % for the time mean
//!   over a finite number of engagements (measured 1.0059). The drive force
//!   `T_tight − T_slack` is at least the weight's component along the slope
//!   `W sin α` and at most that plus a rolling resistance of 6 % of `W`
//!   (tracked vehicles on hard ground: 2–5 %, Wong, *Theory of Ground
//!   Vehicles*, §6; measured 2.5 %).

use crate::support;

use trackgen::assembly::{AssemblyError, assemble};
use trackgen::closure::ClosureMethod;
use trackgen::integrate::Integrator;
use trackgen::multibody::RecursiveModel;
use trackgen::nalgebra::{SVector, Vector2};
use trackgen::simulate::{Output, Results, simulate};
use trackgen::terrain::{Terrain, TerrainError};
use trackgen::vehicle::{Drive, Vehicle};
use trackgen::vehicles::{m113, m113::M113, m113::M113Chassis, m113::M113Track};

use support::vehicle::{Books, m113_pitch_radius, m113_weight, m113_with, mean, window};
use support::{max_abs, max_of};

/// The integrator of the physics checks: tight enough that the checks
/// measure the model, not the integrator.
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
        M113::system(Terrain::Flat { height: 0.0 }, drive).expect("the M113 assembles");
    simulate(
        &mut system,
        integrator(),
        0.0,
        duration,
        Output::Every(0.01),
    )
    .expect("the run completes")
}

/// Static equilibrium on flat ground, the sprocket held: after settling,
/// the chassis is at rest and the ground carries the vehicle's weight
/// (bounds in the file's header).
#[test]
fn settles_into_static_equilibrium() {
    let results = run(M113::speed_drive(|_| 0.0), 10.0);
    let (t0, t1) = (9.5, 10.0);
    let speed = max_abs(window(&results, "speed", t0, t1));
    let heave = max_abs(window(&results, "chassis.vy", t0, t1));
    let pitch_rate = max_abs(window(&results, "chassis.omega_chassis", t0, t1));
    assert!(
        speed < 5e-3 && heave < 5e-3 && pitch_rate < 2e-3,
        "over the last 0.5 s: |v| up to {speed:e} m/s, |v_y| up to {heave:e} m/s, |ω| up to {pitch_rate:e} rad/s"
    );
    let normal = mean(&window(&results, "ground_normal", t0, t1));
    let w = m113_weight();
    eprintln!(
        "at rest: |v| {speed:.2e} m/s, |v_y| {heave:.2e} m/s, |ω| {pitch_rate:.2e} rad/s; ground {:.1e} of the weight",
        (normal - w) / w
    );
    assert!(
        ((normal - w) / w).abs() < 5e-4,
        "ground normal {normal:.1} N, weight {w:.1} N"
    );
}

/// A driven run on flat ground: the energy books close, dissipation never
/// decreases, the commanded speed is reached with a small ground slip, the
/// contacts stay shallow and the loop closed (bounds in the file's header).
#[test]
fn driven_run_balances_energy_reaches_speed_and_stays_shallow() {
    let target = 2.0;
    let results = run(
        M113::speed_drive(move |t| target * ((t - 0.5) / 1.5).clamp(0.0, 1.0)),
        8.0,
    );
    let books = Books::of(&results);
    eprintln!("driven: books {:.2e} of the work", books.relative());
    assert!(books.work > 1e4, "the motor works: {} J", books.work);
    assert!(
        books.relative() < 1e-5,
        "energy books: residual {:.3e} J of {:.0} J",
        books.residual,
        books.work
    );
    assert!(
        books.least_dissipation_step >= 0.0,
        "dissipated work fell by {:e} J between samples",
        -books.least_dissipation_step
    );

    let rolling = 10.0 * m113::SHOE_PITCH / (2.0 * std::f64::consts::PI);
    let omega = window(&results, "sprocket_speed", 3.0, 8.0);
    let recorded = window(&results, "track_speed", 3.0, 8.0);
    for (w, v) in omega.iter().zip(&recorded) {
        assert!(
            (-w * rolling - v).abs() <= 1e-12 * v.abs().max(1.0),
            "{v} vs {}",
            -w * rolling
        );
    }
    let track_speed = mean(&recorded);
    assert!(
        (track_speed - target).abs() < 5e-3 * target,
        "track speed −ω N p/(2π) = {track_speed:.4} m/s for {target} m/s commanded"
    );
    let (t0, t1) = (4.0, 8.0);
    let slip = 1.0
        - mean(&window(&results, "speed", t0, t1)) / mean(&window(&results, "track_speed", t0, t1));
    eprintln!("track speed {track_speed:.5} m/s, slip {slip:.5}");
    assert!(slip.abs() < 5e-3, "ground slip {slip:.4}");

    for (column, bound) in [
        ("ground_penetration", 0.010),
        ("wheel_penetration", 0.006),
        ("sprocket_penetration", 0.004),
    ] {
        let deepest = max_of(results.column(column).unwrap());
        eprintln!("{column}: deepest {:.1} mm", deepest * 1e3);
        assert!(deepest < bound, "{column}: {deepest} m");
    }
    let closure = max_of(results.column("track.closure_error").unwrap());
    assert!(closure < 1e-10, "closure error {closure:e} m");
}

/// The main job's exact integrator settings (Bogacki-Shampine, rtol = atol
/// = 1e-3, steps ≤ 0.01 s) over its bump course, shortened: settle 0.5 s,
/// drive to 3 m/s in 1 s, a 0.1 m bump 1 m wide at x = 4 m, 4 s in all.
/// The vehicle climbs the bump and leaves it, the books close within 5e-3
/// of the work, dissipation never decreases, the loop stays closed.
#[test]
fn main_job_settings_over_the_bump() {
    let terrain = Terrain::Bump {
        centre: 4.0,
        width: 1.0,
        height: 0.1,
    };
    let drive = M113::speed_drive(|t| 3.0 * ((t - 0.5) / 1.0).clamp(0.0, 1.0));
    let mut system = M113::system(terrain, drive).expect("the M113 assembles");
    let results = simulate(
        &mut system,
        Integrator::Bs23 {
            rtol: 1e-3,
            atol: 1e-3,
            max_step: 0.01,
        },
        0.0,
        4.0,
        Output::Every(0.01),
    )
    .expect("the run completes");
    // Over the bump the chassis rises from where it had settled (its mean
    // height over 0.4–1.4 s, before the front reaches the bump) by the
    // share of the bump its wheels carry it over: quasi-statically one
    // to two of its five wheels stand on the 1 m bump at a time, 0.02 to
    // 0.04 m; with the ride's overshoot, between 0.015 and 0.06 m
    // (measured 0.025 m). Its rear (2.2 m behind the centroid) is past
    // the bump at the end.
    let heights = results.column("y").unwrap();
    let settled: Vec<f64> = results
        .times()
        .iter()
        .zip(heights.iter())
        .filter(|(t, _)| (0.4..=1.4).contains(*t))
        .map(|(_, y)| *y)
        .collect();
    let settled = settled.iter().sum::<f64>() / settled.len() as f64;
    let rise = max_of(heights.iter().copied()) - settled;
    assert!((0.015..0.06).contains(&rise), "chassis rose {rise} m");
    let x = *results.column("x").unwrap().last().unwrap();
    assert!(x - 2.2 > 4.5, "the vehicle ended at x = {x} m");

    let books = Books::of(&results);
    eprintln!(
        "main job's settings: books {:.2e} of the work",
        books.relative()
    );
    assert!(
        books.relative() < 5e-3,
        "energy books at the main job's settings: residual {:.3e} of the work",
        books.relative()
    );
    assert!(books.least_dissipation_step >= 0.0);
    let closure = max_of(results.column("track.closure_error").unwrap());
    assert!(closure < 1e-10, "closure error {closure:e} m");
}

/// The recorded chassis coordinates at sample `k`.
fn chassis_q(results: &Results, k: usize) -> SVector<f64, { M113::CHASSIS_DOF }> {
    let first = results
        .columns()
        .iter()
        .position(|c| c == "chassis.x")
        .expect("chassis columns");
    SVector::from_fn(|i, _| results.sample(k).values[first + i])
}

/// The recorded track coordinates at sample `k`.
fn track_q(results: &Results, k: usize) -> SVector<f64, { M113::TRACK_DOF }> {
    let first = results
        .columns()
        .iter()
        .position(|c| c == "track.x")
        .expect("track columns");
    SVector::from_fn(|i, _| results.sample(k).values[first + i])
}

/// Steady driving up a 25 % slope, so that the sprocket carries a real
/// torque: the tension on the tight span exceeds the slack span's by what
/// the statics of the sprocket and its seated links ask, with the pitch
/// radius computed here from pitch and teeth; and the drive force pulls
/// the vehicle up the slope (bounds in the file's header).
#[test]
fn tight_span_tension_matches_sprocket_statics() {
    let slope: f64 = 0.25;
    let terrain = Terrain::Ramp {
        height: 0.0,
        start: 2.5,
        slope,
    };
    let drive = M113::speed_drive(|t| 1.5 * ((t - 0.5) / 1.0).clamp(0.0, 1.0));
    let mut system = m113_with(terrain, drive, ClosureMethod::Declared);
    let results = simulate(&mut system, integrator(), 0.0, 6.0, Output::Every(0.005)).unwrap();
    let r_p = m113_pitch_radius();
    let (t0, t1) = (4.5, 6.0);
    // The moment about the sprocket centre of the weight of the links
    // seated on it (centroids within 1 cm of the pitch circle's reach).
    let mut gravity_moment = Vec::new();
    for k in 0..results.len() {
        if !(t0..=t1).contains(&results.times()[k]) {
            continue;
        }
        let mut links = vec![Vector2::zeros(); M113Track::BODIES];
        M113Track.body_positions(&track_q(&results, k), &mut links);
        let mut bodies = vec![Vector2::zeros(); M113Chassis::BODIES];
        M113Chassis.body_positions(&chassis_q(&results, k), &mut bodies);
        let centre = bodies[M113Chassis::SPROCKET];
        gravity_moment.push(
            links
                .iter()
                .filter(|p| (*p - centre).norm() < r_p + 0.01)
                .map(|p| -(p.x - centre.x) * m113::SHOE_MASS * 9.81)
                .sum::<f64>(),
        );
    }
    // Driving forward turns the sprocket clockwise: torque and the seated
    // links' weight (they hang in front of the centre) both negative.
    let torque = mean(&window(&results, "sprocket_torque", t0, t1));
    let gravity_moment = mean(&gravity_moment);
    let pull = mean(&window(&results, "tension_tight", t0, t1))
        - mean(&window(&results, "tension_slack", t0, t1));
    let ratio = pull * r_p / -(torque + gravity_moment);
    eprintln!(
        "ratio {ratio:.4}; drive force {pull:.0} N = W sin α + {:.1} % of W",
        100.0 * (pull - m113_weight() * 0.25 / (1.0f64 + 0.0625).sqrt()) / m113_weight()
    );
    let chordal = {
        let half = std::f64::consts::PI / 10.0;
        half / half.sin()
    };
    assert!(
        (1.0 - 5e-3..=chordal + 5e-3).contains(&ratio),
        "(T_tight − T_slack) r_p / (|τ| + M_g) = {ratio:.4}: pull {pull:.0} N, torque {torque:.0} N m, seated links' weight {gravity_moment:.0} N m"
    );
    let w = m113_weight();
    let along = w * slope / (1.0 + slope * slope).sqrt();
    assert!(
        pull > along && pull < along + 0.06 * w,
        "drive force {pull:.0} N against W sin α = {along:.0} N (W = {w:.0} N)"
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
    let (shoe, profile) = (M113::geometry().shoe, M113::geometry().sprocket);
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
