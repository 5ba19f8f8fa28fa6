//! Integrating closed chains (formulation §2): conservation, switching of the
//! dependent pair, the three closure methods against one another. Each
//! test's tolerances are justified at the test. Largest and smallest values
//! over a run are taken with `support::max_of` / `min_of` / `max_abs`, which
//! return NaN when a sample is NaN, so a run that produced NaN fails every
//! `<` or `>` check instead of dropping out of the reduction.

use crate::support;

use support::{Lcg, max_abs, max_of, min_of};
use trackgen::closure::{
    ClosureMethod, MultiplierOptions, PartitionOptions, RecoveryError, multipliers,
};
use trackgen::integrate::{Integrator, SimulationError};
use trackgen::laws::PenaltyJoint;
use trackgen::multibody::TrackModel;
use trackgen::nalgebra::SVector;
use trackgen::simulate::{Output, Results, simulate};
use trackgen::system::TrackSystem;

trackgen::model! {
    /// 20 M113 shoes in zero gravity.
    pub track Free20 {
        links: 20,
        link { mass: 18.02, inertia: 0.04, u1: (-0.077, 0.0), u2: (0.077, 0.0) },
        gravity: (0.0, 0.0),
    }

    /// The same under gravity, with heavier links every other one.
    pub track Heavy20 {
        links: 20,
        link { mass: 18.02, inertia: 0.04, u1: (-0.077, 0.0), u2: (0.077, 0.0) },
        link[2..=20 by 2] { mass: 25.0, inertia: 0.06 },
    }

    /// A small loop whose shape changes a lot: the dependent pair passes
    /// through parallel.
    pub track Loop8 {
        links: 8,
        link { mass: 1.0, inertia: 0.01, u1: (-0.1, 0.0), u2: (0.1, 0.0) },
        gravity: (0.0, 0.0),
    }
}

/// A regular polygon (closed) with random velocities projected onto the
/// closure, `C_q q̇ = 0`.
fn start<M: TrackModel<D>, const D: usize>(
    model: &M,
    seed: u64,
    speed: f64,
) -> (SVector<f64, D>, SVector<f64, D>) {
    let n = D - 2;
    let mut rng = Lcg::new(seed);
    let mut q = SVector::<f64, D>::zeros();
    for i in 0..n {
        q[2 + i] = 2.0 * std::f64::consts::PI * i as f64 / n as f64;
    }
    let mut qd = SVector::<f64, D>::from_fn(|_, _| speed * rng.uniform(-1.0, 1.0));
    multipliers::project(model, &mut q, &mut qd, 1e-14).unwrap();
    (q, qd)
}

/// The largest departure of a column from its first value, over `scale`;
/// NaN (failing every `<` check) if any sample is NaN.
fn relative_drift(results: &Results, column: &str, scale: f64) -> f64 {
    let v = results.column(column).unwrap();
    max_abs(v.iter().map(|x| x - v[0])) / scale
}

/// The largest value of a column, NaN if any sample is NaN.
fn max(results: &Results, column: &str) -> f64 {
    max_of(results.column(column).unwrap())
}

/// Test 1: a 20-link loop in zero gravity conserves energy, linear and
/// angular momentum to 1e-8 relative over 10 s (Dormand-Prince at
/// rtol = atol = 1e-12: the global error after ~1e4 steps stays ~1e-10),
/// and partitioning keeps `|C|` below 1e-10 m throughout (Newton-Raphson
/// converges to 1e-13 of the loop length, 3e-13 m).
#[test]
fn free_loop_conserves_energy_and_momentum() {
    let (q, qd) = start(&Free20, 1, 2.0);
    let mut system = TrackSystem::new(Free20, q, qd, ClosureMethod::Declared).unwrap();
    let results = simulate(
        &mut system,
        Integrator::dopri5(1e-12),
        0.0,
        10.0,
        Output::Every(0.05),
    )
    .unwrap();
    assert_eq!(results.len(), 201);
    let energy = results.column("energy").unwrap()[0];
    assert!(energy > 1.0, "a moving loop: T = {energy}");
    let p = results.sample(0);
    let momentum = p
        .get("momentum_x")
        .unwrap()
        .hypot(p.get("momentum_y").unwrap());
    let angular = p.get("angular_momentum").unwrap().abs();
    assert!(
        relative_drift(&results, "energy", energy) < 1e-8,
        "energy drift {:e}",
        relative_drift(&results, "energy", energy)
    );
    // Momenta are compared against their own size, or the energy's scale
    // (m·v, with v from T) where they are near zero.
    let scale_p = (2.0 * 20.0 * 18.02 * energy).sqrt();
    for (col, size) in [
        ("momentum_x", momentum.max(scale_p)),
        ("momentum_y", momentum.max(scale_p)),
        ("angular_momentum", angular.max(scale_p)),
    ] {
        let drift = relative_drift(&results, col, size);
        assert!(drift < 1e-8, "{col} drift {drift:e}");
    }
    assert!(
        max(&results, "closure_error") < 1e-10,
        "|C| up to {:e}",
        max(&results, "closure_error")
    );
    assert!(max(&results, "closure_rate_error") < 1e-10);
}

/// Test 2: under gravity the total energy (kinetic + gravity potential) is
/// conserved to the same order, relative to the initial kinetic energy.
#[test]
fn loop_under_gravity_conserves_energy() {
    let (q, qd) = start(&Heavy20, 2, 2.0);
    let mut system = TrackSystem::new(Heavy20, q, qd, ClosureMethod::Declared).unwrap();
    let results = simulate(
        &mut system,
        Integrator::dopri5(1e-12),
        0.0,
        10.0,
        Output::Every(0.05),
    )
    .unwrap();
    let t0 = results.column("kinetic").unwrap()[0];
    let v_span = {
        let v = results.column("potential").unwrap();
        max_of(v.iter().copied()) - min_of(v.iter().copied())
    };
    // The loop falls freely: gravity exchanges far more energy than the
    // loop starts with, and the drift is measured against the start.
    assert!(v_span > 100.0 * t0, "potential span {v_span}, kinetic {t0}");
    let drift = relative_drift(&results, "energy", t0);
    assert!(drift < 1e-8, "energy drift {drift:e}");
    assert!(max(&results, "closure_error") < 1e-10);
}

