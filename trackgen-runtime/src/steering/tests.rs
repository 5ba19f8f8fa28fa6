//! The closed forms against quadrature of the friction's pointwise law,
//! the steady turn against the balance and the power books computed by
//! that quadrature, its symmetries, and the simplified theory's closed
//! form in its own limit.

use super::shear::{unit_density, unit_shear};
use nalgebra::Vector2;

use super::*;

/// Gauss-Legendre nodes and weights on [−1, 1], 8 points.
const GAUSS: [(f64, f64); 8] = [
    (-0.960_289_856_497_536_3, 0.101_228_536_290_376_26),
    (-0.796_666_477_413_626_7, 0.222_381_034_453_374_48),
    (-0.525_532_409_916_329, 0.313_706_645_877_887_3),
    (-0.183_434_642_495_649_8, 0.362_683_783_378_362),
    (0.183_434_642_495_649_8, 0.362_683_783_378_362),
    (0.525_532_409_916_329, 0.313_706_645_877_887_3),
    (0.796_666_477_413_626_7, 0.222_381_034_453_374_48),
    (0.960_289_856_497_536_3, 0.101_228_536_290_376_26),
];

/// `∫_a^b f` by 8-point Gauss-Legendre on panels graded toward `ξ = 0`
/// (where the integrands bend sharply when `d` is small), split there.
fn quadrature(a: f64, b: f64, f: impl Fn(f64) -> f64) -> f64 {
    let mut edges = vec![a, b];
    if a < 0.0 && b > 0.0 {
        edges.insert(1, 0.0);
    }
    let mut sum = 0.0;
    for w in edges.windows(2) {
        let (lo, hi) = (w[0], w[1]);
        // Geometric panels from the end nearer 0.
        let (near, far, sign) = if lo.abs() <= hi.abs() {
            (lo, hi, 1.0)
        } else {
            (hi, lo, -1.0)
        };
        let mut points = vec![near];
        let span = far - near;
        for i in (0..60).rev() {
            points.push(near + span * 0.75_f64.powi(i));
        }
        for p in points.windows(2) {
            let (h, m) = (0.5 * (p[1] - p[0]), 0.5 * (p[1] + p[0]));
            sum += sign * GAUSS.iter().map(|(x, w)| w * h * f(m + h * x)).sum::<f64>();
        }
    }
    sum
}

/// The ground's force on the vehicle and its moment about the centre of
/// gravity, and the friction's dissipation, at a found turn, by
/// quadrature of the pointwise Coulomb law `−μ p v/|v|` with the point's
/// velocity `v` computed from the hull's motion and the belt speed (not
/// from the centres).
fn shear_by_quadrature(vehicle: &SkidSteer, turn: &SteadyTurn) -> (Vector2<f64>, f64, f64) {
    let (v, omega) = (turn.velocity, turn.yaw_rate);
    let (mut force, mut moment, mut dissipation) = (Vector2::zeros(), 0.0, 0.0);
    for (track, side) in vehicle.tracks.iter().zip(turn.sides) {
        let y = track.lateral;
        for s in &track.stretches {
            let q = vehicle.friction * s.load / (s.to - s.from);
            let slide = |x: f64| Vector2::new(v.x - omega * y - side.belt_speed, v.y + omega * x);
            let unit = |x: f64| {
                let s = slide(x);
                if s.norm() == 0.0 {
                    Vector2::zeros()
                } else {
                    -s / s.norm()
                }
            };
            // The centre (where the velocity vanishes) splits the panels.
            let centre = turn.centre.x;
            let integrate = |f: &dyn Fn(f64) -> f64| {
                if s.from < centre && centre < s.to {
                    quadrature(s.from - centre, 0.0, |xi| f(xi + centre))
                        + quadrature(0.0, s.to - centre, |xi| f(xi + centre))
                } else {
                    quadrature(s.from - centre, s.to - centre, |xi| f(xi + centre))
                }
            };
            let fx = q * integrate(&|x| unit(x).x);
            let fy = q * integrate(&|x| unit(x).y);
            force += Vector2::new(fx, fy);
            moment += q * integrate(&|x| x * unit(x).y) - y * fx;
            dissipation += q * integrate(&|x| slide(x).norm());
        }
    }
    (force, moment, dissipation)
}

