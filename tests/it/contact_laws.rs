//! Contact laws (`trackgen::contact::{NormalLaw, Friction}`): the normal
//! force of Kelvin-Voigt and Hunt-Crossley (exponents 1 and 1.5) by hand,
//! never pulling and zero out of contact; the potential as the integral of
//! the elastic force (by quadrature and by finite differences); regularised
//! Coulomb friction by hand, odd, bounded by μ F_n, zero at zero slip; and
//! the dissipation the three public contact pairs report: never negative,
//! and equal to what the energy books demand, `D = −P − dV/dt`, with the
//! power `P` the loads put into the bodies and `dV/dt` a central difference
//! of the reported potential along the motion.
//!
//! Tolerances, and why:
//! * Hand values of the laws: `1e-14` relative. A force is two or three
//!   roundings (≤ 4.4e-16) from the hand formula; `powf(1.5)` against
//!   `δ · √δ` adds a few ulps. Clipped forces are exactly 0.
//! * Potential by composite Simpson (1000 panels) after `δ = s²`, which
//!   makes every integrand here a polynomial in `s` (`2k s^(2n+1)`, degree
//!   3 or 4): exact for degree 3, and for `2k s⁴` (fourth derivative
//!   `48k`, integral `2k S⁵/5`) the rule's error `S h⁴ · 48k / 180` is
//!   `(48/180)·(5/2)/N⁴ · V ≈ 6.7e-13 V`; summing 1000 terms adds ~1e-13.
//!   `1e-11` relative.
//! * `d potential / dδ = elastic_force` by a central difference with step
//!   `1e-4 δ`: truncation `n(n−1)/6 · 1e-8 ≤ 1.3e-9` relative, rounding
//!   `ε · 1e4 ≈ 2e-12`; `1e-8` relative.
//! * Friction by hand: `1e-14` relative (a square root, a division and two
//!   products). Oddness is exact (the formula is odd term by term in IEEE
//!   arithmetic). The bound `|F_t| ≤ μ F_n` over slip speeds from 1e-150
//!   to 1e150 m/s allows `2ε` relative: at large slip `v/√(v² + v_s²)`
//!   rounds to 1 and `μ F_n v / √…` may land one ulp above `μ F_n`
//!   (measured: 987.6000000000001 for 987.6).
//! * Energy books of the pairs: `|D − (−P − dV/dt)| ≤ 1e-7 · S`, where `S`
//!   is the power scale `|F| |v_rel| + |dV/dt| + F_el |v_rel|` of the
//!   contact (1e2 to 1e5 W here). `dV/dt` is the five-point central
//!   difference with step 1e-6 s: truncation `dt⁴/30 |V⁽⁵⁾|`, at most ~1e-7
//!   W for the Hertzian law (whose `V⁽⁵⁾` grows as `δ^(−5/2)`; penetrations
//!   are kept ≥ 0.2 mm for that reason), and rounding `ε V / dt ≈ 1e-9` W.
//!   Measured worst: 3.4e-10 S. (The plain three-point difference is not
//!   enough: its `dt²/6 |V'''|` reaches 2e-2 W = 8e-7 S for a Hertzian
//!   contact opening at 2 m/s.) A wrong damping power (the full force, not
//!   its non-elastic part, times the rate) is off by ≥ 1e-2 S.
//! * `D ≥ 0` exactly: each term is a product of like-signed factors.

use crate::support;

use support::contact::{GroundContact, SprocketContact, WheelContact};

use support::{Lcg, max_of, min_of};
use trackgen::contact::{BodyState, ContactForce};
use trackgen::laws::{Friction, NormalLaw};
use trackgen::multibody::BodyLoad;
use trackgen::nalgebra::Vector2;
use trackgen::terrain::Terrain;
use trackgen::vehicle::Vehicle;
use trackgen::vehicles::m113::M113;

fn rel_close(label: &str, got: f64, want: f64, rel: f64) {
    assert!(
        (got - want).abs() <= rel * want.abs(),
        "{label}: got {got}, want {want}"
    );
}

