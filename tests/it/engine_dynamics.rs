//! The engine's speed as a state (`vehicle::EngineDynamics`,
//! `Driveline::engine_state`), held to closed forms written here from the
//! declared tables: the acceleration at full fuel, the governor's law, the
//! converter's torques through the coupling and in overrun, the lock-up
//! clutch, and the spin-up from idle against the stall, whose time is a
//! quadrature of the engine's equation.

use crate::support::vehicle::{m113_through, m113a3_driveline, step_course};
use crate::support::{converter_torques, table_at};
use trackgen::vehicle::{
    COUPLING_BAND, Driveline, EngineDynamics, LOCKUP_RELEASE, PowertrainError,
};

/// The M113A3's driveline as declared, with its engine's dynamics.
fn m113a3() -> (Driveline, EngineDynamics) {
    let driveline = m113a3_driveline();
    let dynamics = driveline
        .dynamics
        .clone()
        .expect("the M113A3 declares its engine's inertia");
    (driveline, dynamics)
}

/// The converter's turbine torque by the module's rule, from the tables
/// (`support::converter_torques`).
fn turbine_torque(d: &Driveline, we: f64, wt: f64) -> f64 {
    converter_torques(d, we, wt).1
}

/// The full-load torque of the running engine (the map, its first
/// point's torque held below it).
fn full_load(d: &Driveline, we: f64) -> f64 {
    if we < d.engine[0].0 {
        d.engine[0].1
    } else {
        table_at(&d.engine, we).max(0.0)
    }
}

#[test]
fn at_full_fuel_the_engine_accelerates_by_its_torque_over_the_pump_s() {
    let (d, dynamics) = m113a3();
    let k0 = table_at(&d.capacity, 0.0);
    // The turbine held (SR = 0), far more asked than the stall gives: full
    // fuel at every engine speed up to the stall match.
    let asked = 1e5;
    for we in [40.0, 60.0, 100.0, 150.0, 200.0, 230.0] {
        let state = d.engine_state(false, we, 0.0, 0.0, asked).unwrap();
        let want = (full_load(&d, we) - (we / k0).powi(2)) / dynamics.inertia;
        assert_eq!(state.fuel, 1.0, "at {we} rad/s");
        assert!(
            (state.rate - want).abs() <= 1e-12 * want.abs().max(1.0),
            "at {we} rad/s: {} rad/s² against {want}",
            state.rate
        );
        let tr0 = table_at(&d.torque_ratio, 0.0);
        assert!((state.turbine_torque - tr0 * (we / k0).powi(2)).abs() <= 1e-9);
    }
}

#[test]
fn at_part_load_the_governor_brings_the_engine_to_the_speed_that_gives_the_torque() {
    let (d, dynamics) = m113a3();
    let mut checked = 0;
    for wt in [0.0, 30.0, 80.0, 150.0] {
        let Some(full) = d.operating_point(0, wt) else {
            continue;
        };
        for fraction in [0.1, 0.4, 0.8] {
            let asked = fraction * full.turbine_torque;
            // Find ω* independently: bisection of the tables' rule.
            let (mut lo, mut hi) = (wt.max(1e-9), full.engine_speed * 1.2);
            for _ in 0..200 {
                let mid = 0.5 * (lo + hi);
                if turbine_torque(&d, mid, wt) < asked {
                    lo = mid
                } else {
                    hi = mid
                }
            }
            let target = (0.5 * (lo + hi)).max(d.engine[0].0);
            if wt / target > 1.0 - COUPLING_BAND {
                continue;
            }
            // Near the target the fuel is between none and full: the engine
            // approaches it at the governor's rate.
            let we = target * 0.99;
            let state = d.engine_state(false, we, wt, 0.0, asked).unwrap();
            assert!(state.fuel > 0.0 && state.fuel < 1.0, "fuel {}", state.fuel);
            let want = (target - we) / dynamics.governor_time;
            assert!(
                (state.rate - want).abs() <= 1e-8 * want.abs(),
                "wt {wt}, {fraction} of full load: {} rad/s² against {want}",
                state.rate
            );
            // And at the target, it holds: no acceleration.
            let at = d.engine_state(false, target, wt, 0.0, asked).unwrap();
            assert!(at.rate.abs() <= 1e-6, "{} rad/s² at the target", at.rate);
            assert!((at.turbine_torque - asked).abs() <= 1e-9 * asked);
            checked += 1;
        }
    }
    assert!(checked >= 8, "{checked} points");
}

