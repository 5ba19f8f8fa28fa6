//! The gearbox's shift schedule: hysteresis, the shift's time, and a run
//! that shifts where the schedule says.
//!
//! * A schedule is refused where it cannot work: a list not one speed per
//!   range, a negative speed or time, a downshift at or above its range's
//!   upshift, an upshift landing at or below the next range's downshift
//!   (the gearbox would hunt).
//! * `Shift::next`: up past the upshift speed, down below the downshift
//!   speed, nothing in the band between (the hysteresis); a shift under
//!   way holds until its time has passed, and then ends.
//! * While a shift takes its time the sprocket gets the lesser of the two
//!   ranges' full-load torques, each range's being the converter's own
//!   match through that range (`Driveline::in_range`, whose envelope is
//!   held to an independent route in `converter.rs`): equal to the bit.
//! * The M113A3 with a schedule at its ideal shift points (the speeds where
//!   the next range's full-load torque overtakes, found here by
//!   bisection) and its downshifts 20 % of speed lower, driven from rest
//!   to 16 m/s and slowing evenly to 6 m/s: every shift the run records lands where
//!   the schedule says (the gearbox's input in the range shifted from, at
//!   the rows either side of the shift, brackets the shift speed to 1 %:
//!   the shift is made at the end of the first step past it, and the
//!   sprocket's speed ripples by a few per cent as each tooth engages),
//!   each range up once and down once at most (no hunting), and the
//!   downshifts at lower speeds than the upshifts.

use crate::support::vehicle::{m113_through, m113a3_driveline};
use trackgen::terrain::Terrain;
use trackgen::vehicle::{Driveline, Engaged, PowertrainError, Shift};
use trackgen::vehicles::m113;

/// The sprocket speed (rad/s) above which range `r + 1` gives more
/// full-load torque than range `r`, by bisection between where `r` gives
/// more and where it gives none.
fn crossover(d: &Driveline, r: usize) -> f64 {
    let better = |w: f64| d.in_range(r + 1, w).0 > d.in_range(r, w).0;
    // The lower range is better at rest; scan for the first speed past
    // which the higher is, then bisect.
    let mut w = 0.0;
    while !better(w) {
        w += 0.05;
        assert!(w < 200.0, "range {} never overtakes {}", r + 2, r + 1);
    }
    let (mut low, mut high) = (w - 0.05, w);
    for _ in 0..60 {
        let mid = 0.5 * (low + high);
        if better(mid) {
            high = mid;
        } else {
            low = mid;
        }
    }
    0.5 * (low + high)
}

/// The ideal shift points as a schedule, by the crossovers found here:
/// range `r` shifts up where range `r + 1` overtakes it, range `r + 1`
/// down at 80 % of that sprocket speed; both as the gearbox input's
/// speeds.
fn ideal_schedule(d: &Driveline, time: f64) -> Shift {
    let n = d.ranges.len();
    let mut up = vec![0.0; n];
    let mut down = vec![0.0; n];
    for r in 0..n - 1 {
        let w = crossover(d, r);
        up[r] = d.reduction(r) * w;
        down[r + 1] = d.reduction(r + 1) * 0.8 * w;
    }
    Shift { up, down, time }
}

/// `Driveline::ideal_schedule`, the library's, against the crossovers
/// found here by a coarser scan and 60 bisections (1e-9 relative: the
/// bisections' width).
#[test]
fn the_ideal_schedule_shifts_at_the_envelope_s_crossovers() {
    let d = m113a3_driveline();
    let want = ideal_schedule(&d, 0.25);
    let got = d.ideal_schedule(0.8, 0.25).expect("every range overtakes");
    for (g, w) in got
        .up
        .iter()
        .zip(&want.up)
        .chain(got.down.iter().zip(&want.down))
    {
        assert!(
            (g - w).abs() <= 1e-9 * w.abs().max(1.0),
            "{got:?} against {want:?}"
        );
    }
    assert_eq!(got.time, 0.25);
    let mut scheduled = d.clone();
    scheduled.shift = Some(got);
    scheduled.check().expect("a schedule that does not hunt");
}

