//! `M_i` + `Q_i` of a closed track: generated code against the reference
//! (textbook) route, at n = 8, 16, 32, 64, 128 links, side by side.
//!
//! `cargo bench -p trackgen-benches --bench mass_and_forces`; the ratios are in docs/performance.md.

use criterion::{BenchmarkId, Criterion, criterion_group, criterion_main};
use std::hint::black_box;
use std::time::Duration;
use trackgen::multibody::RecursiveModel;
use trackgen::nalgebra::{DVector, SMatrix, SVector};
use trackgen::reference::ReferenceModel;

use trackgen_benches::*;

fn bench_one<M: RecursiveModel<D>, const D: usize>(c: &mut Criterion, model: M) {
    let n = M::BODIES;
    let (q, qd) = state::<D>();
    let mut group = c.benchmark_group("mass_and_forces");
    group.bench_with_input(BenchmarkId::new("generated", n), &n, |b, _| {
        let mut m = SMatrix::<f64, D, D>::zeros();
        let mut f = SVector::<f64, D>::zeros();
        b.iter(|| {
            model.equations_of_motion(black_box(&q), black_box(&qd), &[], &mut m, &mut f);
            black_box((&m, &f));
        })
    });
    let reference = ReferenceModel::new(model.description());
    let (dq, dqd) = (
        DVector::from_column_slice(q.as_slice()),
        DVector::from_column_slice(qd.as_slice()),
    );
    group.bench_with_input(BenchmarkId::new("reference", n), &n, |b, _| {
        b.iter(|| {
            let m = reference.mass_matrix(black_box(&dq));
            let f = reference.generalized_forces(black_box(&dq), black_box(&dqd), &[]);
            black_box((m, f))
        })
    });
    group.finish();
}

fn mass_and_forces(c: &mut Criterion) {
    bench_one(c, Track8);
    bench_one(c, Track16);
    bench_one(c, Track32);
    bench_one(c, Track64);
    bench_one(c, Track128);
}

criterion_group! {
    name = benches;
    config = Criterion::default().warm_up_time(Duration::from_millis(500)).measurement_time(Duration::from_secs(2)).sample_size(30);
    targets = mass_and_forces
}
criterion_main!(benches);
