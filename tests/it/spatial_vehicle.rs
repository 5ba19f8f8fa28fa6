//! The declared vehicles' `tracks` blocks as compiled: the hull carries
//! both sides' running gear as declared (the M113's right side the planar
//! chassis' bodies unchanged, the left its mirror with the road wheels
//! 0.084–0.085 m forward; the Marder the other way round),
//! the left track has 63 links, the masses add up to the published combat
//! weight less the shoe the left track lacks, and the floating hull built
//! from the layout has the inertia its bodies add up to, summed here from
//! the planar description by the parallel-axis theorem.

use trackgen::multibody::{BodyDescription, RecursiveModel};
use trackgen::nalgebra::{SVector, Vector2, Vector3};
use trackgen::spatial::{
    FloatingTree, OutOfPlaneInertia, PlanePose, PlaneRates, Side, SpatialVehicle,
};
use trackgen::vehicles::m113::{
    self, CHASSIS_INERTIA, CHASSIS_MASS, CHASSIS_ROLL_INERTIA, CHASSIS_YAW_INERTIA, COMBAT_WEIGHT,
    GAUGE, M113, M113Chassis, M113Hull, M113LeftTrack, M113Track, SHOE_MASS,
};
use trackgen::vehicles::marder::{self, Marder, MarderChassis, MarderHull, MarderRightTrack};

/// Hull coordinates.
const DH: usize = <M113 as SpatialVehicle>::HULL_DOF;

/// Each body's centroid in the plane at the design position (every angle
/// zero), from the description's joint points: `p = p_parent +
/// at_parent − at_self`.
fn design_places(bodies: &[BodyDescription]) -> Vec<Vector2<f64>> {
    let mut places: Vec<Vector2<f64>> = Vec::with_capacity(bodies.len());
    for b in bodies {
        let p = match b.parent {
            Some(parent) => places[parent] + b.at_parent - b.at_self,
            None => Vector2::zeros(),
        };
        places.push(p);
    }
    places
}

/// The hull against the planar chassis: the frame the whole hull, the
/// declared side's bodies the planar chassis' unchanged, the mirrored
/// side's the same but where a joint on the frame moved; those moves,
/// per planar body (zero where none). The hull lists the right side
/// first.
fn mirror_moves(
    planar: &[BodyDescription],
    hull: &[BodyDescription],
    declared: Side,
) -> Vec<Vector2<f64>> {
    let side = planar.len() - 1;
    assert_eq!(hull.len(), 1 + 2 * side, "the frame and both sides");
    let (declared, mirror) = match declared {
        Side::Right => (0, side),
        Side::Left => (side, 0),
    };
    let on = |first: usize, q: usize| if q == 0 { 0 } else { q + first };
    (1..=side)
        .map(|k| {
            let (p, same, other) = (&planar[k], &hull[k + declared], &hull[k + mirror]);
            let parent = p.parent.expect("a part hangs from the frame or an arm");
            let moved_parent = BodyDescription {
                parent: Some(on(declared, parent)),
                ..*p
            };
            assert_eq!(*same, moved_parent, "declared body {k}");
            assert_eq!(other.parent, Some(on(mirror, parent)), "mirrored body {k}");
            assert_eq!(
                (other.mass, other.inertia, other.at_self),
                (p.mass, p.inertia, p.at_self)
            );
            let moved = other.at_parent - p.at_parent;
            assert!(
                parent == 0 || moved == Vector2::zeros(),
                "body {k} moved on its arm"
            );
            moved
        })
        .collect()
}

#[test]
fn the_hull_carries_both_sides_as_declared() {
    let planar = M113Chassis.description().bodies;
    let hull = M113Hull.description().bodies;
    let side = planar.len() - 1;
    assert_eq!(DH, hull.len() + 2);
    // The frame is the whole hull: twice the planar side's half.
    assert_eq!(hull[0].mass, CHASSIS_MASS);
    assert_eq!(hull[0].inertia, CHASSIS_INERTIA);
    // The left is the right but for the road wheels' arms' pivots, moved
    // with the wheels from Chrono's right stations to its left ones
    // (`m_susp_locs_R`, `_L`).
    const RIGHT: [f64; 5] = [-0.740, -1.407, -2.074, -2.740, -3.407];
    const LEFT: [f64; 5] = [-0.655, -1.322, -1.989, -2.656, -3.322];
    let moves = mirror_moves(&planar, &hull, Side::Right);
    let arms: Vec<usize> = (1..=side)
        .filter(|&k| planar.iter().any(|c| c.parent == Some(k)))
        .collect();
    assert_eq!(arms.len(), 6, "five road-wheel arms and the tensioner's");
    for (k, moved) in (1..=side).zip(&moves) {
        let expected = match arms.iter().position(|&a| a == k) {
            Some(i) if i < 5 => LEFT[i] - RIGHT[i],
            _ => 0.0,
        };
        assert!(
            (moved - Vector2::new(expected, 0.0)).norm() < 1e-12,
            "left body {k} moved {moved:?}"
        );
    }
    let layout = M113::layout();
    assert_eq!(layout.hull_offsets[0], 0.0);
    for k in 1..=side {
        assert_eq!(layout.hull_offsets[k], -GAUGE / 2.0, "right body {k}");
        assert_eq!(layout.hull_offsets[k + side], GAUGE / 2.0, "left body {k}");
    }
    let parts = layout.part_sides.len();
    assert!(
        layout.part_sides[..parts / 2]
            .iter()
            .all(|&s| s == Side::Right)
    );
    assert!(
        layout.part_sides[parts / 2..]
            .iter()
            .all(|&s| s == Side::Left)
    );
    assert_eq!(layout.gauge, GAUGE);
    assert_eq!(layout.shoe_width, m113::TRACK_WIDTH);
    assert_eq!(layout.guide_play, m113::GUIDE_PLAY);
    assert_eq!(layout.declared, Side::Right);
}

