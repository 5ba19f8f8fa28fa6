//! A sink on its own thread: formatting and writing files off the
//! integrator's.

use std::sync::mpsc::{Receiver, SyncSender, sync_channel};
use std::thread::{Scope, ScopedJoinHandle};

use super::{Sink, SinkError};
use crate::closure::Switch;

/// Rows handed over together: waking the worker for every row cost the
/// run's thread more than the rows' copying (a twentieth of the M113's
/// main job, in the kernel's wake-ups).
const BATCH_ROWS: usize = 16;

/// Batches handed over but not yet taken: 256 rows, enough that the run
/// never waits on a sink that keeps up, few enough that memory stays
/// bounded (a row of the M113's ~300 columns is 2.4 kB) when one does not.
const BATCHES_IN_FLIGHT: usize = 16;

/// What the run hands the worker, in order.
enum Message {
    Begin(Vec<String>),
    /// Rows: their times, and their values one after another.
    Rows(Vec<f64>, Vec<f64>),
    Switch(Switch),
}

/// Runs a sink on a thread of `scope`, so that formatting numbers and
/// writing files overlap the integration instead of following every
/// output step (in the main job, CSV and Arrow writing was a twentieth of
/// the run). The sink is made on that thread by the closure given to
/// [`spawn`](Self::spawn), which may borrow sinks the caller reads after
/// the scope ends:
///
/// ```no_run
/// # use trackgen_runtime::simulate::{Background, CsvSink, Summary, Tee, Sink};
/// # fn main() -> Result<(), Box<dyn std::error::Error>> {
/// let mut csv = CsvSink::create("run.csv")?;
/// let mut summary = Summary::new();
/// std::thread::scope(|scope| {
///     let mut sink = Background::spawn(scope, || Tee::new().and(&mut csv).and(&mut summary));
///     // simulate_into(&mut system, integrator, t0, t1, output, &mut sink, &mut |_| {})
///     # sink.begin(&["x".to_string()])?; sink.row(0.0, &[1.0])?; sink.finish()
/// })?;
/// println!("{:?}", summary.get("x"));
/// # Ok(())
/// # }
/// ```
///
/// Rows are copied and queued in batches of 16 (at most 256 rows in flight
/// and a batch being filled; the run waits when the sink falls that far
/// behind). The sink's errors keep their meaning
/// with a delay: the worker stops at its first error and finishes its
/// sink, so the rows before it are written out; the run learns of it at
/// its next `row` (which fails with that error and so stops the run) or at
/// [`finish`](Sink::finish), which waits for the worker to write
/// everything. A panic of the sink is resumed on the run's thread.
pub struct Background<'scope> {
    /// `None` once the worker has been joined.
    running: Option<Running<'scope>>,
    /// The batch being filled: times, and values row after row.
    times: Vec<f64>,
    values: Vec<f64>,
}

struct Running<'scope> {
    sender: SyncSender<Message>,
    worker: ScopedJoinHandle<'scope, Result<(), SinkError>>,
}

impl std::fmt::Debug for Background<'_> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Background")
            .field("running", &self.running.is_some())
            .finish()
    }
}

impl<'scope> Background<'scope> {
    /// Starts a thread in `scope` that makes its sink with `make` and feeds
    /// it what this sink is fed.
    pub fn spawn<'env, S, F>(scope: &'scope Scope<'scope, 'env>, make: F) -> Self
    where
        F: FnOnce() -> S + Send + 'scope,
        S: Sink,
    {
        let (sender, receiver) = sync_channel(BATCHES_IN_FLIGHT);
        let worker = scope.spawn(move || work(make(), receiver));
        Background {
            running: Some(Running { sender, worker }),
            times: Vec::with_capacity(BATCH_ROWS),
            values: Vec::new(),
        }
    }

    /// Hands over the rows gathered so far, if any.
    fn flush(&mut self) -> Result<(), SinkError> {
        if self.times.is_empty() {
            return Ok(());
        }
        let times = std::mem::replace(&mut self.times, Vec::with_capacity(BATCH_ROWS));
        let capacity = self.values.len();
        let values = std::mem::replace(&mut self.values, Vec::with_capacity(capacity));
        self.send(Message::Rows(times, values))
    }

    /// Hands `message` to the worker; if it has stopped, its error.
    fn send(&mut self, message: Message) -> Result<(), SinkError> {
        let Some(running) = &self.running else {
            return Err(stopped());
        };
        if running.sender.send(message).is_ok() {
            return Ok(());
        }
        // The worker dropped its end: it has stopped, on an error.
        self.join().and(Err(stopped()))
    }

    /// Closes the queue, waits for the worker, and returns its outcome.
    fn join(&mut self) -> Result<(), SinkError> {
        let Some(Running { sender, worker }) = self.running.take() else {
            return Ok(());
        };
        drop(sender);
        match worker.join() {
            Ok(outcome) => outcome,
            Err(panic) => std::panic::resume_unwind(panic),
        }
    }
}

/// The worker: every message into `sink` until the queue closes or the sink
/// fails, then `finish`; the first error.
fn work<S: Sink>(mut sink: S, receiver: Receiver<Message>) -> Result<(), SinkError> {
    let mut outcome = Ok(());
    for message in receiver {
        outcome = match message {
            Message::Begin(columns) => sink.begin(&columns),
            Message::Rows(times, values) => {
                // A batch's rows are of one width (see `row`).
                let width = values.len() / times.len().max(1);
                times
                    .iter()
                    .enumerate()
                    .try_for_each(|(k, &t)| sink.row(t, &values[k * width..(k + 1) * width]))
            }
            Message::Switch(switch) => sink.switch(&switch),
        };
        if outcome.is_err() {
            break;
        }
    }
    let finished = sink.finish();
    outcome.and(finished)
}

/// What a sink says once its worker has stopped without an error to give
/// (it was already reported).
fn stopped() -> SinkError {
    SinkError::Columns("the background sink has already stopped".to_string())
}

impl Sink for Background<'_> {
    fn begin(&mut self, columns: &[String]) -> Result<(), SinkError> {
        self.send(Message::Begin(columns.to_vec()))
    }

    fn row(&mut self, t: f64, values: &[f64]) -> Result<(), SinkError> {
        if self.running.is_none() {
            return Err(stopped());
        }
        // Rows of unequal widths go in batches of their own, so the worker
        // can split them (and its sink refuses them as it would directly).
        if !self.times.is_empty() && self.values.len() != self.times.len() * values.len() {
            self.flush()?;
        }
        self.times.push(t);
        self.values.extend_from_slice(values);
        if self.times.len() == BATCH_ROWS {
            self.flush()?;
        }
        Ok(())
    }

    fn switch(&mut self, switch: &Switch) -> Result<(), SinkError> {
        self.flush()?;
        self.send(Message::Switch(*switch))
    }

    /// Waits for the worker to write every row and finish its sink.
    fn finish(&mut self) -> Result<(), SinkError> {
        let flushed = self.flush();
        let joined = self.join();
        match flushed {
            // A failed hand-over already joined and reported the worker.
            Err(e) => Err(e),
            Ok(()) => joined,
        }
    }
}

impl Drop for Background<'_> {
    /// A sink dropped unfinished hands over its last rows and closes its
    /// queue, so the scope's join does not wait forever; the worker still
    /// finishes its sink, but the outcome is lost.
    fn drop(&mut self) {
        let _ = self.flush();
        if let Some(Running { sender, .. }) = self.running.take() {
            drop(sender);
        }
    }
}
