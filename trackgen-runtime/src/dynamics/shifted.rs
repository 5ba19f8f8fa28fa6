//! A closed track's linear-time equations (formulation §5) with each link's mass
//! replaced by a general 3 × 3 block: the linear systems of a linearly
//! implicit integrator, in O(n).
//!
//! A Rosenbrock step on a mechanical system solves, for the velocity
//! increments `x`, `(M − a C − a² K) x = f` with `C` and `K` the applied
//! forces' derivatives with respect to the velocities and positions
//! (`a = γ h`). In the links' absolute coordinates `M` is block-diagonal and
//! a contact with the ground touches one link only, so the matrix is
//! block-diagonal too, one block `Xᵢ` per link; the revolute joints keep
//! the links together, their forces `λ` the unknowns of formulation §5:
//!
//! ```text
//! Xᵢ xᵢ = fᵢ + D⁺ᵢᵀ λᵢ − D⁻ᵢᵀ λᵢ₋₁,        D⁺ⱼ xⱼ − D⁻ₖ xₖ = 0
//! ```
//!
//! with `xᵢ = (x, y, θ)` increments (the order of a
//! [`BodyLoad`](crate::multibody::BodyLoad)'s force and moment), `D⁺ⱼ = [I₂ | A_θʲ ū2ʲ]`,
//! `D⁻ₖ = [I₂ | A_θᵏ ū1ᵏ]`. With `Wᵢ = Xᵢ⁻¹` the joint forces solve the
//! cyclic block-tridiagonal system of formulation §5, no longer symmetric
//! (`C` and `K` of friction are not):
//!
//! ```text
//! diagonal   D⁺ⱼ Wⱼ D⁺ⱼᵀ + D⁻ₖ Wₖ D⁻ₖᵀ
//! lower      −D⁺ⱼ Wⱼ D⁻ⱼᵀ        (to λⱼ₋₁)
//! upper      −D⁻ₖ Wₖ D⁺ₖᵀ        (to λⱼ₊₁)
//! right side −D⁺ⱼ Wⱼ fⱼ + D⁻ₖ Wₖ fₖ
//! ```
//!
//! factored once by block elimination with the closing joint bordered,
//! then solved for as many right sides as asked, each O(n). The solution
//! `x` satisfies the loop's velocity constraint, `C_q x = 0`: in recursive
//! coordinates it is `B z` for the independent increments `z` of
//! partitioning (formulation §2), and the projected system `Bᵀ Hᵀ X H B z = Bᵀ Hᵀ f`
//! is what this solves.
//!
//! The joints' rows may also carry the linearised velocity constraint of a
//! moving chain: a link turned by `δθ` turns its joint levers, so the
//! joints' relative velocity changes by `−A ū ω δθ` (`∂(A_θ ū)/∂θ = −A ū`).
//! With `δθ = u + a x_θ` (the position increment), the rows become
//! `D̃⁺ⱼ xⱼ − D̃⁻ₖ xₖ = cⱼ` with the levers `A_θ ū − a ω A ū` in `D̃` and
//! `cⱼ` from `u` ([`factor`](ShiftedChain::factor)'s `turning`,
//! [`solve`](ShiftedChain::solve)'s `joints`): the velocity increments
//! then include what a turned configuration does to every link's
//! velocity, which friction's slope multiplies.

use nalgebra::{Matrix2, Matrix2x3, Matrix3, Matrix3x2, Vector2, Vector3};

use crate::multibody::DynamicsError;
use crate::multibody::TreeDescription;
use crate::planar::{Rotation, perp};

