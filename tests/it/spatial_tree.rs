//! The floating tree (`trackgen::spatial`: a track's chain, a hull with
//! its running gear off its plane) against a dense route written apart
//! from it: each body's pose from the coordinates
//! `q = [r¹ (3), ψ, φ, θ¹ … θⁿ]` by plain rotation matrices and the
//! planar description's joint points (not the generated code), its
//! Jacobians and bias accelerations by second-order Taylor arithmetic
//! along `q̇`, `M = Σ m J_rᵀ J_r + J_ωᵀ I J_ω` and Newton–Euler's
//! right-hand side (`F − m J̇_r q̇`, `τ − I J̇_ω q̇ − ω × I ω`) summed and
//! solved densely in the coordinates' own rates `q̈`. The route's
//! quasi-velocity rates are taken to `q̈` through the kinematic map
//! differentiated the same way.

use trackgen::multibody::{RecursiveModel, TreeDescription};
use trackgen::nalgebra::{DMatrix, DVector, Matrix3, SVector, Vector3};
use trackgen::spatial::{FloatingTree, OutOfPlaneInertia, PlanePose, PlaneRates, SpatialLoad};
use trackgen::vehicles::m113::M113Chassis;

trackgen::model! {
    /// 3 links, open, each its own.
    pub track Open3 {
        links: 3,
        link { mass: 24.0, inertia: 0.12, u1: (-0.08, 0.01), u2: (0.07, -0.02) },
        link[2] { mass: 11.5, inertia: 0.21, u1: (-0.06, 0.03) },
        link[3] { mass: 30.2, inertia: 0.09, u2: (0.11, 0.04) },
        closure: open,
    }
    /// 10 links, open, not all alike.
    pub track Open10 {
        links: 10,
        link { mass: 9.7, inertia: 0.27, u1: (-0.08, -0.09), u2: (0.10, 0.14) },
        link[2..=10 by 2] { mass: 16.1, inertia: 0.41 },
        link[3..=9 by 3] { u1: (-0.04, -0.06), u2: (0.07, 0.12) },
        closure: open,
    }
    /// 128 links, open, not all alike: the largest chain the spatial
    /// check asks for.
    pub track Open128 {
        links: 128,
        link { mass: 18.02, inertia: 0.04, u1: (-0.077, 0.0), u2: (0.077, 0.0) },
        link[1..=128 by 3] { mass: 20.5, inertia: 0.05 },
        link[2..=127 by 5] { u1: (-0.08, 0.004), u2: (0.075, -0.002) },
        closure: open,
    }
}

/// A truncated Taylor series `v + d t + h t²` along a path `q + q̇ t`.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Jet {
    v: f64,
    d: f64,
    h: f64,
}

impl Jet {
    fn constant(v: f64) -> Jet {
        Jet { v, d: 0.0, h: 0.0 }
    }
    fn sin(self) -> Jet {
        let (s, c) = self.v.sin_cos();
        Jet {
            v: s,
            d: c * self.d,
            h: c * self.h - 0.5 * s * self.d * self.d,
        }
    }
    fn cos(self) -> Jet {
        let (s, c) = self.v.sin_cos();
        Jet {
            v: c,
            d: -s * self.d,
            h: -s * self.h - 0.5 * c * self.d * self.d,
        }
    }
}

impl std::ops::Add for Jet {
    type Output = Jet;
    fn add(self, o: Jet) -> Jet {
        Jet {
            v: self.v + o.v,
            d: self.d + o.d,
            h: self.h + o.h,
        }
    }
}

impl std::ops::Sub for Jet {
    type Output = Jet;
    fn sub(self, o: Jet) -> Jet {
        Jet {
            v: self.v - o.v,
            d: self.d - o.d,
            h: self.h - o.h,
        }
    }
}

impl std::ops::Mul for Jet {
    type Output = Jet;
    fn mul(self, o: Jet) -> Jet {
        Jet {
            v: self.v * o.v,
            d: self.v * o.d + self.d * o.v,
            h: self.v * o.h + self.d * o.d + self.h * o.v,
        }
    }
}

impl std::ops::Div for Jet {
    type Output = Jet;
    fn div(self, o: Jet) -> Jet {
        let inv_v = 1.0 / o.v;
        let inv = Jet {
            v: inv_v,
            d: -o.d * inv_v * inv_v,
            h: (o.d * o.d * inv_v - o.h) * inv_v * inv_v,
        };
        self * inv
    }
}

type Mat = [[Jet; 3]; 3];
type Vec3 = [Jet; 3];

fn mat_mul(a: &Mat, b: &Mat) -> Mat {
    let mut out = [[Jet::constant(0.0); 3]; 3];
    for i in 0..3 {
        for j in 0..3 {
            for k in 0..3 {
                out[i][j] = out[i][j] + a[i][k] * b[k][j];
            }
        }
    }
    out
}

