//! The linear-time solve with general link blocks
//! (`trackgen::dynamics::ShiftedChain`, what the linearly implicit
//! integrator solves through) against the dense route: the bordered system
//! `[Hᵀ X H, C_qᵀ; C_q, 0] [x; μ] = [Hᵀ f; 0]` in recursive coordinates,
//! built from the compiled model's velocity transform `H` and closure
//! Jacobian `C_q`, solved by LU. Blocks `X` are the links' masses plus
//! random non-symmetric blocks of the size of a contact's `a C + a² K`,
//! at random angles, on a heterogeneous 10-link loop and on the M113's
//! 64 links.
//!
//! Tolerance: 1e-10 of the largest increment. Both routes solve the same
//! well-conditioned system (the blocks dominated by the links' inertia,
//! condition numbers below 1e6 measured) in double precision; they
//! differ by rounding, of order 1e-13 relative here.

mod support;

include!("support/chains.rs");

use support::{Lcg, assert_close};
use trackgen::TrackModel;
use trackgen::dynamics::ShiftedChain;
use trackgen::nalgebra::{DMatrix, DVector, Matrix3, SVector, Vector3};
use trackgen::vehicles::m113::M113Track;

fn check<M: TrackModel<D>, const D: usize>(label: &str, model: M, seed: u64) {
    let n = M::BODIES;
    let mut rng = Lcg::new(seed);
    let description = model.description();
    let mut chain = ShiftedChain::new(&description).expect("a track");
    for trial in 0..5 {
        let (q, _) = rng.state::<D>();
        let trig: Vec<(f64, f64)> = (0..n).map(|i| q[2 + i].sin_cos()).collect();
        let blocks: Vec<Matrix3<f64>> = description
            .bodies
            .iter()
            .map(|b| {
                let stiff = Matrix3::from_fn(|_, _| rng.uniform(-1.0, 1.0));
                Matrix3::from_diagonal(&Vector3::new(b.mass, b.mass, b.inertia))
                    + stiff * (0.2 * b.inertia)
                    + Matrix3::from_diagonal(&Vector3::new(1.0, 1.0, 0.0)) * rng.uniform(0.0, 50.0)
            })
            .collect();
        let loads: Vec<Vector3<f64>> = (0..n)
            .map(|_| Vector3::from_fn(|_, _| rng.uniform(-100.0, 100.0)))
            .collect();
        chain.factor(&trig, &blocks).expect("regular");
        let mut out = vec![Vector3::zeros(); n];
        chain.solve(&loads, &mut out);
        let mut got = vec![out[0][0], out[0][1]];
        got.extend(out.iter().map(|x| x[2]));

        // The dense route, rows of H as `velocity_transform` orders them:
        // every link's (x, y), then every link's θ.
        let h = model.velocity_transform(&q);
        let row = |i: usize, c: usize| match c {
            0 => 2 * i,
            1 => 2 * i + 1,
            _ => 2 * n + i,
        };
        let mut x = DMatrix::zeros(3 * n, 3 * n);
        let mut f = DVector::zeros(3 * n);
        for i in 0..n {
            for r in 0..3 {
                f[row(i, r)] = loads[i][r];
                for c in 0..3 {
                    x[(row(i, r), row(i, c))] = blocks[i][(r, c)];
                }
            }
        }
        let k = h.transpose() * &x * &h;
        let cq = model.closure_jacobian(&q);
        let mut bordered = DMatrix::zeros(D + 2, D + 2);
        bordered.view_mut((0, 0), (D, D)).copy_from(&k);
        for c in 0..D {
            for r in 0..2 {
                bordered[(D + r, c)] = cq[(r, c)];
                bordered[(c, D + r)] = cq[(r, c)];
            }
        }
        let mut rhs = DVector::zeros(D + 2);
        rhs.rows_mut(0, D).copy_from(&(h.transpose() * f));
        let want = bordered.lu().solve(&rhs).expect("regular");
        assert_close(
            &format!("{label}, trial {trial}"),
            &got,
            &want.as_slice()[..D],
            1e-10,
            0.0,
        );
        let closure: SVector<f64, 2> = cq * SVector::<f64, D>::from_column_slice(&got);
        assert!(
            closure.norm() <= 1e-10 * got.iter().map(|v| v.abs()).fold(0.0, f64::max),
            "{label}: the increments keep the loop closed ({closure})"
        );
    }
}

#[test]
fn general_blocks_solve_as_the_dense_bordered_system() {
    check("heterogeneous 10-link loop", PinocchioClosed10, 11);
    check("the M113's 64 links", M113Track, 12);
}
