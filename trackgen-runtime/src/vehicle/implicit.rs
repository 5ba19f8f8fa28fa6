//! A vehicle's own linear solves for a linearly implicit integrator
//! ([`ImplicitSolve`](crate::integrate::ImplicitSolve)): `(I − a W) k = r`,
//! `a = γ h`, for the matrix `W` made of the force elements' exact
//! Jacobians through the mass matrix, in O(n) per solve.
//!
//! The state is the bodies' coordinates `q` (under partitioning, the
//! track's independent ones `z`), their rates `v`, the drive's integral
//! `s`, the books and the ground points' tangential states `w` (stiction
//! deflections on rigid ground, the soil's shear displacements on soft
//! soil: the same coupling to their links). `W` keeps the
//! kinematic rows exactly (`q̇ = v`) and, for the accelerations, every
//! force element's derivatives through the inverse mass matrix:
//! `M⁻¹ (K, C, F_w, F_s)` with `K = ∂F/∂q`, `C = ∂F/∂v` of the contacts
//! (their own [`ContactJacobian`](crate::contact::ContactJacobian)s), the
//! arms' springs and dampers, the drive; the deflections' and the
//! integral's rows are theirs exactly. It leaves out the derivatives of
//! `M` and of the velocity terms (the inertia's share of the Jacobian,
//! whose frequencies are the bodies' rotation rates, far from stiff), and
//! the books (quadratures). A Rosenbrock-W method keeps its order for any
//! `W`; this one holds what is stiff: contact friction and damping, the
//! drive's gain, contact stiffness.
//!
//! Eliminating `k_q = r_q + a k_v` and the deflections' and integral's
//! increments (each local to one link, or to the drive) leaves the
//! velocity increments `x` of every body:
//!
//! ```text
//! (M − a C − a² K − …) x = M r_v + a K r_q + …
//! ```
//!
//! In the bodies' absolute coordinates the matrix is the masses plus a
//! 3 × 3 block per contact: the ground's on its link alone, a rim's or a
//! tooth's between a link and a chassis body, the hull's and a rim's on a
//! terrain corner on their chassis body alone. The track's part, with the
//! loop's constraint, is [`ShiftedChain`]'s O(n) solve; the chassis'
//! (a dozen coordinates) is dense, and the two meet through the rims and
//! teeth by a Schur complement on the chassis: one chain solve per chassis
//! coordinate when factored, two chain-sized sweeps per solve.

mod solve;

use nalgebra::{DMatrix, DVector, Matrix2, Matrix3, Vector2, Vector3};

use super::drive::DriveSlopes;
use super::layout::Starts;
use super::linearisation::{GroundPoints, Linearisation};

use crate::contact::tangent::{DEFLECTION, LINK_POSE, LINK_RATE, OTHER_POSE, OTHER_RATE};
use crate::dynamics::ShiftedChain;
use crate::multibody::DynamicsError;
use crate::multibody::TreeDescription;
use crate::planar::{Rotation, perp};

/// A 3 × 3 block of a contact Jacobian's rows `rows` (a 3-row load) at
/// columns `column..column + 3`.
#[inline]
fn block(rows: &crate::contact::tangent::Rows3, column: usize) -> Matrix3<f64> {
    rows.fixed_view::<3, 3>(0, column).into_owned()
}

/// A rim's or tooth's coupling of link `link` and chassis body `body`:
/// the link's load's derivatives with the body's pose and rates, and the
/// body's with the link's.
#[derive(Debug, Clone, Copy)]
struct Coupling {
    link: usize,
    body: usize,
    link_by_pose: Matrix3<f64>,
    link_by_rate: Matrix3<f64>,
    body_by_pose: Matrix3<f64>,
    body_by_rate: Matrix3<f64>,
}

