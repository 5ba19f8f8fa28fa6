//! Arrow IPC output for trackgen's streamed runs: [`ArrowSink`], a
//! [`Sink`] that writes rows as an Arrow IPC file, a record batch at a
//! time. A crate of its own, so that the runtime builds without arrow.
//!
//! ```no_run
//! # use trackgen_runtime::simulate::{simulate_into, Output};
//! # use trackgen_runtime::integrate::Integrator;
//! # use trackgen_runtime::system::Simulated;
//! # fn demo(system: &mut dyn Simulated) -> Result<(), Box<dyn std::error::Error>> {
//! let mut arrow = trackgen_arrow::ArrowSink::create("run.arrow")?;
//! simulate_into(system, Integrator::dopri5(1e-8), 0.0, 10.0,
//!               Output::Every(0.01), &mut arrow, &mut |_| {})?;
//! # Ok(()) }
//! ```

#![warn(missing_docs)]

use std::fs::File;
use std::io::{self, BufWriter};
use std::path::{Path, PathBuf};
use std::sync::Arc;

use arrow_array::{ArrayRef, Float64Array, RecordBatch};
use arrow_ipc::writer::FileWriter;
use arrow_schema::{DataType, Field, Schema, SchemaRef};

use trackgen_runtime::simulate::{Sink, SinkError};

/// Writes a run as an [Arrow IPC file](https://arrow.apache.org/docs/format/Columnar.html#ipc-file-format)
/// (`.arrow`, also called Feather v2) while it runs: a column `t` (s), then
/// one column per recorded quantity, all non-null `Float64`, in record
/// batches of [`batch_rows`](Self::with_batch_rows) rows (default
/// [`DEFAULT_BATCH_ROWS`](Self::DEFAULT_BATCH_ROWS)). pandas
/// (`read_feather`), polars (`read_ipc`), pyarrow (`ipc.open_file`), DuckDB
/// and R's `arrow` load it directly.
///
/// Holds one batch (`batch_rows × (columns + 1) × 8` bytes) and the
/// footer's index of batches (24 bytes per batch). The file is complete
/// only after [`finish`](Sink::finish), which writes the last, partial
/// batch and the footer; a run calls it also when it stops early.
pub struct ArrowSink<W: io::Write> {
    pending: Option<W>,
    writer: Option<FileWriter<BufWriter<W>>>,
    schema: Option<SchemaRef>,
    path: Option<PathBuf>,
    batch_rows: usize,
    /// `t`, then the values: one vector per column.
    columns: Vec<Vec<f64>>,
    finished: bool,
}

impl<W: io::Write> std::fmt::Debug for ArrowSink<W> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("ArrowSink")
            .field("path", &self.path)
            .field("batch_rows", &self.batch_rows)
            .field("columns", &self.columns.len())
            .field("finished", &self.finished)
            .finish_non_exhaustive()
    }
}

impl<W: io::Write> ArrowSink<W> {
    /// Rows per record batch unless set: 1024 (for the M113's ~180
    /// columns, 1.5 MB held, and a batch on disk every 10 s simulated at
    /// the main job's 0.01 s output interval).
    pub const DEFAULT_BATCH_ROWS: usize = 1024;

    /// A sink writing to `writer` (buffered here: no need for a
    /// `BufWriter`).
    pub fn new(writer: W) -> Self {
        ArrowSink {
            pending: Some(writer),
            writer: None,
            schema: None,
            path: None,
            batch_rows: Self::DEFAULT_BATCH_ROWS,
            columns: Vec::new(),
            finished: false,
        }
    }

    /// Rows per record batch (at least 1; 0 is taken as 1).
    pub fn with_batch_rows(mut self, rows: usize) -> Self {
        self.batch_rows = rows.max(1);
        self
    }

