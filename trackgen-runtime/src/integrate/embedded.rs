use nalgebra::DVector;

use super::{OdeSystem, Stats, Stepper};
use crate::error::SimulationError;

/// An embedded explicit Runge-Kutta pair whose last stage is evaluated at
/// the solution (first-same-as-last).
#[derive(Debug)]
pub(crate) struct Tableau {
    c: &'static [f64],
    /// Row `s`: the weights of stages `0 … s−1` for stage `s`; the last row
    /// is the solution's weights.
    a: &'static [&'static [f64]],
    /// Solution weights minus the embedded ones: the error estimate.
    e: &'static [f64],
    /// Order of the embedded (lower) solution: the error exponent is
    /// `1 / (order + 1)`.
    error_order: f64,
    /// Hairer's continuous-extension weights (`contd5`), or `None` for cubic
    /// Hermite dense output from the end points and slopes.
    dense: Option<&'static [f64]>,
}

/// Dormand & Prince (1980) 5(4), as in Hairer, Nørsett & Wanner, Solving
/// ODEs I, §II.5 (code DOPRI5), with its fourth-order continuous extension.
pub(crate) const DORMAND_PRINCE: Tableau = Tableau {
    c: &[0.0, 1.0 / 5.0, 3.0 / 10.0, 4.0 / 5.0, 8.0 / 9.0, 1.0, 1.0],
    a: &[
        &[],
        &[1.0 / 5.0],
        &[3.0 / 40.0, 9.0 / 40.0],
        &[44.0 / 45.0, -56.0 / 15.0, 32.0 / 9.0],
        &[
            19372.0 / 6561.0,
            -25360.0 / 2187.0,
            64448.0 / 6561.0,
            -212.0 / 729.0,
        ],
        &[
            9017.0 / 3168.0,
            -355.0 / 33.0,
            46732.0 / 5247.0,
            49.0 / 176.0,
            -5103.0 / 18656.0,
        ],
        &[
            35.0 / 384.0,
            0.0,
            500.0 / 1113.0,
            125.0 / 192.0,
            -2187.0 / 6784.0,
            11.0 / 84.0,
        ],
    ],
    e: &[
        71.0 / 57600.0,
        0.0,
        -71.0 / 16695.0,
        71.0 / 1920.0,
        -17253.0 / 339200.0,
        22.0 / 525.0,
        -1.0 / 40.0,
    ],
    error_order: 4.0,
    dense: Some(&[
        -12715105075.0 / 11282082432.0,
        0.0,
        87487479700.0 / 32700410799.0,
        -10690763975.0 / 1880347072.0,
        701980252875.0 / 199316789632.0,
        -1453857185.0 / 822651844.0,
        69997945.0 / 29380423.0,
    ]),
};

/// Bogacki & Shampine (1989) 3(2): four stages, three new evaluations a
/// step; its stability interval (−2.5 on the real axis) is three quarters of
/// Dormand-Prince's (−3.3) at half the evaluations, so where stability
/// sets the step it does the same work for about two thirds the cost.
pub(crate) const BOGACKI_SHAMPINE: Tableau = Tableau {
    c: &[0.0, 0.5, 0.75, 1.0],
    a: &[
        &[],
        &[0.5],
        &[0.0, 0.75],
        &[2.0 / 9.0, 1.0 / 3.0, 4.0 / 9.0],
    ],
    e: &[-5.0 / 72.0, 1.0 / 12.0, 1.0 / 9.0, -1.0 / 8.0],
    error_order: 2.0,
    dense: None,
};

/// A step tried: the solution, the stages (the last is the slope at the
/// solution), and the error norm.
struct Trial {
    y: DVector<f64>,
    stages: Vec<DVector<f64>>,
    error: f64,
}

const SAFETY: f64 = 0.9;
/// PI controller: `β = 0.04`, `α = 1/(q+1) − 0.75 β` (Hairer's DOPRI5).
const BETA: f64 = 0.04;
const MIN_FACTOR: f64 = 0.2;
const MAX_FACTOR: f64 = 5.0;

/// An adaptive embedded Runge-Kutta method (Dormand-Prince 5(4) or
/// Bogacki-Shampine 3(2)), first-same-as-last, with dense output between
/// steps. The error of each step is kept below 1 in the RMS norm weighted by
/// `atol + rtol·|y|` per component, with PI step control; a step whose
/// right-hand side fails is rejected and retried four times shorter.
#[derive(Debug, Clone)]
pub struct Embedded {
    tableau: &'static Tableau,
    rtol: f64,
    atol: f64,
    max_step: f64,
    /// The next step to try; 0 until the first step picks one.
    h: f64,
    /// The last accepted step's error norm, for PI control.
    previous_error: f64,
    f_now: Option<DVector<f64>>,
    /// Dense-output coefficients of the last step and its span.
    dense: Vec<DVector<f64>>,
    span: (f64, f64),
    stats: Stats,
}

/// Dormand-Prince 5(4) (see [`Embedded`]).
pub type Dopri5 = Embedded;

impl Embedded {
    /// Dormand-Prince 5(4) with tolerances `rtol`, `atol` and step limit
    /// `max_step` (s) for `dimension` components.
    pub fn new(rtol: f64, atol: f64, max_step: f64, dimension: usize) -> Self {
        Self::with_tableau(&DORMAND_PRINCE, rtol, atol, max_step, dimension)
    }

    /// Bogacki-Shampine 3(2), otherwise as [`new`](Self::new).
    pub fn bogacki_shampine(rtol: f64, atol: f64, max_step: f64, dimension: usize) -> Self {
        Self::with_tableau(&BOGACKI_SHAMPINE, rtol, atol, max_step, dimension)
    }

