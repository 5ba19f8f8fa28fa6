//! Generated code against the reference (textbook) route, at random states
//! (proptest) of random heterogeneous chains (tests/support/chains.rs), for
//! n in {3, 4, 10, 64}, open, partitioned and penalty-closed.
//!
//! Tolerance 1e-12 relative, norm-wise (`support::assert_close`). The two
//! routes evaluate the same exact quantities by different arithmetic (closed
//! forms and running sums against dense products of eq. (6)'s `H`), so they
//! differ by rounding only: a few ulps of the largest term times the number
//! of terms summed (≤ 3n) stays below 1e-13 even at n = 64. Accelerations go
//! through a solve and are compared at 1e-10, allowing for the condition
//! number of `M_i` (up to ~1e3 here).
//!
//! Both routes end in the same dense solves (`solve_open`, `solve_closed`
//! of the runtime's `dynamics`), so their q̈_i and λ agree whatever those
//! solves do: that comparison re-tests `M_i`, `Q_i`, `C_q` and `γ_c` only.
//! tests/multiplier_residuals.rs checks the solves and λ against the
//! equations themselves.

use crate::support;
include!("support/chains.rs");

use proptest::prelude::*;
use support::{assert_close, dmat, dvec};
use trackgen::multibody::{BodyLoad, RecursiveModel, TrackModel};
use trackgen::nalgebra::{SMatrix, SVector, Vector2};
use trackgen_runtime::reference::ReferenceModel;

const REL: f64 = 1e-12;
const REL_SOLVE: f64 = 1e-10;

fn state<const D: usize>(values: &[f64]) -> (SVector<f64, D>, SVector<f64, D>) {
    let q = SVector::from_fn(|i, _| {
        if i < 2 {
            2.0 * values[i]
        } else {
            std::f64::consts::PI * values[i]
        }
    });
    let qd = SVector::from_fn(|i, _| 3.0 * values[D + i]);
    (q, qd)
}

fn loads(n: usize, values: &[f64]) -> Vec<BodyLoad> {
    (0..n)
        .map(|b| BodyLoad {
            force: Vector2::new(100.0 * values[3 * b], 100.0 * values[3 * b + 1]),
            moment: 10.0 * values[3 * b + 2],
        })
        .collect()
}

fn compare<M: TrackModel<D>, const D: usize>(model: &M, values: &[f64]) {
    let n = M::BODIES;
    let reference = ReferenceModel::new(model.description());
    let (q, qd) = state::<D>(values);
    let applied = loads(n, &values[2 * D..]);
    let (dq, dqd) = (dvec(&q), dvec(&qd));

    let mut pos = vec![Vector2::zeros(); n];
    model.body_positions(&q, &mut pos);
    let flat = |v: &[Vector2<f64>]| v.iter().flat_map(|p| [p.x, p.y]).collect::<Vec<_>>();
    let want_pos: Vec<f64> = flat(&reference.positions(&dq));
    assert_close("positions", &flat(&pos), &want_pos, REL, 1.0);
    // Positions and velocities together are the same numbers.
    let (mut r2, mut v2, mut v1) = (
        vec![Vector2::zeros(); n],
        vec![Vector2::zeros(); n],
        vec![Vector2::zeros(); n],
    );
    model.body_states(&q, &qd, &mut r2, &mut v2);
    model.body_velocities(&q, &qd, &mut v1);
    assert_eq!((r2, v2), (pos.clone(), v1));

    assert_close(
        "H",
        model.velocity_transform(&q).as_slice(),
        reference.velocity_transform(&dq).as_slice(),
        REL,
        0.0,
    );
    assert_close(
        "γ",
        model.gamma(&q, &qd).as_slice(),
        reference.gamma(&dq, &dqd).as_slice(),
        REL,
        0.0,
    );

    let mut mass = SMatrix::<f64, D, D>::zeros();
    model.mass_matrix(&q, &mut mass);
    assert_close(
        "M_i",
        dmat(&mass).as_slice(),
        reference.mass_matrix(&dq).as_slice(),
        REL,
        0.0,
    );

    for loads in [&[][..], &applied[..]] {
        let mut forces = SVector::<f64, D>::zeros();
        model.generalized_forces(&q, &qd, loads, &mut forces);
        assert_close(
            "Q_i",
            forces.as_slice(),
            reference.generalized_forces(&dq, &dqd, loads).as_slice(),
            REL,
            0.0,
        );
        let (mut m2, mut f2) = (SMatrix::<f64, D, D>::zeros(), SVector::<f64, D>::zeros());
        model.equations_of_motion(&q, &qd, loads, &mut m2, &mut f2);
        assert_eq!(m2, mass, "equations_of_motion: M_i");
        assert_eq!(f2, forces, "equations_of_motion: Q_i");

        let got = trackgen::dynamics::dense_forward_dynamics(model, &q, &qd, loads).unwrap();
        let want = reference.forward_dynamics(&dq, &dqd, loads).unwrap();
        assert_close(
            "q̈_i",
            got.qdd.as_slice(),
            want.qdd.as_slice(),
            REL_SOLVE,
            0.0,
        );
        assert_eq!(got.multipliers.is_some(), want.multipliers.is_some());
        if let (Some(a), Some(b)) = (got.multipliers, want.multipliers) {
            assert_close("λ", a.as_slice(), b.as_slice(), REL_SOLVE, 0.0);
        }
    }

    assert_close(
        "T",
        &[model.kinetic_energy(&q, &qd)],
        &[reference.kinetic_energy(&dq, &dqd)],
        REL,
        0.0,
    );
    assert_close(
        "C",
        model.closure(&q).as_slice(),
        reference.closure(&dq).as_slice(),
        REL,
        1.0,
    );
    assert_close(
        "C_q",
        model.closure_jacobian(&q).as_slice(),
        reference.closure_jacobian(&dq).as_slice(),
        REL,
        0.0,
    );
    assert_close(
        "γ_c",
        model.closure_gamma(&q, &qd).as_slice(),
        reference.closure_gamma(&dq, &dqd).as_slice(),
        REL,
        0.0,
    );
}

/// `2 DOF` state values and `3 n` load values, each in [-1, 1].
fn values(dof: usize) -> impl Strategy<Value = Vec<f64>> {
    proptest::collection::vec(-1.0f64..1.0, 2 * dof + 3 * (dof - 2))
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    #[test]
    fn open_3(v in values(5)) { compare(&Hetero3Open, &v); }

    #[test]
    fn partitioned_4(v in values(6)) { compare(&Hetero4Partitioned, &v); }

    #[test]
    fn penalty_10(v in values(12)) { compare(&Hetero10Penalty, &v); }
}

proptest! {
    // The dense reference is O(n³): fewer cases at 64 links.
    #![proptest_config(ProptestConfig::with_cases(12))]

    #[test]
    fn partitioned_64(v in values(66)) { compare(&Hetero64Partitioned, &v); }

    #[test]
    fn open_64(v in values(66)) { compare(&Hetero64Open, &v); }
}

#[test]
fn description_of_a_penalty_track_carries_its_spring() {
    let desc = Hetero10Penalty.description();
    assert_eq!(
        desc.loop_joint.unwrap().closure,
        trackgen::multibody::Closure::Penalty(trackgen::laws::PenaltyJoint {
            stiffness: 2.5e5,
            damping: 40.0
        })
    );
}
