//! The two-level chassis (frame → sprung arm → road wheel or idler, spec
//! §3) against central finite differences of its own positions and
//! energies, at deterministic random states (`support::Lcg`): the
//! counterpart for chassis of tests/finite_differences.rs.
//!
//! * `H = ∂R/∂q_i`: `velocity_transform` (built from `body_velocities`)
//!   against differences of `body_positions`, angle rows included (and
//!   `body_states`, which may share trigonometry, against the two calls);
//! * `γ = d(H q̇)/dt` at `q̈ = 0`: `velocity_terms` against the difference
//!   of `body_velocities(q, q̇)` along `q̇`;
//! * `½ q̇ᵀ M_i q̇ = kinetic_energy` (the closed-form `M_i` against the sum
//!   over absolute velocities) and the Coriolis part of `Q_i`: by
//!   Lagrange, `Q_i(q, q̇) − Q_i(q, 0) = ∂T/∂q − Ṁ_i q̇`, both sides from
//!   differences of `kinetic_energy` and of `M_i q̇`;
//! * at rest, `Q_i = −∂V/∂q_i` for gravity, and with the arms' torques
//!   (`trackgen::vehicle::arms::apply`) as loads,
//!   `Q_i = −∂(V + arm_energy)/∂q_i`; the torques themselves are
//!   `−∂(arm_energy)/∂θ` body by body, and in motion the dampers take
//!   exactly `arm_dissipation` of power.
//!
//! Models: `trackgen::vehicles::m113::M113Chassis` (five road wheels and an
//! idler on arms, 14 bodies), and `Rig`, declared here: an off-centre
//! centroid, gravity with a horizontal part, a road wheel on an arm beside
//! one pinned straight to the frame, an idler on an arm, a roller, so that
//! one- and two-level branches and `g_x` are all exercised.
//!
//! Tolerances. Step `h = 1e-6` with coordinates O(1) (positions within
//! ±2 m, angles within ±3.2 rad, rates within ±3): a central difference
//! errs by `h²/6·|f'''| ≈ 2e-13·|f'|` (the functions are trigonometric in
//! the angles, at most quadratic in `R` and `q̇`) plus rounding
//! `ε|f|/h ≈ 2e-10·|f|`. Where `|f|` is about the size of the derivative
//! compared (positions, velocities, `V` ~ 1e5 J against gravity forces
//! ~ 3e4 N, arm energies ~ 1e6 J against torques ~ 2e5 N m) that is ≲ 1e-9
//! of the largest entry, so 1e-7 relative to the largest entry
//! (norm-wise, `support::assert_close`, as tests/finite_differences.rs
//! does) is safe by two orders and still catches any wrong term, which
//! shows at O(1) (measured worst: 4e-10). One comparison needs a floor:
//! the Coriolis forces (~1e3 N, light parts turning about near pins) are
//! differences of `T ~ 1e4 J` (mostly the frame's), whose rounding is
//! `ε|T|/h ≈ 2e-10·|T|` in absolute terms, so they are held to
//! `1e-7·max(|Q|, |T|/1 m)` (≲ 1e-2 N: 500× that rounding, yet 1e-5 of the
//! forces compared; measured worst 2e-5 N). Identities that
//! involve no differencing (`½ q̇ᵀ M q̇ = T`, the damper power) are held to
//! 1e-10 relative: rounding in sums of a few hundred products is ~1e-13
//! (measured worst: 1e-13).

use crate::support;

use support::arms::{add_arm_torques, arm_dissipation, arm_energy};
use support::{Lcg, assert_close};
use trackgen::multibody::{BodyLoad, ChassisModel, RecursiveModel};
use trackgen::nalgebra::{DMatrix, DVector, SMatrix, SVector, Vector2};
use trackgen::vehicles::m113::M113Chassis;

