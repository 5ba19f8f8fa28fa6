//! The torque converter's full-load match against closed forms and an
//! independent solve.
//!
//! * Stall: on a linear piece of the engine map, `T_e = a + b ω`, the
//!   stall speed solves `(ω / K₀)² = a + b ω`, a quadratic; the turbine
//!   gives `TR(0)` times that torque. Held to 1e-12 relative (the solver
//!   converges to the last bits; the quadratic's own rounding is ~1e-16).
//! * With a flat engine torque `T₀` and a constant capacity factor `K`,
//!   the engine runs at `K √T₀` whatever the turbine does: the speed
//!   ratio is `ω_t / (K √T₀)`, the turbine torque `TR(SR) T₀`, and the
//!   power out over the power in is `SR · TR(SR)`, the converter's
//!   efficiency curve; the coupling point (`TR = 1`) passes the engine's
//!   torque unchanged. To 1e-12 relative.
//! * The M113A3's envelope from rest to its top speed against an
//!   independent route written here: the match by plain bisection of
//!   `T_e(ω) − (ω / K(ω_t/ω))²` on a scan of 20 000 engine speeds, the
//!   lock-up rule, the best range. To 1e-9 relative: bisection to 1e-13
//!   of the speed, and the torque's slope in it is bounded.
//! * Lock-up as declared: range 1 never locks; ranges 2–4 lock where the
//!   match's speed ratio reaches 0.9, and then the engine turns with the
//!   turbine.
//! * The envelope's slope against its central difference (in
//!   `powertrain.rs`, with every other envelope).
//! * Bad data refused, each with its own error.

use crate::support::table_at;
use crate::support::vehicle::m113a3_driveline;
use trackgen::vehicle::{Driveline, Powertrain, PowertrainError};
use trackgen::vehicles::m113;

fn a_driveline(engine: Vec<(f64, f64)>, capacity: Vec<(f64, f64)>) -> Driveline {
    Driveline {
        engine,
        capacity,
        torque_ratio: vec![(0.0, 2.5), (0.4, 1.8), (0.8, 1.1), (0.9, 1.0), (1.0, 1.0)],
        ranges: vec![3.0, 1.5],
        lockup_ranges: vec![1],
        lockup_speed_ratio: 0.9,
        final_drive: 4.0,
        gearbox_efficiency: 0.9,
        final_drive_efficiency: 0.95,
        share: 0.5,
        reverse: None,
        shift: None,
        dynamics: None,
        steer_ratios: vec![],
    }
}

#[test]
fn the_stall_point_is_the_quadratic_s_root() {
    // A falling piece from 100 to 300 rad/s.
    let (a, b) = (1200.0, -1.5); // T_e = a + b ω, N m
    let engine = vec![
        (50.0, a + b * 100.0),
        (100.0, a + b * 100.0),
        (300.0, a + b * 300.0),
    ];
    let k0 = 7.0;
    let driveline = a_driveline(engine, vec![(0.0, k0), (1.0, 3.0 * k0)]);
    driveline.check().unwrap();
    // ω² + B ω + C = 0 with B = −K₀² b, C = −K₀² a: the positive root.
    let (qb, qc) = (-k0 * k0 * b, -k0 * k0 * a);
    let want = 0.5 * (-qb + (qb * qb - 4.0 * qc).sqrt());
    assert!((100.0..300.0).contains(&want), "{want}");
    let point = driveline.converter_match(0.0).unwrap();
    assert!(
        (point.engine_speed - want).abs() <= 1e-12 * want,
        "{} vs {want}",
        point.engine_speed
    );
    let torque = a + b * want;
    assert!((point.engine_torque - torque).abs() <= 1e-12 * torque);
    assert!((point.turbine_torque - 2.5 * torque).abs() <= 1e-12 * torque);
    assert_eq!(point.speed_ratio, 0.0);
    // At rest the sprocket gets it through the lowest range and the final
    // drive, times the stages' efficiencies and the side's share.
    let (at_rest, _, range) = driveline.envelope(0.0);
    let want = 2.5 * torque * 3.0 * 4.0 * 0.9 * 0.95 * 0.5;
    assert_eq!(range, Some(0));
    assert!(
        (at_rest - want).abs() <= 1e-12 * want,
        "{at_rest} vs {want}"
    );
}