#[test]
fn the_closed_forms_equal_quadrature_of_their_integrands() {
    // Stretches across and to one side of the centre, offsets from large
    // to a thousandth of the stretch and none; relative 1e-10 (the
    // quadrature's own error is below 1e-13 on these smooth panels).
    for &(a, b) in &[(-1.3, 1.4), (0.2, 1.9), (-2.1, -0.4), (-0.5, 0.0)] {
        for &d in &[2.0, 0.3, -0.05, 1e-3, 0.0] {
            let unit = unit_shear(a, b, d);
            let rho = |xi: f64| f64::hypot(xi, d);
            let along = quadrature(a, b, |xi| if d == 0.0 { 0.0 } else { d / rho(xi) });
            let across = quadrature(a, b, |xi| -xi / rho(xi));
            let moment = quadrature(a, b, |xi| -xi * xi / rho(xi));
            let dissipation = quadrature(a, b, rho);
            let scale = b - a;
            for (closed, quad, what) in [
                (unit.along, along, "along"),
                (unit.across, across, "across"),
                (unit.moment, moment, "moment"),
                (unit.dissipation, dissipation, "dissipation"),
            ] {
                assert!(
                    (closed - quad).abs() <= 1e-10 * scale * scale.max(1.0),
                    "{what} on [{a}, {b}] at d = {d}: closed {closed}, quadrature {quad}"
                );
            }
        }
    }
}

#[test]
fn the_derivatives_equal_central_differences() {
    // In d at d ≠ 0, and the ends' densities in the centre's place (the
    // stretch's ends move by −h). Step 1e-6 m: the differences' error,
    // h² f''' ~ 1e-12 and the rounding 1e-16/1e-6, both far below 1e-7.
    let h = 1e-6;
    for &(a, b) in &[(-1.3, 1.4), (0.2, 1.9)] {
        for &d in &[2.0, 0.3, -0.05] {
            let unit = unit_shear(a, b, d);
            let (up, down) = (unit_shear(a, b, d + h), unit_shear(a, b, d - h));
            let by_d = [
                (up.along - down.along) / (2.0 * h),
                (up.across - down.across) / (2.0 * h),
                (up.moment - down.moment) / (2.0 * h),
            ];
            for (exact, diff) in [unit.along_d, unit.across_d, unit.moment_d]
                .iter()
                .zip(by_d)
            {
                assert!(
                    (exact - diff).abs() < 1e-7,
                    "{exact} against {diff} at d = {d}"
                );
            }
            let (lo, hi) = (unit_density(a, d), unit_density(b, d));
            let (fwd, back) = (unit_shear(a - h, b - h, d), unit_shear(a + h, b + h, d));
            let by_centre = [
                (fwd.along - back.along) / (2.0 * h),
                (fwd.across - back.across) / (2.0 * h),
                (fwd.moment - back.moment) / (2.0 * h),
            ];
            for i in 0..3 {
                let exact = -(hi[i] - lo[i]);
                assert!(
                    (exact - by_centre[i]).abs() < 1e-7,
                    "{exact} against {}",
                    by_centre[i]
                );
            }
        }
    }
}

#[test]
fn turning_about_the_middles_of_uniform_runs_gives_steeds_moment() {
    // With each track's centre on its own line (d = 0) the run slides
    // sideways only, and the lateral friction's moment about the middle
    // is Steeds' μ W L / 4 (to rounding).
    let (mu, weight, length) = (0.8, 120e3, 2.7);
    let q = mu * 0.5 * weight / length;
    let unit = unit_shear(-0.5 * length, 0.5 * length, 0.0);
    let both = -2.0 * q * unit.moment;
    let steeds = steeds_resisting_moment(mu, weight, length);
    assert!(
        (both - steeds).abs() < 1e-12 * steeds,
        "{both} against {steeds}"
    );
}

