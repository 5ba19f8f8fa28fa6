//! A wheel's rim on a shoe's face and a pin on the sprocket's teeth in
//! space (`contact::axial`). The rim: with the
//! wheel's and the link's planes one, it is the planar rim contact
//! (`contact::wheel` and `ContactLaws::respond`), whatever the plane's
//! place and heading; the rim is a cylinder (sliding along the axle within
//! the guide's play changes nothing); the penetration's rate is the
//! closing velocity along the normal, checked against central differences
//! of the detected depth along rigid motions with the wheel's axle tilted
//! and turning; the power the two bodies give the contact is the rate of
//! its stored energy and its dissipation (the books close), rim and guide
//! together; and the guide (a point of the link) pushes the link back
//! beyond its play only. The teeth: in one plane the planar teeth
//! (`contact::sprocket`) at the M113's sprocket turned against its
//! assembled track; with the sprocket's axle tilted, turning and off the
//! track's plane, the rate against central differences and the books
//! closed.

use trackgen::assembly::assemble;
use trackgen::contact::axial::{GuideLaw, RimContact, SpaceFace, SpaceSprocket, SpaceWheel};
use trackgen::contact::{BodyState, ContactLaws, sprocket, wheel};
use trackgen::laws::{Friction, NormalLaw};
use trackgen::multibody::RecursiveModel;
use trackgen::nalgebra::{Rotation3, Vector2, Vector3};
use trackgen::terrain::Terrain;
use trackgen::vehicle::Vehicle;
use trackgen::vehicles::m113::{M113, M113Chassis, M113Track};

fn laws() -> ContactLaws {
    ContactLaws {
        normal: NormalLaw::HuntCrossley {
            stiffness: 1e7,
            exponent: 1.0,
            chi: 0.5,
        },
        friction: Friction { mu: 0.4, slip: 0.5 },
    }
}

const GUIDE: GuideLaw = GuideLaw {
    play: 0.02,
    stiffness: 1e7,
    damping: 2e3,
    height: 0.05,
};

/// A vertical plane through `origin` heading `yaw`: its forward axis,
/// its normal (left) and up.
struct Plane {
    origin: Vector3<f64>,
    xi: Vector3<f64>,
    eta: Vector3<f64>,
    zeta: Vector3<f64>,
}

impl Plane {
    fn new(origin: Vector3<f64>, yaw: f64) -> Plane {
        let (s, c) = yaw.sin_cos();
        Plane {
            origin,
            xi: Vector3::new(c, s, 0.0),
            eta: Vector3::new(-s, c, 0.0),
            zeta: Vector3::z(),
        }
    }
    fn point(&self, p: Vector2<f64>) -> Vector3<f64> {
        self.origin + self.xi * p.x + self.zeta * p.y
    }
    fn vector(&self, v: Vector2<f64>) -> Vector3<f64> {
        self.xi * v.x + self.zeta * v.y
    }
    /// A counter-clockwise planar rate: about `−η`.
    fn spin(&self, omega: f64) -> Vector3<f64> {
        -self.eta * omega
    }
}

/// A road wheel (radius 0.305 m) pressing 2–4 mm into a link's face,
/// the bodies moving and turning, the face point inside the face or at
/// its ends: the planar states.
fn planar_cases() -> Vec<(BodyState, BodyState)> {
    (0..24)
        .map(|k| {
            let t = k as f64;
            let angle = 0.3 * (0.9 * t).sin();
            let link = BodyState::new(
                Vector2::new(0.1 * t.cos(), 0.02 * t.sin()),
                angle,
                Vector2::new(1.5 * (0.4 * t).cos(), 0.3 * (1.1 * t).sin()),
                2.0 * (0.7 * t).cos(),
            );
            // Along the face, up to past its ends, and 2–4 mm deep.
            let along = 0.09 * (1.3 * t).sin();
            let depth = 0.002 + 0.002 * (0.5 * t).cos().abs();
            let up = link.arm(Vector2::new(0.0, 1.0));
            let forward = link.arm(Vector2::new(1.0, 0.0));
            let centre = link.position + forward * along + up * (0.03 + 0.305 - depth);
            let wheel = BodyState::new(
                centre,
                0.0,
                Vector2::new(1.4 * (0.3 * t).cos(), -0.2 * (0.8 * t).sin()),
                -5.0 * (0.2 * t).cos(),
            );
            (link, wheel)
        })
        .collect()
}

