//! Both sides of a spatial vehicle placed at t = 0 (`assembly::assemble_sides`):
//! the declared M113's right side exactly as the planar vehicle assembles,
//! its left (63 shoes round road wheels 0.084–0.085 m further forward)
//! wrapped and tensioned by its own idler, both tracks resting on the
//! ground with the declared clearance, nothing starting inside anything
//! (the planar start check, per side); the Marder's 78-shoe right side
//! too; a side whose track cannot fit its wheels refused as that
//! side's, naming the link counts that would; and the start in space, the
//! hull and tracks as floating trees, touching as each side in its plane.

use crate::support::twin::{Twin, TwinHull, TwinTrack};
use trackgen::assembly::{AssemblyError, assemble, assemble_sides};
use trackgen::contact::axial::{RimContact, SpaceFace, SpaceSprocket, SpaceWheel};
use trackgen::contact::{BodyState, ShoeGeometry, sprocket, wheel};
use trackgen::multibody::{ChassisModel, PartKind, RecursiveModel, TrackModel};
use trackgen::nalgebra::{Matrix3, SVector, Vector2, Vector3};
use trackgen::spatial::{
    FloatingTree, OutOfPlaneInertia, PlanePose, Side, SpatialVehicle, plane_rotation,
};
use trackgen::terrain::Terrain;
use trackgen::vehicle::Vehicle;
use trackgen::vehicles::m113::{GAUGE, M113, M113Chassis, M113Hull, M113LeftTrack, M113Track};
use trackgen::vehicles::marder::{Marder, MarderHull, MarderRightTrack, MarderTrack};

/// The assembly's clearance between the lowest shoes and the ground, m
/// (the planar build's).
const CLEARANCE: f64 = 1e-3;

const FLAT: Terrain = Terrain::Flat { height: 0.0 };

/// The lowest ground point of any shoe of `track` at `q`, m.
fn lowest<T: TrackModel<D>, const D: usize>(
    track: &T,
    q: &SVector<f64, D>,
    points: &[Vector2<f64>],
) -> f64 {
    let mut r = vec![Vector2::zeros(); T::BODIES];
    track.body_positions(q, &mut r);
    r.iter()
        .zip(&q.as_slice()[2..])
        .flat_map(|(c, &theta)| {
            let (s, co) = theta.sin_cos();
            points.iter().map(move |p| c.y + s * p.x + co * p.y)
        })
        .fold(f64::INFINITY, f64::min)
}

#[test]
fn the_m113s_sides_assemble_its_right_as_the_planar_vehicle() {
    let geometry = M113::geometry();
    let layout = M113::layout();
    let sides = assemble_sides(
        &M113Hull,
        (&M113Track, &M113LeftTrack),
        &layout.part_sides,
        &geometry.shoe,
        &geometry.sprocket,
        &FLAT,
        0.0,
        CLEARANCE,
    )
    .expect("both sides of the declared M113 assemble");
    let planar = assemble(
        &M113Track,
        &M113Chassis,
        &geometry.shoe,
        &geometry.sprocket,
        &FLAT,
        0.0,
        CLEARANCE,
    )
    .expect("the planar M113 assembles");
    // The hull's frame and right side, and the right track: the planar
    // vehicle's to the last bit (the same steps on the same numbers).
    let side = M113Chassis::BODIES - 1;
    assert_eq!(
        sides.hull.rows(0, 3 + side),
        planar.chassis.rows(0, 3 + side)
    );
    assert_eq!(sides.right, planar.track);
    assert_eq!(sides.tensioners[0], planar.tensioner);
    // The left: its own tensioner, within its travel and set apart from
    // the right's (a shorter track round wheels further forward).
    let (arm, angle) = sides.tensioners[1].expect("the left idler is on an arm");
    assert_eq!(arm, M113Hull::LEFT_IDLER_ARM);
    let (right_arm, right_angle) = planar.tensioner.expect("tensioner");
    assert_eq!(right_arm, M113Hull::RIGHT_IDLER_ARM);
    assert!(angle.abs() < std::f64::consts::FRAC_PI_2, "{angle} rad");
    assert!(
        (angle - right_angle).abs() > 1e-3,
        "{angle} against {right_angle}"
    );
    // Both tracks closed, both on the ground.
    let points = &geometry.shoe.ground_points;
    for (which, low, gap) in [
        (
            "right",
            lowest(&M113Track, &sides.right, points),
            M113Track.closure(&sides.right).norm(),
        ),
        (
            "left",
            lowest(&M113LeftTrack, &sides.left, points),
            M113LeftTrack.closure(&sides.left).norm(),
        ),
    ] {
        assert!(gap < 1e-9, "the {which} loop is open by {gap} m");
        assert!(
            (low - CLEARANCE).abs() < 1e-6,
            "the {which} track's lowest shoe at {low} m"
        );
    }
    assert_eq!(<M113 as SpatialVehicle>::LEFT_TRACK_DOF, sides.left.len());
}

