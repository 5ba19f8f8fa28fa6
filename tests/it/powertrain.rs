//! The powertrain: what an engine gives at the sprocket, and the speed it
//! holds up a grade.
//!
//! * The M113's envelope against Chrono's figures: at rest its lowest
//!   gear gives the map's 450 lb·ft through 0.240 × 0.5, times the
//!   driveline's fraction (to 1e-12 relative: the same products in another
//!   order); 395 lb·ft at 2800 rpm is 157 kW
//!   (Chrono's `M113_EngineSimpleMap.cpp`), and the most power, the fraction of
//!   the map's largest `T ω` (past 2800 rpm: 162 kW at 3000), is a scan's
//!   to 1e-9.
//! * Below the speed of its map's peak torque the clutch slips: the
//!   Marder gets its 2702 N m through the lowest gear from rest.
//! * Every envelope's slope against a central difference of the envelope
//!   itself (step 1e-6 rad/s, away from the kinks between gears and map
//!   points), to 1e-6 relative plus the quotient's rounding: on a linear
//!   piece the difference has no truncation error, and `P/ω`'s is
//!   `P h² / ω⁴`, below 1e-12 here.
//! * Up 10, 20 and 30 % grades at full power `P` the M113 settles at the
//!   speed (along the slope: the record's `speed` times `√(1 + g²)`) at
//!   which, on flat ground, the drive holding the same track speed against
//!   a drawbar pull equal to the grade's weight component `m g sin θ`, the
//!   sprocket takes the same power: the pulled run's power `P_D` at its
//!   speed `v_D` gives `v = v_D P / P_D` (at fixed forces the power is
//!   linear in speed), within 2 %. The pull loads the track nearly as the
//!   grade does, so the spans' tensions, the shoes' slip and the running
//!   gear's losses are nearly the grade's. Not quite: on the grade the
//!   weight component of the track and the wheels acts on them (on 10 %,
//!   1 126 N of the 6 022 N is the track's own), not at the hull's
//!   centroid, and the flat's ground carries `m g` where the grade's
//!   carries `cos θ` of it. Measured at the M113A3's weight, the grade
//!   costs more than the pulled flat, never less: −0.10, +0.31 and
//!   −1.70 % on 20, 30 and 10 %; on 10 % at 13 to 17 kW −0.8, −1.7, −1.7,
//!   −0.2 and −1.2 %. Runs of 24 s instead of 16 do not narrow it (on 10 %
//!   at 13 to 17 kW −0.85, −1.64, −0.59, −0.24 and −1.53 %; 20 and 30 %
//!   within 0.65 %): the 2 % bound is that spread, the premise's, not the
//!   power's account. The pulled runs match
//!   the grade's speed along it to 1e-3 and slip under 0.25 % (the grade
//!   runs' `1 − v_x / v_track`, 0.4, 2.0 and 4.4 %, is almost all the
//!   hull's horizontal projection `1 − cos θ`). An unloaded flat run's
//!   resistance `f` is not that route: it follows the shoe passage's place
//!   on the spans' modes (0.010 at 0.8 m/s, 0.023 at 1.17–1.35 m/s, 0.018
//!   at 2.2), which move with the spans' tensions, so `(1 − i) P / (m g
//!   (sin θ + f cos θ))` with it missed by +5.2 % at 20 %, where the run
//!   sat on that peak.
//! * Up 10, 20 and 30 % at full throttle through the M113A3's converter
//!   it settles where the envelope, averaged over the sprocket's ripple,
//!   meets the torque the grade asks at that speed (measured apart, the
//!   speed controller alone holding it): within 3 %; measured +0.60,
//!   −1.01 and −0.32 % on 10, 20 and 30 % through the quasi-static
//!   converter, −2.35, −1.08 and −0.43 % through the declared engine in
//!   the range its gearbox held.

use crate::support;

use support::converter_torques;
use support::table_at;
use support::vehicle::{m113_run, m113_weight, m113a3_driveline, m113a3_quasi_static, window};
use trackgen::terrain::Terrain;
use trackgen::vehicle::{Powertrain, Vehicle};
use trackgen::vehicles::m113::{self, M113};

