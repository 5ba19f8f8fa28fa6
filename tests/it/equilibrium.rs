//! The vehicle at rest (`trackgen::analysis::equilibrium`) and how its
//! rest changes with a spring rate (`equilibrium_sensitivity`), checked
//! against what the forward simulation does and against finite
//! differences of equilibria.

use trackgen::analysis::{
    AnalysisError, Equilibrium, EquilibriumOptions, equilibrium, equilibrium_sensitivity, mode_of,
    modes,
};
use trackgen::contact::GroundFriction;
use trackgen::integrate::{Integrator, OdeSystem};
use trackgen::laws::Friction;
use trackgen::simulate::{Output, simulate};
use trackgen::system::Simulated;
use trackgen::terrain::Terrain;
use trackgen::vehicle::{Drive, Vehicle, VehicleDynamics, build};
use trackgen::vehicles::{m113::M113, marder::Marder};

const FLAT: Terrain = Terrain::Flat { height: 0.0 };

/// The vehicle run for 2 s from its start at `t` (Bogacki-Shampine at
/// 1e-4): how far its hull moved (m) and pitched (rad), printed.
fn left_alone<S: VehicleDynamics>(system: &mut S, t: f64) -> (f64, f64) {
    let integrator = Integrator::Bs23 {
        rtol: 1e-4,
        atol: 1e-4,
        max_step: 0.01,
    };
    let results = simulate(system, integrator, t, t + 2.0, Output::Every(0.1)).expect("runs");
    let moved = |column: &str| {
        let values = results.column(column).unwrap();
        values
            .iter()
            .map(|v| (v - values[0]).abs())
            .fold(0.0, f64::max)
    };
    let (travel, pitch) = (moved("x").max(moved("y")), moved("pitch"));
    println!("  from rest over 2 s: hull moved {travel:.2e} m, pitched {pitch:.2e} rad");
    (travel, pitch)
}

fn at_rest<V: Vehicle>() -> (V::System, Equilibrium) {
    let mut system = V::system(FLAT, V::speed_drive(|_| 0.0)).expect("builds");
    let rest = equilibrium(&mut system, &EquilibriumOptions::default()).expect("rests");
    (system, rest)
}

/// At rest the ground carries the whole weight: the equilibrium's
/// equations are the accelerations, and only gravity and the ground act
/// on the vehicle from outside, so their balance is a check the Newton
/// iteration never looks at. Its residual (10⁻⁸ m/s² on a 5.6e4 N
/// vehicle of 5700 kg: 6e-8 N) bounds the mismatch: 10⁻⁹ relative.
/// Then the vehicle is left there for 2 s: started from its equilibrium
/// it does not move (the hull within 1 µm: the residual acceleration
/// alone moves it ½ · 10⁻⁸ · 2² = 2·10⁻⁸ m, and the integrator's error at
/// rest is nil).
fn stands_still<V: Vehicle>() {
    let (mut system, rest) = at_rest::<V>();
    println!(
        "{}: {} iterations, residual {:.1e}, ground {:.3} N, weight {:.3} N, height {:.6} m, pitch {:.6} rad, holding torque {:.2} N m",
        V::NAME,
        rest.iterations,
        rest.residual,
        rest.ground_force,
        rest.weight,
        rest.height,
        rest.pitch,
        rest.holding_torque
    );
    assert!(rest.residual < 1e-7, "residual {:e}", rest.residual);
    let relative = (rest.ground_force - rest.weight).abs() / rest.weight;
    assert!(
        relative < 1e-9,
        "ground force off the weight by {relative:e}"
    );
    system.set_start(rest.state.as_slice()).unwrap();
    let (moved, pitched) = left_alone(&mut system, 0.0);
    assert!(moved < 1e-6, "the hull moved");
    assert!(pitched < 1e-6, "the hull pitched");
}

#[test]
fn m113_stands_still_at_its_equilibrium() {
    stands_still::<M113>();
}

#[test]
fn marder_stands_still_at_its_equilibrium() {
    stands_still::<Marder>();
}

