//! Soft ground under one shoe (`trackgen::contact::soft_ground`): its
//! forces against the soil laws, its energy books against the power the
//! forces put into the shoe, and its rut.
//!
//! Tolerances, and why:
//! - Forces against the laws evaluated here: 1e-12 relative (the same
//!   arithmetic in another order).
//! - Energy books `D = −P − dV/dt` along a motion, with `dV/dt` by a
//!   five-point difference of the reported stored energy over ±2 µs: the
//!   difference's truncation error is ~h⁴ V⁽⁵⁾, below 1e-9 of the power
//!   here; allowed 1e-6 of the power scale.
//! - Sinkage under a load found by bisection to 1e-12 m.

use crate::support;

use trackgen::contact::{BodyState, ContactForce, ShoeGeometry, soft_ground::SoftGround};
use trackgen::multibody::BodyLoad;
use trackgen::nalgebra::Vector2;
use trackgen::terrain::{Terrain, soil::Soil, soil::SoilError, soil::SoilPreset};
use trackgen::vehicle::Vehicle;
use trackgen::vehicles::m113::M113;

use support::Lcg;
use support::contact::soil_forces;

const WIDTH: f64 = 0.38;

/// The soil over its undisturbed surface.
struct Ground {
    soil: SoftGround,
    terrain: Terrain,
}

impl std::ops::Deref for Ground {
    type Target = SoftGround;
    fn deref(&self) -> &SoftGround {
        &self.soil
    }
}

impl std::ops::DerefMut for Ground {
    fn deref_mut(&mut self) -> &mut SoftGround {
        &mut self.soil
    }
}

impl Ground {
    /// [`SoftGround::press`] over this surface.
    fn press(&mut self, links: &[BodyState], shoe: &ShoeGeometry, shear: &mut [f64]) -> bool {
        self.soil.press(&self.terrain, links, shoe, shear)
    }
}

fn ground(soil: Soil, terrain: Terrain) -> Ground {
    Ground {
        soil: SoftGround::new(soil, WIDTH, 0.154, &M113::geometry().shoe).unwrap(),
        terrain,
    }
}

/// One M113 shoe, level, its ground points at sinkage `z` at rest.
fn shoe_at(z: f64, x: f64, velocity: Vector2<f64>, omega: f64, angle: f64) -> BodyState {
    BodyState::new(Vector2::new(x, 0.03 - z), angle, velocity, omega)
}

fn evaluate(ground: &Ground, shoe: &BodyState, j: [f64; 2]) -> (BodyLoad, Vec<ContactForce>) {
    let mut loads = [BodyLoad::ZERO];
    let mut rate = [0.0; 2];
    let mut contacts = Vec::new();
    soil_forces(
        (&ground.soil, &ground.terrain),
        std::slice::from_ref(shoe),
        &M113::geometry().shoe,
        &mut loads,
        (&j, &mut rate),
        |_, c| contacts.push(*c),
    );
    (loads[0], contacts)
}

#[test]
fn a_shoe_at_rest_carries_bekkers_pressure_on_its_patches() {
    let soil = SoilPreset::DrySand.soil();
    let g = ground(soil, Terrain::Flat { height: 0.0 });
    let patch = WIDTH * 0.154 / 2.0;
    assert!((g.patch_area - patch).abs() < 1e-15);
    for z in [0.001, 0.02, 0.07] {
        let (load, contacts) = evaluate(&g, &shoe_at(z, 1.0, Vector2::zeros(), 0.0, 0.0), [0.0; 2]);
        let want = soil.bekker_pressure(z, WIDTH) * patch;
        assert_eq!(contacts.len(), 2);
        for c in &contacts {
            assert!(
                (c.normal - want).abs() < 1e-12 * want,
                "{} vs {want}",
                c.normal
            );
            assert!((c.penetration - z).abs() < 1e-15);
        }
        assert!((load.force.y - 2.0 * want).abs() < 1e-12 * want);
        // At rest and with no shear displacement: no shear, no moment.
        assert!(load.force.x.abs() < 1e-12 * want && load.moment.abs() < 1e-12 * want);
    }
    // Above the ground: nothing.
    let (load, contacts) = evaluate(
        &g,
        &shoe_at(-0.01, 1.0, Vector2::zeros(), 0.0, 0.0),
        [0.0; 2],
    );
    assert!(contacts.is_empty() && load == BodyLoad::ZERO);
}

