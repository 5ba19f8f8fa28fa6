/// When a simulation records a sample.
#[derive(Debug, Clone, PartialEq)]
pub enum Output {
    /// At `t0, t0 + dt, t0 + 2 dt, …` up to the end (s), by dense output.
    Every(f64),
    /// At the given times (s, increasing), by dense output.
    Times(Vec<f64>),
    /// At the start and after every accepted step.
    Steps,
}

impl Output {
    /// The `i`-th dense-output time, for a run starting at `t0`; `None`
    /// past the last (and always for [`Output::Steps`]).
    pub(crate) fn time(&self, t0: f64, i: usize) -> Option<f64> {
        match self {
            Output::Every(dt) => Some(t0 + i as f64 * dt),
            Output::Times(times) => times.get(i).copied(),
            Output::Steps => None,
        }
    }
}