/// A vehicle of an M113's size on uneven loads: five road wheels' worth
/// of stretches per side, heavier at the front on the left.
fn lumpy() -> SkidSteer {
    let stretches = |scale: [f64; 5]| {
        (0..5)
            .map(|i| Stretch {
                from: -1.35 + 0.6 * i as f64,
                to: -1.35 + 0.6 * i as f64 + 0.3,
                load: 11e3 * scale[i],
            })
            .collect::<Vec<_>>()
    };
    SkidSteer {
        mass: 12_337.7,
        friction: 0.8,
        rolling_resistance: 0.03,
        belt_resistance: 0.02,
        tracks: [
            TrackLoad {
                lateral: 1.1,
                stretches: stretches([1.2, 1.0, 1.0, 0.9, 1.1]),
            },
            TrackLoad {
                lateral: -1.05,
                stretches: stretches([1.0, 1.0, 1.1, 1.0, 1.0]),
            },
        ],
    }
}

#[test]
fn a_found_turn_balances_by_quadrature_and_its_sprockets_pay_for_its_losses() {
    // The turn's forces and moment recomputed by quadrature of the
    // pointwise law from the hull's motion and the belts' speeds balance
    // the centripetal force and the rolling resistance to 1e-9 of the
    // weight (the quadrature's accuracy with Newton's 1e-12); and in a
    // steady turn the sprockets' power equals the friction's dissipation
    // and the rolling loss (the kinetic energy is constant) to 1e-9.
    let vehicle = lumpy();
    let weight = vehicle.load();
    for &(omega, vx) in &[(0.5, 0.0), (0.5, 1.0), (-0.3, 2.0), (0.1, 3.0), (0.05, 2.0)] {
        let turn = vehicle.turn(omega, vx).expect("a steady turn");
        let (shear, moment, dissipation) = shear_by_quadrature(&vehicle, &turn);
        let resistance: f64 = turn.sides.iter().map(|s| s.resistance).sum();
        let rolling_moment: f64 = vehicle
            .tracks
            .iter()
            .zip(turn.sides)
            .map(|(t, s)| -t.lateral * s.resistance)
            .sum();
        let centripetal =
            vehicle.mass * Vector2::new(-omega * turn.velocity.y, omega * turn.velocity.x);
        let out = shear + Vector2::new(resistance, 0.0) - centripetal;
        assert!(
            out.amax() < 1e-9 * weight,
            "ω {omega}, V {vx}: out of balance by {out}"
        );
        assert!(
            (moment + rolling_moment).abs() < 1e-9 * weight,
            "ω {omega}: moment {moment}"
        );
        let paid: f64 = turn.sides.iter().map(|s| s.power).sum();
        let lost = dissipation + turn.rolling_loss;
        assert!(
            (paid - lost).abs() < 1e-9 * lost,
            "ω {omega}, V {vx}: paid {paid}, lost {lost}"
        );
        assert!((turn.dissipation - dissipation).abs() < 1e-9 * dissipation);
    }
}

/// The running gear's losses act inside the vehicle: they move no
/// instantaneous centre (the turn is the one without them, bit for bit),
/// and each sprocket gives them beyond the shear, `f_b N` against its
/// belt's motion, to rounding; where a belt stands (a clutch-brake turn's
/// inner) it gives the shear alone.
#[test]
fn the_running_gears_losses_load_the_sprockets_and_move_no_centre() {
    let with = lumpy();
    let without = SkidSteer {
        belt_resistance: 0.0,
        ..with.clone()
    };
    for (omega, vx) in [(0.5, 1.0), (-0.3, 2.0), (0.8, 0.0)] {
        let (a, b) = (
            with.turn(omega, vx).unwrap(),
            without.turn(omega, vx).unwrap(),
        );
        assert_eq!((a.velocity, a.centre), (b.velocity, b.centre));
        for (j, (sa, sb)) in a.sides.iter().zip(&b.sides).enumerate() {
            assert_eq!(sa.thrust, sb.thrust);
            let loss = with.belt_resistance * with.tracks[j].load() * sa.belt_speed.signum();
            assert!((sa.sprocket_force() - (sb.thrust + loss)).abs() < 1e-9 * loss.abs());
        }
    }
    let [left, right] = [0.0, 1.0];
    let brake = with.drive([left, right]).unwrap();
    assert_eq!(brake.sides[0].belt_loss, 0.0);
    assert_eq!(brake.sides[0].sprocket_force(), brake.sides[0].thrust);
}

