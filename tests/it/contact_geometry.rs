//! Contact geometry of the three pairs and the cached trigonometry, against
//! hand-computed cases:
//! * ground (`GroundContact::apply`): an M113 shoe pressed into flat ground
//!   (level and tilted, moving) and into a ramp by known depths: per-point
//!   forces from the laws by hand, the elastic force equal to minus the
//!   gradient of the reported potential (finite differences), the moment
//!   about the centroid by hand; culling never skips a touching point
//!   (narrow spikes, and 400 random links over rough profiles against a
//!   point-by-point evaluation that does no culling);
//! * rims (`WheelContact::apply`): a rim pressing a shoe's inner face
//!   (mid-face and at its end, at rest and moving): point, normal, force,
//!   the reaction on the wheel, moment balance; nothing from the wrong side
//!   or out of reach; loads are added to, not overwritten;
//! * sprocket (`SprocketContact::apply`, `M113::geometry().sprocket`): seated
//!   pins touch nothing, a pin pushed into a flank or across the tip circle
//!   gets the depth and normal by hand, nothing outside the tip circle;
//!   `nearest_gap` by hand for a turned sprocket, and against all ten gaps;
//! * `BodyState::with_sin_cos` against `BodyState::new`, and the generated
//!   `body_states_with_trig` of the M113 track against `body_states`, the
//!   separate position and velocity routines, and the reference route.
//!
//! Tolerances, and why:
//! * Geometry by hand (points, penetrations, normals): `1e-12` m or `1e-12`
//!   relative. Coordinates are O(1) m built from a few products and sums
//!   (rounding ~1e-16 each); a penetration is the small difference of
//!   O(1) m quantities, so its absolute error is ~1e-16 m, i.e. 1e-13 of a
//!   1 mm depth. Any modelling error (wrong face, wrong side, a missing
//!   offset) is ≥ 1e-4 m.
//! * Forces and moments by hand: `1e-9` relative to the largest force
//!   (1e4 N), i.e. 1e-5 N (1e-6 N in places): a force is `k δ` with δ
//!   carrying ~1e-16 m of absolute error and `k = 1e7` N/m, so ~1e-9 N of
//!   error per point (1e-13 relative); the margin is generous because a
//!   wrong term (friction sign, a dropped `|g|`) is ≥ 1 % off.
//! * Random links against the unculled point-by-point evaluation: `1e-12`
//!   relative to the link's force (floor 1 N). The same formulas in the
//!   same order, except `sin` and `cos` taken separately against
//!   `sin_cos` (an ulp at most); a skipped grouser is off by 100 %.
//! * Moment balance of a pair about a common point: `1e-9` of `|F| · 1 m`;
//!   the terms are O(1e4) N m and cancel exactly in exact arithmetic.
//! * `−∇V` by central differences (step 1e-7 m) against the elastic force:
//!   the potential is quadratic in the point on a linear profile, so the
//!   difference is exact up to rounding `ε V / 1e-7 ≈ 2e-8` N; `1e-7`
//!   relative to the force (6e-4 N).
//! * Cached trigonometry: bit-exact where the same arithmetic is done in
//!   the same order (`new` vs `with_sin_cos`, `body_states` vs
//!   `body_states_with_trig`, trig given for other angles vs evaluating at
//!   those angles); against the reference route (dense sums over up to 64
//!   bodies with coordinates up to 12 m) `1e-13` relative to the largest
//!   entry, i.e. ~100 roundings of the largest term. Velocity from a
//!   central difference of the moving point (step 1e-6 s): truncation
//!   `ω³ |u| h² / 6 < 1e-12`, rounding `ε / h ≈ 2e-10`; `1e-8` m/s.

use crate::support;

use support::contact::{GroundContact, SprocketContact, WheelContact};

use std::f64::consts::PI;

use support::{Lcg, assert_close, max_abs, min_of};
use trackgen::contact::{BodyState, ContactForce, sprocket::ToothProfile};
use trackgen::laws::{Friction, NormalLaw};
use trackgen::nalgebra::{DVector, SVector, Vector2};
use trackgen::terrain::Terrain;
use trackgen::vehicle::Vehicle;
use trackgen::vehicles::{m113::M113, m113::M113Track};
use trackgen_runtime::reference::ReferenceModel;

/// The M113 track's coordinates.
const TRACK_DOF: usize = M113::TRACK_DOF;
use trackgen::multibody::{BodyLoad, RecursiveModel};

fn v(x: f64, y: f64) -> Vector2<f64> {
    Vector2::new(x, y)
}

fn cross(a: Vector2<f64>, b: Vector2<f64>) -> f64 {
    a.x * b.y - a.y * b.x
}

/// `A(θ) u` by hand.
fn rot(theta: f64, u: Vector2<f64>) -> Vector2<f64> {
    let (s, c) = (theta.sin(), theta.cos());
    v(c * u.x - s * u.y, s * u.x + c * u.y)
}

fn at_rest(position: Vector2<f64>, angle: f64) -> BodyState {
    BodyState::new(position, angle, Vector2::zeros(), 0.0)
}

fn close_vec(label: &str, got: Vector2<f64>, want: Vector2<f64>, tol: f64) {
    assert!(
        (got - want).norm() <= tol,
        "{label}: got {got:?}, want {want:?} (off by {:e})",
        (got - want).norm()
    );
}

fn close(label: &str, got: f64, want: f64, tol: f64) {
    assert!(
        (got - want).abs() <= tol,
        "{label}: got {got}, want {want} (off by {:e})",
        (got - want).abs()
    );
}

// ---------------------------------------------------------------------
// Ground.

/// The ground contacts of one link, and its load.
fn ground_on(ground: &GroundContact, link: &BodyState) -> (Vec<ContactForce>, BodyLoad) {
    let mut loads = [BodyLoad::ZERO];
    let mut contacts = vec![];
    ground.apply(
        std::slice::from_ref(link),
        &M113::geometry().shoe,
        &mut loads,
        |i, c| {
            assert_eq!(i, 0);
            contacts.push(*c)
        },
    );
    (contacts, loads[0])
}

