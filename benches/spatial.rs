//! What floating a track's chain in space costs over the planar chain:
//! the closed M113-like chains of 16, 64 and 128 links, their loop cut
//! (`RecursiveModel::tree_dynamics`, the open route both use), the planar
//! forward dynamics against the floating tree's
//! (`spatial::FloatingTree::accelerations`: the planar route under the
//! plane's inertial loads, and the 3 × 3 out-of-plane block), and the same
//! tree with every link off the plane (the hull's running gear: two more
//! planar solves for the coupling).
//!
//! `cargo bench -p trackgen-benches --bench spatial`; the numbers are in
//! docs/performance.md.

use criterion::{BenchmarkId, Criterion, criterion_group, criterion_main};
use std::hint::black_box;
use trackgen::multibody::RecursiveModel;
use trackgen::nalgebra::{SVector, Vector3};
use trackgen::spatial::{FloatingTree, OutOfPlaneInertia, PlanePose, PlaneRates};

use trackgen_benches::*;

fn bench_one<M: RecursiveModel<D>, const D: usize>(c: &mut Criterion, model: M) {
    let n = D - 2;
    let (q, qd) = state::<D>();
    let plate = OutOfPlaneInertia::plate(18.02, 0.154, 0.38, 0.06);
    let tree = FloatingTree::new(&model, vec![plate; n]).unwrap();
    let offset = FloatingTree::new(&model, vec![plate; n])
        .unwrap()
        .with_offsets(vec![0.3; n])
        .unwrap();
    let pose = PlanePose {
        origin: Vector3::new(1.0, 0.5, 0.4),
        yaw: 0.3,
        roll: 0.1,
        planar: q,
    };
    let rates = PlaneRates {
        planar: qd,
        across: Vector3::new(0.1, 0.05, 0.2),
    };
    let mut group = c.benchmark_group("floating_chain");
    group.bench_with_input(BenchmarkId::new("planar", n), &n, |b, _| {
        let trig: Vec<(f64, f64)> = (0..n).map(|i| q[2 + i].sin_cos()).collect();
        b.iter(|| {
            let mut qdd = SVector::<f64, D>::zeros();
            model
                .tree_dynamics(black_box(&trig), black_box(&qd), &[], &mut qdd)
                .unwrap();
            black_box(qdd)
        })
    });
    group.bench_with_input(BenchmarkId::new("floating", n), &n, |b, _| {
        b.iter(|| {
            black_box(
                tree.accelerations(black_box(&pose), black_box(&rates), &[])
                    .unwrap(),
            )
        })
    });
    group.bench_with_input(BenchmarkId::new("floating_off_plane", n), &n, |b, _| {
        b.iter(|| {
            black_box(
                offset
                    .accelerations(black_box(&pose), black_box(&rates), &[])
                    .unwrap(),
            )
        })
    });
    group.finish();
}

fn benches(c: &mut Criterion) {
    bench_one(c, Track16);
    bench_one(c, Track64);
    bench_one(c, Track128);
}

criterion_group!(spatial, benches);
criterion_main!(spatial);
