//! The default vehicle's run speed: 0.5 s of the M113 driving on flat
//! ground (from rest, including the settling drop, speed controller on),
//! Bogacki-Shampine at 1e-3 as in the main job. The assembly is set-up,
//! outside the measured time. Real-time factor = 0.5 s / the time reported.
//!
//! And many vehicles: four such runs one after another against the same
//! four on rayon's pool (all cores), side by side.
//!
//! And soft soil against rigid ground: 2 s of the M113 from rest to
//! 2 m/s on flat rigid ground and on dry sand (Bekker–Wong soil, the rut
//! pressed after every step), side by side (group `ground`): the cost of
//! soft soil per simulated second is the ratio.
//!
//! `cargo bench -p trackgen-benches --bench vehicle`; the numbers are in docs/performance.md.

use criterion::{BatchSize, Criterion, criterion_group, criterion_main};
use rayon::prelude::*;
use std::hint::black_box;
use std::time::Duration;
use trackgen::integrate::Integrator;
use trackgen::simulate::{Output, simulate};
use trackgen::terrain::{Terrain, soil::SoilPreset};
use trackgen::vehicle::Vehicle;
use trackgen::vehicles::{m113, m113::M113};

/// The M113 at rest, speed controller on, ready to run.
fn vehicle_at_rest() -> m113::M113System {
    let drive = M113::speed_drive(|t| 3.0 * t.clamp(0.0, 1.0));
    M113::system(Terrain::Flat { height: 0.0 }, drive).unwrap()
}

fn half_second(mut system: m113::M113System) -> trackgen::simulate::Results {
    let integrator = Integrator::Bs23 {
        rtol: 1e-3,
        atol: 1e-3,
        max_step: 0.01,
    };
    simulate(&mut system, integrator, 0.0, 0.5, Output::Every(0.01)).unwrap()
}

fn vehicle(c: &mut Criterion) {
    c.bench_function("m113_half_second", |b| {
        b.iter_batched(
            vehicle_at_rest,
            |system| black_box(half_second(system)),
            BatchSize::LargeInput,
        )
    });
    let mut group = c.benchmark_group("four_m113_runs");
    let four = || (0..4).map(|_| vehicle_at_rest()).collect::<Vec<_>>();
    group.bench_function("serial", |b| {
        b.iter_batched(
            four,
            |systems| black_box(systems.into_iter().map(half_second).count()),
            BatchSize::LargeInput,
        )
    });
    group.bench_function("parallel", |b| {
        b.iter_batched(
            four,
            |systems| black_box(systems.into_par_iter().map(half_second).count()),
            BatchSize::LargeInput,
        )
    });
    group.finish();

    let mut group = c.benchmark_group("ground");
    let driving = |soil: Option<SoilPreset>| {
        move || {
            let drive = M113::speed_drive(|t| 2.0 * ((t - 0.5) / 1.0).clamp(0.0, 1.0));
            let mut config = M113::declared_config(Terrain::Flat { height: 0.0 }, drive);
            config.soil = soil.map(|s| s.soil());
            M113::system_with(config).unwrap()
        }
    };
    let two_seconds = |mut system: m113::M113System| {
        let integrator = Integrator::Bs23 {
            rtol: 1e-3,
            atol: 1e-3,
            max_step: 0.01,
        };
        simulate(&mut system, integrator, 0.0, 2.0, Output::Every(0.01)).unwrap()
    };
    group.bench_function("rigid", |b| {
        b.iter_batched(
            driving(None),
            |s| black_box(two_seconds(s)),
            BatchSize::LargeInput,
        )
    });
    group.bench_function("dry_sand", |b| {
        b.iter_batched(
            driving(Some(SoilPreset::DrySand)),
            |s| black_box(two_seconds(s)),
            BatchSize::LargeInput,
        )
    });
    group.finish();
}

criterion_group! {
    name = benches;
    config = Criterion::default().warm_up_time(Duration::from_secs(1)).measurement_time(Duration::from_secs(8)).sample_size(10);
    targets = vehicle
}
criterion_main!(benches);
