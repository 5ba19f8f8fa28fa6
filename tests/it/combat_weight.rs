//! The declared vehicles weigh what the variants they name weigh in
//! combat order, the M113A3 and the Marder 1A3: the compiled model's
//! bodies, both sides, add up to the published combat weight. Each hull's
//! mass is declared as that weight less a hand sum of the running gear,
//! so a part added, dropped or changed in the declaration and not in that
//! sum fails here.

use crate::support::vehicle::{m113_mass, side_mass};
use trackgen::vehicles::{m113, marder};

/// Relative 1e-12: the same masses summed in another order, some 170
/// terms of about 1e1 to 1e4 kg (each sum's rounding ~1e-16 a term).
#[test]
fn the_m113_weighs_the_m113a3s_combat_weight() {
    // Both sides: twice the planar side's compiled bodies.
    let mass = 2.0 * m113_mass();
    assert!(
        (mass / m113::COMBAT_WEIGHT - 1.0).abs() < 1e-12,
        "{mass} kg against {} kg",
        m113::COMBAT_WEIGHT
    );
    // 27 200 lb, the published figure, to the pound.
    assert!((mass / 0.453_592_37 - 27_200.0).abs() < 0.5, "{mass} kg");
}

/// The Marder's both sides against the 1A3's 33.5 t, to the same 1e-12
/// (some 190 terms); and its hull's three inertias Chrono's scaled with
/// its mass, each radius of gyration Chrono's to 1e-12.
#[test]
fn the_marder_weighs_the_marder_1a3s_combat_weight() {
    let mass = 2.0 * side_mass(&marder::MarderTrack, &marder::MarderChassis);
    assert!(
        (mass / 33_500.0 - 1.0).abs() < 1e-12,
        "{mass} kg against 33 500 kg"
    );
    let (chrono_mass, chrono): (f64, [f64; 3]) = (25_000.0, [13_653.39, 98_182.71, 101_954.43]);
    let declared = [
        marder::CHASSIS_ROLL_INERTIA,
        marder::CHASSIS_INERTIA,
        marder::CHASSIS_YAW_INERTIA,
    ];
    for (i, c) in declared.into_iter().zip(chrono) {
        let (k, k_chrono) = ((i / marder::CHASSIS_MASS).sqrt(), (c / chrono_mass).sqrt());
        assert!(
            (k / k_chrono - 1.0).abs() < 1e-12,
            "{i} kg m² against Chrono's {c}"
        );
    }
}