#[test]
fn a_flat_engine_and_a_constant_capacity_give_the_efficiency_curve() {
    let t0 = 900.0;
    let k = 9.0;
    let engine = vec![(20.0, t0), (1000.0, t0)];
    let driveline = a_driveline(engine, vec![(0.0, k), (1.0, k)]);
    driveline.check().unwrap();
    let we = k * t0.sqrt();
    for i in 0..=95 {
        let sr = i as f64 * 0.01;
        let wt = sr * we;
        let point = driveline.converter_match(wt).unwrap();
        let tr = table_at(&driveline.torque_ratio, sr);
        assert!((point.engine_speed - we).abs() <= 1e-12 * we);
        assert!((point.speed_ratio - sr).abs() <= 1e-12);
        assert!((point.turbine_torque - tr * t0).abs() <= 1e-12 * t0);
        let efficiency = point.turbine_torque * wt / (point.engine_torque * point.engine_speed);
        assert!(
            (efficiency - sr * tr).abs() <= 1e-12,
            "at SR {sr}: {efficiency}"
        );
        if sr >= 0.9 {
            // Past the coupling point the torque passes unchanged.
            assert!((point.turbine_torque - t0).abs() <= 1e-12 * t0);
        }
    }
}

/// The full-load match by plain bisection: the lowest engine speed on a
/// scan of 20 000 where `T_e − (ω/K)²` turns from positive, refined.
fn independent_match(d: &Driveline, wt: f64) -> Option<(f64, f64)> {
    let first = d.engine[0].0;
    let last = d.engine[d.engine.len() - 1].0;
    let te = |w: f64| {
        if w < first || w > last {
            0.0
        } else {
            table_at(&d.engine, w).max(0.0)
        }
    };
    let g = |w: f64| {
        let k = table_at(&d.capacity, wt / w);
        te(w) - (w / k) * (w / k)
    };
    let low = wt.max(first);
    if low >= last || g(low) <= 0.0 {
        return None;
    }
    let n = 20_000;
    let mut a = low;
    for i in 1..=n {
        let b = low + (last - low) * i as f64 / n as f64;
        if g(b) <= 0.0 {
            let (mut lo, mut hi) = (a, b);
            for _ in 0..200 {
                let mid = 0.5 * (lo + hi);
                if g(mid) > 0.0 {
                    lo = mid;
                } else {
                    hi = mid;
                }
            }
            let we = 0.5 * (lo + hi);
            let tr = table_at(&d.torque_ratio, wt / we);
            return Some((we, tr * te(we)));
        }
        a = b;
    }
    None
}

/// The envelope by the independent match, the lock-up rule and the best
/// range.
fn independent_envelope(d: &Driveline, speed: f64) -> f64 {
    let fraction = d.gearbox_efficiency * d.final_drive_efficiency * d.share;
    let last = d.engine[d.engine.len() - 1].0;
    let mut best: f64 = 0.0;
    for (range, &ratio) in d.ranges.iter().enumerate() {
        let n = ratio * d.final_drive;
        let wt = n * speed;
        let matched = independent_match(d, wt);
        let locked = d.lockup_ranges.contains(&range)
            && matched.is_none_or(|(we, _)| wt / we >= d.lockup_speed_ratio)
            && wt >= d.engine[0].0
            && wt <= last
            && table_at(&d.engine, wt) > 0.0;
        let turbine = if locked {
            table_at(&d.engine, wt)
        } else {
            matched.map_or(0.0, |(_, t)| t)
        };
        best = best.max(fraction * n * turbine);
    }
    best
}

