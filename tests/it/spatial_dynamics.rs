//! The spatial vehicle's forward dynamics (`spatial_vehicle`) against the
//! planar model: a vehicle whose left side mirrors its right exactly,
//! with both sides in the same state, turns neither way, so its hull's
//! and tracks' accelerations in their planes must be the planar vehicle's
//! (the same running gear under the same contacts, the hull twice the
//! planar side's share), and across their planes nothing.
//!
//! The planar route here is built from the planar model's own pieces
//! apart from the spatial ones: the planar detection and laws of the
//! ground, rims and teeth (`contact::{ground, wheel, sprocket}`,
//! `ContactLaws::respond`, `GroundLaws::respond`), the arms'
//! `TorsionSpring`, and the generated O(n) routes of the chassis
//! (`tree_dynamics`) and the closed track (`linear_time_dynamics`). The
//! spatial route takes the bodies' world poses from the floating trees
//! and its contacts from `contact::space` and `contact::axial`, the
//! ground split across the shoe's width.

use trackgen::assembly::assemble_sides;
use trackgen::contact::axial::GuideLaw;
use trackgen::contact::{BodyState, Contact, ground, sprocket, wheel};
use trackgen::multibody::{
    BodyLoad, ChassisModel, ClosingJoint, PartKind, RecursiveModel, TrackModel,
};
use trackgen::nalgebra::{SVector, Vector2, Vector3};
use trackgen::spatial::{PlanePose, PlaneRates, SpatialVehicle};
use trackgen::spatial_vehicle::{SpatialDynamics, SpatialLaws, TreeState};
use trackgen::terrain::Terrain;
use trackgen::terrain::field::HeightField;
use trackgen::vehicle::{Drive, Vehicle};

trackgen::model! {
    /// A light carrier, its left side its right's mirror.
    pub vehicle Twin {
        chassis { mass: 1200.0, inertia: 1900.0, centroid: (-1.3, 0.35) },
        sprocket drive { at: (0.0, 0.0), mass: 15.0, inertia: 0.3, radius: 0.17, teeth: 9 },
        road_wheel rw[4] {
            at: [(-0.45, -0.30), (-1.0, -0.30), (-1.55, -0.30), (-2.1, -0.30)],
            mass: 25.0, inertia: 0.5, radius: 0.2,
            arm { pivot_offset: (0.22, 0.10), mass: 20.0, inertia: 0.2,
                  stiffness: 1.5e4, damping: 300.0, preload: 1.2e3 },
        },
        idler rear { at: (-2.6, -0.08), mass: 20.0, inertia: 0.4, radius: 0.18,
            arm { pivot: (-2.6, 0.12), mass: 3.0, inertia: 0.02,
                  stiffness: 2e4, damping: 600.0, preload: -2e3,
                  travel: (-0.6, 0.6) } },
        track { links: 55, link { mass: 6.0, inertia: 0.01, u1: (-0.06, 0.0), u2: (0.06, 0.0) } },
        shoe { ground_points: [(-0.045, -0.02), (0.045, -0.02)], inner_offset: 0.02,
               pins: [(0.045, 0.0), (-0.045, 0.0)], pin_radius: 0.012, width: 0.3 },
        contact { ground { stiffness: 1.5e6, chi: 2.0, mu: 0.7, slip: 0.1 } },
        tracks {
            gauge: 1.8,
            guide_play: 0.01,
            hull { mass: 2400.0, inertia: (1500.0, 3800.0, 4200.0) },
        },
    }
}

const DH: usize = <Twin as SpatialVehicle>::HULL_DOF;
const DT: usize = Twin::TRACK_DOF;
const DC: usize = Twin::CHASSIS_DOF;

/// The planar states of `bodies` of a tree at `(q, q̇)`.
fn planar_states<M: RecursiveModel<D>, const D: usize>(
    model: &M,
    q: &SVector<f64, D>,
    qd: &SVector<f64, D>,
) -> Vec<BodyState> {
    let (mut r, mut v) = (
        vec![Vector2::zeros(); M::BODIES],
        vec![Vector2::zeros(); M::BODIES],
    );
    model.body_positions(q, &mut r);
    model.body_velocities(q, qd, &mut v);
    (0..M::BODIES)
        .map(|k| BodyState::new(r[k], q[2 + k], v[k], qd[2 + k]))
        .collect()
}

