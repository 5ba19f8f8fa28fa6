//! The engine's side of the drive: where the engine and the converter run
//! at part load, what a run records of them, and the engine's work.
//!
//! * With a constant capacity factor `K` and a linear torque ratio
//!   `TR = a − b SR`, the converter giving `T_t` at turbine speed `ω_t`
//!   runs the engine at the root of `a ω² − b ω_t ω − K² T_t = 0`: the
//!   part-load solve against that closed form, to 1e-12 relative (Newton
//!   to the last bits; the closed form's own rounding is ~1e-16).
//! * At full load the part-load point is the full-load match (two solves
//!   of two equations, `T_t = TR (ω/K)²` for the torque given and
//!   `T_e = (ω/K)²` for the engine's), over the M113A3's ranges from rest
//!   to each range's reach: the engine's speed to 1e-9 relative, the same
//!   lock-up.
//! * Lock-up at part load: a range that locks locks where the part-load
//!   speed ratio reaches the clutch's, range 1 never.
//! * The stages' powers: the sprocket gets the turbine's power times the
//!   gearbox's and final drive's efficiencies, the turbine the engine's
//!   times `SR · TR` (to 1e-12).
//! * A run through the M113A3's converter, from rest over a 0.3 m step:
//!   every recorded row's engine speed against an independent bisection of
//!   the converter's equation from the row's own sprocket torque, speed
//!   and range (1e-9 relative), and the engine's work, a quadrature of the
//!   integrator, against the trapezoidal sum of the recorded engine power
//!   at every 2 ms (1e-3 relative: the trapezoid's error on a power that
//!   jumps where the range changes is of the order of a step's share of
//!   the jump); the converter and gears lose what the engine gives beyond
//!   the sprocket's work; and the books with that loss (summed from the
//!   recorded engine and sprocket powers) close on the engine's work over
//!   the 12 s, within 1e-3 of it at Bogacki-Shampine 1e-4.

use crate::support::table_at;
use crate::support::vehicle::{m113_through, m113a3_quasi_static, step_course};
use trackgen::terrain::Terrain;
use trackgen::vehicle::{Driveline, Powertrain};

#[test]
fn part_load_on_a_linear_torque_ratio_is_the_quadratic_s_root() {
    let (k, a, b) = (9.0, 2.5, 1.5);
    let driveline = Driveline {
        engine: vec![(50.0, 800.0), (400.0, 800.0)],
        capacity: vec![(0.0, k), (1.0, k)],
        torque_ratio: vec![(0.0, a), (1.0, a - b)],
        ranges: vec![3.0],
        lockup_ranges: vec![],
        lockup_speed_ratio: 1.0,
        final_drive: 4.0,
        gearbox_efficiency: 0.9,
        final_drive_efficiency: 0.95,
        share: 0.5,
        reverse: None,
        shift: None,
        dynamics: None,
        steer_ratios: vec![],
    };
    driveline.check().unwrap();
    for wt in [0.0, 20.0, 60.0, 120.0, 200.0] {
        let full = driveline.operating_point(0, wt).expect("the engine drives");
        for fraction in [0.02, 0.1, 0.5, 0.9, 1.0] {
            let tt = fraction * full.turbine_torque;
            let root = (b * wt + (b * b * wt * wt + 4.0 * a * k * k * tt).sqrt()) / (2.0 * a);
            let point = driveline.part_load(0, wt, tt);
            if root < wt {
                // The root asks `SR > 1`, past the maps: the converter at
                // the coupling gives more than asked there, and runs at it.
                assert_eq!(point.engine_speed, wt, "ω_t {wt}, T_t {tt}");
                continue;
            }
            let want = root;
            assert!(
                (point.engine_speed - want).abs() <= 1e-12 * want,
                "ω_t {wt}, T_t {tt}: {} against {want}",
                point.engine_speed
            );
            let tr = a - b * wt / want;
            assert!((point.torque_ratio - tr).abs() <= 1e-12 * tr);
            assert!((point.engine_torque * point.torque_ratio - tt).abs() <= 1e-12 * tt);
            assert!(!point.locked);
        }
    }
}