#[test]
fn the_m113a3s_envelope_is_the_independent_route_s() {
    let driveline = m113a3_driveline();
    driveline.check().unwrap();
    let top = m113::TOP_SPEED / m113::SPROCKET_PITCH_RADIUS;
    let mut worst: f64 = 0.0;
    for i in 0..=300 {
        let speed = 1.1 * top * i as f64 / 300.0;
        let (torque, _, _) = driveline.envelope(speed);
        let want = independent_envelope(&driveline, speed);
        if want == 0.0 {
            assert_eq!(torque, 0.0, "at {speed} rad/s");
            continue;
        }
        let error = (torque / want - 1.0).abs();
        worst = worst.max(error);
        assert!(error <= 1e-9, "at {speed} rad/s: {torque} vs {want}");
    }
    println!("the M113A3's envelope against the independent route: worst {worst:.1e}");
}

#[test]
fn the_m113a3_stalls_at_its_stated_speed_with_the_published_ratio() {
    let driveline = m113a3_driveline();
    let stall = driveline.converter_match(0.0).unwrap();
    let want = m113::STALL_SPEED;
    assert!((stall.engine_speed - want).abs() <= 1e-12 * want);
    let torque = Driveline::full_load(&driveline.engine, want);
    assert!((stall.turbine_torque - 3.32 * torque).abs() <= 1e-12 * torque);
    // The engine's rated power at its rated speed: 275 hp at 2800 rpm.
    let rated = Driveline::full_load(&driveline.engine, m113::ENGINE_RATED_SPEED)
        * m113::ENGINE_RATED_SPEED;
    assert!(
        (rated / m113::ENGINE_RATED_POWER - 1.0).abs() < 1e-12,
        "{rated} W"
    );
    // The final drive the guide quotes, 3.833, derived here from the
    // published figures alone: 2800 rpm in fourth (1.04), locked, turning
    // a ten-tooth sprocket on 0.154 m shoes at 41 mph.
    let pitch = m113::SHOE_PITCH / (2.0 * (std::f64::consts::PI / 10.0).sin());
    assert!((pitch - m113::SPROCKET_PITCH_RADIUS).abs() < 1e-15);
    let derived = 2800.0 * std::f64::consts::PI / 30.0 * pitch / (1.04 * 41.0 * 0.447_04);
    assert!((derived - 3.833).abs() < 5e-4, "{derived}");
    assert_eq!(driveline.final_drive, m113::FINAL_DRIVE);
    assert!((derived / m113::FINAL_DRIVE - 1.0).abs() < 1e-12);
}

#[test]
fn lock_up_engages_as_declared() {
    let driveline = m113a3_driveline();
    let mut locked_seen = [false; 4];
    for i in 1..400 {
        let turbine = 320.0 * i as f64 / 400.0;
        for (range, seen) in locked_seen.iter_mut().enumerate() {
            let Some(point) = driveline.operating_point(range, turbine) else {
                continue;
            };
            let matched = driveline.converter_match(turbine);
            if range == 0 {
                assert!(!point.locked, "range 1 has no lock-up");
                continue;
            }
            let should = matched.is_none_or(|m| m.speed_ratio >= 0.9);
            assert_eq!(point.locked, should, "range {} at {turbine}", range + 1);
            if point.locked {
                *seen = true;
                assert_eq!(point.engine_speed, turbine);
                assert_eq!(point.speed_ratio, 1.0);
            }
        }
    }
    assert_eq!(locked_seen, [false, true, true, true]);
}