/// A ground point's deflection state `w` (index into the tangential
/// states): touching, its link and the terms that tie the two; lifted,
/// only its relaxation.
#[derive(Debug, Clone, Copy)]
struct Point {
    state: usize,
    /// `∂ẇ/∂w`.
    by_self: f64,
    /// Touching: how the point and its link drive each other.
    link: Option<PointLink>,
}

/// A touching ground point's coupling with its link.
#[derive(Debug, Clone, Copy)]
struct PointLink {
    /// The link (0-based).
    index: usize,
    /// `∂F_link/∂w`.
    load_by_state: Vector3<f64>,
    /// `∂ẇ/∂(link pose)`.
    by_pose: Vector3<f64>,
    /// `∂ẇ/∂(link rates)`.
    by_rate: Vector3<f64>,
}

/// The vehicle's `W`, linearised at a state and factored for a shift `a`.
pub(super) struct Implicit {
    chain: ShiftedChain,
    /// `(ū1, ū2)` of every link.
    joints: Vec<(Vector2<f64>, Vector2<f64>)>,
    /// `d̄ʲ` of every link.
    spans: Vec<Vector2<f64>>,
    /// Every link's `diag(m, m, J)`.
    link_mass: Vec<Vector3<f64>>,
    chassis: TreeDescription,
    /// `DC`.
    dof: usize,
    starts: Starts,

    // The linearisation.
    trig: Vec<(f64, f64)>,
    pair: [usize; 2],
    independent: Vec<usize>,
    /// `C_d⁻¹` of the dependent pair.
    dependent_inverse: Matrix2<f64>,
    /// `A_θ ū1`, `A_θ ū2` and `A_θ d̄` of every link.
    levers: Vec<(Vector2<f64>, Vector2<f64>, Vector2<f64>)>,
    /// `A ū1 ω`, `A ū2 ω` of every link: how its joints' velocities turn
    /// with it.
    spin: Vec<(Vector2<f64>, Vector2<f64>)>,
    /// What the factorisation adds to the joints' rows' levers, `−a` times
    /// [`spin`](Self::spin), and a solve's joints' right sides.
    turning: Vec<(Vector2<f64>, Vector2<f64>)>,
    joint_rhs: Vec<Vector2<f64>>,
    link_by_pose: Vec<Matrix3<f64>>,
    link_by_rate: Vec<Matrix3<f64>>,
    body_by_pose: Vec<Matrix3<f64>>,
    body_by_rate: Vec<Matrix3<f64>>,
    couplings: Vec<Coupling>,
    points: Vec<Point>,
    chassis_mass: DMatrix<f64>,
    /// The chassis' velocity transform, rows `(ẋ, ẏ, ω)` per body.
    h: DMatrix<f64>,
    /// The coordinates each chassis body's rows of `h` touch.
    reach: Vec<Vec<usize>>,
    /// `(body, ∂τ/∂φ, ∂τ/∂φ̇)` of every arm.
    arms: Vec<(usize, f64, f64)>,
    drive: Option<(usize, DriveSlopes)>,

    // The factorisation.
    shift: f64,
    blocks: Vec<Matrix3<f64>>,
    schur: Option<nalgebra::LU<f64, nalgebra::Dyn, nalgebra::Dyn>>,
    /// `T⁻¹ E_tc H_c`: every link's increment `(x, y, θ)` per chassis
    /// coordinate, `[(3 i + c) dof + q]` ([`ShiftedChain::solve_columns`]'s
    /// layout), and the same column by column (`[q · 3n + 3 i + c]`).
    coupled: Vec<f64>,
    coupled_columns: Vec<f64>,
    /// The chassis' matrix before the Schur complement's LU, and the
    /// coupling's share of it row by row.
    schur_matrix: DMatrix<f64>,
    schur_rows: Vec<f64>,

    // Scratch of a solve (`3 n` or `3 m` values: `(x, y, θ)` per body).
    loads: Vec<f64>,
    track_q: Vec<f64>,
    track_v: Vec<f64>,
    x: Vec<f64>,
    full: Vec<f64>,
    chassis_rhs: DVector<f64>,
    body_q: Vec<f64>,
    body_forces: Vec<f64>,
    turned: Vec<f64>,
}

