//! The derivative of a track's linear-time forward dynamics (formulation §5):
//! the equations factored once at a state, then solved for as many
//! directions as asked, each in O(n).
//!
//! The unknowns of formulation §5 are every link's absolute accelerations
//! `aᵢ = (θ̈ⁱ, ẍⁱ, ÿⁱ)` and every joint's force `λⱼ`:
//!
//! ```text
//! Nᵢ:  Mᵢ aᵢ − D⁺ᵢᵀ λᵢ + D⁻ᵢᵀ λᵢ₋₁ = Fᵢ
//! Cⱼ:  D⁺ⱼ aⱼ − D⁻ₖ aₖ = κⱼ,   κⱼ = Aʲ ū2ʲ ωⱼ² − Aᵏ ū1ᵏ ωₖ²   (joint j: link j → k)
//! ```
//!
//! with `D⁺ⱼ = [A_θʲ ū2ʲ | I₂]`, `D⁻ₖ = [A_θᵏ ū1ᵏ | I₂]`. Differentiated
//! along a direction (`δθ`, `δω` of the links, `δF` of their loads), the
//! same matrix meets new right sides:
//!
//! ```text
//! Mᵢ δaᵢ − D⁺ᵢᵀ δλᵢ + D⁻ᵢᵀ δλᵢ₋₁ = δFᵢ + δD⁺ᵢᵀ λᵢ − δD⁻ᵢᵀ λᵢ₋₁
//! D⁺ⱼ δaⱼ − D⁻ₖ δaₖ = δκⱼ − δD⁺ⱼ aⱼ + δD⁻ₖ aₖ
//! ```
//!
//! where `δD` is local to its link (`∂(A_θ ū)/∂θ = −A ū`): the first line
//! is a load (a moment `δp2·λᵢ − δp1·λᵢ₋₁` besides `δF`), the second a
//! joint's right side. So the block-tridiagonal system for the `λ`
//! (cyclic for a constrained loop: bordering) is factored once and each
//! direction is one forward and one backward sweep, the way Pinocchio's
//! `computeABADerivatives` reuses the articulated-body factorisation for
//! its derivatives (Carpentier & Mansard, RSS 2018).

use nalgebra::{Matrix2, Vector2};

use crate::multibody::DynamicsError;
use crate::multibody::{BodyLoad, ClosingJoint, TreeDescription};
use crate::planar::{Rotation, perp};

/// A link's constants.
#[derive(Debug, Clone, Copy)]
struct Link {
    inv_mass: f64,
    inv_inertia: f64,
    mass: f64,
    u1: Vector2<f64>,
    u2: Vector2<f64>,
}

/// A link at the factored state: `A ū1`, `A ū2` (`a1`, `a2`), their
/// derivatives `A_θ ū1`, `A_θ ū2` (`p1`, `p2`), `ω`, and the load with
/// gravity (and a cut joint's force) in it.
#[derive(Debug, Clone, Copy, Default)]
struct AtState {
    a1: Vector2<f64>,
    a2: Vector2<f64>,
    p1: Vector2<f64>,
    p2: Vector2<f64>,
    omega: f64,
    force: Vector2<f64>,
    moment: f64,
}

#[inline]
fn outer(a: Vector2<f64>, b: Vector2<f64>) -> Matrix2<f64> {
    a * b.transpose()
}

#[inline]
fn inverse2(m: &Matrix2<f64>) -> Option<Matrix2<f64>> {
    let det = m[(0, 0)] * m[(1, 1)] - m[(0, 1)] * m[(1, 0)];
    (det != 0.0 && det.is_finite())
        .then(|| Matrix2::new(m[(1, 1)], -m[(0, 1)], -m[(1, 0)], m[(0, 0)]) / det)
}