#[test]
fn bad_driveline_data_is_refused() {
    let good = m113a3_driveline();
    good.check().unwrap();
    let refused = |change: &dyn Fn(&mut Driveline)| {
        let mut bad = good.clone();
        change(&mut bad);
        let error = bad.check().expect_err("refused");
        // The powertrain refuses it too, with the same error.
        let whole = Powertrain::Converter(Box::new(bad)).check();
        assert_eq!(format!("{whole:?}"), format!("{:?}", Err::<(), _>(&error)));
        error
    };
    assert!(matches!(
        refused(&|d| d.engine.swap(1, 2)),
        PowertrainError::Table { point: 2, .. }
    ));
    assert!(matches!(
        refused(&|d| d.engine[0].0 = 0.0),
        PowertrainError::Table { point: 0, .. }
    ));
    assert!(matches!(
        refused(&|d| d.capacity[0].0 = 0.1),
        PowertrainError::ConverterStart {
            what: "capacity factor",
            ..
        }
    ));
    assert!(matches!(
        refused(&|d| {
            d.torque_ratio.remove(0);
        }),
        PowertrainError::ConverterStart {
            what: "torque ratio",
            ..
        }
    ));
    assert!(matches!(
        refused(&|d| d.torque_ratio[3].1 = 1.5),
        PowertrainError::ConverterEfficiency { point: 3, .. }
    ));
    assert!(matches!(
        refused(&|d| d.capacity[2].1 = -1.0),
        PowertrainError::Table { point: 2, .. }
    ));
    assert!(matches!(
        refused(&|d| d.ranges[1] = -2.34),
        PowertrainError::Ratio { gear: 1, .. }
    ));
    assert!(matches!(
        refused(&|d| d.final_drive = f64::NAN),
        PowertrainError::FinalDrive(_)
    ));
    assert!(matches!(
        refused(&|d| d.lockup_ranges.push(4)),
        PowertrainError::LockupRange {
            range: 4,
            ranges: 4
        }
    ));
    assert!(matches!(
        refused(&|d| d.lockup_speed_ratio = 1.2),
        PowertrainError::LockupSpeedRatio(_)
    ));
    assert!(matches!(
        refused(&|d| d.gearbox_efficiency = 1.1),
        PowertrainError::Stage {
            what: "gearbox_efficiency",
            ..
        }
    ));
    assert!(matches!(
        refused(&|d| d.steer_ratios.truncate(3)),
        PowertrainError::SteerRatios {
            count: 3,
            ranges: 4
        }
    ));
    assert!(matches!(
        refused(&|d| d.steer_ratios[2] = 1.0),
        PowertrainError::SteerRatio { range: 2, .. }
    ));
    assert!(matches!(
        refused(&|d| d.steer_ratios[0] = f64::INFINITY),
        PowertrainError::SteerRatio { range: 0, .. }
    ));
    // None declared: no steer unit, and nothing to refuse.
    Driveline {
        steer_ratios: Vec::new(),
        ..good.clone()
    }
    .check()
    .unwrap();
    // Every message names what is wrong.
    let message = refused(&|d| d.torque_ratio[3].1 = 1.5).to_string();
    assert!(
        message.contains("efficiency") && message.contains("more than 1"),
        "{message}"
    );
}

/// The most power at the sprocket against a scan of the envelope's
/// `τ ω` every 1e-4 of its reach (the envelope is smooth between its
/// kinks, so the scan's miss is below 1e-6 of the peak).
#[test]
fn the_most_power_is_the_envelope_s_peak() {
    let powertrain = m113::powertrain();
    let reach = 1.1 * m113::ENGINE_HIGH_IDLE / (1.04 * m113::FINAL_DRIVE);
    let scanned = (0..=10_000)
        .map(|i| {
            let w = reach * i as f64 / 10_000.0;
            powertrain.limit(w).0 * w
        })
        .fold(0.0, f64::max);
    let peak = powertrain.max_power();
    assert!(
        peak >= scanned * (1.0 - 1e-12) && peak <= scanned * (1.0 + 1e-6),
        "{peak} W against the scan's {scanned} W"
    );
    // Locked in fourth at the rated speed, the sprocket gets the rated
    // power through the stages: the peak is at least that.
    let rated = m113::ENGINE_RATED_POWER * 0.92 * 0.97 * 0.5;
    assert!(
        peak >= rated * (1.0 - 1e-12),
        "{peak} W, rated through the stages {rated} W"
    );
}

