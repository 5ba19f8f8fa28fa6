//! Track assembly (`trackgen::assembly::wrap`) and vehicle set-up
//! (`VehicleSystem::new`): every error variant is returned for the input
//! that should cause it, with its fields and its message checked; and a
//! successful wrap is checked for what it promises: joints one pitch apart
//! along the belt (tangent lines, arcs on the pitch circles, one circular
//! sagging span), the last joint landing on the first, and coordinates
//! `q_i` that put every link's joints on them and close the loop.
//!
//! Tolerances, and why:
//! * Joint spacing, loop closure and joints on the belt: `1e-9` m (the
//!   brief's figure). The joints are found by bisection to ~1e-16 m of arc
//!   length per joint and the sag by bisection to ~1e-17 m, so rounding
//!   over the 17-19 joints leaves ~1e-14 m; the model's positions from
//!   `q_i` accumulate one rotation per link, ~1e-15 m each. An error in
//!   the wrap (a wrong tangent, a sag in the wrong span, a link laid along
//!   the arc instead of the chord) is ≥ 1e-3 m.
//! * Messages are compared as whole strings: they are formatted with a
//!   fixed number of decimals, so the text is exact.
//! * The sprocket's pitch radius `p / (2 sin(π/z))` by hand: `1e-15`
//!   relative (one sine and one division).

mod support;

use trackgen::TrackModel;
use trackgen::assembly::{AssemblyError, PitchCircle, wrap};
use trackgen::closure::ClosureMethod;
use trackgen::contact::sprocket::ToothProfile;
use trackgen::contact::{ShoeGeometry, Terrain};
use trackgen::nalgebra::{SVector, Vector2};
use trackgen::simulate::SimulationError;
use trackgen::vehicle::{Drive, VehicleConfig, VehicleSystem, assemble};
use trackgen::vehicles::m113::{CHASSIS_DOF, M113Chassis, M113Track, TRACK_DOF};
use trackgen::{RecursiveModel, rotate};

trackgen::model! {
    /// 17 links of 0.2 m pitch: 3.4 m of track.
    pub track Ring17 {
        links: 17,
        link { mass: 1.0, inertia: 0.01, u1: (-0.1, 0.0), u2: (0.1, 0.0) },
        closure: partitioned,
    }

    /// 19 links alternating 0.2 m and 0.16 m pitch: 3.44 m of track.
    pub track Mixed19 {
        links: 19,
        link { mass: 1.0, inertia: 0.01, u1: (-0.1, 0.0), u2: (0.1, 0.0) },
        link[2..=18 by 2] { u1: (-0.08, 0.0), u2: (0.08, 0.0) },
        closure: partitioned,
    }
}

fn circle(x: f64, y: f64, radius: f64) -> PitchCircle {
    PitchCircle {
        centre: Vector2::new(x, y),
        radius,
    }
}

/// Centre distance of [`pair`], m.
const SPAN: f64 = 0.75;

/// Two wheels of radius 0.3 m, 0.75 m apart: a 1.5 + 0.6π = 3.385 m wrap.
/// Laid as chords, the 3.4 m track overshoots it by 0.05 m of belt
/// without sag and falls 0.02 m short with the most sag allowed (a
/// quarter of the span): it fits (measured with `assembly::excess`).
fn pair() -> [PitchCircle; 2] {
    [circle(0.0, 0.0, 0.3), circle(SPAN, 0.0, 0.3)]
}

#[test]
fn too_few_wheels() {
    for wheels in [vec![], vec![circle(0.0, 0.0, 0.3)]] {
        let n = wheels.len();
        // Checked first: a bad span index does not mask it.
        let e = wrap(&Ring17, &wheels, Some(5)).unwrap_err();
        assert_eq!(e, AssemblyError::TooFewWheels(n));
        assert_eq!(
            e.to_string(),
            format!("a track needs at least two wheels to wrap, got {n}")
        );
    }
}

#[test]
fn no_such_span() {
    for span in [2, 3, usize::MAX] {
        let e = wrap(&Ring17, &pair(), Some(span)).unwrap_err();
        assert_eq!(e, AssemblyError::NoSuchSpan(span));
        assert_eq!(
            e.to_string(),
            format!(
                "sag span {span} does not exist (spans are numbered from 0, one after each wheel)"
            )
        );
    }
    // The last span exists.
    assert!(wrap(&Ring17, &pair(), Some(1)).is_ok());
}