/// A closed track's joints with general link blocks, factored for
/// [`solve`](Self::solve).
#[derive(Debug, Clone)]
pub struct ShiftedChain {
    /// `(ū1, ū2)` of every link, its frame.
    joints: Vec<(Vector2<f64>, Vector2<f64>)>,
    /// `A_θ ū1` and `A_θ ū2` of every link at the factored state: its
    /// joint blocks are `D⁻ = [I₂ | p1]`, `D⁺ = [I₂ | p2]`.
    levers: Vec<(Vector2<f64>, Vector2<f64>)>,
    /// The levers of the joints' rows, `D̃` (the levers, turned).
    row_levers: Vec<(Vector2<f64>, Vector2<f64>)>,
    /// `Wᵢ = Xᵢ⁻¹`, and `Wᵢ D⁻ᵢᵀ`, `Wᵢ D⁺ᵢᵀ`.
    inverse_blocks: Vec<Matrix3<f64>>,
    pulls: Vec<(Matrix3x2<f64>, Matrix3x2<f64>)>,
    /// Joint `j`'s coupling to joint `j − 1` (for joint 0, to the closing
    /// joint) and to joint `j + 1` (for the closing joint, to joint 0).
    lower: Vec<Matrix2<f64>>,
    upper: Vec<Matrix2<f64>>,
    /// Elimination of joints 0 … n−2: `lowerⱼ (reducedⱼ₋₁)⁻¹` and the
    /// reduced diagonals' inverses.
    factor: Vec<Matrix2<f64>>,
    inverse: Vec<Matrix2<f64>>,
    /// The bordering: the tridiagonal part's inverse applied to the
    /// closing joint's column, and the Schur complement's inverse.
    border: Vec<Matrix2<f64>>,
    schur_inverse: Matrix2<f64>,
    /// Scratch of a solve: `Wᵢ fᵢ` and the joint forces.
    free: Vec<Vector3<f64>>,
    lambda: Vec<Vector2<f64>>,
    /// Scratch of [`solve_columns`](Self::solve_columns).
    free_columns: Vec<f64>,
    lambda_columns: Vec<f64>,
}

/// `D v = v_xy + p v_θ` of a joint block `[I₂ | p]`.
#[inline]
fn constrain(p: Vector2<f64>, v: &Vector3<f64>) -> Vector2<f64> {
    Vector2::new(v.x + p.x * v.z, v.y + p.y * v.z)
}

/// `[I₂ | p]` as a matrix.
#[inline]
fn joint_block(p: Vector2<f64>) -> Matrix2x3<f64> {
    Matrix2x3::new(1.0, 0.0, p.x, 0.0, 1.0, p.y)
}

impl ShiftedChain {
    /// The chain of the track `description` (a chain with a loop joint:
    /// [`TreeDescription::joints`]); `None` for a tree that is not a track.
    pub fn new(description: &TreeDescription) -> Option<ShiftedChain> {
        let joints = description.joints()?;
        let n = joints.len();
        Some(ShiftedChain {
            joints,
            levers: vec![(Vector2::zeros(), Vector2::zeros()); n],
            row_levers: vec![(Vector2::zeros(), Vector2::zeros()); n],
            inverse_blocks: vec![Matrix3::zeros(); n],
            pulls: vec![(Matrix3x2::zeros(), Matrix3x2::zeros()); n],
            lower: vec![Matrix2::zeros(); n],
            upper: vec![Matrix2::zeros(); n],
            factor: vec![Matrix2::zeros(); n],
            inverse: vec![Matrix2::zeros(); n],
            border: vec![Matrix2::zeros(); n],
            schur_inverse: Matrix2::zeros(),
            free: vec![Vector3::zeros(); n],
            lambda: vec![Vector2::zeros(); n],
            free_columns: Vec::new(),
            lambda_columns: Vec::new(),
        })
    }

    /// Number of links.
    pub fn links(&self) -> usize {
        self.joints.len()
    }