#[test]
fn a_mirrored_vehicle_turns_the_mirrored_way() {
    // Mirror the vehicle across its centre line and the turn: the sides
    // swap, the lateral figures change sign, to 1e-12 of the figures.
    let vehicle = lumpy();
    let mirror = SkidSteer {
        tracks: [vehicle.tracks[1].mirrored(), vehicle.tracks[0].mirrored()],
        ..vehicle.clone()
    };
    let left = vehicle.turn(0.4, 1.5).unwrap();
    let right = mirror.turn(-0.4, 1.5).unwrap();
    let close = |a: f64, b: f64, scale: f64| (a - b).abs() <= 1e-12 * scale;
    assert!(close(left.velocity.y, -right.velocity.y, 1.0));
    assert!(close(left.radius, right.radius, left.radius));
    for j in 0..2 {
        let (a, b) = (left.sides[j], right.sides[1 - j]);
        assert!(
            close(a.belt_speed, b.belt_speed, 1.0),
            "{a:?} against {b:?}"
        );
        assert!(close(a.thrust, b.thrust, 1e5));
        assert!(close(a.lateral, -b.lateral, 1e5));
        assert!(close(a.offset, -b.offset, 1.0));
    }
}

#[test]
fn belts_driven_at_a_turns_speeds_give_that_turn() {
    // `drive` from the belt speeds `turn` found returns the yaw rate and
    // speed asked (1e-9: both converge the balance to 1e-12 of the
    // weight, and the map from belt speeds to the turn is well
    // conditioned away from the straight line).
    let vehicle = lumpy();
    for &(omega, vx) in &[(0.5, 0.0), (0.4, 1.5), (-0.1, 3.0)] {
        let turn = vehicle.turn(omega, vx).unwrap();
        let driven = vehicle
            .drive([turn.sides[0].belt_speed, turn.sides[1].belt_speed])
            .unwrap();
        assert!(
            (driven.yaw_rate - omega).abs() < 1e-9,
            "{} against {omega}",
            driven.yaw_rate
        );
        assert!(
            (driven.velocity.x - vx).abs() < 1e-9,
            "{} against {vx}",
            driven.velocity.x
        );
    }
}

#[test]
fn a_symmetric_pivot_turn_is_symmetric_and_resists_less_than_steeds() {
    // Uniform runs, no forward speed: the belts run at opposite speeds,
    // the centres abreast of the centre of gravity, the thrusts opposite
    // and their couple equal to the moment of turning resistance plus the
    // rolling resistance's; that moment below Steeds' μ W L / 4 (part of
    // the friction drives the runs along instead of across: Wong &
    // Chiang's finding) but more than half of it at this L/B.
    // (The couple turns the hull; the rolling resistance, forward on the
    // inner track running back and back on the outer, and the lateral
    // shear resist.)
    let (mass, gauge, length) = (12_000.0, 2.2, 2.7);
    let vehicle = SkidSteer::uniform(mass, gauge, length, 0.8, 0.03);
    let turn = vehicle.turn(0.6, 0.0).unwrap();
    let [left, right] = turn.sides;
    assert!((left.belt_speed + right.belt_speed).abs() < 1e-12);
    assert!(turn.centre.x.abs() < 1e-12, "{}", turn.centre.x);
    assert!((left.thrust + right.thrust).abs() < 1e-9 * left.thrust.abs());
    let couple = 0.5 * gauge * (right.thrust - left.thrust);
    let rolling = 0.5 * gauge * (left.resistance - right.resistance);
    assert!(
        (couple - rolling - turn.resisting_moment).abs() < 1e-9 * couple,
        "{couple}"
    );
    let steeds = steeds_resisting_moment(0.8, vehicle.load(), length);
    assert!(turn.resisting_moment < steeds && turn.resisting_moment > 0.5 * steeds);
    assert!(turn.speed_ratio() < 0.0);
}

#[test]
fn bad_input_and_impossible_turns_are_errors() {
    let vehicle = lumpy();
    assert!(matches!(
        vehicle.turn(0.0, 1.0),
        Err(SteeringError::Input { .. })
    ));
    assert!(matches!(
        vehicle.turn(f64::NAN, 1.0),
        Err(SteeringError::Input { .. })
    ));
    assert!(matches!(
        vehicle.drive([1.0, 1.0]),
        Err(SteeringError::Input { .. })
    ));
    let mut crossed = vehicle.clone();
    crossed.tracks.swap(0, 1);
    assert!(matches!(
        crossed.turn(0.3, 1.0),
        Err(SteeringError::Input { .. })
    ));
    let mut reversed = vehicle.clone();
    reversed.tracks[0].stretches[0].to = reversed.tracks[0].stretches[0].from;
    assert!(matches!(
        reversed.turn(0.3, 1.0),
        Err(SteeringError::Input { .. })
    ));
    // The centripetal force m ω V beyond the grip μ W: no steady turn.
    let too_fast = vehicle.turn(1.0, 10.0);
    assert!(
        matches!(too_fast, Err(SteeringError::NoSolution { .. })),
        "{too_fast:?}"
    );
}

