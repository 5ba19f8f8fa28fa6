//! Soft soil under a track, checked against the textbook's closed forms
//! (Wong, *Theory of Ground Vehicles*; the guide's "Soft soil"): the static sinkage of a
//! vehicle at rest, the tractive effort of a track under uniform pressure
//! against slip, a second pass over the rut, and the energy books.
//!
//! Tolerances, and why:
//! - **Static sinkage** (the M113 at rest on dry sand): the mean sinkage
//!   of the loaded ground points within 5 % of `z₀ = (W/(b l) / (k_c/b +
//!   k_φ))^{1/n}` (the figure; measured 1.3 %), with `W` the ground
//!   force, `b` the track width and `l` the loaded points' footprint. On
//!   dry sand `n` = 1.1, so the mean sinkage under *any* distribution of
//!   the weight along the track is `z₀` to within Jensen's gap (for
//!   `n = 1` exactly: `Σ k z_i A = W`); the road wheels make the pressure
//!   anything but uniform (the deepest point sinks 1.5 `z₀`). The vehicle
//!   is lowered quasi-statically (soil damping `R` = 1e6 Pa s/m, 10 s): a
//!   vehicle dropped onto soft soil overshoots, and the soil remembers the
//!   overshoot (at Chrono's `R` = 3e4 the mean sinkage is 1.22 `z₀`).
//! - **Tractive effort**: a straight track of M113-pitch shoes laid at the
//!   front and lifted at the rear of a 4 m contact, under the uniform
//!   pressure of 1.4e5 N on 0.4 × 4 m (the soil tests' worked example), slipping
//!   at `i` = 5 … 50 % at a track speed of 4 m/s, its shear displacements
//!   integrated as the vehicle does (`j̇` = slip speed while loaded, reset
//!   when lifted), the rut pressed after each step. Its horizontal force
//!   in steady state within 10 % of Wong's `F = (A c + W tan φ)[1 − K/(i
//!   l)(1 − e^{−i l/K})]` (the figure; measured within 0.05 %: the
//!   shear is sampled at the ground points, 77 mm apart, rather than
//!   integrated).
//! - **Second pass**: the M113 drives off over dry sand, then a second
//!   one over the rut it left: the second pass sinks the ground by less
//!   than half what the first did (the rut's plastic depth over the first
//!   2 m: 0.125 m made by the first pass, 0.020 m more by the second). The
//!   second vehicle rides as deep as the first (it reloads the rut
//!   elastically to the same load, 0.14 against 0.13 m at its deepest),
//!   but it presses the soil only past the first pass's sinkage.
//! - **Energy books** on soil: `motor work = ΔE + dissipated` (the soil's
//!   plastic work, damping and shear among the dissipated) within 2e-3 of
//!   the work at Bogacki-Shampine 1e-4 (the issue asks 2 %; measured
//!   8e-4). The shear is elastic in small reversals (`soft_ground`'s
//!   docs), so the dissipated work may dip between samples by what the
//!   rocking shoes get back, bounded here by 1e-3 of the work (measured
//!   6.8 J of 2.9e4 J).

use crate::support;

use trackgen::contact::{BodyState, ShoeGeometry, soft_ground::Rut, soft_ground::SoftGround};
use trackgen::integrate::Integrator;
use trackgen::multibody::{BodyLoad, RecursiveModel};
use trackgen::nalgebra::{SVector, Vector2};
use trackgen::planar::rotate;
use trackgen::simulate::{Output, Results, simulate};
use trackgen::terrain::{Terrain, soil::SoilPreset};
use trackgen::vehicle::{Drive, Vehicle, VehicleConfig, VehicleDynamics};
use trackgen::vehicles::{m113, m113::M113, m113::M113System, m113::M113Track};

use support::contact::soil_forces;
use support::vehicle::{Books, mean, window};

fn integrator(tolerance: f64) -> Integrator {
    Integrator::Bs23 {
        rtol: tolerance,
        atol: tolerance,
        max_step: 0.01,
    }
}

fn on_dry_sand(drive: Drive, damping: Option<f64>) -> VehicleConfig {
    let mut config = M113::declared_config(Terrain::Flat { height: 0.0 }, drive);
    let mut soil = SoilPreset::DrySand.soil();
    if let Some(r) = damping {
        soil.damping = r;
    }
    config.soil = Some(soil);
    config
}

