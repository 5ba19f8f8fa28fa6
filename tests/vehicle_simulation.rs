//! A declared vehicle in motion: its chassis and track integrated together
//! as two subsystems (spec §3: no contact yet, so they do not interact),
//! driven by a sprocket torque.

use trackgen::closure::ClosureMethod;
use trackgen::integrate::Integrator;
use trackgen::nalgebra::SVector;
use trackgen::simulate::{Output, Pair, Results, TrackSystem, TreeSystem, simulate};
use trackgen::vehicles::m113::{M113Chassis, M113Track};

/// The motor's torque, N m: on the sprocket, and its reaction on the frame.
const TORQUE: f64 = 2000.0;

fn chassis() -> TreeSystem<M113Chassis, 10> {
    TreeSystem::chassis(M113Chassis, SVector::zeros(), SVector::zeros()).with_loads(
        |t, _, _, loads| {
            let torque = TORQUE * (1.0 - (-5.0 * t).exp());
            loads[M113Chassis::SPROCKET].moment += torque;
            loads[M113Chassis::FRAME].moment -= torque;
        },
    )
}

/// The work of the motor, `∫ T (ω_sprocket − ω_frame) dt`, by Simpson's
/// rule on uniformly spaced samples: at samples 0, 2, 4, … (index `i` of
/// the result is the work up to sample `2i`). Its error, O(Δt⁴), is below
/// 1e-9 of the work at 1 ms samples.
fn motor_work(results: &Results, prefix: &str) -> Vec<f64> {
    let t = results.times();
    let ws = results.column(&format!("{prefix}omega_sprocket")).unwrap();
    let wf = results.column(&format!("{prefix}omega_chassis")).unwrap();
    let power: Vec<f64> = (0..t.len())
        .map(|i| TORQUE * (1.0 - (-5.0 * t[i]).exp()) * (ws[i] - wf[i]))
        .collect();
    let mut work = vec![0.0];
    for i in (2..t.len()).step_by(2) {
        let h = t[i] - t[i - 1];
        work.push(work.last().unwrap() + h / 3.0 * (power[i - 2] + 4.0 * power[i - 1] + power[i]));
    }
    work
}

/// The motor's work goes into the chassis' energy (kinetic and gravity
/// potential: it falls freely): `ΔE = W` to 1e-7 of W, the integration at
/// rtol 1e-10 over ~1e3 steps, the quadrature far below.
#[test]
fn sprocket_torque_work_balances_chassis_energy() {
    let mut system = chassis();
    let results = simulate(
        &mut system,
        Integrator::dopri5(1e-10),
        0.0,
        1.0,
        Output::Every(1e-3),
    )
    .unwrap();
    let work = motor_work(&results, "");
    let energy = results.column("energy").unwrap();
    let w = *work.last().unwrap();
    assert!(w > 1e3, "the motor works: {w} J");
    for (e, w) in energy.iter().step_by(2).zip(&work) {
        assert!(
            (e - energy[0] - w).abs() < 1e-7 * work.last().unwrap(),
            "ΔE = {}, W = {w}",
            e - energy[0]
        );
    }
    // The frame turns against the sprocket: zero total angular momentum
    // about the (falling) centre of mass is kept by the internal torque.
    let omega_frame = results.column("omega_chassis").unwrap();
    assert!(*omega_frame.last().unwrap() < 0.0);
}

/// Track and chassis as one system: each keeps its own energy balance and
/// the track its closure; the columns say which subsystem they belong to.
#[test]
fn vehicle_subsystems_integrate_together() {
    // The track as a regular 64-gon spinning at 1 rad/s (closed).
    let mut q = SVector::<f64, 66>::zeros();
    let mut qd = SVector::<f64, 66>::zeros();
    for i in 0..64 {
        q[2 + i] = 2.0 * std::f64::consts::PI * i as f64 / 64.0;
        qd[2 + i] = 1.0;
    }
    let radius = 0.154 / (2.0 * (std::f64::consts::PI / 64.0).sin());
    qd[0] = -radius * (std::f64::consts::PI / 64.0).cos();
    let track = TrackSystem::new(M113Track, q, qd, ClosureMethod::Declared).unwrap();
    let mut vehicle = Pair::new(track, "track", chassis(), "chassis");
    let results = simulate(
        &mut vehicle,
        Integrator::dopri5(1e-10),
        0.0,
        0.5,
        Output::Every(1e-3),
    )
    .unwrap();
    assert!(results.columns().iter().any(|c| c == "track.closure_error"));
    assert!(results.columns().iter().any(|c| c == "chassis.energy"));
    let track_energy = results.column("track.energy").unwrap();
    let kinetic = results.column("track.kinetic").unwrap()[0];
    let drift = track_energy
        .iter()
        .map(|e| (e - track_energy[0]).abs())
        .fold(0.0, f64::max);
    assert!(drift < 1e-8 * kinetic, "track energy drift {drift} J");
    assert!(
        results
            .column("track.closure_error")
            .unwrap()
            .iter()
            .all(|&c| c < 1e-10)
    );
    let work = motor_work(&results, "chassis.");
    let chassis_energy = results.column("chassis.energy").unwrap();
    let balance = chassis_energy.last().unwrap() - chassis_energy[0] - work.last().unwrap();
    assert!(
        balance.abs() < 1e-7 * work.last().unwrap(),
        "chassis energy balance off by {balance} J"
    );
}