/// A level shoe 4 mm into flat ground, sinking at 0.1 m/s and turning at
/// 0.5 rad/s: each grouser's force, friction and energy terms by hand.
#[test]
fn ground_flat_moving_shoe_by_hand() {
    let ground = GroundContact {
        terrain: Terrain::Flat { height: 0.0 },
        normal: NormalLaw::HuntCrossley {
            stiffness: 2e6,
            exponent: 1.0,
            chi: 2.0,
        },
        friction: Friction { mu: 0.8, slip: 0.1 },
    };
    // Grousers at ū = (∓0.06, −0.03): centroid 0.026 m up puts them at
    // y = −0.004.
    let link = BodyState::new(v(1.0, 0.026), 0.0, v(0.0, -0.1), 0.5);
    let (contacts, load) = ground_on(&ground, &link);
    assert_eq!(contacts.len(), 2);
    // Point velocities Ṙ + ω (−u_y, u_x): (0.015, −0.13) and (0.015, −0.07);
    // closing rates 0.13 and 0.07 m/s; k δ = 8000 N.
    let normals: [f64; 2] = [8000.0 * (1.0 + 2.0 * 0.13), 8000.0 * (1.0 + 2.0 * 0.07)];
    assert!((normals[0] - 10080.0).abs() < 1e-9 && (normals[1] - 9120.0).abs() < 1e-9);
    let rates = [0.13, 0.07];
    let slip = 0.015;
    let arms = [v(-0.06, -0.03), v(0.06, -0.03)];
    let mut force = Vector2::zeros();
    let mut moment = 0.0;
    for (i, c) in contacts.iter().enumerate() {
        let friction = -0.8 * normals[i] * slip / (slip * slip + 0.01f64).sqrt();
        let f = v(friction, normals[i]);
        close_vec("point", c.point, v(1.0, 0.026) + arms[i], 1e-12);
        close("penetration", c.penetration, 0.004, 1e-12);
        close("normal", c.normal, normals[i], 1e-9 * 1e4);
        close_vec("force", c.force, f, 1e-9 * 1e4);
        close("potential", c.potential, 0.5 * 2e6 * 0.004 * 0.004, 1e-9);
        // Damping (N − k δ) δ̇ and friction −F_t v_t.
        let dissipation = (normals[i] - 8000.0) * rates[i] - friction * slip;
        close("dissipation", c.dissipation, dissipation, 1e-9 * 1e4);
        force += f;
        moment += cross(arms[i], f);
    }
    // Friction pulls back (−x) against the forward slip.
    assert!(force.x < -1000.0);
    close_vec("load force", load.force, force, 1e-9 * 2e4);
    // −0.06 N₁ + 0.06 N₂ + 0.03 (F_t1 + F_t2).
    close("load moment", load.moment, moment, 1e-9 * 2e4);
    close(
        "moment by hand",
        moment,
        0.06 * (9120.0 - 10080.0) + 0.03 * force.x,
        1e-9,
    );
}

/// A shoe tilted by 0.1 rad at rest, its rear grouser 5 mm in and the
/// front one clear: one vertical force, and its moment about the centroid.
#[test]
fn ground_tilted_shoe_by_hand() {
    let ground = GroundContact {
        terrain: Terrain::Flat { height: 0.0 },
        normal: NormalLaw::KelvinVoigt {
            stiffness: 2e6,
            damping: 5e3,
        },
        friction: Friction { mu: 0.8, slip: 0.1 },
    };
    let (s, c) = (0.1f64.sin(), 0.1f64.cos());
    // Rear grouser arm A ū = (−0.06c + 0.03s, −0.06s − 0.03c).
    let arm = v(-0.06 * c + 0.03 * s, -0.06 * s - 0.03 * c);
    let y0 = -0.005 - arm.y;
    let link = at_rest(v(0.0, y0), 0.1);
    let (contacts, load) = ground_on(&ground, &link);
    // The front grouser is 0.12 sin 0.1 − 0.005 = 7 mm up.
    assert_eq!(contacts.len(), 1);
    close("penetration", contacts[0].penetration, 0.005, 1e-12);
    close_vec("point", contacts[0].point, v(arm.x, -0.005), 1e-12);
    close_vec("force", load.force, v(0.0, 1e4), 1e-5);
    close("moment", load.moment, arm.x * 1e4, 1e-5);
    assert!(
        load.moment < -500.0,
        "the force at the rear turns the shoe nose-down"
    );
}