trackgen::model! {
    /// A small sprung vehicle: the sprocket and one road wheel pinned to
    /// the frame, a road wheel on a trailing arm, an idler on a tensioner
    /// arm, a roller; gravity slanted as on a 9° slope.
    pub vehicle Rig {
        gravity: (1.5, -9.81),
        chassis { mass: 2500.0, inertia: 6000.0, centroid: (-1.6, 0.35) },
        sprocket drive { at: (0.0, 0.0), mass: 27.68, inertia: 1.283, radius: 0.245, teeth: 11 },
        road_wheel front { at: (-0.74, -0.215), mass: 35.56, inertia: 2.16, radius: 0.305,
            arm { pivot: (-0.452, -0.081), mass: 75.26, inertia: 0.77,
                  stiffness: 2.5e4, damping: 500.0, preload: 1.0e4 } },
        road_wheel rear { at: (-2.4, -0.215), mass: 35.56, inertia: 2.16, radius: 0.305 },
        idler tension { at: (-3.1, -0.12), mass: 25.76, inertia: 1.12, radius: 0.255,
            arm { pivot: (-3.1, 0.13), mass: 5.0, inertia: 0.05,
                  stiffness: 6.25e4, damping: 875.0, preload: -5.0e3 } },
        roller top { at: (-1.5, 0.25), mass: 10.0, inertia: 0.1, radius: 0.1 },
        track {
            links: 4,
            link { mass: 18.02, inertia: 0.04, u1: (-0.077, 0.0), u2: (0.077, 0.0) },
            closure: partitioned,
        },
    }
}

const H: f64 = 1e-6;
const REL: f64 = 1e-7;
/// For identities without differencing: rounding only.
const EXACT: f64 = 1e-10;
/// States per model.
const STATES: usize = 8;

/// `[R_0 … R_{n−1}, θ_0 … θ_{n−1}]`, the rows of `H`.
fn positions<M: RecursiveModel<D>, const D: usize>(m: &M, q: &SVector<f64, D>) -> Vec<f64> {
    let mut out = vec![Vector2::zeros(); M::BODIES];
    m.body_positions(q, &mut out);
    out.iter()
        .flat_map(|p| [p.x, p.y])
        .chain(q.iter().skip(2).copied())
        .collect()
}

/// `[Ṙ_0 … Ṙ_{n−1}, ω_0 … ω_{n−1}]` from `body_velocities`.
fn velocities<M: RecursiveModel<D>, const D: usize>(
    m: &M,
    q: &SVector<f64, D>,
    qd: &SVector<f64, D>,
) -> Vec<f64> {
    let mut out = vec![Vector2::zeros(); M::BODIES];
    m.body_velocities(q, qd, &mut out);
    out.iter()
        .flat_map(|v| [v.x, v.y])
        .chain(qd.iter().skip(2).copied())
        .collect()
}

/// Central difference of `f` at `q` along `dir`.
fn along<const D: usize>(
    f: impl Fn(&SVector<f64, D>) -> Vec<f64>,
    q: &SVector<f64, D>,
    dir: &SVector<f64, D>,
) -> Vec<f64> {
    let (a, b) = (f(&(q + dir * H)), f(&(q - dir * H)));
    a.iter().zip(&b).map(|(a, b)| (a - b) / (2.0 * H)).collect()
}

/// The gradient of a scalar `f` at `q`.
fn gradient<const D: usize>(f: impl Fn(&SVector<f64, D>) -> f64, q: &SVector<f64, D>) -> Vec<f64> {
    (0..D)
        .map(|k| along(|q| vec![f(q)], q, &unit(k))[0])
        .collect()
}

fn unit<const D: usize>(k: usize) -> SVector<f64, D> {
    SVector::from_fn(|i, _| if i == k { 1.0 } else { 0.0 })
}

fn forces<M: RecursiveModel<D>, const D: usize>(
    m: &M,
    q: &SVector<f64, D>,
    qd: &SVector<f64, D>,
    loads: &[BodyLoad],
) -> SVector<f64, D> {
    let mut out = SVector::zeros();
    m.generalized_forces(q, qd, loads, &mut out);
    out
}

