//! A vehicle's exact Jacobian `∂f/∂y`, column by column, from the
//! derivatives of its stages: the bodies' kinematics (through the loop's
//! partitioning), every force element's Jacobian beside its load
//! ([`ContactJacobian`], the arms' and the drive's slopes), and the
//! dynamics' own derivatives ([`ChainTangent`] for the track's linear-time
//! solve, [`TreeTangent`] for the chassis), factored once at the state.
//!
//! A column is the change of `f` along one state component: the track's
//! independent coordinates `z` (a change of `z` moves the dependent pair
//! by `δq_d = −C_d⁻¹ C_z δz` and, at fixed `ż`, their rates by
//! `C_d δω_d = Σⱼ Aʲ d̄ʲ ωⱼ δθⱼ`), their rates, the chassis' coordinates
//! and rates, the drive's integral, the ground points' deflections. Each
//! costs O(n): the links' states by running sums down the chain, each
//! contact's load by its Jacobian, one sweep of the factored chain (swept
//! for a block of columns at once). The books' rows (quadratures, which
//! nothing reads) are left zero.

use nalgebra::{Matrix2, SMatrix, SVector, Vector2, Vector3};

use crate::contact::tangent::{DEFLECTION, INPUTS, LINK_POSE, LINK_RATE, OTHER_POSE, OTHER_RATE};
use crate::contact::{Contact, ContactJacobian};
use crate::dynamics::derivative::{ChainDirections, ChainTangent, TreeDirection, TreeTangent};
use crate::multibody::DynamicsError;
use crate::multibody::{BodyLoad, ClosingJoint, TreeDescription};
use crate::planar::{Rotation, perp};

use super::layout::Starts;
use super::linearisation::{GroundPoints, Linearisation};

/// A contact's Jacobian arranged by what a column moves: rows the load on
/// the link `(F_x, F_y, M)`, on the other body, and the deflection's rate;
/// columns the link's pose and rates, or the other body's, or the
/// deflection.
#[derive(Debug, Clone, Copy)]
struct Compact {
    link: usize,
    other: Option<usize>,
    /// The ground point's tangential state: its stiction deflection on
    /// rigid ground, its shear displacement on soil.
    slot: Option<usize>,
    by_link: SMatrix<f64, 7, 6>,
    by_other: SMatrix<f64, 7, 6>,
    by_deflection: SVector<f64, 7>,
}

impl Compact {
    /// `by · state` in the rows this contact loads (its link's; the other
    /// body's, if any; the deflection's rate, if it has one), the rest
    /// zero.
    #[inline]
    fn rows(&self, by: &SMatrix<f64, 7, 6>, state: &SVector<f64, 6>) -> SVector<f64, 7> {
        let mut change = SVector::<f64, 7>::zeros();
        change
            .fixed_rows_mut::<3>(0)
            .copy_from(&(by.fixed_rows::<3>(0) * state));
        if self.other.is_some() {
            change
                .fixed_rows_mut::<3>(3)
                .copy_from(&(by.fixed_rows::<3>(3) * state));
        }
        if self.slot.is_some() {
            change[6] = by.row(6).transpose().dot(state);
        }
        change
    }

    fn of(contact: &Contact, jacobian: &ContactJacobian, slot: Option<usize>) -> Compact {
        let mut rows = SMatrix::<f64, 7, INPUTS>::zeros();
        rows.fixed_rows_mut::<3>(0).copy_from(&jacobian.link);
        rows.fixed_rows_mut::<3>(3).copy_from(&jacobian.other);
        rows.set_row(6, &jacobian.rate);
        let mut by_link = SMatrix::<f64, 7, 6>::zeros();
        by_link
            .fixed_columns_mut::<3>(0)
            .copy_from(&rows.fixed_columns::<3>(LINK_POSE));
        by_link
            .fixed_columns_mut::<3>(3)
            .copy_from(&rows.fixed_columns::<3>(LINK_RATE));
        let mut by_other = SMatrix::<f64, 7, 6>::zeros();
        by_other
            .fixed_columns_mut::<3>(0)
            .copy_from(&rows.fixed_columns::<3>(OTHER_POSE));
        by_other
            .fixed_columns_mut::<3>(3)
            .copy_from(&rows.fixed_columns::<3>(OTHER_RATE));
        Compact {
            link: contact.link,
            other: contact.other,
            slot,
            by_link,
            by_other,
            by_deflection: rows.column(DEFLECTION).into_owned(),
        }
    }
}

