//! The spatial vehicle's energy books at the tolerances a user runs: the
//! `Twin` on firm ground (stiction, `support::twin::firm`) driven from
//! rest into a left turn (belts 1.2 and 0.4 m/s over 0.2 s), for 1 s, on
//! level ground, across a 30 % side slope (turning uphill) and on dry
//! sand (the soil's laws in place of the ground's, the rut pressed after
//! every step: the carrier sinking as it turns), and on level ground
//! under a 2 kN drawbar load (pulling back along the heading as it
//! turns: its work booked as dissipated), by Bogacki-Shampine. The drives' work less the change of the energy in
//! the bodies, in gravity and in the force elements, less what they
//! dissipated, over the largest of the three (the project's residual,
//! `simulate::EnergyBalance::residual`), is within 1e-3 at tolerance
//! 1e-4, and within the project's own bound at the main job's default
//! tolerance (`EnergyBalance::bound_for_tolerance`, 10 × the tolerance).
//! A misbooked term (a drive's power at the sprocket's absolute speed, a
//! contact's energy left out) is of the order of the work.

use trackgen::integrate::{Integrator, OdeSystem};
use trackgen::nalgebra::Vector2;
use trackgen::simulate::EnergyBalance;
use trackgen::spatial_vehicle::{SideDrives, SpatialLaws};
use trackgen::terrain::field::HeightField;
use trackgen::terrain::soil::SoilPreset;

use crate::support::twin::{States, across_slope, at_rest, belt, firm, on};

/// The books of a 1 s left turn on `field` under `laws` from `start`,
/// under a drawbar load of `pull` (N), by Bogacki-Shampine at
/// `tolerance` (relative and absolute), the
/// system's [`after_step`](trackgen::spatial_vehicle::SpatialSystem::after_step)
/// after each step (on soil, the rut pressed).
fn books(
    (field, laws): (HeightField, SpatialLaws),
    (start, pull): (&States, f64),
    tolerance: f64,
) -> EnergyBalance {
    let mut system = on(
        field,
        laws,
        SideDrives {
            right: belt(1.2, 0.2),
            left: belt(0.4, 0.2),
        },
    );
    system.set_drawbar_pull(pull).expect("a pull");
    let mut y = system.state(&start.0, &start.1, &start.2);
    let before = system.energy(y.as_slice());
    let mut stepper = Integrator::Bs23 {
        rtol: tolerance,
        atol: tolerance,
        max_step: Integrator::DEFAULT_MAX_STEP,
    }
    .stepper(system.dimension());
    let (mut t, end) = (0.0, 1.0);
    while t < end {
        stepper
            .step(&mut system, &mut t, &mut y, end)
            .expect("the run");
        if system.after_step(t, y.as_slice()) {
            stepper.restart();
        }
    }
    let after = system.energy(y.as_slice());
    let drawn = after.drawbar - before.drawbar;
    assert!(
        (pull == 0.0) == (drawn == 0.0) && drawn >= 0.0,
        "a pull of {pull} N took {drawn} J"
    );
    let held = |e: &trackgen::spatial_vehicle::SpatialEnergy| e.kinetic + e.gravity + e.stored;
    EnergyBalance {
        motor_work: after.driven - before.driven,
        energy_change: held(&after) - held(&before),
        dissipated: after.dissipated - before.dissipated,
    }
}

#[test]
fn a_turn_on_the_level_and_across_a_side_slope_keeps_its_books_at_a_users_tolerances() {
    let default = Integrator::DEFAULT_EXPLICIT_TOLERANCE;
    let sand = SpatialLaws {
        soil: Some(SoilPreset::DrySand.soil()),
        ..firm()
    };
    let grounds = [
        (
            "level",
            (HeightField::level(), firm()),
            at_rest(0.0, (0.0, 0.0)),
            0.0,
        ),
        (
            "30 % side slope",
            (HeightField::level().tilted(Vector2::new(0.0, 0.3)), firm()),
            across_slope(0.3),
            0.0,
        ),
        (
            "dry sand",
            (HeightField::level(), sand),
            at_rest(0.0, (0.0, 0.0)),
            0.0,
        ),
        (
            "level, under a 2 kN drawbar pull",
            (HeightField::level(), firm()),
            at_rest(0.0, (0.0, 0.0)),
            2e3,
        ),
    ];
    for (name, field, start, pull) in grounds {
        for (tolerance, bound) in [
            (1e-4, 1e-3),
            (default, EnergyBalance::bound_for_tolerance(default)),
        ] {
            let books = books(field.clone(), (&start, pull), tolerance);
            let residual = books.residual();
            println!(
                "{name}, tolerance {tolerance:e}: work {:.1} J, energy change {:.1} J, \
                 dissipated {:.1} J: residual {residual:.2e} (bound {bound:e})",
                books.motor_work, books.energy_change, books.dissipated
            );
            assert!(
                books.motor_work > 100.0,
                "{name}: the drives work: {books:?}"
            );
            assert!(
                residual.abs() <= bound,
                "{name} at {tolerance:e}: residual {residual:e} over {bound:e}: {books:?}"
            );
        }
    }
}
