//! The linear-time forward dynamics (spec §5) against the dense route
//! (`M_i q̈_i = Q_i` and the multiplier form), at random states of random
//! heterogeneous chains, open, closed and penalty-closed, n = 3 … 64; and
//! against Pinocchio's accelerations.
//!
//! Tolerance 1e-10 relative (norm-wise): two exact solutions of the same
//! equations, differing by the rounding of two different eliminations
//! (the dense one with `M_i`'s condition number up to ~1e3). Measured
//! worst: q̈_i 2.5e-13 and λ 1.8e-12 (64 links, closed); the partitioned
//! equations on the manifold 4.5e-12 (pair [62, 63] of the 64-gon: two
//! neighbouring links, 5.6° apart, make `C_d` badly conditioned).
//!
//! Against Pinocchio (4 stored states of `closed-10`, written with 17
//! significant digits): 1e-12, two independent double-precision codes of
//! a 12-coordinate system (spec §5 states 1e-13); measured 2.3e-14.

mod support;
include!("support/chains.rs");

use support::{Lcg, assert_close};
use trackgen::dynamics::{LinearTimeSolver, forward_dynamics};
use trackgen::nalgebra::{SVector, Vector2};
use trackgen::{BodyLoad, TrackModel};

fn check<M: TrackModel<D>, const D: usize>(model: M, seed: u64) {
    let mut solver = LinearTimeSolver::new(&model);
    let mut rng = Lcg::new(seed);
    for _ in 0..20 {
        let (q, qd) = rng.state::<D>();
        let loads: Vec<BodyLoad> = (0..M::BODIES)
            .map(|_| BodyLoad {
                force: Vector2::new(rng.uniform(-100.0, 100.0), rng.uniform(-100.0, 100.0)),
                moment: rng.uniform(-10.0, 10.0),
            })
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
    let text = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tests/data/pinocchio_chains.json"
    ))
    .unwrap();
    let data: serde_json::Value = serde_json::from_str(&text).unwrap();
    let floats = |v: &serde_json::Value| {
        v.as_array()
            .unwrap()
            .iter()
            .map(|x| x.as_f64().unwrap())
            .collect::<Vec<_>>()
    };
    let case = data["cases"]
        .as_array()
        .unwrap()
        .iter()
        .find(|c| c["name"] == "closed-10")
        .unwrap();
    let mut solver = LinearTimeSolver::new(&PinocchioClosed10);
    for state in case["states"].as_array().unwrap() {
        let q = SVector::<f64, 12>::from_column_slice(&floats(&state["q"]));
        let qd = SVector::<f64, 12>::from_column_slice(&floats(&state["qd"]));
        let a = solver
            .forward_dynamics(&PinocchioClosed10, &q, &qd, &[])
            .unwrap();
        assert_close(
            "q̈_i vs Pinocchio",
            a.qdd.as_slice(),
            &floats(&state["qdd"]),
            1e-12,
            0.0,
        );
    }
}

/// On the closure manifold, the partitioned equations of spec §2 (dense,
/// `(Bᵀ M_i B) z̈ = Bᵀ(Q_i − M_i β)`) have the linear-time solution, for
/// any choice of the dependent pair.
#[test]
fn partitioned_equations_agree_on_the_manifold() {
    use trackgen::RecursiveModel;
    use trackgen::closure::{multipliers, partitioning};
    use trackgen::nalgebra::SMatrix;
    let model = Hetero64Partitioned;
    let mut solver = LinearTimeSolver::new(&model);
    let mut rng = Lcg::new(37);
    for pair in [[0, 1], [5, 40], [62, 63]] {
        let mut q = SVector::<f64, 66>::zeros();
        for i in 0..64 {
            q[2 + i] = 2.0 * std::f64::consts::PI * i as f64 / 64.0;
        }
        let mut qd = SVector::<f64, 66>::from_fn(|_, _| rng.uniform(-1.0, 1.0));
        multipliers::project(&model, &mut q, &mut qd, 1e-13).unwrap();
        let (mut mass, mut forces) = (SMatrix::<f64, 66, 66>::zeros(), SVector::<f64, 66>::zeros());
        model.equations_of_motion(&q, &qd, &[], &mut mass, &mut forces);
        let cq = model.closure_jacobian(&q);
        let dense =
            partitioning::accelerations(&mass, &forces, &cq, &model.closure_gamma(&q, &qd), pair)
                .unwrap();
        let fast = solver.forward_dynamics(&model, &q, &qd, &[]).unwrap();
        assert_close("q̈_i", fast.qdd.as_slice(), dense.as_slice(), 1e-10, 0.0);
    }
}