    pub(crate) fn with_tableau(
        tableau: &'static Tableau,
        rtol: f64,
        atol: f64,
        max_step: f64,
        dimension: usize,
    ) -> Self {
        Embedded {
            tableau,
            rtol,
            atol,
            max_step,
            h: 0.0,
            previous_error: 1e-4,
            f_now: None,
            dense: vec![DVector::zeros(dimension); 5],
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
                // A zero is no error whatever the scale: with `atol = 0`
                // a component that is exactly 0 has a scale of 0, and
                // 0/0 = NaN would reject every step down to underflow.
                if v[i] == 0.0 {
                    return 0.0;
                }
                let scale = self.atol + self.rtol * y0[i].abs().max(y1[i].abs());
                (v[i] / scale).powi(2)
            })
            .sum();
        (sum / n).sqrt()
    }

    /// Hairer's starting-step heuristic. Norms taken at `y` alone are
    /// infinite for a component that is 0 when `atol = 0` (pure relative
    /// tolerance, a body at rest): then the heuristic starts at 1e-6 s and
    /// leaves the step control, which scales by the larger of the old and
    /// new values, to find the step.
    fn initial_step(
        &mut self,
        system: &mut dyn OdeSystem,
        t: f64,
        y: &DVector<f64>,
        f0: &DVector<f64>,
    ) -> f64 {
        let d0 = self.norm(y, y, y);
        let d1 = self.norm(f0, y, y);
        let h0 = if d0 < 1e-5 || d1 < 1e-5 || !d1.is_finite() {
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
        } else if !d1.max(d2).is_finite() {
            h0
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
        let tableau = self.tableau;
        let stages = tableau.c.len();
        let mut k: Vec<DVector<f64>> = Vec::with_capacity(stages);
        k.push(f0.clone());
        let mut ys = y.clone();
        for s in 1..stages {
            ys.copy_from(y);
            for (j, &a) in tableau.a[s].iter().enumerate() {
                if a != 0.0 {
                    ys.axpy(h * a, &k[j], 1.0);
                }
            }
            let f = self.eval(system, t + tableau.c[s] * h, &ys)?;
            k.push(f);
        }
        // First same as last: the last stage's argument is the solution.
        let mut err = DVector::zeros(y.len());
        for (j, &e) in tableau.e.iter().enumerate() {
            if e != 0.0 {
                err.axpy(h * e, &k[j], 1.0);
            }
        }
        let error = self.norm(&err, y, &ys);
        Ok(Trial {
            y: ys,
            stages: k,
            error,
        })
    }
}

impl Stepper for Embedded {
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
                    let last = k.last().expect("stages").clone();
                    match self.tableau.dense {
                        Some(d) => {
                            // Hairer's contd5.
                            let ydiff = &y1 - &*y;
                            let bspl = &k[0] * h - &ydiff;
                            let mut d5 = DVector::zeros(y.len());
                            for (j, &dj) in d.iter().enumerate() {
                                if dj != 0.0 {
                                    d5.axpy(h * dj, &k[j], 1.0);
                                }
                            }
                            let d4 = &ydiff - &last * h - &bspl;
                            self.dense = vec![y.clone(), ydiff, bspl, d4, d5];
                        }
                        None => {
                            self.dense = vec![y.clone(), y1.clone(), k[0].clone(), last.clone()]
                        }
                    }
                    self.span = (*t, *t + h);
                    // PI step control (Gustafsson; Hairer's DOPRI5, β = 0.04):
                    // the previous error damps the step's growth, which
                    // keeps a step limited by stability from being
                    // rejected every other time.
                    let err = err.max(1e-10);
                    let alpha = 1.0 / (self.tableau.error_order + 1.0) - 0.75 * BETA;
                    let factor = (SAFETY * err.powf(-alpha) * self.previous_error.powf(BETA))
                        .clamp(MIN_FACTOR, MAX_FACTOR);
                    self.previous_error = err.max(1e-4);
                    // After a rejection, do not grow the step at once.
                    self.h = h * if rejected_last {
                        factor.min(1.0)
                    } else {
                        factor
                    };
                    self.f_now = Some(last);
                    *t += h;
                    *y = y1;
                    self.stats.accepted += 1;
                    return Ok(());
                }
                Ok(Trial { error: err, .. }) => {
                    self.stats.rejected += 1;
                    rejected_last = true;
                    let factor = if err.is_finite() {
                        (SAFETY * err.powf(-1.0 / (self.tableau.error_order + 1.0)))
                            .clamp(MIN_FACTOR, 1.0)
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
        let h = t1 - t0;
        let theta = if h > 0.0 { (t - t0) / h } else { 1.0 };
        let theta1 = 1.0 - theta;
        match &self.dense[..] {
            [r1, r2, r3, r4, r5] => r1 + (r2 + (r3 + (r4 + r5 * theta1) * theta) * theta1) * theta,
            [y0, y1, f0, f1] => {
                // Cubic Hermite.
                let (s2, s3) = (theta * theta, theta * theta * theta);
                y0 * (2.0 * s3 - 3.0 * s2 + 1.0)
                    + f0 * ((s3 - 2.0 * s2 + theta) * h)
                    + y1 * (-2.0 * s3 + 3.0 * s2)
                    + f1 * ((s3 - s2) * h)
            }
            _ => unreachable!("dense output has 5 or 4 vectors"),
        }
    }

    fn restart(&mut self) {
        self.f_now = None;
        self.stats.restarts += 1;
    }

    fn stats(&self) -> Stats {
        self.stats
    }
}
