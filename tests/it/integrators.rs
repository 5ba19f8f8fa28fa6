//! The integrators: order of convergence, dense output, stiffness, and
//! failures that stop a run with a typed error and keep its results.
//!
//! The accuracy tests need an exact answer that is not one of the
//! integrators under test. A chain falling freely has one in closed form,
//! from any state: its centre of mass accelerates at exactly `g`
//! (`R_cm(t) = R_cm + V_cm t + ½ g t²`) and its angular momentum about the
//! centre of mass is constant, whatever the links do relative to each
//! other. The errors below are those of `R_cm`, `V_cm` and `L_cm`, computed
//! from the integrated state (nonlinear in the angles, so they carry the
//! generic error of the method: measured, they converge at exactly the
//! method's order).
//!
//! Tolerances, each with its measured value:
//! * order (RK4, ROS2): the error ratio when the step halves is `2^p`
//!   within ±5 %: the next term of the error expansion moves it by
//!   `O(h)`, measured at most 0.4 % (RK4) and 1.9 % (ROS2) off; a method
//!   one order off is a factor 2 away.
//! * Dormand-Prince dense output, at fixed steps: the worst error between
//!   steps against the exact flow from the step's start falls by `2^5 = 32`
//!   ±15 % per halving (a fourth-order continuous extension has local error
//!   `O(h⁵)`; measured 31.1 … 32.3), where the cubic Hermite interpolant of
//!   the same step end points falls by 16 (measured 15.3 … 16.0), and the
//!   dense output beats that Hermite interpolant by at least 20× (measured
//!   35× … 331×).
//! * Bogacki-Shampine: global error proportional to the tolerance (1000×
//!   tighter: more than 100× smaller, measured 916× … 995×), dense output
//!   within 5 × tol of the exact motion (measured at most 0.83 × tol).

use crate::support;

use support::max_of;
use trackgen::closure::{
    ClosureError, ClosureMethod, PartitionOptions, RecoveryError, multipliers,
};
use trackgen::integrate::{Integrator, OdeSystem, SimulationError};
use trackgen::laws::PenaltyJoint;
use trackgen::multibody::{BodyLoad, RecursiveModel};
use trackgen::nalgebra::{DVector, SVector, Vector2};
use trackgen::simulate::{Output, simulate};
use trackgen::system::{Simulated, TrackSystem, TreeSystem};

/// Gravity of the tumbler, declared explicitly: the exact solution uses it.
const GRAVITY: Vector2<f64> = Vector2::new(0.0, -9.81);

trackgen::model! {
    /// A three-link open chain, tumbling under gravity: smooth motion.
    pub track Tumbler {
        links: 3,
        link { mass: 2.0, inertia: 0.02, u1: (-0.15, 0.0), u2: (0.15, 0.0) },
        link[2] { mass: 3.0, inertia: 0.05, u1: (-0.1, 0.02) },
        closure: open,
        gravity: (0.0, -9.81),
    }

    /// A six-link loop for the stiff and failure cases.
    pub track Loop6 {
        links: 6,
        link { mass: 1.0, inertia: 0.01, u1: (-0.1, 0.0), u2: (0.1, 0.0) },
    }
}

fn tumbler_start() -> (SVector<f64, 5>, SVector<f64, 5>) {
    (
        SVector::from([0.0, 0.0, 0.3, 1.2, -0.4]),
        SVector::from([0.5, 2.0, 3.0, -2.0, 4.0]),
    )
}

/// The tumbler's state `[q_i, q̇_i]` at the start.
fn tumbler_state() -> Vec<f64> {
    let (q, qd) = tumbler_start();
    q.iter().chain(qd.iter()).copied().collect()
}

/// The motion of the tumbler's centre of mass: its position, velocity, and
/// the angular momentum about it.
#[derive(Debug, Clone, Copy)]
struct CentreOfMass {
    r: Vector2<f64>,
    v: Vector2<f64>,
    l: f64,
}