#[test]
fn chrono_s_m113_envelope_is_its_engine_through_its_gears() {
    let powertrain = m113::chrono_simple_map();
    let fraction = m113::DRIVELINE_EFFICIENCY * 0.5;
    let lb_ft = 1.355_817_948_331_400_4;
    let (at_rest, slope) = powertrain.limit(0.0);
    let want = fraction * 450.0 * lb_ft / (0.240 * 0.5);
    assert!(
        (at_rest - want).abs() <= 1e-12 * want,
        "{at_rest} vs {want}"
    );
    assert_eq!(slope, 0.0, "flat below the speed of the map's peak");
    // 395 lb·ft at 2800 rpm is 157 kW.
    let rpm = std::f64::consts::PI / 30.0;
    let at_2800 = 395.0 * lb_ft * 2800.0 * rpm;
    assert!((at_2800 - 157e3).abs() < 0.5e3, "{at_2800} W");
    // The most power, against a scan of T ω over the map (every 0.01 rpm:
    // T ω is a quadratic on each piece, so the scan's miss is below
    // 1e-9 of it).
    let map = [
        (500.0, 450.0),
        (1000.0, 450.0),
        (1500.0, 445.0),
        (2000.0, 435.0),
        (2500.0, 410.0),
        (2800.0, 395.0),
        (3000.0, 380.0),
        (3200.0, -100.0),
    ];
    let scanned = map
        .windows(2)
        .flat_map(|w| {
            let ((n0, t0), (n1, t1)) = (w[0], w[1]);
            (0..=((n1 - n0) * 100.0) as usize).map(move |k| {
                let n = n0 + k as f64 * 0.01;
                (t0 + (t1 - t0) * (n - n0) / (n1 - n0)) * lb_ft * n * rpm
            })
        })
        .fold(0.0, f64::max);
    let peak = powertrain.max_power();
    assert!(
        (peak - fraction * scanned).abs() <= 1e-9 * peak,
        "{peak} vs {}",
        fraction * scanned
    );
    assert!(scanned > at_2800, "past 2800 rpm the power still rises");
    // Beyond the top gear's cut-off nothing drives.
    let top = 3200.0 * std::f64::consts::PI / 30.0 * 0.962 * 0.5;
    assert_eq!(powertrain.limit(top * 1.01), (0.0, 0.0));
}

/// The Marder's map peaks at 2702 N m at 1499 rpm, above its first point
/// (700 N m at 702 rpm): from rest until the lowest gear's engine speed
/// reaches 1499 rpm the clutch slips and the sprocket gets the peak
/// through 0.1708 (to 1e-12: the same products), not the first point's
/// 700 N m.
#[test]
fn below_its_peak_torque_speed_the_clutch_slips_at_the_peak() {
    let powertrain = trackgen::vehicles::marder::chrono_simple_map();
    let fraction = trackgen::vehicles::marder::DRIVELINE_EFFICIENCY * 0.5;
    let want = fraction * 2702.0 / 0.1708;
    let rpm = std::f64::consts::PI / 30.0;
    for engine_rpm in [0.0, 300.0, 702.0, 1000.0, 1498.0] {
        let (torque, slope) = powertrain.limit(engine_rpm * rpm * 0.1708);
        assert!(
            (torque - want).abs() <= 1e-12 * want,
            "{engine_rpm} rpm in the lowest gear: {torque} vs {want}"
        );
        assert_eq!(slope, 0.0);
    }
    // Past the peak the map's own torque, falling.
    let (past, slope) = powertrain.limit(2004.0 * rpm * 0.1708);
    assert!(past < want && slope < 0.0, "{past}, {slope}");
}