/// One direction along which to differentiate: per link, the change of
/// its angle `δθ` (rad), of its angular velocity `δω` (rad/s) and of the
/// load on it besides gravity `δF` (N, N m); for a constrained loop the
/// change of the stabilisation on the closing joint (m/s²), for a cut one
/// of the force across the cut (N). Absent slices are zero.
#[derive(Debug, Clone, Copy, Default)]
pub struct ChainDirection<'a> {
    /// `δθ`, one per link, or empty.
    pub angles: &'a [f64],
    /// `δω`, one per link, or empty.
    pub rates: &'a [f64],
    /// `δF`, one per link, or empty.
    pub loads: &'a [BodyLoad],
    /// The change of the closing joint's stabilisation (constrained) or
    /// cut force (cut).
    pub closing: Vector2<f64>,
}

/// Many directions along which to differentiate
/// ([`ChainTangent::directions`]): the slices of [`ChainDirection`] for
/// `columns` directions, link-major (entry `i · columns + c` is link `i`
/// along direction `c`), and one closing change per direction. Absent
/// slices are zero.
#[derive(Debug, Clone, Copy, Default)]
pub struct ChainDirections<'a> {
    /// How many directions.
    pub columns: usize,
    /// `δθ` (rad), `n × columns`, or empty.
    pub angles: &'a [f64],
    /// `δω` (rad/s), `n × columns`, or empty.
    pub rates: &'a [f64],
    /// `δF` (N, N m), `n × columns`, or empty.
    pub loads: &'a [BodyLoad],
    /// The closing joint's change per direction, or empty.
    pub closing: &'a [Vector2<f64>],
}

/// A track's linear-time equations factored at a state, for the
/// derivative of its accelerations along any number of directions
/// ([`ChainTangent::direction`]), O(n) each.
#[derive(Debug, Clone)]
pub struct ChainTangent {
    links: Vec<Link>,
    gravity: Vector2<f64>,
    /// Whether the closing joint is a constraint (else cut).
    closed: bool,
    /// The force across a cut closing joint at the state.
    cut_force: Vector2<f64>,
    at: Vec<AtState>,
    /// `λ`-system blocks: each joint's coupling to the previous (for joint
    /// 0 of a constrained loop, to the closing joint).
    lower: Vec<Matrix2<f64>>,
    /// The closing joint's diagonal block.
    closing_diagonal: Matrix2<f64>,
    /// Elimination: `lowerⱼ inverseⱼ₋₁` and the reduced diagonals'
    /// inverses, joints 0 … n−2.
    factor: Vec<Matrix2<f64>>,
    inverse: Vec<Matrix2<f64>>,
    /// Bordering (constrained loop): the tridiagonal part's inverse
    /// applied to the closing joint's columns, and the Schur complement's
    /// inverse.
    border: Vec<Matrix2<f64>>,
    schur_inverse: Matrix2<f64>,
    /// The solution at the state: accelerations `(θ̈, ẍ, ÿ)` per link and
    /// the joint forces.
    theta_dd: Vec<f64>,
    linear_dd: Vec<Vector2<f64>>,
    lambda: Vec<Vector2<f64>>,
    /// Scratch of a direction.
    rhs: Vec<Vector2<f64>>,
    forces: Vec<Vector2<f64>>,
    moments: Vec<f64>,
    /// Zero joint forces beyond an open chain's ends, one per direction.
    zeros: Vec<Vector2<f64>>,
}