    /// Factors the equations at the links' `(sin θ, cos θ)` (`trig`) with
    /// the link blocks `blocks` (`Xᵢ`, rows and columns `(x, y, θ)`) and
    /// the joints' rows' levers turned by `turning` (per link, what is
    /// added to `A_θ ū1` and `A_θ ū2` in the rows; empty for none).
    /// [`DynamicsError::SingularClosure`] if a block or the joints' system
    /// is singular.
    ///
    /// # Panics
    /// If `trig` or `blocks` is not one per link, `turning` neither that
    /// nor empty, or the chain has fewer than 3 links (a programming
    /// error).
    // Joint j couples links j and j + 1 (mod n): the loops index neighbours.
    #[allow(clippy::needless_range_loop)]
    pub fn factor(
        &mut self,
        trig: &[(f64, f64)],
        blocks: &[Matrix3<f64>],
        turning: &[(Vector2<f64>, Vector2<f64>)],
    ) -> Result<(), DynamicsError> {
        let n = self.joints.len();
        assert!(n >= 3, "a closed loop of 3 links or more");
        assert_eq!(trig.len(), n, "one (sin, cos) per link");
        assert_eq!(blocks.len(), n, "one block per link");
        assert!(turning.is_empty() || turning.len() == n, "turning per link");
        let singular = || DynamicsError::SingularClosure;
        for i in 0..n {
            let rotation = Rotation::from_sin_cos(trig[i]);
            let (u1, u2) = self.joints[i];
            let (p1, p2) = (perp(rotation.apply(u1)), perp(rotation.apply(u2)));
            self.levers[i] = (p1, p2);
            self.row_levers[i] = match turning.get(i) {
                Some((t1, t2)) => (p1 + t1, p2 + t2),
                None => (p1, p2),
            };
            let w = blocks[i].try_inverse().ok_or_else(singular)?;
            self.inverse_blocks[i] = w;
            self.pulls[i] = (
                w * joint_block(p1).transpose(),
                w * joint_block(p2).transpose(),
            );
        }
        let mut closing_diagonal = Matrix2::zeros();
        for j in 0..n {
            let k = (j + 1) % n;
            let (ahead_j, behind_k) = (
                joint_block(self.row_levers[j].1),
                joint_block(self.row_levers[k].0),
            );
            let d = ahead_j * self.pulls[j].1 + behind_k * self.pulls[k].0;
            self.lower[j] = -(ahead_j * self.pulls[j].0);
            self.upper[j] = -(behind_k * self.pulls[k].1);
            if j + 1 == n {
                closing_diagonal = d;
                continue;
            }
            // Eliminate joint j against joint j − 1 as the diagonal comes.
            let mut reduced = d;
            if j > 0 {
                self.factor[j] = self.lower[j] * self.inverse[j - 1];
                reduced -= self.factor[j] * self.upper[j - 1];
            }
            self.inverse[j] = reduced.try_inverse().ok_or_else(singular)?;
        }
        // The closing joint couples to joint 0 (through link 0) and to
        // joint n − 2 (through link n − 1): its column in rows 0 and m − 1,
        // its row's blocks on columns 0 and m − 1.
        let m = n - 1;
        let mut border = std::mem::take(&mut self.border);
        border.truncate(m);
        border.iter_mut().for_each(|b| *b = Matrix2::zeros());
        border[0] += self.lower[0];
        border[m - 1] += self.upper[m - 1];
        self.solve_tridiagonal(&mut border);
        let schur =
            closing_diagonal - self.upper[n - 1] * border[0] - self.lower[n - 1] * border[m - 1];
        self.schur_inverse = schur.try_inverse().ok_or_else(singular)?;
        border.resize(n, Matrix2::zeros());
        self.border = border;
        Ok(())
    }

    /// The tridiagonal part's inverse (joints 0 … n−2) applied to a column
    /// of blocks or vectors, in place.
    fn solve_tridiagonal<V>(&self, column: &mut [V])
    where
        V: Copy + std::ops::SubAssign,
        Matrix2<f64>: std::ops::Mul<V, Output = V>,
    {
        let m = column.len();
        for j in 1..m {
            let previous = column[j - 1];
            column[j] -= self.factor[j] * previous;
        }
        column[m - 1] = self.inverse[m - 1] * column[m - 1];
        for j in (0..m - 1).rev() {
            let next = column[j + 1];
            let mut v = column[j];
            v -= self.upper[j] * next;
            column[j] = self.inverse[j] * v;
        }
    }

    /// Solves the factored equations for the link loads `loads`
    /// (`(F_x, F_y, M)` per link, 3 values each) and the joints' right
    /// sides `joints` (`cⱼ`, one per joint, or empty for zero), writing
    /// every link's increment `(x, y, θ)` into `out` (3 values each).
    ///
    /// # Panics
    /// If `loads` or `out` is not 3 values per link, or `joints` neither
    /// one per joint nor empty (a programming error).
    pub fn solve(&mut self, loads: &[f64], joints: &[Vector2<f64>], out: &mut [f64]) {
        crate::simd::run(
            #[inline(always)]
            || self.solve_inline(loads, joints, out),
        );
    }