#[test]
fn at_full_load_the_part_load_point_is_the_full_load_match() {
    let driveline = m113a3_quasi_static();
    let mut compared = 0;
    for range in 0..driveline.ranges.len() {
        let n = driveline.reduction(range);
        for i in 0..=200 {
            let wt = 300.0 * i as f64 / 200.0;
            let Some(full) = driveline.operating_point(range, wt) else {
                continue;
            };
            let point = driveline.part_load(range, wt, full.turbine_torque);
            assert_eq!(point.locked, full.locked, "range {range}, ω_t {wt}");
            assert!(
                (point.engine_speed - full.engine_speed).abs() <= 1e-9 * full.engine_speed,
                "range {} at {:.3} rad/s of the sprocket: {} against the full-load {}",
                range + 1,
                wt / n,
                point.engine_speed,
                full.engine_speed
            );
            compared += 1;
        }
    }
    assert!(compared > 400, "{compared} points compared");
}

#[test]
fn at_part_load_the_locking_ranges_lock_at_the_clutch_s_speed_ratio() {
    let driveline = m113a3_quasi_static();
    // Unlocked at full load, about 0.8 of the clutch's speed ratio.
    let wt = 200.0;
    for range in 0..driveline.ranges.len() {
        let full = driveline.operating_point(range, wt).unwrap();
        assert!(!full.locked && full.speed_ratio < 0.9);
        for fraction in [0.9, 0.5, 0.2, 0.05] {
            let tt = fraction * full.turbine_torque;
            let point = driveline.part_load(range, wt, tt);
            // The converter's own solution, apart from the clutch: the
            // speed ratio where `TR (ω/K)²` gives `tt`.
            let open = driveline.part_load(0, wt, tt);
            let locks = range > 0 && open.speed_ratio >= driveline.lockup_speed_ratio;
            assert_eq!(
                point.locked,
                locks,
                "range {}, {fraction} of full load",
                range + 1
            );
            if locks {
                assert_eq!((point.engine_speed, point.engine_torque), (wt, tt));
            }
        }
    }
}

#[test]
fn the_stages_powers_follow_the_efficiencies() {
    let driveline = m113a3_quasi_static();
    let powertrain = Powertrain::Converter(Box::new(driveline.clone()));
    for speed in [0.5, 5.0, 20.0, 40.0, 60.0] {
        let (cap, _, gear) = powertrain.limit_in_gear(speed);
        for load in [0.1, 0.6, 1.0] {
            let torque = load * cap;
            let side = powertrain.engine_side(gear, speed, torque);
            let sprocket = torque * speed;
            let stages = driveline.gearbox_efficiency * driveline.final_drive_efficiency;
            assert!((side.turbine_power * stages - sprocket).abs() <= 1e-12 * sprocket);
            let efficiency = side.speed_ratio * side.torque_ratio;
            assert!(
                (side.engine_power * efficiency - side.turbine_power).abs()
                    <= 1e-12 * side.turbine_power
            );
            assert!(side.engine_power >= side.turbine_power);
        }
    }
}

/// The engine speed where the converter in `range` gives the turbine
/// torque the sprocket's `torque` asks at sprocket `speed`, by plain
/// bisection of `TR(SR) (ω/K(SR))² − T_t` over `[ω_t, 10⁴]`, and the
/// lock-up rule applied to it (or to the full-load point).
fn independent_engine_speed(d: &Driveline, range: usize, speed: f64, torque: f64) -> f64 {
    let n = d.ranges[range] * d.final_drive;
    let fraction = d.gearbox_efficiency * d.final_drive_efficiency * d.share;
    let (wt, tt) = (n * speed.max(0.0), torque / (fraction * n));
    let gives = |w: f64| {
        let sr = wt / w;
        let k = table_at(&d.capacity, sr);
        table_at(&d.torque_ratio, sr) * (w / k) * (w / k)
    };
    let locking = d.lockup_ranges.contains(&range);
    // Where the range locks at full load (the envelope's rule, checked
    // against its own independent route in `converter.rs`), the engine
    // could not reach the open converter's speed: it locks at part load too.
    let locked_at_full_load = d.operating_point(range, wt).is_some_and(|p| p.locked);
    if (wt > 0.0 && gives(wt) >= tt) || locked_at_full_load {
        return wt;
    }
    let (mut lo, mut hi) = (wt, 1e4);
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if gives(mid) < tt { lo = mid } else { hi = mid }
    }
    let we = 0.5 * (lo + hi);
    if locking && wt / we >= d.lockup_speed_ratio {
        wt
    } else {
        we
    }
}