/// The `(x, y, θ)` of body `i` in a flat list.
#[inline]
fn at(v: &[f64], i: usize) -> Vector3<f64> {
    Vector3::new(v[3 * i], v[3 * i + 1], v[3 * i + 2])
}

/// Adds `w` to body `i`'s `(x, y, θ)` in a flat list.
#[inline]
fn add(v: &mut [f64], i: usize, w: Vector3<f64>) {
    v[3 * i] += w.x;
    v[3 * i + 1] += w.y;
    v[3 * i + 2] += w.z;
}

impl Implicit {
    /// The operator of a vehicle whose track is `track` (a loop closed by
    /// partitioning) and chassis `chassis`, its state laid out as
    /// `starts` says. `None` for a track that is not a loop.
    pub fn new(track: &TreeDescription, chassis: &TreeDescription, starts: Starts) -> Option<Self> {
        let chain = ShiftedChain::new(track)?;
        let joints = track.joints()?;
        let n = joints.len();
        let m = chassis.len();
        let dof = m + 2;
        Some(Implicit {
            chain,
            spans: joints.iter().map(|(u1, u2)| u2 - u1).collect(),
            joints,
            link_mass: track
                .bodies
                .iter()
                .map(|b| Vector3::new(b.mass, b.mass, b.inertia))
                .collect(),
            chassis: chassis.clone(),
            dof,
            starts,
            trig: vec![(0.0, 1.0); n],
            pair: [0, 1],
            independent: Vec::with_capacity(n),
            dependent_inverse: Matrix2::identity(),
            levers: vec![(Vector2::zeros(), Vector2::zeros(), Vector2::zeros()); n],
            spin: vec![(Vector2::zeros(), Vector2::zeros()); n],
            turning: vec![(Vector2::zeros(), Vector2::zeros()); n],
            joint_rhs: vec![Vector2::zeros(); n],
            link_by_pose: vec![Matrix3::zeros(); n],
            link_by_rate: vec![Matrix3::zeros(); n],
            body_by_pose: vec![Matrix3::zeros(); m],
            body_by_rate: vec![Matrix3::zeros(); m],
            couplings: Vec::new(),
            points: Vec::new(),
            chassis_mass: DMatrix::zeros(dof, dof),
            h: DMatrix::zeros(3 * m, dof),
            // A body moves with the frame's coordinates and its own angle
            // and its ancestors' (eq. (9)): the columns of its rows of H.
            reach: (0..m)
                .map(|b| {
                    let mut reach = vec![0, 1, 2];
                    let mut c = Some(b);
                    while let Some(body) = c {
                        if body != 0 {
                            reach.push(2 + body);
                        }
                        c = chassis.bodies[body].parent;
                    }
                    reach.sort_unstable();
                    reach
                })
                .collect(),
            arms: Vec::new(),
            drive: None,
            shift: f64::NAN,
            blocks: vec![Matrix3::zeros(); n],
            schur: None,
            coupled: vec![0.0; 3 * n * dof],
            coupled_columns: vec![0.0; 3 * n * dof],
            schur_matrix: DMatrix::zeros(dof, dof),
            schur_rows: vec![0.0; dof * dof],
            loads: vec![0.0; 3 * n],
            track_q: vec![0.0; 3 * n],
            track_v: vec![0.0; 3 * n],
            x: vec![0.0; 3 * n],
            full: vec![0.0; n + 2],
            chassis_rhs: DVector::zeros(dof),
            body_q: vec![0.0; 3 * m],
            body_forces: vec![0.0; 3 * m],
            turned: vec![0.0; 3 * n],
        })
    }

