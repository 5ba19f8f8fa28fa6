//! The default vehicle's run speed: 0.5 s of the M113 driving on flat
//! ground (from rest, speed controller on), Dormand-Prince at 1e-4 as in
//! the main job. Real-time factor = 0.5 s / the time reported.
//!
//! `cargo bench --bench vehicle`; numbers in README.md.

use criterion::{Criterion, criterion_group, criterion_main};
use std::hint::black_box;
use std::time::Duration;
use trackgen::closure::ClosureMethod;
use trackgen::contact::sprocket::ToothProfile;
use trackgen::contact::{ShoeGeometry, Terrain};
use trackgen::integrate::Integrator;
use trackgen::simulate::{Output, simulate};
use trackgen::vehicle::{Drive, VehicleConfig, VehicleSystem, assemble};
use trackgen::vehicles::m113::{M113Chassis, M113Track};

fn vehicle(c: &mut Criterion) {
    let terrain = Terrain::Flat { height: 0.0 };
    let a = assemble(
        &M113Track,
        &M113Chassis,
        &ShoeGeometry::m113(),
        &ToothProfile::m113(),
        &terrain,
        0.0,
        0.001,
    )
    .unwrap();
    c.bench_function("m113_half_second", |b| {
        b.iter(|| {
            let drive = Drive::Speed {
                target: Box::new(|t: f64| 3.0 * t.clamp(0.0, 1.0)),
                proportional: 3000.0,
                integral: 6000.0,
                max_torque: 2e4,
            };
            let config = VehicleConfig::m113(terrain.clone(), drive);
            let mut system = VehicleSystem::new(
                M113Track,
                M113Chassis,
                a.track,
                a.chassis,
                ClosureMethod::Declared,
                config,
            )
            .unwrap();
            let integrator = Integrator::Dopri5 {
                rtol: 1e-4,
                atol: 1e-4,
                max_step: 0.01,
            };
            black_box(simulate(&mut system, integrator, 0.0, 0.5, Output::Every(0.01)).unwrap())
        })
    });
}

criterion_group! {
    name = benches;
    config = Criterion::default().warm_up_time(Duration::from_secs(1)).measurement_time(Duration::from_secs(8)).sample_size(10);
    targets = vehicle
}
criterion_main!(benches);