#[test]
fn every_envelope_s_slope_is_its_difference() {
    let envelopes = [
        m113::powertrain(),
        m113::chrono_simple_map(),
        trackgen::vehicles::marder::chrono_simple_map(),
        Powertrain::Power {
            power: 5e4,
            max_torque: 8e3,
        },
    ];
    for powertrain in &envelopes {
        let mut checked = 0;
        for k in 1..400 {
            let speed = k as f64 * 0.5;
            let (value, slope) = powertrain.limit(speed);
            let h = 1e-6;
            let (above, _) = powertrain.limit(speed + h);
            let (below, _) = powertrain.limit(speed - h);
            let difference = (above - below) / (2.0 * h);
            // Kinks (a gear change, a map point) make the two sides differ.
            let one_sided = ((above - value) / h - (value - below) / h).abs();
            if one_sided > 1e-3 * (1.0 + slope.abs()) || value == 0.0 {
                continue;
            }
            checked += 1;
            assert!(
                // The quotient's rounding is ε value / h ≈ 1e-10 value.
                (difference - slope).abs() <= 1e-6 * (1.0 + slope.abs()) + 1e-9 * value,
                "{powertrain:?} at {speed} rad/s: slope {slope}, difference {difference}"
            );
        }
        assert!(checked > 100, "{checked} speeds checked");
    }
}

/// The M113 driven for `duration` s on `terrain` by a speed drive aiming at
/// `target` m/s, under `powertrain`: the mean speed, the mean sprocket
/// power and the track's slip `1 − v / v_track` over the last whole number
/// of shoe passages (`pitch / v_track` each) that fits in 4 s. The power
/// ripples as each shoe engages; a window of whole periods averages the
/// ripple out, where a fixed 2 s window left f uncertain by ±10 %. Last,
/// the sprocket's speeds over that window (rad/s, its sign as recorded)
/// and the range the gearbox held through it (0-based; `None` if it
/// shifted in it or has no ranges). `drawbar_pull` (N) pulls the hull
/// back throughout.
fn steady(
    terrain: Terrain,
    target: f64,
    powertrain: Option<Powertrain>,
    duration: f64,
    drawbar_pull: f64,
) -> (f64, f64, f64, Vec<f64>, Option<usize>) {
    let results = m113_run(
        powertrain,
        terrain,
        move |t| target * (t / 1.0).min(1.0),
        duration,
        0.001,
        drawbar_pull,
    );
    let mean = |v: Vec<f64>| v.iter().sum::<f64>() / v.len() as f64;
    let track_speed = mean(window(&results, "track_speed", duration - 4.0, duration));
    let period = m113::SHOE_PITCH / track_speed;
    let span = (4.0 / period).floor() * period;
    let last = |c| window(&results, c, duration - span, duration);
    let speed = mean(last("speed"));
    let slip = 1.0 - speed / mean(last("track_speed"));
    let power = mean(
        last("sprocket_torque")
            .into_iter()
            .zip(last("sprocket_speed"))
            .map(|(t, w)| t * w)
            .collect(),
    );
    let gears = last("gear");
    let held =
        (gears.iter().all(|&g| g == gears[0]) && gears[0] >= 1.0).then(|| gears[0] as usize - 1);
    (speed, power, slip, last("sprocket_speed"), held)
}

#[test]
fn up_a_grade_at_full_power_it_holds_the_speed_its_power_buys() {
    // A power that keeps the speeds a few m/s (short runs): a fifth of the
    // M113's own at one sprocket.
    let power = 15e3;
    let powertrain = Powertrain::Power {
        power,
        max_torque: 8e3,
    };
    let weight = m113_weight();
    for grade in [0.2, 0.3, 0.1] {
        // Assembled on the flat, the grade starting just ahead of the
        // track (which spans about ±2.4 m); the whole track is on it after
        // some 5 m, within the first 8 s at the slowest speed (about
        // 0.9 m/s on 30 %).
        let ramp = Terrain::Ramp {
            height: 0.0,
            start: 2.6,
            slope: grade,
        };
        let (speed, sprocket_power, slip, _, _) =
            steady(ramp, 20.0, Some(powertrain.clone()), 16.0, 0.0);
        assert!(
            (sprocket_power - power).abs() < 0.02 * power,
            "{grade}: at full power the sprocket takes {sprocket_power} W of {power}"
        );
        // Along the slope (the record's `speed` is the hull's along x).
        let along = speed * (1.0 + grade * grade).sqrt();
        // The drive holds the track's speed, the grade run's.
        let pull = weight * grade.atan().sin();
        let (pulled_speed, pulled_power, pulled_slip, _, _) = steady(
            Terrain::Flat { height: 0.0 },
            speed / (1.0 - slip),
            None,
            8.0,
            pull,
        );
        assert!(
            (pulled_speed - along).abs() < 0.01 * along,
            "{pulled_speed} m/s pulled against {along} m/s up the grade"
        );
        let want = pulled_speed * sprocket_power / pulled_power;
        println!(
            "{} % grade at {power} W: {along:.4} m/s along it against {want:.4} m/s ({:+.2} %; \
             pulled by {pull:.0} N on the flat: {pulled_power:.0} W at {pulled_speed:.4} m/s, \
             slip {pulled_slip:.4})",
            grade * 100.0,
            100.0 * (along / want - 1.0)
        );
        assert!(
            (along - want).abs() < 0.02 * want,
            "{} % grade: {along} m/s along it, v_D P / P_D = {want} m/s",
            grade * 100.0
        );
    }
}