/// A long settling run ends at the equilibrium. Ground friction
/// regularised: with stiction the settled vehicle keeps whatever
/// tangential loads it caught while settling (rest is then a family of
/// states), while the equilibrium holds none; regularised friction lets
/// those loads creep away, so the run's end is the equilibrium's state.
/// The run: Dormand-Prince at 10⁻⁹, the drive holding, 40 s. Not 8: the
/// hull's modes die within seconds (pitch 1.35 Hz at ζ 0.37), but the
/// upper span rings as a string with almost nothing to damp it (3.1 Hz
/// at ζ 0.003, `modes`): after 8 s its links still swing at 0.8 rad/s and
/// the hull sits 0.2 mm and 1.3·10⁻⁴ rad off its rest; after 24 s,
/// 3·10⁻⁶ m and 9·10⁻⁶ rad; after 40 s it is inside the bounds.
/// The equilibrium is found from the run's end, its track phase (the
/// sprocket's angle) kept: the rest of a track on its wheels depends on
/// where the shoes sit under them. Bounds: 0.1 mm and 10⁻⁵ rad.
#[test]
fn settling_run_ends_at_the_equilibrium() {
    let mut config = M113::declared_config(FLAT, M113::speed_drive(|_| 0.0));
    config.ground.friction = GroundFriction::Regularised(Friction {
        mu: config.ground.friction.mu(),
        slip: 0.1,
    });
    let mut system = build::<M113>(config).unwrap();
    let duration = 40.0;
    let mut stepper = Integrator::dopri5(1e-9).stepper(system.dimension());
    let (mut t, mut settled) = (0.0, system.initial_state());
    while t < duration {
        stepper
            .step(&mut system, &mut t, &mut settled, duration)
            .unwrap();
        if system
            .after_step(t, settled.as_mut_slice(), &mut |_| {})
            .unwrap()
        {
            stepper.restart();
        }
    }
    let mut row = Vec::new();
    system.observe(t, settled.as_slice(), &mut row).unwrap();
    let column = |name: &str| row[system.columns().iter().position(|c| c == name).unwrap()];
    let (height, pitch) = (column("y"), column("pitch"));
    let options = EquilibriumOptions {
        t: duration,
        start: Some(settled.clone()),
        relax: 0.0,
        ..EquilibriumOptions::default()
    };
    let rest = equilibrium(&mut system, &options).unwrap();
    let layout = system.layout();
    let fastest = layout.rates().map(|i| settled[i].abs()).fold(0.0, f64::max);
    println!(
        "settled (fastest rate left {fastest:.1e}): height {height:.7} m, pitch {pitch:.8} rad; equilibrium {:.7} m, {:.8} rad ({} iterations): {:.2e} m, {:.2e} rad apart",
        rest.height,
        rest.pitch,
        rest.iterations,
        (height - rest.height).abs(),
        (pitch - rest.pitch).abs()
    );
    assert!((height - rest.height).abs() < 1e-4);
    assert!((pitch - rest.pitch).abs() < 1e-5);
}

/// The equilibrium's sensitivity to each road-wheel arm's torsion rate
/// (`∂u/∂k = −(∂r/∂u)⁻¹ ∂r/∂k`) against central differences of
/// equilibria at `k ± 1 %` (each found by Newton's method from the
/// equilibrium, its phase kept). The differences' truncation error is
/// `(δk)² ∂³u/∂k³ / 6`, of order 10⁻⁴ of the derivative for a response
/// as smooth as `1/k`; the equilibria are found to 10⁻⁸ m/s², whose
/// position error (10⁻⁸ / ω², ω ≥ 8 rad/s) is 10⁻¹⁰ m against changes of
/// 10⁻⁴ m. Bound: 10⁻³ relative to the largest of the three arms'
/// derivatives.
#[test]
fn sensitivity_to_torsion_rates_matches_finite_differences() {
    let (mut system, rest) = at_rest::<M113>();
    let from_rest = EquilibriumOptions {
        start: Some(rest.state.clone()),
        relax: 0.0,
        ..EquilibriumOptions::default()
    };
    let mut scale: f64 = 0.0;
    let mut checked = Vec::new();
    for arm in [0, 2, 4] {
        let exact = equilibrium_sensitivity(&mut system, &rest, arm).unwrap();
        let k = system.arms_mut()[arm].spring.stiffness;
        let dk = 0.01 * k;
        let mut at = |stiffness: f64| {
            system.arms_mut()[arm].spring.stiffness = stiffness;
            let e = equilibrium(&mut system, &from_rest).unwrap();
            system.arms_mut()[arm].spring.stiffness = k;
            e
        };
        let (plus, minus) = (at(k + dk), at(k - dk));
        let height = (plus.height - minus.height) / (2.0 * dk);
        let pitch = (plus.pitch - minus.pitch) / (2.0 * dk);
        println!(
            "arm {arm}: ∂height/∂k {:.6e} (differences {height:.6e}), ∂pitch/∂k {:.6e} ({pitch:.6e}) per N m/rad",
            exact.height, exact.pitch
        );
        scale = scale.max(exact.height.abs()).max(exact.pitch.abs());
        checked.push((exact.height - height, exact.pitch - pitch));
    }
    for (dh, dp) in checked {
        assert!(dh.abs() < 1e-3 * scale && dp.abs() < 1e-3 * scale);
    }
}

