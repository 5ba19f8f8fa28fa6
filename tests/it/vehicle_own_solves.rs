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
//! * **Moving, W is the Jacobian but for the inertia's share**, entry by
//!   entry (see the test for the bound and what is left out).
//! * **W holds the stiff modes** at a step's shift: the stiffest
//!   eigenvalues of `W` as a 1 ms step sees it (it turns the joints' rows
//!   by `a ω`, so it depends on the step) against the Jacobian's.

use crate::support;
use support::vehicle::{driven, driven_with};

use trackgen::analysis::state_jacobian;
use trackgen::integrate::{ImplicitSolve, OdeSystem};
use trackgen::nalgebra::{DMatrix, DVector};
use trackgen::terrain::{Terrain, soil::SoilPreset};
use trackgen::vehicle::{Vehicle, VehicleDynamics};
use trackgen::vehicles::{m113::M113, marder::Marder};

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

fn at_rest<V: Vehicle>() {
    let (mut system, t, y) = driven::<V>(Terrain::Flat { height: 0.0 }, 0.0, 1e-4);
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

/// `W` as a step of `h` (s) sees it: the solve's map `X = (I − a W)⁻¹`
/// at `a = γ h`, inverted densely, `W = (I − X⁻¹)/a`.
fn step_matrix(system: &mut impl OdeSystem, t: f64, y: &[f64], h: f64) -> DMatrix<f64> {
    let n = y.len();
    let a = 0.435_866_521_508_459 * h;
    own(system).linearise(t, y).expect("linearises");
    own(system).factor(t, a).expect("factors");
    let mut x = DMatrix::zeros(n, n);
    for j in 0..n {
        let mut e = vec![0.0; n];
        e[j] = 1.0;
        own(system).solve(t, &mut e).expect("solves");
        x.set_column(j, &DVector::from_vec(e));
    }
    let inverse = x.try_inverse().expect("the solve's map is regular");
    (DMatrix::identity(n, n) - inverse) / a
}

/// At a state driving at 2 m/s: `W` (at vanishing shift) against the
/// right-hand side's Jacobian by central differences, every entry but the
/// books'. `W` leaves out the chassis' geometric stiffness, the loop
/// constraint's curvature (`δD q̈`, `δκ`) and the inertia's derivatives:
/// measured, the largest difference is 6.4e-4 of the Jacobian's largest
/// entry (1.0e4 /s² on a road wheel's own stiffness, 1.1e6; the largest
/// entry 1.6e7); bound 2e-3, three times that.
#[test]
fn moving_w_is_the_jacobian_but_the_inertia_s_share() {
    let (mut system, t, y) = driven::<Marder>(Terrain::Flat { height: 0.0 }, 1.5, 1e-4);
    let layout = system.layout();
    let states: Vec<usize> = (0..y.len()).filter(|i| !layout.books.contains(i)).collect();
    let w = own_matrix(&mut system, t, y.as_slice(), 1e-9);
    let j = state_jacobian(&mut system, t, y.as_slice(), &states).expect("differences");
    w_near_the_jacobian("Marder", &w, &j, &states, 2e-3);
}

/// `W` (every row and column of the state) against the Jacobian `j`
/// (every row, a column per state in `states`) over the rows and columns
/// of `states`: the largest difference within `bound` of the Jacobian's
/// largest entry.
fn w_near_the_jacobian(
    label: &str,
    w: &DMatrix<f64>,
    j: &DMatrix<f64>,
    states: &[usize],
    bound: f64,
) {
    let largest = j.select_rows(states).amax();
    let mut worst = (0.0, 0, 0);
    for (c, &column) in states.iter().enumerate() {
        for &r in states {
            let d = (w[(r, column)] - j[(r, c)]).abs();
            if d > worst.0 {
                worst = (d, r, column);
            }
        }
    }
    println!(
        "{label}: W against the Jacobian: largest difference {:.3e} (∂f{}/∂y{}) of the largest entry {largest:.3e}",
        worst.0, worst.1, worst.2
    );
    assert!(worst.0 <= bound * largest, "{label}: W off the Jacobian");
}

/// The vehicle's exact Jacobian at `(t, y)` (`OdeSystem::jacobian`, which
/// `tests/it/vehicle_jacobian.rs` holds to differences), every column.
fn exact_jacobian(system: &mut impl OdeSystem, t: f64, y: &[f64]) -> DMatrix<f64> {
    let n = y.len();
    let mut slope = vec![0.0; n];
    system.derivative(t, y, &mut slope).expect("evaluates");
    let mut exact = vec![0.0; n * n];
    assert!(
        system
            .jacobian(t, y, &slope, &mut exact)
            .expect("linearises")
    );
    DMatrix::from_column_slice(n, n, &exact)
}

/// The `count` stiffest eigenvalues of `w` and `j` (square, over the same
/// states) agree within 0.5 %.
fn same_stiffest(label: &str, w: &DMatrix<f64>, j: &DMatrix<f64>, count: usize) {
    let (ew, ej) = (stiffest(w, count), stiffest(j, count));
    println!("{label}: stiffest eigenvalues (1/s): W {ew:.1?}, the Jacobian {ej:.1?}");
    for (a, b) in ew.iter().zip(&ej) {
        assert!(
            (a - b).abs() <= 0.005 * b.abs(),
            "{label}: stiffest eigenvalues: W {ew:?}, Jacobian {ej:?}"
        );
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

/// At the same state, the stiffest eigenvalues of `W` as a step of 1 ms
/// sees it (a step of the Marder's main job at 1e-2: 1.8 ms mean) against
/// the Jacobian's: the five stiffest within 0.5 % (measured 0.04 %).
#[test]
fn w_holds_the_stiffest_modes() {
    let (mut system, t, y) = driven::<Marder>(Terrain::Flat { height: 0.0 }, 1.5, 1e-4);
    let states: Vec<usize> = system.layout().dynamic().collect();
    let w = step_matrix(&mut system, t, y.as_slice(), 1e-3)
        .select_rows(&states)
        .select_columns(&states);
    let j = state_jacobian(&mut system, t, y.as_slice(), &states)
        .expect("differences")
        .select_rows(&states);
    same_stiffest("Marder", &w, &j, 5);
}

/// On dry sand (the soil's law and the shear displacements in `W` as
/// the contacts give them): the M113 driving, `W` at vanishing shift
/// against its exact Jacobian (`tests/vehicle_jacobian.rs` checks that
/// against differences), every entry but the books', to the bound of the
/// Marder's on rigid ground (what `W` leaves out is the same; measured
/// 5.0e-4 of the largest entry); and the four stiffest eigenvalues of
/// `W` at a 1 ms step against the Jacobian's, within 0.5 % (measured
/// 0.1 %). On soil the stiffest two (−3192, −2701 /s) stand apart and a
/// cluster follows (−865 twice, −839, …) whose members the entries `W`
/// leaves out move by more (the fifth by 0.54 %): they are a quarter as
/// stiff as the stiffest and do not set the step.
#[test]
fn on_soil_w_is_the_jacobian_but_the_inertia_s_share() {
    let (mut system, t, y) = driven_with::<M113>(
        Terrain::Flat { height: 0.0 },
        |config| config.soil = Some(SoilPreset::DrySand.soil()),
        1.5,
        1e-4,
    );
    let states: Vec<usize> = system.layout().dynamic().collect();
    let j = exact_jacobian(&mut system, t, y.as_slice()).select_columns(&states);
    let w = own_matrix(&mut system, t, y.as_slice(), 1e-9);
    w_near_the_jacobian("M113 on dry sand", &w, &j, &states, 2e-3);
    let w = step_matrix(&mut system, t, y.as_slice(), 1e-3)
        .select_rows(&states)
        .select_columns(&states);
    same_stiffest("M113 on dry sand", &w, &j.select_rows(&states), 4);
}

/// Leaning on a wall with its hull (the hull's contact with the wall's
/// top edge in `W`, through the chassis' frame): `W` at vanishing shift
/// against the exact Jacobian to the Marder's bound, over the whole
/// matrix and over the frame's own block (measured 1.4e-3 of its largest
/// entry; 3.0e-2 with the hull left out of `W`); and the four stiffest
/// eigenvalues at a 1 ms step within 0.5 %.
#[test]
fn leaning_on_a_wall_w_holds_the_hull() {
    let (mut system, t, y, hull) = support::vehicle::m113_leaning_on_a_wall();
    assert!(hull > 1e3, "the hull bears on the wall: {hull} N");
    let states: Vec<usize> = system.layout().dynamic().collect();
    let j = exact_jacobian(&mut system, t, y.as_slice()).select_columns(&states);
    let w = own_matrix(&mut system, t, y.as_slice(), 1e-9);
    w_near_the_jacobian("M113 on a wall", &w, &j, &states, 2e-3);
    // The frame's accelerations by its pose (x, y, θ), where the hull
    // acts (the whole matrix's largest entries are the links' and the
    // wheels', 1e4 times the hull's), against the same block of the
    // Jacobian, to the same bound of that block's largest entry.
    let layout = system.layout();
    let (rows, columns): (Vec<usize>, Vec<usize>) = (
        layout.chassis_rates.clone().take(3).collect(),
        layout.chassis.clone().take(3).collect(),
    );
    let pick = |m: &DMatrix<f64>, column_of: &dyn Fn(usize) -> usize| {
        DMatrix::from_fn(rows.len(), columns.len(), |r, c| {
            m[(rows[r], column_of(columns[c]))]
        })
    };
    let w_block = pick(&w, &|c| c);
    let j_block = pick(&j, &|c| states.iter().position(|&s| s == c).unwrap());
    let difference = (&w_block - &j_block).amax() / j_block.amax();
    println!(
        "M113 on a wall: W's frame block off the Jacobian's by {difference:.2e} of its largest entry"
    );
    assert!(difference <= 2e-3, "the frame's block: {difference:e}");
    let w = step_matrix(&mut system, t, y.as_slice(), 1e-3)
        .select_rows(&states)
        .select_columns(&states);
    same_stiffest("M113 on a wall", &w, &j.select_rows(&states), 4);
}