fn arm_loads<M: ChassisModel<D>, const D: usize>(
    q: &SVector<f64, D>,
    qd: &SVector<f64, D>,
) -> Vec<BodyLoad> {
    let mut loads = vec![BodyLoad::ZERO; M::BODIES];
    add_arm_torques::<M, D>(q, qd, &mut loads);
    loads
}

/// The model is what this file means to test: a two-level tree whose
/// every arm is a child of the frame carrying exactly its part, sprung.
fn check_structure<M: ChassisModel<D>, const D: usize>(m: &M, arms: usize) {
    let bodies = m.description().bodies;
    assert_eq!(bodies.len(), M::BODIES);
    assert_eq!(D, M::BODIES + 2);
    let sprung: Vec<_> = M::PARTS
        .iter()
        .filter_map(|p| p.arm.map(|a| (p, a)))
        .collect();
    assert_eq!(sprung.len(), arms, "arms declared");
    for (part, arm) in sprung {
        assert_eq!(
            bodies[arm.body].parent,
            Some(0),
            "{}: arm on the frame",
            part.name
        );
        assert_eq!(
            bodies[part.body].parent,
            Some(arm.body),
            "{}: the part hangs from its arm",
            part.name
        );
        assert!(
            arm.spring.stiffness > 0.0 && arm.spring.damping > 0.0,
            "{}: sprung",
            part.name
        );
    }
}