#[test]
fn shear_follows_janosi_hanamoto_against_the_displacement() {
    let soil = SoilPreset::Clay.soil();
    let g = ground(soil, Terrain::Flat { height: 0.0 });
    let z = 0.02;
    let slip = 0.3;
    let j = 0.01;
    let (load, _) = evaluate(
        &g,
        &shoe_at(z, 0.0, Vector2::new(slip, 0.0), 0.0, 0.0),
        [j; 2],
    );
    let p = soil.bekker_pressure(z, WIDTH);
    // Against the displacement, whatever the slip's instant direction.
    let want = -2.0 * soil.shear_stress(p, j) * g.patch_area;
    assert!(
        (load.force.x - want).abs() < 1e-12 * want.abs(),
        "{} vs {want}",
        load.force.x
    );
    for (j, slip) in [(-0.01, 0.3), (-0.01, -0.3), (0.01, -0.3)] {
        let (load, _) = evaluate(
            &g,
            &shoe_at(z, 0.0, Vector2::new(slip, 0.0), 0.0, 0.0),
            [j; 2],
        );
        let want = -2.0 * soil.shear_stress(p, j) * g.patch_area * j.signum();
        assert!(
            (load.force.x - want).abs() < 1e-12 * want.abs(),
            "j {j}, slip {slip}: {} vs {want}",
            load.force.x
        );
    }
}

/// Along random motions of a shoe over flat and sloping soil, fresh and
/// already pressed: the power the soil's forces put into the shoe, the
/// dissipation and the change of stored energy balance.
#[test]
fn energy_books_balance_along_any_motion() {
    let mut rng = Lcg::new(11);
    for preset in SoilPreset::ALL {
        let soil = preset.soil();
        for terrain in [
            Terrain::Flat { height: 0.0 },
            Terrain::Ramp {
                height: 0.0,
                start: -5.0,
                slope: 0.2,
            },
        ] {
            let mut g = ground(soil, terrain.clone());
            // Press the ground once under x ∈ [0.9, 1.1] to 3 cm.
            for k in 0..40 {
                let x = 0.9 + 0.005 * k as f64;
                g.rut.press(&soil, x, 0.03, WIDTH);
            }
            for _ in 0..20 {
                let x = rng.uniform(0.8, 1.2);
                let z = rng.uniform(0.005, 0.05);
                let h = terrain.height(x);
                let velocity = Vector2::new(rng.uniform(-1.0, 1.0), rng.uniform(-0.3, 0.3));
                let omega = rng.uniform(-1.0, 1.0);
                let angle = rng.uniform(-0.1, 0.1);
                let j = [rng.uniform(0.0, 0.05), rng.uniform(0.0, 0.05)];
                let at = |t: f64| {
                    let mut s = shoe_at(z, x, velocity, omega, angle + omega * t);
                    s.position += velocity * t + Vector2::new(0.0, h);
                    BodyState::new(s.position, angle + omega * t, velocity, omega)
                };
                let stored =
                    |t: f64| -> f64 { evaluate(&g, &at(t), j).1.iter().map(|c| c.potential).sum() };
                let (load, contacts) = evaluate(&g, &at(0.0), j);
                if contacts.is_empty() {
                    continue;
                }
                let shoe = at(0.0);
                let power = load.force.dot(&shoe.velocity) + load.moment * shoe.omega;
                let dissipation: f64 = contacts.iter().map(|c| c.dissipation).sum();
                let dt = 2e-6;
                let rate = (stored(-2.0 * dt) - 8.0 * stored(-dt) + 8.0 * stored(dt)
                    - stored(2.0 * dt))
                    / (12.0 * dt);
                let scale = contacts
                    .iter()
                    .map(|c| c.force.norm() * (shoe.velocity.norm() + shoe.omega.abs()))
                    .sum::<f64>();
                assert!(
                    (dissipation + power + rate).abs() < 1e-6 * scale,
                    "{preset} on {terrain:?}: D {dissipation}, P {power}, dV/dt {rate}"
                );
            }
        }
    }
}

