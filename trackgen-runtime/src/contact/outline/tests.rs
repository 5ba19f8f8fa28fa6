//! A terrain corner against an outline: the depth is the distance to the
//! nearest side, the force the potential's gradient, the tangent the
//! differences'; the shoe's outline; the hull's corners below the ground.

use nalgebra::Vector2;

use super::*;
use crate::contact::ContactLaws;
use crate::laws::{Friction, NormalLaw};
use crate::terrain::Terrain;
use crate::terrain::profile::Course;

/// A step 0.3 m high at x = 1: its top edge, (1, 0.3), is a 90° corner.
fn step() -> Terrain {
    let course = Course::starting_at(-5.0, 0.0)
        .unwrap()
        .flat(6.0)
        .unwrap()
        .step(0.3)
        .unwrap()
        .flat(5.0)
        .unwrap();
    Terrain::profile(course.profile().unwrap())
}

/// A 0.4 × 0.2 box, as a hull or a fat shoe.
fn box_outline() -> Outline {
    Outline::new(&[
        Vector2::new(-0.2, -0.1),
        Vector2::new(0.2, -0.1),
        Vector2::new(0.2, 0.1),
        Vector2::new(-0.2, 0.1),
    ])
    .unwrap()
}

fn body(x: f64, y: f64, angle: f64) -> BodyState {
    BodyState::new(Vector2::new(x, y), angle, Vector2::zeros(), 0.0)
}

fn corner_contacts(terrain: &Terrain, state: &BodyState) -> Vec<Contact> {
    let mut out = Vec::new();
    detect_corners(terrain, (state, 3), &box_outline(), &mut out);
    out
}

/// The distance from `p` to the segment `a b`.
fn segment_distance(p: Vector2<f64>, a: Vector2<f64>, b: Vector2<f64>) -> f64 {
    let t = ((p - a).dot(&(b - a)) / (b - a).norm_squared()).clamp(0.0, 1.0);
    (a + (b - a) * t - p).norm()
}

#[test]
fn depth_is_the_distance_to_the_nearest_side() {
    let outline = box_outline();
    let corners = outline.corners().to_vec();
    for i in 0..40 {
        for j in 0..20 {
            let p = Vector2::new(-0.21 + 0.0105 * i as f64, -0.105 + 0.0105 * j as f64);
            let inside = p.x.abs() < 0.2 && p.y.abs() < 0.1;
            match outline.depth(p) {
                Some((depth, _)) => {
                    assert!(inside, "{p:?}");
                    let nearest = (0..4)
                        .map(|k| segment_distance(p, corners[k], corners[(k + 1) % 4]))
                        .fold(f64::INFINITY, f64::min);
                    assert!(
                        (depth - nearest).abs() < 1e-15,
                        "{p:?}: {depth} vs {nearest}"
                    );
                }
                None => assert!(!inside, "{p:?}"),
            }
        }
    }
}

/// The force the corner puts on the body, as a point force at the corner
/// along the side's inward normal, is `−∂U/∂(x, y, θ)` of the contact's
/// potential `U(δ(pose))` (central differences, step 1e-6: the
/// differences' truncation is ~1e-12 of the force; bound 1e-7 relative).
#[test]
fn the_force_is_the_gradient_of_the_potential() {
    let terrain = step();
    let laws = ContactLaws {
        normal: NormalLaw::HuntCrossley {
            stiffness: 2e6,
            exponent: 1.5,
            chi: 0.0,
        },
        friction: Friction { mu: 0.0, slip: 0.5 },
    };
    let potential = |x: f64, y: f64, a: f64| -> f64 {
        corner_contacts(&terrain, &body(x, y, a))
            .iter()
            .map(|c| laws.respond(c).potential)
            .sum()
    };
    // The body over the step's top edge, tilted: the corner inside,
    // nearest its bottom side at some poses and its front at others.
    for (x, y, a) in [(1.1, 0.38, 0.2), (0.85, 0.35, -0.3), (1.05, 0.33, 0.05)] {
        let contacts = corner_contacts(&terrain, &body(x, y, a));
        assert_eq!(contacts.len(), 1, "at ({x}, {y}, {a})");
        let c = contacts[0];
        assert_eq!((c.link, c.feature), (3, TERRAIN_CORNER));
        let f = laws.respond(&c);
        let moment = c.arm.x * f.force.y - c.arm.y * f.force.x;
        let h = 1e-6;
        let grad = [
            (potential(x + h, y, a) - potential(x - h, y, a)) / (2.0 * h),
            (potential(x, y + h, a) - potential(x, y - h, a)) / (2.0 * h),
            (potential(x, y, a + h) - potential(x, y, a - h)) / (2.0 * h),
        ];
        let scale = f.force.norm();
        for (got, want) in [f.force.x, f.force.y, moment].iter().zip(grad) {
            assert!(
                (got + want).abs() < 1e-7 * scale,
                "at ({x}, {y}, {a}): force {got} against −∂U {}",
                -want
            );
        }
    }
}