/// The planar vehicle's accelerations at `(q, q̇)` of its track and its
/// chassis, from the planar model's pieces, and how many contacts of
/// each kind it has: ground, rims, teeth.
fn planar_accelerations(
    (qt, qdt): (&SVector<f64, DT>, &SVector<f64, DT>),
    (qc, qdc): (&SVector<f64, DC>, &SVector<f64, DC>),
) -> (SVector<f64, DT>, SVector<f64, DC>, [usize; 3]) {
    let mut counts = [0; 3];
    let config = Twin::declared_config(
        Terrain::Flat { height: 0.0 },
        Drive::Torque(Box::new(|_| 0.0)),
    );
    let geometry = Twin::geometry();
    let links = planar_states(&TwinTrack, qt, qdt);
    let parts = planar_states(&TwinChassis, qc, qdc);
    let mut track_loads = vec![BodyLoad::default(); links.len()];
    let mut chassis_loads = vec![BodyLoad::default(); parts.len()];
    let mut apply = |c: &Contact, force: Vector2<f64>| {
        track_loads[c.link] = track_loads[c.link].plus(BodyLoad::force_at(force, c.arm));
        if let Some(b) = c.other {
            chassis_loads[b] =
                chassis_loads[b].plus(BodyLoad::force_at(-force, c.point - parts[b].position));
        }
    };
    let mut contacts = Vec::new();
    ground::detect(&config.terrain, &links, &geometry.shoe, &mut contacts);
    counts[0] = contacts.len();
    for c in &contacts {
        apply(c, config.ground.respond(c, 0.0).0.force);
    }
    for part in TwinChassis::PARTS {
        let mut found = Vec::new();
        let body = &parts[part.body];
        if part.kind == PartKind::Sprocket {
            sprocket::detect(
                (body, part.body),
                &geometry.sprocket,
                &links,
                &geometry.shoe,
                &mut found,
            );
            counts[2] += found.len();
            for c in &found {
                apply(c, config.sprocket.respond(c).force);
            }
        } else {
            wheel::detect(
                (body, part.body, part.radius),
                &links,
                &geometry.shoe,
                &mut found,
            );
            counts[1] += found.len();
            for c in &found {
                apply(c, config.wheels.respond(c).force);
            }
        }
    }
    for arm in TwinChassis::PARTS.iter().filter_map(|p| p.arm) {
        let torque = arm
            .spring
            .torque(qc[2 + arm.body] - qc[2], qdc[2 + arm.body] - qdc[2]);
        chassis_loads[arm.body].moment += torque;
        chassis_loads[0].moment -= torque;
    }
    let trig = |q: &[f64]| q[2..].iter().map(|a| a.sin_cos()).collect::<Vec<_>>();
    let (mut qddt, mut qddc) = (SVector::zeros(), SVector::zeros());
    let mut forces = vec![Vector2::zeros(); links.len()];
    let closed = ClosingJoint::Constrained {
        stabilisation: Vector2::zeros(),
    };
    TwinTrack
        .linear_time_dynamics(
            &trig(qt.as_slice()),
            qdt,
            &track_loads,
            closed,
            &mut qddt,
            &mut forces,
        )
        .expect("the planar track's dynamics");
    TwinChassis
        .tree_dynamics(&trig(qc.as_slice()), qdc, &chassis_loads, &mut qddc)
        .expect("the planar chassis' dynamics");
    (qddt, qddc, counts)
}

/// A tree upright at yaw 0, its root at `origin`, with planar `(q, q̇)`
/// and nothing across its plane.
fn upright<const D: usize>(
    origin: Vector3<f64>,
    q: &SVector<f64, D>,
    qd: &SVector<f64, D>,
) -> TreeState<D> {
    let mut planar = *q;
    (planar[0], planar[1]) = (0.0, 0.0);
    TreeState {
        pose: PlanePose {
            origin,
            yaw: 0.0,
            roll: 0.0,
            planar,
        },
        rates: PlaneRates {
            planar: *qd,
            across: Vector3::zeros(),
        },
    }
}

