use nalgebra::DVector;

use super::{OdeSystem, Stats, Stepper};
use crate::simulate::SimulationError;

// Dormand & Prince (1980) 5(4) tableau, as in Hairer, Nørsett & Wanner,
// Solving ODEs I, §II.5 (code DOPRI5).
const C: [f64; 7] = [0.0, 1.0 / 5.0, 3.0 / 10.0, 4.0 / 5.0, 8.0 / 9.0, 1.0, 1.0];
const A: [[f64; 6]; 7] = [
    [0.0; 6],
    [1.0 / 5.0, 0.0, 0.0, 0.0, 0.0, 0.0],
    [3.0 / 40.0, 9.0 / 40.0, 0.0, 0.0, 0.0, 0.0],
    [44.0 / 45.0, -56.0 / 15.0, 32.0 / 9.0, 0.0, 0.0, 0.0],
    [
        19372.0 / 6561.0,
        -25360.0 / 2187.0,
        64448.0 / 6561.0,
        -212.0 / 729.0,
        0.0,
        0.0,
    ],
    [
        9017.0 / 3168.0,
        -355.0 / 33.0,
        46732.0 / 5247.0,
        49.0 / 176.0,
        -5103.0 / 18656.0,
        0.0,
    ],
    [
        35.0 / 384.0,
        0.0,
        500.0 / 1113.0,
        125.0 / 192.0,
        -2187.0 / 6784.0,
        11.0 / 84.0,
    ],
];
/// `b − b̂`: fifth-order weights minus the embedded fourth-order ones.
const E: [f64; 7] = [
    71.0 / 57600.0,
    0.0,
    -71.0 / 16695.0,
    71.0 / 1920.0,
    -17253.0 / 339200.0,
    22.0 / 525.0,
    -1.0 / 40.0,
];
/// Continuous extension (Hairer's `contd5`).
const D: [f64; 7] = [
    -12715105075.0 / 11282082432.0,
    0.0,
    87487479700.0 / 32700410799.0,
    -10690763975.0 / 1880347072.0,
    701980252875.0 / 199316789632.0,
    -1453857185.0 / 822651844.0,
    69997945.0 / 29380423.0,
];

/// A step tried: the fifth-order solution, the seven stages (the last is
/// the slope at the solution), and the error norm.
struct Trial {
    y: DVector<f64>,
    stages: Vec<DVector<f64>>,
    error: f64,
}

const SAFETY: f64 = 0.9;
/// PI controller exponents: `α = 1/5 − 0.75 β`, `β = 0.04`.
const BETA: f64 = 0.04;
const ALPHA: f64 = 0.2 - 0.75 * BETA;
const MIN_FACTOR: f64 = 0.2;
const MAX_FACTOR: f64 = 5.0;

/// Dormand-Prince 5(4): adaptive, first-same-as-last, with the fourth-order
/// continuous extension for output between steps. The error of each step
/// is kept below 1 in the RMS norm weighted by `atol + rtol·|y|` per
/// component; a step whose right-hand side fails is rejected and retried
/// four times shorter.
#[derive(Debug, Clone)]
pub struct Dopri5 {
    rtol: f64,
    atol: f64,
    max_step: f64,
    /// The next step to try; 0 until the first step picks one.
    h: f64,
    /// The last accepted step's error norm, for PI control.
    previous_error: f64,
    f_now: Option<DVector<f64>>,
    /// Dense-output coefficients of the last step and its span.
    dense: [DVector<f64>; 5],
    span: (f64, f64),
    stats: Stats,
}

impl Dopri5 {
    /// A stepper with tolerances `rtol`, `atol` and step limit `max_step`
    /// (s) for `dimension` components.
    pub fn new(rtol: f64, atol: f64, max_step: f64, dimension: usize) -> Self {
        let z = DVector::zeros(dimension);
        Dopri5 {
            rtol,
            atol,
            max_step,
            h: 0.0,
            previous_error: 1e-4,
            f_now: None,
            dense: [z.clone(), z.clone(), z.clone(), z.clone(), z],
            span: (0.0, 0.0),
            stats: Stats::default(),
        }
    }

    fn eval(
        &mut self,
        system: &mut dyn OdeSystem,
        t: f64,
        y: &DVector<f64>,
    ) -> Result<DVector<f64>, SimulationError> {
        super::evaluate(system, &mut self.stats, t, y)
    }

    fn norm(&self, v: &DVector<f64>, y0: &DVector<f64>, y1: &DVector<f64>) -> f64 {
        let n = v.len().max(1) as f64;
        let sum: f64 = (0..v.len())
            .map(|i| {
                let scale = self.atol + self.rtol * y0[i].abs().max(y1[i].abs());
                (v[i] / scale).powi(2)
            })
            .sum();
        (sum / n).sqrt()
    }