#[test]
fn a_schedule_that_cannot_work_is_refused() {
    let mut d = m113a3_driveline();
    let good = ideal_schedule(&d, 0.3);
    d.shift = Some(good.clone());
    d.check().expect("the ideal schedule is a good one");
    let refused = |change: &dyn Fn(&mut Shift)| {
        let mut bad = d.clone();
        change(bad.shift.as_mut().unwrap());
        bad.check().expect_err("refused")
    };
    assert!(matches!(
        refused(&|s| {
            s.up.pop();
        }),
        PowertrainError::Shift {
            what: "upshift speeds",
            ..
        }
    ));
    assert!(matches!(
        refused(&|s| s.down[2] = -1.0),
        PowertrainError::Shift {
            range: 2,
            what: "downshift speeds"
        }
    ));
    assert!(matches!(
        refused(&|s| s.down[1] = s.up[1]),
        PowertrainError::Shift { range: 1, .. }
    ));
    // Range 2's downshift above where the upshift from range 1 lands.
    assert!(matches!(
        refused(&|s| s.down[1] = s.up[0] * 2.34 / 4.16 * 1.01),
        PowertrainError::Shift { range: 1, .. }
    ));
    assert!(matches!(
        refused(&|s| s.time = -0.1),
        PowertrainError::Shift {
            what: "shift time",
            ..
        }
    ));
}

#[test]
fn it_shifts_past_the_band_and_holds_within_it() {
    let shift = Shift {
        up: vec![100.0, 120.0, 0.0],
        down: vec![0.0, 40.0, 60.0],
        time: 0.5,
    };
    let at = |range| Engaged { range, from: None };
    // In range 2 (index 1): the band is (40, 120).
    assert_eq!(shift.next(at(1), 80.0, 1.0), None);
    assert_eq!(shift.next(at(1), 120.0, 1.0), None);
    assert_eq!(
        shift.next(at(1), 120.5, 1.0),
        Some(Engaged {
            range: 2,
            from: Some((1, 1.5))
        })
    );
    assert_eq!(
        shift.next(at(1), 39.9, 1.0),
        Some(Engaged {
            range: 0,
            from: Some((1, 1.5))
        })
    );
    // The top range does not shift up, the lowest not down.
    assert_eq!(shift.next(at(2), 1e3, 1.0), None);
    assert_eq!(shift.next(at(0), 0.0, 1.0), None);
    // A shift under way holds whatever the speed, then ends.
    let shifting = Engaged {
        range: 2,
        from: Some((1, 1.5)),
    };
    assert_eq!(shift.next(shifting, 1e3, 1.2), None);
    assert_eq!(shift.next(shifting, 0.0, 1.2), None);
    assert_eq!(shift.next(shifting, 50.0, 1.5), Some(at(2)));
    // Without a shift time a shift is done at once.
    let instant = Shift { time: 0.0, ..shift };
    assert_eq!(instant.next(at(1), 130.0, 1.0), Some(at(2)));
}

#[test]
fn during_a_shift_the_sprocket_gets_the_lesser_range_s_torque() {
    let d = m113a3_driveline();
    for i in 0..=160 {
        let w = 0.5 * i as f64;
        let (low, high) = (d.in_range(1, w), d.in_range(2, w));
        let shifting = Engaged {
            range: 2,
            from: Some((1, 10.0)),
        };
        let (torque, slope, range, _) = d.scheduled(shifting, w);
        let lesser = if low.0 < high.0 {
            (low.0, low.1, 1)
        } else {
            (high.0, high.1, 2)
        };
        assert_eq!((torque, slope, range), lesser, "at {w} rad/s");
        let done = d.scheduled(
            Engaged {
                range: 2,
                from: None,
            },
            w,
        );
        assert_eq!(
            (done.0, done.1, done.2),
            (high.0, high.1, 2),
            "at {w} rad/s"
        );
    }
}

