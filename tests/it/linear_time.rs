//! The linear-time forward dynamics (formulation §5) against the dense route
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
//! a 12-coordinate system (formulation §5 states 1e-13); measured 2.3e-14.
//!
//! The generated route (`TrackModel::linear_time_dynamics`, each model's
//! own code) is held to the same 1e-10 against the dense route and the
//! generic solver, for the closing joint constrained (with and without
//! Baumgarte's term) and cut (open, and with a penalty force across the
//! cut); its joint forces against Newton's second law link by link,
//! `mᵢ aᵢ = mᵢ g + Fᵢ + λᵢ − λᵢ₋₁` and `Jᵢ θ̈ᵢ = Tᵢ + p2ⁱ·λᵢ − p1ⁱ·λᵢ₋₁`
//! with `aᵢ = H q̈ + γ` from the generated kinematics, at 1e-10 of the
//! largest force.

use crate::support;
include!("support/chains.rs");

use support::{Lcg, assert_close, max_abs};
use trackgen::dynamics::{LinearTimeSolver, dense_forward_dynamics, track_dynamics};
use trackgen::laws::PenaltyJoint;
use trackgen::multibody::{BodyLoad, ClosingJoint, TrackModel};
use trackgen::nalgebra::{SVector, Vector2};

/// The generated route at `(q, q̇)` under `closing`, against the generic
/// solver; its joint forces against Newton's second law.
fn check_generated<M: TrackModel<D>, const D: usize>(
    model: &M,
    solver: &mut LinearTimeSolver,
    (q, qd): (&SVector<f64, D>, &SVector<f64, D>),
    loads: &[BodyLoad],
    closing: ClosingJoint,
) {
    let n = M::BODIES;
    let trig: Vec<(f64, f64)> = (0..n).map(|i| q[2 + i].sin_cos()).collect();
    let mut qdd = SVector::<f64, D>::zeros();
    let mut forces = vec![Vector2::zeros(); n];
    model
        .linear_time_dynamics(&trig, qd, loads, closing, &mut qdd, &mut forces)
        .unwrap();
    let (constrained, stabilisation, cut) = match closing {
        ClosingJoint::Constrained { stabilisation } => (true, stabilisation, None),
        ClosingJoint::Cut { force } => (false, Vector2::zeros(), Some(force)),
    };
    let (generic, lambda) = solver
        .accelerations(q, qd, loads, constrained, stabilisation, cut)
        .unwrap();
    assert_close(
        "generated q̈_i",
        qdd.as_slice(),
        generic.as_slice(),
        1e-10,
        0.0,
    );
    if let Some(lambda) = lambda {
        assert_close(
            "closing λ",
            forces[n - 1].as_slice(),
            lambda.as_slice(),
            1e-10,
            0.0,
        );
    }
    // Newton link by link, with the kinematics of the generated model.
    let description = model.description();
    let (mut accel, mut gamma) = (vec![Vector2::zeros(); n], vec![Vector2::zeros(); n]);
    model.body_velocities(q, &qdd, &mut accel);
    model.velocity_terms(q, qd, &mut gamma);
    let joint = description.loop_joint.unwrap();
    let scale = max_abs(forces.iter().flat_map(|f| [f.x, f.y]))
        .max(max_abs(description.bodies.iter().map(|b| b.mass * 9.81)));
    let mut residual: Vec<f64> = Vec::new();
    for i in 0..n {
        let body = &description.bodies[i];
        let load = loads.get(i).copied().unwrap_or(BodyLoad::ZERO);
        let ahead = if i + 1 < n || constrained {
            forces[i]
        } else {
            cut.unwrap()
        };
        let behind = if i > 0 {
            forces[i - 1]
        } else if constrained {
            forces[n - 1]
        } else {
            cut.unwrap()
        };
        let u1 = if i == 0 { joint.first_u1 } else { body.at_self };
        let u2 = description
            .bodies
            .get(i + 1)
            .map_or(joint.last_u2, |next| next.at_parent);
        let p = |u: Vector2<f64>| trackgen::planar::rotate_derivative(q[2 + i], u);
        let net = description.gravity * body.mass + load.force + ahead - behind;
        let linear = (accel[i] + gamma[i]) * body.mass - net;
        let angular =
            body.inertia * qdd[2 + i] - (load.moment + p(u2).dot(&ahead) - p(u1).dot(&behind));
        residual.extend([linear.x, linear.y, angular]);
    }
    assert!(
        max_abs(residual.iter().copied()) <= 1e-10 * scale,
        "joint forces break Newton's law by {:e} (scale {scale:e})",
        max_abs(residual)
    );
}

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
            let dense = dense_forward_dynamics(&model, &q, &qd, loads).unwrap();
            let fast = solver.forward_dynamics(&model, &q, &qd, loads).unwrap();
            assert_close("q̈_i", fast.qdd.as_slice(), dense.qdd.as_slice(), 1e-10, 0.0);
            assert_eq!(fast.multipliers.is_some(), dense.multipliers.is_some());
            if let (Some(a), Some(b)) = (fast.multipliers, dense.multipliers) {
                assert_close("λ", a.as_slice(), b.as_slice(), 1e-10, 0.0);
            }
            let generated = track_dynamics(&model, &q, &qd, loads).unwrap();
            assert_close(
                "generated q̈_i vs dense",
                generated.qdd.as_slice(),
                dense.qdd.as_slice(),
                1e-10,
                0.0,
            );
            assert_eq!(generated.multipliers.is_some(), dense.multipliers.is_some());
            if let (Some(a), Some(b)) = (generated.multipliers, dense.multipliers) {
                assert_close(
                    "generated λ vs dense",
                    a.as_slice(),
                    b.as_slice(),
                    1e-10,
                    0.0,
                );
            }
            // Every way the closing joint can act, whatever was declared.
            let stabilisation = Vector2::new(rng.uniform(-5.0, 5.0), rng.uniform(-5.0, 5.0));
            let penalty = PenaltyJoint {
                stiffness: 1e5,
                damping: 50.0,
            }
            .force(model.closure(&q), model.closure_jacobian(&q) * qd);
            let mut closings = vec![ClosingJoint::OPEN, ClosingJoint::Cut { force: penalty }];
            if M::BODIES >= 3 {
                closings.extend([
                    ClosingJoint::CLOSED,
                    ClosingJoint::Constrained { stabilisation },
                ]);
            }
            for closing in closings {
                check_generated(&model, &mut solver, (&q, &qd), loads, closing);
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
    let case = support::pinocchio::case("pinocchio_chains.json", "closed-10");
    let floats = support::pinocchio::floats;
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

/// On the closure manifold, the partitioned equations of formulation §2 (dense,
/// `(Bᵀ M_i B) z̈ = Bᵀ(Q_i − M_i β)`) have the linear-time solution, for
/// any choice of the dependent pair.
#[test]
fn partitioned_equations_agree_on_the_manifold() {
    use trackgen::closure::{multipliers, partitioning};
    use trackgen::multibody::RecursiveModel;
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

/// The generated solve works in this thread's tables
/// (`dynamics::elimination::with_tables`), which keep the last solve's
/// numbers: it writes every entry before reading it, so tables left full
/// of NaN change nothing, bit for bit; and one made while they are taken
/// (a solve within a solve) gets tables of its own, the same numbers.
#[test]
fn solves_share_no_numbers_through_their_tables() {
    use trackgen::__private::elimination::with_tables;
    fn solve<M: TrackModel<D>, const D: usize>(
        model: &M,
        (q, qd): (&SVector<f64, D>, &SVector<f64, D>),
    ) -> (SVector<f64, D>, Vec<Vector2<f64>>) {
        let trig: Vec<(f64, f64)> = (0..M::BODIES).map(|i| q[2 + i].sin_cos()).collect();
        let (mut qdd, mut forces) = (SVector::zeros(), vec![Vector2::zeros(); M::BODIES]);
        model
            .linear_time_dynamics(&trig, qd, &[], ClosingJoint::CLOSED, &mut qdd, &mut forces)
            .unwrap();
        (qdd, forces)
    }
    fn poison() {
        with_tables::<64, 63, _>(|links, joints| {
            for link in links.iter_mut() {
                link.p1 = [f64::NAN; 2];
                link.p2 = [f64::NAN; 2];
                link.moment = f64::NAN;
                link.a2 = [f64::NAN; 3];
                link.a1 = [f64::NAN; 3];
                link.coupling = [f64::NAN; 4];
                link.e2 = [f64::NAN; 2];
                link.e1 = [f64::NAN; 2];
            }
            for joint in joints.iter_mut() {
                joint.fac = [f64::NAN; 4];
                joint.yr = [f64::NAN; 2];
                joint.yz = [f64::NAN; 4];
            }
        });
    }
    let mut rng = Lcg::new(37);
    let (q, qd) = rng.state::<6>();
    let (q64, qd64) = rng.state::<66>();
    let first = solve(&Hetero4Partitioned, (&q, &qd));
    let first64 = solve(&Hetero64Partitioned, (&q64, &qd64));
    assert!(
        first
            .0
            .iter()
            .chain(first64.0.iter())
            .all(|v| v.is_finite())
    );
    poison();
    assert_eq!(solve(&Hetero4Partitioned, (&q, &qd)), first, "4 links");
    poison();
    assert_eq!(
        solve(&Hetero64Partitioned, (&q64, &qd64)),
        first64,
        "64 links"
    );
    let nested = with_tables::<64, 63, _>(|_, _| solve(&Hetero4Partitioned, (&q, &qd)));
    assert_eq!(nested, first, "a solve within a solve");
}
