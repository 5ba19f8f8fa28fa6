//! The floating chain's kinematics, kinetic energy and forward dynamics
//! over a planar model's generated code.

use nalgebra::{Matrix2, Matrix3, SVector, Vector2, Vector3};

use super::{OutOfPlaneInertia, SpatialError, plane_rotation};
use crate::multibody::{BodyLoad, DynamicsError, RecursiveModel};

/// Where the chain is: link 1's centroid in the world, the plane's yaw
/// and roll, and the links' angles in the plane.
#[derive(Debug, Clone, PartialEq)]
pub struct ChainPose<const DOF: usize> {
    /// Link 1's centroid, world frame, m.
    pub origin: Vector3<f64>,
    /// The plane's yaw `ψ`, rad.
    pub yaw: f64,
    /// The plane's roll `φ`, rad (|φ| < 90°).
    pub roll: f64,
    /// The planar chain's `q_i` with link 1 at the plane's origin:
    /// `[0, 0, θ¹ … θⁿ]` (the first two are not read).
    pub planar: SVector<f64, DOF>,
}

/// How the chain moves: the quasi-velocities of the module's docs.
#[derive(Debug, Clone, PartialEq)]
pub struct ChainRates<const DOF: usize> {
    /// In the plane: `[v_ξ, v_ζ, θ̇¹ − ω_η … θ̇ⁿ − ω_η]` (m/s, rad/s), the
    /// planar chain's `q̇_i`.
    pub planar: SVector<f64, DOF>,
    /// Out of it: `(v_η, ω_ξ, ω_ζ)` (m/s, rad/s).
    pub across: Vector3<f64>,
}

/// A load on a link at its centroid, world frame: force (N) and moment
/// (N m).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct SpatialLoad {
    /// Force, N.
    pub force: Vector3<f64>,
    /// Moment about the centroid, N m.
    pub moment: Vector3<f64>,
}

/// A planar chain (any [`RecursiveModel`]: its generated code) floating
/// in space with its links' inertia across the plane.
pub struct SpatialChain<'m, M, const DOF: usize> {
    model: &'m M,
    masses: Vec<f64>,
    inertias: Vec<f64>,
    across: Vec<OutOfPlaneInertia>,
    gravity: f64,
}

/// What every link's motion gives at a state, in `P`'s components.
struct LinkMotion {
    /// Centroid relative to link 1, `(ξ, ζ)`, m.
    place: Vec<Vector2<f64>>,
    /// Velocity in the plane, `(V_ξ, V_ζ)`, m/s.
    in_plane: Vec<Vector2<f64>>,
    /// The in-plane velocity's part from the links' rates alone
    /// (`v = 0`), m/s.
    relative: Vec<Vector2<f64>>,
    /// Velocity across the plane, `V_η`, m/s.
    across: Vec<f64>,
    /// `(sin θ, cos θ)` of every link.
    trig: Vec<(f64, f64)>,
}

impl<'m, M: RecursiveModel<DOF>, const DOF: usize> SpatialChain<'m, M, DOF> {
    /// `model` in space, with `across[k]` the out-of-plane inertia of link
    /// `k + 1`.
    pub fn new(model: &'m M, across: Vec<OutOfPlaneInertia>) -> Result<Self, SpatialError> {
        let description = model.description();
        let links = description.bodies.len();
        if across.len() != links {
            return Err(SpatialError::Inertias {
                links,
                given: across.len(),
            });
        }
        for (k, i) in across.iter().enumerate() {
            let finite = [i.xx, i.zz, i.xz].iter().all(|v| v.is_finite());
            if !(finite && i.xx > 0.0 && i.zz > 0.0 && i.xx * i.zz > i.xz * i.xz) {
                return Err(SpatialError::Inertia {
                    link: k + 1,
                    inertia: *i,
                });
            }
        }
        let g = description.gravity;
        if g.x != 0.0 || g.y > 0.0 || !g.y.is_finite() {
            return Err(SpatialError::Gravity { x: g.x, y: g.y });
        }
        Ok(SpatialChain {
            model,
            masses: description.bodies.iter().map(|b| b.mass).collect(),
            inertias: description.bodies.iter().map(|b| b.inertia).collect(),
            across,
            gravity: -g.y,
        })
    }

    /// Every link's centroid in the world, m.
    pub fn positions(&self, pose: &ChainPose<DOF>) -> Vec<Vector3<f64>> {
        let a = plane_rotation(pose.yaw, pose.roll);
        self.places(pose)
            .iter()
            .map(|p| pose.origin + a * Vector3::new(p.x, 0.0, p.y))
            .collect()
    }

