//! The floating tree's kinematics, kinetic energy and forward dynamics
//! over a planar model's generated code.

use nalgebra::{Matrix2, Matrix3, SVector, Vector2, Vector3};

use super::{OutOfPlaneInertia, SpatialError, plane_rotation};
use crate::multibody::{BodyLoad, ClosingJoint, DynamicsError, RecursiveModel, TrackModel};

/// Where the tree is: its root's centroid in the world, the plane's yaw
/// and roll, and the bodies' angles in the plane.
#[derive(Debug, Clone, PartialEq)]
pub struct PlanePose<const DOF: usize> {
    /// The root's centroid (a track's link 1, a hull), world frame, m.
    pub origin: Vector3<f64>,
    /// The plane's yaw `ψ`, rad.
    pub yaw: f64,
    /// The plane's roll `φ`, rad (|φ| < 90°).
    pub roll: f64,
    /// The planar model's `q_i` with its root at the plane's origin:
    /// `[0, 0, θ¹ … θⁿ]` (the first two are not read).
    pub planar: SVector<f64, DOF>,
}

impl<const DOF: usize> PlanePose<DOF> {
    /// The heading's rate `ψ̇ = ω_ζ / cos φ` at `rates`, rad/s (the second
    /// of [`FloatingTree::coordinate_rates`], without the rest).
    #[inline]
    pub fn yaw_rate(&self, rates: &PlaneRates<DOF>) -> f64 {
        rates.across.z / self.roll.cos()
    }
}

/// How the tree moves: the quasi-velocities of the module's docs.
#[derive(Debug, Clone, PartialEq)]
pub struct PlaneRates<const DOF: usize> {
    /// In the plane: `[v_ξ, v_ζ, θ̇¹ − ω_η … θ̇ⁿ − ω_η]` (m/s, rad/s), the
    /// planar model's `q̇_i`.
    pub planar: SVector<f64, DOF>,
    /// Out of it: `(v_η, ω_ξ, ω_ζ)` (m/s, rad/s).
    pub across: Vector3<f64>,
}

/// Every body of a tree in the world ([`FloatingTree::world`]).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct WorldMotion {
    /// Centroids, m.
    pub positions: Vec<Vector3<f64>>,
    /// Orientations: each body's `x`, the plane's normal and its `y` as
    /// columns.
    pub orientations: Vec<Matrix3<f64>>,
    /// Centroid velocities, m/s.
    pub velocities: Vec<Vector3<f64>>,
    /// Angular velocities, rad/s.
    pub angular_velocities: Vec<Vector3<f64>>,
}

/// A tree's bodies in their plane at a state, found once per evaluation
/// ([`FloatingTree::plane_motion`]) and read by both the force elements
/// ([`FloatingTree::world_of`]) and the forward dynamics
/// ([`FloatingTree::accelerations_in`]): every angle's sine and cosine,
/// and every centroid's place and velocity relative to the root in the
/// plane.
#[derive(Debug, Clone, PartialEq)]
pub struct PlaneMotion {
    /// `(sin θ, cos θ)` of every body.
    trig: Vec<(f64, f64)>,
    /// Centroid relative to the root, `(ξ, ζ)`, m.
    place: Vec<Vector2<f64>>,
    /// Centroid velocity in the plane, `(V_ξ, V_ζ)`, m/s.
    planar: Vec<Vector2<f64>>,
}

impl PlaneMotion {
    /// `(sin θ, cos θ)` of every body's angle in the plane.
    pub fn trig(&self) -> &[(f64, f64)] {
        &self.trig
    }
}

/// A load on a body at its centroid, world frame: force (N) and moment
/// (N m).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct SpatialLoad {
    /// Force, N.
    pub force: Vector3<f64>,
    /// Moment about the centroid, N m.
    pub moment: Vector3<f64>,
}

/// A planar tree (any [`RecursiveModel`]: its generated code) floating in
/// space: every body turns about the plane's normal `η`, at its own
/// constant distance along it from the root (a track's links all at 0; a
/// hull's running gear at plus or minus half the gauge), with its
/// inertia about the plane's other two axes.
pub struct FloatingTree<'m, M, const DOF: usize> {
    model: &'m M,
    masses: Vec<f64>,
    inertias: Vec<f64>,
    across: Vec<OutOfPlaneInertia>,
    offsets: Vec<f64>,
    gravity: f64,
}

