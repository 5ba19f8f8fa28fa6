//! q̈_i and λ of closed chains checked against the equations they solve,
//! not against another solver. The reference route shares the dense solve
//! (`solve_closed`) with the generated route, so comparing the two re-tests
//! `M_i` and `Q_i` only; these tests check the solves of both
//! `dynamics::forward_dynamics` (dense, range-space) and
//! `dynamics::LinearTimeSolver` (formulation §5, in absolute coordinates), and λ
//! on its own. Chains: PinocchioClosed4, Hetero4Partitioned,
//! PinocchioClosed10, Hetero64Partitioned (tests/support/chains.rs) and the
//! M113's 64 identical shoes; at random states off the closure manifold
//! (the equations hold at any state) and on it, with and without loads.
//!
//! 1. **Residuals of formulation §2's multiplier form**,
//!    `M_i q̈_i + C_qᵀ λ − Q_i` and `C_q q̈_i − γ_c`, with `M_i`, `Q_i` from
//!    the model's `equations_of_motion`, `C_q` from `closure_jacobian`, `γ_c`
//!    from `closure_gamma`. Each is measured against the size of its
//!    equation's terms: the largest row of `|M_i||q̈_i| + |Q_i| + |C_qᵀ||λ|`
//!    (of `|C_q||q̈_i| + |γ_c|`), and must be below 1e-10 of it. Evaluating
//!    the residual of an exact solution leaves up to `(D + 2) ε` of that
//!    scale (1.5e-14 at D = 66); a solution with relative error δ adds about
//!    δ of it, and δ is about the condition number of `M_i` (~1e3 here)
//!    times ε, ~1e-13; 1e-10 leaves a wide margin over both. Measured
//!    worst (over both equations' own scales): dense route
//!    2.6e-16 and 2.4e-15; linear-time route 1.9e-14 and 1.1e-13 (it solves
//!    for absolute accelerations and maps them back).
//!
//!    λ enters only the angle rows (`C_q` is zero under `R`), and where the
//!    loop falls nearly freely the joint force is small against the weights
//!    and inertial forces in the scale: `C_qᵀ λ` is down to 7e-7 of it
//!    (M113 shoes, no loads, |λ| = 0.16 N). There the residual pins λ only
//!    to ~1e-10 / 7e-7 relative, hence test 2.
//!
//! 2. **λ in closed form.** At rest (`q̇_i = 0`), a force pair across the
//!    closing joint (`F` on link n at ū2ⁿ, `−F` on link 1 at ū1¹) is the
//!    generalised load `C_qᵀ F` (`C = P_n − P_1`). The joint cancels it, so
//!    the chain falls freely (`R̈ = g`, `θ̈ = 0`, which satisfies
//!    `M_i q̈_i = Q_i(gravity)` and `C_q q̈_i = 0 = γ_c`) and, by uniqueness,
//!    `λ = F`: its value and its sign (formulation §2: λ is minus the force the
//!    joint puts on link n, and that force is `−F`). `|F|` from 10 to
//!    1000 N in any direction, at any state. Tolerance 1e-10 relative to
//!    `|F|` for λ and to `|g|` for q̈_i (a solve with `M_i`'s condition
//!    number up to ~1e3, with weights up to 1.1e4 N in the right side);
//!    measured 3.0e-14 and 4.6e-13.
//!
//! 3. **λ's meaning at general states.** Cutting the joint and applying the
//!    force it exerts, `−λ` on link n at ū2ⁿ and `+λ` on link 1 at ū1¹, as
//!    loads of the open chain (`dynamics::open_dynamics`, which solves
//!    `M_i q̈_i = Q_i` and nothing else) gives the same q̈_i: 1e-10 relative,
//!    norm-wise, as in test 2; measured 4.3e-13.

use crate::support;
include!("support/chains.rs");

use support::{Lcg, assert_close, max_abs, max_of};
use trackgen::dynamics::{
    Accelerations, LinearTimeSolver, dense_forward_dynamics, dense_open_dynamics,
};
use trackgen::multibody::{BodyLoad, TrackModel};
use trackgen::nalgebra::{SMatrix, SVector, Vector2};
use trackgen::planar::rotate;
use trackgen::vehicles::m113::M113Track;

const TOL: f64 = 1e-10;

/// The residuals of the multiplier form at one state, each relative to the
/// size of its equation's terms.
#[derive(Debug, Clone, Copy)]
struct Residuals {
    dynamics: f64,
    closure: f64,
}

