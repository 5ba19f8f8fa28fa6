//! The default vehicle's run speed: 0.5 s of the M113 driving on flat
//! ground (from rest, including the settling drop, speed controller on),
//! Bogacki-Shampine at 1e-3 as in the main job. The assembly is set-up,
//! outside the measured time. Real-time factor = 0.5 s / the time reported.
//!
//! `cargo bench --bench vehicle`; numbers in README.md.

use criterion::{BatchSize, Criterion, criterion_group, criterion_main};
use std::hint::black_box;
use std::time::Duration;
use trackgen::contact::Terrain;
use trackgen::integrate::Integrator;
use trackgen::simulate::{Output, simulate};
use trackgen::vehicles::m113;

fn vehicle(c: &mut Criterion) {
    c.bench_function("m113_half_second", |b| {
        b.iter_batched(
            || {
                let drive = m113::speed_drive(|t| 3.0 * t.clamp(0.0, 1.0));
                m113::system(Terrain::Flat { height: 0.0 }, drive).unwrap()
            },
            |mut system| {
                let integrator = Integrator::Bs23 {
                    rtol: 1e-3,
                    atol: 1e-3,
                    max_step: 0.01,
                };
                black_box(simulate(&mut system, integrator, 0.0, 0.5, Output::Every(0.01)).unwrap())
            },
            BatchSize::LargeInput,
        )
    });
}

criterion_group! {
    name = benches;
    config = Criterion::default().warm_up_time(Duration::from_secs(1)).measurement_time(Duration::from_secs(8)).sample_size(10);
    targets = vehicle
}
criterion_main!(benches);
