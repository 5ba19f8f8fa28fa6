//! Simulation: a system of subsystems (a closed track, a chassis),
//! integrated in time, recorded into [`Results`] ([`simulate`]) or streamed
//! to any [`Sink`] as it runs ([`simulate_into`]): CSV files (and Arrow IPC
//! with the crate trackgen-arrow),
//! running figures, a bounded selection for plots, several at once.
//!
//! A run never panics on a bad state: it stops with a typed
//! [`SimulationError`](crate::integrate::SimulationError) carrying the time and the cause, and returns the
//! results computed up to then in a [`SimulationFailure`] (or, streamed,
//! finishes the sink so the rows before the failure are written, and
//! returns a [`StreamFailure`]).

mod energy;
mod error;
mod march;
mod output;
mod results;
mod run;
mod sink;
mod stream;

pub use energy::{
    DISSIPATED, ENERGY, EnergyBalance, EnergyBalanceError, MOTOR_WORK, RESIDUAL_FLOOR,
    RESIDUAL_PER_TOLERANCE,
};
pub use error::{RunError, SimulationFailure};
pub use march::March;
pub use output::Output;
pub use results::{Results, Sample};
pub use run::{simulate, simulate_with_progress};
pub use sink::{
    Background, ColumnSummary, CsvSink, RideFigures, RideIntervalError, RideSink, Select, Sink,
    SinkError, Summary, Tee, Thinned,
};
pub use stream::{RunReport, StreamFailure, simulate_into};