fn residuals<M: TrackModel<D>, const D: usize>(
    model: &M,
    q: &SVector<f64, D>,
    qd: &SVector<f64, D>,
    loads: &[BodyLoad],
    acc: &Accelerations<SVector<f64, D>>,
) -> Residuals {
    let (mut mass, mut forces) = (SMatrix::<f64, D, D>::zeros(), SVector::<f64, D>::zeros());
    model.equations_of_motion(q, qd, loads, &mut mass, &mut forces);
    let cq = model.closure_jacobian(q);
    let gamma = model.closure_gamma(q, qd);
    let lambda = acc.multipliers.expect("a closed chain returns λ");
    let qdd = &acc.qdd;

    let dynamics = mass * qdd + cq.transpose() * lambda - forces;
    let dynamics_scale = max_of((0..D).map(|i| {
        (0..D).map(|j| (mass[(i, j)] * qdd[j]).abs()).sum::<f64>()
            + forces[i].abs()
            + (0..2).map(|k| (cq[(k, i)] * lambda[k]).abs()).sum::<f64>()
    }));
    let closure = cq * qdd - gamma;
    let closure_scale = max_of(
        (0..2).map(|k| (0..D).map(|j| (cq[(k, j)] * qdd[j]).abs()).sum::<f64>() + gamma[k].abs()),
    );
    Residuals {
        dynamics: max_abs(dynamics.iter().copied()) / dynamics_scale,
        closure: max_abs(closure.iter().copied()) / closure_scale,
    }
}

/// Random loads on every link: forces up to 100 N, moments up to 10 N m.
fn random_loads(rng: &mut Lcg, n: usize) -> Vec<BodyLoad> {
    (0..n)
        .map(|_| BodyLoad {
            force: Vector2::new(rng.uniform(-100.0, 100.0), rng.uniform(-100.0, 100.0)),
            moment: rng.uniform(-10.0, 10.0),
        })
        .collect()
}

/// Ten random states (anywhere, the loop open by up to a few metres), and
/// three regular polygons with random velocities projected onto the
/// closure manifold.
fn states<M: TrackModel<D>, const D: usize>(
    model: &M,
    rng: &mut Lcg,
) -> Vec<(SVector<f64, D>, SVector<f64, D>)> {
    let n = D - 2;
    let mut states: Vec<_> = (0..10).map(|_| rng.state::<D>()).collect();
    for _ in 0..3 {
        let mut q = SVector::<f64, D>::from_fn(|i, _| {
            if i < 2 {
                rng.uniform(-2.0, 2.0)
            } else {
                2.0 * std::f64::consts::PI * (i - 2) as f64 / n as f64
            }
        });
        let mut qd = SVector::<f64, D>::from_fn(|_, _| rng.uniform(-3.0, 3.0));
        trackgen::closure::multipliers::project(model, &mut q, &mut qd, 1e-13).unwrap();
        assert!(model.closure(&q).norm() <= 1e-13);
        states.push((q, qd));
    }
    states
}

