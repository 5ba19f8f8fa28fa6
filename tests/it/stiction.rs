//! Friction with stiction (`trackgen::laws::Stiction`) against closed
//! forms (the guide's "Friction and stiction"): a block on an incline, a tangential
//! load ramp, and the energy books along any motion.
//!
//! The block: mass `m` on one contact point of the law, normal load
//! `W = m g cos α` (held: the normal direction is not simulated), the
//! tangential equation `m ẍ = −m g sin α + F_t(z, ẋ)`, `ż` from the law;
//! integrated by Dormand-Prince at 1e-10.
//!
//! Tolerances, and why:
//! - **Sticks below `μ`**: on a 30 % incline with μ = 0.8, the block's
//!   position after settling equals the spring's static deflection
//!   `m g sin α / k` to 1e-9 m and does not change over 100 s (to 1e-12 m:
//!   the integrator's rounding). A regularised Coulomb law creeps at
//!   metres per minute here.
//! - **Slides above `μ`**: on a 100 % incline (tan α = 1 > 0.8), once
//!   sliding the acceleration is `g (sin α − μ cos α)` to 1e-9 relative
//!   (in sliding the force is `μ W` exactly; the element's damper carries
//!   the rest).
//! - **Load ramp**: a horizontal load `F = t` (N, t in s) on a block
//!   under `W`: while it sticks the displacement is the spring-damper's
//!   steady response to the ramp, `(F − c Ḟ/k)/k` (its transient gone at
//!   `e^{−224 t}`), to 1e-6 of it, until `F = μ W`; the block breaks away
//!   within 0.1 % of `μ W` (the damper's force `c Ḟ` is 9e-3 N, and the
//!   output spacing 0.25 N).
//! - **Energy**: along a forced motion crossing stick and slip with a
//!   varying normal load, lifting off and landing, `−∫ F v dt = ΔV + ∫ D
//!   dt` to 1e-9 of the work (the quadrature of the test, Simpson's on a
//!   fine grid), and the dissipation never negative (exactly).

use trackgen::integrate::{Integrator, OdeSystem, SimulationError};
use trackgen::laws::Stiction;
use trackgen::laws::stiction::RELAXED;
use trackgen::nalgebra::DVector;
use trackgen::simulate::{Output, simulate};
use trackgen::system::Simulated;

const G: f64 = 9.81;

/// A block on an incline of slope `tan α`, or on the flat under a
/// horizontal load `load(t)`: state `[x, ẋ, z]`.
struct Block {
    law: Stiction,
    mass: f64,
    /// `(sin α, cos α)`.
    incline: (f64, f64),
    load: fn(f64) -> f64,
}

impl Block {
    fn normal(&self) -> f64 {
        self.mass * G * self.incline.1
    }
}

impl OdeSystem for Block {
    fn dimension(&self) -> usize {
        3
    }

    fn derivative(&mut self, t: f64, y: &[f64], dy: &mut [f64]) -> Result<(), SimulationError> {
        let r = self.law.respond(y[2], y[1], self.normal());
        dy[0] = y[1];
        dy[1] = (-self.mass * G * self.incline.0 + (self.load)(t) + r.force) / self.mass;
        dy[2] = r.rate;
        Ok(())
    }
}

impl Simulated for Block {
    fn initial_state(&self) -> DVector<f64> {
        DVector::zeros(3)
    }

    fn columns(&self) -> Vec<String> {
        ["x", "v", "z", "force", "sliding"]
            .map(String::from)
            .to_vec()
    }

    fn observe(&mut self, _t: f64, y: &[f64], row: &mut Vec<f64>) -> Result<(), SimulationError> {
        let r = self.law.respond(y[2], y[1], self.normal());
        row.extend([y[0], y[1], y[2], r.force, f64::from(u8::from(r.sliding))]);
        Ok(())
    }
}

fn law() -> Stiction {
    Stiction {
        mu: 0.8,
        stiffness: 1e6,
        damping: 2.0 * (1e6f64 * 20.0).sqrt(),
    }
}

fn incline(slope: f64) -> (f64, f64) {
    let norm = (1.0 + slope * slope).sqrt();
    (slope / norm, 1.0 / norm)
}

fn no_load(_: f64) -> f64 {
    0.0
}