#[test]
fn wheel_inside_another() {
    let e = wrap(
        &Ring17,
        &[circle(0.0, 0.0, 0.5), circle(0.1, 0.0, 0.2)],
        None,
    )
    .unwrap_err();
    assert_eq!(
        e,
        AssemblyError::WheelInside {
            a: 0,
            b: 1,
            distance: 0.1
        }
    );
    assert_eq!(
        e.to_string(),
        "wheel 0 and wheel 1 are one inside the other: centres 0.100 m apart"
    );
    // The pair is named by index among three, the small one second.
    let e = wrap(
        &Ring17,
        &[
            circle(0.0, 0.0, 0.3),
            circle(0.7, 0.0, 0.3),
            circle(0.75, 0.05, 0.1),
        ],
        None,
    )
    .unwrap_err();
    match e {
        AssemblyError::WheelInside { a, b, distance } => {
            assert_eq!((a, b), (1, 2));
            assert!((distance - 0.05 * 2f64.sqrt()).abs() < 1e-15, "{distance}");
        }
        other => panic!("{other}"),
    }
    assert_eq!(
        e.to_string(),
        "wheel 1 and wheel 2 are one inside the other: centres 0.071 m apart"
    );
    // Concentric equal wheels are one inside the other too.
    let e = wrap(
        &Ring17,
        &[circle(0.2, 0.1, 0.3), circle(0.2, 0.1, 0.3)],
        None,
    )
    .unwrap_err();
    assert_eq!(
        e,
        AssemblyError::WheelInside {
            a: 0,
            b: 1,
            distance: 0.0
        }
    );
    // Checked before the span: a bad span index does not mask it.
    let e = wrap(
        &Ring17,
        &[circle(0.0, 0.0, 0.5), circle(0.1, 0.0, 0.2)],
        Some(9),
    )
    .unwrap_err();
    assert!(matches!(e, AssemblyError::WheelInside { .. }), "{e}");
    // Overlapping but not nested wheels are fine.
    let overlapping = wrap(
        &Ring17,
        &[circle(0.0, 0.0, 0.3), circle(0.5, 0.0, 0.25)],
        None,
    );
    assert!(!matches!(
        overlapping,
        Err(AssemblyError::WheelInside { .. })
    ));
}

/// 3.4 m of track round wheels 1 m apart (a 2 + 0.6π = 3.885 m wrap).
#[test]
fn track_too_short() {
    let wheels = [circle(0.0, 0.0, 0.3), circle(1.0, 0.0, 0.3)];
    let e = wrap(&Ring17, &wheels, None).unwrap_err();
    match e {
        AssemblyError::TrackTooShort { links, track, wrap } => {
            assert_eq!(links, 17);
            assert!((track - 3.4).abs() < 1e-12, "{track}");
            let want = 2.0 + 0.6 * std::f64::consts::PI;
            assert!((wrap - want).abs() < 1e-12, "{wrap} vs {want}");
        }
        ref other => panic!("{other}"),
    }
    assert_eq!(
        e.to_string(),
        "the track is too short to wrap the wheels: 17 links reach 3.400 m, the wrap needs 3.885 m"
    );
}

/// 3.4 m of track round wheels of 0.1 m, 0.65 m apart (a 1.3 + 0.2π =
/// 1.928 m wrap): a quarter-span sag takes up only 0.07 m of it.
#[test]
fn track_too_long() {
    let wheels = [circle(0.0, 0.0, 0.1), circle(0.65, 0.0, 0.1)];
    for span in [None, Some(0), Some(1)] {
        let e = wrap(&Ring17, &wheels, span).unwrap_err();
        match e {
            AssemblyError::TrackTooLong { track, wrap } => {
                assert!((track - 3.4).abs() < 1e-12, "{track}");
                let want = 1.3 + 0.2 * std::f64::consts::PI;
                assert!((wrap - want).abs() < 1e-12, "{wrap} vs {want}");
            }
            ref other => panic!("{other}"),
        }
        assert_eq!(
            e.to_string(),
            "the track is too long for the wheels: 3.400 m of track for a 1.928 m wrap sags more than a quarter of the span"
        );
    }
}

fn pitches<M: TrackModel<D>, const D: usize>(model: &M) -> Vec<f64> {
    model
        .description()
        .link_spans()
        .unwrap()
        .iter()
        .map(|d| d.norm())
        .collect()
}