impl CentreOfMass {
    /// At the state `y = [q_i, q̇_i]` (the first 10 recorded columns), from
    /// the generated body positions and velocities and the declared masses.
    fn of(y: &[f64]) -> Self {
        let q = SVector::<f64, 5>::from_column_slice(&y[..5]);
        let qd = SVector::<f64, 5>::from_column_slice(&y[5..10]);
        let (mut r, mut v) = ([Vector2::zeros(); 3], [Vector2::zeros(); 3]);
        Tumbler.body_positions(&q, &mut r);
        Tumbler.body_velocities(&q, &qd, &mut v);
        let bodies = Tumbler.description().bodies;
        let mass: f64 = bodies.iter().map(|b| b.mass).sum();
        let weigh = |x: &[Vector2<f64>]| {
            bodies
                .iter()
                .zip(x)
                .map(|(b, x)| x * b.mass)
                .sum::<Vector2<f64>>()
                / mass
        };
        let (rc, vc) = (weigh(&r), weigh(&v));
        let l = (0..3)
            .map(|b| {
                let (dr, dv) = (r[b] - rc, v[b] - vc);
                bodies[b].mass * (dr.x * dv.y - dr.y * dv.x) + bodies[b].inertia * qd[2 + b]
            })
            .sum();
        CentreOfMass { r: rc, v: vc, l }
    }

    /// The exact motion `tau` seconds later: free fall in uniform gravity.
    fn after(&self, tau: f64) -> Self {
        CentreOfMass {
            r: self.r + self.v * tau + GRAVITY * (0.5 * tau * tau),
            v: self.v + GRAVITY * tau,
            l: self.l,
        }
    }

    /// `[|ΔR|, |ΔV|, |ΔL|]` against the exact motion.
    fn errors(&self, exact: &Self) -> [f64; 3] {
        [
            (self.r - exact.r).norm(),
            (self.v - exact.v).norm(),
            (self.l - exact.l).abs(),
        ]
    }
}

/// The errors of `R_cm`, `V_cm`, `L_cm` at t = 1 s against the free fall.
fn free_fall_errors(integrator: Integrator) -> [f64; 3] {
    let (q, qd) = tumbler_start();
    let mut system = TreeSystem::new(Tumbler, q, qd);
    let results = simulate(&mut system, integrator, 0.0, 1.0, Output::Times(vec![1.0])).unwrap();
    assert_eq!(results.last().unwrap().t, 1.0);
    let exact = CentreOfMass::of(&tumbler_state()).after(1.0);
    CentreOfMass::of(&results.last().unwrap().values[..10]).errors(&exact)
}

/// Error ratios of `R_cm`, `V_cm`, `L_cm` when the step halves: 2^p for a
/// method of order p.
fn ratios(steps: [f64; 3], make: impl Fn(f64) -> Integrator) -> Vec<[f64; 3]> {
    let errors: Vec<[f64; 3]> = steps.iter().map(|&h| free_fall_errors(make(h))).collect();
    errors
        .windows(2)
        .map(|w| [0, 1, 2].map(|i| w[0][i] / w[1][i]))
        .collect()
}

/// Test 6: RK4 is fourth order: ratio 16 within ±5 % for each of
/// `R_cm`, `V_cm`, `L_cm` (measured 15.94 … 16.00 at steps of 5, 2.5 and
/// 1.25 ms; the smallest error, 5.9e-12 in `L_cm`, is still far above
/// rounding).
#[test]
fn rk4_converges_at_fourth_order() {
    for r in ratios([0.005, 0.0025, 0.00125], |step| Integrator::Rk4 { step })
        .into_iter()
        .flatten()
    {
        assert!((r - 16.0).abs() < 0.05 * 16.0, "ratio {r}");
    }
}

/// ROS2 is second order whatever its Jacobian: ratio 4 within ±5 % for
/// each of `R_cm`, `V_cm`, `L_cm` (measured 3.92 … 3.99 at steps of 2.5,
/// 1.25 and 0.625 ms: it approaches 4 from below).
#[test]
fn rosenbrock_converges_at_second_order() {
    for r in ratios([0.0025, 0.00125, 0.000625], |step| {
        Integrator::Rosenbrock2 { step }
    })
    .into_iter()
    .flatten()
    {
        assert!((r - 4.0).abs() < 0.05 * 4.0, "ratio {r}");
    }
}

