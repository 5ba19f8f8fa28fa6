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
use trackgen::nalgebra::SVector;

macro_rules! tracks {
    ($($name:ident = $n:literal),*) => {
        trackgen::model! {
            $(
                /// An M113-like closed track.
                pub track $name {
                    links: $n,
                    link { mass: 18.02, inertia: 0.04, u1: (-0.077, 0.0), u2: (0.077, 0.0) },
                    closure: partitioned,
                }
            )*
        }
    };
}

tracks!(Track16 = 16, Track32 = 32, Track64 = 64, Track128 = 128);

fn state<const D: usize>() -> (SVector<f64, D>, SVector<f64, D>) {
    let n = (D - 2) as f64;
    let q = SVector::from_fn(|i, _| {
        if i < 2 {
            0.3
        } else {
            2.0 * std::f64::consts::PI * (i - 2) as f64 / n
        }
    });
    let qd = SVector::from_fn(|i, _| if i < 2 { 1.0 } else { 0.5 });
    (q, qd)
}

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
