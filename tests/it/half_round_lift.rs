//! The hull's lift over a half-round at a crawl follows the geometric
//! envelope of the running gear.
//!
//! The M113 with its road wheels' arms made rigid (torsion stiffness
//! ×1000: a 25 kN wheel load turns an arm 0.3 mrad, 0.1 mm at the wheel)
//! crawls at 0.5 m/s over a 0.2 m half-round. With rigid gear the hull's
//! pose is geometry: whenever a road wheel's centre passes over the crest
//! that wheel rides on the track wrapped over the crest, its centre
//! `r + ρ` above the ground (`r` the obstacle's radius, `ρ` the wheel's
//! radius plus the shoe's thickness under it), and the hull pivots about
//! the end wheel still on the ground (the rear one while the centroid is
//! behind the crest, the front one once it is ahead), whose centre stays
//! `ρ` up. So the pitch is `asin(r / d)` (`d` the two wheels' spacing)
//! and the centroid's height follows from its place in the hull, for
//! wheels 1, 2 (nose up, on wheel 5) and 4, 5 (nose down, on wheel 1).
//! Wheel 3 is left out: the centroid is 6.8 cm ahead of it, and which end
//! goes down there is the drive's and the track's pull's to decide, not
//! the geometry's.
//!
//! Tolerance: the contacts are compliant, so each of the two wheels sits
//! lower than the geometry by up to its contacts' depths under its load,
//! and each load is at most the whole weight `W` (at a crawl the ground
//! carries the weight; the lever rule's share is not a bound, since the
//! track's tension wrapped over the crest presses the shoe there harder
//! than its wheel does). On the crest the shoe bears on one ground point
//! (`W / k_ground`) or straddles the crest on both, sagging by the
//! sagitta of their spacing (`W / 2k_ground + r − √(r² − (s/2)²)`, 9.2 mm
//! here), and the rim presses into the shoe (`W / k_rim`); on the flat the
//! shoe bears on both points. The measured pitch and centroid height must
//! lie within the range of the geometric poses over those depths (the
//! centroid down to 2.9 cm under the exact geometry, the pitch within
//! 1.7e-2 rad of it, against a lift of 0.10–0.14 m and a pitch of
//! 0.075–0.1 rad): a hull that did not rise, or a wheel sunk into the
//! obstacle by more than its contacts allow, falls outside. Measured: the
//! centroid 0.9–1.5 cm under the exact geometry, the pitch within
//! 8.4e-3 rad of it (2.0e-3 with the rear wheel as the pivot).

use trackgen::integrate::Integrator;
use trackgen::laws::NormalLaw;
use trackgen::scene::{Frame, Scene};
use trackgen::simulate::{Output, simulate};
use trackgen::terrain::Terrain;
use trackgen::terrain::profile::Course;
use trackgen::vehicle::{Vehicle, speed_ramp};
use trackgen::vehicles::m113::M113;

use crate::support::vehicle::m113_weight;

/// The half-round's radius (= height), m; its foot at x = 4 m, so its
/// crest at 4.2 m (the chassis centroid starts at 0, the sprocket at
/// 2.0 m).
const RADIUS: f64 = 0.2;
const CREST: f64 = 4.0 + RADIUS;

/// The scene's wheels: the sprocket first, road wheels 1–5 (front to
/// rear), the idler.
const FRONT: usize = 1;
const REAR: usize = 5;

fn stiffness(law: &NormalLaw) -> f64 {
    match *law {
        NormalLaw::HuntCrossley {
            stiffness,
            exponent: 1.0,
            ..
        } => stiffness,
        NormalLaw::KelvinVoigt { stiffness, .. } => stiffness,
        other => panic!("the depths are bounded for a linear law, the M113 declares {other:?}"),
    }
}

/// A wheel's and a body's place in the hull's frame: `(x, y)` from the
/// world pose `point` of a hull at `(x, y, pitch)`.
fn in_hull(point: (f64, f64), hull: (f64, f64, f64)) -> (f64, f64) {
    let (dx, dy) = (point.0 - hull.0, point.1 - hull.1);
    let (s, c) = hull.2.sin_cos();
    (c * dx + s * dy, -s * dx + c * dy)
}