/// The cap through rest: the M113's speed controller asking for 1 m/s
/// forward (the sprocket turning as `−v/r`) with its integral wound up, so
/// that it wants more than the engine gives. Turning forward the torque is
/// the envelope's at that speed; at rest and while the sprocket is forced
/// back (ω > 0, a vehicle rolling back) it is the stall torque, the
/// envelope's at rest, on both sides of ω = 0 to rounding; and the
/// torque's slope is its central difference (step 1e-7 rad/s; the
/// envelope's pieces are linear in ω or `P/ω`, so to 1e-6 relative plus
/// the quotient's rounding, `4 ε τ / h`). A torque against the asked direction (the
/// sprocket turning forward faster than asked, the integral run down)
/// brakes, uncapped by the engine.
#[test]
fn the_cap_holds_the_stall_torque_through_rest() {
    use trackgen::vehicle::TorqueCap;
    let powertrain = m113::powertrain();
    let cap = |omega: f64| {
        let (value, slope) = powertrain.limit(omega.abs());
        TorqueCap {
            value,
            slope,
            stall: powertrain.limit(0.0).0,
        }
    };
    let drive = M113::speed_drive(|_| 1.0);
    let radius = 0.25;
    let integral = -1e3; // wound up forward: the controller wants −1e3 I.
    let torque = |omega: f64| {
        drive
            .checked_torque(0.0, omega, radius, integral, cap(omega))
            .unwrap()
            .0
    };
    let stall = powertrain.limit(0.0).0;
    for omega in [1e-12, 1e-3, 0.5, 3.0] {
        assert!(
            (torque(omega) + stall).abs() <= 1e-12 * stall,
            "forced back at {omega} rad/s: {} against the stall torque {stall}",
            torque(omega)
        );
    }
    assert!((torque(-1e-12) - torque(1e-12)).abs() <= 1e-9 * stall);
    for omega in [-0.5, -2.0, -4.0] {
        let envelope = powertrain.limit(-omega).0;
        assert!((torque(omega) + envelope).abs() <= 1e-12 * envelope);
    }
    for omega in [-2.0, -0.5, 0.5, 2.0] {
        let h = 1e-7;
        let difference = (torque(omega + h) - torque(omega - h)) / (2.0 * h);
        let slope = drive
            .slopes(0.0, omega, radius, integral, cap(omega))
            .torque[0];
        assert!(
            (slope - difference).abs() <= 1e-6 * slope.abs() + 4.0 * f64::EPSILON * stall / h,
            "∂τ/∂ω at {omega}: {slope} against {difference}"
        );
    }
    // Braking: forward faster than asked, the integral run down.
    let braking = drive
        .checked_torque(0.0, -10.0, radius, 0.0, cap(-10.0))
        .unwrap()
        .0;
    assert!(braking > 0.0 && braking > powertrain.limit(10.0).0);
}

