//! The chassis subsystem (formulation §3) of a declared vehicle: generated code
//! against the reference route, against the paper's eq. (11) written out
//! by hand, and the vehicle's generated items.
//!
//! Tolerances as in generated_vs_reference.rs (1e-12, rounding only).

use crate::support;

use support::{Lcg, assert_close, dmat, dvec};
use trackgen::multibody::{BodyLoad, ChassisModel, PartKind, RecursiveModel, TrackModel};
use trackgen::nalgebra::{DMatrix, SMatrix, SVector, Vector2};
use trackgen_runtime::reference::ReferenceModel;

trackgen::model! {
    /// A small vehicle: three road wheels, a sprocket, an idler, a roller.
    pub vehicle Carrier {
        chassis { mass: 3909.62, inertia: 13643.8, centroid: (-2.006, 0.406) },
        sprocket drive { at: (0.0, 0.0), mass: 27.68, inertia: 0.883, radius: 0.245, teeth: 10 },
        road_wheel rw1 { at: (-0.74, -0.215), mass: 35.56, inertia: 2.16, radius: 0.305 },
        road_wheel rw2 { at: (-2.074, -0.215), mass: 35.56, inertia: 2.16, radius: 0.305 },
        road_wheel rw3 { at: (-3.407, -0.215), mass: 35.56, inertia: 2.16, radius: 0.305 },
        idler front { at: (-3.95, -0.12), mass: 25.76, inertia: 1.12, radius: 0.255 },
        roller top { at: (-2.0, 0.25), mass: 10.0, inertia: 0.1, radius: 0.1 },
        track {
            links: 12,
            link { mass: 18.02, inertia: 0.04, u1: (-0.077, 0.0), u2: (0.077, 0.0) },
            closure: partitioned,
        },
    }
}

const DOF: usize = 9;

#[test]
fn chassis_matches_reference_route() {
    let reference = ReferenceModel::new(CarrierChassis.description());
    let mut rng = Lcg::new(21);
    for _ in 0..16 {
        let (q, qd) = rng.state::<DOF>();
        let (dq, dqd) = (dvec(&q), dvec(&qd));
        let mut mass = SMatrix::<f64, DOF, DOF>::zeros();
        CarrierChassis.mass_matrix(&q, &mut mass);
        assert_close(
            "(M_i)_c",
            dmat(&mass).as_slice(),
            reference.mass_matrix(&dq).as_slice(),
            1e-12,
            0.0,
        );
        let loads: Vec<BodyLoad> = (0..7)
            .map(|_| BodyLoad {
                force: Vector2::new(rng.uniform(-1e3, 1e3), rng.uniform(-1e3, 1e3)),
                moment: rng.uniform(-1e3, 1e3),
            })
            .collect();
        let mut forces = SVector::<f64, DOF>::zeros();
        CarrierChassis.generalized_forces(&q, &qd, &loads, &mut forces);
        assert_close(
            "(Q_i)_c",
            forces.as_slice(),
            reference.generalized_forces(&dq, &dqd, &loads).as_slice(),
            1e-12,
            0.0,
        );
        assert_close(
            "H_c",
            CarrierChassis.velocity_transform(&q).as_slice(),
            reference.velocity_transform(&dq).as_slice(),
            1e-12,
            0.0,
        );
        let got =
            trackgen::dynamics::dense_open_dynamics(&CarrierChassis, &q, &qd, &loads).unwrap();
        let want = reference.forward_dynamics(&dq, &dqd, &loads).unwrap();
        assert_close("q̈_c", got.qdd.as_slice(), want.qdd.as_slice(), 1e-10, 0.0);
    }
}

/// Eq. (11) written out: `H_c` has `I` and `A_θᶜ ū_iᶜ` in each part's
/// block row and the identity under the angles; `(M_i)_c = H_cᵀ M_c H_c`.
#[test]
fn chassis_follows_eq_11() {
    let centroid = Vector2::new(-2.006, 0.406);
    let at = [
        (0.0, 0.0),
        (-0.74, -0.215),
        (-2.074, -0.215),
        (-3.407, -0.215),
        (-3.95, -0.12),
        (-2.0, 0.25),
    ]
    .map(|(x, y)| Vector2::new(x, y) - centroid);
    let masses = [3909.62, 27.68, 35.56, 35.56, 35.56, 25.76, 10.0];
    let inertias = [13643.8, 0.883, 2.16, 2.16, 2.16, 1.12, 0.1];
    let mut rng = Lcg::new(22);
    let (q, _) = rng.state::<DOF>();
    let theta = q[2];
    let (s, c) = theta.sin_cos();
    let mut h = DMatrix::<f64>::zeros(21, DOF);
    for b in 0..7 {
        h[(2 * b, 0)] = 1.0;
        h[(2 * b + 1, 1)] = 1.0;
        if b > 0 {
            let u = at[b - 1];
            h[(2 * b, 2)] = -s * u.x - c * u.y;
            h[(2 * b + 1, 2)] = c * u.x - s * u.y;
        }
        h[(14 + b, 2 + b)] = 1.0;
    }
    assert_close(
        "H_c",
        CarrierChassis.velocity_transform(&q).as_slice(),
        h.as_slice(),
        1e-12,
        0.0,
    );
    let m = DMatrix::from_diagonal(&trackgen::nalgebra::DVector::from_fn(21, |r, _| {
        if r < 14 {
            masses[r / 2]
        } else {
            inertias[r - 14]
        }
    }));
    let want = h.transpose() * m * &h;
    let mut mass = SMatrix::<f64, DOF, DOF>::zeros();
    CarrierChassis.mass_matrix(&q, &mut mass);
    assert_close(
        "(M_i)_c",
        dmat(&mass).as_slice(),
        want.as_slice(),
        1e-12,
        0.0,
    );
    // The parts spin independently of the frame: no frame–part coupling.
    for b in 1..7 {
        assert_eq!(mass[(2, 2 + b)], 0.0);
        assert_eq!(mass[(2 + b, 2 + b)], inertias[b]);
    }
}

