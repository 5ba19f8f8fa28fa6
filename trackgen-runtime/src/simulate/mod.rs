//! Simulation: a system of subsystems (a closed track, a chassis),
//! integrated in time, recorded into [`Results`] ([`simulate`]) or streamed
//! to any [`Sink`] as it runs ([`simulate_into`]): CSV and Arrow IPC files,
//! running figures, a bounded selection for plots, several at once.
//!
//! A run never panics on a bad state: it stops with a typed
//! [`SimulationError`] carrying the time and the cause, and returns the
//! results computed up to then in a [`SimulationFailure`] (or, streamed,
//! finishes the sink so the rows before the failure are written, and
//! returns a [`StreamFailure`]).

mod energy;
mod error;
mod loads;
mod observe;
mod output;
mod pair;
mod results;
mod run;
mod sink;
mod stream;
mod track;
mod tree;

pub use crate::error::SimulationError;
pub use energy::{
    DISSIPATED, ENERGY, EnergyBalance, EnergyBalanceError, MOTOR_WORK, RESIDUAL_FLOOR,
    RESIDUAL_PER_TOLERANCE,
};
pub use error::SimulationFailure;
pub use observe::{Momentum, momentum};
pub use output::Output;
pub use pair::Pair;
pub use results::{Results, Sample, Switch};
pub use run::{Simulated, simulate, simulate_with_progress};
#[cfg(feature = "arrow")]
pub use sink::ArrowSink;
pub use sink::{
    Background, ColumnSummary, CsvSink, Select, Sink, SinkError, Summary, Tee, Thinned,
};
pub use stream::{RunError, RunReport, StreamFailure, simulate_into};
pub use track::TrackSystem;
pub use tree::TreeSystem;

/// Applied loads as a function of time and state: `(t, q_i, q̇_i, loads)`,
/// one [`BodyLoad`](crate::BodyLoad) per body. The slice holds the loads
/// already acting (contact, in a vehicle): add to it (`+=`).
pub type LoadFn<const D: usize> = Box<
    dyn FnMut(f64, &nalgebra::SVector<f64, D>, &nalgebra::SVector<f64, D>, &mut [crate::BodyLoad])
        + Send,
>;