const KV: NormalLaw = NormalLaw::KelvinVoigt {
    stiffness: 1e6,
    damping: 1e3,
};
const HC1: NormalLaw = NormalLaw::HuntCrossley {
    stiffness: 2e6,
    exponent: 1.0,
    chi: 2.0,
};
const HC15: NormalLaw = NormalLaw::HuntCrossley {
    stiffness: 1e9,
    exponent: 1.5,
    chi: 0.5,
};

/// `F = k δ + c δ̇`, clipped at zero.
#[test]
fn kelvin_voigt_by_hand() {
    rel_close("closing", KV.force(0.002, 0.5), 2000.0 + 500.0, 1e-14);
    rel_close("at rest", KV.force(0.002, 0.0), 2000.0, 1e-14);
    rel_close(
        "opening slowly",
        KV.force(0.002, -1.5),
        2000.0 - 1500.0,
        1e-14,
    );
    // Opening fast: c δ̇ would pull; the force is 0, not −1000 N.
    assert_eq!(KV.force(0.002, -3.0), 0.0);
    assert_eq!(KV.force(0.002, -2.0), 0.0);
    rel_close("elastic", KV.elastic_force(0.002), 2000.0, 1e-14);
    rel_close(
        "potential",
        KV.potential(0.002),
        0.5 * 1e6 * 0.002 * 0.002,
        1e-14,
    );
}

/// `F = k δⁿ (1 + χ δ̇)`, clipped at zero, for n = 1 and n = 1.5.
#[test]
fn hunt_crossley_by_hand() {
    // n = 1: k δ = 6000 N.
    rel_close("n=1 closing", HC1.force(0.003, 0.25), 6000.0 * 1.5, 1e-14);
    rel_close("n=1 at rest", HC1.force(0.003, 0.0), 6000.0, 1e-14);
    rel_close("n=1 opening", HC1.force(0.003, -0.25), 6000.0 * 0.5, 1e-14);
    assert_eq!(HC1.force(0.003, -0.6), 0.0, "1 + χ δ̇ = −0.2 would pull");
    assert_eq!(HC1.force(0.003, -0.5), 0.0);
    rel_close(
        "n=1 potential",
        HC1.potential(0.003),
        2e6 * 0.003 * 0.003 / 2.0,
        1e-14,
    );
    // n = 1.5: δ = 4e-4 m, δ^1.5 = 4e-4 · 0.02 = 8e-6, k δ^1.5 = 8000 N.
    let d: f64 = 4e-4;
    let hertz = 1e9 * d * d.sqrt();
    rel_close("n=1.5 hand", hertz, 8000.0, 1e-14);
    rel_close("n=1.5 at rest", HC15.force(d, 0.0), hertz, 1e-14);
    rel_close("n=1.5 closing", HC15.force(d, 0.4), hertz * 1.2, 1e-14);
    rel_close("n=1.5 elastic", HC15.elastic_force(d), hertz, 1e-14);
    rel_close("n=1.5 potential", HC15.potential(d), hertz * d / 2.5, 1e-14);
    assert_eq!(HC15.force(d, -2.0), 0.0, "1 + χ δ̇ = 0");
    assert_eq!(HC15.force(d, -3.0), 0.0);
}

/// No force, elastic force or energy without penetration, whatever the
/// rate; and over a grid of penetrations and rates the force is never
/// negative and equals the unclipped law wherever that is non-negative.
#[test]
fn laws_never_pull_and_vanish_out_of_contact() {
    for law in [KV, HC1, HC15] {
        for d in [0.0, -1e-12, -0.001, -1.0] {
            for rate in [-10.0, -0.1, 0.0, 0.1, 10.0] {
                assert_eq!(law.force(d, rate), 0.0, "{law:?} δ = {d}, δ̇ = {rate}");
            }
            assert_eq!(law.elastic_force(d), 0.0);
            assert_eq!(law.potential(d), 0.0);
        }
        let mut clipped = 0;
        for i in 1..=40 {
            let d = 1e-4 * i as f64;
            for j in -40..=40 {
                let rate = 0.1 * j as f64;
                let f = law.force(d, rate);
                let unclipped = match law {
                    NormalLaw::KelvinVoigt { stiffness, damping } => stiffness * d + damping * rate,
                    NormalLaw::HuntCrossley {
                        stiffness,
                        exponent,
                        chi,
                    } => stiffness * d.powf(exponent) * (1.0 + chi * rate),
                };
                assert!(f >= 0.0, "{law:?} pulls: {f} at δ = {d}, δ̇ = {rate}");
                if unclipped >= 0.0 {
                    assert!(
                        (f - unclipped).abs() <= 1e-14 * unclipped.abs(),
                        "{law:?}: {f} vs {unclipped}"
                    );
                } else {
                    assert_eq!(f, 0.0);
                    clipped += 1;
                }
            }
        }
        assert!(clipped > 0, "{law:?}: the grid reaches the clipped region");
    }
}

