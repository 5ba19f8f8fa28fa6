//! Subsystems in motion: a body tree or a closed track as a first-order
//! system `y' = f(t, y)` ([`crate::integrate::OdeSystem`]) that
//! also knows its start, what it records and what to do between steps
//! ([`Simulated`]). A vehicle ([`crate::vehicle`]) is made of two of them;
//! [`crate::simulate`] runs any of them.
//!
//! * [`TrackSystem`]: a track, its loop closed by partitioning with
//!   switching, multipliers or a penalty joint ([`crate::closure`]);
//! * [`TreeSystem`]: a chassis, an open chain, a penalty-closed track;
//! * [`Pair`]: two subsystems side by side in one state.

mod loads;
mod mechanics;
mod pair;
mod record;
mod track;
mod tree;

pub use mechanics::{Mechanics, Momentum, momentum};
pub use pair::Pair;
pub use track::{TrackRecord, TrackSystem};
pub use tree::TreeSystem;

pub(crate) use record::record;

use nalgebra::DVector;

use crate::closure::Switch;
use crate::integrate::OdeSystem;
use crate::integrate::SimulationError;

/// Applied loads as a function of time and state: `(t, q_i, q̇_i, loads)`,
/// one [`BodyLoad`](crate::multibody::BodyLoad) per body. The slice holds the loads
/// already acting (contact, in a vehicle): add to it (`+=`).
pub type LoadFn<const D: usize> = Box<
    dyn FnMut(
            f64,
            &nalgebra::SVector<f64, D>,
            &nalgebra::SVector<f64, D>,
            &mut [crate::multibody::BodyLoad],
        ) + Send,
>;

/// A system a simulation can run: an [`OdeSystem`] that also knows its
/// initial state, what to record, and what to do between steps.
pub trait Simulated: OdeSystem {
    /// The state at the start.
    fn initial_state(&self) -> DVector<f64>;

    /// Names of the recorded quantities.
    fn columns(&self) -> Vec<String>;

    /// Appends the recorded quantities at `(t, y)` to `row`, one per
    /// [`columns`](Self::columns).
    fn observe(&mut self, t: f64, y: &[f64], row: &mut Vec<f64>) -> Result<(), SimulationError>;

    /// As [`observe`](Self::observe) for a run whose sinks read only the
    /// columns `wanted[i]` (one flag per [`columns`](Self::columns)): the
    /// others may be left NaN, and a system may skip computing them. The
    /// columns it does give are bit for bit what `observe` gives. The
    /// default observes every column.
    fn observe_some(
        &mut self,
        t: f64,
        y: &[f64],
        wanted: &[bool],
        row: &mut Vec<f64>,
    ) -> Result<(), SimulationError> {
        let _ = wanted;
        self.observe(t, y, row)
    }

    /// Called after every accepted step; may change the coordinates of the
    /// state (re-partitioning, projection), telling `switched` of every
    /// re-partitioning. Returns whether it changed the state, so the
    /// integrator restarts.
    fn after_step(
        &mut self,
        _t: f64,
        _y: &mut [f64],
        _switched: &mut dyn FnMut(Switch),
    ) -> Result<bool, SimulationError> {
        Ok(false)
    }
}
