//! The derivatives of the forward dynamics against Pinocchio 4.1.0
//! (tests/data/pinocchio_derivatives.json; tests/data/README.md says how
//! it was computed): `∂q̈/∂q` and
//! `∂q̈/∂q̇` of the four reference chains at their states, under gravity.
//!
//! Tolerances (norm-wise relative, `support::assert_close`):
//! - **Open chains**, 1e-10: the reference is Pinocchio's analytic
//!   `computeABADerivatives` ("agreement to about 1e-12"); ours is exact
//!   too, through one more solve than the accelerations' 1e-12, so a few
//!   ulps of the largest entry, with a margin of 100.
//! - **Closed chains**, 1e-6: the reference is central differences
//!   (h = 1e-6) of Pinocchio's closed-chain accelerations, "good to about
//!   1e-8 relative; compare at 1e-6" (its README). Every coordinate is
//!   varied on its own, off the closure manifold too, which is what the
//!   multiplier form the linear-time route solves differentiates.
//!
//! Both routes are held to it: the linear-time derivative the vehicle
//! uses (`dynamics::derivative::ChainTangent`) and the dense one
//! (`TreeTangent`), which share nothing but the description; and to each
//! other to 1e-10 (measured 1e-13 and below; both exact, the difference
//! is rounding in solves of different shapes), which the closed chains'
//! differenced reference cannot tell (measured 5e-10 to 4.5e-7 from it,
//! open chains 2e-14 to 1.6e-13).

use crate::support;
include!("support/chains.rs");

use support::assert_close;
use support::pinocchio::{case, column_major, floats};
use trackgen::dynamics::{
    derivative::ChainTangent, derivative::TreeTangent, track_jacobian, tree_jacobian,
};
use trackgen::multibody::TrackModel;
use trackgen::nalgebra::SVector;

/// The largest difference over the largest reference entry.
fn relative(got: &[f64], want: &[f64]) -> f64 {
    let scale = want.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    got.iter()
        .zip(want)
        .fold(0.0f64, |m, (g, w)| m.max((g - w).abs()))
        / scale
}

fn check<M: TrackModel<D>, const D: usize>(model: M, name: &str) {
    let case = case("pinocchio_derivatives.json", name);
    assert_eq!(
        M::CLOSURE.is_constrained(),
        case["closed"].as_bool().unwrap()
    );
    let rel = if M::CLOSURE.is_constrained() {
        1e-6
    } else {
        1e-10
    };
    assert!(ChainTangent::new(&model.description()).is_some());
    let _ = TreeTangent::new(&model.description());
    for (k, state) in case["states"].as_array().unwrap().iter().enumerate() {
        let q = SVector::<f64, D>::from_column_slice(&floats(&state["q"]));
        let qd = SVector::<f64, D>::from_column_slice(&floats(&state["qd"]));
        let (want_q, want_qd) = (
            column_major(&state["dqdd_dq"]),
            column_major(&state["dqdd_dqd"]),
        );
        let (linear, dense) = (
            track_jacobian(&model, &q, &qd, &[]).unwrap(),
            tree_jacobian(&model, &q, &qd, &[]).unwrap(),
        );
        // The two routes, exact both, agree far closer than the closed
        // chains' differenced reference.
        for (what, a, b) in [
            ("∂q̈/∂q", &linear.coordinates, &dense.coordinates),
            ("∂q̈/∂q̇", &linear.rates, &dense.rates),
        ] {
            assert_close(
                &format!("{name} state {k}: {what}, linear-time against dense"),
                a.as_slice(),
                b.as_slice(),
                1e-10,
                0.0,
            );
        }
        for (route, jacobian) in [("linear-time", linear), ("dense", dense)] {
            eprintln!(
                "{name} state {k}, {route}: ∂q̈/∂q within {:.1e}, ∂q̈/∂q̇ within {:.1e}",
                relative(jacobian.coordinates.as_slice(), &want_q),
                relative(jacobian.rates.as_slice(), &want_qd)
            );
            assert_close(
                &format!("{name} state {k}, {route}: ∂q̈/∂q"),
                jacobian.coordinates.as_slice(),
                &want_q,
                rel,
                0.0,
            );
            assert_close(
                &format!("{name} state {k}, {route}: ∂q̈/∂q̇"),
                jacobian.rates.as_slice(),
                &want_qd,
                rel,
                0.0,
            );
        }
    }
}

#[test]
fn open_3_links_derivatives_match_pinocchio() {
    check(PinocchioOpen3, "open-3");
}

#[test]
fn closed_4_links_derivatives_match_pinocchio() {
    check(PinocchioClosed4, "closed-4");
}

#[test]
fn open_10_links_derivatives_match_pinocchio() {
    check(PinocchioOpen10, "open-10");
}

#[test]
fn closed_10_links_derivatives_match_pinocchio() {
    check(PinocchioClosed10, "closed-10");
}