    /// Hairer's starting-step heuristic.
    fn initial_step(
        &mut self,
        system: &mut dyn OdeSystem,
        t: f64,
        y: &DVector<f64>,
        f0: &DVector<f64>,
    ) -> f64 {
        let d0 = self.norm(y, y, y);
        let d1 = self.norm(f0, y, y);
        let h0 = if d0 < 1e-5 || d1 < 1e-5 {
            1e-6
        } else {
            0.01 * d0 / d1
        };
        let h0 = h0.min(self.max_step);
        let d2 = match self.eval(system, t + h0, &(y + f0 * h0)) {
            Ok(f1) => self.norm(&(f1 - f0), y, y) / h0,
            Err(_) => return h0 * 0.1,
        };
        let h1 = if d1.max(d2) <= 1e-15 {
            (h0 * 1e-3).max(1e-6)
        } else {
            (0.01 / d1.max(d2)).powf(0.2)
        };
        (100.0 * h0).min(h1).min(self.max_step)
    }

    /// Tries one step of length `h`.
    fn attempt(
        &mut self,
        system: &mut dyn OdeSystem,
        t: f64,
        y: &DVector<f64>,
        f0: &DVector<f64>,
        h: f64,
    ) -> Result<Trial, SimulationError> {
        let mut k: Vec<DVector<f64>> = vec![f0.clone()];
        for s in 1..7 {
            let mut ys = y.clone();
            for (j, kj) in k.iter().enumerate() {
                if A[s][j] != 0.0 {
                    ys.axpy(h * A[s][j], kj, 1.0);
                }
            }
            let f = self.eval(system, t + C[s] * h, &ys)?;
            k.push(f);
            if s == 6 {
                // FSAL: stage 7's argument is the fifth-order solution.
                let mut err = DVector::zeros(y.len());
                for (j, kj) in k.iter().enumerate() {
                    if E[j] != 0.0 {
                        err.axpy(h * E[j], kj, 1.0);
                    }
                }
                let error = self.norm(&err, y, &ys);
                return Ok(Trial {
                    y: ys,
                    stages: k,
                    error,
                });
            }
        }
        unreachable!("the loop returns at stage 7")
    }
}

impl Stepper for Dopri5 {
    fn step(
        &mut self,
        system: &mut dyn OdeSystem,
        t: &mut f64,
        y: &mut DVector<f64>,
        t_limit: f64,
    ) -> Result<(), SimulationError> {
        let f0 = match self.f_now.take() {
            Some(f) => f,
            None => self.eval(system, *t, y)?,
        };
        if self.h == 0.0 {
            self.h = self.initial_step(system, *t, y, &f0);
        }
        let mut rejected_last = false;
        loop {
            let h = self.h.min(self.max_step).min(t_limit - *t);
            if h <= 1e-14 * t.abs().max(1.0) {
                return Err(SimulationError::StepSizeUnderflow {
                    t: *t,
                    step: h,
                    cause: None,
                });
            }
            match self.attempt(system, *t, y, &f0, h) {
                Ok(Trial {
                    y: y1,
                    stages: k,
                    error: err,
                }) if err <= 1.0 => {
                    let ydiff = &y1 - &*y;
                    let bspl = &k[0] * h - &ydiff;
                    let mut d5 = DVector::zeros(y.len());
                    for (j, kj) in k.iter().enumerate() {
                        if D[j] != 0.0 {
                            d5.axpy(h * D[j], kj, 1.0);
                        }
                    }
                    let d4 = &ydiff - &k[6] * h - &bspl;
                    self.dense = [y.clone(), ydiff, bspl, d4, d5];
                    self.span = (*t, *t + h);
                    // PI step control (Gustafsson; Hairer's DOPRI5, β = 0.04):
                    // the previous error damps the step's growth, which
                    // keeps a step limited by stability from being
                    // rejected every other time.
                    let err = err.max(1e-10);
                    let factor = (SAFETY * err.powf(-ALPHA) * self.previous_error.powf(BETA))
                        .clamp(MIN_FACTOR, MAX_FACTOR);
                    self.previous_error = err.max(1e-4);
                    // After a rejection, do not grow the step at once.
                    self.h = h * if rejected_last {
                        factor.min(1.0)
                    } else {
                        factor
                    };
                    self.f_now = Some(k[6].clone());
                    *t += h;
                    *y = y1;
                    self.stats.accepted += 1;
                    return Ok(());
                }
                Ok(Trial { error: err, .. }) => {
                    self.stats.rejected += 1;
                    rejected_last = true;
                    let factor = if err.is_finite() {
                        (SAFETY * err.powf(-0.2)).clamp(MIN_FACTOR, 1.0)
                    } else {
                        MIN_FACTOR
                    };
                    self.h = h * factor;
                }
                Err(cause) => {
                    self.stats.rejected += 1;
                    rejected_last = true;
                    self.h = h * 0.25;
                    if self.h <= 1e-14 * t.abs().max(1.0) {
                        return Err(SimulationError::StepSizeUnderflow {
                            t: *t,
                            step: self.h,
                            cause: Some(Box::new(cause)),
                        });
                    }
                }
            }
        }
    }

    fn interpolate(&self, t: f64) -> DVector<f64> {
        let (t0, t1) = self.span;
        let theta = if t1 > t0 { (t - t0) / (t1 - t0) } else { 1.0 };
        let theta1 = 1.0 - theta;
        let [r1, r2, r3, r4, r5] = &self.dense;
        r1 + (r2 + (r3 + (r4 + r5 * theta1) * theta) * theta1) * theta
    }

    fn restart(&mut self) {
        self.f_now = None;
        self.stats.restarts += 1;
    }

    fn stats(&self) -> Stats {
        self.stats
    }
}
