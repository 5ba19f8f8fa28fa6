//! `RecursiveModel::tree_dynamics`, the generated O(n) forward dynamics of
//! a tree without constraints, against the dense route
//! (`dynamics::open_dynamics`: Cholesky of the generated `M_i`, itself held
//! to Pinocchio and to finite differences elsewhere), at random states and
//! loads: the M113's chassis (frame, sprocket, five road wheels on
//! trailing arms, an idler on a tensioner arm), a rig with slanted gravity
//! (parts pinned to the frame and on arms, an off-centre centroid), and
//! tracks as trees (open, penalty-closed, and a partitioned one with its
//! loop cut).
//!
//! Tolerance 1e-10 relative to the largest acceleration (norm-wise): two
//! exact solutions of the same equations, the dense one through a
//! Cholesky factorisation of an `M_i` whose condition number reaches ~1e5
//! for the chassis (a 3900 kg frame beside a 0.05 kg m² arm), rounding
//! amplified by that. Measured (`--nocapture` prints them): 5e-15 for the
//! chassis, 5e-13 for the 64-link tracks.

use crate::support;
include!("support/chains.rs");

use support::{Lcg, assert_close, max_abs};
use trackgen::dynamics::dense_open_dynamics;
use trackgen::multibody::{BodyLoad, RecursiveModel};
use trackgen::nalgebra::{SVector, Vector2};
use trackgen::vehicles::{m113::M113Chassis, m113::M113Track};

trackgen::model! {
    /// A small sprung vehicle on a 9° slope of gravity.
    pub vehicle Rig {
        gravity: (1.5, -9.81),
        chassis { mass: 2500.0, inertia: 6000.0, centroid: (-1.6, 0.35) },
        sprocket drive { at: (0.0, 0.0), mass: 27.68, inertia: 1.283, radius: 0.245, teeth: 11 },
        road_wheel front { at: (-0.74, -0.215), mass: 35.56, inertia: 2.16, radius: 0.305,
            arm { pivot: (-0.452, -0.081), mass: 75.26, inertia: 0.77,
                  stiffness: 2.5e4, damping: 500.0, preload: 1.0e4 } },
        road_wheel rear { at: (-2.4, -0.215), mass: 35.56, inertia: 2.16, radius: 0.305 },
        idler tension { at: (-3.1, -0.12), mass: 25.76, inertia: 1.12, radius: 0.255,
            arm { pivot: (-3.1, 0.13), mass: 5.0, inertia: 0.05,
                  stiffness: 6.25e4, damping: 875.0, preload: -5.0e3 } },
        roller top { at: (-1.5, 0.25), mass: 10.0, inertia: 0.1, radius: 0.1 },
        track { links: 4, link { mass: 18.02, inertia: 0.04, u1: (-0.077, 0.0), u2: (0.077, 0.0) } },
    }
}

fn check<M: RecursiveModel<D>, const D: usize>(name: &str, model: M, seed: u64) {
    let n = M::BODIES;
    let mut rng = Lcg::new(seed);
    let mut worst = 0.0f64;
    for _ in 0..50 {
        let (q, qd) = rng.state::<D>();
        let loads: Vec<BodyLoad> = (0..n)
            .map(|_| BodyLoad {
                force: Vector2::new(rng.uniform(-500.0, 500.0), rng.uniform(-500.0, 500.0)),
                moment: rng.uniform(-200.0, 200.0),
            })
            .collect();
        let trig: Vec<(f64, f64)> = (0..n).map(|b| q[2 + b].sin_cos()).collect();
        for loads in [&[][..], &loads[..]] {
            let dense = dense_open_dynamics(&model, &q, &qd, loads).unwrap().qdd;
            let mut fast = SVector::<f64, D>::zeros();
            model.tree_dynamics(&trig, &qd, loads, &mut fast).unwrap();
            assert_close(name, fast.as_slice(), dense.as_slice(), 1e-10, 0.0);
            let scale = max_abs(dense.iter().copied());
            worst = worst.max(max_abs(fast.iter().zip(dense.iter()).map(|(a, b)| a - b)) / scale);
        }
    }
    println!("{name}: worst difference {worst:e} of the largest acceleration");
}

#[test]
fn chassis_trees_agree_with_the_dense_route() {
    check("M113 chassis", M113Chassis, 1);
    check("rig chassis", RigChassis, 2);
}

#[test]
fn tracks_as_trees_agree_with_the_dense_route() {
    check("open 3", Hetero3Open, 3);
    check("penalty 10", Hetero10Penalty, 4);
    check("partitioned 64, cut", Hetero64Partitioned, 5);
    check("M113 track, cut", M113Track, 6);
}