/// What every body's motion gives at a state, in `P`'s components, read
/// body by body from the plane's motion.
struct BodyMotion<'p> {
    /// Centroid relative to the root in the plane, `(ξ, ζ)`, m.
    place: &'p [Vector2<f64>],
    /// Centroid velocity in the plane, `(V_ξ, V_ζ)`, m/s.
    planar: &'p [Vector2<f64>],
    /// The root's velocity in the plane, `(v_ξ, v_ζ)`, m/s.
    root: Vector2<f64>,
    /// The plane's quasi-velocities across it, `(v_η, ω_ξ, ω_ζ)`.
    across: Vector3<f64>,
    /// Each body's distance along the plane's normal, m.
    offsets: &'p [f64],
    /// The planar quadratic velocity terms `γ` (eq. (14)) at `q̇_i`,
    /// m/s² (found only where a body is off the plane; else empty).
    gamma: Vec<Vector2<f64>>,
    /// `(sin θ, cos θ)` of every body.
    trig: &'p [(f64, f64)],
}

impl BodyMotion<'_> {
    /// Body `k`'s velocity's part from the bodies' rates alone (`v = 0`),
    /// m/s: the velocities are linear in `q̇_i` and the root's `(v_ξ, v_ζ)`
    /// moves every body alike.
    #[inline]
    fn relative(&self, k: usize) -> Vector2<f64> {
        self.planar[k] - self.root
    }

    /// Body `k`'s full velocity, `(V_ξ, V_η, V_ζ)`, m/s.
    #[inline]
    fn velocity(&self, k: usize) -> Vector3<f64> {
        let (p, e) = (self.place[k], self.offsets[k]);
        let [v_eta, w_xi, w_zeta] = [self.across.x, self.across.y, self.across.z];
        let v = self.planar[k] + e * offset_velocity(&self.across);
        Vector3::new(v.x, v_eta + w_zeta * p.x - w_xi * p.y, v.y)
    }
}

/// `D w`: the in-plane velocity a unit offset along `η` adds, `(−ω_ζ, ω_ξ)`.
fn offset_velocity(across: &Vector3<f64>) -> Vector2<f64> {
    Vector2::new(-across.z, across.y)
}

/// `Dᵀ f`: an in-plane force at a unit offset, on the out-of-plane
/// quasi-velocities `(v_η, ω_ξ, ω_ζ)`.
fn offset_force(f: Vector2<f64>) -> Vector3<f64> {
    Vector3::new(0.0, f.y, -f.x)
}

impl<'m, M: RecursiveModel<DOF>, const DOF: usize> FloatingTree<'m, M, DOF> {
    /// `model` in space, every body in the root's plane, with `across[k]`
    /// the out-of-plane inertia of body `k`.
    pub fn new(model: &'m M, across: Vec<OutOfPlaneInertia>) -> Result<Self, SpatialError> {
        let description = model.description();
        let bodies = description.bodies.len();
        if across.len() != bodies {
            return Err(SpatialError::Inertias {
                bodies,
                given: across.len(),
            });
        }
        for (k, i) in across.iter().enumerate() {
            let finite = [i.xx, i.zz, i.xz].iter().all(|v| v.is_finite());
            if !(finite && i.xx > 0.0 && i.zz > 0.0 && i.xx * i.zz > i.xz * i.xz) {
                return Err(SpatialError::Inertia {
                    body: k,
                    inertia: *i,
                });
            }
        }
        let g = description.gravity;
        if g.x != 0.0 || g.y > 0.0 || !g.y.is_finite() {
            return Err(SpatialError::Gravity { x: g.x, y: g.y });
        }
        Ok(FloatingTree {
            model,
            masses: description.bodies.iter().map(|b| b.mass).collect(),
            inertias: description.bodies.iter().map(|b| b.inertia).collect(),
            across,
            offsets: vec![0.0; bodies],
            gravity: -g.y,
        })
    }

