//! The spatial vehicle drawn (`SpatialSystem::scene`, what `spatial`'s
//! `animation.html` plays) against its declared geometry: each track's
//! joints a pitch apart round the loop and in its plane, each wheel at its
//! side's offset, the hull's outline carried rigidly; and the whole scene
//! moved as a rigid body with the vehicle; the floor under it as the
//! ground is, on soft soil with its rut.

use trackgen::integrate::{Integrator, OdeSystem};
use trackgen::multibody::RecursiveModel;
use trackgen::nalgebra::{Rotation3, Vector2, Vector3};
use trackgen::spatial::SpatialVehicle;
use trackgen::spatial_vehicle::{SideDrives, SpatialLaws, SpatialScene, SpatialSystem};
use trackgen::terrain::field::HeightField;
use trackgen::terrain::soil::SoilPreset;
use trackgen::vehicle::Drive;

use crate::support::twin::{System, TRACK, Twin, at_rest, laws, on, spatial};

/// A side view to draw the hull by, m in its centroid frame.
fn outline() -> Vec<Vector2<f64>> {
    [(-1.2, 0.1), (1.0, 0.1), (1.3, 0.6), (-1.2, 0.8)]
        .map(|(x, z)| Vector2::new(x, z))
        .to_vec()
}

/// The `Twin` at rest turned `heading` rad with its hull's root at
/// `place`, drawn.
fn drawn(heading: f64, place: (f64, f64)) -> SpatialScene {
    let system: System = SpatialSystem::new(spatial());
    let (hull, right, left) = at_rest(heading, place);
    let y = system.state(&hull, &right, &left);
    system.scene(0.0, y.as_slice(), &outline())
}

/// Every point of a scene, in one order.
fn points(scene: &SpatialScene) -> Vec<Vector3<f64>> {
    let mut all = vec![scene.centre];
    all.extend(&scene.outline);
    all.extend(&scene.top);
    all.extend(scene.tracks.iter().flatten());
    all.extend(scene.wheels.iter().map(|w| w.0));
    all
}

/// Each track's joints are a pitch apart round the loop: to 1e-12 of the
/// pitch along the chain, whose joints the recursive coordinates hold
/// together exactly, and to 1e-6 across the cut joint, which the
/// assembly closed to its tolerance; the first joint is repeated at the
/// end. Each track's joints lie in its plane, half the gauge to its side
/// (the right's at `y < 0`), and each wheel at its body's offset on its
/// side (as many on either side of the mirrored `Twin`), to 1e-12 m.
#[test]
fn the_tracks_and_wheels_are_drawn_where_the_vehicle_is() {
    let scene = drawn(0.0, (0.0, 0.0));
    let pitch = TRACK.description().pitch().expect("one pitch");
    let layout = Twin::layout();
    for (s, track) in scene.tracks.iter().enumerate() {
        let n = track.len() - 1;
        assert_eq!(track[0], track[n], "the loop closed in the drawing");
        for k in 0..n {
            let apart = (track[k + 1] - track[k]).norm();
            let tolerance = if k + 1 == n { 1e-6 } else { 1e-12 };
            assert!(
                (apart - pitch).abs() < tolerance * pitch,
                "side {s}, joint {k}: {apart} m against a pitch of {pitch} m"
            );
        }
        let lateral = [-0.5, 0.5][s] * layout.gauge;
        for joint in track {
            assert!((joint.y - lateral).abs() < 1e-12, "side {s}: {joint}");
        }
    }
    // The mirrored `Twin`: as many wheels on either side.
    let right = scene.wheels.iter().filter(|w| w.2 == 0).count();
    assert!(
        right > 0 && 2 * right == scene.wheels.len(),
        "{:?}",
        scene.wheels
    );
    for (centre, radius, side) in &scene.wheels {
        assert!(*radius > 0.0);
        let sign = [-1.0, 1.0][*side];
        assert!(centre.y * sign > 0.0, "{centre} on side {side}");
        assert!(
            layout
                .hull_offsets
                .iter()
                .any(|offset| (centre.y - offset).abs() < 1e-12),
            "{centre}: at none of the hull's offsets {:?}",
            layout.hull_offsets
        );
    }
    // The outline in the hull's plane, rigidly: its sides as declared.
    let local = outline();
    for i in 0..local.len() {
        assert!(scene.outline[i].y.abs() < 1e-12, "{}", scene.outline[i]);
        let j = (i + 1) % local.len();
        let declared = (local[j] - local[i]).norm();
        let drawn = (scene.outline[j] - scene.outline[i]).norm();
        assert!(
            (drawn - declared).abs() < 1e-12,
            "{drawn} against {declared}"
        );
    }
}