impl ChainTangent {
    /// The tangent of the track described by `description` (a chain with
    /// a loop joint: [`TreeDescription::joints`]). `None` for a tree that
    /// is not a track.
    pub fn new(description: &TreeDescription) -> Option<ChainTangent> {
        let joints = description.joints()?;
        let n = joints.len();
        let links = description
            .bodies
            .iter()
            .zip(&joints)
            .map(|(body, &(u1, u2))| Link {
                inv_mass: 1.0 / body.mass,
                inv_inertia: 1.0 / body.inertia,
                mass: body.mass,
                u1,
                u2,
            })
            .collect();
        Some(ChainTangent {
            links,
            gravity: description.gravity,
            closed: false,
            cut_force: Vector2::zeros(),
            at: vec![AtState::default(); n],
            lower: vec![Matrix2::zeros(); n],
            closing_diagonal: Matrix2::zeros(),
            factor: vec![Matrix2::zeros(); n],
            inverse: vec![Matrix2::zeros(); n],
            border: vec![Matrix2::zeros(); n],
            schur_inverse: Matrix2::zeros(),
            theta_dd: vec![0.0; n],
            linear_dd: vec![Vector2::zeros(); n],
            lambda: vec![Vector2::zeros(); n],
            rhs: vec![Vector2::zeros(); n],
            forces: vec![Vector2::zeros(); n],
            moments: vec![0.0; n],
            zeros: Vec::new(),
        })
    }

    /// Number of links.
    pub fn links(&self) -> usize {
        self.links.len()
    }

    /// Factors the equations at the state given by every link's
    /// `(sin θ, cos θ)` (`trig`) and `ω` (`rates`), under `loads` besides
    /// gravity (one per link, or none) and the closing joint as `closing`
    /// acts; solves them there (the accelerations and joint forces every
    /// direction needs). The same accelerations as the generated
    /// [`linear_time_dynamics`](crate::multibody::TrackModel::linear_time_dynamics).
    ///
    /// # Panics
    /// If `trig` or `rates` is not one per link, or `loads` neither one per
    /// link nor empty (a programming error).
    // Joint j couples links j and j + 1 (mod n): the loops index neighbours.
    #[allow(clippy::needless_range_loop)]
    pub fn factor(
        &mut self,
        trig: &[(f64, f64)],
        rates: &[f64],
        loads: &[BodyLoad],
        closing: ClosingJoint,
    ) -> Result<(), DynamicsError> {
        let n = self.links.len();
        assert_eq!(trig.len(), n, "one (sin, cos) per link");
        assert_eq!(rates.len(), n, "one rate per link");
        assert!(loads.is_empty() || loads.len() == n, "loads per link");
        let (closed, stabilisation, cut) = match closing {
            ClosingJoint::Constrained { stabilisation } => (true, stabilisation, Vector2::zeros()),
            ClosingJoint::Cut { force } => (false, Vector2::zeros(), force),
        };
        if closed && n < 3 {
            return Err(DynamicsError::WrongLength {
                what: "links of a closed loop (at least 3)",
                expected: 3,
                got: n,
            });
        }
        self.closed = closed;
        self.cut_force = cut;
        for (i, (link, at)) in self.links.iter().zip(self.at.iter_mut()).enumerate() {
            let rotation = Rotation::from_sin_cos(trig[i]);
            let (a1, a2) = (rotation.apply(link.u1), rotation.apply(link.u2));
            let load = loads.get(i).copied().unwrap_or(BodyLoad::ZERO);
            *at = AtState {
                a1,
                a2,
                p1: perp(a1),
                p2: perp(a2),
                omega: rates[i],
                force: self.gravity * link.mass + load.force,
                moment: load.moment,
            };
        }
        if !closed {
            let (last, first) = (self.at[n - 1], self.at[0]);
            self.at[n - 1].force += cut;
            self.at[n - 1].moment += last.p2.dot(&cut);
            self.at[0].force -= cut;
            self.at[0].moment -= first.p1.dot(&cut);
        }
        // The blocks, joint j joining link j to link k = j + 1 (the closing
        // joint, n − 1, link n − 1 to link 0).
        let identity = Matrix2::identity();
        let mut diagonal = vec![Matrix2::zeros(); n];
        for j in 0..n {
            let k = (j + 1) % n;
            let (lj, lk) = (&self.links[j], &self.links[k]);
            let (sj, sk) = (&self.at[j], &self.at[k]);
            diagonal[j] = outer(sj.p2, sj.p2) * lj.inv_inertia
                + outer(sk.p1, sk.p1) * lk.inv_inertia
                + identity * (lj.inv_mass + lk.inv_mass);
            self.lower[j] = -(outer(sj.p2, sj.p1) * lj.inv_inertia + identity * lj.inv_mass);
        }
        self.closing_diagonal = diagonal[n - 1];
        let m = n - 1;
        let singular = || DynamicsError::SingularClosure;
        for j in 0..m {
            let mut d = diagonal[j];
            if j > 0 {
                self.factor[j] = self.lower[j] * self.inverse[j - 1];
                d -= self.factor[j] * self.lower[j].transpose();
            }
            self.inverse[j] = inverse2(&d).ok_or_else(singular)?;
        }
        if closed {
            // The closing joint couples to joint 0 through link 0 and to
            // joint m − 1 through link n − 1: B's two blocks.
            let (b0, bm) = (self.lower[0], self.lower[n - 1].transpose());
            let mut columns = vec![Matrix2::zeros(); m];
            columns[0] += b0;
            columns[m - 1] += bm;
            self.solve_tridiagonal_matrix(&mut columns);
            let schur = self.closing_diagonal
                - b0.transpose() * columns[0]
                - bm.transpose() * columns[m - 1];
            self.schur_inverse = inverse2(&schur).ok_or_else(singular)?;
            self.border = columns;
        }
        // The solution at the state.
        let mut lambda = std::mem::take(&mut self.lambda);
        for j in 0..n {
            let k = (j + 1) % n;
            let (sj, sk) = (self.at[j], self.at[k]);
            lambda[j] = sj.a2 * (sj.omega * sj.omega) - sk.a1 * (sk.omega * sk.omega);
            self.forces[j] = sj.force;
            self.moments[j] = sj.moment;
        }
        if closed {
            lambda[n - 1] -= stabilisation;
        }
        self.solve_loaded(&mut lambda, &self.forces, &self.moments, 1);
        self.lambda = lambda;
        for i in 0..n {
            let load = (self.forces[i], self.moments[i]);
            let (theta, linear) = self.accelerations_of(i, &self.lambda, load);
            self.theta_dd[i] = theta;
            self.linear_dd[i] = linear;
        }
        Ok(())
    }