/// The potential is the integral of the elastic force from 0: Simpson's
/// rule after `δ = s²` (a polynomial integrand), and its derivative is the
/// elastic force (central differences).
#[test]
fn potential_integrates_the_elastic_force() {
    for law in [KV, HC1, HC15] {
        for depth in [1e-4, 1e-3, 5e-3, 2e-2] {
            // ∫₀^D F(x) dx = ∫₀^√D F(s²) 2s ds.
            let n = 1000;
            let top = f64::sqrt(depth);
            let h = top / n as f64;
            let f = |s: f64| law.elastic_force(s * s) * 2.0 * s;
            let mut sum = f(0.0) + f(top);
            for i in 1..n {
                sum += f(i as f64 * h) * if i % 2 == 1 { 4.0 } else { 2.0 };
            }
            let integral = sum * h / 3.0;
            rel_close(
                &format!("{law:?}: ∫ F to {depth}"),
                law.potential(depth),
                integral,
                1e-11,
            );
            let e = 1e-4 * depth;
            let slope = (law.potential(depth + e) - law.potential(depth - e)) / (2.0 * e);
            rel_close(
                &format!("{law:?}: dV/dδ at {depth}"),
                slope,
                law.elastic_force(depth),
                1e-8,
            );
        }
        // Continuous at the contact's edge.
        assert!(law.potential(1e-9) < 1e-8 && law.potential(1e-9) > 0.0);
    }
}

/// `F_t = −μ F_n v / √(v² + v_s²)` by hand.
#[test]
fn friction_by_hand() {
    let f = Friction { mu: 0.8, slip: 0.1 };
    // v = 2 v_s: 0.8 · 1000 · 2/√5 (the "0.89 μ F_n" of the docs).
    rel_close(
        "v = 0.2",
        f.force(1000.0, 0.2),
        -1600.0 / 5f64.sqrt(),
        1e-14,
    );
    rel_close("v = v_s", f.force(1000.0, 0.1), -800.0 / 2f64.sqrt(), 1e-14);
    // v = −0.3: +800 · 3/√10.
    rel_close(
        "v = -0.3",
        f.force(1000.0, -0.3),
        2400.0 / 10f64.sqrt(),
        1e-14,
    );
    assert!((f.force(1000.0, 0.2) / 800.0 + 0.894).abs() < 1e-3);
    // Linear near zero slip with slope μ F_n / v_s.
    rel_close(
        "slope",
        f.force(500.0, 1e-9) / 1e-9,
        -0.8 * 500.0 / 0.1,
        1e-12,
    );
    assert_eq!(f.force(1000.0, 0.0), 0.0);
    assert_eq!(f.force(0.0, 0.7), 0.0);
    // Plain Coulomb (slip 0): ±μ F_n, and 0 (not NaN) at zero slip.
    let c = Friction { mu: 0.5, slip: 0.0 };
    assert_eq!(c.force(200.0, 0.0), 0.0);
    assert_eq!(c.force(200.0, 1e-3), -100.0);
    assert_eq!(c.force(200.0, -4.0), 100.0);
}

/// Regression: a NaN penetration or rate gave a silent zero force
/// (`NaN.max(0.0)` is 0), hiding a broken state from the integrator's
/// finiteness check. It must come out NaN.
#[test]
fn a_nan_state_gives_a_nan_force() {
    for law in [KV, HC1, HC15] {
        assert!(law.force(1e-3, f64::NAN).is_nan(), "{law:?}: NaN rate");
        assert!(
            law.force(f64::NAN, 0.0).is_nan(),
            "{law:?}: NaN penetration"
        );
    }
}