/// The accelerations of both routes at a state.
fn both_routes<M: TrackModel<D>, const D: usize>(
    model: &M,
    solver: &mut LinearTimeSolver,
    q: &SVector<f64, D>,
    qd: &SVector<f64, D>,
    loads: &[BodyLoad],
) -> [(&'static str, Accelerations<SVector<f64, D>>); 2] {
    [
        (
            "dense",
            dense_forward_dynamics(model, q, qd, loads).unwrap(),
        ),
        (
            "linear-time",
            solver.forward_dynamics(model, q, qd, loads).unwrap(),
        ),
    ]
}

/// Adds a force pair across the closing joint to `loads`: `f` on link n at
/// its joint point ū2ⁿ, `−f` on link 1 at ū1¹.
fn add_joint_pair<M: TrackModel<D>, const D: usize>(
    model: &M,
    q: &SVector<f64, D>,
    f: Vector2<f64>,
    loads: &mut [BodyLoad],
) {
    let joint = model.description().loop_joint.unwrap();
    let n = M::BODIES;
    let (last, first) = (q[2 + (n - 1)], q[2]);
    loads[n - 1] = loads[n - 1].plus(BodyLoad::force_at(f, rotate(last, joint.last_u2)));
    loads[0] = loads[0].plus(BodyLoad::force_at(-f, rotate(first, joint.first_u1)));
}

/// Test 1 for one chain.
fn check_residuals<M: TrackModel<D>, const D: usize>(model: M, seed: u64) {
    let mut solver = LinearTimeSolver::new(&model);
    let mut rng = Lcg::new(seed);
    for (q, qd) in states(&model, &mut rng) {
        let loads = random_loads(&mut rng, M::BODIES);
        for loads in [&[][..], &loads[..]] {
            for (route, acc) in both_routes(&model, &mut solver, &q, &qd, loads) {
                let r = residuals(&model, &q, &qd, loads, &acc);
                assert!(
                    r.dynamics <= TOL && r.closure <= TOL,
                    "{route} route, {} links, {} loads: {r:?} at q = {q:?}",
                    M::BODIES,
                    loads.len()
                );
            }
        }
    }
}

/// Test 2 for one chain.
fn check_force_pair<M: TrackModel<D>, const D: usize>(model: M, seed: u64) {
    let mut solver = LinearTimeSolver::new(&model);
    let mut rng = Lcg::new(seed);
    let gravity = model.description().gravity;
    let mut fall = SVector::<f64, D>::zeros();
    fall[0] = gravity.x;
    fall[1] = gravity.y;
    for (q, _) in states(&model, &mut rng) {
        let qd = SVector::<f64, D>::zeros();
        let (size, angle) = (rng.uniform(10.0, 1000.0), rng.uniform(-3.2, 3.2));
        let f = Vector2::new(angle.cos(), angle.sin()) * size;
        let mut loads = vec![BodyLoad::ZERO; M::BODIES];
        add_joint_pair(&model, &q, f, &mut loads);
        for (route, acc) in both_routes(&model, &mut solver, &q, &qd, &loads) {
            let lambda = acc.multipliers.unwrap();
            assert!(
                max_abs((lambda - f).iter().copied()) <= TOL * size,
                "{route} route, {} links: λ = {lambda:?}, want F = {f:?}",
                M::BODIES
            );
            let label = format!("{route} route, {} links: free fall", M::BODIES);
            assert_close(&label, acc.qdd.as_slice(), fall.as_slice(), TOL, 0.0);
        }
    }
}

/// Test 3 for one chain.
fn check_cut_joint<M: TrackModel<D>, const D: usize>(model: M, seed: u64) {
    let mut solver = LinearTimeSolver::new(&model);
    let mut rng = Lcg::new(seed);
    for (q, qd) in states(&model, &mut rng) {
        let loads = random_loads(&mut rng, M::BODIES);
        for loads in [vec![BodyLoad::ZERO; M::BODIES], loads] {
            for (route, acc) in both_routes(&model, &mut solver, &q, &qd, &loads) {
                let mut cut = loads.clone();
                add_joint_pair(&model, &q, -acc.multipliers.unwrap(), &mut cut);
                let open = dense_open_dynamics(&model, &q, &qd, &cut).unwrap();
                let label = format!("{route} route, {} links: joint cut", M::BODIES);
                assert_close(&label, open.qdd.as_slice(), acc.qdd.as_slice(), TOL, 0.0);
            }
        }
    }
}

#[test]
fn four_link_loops_satisfy_the_multiplier_form() {
    check_residuals(PinocchioClosed4, 41);
    check_residuals(Hetero4Partitioned, 42);
}

#[test]
fn ten_link_loop_satisfies_the_multiplier_form() {
    check_residuals(PinocchioClosed10, 43);
}

#[test]
fn sixty_four_link_loops_satisfy_the_multiplier_form() {
    check_residuals(Hetero64Partitioned, 44);
    check_residuals(M113Track, 45);
}

#[test]
fn a_force_pair_across_the_joint_is_lambda() {
    check_force_pair(PinocchioClosed4, 51);
    check_force_pair(Hetero4Partitioned, 52);
    check_force_pair(PinocchioClosed10, 53);
    check_force_pair(Hetero64Partitioned, 54);
    check_force_pair(M113Track, 55);
}

#[test]
fn lambda_is_minus_the_force_on_link_n() {
    check_cut_joint(PinocchioClosed4, 61);
    check_cut_joint(Hetero4Partitioned, 62);
    check_cut_joint(PinocchioClosed10, 63);
    check_cut_joint(Hetero64Partitioned, 64);
    check_cut_joint(M113Track, 65);
}