fn check<M: ChassisModel<D>, const D: usize>(m: &M, seed: u64) {
    let n = M::BODIES;
    let mut rng = Lcg::new(seed);
    for _ in 0..STATES {
        let (q, qd) = rng.state::<D>();
        let zero = SVector::<f64, D>::zeros();

        // H = ∂R/∂q_i, column by column.
        let h = m.velocity_transform(&q);
        let mut fd = DMatrix::zeros(3 * n, D);
        for k in 0..D {
            fd.set_column(
                k,
                &DVector::from_vec(along(|q| positions(m, q), &q, &unit(k))),
            );
        }
        assert_close("H vs ∂R/∂q_i", h.as_slice(), fd.as_slice(), REL, 1.0);
        // And `body_states` (which may share trigonometry) agrees with the
        // two separate calls it stands for.
        let (mut p, mut v) = (vec![Vector2::zeros(); n], vec![Vector2::zeros(); n]);
        m.body_states(&q, &qd, &mut p, &mut v);
        let flat = |x: &[Vector2<f64>]| x.iter().flat_map(|x| [x.x, x.y]).collect::<Vec<_>>();
        assert_close(
            "body_states positions",
            &flat(&p),
            &positions(m, &q)[..2 * n],
            1e-14,
            1.0,
        );
        assert_close(
            "body_states velocities",
            &flat(&v),
            &velocities(m, &q, &qd)[..2 * n],
            1e-14,
            1.0,
        );

        // γ = d(H q̇)/dt along the motion, with q̇ held.
        assert_close(
            "γ vs d(H q̇)/dt",
            m.gamma(&q, &qd).as_slice(),
            &along(|q| velocities(m, q, &qd), &q, &qd),
            REL,
            1.0,
        );

        // ½ q̇ᵀ M_i q̇ = T.
        let mut mass = SMatrix::<f64, D, D>::zeros();
        m.mass_matrix(&q, &mut mass);
        let t = m.kinetic_energy(&q, &qd);
        assert_close(
            "½ q̇ᵀ M_i q̇ vs kinetic_energy",
            &[0.5 * qd.dot(&(mass * qd))],
            &[t],
            EXACT,
            1.0,
        );

        // Lagrange: the velocity-dependent part of Q_i is ∂T/∂q − Ṁ q̇.
        let coriolis = forces(m, &q, &qd, &[]) - forces(m, &q, &zero, &[]);
        let dt_dq = gradient(|q| m.kinetic_energy(q, &qd), &q);
        let mdot_qd = along(
            |q| {
                let mut mass = SMatrix::<f64, D, D>::zeros();
                m.mass_matrix(q, &mut mass);
                (mass * qd).as_slice().to_vec()
            },
            &q,
            &qd,
        );
        let want: Vec<f64> = dt_dq.iter().zip(&mdot_qd).map(|(a, b)| a - b).collect();
        // These forces (light parts turning about near pins, ~1e3 N) are
        // far smaller than the energy differenced for them (mostly the
        // frame's `T`): rounding is `ε|T|/h` in absolute terms, so the
        // scale is at least `|T|` per metre (see the module docs).
        assert_close(
            "Q_i(q, q̇) − Q_i(q, 0) vs ∂T/∂q − Ṁ_i q̇",
            coriolis.as_slice(),
            &want,
            REL,
            t.max(1.0),
        );

        // At rest, gravity: Q_i = −∂V/∂q_i.
        let minus = |g: Vec<f64>| g.into_iter().map(|g| -g).collect::<Vec<_>>();
        let gravity = forces(m, &q, &zero, &[]);
        assert_close(
            "Q_i at rest vs −∂V/∂q_i",
            gravity.as_slice(),
            &minus(gradient(|q| m.potential_energy(q), &q)),
            REL,
            1.0,
        );

        // The arm torques, body by body: [0, 0, τ_0 … τ_{n−1}] = −∂E_arm/∂q.
        let loads = arm_loads::<M, D>(&q, &zero);
        assert!(
            loads.iter().all(|l| l.force == Vector2::zeros()),
            "the arm springs apply torques only"
        );
        let torques: Vec<f64> = [0.0, 0.0]
            .into_iter()
            .chain(loads.iter().map(|l| l.moment))
            .collect();
        let arm_grad = minus(gradient(|q| arm_energy::<M, D>(q), &q));
        assert!(
            arm_grad.iter().any(|g| g.abs() > 1.0),
            "a random state deflects the arms: {arm_grad:?}"
        );
        assert_close("arm torques vs −∂E_arm/∂q", &torques, &arm_grad, REL, 1.0);

        // Through the model: at rest with the arm torques as loads,
        // Q_i = −∂(V + E_arm)/∂q_i.
        assert_close(
            "Q_i with arm torques at rest vs −∂(V + E_arm)/∂q_i",
            forces(m, &q, &zero, &loads).as_slice(),
            &minus(gradient(
                |q| m.potential_energy(q) + arm_energy::<M, D>(q),
                &q,
            )),
            REL,
            1.0,
        );

        // In motion the dampers take exactly `arm_dissipation`:
        // q̇ᵀ (Q_i with the moving arms' torques − with the springs alone).
        let damper = forces(m, &q, &qd, &arm_loads::<M, D>(&q, &qd))
            - forces(m, &q, &qd, &arm_loads::<M, D>(&q, &zero));
        let dissipation = arm_dissipation::<M, D>(&qd);
        assert!(dissipation > 0.0, "the arms move relative to the frame");
        assert_close(
            "q̇ᵀ Q_damper vs −arm_dissipation",
            &[qd.dot(&damper)],
            &[-dissipation],
            EXACT,
            1.0,
        );
    }
}

#[test]
fn m113_chassis() {
    const D: usize = 16;
    check_structure::<M113Chassis, D>(&M113Chassis, 6);
    check::<M113Chassis, D>(&M113Chassis, 31);
}

#[test]
fn rig_chassis() {
    const D: usize = 10;
    check_structure::<RigChassis, D>(&RigChassis, 2);
    // The unsprung road wheel hangs from the frame directly.
    assert_eq!(
        RigChassis.description().bodies[RigChassis::REAR].parent,
        Some(0)
    );
    assert_eq!(RigChassis.description().gravity, Vector2::new(1.5, -9.81));
    check::<RigChassis, D>(&RigChassis, 32);
}
