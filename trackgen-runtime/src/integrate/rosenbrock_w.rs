//! ROS34PW2, an adaptive Rosenbrock-W method of order 3(2) whose linear
//! systems use a Jacobian computed now and then and a factorisation kept
//! while it serves.

use std::sync::LazyLock;

use faer::linalg::solvers::Solve;
use faer::{ColMut, Mat};
use nalgebra::DVector;

use super::control::StepControl;
use super::differences::forward_jacobian;
use super::embedded::{Quadratures, live_rms, step_error};
use super::{OdeSystem, Stats, Stepper};
use crate::integrate::SimulationError;

/// The diagonal `γ` of ROS34PW2.
const GAMMA: f64 = 4.358_665_215_084_59e-1;

/// ROS34PW2 of Rang & Angermann (BIT 45, 2005, 761–787), its coefficients
/// as PETSc registers them (`TSROSWRA34PW2`, `src/ts/impls/rosw/rosw.c`),
/// in the `k` form of Hairer & Wanner (Solving ODEs II, §IV.7):
///
/// ```text
/// (I − γ h W) kᵢ = h f(tₙ + αᵢ h, yₙ + Σⱼ αᵢⱼ kⱼ) + h W Σⱼ γᵢⱼ kⱼ,   yₙ₊₁ = yₙ + Σ bᵢ kᵢ
/// ```
///
/// Third order and L-stable for *any* matrix `W` (a W-method), stiffly
/// accurate, with an embedded second-order solution `b̂`.
struct Tableau {
    alpha: [[f64; 4]; 4],
    gamma: [[f64; 4]; 4],
    b: [f64; 4],
    b_hat: [f64; 4],
    /// PETSc's third-order continuous extension: `y(tₙ + θh) = yₙ +
    /// Σᵢ Σⱼ dᵢⱼ θ^(j+1) kᵢ` (its rows sum to `b`).
    dense: [[f64; 3]; 4],
}

// The digits as published, though f64 keeps fewer.
#[allow(clippy::excessive_precision)]
const ROS34PW2: Tableau = Tableau {
    alpha: [
        [0.0; 4],
        [8.717_330_430_169_180_1e-1, 0.0, 0.0, 0.0],
        [
            8.445_706_001_536_942_3e-1,
            -1.129_906_423_648_418_5e-1,
            0.0,
            0.0,
        ],
        [0.0, 0.0, 1.0, 0.0],
    ],
    gamma: [
        [GAMMA, 0.0, 0.0, 0.0],
        [-8.717_330_430_169_180_1e-1, GAMMA, 0.0, 0.0],
        [
            -9.033_805_701_304_408_2e-1,
            5.418_067_238_809_532_6e-2,
            GAMMA,
            0.0,
        ],
        [
            2.421_238_070_609_534_6e-1,
            -1.223_250_583_904_514_7,
            5.452_602_553_351_021_4e-1,
            GAMMA,
        ],
    ],
    b: [
        2.421_238_070_609_534_6e-1,
        -1.223_250_583_904_514_7,
        1.545_260_255_335_102,
        GAMMA,
    ],
    b_hat: [
        3.781_090_314_581_936_9e-1,
        -9.604_229_221_242_317_8e-2,
        0.5,
        2.179_332_607_542_295e-1,
    ],
    dense: [
        [
            1.056_429_845_579_409_4,
            -1.386_488_269_975_957_3,
            0.572_182_231_457_501_6,
        ],
        [
            2.296_429_974_281_067,
            -8.262_611_700_275_677,
            4.742_931_142_090_097,
        ],
        [
            -1.307_599_564_525_376,
            7.250_979_895_056_055,
            -4.398_120_075_195_578,
        ],
        [
            -1.045_260_255_335_102,
            2.398_120_075_195_581,
            -0.916_993_298_352_019_9,
        ],
    ],
};