/// A planar link's running face, guide and motion in `plane`.
fn face_of(plane: &Plane, link: &BodyState) -> SpaceFace {
    let shoe = M113::geometry().shoe;
    SpaceFace {
        ends: shoe.inner_face.map(|p| plane.point(link.point(p))),
        inward: plane.vector(link.arm(Vector2::new(0.0, 1.0))),
        guide: plane.point(link.point(Vector2::new(0.045, shoe.inner_offset()))),
        centroid: plane.point(link.position),
        velocity: plane.vector(link.velocity),
        angular_velocity: plane.spin(link.omega),
    }
}

fn embed(
    plane: &Plane,
    link: &BodyState,
    wheel: &BodyState,
    lateral: f64,
) -> (SpaceFace, SpaceWheel) {
    let wheel = SpaceWheel {
        centre: plane.point(wheel.position) + plane.eta * lateral,
        axle: plane.eta,
        radius: 0.305,
        velocity: plane.vector(wheel.velocity),
        angular_velocity: plane.spin(wheel.omega),
    };
    (face_of(plane, link), wheel)
}

#[test]
fn in_one_plane_it_is_the_planar_rim() {
    let shoe = M113::geometry().shoe;
    let plane = Plane::new(Vector3::new(3.0, -7.0, 0.4), 2.3);
    let mut clipped = 0;
    for (link, wheel_state) in planar_cases() {
        let mut found = Vec::new();
        wheel::detect((&wheel_state, 1, 0.305), &[link], &shoe, &mut found);
        let planar = found.first().expect("the planar rim touches");
        let expected = laws().respond(planar);
        // Across the wheel's plane within the guide's play, and on it.
        for lateral in [0.0, 0.015, -0.0199] {
            let (face, wheel) = embed(&plane, &link, &wheel_state, lateral);
            let rim = RimContact::detect(&wheel, &face).expect("the rim touches in space");
            let (force, guide) = (laws().respond_axial(&rim.contact), GUIDE.respond(&rim));
            let scale = expected.force.norm();
            assert!(
                (rim.contact.depth - planar.depth).abs() < 1e-15,
                "{} against {}",
                rim.contact.depth,
                planar.depth
            );
            assert!((rim.contact.point - plane.point(planar.point)).norm() < 1e-14);
            assert!(
                (force.force - plane.vector(expected.force)).norm() < 1e-12 * scale,
                "{:?} against {:?}",
                force.force,
                plane.vector(expected.force)
            );
            assert_eq!(guide.force, 0.0);
            assert!((force.dissipation - expected.dissipation).abs() < 1e-12 * scale);
            assert!((force.potential - expected.potential).abs() < 1e-12 * expected.potential);
        }
        let face_ends = shoe.inner_face.map(|p| link.point(p));
        if (planar.point - face_ends[0]).norm() < 1e-15
            || (planar.point - face_ends[1]).norm() < 1e-15
        {
            clipped += 1;
        }
    }
    assert!(clipped > 0, "some cases touch at a face's end");
}

/// `R(ω t) x`.
fn turned(omega: Vector3<f64>, t: f64, x: Vector3<f64>) -> Vector3<f64> {
    Rotation3::new(omega * t) * x
}