/// A shoe on a 1:4 ramp. Flush with it and 3 mm (vertically) in: each
/// grouser gets `k δ (−h', 1)`, of size `k δ √(1 + h'²)`, the gradient of
/// the contact's potential, and the pair's moment vanishes (both forces
/// along the shoe's own normal through its pitch line's foot). Tilted
/// 0.15 rad further: one grouser, its force by `−∇V` and its moment.
#[test]
fn ground_ramp_by_hand_and_by_gradient() {
    let k = 2e6;
    let ground = GroundContact {
        terrain: Terrain::Ramp {
            height: 0.0,
            start: 0.0,
            slope: 0.25,
        },
        normal: NormalLaw::KelvinVoigt {
            stiffness: k,
            damping: 1e3,
        },
        friction: Friction { mu: 0.8, slip: 0.1 },
    };
    let alpha = 0.25f64.atan();
    let depth = 0.003;
    let g = v(-0.25, 1.0);
    // Midpoint of the grousers 3 mm below the surface at x = 2.
    let foot = v(2.0, 0.5 - depth);
    let link = at_rest(foot - rot(alpha, v(0.0, -0.03)), alpha);
    let (contacts, load) = ground_on(&ground, &link);
    assert_eq!(contacts.len(), 2);
    let potential = |p: Vector2<f64>| ground.normal.potential(0.25 * p.x - p.y);
    for (i, c) in contacts.iter().enumerate() {
        let side = [-1.0, 1.0][i];
        close_vec(
            "point",
            c.point,
            foot + rot(alpha, v(0.06 * side, 0.0)),
            1e-12,
        );
        close("vertical penetration", c.penetration, depth, 1e-12);
        close_vec("force", c.force, g * (k * depth), 1e-5);
        close("normal", c.normal, k * depth * 1.0625f64.sqrt(), 1e-5);
        // The force is −∇ of the potential of this point.
        let e = 1e-7;
        let grad = v(
            (potential(c.point + v(e, 0.0)) - potential(c.point - v(e, 0.0))) / (2.0 * e),
            (potential(c.point + v(0.0, e)) - potential(c.point - v(0.0, e))) / (2.0 * e),
        );
        close_vec("−∇V", c.force, -grad, 1e-7 * 6000.0);
    }
    close_vec("load", load.force, g * (2.0 * k * depth), 1e-5);
    close("flush: no moment", load.moment, 0.0, 1e-9 * 6000.0);

    // Tilted nose-up by 0.15 rad more: only the rear grouser touches; put
    // it 4 mm (vertically) under the surface at x = 2.
    let tilt = alpha + 0.15;
    let arm = rot(tilt, v(-0.06, -0.03));
    let target = v(2.0, 0.5 - 0.004);
    let link = at_rest(target - arm, tilt);
    let (contacts, load) = ground_on(&ground, &link);
    assert_eq!(contacts.len(), 1);
    let f = g * (k * 0.004);
    close("penetration", contacts[0].penetration, 0.004, 1e-12);
    close_vec("force", load.force, f, 1e-5);
    close("moment", load.moment, cross(arm, f), 1e-5);
    close(
        "moment by hand",
        cross(arm, f),
        arm.x * 8000.0 + arm.y * 2000.0,
        1e-9,
    );
}

/// Culling: a shoe whose bounding circle reaches below the ground but
/// whose grousers do not gets nothing; a narrow spike between the ends of
/// the culling interval, under a grouser, is found; a shoe 1 mm clear of
/// flat ground gets nothing and its load stays as it was.
#[test]
fn ground_culling_never_skips_a_touching_point() {
    let shoe = M113::geometry().shoe;
    let extent = shoe.extent();
    // The inner face's corners are the farthest features.
    close("extent", extent, f64::hypot(0.077, 0.03), 1e-15);
    let law = NormalLaw::KelvinVoigt {
        stiffness: 2e6,
        damping: 0.0,
    };
    let flat = GroundContact {
        terrain: Terrain::Flat { height: 0.0 },
        normal: law,
        friction: Friction { mu: 0.8, slip: 0.1 },
    };
    // Grousers 1 mm up.
    let (contacts, load) = ground_on(&flat, &at_rest(v(0.0, 0.031), 0.0));
    assert!(contacts.is_empty());
    assert_eq!(load, BodyLoad::ZERO);
    // Bounding circle 0.1 mm into the ground, grousers 5 cm up.
    let (contacts, load) = ground_on(&flat, &at_rest(v(0.0, extent - 1e-4), 0.0));
    assert!(contacts.is_empty());
    assert_eq!(load, BodyLoad::ZERO);
    // A post 2 cm wide at the base, 60 mm high, flat-topped (1 cm) under
    // the rear grouser (x = 0.94), grousers 57.5 mm up: it reaches 2.5 mm
    // in. The bounding circle's bottom (4.9 mm up) clears the table's
    // value at both ends of the culling interval: only the knots between
    // them show that the link must be looked at.
    let spike = GroundContact {
        terrain: Terrain::table(vec![(0.93, 0.0), (0.935, 0.06), (0.945, 0.06), (0.95, 0.0)])
            .unwrap(),
        ..flat.clone()
    };
    let link = at_rest(v(1.0, 0.0875), 0.0);
    assert!(link.position.y - extent > 0.004);
    let (contacts, load) = ground_on(&spike, &link);
    assert_eq!(contacts.len(), 1);
    close("spike depth", contacts[0].penetration, 0.0025, 1e-12);
    close_vec("spike force", load.force, v(0.0, 5000.0), 1e-6);
    // The same with the spike under the link's centre: no grouser there.
    let centred = GroundContact {
        terrain: Terrain::table(vec![(0.99, 0.0), (1.0, 0.06), (1.01, 0.0)]).unwrap(),
        ..flat.clone()
    };
    assert!(ground_on(&centred, &link).0.is_empty());
    // A pit narrower than the shoe (a dip) cannot hold it up.
    let dip = GroundContact {
        terrain: Terrain::Bump {
            centre: 1.0,
            width: 0.1,
            height: -0.05,
        },
        ..flat
    };
    let (contacts, _) = ground_on(&dip, &at_rest(v(1.0, 0.028), 0.0));
    assert_eq!(
        contacts.len(),
        2,
        "the grousers at ±0.06 m straddle the 0.1 m pit"
    );
}

/// One grouser's contact, evaluated without any culling (the route of the
/// module docs, written out).
fn ground_point_by_hand(
    ground: &GroundContact,
    link: &BodyState,
    local: Vector2<f64>,
) -> Option<(Vector2<f64>, Vector2<f64>)> {
    let arm = rot(link.angle, local);
    let p = link.position + arm;
    let (h, slope) = ground.terrain.height_and_slope(p.x);
    let depth = h - p.y;
    if depth <= 0.0 {
        return None;
    }
    let vel = link.velocity + v(-arm.y, arm.x) * link.omega;
    let g = v(-slope, 1.0);
    let normal = ground.normal.force(depth, -vel.dot(&g));
    let tangent = v(1.0, slope) / g.norm();
    let friction = ground.friction.force(normal * g.norm(), vel.dot(&tangent));
    Some((arm, g * normal + tangent * friction))
}

