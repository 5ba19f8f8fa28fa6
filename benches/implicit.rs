//! What the linearly implicit integrator's linear algebra costs on a
//! vehicle, against one evaluation of its right-hand side: the Marder
//! driving at 2 m/s (1.5 s from rest), its own `W`
//! (`integrate::ImplicitSolve`): linearising (the force elements'
//! Jacobians, the chassis' matrices), factoring `I − a W` for a step of
//! 1 ms, and one solve.
//!
//! `cargo bench -p trackgen-benches --bench implicit`; the numbers are in docs/performance.md.

use criterion::{Criterion, criterion_group, criterion_main};
use std::hint::black_box;
use trackgen::integrate::OdeSystem;
use trackgen::terrain::Terrain;
use trackgen::vehicle::Vehicle;
use trackgen::vehicles::marder::Marder;
use trackgen_benches::driven;

fn implicit(c: &mut Criterion) {
    let config = Marder::declared_config(
        Terrain::Flat { height: 0.0 },
        Marder::speed_drive(|t| 2.0 * t.min(1.0)),
    );
    let (mut system, t, y) = driven::<Marder>(config, 1.5);
    let mut dy = vec![0.0; y.len()];
    let a = 0.435_866_521_508_459 * 1e-3;
    let mut group = c.benchmark_group("marder_implicit");
    group.bench_function("evaluation", |b| {
        b.iter(|| {
            system
                .derivative(t, black_box(y.as_slice()), &mut dy)
                .unwrap()
        })
    });
    group.bench_function("evaluation_and_linearisation", |b| {
        b.iter(|| {
            system
                .derivative(t, black_box(y.as_slice()), &mut dy)
                .unwrap();
            system
                .implicit()
                .unwrap()
                .linearise(t, y.as_slice())
                .unwrap();
        })
    });
    system
        .implicit()
        .unwrap()
        .linearise(t, y.as_slice())
        .unwrap();
    group.bench_function("factor", |b| {
        b.iter(|| system.implicit().unwrap().factor(t, black_box(a)).unwrap())
    });
    let mut x = dy.clone();
    group.bench_function("solve", |b| {
        b.iter(|| {
            x.copy_from_slice(&dy);
            system
                .implicit()
                .unwrap()
                .solve(t, black_box(&mut x))
                .unwrap()
        })
    });
    group.finish();
}

criterion_group!(benches, implicit);
criterion_main!(benches);
