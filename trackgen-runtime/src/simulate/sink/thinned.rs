//! A bounded, evenly spaced selection of a run's rows, in memory.

use super::{Sink, SinkError};
use crate::simulate::Results;

/// Keeps at most [`capacity`](Self::capacity) rows of a run of any
/// length, evenly spaced: every row until it is full, then every second
/// one (dropping every other row kept so far), then every fourth, and so
/// on. The last row of the run is always kept, so a plot reaches the end.
/// For plots and animations of long runs; peaks between the kept rows do
/// not show (take extremes from a [`Summary`](super::Summary)).
#[derive(Debug, Clone)]
pub struct Thinned {
    results: Results,
    capacity: usize,
    stride: usize,
    seen: usize,
    last: Option<(f64, Vec<f64>)>,
}

impl Thinned {
    /// At most `capacity` rows (at least 2; less is taken as 2).
    pub fn new(capacity: usize) -> Self {
        Thinned {
            results: Results::default(),
            capacity: capacity.max(2),
            stride: 1,
            seen: 0,
            last: None,
        }
    }

    /// The most rows kept.
    pub fn capacity(&self) -> usize {
        self.capacity
    }

    /// Rows kept are every `stride`-th of those received (1, 2, 4, …).
    pub fn stride(&self) -> usize {
        self.stride
    }

    /// The rows kept; the run's last row is among them after
    /// [`finish`](Sink::finish).
    pub fn results(&self) -> &Results {
        &self.results
    }

    /// The rows kept, by value.
    pub fn into_results(self) -> Results {
        self.results
    }
}

impl Sink for Thinned {
    fn begin(&mut self, columns: &[String]) -> Result<(), SinkError> {
        *self = Thinned::new(self.capacity);
        self.results = Results::new(columns.to_vec());
        Ok(())
    }

    fn row(&mut self, t: f64, values: &[f64]) -> Result<(), SinkError> {
        let width = self.results.columns().len();
        if values.len() != width {
            return Err(SinkError::width(t, values.len(), width));
        }
        if self.seen.is_multiple_of(self.stride) {
            self.results.push(t, values);
            self.last = None;
            let len = self.results.len();
            if len >= self.capacity {
                self.results.keep_every_other();
                self.stride *= 2;
                // Kept are the even positions: an odd last one is the
                // latest row, held back for the end.
                if len.is_multiple_of(2) {
                    self.last = Some((t, values.to_vec()));
                }
            }
        } else {
            match &mut self.last {
                Some((tl, vl)) => {
                    *tl = t;
                    vl.copy_from_slice(values);
                }
                None => self.last = Some((t, values.to_vec())),
            }
        }
        self.seen += 1;
        Ok(())
    }

    fn finish(&mut self) -> Result<(), SinkError> {
        if let Some((t, values)) = self.last.take() {
            self.results.push(t, &values);
        }
        Ok(())
    }
}
