//! The exact derivatives of the dynamics (`trackgen::dynamics::derivative`)
//! against central differences of the generated right-hand sides, at
//! random states and under random loads: the track's linear-time tangent
//! on a constrained loop (the M113's 64 links, the Marder's 77, a 64-link
//! heterogeneous chain), on a penalty-cut loop (whose joint force changes with the
//! state) and on an open chain; the chassis tree's tangent on the M113's
//! and the Marder's chassis; and
//! a load direction (`∂q̈/∂F` along a change of every body's load)
//! against the difference of two solves; and many directions at once
//! (`ChainTangent::directions`, `TreeTangent::load_directions`, what the
//! vehicle's Jacobian uses) against one at a time.
//!
//! Step and bound: central differences with `h = 10⁻⁶` (rad) have a
//! truncation error `h² q⃛/6` of order 10⁻¹² relative for accelerations
//! that vary on the scale of a radian, and a rounding error
//! `ε |q̈| / h` of about 2·10⁻¹⁰ relative; penalty stiffness (2.5·10⁵ N/m
//! on 10 kg links) makes the third derivative larger. Bound: 10⁻⁶ of the
//! largest entry of the column block (measured below 10⁻⁸).

use crate::support;
include!("support/chains.rs");

use support::{Lcg, assert_close};
use trackgen::dynamics::{
    StateJacobian, derivative::ChainDirection, derivative::ChainDirections,
    derivative::ChainTangent, derivative::TreeDirection, derivative::TreeTangent, track_jacobian,
    tree_jacobian,
};
use trackgen::multibody::{BodyLoad, ClosingJoint, Closure, RecursiveModel, TrackModel};
use trackgen::nalgebra::{DMatrix, SVector, Vector2};
use trackgen::vehicles::{
    m113::M113Chassis, m113::M113Track, marder::Marder, marder::MarderChassis, marder::MarderTrack,
};

const H: f64 = 1e-6;
/// The rates' step: `q̈` is a polynomial of degree two in `q̇` (the
/// quadratic velocity terms, a penalty joint's damping), whose central
/// difference is exact for any step, so a long one keeps the rounding
/// (`ε |q̈| / h`, with `|q̈|` up to 10⁴ under a stretched penalty joint at
/// a random state) out.
const H_RATES: f64 = 1e-2;
const REL: f64 = 1e-6;

fn loads(rng: &mut Lcg, n: usize, scale: f64) -> Vec<BodyLoad> {
    (0..n)
        .map(|_| BodyLoad {
            force: Vector2::new(rng.uniform(-scale, scale), rng.uniform(-scale, scale)),
            moment: rng.uniform(-0.1 * scale, 0.1 * scale),
        })
        .collect()
}

/// The track's accelerations as the vehicle computes them: the generated
/// linear-time solve, the loop closed as declared (a penalty joint's
/// force from the state).
fn track_accelerations<M: TrackModel<D>, const D: usize>(
    model: &M,
    q: &SVector<f64, D>,
    qd: &SVector<f64, D>,
    loads: &[BodyLoad],
) -> SVector<f64, D> {
    let trig: Vec<(f64, f64)> = q.iter().skip(2).map(|a| a.sin_cos()).collect();
    let closing = match M::CLOSURE {
        Closure::Penalty(joint) => ClosingJoint::Cut {
            force: joint.force(model.closure(q), model.closure_jacobian(q) * qd),
        },
        Closure::Partitioned => ClosingJoint::CLOSED,
        _ => ClosingJoint::OPEN,
    };
    let mut qdd = SVector::zeros();
    let mut joint_forces = vec![Vector2::zeros(); M::BODIES];
    model
        .linear_time_dynamics(&trig, qd, loads, closing, &mut qdd, &mut joint_forces)
        .unwrap();
    qdd
}