/// The checks on a successful wrap of `model`: spacing, landing, and `q_i`
/// reproducing the joints and closing the loop.
fn check_wrap<M: TrackModel<D>, const D: usize>(
    label: &str,
    model: &M,
    (q, joints): &(SVector<f64, D>, Vec<Vector2<f64>>),
) {
    let pitches = pitches(model);
    let n = pitches.len();
    assert_eq!(joints.len(), n + 1, "{label}: one joint more than links");
    for (j, pitch) in pitches.iter().enumerate() {
        let gap = (joints[j + 1] - joints[j]).norm();
        assert!(
            (gap - pitch).abs() <= 1e-9,
            "{label}: link {j}: {gap} vs {pitch}"
        );
    }
    let landing = (joints[n] - joints[0]).norm();
    assert!(
        landing <= 1e-9,
        "{label}: the last joint lands {landing:e} m from the first"
    );
    let description = model.description();
    let mut centres = vec![Vector2::zeros(); n];
    model.body_positions(q, &mut centres);
    for (j, body) in description.bodies.iter().enumerate() {
        // Each link's ū1 on joint j; its ū2 (the next link's parent joint,
        // or the loop joint's ū2 for the last) on joint j + 1.
        let u2 = match description.bodies.get(j + 1) {
            Some(next) => next.at_parent,
            None => description.loop_joint.unwrap().last_u2,
        };
        // Link 1's ū1 is the loop joint's (the root's `at_self` is zero).
        let u1 = if j == 0 {
            description.loop_joint.unwrap().first_u1
        } else {
            body.at_self
        };
        let rear = centres[j] + rotate(q[2 + j], u1);
        let front = centres[j] + rotate(q[2 + j], u2);
        assert!(
            (rear - joints[j]).norm() <= 1e-9,
            "{label}: link {j} rear {rear:?} vs {:?}",
            joints[j]
        );
        assert!(
            (front - joints[j + 1]).norm() <= 1e-9,
            "{label}: link {j} front {front:?} vs {:?}",
            joints[j + 1]
        );
    }
    let gap = model.closure(q).norm();
    assert!(gap <= 1e-9, "{label}: closure gap {gap:e} m");
}

/// Two wheels, the slack in the lower span (0) or the upper (1): joints
/// one pitch apart, landing on the first; the first at one of wheel 0's
/// tangent points, (0, ±0.3); every joint on a pitch circle, on the
/// straight span (y = ±0.3), or on the sagging span, which is one circular
/// arc through the tangent points bulging inwards by at most a quarter
/// span.
#[test]
fn wrap_lays_joints_one_pitch_apart_on_the_belt() {
    let wheels = pair();
    for (span, sag_side) in [(0, -1.0), (1, 1.0)] {
        let result = wrap(&Ring17, &wheels, Some(span)).unwrap();
        let label = format!("span {span}");
        check_wrap(&label, &Ring17, &result);
        let joints = &result.1;
        // `wrap`'s docs say link 1 starts where the belt leaves wheel 0,
        // (0, −0.3); it starts where the belt reaches it, (0, 0.3) (see
        // the report). Either is a tangent point of wheel 0.
        assert!(
            (joints[0].x.abs() <= 1e-12) && ((joints[0].y.abs() - 0.3).abs() <= 1e-12),
            "{:?}",
            joints[0]
        );
        // Joints on the sagging span, with the tangent points it joins.
        let mut sagging = vec![
            Vector2::new(0.0, 0.3 * sag_side),
            Vector2::new(SPAN, 0.3 * sag_side),
        ];
        for p in &joints[..17] {
            let on = |c: &PitchCircle| ((p - c.centre).norm() - 0.3).abs() <= 1e-9;
            if p.x <= 1e-12 {
                assert!(on(&wheels[0]), "{label}: {p:?} off wheel 0");
            } else if p.x >= SPAN - 1e-12 {
                assert!(on(&wheels[1]), "{label}: {p:?} off wheel 1");
            } else if p.y * sag_side < 0.0 {
                assert!(
                    (p.y + 0.3 * sag_side).abs() <= 1e-9,
                    "{label}: {p:?} off the tight span"
                );
            } else {
                // Inwards from the tangent line, at most a quarter span.
                let inwards = 0.3 - p.y * sag_side;
                assert!(
                    inwards > 0.0 && inwards <= SPAN / 4.0,
                    "{label}: sag {inwards} at {p:?}"
                );
                sagging.push(*p);
            }
        }
        assert!(
            sagging.len() >= 4,
            "{label}: {} points on the sag",
            sagging.len()
        );
        // One circle through them: centre on x = SPAN/2 (the chord's
        // bisector), fixed by the tangent point and the first joint.
        let (a, b) = (sagging[0], sagging[2]);
        let mid = Vector2::new(SPAN / 2.0, 0.0);
        // |a − c|² = |b − c|² with c = (SPAN/2, y): solve for y.
        let y = ((b - mid).norm_squared() - (a - mid).norm_squared()) / (2.0 * (b.y - a.y));
        let centre = Vector2::new(SPAN / 2.0, y);
        let radius = (a - centre).norm();
        for p in &sagging {
            assert!(
                ((p - centre).norm() - radius).abs() <= 1e-9,
                "{label}: {p:?} off the sag circle ({centre:?}, {radius})"
            );
        }
    }
}

