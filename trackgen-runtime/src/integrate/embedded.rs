use nalgebra::DVector;

use super::control::StepControl;
use super::{OdeSystem, Stats, Stepper};
use crate::integrate::SimulationError;

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

/// The RMS of `v` weighted by `atol + rtol · max(|y0|, |y1|)` per
/// component.
#[inline(always)]
pub(crate) fn weighted_rms(
    v: &DVector<f64>,
    y0: &DVector<f64>,
    y1: &DVector<f64>,
    atol: f64,
    rtol: f64,
) -> f64 {
    let n = v.len();
    let (v, y0, y1) = (v.as_slice(), &y0.as_slice()[..n], &y1.as_slice()[..n]);
    rms_of(n, |i| {
        scaled_square(v[i], atol + rtol * y0[i].abs().max(y1[i].abs()))
    })
}

/// `(v / scale)²`, and 0 for `v = 0` whatever the scale: with `atol = 0`
/// a component that is exactly 0 has a scale of 0, and 0/0 = NaN would
/// reject every step down to underflow.
#[inline(always)]
fn scaled_square(v: f64, scale: f64) -> f64 {
    let r = v / scale;
    if v == 0.0 { 0.0 } else { r * r }
}

/// `√(Σ term(i) / n)` over `i < n`, summed in order of `i` (so the same
/// bits as a plain loop), the terms found a block at a time: a block's
/// terms have no order and go as wide as the processor allows, its sum
/// then adds them one by one.
#[inline(always)]
fn rms_of(n: usize, term: impl Fn(usize) -> f64) -> f64 {
    rms_of_live(n, n, term)
}

/// [`rms_of`] divided by `live` (≤ `n`) terms rather than `n`: the others
/// are 0 and not counted. Adding a zero term leaves a sum's bits as they
/// were, so a passive component changes no norm.
#[inline(always)]
fn rms_of_live(n: usize, live: usize, term: impl Fn(usize) -> f64) -> f64 {
    const BLOCK: usize = 32;
    let mut terms = [0.0; BLOCK];
    let mut sum = 0.0;
    let mut start = 0;
    while start < n {
        let len = BLOCK.min(n - start);
        for (j, t) in terms[..len].iter_mut().enumerate() {
            *t = term(start + j);
        }
        for &t in &terms[..len] {
            sum += t;
        }
        start += len;
    }
    (sum / live.max(1) as f64).sqrt()
}

/// Which components of a system are quadratures
/// ([`OdeSystem::is_quadrature`]: the energy books), asked once for its
/// dimension, for the error's weights and the Jacobian's zeros.
#[derive(Debug, Clone, Default)]
pub(crate) struct Quadratures {
    mask: Vec<bool>,
    /// The passive ones ([`OdeSystem::is_passive`]): left out of every
    /// norm.
    passive: Vec<bool>,
    /// Whether any component is one.
    any: bool,
    /// How many components the norms weigh: all but the passive.
    live: usize,
}

impl Quadratures {
    /// Asks `system` about each of its `n` components, unless already
    /// asked for `n`.
    pub fn ask(&mut self, system: &dyn OdeSystem, n: usize) {
        if self.mask.len() != n {
            self.passive = (0..n).map(|i| system.is_passive(i)).collect();
            self.mask = (0..n)
                .map(|i| system.is_quadrature(i) || self.passive[i])
                .collect();
            self.any = self.mask.contains(&true);
            self.live = self.passive.iter().filter(|&&p| !p).count();
        }
    }

    /// Whether component `i` is a quadrature.
    #[inline]
    pub fn contains(&self, i: usize) -> bool {
        self.mask[i]
    }
}

/// A step's error estimate `v` (from `y0` to `y1`) in one number, ≤ 1 to
/// accept: the RMS of the components' errors, each weighted by `atol +
/// rtol · max(|y0|, |y1|)` ([`weighted_rms`]), except the quadratures'
/// (the energy books), weighted by `atol + rtol · |y1 − y0|`, their
/// increment over the step.
///
/// A running integral grows without bound: weighted by its own size, a
/// book of 10⁴ J lets each step err by 10 J at `rtol = 1e-3`, and over
/// 10⁴ steps the errors add up to per cents of it (the books of a 14 s
/// run at 1 m/s were off by 4.2 %, a 12 s crawl over a step by 1.6 %).
/// Weighted by its increment, each step's contribution is held to `rtol`
/// of itself (within the RMS), so the integral is, however long the run:
/// 2e-4 and 7e-5 on those runs, in as many steps. (Their largest instead
/// of the RMS held them tighter still, at 55 % more steps on the main
/// job.) Each book is held to its own increment, not the largest book's:
/// the dissipated work's accuracy is the friction's, and held only to the
/// motor's work the Marder's slip at 3 m/s (Bogacki-Shampine 1e-4) was
/// −0.54 % against −0.40 % at 1e-5; held to its own, −0.41 %.
#[inline(always)]
pub(crate) fn step_error(
    v: &DVector<f64>,
    y0: &DVector<f64>,
    y1: &DVector<f64>,
    tolerances: (f64, f64),
    quadratures: &Quadratures,
) -> f64 {
    norm_over(v, (y0, y1), tolerances, quadratures, true)
}