/// The Marder declares its left side: the right mirrors it with one shoe
/// more and every road wheel and roller 0.1 m forward (Chrono's
/// `Marder_TrackAssemblySinglePin`, `m_right_x_offset`), and the right
/// side still comes first in the hull.
#[test]
fn the_marder_mirrors_its_left_side() {
    let planar = MarderChassis.description().bodies;
    let hull = MarderHull.description().bodies;
    let moves = mirror_moves(&planar, &hull, Side::Left);
    let moved: Vec<&Vector2<f64>> = moves.iter().filter(|m| m.norm() > 0.0).collect();
    assert_eq!(moved.len(), 6 + 3, "six road-wheel arms and three rollers");
    assert!(
        moved
            .iter()
            .all(|m| (*m - Vector2::new(0.1, 0.0)).norm() < 1e-12)
    );
    let layout = Marder::layout();
    assert_eq!(layout.declared, Side::Left);
    assert_eq!(<Marder as SpatialVehicle>::LEFT_TRACK_DOF, 77 + 2);
    assert_eq!(<Marder as SpatialVehicle>::RIGHT_TRACK_DOF, 78 + 2);
    assert_eq!(MarderRightTrack.description().bodies.len(), 78);
    assert_eq!(
        (layout.right_links.len(), layout.left_links.len()),
        (78, 77)
    );
    let side = planar.len() - 1;
    for k in 1..=side {
        assert_eq!(
            layout.hull_offsets[k],
            -marder::GAUGE / 2.0,
            "right body {k}"
        );
        assert_eq!(
            layout.hull_offsets[k + side],
            marder::GAUGE / 2.0,
            "left body {k}"
        );
    }
}

#[test]
fn the_left_track_has_one_shoe_fewer() {
    assert_eq!(<M113 as SpatialVehicle>::LEFT_TRACK_DOF, 63 + 2);
    assert_eq!(<M113 as SpatialVehicle>::RIGHT_TRACK_DOF, 64 + 2);
    let left = M113LeftTrack.description().bodies;
    let right = M113Track.description().bodies;
    assert_eq!((left.len(), right.len()), (63, 64));
    assert!(
        left.iter().zip(&right).all(|(l, r)| l == r),
        "the same links"
    );
    let layout = M113::layout();
    assert_eq!(
        (layout.left_links.len(), layout.right_links.len()),
        (63, 64)
    );
    let declared = OutOfPlaneInertia {
        xx: 0.22,
        zz: 0.25,
        xz: 0.0,
    };
    assert!(
        layout
            .left_links
            .iter()
            .chain(&layout.right_links)
            .all(|&a| a == declared)
    );
}

/// The spatial vehicle weighs the published combat weight (27 200 lb, as
/// the planar declaration does, both sides counted) less the one shoe the
/// left track lacks: the hull's bodies and both tracks' links, summed.
#[test]
fn the_masses_add_up_to_the_combat_weight() {
    let sum = |bodies: Vec<BodyDescription>| bodies.iter().map(|b| b.mass).sum::<f64>();
    let total = sum(M113Hull.description().bodies)
        + sum(M113Track.description().bodies)
        + sum(M113LeftTrack.description().bodies);
    let expected = COMBAT_WEIGHT - SHOE_MASS;
    assert!(
        ((total - expected) / expected).abs() < 1e-12,
        "{total} kg against {expected} kg"
    );
}