/// 400 links at random poses and motions over rough profiles (a table of
/// narrow peaks and pits, a dip, a short sine, a ramp), in one call: each
/// link's load equals the sum over its grousers evaluated one by one
/// without culling, and the contacts are reported for the right links.
#[test]
fn ground_matches_an_unculled_evaluation() {
    let shoe = M113::geometry().shoe;
    let mut rng = Lcg::new(21);
    let mut table = vec![(-3.0, 0.0)];
    let mut x = -3.0;
    while x < 3.0 {
        x += rng.uniform(0.005, 0.06);
        table.push((x, rng.uniform(-0.03, 0.03)));
    }
    let terrains = [
        Terrain::table(table).unwrap(),
        Terrain::Bump {
            centre: 0.0,
            width: 0.5,
            height: -0.04,
        },
        Terrain::Sine {
            amplitude: 0.02,
            wavelength: 0.09,
        },
        Terrain::Ramp {
            height: 0.0,
            start: 0.0,
            slope: -0.4,
        },
    ];
    for terrain in terrains {
        let ground = GroundContact {
            terrain,
            normal: NormalLaw::HuntCrossley {
                stiffness: 2e6,
                exponent: 1.0,
                chi: 2.0,
            },
            friction: Friction { mu: 0.8, slip: 0.1 },
        };
        let links: Vec<BodyState> = (0..100)
            .map(|_| {
                let x = rng.uniform(-2.5, 2.5);
                let y = ground.terrain.height(x) + rng.uniform(-0.02, 0.12);
                BodyState::new(
                    v(x, y),
                    rng.uniform(-1.0, 1.0),
                    v(rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0)),
                    rng.uniform(-2.0, 2.0),
                )
            })
            .collect();
        let mut loads = vec![BodyLoad::ZERO; links.len()];
        let mut counts = vec![0; links.len()];
        ground.apply(&links, &shoe, &mut loads, |i, _| counts[i] += 1);
        let mut touching = 0;
        for (i, link) in links.iter().enumerate() {
            let mut want = BodyLoad::ZERO;
            let mut n = 0;
            for local in &shoe.ground_points {
                if let Some((arm, f)) = ground_point_by_hand(&ground, link, *local) {
                    want = want.plus(BodyLoad {
                        force: f,
                        moment: cross(arm, f),
                    });
                    n += 1;
                }
            }
            assert_eq!(counts[i], n, "{:?} link {i}: contacts", ground.terrain);
            let scale = want.force.norm().max(1.0);
            close_vec("load", loads[i].force, want.force, 1e-12 * scale);
            close("moment", loads[i].moment, want.moment, 1e-12 * scale);
            touching += (n > 0) as usize;
        }
        assert!(
            (10..90).contains(&touching),
            "{:?}: {touching} of 100 links touch (the sample should mix both)",
            ground.terrain
        );
    }
}

// ---------------------------------------------------------------------
// Rims.

fn rim_pair(law: NormalLaw) -> WheelContact {
    WheelContact {
        normal: law,
        friction: Friction { mu: 0.4, slip: 0.5 },
    }
}

/// Runs a rim against one link; the loads start from `start` so that a
/// pair that overwrote them instead of adding would show.
fn rim_on(
    pair: &WheelContact,
    wheel: &BodyState,
    radius: f64,
    link: &BodyState,
) -> (Vec<ContactForce>, BodyLoad, BodyLoad) {
    let start = BodyLoad {
        force: v(1.0, -2.0),
        moment: 3.0,
    };
    let (mut loads, mut wheel_load) = ([start], start);
    let mut contacts = vec![];
    pair.apply(
        (wheel, radius),
        std::slice::from_ref(link),
        &M113::geometry().shoe,
        &mut loads,
        &mut wheel_load,
        |i, c| {
            assert_eq!(i, 0);
            contacts.push(*c)
        },
    );
    let minus = |l: BodyLoad| BodyLoad {
        force: l.force - start.force,
        moment: l.moment - start.moment,
    };
    (contacts, minus(loads[0]), minus(wheel_load))
}

/// Equal and opposite forces at one point: the moments about the origin
/// (`R × F + M` of each body) cancel.
fn assert_balanced(
    label: &str,
    (a, load_a): (&BodyState, BodyLoad),
    (b, load_b): (&BodyState, BodyLoad),
) {
    let scale = load_a.force.norm().max(1.0);
    close_vec(
        &format!("{label}: forces"),
        load_a.force + load_b.force,
        Vector2::zeros(),
        1e-12 * scale,
    );
    let total = cross(a.position, load_a.force)
        + load_a.moment
        + cross(b.position, load_b.force)
        + load_b.moment;
    close(&format!("{label}: moments"), total, 0.0, 1e-9 * scale);
}

/// A 0.3 m rim 2 mm into a level shoe's inner face (y = 0.03) above
/// x = 0.02, both at rest: 2e4 N straight down on the shoe at (0.02,
/// 0.03), moment −0.02 · 2e4 = −400 N m; the reaction up on the wheel
/// through its centre (no moment).
#[test]
fn rim_on_face_at_rest_by_hand() {
    let pair = rim_pair(NormalLaw::KelvinVoigt {
        stiffness: 1e7,
        damping: 3e3,
    });
    let link = at_rest(Vector2::zeros(), 0.0);
    let wheel = at_rest(v(0.02, 0.03 + 0.3 - 0.002), 0.0);
    let (contacts, link_load, wheel_load) = rim_on(&pair, &wheel, 0.3, &link);
    assert_eq!(contacts.len(), 1);
    let c = contacts[0];
    close_vec("point", c.point, v(0.02, 0.03), 1e-12);
    close("penetration", c.penetration, 0.002, 1e-12);
    close("normal", c.normal, 2e4, 1e-5);
    close_vec("force", c.force, v(0.0, -2e4), 1e-5);
    close_vec("link force", link_load.force, v(0.0, -2e4), 1e-5);
    close("link moment", link_load.moment, -400.0, 1e-5);
    close_vec("wheel force", wheel_load.force, v(0.0, 2e4), 1e-5);
    close("wheel moment", wheel_load.moment, 0.0, 1e-5);
    close("potential", c.potential, 0.5 * 1e7 * 0.002 * 0.002, 1e-9);
    close("dissipation", c.dissipation, 0.0, 1e-9);
    assert_balanced("at rest", (&link, link_load), (&wheel, wheel_load));
}