#[test]
fn the_hull_lifts_over_a_half_round_as_its_running_gear_s_envelope() {
    let course = Course::starting_at(-20.0, 0.0)
        .unwrap()
        .flat(24.0)
        .unwrap()
        .half_round(RADIUS)
        .unwrap()
        .flat(20.0)
        .unwrap();
    let mut config = M113::declared_config(
        Terrain::profile(course.profile().unwrap()),
        M113::speed_drive(speed_ramp(1.0, 1.0, 0.5)),
    );
    // The road wheels' torsion bars (the idler's tensioner is left alone:
    // it keeps the track's tension).
    let bar = trackgen::vehicles::m113::TORSION_STIFFNESS;
    for arm in &mut config.arms {
        if arm.spring.stiffness == bar {
            arm.spring.stiffness *= 1000.0;
            arm.spring.damping *= 1000f64.sqrt();
        }
    }
    let (k_ground, k_rim) = (
        stiffness(&config.ground.normal),
        stiffness(&config.wheels.normal),
    );
    let mut system = M113::system_with(config).unwrap();
    let results = simulate(
        &mut system,
        Integrator::DEFAULT,
        0.0,
        16.0,
        Output::Every(0.01),
    )
    .unwrap();
    let frames = Scene::of::<M113>().frames(&results, 0.01);

    let shoe = M113::geometry().shoe;
    let tips = &shoe.ground_points;
    let spacing = (tips[1].x - tips[0].x).abs();
    let thickness = shoe.inner_offset() - tips[0].y;
    let rho = frames[0].wheels[FRONT].2 + thickness;
    let sagitta = RADIUS - (RADIUS * RADIUS - spacing * spacing / 4.0).sqrt();
    let weight = m113_weight();

    // At 4 s all runs on the flat at 0.5 m/s, the front wheel 1.7 m short
    // of the crest: the hull's frame from there (the gear is rigid).
    let rest = frames.iter().find(|f| f.t >= 4.0).unwrap();
    // The hull's frame is centred on its centroid (`Frame::chassis`).
    let place = |f: &Frame, i: usize| in_hull((f.wheels[i].0, f.wheels[i].1), f.chassis);

    for (wheel, pivot) in [(1, REAR), (2, REAR), (4, FRONT), (5, FRONT)] {
        // The frame where the wheel's centre is nearest the crest's x
        // (5 mm apart at 0.5 m/s: its height changes by 2e-5 m there).
        let over = frames
            .iter()
            .min_by(|a, b| {
                let d = |f: &Frame| (f.wheels[wheel].0 - CREST).abs();
                d(a).total_cmp(&d(b))
            })
            .unwrap();
        let (wk, wj) = (place(rest, wheel), place(rest, pivot));
        let d = wk.0 - wj.0;
        // The centroid from the pivot wheel's centre, in the hull.
        let (cx, cy) = (-wj.0, -wj.1);
        // Each wheel's load at most the whole weight (see the header).
        let crest_depth =
            (weight / k_ground).max(weight / (2.0 * k_ground) + sagitta) + weight / k_rim;
        let flat_depth = weight / (2.0 * k_ground) + weight / k_rim;
        // The rigid pose with the crest's wheel `dk` and the pivot's `dj`
        // below the geometry: (pitch, centroid height).
        let pose = |dk: f64, dj: f64| {
            let (yk, yj) = (RADIUS + rho - dk, rho - dj);
            let pitch = ((yk - yj) / d).asin();
            let (s, c) = pitch.sin_cos();
            (pitch, yj + cx * s + cy * c)
        };
        let corners = [
            pose(0.0, 0.0),
            pose(crest_depth, 0.0),
            pose(0.0, flat_depth),
            pose(crest_depth, flat_depth),
        ];
        let range = |i: usize| {
            let values = corners.map(|p| if i == 0 { p.0 } else { p.1 });
            (
                values.iter().copied().fold(f64::INFINITY, f64::min),
                values.iter().copied().fold(f64::NEG_INFINITY, f64::max),
            )
        };
        let (pitch, height) = (over.chassis.2, over.chassis.1);
        let exact = pose(0.0, 0.0);
        println!(
            "wheel {wheel} on the crest at {:.2} s: pitch {pitch:.4} rad (geometry {:.4}, range {:.4}..{:.4}), \
             centroid {height:.4} m (geometry {:.4}, range {:.4}..{:.4})",
            over.t,
            exact.0,
            range(0).0,
            range(0).1,
            exact.1,
            range(1).0,
            range(1).1
        );
        for (what, value, (low, high)) in [
            ("pitch", pitch, range(0)),
            ("centroid height", height, range(1)),
        ] {
            assert!(
                (low..=high).contains(&value),
                "wheel {wheel} on the crest: {what} {value} outside the geometric envelope's {low}..{high}"
            );
        }
    }
}