/// The floating hull from the layout, turned rigidly about each of its
/// axes at the design position: its kinetic energy is `½ I ω²` with `I`
/// the frame's declared inertia plus every part's own (the layout's, by
/// the stated default rule) and `m d²` for its distance `d` from the axis
/// (in the plane and across it, the half gauge), summed here apart. The
/// left bodies sit at `+B/2` in the world (the lateral axis points left).
#[test]
fn the_floating_hull_has_the_inertia_its_bodies_add_up_to() {
    let layout = M113::layout();
    let bodies = M113Hull.description().bodies;
    // The road wheels' declared (Chrono's 1.14 kg m² about both axes),
    // every other part's and arm's by the stated rule.
    let wheels = [
        M113Hull::RIGHT_RW1,
        M113Hull::RIGHT_RW2,
        M113Hull::RIGHT_RW3,
        M113Hull::RIGHT_RW4,
        M113Hull::RIGHT_RW5,
        M113Hull::LEFT_RW1,
        M113Hull::LEFT_RW2,
        M113Hull::LEFT_RW3,
        M113Hull::LEFT_RW4,
        M113Hull::LEFT_RW5,
    ];
    for (k, b) in bodies.iter().enumerate().skip(1) {
        let expected = match wheels.contains(&k) {
            true => OutOfPlaneInertia {
                xx: 1.14,
                zz: 1.14,
                xz: 0.0,
            },
            false => OutOfPlaneInertia::extruded(b.mass, b.inertia, 0.0),
        };
        assert_eq!(layout.hull_across[k], expected, "body {k}");
    }
    let frame = OutOfPlaneInertia {
        xx: CHASSIS_ROLL_INERTIA,
        zz: CHASSIS_YAW_INERTIA,
        xz: 0.0,
    };
    assert_eq!(layout.hull_across[0], frame);
    let tree = FloatingTree::new(&M113Hull, layout.hull_across.clone())
        .and_then(|t| t.with_offsets(layout.hull_offsets.clone()))
        .expect("the declared layout makes a floating tree");
    let pose = PlanePose::<DH> {
        origin: Vector3::new(1.0, -2.0, 0.5),
        yaw: 0.0,
        roll: 0.0,
        planar: SVector::zeros(),
    };
    let places = design_places(&bodies);
    let world = tree.positions(&pose);
    for (k, p) in world.iter().enumerate() {
        let expected = pose.origin + Vector3::new(places[k].x, layout.hull_offsets[k], places[k].y);
        assert!(
            (p - expected).norm() < 1e-12,
            "body {k} at {p:?}, not {expected:?}"
        );
    }
    let sides = &layout.hull_offsets;
    let (mut roll, mut pitch, mut yaw) = (0.0, 0.0, 0.0);
    for (k, b) in bodies.iter().enumerate() {
        let (x, z, e, a) = (places[k].x, places[k].y, sides[k], layout.hull_across[k]);
        roll += a.xx + b.mass * (z * z + e * e);
        pitch += b.inertia + b.mass * (x * x + z * z);
        yaw += a.zz + b.mass * (x * x + e * e);
    }
    let omega = 0.7;
    let energy = |planar: SVector<f64, DH>, across: Vector3<f64>| {
        tree.kinetic_energy(&pose, &PlaneRates { planar, across })
    };
    let mut all_pitch = SVector::<f64, DH>::repeat(omega);
    (all_pitch[0], all_pitch[1]) = (0.0, 0.0);
    let checks = [
        (
            "roll",
            energy(SVector::zeros(), Vector3::new(0.0, omega, 0.0)),
            roll,
        ),
        ("pitch", energy(all_pitch, Vector3::zeros()), pitch),
        (
            "yaw",
            energy(SVector::zeros(), Vector3::new(0.0, 0.0, omega)),
            yaw,
        ),
    ];
    for (axis, found, inertia) in checks {
        let expected = 0.5 * inertia * omega * omega;
        assert!(
            ((found - expected) / expected).abs() < 1e-12,
            "{axis}: {found} J against {expected} J"
        );
    }
}

/// `FloatingTree::world` gives every body's place, orientation, velocity
/// and angular velocity as the four separate calls do, bit for bit, for
/// the M113's hull (its parts off the plane) turned, rolled and moving.
#[test]
fn the_world_motion_is_the_four_at_once() {
    let layout = M113::layout();
    let tree = FloatingTree::new(&M113Hull, layout.hull_across.clone())
        .and_then(|t| t.with_offsets(layout.hull_offsets.clone()))
        .expect("the hull floats");
    let pose = PlanePose::<DH> {
        origin: Vector3::new(1.0, -2.0, 0.5),
        yaw: 0.7,
        roll: -0.2,
        planar: SVector::from_fn(|i, _| 0.1 * (i as f64).sin()),
    };
    let rates = PlaneRates {
        planar: SVector::from_fn(|i, _| 0.3 * (1.7 * i as f64).cos()),
        across: Vector3::new(0.2, -0.1, 0.4),
    };
    let world = tree.world(&pose, &rates);
    assert_eq!(world.positions, tree.positions(&pose));
    assert_eq!(world.orientations, tree.orientations(&pose));
    assert_eq!(world.velocities, tree.velocities(&pose, &rates));
    assert_eq!(
        world.angular_velocities,
        tree.angular_velocities(&pose, &rates)
    );
}