fn tree_accelerations<M: RecursiveModel<D>, const D: usize>(
    model: &M,
    q: &SVector<f64, D>,
    qd: &SVector<f64, D>,
    loads: &[BodyLoad],
) -> SVector<f64, D> {
    let trig: Vec<(f64, f64)> = q.iter().skip(2).map(|a| a.sin_cos()).collect();
    let mut qdd = SVector::zeros();
    model.tree_dynamics(&trig, qd, loads, &mut qdd).unwrap();
    qdd
}

/// `(∂q̈/∂q, ∂q̈/∂q̇)` by central differences of `f`.
fn differences<const D: usize>(
    f: impl Fn(&SVector<f64, D>, &SVector<f64, D>) -> SVector<f64, D>,
    q: &SVector<f64, D>,
    qd: &SVector<f64, D>,
) -> (DMatrix<f64>, DMatrix<f64>) {
    let (mut dq, mut dqd) = (DMatrix::zeros(D, D), DMatrix::zeros(D, D));
    for k in 0..D {
        let mut e = SVector::<f64, D>::zeros();
        e[k] = H;
        dq.set_column(k, &((f(&(q + e), qd) - f(&(q - e), qd)) / (2.0 * H)));
        let e = e * (H_RATES / H);
        dqd.set_column(k, &((f(q, &(qd + e)) - f(q, &(qd - e))) / (2.0 * H_RATES)));
    }
    (dq, dqd)
}

/// The exact Jacobian against differences of `accelerations` at three
/// random states under random loads of `scale` N.
fn check<const D: usize>(
    name: &str,
    seed: u64,
    (bodies, scale): (usize, f64),
    exact: impl Fn(&SVector<f64, D>, &SVector<f64, D>, &[BodyLoad]) -> StateJacobian,
    accelerations: impl Fn(&SVector<f64, D>, &SVector<f64, D>, &[BodyLoad]) -> SVector<f64, D>,
) {
    let mut rng = Lcg::new(seed);
    for state in 0..3 {
        let (q, qd) = rng.state::<D>();
        let loads = loads(&mut rng, bodies, scale);
        let exact = exact(&q, &qd, &loads);
        let (dq, dqd) = differences(|q, qd| accelerations(q, qd, &loads), &q, &qd);
        for (what, got, want) in [
            ("∂q̈/∂q", &exact.coordinates, &dq),
            ("∂q̈/∂q̇", &exact.rates, &dqd),
        ] {
            let label = format!("{name} state {state} {what}");
            assert_close(&label, got.as_slice(), want.as_slice(), REL, 1.0);
        }
    }
}

fn check_track<M: TrackModel<D> + Default, const D: usize>(name: &str, seed: u64) {
    let model = M::default();
    check(
        name,
        seed,
        (M::BODIES, 200.0),
        |q, qd, loads| track_jacobian(&model, q, qd, loads).unwrap(),
        |q, qd, loads| track_accelerations(&model, q, qd, loads),
    );
}

fn check_tree<M: RecursiveModel<D> + Default, const D: usize>(name: &str, seed: u64) {
    let model = M::default();
    check(
        name,
        seed,
        (M::BODIES, 500.0),
        |q, qd, loads| tree_jacobian(&model, q, qd, loads).unwrap(),
        |q, qd, loads| tree_accelerations(&model, q, qd, loads),
    );
}

#[test]
fn m113_track_derivatives_match_differences() {
    check_track::<M113Track, 66>("M113 track", 1);
}

#[test]
fn heterogeneous_constrained_loop_derivatives_match_differences() {
    check_track::<Hetero64Partitioned, 66>("64 heterogeneous links, constrained", 2);
}

#[test]
fn penalty_cut_loop_derivatives_match_differences() {
    check_track::<Hetero10Penalty, 12>("10 heterogeneous links, penalty", 3);
}

#[test]
fn open_chain_derivatives_match_differences() {
    check_track::<Hetero64Open, 66>("64 heterogeneous links, open", 4);
}

#[test]
fn marder_track_derivatives_match_differences() {
    check_track::<MarderTrack, { Marder::TRACK_DOF }>("Marder track", 7);
}