fn mat_vec(a: &Mat, x: &Vec3) -> Vec3 {
    let mut out = [Jet::constant(0.0); 3];
    for i in 0..3 {
        for k in 0..3 {
            out[i] = out[i] + a[i][k] * x[k];
        }
    }
    out
}

/// `R_z(ψ) R_x(φ)`, written out from the two elementary rotations.
fn plane(yaw: Jet, roll: Jet) -> Mat {
    let (zero, one) = (Jet::constant(0.0), Jet::constant(1.0));
    let (sy, cy, sr, cr) = (yaw.sin(), yaw.cos(), roll.sin(), roll.cos());
    let rz = [[cy, zero - sy, zero], [sy, cy, zero], [zero, zero, one]];
    let rx = [[one, zero, zero], [zero, cr, zero - sr], [zero, sr, cr]];
    mat_mul(&rz, &rx)
}

/// A link's orientation in the plane: its `x` to `(cos θ, 0, sin θ)`, its
/// `z` to `(−sin θ, 0, cos θ)`, `y` kept.
fn pitch(theta: Jet) -> Mat {
    let (zero, one) = (Jet::constant(0.0), Jet::constant(1.0));
    let (s, c) = (theta.sin(), theta.cos());
    [[c, zero, zero - s], [zero, one, zero], [s, zero, c]]
}

/// Every link's centroid and orientation in the world along the path
/// `q + q̇ t`, from the description's joint points.
fn poses(description: &TreeDescription, offsets: &[f64], q: &[Jet]) -> Vec<(Vec3, Mat)> {
    let a = plane(q[3], q[4]);
    let bodies = &description.bodies;
    let mut places: Vec<[Jet; 2]> = Vec::with_capacity(bodies.len());
    let turn = |theta: Jet, p: (f64, f64)| {
        let (s, c) = (theta.sin(), theta.cos());
        let (x, z) = (Jet::constant(p.0), Jet::constant(p.1));
        [c * x - s * z, s * x + c * z]
    };
    for (b, body) in bodies.iter().enumerate() {
        let place = match body.parent {
            None => [Jet::constant(0.0); 2],
            Some(p) => {
                let up = turn(q[5 + p], (body.at_parent.x, body.at_parent.y));
                let own = turn(q[5 + b], (body.at_self.x, body.at_self.y));
                [places[p][0] + up[0] - own[0], places[p][1] + up[1] - own[1]]
            }
        };
        places.push(place);
    }
    places
        .iter()
        .enumerate()
        .map(|(b, p)| {
            let local = mat_vec(&a, &[p[0], Jet::constant(offsets[b]), p[1]]);
            let at = [q[0] + local[0], q[1] + local[1], q[2] + local[2]];
            (at, mat_mul(&a, &pitch(q[5 + b])))
        })
        .collect()
}

fn jets(q: &DVector<f64>, qd: &DVector<f64>) -> Vec<Jet> {
    q.iter()
        .zip(qd.iter())
        .map(|(&v, &d)| Jet { v, d, h: 0.0 })
        .collect()
}

fn part(m: &Mat, f: impl Fn(&Jet) -> f64) -> Matrix3<f64> {
    Matrix3::from_fn(|i, j| f(&m[i][j]))
}

fn vee(m: &Matrix3<f64>) -> Vector3<f64> {
    Vector3::new(m[(2, 1)], m[(0, 2)], m[(1, 0)])
}

fn skew(w: &Vector3<f64>) -> Matrix3<f64> {
    Matrix3::new(0.0, -w.z, w.y, w.z, 0.0, -w.x, -w.y, w.x, 0.0)
}

