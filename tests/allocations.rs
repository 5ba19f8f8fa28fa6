//! The simulation's hot path allocates nothing: after a warm-up, an
//! evaluation of the M113's right-hand side (recovery, contact, both
//! subsystems' dynamics, the books) and a whole Bogacki-Shampine or
//! Dormand-Prince step (its stages and error estimate) make no heap
//! allocation, counted on the test's own thread by a global allocator that
//! counts (the harness's other threads do not count). A test binary of
//! its own, so that the counting allocator serves nothing else.

use std::alloc::{GlobalAlloc, Layout, System};
use std::cell::Cell;

use trackgen::integrate::{Integrator, OdeSystem};
use trackgen::nalgebra::DVector;
use trackgen::system::Simulated;
use trackgen::terrain::Terrain;
use trackgen::vehicle::Vehicle;
use trackgen::vehicles::{m113, m113::M113};

/// The system allocator, counting allocations and reallocations per thread.
struct Counting;

thread_local! {
    /// This thread's allocations and reallocations: the test's own, not
    /// the harness's on its other threads. A `const` thread-local without
    /// a destructor, so reading it allocates nothing.
    static ALLOCATIONS: Cell<usize> = const { Cell::new(0) };
}

fn count() {
    // `try_with`: a thread being torn down has no counter left to bump.
    let _ = ALLOCATIONS.try_with(|n| n.set(n.get() + 1));
}

// SAFETY: forwards to the system allocator unchanged.
unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        count();
        unsafe { System.alloc(layout) }
    }

    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        unsafe { System.dealloc(ptr, layout) }
    }

    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        count();
        unsafe { System.realloc(ptr, layout, new_size) }
    }
}

#[global_allocator]
static GLOBAL: Counting = Counting;

fn allocations_in(f: impl FnOnce()) -> usize {
    let before = ALLOCATIONS.with(Cell::get);
    f();
    ALLOCATIONS.with(Cell::get) - before
}

#[test]
fn evaluations_and_steps_allocate_nothing() {
    let drive = M113::speed_drive(|t| 3.0 * t.clamp(0.0, 1.0));
    let mut system = M113::system(
        Terrain::Bump {
            centre: 5.0,
            width: 1.0,
            height: 0.1,
        },
        drive,
    )
    .expect("the M113 assembles");
    for integrator in [
        Integrator::Bs23 {
            rtol: 1e-3,
            atol: 1e-3,
            max_step: 0.01,
        },
        Integrator::dopri5(1e-6),
    ] {
        let mut stepper = integrator.stepper(system.dimension());
        let (mut t, mut y) = (0.0, system.initial_state());
        let mut dy = DVector::zeros(y.len());
        let mut step = |system: &mut m113::M113System, t: &mut f64, y: &mut DVector<f64>| {
            stepper.step(system, t, y, 10.0).expect("a step");
            if system
                .after_step(*t, y.as_mut_slice(), &mut |_| {})
                .expect("after the step")
            {
                stepper.restart();
            }
        };
        // Warm-up: buffers reach their size, the first steps choose theirs.
        for _ in 0..20 {
            step(&mut system, &mut t, &mut y);
        }
        let warm = t;
        let evaluation = allocations_in(|| {
            for _ in 0..50 {
                system
                    .derivative(t, y.as_slice(), dy.as_mut_slice())
                    .expect("an evaluation");
            }
        });
        assert_eq!(
            evaluation, 0,
            "{integrator:?}: allocations in 50 evaluations"
        );
        let steps = allocations_in(|| {
            for _ in 0..200 {
                step(&mut system, &mut t, &mut y);
            }
        });
        assert_eq!(
            steps, 0,
            "{integrator:?}: allocations in 200 steps to t = {t} s"
        );
        assert!(t > warm, "the steps went somewhere: t = {t} s");
    }
}