/// Regression: `√(v² + v_s²)` underflowed and overflowed at extreme slip
/// speeds (|F| 21 % above μ F_n at v = 2.7e-162 m/s with `slip: 0`, and 0
/// at 1e155 m/s); with `hypot` the bound holds over the whole range.
#[test]
fn friction_is_bounded_at_extreme_slip_speeds() {
    for f in [
        Friction { mu: 0.8, slip: 0.1 },
        Friction { mu: 0.6, slip: 0.0 },
    ] {
        let normal = 100.0 / f.mu;
        for v in [2.7e-162, 1e-200, 1e-300, 1e155, 1e200, 1e300] {
            let force = f.force(normal, v);
            assert!(force < 0.0, "{f:?}: opposes {v:e}: {force}");
            assert!(
                force.abs() <= 100.0 * (1.0 + 2.0 * f64::EPSILON),
                "{f:?} at {v:e}: {force}"
            );
        }
    }
}

/// Odd in the slip velocity, opposing it, bounded by μ F_n, for slip
/// speeds over 300 decades and both regularisations.
#[test]
fn friction_is_odd_opposing_and_bounded() {
    for f in [
        Friction { mu: 0.8, slip: 0.1 },
        Friction { mu: 0.4, slip: 0.5 },
        Friction { mu: 0.6, slip: 0.0 },
    ] {
        let normal = 1234.5;
        let bound = f.mu * normal;
        for i in 0..=300 {
            let v = 10f64.powf(-150.0 + i as f64);
            let (plus, minus) = (f.force(normal, v), f.force(normal, -v));
            assert_eq!(plus, -minus, "{f:?}: odd at {v:e}");
            assert!(plus < 0.0, "{f:?}: opposes {v:e}: {plus}");
            assert!(
                plus.abs() <= bound * (1.0 + 2.0 * f64::EPSILON),
                "{f:?}: |{plus}| > μ F_n = {bound} at {v:e}"
            );
        }
        // Approaches μ F_n at large slip.
        assert!(f.force(normal, 1e3 * f.slip.max(1e-3)).abs() > 0.999 * bound);
    }
}

// ---------------------------------------------------------------------
// Dissipation reported by the pairs, against the energy books.

fn friction() -> Friction {
    Friction { mu: 0.4, slip: 0.5 }
}

/// Laws for the pair tests: a Kelvin-Voigt damping strong enough to clip
/// on separation, and Hunt-Crossley of both exponents.
fn pair_laws() -> [NormalLaw; 3] {
    [
        NormalLaw::KelvinVoigt {
            stiffness: 1e7,
            damping: 1e4,
        },
        NormalLaw::HuntCrossley {
            stiffness: 1e7,
            exponent: 1.0,
            chi: 0.8,
        },
        NormalLaw::HuntCrossley {
            stiffness: 5e8,
            exponent: 1.5,
            chi: 0.8,
        },
    ]
}

/// A state advanced by `dt` s at constant velocity and spin.
fn advanced(b: &BodyState, dt: f64) -> BodyState {
    BodyState::new(
        b.position + b.velocity * dt,
        b.angle + b.omega * dt,
        b.velocity,
        b.omega,
    )
}

/// Power a load puts into a body.
fn power(load: &BodyLoad, body: &BodyState) -> f64 {
    load.force.dot(&body.velocity) + load.moment * body.omega
}

/// The checks on one evaluation: `D ≥ 0`, and `D = −P − dV/dt` with `dV/dt`
/// from `potential_at(±dt)`. Returns whether the normal force was clipped.
fn check_books(
    label: &str,
    contact: &ContactForce,
    power_in: f64,
    relative_speed: f64,
    elastic: f64,
    potential_at: impl Fn(f64) -> f64,
) -> bool {
    // The five-point central difference, O(dt⁴).
    let dt = 1e-6;
    let rate = (8.0 * (potential_at(dt) - potential_at(-dt))
        - (potential_at(2.0 * dt) - potential_at(-2.0 * dt)))
        / (12.0 * dt);
    let want = -power_in - rate;
    let scale = contact.force.norm() * relative_speed + rate.abs() + elastic * relative_speed;
    assert!(
        contact.dissipation >= 0.0,
        "{label}: negative dissipation {:e} W",
        contact.dissipation
    );
    assert!(
        (contact.dissipation - want).abs() <= 1e-7 * scale,
        "{label}: dissipation {} W, books say {want} W (P {power_in}, dV/dt {rate}, scale {scale})",
        contact.dissipation
    );
    contact.normal == 0.0
}

