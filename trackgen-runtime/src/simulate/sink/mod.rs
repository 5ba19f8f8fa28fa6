//! Where a run's samples go: a [`Sink`] takes the column names once, then
//! one row per output time as the run produces it, then a
//! [`finish`](Sink::finish) that writes out anything buffered.
//!
//! [`Results`](super::Results) is the in-memory sink. The others hold a
//! bounded amount of memory whatever the length of the run:
//!
//! * [`CsvSink`]: CSV, the same text as [`Results::write_csv`](super::Results::write_csv).
//! * `trackgen_arrow::ArrowSink` (the crate trackgen-arrow): an Arrow IPC
//!   file (`.arrow`), which pandas, polars, pyarrow, DuckDB and R's
//!   `arrow` load directly, in record batches of a bounded number of rows.
//! * [`Summary`]: first, last, smallest and largest value of every column.
//! * [`RideSink`]: the ride at the driver's seat (absorbed power, ISO
//!   2631-1 weighted RMS, peak vertical acceleration) as the rows arrive.
//! * [`Thinned`]: at most a given number of rows, evenly spaced in time
//!   (for plots of long runs).
//! * [`Select`]: some columns only, passed on to another sink.
//! * [`Tee`]: one run feeding several sinks.
//! * [`Background`]: another sink, on its own thread, so writing overlaps
//!   the run.

mod background;
mod csv_sink;
mod ride;
mod select;
mod summary;
mod tee;
mod thinned;

use std::path::{Path, PathBuf};

pub use background::Background;
pub use csv_sink::CsvSink;
pub use ride::{RideFigures, RideIntervalError, RideSink};
pub use select::Select;
pub use summary::{ColumnSummary, Summary};
pub use tee::Tee;
pub use thinned::Thinned;

use thiserror::Error;

use crate::closure::Switch;

/// A receiver of a run's samples, row by row.
///
/// A run calls [`begin`](Sink::begin) once, then [`row`](Sink::row) for
/// every sample in time order, then [`finish`](Sink::finish) once, also
/// when it stops early (so the rows before a failure are written out). An
/// error from `begin` or `row` stops the run.
pub trait Sink {
    /// The names of the recorded quantities, time excluded; every row has
    /// one value per name, in this order.
    fn begin(&mut self, columns: &[String]) -> Result<(), SinkError>;

    /// One sample: the time `t` (s) and the values.
    fn row(&mut self, t: f64, values: &[f64]) -> Result<(), SinkError>;

    /// The end of the run: writes out whatever is buffered.
    fn finish(&mut self) -> Result<(), SinkError>;

    /// The columns this sink reads, as indices into the names `begin`
    /// gave it, once `begin` has run; `None`, the default, reads every
    /// one. A run whose sink reads only some may leave the others
    /// unobserved (NaN in the row): a system need not compute what no one
    /// reads ([`Simulated::observe_some`](crate::system::Simulated::observe_some)).
    fn reads(&self) -> Option<Vec<usize>> {
        None
    }

    /// A re-partitioning of a track (formulation §2), as it happens. Sinks of
    /// rows ignore it; [`Results`](crate::simulate::Results) keeps every
    /// one.
    fn switch(&mut self, switch: &Switch) -> Result<(), SinkError> {
        let _ = switch;
        Ok(())
    }
}

impl<S: Sink + ?Sized> Sink for &mut S {
    fn begin(&mut self, columns: &[String]) -> Result<(), SinkError> {
        (**self).begin(columns)
    }

    fn row(&mut self, t: f64, values: &[f64]) -> Result<(), SinkError> {
        (**self).row(t, values)
    }

    fn finish(&mut self) -> Result<(), SinkError> {
        (**self).finish()
    }

    fn reads(&self) -> Option<Vec<usize>> {
        (**self).reads()
    }

    fn switch(&mut self, switch: &Switch) -> Result<(), SinkError> {
        (**self).switch(switch)
    }
}

impl<S: Sink + ?Sized> Sink for Box<S> {
    fn begin(&mut self, columns: &[String]) -> Result<(), SinkError> {
        (**self).begin(columns)
    }

    fn row(&mut self, t: f64, values: &[f64]) -> Result<(), SinkError> {
        (**self).row(t, values)
    }

    fn finish(&mut self) -> Result<(), SinkError> {
        (**self).finish()
    }

    fn reads(&self) -> Option<Vec<usize>> {
        (**self).reads()
    }

    fn switch(&mut self, switch: &Switch) -> Result<(), SinkError> {
        (**self).switch(switch)
    }
}

/// Why a sink could not take the results.
#[derive(Debug, Error)]
pub enum SinkError {
    /// Writing failed (a full disk, a closed pipe, a missing folder).
    #[error("writing {}: {source}", describe(path))]
    Io {
        /// The file, when the sink was made from a path.
        path: Option<PathBuf>,
        /// The failure.
        source: std::io::Error,
    },
    /// The output format refused the data.
    #[error("encoding {}: {source}", describe(path))]
    Format {
        /// The file, when the sink was made from a path.
        path: Option<PathBuf>,
        /// The encoder's error.
        source: Box<dyn std::error::Error + Send + Sync>,
    },
    /// The rows do not fit the sink: an unknown column name, a row of the
    /// wrong length, `begin` called twice with different columns.
    #[error("{0}")]
    Columns(String),
    /// Not a failure: the sink has what it was run for (a ride measured
    /// over its stretch, a vehicle past its goal), and the run ends at
    /// this row ([`simulate_into`](super::simulate_into) returns the run's
    /// report, [`RunReport::ended_early`](super::RunReport::ended_early)
    /// set).
    #[error("the sink asked the run to end")]
    Done,
}

fn describe(path: &Option<PathBuf>) -> String {
    match path {
        Some(p) => p.display().to_string(),
        None => "the results".to_string(),
    }
}

impl SinkError {
    /// An I/O error, with the file it concerns if known.
    pub fn io(path: Option<&Path>, source: std::io::Error) -> SinkError {
        SinkError::Io {
            path: path.map(Path::to_path_buf),
            source,
        }
    }

    /// A CSV error: its I/O errors stay [`SinkError::Io`].
    pub(crate) fn csv(path: Option<&Path>, error: csv::Error) -> SinkError {
        if !error.is_io_error() {
            return SinkError::Format {
                path: path.map(Path::to_path_buf),
                source: Box::new(error),
            };
        }
        match error.into_kind() {
            csv::ErrorKind::Io(source) => SinkError::io(path, source),
            // `is_io_error` means `Io`; any other kind still says what it is.
            other => SinkError::Format {
                path: path.map(Path::to_path_buf),
                source: format!("{other:?}").into(),
            },
        }
    }

    /// A row whose length is not the number of columns.
    pub fn width(t: f64, got: usize, want: usize) -> SinkError {
        SinkError::Columns(format!(
            "a row of {got} values at t = {t} s for {want} columns"
        ))
    }
}