#[test]
fn marder_chassis_derivatives_match_differences() {
    check_tree::<MarderChassis, { Marder::CHASSIS_DOF }>("Marder chassis", 8);
}

#[test]
fn m113_chassis_derivatives_match_differences() {
    check_tree::<M113Chassis, { trackgen::vehicles::m113::M113::CHASSIS_DOF }>("M113 chassis", 5);
}

/// A load direction: `∂q̈/∂F · δF` from the tangents against the
/// difference of two solves with the loads `F ± h δF` (linear in `F`, so
/// the difference is exact to rounding: bound 10⁻⁹ relative).
#[test]
fn load_directions_match_two_solves() {
    let mut rng = Lcg::new(6);
    let model = M113Track;
    let (q, qd) = rng.state::<66>();
    let base = loads(&mut rng, 64, 200.0);
    let change = loads(&mut rng, 64, 200.0);
    let shifted = |s: f64| -> Vec<BodyLoad> {
        base.iter()
            .zip(&change)
            .map(|(b, c)| BodyLoad {
                force: b.force + c.force * s,
                moment: b.moment + c.moment * s,
            })
            .collect()
    };
    let h = 1e-3;
    let want = (track_accelerations(&model, &q, &qd, &shifted(h))
        - track_accelerations(&model, &q, &qd, &shifted(-h)))
        / (2.0 * h);
    let description = model.description();
    let mut tangent = ChainTangent::new(&description).unwrap();
    let trig: Vec<(f64, f64)> = q.iter().skip(2).map(|a| a.sin_cos()).collect();
    let omega: Vec<f64> = qd.iter().skip(2).copied().collect();
    tangent
        .factor(&trig, &omega, &base, ClosingJoint::CLOSED)
        .unwrap();
    let mut got = vec![0.0; 66];
    tangent.direction(
        &ChainDirection {
            angles: &[],
            rates: &[],
            loads: &change,
            closing: Vector2::zeros(),
        },
        &mut got,
    );
    assert_close("M113 track ∂q̈/∂F δF", &got, want.as_slice(), 1e-9, 1e-6);

    let chassis = M113Chassis;
    let (q, qd) = rng.state::<{ trackgen::vehicles::m113::M113::CHASSIS_DOF }>();
    let n =
        <M113Chassis as RecursiveModel<{ trackgen::vehicles::m113::M113::CHASSIS_DOF }>>::BODIES;
    let base = loads(&mut rng, n, 500.0);
    let change = loads(&mut rng, n, 500.0);
    let shifted = |s: f64| -> Vec<BodyLoad> {
        base.iter()
            .zip(&change)
            .map(|(b, c)| BodyLoad {
                force: b.force + c.force * s,
                moment: b.moment + c.moment * s,
            })
            .collect()
    };
    let want = (tree_accelerations(&chassis, &q, &qd, &shifted(h))
        - tree_accelerations(&chassis, &q, &qd, &shifted(-h)))
        / (2.0 * h);
    let mut tangent = TreeTangent::new(&chassis.description());
    tangent.factor(q.as_slice(), qd.as_slice(), &base).unwrap();
    let mut got = vec![0.0; q.len()];
    tangent.direction(
        &TreeDirection {
            coordinates: &[],
            rates: &[],
            loads: &change,
        },
        &mut got,
    );
    assert_close("M113 chassis ∂q̈/∂F δF", &got, want.as_slice(), 1e-9, 1e-6);
}