/// How many columns go through the dynamics together: enough to keep the
/// chain's sweeps busy, few enough that a block's scratch stays in cache.
const BLOCK: usize = 32;

/// The factored derivatives and the scratch of the columns.
pub(super) struct Tangent {
    chain: ChainTangent,
    tree: TreeTangent,
    chassis: TreeDescription,
    joints: Vec<(Vector2<f64>, Vector2<f64>)>,
    spans: Vec<Vector2<f64>>,
    starts: Starts,
    // Per link at the state: `A ū1`, `A ū2`, `A d̄` and their turned
    // `⟂(·)`; `ω`.
    arms1: Vec<Vector2<f64>>,
    arms2: Vec<Vector2<f64>>,
    turned_spans: Vec<Vector2<f64>>,
    omega: Vec<f64>,
    dependent_inverse: Matrix2<f64>,
    // Per chassis body: its rows of `H` and the levers' turning.
    h: nalgebra::DMatrix<f64>,
    // Scratch.
    angles: Vec<f64>,
    rates: Vec<f64>,
    link_pose: Vec<Vector3<f64>>,
    link_rate: Vec<Vector3<f64>>,
    body_pose: Vec<Vector3<f64>>,
    body_rate: Vec<Vector3<f64>>,
    body_loads: Vec<BodyLoad>,
    chassis_q: Vec<f64>,
    chassis_qd: Vec<f64>,
    chassis_qdd: Vec<f64>,
    // A block's columns, link-major: `i · columns + c`.
    block_angles: Vec<f64>,
    block_rates: Vec<f64>,
    block_loads: Vec<BodyLoad>,
    block_qdd: Vec<f64>,
    compact: Vec<Compact>,
    /// The chassis bodies' own contacts with the ground: the body, and
    /// its load's derivatives by its pose and rates.
    chassis_compact: Vec<(usize, SMatrix<f64, 3, 6>)>,
}

impl Tangent {
    /// The tangent of a vehicle with `track` and `chassis`, its state laid
    /// out as `starts` says; `None` for a track that is not a loop.
    pub fn new(track: &TreeDescription, chassis: &TreeDescription, starts: Starts) -> Option<Self> {
        let joints = track.joints()?;
        let n = joints.len();
        let m = chassis.len();
        Some(Tangent {
            chain: ChainTangent::new(track)?,
            tree: TreeTangent::new(chassis),
            chassis: chassis.clone(),
            spans: joints.iter().map(|(u1, u2)| u2 - u1).collect(),
            joints,
            starts,
            arms1: vec![Vector2::zeros(); n],
            arms2: vec![Vector2::zeros(); n],
            turned_spans: vec![Vector2::zeros(); n],
            omega: vec![0.0; n],
            dependent_inverse: Matrix2::identity(),
            h: nalgebra::DMatrix::zeros(3 * m, m + 2),
            angles: vec![0.0; n],
            rates: vec![0.0; n],
            link_pose: vec![Vector3::zeros(); n],
            link_rate: vec![Vector3::zeros(); n],
            body_pose: vec![Vector3::zeros(); m],
            body_rate: vec![Vector3::zeros(); m],
            body_loads: vec![BodyLoad::ZERO; m],
            chassis_q: vec![0.0; m + 2],
            chassis_qd: vec![0.0; m + 2],
            block_angles: Vec::new(),
            block_rates: Vec::new(),
            block_loads: Vec::new(),
            block_qdd: Vec::new(),
            chassis_qdd: vec![0.0; m + 2],
            compact: Vec::new(),
            chassis_compact: Vec::new(),
        })
    }