/// The vehicle turned 0.7 rad and moved to (3, −2) m is drawn as its
/// drawing at the origin turned and moved so, every point and axis to
/// 1e-12 of the scene's size.
#[test]
fn the_scene_moves_with_the_vehicle() {
    let (heading, place) = (0.7, (3.0, -2.0));
    let home = drawn(0.0, (0.0, 0.0));
    let moved = drawn(heading, place);
    let turn = Rotation3::from_axis_angle(&Vector3::z_axis(), heading);
    let shift = Vector3::new(place.0, place.1, 0.0);
    let (a, b) = (points(&home), points(&moved));
    assert_eq!(a.len(), b.len());
    for (p, q) in a.iter().zip(&b) {
        let want = turn * p + shift;
        assert!((q - want).norm() < 1e-12 * 10.0, "{q} against {want}");
    }
    for (p, q) in home.axes.iter().zip(&moved.axes) {
        assert!((q - turn * p).norm() < 1e-12, "{q} against {}", turn * p);
    }
}

/// The side view's floor is the ground under the right track as it is:
/// on level rigid ground, level with the ground at every sample, from
/// 6 m behind the centroid to 6 m ahead every 0.1 m; on dry sand, after
/// the carrier has settled 0.5 s, the rut under it lies below the level
/// (by its plastic sinkage, as the soil remembers it), and the sand
/// ahead and behind is untouched.
#[test]
fn the_floor_is_the_ground_under_the_right_track_as_it_is() {
    let scene = drawn(0.0, (0.0, 0.0));
    assert_eq!(scene.floor.len(), 121);
    for (i, p) in scene.floor.iter().enumerate() {
        assert!((p.x - (-6.0 + 0.1 * i as f64)).abs() < 1e-12, "{p}");
        assert_eq!(p.y, -scene.centre.z, "{p}");
    }
    let sand = SpatialLaws {
        soil: Some(SoilPreset::DrySand.soil()),
        ..laws()
    };
    let still = || Drive::Torque(Box::new(|_| 0.0));
    let mut system = on(
        HeightField::level(),
        sand,
        SideDrives {
            right: still(),
            left: still(),
        },
    );
    let (hull, right, left) = at_rest(0.0, (0.0, 0.0));
    let mut y = system.state(&hull, &right, &left);
    let mut stepper = Integrator::bs23(1e-4).stepper(system.dimension());
    let mut t = 0.0;
    while t < 0.5 {
        stepper
            .step(&mut system, &mut t, &mut y, 0.5)
            .expect("settles");
        if system.after_step(t, y.as_slice()) {
            stepper.restart();
        }
    }
    let scene = system.scene(t, y.as_slice(), &outline());
    // The deepest sample within `reach` m of `u`: the footprints along a
    // shoe leave gaps (the guide's "In space"), so a single sample may
    // fall in one.
    let depth = |u: f64, reach: f64| {
        scene
            .floor
            .iter()
            .filter(|p| (p.x - u).abs() <= reach)
            .map(|p| -scene.centre.z - p.y)
            .fold(f64::MIN, f64::max)
    };
    let under = depth(0.0, 0.5);
    println!("the rut under the carrier {under:.4} m");
    assert!(under > 0.01, "the rut under the carrier: {under} m");
    assert_eq!(depth(6.0, 1.0), 0.0);
    assert_eq!(depth(-6.0, 1.0), 0.0);
}
