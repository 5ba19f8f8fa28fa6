//! Closed-track forward dynamics, state to accelerations: the linear-time
//! route (spec §5) against the dense multiplier form on the generated
//! `M_i`, at n = 16, 32, 64, 128, side by side.
//!
//! `cargo bench --bench forward_dynamics`; numbers in README.md.

use criterion::{BenchmarkId, Criterion, criterion_group, criterion_main};
use std::hint::black_box;
use std::time::Duration;
use trackgen::TrackModel;
use trackgen::dynamics::{LinearTimeSolver, forward_dynamics};

mod support;
use support::*;

fn bench_one<M: TrackModel<D>, const D: usize>(c: &mut Criterion, model: M, dense: bool) {
    let n = M::BODIES;
    let (q, qd) = state::<D>();
    let mut group = c.benchmark_group("closed_forward_dynamics");
    let mut solver = LinearTimeSolver::new(&model);
    group.bench_with_input(BenchmarkId::new("linear_time", n), &n, |b, _| {
        b.iter(|| {
            black_box(
                solver
                    .forward_dynamics(&model, black_box(&q), black_box(&qd), &[])
                    .unwrap(),
            )
        })
    });
    if dense {
        group.bench_with_input(BenchmarkId::new("dense", n), &n, |b, _| {
            b.iter(|| {
                black_box(forward_dynamics(&model, black_box(&q), black_box(&qd), &[]).unwrap())
            })
        });
    }
    group.finish();
}

fn closed_forward_dynamics(c: &mut Criterion) {
    bench_one(c, Track16, true);
    bench_one(c, Track32, true);
    bench_one(c, Track64, true);
    bench_one(c, Track128, true);
}

criterion_group! {
    name = benches;
    config = Criterion::default().warm_up_time(Duration::from_millis(500)).measurement_time(Duration::from_secs(2)).sample_size(30);
    targets = closed_forward_dynamics
}
criterion_main!(benches);