/// Many directions at once against one at a time: the chain's batched
/// sweeps do each direction's arithmetic in the same order as a single
/// sweep (the batch only interleaves them), so they agree exactly; the
/// chassis' load response through `M_i⁻¹ Hᵀ` agrees with its single
/// direction to rounding (1e-12 of the largest entry: the same product,
/// summed in another order by the matrix multiplication).
#[test]
fn many_directions_at_once_equal_one_at_a_time() {
    fn chain<M: TrackModel<D> + Default, const D: usize>(seed: u64) {
        let model = M::default();
        let mut rng = Lcg::new(seed);
        let (q, qd) = rng.state::<D>();
        let n = M::BODIES;
        let trig: Vec<(f64, f64)> = q.iter().skip(2).map(|a| a.sin_cos()).collect();
        let omega: Vec<f64> = qd.iter().skip(2).copied().collect();
        let closing = match M::CLOSURE {
            Closure::Penalty(joint) => ClosingJoint::Cut {
                force: joint.force(model.closure(&q), model.closure_jacobian(&q) * qd),
            },
            _ => ClosingJoint::CLOSED,
        };
        let mut tangent = ChainTangent::new(&model.description()).unwrap();
        tangent
            .factor(&trig, &omega, &loads(&mut rng, n, 200.0), closing)
            .unwrap();
        let k = 5;
        let random = |rng: &mut Lcg| (0..n * k).map(|_| rng.uniform(-1.0, 1.0)).collect();
        let (angles, rates): (Vec<f64>, Vec<f64>) = (random(&mut rng), random(&mut rng));
        let applied = loads(&mut rng, n * k, 200.0);
        let closings: Vec<Vector2<f64>> = (0..k)
            .map(|_| Vector2::new(rng.uniform(-50.0, 50.0), rng.uniform(-50.0, 50.0)))
            .collect();
        let mut all = vec![0.0; (n + 2) * k];
        tangent.directions(
            &ChainDirections {
                columns: k,
                angles: &angles,
                rates: &rates,
                loads: &applied,
                closing: &closings,
            },
            &mut all,
        );
        for c in 0..k {
            let column =
                |values: &[f64]| -> Vec<f64> { (0..n).map(|i| values[i * k + c]).collect() };
            let loads: Vec<BodyLoad> = (0..n).map(|i| applied[i * k + c]).collect();
            let mut one = vec![0.0; n + 2];
            tangent.direction(
                &ChainDirection {
                    angles: &column(&angles),
                    rates: &column(&rates),
                    loads: &loads,
                    closing: closings[c],
                },
                &mut one,
            );
            let batched: Vec<f64> = (0..n + 2).map(|r| all[r * k + c]).collect();
            assert_eq!(
                batched,
                one,
                "direction {c} of {}",
                std::any::type_name::<M>()
            );
        }
    }
    chain::<M113Track, 66>(11);
    chain::<Hetero10Penalty, 12>(12);
    chain::<Hetero64Open, 66>(13);

    let mut rng = Lcg::new(14);
    const DOF: usize = Marder::CHASSIS_DOF;
    let chassis = MarderChassis;
    let (q, qd) = rng.state::<DOF>();
    let m = <MarderChassis as RecursiveModel<DOF>>::BODIES;
    let mut tangent = TreeTangent::new(&chassis.description());
    tangent
        .factor(q.as_slice(), qd.as_slice(), &loads(&mut rng, m, 500.0))
        .unwrap();
    let k = 4;
    let applied: Vec<Vec<BodyLoad>> = (0..k).map(|_| loads(&mut rng, m, 500.0)).collect();
    let stacked = DMatrix::from_fn(3 * m, k, |r, c| {
        let load = applied[c][r / 3];
        [load.force.x, load.force.y, load.moment][r % 3]
    });
    let all = tangent.load_directions(&stacked);
    for (c, loads) in applied.iter().enumerate() {
        let mut one = vec![0.0; DOF];
        tangent.direction(
            &TreeDirection {
                coordinates: &[],
                rates: &[],
                loads,
            },
            &mut one,
        );
        let batched: Vec<f64> = all.column(c).iter().copied().collect();
        let scale = one.iter().fold(0.0_f64, |a, v| a.max(v.abs()));
        assert_close(
            "Marder chassis load directions",
            &batched,
            &one,
            1e-12,
            scale,
        );
    }
}