#[test]
fn the_marders_sides_assemble() {
    let geometry = Marder::geometry();
    let layout = Marder::layout();
    let sides = assemble_sides(
        &MarderHull,
        (&MarderRightTrack, &MarderTrack),
        &layout.part_sides,
        &geometry.shoe,
        &geometry.sprocket,
        &FLAT,
        0.0,
        CLEARANCE,
    )
    .expect("both sides of the declared Marder assemble");
    let points = &geometry.shoe.ground_points;
    let lows = [
        lowest(&MarderRightTrack, &sides.right, points),
        lowest(&MarderTrack, &sides.left, points),
    ];
    assert!(lows.iter().all(|&l| l >= CLEARANCE - 1e-6), "{lows:?}");
    assert!((lows[0].min(lows[1]) - CLEARANCE).abs() < 1e-6, "{lows:?}");
    assert!(MarderRightTrack.closure(&sides.right).norm() < 1e-9);
    assert!(MarderTrack.closure(&sides.left).norm() < 1e-9);
}

trackgen::model! {
    /// The `Twin`'s track, ten links short.
    pub track Short45 {
        links: 45,
        link { mass: 6.0, inertia: 0.01, u1: (-0.06, 0.0), u2: (0.06, 0.0) },
    }
}

#[test]
fn a_side_that_cannot_fit_is_refused_as_that_sides() {
    let geometry = Twin::geometry();
    let error = assemble_sides(
        &TwinHull,
        (&TwinTrack, &Short45),
        &Twin::layout().part_sides,
        &geometry.shoe,
        &geometry.sprocket,
        &FLAT,
        0.0,
        CLEARANCE,
    )
    .expect_err("45 links cannot wrap wheels that take 55");
    assert_eq!(error.side, Side::Left);
    match &error.error {
        AssemblyError::TrackTooShort {
            links: 45, fits, ..
        } => {
            assert!(fits.range().contains(&55), "{fits}");
        }
        other => panic!("not too short: {other}"),
    }
    let message = error.to_string();
    assert!(
        message.starts_with("the left side: 45 links are"),
        "{message}"
    );
}

/// The assembled M113 in space, its hull pressed into the tracks and its
/// sprockets turned against them: the hull and both tracks as floating
/// trees at their planes (the hull's at the centre line, each track's
/// half a gauge out), every rim and tooth contact found in space
/// (`contact::axial`, from the trees' world poses) is the one the planar
/// detection finds in that side's plane, to rounding, and every guide
/// sits on its wheel's plane. What this holds together: the trees'
/// world poses, the side offsets' signs and the contacts' axes.
#[test]
fn the_start_in_space_touches_as_each_side_in_its_plane() {
    let geometry = M113::geometry();
    let layout = M113::layout();
    let sides = assemble_sides(
        &M113Hull,
        (&M113Track, &M113LeftTrack),
        &layout.part_sides,
        &geometry.shoe,
        &geometry.sprocket,
        &FLAT,
        0.0,
        CLEARANCE,
    )
    .expect("both sides assemble");
    // The hull 3 mm down into the tracks' lower runs and both sprockets
    // turned 0.12 rad against their pins: contacts to compare.
    let mut sides = sides;
    sides.hull[1] -= 0.003;
    for sprocket in [M113Hull::RIGHT_SPROCKET, M113Hull::LEFT_SPROCKET] {
        sides.hull[2 + sprocket] += 0.12;
    }
    let hull = FloatingTree::new(&M113Hull, layout.hull_across.clone())
        .and_then(|t| t.with_offsets(layout.hull_offsets.clone()))
        .expect("the hull floats");
    let qh = sides.hull.as_slice();
    let hull_pose = plane_pose::<DH_M113>((Vector3::new(qh[0], 0.0, qh[1]), qh));
    let (hull_at, hull_turned) = (hull.positions(&hull_pose), hull.orientations(&hull_pose));
    let half = GAUGE / 2.0;
    let mut found = [[0; 2]; 2];
    for (s, side) in [Side::Right, Side::Left].into_iter().enumerate() {
        let (links_at, links_turned, planar_links) = match side {
            Side::Right => track_in_space(
                &M113Track,
                &layout.right_links,
                sides.right.as_slice(),
                -half,
            ),
            Side::Left => track_in_space(
                &M113LeftTrack,
                &layout.left_links,
                sides.left.as_slice(),
                half,
            ),
        };
        for (part, _) in M113Hull::PARTS
            .iter()
            .zip(&layout.part_sides)
            .filter(|(_, s)| **s == side)
        {
            let (centre, turned) = (hull_at[part.body], hull_turned[part.body]);
            assert!(
                (centre.y - side.sign() * half).abs() < 1e-15,
                "{} at {centre:?}",
                part.name
            );
            let planar_part =
                BodyState::at_rest(Vector2::new(centre.x, centre.z), sides.hull[2 + part.body]);
            let mut planar = Vec::new();
            let mut space = Vec::new();
            if part.kind == PartKind::Sprocket {
                sprocket::detect(
                    (&planar_part, part.body),
                    &geometry.sprocket,
                    &planar_links,
                    &geometry.shoe,
                    &mut planar,
                );
                let sprocket = SpaceSprocket {
                    centre,
                    axes: [turned_plane(&hull_pose).0, turned_plane(&hull_pose).2],
                    angle: sides.hull[2 + part.body],
                    velocity: Vector3::zeros(),
                    angular_velocity: Vector3::zeros(),
                };
                for (i, (r, a)) in links_at.iter().zip(&links_turned).enumerate() {
                    let face = face_in_space(&geometry.shoe, *r, a);
                    for (k, pin) in geometry.shoe.pins.iter().enumerate() {
                        let at = r + a * Vector3::new(pin.x, 0.0, pin.y);
                        if let Some(c) = sprocket.pin_contact(
                            &geometry.sprocket,
                            &face,
                            at,
                            geometry.shoe.pin_radius,
                        ) {
                            space.push((i, k, c.depth, c.point));
                        }
                    }
                }
            } else {
                wheel::detect(
                    (&planar_part, part.body, part.radius),
                    &planar_links,
                    &geometry.shoe,
                    &mut planar,
                );
                let wheel = SpaceWheel {
                    centre,
                    axle: turned.column(1).into(),
                    radius: part.radius,
                    velocity: Vector3::zeros(),
                    angular_velocity: Vector3::zeros(),
                };
                for (i, (r, a)) in links_at.iter().zip(&links_turned).enumerate() {
                    if let Some(rim) =
                        RimContact::detect(&wheel, &face_in_space(&geometry.shoe, *r, a))
                    {
                        assert!(
                            rim.offset.abs() < 1e-12,
                            "guide {} m off {}",
                            rim.offset,
                            part.name
                        );
                        space.push((i, 0, rim.contact.depth, rim.contact.point));
                    }
                }
            }
            assert_eq!(
                space.len(),
                planar.len(),
                "{}'s contacts on the {side:?}",
                part.name
            );
            for ((i, k, depth, point), c) in space.iter().zip(&planar) {
                assert_eq!((*i, *k), (c.link, c.feature));
                assert!(
                    (depth - c.depth).abs() < 1e-12,
                    "{depth} against {}",
                    c.depth
                );
                let expected = Vector3::new(c.point.x, side.sign() * half, c.point.y);
                assert!(
                    (point - expected).norm() < 1e-12,
                    "{point:?} against {expected:?}"
                );
            }
            found[s][usize::from(part.kind == PartKind::Sprocket)] += planar.len();
        }
    }
    // Rims and teeth, each side.
    assert!(
        found.iter().flatten().all(|&n| n >= 2),
        "contacts per side, rims and teeth: {found:?}"
    );
}

