//! Steady turns of the spatial `Twin` on firm level ground, its two
//! sprockets speed-controlled apart, against the general theory of skid
//! steering (Wong & Chiang, "A general theory for skid steering of
//! tracked vehicles on firm ground", Proc. IMechE Part D 215, 2001),
//! which `trackgen::steering::SkidSteer` implements apart from the
//! spatial model: fed the run's own shoe loads (time-averaged), its
//! friction coefficient and the rolling resistance a straight run shows,
//! the theory gives the yaw rate, the radius and both sprockets' torques
//! the run should settle at.
//!
//! The theory is Coulomb's friction at its limit wherever the run slides
//! (its shear-deformation modulus `K` → 0) on tracks held to the hull's
//! heading. The run's ground is made firm to match, stiction of 1e6 N/m
//! per point (a point reaches its limit within 0.14 mm of slide), and
//! the guides hold the tracks to 1 mm of play. With the `Twin`'s declared
//! 10 mm of play each track yaws up to 9 mrad within it in a turn and
//! crabs, which moves its instantaneous centre by `u α / ω` (0.1 m at
//! radius/gauge 5); with 1e5 N/m (1.4 mm to the limit) only 70 % of the
//! friction the loads allow is in use at radius/gauge 5, the rest
//! rebuilding as the load under each shoe rises under a wheel. Both are
//! compliances the theory leaves out. Even on the firm ground, at
//! radius/gauge 10 (belts 1.5 and 1.357 m/s) the run's torques fell 7 %
//! below the theory's with 1 mm of play and 9 % with 10 mm, 2–4 % of the
//! friction unused: not asserted here.

use std::collections::BTreeMap;

use trackgen::integrate::{Integrator, OdeSystem};
use trackgen::nalgebra::{Vector2, Vector3};
use trackgen::spatial_vehicle::{
    Differential, DifferentialSteer, Driveline, FullSteer, SideDrives,
};
use trackgen::steering::{SkidSteer, SteadyTurn, TrackLoad, steeds_resisting_moment};
use trackgen::terrain::field::HeightField;
use trackgen::vehicle::Drive;

use trackgen::multibody::RecursiveModel;
use trackgen::spatial::SpatialVehicle;
use trackgen::vehicle::Vehicle;

use crate::spatial_driveline::{brakes, in_neutral, neutral, steer_unit};
use crate::support::twin::{MU, System, TRACK, Twin, at_rest_apart, firm, layout_at, on_layout};

/// What a run shows over its last stretch, averaged over time.
#[derive(Debug)]
struct Observed {
    /// The hull's yaw rate, rad/s.
    yaw_rate: f64,
    /// The centre of mass's velocity in the hull's heading frame
    /// (forward, left), m/s.
    velocity: Vector2<f64>,
    /// The drives' torques (right, left), N m, planar sense.
    torque: [f64; 2],
    /// The belts' speeds (right, left), m/s: each sprocket's speed
    /// relative to the frame times its rolling radius, forward positive.
    belt: [f64; 2],
    /// Each side's normal load (right, left) along the hull, binned
    /// every [`BIN`] m: the bin's middle from the centre of mass, m, and
    /// its mean load, N.
    points: [Vec<(f64, f64)>; 2],
    /// Each side's load-weighted lateral place from the centre of mass,
    /// m (left positive).
    lateral: [f64; 2],
    /// The share of the friction the loads allow that the ground's shear
    /// uses (right, left): 1 where every point slides.
    used: [f64; 2],
    /// The vehicle's mass, kg.
    mass: f64,
}

/// The bins the loads are averaged in along the hull, m.
const BIN: f64 = 0.005;

/// The `Twin`'s sprocket's rolling radius, m: its declared teeth and its
/// track's pitch.
fn rolling_radius() -> f64 {
    let pitch = TRACK.description().pitch().expect("one pitch");
    trackgen::contact::sprocket::rolling_radius(Twin::geometry().sprocket.teeth, pitch)
}

/// Sums over time (each value at an accepted step's end times the
/// step's length) of what [`Observed`] averages.
#[derive(Default)]
struct Sums {
    time: f64,
    velocity: Vector2<f64>,
    torque: [f64; 2],
    belt: [f64; 2],
    bins: [BTreeMap<i64, f64>; 2],
    lateral: [f64; 2],
    shear: [f64; 2],
    limit: [f64; 2],
}