/// Links of two pitches: each pair of consecutive joints is its own
/// link's pitch apart, and the loop still closes.
#[test]
fn wrap_with_mixed_pitches() {
    let pitches = pitches(&Mixed19);
    assert!((pitches[0] - 0.2).abs() < 1e-15 && (pitches[1] - 0.16).abs() < 1e-15);
    let result = wrap(&Mixed19, &pair(), None).unwrap();
    check_wrap("mixed", &Mixed19, &result);
}

/// A wheel inside the belt (under the top span) drops out of the wrap:
/// the result is bit for bit the two-wheel wrap, and a sag span after the
/// dropped wheel, or before it, maps to the span that contains it. The
/// longest span is the default.
#[test]
fn wheels_inside_the_belt_drop_out() {
    let [w0, w1] = pair();
    let inner = circle(SPAN / 2.0, 0.1, 0.1);
    let three = [w0, w1, inner];
    let top = wrap(&Ring17, &pair(), Some(1)).unwrap();
    assert_eq!(wrap(&Ring17, &three, Some(1)).unwrap(), top);
    assert_eq!(wrap(&Ring17, &three, Some(2)).unwrap(), top);
    let bottom = wrap(&Ring17, &pair(), Some(0)).unwrap();
    assert_eq!(wrap(&Ring17, &three, Some(0)).unwrap(), bottom);
    // With the top span tight, no joint passes through the inner wheel's
    // pitch circle. (With the top span sagging it does: see the report.)
    for p in &bottom.1 {
        assert!((p - inner.centre).norm() > inner.radius, "{p:?}");
    }
    // A triangle whose longest span is the first (0 → 1, 0.9 m; the
    // others 0.67 and 0.60 m): the default sags there.
    let triangle = [
        circle(0.0, 0.0, 0.2),
        circle(0.9, 0.0, 0.2),
        circle(0.4, 0.45, 0.2),
    ];
    let default = wrap(&Ring17, &triangle, None).unwrap();
    check_wrap("triangle", &Ring17, &default);
    assert_eq!(default, wrap(&Ring17, &triangle, Some(0)).unwrap());
    assert_ne!(default, wrap(&Ring17, &triangle, Some(1)).unwrap());
}

// ---------------------------------------------------------------------
// Vehicle set-up.

fn config(tension_link: usize, teeth: u32) -> VehicleConfig {
    let mut config = VehicleConfig::m113(Terrain::Flat { height: 0.0 }, Drive::Free);
    config.tension_link = tension_link;
    config.sprocket.profile.teeth = teeth;
    config
}

fn setup(
    q: (SVector<f64, TRACK_DOF>, SVector<f64, CHASSIS_DOF>),
    config: VehicleConfig,
) -> Result<f64, SimulationError> {
    VehicleSystem::new(
        M113Track,
        M113Chassis,
        q.0,
        q.1,
        ClosureMethod::Declared,
        config,
    )
    .map(|s| s.sprocket_radius())
}

/// `tension_link` must name a link (1 to 64), and the sprocket needs 3
/// teeth: set-up errors, checked before anything else (the coordinates
/// here are not even a closed loop), with their messages.
#[test]
fn vehicle_setup_errors() {
    let zeros = (SVector::zeros(), SVector::zeros());
    for (link, teeth, message) in [
        (
            0,
            10,
            "invalid simulation set-up: tension_link 0 is not a link (1 to 64)",
        ),
        (
            65,
            10,
            "invalid simulation set-up: tension_link 65 is not a link (1 to 64)",
        ),
        (
            1000,
            2,
            "invalid simulation set-up: tension_link 1000 is not a link (1 to 64)",
        ),
        (
            1,
            2,
            "invalid simulation set-up: a sprocket needs at least 3 teeth, the profile has 2",
        ),
        (
            64,
            0,
            "invalid simulation set-up: a sprocket needs at least 3 teeth, the profile has 0",
        ),
    ] {
        let e = setup(zeros, config(link, teeth)).unwrap_err();
        assert!(matches!(e, SimulationError::Setup(_)), "{e:?}");
        assert_eq!(e.to_string(), message);
        assert_eq!(e.time(), None);
    }
}