/// The expected exchange between a link and another body at `point` with
/// unit normal `n` (on the link) and penetration `depth`, by hand.
fn exchange_by_hand(
    (law, friction): (NormalLaw, Friction),
    link: &BodyState,
    other: &BodyState,
    (point, n, depth): (Vector2<f64>, Vector2<f64>, f64),
) -> (Vector2<f64>, BodyLoad, BodyLoad) {
    let (la, oa) = (point - link.position, point - other.position);
    let rel = (link.velocity + v(-la.y, la.x) * link.omega)
        - (other.velocity + v(-oa.y, oa.x) * other.omega);
    let fn_ = law.force(depth, -rel.dot(&n));
    let t = v(-n.y, n.x);
    let slip = rel.dot(&t);
    let ft = -friction.mu * fn_ * slip / (slip * slip + friction.slip * friction.slip).sqrt();
    let f = n * fn_ + t * ft;
    (
        f,
        BodyLoad {
            force: f,
            moment: cross(la, f),
        },
        BodyLoad {
            force: -f,
            moment: cross(oa, -f),
        },
    )
}

/// A turned, moving shoe and a spinning, moving rim 3 mm into its face at
/// 30 % of its length: the point is on the face, the normal is the face's
/// outward normal (into the shoe, away from the rim), and the force and
/// both loads are the laws' on the relative velocity, by hand.
#[test]
fn rim_on_face_moving_by_hand() {
    let law = NormalLaw::HuntCrossley {
        stiffness: 1e7,
        exponent: 1.0,
        chi: 0.5,
    };
    let pair = rim_pair(law);
    let theta = 0.4;
    let link = BodyState::new(v(1.0, 0.5), theta, v(0.3, -0.2), 1.2);
    let face = v(-0.077 + 0.3 * 0.154, 0.03);
    let on_face = v(1.0, 0.5) + rot(theta, face);
    let inward = rot(theta, v(0.0, 1.0));
    let radius = 0.33;
    let wheel = BodyState::new(on_face + inward * (radius - 0.003), -1.0, v(0.5, 0.1), -2.0);
    let (contacts, link_load, wheel_load) = rim_on(&pair, &wheel, radius, &link);
    assert_eq!(contacts.len(), 1);
    let c = contacts[0];
    close_vec("point", c.point, on_face, 1e-12);
    close("penetration", c.penetration, 0.003, 1e-12);
    let (f, want_link, want_wheel) = exchange_by_hand(
        (law, pair.friction),
        &link,
        &wheel,
        (on_face, -inward, 0.003),
    );
    assert!(f.norm() > 1e4, "a real force: {f:?}");
    close_vec("force", c.force, f, 1e-9 * 1e4);
    close("normal", c.normal, f.dot(&-inward), 1e-9 * 1e4);
    close_vec("link force", link_load.force, want_link.force, 1e-9 * 1e4);
    close(
        "link moment",
        link_load.moment,
        want_link.moment,
        1e-9 * 1e4,
    );
    close_vec(
        "wheel force",
        wheel_load.force,
        want_wheel.force,
        1e-9 * 1e4,
    );
    close(
        "wheel moment",
        wheel_load.moment,
        want_wheel.moment,
        1e-9 * 1e4,
    );
    assert_balanced("moving", (&link, link_load), (&wheel, wheel_load));
}

/// A rim beyond the end of the face touches its corner: the normal runs
/// from the rim's centre through the corner. A rim on the ground side of
/// the face, one just out of reach, and one whose centre is on the face's
/// line get nothing, and leave the loads alone.
#[test]
fn rim_at_corner_wrong_side_and_out_of_reach() {
    let pair = rim_pair(NormalLaw::KelvinVoigt {
        stiffness: 1e7,
        damping: 0.0,
    });
    let link = at_rest(Vector2::zeros(), 0.0);
    // Corner b = (0.077, 0.03); centre 0.1 m beyond, 0.25 m above.
    let corner = v(0.077, 0.03);
    let centre = corner + v(0.1, 0.25);
    let wheel = at_rest(centre, 0.0);
    let distance = f64::hypot(0.1, 0.25);
    let radius = 0.27;
    let (contacts, link_load, wheel_load) = rim_on(&pair, &wheel, radius, &link);
    assert_eq!(contacts.len(), 1);
    let n = v(-0.1, -0.25) / distance;
    close_vec("corner point", contacts[0].point, corner, 1e-12);
    close(
        "corner depth",
        contacts[0].penetration,
        radius - distance,
        1e-12,
    );
    close_vec(
        "corner force",
        link_load.force,
        n * (1e7 * (radius - distance)),
        1e-6,
    );
    assert_balanced("corner", (&link, link_load), (&wheel, wheel_load));

    // Wrong side: the same overlap of 2 mm, but from below the face.
    let below = at_rest(v(0.02, 0.03 - 0.3 + 0.002), 0.0);
    // Out of reach: 1 µm clear of the face.
    let clear = at_rest(v(0.02, 0.03 + 0.3 + 1e-6), 0.0);
    // Centre on the face's line (inside the shoe).
    let on_line = at_rest(v(0.02, 0.03), 0.0);
    for (label, wheel) in [("below", below), ("clear", clear), ("on line", on_line)] {
        let (contacts, link_load, wheel_load) = rim_on(&pair, &wheel, 0.3, &link);
        assert!(contacts.is_empty(), "{label}: {contacts:?}");
        assert_eq!(link_load.force, Vector2::zeros(), "{label}");
        assert_eq!(link_load.moment, 0.0, "{label}");
        assert_eq!(wheel_load.force, Vector2::zeros(), "{label}");
    }
    // The same rim from below does touch a shoe turned over (its inner
    // side now faces down).
    let flipped = at_rest(Vector2::zeros(), PI);
    let (contacts, _, _) = rim_on(
        &pair,
        &at_rest(v(-0.02, -0.03 - 0.3 + 0.002), 0.0),
        0.3,
        &flipped,
    );
    assert_eq!(contacts.len(), 1);
    close("flipped depth", contacts[0].penetration, 0.002, 1e-12);
}

