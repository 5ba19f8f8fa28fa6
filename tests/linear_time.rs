//! The linear-time forward dynamics (spec §5) against the dense route
//! (`M_i q̈_i = Q_i` and the multiplier form), at random states of random
//! heterogeneous chains, open, closed and penalty-closed, n = 3 … 64; and
//! against Pinocchio's accelerations.
//!
//! Tolerance 1e-10 relative (norm-wise): two exact solutions of the same
//! equations, differing by the rounding of two different eliminations
//! (the dense one with `M_i`'s condition number up to ~1e3).

mod support;
include!("support/chains.rs");

use trackgen::dynamics::{forward_dynamics, LinearTimeSolver};
use trackgen::nalgebra::{SVector, Vector2};
use trackgen::{BodyLoad, TrackModel};
use support::{assert_close, Lcg};

fn check<M: TrackModel<D>, const D: usize>(model: M, seed: u64) {
    let mut solver = LinearTimeSolver::new(&model);
    let mut rng = Lcg::new(seed);
    for _ in 0..20 {
        let (q, qd) = rng.state::<D>();
        let loads: Vec<BodyLoad> = (0..M::BODIES)
            .map(|_| BodyLoad { force: Vector2::new(rng.uniform(-100.0, 100.0), rng.uniform(-100.0, 100.0)), moment: rng.uniform(-10.0, 10.0) })
            .collect();
        for loads in [&[][..], &loads[..]] {
            let dense = forward_dynamics(&model, &q, &qd, loads).unwrap();
            let fast = solver.forward_dynamics(&model, &q, &qd, loads).unwrap();
            assert_close("q̈_i", fast.qdd.as_slice(), dense.qdd.as_slice(), 1e-10, 0.0);
            assert_eq!(fast.multipliers.is_some(), dense.multipliers.is_some());
            if let (Some(a), Some(b)) = (fast.multipliers, dense.multipliers) {
                assert_close("λ", a.as_slice(), b.as_slice(), 1e-10, 0.0);
            }
        }
    }
}

#[test]
fn open_chains_agree_with_the_dense_route() {
    check(Hetero3Open, 31);
    check(Hetero64Open, 32);
}

#[test]
fn closed_chains_agree_with_the_dense_route() {
    check(Hetero4Partitioned, 33);
    check(Hetero64Partitioned, 34);
    check(PinocchioClosed10, 35);
}

#[test]
fn penalty_chains_agree_with_the_dense_route() {
    check(Hetero10Penalty, 36);
}

#[test]
fn agrees_with_pinocchio() {
    let text = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/pinocchio_chains.json")).unwrap();
    let data: serde_json::Value = serde_json::from_str(&text).unwrap();
    let floats = |v: &serde_json::Value| v.as_array().unwrap().iter().map(|x| x.as_f64().unwrap()).collect::<Vec<_>>();
    let case = data["cases"].as_array().unwrap().iter().find(|c| c["name"] == "closed-10").unwrap();
    let mut solver = LinearTimeSolver::new(&PinocchioClosed10);
    for state in case["states"].as_array().unwrap() {
        let q = SVector::<f64, 12>::from_column_slice(&floats(&state["q"]));
        let qd = SVector::<f64, 12>::from_column_slice(&floats(&state["qd"]));
        let a = solver.forward_dynamics(&PinocchioClosed10, &q, &qd, &[]).unwrap();
        assert_close("q̈_i vs Pinocchio", a.qdd.as_slice(), &floats(&state["qdd"]), 1e-12, 0.0);
    }
}