/// Up 10, 20 and 30 % grades at full throttle through the M113A3's torque
/// converter the M113 settles where the converter's envelope meets the
/// torque the grade asks at that speed. The grade's ask is measured apart:
/// the speed controller alone (no powertrain) holding the full-throttle
/// run's speed up the same grade, its mean sprocket torque `τ_g`. The
/// envelope's crossing with it, `τ̄(ω*) = τ_g`, found by bisection of the
/// envelope alone, gives the predicted speed `(1 − i) r ω*` (`r` the
/// sprocket's rolling radius, `i` the slip measured at full throttle):
/// within 3 % of the run's. `τ̄` is the envelope averaged over the
/// sprocket's measured ripple about its mean (the shoes' passage): where
/// the ideal range changes the envelope has a kink (on 10 %, the second
/// range's governor droop meeting the third range), and a ripple across a
/// convex kink gives a mean torque above the envelope at the mean speed
/// (measured there: 5 % above). The grade's ask is measured at the run's
/// own track speed: on 10 % it steps by 5 % between 8.42 and 8.45 m/s of
/// hull speed (2065 → 2179 N m; a resonance of the running gear at the
/// shoes' passage, some 55 Hz), just where the full-throttle run settles.
/// The grade's ask is not taken from the
/// flat's motion resistance, as in the constant-power check above: at
/// these speeds the resistance on the grade is not the flat's times
/// `cos θ` (on 20 %, 5.8 m/s, the flat's `f` = 0.044 asks 4 % more torque
/// than the grade does), and the envelope is flat enough there that 4 %
/// of torque is 5 % of speed.
#[test]
fn up_a_grade_through_the_converter_it_settles_on_the_envelope() {
    let powertrain = Powertrain::Converter(Box::new(m113a3_quasi_static()));
    let averaged = |ripple: &[f64], w: f64, _: Option<usize>| {
        ripple
            .iter()
            .map(|d| powertrain.limit((w + d).max(0.0)).0)
            .sum::<f64>()
            / ripple.len() as f64
    };
    settles("quasi-static converter", powertrain.clone(), &averaged);
}

/// [`up_a_grade_through_the_converter_it_settles_on_the_envelope`] through
/// the M113A3 as declared: its engine's speed a state, its gearbox on its
/// schedule. The engine's inertia does not follow the sprocket's ripple:
/// at the run's mean speed `w` in the range its gearbox held through the
/// window (as recorded: inside the schedule's hysteresis band that is not
/// always the envelope's best; on 30 % the run comes off the flat in
/// range 2 and holds it at some 14.6 rad/s of sprocket speed, above its
/// downshift at 13.2, where range 1 would give 14 % more), the engine's speed
/// is where its full-load torque meets the pump's absorption averaged over
/// the ripple, `T_e(ω_e) = ⟨(ω_e / K(SR_k))²⟩`, and the sprocket gets `f n
/// ⟨TR(SR_k) (ω_e / K(SR_k))²⟩`, `SR_k = n (w + δ_k) / ω_e` over the
/// measured ripple `δ_k` — the tables read here, the engine's speed and
/// the crossing by bisection. The scheduled range does not switch with
/// the ripple, so the convex kink of the quasi-static envelope at the
/// ranges' crossover is not there to average over.
#[test]
fn up_a_grade_through_the_declared_engine_it_settles_where_its_converter_says() {
    let d = m113a3_driveline();
    let powertrain = Powertrain::Converter(Box::new(d.clone()));
    let f = d.gearbox_efficiency * d.final_drive_efficiency * d.share;
    let inertial = |ripple: &[f64], w: f64, held: Option<usize>| {
        let range = held.expect("the run holds one range through its window");
        let n = d.reduction(range);
        if d.lockup_ranges.contains(&range) && d.locks(n * w) {
            // Locked, the engine turns with the turbine's mean speed.
            return f * n * table_at(&d.engine, n * w).max(0.0);
        }
        let turbine: Vec<f64> = ripple.iter().map(|r| n * (w + r).max(0.0)).collect();
        let mean = |g: &dyn Fn(f64) -> f64| {
            turbine.iter().map(|&wt| g(wt)).sum::<f64>() / turbine.len() as f64
        };
        let balance = |we: f64| {
            table_at(&d.engine, we).max(0.0) - mean(&|wt| converter_torques(&d, we, wt).0)
        };
        let (mut lo, mut hi) = (
            turbine.iter().fold(0.0f64, |m, &x| m.max(x)) * 1.0001 + 1e-9,
            d.engine[d.engine.len() - 1].0,
        );
        for _ in 0..100 {
            let mid = 0.5 * (lo + hi);
            if balance(mid) > 0.0 {
                lo = mid
            } else {
                hi = mid
            }
        }
        let we = 0.5 * (lo + hi);
        f * n * mean(&|wt| converter_torques(&d, we, wt).1)
    };
    settles("declared engine", powertrain.clone(), &inertial);
}

