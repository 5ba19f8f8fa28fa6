//! The dense routes of a large track run on a 2 MiB worker thread (a
//! thread's default stack on Linux is 2 MiB when spawned by
//! `std::thread`, 8 MiB for the main thread): `M_i` of a large model lives
//! on the heap, so nothing of size O(n²) is on the stack (issue 12: at 1000
//! links the 8 MB `M_i` on the stack aborted the process).
//!
//! 256 links (`M_i` 532 KB, past `STACK_MATRIX_BYTES`, so the heap route
//! runs) keep this test's build to seconds; 1000 links are measured by
//! `tools/compile-time-stress.sh large 1000`.
//!
//! The multiplier form is compared with the linear-time solver (formulation §5),
//! the open route with the reference route on the same chain without its
//! loop joint: the same equations solved two ways, to 1e-9 relative,
//! norm-wise. The dense elimination's rounding grows with `M_i`'s condition
//! number (~n² for a chain, ~1e5 here, times 2.2e-16); measured 8e-12
//! (multiplier form against linear time) and 7e-11 (open route, and the
//! reference route, against the generated dense route).

use trackgen::dynamics::{
    LinearTimeSolver, STACK_MATRIX_BYTES, dense_forward_dynamics, dense_open_dynamics,
};
use trackgen::multibody::RecursiveModel;
use trackgen::nalgebra::{DVector, SVector};
use trackgen_runtime::reference::ReferenceModel;

const N: usize = 256;
const DOF: usize = N + 2;

trackgen::model! {
    /// 256 links, closed by a constraint, not all alike.
    pub track Large {
        links: 256,
        link { mass: 18.02, inertia: 0.04, u1: (-0.077, 0.0), u2: (0.077, 0.0) },
        link[1..=256 by 3] { mass: 20.5, inertia: 0.05 },
        link[2..=255 by 5] { u1: (-0.08, 0.004), u2: (0.075, -0.002) },
        closure: partitioned,
    }
}

/// A state off the closure manifold (the dense and linear-time routes
/// solve the same equations anywhere).
fn state() -> (SVector<f64, DOF>, SVector<f64, DOF>) {
    let q = SVector::from_fn(|i, _| 0.7 * (0.37 * i as f64).sin());
    let qd = SVector::from_fn(|i, _| 0.5 * (0.23 * i as f64).cos());
    (q, qd)
}

/// Runs `f` on a thread with a 2 MiB stack and returns its result; a stack
/// overflow there aborts the whole test binary, so this fails loudly.
fn on_small_stack<T: Send + 'static>(f: impl FnOnce() -> T + Send + 'static) -> T {
    std::thread::Builder::new()
        .stack_size(2 << 20)
        .spawn(f)
        .expect("spawned a worker thread")
        .join()
        .expect("the worker thread finished")
}

fn relative_difference(a: &SVector<f64, DOF>, b: &SVector<f64, DOF>) -> f64 {
    let d = (a - b).norm() / b.norm();
    assert!(d.is_finite(), "not finite: {d}");
    d
}

fn dynamic(v: &SVector<f64, DOF>) -> DVector<f64> {
    DVector::from_column_slice(v.as_slice())
}

#[test]
fn the_test_exercises_the_heap_route() {
    assert_eq!(Large::LINKS, N);
    const { assert!(8 * DOF * DOF > STACK_MATRIX_BYTES) };
}

#[test]
fn dense_multiplier_form_runs_on_a_2_mib_thread() {
    let (d, dl) = on_small_stack(|| {
        let (q, qd) = state();
        let dense = dense_forward_dynamics(&Large, &q, &qd, &[]).unwrap();
        let linear = LinearTimeSolver::new(&Large)
            .forward_dynamics(&Large, &q, &qd, &[])
            .unwrap();
        let (a, b) = (dense.multipliers.unwrap(), linear.multipliers.unwrap());
        (
            relative_difference(&dense.qdd, &linear.qdd),
            (a - b).norm() / b.norm(),
        )
    });
    assert!(d <= 1e-9, "q̈_i: {d:e}");
    assert!(dl <= 1e-9, "λ: {dl:e}");
}

#[test]
fn dense_open_route_runs_on_a_2_mib_thread() {
    let d = on_small_stack(|| {
        let (q, qd) = state();
        let dense = dense_open_dynamics(&Large, &q, &qd, &[]).unwrap();
        assert!(dense.multipliers.is_none());
        let mut open = Large.description();
        open.loop_joint = None;
        let reference = ReferenceModel::new(open)
            .forward_dynamics(&dynamic(&q), &dynamic(&qd), &[])
            .unwrap();
        relative_difference(
            &dense.qdd,
            &SVector::from_column_slice(reference.qdd.as_slice()),
        )
    });
    assert!(d <= 1e-9, "q̈_i: {d:e}");
}

#[test]
fn reference_route_runs_on_a_2_mib_thread() {
    let d = on_small_stack(|| {
        let (q, qd) = state();
        let reference = ReferenceModel::new(Large.description())
            .forward_dynamics(&dynamic(&q), &dynamic(&qd), &[])
            .unwrap();
        let dense = dense_forward_dynamics(&Large, &q, &qd, &[]).unwrap();
        relative_difference(
            &SVector::from_column_slice(reference.qdd.as_slice()),
            &dense.qdd,
        )
    });
    assert!(d <= 1e-9, "q̈_i: {d:e}");
}