/// The link moved rigidly for `t` s.
fn moved_face(face: &SpaceFace, t: f64) -> SpaceFace {
    let centroid = face.centroid + face.velocity * t;
    SpaceFace {
        ends: face
            .ends
            .map(|e| centroid + turned(face.angular_velocity, t, e - face.centroid)),
        inward: turned(face.angular_velocity, t, face.inward),
        guide: centroid + turned(face.angular_velocity, t, face.guide - face.centroid),
        centroid,
        ..*face
    }
}

/// The bodies moved rigidly for `t` s from `(face, wheel)`.
fn moved(face: &SpaceFace, wheel: &SpaceWheel, t: f64) -> (SpaceFace, SpaceWheel) {
    let wheel = SpaceWheel {
        centre: wheel.centre + wheel.velocity * t,
        axle: turned(wheel.angular_velocity, t, wheel.axle),
        ..*wheel
    };
    (moved_face(face, t), wheel)
}

/// Space cases: the planar ones with the wheel's axle tilted a few
/// degrees out of the link's plane, off the plane across it, and both
/// bodies turning about every axis.
fn space_cases(tilt: bool) -> Vec<(SpaceFace, SpaceWheel)> {
    let plane = Plane::new(Vector3::new(-1.0, 2.0, 0.7), -0.6);
    planar_cases()
        .iter()
        .enumerate()
        .map(|(k, (link, wheel))| {
            let t = k as f64;
            let (mut face, mut wheel) = embed(&plane, link, wheel, 0.03 * (0.6 * t).sin());
            if tilt {
                let tip = Vector3::new(0.04 * t.cos(), 0.0, 0.05 * (0.3 * t).sin());
                wheel.axle = Rotation3::new(tip) * wheel.axle;
            }
            wheel.angular_velocity += Vector3::new(0.4 * t.sin(), -0.3, 0.5 * (0.5 * t).cos());
            face.angular_velocity += Vector3::new(-0.2 * (0.4 * t).cos(), 0.35, 0.25 * t.sin());
            (face, wheel)
        })
        .collect()
}

#[test]
fn the_penetration_rate_is_the_closing_velocity() {
    let h = 1e-6;
    for (face, wheel) in space_cases(true) {
        let rim = RimContact::detect(&wheel, &face).expect("the rim touches");
        let depth = |t: f64| {
            let (f, w) = moved(&face, &wheel, t);
            RimContact::detect(&w, &f)
                .expect("still touching")
                .contact
                .depth
        };
        let numeric = (depth(h) - depth(-h)) / (2.0 * h);
        let offset = |t: f64| {
            let (f, w) = moved(&face, &wheel, t);
            RimContact::detect(&w, &f).expect("still touching").offset
        };
        let e_numeric = (offset(h) - offset(-h)) / (2.0 * h);
        assert!(
            (e_numeric - rim.offset_rate).abs() < 1e-8,
            "ė {} against the central difference {e_numeric}",
            rim.offset_rate
        );
        assert!(
            (numeric - rim.contact.rate()).abs() < 1e-8,
            "δ̇ {} against the central difference {numeric}",
            rim.contact.rate()
        );
    }
}

/// The power the bodies give the contact, `−F · v` at the rim and the
/// guide's at the guide, is the rate of its stored energy (central
/// differences along the motion) and its dissipation: with the wheel's
/// axle tilted and turning and not, the guide bearing in some cases.
#[test]
fn the_contacts_books_close() {
    let h = 1e-6;
    let guide = GuideLaw {
        play: 0.01,
        ..GUIDE
    };
    for tilt in [true, false] {
        let mut engaged = 0;
        for (face, wheel) in space_cases(tilt) {
            let rim = RimContact::detect(&wheel, &face).expect("the rim touches");
            let (force, bearing) = (laws().respond_axial(&rim.contact), guide.respond(&rim));
            engaged += usize::from(bearing.force != 0.0);
            let stored = |t: f64| {
                let (f, w) = moved(&face, &wheel, t);
                let rim = RimContact::detect(&w, &f).expect("still touching");
                laws().respond_axial(&rim.contact).potential + guide.respond(&rim).potential
            };
            let rate = (stored(h) - stored(-h)) / (2.0 * h);
            let given = -force.force.dot(&rim.contact.velocity) - bearing.force * rim.offset_rate;
            assert!(
                (given - rate - force.dissipation - bearing.dissipation).abs()
                    < 1e-6 * given.abs().max(1.0),
                "{given} W given, {rate} W stored, {} W dissipated",
                force.dissipation + bearing.dissipation
            );
        }
        assert!(engaged > 5, "the guide bears in {engaged} cases");
    }
}

