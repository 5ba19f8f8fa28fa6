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
//!
//! Away from symmetry: an uneven state (the hull rolled, yawed and
//! sliding against its tracks, the tracks apart) accelerates alike turned
//! and moved elsewhere, its mirror image accelerates as its mirror, and
//! the force elements' books close at it.

use trackgen::contact::{BodyState, Contact, GroundFriction, GroundLaws, ground, sprocket, wheel};
use trackgen::integrate::{Integrator, OdeSystem};
use trackgen::laws::Stiction;
use trackgen::multibody::{
    BodyLoad, ChassisModel, ClosingJoint, PartKind, RecursiveModel, TrackModel,
};
use trackgen::nalgebra::{SVector, Vector2, Vector3};
use trackgen::spatial::{FloatingTree, SpatialError, SpatialLoad, SpatialVehicle};
use trackgen::spatial_vehicle::{SpatialDynamics, SpatialLaws, SpatialSystem, TreeState};
use trackgen::terrain::Terrain;
use trackgen::terrain::field::HeightField;
use trackgen::terrain::soil::{Soil, SoilPreset};
use trackgen::vehicle::{Drive, Vehicle};

use crate::support::twin::{
    DH, DT, HULL, States, TRACK, Twin, TwinChassis, TwinHull, TwinTrack, assembled, built, laws,
    mirror, spatial, swap_sides, upright,
};
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
/// chassis, from the planar model's pieces, how many contacts of each
/// kind it has (ground, rims, teeth), and the track's joint forces.
fn planar_accelerations(
    ground_laws: GroundLaws,
    (qt, qdt): (&SVector<f64, DT>, &SVector<f64, DT>),
    (qc, qdc): (&SVector<f64, DC>, &SVector<f64, DC>),
) -> (
    SVector<f64, DT>,
    SVector<f64, DC>,
    [usize; 3],
    Vec<Vector2<f64>>,
) {
    let mut counts = [0; 3];
    let mut config = Twin::declared_config(
        Terrain::Flat { height: 0.0 },
        Drive::Torque(Box::new(|_| 0.0)),
    );
    config.ground = ground_laws;
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
    (qddt, qddc, counts, forces)
}

/// Under the declared ground (regularised friction) and under stiction
/// at rest (each ground point's spring unstretched: the planar point's
/// damper alone, shared by its two points across the width, each with
/// half its law).
#[test]
fn a_mirrored_vehicle_accelerates_as_the_planar_one() {
    let regularised = laws();
    let mut sticking = laws();
    sticking.ground.friction = GroundFriction::Stiction(Stiction {
        mu: 0.7,
        stiffness: 1e6,
        damping: 2e3,
    });
    for laws in [regularised, sticking] {
        mirrored_as_planar(laws);
    }
}