// ---------------------------------------------------------------------
// Sprocket.

fn sprocket_pair(law: NormalLaw) -> SprocketContact {
    SprocketContact {
        profile: M113::geometry().sprocket,
        normal: law,
        friction: Friction { mu: 0.4, slip: 0.5 },
    }
}

/// A link with its rear pin (ū = (−0.061, 0)) at `pin`, pointing away from
/// the sprocket centre so that its front pin is far outside the teeth.
fn link_with_rear_pin(sprocket: &BodyState, pin: Vector2<f64>) -> BodyState {
    let out = (pin - sprocket.position).normalize();
    BodyState::new(pin + out * 0.061, out.y.atan2(out.x), Vector2::zeros(), 0.0)
}

fn sprocket_on(
    pair: &SprocketContact,
    sprocket: &BodyState,
    link: &BodyState,
) -> (Vec<ContactForce>, BodyLoad, BodyLoad) {
    let (mut loads, mut sprocket_load) = ([BodyLoad::ZERO], BodyLoad::ZERO);
    let mut contacts = vec![];
    pair.apply(
        sprocket,
        std::slice::from_ref(link),
        &M113::geometry().shoe,
        &mut loads,
        &mut sprocket_load,
        |i, c| {
            assert_eq!(i, 0);
            contacts.push(*c)
        },
    );
    (contacts, loads[0], sprocket_load)
}

/// The unit vector at angle `a`.
fn dir(a: f64) -> Vector2<f64> {
    v(a.cos(), a.sin())
}

/// Pins seated in a gap touch nothing: at the gap's arc centre (0.3 m
/// out), and on the joints' pitch circle (0.154 / (2 sin 18°) = 0.249 m,
/// 0.051 m from the arc centre: 0.051 + 0.015 < 0.089).
#[test]
fn seated_pins_touch_nothing() {
    let pair = sprocket_pair(NormalLaw::KelvinVoigt {
        stiffness: 1e7,
        damping: 0.0,
    });
    let profile = pair.profile;
    let sprocket = at_rest(v(0.5, 0.2), 0.1);
    let pitch_radius = 0.154 / (2.0 * (PI / 10.0).sin());
    for k in 0..10 {
        let phi = 0.1 + (k as f64 + 0.5) * profile.pitch_angle();
        for r in [0.3, pitch_radius] {
            let link = link_with_rear_pin(&sprocket, sprocket.position + dir(phi) * r);
            let (contacts, load, sprocket_load) = sprocket_on(&pair, &sprocket, &link);
            assert!(contacts.is_empty(), "gap {k}, r = {r}: {contacts:?}");
            assert_eq!(load, BodyLoad::ZERO);
            assert_eq!(sprocket_load, BodyLoad::ZERO);
        }
    }
}

/// A pin pushed 3 mm into a flank, 50° from the gap's inward radial: the
/// penetration is 3 mm, the normal points from the pin back to the gap's
/// arc centre, the point is on the arc (0.089 m from its centre), the
/// force is k δ along the normal at rest, and the reaction balances.
#[test]
fn pin_in_flank_by_hand() {
    let pair = sprocket_pair(NormalLaw::KelvinVoigt {
        stiffness: 1e7,
        damping: 2e3,
    });
    let profile = pair.profile;
    let sprocket = at_rest(v(0.5, 0.2), 0.1);
    for (k, psi) in [(2.0, 50.0f64), (7.0, -50.0)] {
        let phi = 0.1 + (k + 0.5) * profile.pitch_angle();
        let gap = sprocket.position + dir(phi) * 0.3;
        let w = rot(psi.to_radians(), -dir(phi));
        let pin = gap + w * (0.089 - 0.015 + 0.003);
        // Still inside the tip circle by more than 3 mm: the flank is the
        // shorter way out.
        let into_tip = 0.2605 + 0.015 - (pin - sprocket.position).norm();
        assert!(into_tip > 0.004, "{into_tip}");
        let link = link_with_rear_pin(&sprocket, pin);
        let (contacts, load, sprocket_load) = sprocket_on(&pair, &sprocket, &link);
        assert_eq!(contacts.len(), 1, "gap {k}");
        let c = contacts[0];
        close("penetration", c.penetration, 0.003, 1e-12);
        close_vec("point", c.point, gap + w * 0.089, 1e-12);
        close_vec("force", c.force, -w * 3e4, 1e-5);
        close_vec("link load", load.force, -w * 3e4, 1e-5);
        close(
            "link moment",
            load.moment,
            cross(c.point - link.position, -w * 3e4),
            1e-5,
        );
        close_vec("sprocket load", sprocket_load.force, w * 3e4, 1e-5);
        close(
            "sprocket moment",
            sprocket_load.moment,
            cross(c.point - sprocket.position, w * 3e4),
            1e-5,
        );
        // A flank force has a lever about the sprocket's centre (it is
        // what turns drive torque into tension): 0.3 m · 3e4 N · sin 50°.
        close(
            "sprocket torque",
            sprocket_load.moment.abs(),
            0.3 * 3e4 * psi.to_radians().sin().abs(),
            1e-5,
        );
        assert_balanced("flank", (&link, load), (&sprocket, sprocket_load));
    }
}