/// Beyond its play the guide pushes the link back toward the wheel's
/// plane with `k (|e| − play)` (at rest), and not at all within it.
#[test]
fn the_guide_bears_beyond_its_play_only() {
    let plane = Plane::new(Vector3::zeros(), 0.0);
    let (link, wheel) = planar_cases()[3];
    let at_rest = |b: BodyState| BodyState::at_rest(b.position, b.angle);
    for (lateral, expected) in [
        (0.019, 0.0),
        (-0.019, 0.0),
        (0.025, 1e7 * 0.005),
        (-0.031, -1e7 * 0.011),
    ] {
        let (face, wheel) = embed(&plane, &at_rest(link), &at_rest(wheel), lateral);
        let rim = RimContact::detect(&wheel, &face).expect("touching");
        let (force, guide) = (laws().respond_axial(&rim.contact), GUIDE.respond(&rim));
        // The wheel sits at −e from the guide: the link is pushed toward it.
        assert!(
            (guide.force - expected).abs() < 1e-6,
            "{} against {expected}",
            guide.force
        );
        assert!(
            force.force.dot(&plane.eta).abs() < 1e-9,
            "the rim pushes in its plane"
        );
    }
    assert!(GUIDE.check().is_ok());
    assert!(
        GuideLaw {
            stiffness: 0.0,
            ..GUIDE
        }
        .check()
        .is_err()
    );
    assert!(
        GuideLaw {
            play: -1e-3,
            ..GUIDE
        }
        .check()
        .is_err()
    );
    assert!(
        GuideLaw {
            damping: f64::NAN,
            ..GUIDE
        }
        .check()
        .is_err()
    );
    assert!(
        GuideLaw {
            height: 0.0,
            ..GUIDE
        }
        .check()
        .is_err()
    );
}

/// Short of the rim, within the horn's height, the guide alone bears:
/// its books close there as at the rim (its power — the push along the
/// axle at the guide and the radial push at the face's nearest point —
/// is the rate of its stored energy less its dissipation, to 1e-6), it
/// bears in proportion to the horn's overlap, and its stored energy goes
/// to nothing as the face leaves the horn's reach (continuous: no energy
/// lost when a link leaves a wheel with its guide pressed).
#[test]
fn the_guide_bears_short_of_the_rim_by_the_horns_overlap() {
    let h = 1e-6;
    let guide = GuideLaw {
        play: 0.005,
        ..GUIDE
    };
    let mut engaged = 0;
    for (face, wheel) in space_cases(true) {
        let rim = RimContact::detect(&wheel, &face).expect("the rim touches");
        // The face moved out along the rim's normal to `gap` short of it.
        let short = |gap: f64| {
            let by = rim.contact.normal * (rim.contact.depth + gap);
            SpaceFace {
                ends: face.ends.map(|e| e + by),
                guide: face.guide + by,
                centroid: face.centroid + by,
                ..face
            }
        };
        let face = short(0.3 * guide.height);
        let near = RimContact::near(&wheel, &face, guide.height).expect("within the horn");
        assert!(
            (near.contact.depth + 0.3 * guide.height).abs() < 1e-12,
            "{}",
            near.contact.depth
        );
        assert!(RimContact::detect(&wheel, &face).is_none());
        let bearing = guide.respond(&near);
        if bearing.force == 0.0 {
            continue;
        }
        engaged += 1;
        let full = guide.respond(&RimContact {
            contact: trackgen::contact::axial::AxialContact {
                depth: 0.0,
                ..near.contact
            },
            ..near
        });
        assert!(
            (bearing.potential - 0.7 * full.potential).abs() < 1e-9 * full.potential,
            "the overlap 0.7 scales the stored energy"
        );
        let stored = |t: f64| {
            let (f, w) = moved(&face, &wheel, t);
            guide
                .respond(&RimContact::near(&w, &f, guide.height).expect("still within"))
                .potential
        };
        let rate = (stored(h) - stored(-h)) / (2.0 * h);
        let given = -bearing.radial * near.contact.normal.dot(&near.contact.velocity)
            - bearing.force * near.offset_rate;
        assert!(
            (given - rate - bearing.dissipation).abs() < 1e-6 * given.abs().max(1.0),
            "{given} W given, {rate} W stored, {} W dissipated",
            bearing.dissipation
        );
        let leaving = RimContact::near(&wheel, &short(guide.height * (1.0 - 1e-9)), guide.height)
            .expect("at the horn's tip");
        assert!(guide.respond(&leaving).potential < 1e-8 * full.potential);
        assert!(
            RimContact::near(&wheel, &short(guide.height * (1.0 + 1e-9)), guide.height).is_none()
        );
    }
    assert!(engaged > 3, "the guide bears in {engaged} cases");
}