    /// The same tree with body `k` at `offsets[k]` (m) along `η` from the
    /// root's plane (the root's own is its centroid's: 0).
    pub fn with_offsets(self, offsets: Vec<f64>) -> Result<Self, SpatialError> {
        if offsets.len() != self.masses.len() {
            return Err(SpatialError::Offsets {
                bodies: self.masses.len(),
                given: offsets.len(),
            });
        }
        if let Some(k) = offsets.iter().position(|e| !e.is_finite()) {
            return Err(SpatialError::Offset {
                body: k,
                offset: offsets[k],
            });
        }
        Ok(FloatingTree { offsets, ..self })
    }

    /// The planar model it floats.
    pub fn model(&self) -> &'m M {
        self.model
    }

    /// Every body's mass, kg.
    pub fn masses(&self) -> &[f64] {
        &self.masses
    }

    /// Gravity's size, m/s², down the world's `z`.
    pub fn gravity(&self) -> f64 {
        self.gravity
    }

    /// Every body's centroid in the world, m.
    pub fn positions(&self, pose: &PlanePose<DOF>) -> Vec<Vector3<f64>> {
        let a = plane_rotation(pose.yaw, pose.roll);
        self.places(pose)
            .iter()
            .zip(&self.offsets)
            .map(|(p, e)| pose.origin + a * Vector3::new(p.x, *e, p.y))
            .collect()
    }

    /// Every body's orientation in the world: the plane's turned by the
    /// body's angle in it (its `x` to `(cos θ, 0, sin θ)` in the plane).
    pub fn orientations(&self, pose: &PlanePose<DOF>) -> Vec<Matrix3<f64>> {
        let a = plane_rotation(pose.yaw, pose.roll);
        (0..self.masses.len())
            .map(|k| {
                let (s, c) = sin_cos(&pose.planar, k);
                a * Matrix3::new(c, 0.0, -s, 0.0, 1.0, 0.0, s, 0.0, c)
            })
            .collect()
    }

    /// Every body's place, orientation, velocity and angular velocity in
    /// the world at once ([`positions`](Self::positions),
    /// [`orientations`](Self::orientations),
    /// [`velocities`](Self::velocities) and
    /// [`angular_velocities`](Self::angular_velocities) from one pass over
    /// the planar model).
    pub fn world(&self, pose: &PlanePose<DOF>, rates: &PlaneRates<DOF>) -> WorldMotion {
        self.world_of(&self.plane_motion(pose, rates), pose, rates)
    }

    /// The bodies in their plane at `pose` and `rates`: one pass over the
    /// planar model, every angle's sine and cosine in one vectorised pass
    /// ([`trig::sin_cos_each`](crate::trig::sin_cos_each)).
    pub fn plane_motion(&self, pose: &PlanePose<DOF>, rates: &PlaneRates<DOF>) -> PlaneMotion {
        let n = self.masses.len();
        let mut trig = vec![(0.0, 0.0); n];
        crate::trig::sin_cos_each(&pose.planar.as_slice()[2..2 + n], &mut trig);
        let (mut place, mut planar) = (vec![Vector2::zeros(); n], vec![Vector2::zeros(); n]);
        self.model.body_states_with_trig(
            &trig,
            &at_origin(&pose.planar),
            &rates.planar,
            &mut place,
            &mut planar,
        );
        PlaneMotion {
            trig,
            place,
            planar,
        }
    }

    /// [`world`](Self::world) from the bodies' `motion` in their plane at
    /// `pose` and `rates` ([`plane_motion`](Self::plane_motion)'s).
    pub fn world_of(
        &self,
        motion: &PlaneMotion,
        pose: &PlanePose<DOF>,
        rates: &PlaneRates<DOF>,
    ) -> WorldMotion {
        let mut world = WorldMotion::default();
        self.world_into(motion, pose, rates, &mut world);
        world
    }

    /// [`world_of`](Self::world_of) into `world`, its vectors' storage
    /// kept (a right-hand side's bodies found without allocating).
    pub fn world_into(
        &self,
        motion: &PlaneMotion,
        pose: &PlanePose<DOF>,
        rates: &PlaneRates<DOF>,
        world: &mut WorldMotion,
    ) {
        let n = self.masses.len();
        let a = plane_rotation(pose.yaw, pose.roll);
        // The plane's axes: a body's orientation `A R(θ)` is its `x`
        // `c ξ + s ζ`, the normal `η` and its `y` `−s ξ + c ζ`, the product
        // with `R(θ)`'s zeros left out.
        let [xi, eta, zeta]: [Vector3<f64>; 3] =
            [a.column(0).into(), a.column(1).into(), a.column(2).into()];
        let (trig, place, planar) = (&motion.trig, &motion.place, &motion.planar);
        let [v_eta, w_xi, w_zeta] = [rates.across.x, rates.across.y, rates.across.z];
        let turning = offset_velocity(&rates.across);
        world.positions.clear();
        world.orientations.clear();
        world.velocities.clear();
        world.angular_velocities.clear();
        world.positions.reserve(n);
        world.orientations.reserve(n);
        world.velocities.reserve(n);
        world.angular_velocities.reserve(n);
        for k in 0..n {
            let (p, e, (s, c)) = (place[k], self.offsets[k], trig[k]);
            let v = planar[k] + e * turning;
            world
                .positions
                .push(pose.origin + (xi * p.x + eta * e + zeta * p.y));
            // `A R(θ)` with `R(θ)`'s zeros and one left out: the same sums
            // as the full product, less the terms that add zero.
            world.orientations.push(Matrix3::from_columns(&[
                xi * c + zeta * s,
                eta,
                zeta * c - xi * s,
            ]));
            world
                .velocities
                .push(a * Vector3::new(v.x, v_eta + w_zeta * p.x - w_xi * p.y, v.y));
            world
                .angular_velocities
                .push(a * Vector3::new(w_xi, -rates.planar[k + 2], w_zeta));
        }
    }

    /// Every body's inertia about its centroid in its own frame, kg m²:
    /// the declared out-of-plane pair and product, and the planar model's
    /// about the pin axis.
    pub fn body_inertias(&self) -> Vec<Matrix3<f64>> {
        self.across
            .iter()
            .zip(&self.inertias)
            .map(|(i, j)| Matrix3::new(i.xx, 0.0, i.xz, 0.0, *j, 0.0, i.xz, 0.0, i.zz))
            .collect()
    }

    /// Every body's centroid velocity in the world, m/s.
    pub fn velocities(&self, pose: &PlanePose<DOF>, rates: &PlaneRates<DOF>) -> Vec<Vector3<f64>> {
        let a = plane_rotation(pose.yaw, pose.roll);
        let plane = self.plane_motion(pose, rates);
        let motion = self.motion(&plane, pose, rates);
        (0..self.masses.len())
            .map(|k| a * motion.velocity(k))
            .collect()
    }

    /// Every body's angular velocity in the world, rad/s: the plane's
    /// about `ξ` and `ζ`, and about `η` the plane's less the body's turning
    /// in it (`−(θ̇ − ω_η)`).
    pub fn angular_velocities(
        &self,
        pose: &PlanePose<DOF>,
        rates: &PlaneRates<DOF>,
    ) -> Vec<Vector3<f64>> {
        let a = plane_rotation(pose.yaw, pose.roll);
        (0..self.masses.len())
            .map(|k| a * Vector3::new(rates.across.y, -rates.planar[k + 2], rates.across.z))
            .collect()
    }

    /// The rates of the coordinates: the root's centroid's velocity in
    /// the world (m/s), `ψ̇`, `φ̇` and the bodies' `θ̇` (rad/s; the vector's
    /// first two entries zero).
    pub fn coordinate_rates(
        &self,
        pose: &PlanePose<DOF>,
        rates: &PlaneRates<DOF>,
    ) -> (Vector3<f64>, f64, f64, SVector<f64, DOF>) {
        let a = plane_rotation(pose.yaw, pose.roll);
        let [v_eta, w_xi, w_zeta] = [rates.across.x, rates.across.y, rates.across.z];
        let velocity = a * Vector3::new(rates.planar[0], v_eta, rates.planar[1]);
        let turning = w_zeta * pose.roll.tan();
        let mut angles = rates.planar;
        angles[0] = 0.0;
        angles[1] = 0.0;
        for k in 2..DOF {
            angles[k] += turning;
        }
        (velocity, pose.yaw_rate(rates), w_xi, angles)
    }

    /// The kinetic energy, J.
    pub fn kinetic_energy(&self, pose: &PlanePose<DOF>, rates: &PlaneRates<DOF>) -> f64 {
        let plane = self.plane_motion(pose, rates);
        let motion = self.motion(&plane, pose, rates);
        let w = Vector2::new(rates.across.y, rates.across.z);
        (0..self.masses.len())
            .map(|k| {
                let inertia = self.in_plane_inertia(k, motion.trig[k]);
                let spin = rates.planar[k + 2];
                0.5 * self.masses[k] * motion.velocity(k).norm_squared()
                    + 0.5 * self.inertias[k] * spin * spin
                    + 0.5 * w.dot(&(inertia * w))
            })
            .sum()
    }

    /// The mass matrix of the out-of-plane quasi-velocities
    /// `(v_η, ω_ξ, ω_ζ)`, 3 × 3 (its coupling with the in-plane ones
    /// aside, which the offsets make).
    pub fn across_mass(&self, pose: &PlanePose<DOF>) -> Matrix3<f64> {
        let trig: Vec<(f64, f64)> = (0..self.masses.len())
            .map(|k| sin_cos(&pose.planar, k))
            .collect();
        self.across_mass_at(&self.places(pose), &trig)
    }

    /// [`across_mass`](Self::across_mass) from the bodies' places in the
    /// plane and their `(sin θ, cos θ)`.
    fn across_mass_at(&self, places: &[Vector2<f64>], trig: &[(f64, f64)]) -> Matrix3<f64> {
        let mut mass = Matrix3::zeros();
        for (k, p) in places.iter().enumerate() {
            self.add_across_mass(&mut mass, k, *p, &self.in_plane_inertia(k, trig[k]));
        }
        mass
    }

    /// Body `k`'s share of [`across_mass`](Self::across_mass) added to
    /// `mass`, at `place` in the plane with `inertia` about its axes.
    #[inline]
    fn add_across_mass(
        &self,
        mass: &mut Matrix3<f64>,
        k: usize,
        place: Vector2<f64>,
        inertia: &Matrix2<f64>,
    ) {
        let (m, e) = (self.masses[k], self.offsets[k]);
        let c = Vector3::new(1.0, -place.y, place.x);
        *mass += m * c * c.transpose();
        let mut turning = mass.fixed_view_mut::<2, 2>(1, 1);
        turning += inertia + Matrix2::identity() * (m * e * e);
    }

    /// Forward dynamics of the open tree (a track's closing joint cut, as
    /// the planar model's [`tree_dynamics`](RecursiveModel::tree_dynamics)
    /// treats it) under gravity and `loads` (one per body, or none): the
    /// rates of the quasi-velocities, in the plane (the planar `q̈_i`) and
    /// across it.
    pub fn accelerations(
        &self,
        pose: &PlanePose<DOF>,
        rates: &PlaneRates<DOF>,
        loads: &[SpatialLoad],
    ) -> Result<(SVector<f64, DOF>, Vector3<f64>), DynamicsError> {
        self.accelerations_in(&self.plane_motion(pose, rates), pose, rates, loads)
    }

    /// [`accelerations`](Self::accelerations) with the bodies' `motion`
    /// in their plane at `pose` and `rates` found already
    /// ([`plane_motion`](Self::plane_motion)).
    pub fn accelerations_in(
        &self,
        motion: &PlaneMotion,
        pose: &PlanePose<DOF>,
        rates: &PlaneRates<DOF>,
        loads: &[SpatialLoad],
    ) -> Result<(SVector<f64, DOF>, Vector3<f64>), DynamicsError> {
        let model = self.model;
        self.dynamics_with((motion, pose, rates), loads, |trig, planar_loads, qdd| {
            model.tree_dynamics(trig, &rates.planar, planar_loads, qdd)
        })
    }

    /// The forward dynamics with `solve` the planar route: from every
    /// body's `(sin θ, cos θ)` and the planar loads (the plane's inertial
    /// terms included) to `q̈_i`. Both ways it is affine in the loads,
    /// which the offsets' coupling relies on.
    fn dynamics_with(
        &self,
        (plane, pose, rates): (&PlaneMotion, &PlanePose<DOF>, &PlaneRates<DOF>),
        loads: &[SpatialLoad],
        mut solve: impl FnMut(
            &[(f64, f64)],
            &[BodyLoad],
            &mut SVector<f64, DOF>,
        ) -> Result<(), DynamicsError>,
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
        let motion = self.motion(plane, pose, rates);
        let [w_xi, w_zeta] = [rates.across.y, rates.across.z];
        let w_eta = w_zeta * pose.roll.tan();
        let omega = Vector3::new(w_xi, w_eta, w_zeta);
        // The plane's gravity: (0, −g sin φ, −g cos φ); the planar code
        // applies (0, −g) in the plane already.
        let (g_across, g_in) = (-self.gravity * sr, -self.gravity * cr);
        let mut planar_loads = vec![BodyLoad::ZERO; n];
        let mut rhs = Vector3::zeros();
        let mut mass = Matrix3::zeros();
        for (k, planar_load) in planar_loads.iter_mut().enumerate() {
            let (m, e) = (self.masses[k], self.offsets[k]);
            let load = loads.get(k).copied().unwrap_or_default();
            let (force, moment) = (a.transpose() * load.force, a.transpose() * load.moment);
            let place = motion.place[k];
            let omega_v = omega.cross(&motion.velocity(k));
            // The bodies' true angular rates turn the relative place:
            // d/dt (ξ, ζ) = relative velocity + ω_η perp(place).
            let moving = motion.relative(k) + w_eta * perp(place);
            // In the plane: the cross term of the bodies' true and
            // relative rates, ω_η perp(ρ̇ relative), and ω × V.
            let bias_in = w_eta * perp(motion.relative(k)) + Vector2::new(omega_v.x, omega_v.z);
            let bias_across = w_zeta * moving.x - w_xi * moving.y + omega_v.y;
            // Rotation: H = (I₂ (ω_ξ, ω_ζ), −J (θ̇ − ω_η)).
            let trig = motion.trig[k];
            let inertia = self.in_plane_inertia(k, trig);
            self.add_across_mass(&mut mass, k, place, &inertia);
            let spin = rates.planar[k + 2];
            let turning = inertia_rate(&inertia, spin + w_eta);
            let h2 = inertia * Vector2::new(w_xi, w_zeta);
            let h = Vector3::new(h2.x, -self.inertias[k] * spin, h2.y);
            let omega_h = omega.cross(&h);
            let bias_turn =
                turning * Vector2::new(w_xi, w_zeta) + Vector2::new(omega_h.x, omega_h.z);
            let in_plane = Vector2::new(force.x, force.z) - m * bias_in;
            *planar_load = BodyLoad {
                force: in_plane + m * Vector2::new(0.0, g_in + self.gravity),
                moment: -moment.y + omega_h.y,
            };
            let c = Vector3::new(1.0, -place.y, place.x);
            rhs += c * (force.y + m * g_across - m * bias_across);
            rhs += Vector3::new(0.0, moment.x - bias_turn.x, moment.z - bias_turn.y);
            // An offset body's in-plane forces act on the plane's turning,
            // less its in-plane inertia besides `H q̈_i` and `e D ẇ` (which
            // the coupling and the mass matrix carry): the planar chain's
            // own centripetal terms γ.
            if e != 0.0 {
                rhs +=
                    e * offset_force(in_plane + m * Vector2::new(0.0, g_in) - m * motion.gamma[k]);
            }
        }
        let mut planar = SVector::<f64, DOF>::zeros();
        solve(motion.trig, &planar_loads, &mut planar)?;
        if self.offsets.iter().all(|&e| e == 0.0) {
            let across = mass
                .cholesky()
                .ok_or(DynamicsError::MassMatrixNotPositiveDefinite)?
                .solve(&rhs);
            return Ok((planar, across));
        }
        // The offsets couple the two sets through C (DOF × 3), the
        // in-plane load `−m e D ẇ` on each body. With the in-plane rates
        // a + A ẇ (A's columns by the planar route under C's columns:
        // v_η's is zero), the out-of-plane equations become
        // (M_w − Cᵀ M_i⁻¹ C) ẇ = f_w − Cᵀ a.
        rhs -= self.coupling_transpose(&pose.planar, &planar);
        let mut columns = [SVector::<f64, DOF>::zeros(); 3];
        for (j, column) in columns.iter_mut().enumerate().skip(1) {
            let d = offset_velocity(&Vector3::ith(j, 1.0));
            let shifted: Vec<BodyLoad> = planar_loads
                .iter()
                .enumerate()
                .map(|(k, l)| BodyLoad {
                    force: l.force - self.masses[k] * self.offsets[k] * d,
                    moment: l.moment,
                })
                .collect();
            let mut moved = SVector::<f64, DOF>::zeros();
            solve(motion.trig, &shifted, &mut moved)?;
            *column = moved - planar;
            let coupled = mass.column(j) + self.coupling_transpose(&pose.planar, column);
            mass.set_column(j, &coupled);
        }
        let across = mass
            .lu()
            .solve(&rhs)
            .ok_or(DynamicsError::MassMatrixNotPositiveDefinite)?;
        let planar = planar + columns[1] * across[1] + columns[2] * across[2];
        Ok((planar, across))
    }

    /// [`accelerations`](Self::accelerations) of a track with its loop
    /// joint `closing` as the planar linear-time route takes it
    /// ([`TrackModel::linear_time_dynamics`]): closed (the plain
    /// constraint, or stabilised), or cut with a force across it. The
    /// plane's turning about its normal moves every angle alike, which
    /// leaves a closed loop closed: on the loop's manifold (`C = 0`,
    /// `C_θ θ̇ = 0`) the planar constraint holds in the relative rates
    /// unchanged, so the planar route closes the floating loop as it is.
    pub fn closed_accelerations(
        &self,
        pose: &PlanePose<DOF>,
        rates: &PlaneRates<DOF>,
        loads: &[SpatialLoad],
        closing: ClosingJoint,
    ) -> Result<(SVector<f64, DOF>, Vector3<f64>), DynamicsError>
    where
        M: TrackModel<DOF>,
    {
        let motion = self.plane_motion(pose, rates);
        let mut forces = vec![Vector2::zeros(); self.masses.len()];
        self.closed_accelerations_in(&motion, (pose, rates), loads, closing, &mut forces)
    }

    /// [`closed_accelerations`](Self::closed_accelerations) with the
    /// bodies' `motion` in their plane found already
    /// ([`plane_motion`](Self::plane_motion)), every joint's force written
    /// to `joint_forces` (one per link, N, the plane's `(ξ, ζ)` axes; as
    /// [`TrackModel::linear_time_dynamics`] writes them: the force link
    /// `j + 2` exerts on link `j + 1`, links numbered from 1, the last the
    /// closing joint's). A track's links lie in its plane (no offsets), so
    /// one planar solve gives them: the forces of the motion found.
    ///
    /// # Panics
    /// If `joint_forces` is not one per link (a programming error).
    pub fn closed_accelerations_in(
        &self,
        motion: &PlaneMotion,
        (pose, rates): (&PlanePose<DOF>, &PlaneRates<DOF>),
        loads: &[SpatialLoad],
        closing: ClosingJoint,
        joint_forces: &mut [Vector2<f64>],
    ) -> Result<(SVector<f64, DOF>, Vector3<f64>), DynamicsError>
    where
        M: TrackModel<DOF>,
    {
        debug_assert!(
            self.offsets.iter().all(|&e| e == 0.0),
            "a track's links lie in its plane: one planar solve gives the joint forces"
        );
        let model = self.model;
        self.dynamics_with((motion, pose, rates), loads, |trig, planar_loads, qdd| {
            model.linear_time_dynamics(
                trig,
                &rates.planar,
                planar_loads,
                closing,
                qdd,
                joint_forces,
            )
        })
    }

    /// `Cᵀ x`: the in-plane accelerations `H x` of the offset bodies
    /// weighed by `m e` onto the out-of-plane quasi-velocities.
    fn coupling_transpose(&self, q: &SVector<f64, DOF>, x: &SVector<f64, DOF>) -> Vector3<f64> {
        let mut moved = vec![Vector2::zeros(); self.masses.len()];
        self.model.body_velocities(&at_origin(q), x, &mut moved);
        moved
            .iter()
            .enumerate()
            .map(|(k, a)| self.masses[k] * self.offsets[k] * offset_force(*a))
            .sum()
    }

    /// Every body's centroid relative to the root in the plane, `(ξ, ζ)`,
    /// m.
    fn places(&self, pose: &PlanePose<DOF>) -> Vec<Vector2<f64>> {
        let mut out = vec![Vector2::zeros(); self.masses.len()];
        self.model
            .body_positions(&at_origin(&pose.planar), &mut out);
        out
    }

    /// What the bodies' motion in their plane (`plane`, at `pose` and
    /// `rates`) gives.
    fn motion<'p>(
        &'p self,
        plane: &'p PlaneMotion,
        pose: &PlanePose<DOF>,
        rates: &PlaneRates<DOF>,
    ) -> BodyMotion<'p> {
        let mut gamma = Vec::new();
        if self.offsets.iter().any(|&e| e != 0.0) {
            gamma.resize(self.masses.len(), Vector2::zeros());
            self.model
                .velocity_terms(&at_origin(&pose.planar), &rates.planar, &mut gamma);
        }
        BodyMotion {
            place: &plane.place,
            planar: &plane.planar,
            root: Vector2::new(rates.planar[0], rates.planar[1]),
            across: rates.across,
            offsets: &self.offsets,
            gamma,
            trig: &plane.trig,
        }
    }

    /// Body `k`'s inertia about the plane's `ξ` and `ζ` axes, its own
    /// turned by its angle: `A(θ) I_b A(θ)ᵀ`, multiplied out.
    #[inline]
    fn in_plane_inertia(&self, k: usize, (s, c): (f64, f64)) -> Matrix2<f64> {
        let i = self.across[k];
        let (cc, ss, cs) = (c * c, s * s, c * s);
        let xz = cs * (i.xx - i.zz) + (cc - ss) * i.xz;
        Matrix2::new(
            cc * i.xx - 2.0 * cs * i.xz + ss * i.zz,
            xz,
            xz,
            ss * i.xx + 2.0 * cs * i.xz + cc * i.zz,
        )
    }
}