    /// `∂f/∂y` at the linearisation `at`, whose bodies carry the loads
    /// `(track_loads, chassis_loads)`, into `out` (column-major,
    /// `dimension × dimension`): each column's
    /// motion and loads, then the dynamics' derivatives for a block of
    /// columns at once (the chain's sweeps over every column of the
    /// block, the chassis' load response as one solve with many right
    /// sides). A lifted ground point's deflection moves nothing but its
    /// own relaxation; the books' columns are zero.
    pub fn jacobian(
        &mut self,
        at: &Linearisation<'_>,
        (track_loads, chassis_loads): (&[BodyLoad], &[BodyLoad]),
        dimension: usize,
        out: &mut [f64],
    ) -> Result<(), DynamicsError> {
        let n = self.joints.len();
        let (_, qdt, trig) = at.track;
        let (qc, qdc, rotations) = at.chassis;
        let dof = qc.len();
        assert_eq!(out.len(), dimension * dimension, "a square Jacobian");
        for i in 0..n {
            let rotation = Rotation::from_sin_cos(trig[i]);
            let (u1, u2) = self.joints[i];
            self.arms1[i] = rotation.apply(u1);
            self.arms2[i] = rotation.apply(u2);
            self.turned_spans[i] = rotation.apply(self.spans[i]);
            self.omega[i] = qdt[2 + i];
        }
        let [k, l] = at.pair;
        self.dependent_inverse =
            Matrix2::from_columns(&[perp(self.turned_spans[k]), perp(self.turned_spans[l])])
                .try_inverse()
                .ok_or(DynamicsError::SingularClosure)?;
        self.chain
            .factor(trig, &qdt[2..], track_loads, ClosingJoint::CLOSED)?;
        self.tree.factor(qc, qdc, chassis_loads)?;
        self.chassis.velocity_transform(rotations, &mut self.h);
        let GroundPoints {
            per_link, touching, ..
        } = at.points;
        self.compact.clear();
        self.compact.extend(
            at.contacts
                .iter()
                .zip(at.jacobians)
                .map(|(contact, jacobian)| {
                    let slot = contact
                        .ground_point_slot(per_link)
                        .filter(|_| !touching.is_empty());
                    Compact::of(contact, jacobian, slot)
                }),
        );
        let (chassis_contacts, chassis_jacobians) = at.chassis_contacts;
        self.chassis_compact.clear();
        self.chassis_compact
            .extend(
                chassis_contacts
                    .iter()
                    .zip(chassis_jacobians)
                    .map(|(contact, jacobian)| {
                        let mut by_body = SMatrix::<f64, 3, 6>::zeros();
                        by_body
                            .fixed_columns_mut::<3>(0)
                            .copy_from(&jacobian.link.fixed_columns::<3>(LINK_POSE));
                        by_body
                            .fixed_columns_mut::<3>(3)
                            .copy_from(&jacobian.link.fixed_columns::<3>(LINK_RATE));
                        (contact.link, by_body)
                    }),
            );
        out.fill(0.0);
        let o = self.starts;
        let independent: Vec<usize> = (0..n + 2)
            .filter(|&c| c < 2 || !at.pair.contains(&(c - 2)))
            .collect();
        let nt = independent.len();
        let mut work = Vec::with_capacity(dimension);
        for column in 0..dimension {
            let (track_q, track_v) = (o.track..o.track + nt, o.track + nt..o.track + 2 * nt);
            let (chassis_q, chassis_v) = (
                o.chassis..o.chassis + dof,
                o.chassis + dof..o.chassis + 2 * dof,
            );
            let mut direction = Direction::default();
            if track_q.contains(&column) {
                direction.track = Some((independent[column - o.track], false));
            } else if track_v.contains(&column) {
                direction.track = Some((independent[column - track_v.start], true));
            } else if chassis_q.contains(&column) {
                direction.chassis = Some((column - o.chassis, false));
            } else if chassis_v.contains(&column) {
                direction.chassis = Some((column - chassis_v.start, true));
            } else if column == o.integral {
                direction.integral = true;
            } else if let Some(e) = o.engine.filter(|e| (*e..e + 2).contains(&column)) {
                direction.engine = Some(column - e);
            } else if column >= o.tangential {
                let slot = column - o.tangential;
                if touching.get(slot).is_some_and(|t| t.is_none()) {
                    // A lifted point's deflection relaxes on its own.
                    if let Some(relax) = at.points.relaxation {
                        out[column * dimension + column] = relax;
                    }
                    continue;
                }
                direction.point = Some(slot);
            } else {
                // The books: nothing depends on them.
                continue;
            }
            work.push((column, direction));
        }
        // Blocks of one kind of column, so that a block moving no angle
        // (or no rate) sweeps none.
        let kind = |d: &Direction| d.track.map_or(0, |(_, rate)| 1 + usize::from(rate));
        work.sort_by_key(|(_, direction)| kind(direction));
        for group in work.chunk_by(|a, b| kind(&a.1) == kind(&b.1)) {
            for block in group.chunks(BLOCK) {
                self.block(at, &independent, block, dimension, out);
            }
        }
        Ok(())
    }

