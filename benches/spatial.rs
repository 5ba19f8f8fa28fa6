//! What floating a track's chain in space costs over the planar chain:
//! the closed M113-like chains of 16, 64 and 128 links, their loop cut
//! (`RecursiveModel::tree_dynamics`, the open route both use), the planar
//! forward dynamics against the floating tree's
//! (`spatial::FloatingTree::accelerations`: the planar route under the
//! plane's inertial loads, and the 3 × 3 out-of-plane block), and the same
//! tree with every link off the plane (the hull's running gear: two more
//! planar solves for the coupling).
//!
//! And the M113's right-hand side, planar (one side) against spatial
//! (both sides and the hull), and the same two settling from their
//! assembled start for 0.5 s under the main job's integrator.
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

/// One evaluation of the M113's right-hand side: the planar vehicle's
/// (`M113System`, one side, at its assembled start) against the spatial
/// one's (`SpatialSystem`: the hull with both sides' gear and both
/// tracks, 64 and 63 links, at its assembled start): the same contacts
/// per side (rims and teeth; the shoes 1 mm above the ground).
fn m113_derivative(c: &mut Criterion) {
    use trackgen::integrate::OdeSystem;
    use trackgen::spatial_vehicle::{SpatialSimulated, SpatialVehicleSystem};
    use trackgen::system::Simulated;
    use trackgen::terrain::Terrain;
    use trackgen::terrain::field::HeightField;
    use trackgen::vehicle::Vehicle;
    use trackgen::vehicles::m113::M113;

    let flat = Terrain::Flat { height: 0.0 };
    let mut planar = M113::system(flat.clone(), M113::speed_drive(|_| 0.0)).unwrap();
    let y0 = planar.initial_state();
    let mut dy = vec![0.0; y0.len()];
    // The declared laws: the guides' horn Chrono's M113 shoe's guide box,
    // 0.075 m high (a secondary source).
    let mut spatial = M113::spatial(M113::declared_laws(), HeightField::level()).unwrap();
    let y = spatial.assembled(&flat).unwrap();
    let mut dys = vec![0.0; y.len()];
    m113_settle(c, (&mut planar, &y0), (&mut spatial, &y));
    let mut group = c.benchmark_group("m113_derivative");
    group.bench_function("planar_one_side", |b| {
        b.iter(|| {
            planar
                .derivative(0.0, black_box(y0.as_slice()), &mut dy)
                .unwrap()
        })
    });
    group.bench_function("spatial_both_sides", |b| {
        b.iter(|| {
            spatial
                .derivative(0.0, black_box(y.as_slice()), &mut dys)
                .unwrap()
        })
    });
    group.finish();
}

/// A whole run, side by side: the M113 from its assembled start (the
/// shoes 1 mm above the ground) settling for 0.5 s under the main job's
/// Bogacki-Shampine at its default tolerance, planar (one side) against
/// spatial (both sides and the hull). Each run's steps and evaluations
/// are printed once: the ratio of the runs' times is the ratio of the
/// evaluations' times times the ratio of their counts.
fn m113_settle(
    c: &mut Criterion,
    planar: (
        &mut impl trackgen::integrate::OdeSystem,
        &trackgen::nalgebra::DVector<f64>,
    ),
    spatial: (
        &mut impl trackgen::integrate::OdeSystem,
        &trackgen::nalgebra::DVector<f64>,
    ),
) {
    use trackgen::integrate::{Integrator, OdeSystem};
    const END: f64 = 0.5;
    fn settle(system: &mut impl OdeSystem, y0: &trackgen::nalgebra::DVector<f64>) -> String {
        let tolerance = Integrator::DEFAULT_EXPLICIT_TOLERANCE;
        let method = Integrator::Bs23 {
            rtol: tolerance,
            atol: tolerance,
            max_step: Integrator::DEFAULT_MAX_STEP,
        };
        let mut stepper = method.stepper(system.dimension());
        let (mut t, mut y) = (0.0, y0.clone());
        while t < END {
            stepper.step(system, &mut t, &mut y, END).unwrap();
        }
        let stats = stepper.stats();
        format!(
            "{} steps ({} rejected), {} evaluations",
            stats.accepted, stats.rejected, stats.evaluations
        )
    }
    let (planar, y_planar) = planar;
    let (spatial, y_spatial) = spatial;
    println!("m113_settle/planar_one_side: {}", settle(planar, y_planar));
    println!(
        "m113_settle/spatial_both_sides: {}",
        settle(spatial, y_spatial)
    );
    let mut group = c.benchmark_group("m113_settle");
    group.sample_size(10);
    group.bench_function("planar_one_side", |b| b.iter(|| settle(planar, y_planar)));
    group.bench_function("spatial_both_sides", |b| {
        b.iter(|| settle(spatial, y_spatial))
    });
    group.finish();
}

fn benches(c: &mut Criterion) {
    bench_one(c, Track16);
    bench_one(c, Track64);
    bench_one(c, Track128);
    m113_derivative(c);
}

criterion_group!(spatial, benches);
criterion_main!(spatial);
