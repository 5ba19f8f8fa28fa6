//! The default vehicle's compiled dynamics at one state: the M113's track
//! and chassis evaluated separately (as the paper's part I does), checked
//! against the reference route, and timed.
//!
//! `cargo run --release --example model_timing`

use std::time::Instant;

use trackgen::multibody::{ChassisModel, RecursiveModel, TrackModel};
use trackgen::nalgebra::{DVector, SVector};
use trackgen::vehicles::{m113::M113Chassis, m113::M113Track};
use trackgen_runtime::reference::ReferenceModel;

const TRACK_DOF: usize = 66;
const CHASSIS_DOF: usize = 16;

/// Mean wall time of `f` over enough calls to take about 0.2 s.
fn time(mut f: impl FnMut()) -> f64 {
    let mut calls = 1u64;
    loop {
        let start = Instant::now();
        for _ in 0..calls {
            f();
        }
        let elapsed = start.elapsed().as_secs_f64();
        if elapsed > 0.2 {
            return elapsed / calls as f64;
        }
        calls *= 4;
    }
}

fn main() {
    let track = M113Track;
    let n = M113Track::LINKS;
    println!(
        "M113 (one side): {n} shoes, {} chassis parts",
        <M113Chassis as ChassisModel<CHASSIS_DOF>>::PARTS.len()
    );

    // The track as a regular polygon, turning at 0.5 rad/s about its centre
    // while the whole loop translates at 2 m/s: a state on the closure.
    let step = 2.0 * std::f64::consts::PI / n as f64;
    let radius = 0.154 / (2.0 * (step / 2.0).sin());
    let mut q = SVector::<f64, TRACK_DOF>::zeros();
    let mut qd = SVector::<f64, TRACK_DOF>::zeros();
    q[0] = radius * (step / 2.0).cos();
    q[1] = -radius * (step / 2.0).cos();
    for i in 0..n {
        q[2 + i] = i as f64 * step;
        qd[2 + i] = 0.5;
    }
    let omega = 0.5;
    qd[0] = 2.0 - omega * q[1];
    qd[1] = omega * q[0];
    println!(
        "closure |C| = {:.2e} m, |C_q q̇| = {:.2e} m/s",
        track.closure(&q).norm(),
        (track.closure_jacobian(&q) * qd).norm()
    );

    let acc =
        trackgen::dynamics::dense_forward_dynamics(&track, &q, &qd, &[]).expect("track dynamics");
    let reference = ReferenceModel::new(track.description());
    let (dq, dqd) = (
        DVector::from_column_slice(q.as_slice()),
        DVector::from_column_slice(qd.as_slice()),
    );
    let want = reference
        .forward_dynamics(&dq, &dqd, &[])
        .expect("reference dynamics");
    let diff =
        (DVector::from_column_slice(acc.qdd.as_slice()) - &want.qdd).amax() / want.qdd.amax();
    println!("track q̈_i: generated vs reference route, max relative difference {diff:.1e}");
    println!(
        "  closing-joint multipliers λ = ({:.1}, {:.1}) N",
        acc.multipliers.unwrap().x,
        acc.multipliers.unwrap().y
    );

    let mut m = trackgen::nalgebra::SMatrix::<f64, TRACK_DOF, TRACK_DOF>::zeros();
    let mut f = SVector::<f64, TRACK_DOF>::zeros();
    let generated = time(|| {
        let (m, f) = (std::hint::black_box(&mut m), std::hint::black_box(&mut f));
        track.equations_of_motion(std::hint::black_box(&q), &qd, &[], m, f);
    });
    let textbook = time(|| {
        std::hint::black_box((
            reference.mass_matrix(&dq),
            reference.generalized_forces(&dq, &dqd, &[]),
        ));
    });
    let forward = time(|| {
        std::hint::black_box(
            trackgen::dynamics::dense_forward_dynamics(&track, std::hint::black_box(&q), &qd, &[])
                .unwrap(),
        );
    });
    println!(
        "M_i + Q_i: generated {:.2} µs, reference route {:.1} µs ({:.0}x)",
        generated * 1e6,
        textbook * 1e6,
        textbook / generated
    );
    println!(
        "closed-track forward dynamics (dense multiplier form): {:.1} µs",
        forward * 1e6
    );

    let chassis = M113Chassis;
    let qc = SVector::<f64, CHASSIS_DOF>::zeros();
    let ac = trackgen::dynamics::dense_open_dynamics(&chassis, &qc, &SVector::zeros(), &[])
        .expect("chassis dynamics");
    println!(
        "chassis alone under gravity: ÿ = {:.3} m/s², θ̈ = {:.2e} rad/s²",
        ac.qdd[1], ac.qdd[2]
    );
}
