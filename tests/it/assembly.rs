//! Track assembly: wrapping a track round its wheels (`assembly::wrap`)
//! and placing a declared vehicle (`vehicle::assemble`, with its
//! tensioner), against what they promise, and every error with its
//! message.
//!
//! What is checked, and why each check could fail:
//! * **A wrap is a closed chain on the belt**: joints one pitch apart,
//!   the last on the first, `q_i` putting every link's joints on them,
//!   no joint inside any wheel's pitch circle; the closure's Newton-Raphson
//!   (`recover_closure`) then closes the loop to 1e-12 m. Tolerance 1e-9 m
//!   (the brief's figure): each joint is found by Newton's method to
//!   ~1e-16 m of arc and the sag by bisection to rounding, so ~1e-14 m is
//!   left after 30 joints; a wrong tangent, a sag in the wrong place or a
//!   link laid along an arc instead of its chord is ≥ 1e-3 m.
//! * **The upper run sags as one circle**, tangent to both wheels from
//!   outside, the lower run tight: joints by hand-derived geometry of two
//!   equal wheels (1e-9 m).
//! * **The link counts an error names are the counts that wrap**: for each
//!   layout, every track of 14 to 30 links is wrapped; those that wrap are
//!   exactly the counts every error names, too short below them and too
//!   long above. And the tight count against a closed form for two equal
//!   wheels: `2D/p` links along the straight spans and `π / asin(p/2r)`
//!   round the wheels, within 0.05 of a link (the two formulas differ only
//!   where a chord straddles an arc and a line, four places, each far less
//!   than a hundredth of a link at these radii).
//! * **Rollers carry the upper run** when it sags onto them, and a wheel
//!   inside the belt is not touched (the wrap is bit for bit the one
//!   without it).
//! * **Random plausible layouts** (proptest): a closed chain as above or a
//!   typed error whose counts exclude the count tried, never a panic.
//! * **A tensioner takes up the slack over its whole travel**: counts
//!   that fit are those the errors name, the arm within its travel, the
//!   upper run nearly tight (sag 0.5 % of its longest span, so the track
//!   tension is set by the tensioner, not by the track's weight); a narrow
//!   travel fits fewer counts, and says so.
//! * Messages are compared as whole strings (fixed decimals).

use proptest::prelude::*;
use trackgen::assembly::{
    Assembled, AssemblyError, LinkCounts, PitchCircle, SlackLimit, Touching, Wrap, assemble, wrap,
};
use trackgen::contact::sprocket::pitch_radius;
use trackgen::multibody::{RecursiveModel, TrackModel};
use trackgen::nalgebra::{SVector, Vector2};
use trackgen::planar::rotate;
use trackgen::terrain::Terrain;
use trackgen::vehicle::{
    ConfigError, Drive, Geometry, Vehicle, VehicleConfig, VehicleDynamics, VehicleSystem,
};
use trackgen::vehicles::{m113::M113, m113::M113Chassis, m113::M113Track};

/// The M113's coordinate counts.
const TRACK_DOF: usize = M113::TRACK_DOF;
const CHASSIS_DOF: usize = M113::CHASSIS_DOF;

/// Declares closed tracks of 0.2 m links.
macro_rules! rings {
    ($($name:ident $n:literal),* $(,)?) => {
        trackgen::model! { $(
            /// A closed track of 0.2 m links.
            pub track $name {
                links: $n,
                link { mass: 1.0, inertia: 0.01, u1: (-0.1, 0.0), u2: (0.1, 0.0) },
                closure: partitioned,
            }
        )* }
        /// Wraps the `n`-link ring (14 to 30) round `wheels` and checks a
        /// success as a closed chain on the belt (panicking if not);
        /// returns the outcome.
        fn wrap_ring(n: usize, wheels: &[PitchCircle]) -> Result<Wrap<0>, AssemblyError> {
            match n {
                $($n => wrap(&$name, wheels).map(|w| {
                    check_wrap(&format!("{n} links"), &$name, &w, wheels);
                    Wrap { q: SVector::zeros(), joints: w.joints, sag_curvature: w.sag_curvature, touching: w.touching }
                }),)*
                _ => unreachable!("no ring of {n} links"),
            }
        }
    };
}

rings!(
    R14 14, R15 15, R16 16, R17 17, R18 18, R19 19, R20 20, R21 21, R22 22, R23 23, R24 24,
    R25 25, R26 26, R27 27, R28 28, R29 29, R30 30,
);
const COUNTS: std::ops::RangeInclusive<usize> = 14..=30;
const PITCH: f64 = 0.2;