/// The tableau rewritten for the variables `Uᵢ = Σⱼ γᵢⱼ kⱼ` (Hairer &
/// Wanner's (7.21)–(7.23)), in which no stage multiplies by the Jacobian:
///
/// ```text
/// (I − γ h W) Uᵢ = γ h f(tₙ + αᵢ h, yₙ + Σⱼ aᵢⱼ Uⱼ) + γ Σⱼ cᵢⱼ Uⱼ
/// yₙ₊₁ = yₙ + Σ mᵢ Uᵢ,   error = Σ (mᵢ − m̂ᵢ) Uᵢ
/// ```
///
/// with `a = α Γ⁻¹`, `c = −Γ⁻¹` below the diagonal, `m = bᵀ Γ⁻¹`. Derived
/// from the published coefficients once, not copied.
#[derive(Debug)]
struct Transformed {
    a: [[f64; 4]; 4],
    c: [[f64; 4]; 4],
    m: [f64; 4],
    error: [f64; 4],
    /// `αᵢ = Σⱼ αᵢⱼ`: where each stage evaluates `f`.
    time: [f64; 4],
    /// `Γ⁻¹`, for the dense output (written in `k`).
    gamma_inverse: [[f64; 4]; 4],
}

impl Transformed {
    fn of(tableau: &Tableau) -> Self {
        // Γ is lower triangular: invert by forward substitution.
        let g = &tableau.gamma;
        let mut inv = [[0.0; 4]; 4];
        for i in 0..4 {
            inv[i][i] = 1.0 / g[i][i];
            for j in (0..i).rev() {
                let s: f64 = (j..i).map(|k| g[i][k] * inv[k][j]).sum();
                inv[i][j] = -s / g[i][i];
            }
        }
        let mut a = [[0.0; 4]; 4];
        let mut c = [[0.0; 4]; 4];
        for i in 0..4 {
            for j in 0..i {
                a[i][j] = (j..i).map(|k| tableau.alpha[i][k] * inv[k][j]).sum();
                c[i][j] = -inv[i][j];
            }
        }
        let row = |w: &[f64; 4]| -> [f64; 4] {
            std::array::from_fn(|j| (j..4).map(|i| w[i] * inv[i][j]).sum())
        };
        let m = row(&tableau.b);
        let m_hat = row(&tableau.b_hat);
        Transformed {
            a,
            c,
            m,
            error: std::array::from_fn(|i| m[i] - m_hat[i]),
            time: std::array::from_fn(|i| tableau.alpha[i].iter().sum()),
            gamma_inverse: inv,
        }
    }
}

/// When the stepper computes a new Jacobian and a new factorisation.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct JacobianReuse {
    /// Accepted steps a Jacobian serves before it is computed again.
    pub max_age: u32,
    /// The factorisation of `I − γ h W` is kept while the step stays within
    /// this factor of the step it was made for (it is then the W-method's
    /// matrix for `W = (h_factored / h) J`, which keeps the order).
    pub step_ratio: f64,
}

/// A differenced Jacobian serves 20 accepted steps and the factorisation
/// is kept while the step stays within 2× of the one it was made for: a
/// W-method keeps its order for any `W`, so only the step count and the
/// books' accuracy change with these, and most Jacobians are taken after
/// rejections whatever the age.
///
/// A system with its own solves ([`OdeSystem::implicit`]) takes its `W`
/// again at every step whatever `max_age` says: its `W` is cheap, and a
/// lagged one costs the books' accuracy what it saves in linear algebra.
/// The measurements behind both are in docs/experiments/jacobian-reuse.md.
impl Default for JacobianReuse {
    fn default() -> Self {
        JacobianReuse {
            max_age: 20,
            step_ratio: 2.0,
        }
    }
}

/// ROS34PW2 in the variables `U`, derived once.
static TRANSFORMED: LazyLock<Transformed> = LazyLock::new(|| Transformed::of(&ROS34PW2));