/// The same flank contact, moving: link and sprocket translating and
/// spinning; force and loads by hand from the relative velocity.
#[test]
fn pin_in_flank_moving_by_hand() {
    let law = NormalLaw::HuntCrossley {
        stiffness: 1e7,
        exponent: 1.0,
        chi: 0.5,
    };
    let pair = sprocket_pair(law);
    let sprocket = BodyState::new(v(-0.3, 0.4), -2.0, v(1.0, 0.2), -4.0);
    let phi = -2.0 + 4.5 * pair.profile.pitch_angle();
    let gap = sprocket.position + dir(phi) * 0.3;
    let w = rot(-0.6, -dir(phi));
    let pin = gap + w * (0.074 + 0.002);
    let placed = link_with_rear_pin(&sprocket, pin);
    let link = BodyState::new(placed.position, placed.angle, v(0.8, -0.5), 1.5);
    let (contacts, load, sprocket_load) = sprocket_on(&pair, &sprocket, &link);
    assert_eq!(contacts.len(), 1);
    let point = gap + w * 0.089;
    close_vec("point", contacts[0].point, point, 1e-12);
    let (f, want_link, want_sprocket) =
        exchange_by_hand((law, pair.friction), &link, &sprocket, (point, -w, 0.002));
    assert!(f.norm() > 1e3);
    close_vec("force", contacts[0].force, f, 1e-9 * 1e4);
    close_vec("link", load.force, want_link.force, 1e-9 * 1e4);
    close("link moment", load.moment, want_link.moment, 1e-9 * 1e4);
    close_vec(
        "sprocket",
        sprocket_load.force,
        want_sprocket.force,
        1e-9 * 1e4,
    );
    close(
        "sprocket moment",
        sprocket_load.moment,
        want_sprocket.moment,
        1e-9 * 1e4,
    );
    assert_balanced("moving flank", (&link, load), (&sprocket, sprocket_load));
}

/// A pin over a tooth: 2 mm inside the tip circle it is pushed radially
/// out (the shorter way: the gap is ~20 mm away); 1 mm outside the tip
/// circle it touches nothing.
#[test]
fn pin_on_tooth_tip_and_outside() {
    let pair = sprocket_pair(NormalLaw::KelvinVoigt {
        stiffness: 1e7,
        damping: 0.0,
    });
    let beta = pair.profile.pitch_angle();
    let sprocket = at_rest(Vector2::zeros(), 0.0);
    // Tooth 3 is centred at 3β = 108°; 0.01 rad off centre breaks the tie
    // between the two gaps (at 90° and 126°).
    let a = 3.0 * beta + 0.01;
    let r = 0.2605 + 0.015 - 0.002;
    let pin = dir(a) * r;
    // Distance to the nearer gap centre, at 3.5β: the flank depth.
    let gap_distance = (pin - dir(3.5 * beta) * 0.3).norm();
    let into_flank = gap_distance + 0.015 - 0.089;
    assert!(into_flank > 0.01, "{into_flank}");
    let link = link_with_rear_pin(&sprocket, pin);
    let (contacts, load, sprocket_load) = sprocket_on(&pair, &sprocket, &link);
    assert_eq!(contacts.len(), 1);
    let c = contacts[0];
    close("tip depth", c.penetration, 0.002, 1e-12);
    close_vec("tip point", c.point, dir(a) * 0.2605, 1e-12);
    close_vec("tip force", c.force, dir(a) * 2e4, 1e-5);
    // Radial: no moment on the sprocket.
    close("sprocket moment", sprocket_load.moment, 0.0, 1e-9 * 2e4);
    assert_balanced("tip", (&link, load), (&sprocket, sprocket_load));
    // Outside the tip circle.
    let outside = link_with_rear_pin(&sprocket, dir(a) * (0.2605 + 0.015 + 0.001));
    assert!(sprocket_on(&pair, &sprocket, &outside).0.is_empty());
}

/// `nearest_gap` for a sprocket at (1, −0.5) turned by 2 rad: a point at
/// angle 2 + fβ belongs to the gap at 2 + (k + ½)β, the half-integer
/// nearest to f; and, for random points and turns, it is the nearest of
/// all the gap centres, for sprockets of 3 to 100 teeth.
#[test]
fn nearest_gap_by_hand_and_by_search() {
    let profile = M113::geometry().sprocket;
    let beta = profile.pitch_angle();
    close("pitch angle", beta, 36f64.to_radians(), 1e-15);
    let centre = v(1.0, -0.5);
    let sprocket = at_rest(centre, 2.0);
    for (f, half) in [
        (3.3, 3.5),
        (3.9, 3.5),
        (4.1, 4.5),
        (-0.2, -0.5),
        (0.2, 0.5),
        (9.7, 9.5),
        (12.3, 12.5),
        (-6.6, -6.5),
    ] {
        let p = centre + dir(2.0 + f * beta) * 0.25;
        let want = centre + dir(2.0 + half * beta) * 0.3;
        close_vec(
            &format!("f = {f}"),
            profile.nearest_gap(&sprocket, p),
            want,
            1e-12,
        );
    }
    // Every tooth count: odd and even, up to the most the gap table holds
    // (60, and 61 whose table is 64 long) and beyond it (62, 100), where
    // each pin's gap direction is computed instead.
    let mut rng = Lcg::new(31);
    for teeth in [3, 7, 10, 15, 60, 61, 62, 100] {
        let profile = ToothProfile::scaled(teeth, 0.154);
        let (beta, radius) = (profile.pitch_angle(), profile.arc_centre_radius);
        for _ in 0..500 {
            let s = at_rest(
                v(rng.uniform(-2.0, 2.0), rng.uniform(-2.0, 2.0)),
                rng.uniform(-20.0, 20.0),
            );
            let p = s.position + dir(rng.uniform(-PI, PI)) * rng.uniform(0.05, 2.0 * radius);
            let got = profile.nearest_gap(&s, p);
            let best = min_of(
                (0..teeth)
                    .map(|k| s.position + dir(s.angle + (k as f64 + 0.5) * beta) * radius)
                    .map(|g| (g - p).norm()),
            );
            close(
                &format!("nearest of {teeth}"),
                (got - p).norm(),
                best,
                1e-12,
            );
            close(
                "on the arc-centre circle",
                (got - s.position).norm(),
                radius,
                1e-12,
            );
        }
    }
}

// ---------------------------------------------------------------------
// Cached trigonometry.