#[test]
fn the_converter_s_torque_is_continuous_through_the_coupling_and_turns_in_overrun() {
    let (d, _) = m113a3();
    let we = 200.0;
    // Range 1 does not lock: the converter alone.
    let at = |sr: f64| {
        d.engine_state(false, we, sr * we, 0.0, 0.0)
            .unwrap()
            .turbine_torque
    };
    let eps = 1e-9;
    assert!(at(1.0 - eps).abs() < 1e-3 && at(1.0 + eps).abs() < 1e-3);
    assert!(at(1.0 - eps) > 0.0 && at(1.0 + eps) < 0.0);
    // Below the band, the tables' own torque.
    let sr = 0.9;
    assert!((at(sr) - turbine_torque(&d, we, sr * we)).abs() <= 1e-9 * at(sr));
    // In overrun the turbine drives the pump: mirrored about SR = 1 with
    // no torque ratio.
    for sr in [1.005, 1.05, 1.3] {
        let mirror = 2.0 - sr;
        let k = table_at(&d.capacity, mirror);
        let taper = ((1.0 - mirror) / COUPLING_BAND).min(1.0);
        let want = -(we / k) * (we / k) * taper;
        assert!(
            (at(sr) - want).abs() <= 1e-9 * want.abs(),
            "SR {sr}: {} against {want}",
            at(sr)
        );
    }
}

#[test]
fn the_lock_up_clutch_engages_where_the_range_locks_and_carries_its_capacity_at_most() {
    let (d, dynamics) = m113a3();
    // The turbine speed from which range 2's full-load match reaches the
    // clutch's speed ratio.
    let locks_from = {
        let (mut lo, mut hi) = (1.0, 400.0);
        for _ in 0..100 {
            let mid = 0.5 * (lo + hi);
            if d.locks(mid) { hi = mid } else { lo = mid }
        }
        hi
    };
    let wt = locks_from * 1.1;
    let sr = d.lockup_speed_ratio;
    // Engaging: a range that locks, past that speed, at the clutch's speed
    // ratio or above, not shifting; range 1 never locks.
    assert!(d.lockup_next(1, false, wt / sr, wt, false));
    assert!(
        !d.lockup_next(1, false, wt / (sr - 0.02), wt, false),
        "below the clutch's speed ratio"
    );
    assert!(
        !d.lockup_next(1, false, wt, locks_from * 0.99, false),
        "below its speed"
    );
    assert!(!d.lockup_next(1, false, wt / sr, wt, true), "shifting");
    assert!(
        !d.lockup_next(0, false, wt / sr, wt, false),
        "range 1 does not lock"
    );
    // Engaged, it holds until the turbine has slowed by the hysteresis,
    // and releases to shift.
    let slowed = locks_from * (1.0 - LOCKUP_RELEASE);
    assert!(d.lockup_next(1, true, 1.001 * slowed, 1.001 * slowed, false));
    assert!(!d.lockup_next(1, true, 0.999 * slowed, 0.999 * slowed, false));
    assert!(!d.lockup_next(1, true, wt, wt, true));
    let (k, c, cap) = (
        dynamics.lockup_stiffness,
        dynamics.lockup_damping,
        dynamics.lockup_capacity,
    );
    // With a slip whose damping alone is twice its capacity the clutch
    // slips at its capacity, the twist growing as the damper lets it:
    // `ż = (T_cap − k z)/c`.
    let (we, z) = (wt + 2.0 * cap / c, 0.01);
    let engaging = d.engine_state(true, we, wt, z, 100.0).unwrap();
    assert!(engaging.locked);
    assert!((engaging.turbine_torque - cap).abs() <= 1e-9 * cap);
    assert!((engaging.twist_rate - (cap - k * z) / c).abs() <= 1e-9 * engaging.twist_rate.abs());
    // Within its capacity it holds: the twist carries `k z + c ż` and
    // grows by the slip.
    let (we, z) = (wt + 0.2, 0.5 * cap / k);
    let held = d.engine_state(true, we, wt, z, 100.0).unwrap();
    let want = k * z + c * 0.2;
    assert!(want < cap);
    assert!((held.turbine_torque - want).abs() <= 1e-9 * want);
    assert!((held.twist_rate - 0.2).abs() <= 1e-12);
    assert!((held.twist_energy - 0.5 * k * z * z).abs() <= 1e-9 * held.twist_energy);
    // Released, the converter drives and the twist relaxes through the
    // damper, carrying nothing to the turbine.
    let open = d.engine_state(false, wt / 0.85, wt, z, 100.0).unwrap();
    assert!(!open.locked);
    assert!((open.twist_rate + k * z / c).abs() <= 1e-9 * open.twist_rate.abs());
    assert!(
        (open.turbine_torque - turbine_torque(&d, wt / 0.85, wt)).abs()
            <= 1e-9 * open.turbine_torque
    );
}