/// [`weighted_rms`] over the components the norms weigh: the passive
/// quadratures left out (no term, and not counted).
pub(crate) fn live_rms(
    v: &DVector<f64>,
    y0: &DVector<f64>,
    y1: &DVector<f64>,
    tolerances: (f64, f64),
    quadratures: &Quadratures,
) -> f64 {
    norm_over(v, (y0, y1), tolerances, quadratures, false)
}

/// The RMS of `v` weighted by `atol + rtol · max(|y0|, |y1|)` per
/// component, the quadratures by their increment `|y1 − y0|` where
/// `by_increment`, the passive ones left out (no term, not counted).
#[inline(always)]
fn norm_over(
    v: &DVector<f64>,
    (y0, y1): (&DVector<f64>, &DVector<f64>),
    (atol, rtol): (f64, f64),
    quadratures: &Quadratures,
    by_increment: bool,
) -> f64 {
    if !quadratures.any {
        return weighted_rms(v, y0, y1, atol, rtol);
    }
    let n = v.len();
    let (v, y0, y1) = (v.as_slice(), &y0.as_slice()[..n], &y1.as_slice()[..n]);
    let (mask, passive) = (&quadratures.mask[..n], &quadratures.passive[..n]);
    rms_of_live(n, quadratures.live, |i| {
        if passive[i] {
            return 0.0;
        }
        let size = if by_increment && mask[i] {
            (y1[i] - y0[i]).abs()
        } else {
            y0[i].abs().max(y1[i].abs())
        };
        scaled_square(v[i], atol + rtol * size)
    })
}

/// `out = base + Σ w_j k_j` (base 0 if `None`) over the nonzero weights, on
/// plain slices: nalgebra's `copy_from` and `axpy` took a generic
/// element-by-element path that cost a step as much as a sixth of an
/// evaluation of the M113. The terms are added three at a time in one
/// pass over the components, each component's sum in the terms' order
/// (`((base + w₀k₀) + w₁k₁) + …`, the bits of adding them one pass per
/// term), so a step of Bogacki-Shampine reads and writes its vectors
/// half as often.
fn combine<'a>(
    out: &mut DVector<f64>,
    base: Option<&DVector<f64>>,
    terms: impl IntoIterator<Item = (f64, &'a DVector<f64>)>,
) {
    let out = out.as_mut_slice();
    let n = out.len();
    // The most stages of a tableau here (Dormand-Prince's seven).
    const MOST: usize = 8;
    let mut live = [(0.0, &[][..]); MOST];
    let mut count = 0;
    for (w, k) in terms {
        if w != 0.0 {
            live[count] = (w, &k.as_slice()[..n]);
            count += 1;
        }
    }
    let mut groups = live[..count].chunks(3);
    let first = groups.next().unwrap_or(&[]);
    match base {
        Some(base) => sum_into(out, |i, _| base[i], first),
        None => sum_into(out, |_, _| 0.0, first),
    }
    for group in groups {
        sum_into(out, |_, o| o, group);
    }
}

/// `out[i] = start(i, out[i]) + w₀k₀[i] (+ w₁k₁[i] (+ w₂k₂[i]))`, summed
/// left to right, for up to three `terms` (each as long as `out`).
#[inline(always)]
fn sum_into(out: &mut [f64], start: impl Fn(usize, f64) -> f64, terms: &[(f64, &[f64])]) {
    match *terms {
        [] => {
            for (i, o) in out.iter_mut().enumerate() {
                *o = start(i, *o);
            }
        }
        [(w0, k0)] => {
            for (i, o) in out.iter_mut().enumerate() {
                *o = start(i, *o) + w0 * k0[i];
            }
        }
        [(w0, k0), (w1, k1)] => {
            for (i, o) in out.iter_mut().enumerate() {
                *o = start(i, *o) + w0 * k0[i] + w1 * k1[i];
            }
        }
        [(w0, k0), (w1, k1), (w2, k2), ..] => {
            for (i, o) in out.iter_mut().enumerate() {
                *o = start(i, *o) + w0 * k0[i] + w1 * k1[i] + w2 * k2[i];
            }
        }
    }
}

