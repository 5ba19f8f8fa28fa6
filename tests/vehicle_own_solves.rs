//! The vehicle's own linear solves for the linearly implicit integrator
//! (`ImplicitSolve`: `(I − a W) x = b` with `W` the force elements'
//! Jacobians through the mass matrix, solved in O(n)), on the M113 and the
//! Marder:
//!
//! * **W is the Jacobian where it is exact.** At rest (the assembled
//!   start) the velocity terms vanish, so `∂f/∂v`, `∂f/∂w` (the ground's
//!   deflections) and `∂f/∂s` (the drive's integral) of the right-hand
//!   side are exactly `W`'s: every such column against central
//!   differences of the right-hand side (`analysis::state_jacobian`, good
//!   to about 1e-7 of a column's scale; bound 1e-5 of it). `W` is read off
//!   the solves themselves, `(x(a) − b)/a` at two tiny shifts combined by
//!   Richardson (`W b + O(a² W³ b)`: 1e-8 relative at `a|λ| ~ 1e-4`).
//! * **The solve is that W's**, at the shifts a step uses (`a|λ|` up to
//!   10): `(I − a W) x = b` for random `b`, with `W` read off as above.
//!   The residual is measured against the largest of its terms (`b`, `x`,
//!   `a W x`; `x` reaches 10⁴ `|b|` where `b` moves a contact), of which
//!   it is 1e-9 (`W`'s own error): bound 1e-6.
//! * **W holds the stiff modes.** At a state driving at 2 m/s the stiffest
//!   eigenvalues of the right-hand side's Jacobian (central differences,
//!   every state with dynamics) and of `W`: the five stiffest within 5 %
//!   (W leaves out only the inertia's derivatives, whose rates are the
//!   bodies' turning rates, tens per second, against thousands here).

mod support;

use support::Lcg;
use trackgen::analysis::state_jacobian;
use trackgen::contact::Terrain;
use trackgen::integrate::{ImplicitSolve, Integrator, OdeSystem};
use trackgen::nalgebra::{DMatrix, DVector};
use trackgen::simulate::Simulated;
use trackgen::vehicle::build;
use trackgen::vehicles::m113::M113;
use trackgen::vehicles::marder::Marder;
use trackgen::{Vehicle, VehicleDynamics};

fn own(system: &mut impl OdeSystem) -> &mut dyn ImplicitSolve {
    system
        .implicit()
        .expect("a vehicle on rigid ground, closed by partitioning, solves its own")
}

/// `W` read off the solves at `(t, y)`: `(x(a) − e)/a` for every unit
/// vector, at `a` and `2a`, combined by Richardson.
fn own_matrix(system: &mut impl OdeSystem, t: f64, y: &[f64], a: f64) -> DMatrix<f64> {
    let n = y.len();
    own(system).linearise(t, y).expect("linearises");
    let mut columns = [DMatrix::zeros(n, n), DMatrix::zeros(n, n)];
    for (k, shift) in [a, 2.0 * a].into_iter().enumerate() {
        own(system).factor(t, shift).expect("factors");
        for j in 0..n {
            let mut x = vec![0.0; n];
            x[j] = 1.0;
            own(system).solve(t, &mut x).expect("solves");
            x[j] -= 1.0;
            for (i, v) in x.iter().enumerate() {
                columns[k][(i, j)] = v / shift;
            }
        }
    }
    &columns[0] * 2.0 - &columns[1]
}

/// A state of `V` driving from rest toward 2 m/s for `duration` s (0: the
/// assembled start, at rest).
fn state<V: Vehicle>(duration: f64) -> (V::System, f64, DVector<f64>) {
    let config = V::config(
        Terrain::Flat { height: 0.0 },
        V::speed_drive(|t| 2.0 * (t / 1.0).min(1.0)),
    );
    let mut system = build::<V>(config).expect("builds");
    let mut y = system.initial_state();
    if duration > 0.0 {
        let integrator = Integrator::Bs23 {
            rtol: 1e-4,
            atol: 1e-4,
            max_step: 0.01,
        };
        let mut stepper = integrator.stepper(system.dimension());
        let mut t = 0.0;
        while t < duration {
            stepper
                .step(&mut system, &mut t, &mut y, duration)
                .expect("steps");
            if system
                .after_step(t, y.as_mut_slice(), &mut |_| {})
                .expect("after a step")
            {
                stepper.restart();
            }
        }
    }
    (system, duration, y)
}