    /// The columns of `block`: each one's motion and loads, then the
    /// dynamics for all of them.
    fn block(
        &mut self,
        at: &Linearisation<'_>,
        independent: &[usize],
        block: &[(usize, Direction)],
        dimension: usize,
        out: &mut [f64],
    ) {
        let n = self.joints.len();
        let (kb, m) = (block.len(), self.chassis.len());
        let dof = m + 2;
        let o = self.starts;
        for scratch in [&mut self.block_angles, &mut self.block_rates] {
            scratch.resize(n * kb, 0.0);
            scratch.fill(0.0);
        }
        self.block_loads.resize(n * kb, BodyLoad::ZERO);
        self.block_loads.fill(BodyLoad::ZERO);
        self.block_qdd.resize((n + 2) * kb, 0.0);
        let mut body_loads = nalgebra::DMatrix::zeros(3 * m, kb);
        for (b, &(column, direction)) in block.iter().enumerate() {
            let col = &mut out[column * dimension..(column + 1) * dimension];
            self.column(at, independent, direction, (b, kb), col);
            // Into the block, link-major (what moved alone: a rate column
            // turns no link, a chassis column moves none).
            let scatter = |from: &[f64], to: &mut [f64]| {
                for (i, &value) in from.iter().enumerate().filter(|(_, v)| **v != 0.0) {
                    to[i * kb + b] = value;
                }
            };
            if let Some((_, rate)) = direction.track {
                if !rate {
                    scatter(&self.angles, &mut self.block_angles);
                }
                scatter(&self.rates, &mut self.block_rates);
            }
            if direction.chassis.is_some() {
                // The chassis' own motion: its derivative in full.
                self.tree.direction(
                    &TreeDirection {
                        coordinates: &self.chassis_q,
                        rates: &self.chassis_qd,
                        loads: &self.body_loads,
                    },
                    &mut self.chassis_qdd,
                );
                col[o.chassis + dof..o.chassis + 2 * dof].copy_from_slice(&self.chassis_qdd);
            } else {
                for (j, load) in self.body_loads.iter().enumerate() {
                    body_loads[(3 * j, b)] = load.force.x;
                    body_loads[(3 * j + 1, b)] = load.force.y;
                    body_loads[(3 * j + 2, b)] = load.moment;
                }
            }
        }
        let moved = |values: &[f64]| values.iter().any(|&v| v != 0.0);
        self.chain.directions(
            &ChainDirections {
                columns: kb,
                angles: if moved(&self.block_angles) {
                    &self.block_angles
                } else {
                    &[]
                },
                rates: if moved(&self.block_rates) {
                    &self.block_rates
                } else {
                    &[]
                },
                loads: &self.block_loads,
                closing: &[],
            },
            &mut self.block_qdd,
        );
        let chassis = self.tree.load_directions(&body_loads);
        let nt = independent.len();
        for (b, &(column, direction)) in block.iter().enumerate() {
            let col = &mut out[column * dimension..(column + 1) * dimension];
            for (slot, &c) in independent.iter().enumerate() {
                col[o.track + nt + slot] = self.block_qdd[c * kb + b];
            }
            if direction.chassis.is_none() {
                for j in 0..dof {
                    col[o.chassis + dof + j] = chassis[(j, b)];
                }
            }
        }
    }