    /// Takes the linearisation `at` (the contacts with their Jacobians,
    /// the bodies' states, the arms' and the drive's slopes), every joint's
    /// force `joint_forces` (the
    /// force link `j + 1` exerts on link `j`, 0-based; the last is the
    /// closing joint's) and the chassis' mass matrix `chassis_mass`.
    pub fn linearise(
        &mut self,
        at: &Linearisation<'_>,
        joint_forces: &[Vector2<f64>],
        chassis_mass: &[f64],
    ) -> Result<(), DynamicsError> {
        let (_, rates, trig) = at.track;
        let n = self.joints.len();
        self.trig.copy_from_slice(trig);
        if self.independent.is_empty() || self.pair != at.pair {
            self.independent.clear();
            self.independent
                .extend((0..n + 2).filter(|&c| c < 2 || !at.pair.contains(&(c - 2))));
        }
        self.pair = at.pair;
        for (i, (lever, spin)) in self.levers.iter_mut().zip(&mut self.spin).enumerate() {
            let rotation = Rotation::from_sin_cos(self.trig[i]);
            let (u1, u2) = self.joints[i];
            let (a1, a2) = (rotation.apply(u1), rotation.apply(u2));
            *lever = (perp(a1), perp(a2), perp(rotation.apply(self.spans[i])));
            let omega = rates[2 + i];
            *spin = (a1 * omega, a2 * omega);
        }
        let [k, l] = self.pair;
        let dependent = Matrix2::from_columns(&[self.levers[k].2, self.levers[l].2]);
        self.dependent_inverse = dependent
            .try_inverse()
            .ok_or(DynamicsError::SingularClosure)?;
        for m in [
            &mut self.link_by_pose,
            &mut self.link_by_rate,
            &mut self.body_by_pose,
            &mut self.body_by_rate,
        ] {
            m.iter_mut().for_each(|b| *b = Matrix3::zeros());
        }
        // The joints' forces on the turning lever arms: a link turned by
        // `δθ` turns `A ū2` and `A ū1` under the forces `λᵢ` (ahead) and
        // `−λᵢ₋₁` (behind), a moment `(−A ū2·λᵢ + A ū1·λᵢ₋₁) δθ`. Under
        // a track's tension this is a stiffness as large as a contact's.
        for i in 0..n {
            let rotation = Rotation::from_sin_cos(self.trig[i]);
            let (u1, u2) = self.joints[i];
            let (ahead, behind) = (joint_forces[i], joint_forces[(i + n - 1) % n]);
            self.link_by_pose[i][(2, 2)] +=
                -rotation.apply(u2).dot(&ahead) + rotation.apply(u1).dot(&behind);
        }
        self.couplings.clear();
        self.points.clear();
        let GroundPoints {
            per_link,
            unit,
            touching,
            relaxation,
        } = at.points;
        // The points touching the ground, from their contacts; the rest
        // relax (stiction) or carry nothing (no states).
        for (contact, jacobian) in at.contacts.iter().zip(at.jacobians) {
            let i = contact.link;
            self.link_by_pose[i] += block(&jacobian.link, LINK_POSE);
            self.link_by_rate[i] += block(&jacobian.link, LINK_RATE);
            match (contact.other, contact.ground_point_slot(per_link)) {
                (Some(body), _) => {
                    self.body_by_pose[body] += block(&jacobian.other, OTHER_POSE);
                    self.body_by_rate[body] += block(&jacobian.other, OTHER_RATE);
                    self.couplings.push(Coupling {
                        link: i,
                        body,
                        link_by_pose: block(&jacobian.link, OTHER_POSE),
                        link_by_rate: block(&jacobian.link, OTHER_RATE),
                        body_by_pose: block(&jacobian.other, LINK_POSE),
                        body_by_rate: block(&jacobian.other, LINK_RATE),
                    });
                }
                (None, Some(state)) if !touching.is_empty() => {
                    // In the state's unit: w = z / unit.
                    let by_state = jacobian.link.column(DEFLECTION) * unit;
                    let rate = &jacobian.rate;
                    self.points.push(Point {
                        state,
                        by_self: rate[DEFLECTION],
                        link: Some(PointLink {
                            index: i,
                            load_by_state: by_state.into_owned(),
                            by_pose: Vector3::new(
                                rate[LINK_POSE],
                                rate[LINK_POSE + 1],
                                rate[LINK_POSE + 2],
                            ) / unit,
                            by_rate: Vector3::new(
                                rate[LINK_RATE],
                                rate[LINK_RATE + 1],
                                rate[LINK_RATE + 2],
                            ) / unit,
                        }),
                    });
                }
                (None, _) => {}
            }
        }
        // The chassis' own contacts with the ground: their body's blocks.
        let (chassis_contacts, chassis_jacobians) = at.chassis_contacts;
        for (contact, jacobian) in chassis_contacts.iter().zip(chassis_jacobians) {
            let body = contact.link;
            self.body_by_pose[body] += block(&jacobian.link, LINK_POSE);
            self.body_by_rate[body] += block(&jacobian.link, LINK_RATE);
        }
        if let Some(relax) = relaxation {
            for (state, normal) in touching.iter().enumerate() {
                if normal.is_none() {
                    self.points.push(Point {
                        state,
                        by_self: relax,
                        link: None,
                    });
                }
            }
        }
        self.chassis_mass.copy_from_slice(chassis_mass);
        self.chassis.velocity_transform(at.chassis.2, &mut self.h);

        self.arms.clear();
        self.arms.extend(at.arms.iter().map(|arm| {
            let (by_angle, by_rate) = arm.spring.slopes();
            (arm.body, by_angle, by_rate)
        }));
        self.drive = at.drive;
        self.shift = f64::NAN;
        self.schur = None;
        Ok(())
    }

