//! Closed-track forward dynamics, side by side at n = 16, 32, 64, 128:
//! the generated linear-time route (formulation §5, each track's own code:
//! `TrackModel::linear_time_dynamics`), the generic linear-time solver
//! (the same algorithm over a run-time description: the baseline), and the
//! dense multiplier form on the generated `M_i`.
//!
//! - `closed_forward_dynamics`: state to accelerations, each route paying
//!   for its sines and cosines the way a simulation does (the generated
//!   route with the runtime's vectorised `sin_cos_each`, the generic one
//!   with `f64::sin_cos` per link, as it always has).
//! - `closed_solve`: the same with every link's `(sin θ, cos θ)` given:
//!   the solves alone.
//!
//! `cargo bench -p trackgen-benches --bench forward_dynamics`; the numbers are in docs/performance.md.

use criterion::{BenchmarkId, Criterion, criterion_group, criterion_main};
use std::hint::black_box;
use std::time::Duration;
use trackgen::dynamics::{LinearTimeSolver, dense_forward_dynamics};
use trackgen::multibody::{ClosingJoint, TrackModel};
use trackgen::nalgebra::{SVector, Vector2};

use trackgen_benches::*;

fn bench_one<M: TrackModel<D>, const D: usize>(c: &mut Criterion, model: M) {
    let n = M::BODIES;
    let (q, qd) = state::<D>();
    let mut solver = LinearTimeSolver::new(&model);
    let (mut trig, mut forces) = (vec![(0.0, 1.0); n], vec![Vector2::zeros(); n]);
    let generated = |trig: &[(f64, f64)], forces: &mut [Vector2<f64>]| {
        let mut qdd = SVector::<f64, D>::zeros();
        model
            .linear_time_dynamics(
                trig,
                black_box(&qd),
                &[],
                ClosingJoint::CLOSED,
                &mut qdd,
                forces,
            )
            .unwrap();
        qdd
    };

    let mut group = c.benchmark_group("closed_forward_dynamics");
    group.bench_with_input(BenchmarkId::new("generated", n), &n, |b, _| {
        b.iter(|| {
            trackgen::trig::sin_cos_each(&black_box(&q).as_slice()[2..], &mut trig);
            black_box(generated(&trig, &mut forces))
        })
    });
    group.bench_with_input(BenchmarkId::new("linear_time", n), &n, |b, _| {
        b.iter(|| {
            black_box(
                solver
                    .forward_dynamics(&model, black_box(&q), black_box(&qd), &[])
                    .unwrap(),
            )
        })
    });
    group.bench_with_input(BenchmarkId::new("dense", n), &n, |b, _| {
        b.iter(|| {
            black_box(dense_forward_dynamics(&model, black_box(&q), black_box(&qd), &[]).unwrap())
        })
    });
    group.finish();

    let mut group = c.benchmark_group("closed_solve");
    let given: Vec<(f64, f64)> = (0..n).map(|i| q[2 + i].sin_cos()).collect();
    group.bench_with_input(BenchmarkId::new("generated", n), &n, |b, _| {
        b.iter(|| black_box(generated(black_box(&given), &mut forces)))
    });
    group.bench_with_input(BenchmarkId::new("linear_time", n), &n, |b, _| {
        b.iter(|| {
            black_box(
                solver
                    .accelerations_with_trig(
                        black_box(&q),
                        black_box(&qd),
                        &[],
                        true,
                        Vector2::zeros(),
                        None,
                        Some(black_box(&given)),
                    )
                    .unwrap(),
            )
        })
    });
    group.finish();
}

fn closed_forward_dynamics(c: &mut Criterion) {
    bench_one(c, Track16);
    bench_one(c, Track32);
    bench_one(c, Track64);
    bench_one(c, Track128);
}

criterion_group! {
    name = benches;
    config = Criterion::default().warm_up_time(Duration::from_millis(500)).measurement_time(Duration::from_secs(2)).sample_size(30);
    targets = closed_forward_dynamics
}
criterion_main!(benches);