    /// The rates of the coordinates: link 1's centroid's velocity in the
    /// world (m/s), `ψ̇`, `φ̇` and the links' `θ̇` (rad/s; the vector's
    /// first two entries zero).
    pub fn coordinate_rates(
        &self,
        pose: &ChainPose<DOF>,
        rates: &ChainRates<DOF>,
    ) -> (Vector3<f64>, f64, f64, SVector<f64, DOF>) {
        let a = plane_rotation(pose.yaw, pose.roll);
        let [v_eta, w_xi, w_zeta] = [rates.across.x, rates.across.y, rates.across.z];
        let velocity = a * Vector3::new(rates.planar[0], v_eta, rates.planar[1]);
        let cos = pose.roll.cos();
        let turning = w_zeta * pose.roll.tan();
        let mut angles = rates.planar;
        angles[0] = 0.0;
        angles[1] = 0.0;
        for k in 2..DOF {
            angles[k] += turning;
        }
        (velocity, w_zeta / cos, w_xi, angles)
    }

    /// The kinetic energy, J: the planar chain's at the in-plane rates,
    /// plus the motion across the plane and the links' rotation about the
    /// plane's `ξ` and `ζ` axes.
    pub fn kinetic_energy(&self, pose: &ChainPose<DOF>, rates: &ChainRates<DOF>) -> f64 {
        let motion = self.motion(pose, rates);
        let planar = self
            .model
            .kinetic_energy(&at_origin(&pose.planar), &rates.planar);
        let w = Vector2::new(rates.across.y, rates.across.z);
        let across: f64 = (0..self.masses.len())
            .map(|k| {
                let inertia = self.in_plane_inertia(k, motion.trig[k]);
                0.5 * self.masses[k] * motion.across[k].powi(2) + 0.5 * w.dot(&(inertia * w))
            })
            .sum();
        planar + across
    }

    /// The 3 × 3 mass matrix of the out-of-plane quasi-velocities
    /// `(v_η, ω_ξ, ω_ζ)`.
    pub fn across_mass(&self, pose: &ChainPose<DOF>) -> Matrix3<f64> {
        let places = self.places(pose);
        let mut mass = Matrix3::zeros();
        for (k, p) in places.iter().enumerate() {
            let c = Vector3::new(1.0, -p.y, p.x);
            mass += self.masses[k] * c * c.transpose();
            let (s, co) = sin_cos(&pose.planar, k);
            let inertia = self.in_plane_inertia(k, (s, co));
            let mut turning = mass.fixed_view_mut::<2, 2>(1, 1);
            turning += inertia;
        }
        mass
    }

    /// Forward dynamics of the open chain (its closing joint cut, as the
    /// planar model's [`tree_dynamics`](RecursiveModel::tree_dynamics)
    /// treats it) under gravity and `loads` (one per link, or none): the
    /// rates of the quasi-velocities, in the plane (the planar `q̈_i`) and
    /// across it.
    pub fn accelerations(
        &self,
        pose: &ChainPose<DOF>,
        rates: &ChainRates<DOF>,
        loads: &[SpatialLoad],
    ) -> Result<(SVector<f64, DOF>, Vector3<f64>), DynamicsError> {
        let n = self.masses.len();
        if !(loads.is_empty() || loads.len() == n) {
            return Err(DynamicsError::WrongLength {
                what: "spatial loads",
                expected: n,
                got: loads.len(),
            });
        }
        let a = plane_rotation(pose.yaw, pose.roll);
        let (sr, cr) = pose.roll.sin_cos();
        let motion = self.motion(pose, rates);
        let [w_xi, w_zeta] = [rates.across.y, rates.across.z];
        let w_eta = w_zeta * pose.roll.tan();
        let omega = Vector3::new(w_xi, w_eta, w_zeta);
        // The plane's gravity: (0, −g sin φ, −g cos φ); the planar code
        // applies (0, −g) in the plane already.
        let (g_across, g_in_extra) = (-self.gravity * sr, self.gravity * (1.0 - cr));
        let mut planar_loads = vec![BodyLoad::ZERO; n];
        let mut rhs = Vector3::zeros();
        for (k, planar_load) in planar_loads.iter_mut().enumerate() {
            let m = self.masses[k];
            let load = loads.get(k).copied().unwrap_or_default();
            let (force, moment) = (a.transpose() * load.force, a.transpose() * load.moment);
            let place = motion.place[k];
            let v = Vector3::new(motion.in_plane[k].x, motion.across[k], motion.in_plane[k].y);
            let omega_v = omega.cross(&v);
            // The links' true angular rates turn the relative place:
            // d/dt (ξ, ζ) = relative velocity + ω_η perp(place).
            let moving = motion.relative[k] + w_eta * perp(place);
            // In the plane: the cross term of the links' true and relative
            // rates, ω_η perp(ρ̇ relative), and ω × V.
            let bias_in = w_eta * perp(motion.relative[k]) + Vector2::new(omega_v.x, omega_v.z);
            let bias_across = w_zeta * moving.x - w_xi * moving.y + omega_v.y;
            // Rotation: H = (I₂ (ω_ξ, ω_ζ), −J (θ̇ − ω_η)).
            let trig = motion.trig[k];
            let inertia = self.in_plane_inertia(k, trig);
            let spin = rates.planar[k + 2];
            let turning = self.in_plane_inertia_rate(k, trig, spin + w_eta);
            let h2 = inertia * Vector2::new(w_xi, w_zeta);
            let h = Vector3::new(h2.x, -self.inertias[k] * spin, h2.y);
            let omega_h = omega.cross(&h);
            let bias_turn =
                turning * Vector2::new(w_xi, w_zeta) + Vector2::new(omega_h.x, omega_h.z);
            *planar_load = BodyLoad {
                force: Vector2::new(force.x, force.z) + m * Vector2::new(0.0, g_in_extra)
                    - m * bias_in,
                moment: -moment.y + omega_h.y,
            };
            let c = Vector3::new(1.0, -place.y, place.x);
            rhs += c * (force.y + m * g_across - m * bias_across);
            rhs += Vector3::new(0.0, moment.x - bias_turn.x, moment.z - bias_turn.y);
        }
        let mut planar = SVector::<f64, DOF>::zeros();
        self.model
            .tree_dynamics(&motion.trig, &rates.planar, &planar_loads, &mut planar)?;
        let across = self
            .across_mass(pose)
            .cholesky()
            .ok_or(DynamicsError::MassMatrixNotPositiveDefinite)?
            .solve(&rhs);
        Ok((planar, across))
    }