/// An adaptive embedded Runge-Kutta method (Dormand-Prince 5(4) or
/// Bogacki-Shampine 3(2)), first-same-as-last, with dense output between
/// steps. The error of each step is kept below 1 in the RMS norm weighted by
/// `atol + rtol·|y|` per component, with PI step control; a step whose
/// right-hand side fails is rejected and retried four times shorter.
///
/// Every vector it needs is allocated with it: a step allocates nothing.
#[derive(Debug, Clone)]
pub struct Embedded {
    tableau: &'static Tableau,
    rtol: f64,
    atol: f64,
    control: StepControl,
    /// Whether `stages[0]` holds `f` at the current state (first same as
    /// last, or the last call's start).
    f_now: bool,
    /// The stages of the step being tried; the last is the slope at its
    /// solution.
    stages: Vec<DVector<f64>>,
    /// The stage argument, then the trial solution.
    trial: DVector<f64>,
    /// The error estimate of the trial.
    error: DVector<f64>,
    /// Dense-output coefficients of the last step (five for Hairer's
    /// `contd5`, four for cubic Hermite) and its span.
    dense: Vec<DVector<f64>>,
    span: (f64, f64),
    stats: Stats,
    /// [`OdeSystem::is_quadrature`] of each component, asked at the first
    /// step.
    quadratures: Quadratures,
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
        let zero = DVector::zeros(dimension);
        let dense = if tableau.dense.is_some() { 5 } else { 4 };
        Embedded {
            tableau,
            rtol,
            atol,
            control: StepControl::new(max_step, tableau.error_order),
            f_now: false,
            stages: vec![zero.clone(); tableau.c.len()],
            trial: zero.clone(),
            error: zero.clone(),
            dense: vec![zero; dense],
            span: (0.0, 0.0),
            stats: Stats::default(),
            quadratures: Quadratures::default(),
        }
    }

    #[inline(always)]
    fn norm(&self, v: &DVector<f64>, y0: &DVector<f64>, y1: &DVector<f64>) -> f64 {
        step_error(v, y0, y1, (self.atol, self.rtol), &self.quadratures)
    }

    /// Hairer's starting-step heuristic, from `f0 = stages[0]`. Norms
    /// taken at `y` alone are infinite for a component that is 0 when
    /// `atol = 0` (pure relative tolerance, a body at rest): then the
    /// heuristic starts at 1e-6 s and leaves the step control, which scales
    /// by the larger of the old and new values, to find the step.
    fn initial_step(&mut self, system: &mut dyn OdeSystem, t: f64, y: &DVector<f64>) -> f64 {
        let d0 = self.norm(y, y, y);
        let d1 = self.norm(&self.stages[0], y, y);
        let h0 = if d0 < 1e-5 || d1 < 1e-5 || !d1.is_finite() {
            1e-6
        } else {
            0.01 * d0 / d1
        };
        let h0 = h0.min(self.control.max_step);
        self.trial.copy_from(y);
        self.trial.axpy(h0, &self.stages[0], 1.0);
        let [f0, f1, ..] = &mut self.stages[..] else {
            unreachable!("a tableau has at least two stages")
        };
        let d2 = match super::evaluate(system, &mut self.stats, t + h0, &self.trial, f1) {
            Ok(()) => {
                f1.axpy(-1.0, f0, 1.0);
                live_rms(f1, y, y, (self.atol, self.rtol), &self.quadratures) / h0
            }
            Err(_) => return h0 * 0.1,
        };
        let h1 = if d1.max(d2) <= 1e-15 {
            (h0 * 1e-3).max(1e-6)
        } else if !d1.max(d2).is_finite() {
            h0
        } else {
            (0.01 / d1.max(d2)).powf(0.2)
        };
        (100.0 * h0).min(h1).min(self.control.max_step)
    }

    /// Tries one step of length `h` from `(t, y)` with `f(t, y)` in
    /// `stages[0]`: the stages, the solution in `trial` (the last stage's
    /// argument: first same as last) and the error estimate's norm.
    fn attempt(
        &mut self,
        system: &mut dyn OdeSystem,
        t: f64,
        y: &DVector<f64>,
        h: f64,
    ) -> Result<f64, SimulationError> {
        // The stages' vector sums four values wide where the processor
        // allows (the same bits).
        crate::simd::run(
            #[inline(always)]
            || self.attempt_inline(system, t, y, h),
        )
    }

    /// [`attempt`](Self::attempt)'s loops, inlined into its wide build.
    #[inline(always)]
    fn attempt_inline(
        &mut self,
        system: &mut dyn OdeSystem,
        t: f64,
        y: &DVector<f64>,
        h: f64,
    ) -> Result<f64, SimulationError> {
        let tableau = self.tableau;
        for s in 1..tableau.c.len() {
            combine(
                &mut self.trial,
                Some(y),
                tableau.a[s]
                    .iter()
                    .zip(&self.stages)
                    .map(|(&a, k)| (h * a, k)),
            );
            super::evaluate(
                system,
                &mut self.stats,
                t + tableau.c[s] * h,
                &self.trial,
                &mut self.stages[s],
            )?;
        }
        combine(
            &mut self.error,
            None,
            tableau.e.iter().zip(&self.stages).map(|(&e, k)| (h * e, k)),
        );
        Ok(self.norm(&self.error, y, &self.trial))
    }

    /// Hairer's `contd5` dense output of the accepted step `y → trial`
    /// (Dormand-Prince's; cubic Hermite's is kept once the step has moved
    /// on, [`keep_hermite_output`](Self::keep_hermite_output)).
    fn keep_dense_output(&mut self, y: &DVector<f64>, h: f64) {
        let Some(d) = self.tableau.dense else {
            return;
        };
        let last = self.stages.len() - 1;
        // r1 = y, r2 = y1 − y, r3 = h f0 − r2, r4 = r2 − h f1 − r3,
        // r5 = h Σ d_j k_j.
        let [r1, r2, r3, r4, r5] = &mut self.dense[..] else {
            unreachable!("contd5 has five coefficients")
        };
        r1.copy_from(y);
        r2.copy_from(&self.trial);
        r2.axpy(-1.0, y, 1.0);
        r3.copy_from(&self.stages[0]);
        r3.axpy(-1.0, r2, h);
        r4.copy_from(r2);
        r4.axpy(-h, &self.stages[last], 1.0);
        r4.axpy(-1.0, r3, 1.0);
        r5.fill(0.0);
        for (j, &dj) in d.iter().enumerate() {
            if dj != 0.0 {
                r5.axpy(h * dj, &self.stages[j], 1.0);
            }
        }
    }

    /// Cubic Hermite's dense output of the step just accepted, once
    /// `step` has moved on: its start `y₀` and slope `f₀` are in the
    /// scratch vectors `trial` and `stages[last]` (the step swapped them
    /// out), so they are swapped into the output, not copied; its end
    /// `y` and slope `stages[0]` stay where they are and are copied.
    fn keep_hermite_output(&mut self, y: &DVector<f64>) {
        if self.tableau.dense.is_some() {
            return;
        }
        let last = self.stages.len() - 1;
        let [y0, y1, f0, f1] = &mut self.dense[..] else {
            unreachable!("Hermite output has four coefficients")
        };
        std::mem::swap(y0, &mut self.trial);
        std::mem::swap(f0, &mut self.stages[last]);
        y1.copy_from_slice(y.as_slice());
        f1.copy_from_slice(self.stages[0].as_slice());
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
        self.quadratures.ask(system, y.len());
        if !self.f_now {
            super::evaluate(system, &mut self.stats, *t, y, &mut self.stages[0])?;
            self.f_now = true;
        }
        if self.control.h == 0.0 {
            self.control.h = self.initial_step(system, *t, y);
        }
        let mut rejected_last = false;
        loop {
            let h = self.control.next(*t, t_limit)?;
            match self.attempt(system, *t, y, h) {
                Ok(err) if err <= 1.0 => {
                    self.keep_dense_output(y, h);
                    self.span = (*t, *t + h);
                    self.control.accept(h, err, rejected_last);
                    // First same as last: the slope at the solution starts
                    // the next step.
                    let last = self.stages.len() - 1;
                    self.stages.swap(0, last);
                    *t += h;
                    std::mem::swap(y, &mut self.trial);
                    self.keep_hermite_output(y);
                    self.stats.accepted += 1;
                    return Ok(());
                }
                outcome => {
                    self.stats.rejected += 1;
                    rejected_last = true;
                    self.control.reject(*t, h, outcome)?;
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
        self.f_now = false;
        self.stats.restarts += 1;
    }

    fn stats(&self) -> Stats {
        self.stats
    }
}

#[cfg(test)]
mod tests {
    use nalgebra::DVector;

    use super::{Quadratures, combine, step_error, weighted_rms};
    use crate::integrate::{OdeSystem, SimulationError};

    /// The one-pass sum is the sum of one pass per term, bit for bit, for
    /// every count of terms a tableau has (0 to 7, zero weights among
    /// them), with and without a base, on components whose products
    /// round, cancel and give a negative zero.
    #[test]
    fn one_pass_is_one_pass_per_term() {
        let n = 37;
        let vector = |seed: f64| {
            DVector::from_fn(n, |i, _| match i % 7 {
                0 => 0.0,
                1 => -0.0,
                _ => (seed * (i as f64 + 1.0)).sin() * 10f64.powi((i % 5) as i32 - 2),
            })
        };
        let stages: Vec<DVector<f64>> = (0..7).map(|j| vector(0.37 + j as f64)).collect();
        let base = vector(5.3);
        let weights = [0.1, -1.0 / 3.0, 0.0, 4.0 / 9.0, 1e-17, -2.5, 0.0];
        for count in 0..=7 {
            for with_base in [false, true] {
                let terms = || weights[..count].iter().copied().zip(&stages);
                let mut plain = match with_base {
                    true => base.clone(),
                    false => DVector::zeros(n),
                };
                for (w, k) in terms() {
                    if w != 0.0 {
                        for (o, &k) in plain.iter_mut().zip(k.iter()) {
                            *o += w * k;
                        }
                    }
                }
                let mut fused = DVector::from_element(n, f64::NAN);
                combine(&mut fused, with_base.then_some(&base), terms());
                for (a, b) in fused.iter().zip(plain.iter()) {
                    assert_eq!(a.to_bits(), b.to_bits(), "{count} terms, base {with_base}");
                }
            }
        }
    }

    /// Two states and two books (components 2 and 3).
    struct Books;

    impl OdeSystem for Books {
        fn dimension(&self) -> usize {
            4
        }
        fn derivative(&mut self, _: f64, _: &[f64], dy: &mut [f64]) -> Result<(), SimulationError> {
            dy.fill(0.0);
            Ok(())
        }
        fn is_quadrature(&self, i: usize) -> bool {
            i >= 2
        }
    }

    /// The states weighted by their size, each book by its own increment
    /// over the step (5 J and 0.01 J): the RMS by hand, to rounding.
    #[test]
    fn the_books_are_weighted_by_their_increments() {
        let mut quadratures = Quadratures::default();
        quadratures.ask(&Books, 4);
        let y0 = DVector::from_vec(vec![2.0, -0.5, 1000.0, 40.0]);
        let y1 = DVector::from_vec(vec![2.1, -0.4, 1005.0, 40.01]);
        let v = DVector::from_vec(vec![1e-4, 2e-5, 3e-3, 1e-6]);
        let (atol, rtol) = (1e-6, 1e-3);
        let terms = [
            1e-4 / (atol + rtol * 2.1),
            2e-5 / (atol + rtol * 0.5),
            3e-3 / (atol + rtol * (1005.0f64 - 1000.0)),
            // 40.01 − 40 as the subtraction gives it (0.01 to 2e-13).
            1e-6 / (atol + rtol * (40.01f64 - 40.0)),
        ];
        let expected = (terms.iter().map(|r| r * r).sum::<f64>() / 4.0).sqrt();
        let got = step_error(&v, &y0, &y1, (atol, rtol), &quadratures);
        assert!(
            (got - expected).abs() <= 1e-15 * expected,
            "{got} against {expected}"
        );
        // Weighted by its size a book of 1000 J hides the same error.
        assert!(weighted_rms(&v, &y0, &y1, atol, rtol) < 0.5 * got);
    }

    /// At `atol = 0` a component whose error is exactly 0 counts nothing,
    /// whatever its scale: a state at 0, and a book that did not move in
    /// the step (a scale of 0 both), give no 0/0 to reject the step on.
    #[test]
    fn an_exact_zero_counts_nothing_at_atol_zero() {
        let mut quadratures = Quadratures::default();
        quadratures.ask(&Books, 4);
        let y0 = DVector::from_vec(vec![2.0, 0.0, 1000.0, 40.0]);
        let y1 = DVector::from_vec(vec![2.1, 0.0, 1005.0, 40.0]);
        let v = DVector::from_vec(vec![1e-4, 0.0, 3e-3, 0.0]);
        let expected = ((1e-4_f64 / (1e-3 * 2.1)).powi(2)
            + (3e-3 / (1e-3 * (1005.0f64 - 1000.0))).powi(2))
            / 4.0;
        let got = step_error(&v, &y0, &y1, (0.0, 1e-3), &quadratures);
        assert!((got - expected.sqrt()).abs() <= 1e-15 * got, "{got}");
        let plain = weighted_rms(&v, &y0, &y1, 0.0, 1e-3);
        assert!(plain.is_finite(), "{plain}");
    }
}
