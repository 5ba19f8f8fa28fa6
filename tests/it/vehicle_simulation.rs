//! A declared vehicle in motion: its chassis and track integrated together
//! as two subsystems (formulation §3: no contact yet, so they do not interact),
//! driven by a sprocket torque.

use crate::support;

use support::arms::{add_arm_torques, arm_energy};
use support::max_abs;
use trackgen::closure::ClosureMethod;
use trackgen::integrate::Integrator;
use trackgen::multibody::ChassisModel;
use trackgen::nalgebra::SVector;
use trackgen::simulate::{Output, Results, simulate};
use trackgen::system::{Pair, TrackSystem, TreeSystem};
use trackgen::vehicles::{m113::M113Chassis, m113::M113Track};

/// The motor's torque, N m: on the sprocket, and its reaction on the frame.
const TORQUE: f64 = 2000.0;

const DOF: usize = 16;

/// The M113 chassis with its torsion-sprung arms and the motor torque.
fn chassis() -> TreeSystem<M113Chassis, DOF> {
    TreeSystem::chassis(M113Chassis, SVector::zeros(), SVector::zeros()).with_loads(
        |t, q, qd, loads| {
            let torque = TORQUE * (1.0 - (-5.0 * t).exp());
            loads[M113Chassis::SPROCKET].moment += torque;
            loads[M113Chassis::FRAME].moment -= torque;
            add_arm_torques::<M113Chassis, DOF>(q, qd, loads);
        },
    )
}

/// Simpson's rule on uniformly spaced samples, cumulative at samples 0, 2,
/// 4, … (index `i` of the result is the integral up to sample `2i`). Its
/// error is O(Δt⁴) and comes from the first 50 ms, where the preloaded
/// arms swing down at 54 rad/s: 0.12 J at 1 ms samples, 2e-4 J at the
/// 0.2 ms used here (5⁴ times less).
fn integral(t: &[f64], f: &[f64]) -> Vec<f64> {
    let mut out = vec![0.0];
    for i in (2..t.len()).step_by(2) {
        let h = t[i] - t[i - 1];
        out.push(out.last().unwrap() + h / 3.0 * (f[i - 2] + 4.0 * f[i - 1] + f[i]));
    }
    out
}

/// The energy going in and out of the chassis: the motor's work
/// `∫ T (ω_sprocket − ω_frame) dt`, less what the arm dampers dissipate,
/// `∫ Σ c φ̇² dt`.
fn net_work(results: &Results, prefix: &str) -> Vec<f64> {
    let t = results.times();
    let column = |name: &str| results.column(&format!("{prefix}{name}")).unwrap();
    let (ws, wf) = (column("omega_sprocket"), column("omega_chassis"));
    let mut power: Vec<f64> = (0..t.len())
        .map(|i| TORQUE * (1.0 - (-5.0 * t[i]).exp()) * (ws[i] - wf[i]))
        .collect();
    for part in <M113Chassis as ChassisModel<DOF>>::PARTS {
        if let Some(arm) = &part.arm {
            let wa = column(&format!("omega_{}_arm", part.name));
            for i in 0..t.len() {
                power[i] -= arm.spring.damping * (wa[i] - wf[i]).powi(2);
            }
        }
    }
    integral(t, &power)
}

/// The chassis' energy: kinetic, gravity, and the torsion springs'.
fn chassis_energy(results: &Results, prefix: &str) -> Vec<f64> {
    let energy = results.column(&format!("{prefix}energy")).unwrap();
    let offset = results
        .columns()
        .iter()
        .position(|c| c == &format!("{prefix}x"))
        .unwrap();
    results
        .iter()
        .zip(energy)
        .map(|(s, e)| {
            e + arm_energy::<M113Chassis, DOF>(&SVector::from_column_slice(
                &s.values[offset..offset + DOF],
            ))
        })
        .collect()
}

/// The motor's work, less the dampers' dissipation, goes into the
/// chassis' energy (kinetic, gravity — it falls freely — and the torsion
/// springs'): `ΔE = W` to 1e-7 of the final work (about 1 MJ; measured
/// 2e-4 J, all of it quadrature error).
#[test]
fn sprocket_torque_work_balances_chassis_energy() {
    let mut system = chassis();
    let results = simulate(
        &mut system,
        Integrator::dopri5(1e-10),
        0.0,
        1.0,
        Output::Every(2e-4),
    )
    .unwrap();
    let work = net_work(&results, "");
    let energy = chassis_energy(&results, "");
    let scale = work.last().unwrap().abs();
    assert!(
        *work.last().unwrap() > 1e3,
        "the motor works: {} J",
        work.last().unwrap()
    );
    for (e, w) in energy.iter().step_by(2).zip(&work) {
        assert!(
            (e - energy[0] - w).abs() < 1e-7 * scale,
            "ΔE = {}, W = {w}",
            e - energy[0]
        );
    }
    // The frame turns against the sprocket.
    assert!(*results.column("omega_chassis").unwrap().last().unwrap() < 0.0);
    // The preloaded arms swing their wheels down, and the dampers work.
    assert!(
        results.column("theta_rw1_arm").unwrap().last().unwrap()
            - results.column("theta_chassis").unwrap().last().unwrap()
            > 0.01
    );
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
        Output::Every(2e-4),
    )
    .unwrap();
    assert!(results.columns().iter().any(|c| c == "track.closure_error"));
    assert!(results.columns().iter().any(|c| c == "chassis.energy"));
    let track_energy = results.column("track.energy").unwrap();
    let kinetic = results.column("track.kinetic").unwrap()[0];
    let drift = max_abs(track_energy.iter().map(|e| e - track_energy[0]));
    assert!(drift < 1e-8 * kinetic, "track energy drift {drift} J");
    assert!(
        results
            .column("track.closure_error")
            .unwrap()
            .iter()
            .all(|&c| c < 1e-10)
    );
    let work = net_work(&results, "chassis.");
    let energy = chassis_energy(&results, "chassis.");
    let balance = energy.last().unwrap() - energy[0] - work.last().unwrap();
    assert!(
        balance.abs() < 1e-7 * work.last().unwrap().abs(),
        "chassis energy balance off by {balance} J"
    );
}