/// Dormand-Prince's dense output is its fourth-order continuous extension,
/// not something cheaper. At fixed steps `h` (tolerance 1, so `max_step`
/// sets every step), the dense output at five points inside every step is
/// compared with the exact free fall from the step's start (so the error
/// is the interpolant's, not the accumulated global error), and so is the
/// cubic Hermite interpolant of the same step's end points and slopes.
/// The continuous extension's local error is `O(h⁵)`: its worst error
/// falls 32× per halving of `h` (±15 %; measured 31.1 … 32.3); Hermite's
/// is `O(h⁴)` and falls 16× (measured 15.3 … 16.0); and the dense output
/// is at least 20× more accurate than Hermite at every `h` (measured 35×
/// at 20 ms in `V_cm`, up to 331× at 5 ms in `R_cm`). Worst dense-output
/// errors at 5 ms: 4.0e-12 m, 1.9e-10 m/s, 2.6e-11 kg m²/s.
#[test]
fn dopri5_dense_output_is_its_fourth_order_extension() {
    const THETAS: [f64; 5] = [0.2, 0.4, 0.5, 0.6, 0.8];
    let (q, qd) = tumbler_start();
    // Per step length: the worst errors of R_cm, V_cm, L_cm, for the dense
    // output and for Hermite.
    let mut worst: Vec<([f64; 3], [f64; 3])> = Vec::new();
    for h in [0.02, 0.01, 0.005] {
        let integrator = Integrator::Dopri5 {
            rtol: 1.0,
            atol: 1.0,
            max_step: h,
        };
        let run = |output| {
            let mut system = TreeSystem::new(Tumbler, q, qd);
            simulate(&mut system, integrator, 0.0, 1.0, output).unwrap()
        };
        // The step end points: every step is h long.
        let steps = run(Output::Steps);
        let n = (1.0 / h).round() as usize;
        assert_eq!(steps.len(), n + 1);
        assert_eq!(steps.stats.rejected, 0);
        for (k, s) in steps.iter().enumerate() {
            assert!(
                (s.t - k as f64 * h).abs() < 1e-12,
                "step {k} ends at {}",
                s.t
            );
        }
        // The same run, sampled inside every step by dense output.
        let times: Vec<f64> = (0..n)
            .flat_map(|k| THETAS.map(|s| (k as f64 + s) * h))
            .collect();
        let dense = run(Output::Times(times.clone()));
        assert_eq!(dense.stats, steps.stats, "the same steps");
        assert_eq!(dense.times(), &times[..]);
        let mut system = TreeSystem::new(Tumbler, q, qd);
        let mut slope = |t: f64, y: &[f64]| {
            let mut f = DVector::zeros(10);
            system.derivative(t, y, f.as_mut_slice()).unwrap();
            f
        };
        let (mut dense_errors, mut hermite_errors) = (Vec::new(), Vec::new());
        for k in 0..n {
            let (t0, t1) = (steps.sample(k).t, steps.sample(k + 1).t);
            let (y0, y1) = (
                &steps.sample(k).values[..10],
                &steps.sample(k + 1).values[..10],
            );
            let (f0, f1) = (slope(t0, y0), slope(t1, y1));
            let start = CentreOfMass::of(y0);
            for (j, s) in THETAS.into_iter().enumerate() {
                let sample = dense.sample(THETAS.len() * k + j);
                let exact = start.after(sample.t - t0);
                dense_errors.push(CentreOfMass::of(&sample.values[..10]).errors(&exact));
                let (s2, s3) = (s * s, s * s * s);
                let hermite: Vec<f64> = (0..10)
                    .map(|i| {
                        y0[i] * (2.0 * s3 - 3.0 * s2 + 1.0)
                            + f0[i] * ((s3 - 2.0 * s2 + s) * h)
                            + y1[i] * (-2.0 * s3 + 3.0 * s2)
                            + f1[i] * ((s3 - s2) * h)
                    })
                    .collect();
                hermite_errors.push(CentreOfMass::of(&hermite).errors(&exact));
            }
        }
        let max = |e: &[[f64; 3]]| [0, 1, 2].map(|i| max_of(e.iter().map(|e| e[i])));
        let (d, m) = (max(&dense_errors), max(&hermite_errors));
        for i in 0..3 {
            assert!(
                d[i] * 20.0 < m[i],
                "h = {h}: dense output error {:e} against Hermite's {:e}",
                d[i],
                m[i]
            );
        }
        worst.push((d, m));
    }
    for w in worst.windows(2) {
        for i in 0..3 {
            let (dense, hermite) = (w[0].0[i] / w[1].0[i], w[0].1[i] / w[1].1[i]);
            assert!(
                (dense - 32.0).abs() < 0.15 * 32.0,
                "dense output error ratio {dense} (quantity {i})"
            );
            assert!(
                (hermite - 16.0).abs() < 0.15 * 16.0,
                "Hermite error ratio {hermite} (quantity {i})"
            );
        }
    }
}

