//! What a powertrain's cap costs an evaluation: the M113A3's converter
//! envelope (`Powertrain::limit`: each range's full-load match solved, the
//! ranges bounded) against Chrono's simple map through ideally shifted
//! gears (a table lookup per gear), over a sweep of sprocket speeds from
//! rest to beyond the top speed, and at rest alone (the stall torque, found
//! once per build by a vehicle).
//!
//! `cargo bench -p trackgen-benches --bench powertrain`; the numbers are in
//! docs/performance.md.

use criterion::{Criterion, criterion_group, criterion_main};
use std::hint::black_box;
use trackgen::vehicles::m113;

fn powertrain(c: &mut Criterion) {
    let mut group = c.benchmark_group("powertrain");
    let speeds: Vec<f64> = (0..100).map(|k| k as f64 * 0.8).collect();
    for (name, powertrain) in [
        ("converter (M113A3)", m113::powertrain()),
        ("simple map (Chrono's M113)", m113::chrono_simple_map()),
    ] {
        group.bench_function(format!("{name}: 100 speeds, 0 to 80 rad/s"), |b| {
            b.iter(|| {
                speeds
                    .iter()
                    .map(|&w| powertrain.limit(black_box(w)).0)
                    .sum::<f64>()
            })
        });
        group.bench_function(format!("{name}: at rest"), |b| {
            b.iter(|| powertrain.limit(black_box(0.0)).0)
        });
    }
    group.finish();
}

criterion_group!(benches, powertrain);
criterion_main!(benches);
