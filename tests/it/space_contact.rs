//! A shoe's point against the ground in space (`contact::space`): on
//! level ground, moving in the `x`-`z` plane, it is the planar ground
//! contact's law (to rounding); on a tilted field its normal force acts
//! along the field's gradient and its friction in the tangent plane, at
//! most `μ` times the pressing force; the power the point puts in is the
//! stored energies' rate and the dissipation (the books close), under
//! stiction and under regularised friction; above the ground, no contact.

use trackgen::contact::space::SpaceContact;
use trackgen::contact::{Contact, GroundFriction, GroundLaws};
use trackgen::laws::{Friction, NormalLaw, Stiction};
use trackgen::nalgebra::{Vector2, Vector3};
use trackgen::terrain::field::HeightField;

fn laws(friction: GroundFriction) -> GroundLaws {
    GroundLaws {
        normal: NormalLaw::HuntCrossley {
            stiffness: 2e6,
            exponent: 1.0,
            chi: 2.0,
        },
        friction,
    }
}

fn stiction() -> Stiction {
    Stiction {
        mu: 0.8,
        stiffness: 2e5,
        damping: 2e3,
    }
}

/// Points a few mm in the ground with velocities every way, deflections.
fn cases() -> Vec<(Vector3<f64>, Vector3<f64>, Vector2<f64>)> {
    (0..60)
        .map(|k| {
            let t = k as f64;
            let point = Vector3::new(
                3.0 * (0.7 * t).sin(),
                1.5 * (1.1 * t).cos(),
                -0.004 - 0.003 * (0.3 * t).sin(),
            );
            let velocity = Vector3::new(
                0.6 * (0.5 * t).cos(),
                0.4 * (0.9 * t).sin(),
                0.2 * (1.7 * t).cos(),
            );
            let z = 2e-3 * Vector2::new((1.3 * t).sin(), (0.4 * t).cos());
            (point, velocity, z)
        })
        .collect()
}

#[test]
fn on_level_ground_in_the_plane_it_is_the_planar_law() {
    let laws = laws(GroundFriction::Stiction(stiction()));
    for (point, velocity, z) in cases() {
        let (point, velocity) = (
            Vector3::new(point.x, 0.0, point.z),
            Vector3::new(velocity.x, 0.0, velocity.z),
        );
        let space = SpaceContact::at(&HeightField::level(), point, velocity).unwrap();
        let planar = Contact {
            link: 0,
            other: None,
            feature: 0,
            point: Vector2::new(point.x, point.z),
            arm: Vector2::zeros(),
            depth: space.depth,
            gradient: Vector2::new(0.0, 1.0),
            gradient_norm: 1.0,
            velocity: Vector2::new(velocity.x, velocity.z),
        };
        let (flat, rate) = laws.respond(&planar, z.x);
        let r = laws.respond_in_space(&space, Vector2::new(z.x, 0.0));
        let scale = flat.force.norm();
        assert!((r.force.x - flat.force.x).abs() <= 1e-15 * scale);
        assert!((r.force.z - flat.force.y).abs() <= 1e-15 * scale);
        assert_eq!(r.force.y, 0.0);
        assert_eq!(r.rate, Vector2::new(rate, 0.0));
        assert!(
            (r.dissipation - flat.dissipation).abs() <= 1e-15 * flat.dissipation.abs().max(1.0)
        );
    }
}

#[test]
fn on_a_tilted_field_the_forces_are_normal_and_tangent_and_the_books_close() {
    // A 30 % grade at 35° from the path (a side slope's share of it):
    // the force less its normal part lies in the tangent plane, is at most
    // μ times the pressing force, and −F·v = (the normal law's elastic
    // force) δ̇ + k z·ż + the dissipation, to 1e-12 of the largest term.
    let field = HeightField::plane(0.3, 35f64.to_radians());
    for friction in [
        GroundFriction::Stiction(stiction()),
        GroundFriction::Regularised(Friction {
            mu: 0.8,
            slip: 0.05,
        }),
    ] {
        let laws = laws(friction);
        for (point, velocity, z) in cases() {
            let lifted = Vector3::new(point.x, point.y, point.z + field.height(point.x, point.y));
            let contact = SpaceContact::at(&field, lifted, velocity).unwrap();
            let r = laws.respond_in_space(&contact, z);
            let g = contact.gradient;
            let pressing = laws.normal.respond(contact.depth, contact.rate()).force;
            let tangential = r.force - g * pressing;
            assert!(tangential.dot(&g).abs() <= 1e-12 * r.force.norm());
            assert!(tangential.norm() <= 0.8 * r.normal * (1.0 + 1e-12));
            let elastic = laws.normal.elastic_force(contact.depth) * contact.rate();
            let stored = match friction {
                GroundFriction::Stiction(s) => s.stiffness * z.dot(&r.rate),
                GroundFriction::Regularised(_) => 0.0,
            };
            let paid = -r.force.dot(&velocity);
            let kept = elastic + stored + r.dissipation;
            let scale = paid.abs().max(r.dissipation).max(elastic.abs());
            assert!(
                (paid - kept).abs() <= 1e-12 * scale,
                "{paid} against {kept}"
            );
        }
    }
}

#[test]
fn above_the_ground_there_is_no_contact() {
    let field = HeightField::plane(0.3, 0.0);
    assert!(SpaceContact::at(&field, Vector3::new(1.0, 0.0, 0.31), Vector3::zeros()).is_none());
    assert!(SpaceContact::at(&field, Vector3::new(1.0, 0.0, 0.29), Vector3::zeros()).is_some());
}