/// From idle against a held turbine at full fuel the engine's speed
/// follows `J ω̇ = T_e(ω) − (ω / K(0))²`: the time to reach a speed is
/// the quadrature `∫ J dω / (T_e − (ω/K₀)²)`, here by Simpson's rule on
/// 20 000 intervals; the law, stepped by RK4 at 10 µs, reaches 95 % of
/// the stall speed within 1e-5 of it.
#[test]
fn from_idle_the_engine_spins_up_against_the_stall_as_its_quadrature_says() {
    let (d, dynamics) = m113a3();
    let k0 = table_at(&d.capacity, 0.0);
    let net = |w: f64| full_load(&d, w) - (w / k0).powi(2);
    // The stall match, by bisection.
    let (mut lo, mut hi) = (d.engine[0].0, 400.0);
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if net(mid) > 0.0 { lo = mid } else { hi = mid }
    }
    let stall = 0.5 * (lo + hi);
    let (from, to) = (d.engine[0].0, 0.95 * stall);
    let n = 20_000;
    let h = (to - from) / n as f64;
    let f = |w: f64| dynamics.inertia / net(w);
    let simpson: f64 = (0..=n)
        .map(|i| {
            let w = from + i as f64 * h;
            let weight = if i == 0 || i == n {
                1.0
            } else if i % 2 == 1 {
                4.0
            } else {
                2.0
            };
            weight * f(w)
        })
        .sum::<f64>()
        * h
        / 3.0;
    let rate = |w: f64| d.engine_state(false, w, 0.0, 0.0, 1e5).unwrap().rate;
    let dt = 1e-5;
    let (mut t, mut w) = (0.0, from);
    while w < to {
        let k1 = rate(w);
        let k2 = rate(w + 0.5 * dt * k1);
        let k3 = rate(w + 0.5 * dt * k2);
        let k4 = rate(w + dt * k3);
        let next = w + dt / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
        if next >= to {
            t += dt * (to - w) / (next - w);
            break;
        }
        (t, w) = (t + dt, next);
    }
    println!(
        "idle to {to:.1} rad/s (95 % of the stall's {stall:.1}): {t:.5} s, quadrature {simpson:.5} s"
    );
    assert!(
        (t - simpson).abs() <= 1e-5 * simpson,
        "{t} s against {simpson} s"
    );
}

#[test]
fn bad_engine_dynamics_are_refused() {
    let (d, _) = m113a3();
    let refused = |change: &dyn Fn(&mut EngineDynamics)| {
        let mut bad = d.clone();
        change(bad.dynamics.as_mut().unwrap());
        bad.check()
    };
    assert!(matches!(
        refused(&|e| e.inertia = 0.0),
        Err(PowertrainError::Limit {
            what: "engine_inertia",
            ..
        })
    ));
    assert!(matches!(
        refused(&|e| e.governor_time = f64::NAN),
        Err(PowertrainError::Limit {
            what: "governor_time",
            ..
        })
    ));
    assert!(matches!(
        refused(&|e| e.lockup_stiffness = -1.0),
        Err(PowertrainError::Limit {
            what: "lockup_stiffness",
            ..
        })
    ));
    assert!(matches!(
        refused(&|e| e.lockup_damping = 0.0),
        Err(PowertrainError::Limit {
            what: "lockup_damping",
            ..
        })
    ));
    assert!(matches!(
        refused(&|e| e.drag[2].1 = 5.0),
        Err(PowertrainError::Table {
            what: "engine's drag",
            point: 2
        })
    ));
    assert!(matches!(
        refused(&|e| e.drag[1].0 = 0.0),
        Err(PowertrainError::Table {
            what: "engine's drag",
            point: 1
        })
    ));
}

/// Full throttle from rest after 0.5 s.
fn full_throttle(t: f64) -> f64 {
    if t < 0.5 { 0.0 } else { 15.0 }
}