/// The dense route: `q̈`, the kinetic energy `½ q̇ᵀ M q̇`, `M` and the
/// right-hand side.
fn dense(
    description: &TreeDescription,
    offsets: &[f64],
    across: &[OutOfPlaneInertia],
    q: &DVector<f64>,
    qd: &DVector<f64>,
    loads: &[SpatialLoad],
) -> (DVector<f64>, f64, DMatrix<f64>, DVector<f64>) {
    let n = description.bodies.len();
    let dof = n + 5;
    let g = Vector3::new(0.0, 0.0, description.gravity.y);
    let inertia = |b: usize| {
        let (i, body) = (across[b], &description.bodies[b]);
        Matrix3::new(i.xx, 0.0, i.xz, 0.0, body.inertia, 0.0, i.xz, 0.0, i.zz)
    };
    // Jacobians: one column per coordinate.
    let mut jr = vec![DMatrix::<f64>::zeros(3, dof); n];
    let mut jw = vec![DMatrix::<f64>::zeros(3, dof); n];
    for j in 0..dof {
        let unit = DVector::from_fn(dof, |i, _| if i == j { 1.0 } else { 0.0 });
        for (b, (at, rot)) in poses(description, offsets, &jets(q, &unit))
            .iter()
            .enumerate()
        {
            let (r, rd) = (part(rot, |x| x.v), part(rot, |x| x.d));
            jr[b].set_column(j, &Vector3::new(at[0].d, at[1].d, at[2].d));
            jw[b].set_column(j, &vee(&(rd * r.transpose())));
        }
    }
    let mut mass = DMatrix::<f64>::zeros(dof, dof);
    let mut rhs = DVector::<f64>::zeros(dof);
    for (b, (at, rot)) in poses(description, offsets, &jets(q, qd)).iter().enumerate() {
        let m = description.bodies[b].mass;
        let (r, rd, rdd) = (
            part(rot, |x| x.v),
            part(rot, |x| x.d),
            part(rot, |x| 2.0 * x.h),
        );
        let world = r * inertia(b) * r.transpose();
        let w = vee(&(rd * r.transpose()));
        let w_bias = vee(&((rdd - skew(&w) * rd) * r.transpose()));
        let a_bias = Vector3::new(2.0 * at[0].h, 2.0 * at[1].h, 2.0 * at[2].h);
        mass += m * jr[b].transpose() * &jr[b] + jw[b].transpose() * world * &jw[b];
        let load = loads.get(b).copied().unwrap_or_default();
        let force = load.force + m * g - m * a_bias;
        let moment = load.moment - world * w_bias - w.cross(&(world * w));
        rhs += jr[b].transpose() * force + jw[b].transpose() * moment;
    }
    let energy = 0.5 * qd.dot(&(&mass * qd));
    let qdd = mass
        .clone()
        .lu()
        .solve(&rhs)
        .expect("a positive definite mass matrix");
    (qdd, energy, mass, rhs)
}

/// The kinematic map `q̇ = K(q) u`, along the path `q + q̇ t` (its `d`
/// part is `(∂K/∂q q̇) u`).
fn coordinate_rates(q: &[Jet], u_in: &[f64], across: &Vector3<f64>) -> Vec<Jet> {
    let n = u_in.len() - 2;
    let a = plane(q[3], q[4]);
    let c = |v| Jet::constant(v);
    let v = mat_vec(&a, &[c(u_in[0]), c(across.x), c(u_in[1])]);
    let (sr, cr) = (q[4].sin(), q[4].cos());
    let mut out = vec![v[0], v[1], v[2], c(across.z) / cr, c(across.y)];
    for k in 0..n {
        out.push(c(u_in[2 + k]) + c(across.z) * sr / cr);
    }
    out
}