impl Sums {
    /// Adds the state `y` at time `t`, held for `dt` s.
    fn add(&mut self, system: &System, t: f64, y: &[f64], dt: f64) {
        let psi = system.states(y).0.pose.yaw;
        let forward = Vector3::new(psi.cos(), psi.sin(), 0.0);
        let left = Vector3::new(-psi.sin(), psi.cos(), 0.0);
        let centre = system.mass_centre(y);
        self.time += dt;
        self.velocity +=
            dt * Vector2::new(centre.velocity.dot(&forward), centre.velocity.dot(&left));
        let drive = system.drive_state(t, y).expect("the drives");
        for s in 0..2 {
            self.torque[s] += dt * drive.torque[s];
            self.belt[s] -= dt * drive.speed[s] * rolling_radius();
        }
        for point in system.ground_forces(y) {
            let s = point.side.index();
            let d = point.at - centre.position;
            let n = dt * point.force.z;
            *self.bins[s]
                .entry((d.dot(&forward) / BIN).round() as i64)
                .or_default() += n;
            self.lateral[s] += n * d.dot(&left);
            self.shear[s] += dt * point.force.xy().norm();
            self.limit[s] += MU * n;
        }
    }
}

/// A speed drive holding the belt at `speed` (m/s), reached over 1 s: a
/// PI controller critically damped on the vehicle's mass reflected to
/// the sprocket (`m r²`, about 100 kg m²) at 14 rad/s.
fn held(speed: f64) -> Drive {
    Drive::Speed {
        target: Box::new(move |t| speed * t.min(1.0)),
        proportional: 3000.0,
        integral: 2e4,
        max_torque: 5000.0,
    }
}

/// How a run is driven: its belts held at speeds (m/s, right and left),
/// or one drive through a differential steered at a constant input.
#[derive(Debug, Clone, Copy)]
enum Driven {
    Belts([f64; 2]),
    Differential {
        /// The belts' mean speed held, m/s (in neutral, none: the box is
        /// free).
        mean: f64,
        steer: DifferentialSteer,
        input: f64,
    },
}

/// The `Twin` on [`firm`] ground driven from rest as `driven` says for
/// `end` s, observed over its last `window` s (Dormand–Prince at rtol
/// 1e-5). Its differential's box takes twice a side's drive ([`held`]).
fn observe(driven: Driven, end: f64, window: f64) -> Observed {
    observe_apart(Twin::layout().gauge, driven, end, window)
}

/// [`observe`] with the `Twin`'s tracks `gauge` m apart
/// ([`layout_at`]).
fn observe_apart(gauge: f64, driven: Driven, end: f64, window: f64) -> Observed {
    let mut system: System = on_layout(
        HeightField::level(),
        firm(),
        SideDrives {
            right: held(0.0),
            left: held(0.0),
        },
        &layout_at(gauge),
    );
    system = match driven {
        Driven::Belts([right, left]) => system
            .with_drives(SideDrives {
                right: held(right),
                left: held(left),
            })
            .map_err(|e| e.to_string()),
        Driven::Differential { mean, steer, input } => system
            .with_driveline(Driveline::Differential(Differential {
                drive: if in_neutral(&steer) {
                    Drive::Free
                } else {
                    Drive::Speed {
                        target: Box::new(move |t| mean * t.min(1.0)),
                        proportional: 6000.0,
                        integral: 4e4,
                        max_torque: 10000.0,
                    }
                },
                steer,
                input: Box::new(move |t| input * t.min(1.0)),
                engine: None,
            }))
            .map_err(|e| e.to_string()),
    }
    .expect("a driveline in range");
    let start = at_rest_apart(gauge, 0.0, (0.0, 0.0));
    let mut y = system.state(&start.0, &start.1, &start.2);
    let method = Integrator::Dopri5 {
        rtol: 1e-5,
        atol: 1e-7,
        max_step: 2e-3,
    };
    let mut stepper = method.stepper(system.dimension());
    let mut t = 0.0;
    let from = end - window;
    while t < from {
        stepper
            .step(&mut system, &mut t, &mut y, from)
            .expect("the run");
    }
    let yaw = system.states(y.as_slice()).0.pose.yaw;
    let mut sums = Sums::default();
    while t < end {
        let before = t;
        stepper
            .step(&mut system, &mut t, &mut y, end)
            .expect("the run");
        sums.add(&system, t, y.as_slice(), t - before);
    }
    let mean = 1.0 / sums.time;
    let loads = sums.bins.each_ref().map(|bins| bins.values().sum::<f64>());
    Observed {
        yaw_rate: (system.states(y.as_slice()).0.pose.yaw - yaw) / window,
        velocity: sums.velocity * mean,
        torque: sums.torque.map(|v| v * mean),
        belt: sums.belt.map(|v| v * mean),
        points: sums.bins.map(|bins| {
            bins.into_iter()
                .map(|(bin, n)| (bin as f64 * BIN, n * mean))
                .collect()
        }),
        lateral: [0, 1].map(|s| sums.lateral[s] / loads[s]),
        used: [0, 1].map(|s| sums.shear[s] / sums.limit[s]),
        mass: system.mass_centre(y.as_slice()).mass,
    }
}

