//! Terrain from data: reading a surveyed profile, generating a random
//! course, and looking up the ground under a contact.
//!
//! `cargo bench -p trackgen-benches --bench terrain`; the numbers are in
//! docs/performance.md.

use std::hint::black_box;

use criterion::{Criterion, criterion_group, criterion_main};
use trackgen::terrain::profile::Profile;
use trackgen::terrain::roughness::{Iso8608Class, RoughCourse, Spectrum};

/// A 10 km course at 5 cm spacing, as a CSV file's bytes.
fn ten_kilometres() -> Vec<u8> {
    let course = RoughCourse::new(Spectrum::Iso8608(Iso8608Class::C), 10_000.0, 0.05, 7)
        .profile()
        .expect("its profile");
    let mut bytes = Vec::new();
    course.write_csv(&mut bytes).expect("written");
    bytes
}

fn terrain(c: &mut Criterion) {
    let bytes = ten_kilometres();
    let mut group = c.benchmark_group("terrain");
    group.sample_size(10);
    group.bench_function("read a 10 km profile at 5 cm (200 001 points)", |b| {
        b.iter(|| Profile::from_csv_reader(black_box(&bytes[..]), "bench").expect("reads"))
    });
    group.bench_function("generate a 10 km ISO 8608 class C course at 5 cm", |b| {
        b.iter(|| {
            RoughCourse::new(
                Spectrum::Iso8608(Iso8608Class::C),
                10_000.0,
                0.05,
                black_box(7),
            )
            .profile()
            .expect("its profile")
        })
    });
    let profile = Profile::from_csv_reader(&bytes[..], "bench").expect("reads");
    group.bench_function("1000 height lookups marching forward", |b| {
        let mut x0 = 0.0;
        b.iter(|| {
            x0 = (x0 + 3.7) % 9_900.0;
            (0..1000).fold(0.0, |sum, k| {
                sum + profile.height(black_box(x0 + k as f64 * 0.0137))
            })
        })
    });
    group.finish();
}

criterion_group!(benches, terrain);
criterion_main!(benches);
