//! The energy books carried by results (`Results::energy_balance`,
//! `Summary::energy_balance`) and their check against the bound derived
//! from the tolerance.
//!
//! Tolerances, and why:
//! - The residual of hand-made books is exact arithmetic on a few numbers:
//!   compared to 1e-15 relative.
//! - On a driven M113 run, the residual the results carry must equal the one
//!   this test computes from the recorded columns itself (first and last
//!   rows), to 1e-12 of the work (the same three differences, rounding
//!   only), and lie within `EnergyBalance::bound_for_tolerance(1e-3)` = 1e-2
//!   at Bogacki-Shampine 1e-3 (measured −3.8e-3 on this 3 s run of the
//!   M113 as it ships, 8.5e-5 before the ground had stiction's states;
//!   most of it accrues while the drive ramps up: −41 J of −44 J over the
//!   main job's first 3 s; the main job's 8 s bump course −1.0e-3).

use crate::support;

use support::vehicle::m113_with;
use trackgen::closure::ClosureMethod;
use trackgen::integrate::Integrator;
use trackgen::simulate::{EnergyBalance, Output, RESIDUAL_FLOOR, Results, Sink, Summary, simulate};
use trackgen::terrain::Terrain;
use trackgen::vehicle::Vehicle;
use trackgen::vehicles::m113::M113;

/// Results with the three book columns, one row per `(t, energy, work,
/// dissipated)`.
fn books(rows: &[(f64, f64, f64, f64)]) -> (Results, Summary) {
    let columns: Vec<String> = ["x", "energy", "motor_work", "dissipated"]
        .iter()
        .map(|c| c.to_string())
        .collect();
    let mut results = Results::new(columns.clone());
    let mut summary = Summary::new();
    results.begin(&columns).unwrap();
    summary.begin(&columns).unwrap();
    for &(t, e, w, d) in rows {
        results.row(t, &[t, e, w, d]).unwrap();
        summary.row(t, &[t, e, w, d]).unwrap();
    }
    (results, summary)
}

#[test]
fn residual_is_the_unexplained_work_over_the_largest_term() {
    // W = 1000, ΔE = 300 − 100 = 200, D = 790: 10 J unexplained.
    let (results, summary) = books(&[(0.0, 100.0, 0.0, 0.0), (1.0, 300.0, 1000.0, 790.0)]);
    for b in [
        results.energy_balance().unwrap(),
        summary.energy_balance().unwrap(),
    ] {
        assert_eq!(
            b,
            EnergyBalance {
                motor_work: 1000.0,
                energy_change: 200.0,
                dissipated: 790.0
            }
        );
        assert!((b.residual() - 0.01).abs() < 1e-15);
        assert!(b.check(0.011).is_ok());
        let error = b.check(0.009).unwrap_err();
        assert_eq!(error.bound, 0.009);
        let message = error.to_string();
        assert!(message.contains("1.00e-2"), "{message}");
        assert!(message.contains("motor work 1000 J"), "{message}");
    }
    // Settling without drive: the largest term is the energy lost.
    let (settling, _) = books(&[(0.0, 500.0, 0.0, 0.0), (1.0, 400.0, 0.0, 99.0)]);
    let b = settling.energy_balance().unwrap();
    assert!((b.residual() - 0.01).abs() < 1e-15, "{}", b.residual());
    // Nothing happened: closed books.
    let (still, _) = books(&[(0.0, 5.0, 0.0, 0.0), (1.0, 5.0, 0.0, 0.0)]);
    assert_eq!(still.energy_balance().unwrap().residual(), 0.0);
}

#[test]
fn a_nan_in_the_books_fails_the_check() {
    let (results, _) = books(&[(0.0, 0.0, 0.0, 0.0), (1.0, f64::NAN, 10.0, 5.0)]);
    let b = results.energy_balance().unwrap();
    assert!(b.residual().is_nan());
    assert!(b.check(1.0).is_err());
}

#[test]
fn runs_without_books_have_none() {
    let columns = vec!["x".to_string()];
    let mut results = Results::new(columns.clone());
    results.begin(&columns).unwrap();
    results.row(0.0, &[1.0]).unwrap();
    assert_eq!(results.energy_balance(), None);
    let (empty, _) = books(&[]);
    assert_eq!(empty.energy_balance(), None);
}

#[test]
fn the_bound_follows_the_tolerance_with_a_floor() {
    assert_eq!(EnergyBalance::bound_for_tolerance(1e-3), 1e-2);
    assert_eq!(EnergyBalance::bound_for_tolerance(1e-12), RESIDUAL_FLOOR);
}

#[test]
fn a_driven_m113_carries_closed_books() {
    let drive = M113::speed_drive(|t| 2.0 * (t / 1.5).min(1.0));
    let mut vehicle = m113_with(
        Terrain::Flat { height: 0.0 },
        drive,
        ClosureMethod::Declared,
    );
    let rtol = 1e-3;
    let results = simulate(
        &mut vehicle,
        Integrator::Bs23 {
            rtol,
            atol: rtol,
            max_step: 0.01,
        },
        0.0,
        3.0,
        Output::Every(0.01),
    )
    .expect("the M113 drives");
    let column = |c: &str| results.column(c).unwrap();
    let (e, w, d) = (column("energy"), column("motor_work"), column("dissipated"));
    let n = e.len() - 1;
    let by_hand = (w[n] - w[0] - (e[n] - e[0]) - (d[n] - d[0])) / (w[n] - w[0]);
    let books = results.energy_balance().expect("a vehicle keeps books");
    eprintln!("books {books:?}, residual {:.3e}", books.residual());
    assert!(books.motor_work > 1e4, "{books:?}");
    assert!(
        (books.residual() - by_hand).abs() < 1e-12,
        "{} vs {by_hand}",
        books.residual()
    );
    books
        .check(EnergyBalance::bound_for_tolerance(rtol))
        .expect("books within the bound");
}