/// The theory's turn for what `seen` shows: its loads, its belts, the
/// rolling resistance `rolling`, all the running gear's (the rims' and
/// teeth's losses at the belt: the ground is rigid).
fn theory(seen: &Observed, rolling: f64) -> SteadyTurn {
    let vehicle = SkidSteer {
        mass: seen.mass,
        friction: MU,
        rolling_resistance: 0.0,
        belt_resistance: rolling,
        tracks: [
            TrackLoad::from_points(seen.lateral[1], &seen.points[1]),
            TrackLoad::from_points(seen.lateral[0], &seen.points[0]),
        ],
    };
    // A belt held still (by its brake, or a drive asked for 0) creeps
    // within its holder's elastic stage, by under a millimetre a second
    // on average: the theory, whose losses are Coulomb's and turn over at
    // the belt's standstill, takes it as standing.
    let belt = |u: f64| if u.abs() < 1e-3 { 0.0 } else { u };
    vehicle
        .drive([belt(seen.belt[1]), belt(seen.belt[0])])
        .expect("the theory's turn")
}

/// `run` within 5 % of `theory`, as the check asks.
fn within(what: &str, run: f64, theory: f64, seen: &Observed) {
    assert!(
        (run / theory - 1.0).abs() < 0.05,
        "{what}: the run's {run} against the theory's {theory} ({seen:?})"
    );
}

/// Driven at belt speeds from a pivot (±1 m/s) through radius/gauge
/// 1.3 and 2.6 to a gentle turn (outer 1.5 m/s, inner 1.227 m/s:
/// radius/gauge 6.4), the `Twin` settles within 5 % of the theory's yaw
/// rate, radius and both sprockets' torques (the tolerance the theory's
/// check is set at; the largest departure measured is 4.4 %, the inner
/// torque at radius/gauge 1.3; the theory's loads are the run's own; a
/// gentle turn taken 2 s further moved its averages by under 0.5 %).
/// The rolling resistance is the straight run's at 1.2 m/s: both
/// sprockets' force over the weight (2 %: the rims' and teeth's losses). Each turn's moment of turning resistance is printed beside
/// Steeds' `μ W L / 4`.
#[test]
fn steady_turns_match_the_skid_steering_theory() {
    let straight = observe(Driven::Belts([1.2, 1.2]), 3.0, 1.5);
    let weight = straight.mass * trackgen::ride::G;
    let rolling = -(straight.torque[0] + straight.torque[1]) / rolling_radius() / weight;
    assert!(
        (0.0..0.05).contains(&rolling),
        "rolling resistance {rolling}"
    );
    let turns = [[1.0, -1.0], [1.5, 0.5], [1.5, 0.9], [1.5, 1.227]];
    let seen: Vec<Observed> = std::thread::scope(|scope| {
        let runs: Vec<_> = turns
            .iter()
            .map(|&belts| scope.spawn(move || observe(Driven::Belts(belts), 5.0, 2.0)))
            .collect();
        runs.into_iter()
            .map(|run| run.join().expect("a run"))
            .collect()
    });
    for seen in &seen {
        agrees_with_the_theory(seen, rolling, weight, Twin::layout().gauge);
    }
}