/// In the limit of no inertia and an instant governor the engine runs
/// where the converter's steady match puts it: the M113A3 with an engine
/// of a hundredth of a kilogram metre squared and a governor of 2 ms,
/// driven toward 3 m/s (the first range, neither shifting nor locking up:
/// those follow rules of their own, each checked apart) and over the
/// 0.3 m step at full throttle, goes as the quasi-static converter does:
/// its distance after 12 s within 0.5 % and the sprocket's work within
/// 1 %. (The engine at idle creeps the vehicle in the first 0.5 s, where
/// the quasi-static one gives nothing: the speed controller holds it
/// there, a few millimetres.)
#[test]
fn with_no_inertia_the_engine_runs_where_the_steady_match_puts_it() {
    let declared = m113a3_driveline();
    let quasi_static = Driveline {
        dynamics: None,
        ..declared.clone()
    };
    let inertia = 0.01;
    let stiffness = inertia * (2.0 * std::f64::consts::PI * 100.0).powi(2);
    let light = Driveline {
        dynamics: Some(EngineDynamics {
            inertia,
            governor_time: 0.002,
            lockup_stiffness: stiffness,
            lockup_damping: EngineDynamics::lockup_damping_for(inertia, stiffness),
            ..declared.dynamics.clone().unwrap()
        }),
        ..declared
    };
    let target = |t: f64| if t < 0.5 { 0.0 } else { 3.0 };
    let run = |d: &Driveline| m113_through(d, step_course(0.3), target, 12.0, 0.01);
    let (a, b) = (run(&quasi_static), run(&light));
    let last = |r: &trackgen::simulate::Results, c: &str| *r.column(c).unwrap().last().unwrap();
    let first = |r: &trackgen::simulate::Results, c: &str| r.column(c).unwrap()[0];
    let gears = |r: &trackgen::simulate::Results| {
        r.column("gear")
            .unwrap()
            .iter()
            .fold(0.0f64, |m, &g| m.max(g))
    };
    assert_eq!(
        (gears(&a), gears(&b)),
        (1.0, 1.0),
        "the first range throughout"
    );
    let (xa, xb) = (
        last(&a, "x") - first(&a, "x"),
        last(&b, "x") - first(&b, "x"),
    );
    let (wa, wb) = (last(&a, "motor_work"), last(&b, "motor_work"));
    println!(
        "quasi-static: {xa:.3} m, {wa:.0} J at the sprocket; an engine of 0.01 kg m²: {xb:.3} m ({:+.2e}), {wb:.0} J ({:+.2e})",
        xb / xa - 1.0,
        wb / wa - 1.0
    );
    assert!(xa > 28.0, "over the step: {xa} m");
    assert!((xb - xa).abs() <= 5e-3 * xa, "{xb} m against {xa} m");
    assert!((wb - wa).abs() <= 1e-2 * wa, "{wb} J against {wa} J");
}

/// The engine's books over the 12 s full-throttle climb of the 0.3 m
/// step through the M113A3 as declared (its engine's speed and the locked
/// driveline's twist states): the engine's work (the recorded quadrature)
/// against the change of its rotating energy, `share · ½ J ω_e²`, plus
/// what its shaft gave the converter, summed here row by row: unlocked,
/// the pump's power from the declared tables at the recorded engine speed
/// and speed ratio, `share · (ω_e / K(SR))² ω_e` (with the coupling band);
/// locked, the clutch's, the turbine's recorded power times `ω_e / ω_t`
/// (the clutch carries the same torque on both sides), `ω_t` the range's
/// reduction times the sprocket's speed. Within 1e-3 of the work at
/// Bogacki-Shampine 1e-4, rows every millisecond (trapezoids).
#[test]
fn the_engine_s_books_close_with_its_rotating_energy_and_the_converter_s_power() {
    let d = m113a3_driveline();
    let dynamics = d.dynamics.clone().unwrap();
    let results = m113_through(&d, step_course(0.3), full_throttle, 12.0, 0.001);
    let column = |name: &str| results.column(name).expect(name);
    let t = results.times().to_vec();
    let (we, sr, locked, gear) = (
        column("engine_speed"),
        column("speed_ratio"),
        column("locked"),
        column("gear"),
    );
    let (turbine, omega, work) = (
        column("turbine_power"),
        column("sprocket_speed"),
        column("engine_work"),
    );
    let share = d.share;
    let shaft = |i: usize| {
        if locked[i] == 1.0 {
            let wt = d.reduction(gear[i] as usize - 1) * omega[i].abs();
            turbine[i] * we[i] / wt
        } else {
            // Overrun (SR > 1): the maps read at 2 − SR, the torque turned.
            let (s, sign) = if sr[i] > 1.0 {
                (2.0 - sr[i], -1.0)
            } else {
                (sr[i], 1.0)
            };
            let s = s.max(0.0);
            let k = table_at(&d.capacity, s);
            let taper = ((1.0 - s) / COUPLING_BAND).min(1.0);
            sign * share * (we[i] / k).powi(2) * taper * we[i]
        }
    };
    let given: f64 = (1..t.len())
        .map(|i| 0.5 * (shaft(i) + shaft(i - 1)) * (t[i] - t[i - 1]))
        .sum();
    let last = t.len() - 1;
    let rotating = share * 0.5 * dynamics.inertia * (we[last].powi(2) - we[0].powi(2));
    let done = work[last] - work[0];
    let books = rotating + given;
    let locked_rows = locked.iter().filter(|&&l| l == 1.0).count();
    println!(
        "the engine's work {done:.1} J against its rotating energy {rotating:.1} J and the converter's \
         {given:.1} J: {:+.2e} ({locked_rows} of {} rows locked)",
        books / done - 1.0,
        t.len()
    );
    assert!(locked_rows > 100, "the climb locks up: {locked_rows} rows");
    assert!(
        (books - done).abs() <= 1e-3 * done,
        "{books} J against {done} J"
    );
}