/// `with_sin_cos` given `θ.sin_cos()` is `new`, field for field and in
/// every derived quantity, bit for bit; given another angle's trig, it
/// uses that (the cache is what is used); `arm` is `A(θ) ū`, and
/// `velocity_at` is the derivative of the moving point.
#[test]
fn body_state_with_sin_cos_is_new() {
    let mut rng = Lcg::new(41);
    for _ in 0..200 {
        let position = v(rng.uniform(-5.0, 5.0), rng.uniform(-5.0, 5.0));
        let angle = rng.uniform(-10.0, 10.0);
        let velocity = v(rng.uniform(-3.0, 3.0), rng.uniform(-3.0, 3.0));
        let omega = rng.uniform(-3.0, 3.0);
        let a = BodyState::new(position, angle, velocity, omega);
        let b = BodyState::with_sin_cos(position, angle, angle.sin_cos(), velocity, omega);
        assert_eq!(a, b);
        assert_eq!(a.sin_cos(), angle.sin_cos());
        let u = v(rng.uniform(-0.1, 0.1), rng.uniform(-0.1, 0.1));
        assert_eq!(a.arm(u), b.arm(u));
        assert_eq!(a.point(u), b.point(u));
        assert_eq!(a.velocity_at(a.arm(u)), b.velocity_at(b.arm(u)));
        assert_eq!(a.arm(u), trackgen::planar::rotate(angle, u));
        assert_eq!(a.point(u), position + trackgen::planar::rotate(angle, u));
        // ω × arm by hand.
        let arm = a.arm(u);
        assert_eq!(
            a.velocity_at(arm),
            velocity + v(-omega * arm.y, omega * arm.x)
        );
        // The derivative of R + v t + A(θ + ω t) ū at t = 0.
        let h = 1e-6;
        let moving =
            |t: f64| position + velocity * t + trackgen::planar::rotate(angle + omega * t, u);
        close_vec(
            "velocity_at",
            a.velocity_at(arm),
            (moving(h) - moving(-h)) / (2.0 * h),
            1e-8,
        );
        // Another angle's trig is used as given.
        let other = angle + 0.7;
        let c = BodyState::with_sin_cos(position, angle, other.sin_cos(), velocity, omega);
        assert_eq!(c.arm(u), trackgen::planar::rotate(other, u));
        assert_eq!(c.angle, angle);
    }
}

fn states(
    model: &M113Track,
    q: &SVector<f64, TRACK_DOF>,
    qd: &SVector<f64, TRACK_DOF>,
    trig: Option<&[(f64, f64)]>,
) -> (Vec<Vector2<f64>>, Vec<Vector2<f64>>) {
    let n = <M113Track as RecursiveModel<TRACK_DOF>>::BODIES;
    let (mut r, mut w) = (vec![Vector2::zeros(); n], vec![Vector2::zeros(); n]);
    match trig {
        Some(t) => model.body_states_with_trig(t, q, qd, &mut r, &mut w),
        None => model.body_states(q, qd, &mut r, &mut w),
    }
    (r, w)
}

fn flat(vs: &[Vector2<f64>]) -> Vec<f64> {
    vs.iter().flat_map(|p| [p.x, p.y]).collect()
}

/// The generated M113 track (64 links): `body_states_with_trig` given each
/// angle's `trackgen::trig::sin_cos` is bit for bit `body_states`, and `body_positions` /
/// `body_velocities`; given the trig of other angles, it is `body_states`
/// at those angles (positions depend on the angles only through the trig);
/// and it agrees with the reference route (`H q̇` of the dense transform).
#[test]
fn m113_body_states_with_trig_is_body_states() {
    let model = M113Track;
    let n = <M113Track as RecursiveModel<TRACK_DOF>>::BODIES;
    assert_eq!(n, 64);
    let reference = ReferenceModel::new(model.description());
    let mut rng = Lcg::new(51);
    for case in 0..20 {
        let (q, qd) = rng.state::<TRACK_DOF>();
        // The generated code's own trig (`trackgen::trig::sin_cos`, within an
        // ulp of the library's), so equality is bit for bit.
        let trig: Vec<(f64, f64)> = (0..n).map(|b| trackgen::trig::sin_cos(q[2 + b])).collect();
        let (r1, v1) = states(&model, &q, &qd, Some(&trig));
        let (r2, v2) = states(&model, &q, &qd, None);
        assert_eq!(r1, r2, "case {case}: positions");
        assert_eq!(v1, v2, "case {case}: velocities");
        let (mut r3, mut v3) = (vec![Vector2::zeros(); n], vec![Vector2::zeros(); n]);
        model.body_positions(&q, &mut r3);
        model.body_velocities(&q, &qd, &mut v3);
        assert_eq!(r1, r3, "case {case}: body_positions");
        assert_eq!(v1, v3, "case {case}: body_velocities");
        // The reference route.
        let qv = DVector::from_column_slice(q.as_slice());
        let qdv = DVector::from_column_slice(qd.as_slice());
        assert_close(
            "positions",
            &flat(&r1),
            &flat(&reference.positions(&qv)),
            1e-13,
            1.0,
        );
        let hq = reference.velocity_transform(&qv) * &qdv;
        assert_close(
            "velocities",
            &flat(&v1),
            &hq.as_slice()[..2 * n],
            1e-13,
            1.0,
        );
        // The trig of other angles: the states at those angles.
        let mut shifted = q;
        for b in 0..n {
            shifted[2 + b] += rng.uniform(-0.5, 0.5);
        }
        let other: Vec<(f64, f64)> = (0..n)
            .map(|b| trackgen::trig::sin_cos(shifted[2 + b]))
            .collect();
        let (r4, v4) = states(&model, &q, &qd, Some(&other));
        let (r5, v5) = states(&model, &shifted, &qd, None);
        assert_eq!(r4, r5, "case {case}: positions from given trig");
        assert_eq!(v4, v5, "case {case}: velocities from given trig");
        assert!(max_abs(flat(&r4).iter().zip(flat(&r1)).map(|(a, b)| a - b)) > 1e-3);
    }
}
