//! One run, several sinks.

use super::{Sink, SinkError};
use crate::closure::Switch;

/// Feeds every row to each of its sinks, in the order they were added:
/// `Tee::new().and(&mut csv).and(&mut arrow).and(&mut summary)`. The first
/// error of `begin` or `row` stops there (and so stops the run);
/// [`finish`](Sink::finish) finishes every sink, so the others are written
/// out, and returns the first error.
#[derive(Default)]
pub struct Tee<'a> {
    sinks: Vec<Box<dyn Sink + 'a>>,
}

impl std::fmt::Debug for Tee<'_> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Tee")
            .field("sinks", &self.sinks.len())
            .finish()
    }
}

impl<'a> Tee<'a> {
    /// No sinks yet.
    pub fn new() -> Self {
        Tee::default()
    }

    /// Adds a sink (by value, or `&mut sink` to keep it).
    pub fn and(mut self, sink: impl Sink + 'a) -> Self {
        self.push(sink);
        self
    }

    /// Adds a sink.
    pub fn push(&mut self, sink: impl Sink + 'a) {
        self.sinks.push(Box::new(sink));
    }

    /// Number of sinks.
    pub fn len(&self) -> usize {
        self.sinks.len()
    }

    /// Whether there are none.
    pub fn is_empty(&self) -> bool {
        self.sinks.is_empty()
    }
}

impl Sink for Tee<'_> {
    fn begin(&mut self, columns: &[String]) -> Result<(), SinkError> {
        self.sinks.iter_mut().try_for_each(|s| s.begin(columns))
    }

    fn row(&mut self, t: f64, values: &[f64]) -> Result<(), SinkError> {
        self.sinks.iter_mut().try_for_each(|s| s.row(t, values))
    }

    fn switch(&mut self, switch: &Switch) -> Result<(), SinkError> {
        self.sinks.iter_mut().try_for_each(|s| s.switch(switch))
    }

    /// What any of its sinks reads; every column if one reads every one.
    fn reads(&self) -> Option<Vec<usize>> {
        let mut all = Vec::new();
        for sink in &self.sinks {
            all.extend(sink.reads()?);
        }
        all.sort_unstable();
        all.dedup();
        Some(all)
    }

    fn finish(&mut self) -> Result<(), SinkError> {
        let mut first = Ok(());
        for s in &mut self.sinks {
            let result = s.finish();
            if first.is_ok() {
                first = result;
            }
        }
        first
    }
}
