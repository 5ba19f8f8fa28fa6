//! Structural properties that hold whatever the parameters:
//!
//! * `M_i` is symmetric positive definite (it is `Hᵀ M H` with `H` of full
//!   column rank and `M` positive diagonal);
//! * `½ q̇_iᵀ M_i q̇_i` is the kinetic energy summed from the absolute
//!   velocities (generated `kinetic_energy`, eq. (6) velocities);
//! * closed-chain accelerations satisfy the closure's acceleration equation
//!   `C_q q̈_i = γ_c` (formulation §2).
//!
//! Tolerances: symmetry is exact by construction (checked bit for bit);
//! the energy identity 1e-12 relative (two O(n)-term sums of the same
//! products, rounding only); the acceleration residual 1e-10 relative to
//! `|C_q| |q̈_i| + |γ_c|` (a solve with condition number up to ~1e3).

use crate::support;
include!("support/chains.rs");

use support::{Lcg, assert_close, dmat};
use trackgen::multibody::TrackModel;
use trackgen::nalgebra::{SMatrix, SVector};

fn check<M: TrackModel<D>, const D: usize>(m: &M, seed: u64) {
    let mut rng = Lcg::new(seed);
    for _ in 0..16 {
        let (q, qd) = rng.state::<D>();
        let mut mass = SMatrix::<f64, D, D>::zeros();
        m.mass_matrix(&q, &mut mass);
        assert_eq!(mass, mass.transpose(), "M_i symmetric");
        let eigen = dmat(&mass).symmetric_eigenvalues();
        assert!(
            eigen.min() > 0.0,
            "M_i positive definite, smallest eigenvalue {}",
            eigen.min()
        );

        let quadratic = 0.5 * qd.dot(&(mass * qd));
        assert_close(
            "½ q̇ᵀ M_i q̇ vs T",
            &[quadratic],
            &[m.kinetic_energy(&q, &qd)],
            1e-12,
            0.0,
        );

        if M::CLOSURE.is_constrained() {
            let acc = trackgen::dynamics::dense_forward_dynamics(m, &q, &qd, &[]).unwrap();
            let cq = m.closure_jacobian(&q);
            let gamma = m.closure_gamma(&q, &qd);
            let residual = cq * acc.qdd - gamma;
            let scale = cq.norm() * acc.qdd.norm() + gamma.norm();
            assert!(
                residual.norm() <= 1e-10 * scale,
                "C_q q̈ − γ_c = {residual:?} (scale {scale})"
            );
        }
    }
}

#[test]
fn open_3() {
    check(&Hetero3Open, 11);
}

#[test]
fn closed_4() {
    check(&Hetero4Partitioned, 12);
}

#[test]
fn penalty_10() {
    check(&Hetero10Penalty, 13);
}

#[test]
fn closed_64() {
    check(&Hetero64Partitioned, 14);
}

#[test]
fn accelerations_of_a_closed_chain_are_not_those_of_the_open_one() {
    // Guards the test above: the multiplier form must change the answer.
    let mut rng = Lcg::new(15);
    let (q, qd) = rng.state::<6>();
    let closed =
        trackgen::dynamics::dense_forward_dynamics(&Hetero4Partitioned, &q, &qd, &[]).unwrap();
    let open = trackgen::dynamics::dense_open_dynamics(&Hetero4Partitioned, &q, &qd, &[]).unwrap();
    assert!((closed.qdd - open.qdd).norm() > 1e-3 * open.qdd.norm());
    let _: SVector<f64, 6> = closed.qdd;
}