/// What cannot rest gets a typed error, not a wrong answer.
#[test]
fn what_cannot_rest_is_refused() {
    let mut free = M113::system(FLAT, Drive::Free).unwrap();
    assert!(matches!(
        equilibrium(&mut free, &EquilibriumOptions::default()),
        Err(AnalysisError::NoHold { .. })
    ));
    let mut moving = M113::system(FLAT, M113::speed_drive(|_| 1.0)).unwrap();
    assert!(matches!(
        equilibrium(&mut moving, &EquilibriumOptions::default()),
        Err(AnalysisError::Moving { .. })
    ));
    // Pulled by a drawbar on regularised friction, which holds nothing at
    // rest: no equilibrium, and the error says how far from one.
    let mut config = M113::declared_config(FLAT, M113::speed_drive(|_| 0.0));
    config.drawbar_pull = 5000.0;
    config.ground.friction = GroundFriction::Regularised(Friction {
        mu: config.ground.friction.mu(),
        slip: 0.1,
    });
    let mut pulled = build::<M113>(config).unwrap();
    let error = equilibrium(&mut pulled, &EquilibriumOptions::default()).unwrap_err();
    println!("pulled: {error}");
    assert!(
        matches!(error, AnalysisError::NotConverged { .. }),
        "{error}"
    );
}

/// Held by stiction (the ground points in contact sharing one tangential
/// deflection): under a 5 kN drawbar pull on level ground, and parked
/// across a 30 % grade, the vehicle rests, and started there it stays
/// (the hull within 1 µm over 2 s: as on level ground, the residual
/// moves it 2·10⁻⁸ m). On the grade the sprocket's holding torque carries
/// the weight's share along the slope through the track. The hull's
/// bounce and pitch are found there too (`mode_of`).
#[test]
fn stiction_holds_a_pull_and_a_grade() {
    let mut config = M113::declared_config(FLAT, M113::speed_drive(|_| 0.0));
    config.drawbar_pull = 5000.0;
    let pulled = build::<M113>(config).unwrap();
    let (parked, stopped, t) = drive_onto_a_grade(0.3);
    for (what, mut system, start, t) in [
        ("pulled", pulled, None, 0.0),
        ("on 30 %", parked, Some(stopped), t),
    ] {
        let options = EquilibriumOptions {
            t,
            start,
            ..EquilibriumOptions::default()
        };
        let rest = equilibrium(&mut system, &options).unwrap_or_else(|e| panic!("{what}: {e}"));
        let modes = modes(&mut system, rest.t, &rest.state).unwrap();
        let hull = |motion| mode_of(&modes, motion).map_or(f64::NAN, |m| m.frequency);
        println!(
            "{what}: {} iterations, residual {:.1e}, pitch {:.5} rad, holding torque {:.1} N m; hull bounce {:.3} Hz, pitch {:.3} Hz",
            rest.iterations,
            rest.residual,
            rest.pitch,
            rest.holding_torque,
            hull("hull bounce"),
            hull("hull pitch")
        );
        assert!(hull("hull bounce").is_finite() && hull("hull pitch").is_finite());
        system.set_start(rest.state.as_slice()).unwrap();
        let (moved, _) = left_alone(&mut system, t);
        assert!(moved < 1e-6, "{what}: the hull moved");
    }
}

/// The M113 driven at 1 m/s from level ground onto a `grade` ramp
/// starting 3 m ahead, until its rear wheel is a metre up it, and stopped
/// there with the
/// sprocket held (as `examples/grade_hold.rs` parks it): the vehicle, its
/// state when the drive's target has been 0 for a second, and that time.
fn drive_onto_a_grade(
    grade: f64,
) -> (
    trackgen::vehicles::m113::M113System,
    trackgen::nalgebra::DVector<f64>,
    f64,
) {
    // The rear wheel's back starts at x = −4.1 m.
    let (start, climb) = (3.0, 1.0);
    let stop = 1.5 + (start + 4.1 + 1.0) / climb;
    let target = move |t: f64| {
        let up = ((t - 0.5) / 1.0).clamp(0.0, 1.0);
        let down = ((stop + 1.0 - t) / 1.0).clamp(0.0, 1.0);
        climb * up.min(down)
    };
    let terrain = Terrain::Ramp {
        height: 0.0,
        start,
        slope: grade,
    };
    let mut system = M113::system(terrain, M113::speed_drive(target)).unwrap();
    let end = stop + 2.0;
    let mut stepper = Integrator::Bs23 {
        rtol: 1e-4,
        atol: 1e-4,
        max_step: 0.01,
    }
    .stepper(system.dimension());
    let (mut t, mut y) = (0.0, system.initial_state());
    while t < end {
        stepper.step(&mut system, &mut t, &mut y, end).unwrap();
        if system.after_step(t, y.as_mut_slice(), &mut |_| {}).unwrap() {
            stepper.restart();
        }
    }
    (system, y, t)
}