    /// Factors `I − a W` for the shift `a = γ h` (s).
    pub fn factor(&mut self, a: f64) -> Result<(), DynamicsError> {
        crate::simd::run(
            #[inline(always)]
            || self.factor_inline(a),
        )
    }

    /// [`factor`](Self::factor)'s loops, inlined into its wide build.
    #[inline(always)]
    fn factor_inline(&mut self, a: f64) -> Result<(), DynamicsError> {
        let dof = self.dof;
        let a2 = a * a;
        for (i, x) in self.blocks.iter_mut().enumerate() {
            *x = Matrix3::from_diagonal(&self.link_mass[i])
                - self.link_by_rate[i] * a
                - self.link_by_pose[i] * a2;
        }
        // A touching point's deflection, eliminated: its increment
        // `k_w = (r_w + a ∂ẇ/∂q k_q + a ∂ẇ/∂v x)/(1 − a ∂ẇ/∂w)` with
        // `k_q = u_q + a x` feeds `a F_w k_w` back into its link.
        for point in &self.points {
            if let Some(link) = point.link {
                let gain = a / (1.0 - a * point.by_self);
                self.blocks[link.index] -=
                    link.load_by_state * (link.by_pose * a + link.by_rate).transpose() * (a * gain);
            }
        }
        for (turning, (s1, s2)) in self.turning.iter_mut().zip(&self.spin) {
            *turning = (-s1 * a, -s2 * a);
        }
        self.chain
            .factor(&self.trig, &self.blocks, &self.turning)
            .map_err(|_| DynamicsError::SingularClosure)?;
        // The chassis: M − Hᵀ(a C + a² K)H, the arms, the drive. A body's
        // rows of H touch the frame's coordinates and its own (and its
        // arm's): a handful of columns each (`reach`).
        let mut schur = std::mem::take(&mut self.schur_matrix);
        schur.copy_from(&self.chassis_mass);
        let m = self.chassis.len();
        for b in 0..m {
            let stiff = self.body_by_rate[b] * a + self.body_by_pose[b] * a2;
            if stiff == Matrix3::zeros() {
                continue;
            }
            for &p in &self.reach[b] {
                let hp = self.h.fixed_view::<3, 1>(3 * b, p).into_owned();
                let row = hp.transpose() * stiff;
                for &q in &self.reach[b] {
                    schur[(p, q)] -= row.dot(&self.h.fixed_view::<3, 1>(3 * b, q).transpose());
                }
            }
        }
        for &(body, by_angle, by_rate) in &self.arms {
            let weight = -(a * by_rate + a2 * by_angle);
            add_relative(&mut schur, body, weight);
        }
        if let Some((body, slopes)) = self.drive {
            let [torque_by_speed, torque_by_integral, ..] = slopes.torque;
            let [rate_by_speed, rate_by_integral, ..] = slopes.rate;
            let weight = match self.starts.engine {
                None => {
                    -a * torque_by_speed
                        - a * torque_by_integral * a * rate_by_speed / (1.0 - a * rate_by_integral)
                }
                // The drive's own states (s, ω_e, z) eliminated together:
                // `k_l = P (r_l + a b δω)`, `P = (I − a A)⁻¹`.
                Some(_) => {
                    let (p, b, c) = drive_block(a, &slopes);
                    -a * torque_by_speed - a * a * c.dot(&(p * b))
                }
            };
            add_relative(&mut schur, body, weight);
        }
        // The track's answer to every chassis coordinate, through the rims
        // and teeth: `Z = T⁻¹ E_tc H_c` (all coordinates in one sweep), and
        // `S = K_cc − H_cᵀ E_ct Z`.
        let z = &mut self.coupled;
        z.fill(0.0);
        for c in &self.couplings {
            let e = -(c.link_by_rate * a + c.link_by_pose * a2);
            for &q in &self.reach[c.body] {
                let load = e * self.h.fixed_view::<3, 1>(3 * c.body, q);
                for (k, v) in load.iter().enumerate() {
                    z[(3 * c.link + k) * dof + q] += v;
                }
            }
        }
        self.chain.solve_columns(z, dof);
        // The same column by column, for the solves' `x −= Z x_c`.
        let rows = z.len() / dof;
        for (q, column) in self.coupled_columns.chunks_exact_mut(rows).enumerate() {
            for (value, row) in column.iter_mut().zip(z.chunks_exact(dof)) {
                *value = row[q];
            }
        }
        // Row by row into a row-major scratch (each update a contiguous
        // row of dof), added to the column-major matrix at the end.
        let rows_of = &mut self.schur_rows;
        rows_of.fill(0.0);
        for c in &self.couplings {
            let e = -(c.body_by_rate * a + c.body_by_pose * a2);
            let link = &z[3 * c.link * dof..3 * (c.link + 1) * dof];
            let (z0, rest) = link.split_at(dof);
            let (z1, z2) = rest.split_at(dof);
            for &p in &self.reach[c.body] {
                // `H_pᵀ E_bl Z_l`, a row of dof.
                let w = self.h.fixed_view::<3, 1>(3 * c.body, p).transpose() * e;
                let row = &mut rows_of[p * dof..(p + 1) * dof];
                for (q, r) in row.iter_mut().enumerate() {
                    *r += w[0] * z0[q] + w[1] * z1[q] + w[2] * z2[q];
                }
            }
        }
        for p in 0..dof {
            for q in 0..dof {
                schur[(p, q)] -= rows_of[p * dof + q];
            }
        }
        let lu = schur.clone().lu();
        self.schur_matrix = schur;
        if !lu.is_invertible() {
            return Err(DynamicsError::SingularClosure);
        }
        self.schur = Some(lu);
        self.shift = a;
        Ok(())
    }

