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

use crate::support;

include!("support/chains.rs");

use support::{Lcg, assert_close};
use trackgen::dynamics::ShiftedChain;
use trackgen::multibody::{RecursiveModel, TrackModel};
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
        chain.factor(&trig, &blocks, &[]).expect("regular");
        let flat: Vec<f64> = loads.iter().flat_map(|f| f.iter().copied()).collect();
        let mut out = vec![0.0; 3 * n];
        chain.solve(&flat, &[], &mut out);
        let out: Vec<Vector3<f64>> = out
            .chunks_exact(3)
            .map(Vector3::from_column_slice)
            .collect();
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

/// With the joints' rows turned and given right sides, against the whole
/// sparse system solved densely: unknowns every link's `x` and every
/// joint's `λ`, rows `Xᵢ xᵢ − D⁺ᵢᵀ λᵢ + D⁻ᵢᵀ λᵢ₋₁ = fᵢ` and
/// `D̃⁺ⱼ xⱼ − D̃⁻ₖ xₖ = cⱼ`. Same bound as above.
#[test]
fn turned_rows_with_right_sides_solve_as_the_whole_system() {
    use trackgen::nalgebra::Vector2;
    let description = M113Track.description();
    let joints = description.joints().expect("a track");
    let n = joints.len();
    let mut rng = Lcg::new(21);
    let mut chain = ShiftedChain::new(&description).expect("a track");
    for trial in 0..3 {
        let trig: Vec<(f64, f64)> = (0..n).map(|_| rng.uniform(-3.2, 3.2).sin_cos()).collect();
        let blocks: Vec<Matrix3<f64>> = description
            .bodies
            .iter()
            .map(|b| {
                Matrix3::from_diagonal(&Vector3::new(b.mass, b.mass, b.inertia))
                    + Matrix3::from_fn(|_, _| rng.uniform(-1.0, 1.0)) * (0.2 * b.inertia)
            })
            .collect();
        let mut random2 =
            |scale: f64| Vector2::new(rng.uniform(-scale, scale), rng.uniform(-scale, scale));
        let turning: Vec<(Vector2<f64>, Vector2<f64>)> =
            (0..n).map(|_| (random2(0.01), random2(0.01))).collect();
        let rights: Vec<Vector2<f64>> = (0..n).map(|_| random2(1.0)).collect();
        let loads: Vec<f64> = (0..3 * n).map(|_| rng.uniform(-100.0, 100.0)).collect();
        chain.factor(&trig, &blocks, &turning).expect("regular");
        let mut got = vec![0.0; 3 * n];
        chain.solve(&loads, &rights, &mut got);

        let lever = |i: usize, u: Vector2<f64>| {
            let (s, c) = trig[i];
            Vector2::new(-(s * u.x + c * u.y), c * u.x - s * u.y)
        };
        let size = 5 * n;
        let mut a = DMatrix::zeros(size, size);
        let mut b = DVector::zeros(size);
        for i in 0..n {
            for r in 0..3 {
                b[3 * i + r] = loads[3 * i + r];
                for c in 0..3 {
                    a[(3 * i + r, 3 * i + c)] = blocks[i][(r, c)];
                }
            }
        }
        for j in 0..n {
            let k = (j + 1) % n;
            let (p2, p1) = (lever(j, joints[j].1), lever(k, joints[k].0));
            let row = 3 * n + 2 * j;
            // The force columns: −D⁺ⱼᵀ λⱼ on link j, +D⁻ₖᵀ λⱼ on link k.
            for r in 0..2 {
                a[(3 * j + r, row + r)] -= 1.0;
                a[(3 * k + r, row + r)] += 1.0;
                a[(3 * j + 2, row + r)] -= p2[r];
                a[(3 * k + 2, row + r)] += p1[r];
            }
            // The rows, turned.
            let (t2, t1) = (p2 + turning[j].1, p1 + turning[k].0);
            for r in 0..2 {
                a[(row + r, 3 * j + r)] += 1.0;
                a[(row + r, 3 * k + r)] -= 1.0;
                a[(row + r, 3 * j + 2)] += t2[r];
                a[(row + r, 3 * k + 2)] -= t1[r];
                b[row + r] = rights[j][r];
            }
        }
        let want = a.lu().solve(&b).expect("regular");
        assert_close(
            &format!("turned rows, trial {trial}"),
            &got,
            &want.as_slice()[..3 * n],
            1e-10,
            0.0,
        );
    }
}

/// Many right sides at once are the same as one at a time, bit for bit
/// or to rounding (1e-13 of the largest increment).
#[test]
fn columns_solve_as_one_side_at_a_time() {
    let description = M113Track.description();
    let n = M113Track::BODIES;
    let mut rng = Lcg::new(31);
    let mut chain = ShiftedChain::new(&description).expect("a track");
    let trig: Vec<(f64, f64)> = (0..n).map(|_| rng.uniform(-3.2, 3.2).sin_cos()).collect();
    let blocks: Vec<Matrix3<f64>> = description
        .bodies
        .iter()
        .map(|b| {
            Matrix3::from_diagonal(&Vector3::new(b.mass, b.mass, b.inertia))
                + Matrix3::from_fn(|_, _| rng.uniform(-1.0, 1.0)) * (0.2 * b.inertia)
        })
        .collect();
    chain.factor(&trig, &blocks, &[]).expect("regular");
    let k = 7;
    let sides: Vec<Vec<f64>> = (0..k)
        .map(|_| (0..3 * n).map(|_| rng.uniform(-100.0, 100.0)).collect())
        .collect();
    let mut columns = vec![0.0; 3 * n * k];
    for (r, side) in sides.iter().enumerate() {
        for (row, v) in side.iter().enumerate() {
            columns[row * k + r] = *v;
        }
    }
    chain.solve_columns(&mut columns, k);
    for (r, side) in sides.iter().enumerate() {
        let mut one = vec![0.0; 3 * n];
        chain.solve(side, &[], &mut one);
        let many: Vec<f64> = (0..3 * n).map(|row| columns[row * k + r]).collect();
        assert_close(&format!("side {r}"), &many, &one, 1e-13, 0.0);
    }
}
