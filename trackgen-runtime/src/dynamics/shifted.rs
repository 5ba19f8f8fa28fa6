//! A closed track's linear-time equations (spec §5) with each link's mass
//! replaced by a general 3 × 3 block: the linear systems of a linearly
//! implicit integrator, in O(n).
//!
//! A Rosenbrock step on a mechanical system solves, for the velocity
//! increments `x`, `(M − a C − a² K) x = f` with `C` and `K` the applied
//! forces' derivatives with respect to the velocities and positions
//! (`a = γ h`). In the links' absolute coordinates `M` is block-diagonal and
//! a contact with the ground touches one link only, so the matrix is
//! block-diagonal too, one block `Xᵢ` per link; the revolute joints keep
//! the links together, their forces `λ` the unknowns of spec §5:
//!
//! ```text
//! Xᵢ xᵢ = fᵢ + D⁺ᵢᵀ λᵢ − D⁻ᵢᵀ λᵢ₋₁,        D⁺ⱼ xⱼ − D⁻ₖ xₖ = 0
//! ```
//!
//! with `xᵢ = (x, y, θ)` increments (the order of a
//! [`BodyLoad`](crate::BodyLoad)'s force and moment), `D⁺ⱼ = [I₂ | A_θʲ ū2ʲ]`,
//! `D⁻ₖ = [I₂ | A_θᵏ ū1ᵏ]`. With `Wᵢ = Xᵢ⁻¹` the joint forces solve the
//! cyclic block-tridiagonal system of spec §5, no longer symmetric
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
//! partitioning (spec §2), and the projected system `Bᵀ Hᵀ X H B z = Bᵀ Hᵀ f`
//! is what this solves.

use nalgebra::{Matrix2, Matrix2x3, Matrix3, Vector2, Vector3};

use crate::DynamicsError;
use crate::model::TreeDescription;
use crate::planar::Rotation;

/// The quarter turn `(x, y) → (−y, x)`: `A_θ ū = ⟂(A ū)`.
#[inline]
fn perp(v: Vector2<f64>) -> Vector2<f64> {
    Vector2::new(-v.y, v.x)
}

/// `[I₂ | p]`: a joint's constraint row block on a link, `p = A_θ ū`.
#[inline]
fn joint_block(p: Vector2<f64>) -> Matrix2x3<f64> {
    Matrix2x3::new(1.0, 0.0, p.x, 0.0, 1.0, p.y)
}

/// A closed track's joints with general link blocks, factored for
/// [`solve`](Self::solve).
#[derive(Debug, Clone)]
pub struct ShiftedChain {
    /// `(ū1, ū2)` of every link, its frame.
    joints: Vec<(Vector2<f64>, Vector2<f64>)>,
    /// `D⁻ᵢ` and `D⁺ᵢ` at the factored state.
    behind: Vec<Matrix2x3<f64>>,
    ahead: Vec<Matrix2x3<f64>>,
    /// `Wᵢ = Xᵢ⁻¹`.
    inverse_blocks: Vec<Matrix3<f64>>,
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
    /// Scratch: the joint forces of a solve.
    lambda: Vec<Vector2<f64>>,
}

impl ShiftedChain {
    /// The chain of the track `description` (a chain with a loop joint:
    /// [`TreeDescription::joints`]); `None` for a tree that is not a track.
    pub fn new(description: &TreeDescription) -> Option<ShiftedChain> {
        let joints = description.joints()?;
        let n = joints.len();
        Some(ShiftedChain {
            joints,
            behind: vec![Matrix2x3::zeros(); n],
            ahead: vec![Matrix2x3::zeros(); n],
            inverse_blocks: vec![Matrix3::zeros(); n],
            lower: vec![Matrix2::zeros(); n],
            upper: vec![Matrix2::zeros(); n],
            factor: vec![Matrix2::zeros(); n],
            inverse: vec![Matrix2::zeros(); n],
            border: vec![Matrix2::zeros(); n],
            schur_inverse: Matrix2::zeros(),
            lambda: vec![Vector2::zeros(); n],
        })
    }

    /// Number of links.
    pub fn links(&self) -> usize {
        self.joints.len()
    }

    /// Factors the equations at the links' `(sin θ, cos θ)` (`trig`) with
    /// the link blocks `blocks` (`Xᵢ`, rows and columns `(x, y, θ)`).
    /// [`DynamicsError::SingularClosure`] if a block or the joints' system
    /// is singular.
    ///
    /// # Panics
    /// If `trig` or `blocks` is not one per link, or the chain has fewer
    /// than 3 links (a programming error).
    // Joint j couples links j and j + 1 (mod n): the loops index neighbours.
    #[allow(clippy::needless_range_loop)]
    pub fn factor(
        &mut self,
        trig: &[(f64, f64)],
        blocks: &[Matrix3<f64>],
    ) -> Result<(), DynamicsError> {
        let n = self.joints.len();
        assert!(n >= 3, "a closed loop of 3 links or more");
        assert_eq!(trig.len(), n, "one (sin, cos) per link");
        assert_eq!(blocks.len(), n, "one block per link");
        let singular = || DynamicsError::SingularClosure;
        for i in 0..n {
            let rotation = Rotation::from_sin_cos(trig[i]);
            let (u1, u2) = self.joints[i];
            self.behind[i] = joint_block(perp(rotation.apply(u1)));
            self.ahead[i] = joint_block(perp(rotation.apply(u2)));
            self.inverse_blocks[i] = blocks[i].try_inverse().ok_or_else(singular)?;
        }
        let mut closing_diagonal = Matrix2::zeros();
        for j in 0..n {
            let k = (j + 1) % n;
            let (wj, wk) = (&self.inverse_blocks[j], &self.inverse_blocks[k]);
            let d = self.ahead[j] * wj * self.ahead[j].transpose()
                + self.behind[k] * wk * self.behind[k].transpose();
            self.lower[j] = -(self.ahead[j] * wj * self.behind[j].transpose());
            self.upper[j] = -(self.behind[k] * wk * self.ahead[k].transpose());
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
    /// (`(F_x, F_y, M)` per link), writing every link's increment
    /// `(x, y, θ)` into `out`.
    ///
    /// # Panics
    /// If `loads` or `out` is not one per link (a programming error).
    pub fn solve(&mut self, loads: &[Vector3<f64>], out: &mut [Vector3<f64>]) {
        let n = self.joints.len();
        assert_eq!(loads.len(), n, "one load per link");
        assert_eq!(out.len(), n, "one increment per link");
        // xᵢ without joint forces, and the joints' right sides.
        for (x, (w, f)) in out.iter_mut().zip(self.inverse_blocks.iter().zip(loads)) {
            *x = w * f;
        }
        let mut lambda = std::mem::take(&mut self.lambda);
        for j in 0..n {
            let k = (j + 1) % n;
            lambda[j] = self.behind[k] * out[k] - self.ahead[j] * out[j];
        }
        let m = n - 1;
        self.solve_tridiagonal(&mut lambda[..m]);
        let closing = self.schur_inverse
            * (lambda[m] - self.upper[m] * lambda[0] - self.lower[m] * lambda[m - 1]);
        for (l, b) in lambda[..m].iter_mut().zip(&self.border) {
            *l -= b * closing;
        }
        lambda[m] = closing;
        for i in 0..n {
            let behind = lambda[(i + n - 1) % n];
            let pull = self.ahead[i].transpose() * lambda[i] - self.behind[i].transpose() * behind;
            out[i] += self.inverse_blocks[i] * pull;
        }
        self.lambda = lambda;
    }
}