fn random_body(rng: &mut Lcg, position: Vector2<f64>, angle: f64, speed: f64) -> BodyState {
    BodyState::new(
        position,
        angle,
        Vector2::new(rng.uniform(-speed, speed), rng.uniform(-speed, speed)),
        rng.uniform(-3.0, 3.0),
    )
}

/// Rim on shoe: random link poses and motions, the rim placed to press the
/// inner face by 0.5-5 mm at a random point of it.
#[test]
fn wheel_contact_dissipation_balances_the_books() {
    let shoe = M113::geometry().shoe;
    let radius = 0.3;
    let mut rng = Lcg::new(11);
    let mut clipped = 0;
    let mut checked = 0;
    for law in pair_laws() {
        let pair = WheelContact {
            normal: law,
            friction: friction(),
        };
        for case in 0..60 {
            let at = Vector2::new(rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0));
            let angle = rng.uniform(-3.2, 3.2);
            let link = random_body(&mut rng, at, angle, 1.5);
            let depth = rng.uniform(5e-4, 5e-3);
            let along = rng.uniform(0.1, 0.9);
            let face = shoe.inner_face[0] + (shoe.inner_face[1] - shoe.inner_face[0]) * along;
            let inward = link.arm(Vector2::new(0.0, 1.0));
            let centre = link.point(face) + inward * (radius - depth);
            let spin_angle = rng.uniform(-3.2, 3.2);
            let wheel = random_body(&mut rng, centre, spin_angle, 1.5);
            let evaluate = |link: &BodyState, wheel: &BodyState| {
                let (mut loads, mut wheel_load) = ([BodyLoad::ZERO], BodyLoad::ZERO);
                let mut contacts = vec![];
                pair.apply(
                    (wheel, radius),
                    std::slice::from_ref(link),
                    &shoe,
                    &mut loads,
                    &mut wheel_load,
                    |_, c| contacts.push(*c),
                );
                assert_eq!(contacts.len(), 1, "one rim contact");
                (contacts[0], loads[0], wheel_load)
            };
            let (contact, link_load, wheel_load) = evaluate(&link, &wheel);
            assert!((contact.penetration - depth).abs() < 1e-12);
            let relative = link.velocity_at(contact.point - link.position)
                - wheel.velocity_at(contact.point - wheel.position);
            let p = power(&link_load, &link) + power(&wheel_load, &wheel);
            clipped += check_books(
                &format!("{law:?} case {case}"),
                &contact,
                p,
                relative.norm(),
                law.elastic_force(contact.penetration),
                |dt| {
                    evaluate(&advanced(&link, dt), &advanced(&wheel, dt))
                        .0
                        .potential
                },
            ) as usize;
            checked += 1;
        }
    }
    assert_eq!(checked, 180);
    assert!(clipped > 0, "some separating cases clip the damping");
}