/// The M113's sprocket turned a little against its assembled track, the
/// bodies moving: the planar states of the sprocket and the links.
fn tooth_cases() -> Vec<(BodyState, Vec<BodyState>)> {
    let geometry = M113::geometry();
    let start = assemble(
        &M113Track,
        &M113Chassis,
        &geometry.shoe,
        &geometry.sprocket,
        &Terrain::Flat { height: 0.0 },
        0.0,
        1e-3,
    )
    .expect("the M113 assembles");
    let mut rt = vec![Vector2::zeros(); M113Track::BODIES];
    M113Track.body_positions(&start.track, &mut rt);
    let mut rc = vec![Vector2::zeros(); M113Chassis::BODIES];
    M113Chassis.body_positions(&start.chassis, &mut rc);
    let s = M113Chassis::SPROCKET;
    [0.12, -0.1, 0.15, -0.13]
        .iter()
        .enumerate()
        .map(|(k, turn)| {
            let t = k as f64;
            let sprocket = BodyState::new(
                rc[s],
                start.chassis[2 + s] + turn,
                Vector2::new(1.2 * t.cos(), -0.3),
                8.0 * (0.6 * t).sin(),
            );
            let links = (0..M113Track::BODIES)
                .map(|i| {
                    let u = i as f64 + t;
                    BodyState::new(
                        rt[i],
                        start.track[2 + i],
                        Vector2::new(1.5 * (0.3 * u).cos(), 0.4 * (0.7 * u).sin()),
                        3.0 * (0.5 * u).cos(),
                    )
                })
                .collect();
            (sprocket, links)
        })
        .collect()
}

fn space_sprocket(plane: &Plane, sprocket: &BodyState) -> SpaceSprocket {
    SpaceSprocket {
        centre: plane.point(sprocket.position),
        axes: [plane.xi, plane.zeta],
        angle: sprocket.angle,
        velocity: plane.vector(sprocket.velocity),
        angular_velocity: plane.spin(sprocket.omega),
    }
}