#[test]
fn a_block_sticks_on_an_incline_below_mu() {
    let mut block = Block {
        law: law(),
        mass: 20.0,
        incline: incline(0.3),
        load: no_load,
    };
    let results = simulate(
        &mut block,
        Integrator::dopri5(1e-10),
        0.0,
        100.0,
        Output::Times(vec![1.0, 100.0]),
    )
    .expect("the block rests");
    let x = results.column("x").unwrap();
    let deflection = -20.0 * G * incline(0.3).0 / 1e6;
    assert!((x[0] - deflection).abs() < 1e-9, "{} vs {deflection}", x[0]);
    assert!((x[1] - x[0]).abs() < 1e-12, "crept {} m", x[1] - x[0]);
    assert_eq!(results.column("sliding").unwrap(), vec![0.0, 0.0]);
}

#[test]
fn a_block_slides_on_an_incline_above_mu() {
    let (s, c) = incline(1.0);
    let mut block = Block {
        law: law(),
        mass: 20.0,
        incline: (s, c),
        load: no_load,
    };
    let results = simulate(
        &mut block,
        Integrator::dopri5(1e-10),
        0.0,
        2.0,
        Output::Times(vec![1.0, 1.5, 2.0]),
    )
    .expect("the block slides");
    let v = results.column("v").unwrap();
    let want = -G * (s - 0.8 * c);
    for k in 0..2 {
        let a = (v[k + 1] - v[k]) / 0.5;
        assert!(
            ((a - want) / want).abs() < 1e-9,
            "acceleration {a} vs {want}"
        );
    }
    assert!(results.column("sliding").unwrap().iter().all(|&s| s == 1.0));
    let force = results.column("force").unwrap();
    assert!(
        force
            .iter()
            .all(|f| (f - 0.8 * 20.0 * G * c).abs() < 1e-9 * f)
    );
}

#[test]
fn a_load_ramp_deflects_the_spring_then_breaks_away_at_mu_w() {
    let mut block = Block {
        law: law(),
        mass: 20.0,
        incline: (0.0, 1.0),
        load: |t| t,
    };
    let limit = 0.8 * 20.0 * G;
    let results = simulate(
        &mut block,
        Integrator::dopri5(1e-11),
        0.0,
        limit + 20.0,
        Output::Every(0.25),
    )
    .expect("the ramp runs");
    let (t, x, sliding) = (
        results.times(),
        results.column("x").unwrap(),
        results.column("sliding").unwrap(),
    );
    let breakaway = t[sliding.iter().position(|&s| s == 1.0).expect("it slides")];
    assert!(
        (breakaway - limit).abs() <= 1e-3 * limit + 0.25,
        "breaks away at {breakaway} N against μW = {limit} N"
    );
    for k in 0..t.len() {
        if t[k] < 0.99 * limit && t[k] > 1.0 {
            let c = law().damping;
            let want = (t[k] - c / 1e6) / 1e6;
            assert!(
                (x[k] - want).abs() < 1e-6 * want,
                "x {} vs F/k {want}",
                x[k]
            );
        }
    }
}

