//! Some columns of a run, passed on to another sink.

use super::{Sink, SinkError};

/// Passes on the columns it names, in its order, to the sink it wraps:
/// `Select::new(["x", "speed"], CsvSink::create("short.csv")?)` writes
/// `t,x,speed`. A name the run does not record is an error at
/// [`begin`](Sink::begin), before any row.
#[derive(Debug)]
pub struct Select<S> {
    names: Vec<String>,
    indices: Vec<usize>,
    width: usize,
    buffer: Vec<f64>,
    inner: S,
}

impl<S: Sink> Select<S> {
    /// The columns `names` of every row, given to `inner`.
    pub fn new<I>(names: I, inner: S) -> Self
    where
        I: IntoIterator,
        I::Item: Into<String>,
    {
        Select {
            names: names.into_iter().map(Into::into).collect(),
            indices: Vec::new(),
            width: 0,
            buffer: Vec::new(),
            inner,
        }
    }

    /// The names passed on.
    pub fn names(&self) -> &[String] {
        &self.names
    }

    /// The wrapped sink.
    pub fn inner(&self) -> &S {
        &self.inner
    }

    /// The wrapped sink, by value.
    pub fn into_inner(self) -> S {
        self.inner
    }
}

impl<S: Sink> Sink for Select<S> {
    fn begin(&mut self, columns: &[String]) -> Result<(), SinkError> {
        self.indices = self
            .names
            .iter()
            .map(|name| {
                columns.iter().position(|c| c == name).ok_or_else(|| {
                    SinkError::Columns(format!(
                        "no column `{name}` among the {} recorded",
                        columns.len()
                    ))
                })
            })
            .collect::<Result<_, _>>()?;
        self.width = columns.len();
        self.buffer = vec![0.0; self.names.len()];
        self.inner.begin(&self.names)
    }

    fn row(&mut self, t: f64, values: &[f64]) -> Result<(), SinkError> {
        if values.len() != self.width {
            return Err(SinkError::width(t, values.len(), self.width));
        }
        for (b, &i) in self.buffer.iter_mut().zip(&self.indices) {
            *b = values[i];
        }
        self.inner.row(t, &self.buffer)
    }

    fn finish(&mut self) -> Result<(), SinkError> {
        self.inner.finish()
    }
}