#[test]
fn in_one_plane_the_teeth_are_the_planar_teeth() {
    let geometry = M113::geometry();
    let plane = Plane::new(Vector3::new(-4.0, 1.5, 0.2), -1.1);
    let mut found = 0;
    for (sprocket, links) in tooth_cases() {
        let mut contacts = Vec::new();
        sprocket::detect(
            (&sprocket, 1),
            &geometry.sprocket,
            &links,
            &geometry.shoe,
            &mut contacts,
        );
        let space = space_sprocket(&plane, &sprocket);
        for planar in &contacts {
            let link = &links[planar.link];
            let pin = plane.point(link.point(geometry.shoe.pins[planar.feature]));
            let contact = space
                .pin_contact(
                    &geometry.sprocket,
                    &face_of(&plane, link),
                    pin,
                    geometry.shoe.pin_radius,
                )
                .expect("the pin is in a tooth in space");
            let expected = laws().respond(planar);
            let force = laws().respond_axial(&contact);
            assert!((contact.depth - planar.depth).abs() < 1e-15);
            assert!((contact.point - plane.point(planar.point)).norm() < 1e-14);
            assert!(
                (force.force - plane.vector(expected.force)).norm() < 1e-12 * expected.force.norm(),
                "{:?} against {:?}",
                force.force,
                plane.vector(expected.force)
            );
            assert!(
                (force.dissipation - expected.dissipation).abs() < 1e-9 * expected.force.norm()
            );
            found += 1;
        }
    }
    assert!(found >= 8, "{found} pins in teeth");
}

/// The pins' penetration rate against central differences, and the books
/// of the teeth's force, with the sprocket's axle tilted, turning about
/// every axis, and off the track's plane along it.
#[test]
fn the_teeths_rate_and_books() {
    let geometry = M113::geometry();
    let (profile, radius) = (geometry.sprocket, geometry.shoe.pin_radius);
    let plane = Plane::new(Vector3::new(2.0, 0.5, -0.3), 0.7);
    let h = 1e-6;
    let mut checked = 0;
    for (k, (sprocket, links)) in tooth_cases().into_iter().enumerate() {
        let t = k as f64;
        let mut contacts = Vec::new();
        sprocket::detect(
            (&sprocket, 1),
            &profile,
            &links,
            &geometry.shoe,
            &mut contacts,
        );
        let mut space = space_sprocket(&plane, &sprocket);
        let tip = Rotation3::new(Vector3::new(0.03 * t.cos(), 0.02, 0.04 * t.sin()));
        space.axes = space.axes.map(|a| tip * a);
        space.centre += space.axle() * 0.02 * (t - 1.5);
        space.angular_velocity += Vector3::new(0.3 * t.sin(), -0.4, 0.2);
        for planar in &contacts {
            let local = geometry.shoe.pins[planar.feature];
            let mut face = face_of(&plane, &links[planar.link]);
            face.angular_velocity += Vector3::new(0.25, 0.1 * t, -0.3);
            let pin = plane.point(links[planar.link].point(local));
            let at = |time: f64| {
                let moved = moved_face(&face, time);
                let sprocket = SpaceSprocket {
                    centre: space.centre + space.velocity * time,
                    axes: space.axes.map(|a| turned(space.angular_velocity, time, a)),
                    ..space
                };
                let pin = moved.centroid + turned(face.angular_velocity, time, pin - face.centroid);
                sprocket.pin_contact(&profile, &moved, pin, radius)
            };
            let Some(contact) = at(0.0) else { continue };
            let (Some(ahead), Some(behind)) = (at(h), at(-h)) else {
                continue;
            };
            let numeric = (ahead.depth - behind.depth) / (2.0 * h);
            assert!(
                (numeric - contact.rate()).abs() < 1e-8,
                "δ̇ {} against {numeric}",
                contact.rate()
            );
            let force = laws().respond_axial(&contact);
            let stored = (laws().respond_axial(&ahead).potential
                - laws().respond_axial(&behind).potential)
                / (2.0 * h);
            let given = -force.force.dot(&contact.velocity);
            assert!(
                (given - stored - force.dissipation).abs() < 1e-6 * given.abs().max(1.0),
                "{given} W given, {stored} W stored, {} W dissipated",
                force.dissipation
            );
            checked += 1;
        }
    }
    assert!(checked >= 8, "{checked} pins checked");
}