/// Shoe on ground: flat, ramp, bump and sine terrains, the link's lower
/// ground point pressed 0.5-5 mm below the profile.
#[test]
fn ground_contact_dissipation_balances_the_books() {
    let shoe = M113::geometry().shoe;
    let terrains = [
        Terrain::Flat { height: 0.1 },
        Terrain::Ramp {
            height: 0.0,
            start: -5.0,
            slope: 0.3,
        },
        Terrain::Bump {
            centre: 0.0,
            width: 4.0,
            height: 0.3,
        },
        Terrain::Sine {
            amplitude: 0.1,
            wavelength: 3.0,
        },
    ];
    let mut rng = Lcg::new(12);
    let mut clipped = 0;
    let mut contacts_checked = 0;
    let mut skipped = 0;
    for terrain in terrains {
        for law in pair_laws() {
            let ground = GroundContact {
                terrain: terrain.clone(),
                normal: law,
                friction: Friction { mu: 0.8, slip: 0.1 },
            };
            for case in 0..20 {
                let angle = rng.uniform(-0.3, 0.3);
                let x = rng.uniform(-1.5, 1.5);
                let probe = BodyState::new(Vector2::new(x, 0.0), angle, Vector2::zeros(), 0.0);
                // Lower the link until its deeper ground point is `depth`
                // below the profile.
                let depth = rng.uniform(5e-4, 5e-3);
                let lift = min_of(shoe.ground_points.iter().map(|u| {
                    let p = probe.point(*u);
                    p.y - terrain.height(p.x)
                }));
                let link = random_body(&mut rng, Vector2::new(x, -lift - depth), angle, 1.0);
                let evaluate = |link: &BodyState| {
                    let mut loads = [BodyLoad::ZERO];
                    let mut contacts = vec![];
                    ground.apply(std::slice::from_ref(link), &shoe, &mut loads, |_, c| {
                        contacts.push(*c)
                    });
                    (contacts, loads[0])
                };
                let (contacts, load) = evaluate(&link);
                assert!(!contacts.is_empty(), "{terrain:?} case {case}: in contact");
                // A second point barely touching would make the difference
                // of V meaningless (the Hertzian V⁽⁵⁾ grows as δ^(−5/2)).
                if contacts.iter().any(|c| c.penetration < 2e-4) {
                    skipped += 1;
                    continue;
                }
                let deepest = max_of(contacts.iter().map(|c| c.penetration));
                assert!((deepest - depth).abs() < 1e-9, "{deepest} vs {depth}");
                // The books of the link as a whole: the sum over points.
                // Contacts that open or close within ±dt would spoil the
                // difference; the shallow one must stay in or out.
                let potential = |dt: f64| {
                    let (c, _) = evaluate(&advanced(&link, dt));
                    assert_eq!(c.len(), contacts.len(), "contact set changes within dt");
                    c.iter().map(|c| c.potential).sum::<f64>()
                };
                let total = ContactForce {
                    point: Vector2::zeros(),
                    force: load.force,
                    normal: contacts.iter().map(|c| c.normal).sum(),
                    penetration: deepest,
                    dissipation: contacts.iter().map(|c| c.dissipation).sum(),
                    potential: 0.0,
                };
                let speed = link.velocity.norm() + link.omega.abs() * shoe.extent();
                let elastic: f64 = contacts
                    .iter()
                    .map(|c| law.elastic_force(c.penetration))
                    .sum();
                for c in &contacts {
                    assert!(c.dissipation >= 0.0, "point dissipation {}", c.dissipation);
                }
                check_books(
                    &format!("{terrain:?} {law:?} case {case}"),
                    &total,
                    power(&load, &link),
                    speed,
                    elastic * 1.05,
                    potential,
                );
                clipped += contacts.iter().filter(|c| c.normal == 0.0).count();
                contacts_checked += contacts.len();
            }
        }
    }
    assert!(skipped < 10, "{skipped} cases skipped");
    assert!(contacts_checked >= 240);
    assert!(clipped > 0, "some separating points clip the damping");
}

