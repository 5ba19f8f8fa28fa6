//! Each track on its own ground ([`on_grounds`], [`HeightField::sides`];
//! [`on_grid`], heights on a grid):
//! the mirrored light carrier (`Twin`) driven straight at 2 m/s with a
//! cosine bump 60 mm high and 1 m long under one track alone, the other
//! on level ground.
//!
//! - The bump under the left track and the same bump under the right
//!   give mirror images (#41's check of a model with no preferred side):
//!   the heave, pitch and progress the same, the roll, heading and
//!   sideways place reversed, the sides' sprocket torques exchanged, to
//!   1e-9 (fixed RK4 steps, so both runs take the same steps; measured
//!   3.5e-11).
//! - The bumped side rises: the hull rolls away from the bump, and by
//!   less than the rigid bound `atan(h / B)` (the whole bumped track
//!   lifted by the bump's height `h`, `B` the gauge: the bump lifts only
//!   the wheels on it, and the suspension takes part of that: measured
//!   0.0129 rad of 0.0333).
//! - Two sides of one profile, made as `Sides`, drive the vehicle over
//!   the bump bit for bit as the profile laid across: the sides' route
//!   gives a track's points the same heights and slopes.
//! - A diagonal ridge on a grid and its mirror give mirror images.

use trackgen::integrate::{Integrator, OdeSystem};
use trackgen::nalgebra::DVector;
use trackgen::spatial::SpatialVehicle;
use trackgen::spatial_vehicle::{
    SideDrives, SpatialSimulated, SpatialVehicleSystem, on_grid, on_grounds,
};
use trackgen::terrain::Terrain;
use trackgen::terrain::field::{FieldShape, Grid, HeightField};

use crate::support::twin::{System, Twin, belt};

/// The bump: 60 mm high, 1 m long, its crest 2.5 m ahead (the `Twin`
/// assembles with its hull's centroid over x = 0).
fn bump() -> Terrain {
    Terrain::Bump {
        centre: 2.5,
        width: 1.0,
        height: 0.06,
    }
}

fn level() -> Terrain {
    Terrain::Flat { height: 0.0 }
}

/// Fixed steps: both mirrored runs take the same ones.
const FIXED: Integrator = Integrator::Rk4 { step: 1e-4 };
/// How long each run lasts, s: some 4.7 m driven, the bump under the
/// track's rear half by then.
const DURATION: f64 = 2.6;
/// The rows' interval, s.
const EVERY: f64 = 0.05;

/// What a row shows: heave-free height and pitch, progress, roll,
/// heading, sideways place (m, rad, m, rad, rad, m) and the sprockets'
/// torques (right, left; N m).
#[derive(Debug, Clone, Copy)]
struct Row {
    height: f64,
    pitch: f64,
    forward: f64,
    roll: f64,
    heading: f64,
    across: f64,
    torque: [f64; 2],
}

/// The `Twin` on `right` and `left` (the grounds under its right and left
/// tracks), both belts driven to 2 m/s over 0.5 s: its rows.
fn run(right: &Terrain, left: &Terrain) -> Vec<Row> {
    let (mut system, mut y, _) =
        on_grounds::<Twin>(Twin::declared_laws(), (right, left), 0.0).expect("on its grounds");
    drive(&mut system, &mut y)
}

/// `system` from `y`, both belts driven to 2 m/s over 0.5 s: its rows.
fn drive(system: &mut System, y: &mut DVector<f64>) -> Vec<Row> {
    system
        .set_drives(SideDrives {
            right: belt(2.0, 0.5),
            left: belt(2.0, 0.5),
        })
        .expect("the drives");
    let mut stepper = FIXED.stepper(system.dimension());
    let (mut t, mut rows) = (0.0, Vec::new());
    for k in 0..=(DURATION / EVERY).round() as usize {
        let next = k as f64 * EVERY;
        while t < next {
            stepper.step(system, &mut t, y, next).expect("steps");
        }
        rows.push(row(system, t, y));
    }
    rows
}

fn row(system: &System, t: f64, y: &DVector<f64>) -> Row {
    let out = system.outputs(t, y.as_slice()).expect("outputs");
    let (hull, ..) = system.states(y.as_slice());
    let root = hull.pose.origin;
    Row {
        height: root.z,
        pitch: out.pitch,
        forward: root.x,
        roll: out.roll,
        heading: out.heading,
        across: root.y,
        torque: [out.sides[0].sprocket_torque, out.sides[1].sprocket_torque],
    }
}

/// How far the rows `a` are from the mirror images of `b`: the heave,
/// pitch and progress against `b`'s, the roll, heading and sideways place
/// against theirs reversed (m, rad), the sprockets' torques against the
/// other side's (in kN m).
fn mirror_apart(a: &[Row], b: &[Row]) -> f64 {
    let mut apart: f64 = 0.0;
    for (l, r) in a.iter().zip(b) {
        for (p, q) in [
            (l.height, r.height),
            (l.pitch, r.pitch),
            (l.forward, r.forward),
            (l.roll, -r.roll),
            (l.heading, -r.heading),
            (l.across, -r.across),
            (l.torque[0] / 1e3, r.torque[1] / 1e3),
            (l.torque[1] / 1e3, r.torque[0] / 1e3),
        ] {
            apart = apart.max((p - q).abs());
        }
    }
    apart
}

