//! The M113 parked on a grade stays put; on a grade steeper than its
//! friction allows, it slides, its books closed.
//!
//! The M113 as it ships (friction with stiction on the ground, μ = 0.8) is
//! driven at 1 m/s up a ramp of 10, 30 or 60 % until its rearmost wheel is
//! on it, stopped (the speed controller's target ramped to 0 over 1 s, so
//! its integral holds the sprocket), given 4 s to settle, and watched for
//! 10 s (Bogacki-Shampine 1e-4).
//!
//! Tolerances, and why:
//! - **Holds**: the hull moves less than 1 mm along the slope over the
//!   10 s (the bound; measured 0.09, 0.007 and 0.04 mm on 10, 30
//!   and 60 %: the settling's last ringing). Regularised Coulomb friction
//!   (μ over 0.1 m/s) lets it slide 126, 404 and 1132 mm in the same 10 s.
//! - **Slides above μ**: parked on the 60 % grade, the ground's μ then
//!   drops to 0.5 (tan α = 0.6 > μ: ice), a vehicle started from the
//!   parked coordinates slides: it moves more than 0.5 m down the slope in
//!   3 s (measured 2.34 m; a block sliding freely would move
//!   `½ g (sin α − μ cos α) t²` = 3.8 m, the vehicle first settles onto
//!   its shoes and its sprocket is held), its energy books within the
//!   bound for the tolerance (`EnergyBalance::bound_for_tolerance(1e-4)` =
//!   1e-3; measured 8e-6) and the dissipated work never decreasing.

use crate::support;

use trackgen::assembly::Assembled;
use trackgen::integrate::Integrator;
use trackgen::nalgebra::SVector;
use trackgen::simulate::{EnergyBalance, Output, Results, simulate};
use trackgen::terrain::Terrain;
use trackgen::vehicle::{Vehicle, VehicleDynamics, VehicleSystem};
use trackgen::vehicles::{m113::M113, m113::M113Chassis, m113::M113Track};

use support::vehicle::{Books, along_slope};

const RAMP_START: f64 = 3.0;

fn integrator() -> Integrator {
    Integrator::Bs23 {
        rtol: 1e-4,
        atol: 1e-4,
        max_step: 0.01,
    }
}

/// The M113 driven onto a ramp of `grade` and stopped at `stop` s; the
/// results to `end` s and the vehicle.
fn park(grade: f64, stop: f64, end: f64) -> (Results, trackgen::vehicles::m113::M113System) {
    let target = move |t: f64| {
        let up = ((t - 0.5) / 1.0).clamp(0.0, 1.0);
        let down = ((stop + 1.0 - t) / 1.0).clamp(0.0, 1.0);
        up.min(down)
    };
    let terrain = Terrain::Ramp {
        height: 0.0,
        start: RAMP_START,
        slope: grade,
    };
    let mut vehicle = M113::system(terrain, M113::speed_drive(target)).expect("it builds");
    let results = simulate(&mut vehicle, integrator(), 0.0, end, Output::Every(0.02))
        .expect("the run completes");
    (results, vehicle)
}

/// The stop: the rearmost wheel (the idler, 2.2 m behind the centroid) a
/// metre up the ramp at 1 m/s.
const STOP: f64 = 1.5 + RAMP_START + 2.2 + 1.0;

#[test]
fn parked_on_grades_below_mu_it_stays_put() {
    for grade in [0.1, 0.3, 0.6] {
        let end = STOP + 1.0 + 4.0 + 10.0;
        let (results, _) = park(grade, STOP, end);
        let along = along_slope(&results, grade);
        let at = |t: f64| {
            along[results
                .times()
                .partition_point(|&s| s < t)
                .min(along.len() - 1)]
        };
        let climbed = at(STOP) - at(0.0);
        assert!(climbed > 5.0, "{grade}: climbed {climbed} m");
        let moved = at(end) - at(end - 10.0);
        eprintln!(
            "{:.0} % grade: the hull moved {:.4} mm in 10 s",
            grade * 100.0,
            moved * 1e3
        );
        assert!(
            moved.abs() < 1e-3,
            "{:.0} % grade: the parked hull moved {:.3} mm in 10 s",
            grade * 100.0,
            moved * 1e3
        );
    }
}

#[test]
fn above_mu_it_slides_with_its_books_closed() {
    let grade = 0.6;
    let (results, parked) = park(grade, STOP, STOP + 1.0 + 4.0);
    let last = results.sample(results.len() - 1);
    let column = |prefix: &str, n: usize| -> Vec<f64> {
        let start = results
            .columns()
            .iter()
            .position(|c| *c == format!("{prefix}.x"))
            .expect("coordinates");
        last.values[start..start + n].to_vec()
    };
    let start = Assembled {
        track: SVector::<f64, { M113::TRACK_DOF }>::from_column_slice(&column(
            "track",
            M113::TRACK_DOF,
        )),
        chassis: SVector::<f64, { M113::CHASSIS_DOF }>::from_column_slice(&column(
            "chassis",
            M113::CHASSIS_DOF,
        )),
        tensioner: None,
    };
    // The parked vehicle's configuration (its tensioner already set), on
    // ice: μ 0.5 < tan α.
    let mut config = M113::declared_config(
        Terrain::Ramp {
            height: 0.0,
            start: RAMP_START,
            slope: grade,
        },
        M113::speed_drive(|_| 0.0),
    );
    config.arms = parked.config().arms.clone();
    config.ground.friction = config.ground.friction.with_mu(0.5);
    let mut sliding = VehicleSystem::new(M113Track, M113Chassis, &start, M113::geometry(), config)
        .expect("the parked vehicle restarts");
    let results = simulate(&mut sliding, integrator(), 0.0, 3.0, Output::Every(0.01))
        .expect("the slide runs");
    let along = along_slope(&results, grade);
    let slid = along[0] - along[along.len() - 1];
    let books = Books::of(&results);
    eprintln!(
        "slid {slid:.3} m in 3 s; books {:e} of the largest term",
        results.energy_balance().expect("books").residual()
    );
    assert!(slid > 0.5, "slid {slid} m down the 60 % grade on μ 0.5");
    results
        .energy_balance()
        .expect("books")
        .check(EnergyBalance::bound_for_tolerance(1e-4))
        .expect("books within the bound");
    assert!(
        books.least_dissipation_step >= 0.0,
        "dissipated work fell by {} J",
        -books.least_dissipation_step
    );
}