#[test]
fn a_run_shifts_where_the_schedule_says() {
    let mut d = m113a3_driveline();
    let schedule = ideal_schedule(&d, 0.0);
    d.shift = Some(schedule.clone());
    // Up to 16 m/s at full throttle, then slowing evenly to 6 m/s (a
    // driver's deceleration: a target dropped at once makes the controller
    // brake the sprocket so hard that its speed swings by half within
    // 0.1 s, and a gearbox shifting on it follows the swings).
    let target = |t: f64| {
        if t < 0.5 {
            0.0
        } else if t < 14.0 {
            16.0
        } else {
            16.0 - 10.0 * ((t - 14.0) / 6.0).min(1.0)
        }
    };
    let results = m113_through(&d, Terrain::Flat { height: 0.0 }, target, 24.0, 0.002);
    let gear = results.column("gear").unwrap();
    let omega = results.column("sprocket_speed").unwrap();
    let t = results.times();
    let mut ups = vec![0; d.ranges.len()];
    let mut downs = vec![0; d.ranges.len()];
    let mut up_speeds = vec![f64::NAN; d.ranges.len()];
    let mut down_speeds = vec![f64::NAN; d.ranges.len()];
    for i in 1..t.len() {
        let (before, after) = (gear[i - 1], gear[i]);
        if before == after || before == 0.0 || after == 0.0 {
            continue;
        }
        let from = before as usize - 1;
        // The input in the range shifted from, at the rows either side of
        // the step end where the gearbox shifted: the scheduled speed lies
        // between them (the sprocket's speed ripples as each tooth
        // engages, by a few per cent of the input within 2 ms).
        let input = |k: usize| d.reduction(from) * omega[k].abs();
        let (low, high) = (input(i - 1).min(input(i)), input(i - 1).max(input(i)));
        let between = |want: f64| low <= 1.01 * want && high >= 0.99 * want;
        if after > before {
            let want = schedule.up[from];
            assert!(
                between(want),
                "t = {} s: up from range {} between {low} and {high} rad/s of input, scheduled {want}",
                t[i],
                from + 1
            );
            ups[from] += 1;
            up_speeds[from] = omega[i].abs();
        } else {
            let want = schedule.down[from];
            assert!(
                between(want),
                "t = {} s: down from range {} between {low} and {high} rad/s of input, scheduled {want}",
                t[i],
                from + 1
            );
            downs[from] += 1;
            down_speeds[from] = omega[i].abs();
        }
    }
    println!("upshifts per range {ups:?}, downshifts {downs:?}");
    assert!(ups[0] == 1 && ups[1] == 1 && ups[2] == 1, "{ups:?}");
    assert!(
        ups.iter().chain(&downs).all(|&n| n <= 1),
        "hunting: {ups:?} {downs:?}"
    );
    assert!(downs[3] == 1 && downs[2] == 1 && downs[1] == 0, "{downs:?}");
    for r in 1..d.ranges.len() {
        if downs[r] == 1 {
            assert!(down_speeds[r] < up_speeds[r - 1], "range {}", r + 1);
        }
    }
}

/// The M113A3 declares its ideal shift points (none of the X200-4's are
/// published): upshifts at the envelope's crossovers, downshifts at
/// `m113::DOWNSHIFT_FRACTION` of them, `m113::SHIFT_TIME` a shift — the
/// schedule `Driveline::ideal_schedule` gives its quasi-static form, to
/// the last printed digit (1e-12).
#[test]
fn the_m113a3_declares_its_ideal_schedule() {
    let d = crate::support::vehicle::m113a3_quasi_static();
    let ideal = d
        .ideal_schedule(m113::DOWNSHIFT_FRACTION, m113::SHIFT_TIME)
        .expect("each range overtakes the one below");
    let declared = m113a3_driveline()
        .shift
        .expect("the M113A3 declares a schedule");
    for (what, a, b) in [
        ("upshift", &declared.up, &ideal.up),
        ("downshift", &declared.down, &ideal.down),
    ] {
        for (r, (x, y)) in a.iter().zip(b).enumerate() {
            assert!(
                (x - y).abs() <= 1e-12 * y.max(1.0),
                "{what} of range {}: {x} against {y}",
                r + 1
            );
        }
    }
    assert_eq!(declared.time, ideal.time);
}