#[test]
fn the_simplified_criterion_is_its_closed_form() {
    // 2 (μ − f_r)/μ_t: μ = 0.8, f_r = 0.03 → 1.925 at μ_t = μ.
    assert!((largest_length_to_gauge(0.8, 0.03, 0.8) - 1.925).abs() < 1e-15);
}

#[test]
fn point_loads_spread_keep_their_sum_and_moment() {
    // Loads in clusters (under wheels) with gaps and a repeated place:
    // the stretches carry the same total and first moment (to rounding),
    // none wider than the median spacing, none overlapping.
    let points = [
        (-1.2, 3e3),
        (-1.1, 4e3),
        (-1.0, 2e3),
        (-0.4, 5e3),
        (-0.3, 5e3),
        (-0.3, 1e3),
        (0.4, 6e3),
        (0.5, 2e3),
        (1.3, 4e3),
    ];
    let run = TrackLoad::from_points(1.0, &points);
    let total: f64 = points.iter().map(|p| p.1).sum();
    let moment: f64 = points.iter().map(|p| p.0 * p.1).sum();
    let spread: f64 = run
        .stretches
        .iter()
        .map(|s| 0.5 * (s.from + s.to) * s.load)
        .sum();
    assert!((run.load() - total).abs() < 1e-9);
    assert!((spread - moment).abs() < 1e-9, "{spread} against {moment}");
    assert_eq!(run.stretches.len(), 8, "the two at −0.3 m share a cell");
    for pair in run.stretches.windows(2) {
        assert!(pair[0].to <= pair[1].from + 1e-15, "{pair:?}");
    }
    assert!(run.stretches.iter().all(|s| s.to - s.from <= 0.1 + 1e-12));
}

/// With friction the same in every direction the general theory has no
/// steerability cut: as `L/B` grows through the simplified criterion
/// (`largest_length_to_gauge`, 1.94 here) a clutch-brake turn (the inner
/// belt standing, the outer at 1 m/s) turns ever more slowly against its
/// kinematic yaw rate, smoothly, and the outer track's thrust nears its
/// grip `μ W/2` without reaching it: a run sliding along as well as
/// across resists the turn less. What the simplified theory calls "fails
/// to turn" is its lateral coefficient held apart from the slip along.
#[test]
fn the_general_theory_turns_smoothly_through_the_simplified_criterion() {
    let (mass, length, mu, rolling) = (3500.0, 2.6, 0.7, 0.02);
    let criterion = largest_length_to_gauge(mu, rolling, mu);
    assert!((criterion - 2.0 * 0.68 / 0.7).abs() < 1e-15);
    let mut last: Option<(f64, f64)> = None;
    for k in 0..=20 {
        let ratio = 1.0 + 0.1 * k as f64;
        let gauge = length / ratio;
        let vehicle = SkidSteer::uniform(mass, gauge, length, mu, rolling);
        let turn = vehicle.drive([0.0, 1.0]).expect("a steady turn");
        let share = turn.yaw_rate / (1.0 / gauge);
        let grip = turn.sides[1].thrust / (0.5 * mu * vehicle.load());
        assert!(share > 0.25 && grip < 0.9, "L/B {ratio}: {share}, {grip}");
        if let Some((previous, previous_grip)) = last {
            // Each step of 0.1 in L/B takes 3–6 % of the yaw rate's share
            // (0.83 at 1.0, 0.27 at 3.0): no step near the criterion.
            let fall = (previous - share) / previous;
            assert!((0.02..0.07).contains(&fall), "L/B {ratio}: {fall}");
            assert!(grip > previous_grip, "L/B {ratio}");
        }
        last = Some((share, grip));
    }
}