/// Hull coordinates of the M113.
const DH_M113: usize = <M113 as SpatialVehicle>::HULL_DOF;

/// A tree's pose upright at yaw 0: its root's centroid (world) and its
/// planar coordinates.
fn plane_pose<const D: usize>((origin, q): (Vector3<f64>, &[f64])) -> PlanePose<D> {
    let mut planar = SVector::<f64, D>::from_column_slice(q);
    (planar[0], planar[1]) = (0.0, 0.0);
    PlanePose {
        origin,
        yaw: 0.0,
        roll: 0.0,
        planar,
    }
}

/// The plane's forward, lateral and up axes.
fn turned_plane<const D: usize>(pose: &PlanePose<D>) -> (Vector3<f64>, Vector3<f64>, Vector3<f64>) {
    let a = plane_rotation(pose.yaw, pose.roll);
    (a.column(0).into(), a.column(1).into(), a.column(2).into())
}

/// A track in space half a gauge out: its links' world centroids and
/// orientations, and their planar states in their plane.
fn track_in_space<T: TrackModel<D>, const D: usize>(
    track: &T,
    across: &[OutOfPlaneInertia],
    q: &[f64],
    lateral: f64,
) -> (Vec<Vector3<f64>>, Vec<Matrix3<f64>>, Vec<BodyState>) {
    let tree = FloatingTree::new(track, across.to_vec()).expect("the track floats");
    let pose = plane_pose::<D>((Vector3::new(q[0], lateral, q[1]), q));
    let mut planar = vec![Vector2::zeros(); T::BODIES];
    track.body_positions(&SVector::from_column_slice(q), &mut planar);
    let states = planar
        .iter()
        .zip(&q[2..])
        .map(|(p, a)| BodyState::at_rest(*p, *a))
        .collect();
    (tree.positions(&pose), tree.orientations(&pose), states)
}

/// A link's running face and guide in space, at rest.
fn face_in_space(shoe: &ShoeGeometry, centroid: Vector3<f64>, turned: &Matrix3<f64>) -> SpaceFace {
    let at = |p: Vector2<f64>| centroid + turned * Vector3::new(p.x, 0.0, p.y);
    SpaceFace {
        ends: shoe.inner_face.map(at),
        inward: turned.column(2).into(),
        guide: at(Vector2::new(0.045, shoe.inner_offset())),
        centroid,
        velocity: Vector3::zeros(),
        angular_velocity: Vector3::zeros(),
    }
}
