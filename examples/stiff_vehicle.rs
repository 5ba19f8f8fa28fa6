//! A vehicle whose step its stiffest modes set, on the explicit and the
//! linearly implicit integrator side by side.
//!
//! ```text
//! cargo run --release --example stiff_vehicle [-- --quick]
//! ```
//!
//! The vehicle: the Marder with the friction of its rims and teeth closer
//! to Coulomb's — regularised over 0.1 m/s instead of 0.5 (`slip`), a
//! slope `μ F_n / v_s` five times steeper — and a speed drive of twice the
//! gains. Driven over the main job's course on flat ground (settle 1 s,
//! to 3 m/s in 2 s, 8 s in all), it prints for Bogacki-Shampine at 1e-3,
//! ROS34PW2 at 1e-2 (the tolerances at which each closes the books to
//! about 1e-3 of the motor's work on the vehicles) and `Integrator::Auto`:
//! the steps, the evaluations of the right-hand side, the energy books and
//! the wall time; and, as `examples/step_limit` would, the stiffest rate
//! driving and the step Bogacki-Shampine is stable at. `--quick`: 1 s, for
//! a smoke test.

use std::error::Error;
use std::time::Instant;

use trackgen::integrate::{Integrator, auto::EXPLICIT_STABILITY};
use trackgen::simulate::{Output, simulate};
use trackgen::terrain::Terrain;
use trackgen::vehicle::{Drive, Vehicle, VehicleConfig, build};
use trackgen::vehicles::marder::Marder;

/// The rims' and teeth's regularisation speed, m/s (the Marder's: 0.5).
const SLIP: f64 = 0.1;

fn target(t: f64) -> f64 {
    3.0 * ((t - 1.0) / 2.0).clamp(0.0, 1.0)
}

/// The vehicle declared for this: the Marder's compiled bodies, its laws
/// changed where the stiffness comes from.
fn config() -> VehicleConfig {
    let mut config =
        Marder::declared_config(Terrain::Flat { height: 0.0 }, Marder::speed_drive(target));
    config.wheels.friction.slip = SLIP;
    config.sprocket.friction.slip = SLIP;
    if let Drive::Speed {
        proportional,
        integral,
        ..
    } = &mut config.drive
    {
        *proportional *= 2.0;
        *integral *= 2.0;
    }
    config
}

fn main() -> Result<(), Box<dyn Error>> {
    let quick = std::env::args().any(|a| a == "--quick");
    let duration = if quick { 1.0 } else { 8.0 };
    println!(
        "the Marder with rim and tooth friction regularised over {SLIP} m/s and twice the drive's gains, {duration} s"
    );
    let runs = [
        (
            "Bogacki-Shampine 1e-3",
            Integrator::Bs23 {
                rtol: 1e-3,
                atol: 1e-3,
                max_step: 0.01,
            },
        ),
        (
            "ROS34PW2 1e-2",
            Integrator::Ros34pw2 {
                rtol: 1e-2,
                atol: 1e-2,
                max_step: 0.01,
            },
        ),
        (
            "auto",
            Integrator::Auto {
                explicit_tolerance: 1e-3,
                implicit_tolerance: 1e-2,
                max_step: 0.01,
            },
        ),
    ];
    let mut stiffness = None;
    for (label, integrator) in runs {
        let mut vehicle = build::<Marder>(config())?;
        let started = Instant::now();
        let results = simulate(&mut vehicle, integrator, 0.0, duration, Output::Every(0.1))?;
        let wall = started.elapsed().as_secs_f64();
        let books = results.energy_balance().map_or(f64::NAN, |b| b.residual());
        println!(
            "{label:<22} {:>6} steps {:>5} rejected {:>7} evaluations  books {books:>9.2e}  {wall:.2} s",
            results.stats.accepted, results.stats.rejected, results.stats.evaluations
        );
        // The auto run's checks: the stiffest rate along the run.
        if let Some(check) = results
            .checks
            .iter()
            .max_by(|a, b| a.stiffest.total_cmp(&b.stiffest))
        {
            stiffness = Some((check.stiffest, check.t));
        }
    }
    if let Some((rate, t)) = stiffness {
        println!(
            "stiffest rate (auto's checks): {rate:.3e} /s at {t:.1} s: Bogacki-Shampine stable to {:.3} ms",
            1e3 * EXPLICIT_STABILITY / rate
        );
    }
    Ok(())
}
