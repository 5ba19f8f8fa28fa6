//! The system the sinks' tests stream: a harmonic oscillator
//! (`ẍ = −ω² x`, ω = 2π rad/s) recording `x`, `v` and its energy,
//! integrated by RK4 at a fixed 1 ms step, so two runs with the same
//! settings produce the same bits. A variant's derivative turns NaN after
//! `fail_at`: RK4 stops at the first stage past it. Shared by
//! `tests/sinks.rs` and trackgen-arrow's tests (which include this file).
#![allow(dead_code, clippy::result_large_err)]

use std::path::PathBuf;

use nalgebra::DVector;
use trackgen_runtime::integrate::{Integrator, OdeSystem, SimulationError};
use trackgen_runtime::simulate::{
    Output, Results, RunReport, Sink, StreamFailure, simulate, simulate_into,
};
use trackgen_runtime::system::Simulated;

/// Its angular frequency, rad/s.
pub const OMEGA: f64 = 2.0 * std::f64::consts::PI;
/// RK4's step, s.
pub const STEP: f64 = 1e-3;
/// The output interval, s.
pub const INTERVAL: f64 = 0.01;

pub struct Oscillator {
    /// When its derivative turns NaN, s.
    pub fail_at: Option<f64>,
}

impl OdeSystem for Oscillator {
    fn dimension(&self) -> usize {
        2
    }

    fn derivative(&mut self, t: f64, y: &[f64], dy: &mut [f64]) -> Result<(), SimulationError> {
        let load = match self.fail_at {
            Some(at) if t > at => f64::NAN,
            _ => 0.0,
        };
        dy[0] = y[1];
        dy[1] = -OMEGA * OMEGA * y[0] + load;
        Ok(())
    }
}

impl Simulated for Oscillator {
    fn initial_state(&self) -> DVector<f64> {
        DVector::from_column_slice(&[1.0, 0.0])
    }

    fn columns(&self) -> Vec<String> {
        ["x", "v", "energy"].map(String::from).to_vec()
    }

    fn observe(&mut self, _t: f64, y: &[f64], row: &mut Vec<f64>) -> Result<(), SimulationError> {
        let energy = 0.5 * (y[1] * y[1] + OMEGA * OMEGA * y[0] * y[0]);
        row.extend_from_slice(&[y[0], y[1], energy]);
        Ok(())
    }
}

pub fn rk4() -> Integrator {
    Integrator::Rk4 { step: STEP }
}

/// The reference: the same run, in memory.
pub fn in_memory(duration: f64, fail_at: Option<f64>) -> Results {
    let mut system = Oscillator { fail_at };
    match simulate(&mut system, rk4(), 0.0, duration, Output::Every(INTERVAL)) {
        Ok(r) => r,
        Err(f) => f.results,
    }
}

/// The oscillator (its derivative NaN after `fail_at`) streamed for
/// `duration` s into `sink`.
pub fn stream(
    sink: &mut dyn Sink,
    duration: f64,
    fail_at: Option<f64>,
) -> Result<RunReport, StreamFailure> {
    simulate_into(
        &mut Oscillator { fail_at },
        rk4(),
        0.0,
        duration,
        Output::Every(INTERVAL),
        sink,
        &mut |_| {},
    )
}

pub fn results_csv(results: &Results) -> Vec<u8> {
    let mut text = Vec::new();
    results.write_csv(&mut text).unwrap();
    text
}

/// `results` as columns: `t`, then each recorded quantity.
pub fn columns_of(results: &Results) -> (Vec<String>, Vec<Vec<f64>>) {
    let mut names = vec!["t".to_string()];
    names.extend(results.columns().iter().cloned());
    let mut columns = vec![results.times().to_vec()];
    for c in results.columns() {
        columns.push(results.column(c).unwrap());
    }
    (names, columns)
}

pub fn bits(columns: &[Vec<f64>]) -> Vec<Vec<u64>> {
    columns
        .iter()
        .map(|c| c.iter().map(|v| v.to_bits()).collect())
        .collect()
}

pub fn scratch(name: &str) -> PathBuf {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("sinks");
    std::fs::create_dir_all(&dir).unwrap();
    dir.join(name)
}