/// A state of `links` links and loads on them, from a small generator
/// (the same numbers on every machine).
fn state<const DOF: usize>(
    links: usize,
    seed: u64,
) -> (
    PlanePose<DOF>,
    PlaneRates<DOF>,
    Vec<SpatialLoad>,
    Vec<OutOfPlaneInertia>,
) {
    let mut x = seed;
    let mut next = move || {
        x ^= x << 13;
        x ^= x >> 7;
        x ^= x << 17;
        (x >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
    };
    let mut planar = SVector::<f64, DOF>::zeros();
    let mut rates = SVector::<f64, DOF>::zeros();
    for k in 0..links {
        planar[k + 2] = 3.0 * next();
        rates[k + 2] = 2.0 * next();
    }
    rates[0] = 3.0 * next();
    rates[1] = next();
    let pose = PlanePose {
        origin: Vector3::new(40.0 * next(), 5.0 * next(), next()),
        yaw: 3.0 * next(),
        roll: 0.6 * next(),
        planar,
    };
    let rates = PlaneRates {
        planar: rates,
        across: Vector3::new(next(), 0.5 * next(), 0.8 * next()),
    };
    let loads = (0..links)
        .map(|_| SpatialLoad {
            force: 300.0 * Vector3::new(next(), next(), next()),
            moment: 20.0 * Vector3::new(next(), next(), next()),
        })
        .collect();
    let across = (0..links)
        .map(|_| OutOfPlaneInertia {
            xx: 0.2 + 0.1 * next(),
            zz: 0.3 + 0.1 * next(),
            xz: 0.02 * next(),
        })
        .collect();
    (pose, rates, loads, across)
}

/// The coordinates `q`, their rates `q̇` and the route's `q̈ = K u̇ +
/// (∂K/∂q q̇) u` from a pose, its quasi-velocities and their rates.
fn in_coordinates<const DOF: usize>(
    pose: &PlanePose<DOF>,
    rates: &PlaneRates<DOF>,
    (u_in, w): (&SVector<f64, DOF>, &Vector3<f64>),
) -> (DVector<f64>, DVector<f64>, DVector<f64>) {
    let links = DOF - 2;
    let mut q = DVector::zeros(links + 5);
    q.rows_mut(0, 3).copy_from(&pose.origin);
    q[3] = pose.yaw;
    q[4] = pose.roll;
    for k in 0..links {
        q[5 + k] = pose.planar[k + 2];
    }
    let still: Vec<Jet> = q.iter().map(|&v| Jet::constant(v)).collect();
    let qd = DVector::from_iterator(
        links + 5,
        coordinate_rates(&still, rates.planar.as_slice(), &rates.across)
            .iter()
            .map(|j| j.v),
    );
    let moving = coordinate_rates(&jets(&q, &qd), rates.planar.as_slice(), &rates.across);
    let pushed = coordinate_rates(&still, u_in.as_slice(), w);
    let route = DVector::from_iterator(
        links + 5,
        moving.iter().zip(&pushed).map(|(m, p)| m.d + p.v),
    );
    (q, qd, route)
}

/// The route's `q̈`, the dense route's, and both kinetic energies, at one
/// state of `model`.
fn both<M: RecursiveModel<DOF>, const DOF: usize>(
    model: &M,
    offsets: &[f64],
    seed: u64,
) -> (f64, f64, f64) {
    let links = DOF - 2;
    let (pose, rates, loads, across) = state::<DOF>(links, seed);
    let chain = FloatingTree::new(model, across.clone())
        .unwrap()
        .with_offsets(offsets.to_vec())
        .unwrap();
    let (u_in, w) = chain.accelerations(&pose, &rates, &loads).unwrap();
    let (q, qd, route) = in_coordinates(&pose, &rates, (&u_in, &w));
    // The route's own map agrees with the written-out one.
    let (velocity, yaw_rate, roll_rate, angles) = chain.coordinate_rates(&pose, &rates);
    assert!((velocity - qd.rows(0, 3)).amax() < 1e-12 * (1.0 + velocity.amax()));
    assert!((yaw_rate - qd[3]).abs() < 1e-12 && (roll_rate - qd[4]).abs() < 1e-12);
    for k in 0..links {
        assert!((angles[k + 2] - qd[5 + k]).abs() < 1e-12);
    }
    let (oracle, energy, _, _) = dense(&model.description(), offsets, &across, &q, &qd, &loads);
    let error = (&route - &oracle).norm() / oracle.norm();
    let energy_route = chain.kinetic_energy(&pose, &rates);
    (error, (energy_route - energy).abs() / energy, oracle.norm())
}

#[test]
fn the_floating_chain_equals_the_dense_spatial_route() {
    // Norm-wise relative, over five states each of 3, 10 and 128 links
    // in one plane: the accelerations to 1e-10 (the dense LU's rounding
    // grows with the mass matrix's condition number, ~n² for a chain:
    // measured 1e-15 at 3 and 10 links, 0.8–1.5e-12 at 128), the kinetic
    // energy to 1e-12 (measured 3e-15). Leaving out one inertial term the
    // plane's motion adds (the cross term of the links' true and relative
    // rates, or the links' inertia turning at their true rate) is off by
    // 2e-3 and 3e-4 at 3 links.
    for seed in 1..=5 {
        for (links, (error, energy, size)) in [
            (3, both(&Open3, &[0.0; 3], seed)),
            (10, both(&Open10, &[0.0; 10], seed)),
            (128, both(&Open128, &[0.0; 128], seed)),
        ] {
            assert!(size > 1.0, "a state that moves: |q̈| {size}");
            assert!(
                error < 1e-10,
                "{links} links, seed {seed}: q̈ off by {error:e}"
            );
            assert!(
                energy < 1e-12,
                "{links} links, seed {seed}: energy off by {energy:e}"
            );
        }
    }
}

/// The offsets of the M113's chassis with every part half a gauge to the
/// left of the hull's plane, and of a 10-link chain scattered across its
/// plane.
fn off_the_plane() -> (Vec<f64>, Vec<f64>) {
    let parts = M113Chassis.description().bodies.len();
    let mut left = vec![1.08; parts];
    left[0] = 0.0;
    (left, (0..10).map(|k| 0.3 * (k as f64 - 4.5)).collect())
}

#[test]
fn a_hull_with_its_running_gear_off_its_plane_equals_the_dense_route() {
    // The M113's chassis (hull, sprocket, arms, wheels, tensioner, idler)
    // with every part half a gauge to the left of the hull's plane, and a
    // 10-link chain with every link at its own offset: the offsets couple
    // the in-plane and out-of-plane rates (the Schur complement through
    // the planar route). The same bounds as in one plane (measured
    // 2–5e-15 and up to 1.3e-14); without the planar centripetal terms in
    // the offset bodies' share of the out-of-plane equations the
    // accelerations were off by 5e-2 to 2e-1.
    let (left, scattered) = off_the_plane();
    for seed in 1..=5 {
        for (what, (error, energy, size)) in [
            ("the M113's chassis", both(&M113Chassis, &left, seed)),
            ("a chain off its plane", both(&Open10, &scattered, seed)),
        ] {
            assert!(size > 1.0, "{what}: |q̈| {size}");
            assert!(error < 1e-10, "{what}, seed {seed}: q̈ off by {error:e}");
            assert!(
                energy < 1e-12,
                "{what}, seed {seed}: energy off by {energy:e}"
            );
        }
    }
}

#[test]
fn a_tree_without_its_inertias_or_offsets_or_with_bad_ones_is_refused() {
    use trackgen::spatial::SpatialError;
    let plate = OutOfPlaneInertia::plate(18.0, 0.154, 0.38, 0.06);
    assert!(matches!(
        FloatingTree::new(&Open3, vec![plate; 2]),
        Err(SpatialError::Inertias {
            bodies: 3,
            given: 2
        })
    ));
    let flat = OutOfPlaneInertia {
        xx: 0.1,
        zz: 0.1,
        xz: 0.2,
    };
    assert!(matches!(
        FloatingTree::new(&Open3, vec![plate, flat, plate]),
        Err(SpatialError::Inertia { body: 1, .. })
    ));
    let nan = OutOfPlaneInertia {
        xx: f64::NAN,
        ..plate
    };
    assert!(FloatingTree::new(&Open3, vec![nan, plate, plate]).is_err());
    let tree = FloatingTree::new(&Open3, vec![plate; 3]).unwrap();
    assert!(matches!(
        tree.with_offsets(vec![0.0, f64::INFINITY, 0.0]),
        Err(SpatialError::Offset { body: 1, .. })
    ));
    let tree = FloatingTree::new(&Open3, vec![plate; 3]).unwrap();
    assert!(matches!(
        tree.with_offsets(vec![0.0; 4]),
        Err(SpatialError::Offsets {
            bodies: 3,
            given: 4
        })
    ));
}

/// The coordinates' rates and the quasi-velocities' rates.
type Derivative<const DOF: usize> = (
    (Vector3<f64>, f64, f64, SVector<f64, DOF>),
    (SVector<f64, DOF>, Vector3<f64>),
);

/// One classic RK4 step of the floating tree under gravity alone, in its
/// coordinates and quasi-velocities.
fn rk4_step<M: RecursiveModel<DOF>, const DOF: usize>(
    tree: &FloatingTree<M, DOF>,
    pose: &PlanePose<DOF>,
    rates: &PlaneRates<DOF>,
    h: f64,
) -> (PlanePose<DOF>, PlaneRates<DOF>) {
    let derivative = |p: &PlanePose<DOF>, r: &PlaneRates<DOF>| {
        let (velocity, yaw, roll, angles) = tree.coordinate_rates(p, r);
        let (planar, across) = tree.accelerations(p, r, &[]).unwrap();
        ((velocity, yaw, roll, angles), (planar, across))
    };
    let advance = |p: &PlanePose<DOF>, r: &PlaneRates<DOF>, d: &Derivative<DOF>, s: f64| {
        let ((velocity, yaw, roll, angles), (planar, across)) = d;
        (
            PlanePose {
                origin: p.origin + s * velocity,
                yaw: p.yaw + s * yaw,
                roll: p.roll + s * roll,
                planar: p.planar + s * angles,
            },
            PlaneRates {
                planar: r.planar + s * planar,
                across: r.across + s * across,
            },
        )
    };
    let k1 = derivative(pose, rates);
    let (p2, r2) = advance(pose, rates, &k1, 0.5 * h);
    let k2 = derivative(&p2, &r2);
    let (p3, r3) = advance(pose, rates, &k2, 0.5 * h);
    let k3 = derivative(&p3, &r3);
    let (p4, r4) = advance(pose, rates, &k3, h);
    let k4 = derivative(&p4, &r4);
    let mut next = (pose.clone(), rates.clone());
    for (k, w) in [(&k1, 1.0), (&k2, 2.0), (&k3, 2.0), (&k4, 1.0)] {
        next = advance(&next.0, &next.1, k, w * h / 6.0);
    }
    next
}

/// Energy, linear momentum and angular momentum about the centre of
/// mass, from the tree's world velocities, orientations and inertias.
fn invariants<M: RecursiveModel<DOF>, const DOF: usize>(
    model: &M,
    tree: &FloatingTree<M, DOF>,
    pose: &PlanePose<DOF>,
    rates: &PlaneRates<DOF>,
) -> (f64, Vector3<f64>, Vector3<f64>) {
    let masses: Vec<f64> = model.description().bodies.iter().map(|b| b.mass).collect();
    let g = -model.description().gravity.y;
    let (at, v) = (tree.positions(pose), tree.velocities(pose, rates));
    let (turn, w) = (
        tree.orientations(pose),
        tree.angular_velocities(pose, rates),
    );
    let inertia = tree.body_inertias();
    let total: f64 = masses.iter().sum();
    let centre = at
        .iter()
        .zip(&masses)
        .map(|(r, m)| *m * r)
        .sum::<Vector3<f64>>()
        / total;
    let energy = tree.kinetic_energy(pose, rates)
        + at.iter()
            .zip(&masses)
            .map(|(r, m)| m * g * r.z)
            .sum::<f64>();
    let momentum = v.iter().zip(&masses).map(|(v, m)| *m * v).sum();
    let spin = (0..masses.len())
        .map(|k| {
            masses[k] * (at[k] - centre).cross(&v[k])
                + turn[k] * inertia[k] * turn[k].transpose() * w[k]
        })
        .sum();
    (energy, momentum, spin)
}

#[test]
fn a_floating_tree_under_gravity_keeps_its_energy_and_momenta() {
    // Tumbling freely for 0.5 s (RK4 at 0.1 ms), the M113's chassis with
    // its parts half a gauge to the left and a 10-link chain scattered
    // across its plane keep their energy, their horizontal momentum and
    // their angular momentum about the centre of mass (gravity has no
    // moment there), each relative, to 1e-10 (measured 1e-14 to 7e-14:
    // RK4's error at this step and the rounding). Leaving the planar
    // centripetal terms out of the offset parts' share breaks the energy
    // by 9e-6 and the angular momentum by 6e-3.
    let (left, scattered) = off_the_plane();
    fn run<M: RecursiveModel<DOF>, const DOF: usize>(model: &M, offsets: &[f64]) -> [f64; 3] {
        let (mut pose, mut rates, _, across) = state::<DOF>(DOF - 2, 7);
        let tree = FloatingTree::new(model, across)
            .unwrap()
            .with_offsets(offsets.to_vec())
            .unwrap();
        let (e0, p0, l0) = invariants(model, &tree, &pose, &rates);
        for _ in 0..5000 {
            (pose, rates) = rk4_step(&tree, &pose, &rates, 1e-4);
        }
        let (e1, p1, l1) = invariants(model, &tree, &pose, &rates);
        let kinetic = tree.kinetic_energy(&pose, &rates);
        [
            (e1 - e0).abs() / kinetic,
            (p1.xy() - p0.xy()).norm() / p0.norm(),
            (l1 - l0).norm() / l0.norm(),
        ]
    }
    for (what, drift) in [
        ("the M113's chassis", run(&M113Chassis, &left)),
        ("a scattered chain", run(&Open10, &scattered)),
    ] {
        eprintln!("{what}: {drift:?}");
        assert!(drift[0] < 1e-7, "{what}: energy drifts by {:e}", drift[0]);
        assert!(
            drift[1] < 1e-12,
            "{what}: horizontal momentum by {:e}",
            drift[1]
        );
        assert!(
            drift[2] < 1e-7,
            "{what}: angular momentum by {:e}",
            drift[2]
        );
    }
}

trackgen::model! {
    /// 24 M113-like shoes closed by a stiff spring (no damping): a track
    /// loop that can float.
    pub track Loop24 {
        links: 24,
        link { mass: 18.02, inertia: 0.04, u1: (-0.077, 0.0), u2: (0.077, 0.0) },
        closure: penalty { stiffness: 1e7, damping: 0.0 },
    }
}

#[test]
fn a_track_loop_dropped_in_space_keeps_its_books() {
    // A loop of 24 shoes, rolled 0.3 rad and turning, dropped 0.1 m onto
    // a 20 % side slope: each shoe's two edges (±0.19 m across, 3 cm
    // below its centroid) meet the ground through `contact::space`
    // (Hunt-Crossley 2e6 N/m, χ = 2 s/m; regularised Coulomb, μ 0.8 over
    // 0.05 m/s), the loop closed by its spring, under gravity, for 0.4 s
    // by RK4 at 20 µs. Kinetic energy, gravity's and the springs' (the
    // closing joint's and the contacts') plus the power the contacts
    // dissipated, integrated alongside, stay the energy it started with,
    // to 1e-5 of the energy the drop and the spin bring (measured 3e-7,
    // 1.6e-4 J of 510 J, while the contacts took 1 008 J as it slid down
    // the slope: RK4's error at the contacts' kinks, where the laws'
    // slopes jump).
    use trackgen::contact::GroundFriction;
    use trackgen::contact::GroundLaws;
    use trackgen::contact::space::SpaceContact;
    use trackgen::laws::{Friction, NormalLaw};
    use trackgen::terrain::field::HeightField;
    const D: usize = 26;
    let model = Loop24;
    let n = 24;
    let plate = OutOfPlaneInertia::plate(18.02, 0.154, 0.38, 0.06);
    let tree = FloatingTree::new(&model, vec![plate; n]).unwrap();
    let field = HeightField::plane(0.2, std::f64::consts::FRAC_PI_2);
    let laws = GroundLaws {
        normal: NormalLaw::HuntCrossley {
            stiffness: 2e6,
            exponent: 1.0,
            chi: 2.0,
        },
        friction: GroundFriction::Regularised(Friction {
            mu: 0.8,
            slip: 0.05,
        }),
    };
    let mut planar = SVector::<f64, D>::zeros();
    for k in 0..n {
        planar[k + 2] = std::f64::consts::TAU * k as f64 / n as f64;
    }
    let mut pose = PlanePose {
        origin: Vector3::zeros(),
        yaw: 0.4,
        roll: 0.3,
        planar,
    };
    // Its lowest edge 0.1 m above the ground.
    let edges = |pose: &PlanePose<D>| {
        let (at, turn) = (tree.positions(pose), tree.orientations(pose));
        (0..n)
            .flat_map(|k| [-0.19, 0.19].map(|e| (k, at[k] + turn[k] * Vector3::new(0.0, e, -0.03))))
            .collect::<Vec<_>>()
    };
    let gap = edges(&pose)
        .iter()
        .map(|(_, p)| p.z - field.height(p.x, p.y))
        .fold(f64::INFINITY, f64::min);
    pose.origin.z += 0.1 - gap;
    let rates = PlaneRates {
        planar: SVector::from_fn(|i, _| {
            if i == 0 {
                0.5
            } else if i == 1 {
                0.0
            } else {
                1.0
            }
        }),
        across: Vector3::new(0.2, 0.3, -0.4),
    };
    // Loads, stored contact energy and dissipated power at a state.
    let contacts = |pose: &PlanePose<D>, rates: &PlaneRates<D>| {
        let (at, v, w) = (
            tree.positions(pose),
            tree.velocities(pose, rates),
            tree.angular_velocities(pose, rates),
        );
        let mut loads = vec![SpatialLoad::default(); n];
        let (mut stored, mut lost) = (0.0, 0.0);
        for (k, p) in edges(pose) {
            let velocity = v[k] + w[k].cross(&(p - at[k]));
            if let Some(contact) = SpaceContact::at(&field, p, velocity) {
                let r = laws.respond_in_space(&contact, trackgen::nalgebra::Vector2::zeros());
                loads[k].force += r.force;
                loads[k].moment += (p - at[k]).cross(&r.force);
                stored += r.potential;
                lost += r.dissipation;
            }
        }
        (loads, stored, lost)
    };
    let masses: Vec<f64> = model.description().bodies.iter().map(|b| b.mass).collect();
    let g = -model.description().gravity.y;
    let energy = |pose: &PlanePose<D>, rates: &PlaneRates<D>| {
        let at = tree.positions(pose);
        let gravity: f64 = at.iter().zip(&masses).map(|(r, m)| m * g * r.z).sum();
        // The closing spring's: the planar potential less its gravity.
        let mut q0 = pose.planar;
        q0[0] = 0.0;
        q0[1] = 0.0;
        let mut rho = vec![trackgen::nalgebra::Vector2::zeros(); n];
        model.body_positions(&q0, &mut rho);
        let planar_gravity: f64 = rho.iter().zip(&masses).map(|(p, m)| m * g * p.y).sum();
        let spring = model.potential_energy(&q0) - planar_gravity;
        tree.kinetic_energy(pose, rates) + gravity + spring + contacts(pose, rates).1
    };
    type State<const D: usize> = (PlanePose<D>, PlaneRates<D>, f64);
    let derivative = |s: &State<D>| {
        let (loads, _, lost) = contacts(&s.0, &s.1);
        let coordinates = tree.coordinate_rates(&s.0, &s.1);
        let accelerations = tree.accelerations(&s.0, &s.1, &loads).unwrap();
        ((coordinates, accelerations), lost)
    };
    let advance = |s: &State<D>, d: &(Derivative<D>, f64), h: f64| -> State<D> {
        let (((velocity, yaw, roll, angles), (planar, across)), lost) = d;
        (
            PlanePose {
                origin: s.0.origin + h * velocity,
                yaw: s.0.yaw + h * yaw,
                roll: s.0.roll + h * roll,
                planar: s.0.planar + h * angles,
            },
            PlaneRates {
                planar: s.1.planar + h * planar,
                across: s.1.across + h * across,
            },
            s.2 + h * lost,
        )
    };
    let start = energy(&pose, &rates);
    let brought = 18.02 * n as f64 * g * 0.1 + tree.kinetic_energy(&pose, &rates);
    let mut state: State<D> = (pose, rates, 0.0);
    let h = 2e-5;
    let mut touched = false;
    for _ in 0..20_000 {
        let k1 = derivative(&state);
        let k2 = derivative(&advance(&state, &k1, 0.5 * h));
        let k3 = derivative(&advance(&state, &k2, 0.5 * h));
        let k4 = derivative(&advance(&state, &k3, h));
        for (k, w) in [(&k1, 1.0), (&k2, 2.0), (&k3, 2.0), (&k4, 1.0)] {
            state = advance(&state, k, w * h / 6.0);
        }
        touched |= contacts(&state.0, &state.1)
            .0
            .iter()
            .any(|l| l.force.norm() > 0.0);
    }
    let end = energy(&state.0, &state.1) + state.2;
    eprintln!(
        "start {start} end {end} dissipated {} brought {brought}",
        state.2
    );
    assert!(touched, "the loop reached the ground");
    assert!(
        state.2 > 0.1 * brought,
        "the contacts took energy: {}",
        state.2
    );
    assert!(
        (end - start).abs() < 1e-4 * brought,
        "books off by {:e} of {brought} J",
        end - start
    );
}

trackgen::model! {
    /// 12 identical links closed by the constraint: a ring.
    pub track Ring12 {
        links: 12,
        link { mass: 18.02, inertia: 0.04, u1: (-0.077, 0.0), u2: (0.077, 0.0) },
        closure: partitioned,
    }
}

#[test]
fn a_closed_loop_floating_in_space_equals_the_dense_constrained_route() {
    // A ring of 12 links closed by the constraint (the gap between link
    // n's ū2 and link 1's ū1 in the plane: two equations), its rates on
    // the loop's manifold, turning and rolled: the floating tree over the
    // planar linear-time route (`closed_accelerations`) against the dense
    // route with the constraint's rows (`[M Φ_qᵀ; Φ_q 0]`, `Φ_q` and
    // `Φ̈`'s bias by the same Taylor arithmetic): to 1e-10 over five
    // states (measured 6e-15 to 1.5e-14).
    use trackgen::multibody::{ClosingJoint, TrackModel};
    const D: usize = 14;
    let description = Ring12.description();
    let joint = description.loop_joint.expect("a track");
    for seed in 1..=5 {
        let (mut pose, mut rates, loads, across) = state::<D>(12, seed);
        for k in 0..12 {
            pose.planar[k + 2] = std::f64::consts::TAU * k as f64 / 12.0 + 0.3 * seed as f64;
        }
        // Rates on the manifold: C_θ θ̇ = 0.
        let cq = Ring12.closure_jacobian(&pose.planar);
        let spins = DVector::from_iterator(12, (0..12).map(|k| rates.planar[k + 2]));
        let c = DMatrix::from_fn(2, 12, |i, j| cq[(i, j + 2)]);
        let projected =
            &spins - c.transpose() * (&c * c.transpose()).lu().solve(&(&c * &spins)).unwrap();
        for k in 0..12 {
            rates.planar[k + 2] = projected[k];
        }
        let tree = FloatingTree::new(&Ring12, across.clone()).unwrap();
        let (u_in, w) = tree
            .closed_accelerations(&pose, &rates, &loads, ClosingJoint::CLOSED)
            .unwrap();
        let (q, qd, route) = in_coordinates(&pose, &rates, (&u_in, &w));
        // The dense constrained route.
        let (_, _, mass, rhs) = dense(&description, &[0.0; 12], &across, &q, &qd, &loads);
        let gap = |q: &[Jet]| {
            let poses = poses(&description, &[0.0; 12], q);
            let point = |b: usize, u: trackgen::nalgebra::Vector2<f64>| {
                let (at, rot) = &poses[b];
                let local = mat_vec(
                    rot,
                    &[Jet::constant(u.x), Jet::constant(0.0), Jet::constant(u.y)],
                );
                [at[0] + local[0], at[1] + local[1], at[2] + local[2]]
            };
            let (last, first) = (point(11, joint.last_u2), point(0, joint.first_u1));
            let a = plane(q[3], q[4]);
            let g = [last[0] - first[0], last[1] - first[1], last[2] - first[2]];
            [0, 2].map(|c| a[0][c] * g[0] + a[1][c] * g[1] + a[2][c] * g[2])
        };
        let mut phi_q = DMatrix::<f64>::zeros(2, 17);
        for j in 0..17 {
            let unit = DVector::from_fn(17, |i, _| if i == j { 1.0 } else { 0.0 });
            let g = gap(&jets(&q, &unit));
            phi_q[(0, j)] = g[0].d;
            phi_q[(1, j)] = g[1].d;
            assert!(
                g[0].v.abs() < 1e-12 && g[1].v.abs() < 1e-12,
                "closed: {g:?}"
            );
        }
        let along = gap(&jets(&q, &qd));
        assert!(
            along[0].d.abs() < 1e-12 && along[1].d.abs() < 1e-12,
            "on the manifold"
        );
        let mut kkt = DMatrix::<f64>::zeros(19, 19);
        kkt.view_mut((0, 0), (17, 17)).copy_from(&mass);
        kkt.view_mut((0, 17), (17, 2)).copy_from(&phi_q.transpose());
        kkt.view_mut((17, 0), (2, 17)).copy_from(&phi_q);
        let mut b = DVector::<f64>::zeros(19);
        b.rows_mut(0, 17).copy_from(&rhs);
        b[17] = -2.0 * along[0].h;
        b[18] = -2.0 * along[1].h;
        let solved = kkt.lu().solve(&b).unwrap();
        let oracle = solved.rows(0, 17).into_owned();
        let error = (&route - &oracle).norm() / oracle.norm();
        assert!(error < 1e-10, "seed {seed}: q̈ off by {error:e}");
    }
}