fn loop6_start() -> (SVector<f64, 8>, SVector<f64, 8>) {
    let mut q = SVector::<f64, 8>::zeros();
    for i in 0..6 {
        q[2 + i] = std::f64::consts::PI * i as f64 / 3.0;
    }
    let mut qd = SVector::<f64, 8>::from_fn(|i, _| [0.0, 0.0, 1.0, -2.0, 0.5, 1.5, -1.0, 0.3][i]);
    multipliers::project(&Loop6, &mut q, &mut qd, 1e-14).unwrap();
    (q, qd)
}

/// A very stiff penalty joint (k = 1e9 N/m on 1 kg links: a period of
/// 0.2 ms): RK4 at 2 ms diverges and stops with a typed error; the
/// L-stable ROS2 at the same step completes with the loop closed and the
/// energy bounded (measured within 7 % over 1 s: ROS2 is second order and
/// damps the unresolved spring mode; 10 % allowed).
#[test]
fn stiff_penalty_needs_the_implicit_method() {
    let (q, qd) = loop6_start();
    let method = ClosureMethod::Penalty(PenaltyJoint {
        stiffness: 1e9,
        damping: 0.0,
    });
    let mut explicit = TrackSystem::new(Loop6, q, qd, method).unwrap();
    let failure = simulate(
        &mut explicit,
        Integrator::Rk4 { step: 2e-3 },
        0.0,
        1.0,
        Output::Every(0.01),
    )
    .unwrap_err();
    assert!(
        matches!(failure.error, SimulationError::NonFinite { .. }),
        "{}",
        failure.error
    );
    assert!(failure.error.time().unwrap() < 1.0);

    let mut implicit = TrackSystem::new(Loop6, q, qd, method).unwrap();
    let results = simulate(
        &mut implicit,
        Integrator::Rosenbrock2 { step: 2e-3 },
        0.0,
        1.0,
        Output::Every(0.01),
    )
    .unwrap();
    let energy = results.column("energy").unwrap();
    let gap = max_of(results.column("closure_error").unwrap());
    assert!(
        energy
            .iter()
            .all(|e| (e - energy[0]).abs() < 0.1 * energy[0].abs().max(1.0)),
        "energy {energy:?}"
    );
    assert!(gap < 1e-6, "gap {gap}");
}

/// A load that turns NaN at t = 0.3 s: the run stops there with a typed
/// error carrying the time, and every sample before it is kept.
#[test]
fn non_finite_loads_stop_the_run_and_keep_results() {
    let (q, qd) = loop6_start();
    for integrator in [Integrator::Rk4 { step: 1e-3 }, Integrator::dopri5(1e-9)] {
        let mut system = TrackSystem::new(Loop6, q, qd, ClosureMethod::Declared)
            .unwrap()
            .with_loads(|t, _, _, loads: &mut [BodyLoad]| {
                loads[2].moment = if t < 0.3 { 1.0 } else { f64::NAN };
            });
        let failure = simulate(&mut system, integrator, 0.0, 1.0, Output::Every(0.01)).unwrap_err();
        let t = failure.error.time().unwrap();
        assert!(
            (0.299..0.302).contains(&t),
            "{integrator:?}: stopped at {t}: {}",
            failure.error
        );
        let root = match &failure.error {
            SimulationError::StepSizeUnderflow {
                cause: Some(cause), ..
            } => cause.as_ref(),
            e => e,
        };
        assert!(
            matches!(
                root,
                SimulationError::NonFinite { .. }
                    | SimulationError::Recovery(RecoveryError::NewtonFailed { .. })
            ),
            "{}",
            failure.error
        );
        // Every sample up to 0.29 is kept (0.30 too when a step could end
        // within rounding of it), none past the failure.
        let n = failure.results.len();
        assert!(
            (30..=31).contains(&n) && failure.results.last().unwrap().t <= t,
            "{n} samples"
        );
        assert!(
            failure
                .results
                .iter()
                .all(|s| s.values.iter().all(|v| v.is_finite()))
        );
    }
}

