//! Soft soil under a point in space (`trackgen::contact::soft_space`):
//! its force against the soil's laws in closed form (Bekker's pressure on
//! the point's half patch, Janosi–Hanamoto's shear against the shear
//! displacement whichever way it points), the state's rate (the slip in
//! the ground's plane), and what a point leaves behind (its memory in
//! the rut where it lifts, its displacement counted again from there).
//!
//! Tolerances: 1e-12 relative, the same laws evaluated in another order.

use trackgen::contact::ShoeGeometry;
use trackgen::contact::soft_space::SoftSpace;
use trackgen::contact::space::SpaceContact;
use trackgen::nalgebra::{Vector2, Vector3};
use trackgen::terrain::soil::{Soil, SoilPreset};

const WIDTH: f64 = 0.38;
const PITCH: f64 = 0.154;
const POINTS: usize = 4;
/// Each point's patch, m²: half the planar point's.
const AREA: f64 = 0.5 * WIDTH * PITCH / POINTS as f64;

/// A shoe `WIDTH` wide with `POINTS` ground points evenly along it.
fn shoe() -> ShoeGeometry {
    shoe_of(Some(WIDTH))
}

/// [`shoe`] of declared width `width`.
fn shoe_of(width: Option<f64>) -> ShoeGeometry {
    ShoeGeometry {
        ground_points: (0..POINTS)
            .map(|k| {
                Vector2::new(
                    (k as f64 + 0.5) / POINTS as f64 * PITCH - 0.5 * PITCH,
                    -0.03,
                )
            })
            .collect(),
        inner_face: [Vector2::new(-0.07, 0.03), Vector2::new(0.07, 0.03)],
        pins: Vec::new(),
        pin_radius: 0.0,
        width,
    }
}

fn sand() -> Soil {
    SoilPreset::DrySand.soil()
}

/// Dry sand under tracks of 10 links a side.
fn ground() -> SoftSpace {
    SoftSpace::new(sand(), &shoe(), [PITCH; 2], [10, 10]).expect("a soil")
}

/// A point at `(x, y)` sunk `depth` m into level ground at `velocity`.
fn contact(at: Vector2<f64>, depth: f64, velocity: Vector3<f64>) -> SpaceContact {
    SpaceContact {
        point: Vector3::new(at.x, at.y, -depth),
        depth,
        gradient: Vector3::z(),
        velocity,
    }
}

fn close(a: f64, b: f64) -> bool {
    (a - b).abs() <= 1e-12 * a.abs().max(b.abs())
}

/// At rest in fresh sand with no shear: Bekker's pressure on the half
/// patch, straight up, storing `A p²/(2 K_e)`, and nothing moving.
#[test]
fn at_rest_the_point_bears_bekkers_pressure_on_its_half_patch() {
    let soil = sand();
    let z: f64 = 0.03;
    let (force, rate) = ground().respond(
        0,
        0,
        &contact(Vector2::zeros(), z, Vector3::zeros()),
        Vector2::zeros(),
    );
    let force = force.expect("the soil bears");
    let p = (soil.k_c / WIDTH + soil.k_phi) * z.powf(soil.n);
    assert!(
        close(force.force.z, p * AREA),
        "{force:?} against {}",
        p * AREA
    );
    assert_eq!((force.force.x, force.force.y), (0.0, 0.0));
    assert!(close(force.normal, p * AREA));
    assert!(close(
        force.potential,
        AREA * p * p / (2.0 * soil.unloading_stiffness)
    ));
    assert_eq!(rate, Vector2::zeros());
}