/// The edges are accepted: the last link, and a three-tooth sprocket,
/// whose pitch radius is `p / (2 sin 60°)`.
#[test]
fn vehicle_setup_edges_are_accepted() {
    let a = assemble(
        &M113Track,
        &M113Chassis,
        &ShoeGeometry::m113(),
        &ToothProfile::m113(),
        &Terrain::Flat { height: 0.0 },
        0.0,
        0.001,
    )
    .unwrap();
    let q = (a.track, a.chassis);
    let radius = setup(q, config(64, 3)).unwrap();
    let want = 0.154 / (2.0 * (std::f64::consts::PI / 3.0).sin());
    assert!((radius - want).abs() <= 1e-15 * want, "{radius} vs {want}");
    let radius = setup(q, config(1, 10)).unwrap();
    let want = 0.154 / (2.0 * (std::f64::consts::PI / 10.0).sin());
    assert!((radius - want).abs() <= 1e-15 * want, "{radius} vs {want}");
    assert_eq!(<M113Track as RecursiveModel<TRACK_DOF>>::BODIES, 64);
}

trackgen::model! {
    /// A carrier whose top span sags freely (no tensioner arm): with 52 or
    /// 54 shoes the sag that closes the loop reaches into the idler and
    /// the road wheels.
    pub vehicle Sagging52 {
        chassis { mass: 1000.0, inertia: 500.0 },
        sprocket drive { at: (0.0, 0.0), mass: 20.0, inertia: 1.0, radius: 0.245, teeth: 10 },
        road_wheel rw1 { at: (-0.6, -0.35), mass: 30.0, inertia: 2.0, radius: 0.3 },
        road_wheel rw2 { at: (-2.4, -0.35), mass: 30.0, inertia: 2.0, radius: 0.3 },
        idler rear { at: (-3.0, 0.0), mass: 20.0, inertia: 1.0, radius: 0.25 },
        roller top { at: (-1.5, 0.05), mass: 10.0, inertia: 0.1, radius: 0.1 },
        track { links: 52, link { mass: 18.0, inertia: 0.04, u1: (-0.077, 0.0), u2: (0.077, 0.0) } },
    }

    /// The same with 54 shoes.
    pub vehicle Sagging54 {
        chassis { mass: 1000.0, inertia: 500.0 },
        sprocket drive { at: (0.0, 0.0), mass: 20.0, inertia: 1.0, radius: 0.245, teeth: 10 },
        road_wheel rw1 { at: (-0.6, -0.35), mass: 30.0, inertia: 2.0, radius: 0.3 },
        road_wheel rw2 { at: (-2.4, -0.35), mass: 30.0, inertia: 2.0, radius: 0.3 },
        idler rear { at: (-3.0, 0.0), mass: 20.0, inertia: 1.0, radius: 0.25 },
        roller top { at: (-1.5, 0.05), mass: 10.0, inertia: 0.1, radius: 0.1 },
        track { links: 54, link { mass: 18.0, inertia: 0.04, u1: (-0.077, 0.0), u2: (0.077, 0.0) } },
    }
}

/// Regression: a wrap whose sagging span passes through a wheel was
/// returned as a start, and the run began with shoes centimetres inside
/// the wheels. The assembled start is checked pair by pair (ground, every
/// wheel, the sprocket's teeth) against `START_PENETRATION` (2 mm), and a
/// deeper start is a typed error naming the part, the link and the depth.
/// The M113 starts clear of everything (its runs assemble in every
/// vehicle test).
#[test]
fn a_start_inside_a_wheel_is_an_error() {
    let (shoe, profile) = (ShoeGeometry::m113(), ToothProfile::m113());
    let flat = Terrain::Flat { height: 0.0 };
    let e52 = assemble(
        &Sagging52Track,
        &Sagging52Chassis,
        &shoe,
        &profile,
        &flat,
        0.0,
        0.001,
    )
    .unwrap_err();
    let e54 = assemble(
        &Sagging54Track,
        &Sagging54Chassis,
        &shoe,
        &profile,
        &flat,
        0.0,
        0.001,
    )
    .unwrap_err();
    for (e, part, at_least) in [
        (&e52, "idler `rear`", 0.005),
        (&e54, "road wheel `rw1`", 0.1),
    ] {
        match e {
            AssemblyError::StartsInside { what, link, depth } => {
                assert_eq!(what, part, "{e}");
                assert!((1..=54).contains(link), "{e}");
                assert!(*depth > at_least, "{e}");
            }
            other => panic!("{other}"),
        }
        let message = e.to_string();
        assert!(
            message.contains(part)
                && message.contains("mm inside")
                && message.contains("at most 2 mm"),
            "{message}"
        );
    }
    let _ = (Sagging52, Sagging54);
}