/// Up 10, 20 and 30 % at full throttle through `powertrain`: the run's
/// mean speed against the crossing of `expected(ripple, w)` (the
/// sprocket's torque at mean sprocket speed `w` with the run's ripple
/// about it) with the grade's ask, within 3 %. The ask is measured at the
/// run's speed and 2 % either side (the speed controller alone holding
/// each), linear between: on 10 % it steps by 5 % between 8.42 and 8.45
/// m/s (a resonance of the running gear at the shoes' passage), and a run
/// that settles against the step bears the step's torque, not the ask
/// below it.
/// The sprocket torque a run settling at the sprocket's mean speed `w`
/// (rad/s) should get, N m, from the run's speed ripple about its mean
/// (rad/s) and the range its gearbox held (0-based; `None` if it shifted
/// or has no ranges).
type Expected<'a> = dyn Fn(&[f64], f64, Option<usize>) -> f64 + 'a;

fn settles(label: &str, powertrain: Powertrain, expected: &Expected) {
    use trackgen::contact::sprocket::rolling_radius;
    let r = rolling_radius(10, m113::SHOE_PITCH);
    for grade in [0.1, 0.2, 0.3] {
        let ramp = Terrain::Ramp {
            height: 0.0,
            start: 2.6,
            slope: grade,
        };
        let (speed, _, slip, omegas, held) =
            steady(ramp.clone(), 25.0, Some(powertrain.clone()), 20.0, 0.0);
        let mean = |v: &[f64]| v.iter().map(|w| w.abs()).sum::<f64>() / v.len() as f64;
        // The controller holds the track's speed: the hull's is `1 − i` of it.
        let asks: Vec<(f64, f64)> = [0.98, 1.0, 1.02]
            .iter()
            .map(|k| {
                let (kept, kept_power, _, kept_omegas, _) =
                    steady(ramp.clone(), k * speed / (1.0 - slip), None, 10.0, 0.0);
                assert!(
                    (kept - k * speed).abs() < 0.01 * speed,
                    "{kept} vs {}",
                    k * speed
                );
                (kept, kept_power / mean(&kept_omegas))
            })
            .collect();
        let ask = |v: f64| {
            let i = if v < asks[1].0 { 1 } else { 2 };
            let ((v0, a0), (v1, a1)) = (asks[i - 1], asks[i]);
            a0 + (a1 - a0) * (v - v0) / (v1 - v0)
        };
        let centre = mean(&omegas);
        let ripple: Vec<f64> = omegas.iter().map(|w| w.abs() - centre).collect();
        let hull = |w: f64| (1.0 - slip) * r * w;
        // The expected torque falls with speed and the ask rises: bisect
        // their crossing.
        let (mut low, mut high) = (0.0, 100.0);
        for _ in 0..60 {
            let mid = 0.5 * (low + high);
            if expected(&ripple, mid, held) > ask(hull(mid)) {
                low = mid;
            } else {
                high = mid;
            }
        }
        let want = hull(0.5 * (low + high));
        println!(
            "{} % grade through the {label}: {speed:.4} m/s against {want:.4} m/s \
             ({:+.2} %; the grade asks {:.0} / {:.0} / {:.0} N m at {:.3} / {:.3} / {:.3} m/s, slip {slip:.4})",
            grade * 100.0,
            100.0 * (speed / want - 1.0),
            asks[0].1,
            asks[1].1,
            asks[2].1,
            asks[0].0,
            asks[1].0,
            asks[2].0,
        );
        assert!(
            (speed - want).abs() < 0.03 * want,
            "{label}, {} % grade: {speed} m/s against {want} m/s",
            grade * 100.0
        );
    }
}
