//! Kinematics against central finite differences of the generated
//! positions and closure, at deterministic random states:
//!
//! * `H` is the Jacobian of the positions (eq. (6));
//! * `γ = Ḣ q̇_i` (eq. (14)): the derivative of `H(q) q̇_i` along `q̇_i`;
//! * `C_q` is the Jacobian of `C`, and `γ_c = −(d/dt C_q) q̇_i` (formulation §2);
//!   `C` and `C_q q̇_i` from the links' sines and cosines are the generated
//!   ones (to rounding);
//! * at rest, `Q_i = −∂V/∂q_i` for the conservative forces (gravity and the
//!   penalty spring).
//!
//! Step `h = 1e-6` (coordinates are O(1)): central differences err by
//! `O(h²)·|f'''| ≈ 1e-12` plus rounding `ε|f|/h ≈ 1e-10`, so 1e-7 relative
//! (norm-wise) is a safe bound that still catches any wrong term, which
//! shows as O(1).

use crate::support;
include!("support/chains.rs");

use support::{Lcg, assert_close};
use trackgen::multibody::{RecursiveModel, TrackModel};
use trackgen::nalgebra::{DMatrix, SVector, Vector2};

const H: f64 = 1e-6;
const REL: f64 = 1e-7;

fn positions<M: RecursiveModel<D>, const D: usize>(m: &M, q: &SVector<f64, D>) -> Vec<f64> {
    let mut out = vec![Vector2::zeros(); M::BODIES];
    m.body_positions(q, &mut out);
    out.iter()
        .flat_map(|p| [p.x, p.y])
        .chain(q.iter().skip(2).copied())
        .collect()
}

/// Central difference of `f` along `dir`.
fn along<const D: usize>(
    f: impl Fn(&SVector<f64, D>) -> Vec<f64>,
    q: &SVector<f64, D>,
    dir: &SVector<f64, D>,
) -> Vec<f64> {
    let (a, b) = (f(&(q + dir * H)), f(&(q - dir * H)));
    a.iter().zip(&b).map(|(a, b)| (a - b) / (2.0 * H)).collect()
}

fn unit<const D: usize>(k: usize) -> SVector<f64, D> {
    SVector::from_fn(|i, _| if i == k { 1.0 } else { 0.0 })
}

fn check<M: TrackModel<D>, const D: usize>(m: &M, seed: u64) {
    let mut rng = Lcg::new(seed);
    for _ in 0..8 {
        let (q, qd) = rng.state::<D>();
        let h = m.velocity_transform(&q);
        let mut fd = DMatrix::zeros(3 * M::BODIES, D);
        for k in 0..D {
            fd.set_column(
                k,
                &trackgen::nalgebra::DVector::from_vec(along(|q| positions(m, q), &q, &unit(k))),
            );
        }
        assert_close("H vs ∂R/∂q_i", h.as_slice(), fd.as_slice(), REL, 1.0);

        let hv = |q: &SVector<f64, D>| (m.velocity_transform(q) * qd).as_slice().to_vec();
        assert_close(
            "γ vs d(H q̇)/dt",
            m.gamma(&q, &qd).as_slice(),
            &along(hv, &q, &qd),
            REL,
            1.0,
        );

        let c = |q: &SVector<f64, D>| m.closure(q).as_slice().to_vec();
        let cq = m.closure_jacobian(&q);
        let fd_cq: Vec<f64> = (0..D).flat_map(|k| along(c, &q, &unit(k))).collect();
        assert_close("C_q vs ∂C/∂q_i", cq.as_slice(), &fd_cq, REL, 1.0);
        // The closure and its rate from the links' sines and cosines
        // (`closure_and_rate`, through `C_q`'s columns) are the generated
        // `C` and `C_q q̇_i`: the same sums in another order, so to
        // rounding.
        let trig: Vec<(f64, f64)> = q.iter().skip(2).map(|a| a.sin_cos()).collect();
        let (gap, rate) = m.closure_and_rate(&trig, &qd);
        assert_close(
            "C from C_q's columns",
            gap.as_slice(),
            m.closure(&q).as_slice(),
            1e-13,
            1.0,
        );
        let cq_qd = cq * qd;
        assert_close(
            "C_q q̇ from its columns",
            rate.as_slice(),
            cq_qd.as_slice(),
            1e-13,
            1.0,
        );
        let cqv = |q: &SVector<f64, D>| (m.closure_jacobian(q) * qd).as_slice().to_vec();
        let want: Vec<f64> = along(cqv, &q, &qd).iter().map(|v| -v).collect();
        assert_close(
            "γ_c vs −d(C_q q̇)/dt",
            m.closure_gamma(&q, &qd).as_slice(),
            &want,
            REL,
            1.0,
        );

        let mut forces = SVector::<f64, D>::zeros();
        m.generalized_forces(&q, &SVector::zeros(), &[], &mut forces);
        let grad: Vec<f64> = (0..D)
            .map(|k| -along(|q| vec![m.potential_energy(q)], &q, &unit(k))[0])
            .collect();
        assert_close(
            "Q_i at rest vs −∂V/∂q_i",
            forces.as_slice(),
            &grad,
            REL,
            1.0,
        );
    }
}

#[test]
fn open_chain() {
    check(&Hetero3Open, 1);
}

#[test]
fn closed_chain() {
    check(&Hetero4Partitioned, 2);
}

#[test]
fn penalty_chain() {
    check(&Hetero10Penalty, 3);
}

#[test]
fn long_chain() {
    check(&Hetero64Partitioned, 4);
}