/// ROS34PW2 (Rang & Angermann 2005), adaptive: error per step below 1 in
/// the RMS norm weighted by `atol + rtol·|y|`, the step controlled as
/// [`Embedded`](super::Embedded)'s, four evaluations of `f` a step, PETSc's
/// third-order dense output.
///
/// The Jacobian `J` comes from [`OdeSystem::jacobian`] if the system gives
/// one and from forward differences otherwise; since any matrix keeps the
/// method's order, a Jacobian and the factorisation of `I − γ h J` are kept
/// across steps as [`JacobianReuse`] says, and computed again after a
/// rejection (if they are not fresh) and after a [`restart`](Stepper::restart)
/// (the state's coordinates may have changed).
#[derive(Debug)]
pub struct Ros34pw2 {
    rtol: f64,
    atol: f64,
    reuse: JacobianReuse,
    control: StepControl,
    /// Whether `f0` holds `f` at the current state.
    f_now: bool,
    f0: DVector<f64>,
    stages: [DVector<f64>; 4],
    argument: DVector<f64>,
    slope: DVector<f64>,
    trial: DVector<f64>,
    error: DVector<f64>,
    /// `J` (column-major), and the accepted steps since it was computed
    /// (`None`: none, or stale after a restart).
    jacobian: Vec<f64>,
    jacobian_age: Option<u32>,
    /// [`OdeSystem::is_quadrature`] of each component, asked once.
    quadratures: Quadratures,
    /// Whether the system solves its own linear systems
    /// ([`OdeSystem::implicit`]), asked at each Jacobian.
    own: bool,
    /// The factorisation of `I − γ h J` (`None` when the system keeps its
    /// own) and the `h` it was made for.
    factorisation: Option<(Option<faer::linalg::solvers::PartialPivLu<f64>>, f64)>,
    /// The accepted step's start, length and stages, for dense output.
    dense_start: DVector<f64>,
    dense_stages: [DVector<f64>; 4],
    span: (f64, f64),
    stats: Stats,
    /// Jacobians computed and matrices factorised.
    work: LinearAlgebraWork,
}

/// What the linearly implicit method spent beyond evaluations of `f`.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct LinearAlgebraWork {
    /// Jacobians computed (each `dimension` evaluations when by
    /// differences, counted in [`Stats::evaluations`] too).
    pub jacobians: u64,
    /// LU factorisations of `I − γ h J`.
    pub factorisations: u64,
}

impl Ros34pw2 {
    /// A stepper with tolerances `rtol`, `atol`, step limit `max_step` (s)
    /// and the default [`JacobianReuse`], for `dimension` components.
    pub fn new(rtol: f64, atol: f64, max_step: f64, dimension: usize) -> Self {
        Self::with_reuse(rtol, atol, max_step, dimension, JacobianReuse::default())
    }

    /// As [`new`](Self::new), with the Jacobian kept as `reuse` says.
    pub fn with_reuse(
        rtol: f64,
        atol: f64,
        max_step: f64,
        dimension: usize,
        reuse: JacobianReuse,
    ) -> Self {
        let zero = DVector::zeros(dimension);
        let four = || std::array::from_fn(|_| zero.clone());
        Ros34pw2 {
            rtol,
            atol,
            reuse,
            // The embedded solution is second order.
            control: StepControl::new(max_step, 2.0),
            f_now: false,
            f0: zero.clone(),
            stages: four(),
            argument: zero.clone(),
            slope: zero.clone(),
            trial: zero.clone(),
            error: zero.clone(),
            jacobian: vec![0.0; dimension * dimension],
            jacobian_age: None,
            quadratures: Quadratures::default(),
            own: false,
            factorisation: None,
            dense_start: zero.clone(),
            dense_stages: four(),
            span: (0.0, 0.0),
            stats: Stats::default(),
            work: LinearAlgebraWork::default(),
        }
    }

    /// Starts with a step of `h` (s) instead of Hairer's heuristic: with
    /// `max_step = h` and loose tolerances, a fixed-step method (for
    /// measuring its order).
    pub fn with_first_step(mut self, h: f64) -> Self {
        self.control.h = h;
        self
    }

    /// Jacobians and factorisations so far.
    pub fn work(&self) -> LinearAlgebraWork {
        self.work
    }

    /// `J` at `(t, y)`, whose slope is `f0`: the system's own, or forward
    /// differences (but for the quadratures' columns: nothing reads them);
    /// the quadratures' rows and columns zero.
    fn compute_jacobian(
        &mut self,
        system: &mut dyn OdeSystem,
        t: f64,
        y: &DVector<f64>,
    ) -> Result<(), SimulationError> {
        self.work.jacobians += 1;
        self.factorisation = None;
        if let Some(own) = system.implicit() {
            own.linearise(t, y.as_slice())?;
            self.own = true;
            self.jacobian_age = Some(0);
            return Ok(());
        }
        self.own = false;
        let n = y.len();
        if system.jacobian(t, y.as_slice(), self.f0.as_slice(), &mut self.jacobian)? {
            if !super::all_finite(&self.jacobian) {
                return Err(SimulationError::NonFinite {
                    t,
                    what: "the Jacobian",
                });
            }
        } else {
            let quadratures = &self.quadratures;
            forward_jacobian(
                system,
                &mut self.stats,
                (t, y, &self.f0),
                |j| quadratures.contains(j),
                &mut self.argument,
                &mut self.slope,
                &mut self.jacobian,
            )?;
        }
        for (j, column) in self.jacobian.chunks_exact_mut(n).enumerate() {
            for (i, c) in column.iter_mut().enumerate() {
                if self.quadratures.contains(i) || self.quadratures.contains(j) {
                    *c = 0.0;
                }
            }
        }
        self.jacobian_age = Some(0);
        Ok(())
    }