trackgen::model! {
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

/// Two wheels of radius 0.3 m, `span` apart, the first on the right so
/// that the list runs counter-clockwise: the upper run heads backwards.
fn pair(span: f64) -> [PitchCircle; 2] {
    [circle(0.0, 0.0, 0.3), circle(-span, 0.0, 0.3)]
}

/// A small vehicle's wheels, counter-clockwise from the sprocket (front,
/// high): rollers (if any) under the upper run, the idler at the back,
/// road wheels low.
fn carrier(rollers: bool) -> Vec<PitchCircle> {
    let mut w = vec![circle(0.0, 0.05, 0.25)];
    if rollers {
        w.extend([circle(-0.6, 0.1, 0.1), circle(-1.2, 0.1, 0.1)]);
    }
    w.extend([
        circle(-1.8, 0.0, 0.25),
        circle(-1.4, -0.45, 0.25),
        circle(-0.4, -0.45, 0.25),
    ]);
    w
}

/// The checks on a successful wrap of `model` round `wheels`: spacing,
/// landing, `q_i` reproducing the joints, no joint inside a pitch circle,
/// and the loop closed by the generated Newton-Raphson.
fn check_wrap<M: TrackModel<D>, const D: usize>(
    label: &str,
    model: &M,
    wrapped: &Wrap<D>,
    wheels: &[PitchCircle],
) {
    let (q, joints) = (&wrapped.q, &wrapped.joints);
    let description = model.description();
    let spans = description.link_spans().unwrap();
    let n = spans.len();
    assert_eq!(joints.len(), n + 1, "{label}: one joint more than links");
    for (j, span) in spans.iter().enumerate() {
        let gap = (joints[j + 1] - joints[j]).norm();
        assert!(
            (gap - span.norm()).abs() <= 1e-9,
            "{label}: link {j}: {gap} vs {}",
            span.norm()
        );
    }
    let landing = (joints[n] - joints[0]).norm();
    assert!(
        landing <= 1e-9,
        "{label}: the last joint lands {landing:e} m from the first"
    );
    for p in joints {
        for (i, w) in wheels.iter().enumerate() {
            let inside = w.radius - (p - w.centre).norm();
            assert!(
                inside <= 1e-9,
                "{label}: joint {p:?} {inside:e} m inside wheel {i}"
            );
        }
    }
    let mut centres = vec![Vector2::zeros(); n];
    model.body_positions(q, &mut centres);
    for (j, body) in description.bodies.iter().enumerate() {
        let u2 = match description.bodies.get(j + 1) {
            Some(next) => next.at_parent,
            None => description.loop_joint.unwrap().last_u2,
        };
        let u1 = if j == 0 {
            description.loop_joint.unwrap().first_u1
        } else {
            body.at_self
        };
        let rear = centres[j] + rotate(q[2 + j], u1);
        let front = centres[j] + rotate(q[2 + j], u2);
        assert!((rear - joints[j]).norm() <= 1e-9, "{label}: link {j} rear");
        assert!(
            (front - joints[j + 1]).norm() <= 1e-9,
            "{label}: link {j} front"
        );
    }
    let gap = model.closure(q).norm();
    assert!(gap <= 1e-9, "{label}: closure gap {gap:e} m");
    // The Newton-Raphson closes the rest: the pair of links a quarter of
    // the loop apart, well conditioned on any convex wrap.
    let (mut q, mut qd) = (*q, SVector::<f64, D>::zeros());
    let mut trig = vec![(0.0, 0.0); n];
    model
        .recover_closure(&mut q, &mut qd, [0, n / 4], 1e-13, 20, &mut trig)
        .unwrap_or_else(|e| panic!("{label}: the recovery fails: {e:?}"));
    let gap = model.closure(&q).norm();
    assert!(gap <= 1e-12, "{label}: closure after recovery {gap:e} m");
}

/// The counts that fit, by wrapping every ring; checks that they are
/// contiguous and are what each error names, too short below and too long
/// above. Returns them.
fn counts_that_wrap(label: &str, wheels: &[PitchCircle]) -> (Vec<usize>, Vec<AssemblyError>) {
    let mut fit = Vec::new();
    let mut errors = Vec::new();
    for n in COUNTS {
        match wrap_ring(n, wheels) {
            Ok(_) => fit.push(n),
            Err(e) => errors.push(e),
        }
    }
    assert!(
        fit.windows(2).all(|w| w[1] == w[0] + 1),
        "{label}: the counts that wrap are not contiguous: {fit:?}"
    );
    for e in &errors {
        let (links, fits, short) = match e {
            AssemblyError::TrackTooShort { links, fits, .. } => (*links, fits, true),
            AssemblyError::TrackTooLong { links, fits, .. } => (*links, fits, false),
            other => panic!("{label}: {other}"),
        };
        let named: Vec<usize> = fits.range().collect();
        assert_eq!(named, fit, "{label}: {links} links: {e}");
        assert!((fits.pitch - PITCH).abs() < 1e-15, "{label}: {e}");
        assert!(fits.tight <= fits.slack, "{label}: {e}");
        if short {
            assert!((links as f64) < fits.tight, "{label}: {e}");
        } else {
            assert!((links as f64) > fits.slack, "{label}: {e}");
        }
    }
    (fit, errors)
}

#[test]
fn too_few_wheels() {
    for wheels in [vec![], vec![circle(0.0, 0.0, 0.3)]] {
        let n = wheels.len();
        let e = wrap(&R17, &wheels).unwrap_err();
        assert_eq!(e, AssemblyError::TooFewWheels(n));
        assert_eq!(
            e.to_string(),
            format!("a track needs at least two wheels to wrap, got {n}")
        );
    }
}

#[test]
fn wheel_inside_another() {
    let e = wrap(&R17, &[circle(0.0, 0.0, 0.5), circle(0.1, 0.0, 0.2)]).unwrap_err();
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
    let e = wrap(
        &R17,
        &[
            circle(0.0, 0.0, 0.3),
            circle(0.7, 0.0, 0.3),
            circle(0.75, 0.05, 0.1),
        ],
    )
    .unwrap_err();
    match e {
        AssemblyError::WheelInside { a, b, distance } => {
            assert_eq!((a, b), (1, 2));
            assert!((distance - 0.05 * 2f64.sqrt()).abs() < 1e-15, "{distance}");
        }
        ref other => panic!("{other}"),
    }
    // Concentric equal wheels are one inside the other too.
    let e = wrap(&R17, &[circle(0.2, 0.1, 0.3), circle(0.2, 0.1, 0.3)]).unwrap_err();
    assert!(matches!(e, AssemblyError::WheelInside { distance, .. } if distance == 0.0));
    // Overlapping but not nested wheels are fine.
    let overlapping = wrap(&R17, &[circle(0.0, 0.0, 0.3), circle(0.5, 0.0, 0.25)]);
    assert!(!matches!(
        overlapping,
        Err(AssemblyError::WheelInside { .. })
    ));
}

/// Tracks of 14 to 30 links round two wheels 2 m apart, a triangle, and a
/// small vehicle with and without return rollers: the counts that wrap
/// are the counts each error names.
#[test]
fn errors_name_the_link_counts_that_wrap() {
    let triangle = [
        circle(0.9, 0.0, 0.2),
        circle(0.4, 0.45, 0.2),
        circle(0.0, 0.0, 0.2),
    ];
    for (label, wheels) in [
        ("pair", pair(2.0).to_vec()),
        ("triangle", triangle.to_vec()),
        ("carrier", carrier(false)),
        ("carrier with rollers", carrier(true)),
    ] {
        let (fit, errors) = counts_that_wrap(label, &wheels);
        assert!(!fit.is_empty(), "{label}: nothing fits");
        assert!(!errors.is_empty(), "{label}: everything fits");
    }
    // Messages, whole.
    let e = wrap(&R24, &pair(2.0)).unwrap_err();
    assert_eq!(
        e.to_string(),
        "24 links are 1.051 m too short to wrap the wheels; 30 fit"
    );
}

/// The tight count round two equal wheels against the closed form, and
/// the shortfall of a short track: one pitch less per link less.
#[test]
fn tight_count_of_two_wheels_by_hand() {
    for span in [1.0, 1.5, 2.0] {
        let e = wrap(&R14, &pair(span)).unwrap_err();
        let AssemblyError::TrackTooShort { short, fits, .. } = e else {
            panic!("{e}")
        };
        let r: f64 = 0.3;
        let by_hand = 2.0 * span / PITCH + std::f64::consts::PI / (PITCH / (2.0 * r)).asin();
        assert!(
            (fits.tight - by_hand).abs() <= 0.05,
            "span {span}: {} vs {by_hand}",
            fits.tight
        );
        // 14 links fall short of the tight belt by its length in chords
        // less 14, in metres of belt: within a fifth of a pitch of
        // (tight − 14) pitches (arcs are longer than their chords).
        let want = (fits.tight - 14.0) * PITCH;
        assert!(
            (short - want).abs() <= 0.2 * PITCH,
            "span {span}: {short} vs {want}"
        );
        let e15 = wrap(&R15, &pair(span)).unwrap_err();
        let AssemblyError::TrackTooShort { short: short15, .. } = e15 else {
            panic!("{e15}")
        };
        assert!(
            (short - short15 - PITCH).abs() <= 0.02 * PITCH,
            "span {span}"
        );
    }
}

/// Two equal wheels 1.9 to 2.1 m apart, the slack in the upper run: the
/// lower run is the tight tangent (y = −0.3); the upper run's joints lie
/// on one circle of the reported curvature tangent to both wheels from
/// outside (centre on the bisector, `1/κ + r` from each wheel's centre),
/// sagging at most a quarter of the span; the rest lie on the wheels.
#[test]
fn the_upper_run_sags_as_one_circle() {
    let mut checked = 0;
    for span in [1.9, 2.0, 2.1] {
        let wheels = pair(span);
        for (n, w) in COUNTS.filter_map(|n| wrap_ring(n, &wheels).ok().map(|w| (n, w))) {
            let kappa = w.sag_curvature;
            assert!(kappa > 0.0, "{n}: no sag");
            let rho = 1.0 / kappa;
            let half = span / 2.0;
            let centre = Vector2::new(-half, ((rho + 0.3).powi(2) - half * half).sqrt());
            let mut on_sag = 0;
            for p in &w.joints {
                let on = |c: &PitchCircle| ((p - c.centre).norm() - 0.3).abs() <= 1e-9;
                if on(&wheels[0]) || on(&wheels[1]) {
                    continue;
                }
                if (p.y + 0.3).abs() <= 1e-9 {
                    // On the lower run.
                } else {
                    assert!(
                        ((p - centre).norm() - rho).abs() <= 1e-9,
                        "{n}: {p:?} off the sag circle"
                    );
                    assert!(0.3 - p.y <= 0.25 * span + 1e-12, "{n}: {p:?} sags too far");
                    on_sag += 1;
                }
            }
            assert!(on_sag >= 5, "{n}: {on_sag} joints on the sag");
            assert_eq!(w.touching, vec![0, 1]);
            checked += 1;
        }
    }
    assert!(checked >= 2, "{checked} wraps checked");
    // Mixed pitches close too (round wheels of 0.15 m, 1.2 m apart).
    let small = [circle(0.0, 0.0, 0.15), circle(-1.2, 0.0, 0.15)];
    let w = wrap(&Mixed19, &small).unwrap();
    assert!(w.sag_curvature > 0.0);
    check_wrap("mixed", &Mixed19, &w, &small);
}

/// Return rollers under the upper run carry it: the longest track that
/// wraps with them rests on both (and no joint is inside them,
/// `check_wrap`), while the same track without them sags below their
/// tops. Holding the run up, they take up less slack than a free sag: the
/// longest count with them is no longer than without.
#[test]
fn rollers_carry_the_upper_run() {
    let (with, _) = counts_that_wrap("with rollers", &carrier(true));
    let (without, _) = counts_that_wrap("without", &carrier(false));
    let last = *with.last().unwrap();
    let carried = wrap_ring(last, &carrier(true)).unwrap();
    assert_eq!(carried.touching, vec![0, 1, 2, 3, 4, 5]);
    let free = wrap_ring(last, &carrier(false)).unwrap();
    // The roller tops, y = 0.1 + 0.1; the free upper run between them.
    let lowest = free
        .joints
        .iter()
        .filter(|p| p.x < -0.6 && p.x > -1.2 && p.y > -0.1)
        .map(|p| p.y)
        .fold(f64::INFINITY, f64::min);
    assert!(
        lowest < 0.2,
        "the free run's lowest joint between the rollers: {lowest}"
    );
    assert!(last <= *without.last().unwrap(), "{with:?} vs {without:?}");
}

/// A wheel inside the belt (above the lower run, clear of the upper run's
/// most sag) is not touched: the wrap is bit for bit the two-wheel one.
#[test]
fn wheels_inside_the_belt_are_not_touched() {
    let [a, b] = pair(2.0);
    let inner = circle(-1.0, -0.26, 0.03);
    let three = [a, b, inner];
    for n in 29..=30 {
        let (two, with) = (wrap_ring(n, &[a, b]), wrap_ring(n, &three));
        let Ok(two) = two else {
            assert_eq!(two.unwrap_err(), with.unwrap_err());
            continue;
        };
        let with = with.unwrap();
        assert_eq!(with.joints, two.joints);
        assert_eq!(with.touching, vec![0, 1]);
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 256, failure_persistence: None, ..ProptestConfig::default() })]

    /// Random plausible layouts: a sprocket, an idler 1.2 to 2.2 m behind
    /// it, two to four road wheels below, up to two return rollers above
    /// them; any count of links. The outcome is a closed chain on the belt
    /// (`wrap_ring` checks it), or a typed error naming counts that
    /// exclude the one tried.
    #[test]
    fn random_layouts_wrap_or_say_why(
        length in 1.2f64..2.2,
        sprocket in (0.15f64..0.32, -0.1f64..0.15),
        idler in (0.15f64..0.32, -0.15f64..0.1),
        road in prop::collection::vec((0.15f64..0.3, -0.45f64..-0.25, -0.1f64..0.1), 2..=4),
        rollers in prop::collection::vec((0.06f64..0.12, 0.0f64..0.15), 0..=2),
        n in COUNTS,
    ) {
        let mut wheels = vec![circle(0.0, sprocket.1, sprocket.0)];
        let k = rollers.len();
        for (i, (r, y)) in rollers.iter().enumerate() {
            wheels.push(circle(-length * (i + 1) as f64 / (k + 1) as f64, *y, *r));
        }
        wheels.push(circle(-length, idler.1, idler.0));
        let m = road.len();
        for (i, (r, y, jitter)) in road.iter().enumerate() {
            // From the back to the front, as the loop runs.
            let x = -length * (m - i) as f64 / (m + 1) as f64 + jitter;
            wheels.push(circle(x, *y, *r));
        }
        match wrap_ring(n, &wheels) {
            Ok(_) => {}
            Err(AssemblyError::TrackTooShort { links, short, fits }) => {
                prop_assert_eq!(links, n);
                prop_assert!(short > 0.0 && (n as f64) < fits.tight, "{} {:?}", short, fits);
            }
            Err(AssemblyError::TrackTooLong { links, long, fits, limit }) => {
                prop_assert_eq!(links, n);
                prop_assert_eq!(limit, SlackLimit::Sag);
                prop_assert!(long > 0.0 && (n as f64) > fits.slack, "{} {:?}", long, fits);
            }
            Err(AssemblyError::WheelInside { .. }) => {}
            Err(other) => prop_assert!(false, "{}", other),
        }
    }
}

