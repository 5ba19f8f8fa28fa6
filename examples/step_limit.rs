//! What sets a vehicle's step: accuracy or stability, and which mode.
//!
//! ```text
//! cargo run --release --example step_limit [-- [--quick] [--vehicle marder]]
//! ```
//!
//! (`--quick`: 0.5 s and the main job's tolerance only, for a smoke test;
//! `--vehicle marder`: the Marder instead of the M113.)
//!
//! Drives the vehicle from rest to 3 m/s on flat ground for 4 s with
//! Bogacki-Shampine, the main job's integrator, and prints the steps,
//! rejections, evaluations and energy books for:
//!
//! - tolerances 1e-4 … 1e-2: where accuracy sets the step, the step count
//!   falls as `tol^(-1/3)` (third order); where a stiff mode's stability
//!   sets it, the count stops falling;
//! - at the main job's 1e-3, the same vehicle without rim and sprocket
//!   friction, without any friction, with the ground's friction
//!   regularised (no stiction states; sliding speed 0.1 m/s, what the
//!   vehicles declared before stiction), and with every contact's damping
//!   (Hunt-Crossley's `χ`) a tenth: if a friction slope or a damping rate
//!   set the step, removing it would lengthen the step;
//! - and the stiffest eigenvalues of the right-hand side's Jacobian
//!   (`trackgen::analysis::linearise`: central differences over every
//!   state with dynamics) at the end, with the step at which
//!   Bogacki-Shampine's stability (`|h λ| ≤ 2.5` on the real axis) would
//!   stop.

use std::time::Instant;

use trackgen::analysis::linearise;
use trackgen::contact::GroundFriction;
use trackgen::integrate::{Integrator, OdeSystem};
use trackgen::laws::{Friction, NormalLaw};
use trackgen::nalgebra::DMatrix;
use trackgen::simulate::{Output, simulate};
use trackgen::system::Simulated;
use trackgen::terrain::Terrain;
use trackgen::vehicle::{Vehicle, VehicleConfig, VehicleDynamics, build};
use trackgen::vehicles::{m113::M113, marder::Marder};

/// The vehicle's declared configuration, driven from rest to 3 m/s.
fn config<V: Vehicle>() -> VehicleConfig {
    V::declared_config(Terrain::Flat { height: 0.0 }, V::speed_drive(ramp))
}

fn ramp(t: f64) -> f64 {
    3.0 * ((t - 1.0) / 2.0).clamp(0.0, 1.0)
}

fn damped(law: NormalLaw, factor: f64) -> NormalLaw {
    match law {
        NormalLaw::HuntCrossley {
            stiffness,
            exponent,
            chi,
        } => NormalLaw::HuntCrossley {
            stiffness,
            exponent,
            chi: chi * factor,
        },
        NormalLaw::KelvinVoigt { stiffness, damping } => NormalLaw::KelvinVoigt {
            stiffness,
            damping: damping * factor,
        },
    }
}

fn run<V: Vehicle>(
    label: &str,
    config: VehicleConfig,
    tol: f64,
    duration: f64,
) -> Result<(), Box<dyn std::error::Error>> {
    let mut system = build::<V>(config)?;
    let integrator = Integrator::Bs23 {
        rtol: tol,
        atol: tol,
        max_step: 0.01,
    };
    let started = Instant::now();
    let results = simulate(&mut system, integrator, 0.0, duration, Output::Every(0.01))
        .map_err(|f| f.error.to_string())?;
    let wall = started.elapsed().as_secs_f64();
    let s = results.stats;
    let books = results.energy_balance().ok_or("no books")?;
    println!(
        "{label:<28} tol {tol:7.0e}: {:6} steps {:5} rejected {:6} evaluations  mean step {:.2} ms  books {:9.2e}  {:.3} s",
        s.accepted,
        s.rejected,
        s.evaluations,
        duration / s.accepted as f64 * 1e3,
        books.residual(),
        wall
    );
    Ok(())
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let (mut quick, mut marder) = (false, false);
    let mut args = std::env::args().skip(1);
    while let Some(arg) = args.next() {
        match (arg.as_str(), args.next()) {
            ("--quick", next) => {
                quick = true;
                if let Some(next) = next {
                    return Err(format!("unknown argument {next:?}").into());
                }
            }
            ("--vehicle", Some(v)) if v == "marder" => marder = true,
            ("--vehicle", Some(v)) if v == "m113" => {}
            _ => {
                return Err(
                    format!("unknown argument {arg:?} (--quick, --vehicle m113|marder)").into(),
                );
            }
        }
    }
    if marder {
        study::<Marder>(quick)
    } else {
        study::<M113>(quick)
    }
}