    /// One column's motion and loads along `direction`: every link's and
    /// body's state change, the contacts', arms' and drive's loads (kept
    /// for the dynamics), and the rows that follow from them directly
    /// (the rates' own rows, the deflections' and the integral's).
    fn column(
        &mut self,
        at: &Linearisation<'_>,
        independent: &[usize],
        direction: Direction,
        (b, kb): (usize, usize),
        out: &mut [f64],
    ) {
        let (_, qdc, _) = at.chassis;
        let dof = qdc.len();
        let o = self.starts;
        let root = self.track_motion(at, direction);
        // The chassis.
        self.chassis_q.fill(0.0);
        self.chassis_qd.fill(0.0);
        if let Some((coordinate, rate)) = direction.chassis {
            if rate {
                self.chassis_qd[coordinate] = 1.0;
            } else {
                self.chassis_q[coordinate] = 1.0;
            }
        }
        if direction.chassis.is_some() {
            self.body_motion(at);
        }
        self.contact_loads(at, direction, (b, kb), out);
        // The arms: τ = preload − k φ − c φ̇, φ = θ_b − θ_frame.
        for arm in at.arms {
            let (by_angle, by_rate) = arm.spring.slopes();
            let b = arm.body;
            let torque = by_angle * (self.chassis_q[2 + b] - self.chassis_q[2])
                + by_rate * (self.chassis_qd[2 + b] - self.chassis_qd[2]);
            self.body_loads[b].moment += torque;
            self.body_loads[0].moment -= torque;
        }
        // The drive on the sprocket's speed relative to the frame, its
        // integral and the engine's speed (where a state).
        if let Some((s, slopes)) = at.drive {
            let speed = self.chassis_qd[2 + s] - self.chassis_qd[2];
            let integral = if direction.integral { 1.0 } else { 0.0 };
            let engine = |k: usize| {
                if direction.engine == Some(k) {
                    1.0
                } else {
                    0.0
                }
            };
            let along = [speed, integral, engine(0), engine(1)];
            let dot = |row: [f64; 4]| row.iter().zip(along).map(|(r, a)| r * a).sum::<f64>();
            let torque = dot(slopes.torque);
            self.body_loads[s].moment += torque;
            self.body_loads[0].moment -= torque;
            out[o.integral] = dot(slopes.rate);
            if let Some(e) = o.engine {
                out[e] = dot(slopes.engine);
                out[e + 1] = dot(slopes.twist);
            }
        }
        if direction.track.is_some_and(|(_, rate)| rate) {
            // ∂ż/∂y: the rates' own columns.
            for (slot, &c) in independent.iter().enumerate() {
                out[o.track + slot] = if c < 2 { root.1[c] } else { self.rates[c - 2] };
            }
        }
        out[o.chassis..o.chassis + dof].copy_from_slice(&self.chassis_qd);
    }