/// The rated speed is where the full-load map's power peaks: the
/// M113A3's map at its published 2800 rpm (the droop falls to none at
/// 3000 rpm, too steeply for `T ω` to rise past it); on a map falling
/// linearly from 100 N m at 100 rad/s to none at 300 rad/s, `T ω =
/// (150 − ω/2) ω` peaks inside the segment at 150 rad/s (11 250 W against
/// 10 000 W at its first point), to 1e-12; against a scan of 200 000
/// speeds on both.
#[test]
fn the_rated_speed_is_the_full_load_power_s_peak() {
    let scan = |d: &Driveline| {
        let last = d.engine[d.engine.len() - 1].0;
        (0..=200_000)
            .map(|i| last * i as f64 / 200_000.0)
            .map(|w| (w, Driveline::full_load(&d.engine, w) * w))
            .fold(
                (0.0, 0.0),
                |best, (w, p)| if p > best.1 { (w, p) } else { best },
            )
    };
    let m113a3 = m113a3_driveline();
    let rated = m113a3.rated_speed();
    assert!(
        (rated / m113::ENGINE_RATED_SPEED - 1.0).abs() < 1e-12,
        "{rated} rad/s against {}",
        m113::ENGINE_RATED_SPEED
    );
    let falling = a_driveline(
        vec![(100.0, 100.0), (300.0, 0.0)],
        vec![(0.0, 10.0), (1.0, 10.0)],
    );
    let rated = falling.rated_speed();
    assert!((rated / 150.0 - 1.0).abs() < 1e-12, "{rated}");
    for d in [&m113a3, &falling] {
        let (w, _) = scan(d);
        assert!(
            (w / d.rated_speed() - 1.0).abs() < 1e-4,
            "{w} against {}",
            d.rated_speed()
        );
    }
}

/// The declared capacity factor at stall is the one that stalls the
/// declared engine at the stated speed: `K(0) = ω / √T_e(ω)`, to 1e-12
/// (the declaration holds the figure as a literal: a square root is not a
/// constant expression).
#[test]
fn the_declared_stall_capacity_is_its_derivation() {
    let driveline = m113a3_driveline();
    let torque = Driveline::full_load(&driveline.engine, m113::STALL_SPEED);
    let want = m113::STALL_SPEED / torque.sqrt();
    assert!(
        (m113::STALL_CAPACITY / want - 1.0).abs() < 1e-12,
        "{} vs {want}",
        m113::STALL_CAPACITY
    );
    assert_eq!(driveline.capacity[0], (0.0, m113::STALL_CAPACITY));
}

/// An ideally shifted engine map is refused by the same rule as the
/// converter's tables: at the point where its speeds stop increasing.
#[test]
fn a_bad_engine_map_is_refused_by_the_tables_rule() {
    let bad = Powertrain::Engine {
        map: vec![(50.0, 500.0), (200.0, 600.0), (150.0, 550.0)],
        ratios: vec![0.2],
        fraction: 0.4,
    };
    assert!(matches!(
        bad.check(),
        Err(PowertrainError::Table { point: 2, .. })
    ));
}

/// Reverse is one more range through the converter: at stall the engine
/// and the converter run as in any range (the turbine at rest), so the
/// sprocket's stall torque in reverse is the first range's times the ratio
/// of their reductions, 6.62 / 4.16 for the X200-4 (to 1e-12: the same
/// match, scaled); it never locks up; a reverse reduction not above 0 is
/// refused.
#[test]
fn reverse_is_a_range_through_the_converter() {
    let d = m113a3_driveline();
    let reverse = d.reverse_range().expect("the X200-4 has a reverse range");
    assert_eq!(reverse, d.ranges.len());
    let (first, back) = (d.in_range(0, 0.0).0, d.in_range(reverse, 0.0).0);
    let want = first * 6.62 / 4.16;
    assert!((back - want).abs() <= 1e-12 * want, "{back} against {want}");
    for i in 0..=100 {
        let w = 0.2 * i as f64;
        if let (_, _, Some(point)) = d.in_range(reverse, w) {
            assert!(!point.locked, "reverse locked at {w} rad/s");
        }
    }
    let mut bad = d.clone();
    bad.reverse = Some(-6.62);
    assert!(matches!(
        bad.check(),
        Err(PowertrainError::Ratio { gear: 4, .. })
    ));
}