#[test]
fn a_bump_under_one_track_mirrors_the_other_and_rolls_the_hull_away() {
    let (under_left, under_right) = std::thread::scope(|scope| {
        let left = scope.spawn(|| run(&level(), &bump()));
        (left.join().expect("the left run"), run(&bump(), &level()))
    });
    let apart = mirror_apart(&under_left, &under_right);
    let most_roll = under_left.iter().map(|r| r.roll).fold(0.0, f64::max);
    println!("mirror images apart by {apart:.1e}; the largest roll {most_roll:.5} rad");
    assert!(apart <= 1e-9, "the mirrored runs differ by {apart}");
    let rigid = (0.06_f64 / Twin::layout().gauge).atan();
    assert!(
        most_roll > 0.0 && most_roll < rigid,
        "the left side up by {most_roll} rad (the rigid bound {rigid})"
    );
    // It crossed the bump: 4.7 m driven, the bump 2 to 3 m ahead.
    let moved = under_left[under_left.len() - 1].forward - under_left[0].forward;
    assert!(moved > 4.0, "it drove {moved} m");
}

/// The field of two sides that are the same profile (made as `Sides`,
/// not folded into one profile as [`HeightField::sides`] folds it) drives
/// the `Twin` over the bump exactly as the profile laid across: the
/// sides' route gives a track's points the same heights and slopes,
/// bit for bit, and none stands in the band between the tracks.
#[test]
fn two_sides_of_one_profile_are_the_profile_laid_across() {
    let across = HeightField::profile(&bump());
    let sides = HeightField {
        base: FieldShape::Sides {
            left: bump(),
            right: bump(),
            divide: 0.0,
            band: Twin::layout().gauge - Twin::layout().shoe_width,
        },
        ..HeightField::level()
    };
    let rows = [across, sides].map(|field| {
        std::thread::spawn(move || {
            let mut system = Twin::spatial(Twin::declared_laws(), field).expect("the vehicle");
            let mut y = system.assembled(&bump()).expect("assembled");
            drive(&mut system, &mut y)
        })
    });
    let [a, b] = rows.map(|r| r.join().expect("the run"));
    for (p, q) in a.iter().zip(&b) {
        let bits = |r: &Row| {
            [
                r.height,
                r.pitch,
                r.forward,
                r.roll,
                r.torque[0],
                r.torque[1],
            ]
        };
        assert_eq!(
            bits(p).map(f64::to_bits),
            bits(q).map(f64::to_bits),
            "{p:?} against {q:?}"
        );
    }
}

/// [`HeightField::sides`] folds two equal profiles into one laid across;
/// two different ones put each track's points on its own, blended only
/// between the tracks.
#[test]
fn each_track_stands_on_its_own_profile() {
    let field = HeightField::sides(&bump(), &bump(), 1.5);
    assert_eq!(field.base, FieldShape::Profile(bump()));
    // Two grounds: each track's points on its own, blended between.
    let field = HeightField::sides(&level(), &bump(), 1.5);
    let crest = HeightField::profile(&bump()).height(2.5, 0.0);
    for y in [0.75, 0.9, 1.2] {
        assert_eq!(field.height(2.5, y), crest, "left, y = {y}");
        assert_eq!(field.height(2.5, -y), 0.0, "right, y = {y}");
    }
    assert!((field.height(2.5, 0.0) - 0.5 * crest).abs() < 1e-15);
}

/// A ridge 50 mm high and 1 m wide running diagonally across the path at
/// 45° (a cross-slope obstacle no profile can be), as heights on a grid
/// every 0.1 m; `toward_left`: its line running ahead toward the left
/// (the right track meets it first), else its mirror.
fn ridge(toward_left: bool) -> Grid {
    let (nx, ny, d) = (81, 41, 0.1);
    let (x0, y0) = (-1.0, -2.0);
    let mut heights = Vec::with_capacity(nx * ny);
    for j in 0..ny {
        for i in 0..nx {
            let (x, y) = (x0 + i as f64 * d, y0 + j as f64 * d);
            let along = if toward_left { x - y } else { x + y } - 3.5;
            let h = if along.abs() < 0.5 {
                0.025 * (1.0 + (std::f64::consts::PI * along / 0.5).cos())
            } else {
                0.0
            };
            heights.push(h);
        }
    }
    Grid::new((x0, y0), (d, d), (nx, ny), heights).expect("a grid")
}

/// The `Twin` over a diagonal ridge on a grid ([`on_grid`]) and over its
/// mirror give mirror images to 1e-9 (measured 4.7e-14): the grid's
/// heights and gradients, and each track's assembly on its section, hold
/// no preferred side. The ridge meets the right track first: the hull
/// rolls left (the right side up, roll negative) and then right as the
/// left track climbs it (measured: the roll from −0.0135 to 0.0130 rad),
/// and the ridge's push across turns it (0.0071 rad at most).
#[test]
fn a_diagonal_ridge_on_a_grid_mirrors_its_mirror() {
    let runs = [true, false].map(|toward_left| {
        std::thread::spawn(move || {
            let (mut system, mut y, _) =
                on_grid::<Twin>(Twin::declared_laws(), ridge(toward_left), 0.0).expect("on it");
            drive(&mut system, &mut y)
        })
    });
    let [a, b] = runs.map(|r| r.join().expect("the run"));
    let apart = mirror_apart(&a, &b);
    let (least, most) = a.iter().fold((0.0_f64, 0.0_f64), |(lo, hi), r| {
        (lo.min(r.roll), hi.max(r.roll))
    });
    let turned = a.iter().map(|r| r.heading.abs()).fold(0.0, f64::max);
    println!("apart {apart:.1e}; roll {least:.5} to {most:.5} rad; heading {turned:.5} rad");
    assert!(apart <= 1e-9, "the mirrored runs differ by {apart}");
    let first_up = a.iter().find(|r| r.roll.abs() > 1e-4).expect("it rolled");
    assert!(
        first_up.roll < 0.0,
        "the right side rose first: {first_up:?}"
    );
    assert!(least < -1e-4 && most > 1e-4, "{least} to {most}");
}
