//! Running figures of every column, without keeping the rows.

use super::{Sink, SinkError};

/// First, last, smallest and largest value of one column over a run.
///
/// A NaN anywhere in the column makes `min` and `max` NaN (a plain
/// `f64::max` would drop it and hide the failure).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ColumnSummary {
    /// The value in the first row.
    pub first: f64,
    /// The value in the last row.
    pub last: f64,
    /// The smallest value.
    pub min: f64,
    /// The largest value.
    pub max: f64,
}

impl ColumnSummary {
    /// The largest magnitude, `max(|min|, |max|)`; NaN if any value was.
    pub fn max_abs(&self) -> f64 {
        if self.min.is_nan() || self.max.is_nan() {
            f64::NAN
        } else {
            self.min.abs().max(self.max.abs())
        }
    }

    /// `last − first`.
    pub fn change(&self) -> f64 {
        self.last - self.first
    }

    fn start(v: f64) -> Self {
        ColumnSummary {
            first: v,
            last: v,
            min: v,
            max: v,
        }
    }

    fn add(&mut self, v: f64) {
        self.last = v;
        if v.is_nan() || self.min.is_nan() {
            self.min = f64::NAN;
            self.max = f64::NAN;
        } else {
            self.min = self.min.min(v);
            self.max = self.max.max(v);
        }
    }
}

/// A [`ColumnSummary`] of every column, kept up to date row by row: memory
/// in proportion to the number of columns, not of rows. For the figures a
/// report prints at the end of a run that is streamed to files.
#[derive(Debug, Clone, Default)]
pub struct Summary {
    columns: Vec<String>,
    values: Vec<ColumnSummary>,
    time: Option<ColumnSummary>,
    rows: usize,
}

impl Summary {
    /// Nothing seen yet.
    pub fn new() -> Self {
        Summary::default()
    }

    /// The column names (time excluded).
    pub fn columns(&self) -> &[String] {
        &self.columns
    }

    /// Number of rows seen.
    pub fn rows(&self) -> usize {
        self.rows
    }

    /// The time column: first and last time are the run's span, s.
    /// `None` before the first row.
    pub fn time(&self) -> Option<ColumnSummary> {
        self.time
    }

    /// The figures of a named column; `None` for an unknown name or before
    /// the first row.
    pub fn get(&self, column: &str) -> Option<ColumnSummary> {
        let i = self.columns.iter().position(|c| c == column)?;
        self.values.get(i).copied()
    }
}

impl Sink for Summary {
    fn begin(&mut self, columns: &[String]) -> Result<(), SinkError> {
        *self = Summary {
            columns: columns.to_vec(),
            ..Summary::default()
        };
        Ok(())
    }

    fn row(&mut self, t: f64, values: &[f64]) -> Result<(), SinkError> {
        if values.len() != self.columns.len() {
            return Err(SinkError::width(t, values.len(), self.columns.len()));
        }
        match &mut self.time {
            None => {
                self.time = Some(ColumnSummary::start(t));
                self.values = values.iter().map(|&v| ColumnSummary::start(v)).collect();
            }
            Some(time) => {
                time.add(t);
                for (s, &v) in self.values.iter_mut().zip(values) {
                    s.add(v);
                }
            }
        }
        self.rows += 1;
        Ok(())
    }

    fn finish(&mut self) -> Result<(), SinkError> {
        Ok(())
    }
}