#[test]
fn a_run_records_the_converter_and_books_the_engine_s_work() {
    let driveline = m113a3_quasi_static();
    let target = |t: f64| if t < 0.5 { 0.0 } else { 15.0 };
    let results = m113_through(&driveline, step_course(0.3), target, 12.0, 0.002);
    let column = |name: &str| results.column(name).expect(name);
    let t = results.times().to_vec();
    let (torque, omega) = (column("sprocket_torque"), column("sprocket_speed"));
    let (gear, engine_speed, load) = (
        column("gear"),
        column("engine_speed"),
        column("engine_load"),
    );
    let (engine_power, engine_work, motor_work) = (
        column("engine_power"),
        column("engine_work"),
        column("motor_work"),
    );
    let mut driving = 0;
    let mut ranges = [false; 4];
    for i in 0..t.len() {
        if load[i] <= 0.0 {
            assert_eq!(
                engine_power[i], 0.0,
                "braking at {} s, the engine gives nothing",
                t[i]
            );
            continue;
        }
        let range = gear[i] as usize - 1;
        ranges[range] = true;
        // Driving forward the sprocket turns and pushes negative.
        let want = independent_engine_speed(&driveline, range, -omega[i], -torque[i]);
        assert!(
            (engine_speed[i] - want).abs() <= 1e-9 * want,
            "t = {} s, range {}: {} rad/s against {want}",
            t[i],
            range + 1,
            engine_speed[i]
        );
        driving += 1;
    }
    assert!(driving > t.len() / 2, "{driving} of {} rows drive", t.len());
    assert!(
        ranges[0] && ranges[1] && ranges[2],
        "ranges used: {ranges:?}"
    );
    let trapezoid: f64 = (1..t.len())
        .map(|i| 0.5 * (engine_power[i] + engine_power[i - 1]) * (t[i] - t[i - 1]))
        .sum();
    let (work, motor) = (engine_work[t.len() - 1], motor_work[t.len() - 1]);
    println!(
        "engine's work {work:.1} J, trapezoid {trapezoid:.1} J ({:+.2e}); sprocket's {motor:.1} J: \
         the converter and gears lost {:.1} % of it",
        work / trapezoid - 1.0,
        100.0 * (1.0 - motor / work)
    );
    assert!((work - trapezoid).abs() <= 1e-3 * work);
    assert!(motor > 0.0 && work > motor);
    // The books with the converter's and gears' loss: the engine's work
    // against the change of energy, the dissipated work and the loss, the
    // loss summed apart from the recorded powers (the engine's less the
    // sprocket's).
    let (energy, dissipated) = (column("energy"), column("dissipated"));
    let last = t.len() - 1;
    let loss: f64 = (1..t.len())
        .map(|i| {
            let rate = |k: usize| engine_power[k] - torque[k] * omega[k];
            0.5 * (rate(i) + rate(i - 1)) * (t[i] - t[i - 1])
        })
        .sum();
    let books = energy[last] - energy[0] + dissipated[last] + loss;
    println!(
        "the engine's work {work:.1} J against ΔE + dissipated + the loss {books:.1} J ({:+.2e}; the loss {loss:.1} J)",
        books / work - 1.0
    );
    assert!((books - work).abs() <= 1e-3 * work);
}

/// Backing at full throttle the M113A3 takes its reverse range: the
/// recorded gear is −1, and wherever the engine sets the torque (load 1)
/// the sprocket's is the reverse range's full-load torque at its speed
/// (to 1e-9: the same match, the cap's rounding).
#[test]
fn backing_at_full_throttle_takes_the_reverse_range() {
    let driveline = m113a3_quasi_static();
    let reverse = driveline.reverse_range().unwrap();
    let target = |t: f64| if t < 0.5 { 0.0 } else { -3.0 };
    let results = m113_through(
        &driveline,
        Terrain::Flat { height: 0.0 },
        target,
        3.0,
        0.002,
    );
    let column = |name: &str| results.column(name).expect(name);
    let (gear, load, torque, omega) = (
        column("gear"),
        column("engine_load"),
        column("sprocket_torque"),
        column("sprocket_speed"),
    );
    let mut capped = 0;
    for i in 0..gear.len() {
        if results.times()[i] < 0.6 {
            continue;
        }
        assert_eq!(gear[i], -1.0, "at {} s", results.times()[i]);
        if load[i] == 1.0 && torque[i] * omega[i] >= 0.0 {
            let (want, _, _) = driveline.in_range(reverse, omega[i].abs());
            assert!(
                (torque[i].abs() - want).abs() <= 1e-9 * want,
                "at {} s: {} N m against reverse's {want}",
                results.times()[i],
                torque[i]
            );
            capped += 1;
        }
    }
    assert!(capped > 100, "{capped} rows at full load");
}