    /// Factorises `I − γ h J`; a singular matrix is an error (the step is
    /// rejected, and a shorter one makes it regular).
    fn factorise(
        &mut self,
        system: &mut dyn OdeSystem,
        t: f64,
        h: f64,
    ) -> Result<(), SimulationError> {
        if self.own {
            let own = system.implicit().ok_or(SimulationError::SingularMatrix {
                t,
                what: "I − γhW of the Rosenbrock-W step (the system's own solves went away)",
            })?;
            self.factorisation = None;
            own.factor(t, GAMMA * h)?;
            self.work.factorisations += 1;
            self.factorisation = Some((None, h));
            return Ok(());
        }
        let n = self.f0.len();
        let jacobian = &self.jacobian;
        let w = Mat::<f64>::from_fn(n, n, |i, j| {
            let identity = if i == j { 1.0 } else { 0.0 };
            identity - GAMMA * h * jacobian[j * n + i]
        });
        let lu = w.partial_piv_lu();
        self.work.factorisations += 1;
        let u = lu.U();
        let singular = (0..n).any(|i| {
            let p = u[(i, i)];
            p == 0.0 || !p.is_finite()
        });
        if singular {
            self.factorisation = None;
            return Err(SimulationError::SingularMatrix {
                t,
                what: "I − γhJ of the Rosenbrock-W step",
            });
        }
        self.factorisation = Some((Some(lu), h));
        Ok(())
    }

    /// Makes the Jacobian and factorisation serve a step of length `h`.
    fn prepare(
        &mut self,
        system: &mut dyn OdeSystem,
        t: f64,
        y: &DVector<f64>,
        h: f64,
    ) -> Result<(), SimulationError> {
        // A system's own `W` is cheap to take again and keeps the step's
        // accuracy when fresh ([`JacobianReuse`]'s measurements): every
        // step; a dense Jacobian serves `max_age` steps.
        let max_age = if self.own { 1 } else { self.reuse.max_age };
        let stale = match self.jacobian_age {
            None => true,
            Some(age) => age >= max_age,
        };
        if stale {
            self.compute_jacobian(system, t, y)?;
        }
        let refactor = match &self.factorisation {
            None => true,
            Some((_, h_lu)) => {
                let ratio = h / h_lu;
                ratio > self.reuse.step_ratio || ratio * self.reuse.step_ratio < 1.0
            }
        };
        if refactor {
            self.factorise(system, t, h)?;
        }
        Ok(())
    }

    /// Tries one step of length `h` from `(t, y)`: the stages, the solution
    /// in `trial` and the error estimate's norm.
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
        let tab: &Transformed = &TRANSFORMED;
        let Some((lu, _)) = &self.factorisation else {
            unreachable!("prepare factorises before a step")
        };
        for i in 0..4 {
            let f = if i == 0 {
                &self.f0
            } else {
                self.argument.copy_from(y);
                for j in 0..i {
                    self.argument.axpy(tab.a[i][j], &self.stages[j], 1.0);
                }
                super::evaluate(
                    system,
                    &mut self.stats,
                    t + tab.time[i] * h,
                    &self.argument,
                    &mut self.slope,
                )?;
                &self.slope
            };
            // The right-hand side γ h f + γ Σ cᵢⱼ Uⱼ, solved in place.
            let (done, rest) = self.stages.split_at_mut(i);
            let u = &mut rest[0];
            u.copy_from(f);
            *u *= GAMMA * h;
            for (j, uj) in done.iter().enumerate() {
                u.axpy(GAMMA * tab.c[i][j], uj, 1.0);
            }
            match lu {
                Some(lu) => lu.solve_in_place(ColMut::from_slice_mut(u.as_mut_slice())),
                None => system
                    .implicit()
                    .expect("the system's own solves, factored")
                    .solve(t, u.as_mut_slice())?,
            }
            if !super::all_finite(u.as_slice()) {
                return Err(SimulationError::SingularMatrix {
                    t,
                    what: "I − γhJ of the Rosenbrock-W step",
                });
            }
        }
        self.trial.copy_from(y);
        self.error.fill(0.0);
        for i in 0..4 {
            self.trial.axpy(tab.m[i], &self.stages[i], 1.0);
            self.error.axpy(tab.error[i], &self.stages[i], 1.0);
        }
        Ok(step_error(
            &self.error,
            y,
            &self.trial,
            (self.atol, self.rtol),
            &self.quadratures,
        ))
    }

    /// Hairer's starting step from the slope alone (the explicit methods'
    /// heuristic without its second evaluation): `0.01 ‖y‖ / ‖f‖`, capped.
    fn initial_step(&self, y: &DVector<f64>) -> f64 {
        let tolerances = (self.atol, self.rtol);
        let d0 = live_rms(y, y, y, tolerances, &self.quadratures);
        let d1 = live_rms(&self.f0, y, y, tolerances, &self.quadratures);
        let h = if d0 < 1e-5 || d1 < 1e-5 || !d1.is_finite() {
            1e-6
        } else {
            0.01 * d0 / d1
        };
        h.min(self.control.max_step)
    }
}