    /// The track's independent increments `z` (its integrated
    /// coordinates, or rates) as every link's absolute increment `(x, y,
    /// θ)`: the dependent pair from `C_q δq = 0`, then the velocity
    /// transform's running sum (eq. (4) differentiated).
    fn track_increments(&mut self, z: &[f64], out: &mut [f64]) {
        let full = &mut self.full;
        for (&c, &v) in self.independent.iter().zip(z) {
            full[c] = v;
        }
        let [k, l] = self.pair;
        full[2 + k] = 0.0;
        full[2 + l] = 0.0;
        let moved: Vector2<f64> = self
            .levers
            .iter()
            .enumerate()
            .map(|(j, lever)| lever.2 * full[2 + j])
            .sum();
        let dependent = -(self.dependent_inverse * moved);
        full[2 + k] = dependent.x;
        full[2 + l] = dependent.y;
        let mut position = Vector2::new(full[0], full[1]);
        for (i, out) in out.chunks_exact_mut(3).enumerate() {
            let angle = full[2 + i];
            if i > 0 {
                position -= self.levers[i].0 * angle;
            }
            out.copy_from_slice(&[position.x, position.y, angle]);
            position += self.levers[i].1 * angle;
        }
    }

    /// The change of every link's absolute velocity `(ẋ, ẏ, ω)` when the
    /// track's configuration moves by `positions` (every link's `(x, y,
    /// θ)` increment, a consistent one) at fixed independent rates `ż`,
    /// into `out`: the dependent pair's rates follow from `C_q q̇ = 0`
    /// (`C_d δω_d = Σⱼ Aʲ d̄ʲ ωⱼ δθⱼ`, as `∂(A_θ d̄)/∂θ = −A d̄`), and each
    /// turned lever `A_θ ū ω` changes by `−A ū ω δθ` down the chain.
    fn convective(&self, positions: &[f64], out: &mut [f64]) {
        let angle = |i: usize| positions[3 * i + 2];
        let turned: Vector2<f64> = self
            .spin
            .iter()
            .enumerate()
            .map(|(j, (s1, s2))| (s2 - s1) * angle(j))
            .sum();
        let dependent = self.dependent_inverse * turned;
        let [k, l] = self.pair;
        let rate = |i: usize| {
            if i == k {
                dependent.x
            } else if i == l {
                dependent.y
            } else {
                0.0
            }
        };
        let mut velocity = Vector2::zeros();
        for (i, out) in out.chunks_exact_mut(3).enumerate() {
            let (p1, p2, _) = self.levers[i];
            let (s1, s2) = self.spin[i];
            let (w, t) = (rate(i), angle(i));
            if i > 0 {
                velocity -= p1 * w - s1 * t;
            }
            out.copy_from_slice(&[velocity.x, velocity.y, w]);
            velocity += p2 * w - s2 * t;
        }
    }
}