/// `tangent`'s depth and gradient rows against central differences
/// (step 1e-7, to 1e-7) of the contact `contact_at` detects with the body
/// at each pose `(x, y, θ)` about `pose`; the contact point is the corner,
/// fixed.
fn tangent_against_differences(
    contact_at: impl Fn([f64; 3]) -> Contact,
    pose: [f64; 3],
    tangent: &GeometryTangent,
) {
    let h = 1e-7;
    for k in 0..3 {
        let (mut plus, mut minus) = (pose, pose);
        plus[k] += h;
        minus[k] -= h;
        let (cp, cm) = (contact_at(plus), contact_at(minus));
        let depth = (cp.depth - cm.depth) / (2.0 * h);
        assert!(
            (tangent.depth[k] - depth).abs() < 1e-7,
            "∂δ/∂{k}: {} vs {depth}",
            tangent.depth[k]
        );
        let g = (cp.gradient - cm.gradient) / (2.0 * h);
        for (row, diff) in [g.x, g.y].into_iter().enumerate() {
            assert!(
                (tangent.gradient[(row, k)] - diff).abs() < 1e-7,
                "∂g{row}/∂{k}: {} vs {diff}",
                tangent.gradient[(row, k)]
            );
        }
        assert_eq!((cp.point - cm.point).norm(), 0.0);
        assert_eq!(tangent.point.column(k).norm(), 0.0);
    }
}

/// [`tangent`]'s depth and gradient rows against central differences of
/// the detected contact over the body's pose.
#[test]
fn tangent_matches_differences() {
    let terrain = step();
    let contact_at = |p: [f64; 3]| corner_contacts(&terrain, &body(p[0], p[1], p[2]))[0];
    let pose = [1.1, 0.38, 0.2];
    tangent_against_differences(contact_at, pose, &tangent(&contact_at(pose)));
}

/// The M113's shoe: two ground points and the inner face make a
/// rectangle 0.154 m long (the face spans the pitch), 0.06 m high.
#[test]
fn a_shoes_outline_is_the_hull_of_its_features() {
    let shoe = ShoeGeometry {
        ground_points: vec![Vector2::new(-0.06, -0.03), Vector2::new(0.06, -0.03)],
        inner_face: [Vector2::new(-0.077, 0.03), Vector2::new(0.077, 0.03)],
        pins: vec![Vector2::new(0.0535, 0.0)],
        pin_radius: 0.015,
        width: None,
    };
    let outline = Outline::of_shoe(&shoe).unwrap();
    assert_eq!(outline.corners().len(), 4);
    assert!(outline.depth(Vector2::new(0.0, 0.0)).is_some());
    // Between the two ground points, 1 mm up from the ground face: inside.
    let (depth, normal) = outline.depth(Vector2::new(0.0, -0.029)).unwrap();
    assert!((depth - 0.001).abs() < 1e-12);
    assert!((normal - Vector2::new(0.0, 1.0)).norm() < 1e-12);
    // A shoe of one point on its pitch line has no area.
    let thin = ShoeGeometry {
        ground_points: vec![Vector2::new(0.0, 0.0)],
        inner_face: [Vector2::new(-0.077, 0.0), Vector2::new(0.077, 0.0)],
        ..shoe
    };
    assert!(Outline::of_shoe(&thin).is_none());
}

/// Only sharp corners count: a half-round's facets and a gentle ramp's
/// vertices are left to the ground points; a step's top edge is one.
#[test]
fn only_sharp_corners_count() {
    let course = Course::starting_at(-5.0, 0.0)
        .unwrap()
        .flat(5.0)
        .unwrap()
        .half_round(0.3)
        .unwrap()
        .flat(2.0)
        .unwrap()
        .step(0.2)
        .unwrap()
        .flat(3.0)
        .unwrap();
    let terrain = Terrain::profile(course.profile().unwrap());
    let sharp: Vec<_> = sharp_corners(&terrain, -10.0, 20.0).collect();
    // The step's top edge alone: the half-round's feet turn the ground
    // up (concave), its crest's facets by a few degrees each.
    assert_eq!(sharp.len(), 1, "{sharp:?}");
    assert!(
        (sharp[0] - Vector2::new(2.6, 0.2)).norm() < 1e-12,
        "{sharp:?}"
    );
    assert_eq!(
        sharp_corners(&Terrain::Flat { height: 0.0 }, -10.0, 10.0).count(),
        0
    );
}