#[test]
fn vehicle_items_describe_the_declaration() {
    assert_eq!(CarrierChassis::FRAME, 0);
    assert_eq!(CarrierChassis::DRIVE, 1);
    assert_eq!(CarrierChassis::TOP, 6);
    let parts = <CarrierChassis as ChassisModel<DOF>>::PARTS;
    assert_eq!(parts.len(), 6);
    assert_eq!(parts[0].kind, PartKind::Sprocket);
    assert_eq!(parts[0].teeth, 10);
    assert_eq!(parts[4].kind, PartKind::Idler);
    assert_eq!(parts[5].kind, PartKind::Roller);
    assert_eq!(parts[1].radius, 0.305);
    assert_eq!(CarrierTrack::LINKS, 12);
    assert!(<CarrierTrack as TrackModel<14>>::CLOSURE.is_constrained());
    let _ = (Carrier::TRACK, Carrier::CHASSIS);
    // The vehicle's gravity reaches the track.
    assert_eq!(CarrierTrack.description().gravity, Vector2::new(0.0, -9.81));
}

/// The M113 chassis is a two-level tree (frame → trailing arm → road
/// wheel): generated against the reference route at random states.
#[test]
fn sprung_chassis_matches_reference_route() {
    use trackgen::vehicles::m113::M113Chassis;
    const D: usize = 16;
    let reference = ReferenceModel::new(M113Chassis.description());
    let depth_two = M113Chassis
        .description()
        .bodies
        .iter()
        .filter(|b| b.parent.is_some_and(|p| p > 0))
        .count();
    assert_eq!(
        depth_two, 6,
        "five road wheels and the idler hang from arms"
    );
    let mut rng = Lcg::new(23);
    for _ in 0..16 {
        let (q, qd) = rng.state::<D>();
        let (dq, dqd) = (dvec(&q), dvec(&qd));
        let mut mass = SMatrix::<f64, D, D>::zeros();
        M113Chassis.mass_matrix(&q, &mut mass);
        assert_close(
            "(M_i)_c",
            dmat(&mass).as_slice(),
            reference.mass_matrix(&dq).as_slice(),
            1e-12,
            0.0,
        );
        let mut forces = SVector::<f64, D>::zeros();
        M113Chassis.generalized_forces(&q, &qd, &[], &mut forces);
        assert_close(
            "(Q_i)_c",
            forces.as_slice(),
            reference.generalized_forces(&dq, &dqd, &[]).as_slice(),
            1e-12,
            0.0,
        );
        assert_close(
            "H_c",
            M113Chassis.velocity_transform(&q).as_slice(),
            reference.velocity_transform(&dq).as_slice(),
            1e-12,
            0.0,
        );
    }
}

/// The arm torques are the negative gradient of the springs' energy (with
/// the dampers at rest): central differences, h = 1e-6, 1e-7 relative.
#[test]
fn arm_torques_derive_from_the_spring_energy() {
    use support::arms::{add_arm_torques, arm_energy};
    use trackgen::vehicles::m113::M113Chassis;
    const D: usize = 16;
    let mut rng = Lcg::new(24);
    let (q, _) = rng.state::<D>();
    let mut loads = vec![BodyLoad::ZERO; 14];
    add_arm_torques::<M113Chassis, D>(&q, &SVector::zeros(), &mut loads);
    for b in 0..14 {
        let mut e = SVector::<f64, D>::zeros();
        e[2 + b] = 1e-6;
        let grad = (arm_energy::<M113Chassis, D>(&(q + e))
            - arm_energy::<M113Chassis, D>(&(q - e)))
            / 2e-6;
        assert!(
            (loads[b].moment + grad).abs() < 1e-7 * 2.5e4,
            "body {b}: torque {} vs −∂V/∂θ {}",
            loads[b].moment,
            -grad
        );
    }
    // Every arm is sprung, and the frame takes the reactions.
    let total: f64 = loads.iter().map(|l| l.moment).sum();
    assert!(total.abs() < 1e-9, "internal torques sum to zero: {total}");
    assert!(
        <M113Chassis as ChassisModel<D>>::PARTS
            .iter()
            .filter(|p| p.arm.is_some())
            .count()
            == 6
    );
}