/// The simplified theory's steerability criterion (Steeds; Wong, *Theory
/// of Ground Vehicles*, ch. 7): the outer track must give `f_r W/2 +
/// M_r/B` against the moment of turning resistance `M_r = μ_t W L/4` and
/// has `μ W/2` of grip, so a vehicle whose length over gauge passes
/// `2 (μ − f_r)/μ_t` cannot turn. That cut is the simplified theory's
/// own, whose runs slide only across: with friction the same in every
/// direction a run sliding along as well as across resists the turn
/// less, and the general theory turns smoothly through it
/// (`steering`'s `the_general_theory_turns_smoothly_through_the_simplified_criterion`).
/// The spatial model has its friction so, and turns as the general
/// theory does on both sides of the criterion: the `Twin` in a
/// clutch-brake turn (the left belt standing, the right at 1 m/s) with
/// its tracks set apart for `L/B` of 1.0, 10 % past the criterion
/// (`μ_t = μ`) and 50 % past it settles within 5 % of the general
/// theory's yaw rate, radius and torques for its loads, and 50 % past
/// the criterion still turns at over a fifth of its kinematic rate `u/B`
/// (the general theory's fraction there, on the guide's 2.6 m runs, is
/// 0.3–0.4).
#[test]
fn past_the_simplified_steerability_criterion_the_spatial_model_turns_as_the_general_theory() {
    let straight = observe(Driven::Belts([1.2, 1.2]), 3.0, 1.5);
    let weight = straight.mass * trackgen::ride::G;
    let rolling = -(straight.torque[0] + straight.torque[1]) / rolling_radius() / weight;
    let length = TrackLoad::from_points(0.0, &straight.points[0]).length();
    let criterion = 2.0 * (MU - rolling) / MU;
    let ratios = [1.0, 1.1 * criterion, 1.5 * criterion];
    let seen: Vec<Observed> = std::thread::scope(|scope| {
        let runs: Vec<_> = ratios
            .iter()
            .map(|&ratio| {
                scope.spawn(move || {
                    observe_apart(length / ratio, Driven::Belts([1.0, 0.0]), 5.0, 2.0)
                })
            })
            .collect();
        runs.into_iter()
            .map(|run| run.join().expect("a run"))
            .collect()
    });
    for (ratio, seen) in ratios.iter().zip(&seen) {
        let kinematic = 1.0 / (length / ratio);
        eprintln!(
            "L/B {ratio:.3} (criterion {criterion:.3}, L {length:.3} m): yaw rate {:.4} rad/s, \
             {:.3} of the kinematic",
            seen.yaw_rate,
            seen.yaw_rate / kinematic
        );
        agrees_with_the_theory(seen, rolling, weight, length / ratio);
    }
    let past = &seen[2];
    assert!(
        past.yaw_rate > 0.2 / (length / ratios[2]),
        "50 % past the criterion: yaw rate {} rad/s",
        past.yaw_rate
    );
}

/// `seen` within 5 % of the theory's turn for its own loads and belts at
/// the rolling resistance `rolling` (of the weight `weight`, N): the yaw
/// rate, the radius (on the scale of the run's `gauge`, m, where the
/// radius is smaller) and both sprockets' torques, as the check
/// asks; the moment of turning resistance printed beside Steeds'.
fn agrees_with_the_theory(seen: &Observed, rolling: f64, weight: f64, gauge: f64) {
    let r = rolling_radius();
    let turn = theory(seen, rolling);
    let expected = |side: &trackgen::steering::SideInTurn| -side.sprocket_force() * r;
    let radius = seen.velocity.norm() / seen.yaw_rate;
    let length = TrackLoad::from_points(0.0, &seen.points[0]).length();
    eprintln!(
        "belts {:.3?} m/s: yaw rate {:.4} rad/s (theory {:.4}), radius {:.3} m ({:.3}), \
         torques {:.0?} N m ({:.0}, {:.0}), friction used {:.3?}, \
         resisting moment {:.0} N m against Steeds' {:.0}",
        seen.belt,
        seen.yaw_rate,
        turn.yaw_rate,
        radius,
        turn.radius,
        seen.torque,
        expected(&turn.sides[1]),
        expected(&turn.sides[0]),
        seen.used,
        turn.resisting_moment,
        steeds_resisting_moment(MU, weight, length),
    );
    within("yaw rate", seen.yaw_rate, turn.yaw_rate, seen);
    // A pivot's radius is the centre of gravity's few centimetres
    // from the turn's centre: compared on the gauge's scale.
    let scale = turn.radius.max(gauge);
    assert!(
        (radius - turn.radius).abs() < 0.05 * scale,
        "radius: the run's {radius} m against the theory's {} m ({seen:?})",
        turn.radius
    );
    within(
        "right torque",
        seen.torque[0],
        expected(&turn.sides[1]),
        seen,
    );
    within(
        "left torque",
        seen.torque[1],
        expected(&turn.sides[0]),
        seen,
    );
}