impl Stepper for Ros34pw2 {
    fn step(
        &mut self,
        system: &mut dyn OdeSystem,
        t: &mut f64,
        y: &mut DVector<f64>,
        t_limit: f64,
    ) -> Result<(), SimulationError> {
        // Here, not with the Jacobian (which only `step` reaches, after
        // this): a system that solves its own linear systems has its books
        // weighted by their increment too.
        self.quadratures.ask(system, y.len());
        if !self.f_now {
            super::evaluate(system, &mut self.stats, *t, y, &mut self.f0)?;
            self.f_now = true;
        }
        if self.control.h == 0.0 {
            self.control.h = self.initial_step(y);
        }
        let mut rejected_last = false;
        loop {
            let h = self.control.next(*t, t_limit)?;
            let outcome = self
                .prepare(system, *t, y, h)
                .and_then(|()| self.attempt(system, *t, y, h));
            match outcome {
                Ok(err) if err <= 1.0 => {
                    self.control.accept(h, err, rejected_last);
                    self.span = (*t, *t + h);
                    *t += h;
                    std::mem::swap(y, &mut self.trial);
                    // Dense output keeps the start and the stages: the next
                    // attempt overwrites both scratch copies.
                    std::mem::swap(&mut self.dense_start, &mut self.trial);
                    std::mem::swap(&mut self.dense_stages, &mut self.stages);
                    self.stats.accepted += 1;
                    if let Some(age) = &mut self.jacobian_age {
                        *age += 1;
                    }
                    // The stages give no slope at the solution: the next
                    // step evaluates it (after any change between steps).
                    self.f_now = false;
                    return Ok(());
                }
                outcome => {
                    self.stats.rejected += 1;
                    rejected_last = true;
                    // A Jacobian that has served a step may be what failed:
                    // take a fresh one before shrinking further.
                    if self.jacobian_age.is_some_and(|age| age > 0) {
                        self.jacobian_age = None;
                    }
                    self.control.reject(*t, h, outcome)?;
                }
            }
        }
    }

    fn interpolate(&self, t: f64) -> DVector<f64> {
        let (t0, t1) = self.span;
        let h = t1 - t0;
        let theta = if h > 0.0 { (t - t0) / h } else { 1.0 };
        let d = &ROS34PW2.dense;
        // y(θ) = y₀ + Σᵢ Bᵢ(θ) kᵢ with k = Γ⁻¹ U.
        let b: [f64; 4] =
            std::array::from_fn(|i| theta * (d[i][0] + theta * (d[i][1] + theta * d[i][2])));
        let inv = &TRANSFORMED.gamma_inverse;
        let mut out = self.dense_start.clone();
        for (j, stage) in self.dense_stages.iter().enumerate() {
            let w: f64 = (j..4).map(|i| b[i] * inv[i][j]).sum();
            out.axpy(w, stage, 1.0);
        }
        out
    }

    fn restart(&mut self) {
        self.f_now = false;
        self.jacobian_age = None;
        self.factorisation = None;
        self.stats.restarts += 1;
    }

    fn stats(&self) -> Stats {
        Stats {
            implicit: self.stats.accepted,
            ..self.stats
        }
    }
}