    /// `q̈_i` at the factored state: `(ẍ¹, ÿ¹, θ̈¹ … θ̈ⁿ)`, into `out`
    /// (`n + 2` long).
    pub fn accelerations(&self, out: &mut [f64]) {
        out[0] = self.linear_dd[0].x;
        out[1] = self.linear_dd[0].y;
        out[2..].copy_from_slice(&self.theta_dd);
    }

    /// The joint forces at the factored state, as
    /// [`linear_time_dynamics`](crate::multibody::TrackModel::linear_time_dynamics)
    /// gives them (the last the closing joint's; zero when cut).
    pub fn joint_forces(&self) -> &[Vector2<f64>] {
        &self.lambda
    }

    /// The derivative of `q̈_i` along `direction`, into `out` (`n + 2`
    /// long): `(δẍ¹, δÿ¹, δθ̈¹ … δθ̈ⁿ)`.
    ///
    /// # Panics
    /// If a slice of `direction` is neither empty nor one per link, or
    /// `out` not `n + 2` long (a programming error).
    pub fn direction(&mut self, direction: &ChainDirection<'_>, out: &mut [f64]) {
        self.directions(
            &ChainDirections {
                columns: 1,
                angles: direction.angles,
                rates: direction.rates,
                loads: direction.loads,
                closing: std::slice::from_ref(&direction.closing),
            },
            out,
        );
    }

