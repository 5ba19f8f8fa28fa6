//! Both sides of a spatial vehicle placed at t = 0 (`assembly::assemble_sides`):
//! the declared M113's right side exactly as the planar vehicle assembles,
//! its left (63 shoes round road wheels 0.084–0.085 m further forward)
//! wrapped and tensioned by its own idler, both tracks resting on the
//! ground with the declared clearance, nothing starting inside anything
//! (the planar start check, per side); the Marder's 78-shoe right side
//! too; and a side whose track cannot fit its wheels refused as that
//! side's, naming the link counts that would.

use trackgen::assembly::{AssemblyError, assemble, assemble_sides};
use trackgen::multibody::{RecursiveModel, TrackModel};
use trackgen::nalgebra::{SVector, Vector2};
use trackgen::spatial::{Side, SpatialVehicle};
use trackgen::terrain::Terrain;
use trackgen::vehicle::Vehicle;
use trackgen::vehicles::m113::{M113, M113Chassis, M113Hull, M113LeftTrack, M113Track};
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
    /// A light carrier whose left track is ten links short.
    pub vehicle Short {
        chassis { mass: 2400.0, inertia: 3800.0, centroid: (-1.3, 0.35) },
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
        tracks {
            gauge: 1.8,
            hull { mass: 4800.0, inertia: (2000.0, 7600.0, 8400.0) },
            left { links: 45 },
        },
    }
}

#[test]
fn a_side_that_cannot_fit_is_refused_as_that_sides() {
    let geometry = Short::geometry();
    let error = assemble_sides(
        &ShortHull,
        (&ShortTrack, &ShortLeftTrack),
        &Short::layout().part_sides,
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
