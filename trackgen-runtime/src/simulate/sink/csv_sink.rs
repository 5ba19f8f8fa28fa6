//! Rows written as CSV as they come.

use std::fs::File;
use std::io;
use std::path::{Path, PathBuf};

use super::{Sink, SinkError};

/// Writes a run as CSV while it runs: a header `t,<columns>`, then one line
/// per sample, every number in its shortest round-trip form (by `ryu`:
/// `1.0`, `0.154`, `1e-7`, `NaN`; what any CSV reader parses back to the
/// same `f64`), the text of
/// [`Results::write_csv`](crate::simulate::Results::write_csv). Holds the
/// `csv` writer's buffer (8 KiB), whatever the length of the run;
/// [`finish`](Sink::finish) flushes.
pub struct CsvSink<W: io::Write> {
    writer: csv::Writer<W>,
    path: Option<PathBuf>,
    width: Option<usize>,
    number: ryu::Buffer,
}

impl<W: io::Write> std::fmt::Debug for CsvSink<W> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("CsvSink")
            .field("path", &self.path)
            .field("width", &self.width)
            .finish_non_exhaustive()
    }
}

impl<W: io::Write> CsvSink<W> {
    /// A sink writing to `writer` (buffered here: no need for a
    /// `BufWriter`).
    pub fn new(writer: W) -> Self {
        CsvSink {
            writer: csv::Writer::from_writer(writer),
            path: None,
            width: None,
            number: ryu::Buffer::new(),
        }
    }

    /// Flushes and returns the writer.
    pub fn into_inner(self) -> Result<W, SinkError> {
        let path = self.path;
        self.writer
            .into_inner()
            .map_err(|e| SinkError::io(path.as_deref(), e.into_error()))
    }

    fn err(&self) -> impl Fn(csv::Error) -> SinkError + '_ {
        |e| SinkError::csv(self.path.as_deref(), e)
    }
}

impl CsvSink<File> {
    /// A sink writing to a new file at `path` (an existing one is
    /// truncated). Errors name the file.
    pub fn create(path: impl AsRef<Path>) -> Result<Self, SinkError> {
        let path = path.as_ref();
        let file = File::create(path).map_err(|e| SinkError::io(Some(path), e))?;
        let mut sink = CsvSink::new(file);
        sink.path = Some(path.to_path_buf());
        Ok(sink)
    }
}

impl<W: io::Write> Sink for CsvSink<W> {
    fn begin(&mut self, columns: &[String]) -> Result<(), SinkError> {
        if self.width.is_some() {
            return Err(SinkError::Columns(
                "a CSV sink takes one run: `begin` called twice".to_string(),
            ));
        }
        self.width = Some(columns.len());
        let header = std::iter::once("t").chain(columns.iter().map(String::as_str));
        let result = self.writer.write_record(header);
        result.map_err(self.err())
    }

    fn row(&mut self, t: f64, values: &[f64]) -> Result<(), SinkError> {
        let width = self.width.unwrap_or(0);
        if values.len() != width {
            return Err(SinkError::width(t, values.len(), width));
        }
        for v in std::iter::once(t).chain(values.iter().copied()) {
            let result = self.writer.write_field(self.number.format(v));
            result.map_err(|e| SinkError::csv(self.path.as_deref(), e))?;
        }
        let result = self.writer.write_record(None::<&[u8]>);
        result.map_err(self.err())
    }

    fn finish(&mut self) -> Result<(), SinkError> {
        let path = self.path.as_deref();
        self.writer.flush().map_err(|e| SinkError::io(path, e))
    }
}