// ---------------------------------------------------------------------
// Vehicles: the tensioner.

/// Declares the same carrier with `$n` links, its rear idler on a 0.2 m
/// tensioner arm with the given travel.
macro_rules! carriers {
    ($($name:ident $n:literal ($low:expr, $high:expr)),* $(,)?) => { trackgen::model! { $(
        /// A small carrier, one side, with a tensioner.
        pub vehicle $name {
            chassis { mass: 2400.0, inertia: 3800.0, centroid: (-1.3, 0.35) },
            sprocket drive { at: (0.0, 0.0), mass: 15.0, inertia: 0.3, radius: 0.17, teeth: 9 },
            road_wheel rw[4] {
                at: [(-0.45, -0.30), (-1.0, -0.30), (-1.55, -0.30), (-2.1, -0.30)],
                mass: 25.0, inertia: 0.5, radius: 0.2,
                arm { pivot_offset: (0.22, 0.10), mass: 20.0, inertia: 0.2,
                      stiffness: 1.5e4, damping: 300.0, preload: 1.2e3 },
            },
            roller top[2] { at: [(-0.75, 0.12), (-1.75, 0.12)], mass: 5.0, inertia: 0.02, radius: 0.08 },
            idler rear { at: (-2.6, -0.08), mass: 20.0, inertia: 0.4, radius: 0.18,
                arm { pivot: (-2.6, 0.12), mass: 3.0, inertia: 0.02, stiffness: 2e4, damping: 600.0,
                      preload: -2e3, travel: ($low, $high) } },
            track { links: $n, link { mass: 6.0, inertia: 0.01, u1: (-0.06, 0.0), u2: (0.06, 0.0) } },
            shoe { ground_points: [(-0.045, -0.02), (0.045, -0.02)], inner_offset: 0.02,
                   pins: [(0.045, 0.0), (-0.045, 0.0)], pin_radius: 0.012 },
        }
    )* } };
}