/// The ground points of the track at the last sample: (x, sinkage) of
/// every one below the undisturbed surface y = 0.
fn sunk_points(results: &Results) -> Vec<(f64, f64)> {
    let columns = results.columns();
    let start = columns.iter().position(|c| c == "track.x").unwrap();
    let last = results.sample(results.len() - 1);
    let q = SVector::<f64, { M113::TRACK_DOF }>::from_column_slice(
        &last.values[start..start + M113::TRACK_DOF],
    );
    let mut centres = vec![Vector2::zeros(); 64];
    M113Track.body_positions(&q, &mut centres);
    let shoe = M113::geometry().shoe;
    let mut out = Vec::new();
    for (j, c) in centres.iter().enumerate() {
        for g in &shoe.ground_points {
            let p = c + rotate(q[2 + j], *g);
            if p.y < 0.0 {
                out.push((p.x, -p.y));
            }
        }
    }
    out
}

#[test]
fn static_sinkage_on_dry_sand_is_bekkers() {
    let config = on_dry_sand(M113::speed_drive(|_| 0.0), Some(1e6));
    let mut system = M113::system_with(config).unwrap();
    let results = simulate(
        &mut system,
        integrator(1e-4),
        0.0,
        10.0,
        Output::Every(0.01),
    )
    .expect("the run completes");
    let points = sunk_points(&results);
    let weight = mean(&window(&results, "ground_normal", 9.5, 10.0));
    // Each ground point carries a patch of the shoe's footprint, half a
    // pitch long.
    let length = points.len() as f64 * m113::SHOE_PITCH / 2.0;
    let z0 = SoilPreset::DrySand
        .soil()
        .static_sinkage(weight, m113::TRACK_WIDTH, length);
    let sinkage = points.iter().map(|p| p.1).sum::<f64>() / points.len() as f64;
    eprintln!("mean sinkage {sinkage} m, z0 {z0} m over {length} m");
    assert!(
        ((sinkage - z0) / z0).abs() < 0.05,
        "mean sinkage {sinkage:.4} m against Bekker's {z0:.4} m"
    );
}

/// A straight track under uniform pressure, slipping at `slip`: the
/// steady horizontal force from the soil, N.
fn track_rig(slip: f64) -> f64 {
    let soil = SoilPreset::DrySand.soil();
    let (width, length, weight) = (0.4, 4.0, 1.4e5);
    let pitch = m113::SHOE_PITCH;
    // Ground points a quarter pitch either side of the shoe's centre, so
    // they are evenly spaced along the track.
    let shoe = ShoeGeometry {
        ground_points: vec![
            Vector2::new(-pitch / 4.0, 0.0),
            Vector2::new(pitch / 4.0, 0.0),
        ],
        ..M113::geometry().shoe
    };
    let flat = Terrain::Flat { height: 0.0 };
    let mut ground = SoftGround::new(soil, width, pitch, &shoe).unwrap();
    let z0 = soil.static_sinkage(weight, width, length);
    let track_speed = 4.0;
    let speed = (1.0 - slip) * track_speed;
    // Enough shoes for the contact and the return run: they cycle.
    let in_contact = (length / pitch).round() as usize;
    let shoes = in_contact + 4;
    // Shoe k's position along the loop, m behind the contact's front.
    let mut behind: Vec<f64> = (0..shoes).map(|k| k as f64 * pitch).collect();
    let mut shear = vec![0.0; 2 * shoes];
    let mut rate = vec![0.0; 2 * shoes];
    let dt = 1e-3;
    let mut force = Vec::new();
    let mut t: f64 = 0.0;
    while t < 1.5 * length / track_speed + 0.5 {
        let front = speed * t;
        let states: Vec<BodyState> = behind
            .iter()
            .map(|&s| {
                // On the ground (sunk z₀) over the contact, lifted beyond it.
                let (x, y) = if s < length {
                    (front - s, -z0)
                } else {
                    (front - s, 1.0)
                };
                // On the ground a shoe slips back at `slip` × track speed.
                BodyState::new(
                    Vector2::new(x, y),
                    0.0,
                    Vector2::new(speed - track_speed, 0.0),
                    0.0,
                )
            })
            .collect();
        let mut loads = vec![BodyLoad::ZERO; shoes];
        soil_forces(
            (&ground, &flat),
            &states,
            &shoe,
            &mut loads,
            (&shear, &mut rate),
            |_, _| {},
        );
        if t > 1.2 * length / track_speed {
            force.push(loads.iter().map(|l| l.force.x).sum::<f64>());
        }
        for (j, r) in shear.iter_mut().zip(&rate) {
            *j += r * dt;
        }
        t += dt;
        for s in &mut behind {
            *s += track_speed * dt;
            if *s >= shoes as f64 * pitch {
                *s -= shoes as f64 * pitch;
            }
        }
        let moved: Vec<BodyState> = behind
            .iter()
            .map(|&s| {
                let y = if s < length { -z0 } else { 1.0 };
                BodyState::new(Vector2::new(speed * t - s, y), 0.0, Vector2::zeros(), 0.0)
            })
            .collect();
        ground.press(&flat, &moved, &shoe, &mut shear);
    }
    force.iter().sum::<f64>() / force.len() as f64
}