    /// The derivative of `q̈_i` along many directions at once (the same
    /// sweeps as [`ChainTangent::direction`], each step over every
    /// direction: a Jacobian's columns), into `out`, `(n + 2) × columns`
    /// row by row: entry `r · columns + c` is row `r` of
    /// `(δẍ¹, δÿ¹, δθ̈¹ … δθ̈ⁿ)` along direction `c`.
    ///
    /// # Panics
    /// If a slice of `directions` is neither empty nor its documented
    /// length, or `out` not `(n + 2) × columns` long (a programming error).
    // Joint j couples links j and j + 1 (mod n): the loops index neighbours.
    #[allow(clippy::needless_range_loop)]
    pub fn directions(&mut self, directions: &ChainDirections<'_>, out: &mut [f64]) {
        let n = self.links.len();
        let k = directions.columns;
        let size = n * k;
        let ChainDirections {
            angles,
            rates,
            loads,
            closing,
            ..
        } = *directions;
        assert!(
            angles.is_empty() || angles.len() == size,
            "angles per link and direction"
        );
        assert!(
            rates.is_empty() || rates.len() == size,
            "rates per link and direction"
        );
        assert!(
            loads.is_empty() || loads.len() == size,
            "loads per link and direction"
        );
        assert!(
            closing.is_empty() || closing.len() == k,
            "a closing change per direction"
        );
        assert_eq!(out.len(), (n + 2) * k, "(n + 2) rows per direction");
        let angle = |e: usize| angles.get(e).copied().unwrap_or(0.0);
        let mut forces = std::mem::take(&mut self.forces);
        let mut moments = std::mem::take(&mut self.moments);
        let mut rhs = std::mem::take(&mut self.rhs);
        forces.clear();
        moments.clear();
        rhs.clear();
        if loads.is_empty() {
            forces.resize(size, Vector2::zeros());
            moments.resize(size, 0.0);
        } else {
            forces.extend(loads.iter().map(|l| l.force));
            moments.extend(loads.iter().map(|l| l.moment));
        }
        // The loads: `δF`, and the moment of the joint forces on the
        // turned lever arms, `δp2·λᵢ − δp1·λᵢ₋₁` (`δp = −A ū δθ`).
        if !angles.is_empty() {
            for i in 0..n {
                let at = &self.at[i];
                let (ahead, behind) = self.neighbours(i, &self.lambda);
                let turning = -at.a2.dot(&ahead) + at.a1.dot(&behind);
                let row = i * k..(i + 1) * k;
                for (moment, dtheta) in moments[row.clone()].iter_mut().zip(&angles[row]) {
                    *moment += turning * dtheta;
                }
            }
        }
        if !self.closed {
            // The cut force on the turned arms, and its own change.
            let f = self.cut_force;
            let (last, first) = (self.at[n - 1], self.at[0]);
            for c in 0..k {
                let df = closing.get(c).copied().unwrap_or_else(Vector2::zeros);
                let (e_last, dl, d0) = ((n - 1) * k + c, angle((n - 1) * k + c), angle(c));
                forces[e_last] += df;
                moments[e_last] += last.p2.dot(&df) - last.a2.dot(&f) * dl;
                forces[c] -= df;
                moments[c] -= first.p1.dot(&df) - first.a1.dot(&f) * d0;
            }
        }
        // The joints' right sides: `δκⱼ − δD⁺ⱼ aⱼ + δD⁻ₖ aₖ`, with
        // `δκⱼ = p2ⱼ ωⱼ² δθⱼ + 2 a2ⱼ ωⱼ δωⱼ − p1ₖ ωₖ² δθₖ − 2 a1ₖ ωₖ δωₖ` and
        // `δD⁺ⱼ aⱼ = δp2ⱼ θ̈ⱼ = −a2ⱼ θ̈ⱼ δθⱼ`.
        rhs.resize(size, Vector2::zeros());
        for j in 0..n {
            let l = (j + 1) % n;
            let (sj, sl) = (&self.at[j], &self.at[l]);
            let (wj, wl) = (sj.omega, sl.omega);
            let row = &mut rhs[j * k..(j + 1) * k];
            if !angles.is_empty() {
                let by_angle_j = sj.p2 * (wj * wj) + sj.a2 * self.theta_dd[j];
                let by_angle_l = sl.p1 * (wl * wl) + sl.a1 * self.theta_dd[l];
                let (tj, tl) = (&angles[j * k..(j + 1) * k], &angles[l * k..(l + 1) * k]);
                for ((r, a), b) in row.iter_mut().zip(tj).zip(tl) {
                    *r += by_angle_j * *a - by_angle_l * *b;
                }
            }
            if !rates.is_empty() {
                let (by_rate_j, by_rate_l) = (sj.a2 * (2.0 * wj), sl.a1 * (2.0 * wl));
                let (rj, rl) = (&rates[j * k..(j + 1) * k], &rates[l * k..(l + 1) * k]);
                for ((r, a), b) in row.iter_mut().zip(rj).zip(rl) {
                    *r += by_rate_j * *a - by_rate_l * *b;
                }
            }
        }
        if self.closed {
            for (r, change) in rhs[(n - 1) * k..].iter_mut().zip(closing) {
                *r -= change;
            }
        }
        self.solve_loaded(&mut rhs, &forces, &moments, k);
        // Every link's `δθ̈` (and link 0's `δẍ`, `δÿ`) from the joints'
        // force changes on either side (a cut chain has none at its ends).
        if self.zeros.len() < k {
            self.zeros.resize(k, Vector2::zeros());
        }
        let zeros = &self.zeros[..k];
        for i in 0..n {
            let (link, at) = (&self.links[i], &self.at[i]);
            let ahead = if i + 1 < n || self.closed {
                &rhs[i * k..(i + 1) * k]
            } else {
                zeros
            };
            let behind = match i {
                0 if self.closed => &rhs[(n - 1) * k..],
                0 => zeros,
                _ => &rhs[(i - 1) * k..i * k],
            };
            let row = i * k..(i + 1) * k;
            let (p1, p2) = (at.p1 * link.inv_inertia, at.p2 * link.inv_inertia);
            for (((o, moment), a), b) in out[(2 + i) * k..(3 + i) * k]
                .iter_mut()
                .zip(&moments[row.clone()])
                .zip(ahead)
                .zip(behind)
            {
                *o = moment * link.inv_inertia + p2.dot(a) - p1.dot(b);
            }
            if i == 0 {
                for (c, ((force, a), b)) in forces[row].iter().zip(ahead).zip(behind).enumerate() {
                    let linear = (force + a - b) * link.inv_mass;
                    out[c] = linear.x;
                    out[k + c] = linear.y;
                }
            }
        }
        self.forces = forces;
        self.moments = moments;
        self.rhs = rhs;
    }