/// The rate of a body's in-plane inertia `I = A(θ) I_b A(θ)ᵀ` when it
/// turns at `rate` (rad/s) in the plane: `θ̇ dI/dθ`, whose entries are
/// `I`'s own, `dI₁₁/dθ = −2 I₁₂`, `dI₁₂/dθ = I₁₁ − I₂₂`,
/// `dI₂₂/dθ = 2 I₁₂`.
#[inline]
fn inertia_rate(inertia: &Matrix2<f64>, rate: f64) -> Matrix2<f64> {
    let (xx, xz, zz) = (inertia[(0, 0)], inertia[(0, 1)], inertia[(1, 1)]);
    let apart = xx - zz;
    rate * Matrix2::new(-2.0 * xz, apart, apart, 2.0 * xz)
}

/// `q_i` with the root at the plane's origin.
fn at_origin<const DOF: usize>(q: &SVector<f64, DOF>) -> SVector<f64, DOF> {
    let mut q = *q;
    q[0] = 0.0;
    q[1] = 0.0;
    q
}

/// Body `k`'s `(sin θ, cos θ)`: the project's sine and cosine, the same
/// bits as [`FloatingTree::plane_motion`]'s.
fn sin_cos<const DOF: usize>(q: &SVector<f64, DOF>, k: usize) -> (f64, f64) {
    crate::trig::sin_cos(q[k + 2])
}

/// A plane vector turned a quarter counter-clockwise (from `ξ` toward
/// `ζ`).
fn perp(v: Vector2<f64>) -> Vector2<f64> {
    Vector2::new(-v.y, v.x)
}