    /// [`solve`](Self::solve)'s loops, inlined into its wide build.
    #[inline(always)]
    fn solve_inline(&mut self, loads: &[f64], joints: &[Vector2<f64>], out: &mut [f64]) {
        let n = self.joints.len();
        assert_eq!(loads.len(), 3 * n, "one load per link");
        assert_eq!(out.len(), 3 * n, "one increment per link");
        assert!(
            joints.is_empty() || joints.len() == n,
            "one right side per joint"
        );
        // xᵢ without joint forces, and the joints' right sides.
        let mut free = std::mem::take(&mut self.free);
        for ((x, w), f) in free
            .iter_mut()
            .zip(&self.inverse_blocks)
            .zip(loads.chunks_exact(3))
        {
            *x = w * Vector3::new(f[0], f[1], f[2]);
        }
        let mut lambda = std::mem::take(&mut self.lambda);
        for j in 0..n {
            let k = (j + 1) % n;
            lambda[j] = joints.get(j).copied().unwrap_or_else(Vector2::zeros)
                + constrain(self.row_levers[k].0, &free[k])
                - constrain(self.row_levers[j].1, &free[j]);
        }
        let m = n - 1;
        self.solve_tridiagonal(&mut lambda[..m]);
        let closing = self.schur_inverse
            * (lambda[m] - self.upper[m] * lambda[0] - self.lower[m] * lambda[m - 1]);
        for (l, b) in lambda[..m].iter_mut().zip(&self.border) {
            *l -= b * closing;
        }
        lambda[m] = closing;
        for (i, x) in out.chunks_exact_mut(3).enumerate() {
            let behind = lambda[(i + n - 1) % n];
            let (from_behind, from_ahead) = &self.pulls[i];
            let v = free[i] + from_ahead * lambda[i] - from_behind * behind;
            x.copy_from_slice(v.as_slice());
        }
        self.free = free;
        self.lambda = lambda;
    }

    /// [`solve`](Self::solve) for `k` right sides at once (the joints'
    /// right sides zero), in place: `columns[(3 i + c) k + r]` is
    /// component `c` (`F_x, F_y, M` in, `x, y, θ` out) of link `i` in
    /// right side `r`. The sweeps run along the chain once, each step on
    /// all `k` sides: what factoring a coupled system needs (one side per
    /// coupled coordinate), with the chain's factors read once for all
    /// `k` sides instead of once per side.
    ///
    /// # Panics
    /// If `columns` is not `3 n k` long (a programming error).
    // Joint j couples links j and j + 1 (mod n): the loops index neighbours.
    #[allow(clippy::needless_range_loop)]
    pub fn solve_columns(&mut self, columns: &mut [f64], k: usize) {
        let n = self.joints.len();
        assert_eq!(columns.len(), 3 * n * k, "3 values per link per side");
        let mut free = std::mem::take(&mut self.free_columns);
        let mut lambda = std::mem::take(&mut self.lambda_columns);
        free.resize(3 * n * k, 0.0);
        lambda.resize(2 * n * k, 0.0);
        #[cfg(target_arch = "x86_64")]
        if std::arch::is_x86_feature_detected!("avx2") {
            // SAFETY: the processor has AVX2, checked just above.
            unsafe { self.sweep_columns_avx2(columns, k, &mut free, &mut lambda) };
        } else {
            self.sweep_columns(columns, k, &mut free, &mut lambda);
        }
        #[cfg(not(target_arch = "x86_64"))]
        self.sweep_columns(columns, k, &mut free, &mut lambda);
        self.free_columns = free;
        self.lambda_columns = lambda;
    }

    /// [`sweep_columns`](Self::sweep_columns) compiled for AVX2: four
    /// sides at a time instead of two, the same bits. Not through
    /// [`simd::run`](crate::simd::run): behind its closure the sweeps are
    /// not inlined into the wide build (docs/experiments/avx2-builds.md).
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2")]
    fn sweep_columns_avx2(
        &self,
        columns: &mut [f64],
        k: usize,
        free: &mut [f64],
        lambda: &mut [f64],
    ) {
        self.sweep_columns(columns, k, free, lambda);
    }