    /// The joint forces on either side of link `i`: the one ahead (its
    /// joint to the next link) and behind, zero where a cut chain has
    /// none.
    #[inline]
    fn neighbours(&self, i: usize, lambda: &[Vector2<f64>]) -> (Vector2<f64>, Vector2<f64>) {
        let n = self.links.len();
        let ahead = if i + 1 < n || self.closed {
            lambda[i]
        } else {
            Vector2::zeros()
        };
        let behind = if i > 0 {
            lambda[i - 1]
        } else if self.closed {
            lambda[n - 1]
        } else {
            Vector2::zeros()
        };
        (ahead, behind)
    }

    /// Link `i`'s `(θ̈, (ẍ, ÿ))` under joint forces `lambda` and load
    /// `(force, moment)`: `Wᵢ (Fᵢ + D⁺ᵢᵀ λᵢ − D⁻ᵢᵀ λᵢ₋₁)`.
    #[inline]
    fn accelerations_of(
        &self,
        i: usize,
        lambda: &[Vector2<f64>],
        (force, moment): (Vector2<f64>, f64),
    ) -> (f64, Vector2<f64>) {
        let (link, at) = (&self.links[i], &self.at[i]);
        let (ahead, behind) = self.neighbours(i, lambda);
        (
            (moment + at.p2.dot(&ahead) - at.p1.dot(&behind)) * link.inv_inertia,
            (force + ahead - behind) * link.inv_mass,
        )
    }