#[test]
fn the_books_close_along_any_motion() {
    let law = law();
    // A forced motion: velocity and normal load varying, the load going
    // to zero (lift-off) and back, crossing stick and slip many times.
    let v = |t: f64| 0.02 * (7.0 * t).sin() + 0.01 * (2.3 * t).cos();
    let normal =
        |t: f64| (150.0 * (1.0 + (3.1 * t).sin())).max(0.0) * (0.5 + 0.5 * (0.7 * t).cos());
    let n = 400_000;
    let dt = 20.0 / n as f64;
    let mut z = 0.0;
    let (mut work, mut dissipated) = (0.0, 0.0);
    let mut sliding = (0, 0);
    let mut least = f64::INFINITY;
    let step = |t: f64, z: f64| law.respond(z, v(t), normal(t));
    for k in 0..n {
        let t = k as f64 * dt;
        // Runge-Kutta 4 on `ż`, Simpson's rule on the power terms.
        let r0 = step(t, z);
        let r1 = step(t + dt / 2.0, z + dt / 2.0 * r0.rate);
        let r2 = step(t + dt / 2.0, z + dt / 2.0 * r1.rate);
        let r3 = step(t + dt, z + dt * r2.rate);
        let power = |r: &trackgen::laws::TangentialResponse, t: f64| -r.force * v(t);
        work += dt / 6.0
            * (power(&r0, t)
                + 2.0 * power(&r1, t + dt / 2.0)
                + 2.0 * power(&r2, t + dt / 2.0)
                + power(&r3, t + dt));
        dissipated += dt / 6.0
            * (r0.dissipation + 2.0 * r1.dissipation + 2.0 * r2.dissipation + r3.dissipation);
        least = least.min(r0.dissipation);
        if r0.sliding {
            sliding.0 += 1;
        } else {
            sliding.1 += 1;
        }
        z += dt / 6.0 * (r0.rate + 2.0 * r1.rate + 2.0 * r2.rate + r3.rate);
    }
    let stored = 0.5 * law.stiffness * z * z;
    assert!(
        sliding.0 > 1000 && sliding.1 > 1000,
        "stick and slip: {sliding:?}"
    );
    assert!(least >= 0.0, "dissipation {least}");
    assert!(
        (work - stored - dissipated).abs() < 1e-9 * work.abs(),
        "work {work} J, stored {stored} J, dissipated {dissipated} J"
    );
}

/// Off the ground the law relaxes the deflection down to `RELAXED` and
/// stops there. Explicit Euler at half the relaxation's time constant
/// halves the deflection each step: from 1 mm it would pass `10⁻¹⁵⁴` m
/// (its energy then subnormal) in 500 steps and be a subnormal number
/// itself after 1013. Checked over 2000 steps: it comes to rest below
/// `RELAXED` and at half of it or more, and no number the law returns is
/// subnormal. Above `RELAXED` the law is `ż = −k z / c` exactly.
#[test]
fn a_relaxing_deflection_stops_short_of_subnormal_numbers() {
    let law = law();
    let h = 0.5 * law.damping / law.stiffness;
    let mut z = 1e-3;
    for _ in 0..2000 {
        let r = law.relax(z);
        for value in [z, r.rate, r.potential, r.dissipation] {
            assert!(!value.is_subnormal(), "{value:e} at z = {z:e}");
        }
        z += h * r.rate;
    }
    assert!((0.5 * RELAXED..RELAXED).contains(&z), "z = {z:e}");
    let at = law.relax(RELAXED);
    assert_eq!(at.rate, -law.stiffness * RELAXED / law.damping);
    assert_eq!(at.potential, 0.5 * law.stiffness * RELAXED * RELAXED);
    let below = law.relax(-0.9 * RELAXED);
    assert_eq!(
        (below.rate, below.potential, below.dissipation),
        (0.0, 0.0, 0.0)
    );
}

/// `relax_each` over a run of deflections (relaxing, relaxed, zero, of
/// either sign; a length that is no multiple of its four lanes) gives
/// each deflection `relax`'s rate to the bit, and sums of the energy and
/// power within 1e-15 of theirs added one by one (the lanes only reorder
/// the additions of positive terms: a few ulps).
#[test]
fn relaxing_a_run_of_deflections_is_relaxing_each() {
    let law = law();
    let deflections: Vec<f64> = (0..23)
        .map(|i| match i % 5 {
            0 => 1e-3 / f64::from(i + 1),
            1 => -2e-4 * f64::from(i),
            2 => 0.0,
            3 => 0.5 * RELAXED,
            _ => 3e-6 * f64::from(i),
        })
        .collect();
    let mut rates = vec![f64::NAN; deflections.len() + 2];
    let (stored, lost) = law.relax_each(&deflections, &mut rates);
    let (mut stored_one, mut lost_one) = (0.0, 0.0);
    for (z, rate) in deflections.iter().zip(&rates) {
        let r = law.relax(*z);
        assert_eq!(rate.to_bits(), r.rate.to_bits(), "at z = {z:e}");
        stored_one += r.potential;
        lost_one += r.dissipation;
    }
    assert!(rates[deflections.len()..].iter().all(|r| r.is_nan()));
    assert!(stored_one > 0.0 && lost_one > 0.0);
    assert!((stored - stored_one).abs() <= 1e-15 * stored_one);
    assert!((lost - lost_one).abs() <= 1e-15 * lost_one);
}