const QUARTER: f64 = std::f64::consts::FRAC_PI_2;
carriers!(
    C52 52 (-QUARTER, QUARTER),
    C53 53 (-QUARTER, QUARTER),
    C55 55 (-QUARTER, QUARTER),
    C58 58 (-QUARTER, QUARTER),
    C59 59 (-QUARTER, QUARTER),
    Narrow57 57 (-0.2, 0.2),
);

macro_rules! place {
    ($vehicle:ident, $track:ident, $chassis:ident) => {{
        let flat = Terrain::Flat { height: 0.0 };
        let geometry = $vehicle::geometry();
        let placed = assemble(
            &$track,
            &$chassis,
            &geometry.shoe,
            &geometry.sprocket,
            &flat,
            0.0,
            0.001,
        );
        placed.map(
            |a: Assembled<{ $vehicle::TRACK_DOF }, { $vehicle::CHASSIS_DOF }>| {
                a.chassis[2 + $chassis::REAR_ARM]
            },
        )
    }};
}

/// The counts that fit the tensioner's travel (±90°) assemble, with the
/// arm inside its travel; the counts just outside are errors naming them.
/// A narrow travel (±0.2 rad) fits fewer, and says so.
#[test]
fn a_tensioner_takes_up_the_slack_over_its_travel() {
    for (n, arm) in [
        (53, place!(C53, C53Track, C53Chassis)),
        (55, place!(C55, C55Track, C55Chassis)),
        (58, place!(C58, C58Track, C58Chassis)),
    ] {
        let phi = arm.unwrap_or_else(|e| panic!("{n} links: {e}"));
        assert!(phi.abs() <= QUARTER, "{n} links: arm at {phi} rad");
    }
    let short = place!(C52, C52Track, C52Chassis).unwrap_err();
    let long = place!(C59, C59Track, C59Chassis).unwrap_err();
    for (e, want) in [
        (&short, "too short"),
        (&long, "too long for the tensioner's travel"),
    ] {
        let fits: &LinkCounts = match e {
            AssemblyError::TrackTooShort { fits, .. } => fits,
            AssemblyError::TrackTooLong { fits, limit, .. } => {
                assert_eq!(*limit, SlackLimit::Tensioner);
                fits
            }
            other => panic!("{other}"),
        };
        assert_eq!(fits.range(), 53..=58, "{e}");
        assert!(
            e.to_string().contains(want) && e.to_string().ends_with("53 to 58 fit"),
            "{e}"
        );
    }
    let narrow = place!(Narrow57, Narrow57Track, Narrow57Chassis).unwrap_err();
    match &narrow {
        AssemblyError::TrackTooLong {
            links: 57,
            fits,
            limit: SlackLimit::Tensioner,
            ..
        } => {
            assert!(
                fits.range().end() < &57 && !fits.range().is_empty(),
                "{narrow}"
            );
        }
        other => panic!("{other}"),
    }
}

