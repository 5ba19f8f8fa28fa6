//! A sink that keeps one row: the one where a column comes nearest a
//! value (the vehicle at the bump, for `frame.svg`).

use trackgen::simulate::{Results, Sink, SinkError};

/// Keeps the first row at which `column` is nearest `target`; after
/// `finish`, [`results`](Self::results) holds it.
pub struct Nearest {
    column: String,
    target: f64,
    index: usize,
    distance: f64,
    best: Option<(f64, Vec<f64>)>,
    kept: Results,
}

impl Nearest {
    pub fn new(column: &str, target: f64) -> Self {
        Nearest {
            column: column.to_string(),
            target,
            index: 0,
            distance: f64::INFINITY,
            best: None,
            kept: Results::default(),
        }
    }

    /// The row kept: none before `finish`, nor if the column was never
    /// finite.
    pub fn results(&self) -> &Results {
        &self.kept
    }
}

impl Sink for Nearest {
    fn begin(&mut self, columns: &[String]) -> Result<(), SinkError> {
        self.index = columns
            .iter()
            .position(|c| *c == self.column)
            .ok_or_else(|| SinkError::Columns(format!("no column `{}`", self.column)))?;
        self.kept = Results::new(columns.to_vec());
        Ok(())
    }

    fn row(&mut self, t: f64, values: &[f64]) -> Result<(), SinkError> {
        let Some(&v) = values.get(self.index) else {
            return Err(SinkError::Columns(format!("a short row at t = {t} s")));
        };
        let distance = (v - self.target).abs();
        if distance < self.distance {
            self.distance = distance;
            match &mut self.best {
                Some((tb, best)) if best.len() == values.len() => {
                    *tb = t;
                    best.copy_from_slice(values);
                }
                _ => self.best = Some((t, values.to_vec())),
            }
        }
        Ok(())
    }

    fn finish(&mut self) -> Result<(), SinkError> {
        if let Some((t, values)) = self.best.take() {
            self.kept.row(t, &values)?;
        }
        Ok(())
    }
}
