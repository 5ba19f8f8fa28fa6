//! Instances leak nothing: 100 instantiate / run / free cycles, counted
//! by a global allocator that tracks the bytes alive.

use std::alloc::{GlobalAlloc, Layout, System};
use std::sync::atomic::{AtomicIsize, Ordering};

use trackgen::vehicles::m113::M113;
use trackgen_fmu::component::{self, Component, Logger, Status};

struct Counting;

static LIVE: AtomicIsize = AtomicIsize::new(0);

// SAFETY: forwards to the system allocator, counting.
unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        LIVE.fetch_add(layout.size() as isize, Ordering::Relaxed);
        unsafe { System.alloc(layout) }
    }
    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        LIVE.fetch_sub(layout.size() as isize, Ordering::Relaxed);
        unsafe { System.dealloc(ptr, layout) }
    }
    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        LIVE.fetch_add(
            new_size as isize - layout.size() as isize,
            Ordering::Relaxed,
        );
        unsafe { System.realloc(ptr, layout, new_size) }
    }
}

#[global_allocator]
static ALLOCATOR: Counting = Counting;

/// One cycle as a master makes it through the C API's shared layer:
/// instantiate, initialise, two steps, a refused value, terminate, free.
fn cycle() {
    let created = Component::<M113>::create(
        "cycle",
        Logger::None,
        Some(trackgen::vehicles::m113::powertrain),
    )
    .unwrap();
    let pointer = Box::into_raw(created) as *mut std::ffi::c_void;
    // SAFETY: `pointer` is the instance just made, freed once at the end.
    unsafe {
        let status = component::with::<M113>(pointer, |c| {
            c.instance.setup_experiment(None, 0.0, Some(0.02))?;
            c.instance.enter_initialization()?;
            c.instance.exit_initialization()?;
            c.instance.do_step(0.0, 0.01)?;
            c.instance.do_step(0.01, 0.01)?;
            Ok(Status::Ok)
        });
        assert_eq!(status, Status::Ok);
        let refused = component::with::<M113>(pointer, |c| {
            c.instance.set_f64(&[0], &[f64::NAN]).map(|()| Status::Ok)
        });
        assert_eq!(refused, Status::Error);
        component::free::<M113>(pointer);
    }
}

#[test]
fn a_hundred_cycles_leak_nothing() {
    // The first cycle may fill lazily made tables (the generated code's
    // constants, the standard library's); the rest must not grow.
    cycle();
    let before = LIVE.load(Ordering::Relaxed);
    for _ in 0..100 {
        cycle();
    }
    let after = LIVE.load(Ordering::Relaxed);
    assert_eq!(after - before, 0, "bytes alive grew by {}", after - before);
}