// ---------------------------------------------------------------------
// Vehicle set-up.

fn config(tension_link: usize) -> VehicleConfig {
    let mut config = M113::declared_config(Terrain::Flat { height: 0.0 }, Drive::Free);
    config.tension_link = tension_link;
    config
}

fn setup(
    q: (SVector<f64, TRACK_DOF>, SVector<f64, CHASSIS_DOF>),
    geometry: Geometry,
    config: VehicleConfig,
) -> Result<f64, ConfigError> {
    let start = Assembled {
        track: q.0,
        chassis: q.1,
        tensioner: None,
    };
    VehicleSystem::new(M113Track, M113Chassis, &start, geometry, config)
        .map(|s| s.sprocket_pitch_radius())
}

/// `tension_link` must name a link (1 to 64), and a tooth profile must
/// have the compiled sprocket's teeth: typed errors, checked before
/// anything else (the coordinates here are not even a closed loop), with
/// their messages.
#[test]
fn vehicle_setup_errors() {
    let zeros = (SVector::zeros(), SVector::zeros());
    for link in [0, 65, 1000] {
        let e = setup(zeros, M113::geometry(), config(link)).unwrap_err();
        assert_eq!(e, ConfigError::TensionLink { link, links: 64 });
        assert_eq!(
            e.to_string(),
            format!("tension_link {link} is not a link (1 to 64)")
        );
    }
    let mut nine = M113::geometry();
    nine.sprocket.teeth = 9;
    let e = setup(zeros, nine, config(1)).unwrap_err();
    assert_eq!(
        e,
        ConfigError::Teeth {
            profile: 9,
            declared: 10
        }
    );
    assert_eq!(
        e.to_string(),
        "the tooth profile has 9 teeth; the declared sprocket has 10"
    );
}