/// At rest the tensioner arm's spring balances the track's pull on its
/// idler: the torque of the arm's spring (its declared law at the arm's
/// angle) against the moments about the pivot of the idler's and the
/// arm's weights and of the track's resultant on the idler. That
/// resultant comes from the track's own solve, not from the contact
/// forces: the run of links round the idler is at rest, so the idler's
/// push on it balances the joint forces at its two ends and its weight
/// (`F = F_out − F_in + G_run`, through the idler's centre: its rim
/// contacts are radial at rest). Bound: 10⁻³ of the spring's torque (the
/// equilibrium's residual, 10⁻⁸ m/s², is far below; what could differ is
/// a run link touching something besides the idler). Measured 7·10⁻¹³:
/// 6 links on the idler, a pull of 34.6 kN, the spring's 6894 N m.
#[test]
fn the_tensioner_balances_the_track_tension() {
    let (mut system, rest) = at_rest::<M113>();
    let (t, y) = (rest.t, &rest.state);
    let mut dy = vec![0.0; y.len()];
    system.derivative(t, y.as_slice(), &mut dy).unwrap();
    let forces = system.track().joint_forces().to_vec();
    let (qt, qc) = system.coordinates(t, y.as_slice()).unwrap();
    type S = trackgen::vehicles::m113::M113System;
    let track = <S as VehicleDynamics>::track_description();
    let chassis = <S as VehicleDynamics>::chassis_description();
    let gravity = chassis.gravity;
    let n = track.len();
    let mut centroids = vec![trackgen::nalgebra::Vector2::zeros(); n];
    <S as VehicleDynamics>::track_positions(qt.as_slice(), &mut centroids);
    let mut bodies = vec![trackgen::nalgebra::Vector2::zeros(); chassis.len()];
    <S as VehicleDynamics>::chassis_positions(qc.as_slice(), &mut bodies);
    let idler = <S as VehicleDynamics>::parts()
        .iter()
        .find(|p| p.kind == trackgen::multibody::PartKind::Idler)
        .unwrap();
    let arm = idler.arm.unwrap();
    let centre = bodies[idler.body];
    let pivot = bodies[arm.body]
        + trackgen::planar::rotate(qc[2 + arm.body], chassis.bodies[arm.body].at_self);
    // The run on the idler: links whose pins both lie within 2 cm of the
    // circle the seated pins describe (rim plus the shoe's inner offset).
    let joints = track.joints().unwrap();
    let seated = idler.radius + system.geometry().shoe.inner_offset();
    let on_idler: Vec<bool> = (0..n)
        .map(|k| {
            let ends = [joints[k].0, joints[k].1]
                .map(|u| centroids[k] + trackgen::planar::rotate(qt[2 + k], u));
            ends.iter()
                .all(|e| ((e - centre).norm() - seated).abs() < 0.02)
        })
        .collect();
    let first = (0..n)
        .find(|&k| on_idler[k] && !on_idler[(k + n - 1) % n])
        .unwrap();
    let run: Vec<usize> = (0..n)
        .map(|i| (first + i) % n)
        .take_while(|&k| on_idler[k])
        .collect();
    let last = *run.last().unwrap();
    let weight: trackgen::nalgebra::Vector2<f64> =
        run.iter().map(|&k| gravity * track.bodies[k].mass).sum();
    let pull = forces[last] - forces[(first + n - 1) % n] + weight;
    let cross = |a: trackgen::nalgebra::Vector2<f64>, b: trackgen::nalgebra::Vector2<f64>| {
        a.x * b.y - a.y * b.x
    };
    let loads = cross(
        centre - pivot,
        pull + gravity * chassis.bodies[idler.body].mass,
    ) + cross(
        bodies[arm.body] - pivot,
        gravity * chassis.bodies[arm.body].mass,
    );
    let spring = system
        .arms_mut()
        .iter()
        .find(|a| a.body == arm.body)
        .unwrap()
        .spring;
    let torque = spring.torque(qc[2 + arm.body] - qc[2], 0.0);
    println!(
        "tensioner: {} links on the idler, track pull {:.1} N, spring {torque:.2} N m, loads {loads:.2} N m ({:.1e} of the spring)",
        run.len(),
        pull.norm(),
        (torque + loads).abs() / torque.abs()
    );
    assert!((torque + loads).abs() < 1e-3 * torque.abs());
}