/// An inconsistent start that Newton-Raphson cannot close in one
/// iteration is a typed error at t = 0, not a panic.
#[test]
fn newton_failure_is_a_typed_error() {
    let q = SVector::<f64, 8>::from_fn(|i, _| if i < 2 { 0.0 } else { 0.1 * i as f64 });
    let options = PartitionOptions {
        newton_max_iterations: 1,
        ..Default::default()
    };
    let result = TrackSystem::new(
        Loop6,
        q,
        SVector::zeros(),
        ClosureMethod::Partitioning(options),
    );
    assert!(matches!(
        result,
        Err(ClosureError::StartNotClosed { iterations: 1, .. })
    ));
}

/// Results write a CSV with a header and one row per sample.
#[test]
fn results_write_csv() {
    let (q, qd) = loop6_start();
    let mut system = TrackSystem::new(Loop6, q, qd, ClosureMethod::Declared).unwrap();
    let results = simulate(
        &mut system,
        Integrator::dopri5(1e-9),
        0.0,
        0.1,
        Output::Every(0.05),
    )
    .unwrap();
    let mut bytes = Vec::new();
    results.write_csv(&mut bytes).unwrap();
    let text = String::from_utf8(bytes).unwrap();
    let lines: Vec<&str> = text.lines().collect();
    assert_eq!(lines.len(), 4);
    assert!(lines[0].starts_with("t,x,y,theta_1,"));
    assert_eq!(lines[0].split(',').count(), 1 + results.columns().len());
    assert!(lines[3].starts_with("0.1,"));
}

/// Settings that would hang a run or make it meaningless are set-up
/// errors, before any step.
#[test]
fn bad_settings_are_setup_errors() {
    let (q, qd) = loop6_start();
    let cases = [
        (Integrator::Rk4 { step: 0.0 }, 0.0, 1.0, Output::Every(0.01)),
        (
            Integrator::Rk4 { step: f64::NAN },
            0.0,
            1.0,
            Output::Every(0.01),
        ),
        (Integrator::dopri5(0.0), 0.0, 1.0, Output::Every(0.01)),
        (Integrator::dopri5(1e-9), 0.0, 1.0, Output::Every(-0.01)),
        (Integrator::dopri5(1e-9), 1.0, 0.0, Output::Steps),
        (Integrator::dopri5(1e-9), 0.0, f64::INFINITY, Output::Steps),
        (
            Integrator::dopri5(1e-9),
            0.0,
            1.0,
            Output::Times(vec![0.5, 0.2]),
        ),
    ];
    for (integrator, t0, t_end, output) in cases {
        let mut system = TrackSystem::new(Loop6, q, qd, ClosureMethod::Declared).unwrap();
        let failure = simulate(&mut system, integrator, t0, t_end, output).unwrap_err();
        assert!(
            matches!(failure.error, SimulationError::Settings(_)),
            "{integrator:?}: {}",
            failure.error
        );
        assert!(failure.results.is_empty());
    }
}

/// Bogacki-Shampine 3(2) on the same engine, against the free fall: its
/// global error at t = 1 s follows the tolerance (a thousandfold tighter
/// tolerance, at least a hundredfold smaller error in each of `R_cm`,
/// `V_cm`, `L_cm`: measured 916× … 995×), and its dense output (cubic
/// Hermite) stays within 5 × tol of the exact motion at every 10 ms sample
/// (measured at most 0.83 × tol, at both tolerances; steps of ~8 ms at
/// 1e-6, where linear interpolation would be off by ~1e-4).
#[test]
fn bogacki_shampine_follows_its_tolerance() {
    let bs23 = |tol: f64| Integrator::Bs23 {
        rtol: tol,
        atol: tol,
        max_step: f64::INFINITY,
    };
    let (loose, tight) = (free_fall_errors(bs23(1e-6)), free_fall_errors(bs23(1e-9)));
    for i in 0..3 {
        assert!(
            tight[i] < loose[i] / 100.0,
            "errors {loose:?} at 1e-6, {tight:?} at 1e-9"
        );
    }
    let (q, qd) = tumbler_start();
    let start = CentreOfMass::of(&tumbler_state());
    for tol in [1e-6, 1e-9] {
        let mut system = TreeSystem::new(Tumbler, q, qd);
        let run = simulate(&mut system, bs23(tol), 0.0, 1.0, Output::Every(0.01)).unwrap();
        assert_eq!(run.len(), 101);
        let worst = max_of(
            run.iter()
                .flat_map(|s| CentreOfMass::of(&s.values[..10]).errors(&start.after(s.t))),
        );
        assert!(
            worst < 5.0 * tol,
            "tol {tol}: dense output off by {worst:e}"
        );
    }
}