/// The edges are accepted: the last link; the pitch radius is
/// `p / (2 sin(π/N))` (for three teeth `p / (2 sin 60°)`).
#[test]
fn vehicle_setup_edges_are_accepted() {
    let a = assemble(
        &M113Track,
        &M113Chassis,
        &M113::geometry().shoe,
        &M113::geometry().sprocket,
        &Terrain::Flat { height: 0.0 },
        0.0,
        0.001,
    )
    .unwrap();
    let q = (a.track, a.chassis);
    for link in [1, 64] {
        let radius = setup(q, M113::geometry(), config(link)).unwrap();
        let want = 0.154 / (2.0 * (std::f64::consts::PI / 10.0).sin());
        assert!((radius - want).abs() <= 1e-15 * want, "{radius} vs {want}");
    }
    let three = pitch_radius(3, 0.154);
    let want = 0.154 / (2.0 * (std::f64::consts::PI / 3.0).sin());
    assert!((three - want).abs() <= 1e-15 * want, "{three} vs {want}");
    assert_eq!(<M113Track as RecursiveModel<TRACK_DOF>>::BODIES, 64);
}

/// Declares a carrier whose upper run sags freely (no tensioner arm)
/// onto a return roller, with `$n` shoes.
macro_rules! sagging {
    ($($name:ident $n:literal),* $(,)?) => { trackgen::model! { $(
        /// A carrier with a freely sagging upper run over a roller.
        pub vehicle $name {
            chassis { mass: 1000.0, inertia: 500.0 },
            sprocket drive { at: (0.0, 0.0), mass: 20.0, inertia: 1.0, radius: 0.245, teeth: 10 },
            road_wheel rw1 { at: (-0.6, -0.35), mass: 30.0, inertia: 2.0, radius: 0.3 },
            road_wheel rw2 { at: (-2.4, -0.35), mass: 30.0, inertia: 2.0, radius: 0.3 },
            idler rear { at: (-3.0, 0.0), mass: 20.0, inertia: 1.0, radius: 0.25 },
            roller top { at: (-1.5, 0.05), mass: 10.0, inertia: 0.1, radius: 0.1 },
            track { links: $n, link { mass: 18.0, inertia: 0.04, u1: (-0.077, 0.0), u2: (0.077, 0.0) } },
        }
    )* } };
}