/// Steered through a differential whose drive holds the belts' mean at
/// 1.2 m/s, by the left brake fully on (it holds: a clutch-brake turn,
/// the inner belt standing, the outer at 2.4 m/s) or by the steer unit at
/// full and half steer (minimum steer ratio 2.31), the `Twin` settles
/// within 5 % of the theory's turn for the belts it runs at (each
/// sprocket's torque the drive's half with the brake's or the unit's),
/// and the unit holds the belts' ratio at the one its input asks,
/// `(2 + s q)/(2 − s q)` with `q = 2 (ρ − 1)/(ρ + 1)`, within 1 % (its
/// integral takes out the steady error; the belts are averaged over 2 s).
/// In neutral, its box free, the unit at full steer pivots the `Twin`
/// with its sprockets held the full-steer difference apart (within 1 %),
/// as the theory's pivot for those belts. Nothing holds the belts' mean:
/// it settles where the two tracks' resistances balance (measured 1.225
/// and −1.175 m/s), and the radius's check holds the turn's centre
/// within 5 % of the gauge of the theory's.
#[test]
fn steady_turns_through_a_differential_match_the_skid_steering_theory() {
    let full = 2.4 / rolling_radius();
    let runs = [
        Driven::Belts([1.2, 1.2]),
        Driven::Differential {
            mean: 1.2,
            steer: brakes(),
            input: 1.0,
        },
        Driven::Differential {
            mean: 1.2,
            steer: steer_unit(2.31),
            input: 1.0,
        },
        Driven::Differential {
            mean: 1.2,
            steer: steer_unit(2.31),
            input: 0.5,
        },
        Driven::Differential {
            mean: 0.0,
            steer: neutral(full),
            input: 1.0,
        },
    ];
    let seen: Vec<Observed> = std::thread::scope(|scope| {
        let runs: Vec<_> = runs
            .iter()
            .enumerate()
            .map(|(k, &driven)| {
                let end = if k == 0 { 3.0 } else { 5.0 };
                scope.spawn(move || observe(driven, end, 2.0_f64.min(end / 2.0)))
            })
            .collect();
        runs.into_iter()
            .map(|run| run.join().expect("a run"))
            .collect()
    });
    let straight = &seen[0];
    let weight = straight.mass * trackgen::ride::G;
    let rolling = -(straight.torque[0] + straight.torque[1]) / rolling_radius() / weight;
    for (seen, driven) in seen.iter().zip(runs).skip(1) {
        agrees_with_the_theory(seen, rolling, weight, Twin::layout().gauge);
        let Driven::Differential {
            steer: DifferentialSteer::Unit(unit),
            input,
            ..
        } = driven
        else {
            continue;
        };
        match unit.full_steer {
            FullSteer::Ratio(rho) => {
                let q = input * 2.0 * (rho - 1.0) / (rho + 1.0);
                let asked = (2.0 + q) / (2.0 - q);
                let ratio = seen.belt[0] / seen.belt[1];
                assert!(
                    (ratio / asked - 1.0).abs() < 0.01,
                    "the belts' ratio {ratio} against the {asked} asked"
                );
            }
            FullSteer::Neutral(full) => {
                let apart = (seen.belt[0] - seen.belt[1]) / rolling_radius();
                let asked = input * full;
                assert!(
                    (apart / asked - 1.0).abs() < 0.01,
                    "the sprockets {apart} rad/s apart against the {asked} asked"
                );
            }
            FullSteer::Engine(_) => unreachable!("these runs drive no engine"),
        }
    }
}