fn at_rest<V: Vehicle>() {
    let (mut system, t, y) = state::<V>(0.0);
    let layout = system.layout();
    let mut columns: Vec<usize> = layout.rates().collect();
    columns.push(layout.integral);
    columns.extend(layout.tangential.clone());
    let books = layout.books;
    let w = own_matrix(&mut system, t, y.as_slice(), 1e-9);
    let j = state_jacobian(&mut system, t, y.as_slice(), &columns).expect("differences");
    for (c, &column) in columns.iter().enumerate() {
        let rows: Vec<usize> = (0..y.len()).filter(|r| !books.contains(r)).collect();
        let scale = rows
            .iter()
            .map(|&r| j[(r, c)].abs())
            .fold(0.0, f64::max)
            .max(1e-12);
        for &r in &rows {
            let (got, want) = (w[(r, column)], j[(r, c)]);
            assert!(
                (got - want).abs() <= 1e-5 * scale,
                "{}: ∂f{r}/∂y{column}: W {got:e}, differences {want:e} (column scale {scale:e})",
                V::NAME
            );
        }
    }
}

#[test]
fn at_rest_w_is_the_jacobian_of_rates_deflections_and_integral() {
    at_rest::<M113>();
    at_rest::<Marder>();
}

#[test]
fn the_solve_is_its_own_w_at_a_steps_shift() {
    let (mut system, t, y) = state::<Marder>(1.5);
    let n = y.len();
    let w = own_matrix(&mut system, t, y.as_slice(), 1e-9);
    let mut rng = Lcg::new(5);
    for a in [1e-5, 1e-4, 1e-3] {
        own(&mut system).factor(t, a).expect("factors");
        for _ in 0..3 {
            let b = DVector::from_fn(n, |_, _| rng.uniform(-1.0, 1.0));
            let mut x = b.clone();
            own(&mut system).solve(t, x.as_mut_slice()).expect("solves");
            let wx = &w * &x * a;
            let residual = &x - &wx - &b;
            let scale = b.amax().max(x.amax()).max(wx.amax());
            println!(
                "a = {a}: |b| {:.2e}, |x| {:.2e}, |aWx| {:.2e}, residual {:.2e}",
                b.amax(),
                x.amax(),
                wx.amax(),
                residual.amax()
            );
            assert!(
                residual.amax() <= 1e-6 * scale,
                "a = {a}: (I − aW) x − b = {:e} against terms of {scale:e}",
                residual.amax()
            );
        }
    }
}

/// The `count` stiffest eigenvalues (most negative real part first).
fn stiffest(m: &DMatrix<f64>, count: usize) -> Vec<f64> {
    let n = m.nrows();
    let dense = faer::Mat::<f64>::from_fn(n, n, |i, j| m[(i, j)]);
    let values = dense.eigenvalues().expect("eigenvalues");
    let mut re: Vec<f64> = values.iter().map(|v| v.re).collect();
    re.sort_by(|a, b| a.total_cmp(b));
    re.truncate(count);
    re
}

#[test]
fn w_holds_the_stiffest_modes() {
    let (mut system, t, y) = state::<Marder>(1.5);
    let states: Vec<usize> = system.layout().dynamic().collect();
    let w = own_matrix(&mut system, t, y.as_slice(), 1e-9)
        .select_rows(&states)
        .select_columns(&states);
    let j = state_jacobian(&mut system, t, y.as_slice(), &states)
        .expect("differences")
        .select_rows(&states);
    let (ew, ej) = (stiffest(&w, 5), stiffest(&j, 5));
    println!("stiffest eigenvalues (1/s): W {ew:.1?}, the Jacobian {ej:.1?}");
    for (a, b) in ew.iter().zip(&ej) {
        assert!(
            (a - b).abs() <= 0.05 * b.abs(),
            "stiffest eigenvalues: W {ew:?}, Jacobian {ej:?}"
        );
    }
}
