//! [`Implicit`]'s solve with a factored `I − a W`: the stage's loads on
//! the bodies, the track's chain and the chassis' Schur complement, and
//! the whole state's increments from the bodies' (the factorisation is
//! the parent module's).

use nalgebra::Vector3;

use super::{Implicit, PointLink, add, at, drive_block};
use crate::vehicle::layout::Starts;

impl Implicit {
    /// Solves `(I − a W) k = r` in place (`r` the whole state's length),
    /// with the factorisation of [`factor`](Self::factor).
    ///
    /// # Panics
    /// If not factored (a programming error).
    pub fn solve(&mut self, r: &mut [f64]) {
        crate::simd::run(
            #[inline(always)]
            || self.solve_inline(r),
        );
    }

    /// [`solve`](Self::solve)'s loops, inlined into its wide build.
    #[inline(always)]
    fn solve_inline(&mut self, r: &mut [f64]) {
        let dof = self.dof;
        let Starts { track, chassis, .. } = self.starts;
        let nt = self.independent.len();
        let mut track_q = std::mem::take(&mut self.track_q);
        let mut track_v = std::mem::take(&mut self.track_v);
        self.track_increments(&r[track..track + nt], &mut track_q);
        self.track_increments(&r[track + nt..track + 2 * nt], &mut track_v);
        let r_qc = &r[chassis..chassis + dof];
        // The chassis bodies' position increments, `H r_q`, column by
        // column (H is column-major).
        let rows = self.h.nrows();
        self.body_q.fill(0.0);
        for (column, &v) in self.h.as_slice().chunks_exact(rows).zip(r_qc) {
            if v != 0.0 {
                for (q, h) in self.body_q.iter_mut().zip(column) {
                    *q += h * v;
                }
            }
        }
        self.stage_loads(r, &track_q, &track_v);
        let mut x = std::mem::take(&mut self.x);
        self.solve_track_and_chassis(r, &track_q, &mut x);
        self.increments(r, &track_q, &x);
        self.track_q = track_q;
        self.track_v = track_v;
        self.x = x;
    }

    /// The links' and the chassis bodies' loads of a solve's right side:
    /// `M u_v + a K u_q` (own and coupled), the velocities the
    /// configuration's increment turns, the ground points' deflections'
    /// share. Part of [`solve_inline`](Self::solve_inline).
    #[inline(always)]
    fn stage_loads(&mut self, r: &[f64], track_q: &[f64], track_v: &[f64]) {
        let a = self.shift;
        let tangential = self.starts.tangential;
        // The links' loads: M u_v + a K u_q (own and coupled), the
        // deflections' share; the chassis bodies': a K u_q.
        for (i, ((load, v), q)) in self
            .loads
            .chunks_exact_mut(3)
            .zip(track_v.chunks_exact(3))
            .zip(track_q.chunks_exact(3))
            .enumerate()
        {
            let q = Vector3::new(q[0], q[1], q[2]) * a;
            let f = Vector3::new(v[0], v[1], v[2]).component_mul(&self.link_mass[i])
                + self.link_by_pose[i] * q;
            load.copy_from_slice(f.as_slice());
        }
        // The velocities the configuration's increment turns, `V r_q`:
        // the stage's velocity increments `x` are the bodies' whole
        // velocity changes, `H B k_v + V k_q`, so `M V r_q` joins `M u_v`
        // (`a M V k_v`, the inertia's convective share, is left out).
        let mut turned = std::mem::take(&mut self.turned);
        self.convective(track_q, &mut turned);
        for (i, (load, v)) in self
            .loads
            .chunks_exact_mut(3)
            .zip(turned.chunks_exact(3))
            .enumerate()
        {
            let m = self.link_mass[i];
            load[0] += m.x * v[0];
            load[1] += m.y * v[1];
            load[2] += m.z * v[2];
        }
        self.turned = turned;
        for (b, f) in self.body_forces.chunks_exact_mut(3).enumerate() {
            let w = self.body_by_pose[b] * (at(&self.body_q, b) * a);
            f.copy_from_slice(w.as_slice());
        }
        for c in &self.couplings {
            add(
                &mut self.loads,
                c.link,
                c.link_by_pose * (at(&self.body_q, c.body) * a),
            );
            add(
                &mut self.body_forces,
                c.body,
                c.body_by_pose * (at(track_q, c.link) * a),
            );
        }
        for point in &self.points {
            if let Some(PointLink {
                index: i,
                load_by_state: by_state,
                by_pose,
                ..
            }) = point.link
            {
                let free = (r[tangential + point.state] + a * by_pose.dot(&at(track_q, i)))
                    / (1.0 - a * point.by_self);
                add(&mut self.loads, i, by_state * (a * free));
            }
        }
    }