    /// Every link's centroid relative to link 1, `(ξ, ζ)`, m.
    fn places(&self, pose: &ChainPose<DOF>) -> Vec<Vector2<f64>> {
        let mut out = vec![Vector2::zeros(); self.masses.len()];
        self.model
            .body_positions(&at_origin(&pose.planar), &mut out);
        out
    }

    fn motion(&self, pose: &ChainPose<DOF>, rates: &ChainRates<DOF>) -> LinkMotion {
        let n = self.masses.len();
        let q = at_origin(&pose.planar);
        let mut place = vec![Vector2::zeros(); n];
        self.model.body_positions(&q, &mut place);
        let mut in_plane = vec![Vector2::zeros(); n];
        self.model.body_velocities(&q, &rates.planar, &mut in_plane);
        let mut spins = rates.planar;
        spins[0] = 0.0;
        spins[1] = 0.0;
        let mut relative = vec![Vector2::zeros(); n];
        self.model.body_velocities(&q, &spins, &mut relative);
        let [v_eta, w_xi, w_zeta] = [rates.across.x, rates.across.y, rates.across.z];
        let across = place
            .iter()
            .map(|p| v_eta + w_zeta * p.x - w_xi * p.y)
            .collect();
        let trig = (0..n).map(|k| sin_cos(&pose.planar, k)).collect();
        LinkMotion {
            place,
            in_plane,
            relative,
            across,
            trig,
        }
    }

    /// Link `k`'s inertia about the plane's `ξ` and `ζ` axes, its own
    /// turned by its angle: `A(θ) I_b A(θ)ᵀ`.
    fn in_plane_inertia(&self, k: usize, (s, c): (f64, f64)) -> Matrix2<f64> {
        let i = self.across[k];
        let body = Matrix2::new(i.xx, i.xz, i.xz, i.zz);
        let turn = Matrix2::new(c, -s, s, c);
        turn * body * turn.transpose()
    }

    /// Its rate when the link turns at `rate` (rad/s) in the plane.
    fn in_plane_inertia_rate(&self, k: usize, (s, c): (f64, f64), rate: f64) -> Matrix2<f64> {
        let i = self.across[k];
        let body = Matrix2::new(i.xx, i.xz, i.xz, i.zz);
        let turn = Matrix2::new(c, -s, s, c);
        let slope = Matrix2::new(-s, -c, c, -s);
        let half = slope * body * turn.transpose();
        rate * (half + half.transpose())
    }
}

/// `q_i` with link 1 at the plane's origin.
fn at_origin<const DOF: usize>(q: &SVector<f64, DOF>) -> SVector<f64, DOF> {
    let mut q = *q;
    q[0] = 0.0;
    q[1] = 0.0;
    q
}

fn sin_cos<const DOF: usize>(q: &SVector<f64, DOF>, k: usize) -> (f64, f64) {
    q[k + 2].sin_cos()
}

/// A plane vector turned a quarter counter-clockwise (from `ξ` toward
/// `ζ`).
fn perp(v: Vector2<f64>) -> Vector2<f64> {
    Vector2::new(-v.y, v.x)
}