/// A damped oscillator with its books (`y₂`: the work its damper
/// dissipates), and with a passive quadrature besides (`y₃ = ∫ x² dt`) or
/// without it.
struct Oscillating {
    passive: bool,
}

impl OdeSystem for Oscillating {
    fn dimension(&self) -> usize {
        if self.passive { 4 } else { 3 }
    }

    fn derivative(&mut self, _t: f64, y: &[f64], dy: &mut [f64]) -> Result<(), SimulationError> {
        dy[0] = y[1];
        dy[1] = -40.0 * y[0] - 0.3 * y[1];
        dy[2] = 0.3 * y[1] * y[1];
        if self.passive {
            dy[3] = y[0] * y[0];
        }
        Ok(())
    }

    fn is_quadrature(&self, i: usize) -> bool {
        i >= 2
    }

    fn is_passive(&self, i: usize) -> bool {
        i == 3
    }
}

impl Simulated for Oscillating {
    fn initial_state(&self) -> DVector<f64> {
        DVector::from_vec(vec![1.0, 0.0, 0.0, 0.0][..self.dimension()].to_vec())
    }

    fn columns(&self) -> Vec<String> {
        ["x", "v", "dissipated", "passive"][..self.dimension()]
            .iter()
            .map(|c| c.to_string())
            .collect()
    }

    fn observe(&mut self, _t: f64, y: &[f64], row: &mut Vec<f64>) -> Result<(), SimulationError> {
        row.extend_from_slice(y);
        Ok(())
    }
}

/// A passive quadrature (`OdeSystem::is_passive`) changes no step: with
/// it and without it every method takes the same steps to the same bits
/// (the norms leave it out, and a zero term changes no sum), and it is
/// still integrated: `∫ x² dt` against the trapezoidal sum of the rows
/// every 1 ms, whose error is at most `T h² max|(x²)''| / 12` with
/// `|(x²)''| = 2 |v² + x a| ≤ 160` here: 6.7e-5 over 5 s; 1e-4 allowed.
#[test]
fn a_passive_quadrature_changes_no_step() {
    for integrator in [
        Integrator::Bs23 {
            rtol: 1e-6,
            atol: 1e-6,
            max_step: 0.05,
        },
        Integrator::Dopri5 {
            rtol: 1e-6,
            atol: 1e-6,
            max_step: 0.05,
        },
        Integrator::Ros34pw2 {
            rtol: 1e-6,
            atol: 1e-6,
            max_step: 0.05,
        },
    ] {
        let run = |passive| {
            simulate(
                &mut Oscillating { passive },
                integrator,
                0.0,
                5.0,
                Output::Every(0.001),
            )
            .expect("runs")
        };
        let (with, without) = (run(true), run(false));
        assert_eq!(with.stats, without.stats, "{integrator:?}");
        for name in ["x", "v", "dissipated"] {
            assert_eq!(
                with.column(name),
                without.column(name),
                "{integrator:?}: {name}"
            );
        }
        let (t, x) = (with.times(), with.column("x").unwrap());
        let trapezoid: f64 = (1..t.len())
            .map(|i| 0.5 * (x[i] * x[i] + x[i - 1] * x[i - 1]) * (t[i] - t[i - 1]))
            .sum();
        let passive = with.last().unwrap().get("passive").unwrap();
        assert!(
            (passive - trapezoid).abs() < 1e-4,
            "{integrator:?}: {passive} against {trapezoid}"
        );
    }
}