    /// The track's solve without the chassis' answer, the chassis' right
    /// side and its solve through the Schur complement, then the track's
    /// answer corrected: `x` the links' velocity increments, the chassis'
    /// in `chassis_rhs`. Part of [`solve_inline`](Self::solve_inline).
    #[inline(always)]
    fn solve_track_and_chassis(&mut self, r: &[f64], track_q: &[f64], x: &mut [f64]) {
        let a = self.shift;
        let dof = self.dof;
        let Starts {
            chassis, integral, ..
        } = self.starts;
        let (r_qc, r_vc) = r[chassis..chassis + 2 * dof].split_at(dof);
        let rows = self.h.nrows();
        // The track without the chassis' answer, and what it does to the
        // chassis through the rims and teeth.
        // The joints' rows: a turned link turns its joints' velocities,
        // `A ū ω δθ` with the position's part of `δθ` here.
        let n = self.joints.len();
        for j in 0..n {
            let k = (j + 1) % n;
            self.joint_rhs[j] =
                self.spin[j].1 * track_q[3 * j + 2] - self.spin[k].0 * track_q[3 * k + 2];
        }
        self.chain.solve(&self.loads, &self.joint_rhs, x);
        for c in &self.couplings {
            let e = c.body_by_rate * a + c.body_by_pose * (a * a);
            add(&mut self.body_forces, c.body, e * at(x, c.link));
        }
        // The chassis' right side: M r_v + Hᵀ (the bodies' loads), the
        // arms, the drive; then its increments.
        let g = &mut self.chassis_rhs;
        g.fill(0.0);
        for (column, &v) in self.chassis_mass.as_slice().chunks_exact(dof).zip(r_vc) {
            for (g, m) in g.as_mut_slice().iter_mut().zip(column) {
                *g += m * v;
            }
        }
        for (g, column) in g
            .as_mut_slice()
            .iter_mut()
            .zip(self.h.as_slice().chunks_exact(rows))
        {
            *g += column
                .iter()
                .zip(&self.body_forces)
                .map(|(h, f)| h * f)
                .sum::<f64>();
        }
        for &(body, by_angle, _) in &self.arms {
            let phi = a * by_angle * (r_qc[2 + body] - r_qc[2]);
            g[2 + body] += phi;
            g[2] -= phi;
        }
        if let Some((body, slopes)) = self.drive {
            let push = match self.starts.engine {
                None => {
                    let [_, torque_by_integral, ..] = slopes.torque;
                    let [_, rate_by_integral, ..] = slopes.rate;
                    a * torque_by_integral * r[integral] / (1.0 - a * rate_by_integral)
                }
                Some(engine) => {
                    let (p, _, c) = drive_block(a, &slopes);
                    a * c.dot(&(p * Vector3::new(r[integral], r[engine], r[engine + 1])))
                }
            };
            g[2 + body] += push;
            g[2] -= push;
        }
        let lu = self.schur.as_ref().expect("factored before a solve");
        if !lu.solve_mut(g) {
            g.fill(f64::NAN);
        }
        // `x −= Z x_c`, a column of Z at a time (contiguous, no reduction:
        // it vectorises).
        let x_c = self.chassis_rhs.as_slice();
        for (column, &v) in self.coupled_columns.chunks_exact(x.len()).zip(x_c) {
            if v != 0.0 {
                for (xi, z) in x.iter_mut().zip(column) {
                    *xi -= z * v;
                }
            }
        }
    }

    /// Back to the state's increments from the links' `x` and the
    /// chassis' `chassis_rhs`. Part of [`solve_inline`](Self::solve_inline).
    #[inline(always)]
    fn increments(&self, r: &mut [f64], track_q: &[f64], x: &[f64]) {
        let a = self.shift;
        let dof = self.dof;
        let Starts {
            track,
            chassis,
            integral,
            engine,
            tangential,
        } = self.starts;
        let nt = self.independent.len();
        let x_c = self.chassis_rhs.as_slice();
        // Back to the state's increments.
        for point in &self.points {
            let denominator = 1.0 - a * point.by_self;
            let slot = tangential + point.state;
            r[slot] = match point.link {
                Some(PointLink {
                    index: i,
                    by_pose,
                    by_rate,
                    ..
                }) => {
                    let xi = at(x, i);
                    (r[slot] + a * by_pose.dot(&(at(track_q, i) + xi * a)) + a * by_rate.dot(&xi))
                        / denominator
                }
                None => r[slot] / denominator,
            };
        }
        if let Some((body, slopes)) = self.drive {
            let speed = x_c[2 + body] - x_c[2];
            match engine {
                None => {
                    let [rate_by_speed, rate_by_integral, ..] = slopes.rate;
                    r[integral] =
                        (r[integral] + a * rate_by_speed * speed) / (1.0 - a * rate_by_integral);
                }
                Some(engine) => {
                    let (p, b, _) = drive_block(a, &slopes);
                    let local = Vector3::new(r[integral], r[engine], r[engine + 1]);
                    let k = p * (local + b * (a * speed));
                    r[integral] = k.x;
                    r[engine] = k.y;
                    r[engine + 1] = k.z;
                }
            }
        }
        for (slot, &c) in self.independent.iter().enumerate() {
            let v = if c < 2 { x[c] } else { x[3 * (c - 2) + 2] };
            r[track + nt + slot] = v;
            r[track + slot] += a * v;
        }
        for (j, &v) in x_c.iter().enumerate() {
            r[chassis + dof + j] = v;
            r[chassis + j] += a * v;
        }
    }
}