fn study<V: Vehicle>(quick: bool) -> Result<(), Box<dyn std::error::Error>> {
    let config = config::<V>;
    let (duration, tolerances): (f64, &[f64]) = if quick {
        (0.5, &[1e-3])
    } else {
        (4.0, &[1e-4, 3e-4, 1e-3, 3e-3, 1e-2])
    };
    for &tol in tolerances {
        run::<V>(V::NAME, config(), tol, duration)?;
    }
    let mut no_rim_friction = config();
    no_rim_friction.wheels.friction.mu = 0.0;
    no_rim_friction.sprocket.friction.mu = 0.0;
    run::<V>(
        "no rim or sprocket friction",
        no_rim_friction,
        1e-3,
        duration,
    )?;
    let mut no_friction = config();
    no_friction.wheels.friction.mu = 0.0;
    no_friction.sprocket.friction.mu = 0.0;
    no_friction.ground.friction = no_friction.ground.friction.with_mu(0.0);
    run::<V>("no friction at all", no_friction, 1e-3, duration)?;
    let mut regularised = config();
    regularised.ground.friction = GroundFriction::Regularised(Friction {
        mu: regularised.ground.friction.mu(),
        slip: 0.1,
    });
    run::<V>("ground regularised 0.1 m/s", regularised, 1e-3, duration)?;
    let mut less_damping = config();
    less_damping.ground.normal = damped(less_damping.ground.normal, 0.1);
    less_damping.wheels.normal = damped(less_damping.wheels.normal, 0.1);
    less_damping.sprocket.normal = damped(less_damping.sprocket.normal, 0.1);
    run::<V>("contact damping / 10", less_damping, 1e-3, duration)?;

    // The Jacobian at the end of the default run.
    let mut system = build::<V>(config())?;
    let integrator = Integrator::Bs23 {
        rtol: 1e-3,
        atol: 1e-3,
        max_step: 0.01,
    };
    let mut stepper = integrator.stepper(system.dimension());
    let (mut t, mut y) = (0.0, system.initial_state());
    while t < duration {
        stepper.step(&mut system, &mut t, &mut y, duration)?;
        if system.after_step(t, y.as_mut_slice(), &mut |_| {})? {
            stepper.restart();
        }
    }
    // The books' two quadratures (the motor's work, the dissipated work)
    // feed nothing back: their eigenvalues are zero, but their rows (the
    // power, of the order of the torque per unit of sprocket speed) would
    // dominate the modes' vectors. The modes are those of the rest.
    let layout = system.layout();
    let dynamic: Vec<usize> = layout.dynamic().collect();
    let jacobian = linearise(&mut system, t, y.as_slice(), &dynamic)?;
    let n = dynamic.len();
    let points = V::geometry().shoe.ground_points.len();
    let state_name = |i: usize| layout.name(i, points);
    // faer's eigenvalues (nalgebra's Schur iteration, unshifted, can cycle
    // on a Jacobian of hundreds of states).
    let dense = faer::Mat::<f64>::from_fn(n, n, |i, j| jacobian[(i, j)]);
    let mut eigenvalues: Vec<_> = dense
        .eigenvalues()
        .map_err(|e| format!("the Jacobian's eigenvalues: {e:?}"))?
        .into_iter()
        .map(|z| trackgen::nalgebra::Complex::new(z.re, z.im))
        .collect();
    eigenvalues.sort_by(|a, b| b.norm().total_cmp(&a.norm()));
    println!("stiffest eigenvalues of the Jacobian at t = {t:.1} s (1/s):");
    if std::env::var("STEP_LIMIT_DIAGONAL").is_ok() {
        for i in 0..n {
            if jacobian[(i, i)].abs() > 1000.0 {
                println!(
                    "  J[{0},{0}] = {1:.1} ({2})",
                    dynamic[i],
                    jacobian[(i, i)],
                    state_name(dynamic[i])
                );
            }
        }
    }
    // Which coordinates the stiffest real mode moves: the null vector of
    // J − λI, by its smallest singular value.
    for e in eigenvalues.iter().take(3).filter(|e| e.im == 0.0) {
        let shifted = &jacobian - DMatrix::identity(n, n) * e.re;
        let svd = shifted.svd(false, true);
        let v_t = svd.v_t.expect("V");
        let k = svd.singular_values.imin();
        let mut parts: Vec<(usize, f64)> = v_t.row(k).iter().copied().enumerate().collect();
        parts.sort_by(|a, b| b.1.abs().total_cmp(&a.1.abs()));
        let top: Vec<String> = parts
            .iter()
            .take(6)
            .map(|(i, v)| format!("{} {:+.2}", state_name(dynamic[*i]), v))
            .collect();
        println!("  mode {:.1}: {}", e.re, top.join(", "));
    }
    for e in eigenvalues.iter().take(6) {
        println!(
            "  {:9.1} {:+9.1}i   |λ| {:7.1}   Bogacki-Shampine stable to h = {:.2} ms on the real axis",
            e.re,
            e.im,
            e.norm(),
            2.5 / e.norm() * 1e3
        );
    }
    Ok(())
}
