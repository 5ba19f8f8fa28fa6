//! The frames of a 3-D run that its page plays (`animation.html`,
//! [`spatial_animation`](trackgen_draw::spatial_animation)): the vehicle
//! drawn at the rows' times, at most [`MAX_FRAMES`] of them and no closer
//! than [`FRAME_EVERY`] s apart, over the ruts it pressed on soft soil.

use std::path::Path;

use trackgen::contact::rut_grid::RutPatch;
use trackgen::nalgebra::Vector2;
use trackgen::spatial_vehicle::{SpatialScene, SpatialSimulated, SpatialVehicleSystem};
use trackgen_draw::spatial_animation;

/// The most frames a page holds: some 650 numbers each, a page of a few
/// megabytes at most.
const MAX_FRAMES: f64 = 600.0;
/// The closest frames, s: the page plays 25 a second, so a run plays in
/// real time where it can.
const FRAME_EVERY: f64 = 0.04;
/// The ruts are drawn in squares of this many of the rut's cells a side
/// (8 cm at its 2 cm cells): some 2 500 squares for the M113's two ruts
/// over 40 m.
const RUT_CELLS: usize = 4;

/// The frames kept so far, and when the next is due.
pub(crate) struct Frames {
    every: f64,
    next: f64,
    outline: Vec<Vector2<f64>>,
    kept: Vec<SpatialScene>,
    ruts: Vec<RutPatch>,
}

impl Frames {
    /// No frames yet, for a run of `V` lasting `duration` s.
    pub(crate) fn new<V: SpatialVehicleSystem>(duration: f64) -> Frames {
        Frames {
            every: (duration / MAX_FRAMES).max(FRAME_EVERY),
            next: 0.0,
            outline: trackgen::scene::outline::<V>(),
            kept: Vec::new(),
            ruts: Vec::new(),
        }
    }

    /// `system` at time `t` and state `y` (a row's), kept if a frame is
    /// due.
    pub(crate) fn offer(&mut self, system: &dyn SpatialSimulated, t: f64, y: &[f64]) {
        // A row's time may fall a rounding short of the frame's.
        if t < self.next - 1e-9 {
            return;
        }
        self.kept.push(system.scene(t, y, &self.outline));
        self.next += self.every * ((t - self.next) / self.every).floor().max(0.0) + self.every;
    }

    /// The ruts `system` has pressed by the run's end, each square with
    /// when it was first pressed: the page draws those pressed by each
    /// frame's time (none on rigid ground).
    pub(crate) fn take_ruts(&mut self, system: &dyn SpatialSimulated) {
        self.ruts = system.rut_patches(RUT_CELLS);
    }

    /// The page of the frames kept, each over its floor, into `file`,
    /// headed `title`; nothing where fewer than two were kept.
    pub(crate) fn write(&self, file: &Path, title: &str) -> std::io::Result<bool> {
        if self.kept.len() < 2 {
            return Ok(false);
        }
        let page = spatial_animation::html(&self.kept, &self.ruts, title);
        std::fs::write(file, page)?;
        Ok(true)
    }
}