/// The hull's corners below the ground are contacts numbered by corner,
/// measured as the ground points are; a hull clear of the ground has none.
#[test]
fn hull_corners_below_the_ground() {
    let flat = Terrain::Flat { height: 0.0 };
    let mut out = Vec::new();
    detect_hull(&flat, &body(0.0, 0.08, 0.0), &box_outline(), &mut out);
    assert_eq!(out.len(), 2);
    for c in &out {
        assert!(c.feature < 4);
        assert!((c.depth - 0.02).abs() < 1e-15);
        assert!((c.gradient - Vector2::new(0.0, 1.0)).norm() < 1e-15);
    }
    out.clear();
    detect_hull(&flat, &body(0.0, 0.5, 0.3), &box_outline(), &mut out);
    assert!(out.is_empty());
    // A NaN pose is not culled, high above the ground as its numbers may
    // be: its corners are looked at, and their depths are NaN (so is the
    // force, and the run stops with the cause).
    let waves = Terrain::Sine {
        amplitude: 0.05,
        wavelength: 2.0,
    };
    for pose in [
        (f64::NAN, 0.5, 0.0),
        (0.0, f64::NAN, 0.0),
        (0.0, 0.5, f64::NAN),
    ] {
        out.clear();
        detect_hull(
            &waves,
            &body(pose.0, pose.1, pose.2),
            &box_outline(),
            &mut out,
        );
        assert!(!out.is_empty(), "{pose:?}");
        assert!(out.iter().all(|c| c.depth.is_nan()), "{pose:?}");
    }
}

/// The profile's list of sharp corners, searched by range, is the scan of
/// every corner in the range kept by [`Corner::is_sharp`], on a rough
/// course (many corners, some sharp) over ranges of every size.
#[test]
fn sharp_corners_by_range_are_the_scans() {
    use crate::terrain::roughness::{Iso8608Class, RoughCourse, SPACING, Spectrum};
    let profile = RoughCourse::new(Spectrum::Iso8608(Iso8608Class::F), 50.0, SPACING, 3)
        .profile()
        .unwrap();
    let total = profile.sharp_points_in(-1e9, 1e9).count();
    assert!(
        total > 10 && total < profile.point_count(),
        "{total} sharp corners"
    );
    for k in 0..200 {
        let x0 = -1.0 + 0.26 * k as f64;
        for width in [0.0, 0.05, 0.3, 2.0, 60.0] {
            let listed: Vec<(f64, f64)> = profile.sharp_points_in(x0, x0 + width).collect();
            let scanned: Vec<(f64, f64)> = profile
                .corners_in(x0, x0 + width)
                .filter(|c| c.is_sharp())
                .map(|c| c.point)
                .collect();
            assert_eq!(listed, scanned, "[{x0}, {}]", x0 + width);
        }
    }
}

/// A rim on a step's edge: as deep as the radius less the distance to its
/// centre, pushed straight away from the corner; its potential's gradient
/// is that point force (no moment: the line passes through the centre).
#[test]
fn a_rim_on_a_corner() {
    let terrain = step();
    let laws = ContactLaws {
        normal: NormalLaw::HuntCrossley {
            stiffness: 2e6,
            exponent: 1.0,
            chi: 0.0,
        },
        friction: Friction { mu: 0.0, slip: 0.5 },
    };
    let contacts = |x: f64, y: f64| {
        let mut out = Vec::new();
        detect_rim(&terrain, (&body(x, y, 0.7), 5, 0.3), &mut out);
        out
    };
    let (x, y) = (0.85, 0.5);
    let found = contacts(x, y);
    assert_eq!(found.len(), 1);
    let c = found[0];
    let centre = Vector2::new(x, y);
    let corner = Vector2::new(1.0, 0.3);
    assert_eq!(c.link, 5);
    assert!((c.depth - (0.3 - (corner - centre).norm())).abs() < 1e-15);
    let f = laws.respond(&c);
    assert!((c.arm.x * f.force.y - c.arm.y * f.force.x).abs() < 1e-9 * f.force.norm());
    let potential = |x: f64, y: f64| -> f64 {
        contacts(x, y)
            .iter()
            .map(|c| laws.respond(c).potential)
            .sum()
    };
    let h = 1e-6;
    let gx = (potential(x + h, y) - potential(x - h, y)) / (2.0 * h);
    let gy = (potential(x, y + h) - potential(x, y - h)) / (2.0 * h);
    assert!((f.force.x + gx).abs() < 1e-7 * f.force.norm());
    assert!((f.force.y + gy).abs() < 1e-7 * f.force.norm());
    // Clear of the corner: nothing.
    assert!(contacts(0.5, 0.7).is_empty());
}

/// [`rim_tangent`]'s depth and gradient rows against central differences
/// of the detected rim contact over the body's pose (the angle too: the
/// rim is round, so turning it changes neither).
#[test]
fn rim_tangent_matches_differences() {
    let terrain = step();
    let contact_at = |p: [f64; 3]| {
        let mut out = Vec::new();
        detect_rim(&terrain, (&body(p[0], p[1], p[2]), 2, 0.3), &mut out);
        out[0]
    };
    let pose = [0.85, 0.5, 0.7];
    let t = rim_tangent(&contact_at(pose));
    tangent_against_differences(contact_at, pose, &t);
    // Not zero: the test can fail.
    assert!(t.gradient.norm() > 1.0);
}
