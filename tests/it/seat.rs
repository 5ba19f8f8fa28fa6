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

use trackgen::integrate::Integrator;
use trackgen::multibody::ChassisModel;
use trackgen::nalgebra::Vector2;
use trackgen::planar::Rotation;
use trackgen::simulate::{Output, simulate};
use trackgen::terrain::Terrain;
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

/// The M113 driven to 3 m/s in 0.5 s towards a 0.1 m bump 1 m wide at
/// x = 3.5 m.
fn m113_over_the_bump() -> trackgen::vehicles::m113::M113System {
    let drive = M113::speed_drive(|t| 3.0 * (t / 0.5).clamp(0.0, 1.0));
    let terrain = Terrain::Bump {
        centre: 3.5,
        width: 1.0,
        height: 0.1,
    };
    M113::system(terrain, drive).expect("the M113 assembles")
}

/// The seat's recorded acceleration against the central second
/// difference of its recorded position (turned into the frame's axes by
/// the sample's pitch) at spacing `h`, over the M113 crossing the bump:
/// the 99th percentile and the largest of the differences, and the
/// acceleration's range (m/s²). Also checks the recorded position is the
/// frame's point.
fn seat_against_differences(h: f64) -> (f64, f64, f64) {
    let mut system = m113_over_the_bump();
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

/// A sink that reads only the hull's `x` and `pitch` and the seat's two
/// accelerations, and keeps every row it is given.
struct SeatOnly {
    read: Vec<usize>,
    rows: Vec<Vec<f64>>,
}

impl trackgen::simulate::Sink for SeatOnly {
    fn begin(&mut self, columns: &[String]) -> Result<(), trackgen::simulate::SinkError> {
        let at = |name: &str| columns.iter().position(|c| c == name).expect("the column");
        self.read = vec![at("x"), at("pitch"), at("seat_ax"), at("seat_az")];
        Ok(())
    }

    fn row(&mut self, _t: f64, values: &[f64]) -> Result<(), trackgen::simulate::SinkError> {
        self.rows.push(values.to_vec());
        Ok(())
    }

    fn finish(&mut self) -> Result<(), trackgen::simulate::SinkError> {
        Ok(())
    }

    fn reads(&self) -> Option<Vec<usize>> {
        Some(self.read.clone())
    }
}

/// A run whose sink reads only the hull and the seat is observed lean
/// (`Simulated::observe_some`: no track accelerations, link kinematics,
/// tensions or energies), and what it reads is bit for bit what the full
/// observation gives: the M113 over the bump, rows every 1 ms for 3 s,
/// against the same run recorded in full. The columns it does not read
/// are NaN there, which is how the test knows the lean path ran.
#[test]
fn a_lean_observation_gives_the_full_ones_bits() {
    let run = |sink: &mut dyn trackgen::simulate::Sink| {
        let mut system = m113_over_the_bump();
        trackgen::simulate::simulate_into(
            &mut system,
            Integrator::Bs23 {
                rtol: 1e-3,
                atol: 1e-3,
                max_step: 0.01,
            },
            0.0,
            3.0,
            Output::Every(1e-3),
            sink,
            &mut |_| {},
        )
        .expect("the run finishes");
    };
    let mut lean = SeatOnly {
        read: Vec::new(),
        rows: Vec::new(),
    };
    run(&mut lean);
    let mut full = trackgen::simulate::Results::default();
    run(&mut full);
    let energy = full
        .columns()
        .iter()
        .position(|c| c == "energy")
        .expect("a vehicle records its energy");
    assert_eq!(lean.rows.len(), full.len());
    assert_eq!(lean.rows.len(), 3001);
    for (k, row) in lean.rows.iter().enumerate() {
        let whole = full.get(k).expect("the row");
        for &i in &lean.read {
            assert_eq!(
                row[i].to_bits(),
                whole.values[i].to_bits(),
                "row {k}, column {i}"
            );
        }
        assert!(row[energy].is_nan(), "row {k}: the energy was observed");
        assert!(whole.values[energy].is_finite());
    }
}

/// A tee reads what any of its sinks reads, each column once; a sink that
/// reads every column makes the tee read every one.
#[test]
fn a_tee_reads_the_union_of_its_sinks() {
    use trackgen::simulate::{Results, Sink, Tee};
    let columns: Vec<String> = ["x", "pitch", "seat_ax", "seat_az", "energy"]
        .iter()
        .map(|c| c.to_string())
        .collect();
    let seat_only = || SeatOnly {
        read: Vec::new(),
        rows: Vec::new(),
    };
    let (mut a, mut b) = (seat_only(), seat_only());
    let mut tee = Tee::new().and(&mut a).and(&mut b);
    tee.begin(&columns).unwrap();
    assert_eq!(tee.reads(), Some(vec![0, 1, 2, 3]));
    drop(tee);
    let (mut c, mut all) = (seat_only(), Results::default());
    let mut tee = Tee::new().and(&mut c).and(&mut all);
    tee.begin(&columns).unwrap();
    assert_eq!(tee.reads(), None);
}