/// The drive's own states `l = (s, ω_e, z)` in `(I − a W) k = r`: their
/// rows `k_l − a (A k_l + b δω) = r_l` and the torque's `c · k_l`, with
/// `A` their slopes on each other, `b` on the sprocket's speed and `c` the
/// torque's on them; returns `(P = (I − a A)⁻¹, b, c)`.
#[inline(always)]
fn drive_block(a: f64, slopes: &DriveSlopes) -> (Matrix3<f64>, Vector3<f64>, Vector3<f64>) {
    let rows = [slopes.rate, slopes.engine, slopes.twist];
    let shifted = Matrix3::from_fn(|i, j| f64::from(u8::from(i == j)) - a * rows[i][j + 1]);
    let p = shifted
        .try_inverse()
        .unwrap_or_else(|| Matrix3::from_element(f64::NAN));
    (
        p,
        Vector3::new(rows[0][0], rows[1][0], rows[2][0]),
        Vector3::new(slopes.torque[1], slopes.torque[2], slopes.torque[3]),
    )
}

/// Adds `weight (e_b − e_0)(e_b − e_0)ᵀ` to a chassis matrix: a law on the
/// angle of body `body` relative to the frame (coordinate 2).
fn add_relative(matrix: &mut DMatrix<f64>, body: usize, weight: f64) {
    let (b, c) = (2 + body, 2);
    matrix[(b, b)] += weight;
    matrix[(c, c)] += weight;
    matrix[(b, c)] -= weight;
    matrix[(c, b)] -= weight;
}