    /// Finishes the file if it is not yet, and returns the writer.
    pub fn into_inner(mut self) -> Result<W, SinkError> {
        self.finish()?;
        if let Some(writer) = self.pending.take() {
            return Ok(writer);
        }
        let path = self.path.clone();
        let Some(writer) = self.writer.take() else {
            // `begin` failed to write the header: the writer went with it.
            return Err(SinkError::io(
                path.as_deref(),
                io::Error::other("the Arrow header could not be written; the writer is gone"),
            ));
        };
        let buffered = writer
            .into_inner()
            .map_err(|e| arrow_error(path.as_deref(), e))?;
        buffered
            .into_inner()
            .map_err(|e| SinkError::io(path.as_deref(), e.into_error()))
    }

    /// Writes the rows held as one record batch.
    fn flush_batch(&mut self) -> Result<(), SinkError> {
        let (Some(writer), Some(schema)) = (self.writer.as_mut(), self.schema.as_ref()) else {
            return Ok(());
        };
        if self.columns.first().is_none_or(Vec::is_empty) {
            return Ok(());
        }
        let path = self.path.as_deref();
        let arrays: Vec<ArrayRef> = self
            .columns
            .iter_mut()
            .map(|c| {
                let full = std::mem::replace(c, Vec::with_capacity(self.batch_rows));
                Arc::new(Float64Array::from(full)) as ArrayRef
            })
            .collect();
        let batch =
            RecordBatch::try_new(schema.clone(), arrays).map_err(|e| arrow_error(path, e))?;
        writer.write(&batch).map_err(|e| arrow_error(path, e))
    }
}

/// An Arrow error as a sink's: its I/O errors stay [`SinkError::Io`].
fn arrow_error(path: Option<&Path>, error: arrow_schema::ArrowError) -> SinkError {
    match error {
        arrow_schema::ArrowError::IoError(_, source) => SinkError::io(path, source),
        other => SinkError::Format {
            path: path.map(Path::to_path_buf),
            source: Box::new(other),
        },
    }
}

impl ArrowSink<File> {
    /// A sink writing to a new file at `path` (an existing one is
    /// truncated). Errors name the file.
    pub fn create(path: impl AsRef<Path>) -> Result<Self, SinkError> {
        let path = path.as_ref();
        let file = File::create(path).map_err(|e| SinkError::io(Some(path), e))?;
        let mut sink = ArrowSink::new(file);
        sink.path = Some(path.to_path_buf());
        Ok(sink)
    }
}

impl<W: io::Write> Sink for ArrowSink<W> {
    fn begin(&mut self, columns: &[String]) -> Result<(), SinkError> {
        let Some(writer) = self.pending.take() else {
            return Err(SinkError::Columns(
                "an Arrow sink takes one run: `begin` called twice".to_string(),
            ));
        };
        let fields: Vec<Field> = std::iter::once("t")
            .chain(columns.iter().map(String::as_str))
            .map(|name| Field::new(name, DataType::Float64, false))
            .collect();
        let schema = Arc::new(Schema::new(fields));
        let path = self.path.as_deref();
        let writer =
            FileWriter::try_new_buffered(writer, &schema).map_err(|e| arrow_error(path, e))?;
        self.columns = vec![Vec::with_capacity(self.batch_rows); columns.len() + 1];
        self.writer = Some(writer);
        self.schema = Some(schema);
        Ok(())
    }

    fn row(&mut self, t: f64, values: &[f64]) -> Result<(), SinkError> {
        let width = self.columns.len().saturating_sub(1);
        if self.writer.is_none() || values.len() != width {
            return Err(SinkError::width(t, values.len(), width));
        }
        for (column, v) in self
            .columns
            .iter_mut()
            .zip(std::iter::once(t).chain(values.iter().copied()))
        {
            column.push(v);
        }
        if self.columns[0].len() >= self.batch_rows {
            self.flush_batch()?;
        }
        Ok(())
    }

    fn finish(&mut self) -> Result<(), SinkError> {
        if self.finished || self.writer.is_none() {
            return Ok(());
        }
        self.flush_batch()?;
        let path = self.path.as_deref();
        if let Some(writer) = self.writer.as_mut() {
            writer.finish().map_err(|e| arrow_error(path, e))?;
        }
        self.finished = true;
        Ok(())
    }
}