// 52 shoes fit; with 54 the sag that closes the loop would reach a road
// wheel. (The declarations' `…System` aliases go unused here.)
#[allow(dead_code)]
mod sagging {
    sagging!(Sagging52 52, Sagging54 54);
}
use sagging::{
    Sagging52, Sagging52Chassis, Sagging52Track, Sagging54, Sagging54Chassis, Sagging54Track,
};

/// Regression: a wrap whose sagging span passed through a wheel was
/// returned as a start, and the run began with shoes centimetres inside
/// the wheels. The upper run now rests on the roller (52 shoes assemble);
/// a sag that would reach a road wheel (54 shoes) is a track too long,
/// naming the count that fits. And what the wrap cannot see is checked on
/// the assembled start, pair by pair (ground, every wheel, the sprocket's
/// teeth), against `START_PENETRATION` (2 mm): the M113 placed over a
/// 0.3 m bump between its road wheels starts inside the ground, a typed
/// error naming the link and the depth.
#[test]
fn a_start_inside_a_wheel_or_the_ground_is_an_error() {
    let (shoe, profile) = (M113::geometry().shoe, M113::geometry().sprocket);
    let flat = Terrain::Flat { height: 0.0 };
    assemble(
        &Sagging52Track,
        &Sagging52Chassis,
        &shoe,
        &profile,
        &flat,
        0.0,
        0.001,
    )
    .unwrap_or_else(|e| panic!("52 shoes: {e}"));
    let e = assemble(
        &Sagging54Track,
        &Sagging54Chassis,
        &shoe,
        &profile,
        &flat,
        0.0,
        0.001,
    )
    .unwrap_err();
    assert!(
        matches!(&e, AssemblyError::TrackTooLong { links: 54, limit: SlackLimit::Sag, fits, .. } if fits.range() == (52..=52)),
        "{e}"
    );
    assert!(e.to_string().ends_with("; 52 fit"), "{e}");
    // Road wheels at x = −0.74 − 2.006 … −3.407 − 2.006 from the centroid
    // at 0: a bump centred between wheels 2 and 3.
    let bump = Terrain::Bump {
        centre: -1.74 - 2.006 + 2.006 - 0.0,
        width: 0.5,
        height: 0.3,
    };
    let e = assemble(&M113Track, &M113Chassis, &shoe, &profile, &bump, 0.0, 0.001).unwrap_err();
    match &e {
        AssemblyError::StartsInside { what, link, depth } => {
            assert_eq!(*what, Touching::Ground, "{e}");
            assert!((1..=64).contains(link), "{e}");
            assert!(*depth > 0.01, "{e}");
        }
        other => panic!("{other}"),
    }
    let message = e.to_string();
    assert!(
        message.contains("mm inside the ground") && message.contains("at most 2 mm"),
        "{message}"
    );
    let _ = (Sagging52, Sagging54);
}