    /// [`solve_columns`](Self::solve_columns)'s sweeps, with its scratch.
    // Joint j couples links j and j + 1 (mod n): the loops index neighbours.
    #[allow(clippy::needless_range_loop)]
    #[inline(always)]
    fn sweep_columns(&self, columns: &mut [f64], k: usize, free: &mut [f64], lambda: &mut [f64]) {
        let n = self.joints.len();
        // `Wᵢ fᵢ`.
        for i in 0..n {
            let w = &self.inverse_blocks[i];
            let f = &columns[3 * i * k..3 * (i + 1) * k];
            let (f0, rest) = f.split_at(k);
            let (f1, f2) = rest.split_at(k);
            let out = &mut free[3 * i * k..3 * (i + 1) * k];
            for c in 0..3 {
                let (w0, w1, w2) = (w[(c, 0)], w[(c, 1)], w[(c, 2)]);
                for (r, o) in out[c * k..(c + 1) * k].iter_mut().enumerate() {
                    *o = w0 * f0[r] + w1 * f1[r] + w2 * f2[r];
                }
            }
        }
        // The joints' right sides: `D̃⁻ₖ Wₖ fₖ − D̃⁺ⱼ Wⱼ fⱼ`.
        // On slices of k (no index arithmetic inside: the loops vectorise).
        let side = |i: usize, c: usize| &free[(3 * i + c) * k..(3 * i + c + 1) * k];
        for (j, rows) in lambda.chunks_exact_mut(2 * k).enumerate() {
            let next = (j + 1) % n;
            let (p1, p2) = (self.row_levers[next].0, self.row_levers[j].1);
            let (turn_ahead, turn_here) = (side(next, 2), side(j, 2));
            for (c, row) in rows.chunks_exact_mut(k).enumerate() {
                let (ahead, here) = (side(next, c), side(j, c));
                for ((((l, &a), &ta), &h), &th) in row
                    .iter_mut()
                    .zip(ahead)
                    .zip(turn_ahead)
                    .zip(here)
                    .zip(turn_here)
                {
                    *l = (a + p1[c] * ta) - (h + p2[c] * th);
                }
            }
        }
        // `λ ← M λ` and `λ_row ← λ_row − M λ_other` on 2 × k blocks.
        #[inline(always)]
        fn apply(m: &Matrix2<f64>, v: &mut [f64], k: usize) {
            let (v0, v1) = v[..2 * k].split_at_mut(k);
            for (x, y) in v0.iter_mut().zip(v1) {
                let (a, b) = (*x, *y);
                *x = m[(0, 0)] * a + m[(0, 1)] * b;
                *y = m[(1, 0)] * a + m[(1, 1)] * b;
            }
        }
        #[inline(always)]
        fn subtract(m: &Matrix2<f64>, row: &mut [f64], other: &[f64], k: usize) {
            let (r0, r1) = row[..2 * k].split_at_mut(k);
            let (o0, o1) = other[..2 * k].split_at(k);
            for (((x, y), &a), &b) in r0.iter_mut().zip(r1).zip(o0).zip(o1) {
                *x -= m[(0, 0)] * a + m[(0, 1)] * b;
                *y -= m[(1, 0)] * a + m[(1, 1)] * b;
            }
        }
        let m = n - 1;
        let block = 2 * k;
        for j in 1..m {
            let (before, after) = lambda.split_at_mut(block * j);
            subtract(
                &self.factor[j],
                &mut after[..block],
                &before[block * (j - 1)..],
                k,
            );
        }
        apply(
            &self.inverse[m - 1],
            &mut lambda[block * (m - 1)..block * m],
            k,
        );
        for j in (0..m - 1).rev() {
            let (here, after) = lambda.split_at_mut(block * (j + 1));
            let row = &mut here[block * j..];
            subtract(&self.upper[j], row, &after[..block], k);
            apply(&self.inverse[j], row, k);
        }
        {
            let (head, last) = lambda.split_at_mut(block * m);
            subtract(&self.upper[m], last, &head[..block], k);
            subtract(&self.lower[m], last, &head[block * (m - 1)..], k);
            apply(&self.schur_inverse, last, k);
            for j in 0..m {
                subtract(
                    &self.border[j],
                    &mut head[block * j..block * (j + 1)],
                    last,
                    k,
                );
            }
        }
        // `xᵢ = Wᵢ fᵢ + Wᵢ D⁺ᵢᵀ λᵢ − Wᵢ D⁻ᵢᵀ λᵢ₋₁`.
        for (i, (link, free)) in columns
            .chunks_exact_mut(3 * k)
            .zip(free.chunks_exact(3 * k))
            .enumerate()
        {
            let behind = (i + n - 1) % n;
            let (from_behind, from_ahead) = &self.pulls[i];
            let (l0, l1) = lambda[2 * i * k..2 * (i + 1) * k].split_at(k);
            let (b0s, b1s) = lambda[2 * behind * k..2 * (behind + 1) * k].split_at(k);
            for (c, (out, free)) in link
                .chunks_exact_mut(k)
                .zip(free.chunks_exact(k))
                .enumerate()
            {
                let (a0, a1) = (from_ahead[(c, 0)], from_ahead[(c, 1)]);
                let (b0, b1) = (from_behind[(c, 0)], from_behind[(c, 1)]);
                for (((((o, &f), &x0), &x1), &y0), &y1) in
                    out.iter_mut().zip(free).zip(l0).zip(l1).zip(b0s).zip(b1s)
                {
                    *o = f + a0 * x0 + a1 * x1 - b0 * y0 - b1 * y1;
                }
            }
        }
    }
}
