//! The generated recovery of generalised coordinate partitioning
//! (`TrackModel::recover_closure`, formulation §2): from a closed loop with every
//! coordinate moved by up to 1e-3 (more than a step of the vehicle moves
//! the loop's gap), the dependent pair's angles close the loop
//! and their rates keep it closed, checked with the generated closure and
//! its Jacobian (independent code), for every pair the simulation could
//! choose (conditioning `|sin| ≥ 0.3`; it switches below 0.5): `|C| ≤` the
//! tolerance asked (1e-13 of
//! the loop's length), `|C_q q̇| ≤ 1e-12` of `Σ |d̄ʲ ωʲ|` (the rate
//! equation is solved exactly, to rounding in a sum of 64 terms). The
//! other coordinates are untouched, the trigonometry given back is that of
//! the result bit for bit, and a pair of parallel links is an error, not a
//! panic.

use crate::support;
include!("support/chains.rs");

use support::Lcg;
use trackgen::closure::multipliers;
use trackgen::multibody::TrackModel;
use trackgen::nalgebra::SVector;

fn check<M: TrackModel<D>, const D: usize>(model: M, seed: u64) {
    let n = M::BODIES;
    let spans = model.description().link_spans().unwrap();
    let length: f64 = spans.iter().map(|d| d.norm()).sum();
    let tolerance = 1e-13 * length;
    let mut rng = Lcg::new(seed);
    // A closed start: a polygon, projected onto C = 0.
    let mut closed = SVector::<f64, D>::zeros();
    for i in 0..n {
        closed[2 + i] = 2.0 * std::f64::consts::PI * i as f64 / n as f64;
    }
    let mut rates = SVector::<f64, D>::zeros();
    multipliers::project(&model, &mut closed, &mut rates, 1e-14).unwrap();
    let mut trig = vec![(0.0, 1.0); n];
    for _ in 0..200 {
        let (k, l) = (
            (rng.uniform(0.0, n as f64) as usize).min(n - 1),
            (rng.uniform(0.0, n as f64) as usize).min(n - 1),
        );
        // Pairs the simulation would use: conditioning |sin| ≥ 0.3 (it
        // switches below 0.5); a nearly parallel pair is singular.
        let cq = model.closure_jacobian(&closed);
        let (a, b) = (cq.column(2 + k), cq.column(2 + l));
        if k == l || (a[0] * b[1] - a[1] * b[0]).abs() < 0.3 * a.norm() * b.norm() {
            continue;
        }
        let pair = [k, l];
        let mut q = closed;
        for i in 0..D {
            q[i] += rng.uniform(-1e-3, 1e-3);
        }
        let mut qd = SVector::<f64, D>::from_fn(|_, _| rng.uniform(-2.0, 2.0));
        let (q0, qd0) = (q, qd);
        let result = model.recover_closure(&mut q, &mut qd, pair, tolerance, 20, &mut trig);
        result.unwrap_or_else(|e| panic!("pair {pair:?}: {e:?}"));
        let gap = model.closure(&q).norm();
        assert!(gap <= tolerance, "pair {pair:?}: |C| = {gap:e} m");
        let rate = (model.closure_jacobian(&q) * qd).norm();
        let scale: f64 = (0..n).map(|j| spans[j].norm() * qd[2 + j].abs()).sum();
        assert!(rate <= 1e-12 * scale, "pair {pair:?}: |C_q q̇| = {rate:e}");
        for i in 0..D {
            if i != 2 + k && i != 2 + l {
                assert_eq!(q[i], q0[i], "q[{i}] moved");
                assert_eq!(qd[i], qd0[i], "q̇[{i}] moved");
            }
        }
        for j in 0..n {
            assert_eq!(
                trig[j],
                trackgen::trig::sin_cos(q[2 + j]),
                "trig of link {j}"
            );
        }
    }
}

#[test]
fn recovered_pairs_close_the_loop() {
    check(Hetero4Partitioned, 1);
    check(PinocchioClosed10, 2);
    check(Hetero64Partitioned, 3);
}

trackgen::model! {
    /// Four equal links.
    track Square { links: 4, link { mass: 1.0, inertia: 0.1, u1: (-0.5, 0.0), u2: (0.5, 0.0) } }
}

#[test]
fn a_parallel_pair_is_an_error() {
    // Near a square of four equal links, links 1 and 3 are antiparallel:
    // C_d is singular, and the loop opened by moving link 2 cannot be
    // closed by turning them.
    let mut q = SVector::<f64, 6>::zeros();
    for i in 0..4 {
        q[2 + i] = std::f64::consts::FRAC_PI_2 * i as f64;
    }
    q[3] += 0.1;
    let mut qd = SVector::<f64, 6>::zeros();
    let mut trig = vec![(0.0, 1.0); 4];
    let result = Square.recover_closure(&mut q, &mut qd, [0, 2], 1e-13, 20, &mut trig);
    assert!(result.is_err(), "{result:?}");
}