/// A profile that cannot drive its track is refused when the vehicle is
/// built from a hand-made geometry, by the rules the compiler applies to a
/// declaration (`trackgen_sprocket`), with what would work: gaps far too
/// wide for the sprocket, and pins at the links' centres, between the
/// gaps.
#[test]
fn profiles_that_cannot_drive_are_config_errors() {
    use trackgen::contact::sprocket::ProfileProblem;
    let a = assemble(
        &M113Track,
        &M113Chassis,
        &M113::geometry().shoe,
        &M113::geometry().sprocket,
        &Terrain::Flat { height: 0.0 },
        0.0,
        0.001,
    )
    .unwrap();
    let q = (a.track, a.chassis);
    let mut wide = M113::geometry();
    wide.sprocket.arc_radius = 0.5;
    let e = setup(q, wide, config(1)).unwrap_err();
    assert!(
        matches!(e, ConfigError::Profile(ProfileProblem::GapsOverlap { largest, .. })
            if (largest - 0.3 * (std::f64::consts::PI / 10.0).sin()).abs() < 1e-12),
        "{e}"
    );
    let mut centred = M113::geometry();
    centred.shoe.pins = vec![Vector2::new(0.0, 0.0)];
    let e = setup(q, centred, config(1)).unwrap_err();
    match &e {
        ConfigError::Profile(ProfileProblem::PinInTooth {
            pin: 1,
            from_joint,
            seats_within,
            wider_gap: None,
            ..
        }) => {
            assert!((from_joint - 0.077).abs() < 1e-12, "{e}");
            // √((ρ − r_pin)² − (d − R)²) for the M113's figures.
            let r = 0.154 / (2.0 * (std::f64::consts::PI / 10.0).sin());
            let want = ((0.089f64 - 0.015).powi(2) - (0.3 - r).powi(2)).sqrt();
            assert!((seats_within - want).abs() < 1e-12, "{e}");
        }
        other => panic!("{other}"),
    }
    assert!(
        e.to_string()
            .contains("move `pins` to within 0.0538 m of a joint"),
        "{e}"
    );
}

/// Teeth that stop short of the pins cannot drive the track: Chrono's
/// Marder profile (tip circle 0.3 m, its gaps centred on the pitch
/// circle) under its own shoe is refused, naming how far out the pins'
/// inner edges lie; the declared Marder's 0.34 m reaches past them. The
/// closed form: a seated link is a chord of the pitch circle, `R cos(π/N)`
/// from the centre, and its pin nearer the link's middle, 0.0535 m from
/// it along the chord, has its inner edge `√((R cos(π/N))² + 0.0535²) −
/// r_pin` out.
#[test]
fn teeth_that_miss_the_pins_are_refused() {
    use trackgen::contact::sprocket::ProfileProblem;
    use trackgen::vehicles::marder::{Marder, SHOE_PITCH};
    let geometry = Marder::geometry();
    let joints = (
        Vector2::new(-SHOE_PITCH / 2.0, 0.0),
        Vector2::new(SHOE_PITCH / 2.0, 0.0),
    );
    assert_eq!(geometry.sprocket.check(joints, &geometry.shoe), Ok(()));
    let mut chrono = geometry.sprocket;
    chrono.addendum = 0.3;
    // The pitch circle of 12 joints 0.17 m apart, and the chord's distance.
    let half = std::f64::consts::PI / 12.0;
    let chord = SHOE_PITCH / (2.0 * half.sin()) * half.cos();
    let want = chord.hypot(0.0535) - geometry.shoe.pin_radius;
    match chrono.check(joints, &geometry.shoe) {
        Err(ProfileProblem::TeethMissPins {
            addendum,
            lowest_pin,
        }) => {
            assert_eq!(addendum, 0.3);
            assert!((lowest_pin - want).abs() < 1e-12, "{lowest_pin} {want}");
            assert!((lowest_pin - 0.3067).abs() < 5e-5, "{lowest_pin}");
        }
        other => panic!("{other:?}"),
    }
    // Just past the pins' inner edge, a tooth meets them.
    chrono.addendum = want + 1e-9;
    assert_eq!(chrono.check(joints, &geometry.shoe), Ok(()));
}