/// A second pass over the same ground sinks less under the same load: the
/// first pass left a rut, and reloading it is elastic up to the first
/// pass's sinkage.
#[test]
fn the_rut_makes_a_second_pass_sink_less() {
    let soil = SoilPreset::SandyLoam.soil();
    let mut g = ground(soil, Terrain::Flat { height: 0.0 });
    let load = 4e3; // N on each patch
    let sinkage = |g: &Ground| {
        let (mut lo, mut hi) = (0.0, 0.5);
        while hi - lo > 1e-12 {
            let mid = 0.5 * (lo + hi);
            let (_, contacts) =
                evaluate(g, &shoe_at(mid, 1.0, Vector2::zeros(), 0.0, 0.0), [0.0; 2]);
            if contacts.iter().map(|c| c.normal).sum::<f64>() < 2.0 * load {
                lo = mid
            } else {
                hi = mid
            }
        }
        lo
    };
    let first = sinkage(&g);
    let want = soil.static_sinkage(2.0 * load, WIDTH, 0.154);
    assert!(
        (first - want).abs() < 1e-9,
        "first pass {first} m, Bekker {want} m"
    );
    let shoe = shoe_at(first, 1.0, Vector2::zeros(), 0.0, 0.0);
    let mut j = [0.02; 2];
    let (_, before) = evaluate(&g, &shoe, j);
    // Pressing where the shoe stands leaves the force there as it was
    // (Bekker's at the new yield point): no restart needed.
    assert!(!g.press(std::slice::from_ref(&shoe), &M113::geometry().shoe, &mut j));
    assert_eq!(j, [0.02; 2], "loaded points keep their shear displacement");
    let (_, after) = evaluate(&g, &shoe, j);
    for (b, a) in before.iter().zip(&after) {
        assert!(
            (a.normal - b.normal).abs() <= 1e-9 * b.normal,
            "{} N before pressing, {} N after",
            b.normal,
            a.normal
        );
    }
    assert!(
        g.rut.profile().count() > 0,
        "the press is imprinted on the rut"
    );
    // Half the load again: the shoe sits in its rut, above the first
    // pass's sinkage.
    let second = {
        let half = &g;
        let (mut lo, mut hi) = (0.0, 0.5);
        while hi - lo > 1e-12 {
            let mid = 0.5 * (lo + hi);
            let (_, contacts) = evaluate(
                half,
                &shoe_at(mid, 1.0, Vector2::zeros(), 0.0, 0.0),
                [0.0; 2],
            );
            if contacts.iter().map(|c| c.normal).sum::<f64>() < load {
                lo = mid
            } else {
                hi = mid
            }
        }
        lo
    };
    assert!(second < first, "second pass {second} m, first {first} m");
    let fresh = soil.static_sinkage(load, WIDTH, 0.154);
    // …but deeper than the half load alone would sink fresh soil: the rut
    // of the first pass is still there.
    assert!(second > fresh, "second pass {second} m, fresh {fresh} m");
    // Lifted off the ground: the shear displacement resets.
    let lifted = shoe_at(-0.05, 1.0, Vector2::zeros(), 0.0, 0.0);
    assert!(!g.press(
        std::slice::from_ref(&lifted),
        &M113::geometry().shoe,
        &mut j
    ));
    assert_eq!(j, [0.0; 2]);
    let profile: Vec<(f64, f64)> = g.rut.profile().collect();
    assert!(!profile.is_empty() && profile.iter().all(|&(_, z)| z > 0.0 && z < first));
}

#[test]
fn bad_soft_ground_is_a_clear_error() {
    let shoe = M113::geometry().shoe;
    let bad = Soil {
        n: -1.0,
        ..SoilPreset::Snow.soil()
    };
    assert!(matches!(
        SoftGround::new(bad, WIDTH, 0.154, &shoe),
        Err(SoilError::OutOfRange { name: "n", .. })
    ));
    let err = SoftGround::new(SoilPreset::Snow.soil(), 0.0, 0.154, &shoe).unwrap_err();
    assert!(err.to_string().contains("track width"), "{err}");
}
