//! Runs whose samples go to a [`Sink`] as they are produced.

use std::fmt;

use super::run::drive;
use super::{Output, RunError, Sink, SinkError};
use crate::closure::Switch;
use crate::integrate::{Check, Integrator, Stats};
use crate::system::Simulated;

/// What a streamed run did, besides its rows: how many it gave the sink,
/// how many partition switches it made and the integrator's counters. The
/// switches themselves went to the sink as they happened
/// ([`Sink::switch`]), so a run's memory stays bounded however long it is.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct RunReport {
    /// Rows given to the sink.
    pub rows: usize,
    /// The time of the last row, s (`None` when there was none).
    pub last_time: Option<f64>,
    /// Re-partitionings made (each given to the sink).
    pub switches: usize,
    /// Integrator counters.
    pub stats: Stats,
    /// The stiffness checks that chose the method, with
    /// [`Integrator::Auto`](crate::integrate::Integrator::Auto).
    pub checks: Vec<Check>,
    /// The sink ended the run before its end time
    /// ([`SinkError::Done`]): `last_time` is when.
    pub ended_early: bool,
}

/// A streamed run that stopped early. The sink was finished: every row
/// before the failure is in it, unless [`finish`](Self::finish) says
/// otherwise.
#[derive(Debug)]
pub struct StreamFailure {
    /// Why the run stopped.
    pub error: RunError,
    /// What it did until then.
    pub report: RunReport,
    /// Finishing the sink after the failure failed too: its output may
    /// lack rows (for an Arrow file, the footer).
    pub finish: Option<SinkError>,
}

impl fmt::Display for StreamFailure {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{} ({} rows written", self.error, self.report.rows)?;
        if let Some(t) = self.report.last_time {
            write!(f, ", up to t = {t} s")?;
        }
        write!(f, ")")?;
        if let Some(e) = &self.finish {
            write!(f, "; then finishing the output failed: {e}")?;
        }
        Ok(())
    }
}

impl std::error::Error for StreamFailure {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        Some(&self.error)
    }
}

/// Integrates `system` from `t0` to `t_end` (s), giving `sink` a row at
/// every output time as the run goes: memory does not grow with the length
/// of the run (beyond what the sink keeps). `progress(t)` is called after
/// every accepted step (for a progress bar; `&mut |_| {}` for none).
///
/// The sink is finished in every case, so on failure the rows before it
/// are written out; the error carries the time and the cause. A sink's
/// error stops the run; [`SinkError::Done`] stops it as a success (the
/// report's `ended_early`).
///
/// ```no_run
/// # use trackgen_runtime::simulate::*;
/// # use trackgen_runtime::integrate::Integrator;
/// # use trackgen_runtime::system::Simulated;
/// # fn demo(system: &mut dyn Simulated) -> Result<(), Box<dyn std::error::Error>> {
/// let mut csv = CsvSink::create("run.csv")?;
/// let mut summary = Summary::new();
/// let mut sinks = Tee::new().and(&mut csv).and(&mut summary);
/// let report = simulate_into(system, Integrator::dopri5(1e-8), 0.0, 3600.0,
///                            Output::Every(0.01), &mut sinks, &mut |_| {})?;
/// drop(sinks);
/// println!("{} rows; max |C| {:e} m", report.rows, summary.get("closure_error").unwrap().max);
/// # Ok(()) }
/// ```
// The failure carries the report by design; it is the rare path.
#[allow(clippy::result_large_err)]
pub fn simulate_into(
    system: &mut dyn Simulated,
    integrator: Integrator,
    t0: f64,
    t_end: f64,
    output: Output,
    sink: &mut dyn Sink,
    progress: &mut dyn FnMut(f64),
) -> Result<RunReport, StreamFailure> {
    let mut counted = Counted {
        inner: sink,
        rows: 0,
        last_time: None,
        switches: 0,
    };
    let (outcome, stats, checks) = drive(
        system,
        integrator,
        t0,
        t_end,
        &output,
        &mut counted,
        progress,
    );
    let finished = counted.inner.finish();
    let ended_early = matches!(
        outcome,
        Err(RunError::Sink {
            source: SinkError::Done,
            ..
        })
    );
    let outcome = if ended_early { Ok(()) } else { outcome };
    let report = RunReport {
        rows: counted.rows,
        last_time: counted.last_time,
        switches: counted.switches,
        stats,
        checks,
        ended_early,
    };
    match (outcome, finished) {
        (Ok(()), Ok(())) => Ok(report),
        (Ok(()), Err(source)) => Err(StreamFailure {
            error: RunError::Sink {
                t: report.last_time.unwrap_or(t0),
                source,
            },
            report,
            finish: None,
        }),
        (Err(error), finished) => Err(StreamFailure {
            error,
            report,
            finish: finished.err(),
        }),
    }
}

/// Counts the rows on their way to the sink.
struct Counted<'a> {
    inner: &'a mut dyn Sink,
    rows: usize,
    last_time: Option<f64>,
    switches: usize,
}

impl Sink for Counted<'_> {
    fn begin(&mut self, columns: &[String]) -> Result<(), SinkError> {
        self.inner.begin(columns)
    }

    fn row(&mut self, t: f64, values: &[f64]) -> Result<(), SinkError> {
        let taken = self.inner.row(t, values);
        // A sink that ends the run has taken its last row.
        if matches!(taken, Ok(()) | Err(SinkError::Done)) {
            self.rows += 1;
            self.last_time = Some(t);
        }
        taken
    }

    fn finish(&mut self) -> Result<(), SinkError> {
        self.inner.finish()
    }

    fn reads(&self) -> Option<Vec<usize>> {
        self.inner.reads()
    }

    fn switch(&mut self, switch: &Switch) -> Result<(), SinkError> {
        self.inner.switch(switch)?;
        self.switches += 1;
        Ok(())
    }
}