#[test]
fn a_mirrored_vehicle_accelerates_as_the_planar_one() {
    let geometry = Twin::geometry();
    let layout = Twin::layout();
    let start = assemble_sides(
        &TwinHull,
        (&TwinTrack, &TwinTrack),
        &layout.part_sides,
        &geometry.shoe,
        &geometry.sprocket,
        &Terrain::Flat { height: 0.0 },
        0.0,
        1e-3,
    )
    .expect("both sides assemble");
    assert_eq!(start.right, start.left, "a mirror assembles alike");
    // The track 2 mm into the ground, the hull 1 mm into the tracks and
    // pitched, the
    // sprocket turned against its pins, everything moving.
    let mut qh = start.hull;
    let mut qt = start.right;
    qh[1] -= 0.004;
    qt[1] -= 0.003;
    qh[2] += 0.004;
    qh[2 + TwinHull::RIGHT_DRIVE] += 0.15;
    qh[2 + TwinHull::LEFT_DRIVE] += 0.15;
    let side = TwinChassis::BODIES - 1;
    let qdh = SVector::<f64, DH>::from_fn(|i, _| match i {
        0 => 1.2,
        1 => -0.05,
        _ => 0.3 * (i as f64).sin(),
    });
    // Both sides alike: the left's bodies move as the right's.
    let qdh =
        SVector::<f64, DH>::from_fn(|i, _| if i >= 3 + side { qdh[i - side] } else { qdh[i] });
    let qdt = SVector::<f64, DT>::from_fn(|i, _| 0.2 * (0.7 * i as f64).cos());
    let qc = SVector::<f64, DC>::from_fn(|i, _| qh[i]);
    let qdc = SVector::<f64, DC>::from_fn(|i, _| qdh[i]);
    let (qddt, qddc, counts) = planar_accelerations((&qt, &qdt), (&qc, &qdc));
    assert!(
        counts.iter().all(|&n| n >= 2),
        "ground, rim and tooth contacts: {counts:?}"
    );
    let config = Twin::declared_config(
        Terrain::Flat { height: 0.0 },
        Drive::Torque(Box::new(|_| 0.0)),
    );
    let laws = SpatialLaws {
        ground: config.ground,
        wheels: config.wheels,
        sprocket: config.sprocket,
        guide: GuideLaw {
            play: layout.guide_play,
            stiffness: 1e7,
            damping: 1e3,
        },
    };
    let dynamics = SpatialDynamics::new(
        &TwinHull,
        (&TwinTrack, &TwinTrack),
        &layout,
        geometry.shoe.clone(),
        geometry.sprocket,
        laws,
        HeightField::level(),
    )
    .expect("the spatial vehicle");
    let half = layout.gauge / 2.0;
    let hull = upright(Vector3::new(qh[0], 0.0, qh[1]), &qh, &qdh);
    let right = upright(Vector3::new(qt[0], -half, qt[1]), &qt, &qdt);
    let left = upright(Vector3::new(qt[0], half, qt[1]), &qt, &qdt);
    let ((hull_planar, hull_across), (right_planar, right_across), (left_planar, left_across)) =
        dynamics
            .accelerations(&hull, &right, &left)
            .expect("the spatial dynamics");
    let close = |a: f64, b: f64, what: String| {
        assert!(
            (a - b).abs() <= 1e-9 * b.abs().max(1.0),
            "{what}: {a} against the plane's {b}"
        );
    };
    for i in 0..DC {
        close(hull_planar[i], qddc[i], format!("hull q̈[{i}]"));
    }
    for k in 0..side {
        close(
            hull_planar[3 + side + k],
            qddc[3 + k],
            format!("left body {k}"),
        );
    }
    for i in 0..DT {
        close(right_planar[i], qddt[i], format!("right track q̈[{i}]"));
        close(left_planar[i], qddt[i], format!("left track q̈[{i}]"));
    }
    // Across the planes: the hull neither slides, rolls nor yaws; the
    // tracks move out as far as the other comes in (the hull's lateral
    // axis points left, so a mirror's lateral accelerations are equal
    // and opposite, and its roll and yaw rates equal and opposite too).
    assert!(
        hull_across.norm() < 1e-9,
        "the hull across its plane: {hull_across:?}"
    );
    assert!(
        (right_across.x + left_across.x).abs() < 1e-9,
        "{right_across:?} {left_across:?}"
    );
    assert!((right_across.y + left_across.y).abs() < 1e-9);
    assert!((right_across.z + left_across.z).abs() < 1e-9);
}