    /// A track column's motion: every link's full angle and rate change
    /// (the independent coordinate's, the loop's pair following it, and at
    /// fixed independent rates the pair's rates following the
    /// configuration), then every link's pose and velocity change down the
    /// chain; the root's position and velocity change. A column that does
    /// not move the track moves no link.
    fn track_motion(
        &mut self,
        at: &Linearisation<'_>,
        direction: Direction,
    ) -> (Vector2<f64>, Vector2<f64>) {
        let n = self.joints.len();
        // The track: full angle and rate changes of every link.
        self.angles.fill(0.0);
        self.rates.fill(0.0);
        let mut root = (Vector2::zeros(), Vector2::zeros());
        if let Some((coordinate, rate)) = direction.track {
            let [k, l] = at.pair;
            let moved = if coordinate < 2 {
                Vector2::zeros()
            } else {
                perp(self.turned_spans[coordinate - 2])
            };
            let dependent = -(self.dependent_inverse * moved);
            let (target, root_of) = if rate {
                (&mut self.rates, &mut root.1)
            } else {
                (&mut self.angles, &mut root.0)
            };
            if coordinate < 2 {
                root_of[coordinate] = 1.0;
            } else {
                target[coordinate - 2] = 1.0;
            }
            target[k] = dependent.x;
            target[l] = dependent.y;
            if !rate {
                // At fixed independent rates the pair's rates follow the
                // configuration: C_d δω_d = Σⱼ Aʲ d̄ʲ ωⱼ δθⱼ.
                let turned: Vector2<f64> = (0..n)
                    .map(|j| self.turned_spans[j] * (self.omega[j] * self.angles[j]))
                    .sum();
                let rates = self.dependent_inverse * turned;
                self.rates[k] = rates.x;
                self.rates[l] = rates.y;
            }
        }
        // Every link's pose and velocity change, down the chain:
        // `R_{i+1} = Rᵢ + Aⁱ ū2ⁱ − A^{i+1} ū1^{i+1}` and its rate (a track
        // column's alone: the others move no link).
        if direction.track.is_some() {
            let (mut position, mut velocity) = root;
            let links = self
                .arms1
                .iter()
                .zip(&self.arms2)
                .zip(self.omega.iter().zip(&self.angles).zip(&self.rates))
                .zip(self.link_pose.iter_mut().zip(&mut self.link_rate));
            for (i, (((a1, a2), ((&w, &dt), &dw)), (pose, rate))) in links.enumerate() {
                if i > 0 {
                    position -= perp(*a1) * dt;
                    velocity -= perp(*a1) * dw - a1 * (w * dt);
                }
                *pose = Vector3::new(position.x, position.y, dt);
                *rate = Vector3::new(velocity.x, velocity.y, dw);
                position += perp(*a2) * dt;
                velocity += perp(*a2) * dw - a2 * (w * dt);
            }
        }
        root
    }

    /// Each contact's load by what the column moves — the links' states
    /// (a track column), the bodies' (a chassis column: the rims and teeth
    /// alone), or one ground point's deflection — into the links' block
    /// (`(b, kb)`: this column's place in it) and the bodies' loads, the
    /// deflections' rows into `out`.
    fn contact_loads(
        &mut self,
        at: &Linearisation<'_>,
        direction: Direction,
        (b, kb): (usize, usize),
        out: &mut [f64],
    ) {
        let o = self.starts;
        // The loads' changes.
        self.body_loads.fill(BodyLoad::ZERO);
        let unit = at.points.unit;
        let deflection = direction.point;
        // Each contact's load by what the column moves: the links' states
        // (a track column), the bodies' (a chassis column: the rims and
        // teeth alone), or one ground point's deflection.
        let add = |c: &Compact,
                   change: SVector<f64, 7>,
                   loads: &mut [BodyLoad],
                   bodies: &mut [BodyLoad],
                   out: &mut [f64]| {
            // The links' loads straight into the block, link-major.
            let e = c.link * kb + b;
            loads[e] = loads[e].plus(BodyLoad {
                force: Vector2::new(change[0], change[1]),
                moment: change[2],
            });
            if let Some(b) = c.other {
                bodies[b] = bodies[b].plus(BodyLoad {
                    force: Vector2::new(change[3], change[4]),
                    moment: change[5],
                });
            }
            if let Some(slot) = c.slot {
                out[o.tangential + slot] += change[6] / unit;
            }
        };
        if direction.track.is_some() {
            for c in &self.compact {
                let mut state = SVector::<f64, 6>::zeros();
                state
                    .fixed_rows_mut::<3>(0)
                    .copy_from(&self.link_pose[c.link]);
                state
                    .fixed_rows_mut::<3>(3)
                    .copy_from(&self.link_rate[c.link]);
                add(
                    c,
                    c.rows(&c.by_link, &state),
                    &mut self.block_loads,
                    &mut self.body_loads,
                    out,
                );
            }
        } else if direction.chassis.is_some() {
            for c in &self.compact {
                if let Some(b) = c.other {
                    let mut state = SVector::<f64, 6>::zeros();
                    state.fixed_rows_mut::<3>(0).copy_from(&self.body_pose[b]);
                    state.fixed_rows_mut::<3>(3).copy_from(&self.body_rate[b]);
                    add(
                        c,
                        c.rows(&c.by_other, &state),
                        &mut self.block_loads,
                        &mut self.body_loads,
                        out,
                    );
                }
            }
            for (b, by_body) in &self.chassis_compact {
                let mut state = SVector::<f64, 6>::zeros();
                state.fixed_rows_mut::<3>(0).copy_from(&self.body_pose[*b]);
                state.fixed_rows_mut::<3>(3).copy_from(&self.body_rate[*b]);
                let change = by_body * state;
                self.body_loads[*b] = self.body_loads[*b].plus(BodyLoad {
                    force: Vector2::new(change[0], change[1]),
                    moment: change[2],
                });
            }
        } else if let Some(slot) = deflection {
            for c in self.compact.iter().filter(|c| c.slot == Some(slot)) {
                add(
                    c,
                    c.by_deflection * unit,
                    &mut self.block_loads,
                    &mut self.body_loads,
                    out,
                );
            }
        }
    }