fn partitioned(switching: bool) -> ClosureMethod {
    ClosureMethod::Partitioning(PartitionOptions {
        switching,
        initial_pair: Some([1, 3]),
        ..Default::default()
    })
}

/// Test 3: the loop's motion drives the initial dependent pair (links 1
/// and 3) through parallel. Without switching the run stops with the typed
/// error; with switching it completes, conserves energy, and records the
/// switches.
#[test]
fn switching_avoids_singular_partitions() {
    let (q, qd) = start(&Loop8, 3, 3.0);
    let mut fixed = TrackSystem::new(Loop8, q, qd, partitioned(false)).unwrap();
    let failure = simulate(
        &mut fixed,
        Integrator::dopri5(1e-11),
        0.0,
        5.0,
        Output::Every(0.01),
    )
    .unwrap_err();
    let SimulationError::Recovery(RecoveryError::SingularPartition {
        t,
        pair,
        conditioning,
    }) = failure.error
    else {
        panic!("expected a singular partition, got {}", failure.error);
    };
    assert_eq!(pair, [1, 3]);
    assert!(conditioning < 0.01 && t > 0.0 && t < 5.0);
    // The results up to the failure are kept.
    assert!(!failure.results.is_empty() && failure.results.last().unwrap().t <= t);

    let mut switching = TrackSystem::new(Loop8, q, qd, partitioned(true)).unwrap();
    let results = simulate(
        &mut switching,
        Integrator::dopri5(1e-11),
        0.0,
        5.0,
        Output::Every(0.01),
    )
    .unwrap();
    assert!(!results.switches.is_empty());
    let first = results.switches[0];
    assert_eq!(first.from, [1, 3]);
    assert!(
        first.t < t,
        "switched at {} before the singularity at {t}",
        first.t
    );
    assert!(first.conditioning < 0.5 && first.new_conditioning > first.conditioning);
    let energy = results.column("energy").unwrap()[0];
    assert!(relative_drift(&results, "energy", energy) < 1e-8);
    assert!(max(&results, "closure_error") < 1e-10);
    // Switching keeps the pair well conditioned all along.
    let worst = min_of(results.column("conditioning").unwrap());
    assert!(worst > 0.3, "conditioning fell to {worst}");
}

/// Test 4: with a penalty joint, the loop's gap falls as the stiffness
/// rises (roughly as 1/k: the joint force is fixed by the motion, the gap
/// is force/k), and with zero damping the energy, spring included, stays
/// bounded.
#[test]
fn penalty_gap_falls_with_stiffness() {
    let (q, qd) = start(&Heavy20, 4, 1.0);
    let mut gaps = Vec::new();
    for stiffness in [1e4, 1e5, 1e6] {
        let method = ClosureMethod::Penalty(PenaltyJoint {
            stiffness,
            damping: 0.0,
        });
        let mut system = TrackSystem::new(Heavy20, q, qd, method).unwrap();
        let results = simulate(
            &mut system,
            Integrator::dopri5(1e-9),
            0.0,
            1.0,
            Output::Every(0.01),
        )
        .unwrap();
        let energy_scale = results.column("kinetic").unwrap()[0].max(1.0);
        let drift = relative_drift(&results, "energy", energy_scale);
        assert!(drift < 1e-5, "k = {stiffness}: energy drift {drift:e}");
        gaps.push(max(&results, "closure_error"));
    }
    assert!(
        gaps[0] > 5.0 * gaps[1] && gaps[1] > 5.0 * gaps[2],
        "gaps {gaps:?}"
    );
}

/// Test 5: the three methods agree on a 1 s trajectory. Partitioning and
/// multipliers solve the same equations (measured 6e-11 apart, at
/// rtol 1e-11; 1e-8 allowed); a penalty joint of k = 1e8 N/m leaves a gap
/// of order force/k and differs by about that (measured 2e-6; 1e-5
/// allowed).
#[test]
fn three_closure_methods_agree() {
    let (q, qd) = start(&Heavy20, 5, 1.0);
    let run = |method| {
        let mut system = TrackSystem::new(Heavy20, q, qd, method).unwrap();
        simulate(
            &mut system,
            Integrator::dopri5(1e-11),
            0.0,
            1.0,
            Output::Times(vec![0.5, 1.0]),
        )
        .unwrap()
    };
    let partition = run(ClosureMethod::Partitioning(PartitionOptions::default()));
    let multiplier = run(ClosureMethod::Multipliers(MultiplierOptions::default()));
    let penalty = run(ClosureMethod::Penalty(PenaltyJoint {
        stiffness: 1e8,
        damping: 0.0,
    }));
    let coords = |r: &Results, i: usize| r.sample(i).values[..22].to_vec();
    for i in 0..2 {
        let a = coords(&partition, i);
        let worst = |b: Vec<f64>| max_abs(a.iter().zip(&b).map(|(x, y)| x - y));
        let (dm, dp) = (worst(coords(&multiplier, i)), worst(coords(&penalty, i)));
        assert!(dm < 1e-8, "multipliers differ by {dm:e}");
        assert!(dp < 1e-5, "penalty differs by {dp:e}");
        assert!(dp > dm, "the penalty joint is the approximate one");
    }
}