    /// Solves the `λ` system for `k` directions' joint right sides in
    /// `rhs` (`n × k`, joint-major; replaced by `λ`) once their loads
    /// (`forces`, `moments`, link-major) are folded in:
    /// `rhsⱼ − D⁺ⱼ Wⱼ Fⱼ + D⁻ₗ Wₗ Fₗ`.
    fn solve_loaded(
        &self,
        rhs: &mut [Vector2<f64>],
        forces: &[Vector2<f64>],
        moments: &[f64],
        k: usize,
    ) {
        let n = self.links.len();
        for j in 0..n {
            let l = (j + 1) % n;
            if j + 1 == n && !self.closed {
                break;
            }
            let (lj, ll) = (&self.links[j], &self.links[l]);
            let (cj, cl) = (
                self.at[j].p2 * lj.inv_inertia,
                self.at[l].p1 * ll.inv_inertia,
            );
            let (ij, il) = (lj.inv_mass, ll.inv_mass);
            let (own, next) = (j * k..(j + 1) * k, l * k..(l + 1) * k);
            let here = moments[own.clone()].iter().zip(&forces[own.clone()]);
            let ahead = moments[next.clone()].iter().zip(&forces[next]);
            for (r, ((mj, fj), (ml, fl))) in rhs[own].iter_mut().zip(here.zip(ahead)) {
                *r += -(cj * *mj + fj * ij) + (cl * *ml + fl * il);
            }
        }
        let m = n - 1;
        if m > 0 {
            for j in 1..m {
                let (done, rest) = rhs.split_at_mut(j * k);
                let factor = self.factor[j];
                for (x, previous) in rest[..k].iter_mut().zip(&done[(j - 1) * k..]) {
                    *x -= factor * previous;
                }
            }
            let inverse = self.inverse[m - 1];
            for x in &mut rhs[(m - 1) * k..m * k] {
                *x = inverse * *x;
            }
            for j in (0..m - 1).rev() {
                let (head, tail) = rhs.split_at_mut((j + 1) * k);
                let (inverse, upper) = (self.inverse[j], self.lower[j + 1].transpose());
                for (x, next) in head[j * k..].iter_mut().zip(&tail[..k]) {
                    *x = inverse * (*x - upper * next);
                }
            }
        }
        if self.closed {
            let (b0, bm) = (self.lower[0].transpose(), self.lower[n - 1]);
            let (body, last) = rhs.split_at_mut((n - 1) * k);
            let (first, before_last) = (&body[..k], &body[(m - 1) * k..]);
            for ((y, x0), xm) in last.iter_mut().zip(first).zip(before_last) {
                *y = self.schur_inverse * (*y - b0 * x0 - bm * xm);
            }
            for (j, z) in self.border.iter().enumerate() {
                for (x, y) in body[j * k..(j + 1) * k].iter_mut().zip(last.iter()) {
                    *x -= z * y;
                }
            }
        } else {
            rhs[(n - 1) * k..].fill(Vector2::zeros());
        }
    }

    /// The tridiagonal part's inverse applied to two columns per joint
    /// (the bordering columns), in place.
    fn solve_tridiagonal_matrix(&self, columns: &mut [Matrix2<f64>]) {
        let m = columns.len();
        for j in 1..m {
            let previous = columns[j - 1];
            columns[j] -= self.factor[j] * previous;
        }
        columns[m - 1] = self.inverse[m - 1] * columns[m - 1];
        for j in (0..m - 1).rev() {
            let next = columns[j + 1];
            columns[j] = self.inverse[j] * (columns[j] - self.lower[j + 1].transpose() * next);
        }
    }
}
