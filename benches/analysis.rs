//! What the derivatives cost, side by side with what they replace.
//!
//! * `track_jacobian`: the track's exact `∂q̈/∂(q, q̇)`
//!   (`dynamics::track_jacobian`, the linear-time solve's tangent, O(n)
//!   per direction) at 64 and 128 links: the ratio shows O(n²).
//! * `m113_state_jacobian`: one evaluation of the M113's right-hand side
//!   against its state Jacobian over every state with dynamics by central
//!   differences (`analysis::state_jacobian`: two evaluations a column)
//!   and exactly (`OdeSystem::jacobian`, every column of the state),
//!   beside its yardstick: forward differences over every column (one
//!   evaluation per state component plus one).
//! * `m113_sand_state_jacobian`: the same two on dry sand, driving (the
//!   soil's contacts and shear displacements in the Jacobian).
//! * `m113_rest`: the M113 at rest by `analysis::equilibrium` against the
//!   settling runs it replaces (1 s, the main job's, which still rings;
//!   3 s), Bogacki-Shampine at 1e-3 as in the main job.
//!
//! `cargo bench -p trackgen-benches --bench analysis`; the numbers are in docs/performance.md.

use criterion::measurement::WallTime;
use criterion::{BatchSize, BenchmarkGroup, Criterion, criterion_group, criterion_main};
use std::hint::black_box;
use std::time::Duration;
use trackgen::analysis::{EquilibriumOptions, equilibrium, state_jacobian};
use trackgen::dynamics::track_jacobian;
use trackgen::integrate::{Integrator, OdeSystem};
use trackgen::multibody::TrackModel;
use trackgen::simulate::{Output, simulate};
use trackgen::system::Simulated;
use trackgen::terrain::{Terrain, soil::SoilPreset};
use trackgen::vehicle::{Vehicle, VehicleDynamics};
use trackgen::vehicles::{m113::M113, m113::M113System};
use trackgen_benches::{Track64, Track128, driven, state};

fn track<M: TrackModel<D>, const D: usize>(model: M) -> impl FnMut() {
    let (q, qd) = state::<D>();
    move || {
        black_box(track_jacobian(&model, &q, &qd, &[]).unwrap());
    }
}

fn at_rest() -> M113System {
    M113::system(Terrain::Flat { height: 0.0 }, M113::speed_drive(|_| 0.0)).unwrap()
}

/// The M113 on dry sand driven from rest toward 2 m/s for 1.5 s (the
/// ground pressed after every step, as in a run): its system, time and
/// state.
fn on_sand() -> (M113System, f64, Vec<f64>) {
    let mut config = M113::declared_config(
        Terrain::Flat { height: 0.0 },
        M113::speed_drive(|t| 2.0 * t.min(1.0)),
    );
    config.soil = Some(SoilPreset::DrySand.soil());
    let (system, t, y) = driven::<M113>(config, 1.5);
    (system, t, y.as_slice().to_vec())
}

/// `forward_differences`, the yardstick (one evaluation per state
/// component plus one, every column of the state, as the integrators'
/// differences: the step √ε·max(|yⱼ|, 1)), beside `exact`
/// (`OdeSystem::jacobian`) at `(t, y)`.
fn forward_and_exact(
    group: &mut BenchmarkGroup<'_, WallTime>,
    system: &mut impl OdeSystem,
    t: f64,
    y: &[f64],
) {
    let n = y.len();
    let mut full = vec![0.0; n * n];
    let mut argument = y.to_vec();
    let mut base = vec![0.0; n];
    let mut moved = vec![0.0; n];
    group.bench_function("forward_differences", |b| {
        b.iter(|| {
            system.derivative(t, black_box(y), &mut base).unwrap();
            for (j, column) in full.chunks_exact_mut(n).enumerate() {
                let d = f64::EPSILON.sqrt() * y[j].abs().max(1.0);
                argument[j] = y[j] + d;
                system.derivative(t, &argument, &mut moved).unwrap();
                argument[j] = y[j];
                for ((c, fp), f) in column.iter_mut().zip(&moved).zip(&base) {
                    *c = (fp - f) / d;
                }
            }
        })
    });
    let mut slope = vec![0.0; n];
    system.derivative(t, y, &mut slope).unwrap();
    group.bench_function("exact", |b| {
        b.iter(|| {
            assert!(system.jacobian(t, black_box(y), &slope, &mut full).unwrap());
        })
    });
}

fn analysis(c: &mut Criterion) {
    let mut group = c.benchmark_group("track_jacobian");
    let mut t64 = track(Track64);
    group.bench_function("64", |b| b.iter(&mut t64));
    let mut t128 = track(Track128);
    group.bench_function("128", |b| b.iter(&mut t128));
    group.finish();

    let mut system = at_rest();
    let rest = equilibrium(&mut system, &EquilibriumOptions::default()).unwrap();
    let states: Vec<usize> = system.layout().dynamic().collect();
    let y = rest.state.clone();
    let mut dy = vec![0.0; y.len()];
    let mut group = c.benchmark_group("m113_state_jacobian");
    group.bench_function("one_evaluation", |b| {
        b.iter(|| {
            system
                .derivative(0.0, black_box(y.as_slice()), &mut dy)
                .unwrap()
        })
    });
    group.bench_function("central_differences", |b| {
        b.iter(|| black_box(state_jacobian(&mut system, 0.0, y.as_slice(), &states).unwrap()))
    });
    forward_and_exact(&mut group, &mut system, 0.0, y.as_slice());
    group.finish();

    // On dry sand, driving: the soil's contacts and shear states in the
    // Jacobian.
    let (mut sand, t, y) = on_sand();
    let mut group = c.benchmark_group("m113_sand_state_jacobian");
    forward_and_exact(&mut group, &mut sand, t, &y);
    group.finish();

    let mut group = c.benchmark_group("m113_rest");
    group.bench_function("equilibrium", |b| {
        b.iter_batched(
            at_rest,
            |mut s| black_box(equilibrium(&mut s, &EquilibriumOptions::default()).unwrap()),
            BatchSize::LargeInput,
        )
    });
    for seconds in [1.0, 3.0] {
        group.bench_function(format!("settle_{seconds}_s"), |b| {
            b.iter_batched(
                at_rest,
                |mut s| {
                    let integrator = Integrator::Bs23 {
                        rtol: 1e-3,
                        atol: 1e-3,
                        max_step: 0.01,
                    };
                    let _ = s.initial_state();
                    black_box(
                        simulate(&mut s, integrator, 0.0, seconds, Output::Every(0.1)).unwrap(),
                    )
                },
                BatchSize::LargeInput,
            )
        });
    }
    group.finish();
}

criterion_group! {
    name = benches;
    config = Criterion::default().measurement_time(Duration::from_secs(5)).sample_size(20);
    targets = analysis
}
criterion_main!(benches);