fn mirrored_as_planar(laws: SpatialLaws) {
    let layout = Twin::layout();
    let start = assembled();
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
    let (qddt, qddc, counts, forces) = planar_accelerations(laws.ground, (&qt, &qdt), (&qc, &qdc));
    assert!(
        counts.iter().all(|&n| n >= 2),
        "ground, rim and tooth contacts: {counts:?}"
    );
    let dynamics = built(laws, HeightField::level()).expect("the spatial vehicle");
    let half = layout.gauge / 2.0;
    let hull = upright(Vector3::new(qh[0], 0.0, qh[1]), &qh, &qdh);
    let right = upright(Vector3::new(qt[0], -half, qt[1]), &qt, &qdt);
    let left = upright(Vector3::new(qt[0], half, qt[1]), &qt, &qdt);
    let states = (&hull, &right, &left);
    let loads = dynamics.loads(&hull, &right, &left);
    let closed = ClosingJoint::Constrained {
        stabilisation: Vector2::zeros(),
    };
    let (mut right_forces, mut left_forces) = (
        vec![Vector2::zeros(); TwinTrack::BODIES],
        vec![Vector2::zeros(); TwinTrack::BODIES],
    );
    let ((hull_planar, hull_across), (right_planar, right_across), (left_planar, left_across)) =
        dynamics
            .accelerations_in(
                &dynamics.plane_motions(states),
                states,
                (&loads, [closed; 2]),
                [&mut right_forces, &mut left_forces],
            )
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
    // The track's joint forces (what its tensions are read from), in the
    // track's plane as in the planar one's.
    let largest = forces.iter().map(|f| f.norm()).fold(0.0, f64::max);
    for (j, f) in forces.iter().enumerate() {
        for (side, found) in [("right", right_forces[j]), ("left", left_forces[j])] {
            assert!(
                (found - f).norm() <= 1e-9 * largest,
                "{side} joint {j}: {found:?} against the plane's {f:?}"
            );
        }
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

/// The three trees' accelerations, in and across their planes.
type Rates = (
    (SVector<f64, DH>, Vector3<f64>),
    (SVector<f64, DT>, Vector3<f64>),
    (SVector<f64, DT>, Vector3<f64>),
);

/// An uneven state: the assembled `Twin` pressed into the ground, its
/// hull rolled, yawed against its tracks and sliding and turning across
/// its plane, the two tracks apart in place and motion, every body moving.
fn uneven() -> States {
    let layout = Twin::layout();
    let start = assembled();
    let half = layout.gauge / 2.0;
    let (mut qh, qt) = (start.hull, start.right);
    qh[1] -= 0.004;
    qh[2] += 0.003;
    qh[2 + TwinHull::RIGHT_DRIVE] += 0.15;
    qh[2 + TwinHull::LEFT_DRIVE] -= 0.12;
    let qdh = SVector::<f64, DH>::from_fn(|i, _| 0.3 * (1.3 * i as f64).sin() + 0.5);
    let mut hull = upright(Vector3::new(qh[0], 0.004, qh[1]), &qh, &qdh);
    (hull.pose.yaw, hull.pose.roll) = (0.006, -0.008);
    hull.rates.across = Vector3::new(0.05, 0.1, -0.2);
    let track = |lateral: f64, lift: f64, phase: f64| {
        let mut q = qt;
        q[1] -= lift;
        let qd = SVector::<f64, DT>::from_fn(|i, _| 0.2 * (0.7 * i as f64 + phase).cos());
        let mut state = upright(Vector3::new(q[0], lateral, q[1]), &q, &qd);
        (state.pose.yaw, state.pose.roll) = (-0.004 * phase, 0.003);
        state.rates.across = Vector3::new(-0.02 * phase, 0.04, 0.1 * phase);
        state
    };
    (
        hull,
        track(-half - 0.003, 0.003, 1.0),
        track(half + 0.012, 0.002, -0.5),
    )
}

/// The accelerations at `states` (which must touch: the contacts store
/// energy and dissipate).
fn accelerate(states: &States) -> Rates {
    let dynamics = spatial();
    let loads = dynamics.loads(&states.0, &states.1, &states.2);
    assert!(loads.potential > 0.0 && loads.dissipation > 0.0);
    dynamics
        .accelerations(&states.0, &states.1, &states.2)
        .expect("the spatial dynamics")
}

/// `a` and `b` equal to `1e-9` of their size (or of 1).
fn same(a: &[f64], b: &[f64], what: &str) {
    let scale = b.iter().fold(1.0_f64, |m, v| m.max(v.abs()));
    for (i, (x, y)) in a.iter().zip(b).enumerate() {
        assert!(
            (x - y).abs() <= 1e-9 * scale,
            "{what}[{i}]: {x} against {y}"
        );
    }
}

/// The same vehicle turned 1.1 rad about the vertical and moved
/// elsewhere on level ground accelerates alike: every acceleration is in
/// its tree's plane's frame.
#[test]
fn a_vehicle_moved_rigidly_accelerates_alike() {
    let states = uneven();
    let turn = 1.1;
    let (s, c) = f64::sin_cos(turn);
    let shift = Vector3::new(40.0, -7.0, 0.0);
    let moved = |origin: Vector3<f64>| {
        Vector3::new(
            c * origin.x - s * origin.y,
            s * origin.x + c * origin.y,
            origin.z,
        ) + shift
    };
    let mut turned = states.clone();
    turned.0.pose.origin = moved(turned.0.pose.origin);
    turned.0.pose.yaw += turn;
    turned.1.pose.origin = moved(turned.1.pose.origin);
    turned.1.pose.yaw += turn;
    turned.2.pose.origin = moved(turned.2.pose.origin);
    turned.2.pose.yaw += turn;
    let (a, b) = (accelerate(&states), accelerate(&turned));
    same(b.0.0.as_slice(), a.0.0.as_slice(), "hull in its plane");
    same(b.0.1.as_slice(), a.0.1.as_slice(), "hull across");
    same(
        b.1.0.as_slice(),
        a.1.0.as_slice(),
        "right track in its plane",
    );
    same(b.1.1.as_slice(), a.1.1.as_slice(), "right track across");
    same(
        b.2.0.as_slice(),
        a.2.0.as_slice(),
        "left track in its plane",
    );
    same(b.2.1.as_slice(), a.2.1.as_slice(), "left track across");
}

/// The vehicle's mirror image across its centre plane (the world's `y`
/// reversed) is the vehicle with its sides exchanged: the mirrored state
/// (each tree's origin's `y`, yaw and roll reversed, its rates across
/// its plane reversed, the hull's right and left bodies and the two
/// tracks exchanged) accelerates as the mirror of the state's
/// accelerations, to 1e-9.
#[test]
fn the_mirror_image_accelerates_as_the_mirror() {
    let states = uneven();
    let mirrored = mirror(&states);
    let (a, b) = (accelerate(&states), accelerate(&mirrored));
    same(
        b.0.0.as_slice(),
        swap_sides(&a.0.0).as_slice(),
        "hull in its plane",
    );
    same((-b.0.1).as_slice(), a.0.1.as_slice(), "hull across");
    same(
        b.1.0.as_slice(),
        a.2.0.as_slice(),
        "right track as the left",
    );
    same(
        (-b.1.1).as_slice(),
        a.2.1.as_slice(),
        "right track across as the left",
    );
    same(
        b.2.0.as_slice(),
        a.1.0.as_slice(),
        "left track as the right",
    );
    same(
        (-b.2.1).as_slice(),
        a.1.1.as_slice(),
        "left track across as the right",
    );
}

/// The force elements' books at an uneven state: the power the loads do
/// on the bodies (`Σ F · v + M · ω`, every body of the three trees, from
/// the trees' world velocities) is what the elements' stored energy loses
/// (its rate by central differences along the motion, each tree's
/// coordinates advanced at their rates) less what they dissipate, to
/// 1e-6: every force acts at the material point whose motion its law
/// reads, every moment arm from its body's centroid.
#[test]
fn the_force_elements_books_close() {
    let states = uneven();
    let dynamics = spatial();
    let loads = dynamics.loads(&states.0, &states.1, &states.2);
    let given = power(&dynamics.hull, &states.0, &loads.hull)
        + power(&dynamics.right, &states.1, &loads.right)
        + power(&dynamics.left, &states.2, &loads.left);
    let h = 1e-7;
    let stored_at = |by: f64| {
        let hull = advanced(&dynamics.hull, &states.0, by);
        let right = advanced(&dynamics.right, &states.1, by);
        let left = advanced(&dynamics.left, &states.2, by);
        dynamics.loads(&hull, &right, &left).potential
    };
    let stored = (stored_at(h) - stored_at(-h)) / (2.0 * h);
    assert!(
        (given + stored + loads.dissipation).abs() < 1e-6 * loads.dissipation,
        "{given} W given, {stored} W stored, {} W dissipated",
        loads.dissipation
    );
}

/// The power `loads` do on a tree's bodies at `state`, W.
fn power<M: RecursiveModel<D>, const D: usize>(
    tree: &FloatingTree<'_, M, D>,
    state: &TreeState<D>,
    loads: &[SpatialLoad],
) -> f64 {
    let v = tree.velocities(&state.pose, &state.rates);
    let w = tree.angular_velocities(&state.pose, &state.rates);
    loads
        .iter()
        .zip(v.iter().zip(&w))
        .map(|(l, (v, w))| l.force.dot(v) + l.moment.dot(w))
        .sum()
}

/// A tree's state with its coordinates advanced `by` seconds at their
/// rates (its rates kept).
fn advanced<M: RecursiveModel<D>, const D: usize>(
    tree: &FloatingTree<'_, M, D>,
    state: &TreeState<D>,
    by: f64,
) -> TreeState<D> {
    let (velocity, yaw, roll, angles) = tree.coordinate_rates(&state.pose, &state.rates);
    let mut s = state.clone();
    s.pose.origin += velocity * by;
    s.pose.yaw += yaw * by;
    s.pose.roll += roll * by;
    for k in 2..D {
        s.pose.planar[k] += angles[k] * by;
    }
    s
}

/// A layout that does not fit the trees is refused: a side missing, an
/// inertia missing.
#[test]
fn a_layout_that_does_not_fit_is_refused() {
    let geometry = Twin::geometry();
    let build = |layout: &trackgen::spatial::SpatialLayout| {
        SpatialDynamics::new(
            &HULL,
            (&TRACK, &TRACK),
            layout,
            geometry.shoe.clone(),
            geometry.sprocket,
            laws(),
            HeightField::level(),
        )
        .err()
    };
    let mut layout = Twin::layout();
    layout.part_sides.pop();
    assert!(matches!(build(&layout), Some(SpatialError::Sides { .. })));
    let mut layout = Twin::layout();
    layout.left_links.pop();
    assert!(matches!(
        build(&layout),
        Some(SpatialError::Inertias { .. })
    ));
    assert!(build(&Twin::layout()).is_none());
}

/// A contact law out of its range is refused by its contacts' name: a
/// guide with no stiffness, a horn of no height, a negative ground
/// friction; each message names the contacts and the parameter.
#[test]
fn a_law_out_of_range_is_refused() {
    let build = |laws| built(laws, HeightField::level()).err();
    let mut soft = laws();
    soft.guide.stiffness = 0.0;
    let mut flat = laws();
    flat.guide.height = f64::NAN;
    let mut slippery = laws();
    slippery.ground.friction = slippery.ground.friction.with_mu(-0.1);
    for (bad, pair, parameter) in [
        (soft, "guides", "stiffness"),
        (flat, "guides", "height"),
        (slippery, "ground", "mu"),
    ] {
        let error = build(bad).expect("refused");
        assert!(
            matches!(error, SpatialError::Law { pair: p, .. } if p == pair),
            "{error:?}"
        );
        let message = error.to_string();
        assert!(
            message.contains(pair) && message.contains(parameter),
            "{message}"
        );
    }
}

/// A soil that bears nothing, or whose unloading is softer than its
/// loading, is refused naming the soil, before anything runs.
#[test]
fn a_soil_that_is_no_soil_is_refused() {
    let build = |laws| built(laws, HeightField::level()).err();
    let sand = SoilPreset::DrySand.soil();
    let bearing_nothing = Soil {
        k_c: 0.0,
        k_phi: 0.0,
        ..sand
    };
    let soft_unloading = Soil {
        unloading_stiffness: 0.5 * sand.k_phi,
        ..sand
    };
    for (soil, says) in [
        (bearing_nothing, "carries no load"),
        (soft_unloading, "K_e"),
    ] {
        let laws = SpatialLaws {
            soil: Some(soil),
            ..laws()
        };
        let error = build(laws).expect("refused");
        assert!(matches!(error, SpatialError::Soil(_)), "{error:?}");
        let message = error.to_string();
        assert!(
            message.contains("soil") && message.contains(says),
            "{message}"
        );
    }
    let laws = SpatialLaws {
        soil: Some(sand),
        ..laws()
    };
    assert!(build(laws).is_none(), "dry sand is a soil");
}

/// The mirrored `Twin` dropped 5 mm onto level ground from its assembled
/// start, integrated 0.25 s (Dormand–Prince, rtol 1e-7; `SpatialSystem`
/// with the tracks' loops held by Baumgarte's stabilisation): its energy —
/// kinetic, gravity's, what its force elements store and what they have
/// dissipated — stays what it was, and it neither slides, rolls nor yaws
/// (the hull's lateral place, roll and yaw stay at rounding).
#[test]
fn a_dropped_mirror_keeps_its_books_and_turns_neither_way() {
    let start = assembled();
    let half = Twin::layout().gauge / 2.0;
    let drop = 0.005;
    let (qh, qt) = (start.hull, start.right);
    let hull = upright(
        Vector3::new(qh[0], 0.0, qh[1] + drop),
        &qh,
        &SVector::zeros(),
    );
    let track = |lateral: f64| {
        upright(
            Vector3::new(qt[0], lateral, qt[1] + drop),
            &qt,
            &SVector::zeros(),
        )
    };
    let mut system = SpatialSystem::new(spatial());
    let mut y = system.state(&hull, &track(-half), &track(half));
    let before = system.energy(y.as_slice());
    let mut stepper = Integrator::Dopri5 {
        rtol: 1e-7,
        atol: 1e-9,
        max_step: 1e-3,
    }
    .stepper(system.dimension());
    let (mut t, end) = (0.0, 0.25);
    while t < end {
        stepper
            .step(&mut system, &mut t, &mut y, end)
            .expect("the drop runs");
    }
    let after = system.energy(y.as_slice());
    let (hull, right, left, _) = system.states(y.as_slice());
    assert!(after.dissipated > 0.0);
    // At rtol 1e-7 the books close to about 4e-8 of the energy
    // dissipated (2.5e-5 J of 635 J); 1e-6 leaves the integrator's
    // tolerance room, far below any missing term (a force element's
    // power misbooked, gravity's work on one tree).
    assert!(
        (after.total() - before.total()).abs() < 1e-6 * after.dissipated,
        "{} J against {} J, {} J dissipated",
        after.total(),
        before.total(),
        after.dissipated
    );
    let (r, l) = (right.pose.origin, left.pose.origin);
    assert!((r.x - l.x).abs() < 1e-12 && (r.y + l.y).abs() < 1e-12 && (r.z - l.z).abs() < 1e-12);
    assert!(
        hull.pose.origin.y.abs() < 1e-9
            && hull.pose.yaw.abs() < 1e-9
            && hull.pose.roll.abs() < 1e-9
    );
}
