use std::io;
use std::path::Path;

use super::{CsvSink, Select, Sink, SinkError};
use crate::closure::Switch;
use crate::integrate::{Check, Stats};

/// The time series of a run: one row of named quantities per output time,
/// the partition switches, and the integrator's counters. Kept whole when a
/// run fails.
#[derive(Debug, Clone, Default)]
pub struct Results {
    columns: Vec<String>,
    times: Vec<f64>,
    values: Vec<f64>,
    /// Every re-partitioning, in order.
    pub switches: Vec<Switch>,
    /// Integrator counters.
    pub stats: Stats,
    /// The stiffness checks that chose the method, with
    /// [`Integrator::Auto`](crate::integrate::Integrator::Auto).
    pub checks: Vec<Check>,
}

/// One output time of [`Results`].
#[derive(Debug, Clone, Copy)]
pub struct Sample<'a> {
    /// Time, s.
    pub t: f64,
    /// The values, in the order of [`Results::columns`].
    pub values: &'a [f64],
    columns: &'a [String],
}

impl Sample<'_> {
    /// The value of a named column.
    pub fn get(&self, column: &str) -> Option<f64> {
        self.columns
            .iter()
            .position(|c| c == column)
            .map(|i| self.values[i])
    }
}

impl Results {
    /// Empty results with these columns (time excluded).
    pub fn new(columns: Vec<String>) -> Self {
        Results {
            columns,
            ..Default::default()
        }
    }

    pub(crate) fn push(&mut self, t: f64, row: &[f64]) {
        assert_eq!(
            row.len(),
            self.columns.len(),
            "a row has one value per column"
        );
        self.times.push(t);
        self.values.extend_from_slice(row);
    }

    /// Keeps the samples at even positions (0, 2, 4, …).
    pub(crate) fn keep_every_other(&mut self) {
        let w = self.columns.len();
        let kept = self.len().div_ceil(2);
        for k in 1..kept {
            self.times[k] = self.times[2 * k];
            self.values.copy_within(2 * k * w..(2 * k + 1) * w, k * w);
        }
        self.times.truncate(kept);
        self.values.truncate(kept * w);
    }

    /// Column names (time excluded).
    pub fn columns(&self) -> &[String] {
        &self.columns
    }

    /// Output times, s.
    pub fn times(&self) -> &[f64] {
        &self.times
    }

    /// Number of output times.
    pub fn len(&self) -> usize {
        self.times.len()
    }

    /// Whether nothing was output.
    pub fn is_empty(&self) -> bool {
        self.times.is_empty()
    }

    /// Sample `i`, if there is one.
    pub fn get(&self, i: usize) -> Option<Sample<'_>> {
        (i < self.len()).then(|| self.sample(i))
    }

    /// Sample `i`.
    ///
    /// # Panics
    /// If `i` is not below [`len`](Self::len); see [`get`](Self::get).
    pub fn sample(&self, i: usize) -> Sample<'_> {
        let w = self.columns.len();
        Sample {
            t: self.times[i],
            values: &self.values[i * w..(i + 1) * w],
            columns: &self.columns,
        }
    }

    /// The samples in time order.
    pub fn iter(&self) -> impl Iterator<Item = Sample<'_>> + '_ {
        (0..self.len()).map(|i| self.sample(i))
    }

    /// The last sample.
    pub fn last(&self) -> Option<Sample<'_>> {
        self.len().checked_sub(1).map(|i| self.sample(i))
    }

    /// A column's time series.
    pub fn column(&self, name: &str) -> Option<Vec<f64>> {
        let i = self.columns.iter().position(|c| c == name)?;
        let w = self.columns.len();
        Some((0..self.len()).map(|r| self.values[r * w + i]).collect())
    }

    /// Writes CSV: `t`, then every column (the text of a
    /// [`CsvSink`](crate::simulate::CsvSink)).
    pub fn write_csv<W: io::Write>(&self, writer: W) -> Result<(), SinkError> {
        self.write_to(CsvSink::new(writer))
    }

    /// Writes CSV of some columns only (`t` first, then these, in this
    /// order); unknown names are an error.
    pub fn write_csv_columns<W: io::Write>(
        &self,
        writer: W,
        columns: &[&str],
    ) -> Result<(), SinkError> {
        self.write_to(Select::new(columns.iter().copied(), CsvSink::new(writer)))
    }

    /// Gives every sample to `sink`, as a run would: `begin`, the rows,
    /// `finish`. For saving results held in memory in another format:
    /// `results.write_to(trackgen_arrow::ArrowSink::create("run.arrow")?)`.
    pub fn write_to(&self, mut sink: impl Sink) -> Result<(), SinkError> {
        sink.begin(&self.columns)?;
        for s in self.iter() {
            sink.row(s.t, s.values)?;
        }
        sink.finish()
    }

    /// Writes CSV to a file; errors name it.
    pub fn save_csv(&self, path: impl AsRef<Path>) -> Result<(), SinkError> {
        self.write_to(CsvSink::create(path)?)
    }
}

/// The in-memory sink: every row is kept. `begin` on results that hold
/// samples already must name the same columns (the rows are appended).
impl Sink for Results {
    fn begin(&mut self, columns: &[String]) -> Result<(), SinkError> {
        if self.is_empty() {
            self.columns = columns.to_vec();
            Ok(())
        } else if self.columns == columns {
            Ok(())
        } else {
            Err(SinkError::Columns(format!(
                "these results hold {} samples of {} other columns",
                self.len(),
                self.columns.len()
            )))
        }
    }

    fn row(&mut self, t: f64, values: &[f64]) -> Result<(), SinkError> {
        if values.len() != self.columns.len() {
            return Err(SinkError::width(t, values.len(), self.columns.len()));
        }
        self.push(t, values);
        Ok(())
    }

    fn finish(&mut self) -> Result<(), SinkError> {
        Ok(())
    }

    fn switch(&mut self, switch: &Switch) -> Result<(), SinkError> {
        self.switches.push(*switch);
        Ok(())
    }
}