/// Pin on sprocket flank: random sprocket poses, a random gap, the pin
/// pushed 0.5-3 mm into the flank at 20-55° from the gap's inward radial.
#[test]
fn sprocket_contact_dissipation_balances_the_books() {
    let shoe = M113::geometry().shoe;
    let profile = M113::geometry().sprocket;
    let mut rng = Lcg::new(13);
    let mut checked = 0;
    for law in pair_laws() {
        let pair = SprocketContact {
            profile,
            normal: law,
            friction: friction(),
        };
        for case in 0..60 {
            let at = Vector2::new(rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0));
            let turned = rng.uniform(-7.0, 7.0);
            let sprocket = random_body(&mut rng, at, turned, 1.0);
            let k = (rng.uniform(0.0, 10.0)).floor();
            let phi = sprocket.angle + (k + 0.5) * profile.pitch_angle();
            let radial = Vector2::new(phi.cos(), phi.sin());
            let gap = sprocket.position + radial * profile.arc_centre_radius;
            let side = if rng.uniform(0.0, 1.0) < 0.5 {
                -1.0
            } else {
                1.0
            };
            let psi = side * rng.uniform(20.0, 55.0).to_radians();
            let inward = -radial;
            let w = Vector2::new(
                psi.cos() * inward.x - psi.sin() * inward.y,
                psi.sin() * inward.x + psi.cos() * inward.y,
            );
            let depth = rng.uniform(5e-4, 3e-3);
            let pin = gap + w * (profile.arc_radius - shoe.pin_radius + depth);
            // Pin 2 (ū = (−0.061, 0)) at `pin`, the link pointing away
            // from the sprocket so that pin 1 is well outside its teeth.
            let out = (pin - sprocket.position).normalize();
            let angle = out.y.atan2(out.x);
            let link = random_body(&mut rng, pin + out * 0.061, angle, 1.0);
            let evaluate = |link: &BodyState, sprocket: &BodyState| {
                let (mut loads, mut sprocket_load) = ([BodyLoad::ZERO], BodyLoad::ZERO);
                let mut contacts = vec![];
                pair.apply(
                    sprocket,
                    std::slice::from_ref(link),
                    &shoe,
                    &mut loads,
                    &mut sprocket_load,
                    |_, c| contacts.push(*c),
                );
                assert_eq!(contacts.len(), 1, "one pin in one flank");
                (contacts[0], loads[0], sprocket_load)
            };
            let (contact, link_load, sprocket_load) = evaluate(&link, &sprocket);
            assert!(
                (contact.penetration - depth).abs() < 1e-12,
                "case {case}: penetration {} vs {depth}",
                contact.penetration
            );
            let relative = link.velocity_at(contact.point - link.position)
                - sprocket.velocity_at(contact.point - sprocket.position);
            check_books(
                &format!("{law:?} case {case}"),
                &contact,
                power(&link_load, &link) + power(&sprocket_load, &sprocket),
                relative.norm(),
                law.elastic_force(contact.penetration),
                |dt| {
                    evaluate(&advanced(&link, dt), &advanced(&sprocket, dt))
                        .0
                        .potential
                },
            );
            checked += 1;
        }
    }
    assert_eq!(checked, 180);
}

/// A rim leaving the face fast under Kelvin-Voigt: the damping would pull,
/// so the force is zero, and the whole elastic force times the opening
/// rate is dissipated (the energy released by the spring is lost), by hand.
#[test]
fn separating_contact_does_not_pull_and_dissipates_by_hand() {
    let shoe = M113::geometry().shoe;
    let pair = WheelContact {
        normal: NormalLaw::KelvinVoigt {
            stiffness: 1e7,
            damping: 1e4,
        },
        friction: friction(),
    };
    // Link at rest, face at y = 0.03; rim 2 mm into it, rising at 3 m/s:
    // k δ = 2e4 N, c δ̇ = −3e4 N.
    let link = BodyState::new(Vector2::zeros(), 0.0, Vector2::zeros(), 0.0);
    let wheel = BodyState::new(
        Vector2::new(0.01, 0.03 + 0.3 - 0.002),
        0.0,
        Vector2::new(0.0, 3.0),
        0.0,
    );
    let (mut loads, mut wheel_load) = ([BodyLoad::ZERO], BodyLoad::ZERO);
    let mut contacts = vec![];
    pair.apply(
        (&wheel, 0.3),
        &[link],
        &shoe,
        &mut loads,
        &mut wheel_load,
        |_, c| contacts.push(*c),
    );
    assert_eq!(contacts.len(), 1);
    let c = contacts[0];
    assert_eq!(c.normal, 0.0);
    assert_eq!(c.force, Vector2::zeros());
    assert_eq!(loads[0], BodyLoad::ZERO);
    assert_eq!(wheel_load, BodyLoad::ZERO);
    // D = (0 − k δ) · δ̇ with δ̇ = −3 m/s: 2e4 · 3 = 6e4 W.
    rel_close("dissipation", c.dissipation, 6e4, 1e-12);
    rel_close("potential", c.potential, 0.5 * 1e7 * 0.002 * 0.002, 1e-12);
}
