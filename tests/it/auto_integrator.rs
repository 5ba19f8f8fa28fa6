//! `Integrator::Auto`: the stiffness estimate it decides with, and the
//! decision.
//!
//! * The power iteration (`integrate::auto::stiffest_rate`) finds the
//!   dominant eigenvalue's magnitude of a linear system with a spread of
//!   real and complex eigenvalues, within 1 % (it converges as the ratio
//!   of the two largest magnitudes to the 40th power: 0.5⁴⁰ here).
//! * On a problem that turns stiff at t = 1.5 s (a slow mode and one whose
//!   rate jumps from 10 to 10⁵ /s) the checks at 0 and 1 s keep
//!   Bogacki-Shampine; the steps it then makes, held to 2.5e-5 s by the
//!   stiff mode, bring a check within `CHECK_AFTER_STEPS` that hands over
//!   to ROS34PW2 before 2 s. The run ends at the exact solution to 10 ×
//!   the tolerance (a global error of the local tolerance's order), in a
//!   fifth of the explicit method's steps or less.

use trackgen::integrate::{
    Integrator, OdeSystem, SimulationError, auto::CHECK_EVERY, auto::stiffest_rate,
};
use trackgen::nalgebra::DVector;
use trackgen::simulate::{Output, simulate};
use trackgen::system::Simulated;

/// `y' = A y` with `A` block-diagonal: real eigenvalues and one complex
/// pair `a ± b i`.
struct Linear {
    real: Vec<f64>,
    pair: (f64, f64),
}

impl OdeSystem for Linear {
    fn dimension(&self) -> usize {
        self.real.len() + 2
    }

    fn derivative(&mut self, _t: f64, y: &[f64], dy: &mut [f64]) -> Result<(), SimulationError> {
        let n = self.real.len();
        for i in 0..n {
            dy[i] = self.real[i] * y[i];
        }
        let (a, b) = self.pair;
        dy[n] = a * y[n] - b * y[n + 1];
        dy[n + 1] = b * y[n] + a * y[n + 1];
        Ok(())
    }
}

#[test]
fn the_power_iteration_finds_the_dominant_rate() {
    for (real, pair, want) in [
        (vec![-1.0, -30.0, -6000.0, -2.0], (-5.0, 400.0), 6000.0),
        (
            vec![-1.0, -30.0, -200.0],
            (-50.0, 1000.0),
            (50.0f64 * 50.0 + 1e6).sqrt(),
        ),
    ] {
        let mut system = Linear { real, pair };
        let y: Vec<f64> = (0..system.dimension()).map(|i| 1.0 + i as f64).collect();
        let got = stiffest_rate(&mut system, 0.0, &y).expect("evaluates");
        assert!(
            (got - want).abs() <= 0.01 * want,
            "stiffest rate {got}, the dominant eigenvalue's magnitude {want}"
        );
    }
}

/// `y₀' = −y₀` (slow) and `y₁' = −k(t) (y₁ − cos t) − sin t` with `k` 10
/// until 1.5 s and 10⁵ after: `y₁ = cos t` exactly from `y₁(0) = 1`.
struct TurnsStiff;

impl OdeSystem for TurnsStiff {
    fn dimension(&self) -> usize {
        2
    }

    fn derivative(&mut self, t: f64, y: &[f64], dy: &mut [f64]) -> Result<(), SimulationError> {
        let k = if t < 1.5 { 10.0 } else { 1e5 };
        dy[0] = -y[0];
        dy[1] = -k * (y[1] - t.cos()) - t.sin();
        Ok(())
    }
}

impl Simulated for TurnsStiff {
    fn initial_state(&self) -> DVector<f64> {
        DVector::from_vec(vec![1.0, 1.0])
    }

    fn columns(&self) -> Vec<String> {
        vec!["slow".into(), "stiff".into()]
    }

    fn observe(&mut self, _t: f64, y: &[f64], row: &mut Vec<f64>) -> Result<(), SimulationError> {
        row.extend_from_slice(y);
        Ok(())
    }
}

#[test]
fn auto_hands_over_when_the_problem_turns_stiff() {
    let tol = 1e-6;
    let end = 4.0;
    let auto = Integrator::Auto {
        explicit_tolerance: tol,
        implicit_tolerance: tol,
        max_step: 0.1,
    };
    let results = simulate(&mut TurnsStiff, auto, 0.0, end, Output::Every(0.5)).expect("runs");
    let checks = &results.checks;
    assert_eq!(CHECK_EVERY, 1.0);
    let before: Vec<_> = checks.iter().filter(|c| c.t < 1.5).collect();
    assert!(
        before.len() >= 2 && before.iter().all(|c| !c.implicit),
        "{checks:?}"
    );
    let turned = checks
        .iter()
        .find(|c| c.t >= 1.5)
        .expect("a check after 1.5 s");
    assert!(turned.implicit && turned.t < 1.6, "{checks:?}");
    assert!(
        checks.iter().filter(|c| c.t >= 1.5).all(|c| c.implicit),
        "{checks:?}"
    );
    let last = results.last().expect("a row");
    let (slow, stiff) = (last.get("slow").unwrap(), last.get("stiff").unwrap());
    assert!((slow - (-end).exp()).abs() <= 10.0 * tol, "slow {slow}");
    assert!((stiff - end.cos()).abs() <= 10.0 * tol, "stiff {stiff}");
    let explicit = simulate(
        &mut TurnsStiff,
        Integrator::Bs23 {
            rtol: tol,
            atol: tol,
            max_step: 0.1,
        },
        0.0,
        end,
        Output::Every(0.5),
    )
    .expect("runs");
    println!(
        "auto: {} steps ({} implicit); Bogacki-Shampine alone: {}",
        results.stats.accepted, results.stats.implicit, explicit.stats.accepted
    );
    assert!(results.stats.implicit > 0);
    assert!(5 * results.stats.accepted < explicit.stats.accepted);
}
