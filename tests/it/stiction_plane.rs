//! Stiction in the ground's plane (`Stiction::respond_in_plane`): along
//! an axis it is the law along one tangent (its force and rate bit for
//! bit, its energies to rounding); it is isotropic
//! (a turned state gives the turned response); its books close (`−F·v` =
//! the stored energy's rate + the dissipation); its force never exceeds
//! `μ F_n` and, sliding, opposes the trial force; its slopes are its
//! central differences; and a puck set sliding in any direction on a
//! level plane goes straight and stops after `v₀²/(2 μ g)`.

use trackgen::laws::Stiction;
use trackgen::nalgebra::{Matrix2, Vector2};

fn law() -> Stiction {
    Stiction {
        mu: 0.8,
        stiffness: 2e5,
        damping: 2e3,
    }
}

/// States that stick and states that slide: (z, v, F_n).
fn states() -> Vec<(Vector2<f64>, Vector2<f64>, f64)> {
    let mut out = Vec::new();
    let mut x = 0x2545_f491_4f6c_dd1d_u64;
    let mut next = move || {
        x ^= x << 13;
        x ^= x >> 7;
        x ^= x << 17;
        (x >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
    };
    for _ in 0..200 {
        let z = 4e-3 * Vector2::new(next(), next());
        let v = 0.5 * Vector2::new(next(), next());
        let normal = 1000.0 * (1.0 + next());
        out.push((z, v, normal));
    }
    out
}

#[test]
fn along_an_axis_it_is_the_law_along_one_tangent() {
    let law = law();
    let mut sliding = 0;
    for (z, v, normal) in states() {
        let line = law.respond(z.x, v.x, normal);
        let plane = law.respond_in_plane(Vector2::new(z.x, 0.0), Vector2::new(v.x, 0.0), normal);
        assert_eq!(plane.force, Vector2::new(line.force, 0.0));
        assert_eq!(plane.rate, Vector2::new(line.rate, 0.0));
        // The energies multiply in another order: to a few units in the
        // last place.
        assert!((plane.potential - line.potential).abs() <= 1e-15 * line.potential);
        assert!((plane.dissipation - line.dissipation).abs() <= 1e-15 * line.dissipation);
        assert_eq!(plane.sliding, line.sliding);
        sliding += usize::from(line.sliding);
    }
    assert!(
        sliding > 20 && sliding < 180,
        "both regimes met: {sliding} of 200 slide"
    );
}

#[test]
fn it_is_isotropic_bounded_and_its_books_close() {
    // Turned by any angle, the response turns with the state (1e-12 of
    // the limit); |F| ≤ μ F_n (to rounding); sliding, F opposes the
    // trial force k z + c v; and −F·v = k z·ż + dissipation (1e-12 of
    // the largest term).
    let law = law();
    for (i, (z, v, normal)) in states().into_iter().enumerate() {
        let r = law.respond_in_plane(z, v, normal);
        let limit = law.mu * normal;
        assert!(r.force.norm() <= limit * (1.0 + 1e-15));
        let turn = Matrix2::new(0.6, -0.8, 0.8, 0.6)
            * Matrix2::new(
                (i as f64).cos(),
                -(i as f64).sin(),
                (i as f64).sin(),
                (i as f64).cos(),
            );
        let t = law.respond_in_plane(turn * z, turn * v, normal);
        assert!((t.force - turn * r.force).amax() <= 1e-12 * limit);
        assert!((t.rate - turn * r.rate).amax() <= 1e-12 * (1.0 + r.rate.amax()));
        assert!((t.dissipation - r.dissipation).abs() <= 1e-12 * (1.0 + r.dissipation));
        if r.sliding {
            let trial = law.stiffness * z + law.damping * v;
            assert!(r.force.dot(&trial) < 0.0);
            assert!((r.force.perp(&trial)).abs() <= 1e-9 * limit * trial.norm());
        }
        let paid = -r.force.dot(&v);
        let kept = law.stiffness * z.dot(&r.rate) + r.dissipation;
        let scale = paid.abs().max(r.dissipation).max(1e-12);
        assert!(
            (paid - kept).abs() <= 1e-12 * scale,
            "{paid} against {kept}"
        );
        assert!(r.dissipation >= 0.0);
    }
}

#[test]
fn its_slopes_are_its_central_differences() {
    // Away from the stick-slip boundary (where the slopes jump), steps of
    // 1e-9 m, 1e-7 m/s and 1e-4 N; agreement to 1e-6 of each slope's scale
    // (k, c, k/c, 1, μ, μ/c): the differences' truncation error (the step
    // squared times the third derivative) and their rounding (ε over the
    // step) are both some 1e-10 of it.
    let law = law();
    // The central differences of the force and of ż along one argument
    // moved by ±`step` (`at(±1)` evaluating the law there).
    let central = |at: &dyn Fn(f64) -> (Vector2<f64>, Vector2<f64>), step: f64| {
        let ((f1, r1), (f0, r0)) = (at(1.0), at(-1.0));
        ((f1 - f0) / (2.0 * step), (r1 - r0) / (2.0 * step))
    };
    let respond = |z, v, n| {
        let r = law.respond_in_plane(z, v, n);
        (r.force, r.rate)
    };
    for (z, v, normal) in states() {
        let trial = (law.stiffness * z + law.damping * v).norm();
        if (trial - law.mu * normal).abs() < 1e-3 * law.mu * normal {
            continue;
        }
        let s = law.slopes_in_plane(z, v, normal);
        for axis in 0..2 {
            let (dz, dv) = (
                1e-9 * Vector2::ith(axis, 1.0),
                1e-7 * Vector2::ith(axis, 1.0),
            );
            let (force_z, rate_z) = central(&|sign| respond(z + sign * dz, v, normal), 1e-9);
            let (force_v, rate_v) = central(&|sign| respond(z, v + sign * dv, normal), 1e-7);
            assert!((s.force.0.column(axis) - force_z).amax() <= 1e-6 * law.stiffness);
            assert!((s.force.1.column(axis) - force_v).amax() <= 1e-6 * law.damping);
            assert!((s.rate.0.column(axis) - rate_z).amax() <= 1e-6 * law.stiffness / law.damping);
            assert!((s.rate.1.column(axis) - rate_v).amax() <= 1e-6);
        }
        let (force_n, rate_n) = central(&|sign| respond(z, v, normal + sign * 1e-4), 1e-4);
        assert!((s.force.2 - force_n).amax() <= 1e-6 * law.mu);
        assert!((s.rate.2 - rate_n).amax() <= 1e-6 * law.mu / law.damping);
    }
}

#[test]
fn a_puck_slides_straight_and_stops_after_the_coulomb_distance() {
    // A 10 kg puck at 2 m/s on a level plane in three directions, classic
    // RK4 at 10 µs (the law's stiffest mode, k/m ~ 2e4 /s², and c/m =
    // 200 /s, well inside RK4's stability at this step): it stops on its
    // starting line, v₀²/(2 μ g) = 0.2549 m on, to 0.1 mm (the spring's
    // deflection at the stop, μ m g / k = 0.4 mm, is where it rests: the
    // distance is within that of the closed form), the same in every
    // direction to 1e-9 m.
    let law = law();
    let (m, g, v0) = (10.0, 9.81, 2.0);
    let closed = v0 * v0 / (2.0 * law.mu * g);
    let mut reached = Vec::new();
    for angle in [0.0_f64, 0.7, 2.3] {
        let dir = Vector2::new(angle.cos(), angle.sin());
        // State: position, velocity, deflection.
        let mut s = [Vector2::zeros(), v0 * dir, Vector2::zeros()];
        let f = |s: &[Vector2<f64>; 3]| {
            let r = law.respond_in_plane(s[2], s[1], m * g);
            [s[1], r.force / m, r.rate]
        };
        let h = 1e-5;
        for _ in 0..(0.6 / h) as usize {
            let k1 = f(&s);
            let a = [
                s[0] + 0.5 * h * k1[0],
                s[1] + 0.5 * h * k1[1],
                s[2] + 0.5 * h * k1[2],
            ];
            let k2 = f(&a);
            let b = [
                s[0] + 0.5 * h * k2[0],
                s[1] + 0.5 * h * k2[1],
                s[2] + 0.5 * h * k2[2],
            ];
            let k3 = f(&b);
            let c = [s[0] + h * k3[0], s[1] + h * k3[1], s[2] + h * k3[2]];
            let k4 = f(&c);
            for i in 0..3 {
                s[i] += h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
            }
        }
        assert!(s[1].norm() < 1e-3, "stopped: {}", s[1].norm());
        assert!(
            s[0].perp(&dir).abs() < 1e-12,
            "straight: {}",
            s[0].perp(&dir)
        );
        let along = s[0].dot(&dir);
        assert!(
            (along - closed).abs() < 1e-4 + law.mu * m * g / law.stiffness,
            "{along} against {closed}"
        );
        reached.push(along);
    }
    assert!(
        reached.windows(2).all(|w| (w[0] - w[1]).abs() < 1e-9),
        "{reached:?}"
    );
}