    /// Every chassis body's pose and velocity change from the chassis'
    /// coordinate and rate changes: `H δq` and `H δq̇ + (∂H/∂q δq) q̇`, a
    /// lever `A_θᵖ u` turning by `−Aᵖ u δθₚ`.
    fn body_motion(&mut self, at: &Linearisation<'_>) {
        let (_, qdc, rotations) = at.chassis;
        let bodies = &self.chassis.bodies;
        let m = bodies.len();
        let rows = self.h.nrows();
        let h = self.h.as_slice();
        for b in 0..m {
            // Rows 3b … 3b + 2 of the column-major H times δq, δq̇.
            let (mut pose, mut rate) = (Vector3::<f64>::zeros(), Vector3::<f64>::zeros());
            for (j, (&dq, &dqd)) in self.chassis_q.iter().zip(&self.chassis_qd).enumerate() {
                if dq == 0.0 && dqd == 0.0 {
                    continue;
                }
                let column = &h[j * rows + 3 * b..j * rows + 3 * b + 3];
                for r in 0..3 {
                    pose[r] += column[r] * dq;
                    rate[r] += column[r] * dqd;
                }
            }
            // The levers turning with the configuration.
            let own = rotations[b].apply(bodies[b].at_self);
            let mut turning = own * (qdc[2 + b] * self.chassis_q[2 + b]);
            let mut c = b;
            while let Some(p) = bodies[c].parent {
                let toward = rotations[p].apply(bodies[c].at_parent);
                let lever = toward - rotations[p].apply(bodies[p].at_self);
                turning -= lever * (qdc[2 + p] * self.chassis_q[2 + p]);
                c = p;
            }
            rate[0] += turning.x;
            rate[1] += turning.y;
            self.body_pose[b] = Vector3::new(pose[0], pose[1], pose[2]);
            self.body_rate[b] = Vector3::new(rate[0], rate[1], rate[2]);
        }
    }
}

/// Which state component a column varies.
#[derive(Debug, Clone, Copy, Default)]
struct Direction {
    /// A track coordinate (`q_i` index) and whether its rate.
    track: Option<(usize, bool)>,
    /// A chassis coordinate and whether its rate.
    chassis: Option<(usize, bool)>,
    /// The drive's integral.
    integral: bool,
    /// The engine's speed (0) or the locked driveline's twist (1).
    engine: Option<usize>,
    /// A ground point's deflection.
    point: Option<usize>,
}
