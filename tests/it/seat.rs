//! The driver's seat: where the declaration puts it, and what it records.
//!
//! * The M113 declares its seat at Chrono's driver position, (0, 1.2) m in
//!   its track-assembly frame: `SEAT` is that point from the chassis
//!   centroid (−2.006, 0.406), (2.006, 0.794) m, exactly (the macro folds
//!   the subtraction; the same `f64` operations here).
//! * The recorded `seat_x`, `seat_y` are the frame's point `A(θ) s̄ + R`
//!   at the recorded chassis pose, to 1e-12 m (the same products).
//! * The recorded acceleration `(seat_ax, seat_az)` (the frame's axes,
//!   kinematic) equals the second difference of the recorded position
//!   turned into the frame's axes, over the M113 crossing the bump at
//!   3 m/s (Dormand-Prince at 1e-10, whose dense output's error is far
//!   below the bounds): at 99 % of the samples within 1e-3 of the
//!   acceleration's range, everywhere within 1e-2 and shrinking as the
//!   spacing halves (see the test for why the largest differences are
//!   where a contact begins). The pitch used to turn the difference is the
//!   sample's, exact. A recorded acceleration off by a term (the
//!   centripetal `−θ̇² A s̄`, say) does not shrink with the spacing.

use trackgen::contact::Terrain;
use trackgen::integrate::Integrator;
use trackgen::multibody::ChassisModel;
use trackgen::nalgebra::Vector2;
use trackgen::planar::Rotation;
use trackgen::simulate::{Output, simulate};
use trackgen::vehicle::Vehicle;
use trackgen::vehicles::m113::{DRIVER_SEAT, M113, M113Chassis};

/// The M113's chassis has 2 + 12 coordinates.
const CHASSIS_DOF: usize = M113::CHASSIS_DOF;

#[test]
fn the_m113_declares_its_seat_at_the_drivers_position() {
    let seat = <M113Chassis as ChassisModel<CHASSIS_DOF>>::SEAT;
    assert_eq!(seat, [DRIVER_SEAT.0 - -2.006, DRIVER_SEAT.1 - 0.406]);
    assert_eq!(DRIVER_SEAT, (0.0, 1.2));
}

/// The seat's recorded acceleration against the central second
/// difference of its recorded position (turned into the frame's axes by
/// the sample's pitch) at spacing `h`, over the M113 crossing the bump:
/// the 99th percentile and the largest of the differences, and the
/// acceleration's range (m/s²). Also checks the recorded position is the
/// frame's point.
fn seat_against_differences(h: f64) -> (f64, f64, f64) {
    let drive = M113::speed_drive(|t| 3.0 * (t / 0.5).clamp(0.0, 1.0));
    let terrain = Terrain::Bump {
        centre: 3.5,
        width: 1.0,
        height: 0.1,
    };
    let mut system = M113::system(terrain, drive).expect("the M113 assembles");
    // The front road wheels cross the bump between 1.2 and 1.8 s.
    let samples = (0.6 / h).round() as usize;
    let times: Vec<f64> = (0..=samples).map(|k| 1.2 + k as f64 * h).collect();
    let results = simulate(
        &mut system,
        Integrator::dopri5(1e-10),
        0.0,
        1.8 + h,
        Output::Times(times),
    )
    .expect("the run finishes");
    let column = |name: &str| results.column(name).expect("a recorded column");
    let (x, y, pitch) = (column("x"), column("y"), column("pitch"));
    let (sx, sy) = (column("seat_x"), column("seat_y"));
    let (ax, az) = (column("seat_ax"), column("seat_az"));
    let seat = <M113Chassis as ChassisModel<CHASSIS_DOF>>::SEAT;
    let offset = Vector2::new(seat[0], seat[1]);
    for k in 0..x.len() {
        let at = Vector2::new(x[k], y[k]) + Rotation::new(pitch[k]).apply(offset);
        assert!(
            (at.x - sx[k]).abs() < 1e-12 && (at.y - sy[k]).abs() < 1e-12,
            "seat position at sample {k}: recorded ({}, {}), the frame's point {at}",
            sx[k],
            sy[k]
        );
    }
    let range = |v: &[f64]| {
        let (lo, hi) = v
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(l, u), &a| {
                (l.min(a), u.max(a))
            });
        hi - lo
    };
    let mut differences: Vec<f64> = (1..x.len() - 1)
        .map(|k| {
            let second = |v: &[f64]| (v[k + 1] - 2.0 * v[k] + v[k - 1]) / (h * h);
            let global = Vector2::new(second(&sx), second(&sy));
            let local = Rotation::new(pitch[k]).apply_inverse(global);
            (local.x - ax[k]).abs().max((local.y - az[k]).abs())
        })
        .collect();
    differences.sort_by(f64::total_cmp);
    let p99 = differences[differences.len() * 99 / 100];
    let largest = *differences.last().expect("samples");
    (p99, largest, range(&ax).max(range(&az)))
}

/// The recorded acceleration is the second derivative of the recorded
/// position. At 99 % of the samples within 1e-3 of the range at a 20 µs
/// spacing (measured 3e-5); everywhere within 1e-2 of it, and converging
/// as the spacing halves (the largest differences sit where a shoe's
/// contact begins: the force is continuous there but its rate jumps, so a
/// central difference across the instant errs by `O(h)` of that jump,
/// halving with `h`; measured 2.8e-3 of the range at 20 µs). A wrong
/// term would not shrink with `h`.
#[test]
fn the_seats_acceleration_is_the_second_difference_of_its_position() {
    let (p99_coarse, largest_coarse, _) = seat_against_differences(4e-5);
    let (p99, largest, range) = seat_against_differences(2e-5);
    println!(
        "seat against second differences, of the range {range:.2} m/s²: 99 % within {:.1e} \
         (40 µs: {:.1e}), largest {:.1e} (40 µs: {:.1e})",
        p99 / range,
        p99_coarse / range,
        largest / range,
        largest_coarse / range
    );
    assert!(range > 1.0, "the bump shakes the seat: range {range} m/s²");
    assert!(
        p99 <= 1e-3 * range,
        "99 % of the samples within {:.1e} of the range, not 1e-3",
        p99 / range
    );
    assert!(
        largest <= 1e-2 * range,
        "the largest difference is {:.1e} of the range, over 1e-2",
        largest / range
    );
    assert!(
        largest <= 0.75 * largest_coarse && p99 <= 0.75 * p99_coarse,
        "the differences do not shrink with the spacing: largest {largest_coarse:e} -> \
         {largest:e}, 99th percentile {p99_coarse:e} -> {p99:e} m/s²"
    );
}