#[test]
fn tractive_effort_under_uniform_pressure_follows_wong() {
    let soil = SoilPreset::DrySand.soil();
    for slip in [0.05, 0.1, 0.2, 0.3, 0.5] {
        let simulated = track_rig(slip);
        let wong = soil.tractive_effort(1.4e5, 0.4, 4.0, slip);
        eprintln!("slip {slip}: {simulated:.0} N, Wong {wong:.0} N");
        assert!(
            ((simulated - wong) / wong).abs() < 0.10,
            "slip {slip}: {simulated:.0} N against Wong's {wong:.0} N"
        );
    }
}

/// Drives the M113 at 1.5 m/s from rest for 4 s over dry sand (the rut
/// `rut` left before, if any); returns the system and its results.
fn pass(rut: Option<Rut>) -> (M113System, Results) {
    let mut config = on_dry_sand(
        M113::speed_drive(|t| 1.5 * ((t - 0.5) / 1.0).clamp(0.0, 1.0)),
        None,
    );
    config.rut = rut;
    let mut system = M113::system_with(config).unwrap();
    let results = simulate(&mut system, integrator(1e-4), 0.0, 4.0, Output::Every(0.01))
        .expect("the run completes");
    (system, results)
}

/// The deepest plastic sinkage the rut holds over `x ∈ [a, b]`, m.
fn rut_depth(rut: &Rut, a: f64, b: f64) -> f64 {
    rut.profile()
        .filter(|(x, _)| (a..=b).contains(x))
        .map(|(_, z)| z)
        .fold(0.0, f64::max)
}

#[test]
fn a_second_pass_over_the_rut_sinks_less() {
    let (first, results) = pass(None);
    let rut = first.rut().expect("on soil").clone();
    let made = rut_depth(&rut, 0.0, 2.0);
    let deepest_first = mean(&window(&results, "ground_penetration", 3.0, 4.0));
    // The second vehicle starts where the first did, on its rut.
    let (second, results) = pass(Some(rut));
    let after = rut_depth(second.rut().expect("on soil"), 0.0, 2.0);
    let deepest_second = mean(&window(&results, "ground_penetration", 3.0, 4.0));
    eprintln!(
        "rut {made} m, deepened by {} m; deepest sinkage {deepest_first} then {deepest_second} m",
        after - made
    );
    assert!(made > 0.01, "the first pass leaves a rut: {made} m");
    assert!(
        after - made < 0.5 * made,
        "the second pass deepens the {made:.4} m rut by {:.4} m",
        after - made
    );
}

#[test]
fn energy_books_close_on_soil() {
    let (_, results) = pass(None);
    let books = Books::of(&results);
    eprintln!("books {:e} of {} J", books.relative(), books.work);
    assert!(books.work > 1e3, "the motor works: {} J", books.work);
    assert!(
        books.relative() < 2e-3,
        "energy books on soil: residual {:.3e} J of {:.0} J",
        books.residual,
        books.work
    );
    // The shear gives back what small reversals stored (the shoes rock
    // under the road wheels): the dissipated work may dip by that, a few
    // joules (measured 6.8 J), never by 1e-3 of the work.
    assert!(
        -books.least_dissipation_step < 1e-3 * books.work,
        "dissipated work fell by {:e} J between samples",
        -books.least_dissipation_step
    );
}