/// Sheared by `j` (m) in any direction of the ground's plane, the soil
/// pushes back against it with `(c + p tan φ)(1 − e^{−|j|/K}) A`: the
/// same magnitude whichever way (friction in soil is isotropic), along
/// `−j`. The state's rate is the slip in the plane, whatever the shear.
#[test]
fn the_shear_opposes_the_displacement_whichever_way_it_points() {
    let soil = sand();
    let z: f64 = 0.03;
    let p = (soil.k_c / WIDTH + soil.k_phi) * z.powf(soil.n);
    let tan_phi = soil.friction_angle_deg.to_radians().tan();
    let ground = ground();
    for (j, angle) in [(0.002, 0.0), (0.01, 1.0), (0.05, 2.5), (0.3, -2.0)] {
        let shear = Vector2::new(f64::cos(angle), f64::sin(angle)) * j;
        let slip = Vector3::new(0.3, -0.2, 0.0);
        let (force, rate) = ground.respond(1, 7, &contact(Vector2::new(4.0, -1.0), z, slip), shear);
        let force = force.expect("the soil bears");
        let expected = (soil.cohesion + p * tan_phi) * -(-j / soil.shear_modulus).exp_m1() * AREA;
        let along = force.force.xy();
        assert!(
            close(along.norm(), expected),
            "{j} m at {angle}: {along:?}, {expected}"
        );
        assert!(
            (along.normalize() + shear.normalize()).norm() <= 1e-12,
            "against the displacement: {along:?}, {shear:?}"
        );
        assert_eq!(rate, slip.xy());
        // Its work on the slipping point is dissipated.
        assert!(
            close(force.dissipation, -along.dot(&slip.xy())),
            "{force:?}"
        );
    }
}

/// A point pressed 4 cm into fresh sand and then lifted out of it leaves
/// its memory in the rut where it lifts: a point sunk 2 cm there later
/// bears the soil's elastic reloading from the plastic sinkage left
/// (`K_e (z − z_p)`, nothing where `z < z_p`), not fresh soil's Bekker
/// pressure. Its shear displacement counts again from the state it had
/// when it rose: the same state gives no shear.
#[test]
fn a_lifted_point_leaves_its_memory_in_the_rut_and_starts_its_shear_again() {
    let soil = sand();
    let mut ground = ground();
    let at = Vector3::new(2.0, 1.0, 0.0);
    let forward = Vector2::x();
    let state = Vector2::new(0.04, -0.01);
    let slot = (0, 3);
    let half = (at.xy(), forward);
    assert!(!ground.press_point(slot, (at, 0.04), half, state));
    assert!(!ground.press_point(slot, (at, -0.01), half, state));
    let p = (soil.k_c / WIDTH + soil.k_phi) * 0.04_f64.powf(soil.n);
    let plastic = 0.04 - p / soil.unloading_stiffness;
    let left = ground.rut.memory(at.xy());
    assert!(close(left.plastic, plastic), "{left:?}");
    assert!(close(left.yield_pressure, p), "{left:?}");
    // Deeper than the plastic sinkage: elastic reloading, no shear.
    let z = plastic + 1e-4;
    let (force, _) = ground.respond(0, 3, &contact(at.xy(), z, Vector3::zeros()), state);
    let force = force.expect("the rut bears");
    assert!(
        close(force.force.z, soil.unloading_stiffness * 1e-4 * AREA),
        "{force:?}"
    );
    assert_eq!(force.force.xy(), Vector2::zeros());
    // Beside the footprint (a shoe's width away) the soil is fresh.
    let beside = Vector2::new(2.0, 1.0 + WIDTH);
    assert_eq!(ground.rut.memory(beside), Default::default());
}

/// A shoe with no width (declared 0, or none), a pitch that is not a
/// number, or a soil that bears nothing, is refused.
#[test]
fn no_width_and_no_soil_are_refused() {
    assert!(SoftSpace::new(sand(), &shoe_of(None), [PITCH; 2], [10, 10]).is_err());
    assert!(SoftSpace::new(sand(), &shoe_of(Some(0.0)), [PITCH; 2], [10, 10]).is_err());
    assert!(SoftSpace::new(sand(), &shoe(), [PITCH, f64::NAN], [10, 10]).is_err());
    let bearing_nothing = Soil {
        k_c: 0.0,
        k_phi: 0.0,
        ..sand()
    };
    let error = SoftSpace::new(bearing_nothing, &shoe(), [PITCH; 2], [10, 10]).unwrap_err();
    assert!(error.to_string().contains("carries no load"), "{error}");
}
